//! The least size of a dynamics result, known before it is computed: its
//! `samples` instants, each at least as long as the same instant with every
//! number zero (a number is never shorter than `0.0`), the mechanism's
//! names and every joint's reaction written out. A run whose least size is
//! over the limit on a result is refused at once, saying how many samples
//! would fit, as kinetostatics refuses from its first steps; one that may
//! fit is computed, and refused after if it does not.
//!
//! A mechanism with a contact joint is not sized so: its run may stop
//! where the contact opens, with fewer samples than asked.

use super::machine::{Report, sample};
use super::request::Problem;
use super::result::SampleDto;
use crate::engine::dynamics::mechanism::{MechanismProblem, MechanismSample};
use crate::engine::kinetostatics::{Energy, Reaction};
use crate::engine::model::JointKind;
use crate::kind::problem::ApiError;
use crate::kind::{Rows, SizeBy, json_len, too_large};
use crate::kinds::mechanism::Names;

/// `Err`, the 422 of a result too large, where even the least size of the
/// result of `problem` is over `limit` bytes.
pub(super) fn refuse_if_it_cannot_fit(problem: &Problem, limit: usize) -> Result<(), ApiError> {
    let (each, samples) = match problem {
        Problem::Reduced(p) => (least_sample(), p.samples),
        Problem::Machine(p, report) if !has_contact(p) => (least_sample() + least_machine_sample(p, report), p.samples),
        Problem::Machine(..) | Problem::Spatial(..) => return Ok(()),
    };
    // Each sample and its comma, in `samples` and in `machine.samples`.
    let least = (each + 2).saturating_mul(samples);
    if least <= limit {
        return Ok(());
    }
    let rows = Rows { field: "/samples".into(), count: samples, also: "size-also-events" };
    Err(too_large(least, limit, Some(rows), SizeBy::AtLeast))
}

fn has_contact(p: &MechanismProblem) -> bool {
    p.mechanism.joints.iter().any(|j| matches!(j.kind, JointKind::Contact(_)))
}

/// A sample of the motion with every number zero.
fn least_sample() -> usize {
    json_len(&SampleDto { t: 0.0, angle: 0.0, speed: 0.0, acceleration: 0.0, energy_residual: 0.0 })
}

/// The mechanism at an instant with every number zero: each input, each
/// moving body's position and energy, each joint's reaction where asked.
fn least_machine_sample(p: &MechanismProblem, report: &Report) -> usize {
    let m = &p.mechanism;
    let moving = m.bodies.len().saturating_sub(1);
    let zero = |k: usize, j: &crate::engine::model::Joint| Reaction {
        joint: k,
        on: j.bodies[1],
        by: j.bodies[0],
        fx: 0.0,
        fy: 0.0,
        moment: 0.0,
        ends: None,
        determinate: true,
    };
    let reactions =
        if p.reactions { m.joints.iter().enumerate().map(|(k, j)| zero(k, j)).collect() } else { Vec::new() };
    let at_zero = MechanismSample {
        inputs: vec![[0.0; 3]; m.drivers.len()],
        poses: vec![[0.0; 3]; moving],
        reactions,
        contacts: Vec::new(),
        constraint_residual: 0.0,
        energy: Energy { bodies: vec![0.0; moving], kinetic: 0.0, gravity: 0.0, springs: 0.0 },
        motion: None,
    };
    let names = Names::new(&report.joint_names, &report.body_names);
    json_len(&sample(0.0, &at_zero, (&names, m, report)))
}
