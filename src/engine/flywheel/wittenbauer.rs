//! The exact flywheel (Wittenbauer). With z = (ω/ω_a)², κ = 2/ω_a² and
//! F(φ) = κ·W(φ), the energy equation gives z(φ) = (F(φ) + C)/(I + I*(φ)).
//! Requiring max z = a = (1 + ε/2)² and min z = b = (1 − ε/2)²:
//!
//! ```text
//! C = min_φ [a(I + I*) − F] = max_φ [b(I + I*) − F]
//! I = (max_φ [b I* − F] − min_φ [a I* − F]) / (a − b)
//! ```
//!
//! I enters only linearly, so the two extrema are taken once: at the ends of
//! the smooth pieces (both sides) and at the stationary points
//! a·I*'(φ) = κ·M*(φ), resp. b·I*'(φ) = κ·M*(φ). With I* constant they are
//! the extrema of W, already known from the lobes (closed form).

use super::cycle::{Cycle, Samples};
use super::lobes::{Lobes, ZERO_FRACTION};
use crate::engine::function::Side;
use crate::engine::numeric::quadrature::Integral;
use crate::engine::numeric::roots::{SignChange, scan_sign_changes};

pub(crate) struct Exact {
    pub inertia: f64,
    /// The constant C of z(φ) = (F(φ) + C)/(I + I*(φ)).
    pub c: f64,
    pub phi_omega_max: f64,
    pub phi_omega_min: f64,
    /// I + I* vanishes somewhere (M* ≡ 0 with I* constant): the speed is
    /// constant for any inertia and z is undefined.
    pub degenerate: bool,
    pub quadrature: Integral,
}

/// A candidate extremum: angle, side, and W there.
struct Candidate {
    phi: f64,
    side: Side,
    work: f64,
}

pub(crate) fn exact(cycle: &Cycle, samples: &Samples, lobes: &Lobes, eps: f64, omega_a: f64) -> Exact {
    let (a, b) = ((1.0 + eps / 2.0).powi(2), (1.0 - eps / 2.0).powi(2));
    let kappa = 2.0 / (omega_a * omega_a);
    let (candidates, quadrature) = match cycle.inertia.constant() {
        Some(_) => (
            vec![
                Candidate { phi: lobes.phi_s_max, side: Side::Right, work: s_at(lobes, lobes.phi_s_max) },
                Candidate { phi: lobes.phi_s_min, side: Side::Right, work: s_at(lobes, lobes.phi_s_min) },
            ],
            Integral::default(),
        ),
        None => general_candidates(cycle, samples, kappa, [a, b]),
    };
    let h = |k: f64, c: &Candidate| k * cycle.inertia_at(c.phi, c.side) - kappa * c.work;
    let arg = |k: f64, better: fn(f64, f64) -> bool| {
        candidates.iter().fold(&candidates[0], |best, c| if better(h(k, c), h(k, best)) { c } else { best })
    };
    let (at_max, at_min) = (arg(a, |x, y| x < y), arg(b, |x, y| x > y));
    let inertia = (h(b, at_min) - h(a, at_max)) / (a - b);
    let c = a * inertia + h(a, at_max);
    let scale = inertia.abs() + candidates.iter().map(|c| cycle.inertia_at(c.phi, c.side).abs()).fold(0.0, f64::max);
    let lowest_total =
        candidates.iter().map(|c| inertia + cycle.inertia_at(c.phi, c.side)).fold(f64::INFINITY, f64::min);
    Exact {
        inertia,
        c,
        phi_omega_max: at_max.phi,
        phi_omega_min: at_min.phi,
        degenerate: lowest_total <= 1e-12 * scale.max(f64::MIN_POSITIVE),
        quadrature,
    }
}

/// S at a split point (0 at φ = 0).
fn s_at(lobes: &Lobes, phi: f64) -> f64 {
    lobes.areas.iter().zip(&lobes.cumulative).find(|(a, _)| a.to == phi).map_or(0.0, |(_, s)| *s)
}

/// Piece ends (both sides) and the stationary points of k·I* − κW for k = a, b.
fn general_candidates(cycle: &Cycle, samples: &Samples, kappa: f64, ks: [f64; 2]) -> (Vec<Candidate>, Integral) {
    let mut at: Vec<(f64, Side)> = Vec::new();
    for &p in &cycle.pieces {
        if p > 0.0 {
            at.push((p, Side::Left));
        }
        if p < cycle.period {
            at.push((p, Side::Right));
        }
    }
    let zero = ZERO_FRACTION * kappa * samples.max_abs_torque;
    for k in ks {
        for ((xs, ms), slopes) in samples.pieces.iter().zip(&samples.slopes) {
            let anchor = 0.5 * (xs[0] + xs[xs.len() - 1]);
            let slope = cycle.inertia_slope.as_ref();
            let mut g =
                |x: f64| k * slope.map_or(0.0, |s| s.eval_frozen(x, anchor)) - kappa * cycle.torque_frozen(x, anchor);
            // The samples' one-sided values are the piece's own formula at its ends.
            let gs: Vec<f64> =
                ms.iter().enumerate().map(|(j, &m)| k * slopes.get(j).copied().unwrap_or(0.0) - kappa * m).collect();
            let (mut current, mut out) = (0.0, Vec::<SignChange>::new());
            scan_sign_changes(&mut g, xs, &gs, zero, &mut current, &mut out);
            at.extend(out.iter().map(|c| (c.at, Side::Right)));
        }
    }
    at.sort_by(|x, y| x.0.total_cmp(&y.0));
    let phis: Vec<f64> = at.iter().map(|c| c.0).collect();
    let (works, quadrature) = cycle.work_at(&phis);
    let candidates = at.iter().zip(works).map(|(&(phi, side), work)| Candidate { phi, side, work }).collect();
    (candidates, quadrature)
}
