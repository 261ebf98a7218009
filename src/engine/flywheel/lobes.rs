//! The textbook's approximate method: split the cycle where M*(φ) changes
//! sign, integrate each lobe (areas A_i), accumulate them (S_i) and take
//! ΔE = S_max − S_min with S₀ = 0 at φ = 0.

use super::cycle::{Cycle, Samples};
use crate::engine::numeric::quadrature::Integral;
use crate::engine::numeric::roots::{SignChange, scan_sign_changes, sign};

/// One lobe of M*: its work between two split points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Area {
    pub from: f64,
    pub to: f64,
    pub work: f64,
}

pub(crate) struct Lobes {
    pub crossings: Vec<f64>,
    pub areas: Vec<Area>,
    pub cumulative: Vec<f64>,
    /// ΔE and the split points where S is largest and smallest (0 counts, at φ = 0).
    pub energy_fluctuation: f64,
    pub phi_s_max: f64,
    pub phi_s_min: f64,
    pub quadrature: Integral,
}

/// Values of M* below this fraction of its largest magnitude count as zero.
pub(crate) const ZERO_FRACTION: f64 = 1e-13;

/// Angles in (0, period) where M* changes sign, jumps across zero included;
/// an interval where M* ≡ 0 joins the preceding lobe.
pub(crate) fn crossings(cycle: &Cycle, samples: &Samples) -> Vec<f64> {
    let zero = ZERO_FRACTION * samples.max_abs_torque;
    let mut current = 0.0;
    let mut out: Vec<SignChange> = Vec::new();
    for (k, (xs, ys)) in samples.pieces.iter().enumerate() {
        let first = sign(ys[0], zero);
        if k > 0 && current != 0.0 && first != 0.0 && first != current {
            out.push(SignChange { at: xs[0], sign_after: first });
            current = first;
        }
        let anchor = 0.5 * (xs[0] + xs[xs.len() - 1]);
        let mut f = |x: f64| cycle.torque_frozen(x, anchor);
        scan_sign_changes(&mut f, xs, ys, zero, &mut current, &mut out);
    }
    let eps = 1e-12 * cycle.period;
    let mut at: Vec<f64> = out.iter().map(|c| c.at).filter(|&x| x > eps && x < cycle.period - eps).collect();
    at.dedup_by(|a, b| (*a - *b).abs() <= eps);
    at
}

pub(crate) fn lobes(cycle: &Cycle, crossings: Vec<f64>) -> Lobes {
    let mut splits = crossings.clone();
    splits.push(cycle.period);
    let (w, quadrature) = cycle.work_at(&splits);
    let mut from = 0.0;
    let mut prev = 0.0;
    let areas = splits
        .iter()
        .zip(&w)
        .map(|(&to, &s)| {
            let a = Area { from, to, work: s - prev };
            (from, prev) = (to, s);
            a
        })
        .collect();
    let (mut s_max, mut s_min, mut phi_s_max, mut phi_s_min) = (0.0, 0.0, 0.0, 0.0);
    for (&phi, &s) in splits.iter().zip(&w) {
        if s > s_max {
            (s_max, phi_s_max) = (s, phi);
        }
        if s < s_min {
            (s_min, phi_s_min) = (s, phi);
        }
    }
    Lobes { crossings, areas, cumulative: w, energy_fluctuation: s_max - s_min, phi_s_max, phi_s_min, quadrature }
}
