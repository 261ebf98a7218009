//! A joint reaction as the results say it, with its joint's and bodies'
//! names, and a contact's state at a step.

use super::NameOrder;
use crate::engine::kinetostatics::{ContactState, Reaction};
use crate::engine::model::{JointKind, Mechanism};
use crate::i18n::Msg;
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use utoipa::ToSchema;

/// A joint's or a body's name in a result, serialized as the string: one
/// of up to 23 bytes is held inline (a clone is a copy of 24 bytes, where
/// an `Arc<str>`'s count made three atomic operations of every reaction of
/// every step), a longer one shared.
pub type Name = smol_str::SmolStr;

/// The names as results hold them.
pub fn names(list: &[String]) -> Vec<Name> {
    list.iter().map(|n| Name::from(n.as_str())).collect()
}

/// The joints' and the bodies' names (ground first) a job's reactions
/// refer to, made once and shared by every step's [`Reactions`].
#[derive(Debug, Default)]
pub struct Names {
    pub joints: Vec<Name>,
    pub bodies: Vec<Name>,
    /// The order the moving bodies' names (`bodies[1..]`) are written in.
    pub moving: NameOrder,
}

impl Names {
    pub fn new(joints: &[String], bodies: &[String]) -> Arc<Self> {
        let bodies = names(bodies);
        let moving = NameOrder::new(bodies.get(1..).unwrap_or_default());
        Arc::new(Self { joints: names(joints), bodies, moving })
    }
}

/// The force body `by` exerts on body `on` at the joint (ground frame) and the
/// couple about the joint point, the joint's friction included (the force
/// along a slide, the couple of a pin), so that every body's forces
/// balance. Null when redundant constraints leave it undetermined.
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct ReactionDto<'a> {
    pub joint: &'a str,
    pub on: &'a str,
    pub by: &'a str,
    pub fx: Option<f64>,
    pub fy: Option<f64>,
    pub moment: Option<f64>,
    /// A prismatic joint with a `length`: the normal forces N₁, N₂ at the
    /// guide's ends (at − L/2 and at + L/2 along the axis), N, on `on`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ends: Option<[f64; 2]>,
    /// A contact: the normal force (N ≥ 0 when the bodies press on each other).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub normal: Option<f64>,
    /// A contact: the force along the common tangent (the friction, or the
    /// force rolling needs). A sliding contact that is an input, or an
    /// input's actuator, leaves out the driving effort: it is the
    /// actuator's (in `driving`), acting along the contact's arc length.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential: Option<f64>,
    /// A rolling contact: |tangential|/normal, the least friction coefficient that rolls.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mu_required: Option<f64>,
    pub determinate: bool,
}

/// A step's joint reactions, written as a list of [`ReactionDto`]: the
/// engine's, each contact's with its normal and tangential parts, named
/// only as they are written (a step of K1 copied and dropped twelve
/// names).
#[derive(Clone, Debug)]
pub struct Reactions {
    names: Arc<Names>,
    list: Vec<(Reaction, Option<Parts>)>,
}

/// A contact's reaction along its normal and its tangent, and for a
/// rolling one the least friction coefficient that rolls.
#[derive(Clone, Copy, Debug)]
struct Parts {
    normal: f64,
    tangential: f64,
    mu_required: Option<f64>,
}

impl Reactions {
    /// The engine's `reactions`, each contact's with its state's normal and
    /// tangential forces (`contacts`); `m` tells a rolling contact.
    pub fn new(names: &Arc<Names>, reactions: &[Reaction], contacts: &[ContactState], m: &Mechanism) -> Self {
        let parts = |r: &Reaction| {
            let c = contacts.iter().find(|c| c.joint == r.joint)?;
            let rolling = matches!(&m.joints[c.joint].kind, JointKind::Contact(k) if k.rolling);
            let mu_required = rolling.then(|| c.tangential.abs() / c.normal).filter(|v| v.is_finite());
            Some(Parts { normal: c.normal, tangential: c.tangential, mu_required })
        };
        Self { names: Arc::clone(names), list: reactions.iter().map(|r| (*r, parts(r))).collect() }
    }

    fn dto<'a>(&'a self, (r, parts): &(Reaction, Option<Parts>)) -> ReactionDto<'a> {
        let v = |x: f64| r.determinate.then_some(x);
        ReactionDto {
            joint: &self.names.joints[r.joint],
            on: &self.names.bodies[r.on],
            by: &self.names.bodies[r.by],
            fx: v(r.fx),
            fy: v(r.fy),
            moment: v(r.moment),
            ends: r.ends.filter(|_| r.determinate),
            normal: parts.map(|p| p.normal),
            tangential: parts.map(|p| p.tangential),
            mu_required: parts.and_then(|p| p.mu_required),
            determinate: r.determinate,
        }
    }
}

impl Serialize for Reactions {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.list.iter().map(|row| self.dto(row)))
    }
}

