//! A spatial mechanism's free bodies in the notes' words (the notation of
//! [`crate::kind::solution`]): each action a force [fx, fy, fz] at a point
//! [x, y, z] or a couple (mx, my, moment about z), each body's six
//! equations. Space has no Assur groups to solve one by one: every body's
//! equations are solved together (Φ_qᵀ·λ = Q − M·a), one group.

use super::solution::{kind, pair, virtual_power};
use crate::engine::spatial::free_body::{Action, FreeBody};
use crate::engine::spatial::{Coordinate, Load, Mechanism};
use crate::kind::solution::{self as wire, Solution};
use std::collections::BTreeMap;

/// The free bodies in the notes' words; `free`: the inputs move freely (a
/// run's sample), so their equations give accelerations, not efforts.
pub fn written(
    m: &Mechanism,
    names: &[String],
    loads: &[Load],
    (step, input): (usize, &[f64]),
    bodies: &[FreeBody],
    free: bool,
) -> Solution {
    let notation = Notation { m, names, loads, free };
    let reactions = m.joints.iter().map(|j| format!("R{}", pair(j.bodies[0], j.bodies[1])));
    let efforts = (0..m.inputs.len()).map(|i| notation.driving(i));
    let group = wire::Group { bodies: names[1..].to_vec(), unknowns: reactions.chain(efforts).collect() };
    let written: Vec<wire::FreeBody> = bodies.iter().map(|fb| notation.free_body(fb)).collect();
    Solution {
        step,
        input: input.to_vec(),
        numbering: names.iter().enumerate().map(|(b, n)| (n.clone(), b + 1)).collect::<BTreeMap<_, _>>(),
        order: names[1..].to_vec(),
        groups: vec![group],
        virtual_power: virtual_power(&written),
        bodies: written,
    }
}

struct Notation<'a> {
    m: &'a Mechanism,
    names: &'a [String],
    loads: &'a [Load],
    free: bool,
}

impl Notation<'_> {
    /// Input i's effort, `M_m` (a rotation's couple) or `F_m` (a slide's
    /// force), numbered when there are several; a free input's acceleration.
    fn driving(&self, i: usize) -> String {
        let slide = self.m.inputs[i].coordinate == Coordinate::Slide;
        let n = if self.m.inputs.len() > 1 { format!("{}", i + 1) } else { String::new() };
        match (self.free, slide) {
            (true, true) => format!("ẍ{n}"),
            (true, false) => format!("φ̈{n}"),
            (false, true) => format!("F_m{n}"),
            (false, false) => format!("M_m{n}"),
        }
    }

    /// An action's name on body `on`: a force's (`R23`, `F_I3`) or a couple's (`M23`, `M_I3`).
    fn name(&self, action: Action, on: usize, couple: bool) -> String {
        let n = on + 1;
        let letter = if couple { "M" } else { "R" };
        match action {
            Action::Reaction { by, .. } => format!("{letter}{}", pair(by, on)),
            Action::Inertia => format!("{}_I{n}", if couple { "M" } else { "F" }),
            Action::Weight => format!("W{n}"),
            Action::Load(k) => match &self.loads[k] {
                Load::Force { .. } => format!("F{}", k + 1),
                Load::Torque { .. } => format!("M{}", k + 1),
                Load::Spring { .. } => format!("F_k{}", k + 1),
            },
            Action::Driving(i) => {
                let base = self.driving(i);
                match (couple, base.strip_prefix('F')) {
                    (true, Some(rest)) => format!("M{rest}"),
                    (false, _) if base.starts_with('M') => base.replacen('M', "F", 1),
                    _ => base,
                }
            }
        }
    }

    /// The body it comes from and the joint it acts through.
    fn source(&self, action: Action) -> (Option<String>, Option<String>) {
        match action {
            Action::Reaction { joint, by } => (Some(self.names[by].clone()), Some(self.m.joints[joint].name.clone())),
            Action::Driving(i) => (None, Some(self.m.joints[self.m.inputs[i].joint].name.clone())),
            _ => (None, None),
        }
    }

    fn free_body(&self, fb: &FreeBody) -> wire::FreeBody {
        let forces = fb.forces.iter().map(|f| {
            let (by, joint) = self.source(f.action);
            let (name, kind) = (self.name(f.action, fb.body, false), kind(f.action).into());
            let [fx, fy, fz] = [f.f.x, f.f.y, f.f.z];
            let power = fb.power(&f.at, &f.f);
            wire::Force { name, kind, by, joint, at: f.at.iter().copied().collect(), fx, fy, fz: Some(fz), power }
        });
        let couples = fb.couples.iter().map(|c| {
            let (by, joint) = self.source(c.action);
            let (name, kind) = (self.name(c.action, fb.body, true), kind(c.action).into());
            let power = c.moment.dot(&fb.omega);
            wire::Couple {
                name,
                kind,
                by,
                joint,
                moment: c.moment.z,
                mx: Some(c.moment.x),
                my: Some(c.moment.y),
                power,
            }
        });
        let [f, m] = fb.sums;
        wire::FreeBody {
            body: self.names[fb.body].clone(),
            number: fb.body + 1,
            cg: fb.cg.iter().copied().collect(),
            forces: forces.collect(),
            couples: couples.collect(),
            equations: wire::Equations {
                sum_fx: f.x,
                sum_fy: f.y,
                sum_moment_about_cg: m.z,
                sum_fz: Some(f.z),
                sum_mx_about_cg: Some(m.x),
                sum_my_about_cg: Some(m.y),
            },
        }
    }
}
