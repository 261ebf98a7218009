//! Free bodies, as the course solves kinetostatics element by element (seed
//! 000, "Diagramas de sólido libre"): each moving body isolated with every
//! action on it at one solved position, and d'Alembert's three equations
//! with their numbers,
//!
//! ```text
//! ΣF_x = 0,   ΣF_y = 0,   ΣM_G = Σ (r_P − r_G) × F + Σ M = 0,
//! ```
//!
//! where the actions are: each joint's reaction R_ij from its neighbour (a
//! force at the joint's point, and the couple a guide or a pin's friction
//! bears; a guide of given length as two forces at its ends), the inertia
//! force −m·a_G at G and couple −I_G·α, the weight m·g, the applied loads,
//! springs and dampers, and each input's driving effort, where it acts:
//! the row ∇c of the coordinate c it works along times the effort (a
//! couple at a revolute joint, a force along a prismatic one's axis or a
//! point's direction). The sums are not forced to zero: they are what these
//! numbers add up to, zero to rounding when the step is right.

use super::loads::{Load, point_acceleration, point_motion};
use super::{Reaction, Step};
use crate::engine::constraints::{State, System, evaluate_into};
use crate::engine::function::Side;
use crate::engine::model::{BodyId, Coordinate, Guide, JointKind, Mechanism, cross, dot, perp, rotate_by};

/// What an action is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Joint `joint`'s reaction from body `by`.
    Reaction { joint: usize, by: BodyId },
    /// −m·a_G at G, or −I_G·α.
    Inertia,
    /// m·g at G.
    Weight,
    /// The request's load `k` (a force, torque, spring or damper).
    Load(usize),
    /// Input `k`'s driving effort.
    Driving(usize),
}

/// A force `f` (N) at the point `at` (m, ground frame, at the step's position).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Force {
    pub action: Action,
    pub at: [f64; 2],
    pub f: [f64; 2],
}

/// A couple (N·m, counter-clockwise positive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Couple {
    pub action: Action,
    pub moment: f64,
}

/// One moving body isolated: where its G is and how it moves (v_G, ω: the
/// actions' powers), its actions, and [ΣF_x, ΣF_y, ΣM_G] with them.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeBody {
    pub body: BodyId,
    pub cg: [f64; 2],
    pub v_cg: [f64; 2],
    pub omega: f64,
    pub forces: Vec<Force>,
    pub couples: Vec<Couple>,
    pub sums: [f64; 3],
}

/// Every moving body's free body at a solved `step` (its motion kept),
/// reached by `inputs` (coordinate, speed, acceleration of each) at `time`
/// (the loads' functions read the first input's coordinate and speed, and
/// the time); None at a singular position or without the motion.
pub fn free_bodies(
    m: &Mechanism,
    loads: &[Load],
    step: &Step,
    (inputs, time): (&[[f64; 3]], f64),
) -> Option<Vec<FreeBody>> {
    let motion = step.kinematics.as_ref().filter(|_| !step.singular)?;
    let (q, qd, qdd) = (&motion.q[..], &motion.qd[..], &motion.qdd[..]);
    let mut bodies: Vec<FreeBody> = (1..m.bodies.len()).map(|b| own_actions(m, (q, qd, qdd), b)).collect();
    let mut on = |b: BodyId, action: Action, at: Option<[f64; 2]>, f: [f64; 2], moment: f64| {
        let Some(fb) = b.checked_sub(1).and_then(|i| bodies.get_mut(i)) else { return };
        if let Some(at) = at {
            fb.forces.push(Force { action, at, f });
        }
        if moment != 0.0 || at.is_none() {
            fb.couples.push(Couple { action, moment });
        }
    };
    let first = inputs.first().copied().unwrap_or([0.0; 3]);
    for (k, load) in loads.iter().enumerate() {
        for (b, at, f, moment) in load_actions(m, (q, qd), load, (first[0], [first[1], time])) {
            on(b, Action::Load(k), at, f, moment);
        }
    }
    for r in &step.reactions {
        for (b, by, sign) in [(r.on, r.by, 1.0), (r.by, r.on, -1.0)] {
            for (at, f, moment) in reaction_parts(m, q, r) {
                on(b, Action::Reaction { joint: r.joint, by }, Some(at), [sign * f[0], sign * f[1]], sign * moment);
            }
        }
    }
    for (i, (b, at, f, moment)) in driving_actions(m, q, &step.driving, inputs) {
        on(b, Action::Driving(i), at, f, moment);
    }
    for fb in &mut bodies {
        fb.sums = sums(fb);
    }
    Some(bodies)
}