/// A contact joint at a step: where its curves touch and what passes there.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct ContactDto {
    #[schema(value_type = String)]
    pub joint: Name,
    /// [x, y] (m), ground frame.
    pub point: [f64; 2],
    /// (v₂ − v₁)·t of the material points at the contact (m/s): 0 rolling.
    pub sliding_velocity: f64,
    /// The velocity (m/s, [vx, vy]) of the material point at the contact
    /// of each body: the first's, then the second's.
    pub velocities: [[f64; 2]; 2],
    /// The first body's force on the second along the normal (N ≥ 0 pressing).
    pub normal: f64,
    /// ... and along the common tangent (N).
    pub tangential: f64,
    /// Each curve's radius of curvature there (m; signed as the curve
    /// turns; null: straight, or a point).
    pub curvature_radius: [Option<f64>; 2],
    /// The angle between the normal and the follower's velocity there (rad),
    /// where the second body turns or slides on the ground.
    pub pressure_angle: Option<f64>,
    /// The contact ran off the end of an open curve here (a warning says where).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub off_end: bool,
    /// The curves overlap around the contact here (a flat face on a concave
    /// stretch, a roller in a tighter hollow): the bodies would touch
    /// elsewhere, at another lobe (a warning says where).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub overlap: bool,
    /// The contact jumped here from far off where it was followed to:
    /// another lobe (a warning says where).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub jumped: bool,
    /// The bodies cut into each other here, away from the contact, this
    /// deep (m): the contact the equations follow cannot be, and none
    /// outside both bodies was found (a warning says where). Absent where
    /// they only touch.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub penetration: Option<f64>,
    /// Direct dynamics, a rolling contact with friction: "rolling" or
    /// "slipping" at this instant.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub state: Option<String>,
}

impl ContactDto {
    pub fn new(c: &ContactState, joint_names: &[Name]) -> Self {
        Self {
            joint: joint_names[c.joint].clone(),
            point: c.point,
            sliding_velocity: c.sliding_velocity,
            velocities: c.velocities,
            normal: c.normal,
            tangential: c.tangential,
            curvature_radius: c.curvature_radius,
            pressure_angle: c.pressure_angle,
            off_end: c.off_end,
            overlap: c.overlap,
            jumped: c.jumped,
            penetration: c.penetration,
            state: c.slipping.map(|s| if s { "slipping" } else { "rolling" }.into()),
        }
    }
}

/// The conditions [`contact_warnings`] follows for each contact, in the order of
/// its slots: separates, slips, off the end, overlaps, jumped, cut.
const CONDITIONS: usize = 6;

