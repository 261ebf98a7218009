//! Rolling contacts with friction in direct dynamics ("grips"): each rolls
//! — its rolling row held — while |F_t| ≤ μN, and otherwise slips with
//! kinetic friction F_t = −μN·σ, σ the sign of the sliding velocity v_s.
//! While it slips its rolling row is left out of the equations and the
//! friction is applied along that row's gradient instead: the gradient
//! acts on the curve parameters, and reaches the bodies through the
//! contact's other rows exactly as the multiplier of the held row did (the
//! parameters carry no mass: the row's multiplier is the tangential force).
//! A force along the gradient with multiplier α gives the solution x₀ +
//! α·x₁ of the equations (x₁ that of a unit force): α is the one that makes
//! F_t + μσN = 0, one linear equation per slipping grip.
//!
//! Symbols as in [`crate::engine::kinetostatics::contacts`]: N and F_t the
//! normal and tangential force of the first body on the second (N > 0:
//! they press), v_s = (v₂ − v₁)·t. The contact's force is −λ of its two
//! coincidence rows (P₂ − P₁ = 0).

use crate::engine::constraints::joint_offsets;
use crate::engine::kinetostatics::Frame;
use crate::engine::model::{JointKind, Mechanism};
use nalgebra::{DMatrix, DVector};

/// How far past μN the force rolling needs may go and the grip still
/// rolls, relative to μN. At the limit itself rolling and slipping are the
/// same motion (kinetic friction supplies exactly what rolling needs), and
/// the rounding of F_t would otherwise switch the grip at every step: a
/// disk at exactly μ = tan α / 3 slipped and rolled 10 001 times at t = 0.
pub(crate) const ROLLING_TOLERANCE: f64 = 1e-9;

/// How a grip moves now.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Mode {
    Roll,
    /// Slipping, v_s of this sign (±1).
    Slip(f64),
}

/// A rolling contact with friction: its joint, the first of its rows (the
/// coincidence), its rolling row and μ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Grip {
    pub joint: usize,
    pub first_row: usize,
    pub roll_row: usize,
    pub mu: f64,
}

/// Every grip's mode, and the arc length its rolling row has moved while
/// it slipped (the row's offset once it rolls again).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Grips {
    pub modes: Vec<Mode>,
    pub slipped: Vec<f64>,
}

/// The grips of a mechanism: its rolling contacts with friction (rows:
/// coincidence 2, common tangent 1 — rolling needs both curves to have a
/// parameter — then rolling).
pub(crate) fn grips(m: &Mechanism) -> Vec<Grip> {
    let offsets = joint_offsets(m);
    let grip = |(k, j): (usize, &crate::engine::model::Joint)| {
        let JointKind::Contact(c) = &j.kind else { return None };
        let mu = j.friction.filter(|_| c.rolling)?.mu;
        Some(Grip { joint: k, first_row: offsets[k], roll_row: offsets[k] + 3, mu })
    };
    m.joints.iter().enumerate().filter_map(grip).collect()
}

/// The contacts that push and never pull other than the grips (which
/// guard their own normal force): (joint, the first of its rows) of every
/// contact that is not a particle threaded on its curve (held both ways).
pub(crate) fn one_sided(m: &Mechanism, grips: &[Grip]) -> Vec<(usize, usize)> {
    let offsets = joint_offsets(m);
    (m.joints.iter().enumerate())
        .filter(|(k, j)| matches!(&j.kind, JointKind::Contact(c) if !c.particle) && grips.iter().all(|g| g.joint != *k))
        .map(|(k, _)| (k, offsets[k]))
        .collect()
}

impl Grip {
    /// [N, F_t] from the multipliers of every joint row.
    pub fn parts(&self, frame: &Frame, lambda: &[f64]) -> [f64; 2] {
        frame.parts([-lambda[self.first_row], -lambda[self.first_row + 1]])
    }

    /// The grip's guards, each ≥ 0 while its mode holds: rolling
    /// μN(1 + [`ROLLING_TOLERANCE`]) − |F_t|, slipping σ·v_s; and N (the
    /// contact stays closed).
    pub fn guards(&self, mode: Mode, frame: &Frame, lambda: &[f64]) -> [f64; 2] {
        let [n, ft] = self.parts(frame, lambda);
        match mode {
            Mode::Roll => [self.mu * n * (1.0 + ROLLING_TOLERANCE) - ft.abs(), n],
            Mode::Slip(sigma) => [sigma * frame.sliding(), n],
        }
    }
}

/// The multipliers α of the friction forces along the slipping grips'
/// rolling rows: `slipping` holds each grip, its σ and frame; `lambda0`
/// the multipliers without friction and `units[j]` those of a unit force
/// along grip j's row alone (the equations' linear part). None where the
/// friction locks the motion (the equations for α are singular).
pub(crate) fn friction(slipping: &[(Grip, f64, Frame)], lambda0: &[f64], units: &[Vec<f64>]) -> Option<Vec<f64>> {
    let m = slipping.len();
    // F_t + μσN of grip i for multipliers λ.
    let law = |i: usize, lambda: &[f64]| {
        let (grip, sigma, frame) = &slipping[i];
        let [n, ft] = grip.parts(frame, lambda);
        ft + grip.mu * sigma * n
    };
    let a = DMatrix::from_fn(m, m, |i, j| law(i, &units[j]));
    let b = DVector::from_fn(m, |i, _| -law(i, lambda0));
    let alpha = a.lu().solve(&b)?;
    alpha.iter().all(|v| v.is_finite()).then(|| alpha.iter().copied().collect())
}