/// Body b with what it has of its own: its inertia force and couple, its weight.
fn own_actions(m: &Mechanism, (q, qd, qdd): (&[f64], &[f64], &[f64]), b: BodyId) -> FreeBody {
    let body = &m.bodies[b];
    let (cg, v_cg) = point_motion(m, q, qd, (b, body.cg));
    let a = point_acceleration(m, q, qd, qdd, (b, body.cg));
    let (omega, alpha) = m.column(b).map_or((0.0, 0.0), |c| (qd[c + 2], qdd[c + 2]));
    let forces = vec![
        Force { action: Action::Inertia, at: cg, f: [-body.mass * a[0], -body.mass * a[1]] },
        Force { action: Action::Weight, at: cg, f: [body.mass * m.gravity[0], body.mass * m.gravity[1]] },
    ];
    let couples = vec![Couple { action: Action::Inertia, moment: -body.inertia * alpha }];
    FreeBody { body: b, cg, v_cg, omega, forces, couples, sums: [0.0; 3] }
}

impl FreeBody {
    /// The power of a force at `at` on this body: f·(v_G + ω × (r − r_G)).
    pub fn power(&self, at: [f64; 2], f: [f64; 2]) -> f64 {
        let r = [at[0] - self.cg[0], at[1] - self.cg[1]];
        let v = [self.v_cg[0] - self.omega * r[1], self.v_cg[1] + self.omega * r[0]];
        dot(f, v)
    }
}

/// The joint input i's effort acts at (its actuator, or its own joint), if any.
pub fn acting_joint(m: &Mechanism, i: usize) -> Option<usize> {
    let d = &m.drivers[i];
    d.actuator.or(if let Coordinate::Joint(k) = d.coordinate { Some(k) } else { None })
}

/// Whether input i's effort is a force (along a slide, a contact or a
/// point's direction) rather than a couple.
pub fn linear_input(m: &Mechanism, i: usize) -> bool {
    match acting_joint(m, i) {
        Some(k) => !matches!(m.joints[k].kind, JointKind::Revolute | JointKind::Gear { .. }),
        None => matches!(m.drivers[i].coordinate, Coordinate::Point { .. }),
    }
}

/// [ΣF_x, ΣF_y, ΣM_G] of a free body's actions.
fn sums(fb: &FreeBody) -> [f64; 3] {
    let (mut fx, mut fy, mut moment) = (0.0, 0.0, 0.0);
    for force in &fb.forces {
        (fx, fy) = (fx + force.f[0], fy + force.f[1]);
        moment += cross([force.at[0] - fb.cg[0], force.at[1] - fb.cg[1]], force.f);
    }
    [fx, fy, moment + fb.couples.iter().map(|c| c.moment).sum::<f64>()]
}

/// Where body b's point p (reference coordinates) is at q.
fn placed(m: &Mechanism, q: &[f64], b: BodyId, p: [f64; 2]) -> [f64; 2] {
    point_motion(m, q, &vec![0.0; q.len()], (b, p)).0
}

/// (sin θ, cos θ) of body b at q.
fn turn(m: &Mechanism, q: &[f64], b: BodyId) -> (f64, f64) {
    m.column(b).map_or((0.0, 1.0), |c| q[c + 2].sin_cos())
}

/// A body's action: (body, where a force acts or None for a couple alone, force, couple).
type Part = (BodyId, Option<[f64; 2]>, [f64; 2], f64);

/// What a load puts on each body it acts on, its functions at (φ, [ω, t]).
fn load_actions(m: &Mechanism, (q, qd): (&[f64], &[f64]), load: &Load, (phi, state): (f64, [f64; 2])) -> Vec<Part> {
    let line = |a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2])| {
        let ((pa, va), (pb, vb)) = (point_motion(m, q, qd, a), point_motion(m, q, qd, b));
        let d = [pb[0] - pa[0], pb[1] - pa[1]];
        let length = d[0].hypot(d[1]);
        let u = if length > 0.0 { [d[0] / length, d[1] / length] } else { [0.0; 2] };
        (pa, pb, u, length, dot([vb[0] - va[0], vb[1] - va[1]], u))
    };
    let pair =
        |(a, b): ((BodyId, [f64; 2]), (BodyId, [f64; 2])), (pa, pb, u): ([f64; 2], [f64; 2], [f64; 2]), t: f64| {
            vec![(a.0, Some(pa), [t * u[0], t * u[1]], 0.0), (b.0, Some(pb), [-t * u[0], -t * u[1]], 0.0)]
        };
    match load {
        Load::Force { body, at, direction, magnitude } => {
            let f = magnitude.eval_at(phi, Side::Right, state);
            vec![(*body, Some(placed(m, q, *body, *at)), [f * direction[0], f * direction[1]], 0.0)]
        }
        Load::Torque { body, value } => vec![(*body, None, [0.0; 2], value.eval_at(phi, Side::Right, state))],
        Load::Spring { a, b, stiffness, free_length } => {
            let (pa, pb, u, length, _) = line(*a, *b);
            pair((*a, *b), (pa, pb, u), stiffness * (length - free_length))
        }
        Load::Damper { a, b, coefficient } => {
            let (pa, pb, u, _, rate) = line(*a, *b);
            pair((*a, *b), (pa, pb, u), coefficient * rate)
        }
    }
}

