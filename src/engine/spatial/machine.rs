//! A spatial 1-DOF mechanism seen from its input, as
//! [`crate::engine::machine`] sees a planar one (Zhukovsky). With v(φ) and
//! a(φ) the bodies' velocities and accelerations at unit input speed and
//! no input acceleration:
//!
//! ```text
//! I*      = Σ m·|ṙ|² + ωᵀ·J·ω                      (2T at φ̇ = 1)
//! dI*/dφ  = 2 Σ m·ṙ·r̈ + ω·(J·α + ω × J·ω)          (ω·(ω × J·ω) = 0)
//! M*      = Σ Q(q, v·ω̄)·v                          (the loads' power per unit input speed)
//! ```
//!
//! dI*/dφ is d(2T)/dt at φ̇ = 1: d(ωᵀJω)/dt = 2ωᵀJα, since J̇ = [ω×]J − J[ω×]
//! adds ωᵀ[ω×]Jω − ωᵀJ[ω×]ω = 0. ω̄ is the mean speed (for dampers).
//! Every evaluation assembles the mechanism by Newton's method from the
//! nearest of a ring of anchor poses, so the flywheel's quadrature and
//! root finding see the true functions.

use super::kinematics::{Motion, assemble, motion, sweep};
use super::kinetostatics::{applied, inertia};
use super::mobility::mobility;
use super::model::{LoadLaw, Mechanism, Pose};
use crate::engine::machine::{Anchor, Last, Reduced, Reduces, jumps, remembered};
use crate::engine::{Deadline, EngineError};
use std::sync::Mutex;

/// Anchor poses per period.
const ANCHORS: usize = 360;

/// A driven 1-DOF spatial mechanism (its one input a rotation) with its
/// loads, reduced to the input's angle φ.
#[derive(Debug)]
pub struct SpatialMachine {
    mechanism: Mechanism,
    loads: Vec<LoadLaw>,
    /// ω̄, the input's speed for velocity-dependent loads (dampers).
    speed: f64,
    period: f64,
    /// φ as drawn: the engine's input coordinate is φ − reference.
    reference: f64,
    /// The motion at unit speed at φ = period·k/ANCHORS.
    anchors: Vec<Motion>,
    last: Last,
    deadline: Deadline,
}

impl SpatialMachine {
    /// Assembles `mechanism` (one input) around one period of φ, from the
    /// anchor nearest the drawing (φ = `reference`) once round the period.
    pub fn new(
        mechanism: Mechanism,
        loads: Vec<LoadLaw>,
        (speed, period, reference): (f64, f64, f64),
        deadline: Deadline,
    ) -> Result<Self, EngineError> {
        let dof = mobility(&mechanism, &Pose::drawn(&mechanism))?.dof;
        if dof != 1 || mechanism.inputs.len() != 1 {
            return Err(EngineError::DofMismatch { dof, inputs: mechanism.inputs.len() });
        }
        let first = ((reference / period * ANCHORS as f64).round() as i64).rem_euclid(ANCHORS as i64) as usize;
        let order: Vec<usize> = (first..first + ANCHORS).collect();
        let steps: Vec<Vec<[f64; 3]>> = order.iter().map(|&k| vec![[angle(k, period) - reference, 1.0, 0.0]]).collect();
        let swept = sweep(&mechanism, &steps, &deadline).map_err(|e| match e {
            EngineError::Singular { input, .. } => EngineError::SingularCycle { input: input + reference, count: 1 },
            other => other,
        })?;
        let mut anchors: Vec<Option<Motion>> = vec![None; ANCHORS];
        for (k, m) in order.iter().zip(swept) {
            anchors[k % ANCHORS] = Some(m);
        }
        let anchors: Vec<Motion> = anchors.into_iter().flatten().collect();
        let placed: Vec<Anchor> =
            anchors.iter().enumerate().map(|(k, m)| centres(&mechanism, angle(k, period), m)).collect();
        let passed = vec![true; ANCHORS];
        let impassable = jumps(&placed, &passed, (3 * mechanism.n(), mechanism.size()), |_| false);
        if let Some(&input) = impassable.first() {
            return Err(EngineError::SingularCycle { input, count: impassable.len() });
        }
        Ok(Self { mechanism, loads, speed, period, reference, anchors, last: Mutex::new(None), deadline })
    }

    /// The motion at unit input speed at φ (taken within the period), None
    /// where the mechanism cannot be assembled there; and φ within the period.
    fn assembled(&self, phi: f64) -> Option<(Motion, f64)> {
        let u = phi.rem_euclid(self.period);
        let k = ((u / self.period * ANCHORS as f64).round() as usize) % ANCHORS;
        let near = &self.anchors[k];
        let mut d = u - angle(k, self.period);
        if d > self.period / 2.0 {
            d -= self.period;
        }
        let mut start = near.pose.clone();
        let delta: Vec<f64> = (0..near.v.len()).map(|i| near.v[i] * d + 0.5 * near.a[i] * d * d).collect();
        start.apply(&delta);
        // The input counted on from the anchor's (past a full turn just
        // below it): the same pose, and Newton starts next to it.
        let unit = [[angle(k, self.period) + d - self.reference, 1.0, 0.0]];
        let (pose, _) = assemble(&self.mechanism, &unit, &start, 0).ok()?;
        Some((motion(&self.mechanism, pose, &unit, 0).ok()?, u))
    }

    fn reduced(&self, phi: f64) -> Option<[f64; 3]> {
        let (now, u) = self.assembled(phi)?;
        let m = &self.mechanism;
        let inertia_star = 2.0 * super::kinetic(m, &now.pose, &now.v);
        let slope = 2.0 * now.v.dot(&inertia(m, &now));
        let loads: Vec<_> = self.loads.iter().map(|l| l.at(u, [self.speed, 0.0])).collect();
        let torque = applied(m, &loads, &now.pose, &(&now.v * self.speed)).dot(&now.v);
        Some([inertia_star, slope, torque])
    }
}

impl Reduces for SpatialMachine {
    fn eval(&self, phi: f64, what: Reduced) -> f64 {
        if self.deadline.expired() {
            return f64::NAN;
        }
        remembered(&self.last, phi, what, || self.reduced(phi))
    }

    fn breakpoints(&self) -> Vec<f64> {
        let functions = self.loads.iter().filter_map(|l| match l {
            LoadLaw::Force { magnitude: f, .. } | LoadLaw::Torque { value: f, .. } => Some(f),
            LoadLaw::Fixed(_) => None,
        });
        functions.flat_map(|f| f.breakpoints(self.period)).collect()
    }
}

/// φ at anchor k (k may pass a period: the input counted on).
fn angle(k: usize, period: f64) -> f64 {
    period * k as f64 / ANCHORS as f64
}

/// The bodies' centres and their rates at an anchor, for [`jumps`].
fn centres(m: &Mechanism, phi: f64, motion: &Motion) -> Anchor {
    let q = (1..=m.n()).flat_map(|b| motion.pose.origin(b).iter().copied().collect::<Vec<_>>()).collect();
    let g = (0..m.n()).flat_map(|b| (0..3).map(move |c| 6 * b + c)).map(|i| motion.v[i]).collect();
    Anchor { phi, q, g, h: Vec::new() }
}

#[cfg(test)]
mod tests;
