//! A mechanism's free bodies in the notes' words (contract part five, "Free
//! bodies"; the notation in [`crate::kind::solution`]): the bodies
//! numbered from the ground's 1, each action named (R_ij, F_Ij, M_Ij, W_j,
//! the loads, M_m), the Assur groups in the order their equations are
//! solved with what each gives, and the actions' powers. Shared by the
//! kinds whose jobs are mechanisms (kinetostatics, dynamics).

use crate::engine::kinetostatics::{Action, FreeBody, Load, solving_order};
use crate::engine::model::{BodyId, Mechanism};
use crate::kind::solution::{self as wire, Solution};
use std::collections::BTreeMap;

/// The free bodies in the notes' words.
pub fn written(
    m: &Mechanism,
    names: &[String],
    loads: &[Load],
    (step, input): (usize, &[f64]),
    bodies: &[FreeBody],
    free: bool,
) -> Solution {
    let notation = Notation { m, names, loads, free };
    let groups: Vec<wire::Group> = solving_order(m)
        .into_iter()
        .map(|g| wire::Group {
            bodies: g.bodies.iter().map(|&b| names[b].clone()).collect(),
            unknowns: g
                .joints
                .iter()
                .map(|&k| notation.reaction(k, &g.bodies))
                .chain(g.inputs.iter().map(|&i| notation.driving(i)))
                .collect(),
        })
        .collect();
    let written: Vec<wire::FreeBody> = bodies.iter().map(|fb| notation.free_body(fb)).collect();
    Solution {
        step,
        input: input.to_vec(),
        numbering: (0..m.bodies.len()).map(|b| (names[b].clone(), b + 1)).collect(),
        order: groups.iter().flat_map(|g| g.bodies.clone()).collect(),
        groups,
        virtual_power: virtual_power(&written),
        bodies: written,
    }
}

/// Names as the notes write them.
struct Notation<'a> {
    m: &'a Mechanism,
    names: &'a [String],
    loads: &'a [Load],
    /// The inputs move freely (a run's sample): what their equations give
    /// is their acceleration, not an effort.
    free: bool,
}

impl Notation<'_> {
    /// Joint k's reaction as its group's equations give it: on the group's
    /// body (on its second body when both are the group's).
    fn reaction(&self, k: usize, group: &[BodyId]) -> String {
        let [i, j] = self.m.joints[k].bodies;
        let (by, on) = if group.contains(&j) { (i, j) } else { (j, i) };
        format!("R{}", pair(by, on))
    }

    /// Input i's effort: `M_m` (a couple) or `F_m` (a force), numbered when
    /// there are several; a free input's acceleration, `φ̈` or `ẍ`.
    fn driving(&self, i: usize) -> String {
        let linear = crate::engine::kinetostatics::linear_input(self.m, i);
        let n = if self.m.drivers.len() > 1 { format!("{}", i + 1) } else { String::new() };
        match (self.free, linear) {
            (true, true) => format!("ẍ{n}"),
            (true, false) => format!("φ̈{n}"),
            (false, true) => format!("F_m{n}"),
            (false, false) => format!("M_m{n}"),
        }
    }

    /// An action's name on body `on`, for a force (`R23`, `F_I3`) or a couple (`M23`, `M_I3`).
    fn name(&self, action: Action, on: BodyId, couple: bool) -> String {
        let n = on + 1;
        match action {
            Action::Reaction { by, .. } => format!("{}{}", if couple { "M" } else { "R" }, pair(by, on)),
            Action::Inertia => format!("{}_I{n}", if couple { "M" } else { "F" }),
            Action::Weight => format!("W{n}"),
            Action::Load(k) => load_name(&self.loads[k], k),
            Action::Driving(i) => {
                let base = self.driving(i);
                if couple && base.starts_with('F') { base.replacen('F', "M", 1) } else { base }
            }
        }
    }

    /// The body it comes from and the joint it acts through.
    fn source(&self, action: Action) -> (Option<String>, Option<String>) {
        match action {
            Action::Reaction { joint, by } => (Some(self.names[by].clone()), Some(self.m.joints[joint].name.clone())),
            Action::Driving(i) => {
                (None, crate::engine::kinetostatics::acting_joint(self.m, i).map(|k| self.m.joints[k].name.clone()))
            }
            _ => (None, None),
        }
    }

    fn free_body(&self, fb: &FreeBody) -> wire::FreeBody {
        let forces = fb
            .forces
            .iter()
            .map(|f| {
                let (by, joint) = self.source(f.action);
                let name = self.name(f.action, fb.body, false);
                let power = fb.power(f.at, f.f);
                wire::Force {
                    name,
                    kind: kind(f.action).into(),
                    by,
                    joint,
                    at: f.at.to_vec(),
                    fx: f.f[0],
                    fy: f.f[1],
                    fz: None,
                    power,
                }
            })
            .collect();
        let couples = fb
            .couples
            .iter()
            .map(|c| {
                let (by, joint) = self.source(c.action);
                let name = self.name(c.action, fb.body, true);
                let power = c.moment * fb.omega;
                let kind = kind(c.action).into();
                wire::Couple { name, kind, by, joint, moment: c.moment, mx: None, my: None, power }
            })
            .collect();
        let [sum_fx, sum_fy, sum_moment_about_cg] = fb.sums;
        wire::FreeBody {
            body: self.names[fb.body].clone(),
            number: fb.body + 1,
            cg: fb.cg.to_vec(),
            forces,
            couples,
            equations: wire::Equations {
                sum_fx,
                sum_fy,
                sum_moment_about_cg,
                sum_fz: None,
                sum_mx_about_cg: None,
                sum_my_about_cg: None,
            },
        }
    }
}

/// An action's `kind` as the solution says it.
pub fn kind(action: Action) -> &'static str {
    match action {
        Action::Reaction { .. } => "reaction",
        Action::Inertia => "inertia",
        Action::Weight => "weight",
        Action::Load(_) => "load",
        Action::Driving(_) => "driving",
    }
}

/// `ij` of bodies i and j (the ground 1), `i,j` where one has two digits.
pub fn pair(by: BodyId, on: BodyId) -> String {
    let (i, j) = (by + 1, on + 1);
    if i < 10 && j < 10 { format!("{i}{j}") } else { format!("{i},{j}") }
}

/// A load's name: `F1` (a force), `M2` (a torque), `F_k3` (a spring), `F_c4` (a damper), by its place in `loads`.
fn load_name(load: &Load, k: usize) -> String {
    let n = k + 1;
    match load {
        Load::Force { .. } => format!("F{n}"),
        Load::Torque { .. } => format!("M{n}"),
        Load::Spring { .. } => format!("F_k{n}"),
        Load::Damper { .. } => format!("F_c{n}"),
    }
}

/// Every action's power summed by name over the bodies, the reactions' together.
pub fn virtual_power(bodies: &[wire::FreeBody]) -> wire::VirtualPower {
    let (mut actions, mut reactions) = (BTreeMap::<String, f64>::new(), 0.0);
    let all = bodies.iter().flat_map(|b| {
        let forces = b.forces.iter().map(|f| (f.kind.as_str(), &f.name, f.power));
        forces.chain(b.couples.iter().map(|c| (c.kind.as_str(), &c.name, c.power)))
    });
    for (kind, name, power) in all {
        match kind {
            "reaction" => reactions += power,
            _ => *actions.entry(name.clone()).or_default() += power,
        }
    }
    let total = actions.values().sum::<f64>() + reactions;
    wire::VirtualPower { actions, reactions, total }
}