/// A reaction on its `on` body as forces at points and a couple: at the
/// joint's point (a contact's where it touches, a mesh's pitch point), or
/// a guide of given length as its two ends, each its normal force and its
/// share of the friction along the axis.
fn reaction_parts(m: &Mechanism, q: &[f64], r: &Reaction) -> Vec<([f64; 2], [f64; 2], f64)> {
    let joint = &m.joints[r.joint];
    let [i, j] = joint.bodies;
    let b = if j != 0 { j } else { i };
    let f = [r.fx, r.fy];
    if let JointKind::Gear { pitch: Some(pitch), .. } = &joint.kind {
        return vec![(super::reactions::pitch_point(m, q, [i, j], pitch), f, 0.0)];
    }
    if let (JointKind::Prismatic { axis }, Some(guide), Some([n1, n2])) = (&joint.kind, joint.length, r.ends) {
        let carrier = if matches!(guide, Guide::Fixed(_)) { i } else { j };
        let (centre, u) = (placed(m, q, carrier, joint.at), rotate_by(turn(m, q, i), *axis));
        let (n, half, t) = (perp(u), guide.length() / 2.0, dot(f, u));
        let share = if n1 == 0.0 && n2 == 0.0 { 0.5 } else { n1.abs() / (n1.abs() + n2.abs()) };
        let end = |s: f64, normal: f64, t: f64| {
            (
                [centre[0] + s * half * u[0], centre[1] + s * half * u[1]],
                [normal * n[0] + t * u[0], normal * n[1] + t * u[1]],
                0.0,
            )
        };
        return vec![end(-1.0, n1, t * share), end(1.0, n2, t * (1.0 - share))];
    }
    let at = m.contact_point(r.joint, b, q).unwrap_or(joint.at);
    vec![(placed(m, q, b, at), f, r.moment)]
}

/// Each input's effort where it acts: the row ∇c of the coordinate it
/// works along (its actuator's, else its own) times the effort, on every
/// body that row moves: a force at the joint's or the point's place (none
/// for a rotation) and the couple about G left beside it.
fn driving_actions(m: &Mechanism, q: &[f64], driving: &[f64], inputs: &[[f64; 3]]) -> Vec<(usize, Part)> {
    let mut by_actuators = m.clone();
    for d in &mut by_actuators.drivers {
        d.coordinate = d.actuator.map_or(d.coordinate, Coordinate::Joint);
    }
    let mut sys = System::default();
    evaluate_into(&by_actuators, &State { q, qd: None, inputs }, &mut sys);
    let first = sys.jacobian.nrows() - m.drivers.len();
    let mut out = vec![];
    for (i, (d, &effort)) in by_actuators.drivers.iter().zip(driving).enumerate().filter(|(_, (_, e))| e.is_finite()) {
        if let Some(part) = sliding_contact_effort(m, q, d.coordinate, effort) {
            out.extend(part.map(|p| (i, p)));
            continue;
        }
        for b in 1..m.bodies.len() {
            let c = m.column(b).expect("a moving body has coordinates");
            let [qx, qy, qm] = [0, 1, 2].map(|k| sys.jacobian[(first + i, c + k)] * effort);
            if qx == 0.0 && qy == 0.0 && qm == 0.0 {
                continue;
            }
            let at = match d.coordinate {
                Coordinate::Joint(k) if !matches!(m.joints[k].kind, JointKind::Revolute) => {
                    Some(placed(m, q, b, m.contact_point(k, b, q).unwrap_or(m.joints[k].at)))
                }
                Coordinate::Point { body, at, .. } if body == b => Some(placed(m, q, b, at)),
                _ => None,
            };
            // A force at its place (at G where it has none), and the couple about G left beside it.
            let cg = placed(m, q, b, m.bodies[b].cg);
            let p = at.unwrap_or(cg);
            match qx != 0.0 || qy != 0.0 {
                true => out.push((i, (b, Some(p), [qx, qy], qm - cross([p[0] - cg[0], p[1] - cg[1]], [qx, qy])))),
                false => out.push((i, (b, None, [0.0; 2], qm))),
            }
        }
    }
    out
}

/// An effort along a sliding contact's arc length (its row moves the arc's
/// parameter, no body): the force effort·t the contact passes to its second
/// body at the point of contact, t the way the arc runs, and its opposite
/// to the first — what [`super::reactions`] leaves out of the contact's
/// reaction.
fn sliding_contact_effort(m: &Mechanism, q: &[f64], c: Coordinate, effort: f64) -> Option<[Part; 2]> {
    let Coordinate::Joint(k) = c else { return None };
    let JointKind::Contact(contact) = &m.joints[k].kind else { return None };
    if contact.rolling {
        return None;
    }
    let t = m.contact_arc_direction(k, q)?;
    let [i, j] = m.joints[k].bodies;
    let f = [effort * t[0], effort * t[1]];
    let at = |b: BodyId| Some(placed(m, q, b, m.contact_point(k, b, q).unwrap_or(m.joints[k].at)));
    Some([(j, at(j), f, 0.0), (i, at(i), [-f[0], -f[1]], 0.0)])
}