/// The warnings a sweep's contacts call for, each over the runs of
/// consecutive positions where it holds (`at` the position, shown by
/// `show`): a negative normal force (the bodies would separate there: a
/// follower jump, a disk leaving its track), and a rolling contact needing
/// more friction than its `friction` gives (it would slip), each unless
/// `dynamics` models it (a slip is then integrated, a separation stops the
/// run, and the kind says so), a contact run off the end of
/// an open curve, a jump to another lobe, curves that overlap round the
/// contact or bodies cut into each other elsewhere. A particle's
/// contact (a ring threaded on a rim) holds both ways: no warning.
pub fn contact_warnings<'a>(
    steps: impl Iterator<Item = (f64, &'a [ContactDto])>,
    m: &Mechanism,
    show: impl Fn(f64) -> Msg,
    dynamics: bool,
) -> Vec<Msg> {
    let joints: Vec<(usize, &str)> = (m.joints.iter().enumerate())
        .filter(|(_, j)| matches!(j.kind, JointKind::Contact(_)))
        .map(|(k, j)| (k, j.name.as_str()))
        .collect();
    // Per contact joint and condition, the runs [from, to] of positions.
    let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new(); CONDITIONS * joints.len()];
    let mut open = vec![false; CONDITIONS * joints.len()];
    for (at, contacts) in steps {
        for (i, &(k, name)) in joints.iter().enumerate() {
            let c = contacts.iter().find(|c| &*c.joint == name);
            let mu = m.joints[k].friction.map(|f| f.mu);
            let rolling = matches!(&m.joints[k].kind, JointKind::Contact(c) if c.rolling);
            let slips = |c: &ContactDto| {
                !dynamics && rolling && mu.is_some_and(|mu| c.tangential.abs() > mu * c.normal.max(0.0))
            };
            let threaded = matches!(&m.joints[k].kind, JointKind::Contact(c) if c.particle);
            let separates = c.is_some_and(|c| c.normal < 0.0) && !threaded && !dynamics;
            let conditions = [
                separates,
                c.is_some_and(slips),
                c.is_some_and(|c| c.off_end),
                c.is_some_and(|c| c.overlap),
                c.is_some_and(|c| c.jumped),
                c.is_some_and(|c| c.penetration.is_some()),
            ];
            for (slot, holds) in conditions.into_iter().enumerate().map(|(n, h)| (CONDITIONS * i + n, h)) {
                match (holds, open[slot]) {
                    (true, true) => runs[slot].last_mut().expect("an open run").1 = at,
                    (true, false) => runs[slot].push((at, at)),
                    _ => {}
                }
                open[slot] = holds;
            }
        }
    }
    let span = |r: &[(f64, f64)]| {
        let run = |&(a, b): &(f64, f64)| match a == b {
            true => show(a),
            false => Msg::new("warning-span").with("from", show(a)).with("to", show(b)),
        };
        r.iter().map(run).collect::<Vec<_>>()
    };
    let mut out = Vec::new();
    for (i, &(k, name)) in joints.iter().enumerate() {
        let said = |id, slot: usize| Msg::new(id).arg("name", name).list("at", span(&runs[CONDITIONS * i + slot]));
        // In the order a reader needs them: where the results are not a contact's first.
        let conditions = [
            (2, "warning-contact-off-end"),
            (4, "warning-contact-jumped"),
            (5, "warning-contact-cut"),
            (3, "warning-contact-overlap"),
            (0, "warning-contact-separates"),
        ];
        for (slot, id) in conditions {
            if !runs[CONDITIONS * i + slot].is_empty() {
                out.push(said(id, slot));
            }
        }
        if let (false, Some(f)) = (runs[CONDITIONS * i + 1].is_empty(), m.joints[k].friction) {
            out.push(said("warning-contact-slips", 1).num("mu", f.mu));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::samples::eccentric_cam;
    use serde_json::json;

    /// Each reaction as the list writes it, against the JSON written out
    /// from the fields' definitions: names from the job's, null forces and
    /// no `ends` where it is not determinate, a contact's normal and
    /// tangential parts, and μ required only where the contact rolls (and
    /// |F_t|/N is finite). Values exact in binary.
    #[test]
    fn every_reaction_is_written_with_its_names_and_its_contact_s_parts() {
        let mut m = eccentric_cam();
        let names = Names::new(
            &["O".into(), "guide".into(), "contact".into()],
            &["ground".into(), "cam".into(), "follower".into()],
        );
        let reaction = |joint: usize, [on, by]: [usize; 2], ends: Option<[f64; 2]>, determinate: bool| Reaction {
            joint,
            on,
            by,
            fx: 1.5,
            fy: -2.0,
            moment: 0.25,
            ends,
            determinate,
        };
        let list = [
            reaction(0, [1, 0], None, false),
            reaction(1, [2, 0], Some([3.0, 4.0]), true),
            reaction(2, [2, 1], Some([3.0, 4.0]), false),
            reaction(2, [2, 1], None, true),
        ];
        let contact = ContactState {
            joint: 2,
            point: [0.0, 0.03],
            normal: 8.0,
            tangential: -2.0,
            sliding_velocity: 0.5,
            velocities: [[0.0; 2]; 2],
            curvature_radius: [Some(0.05), None],
            pressure_angle: Some(0.0),
            off_end: false,
            overlap: false,
            jumped: false,
            penetration: None,
            slipping: None,
        };
        let forces = json!({"fx": 1.5, "fy": -2.0, "moment": 0.25});
        let undetermined = json!({"fx": null, "fy": null, "moment": null});
        let with = |names: [&str; 3], forces: &serde_json::Value, extra: serde_json::Value, determinate: bool| {
            let mut v = json!({"joint": names[0], "on": names[1], "by": names[2], "determinate": determinate});
            v.as_object_mut().unwrap().extend(forces.as_object().unwrap().clone());
            v.as_object_mut().unwrap().extend(extra.as_object().unwrap().clone());
            v
        };
        let sliding = serde_json::to_value(Reactions::new(&names, &list, &[contact], &m)).unwrap();
        let parts = json!({"normal": 8.0, "tangential": -2.0});
        let want = |contact_extra: serde_json::Value| {
            json!([
                with(["O", "cam", "ground"], &undetermined, json!({}), false),
                with(["guide", "follower", "ground"], &forces, json!({"ends": [3.0, 4.0]}), true),
                with(["contact", "follower", "cam"], &undetermined, contact_extra.clone(), false),
                with(["contact", "follower", "cam"], &forces, contact_extra, true),
            ])
        };
        assert_eq!(sliding, want(parts.clone()));
        if let JointKind::Contact(c) = &mut m.joints[2].kind {
            c.rolling = true;
        }
        let rolling = serde_json::to_value(Reactions::new(&names, &list, &[contact], &m)).unwrap();
        assert_eq!(rolling, want(json!({"normal": 8.0, "tangential": -2.0, "mu_required": 0.25})), "|−2|/8");
        let separate = ContactState { normal: 0.0, ..contact };
        let no_mu = serde_json::to_value(Reactions::new(&names, &list, &[separate], &m)).unwrap();
        assert_eq!(no_mu, want(json!({"normal": 0.0, "tangential": -2.0})), "|−2|/0 is not finite: no μ");
        // The serialized text keeps the fields' order of the list's schema.
        let text = serde_json::to_string(&Reactions::new(&names, &list[1..2], &[], &m)).unwrap();
        assert_eq!(
            text,
            r#"[{"joint":"guide","on":"follower","by":"ground","fx":1.5,"fy":-2.0,"moment":0.25,"ends":[3.0,4.0],"determinate":true}]"#
        );
    }
}
