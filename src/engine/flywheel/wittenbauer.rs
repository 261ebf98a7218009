//! The exact flywheel (Wittenbauer). With z = (ω/ω_a)², κ = 2/ω_a² and
//! F(φ) = κ·W(φ), the energy equation gives z(φ) = (F(φ) + C)/(I + I*(φ)).
//! Requiring max z = a = (1 + ε/2)² and min z = b = (1 − ε/2)²:
//!
//! ```text
//! C = min_φ [a(I + I*) − F] = max_φ [b(I + I*) − F]
//! I = (max_φ [b I* − F] − min_φ [a I* − F]) / (a − b)
//! ```
//!
//! With a = 1 + d_a and b = 1 − d_b (d_a = ε + ε²/4, d_b = ε − ε²/4, so
//! a − b = 2ε exactly), each k·I* − κW is formed as (I* − κW) + d·I*: a
//! and b themselves would carry a rounding of 1e-16 into a − b, 5e-5 of
//! it at ε = 1e-12. What rounding is left — each I* − κW known to about
//! 1e-16 of its terms — and the works' quadrature error E (J), over the
//! numerator's size 2ε(|I| + |I*|), bound the relative error of I (of
//! I + I* where I is near 0): `rounding` + `per_joule`·E.
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
    /// I's relative error from rounding, and per joule of the works'
    /// quadrature error (see the module's notes).
    pub rounding: f64,
    pub per_joule: f64,
}

/// A candidate extremum: angle, side, and W there.
struct Candidate {
    phi: f64,
    side: Side,
    work: f64,
}

pub(crate) fn exact(cycle: &Cycle, samples: &Samples, lobes: &Lobes, eps: f64, omega_a: f64) -> Exact {
    let (da, db) = (eps + eps * eps / 4.0, eps - eps * eps / 4.0);
    let kappa = 2.0 / (omega_a * omega_a);
    let (candidates, quadrature) = match cycle.inertia.constant() {
        Some(_) => (
            vec![
                Candidate { phi: lobes.phi_s_max, side: Side::Right, work: s_at(lobes, lobes.phi_s_max) },
                Candidate { phi: lobes.phi_s_min, side: Side::Right, work: s_at(lobes, lobes.phi_s_min) },
            ],
            Integral::default(),
        ),
        None => general_candidates(cycle, samples, kappa, [1.0 + da, 1.0 - db]),
    };
    // k·I* − κW for k = 1 + d.
    let h = |d: f64, c: &Candidate| {
        let i = cycle.inertia_at(c.phi, c.side);
        (i - kappa * c.work) + d * i
    };
    let arg = |d: f64, better: fn(f64, f64) -> bool| {
        candidates.iter().fold(&candidates[0], |best, c| if better(h(d, c), h(d, best)) { c } else { best })
    };
    let (at_max, at_min) = (arg(da, |x, y| x < y), arg(-db, |x, y| x > y));
    let numerator = h(-db, at_min) - h(da, at_max);
    let inertia = numerator / (da + db);
    let c = (1.0 + da) * inertia + h(da, at_max);
    let size = |c: &Candidate| cycle.inertia_at(c.phi, c.side).abs() + (kappa * c.work).abs();
    let largest = cycle.inertia_at(at_min.phi, at_min.side).abs().max(cycle.inertia_at(at_max.phi, at_max.side).abs());
    let total = numerator.abs() + (da + db) * largest;
    let relative = |x: f64| if total > 0.0 { x / total } else { 0.0 };
    let (rounding, per_joule) = (relative(4.0 * f64::EPSILON * (size(at_min) + size(at_max))), relative(2.0 * kappa));
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
        rounding,
        per_joule,
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
