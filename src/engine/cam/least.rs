//! The least base radius in closed form: where the follower allows it, a
//! size's condition at one cam angle is a bound on one quantity of the
//! cam (the base radius, or a function of it), and the least base radius
//! is the largest of those bounds over the turn — a maximum of a formula
//! in s, s′ and s″, scanned by pieces and refined at its arg-max
//! ([`extremes::largest`]), not a search over whole turns.
//!
//! Symbols (besides those of [`super::design`]): φ_a the largest pressure
//! angle allowed and k = tan φ_a; ρ_a the least radius of curvature
//! allowed (0 where none is asked: no undercut).
//! - A translating roller (a knife, r_r = 0): tan φ = (s′ + e)/(d₀ + s),
//!   so |φ| ≤ φ_a wherever d₀ ≥ g(θ) = |s′ + e|/k − s; d₀ = max g, R_p =
//!   √(d₀² + e²), R_b = R_p − r_r.
//! - A translating flat face: φ = 0, and its radius of curvature R_b + s +
//!   s″ ≥ ρ_a wherever R_b ≥ ρ_a − s − s″: R_b = max(ρ_a − s − s″).
//! - An oscillating roller: with u = ∂P/∂s/L, tan φ = (L(1 + σs′) − a cos ψ)
//!   /(a sin ψ), σ = +1 counter-clockwise and −1 clockwise (the arm turns
//!   with the cam or against it); with c = L(1 + σs′)/a, γ = atan k,
//!   m = √(1 + k²) and α = acos(c/m), |φ| ≤ φ_a holds for ψ in
//!   [|α − γ|, min(α + γ, 2π − α − γ)] (none where |c| > m), so
//!   ψ₀ = ψ − s ≥ max(|α − γ| − s) and R_p² = a² + L² − 2aL cos ψ₀ grows
//!   with ψ₀.
//! - An oscillating flat face, or a roller's radius of curvature: no such
//!   bound (the pitch curve's curvature is not monotone in one quantity at
//!   an angle): [`Least::Search`], the caller's search over radii.
//!
//! The roller's radius found for its pressure angle may still undercut, or
//! miss ρ_a: the caller tests the cam at it and searches above it where it
//! does ([`Least::Base`] is a lower bound that is met by construction for
//! the pressure angle only).

use super::design::{Cam, Follower, Guide, Lift};
use super::extremes;
use std::f64::consts::{PI, TAU};

/// Scan parts per piece of the motion for the bounds' maxima: each bound is
/// smooth on a piece and a coarse scan finds its humps; a narrower hump
/// missed is caught by the caller's test of the cam at the radius found.
const PER_PIECE: usize = 24;

/// How far above the bound the radius returned is (relative): the bound
/// met to rounding, not a hair under it.
const MARGIN: f64 = 1e-13;

/// The largest of a function over the turn (NaN where it has no value).
type Most<'a> = &'a dyn Fn(&dyn Fn(f64) -> f64) -> f64;

/// What the closed form tells of the least base radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Least {
    /// This radius meets the bounds that have a closed form (the
    /// pressure angle; a flat face's curvature) and nothing less does.
    Base(f64),
    /// No base radius meets them (an oscillating arm that cannot reach any).
    Unmet,
    /// No closed form here: search upwards from this radius.
    Search(f64),
}

/// The least base radius of `cam` (its own `base` ignored) with `lift`
/// for a largest pressure angle `angle` (rad) and a least radius of
/// curvature `rho` (m), from the turn's pieces starting at `breaks`; `lo`
/// the least radius the follower can start from.
pub fn least_base(cam: &Cam, lift: Lift, breaks: &[f64], angle: Option<f64>, rho: Option<f64>, lo: f64) -> Least {
    let grid = extremes::pieces(breaks, PER_PIECE);
    let side = if cam.clockwise { -1.0 } else { 1.0 };
    let most = |f: &dyn Fn(f64) -> f64| extremes::largest(&|t| Some(f(t)), &grid).map_or(f64::NAN, |a| a.value);
    let raised = |x: f64| x + MARGIN * x.abs().max(f64::MIN_POSITIVE);
    match (cam.follower, cam.guide, angle) {
        (Follower::Flat, Guide::Translating { .. }, _) => {
            let rho = rho.unwrap_or(0.0).max(0.0);
            let least = most(&|t| {
                let [s, _, s2, _] = lift(t);
                rho - s - s2
            });
            Least::Base(raised(least.max(lo)))
        }
        (Follower::Roller(r), Guide::Translating { offset }, Some(phi)) => {
            let (k, e) = (phi.tan(), side * offset);
            let g = most(&|t| {
                let [s, s1, ..] = lift(t);
                (s1 + e).abs() / k - s
            });
            let d0 = raised(g.max((r * r - e * e).max(0.0).sqrt()));
            if d0.is_nan() || d0 <= 0.0 {
                return Least::Search(lo);
            }
            Least::Base((d0.hypot(e) - r).max(lo))
        }
        (Follower::Roller(r), Guide::Oscillating { pivot, arm }, Some(phi)) => {
            oscillating(lift, &most, phi, [pivot, arm, r, side], lo)
        }
        _ => Least::Search(lo),
    }
}

/// An oscillating roller's least base radius for |φ| ≤ `phi` ([module](self)):
/// pivot a, arm L, roller r_r.
fn oscillating(lift: Lift, most: Most, phi: f64, [a, l, r, side]: [f64; 4], lo: f64) -> Least {
    let (gamma, m) = (phi.tan().atan(), phi.tan().hypot(1.0));
    // ψ's interval at θ, [from, to], or None where no ψ meets the angle.
    let window = |t: f64| {
        let [s, s1, ..] = lift(t);
        let q = l * (1.0 + side * s1) / (a * m);
        if q.is_nan() || q.abs() > 1.0 {
            return None;
        }
        let alpha = q.acos();
        Some([(alpha - gamma).abs() - s, (alpha + gamma).min(TAU - alpha - gamma) - s])
    };
    let from = most(&|t| window(t).map_or(f64::INFINITY, |w| w[0]));
    let to = -most(&|t| window(t).map_or(f64::NEG_INFINITY, |w| -w[1]));
    let psi_lo = ((a * a + l * l - (lo + r).powi(2)) / (2.0 * a * l)).clamp(-1.0, 1.0).acos();
    let psi0 = from.max(psi_lo) * (1.0 + MARGIN);
    if to.is_nan() || psi0 > to || psi0 >= PI {
        return Least::Unmet;
    }
    Least::Base(((a * a + l * l - 2.0 * a * l * psi0.cos()).sqrt() - r).max(lo))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cam's own geometry ([`Cam::at`]: the pitch curve's normal, not
    /// the closed form) at `base`: its largest |φ| and least convex radius
    /// of curvature over the turn, scanned and refined.
    fn drawn(cam: &Cam, base: f64, lift: Lift, breaks: &[f64]) -> (f64, f64) {
        let e = extremes::of(&Cam { base, ..*cam }, lift, &extremes::scan(breaks));
        (e.max_pressure_angle.value, e.min_curvature_radius.map_or(f64::INFINITY, |a| a.value))
    }

    /// For every follower with a closed form, in either sense: at the
    /// radius found the cam's own geometry meets the bound to 1e-9 of it,
    /// and 1e-7 less misses it — the least radius, whatever the formula.
    #[test]
    fn the_closed_forms_radius_is_the_least_that_meets_the_bound() {
        let p = crate::engine::cam::sample::rise_dwell_fall();
        let lift = |t: f64| p.lift(t);
        let breaks = p.starts();
        let phi = 30f64.to_radians();
        let roller = |guide, clockwise| Cam { follower: Follower::Roller(0.01), guide, base: 0.0, clockwise };
        let translating = |offset| Guide::Translating { offset };
        let oscillating = Guide::Oscillating { pivot: 0.15, arm: 0.1 };
        for cam in [
            roller(translating(0.0), false),
            roller(translating(0.008), false),
            roller(translating(0.008), true),
            Cam { follower: Follower::Roller(0.0), ..roller(translating(-0.005), false) },
            roller(oscillating, false),
            roller(oscillating, true),
        ] {
            let Least::Base(base) = least_base(&cam, &lift, &breaks, Some(phi), None, 0.0) else {
                panic!("{cam:?}: no closed form")
            };
            let (at, below) = (drawn(&cam, base, &lift, &breaks).0, drawn(&cam, base * (1.0 - 1e-7), &lift, &breaks).0);
            assert!((at - phi).abs() < 1e-9 * phi && at <= phi, "{cam:?}: {} at {base}", at.to_degrees());
            assert!(below > phi, "{cam:?}: {} below {base}", below.to_degrees());
        }
        for rho in [0.0, 0.015] {
            let flat = Cam { follower: Follower::Flat, guide: translating(0.004), base: 0.0, clockwise: false };
            let Least::Base(base) = least_base(&flat, &lift, &breaks, None, Some(rho), 0.0) else { panic!() };
            let (at, below) = (drawn(&flat, base, &lift, &breaks).1, drawn(&flat, base - 1e-9, &lift, &breaks).1);
            assert!((at - rho).abs() < 1e-12 && at >= rho, "ρ {at} at {base} for {rho}");
            assert!(below < rho);
        }
    }

    /// The trial's swing (pivot 120 mm, arm 90 mm, roller 10 mm; a
    /// cycloidal rise of 20° over 120°, a dwell of 60°, a harmonic fall
    /// over 90°): its rise and fall differ, so each sense has its own
    /// radius, each the least that meets 24° and 30° (the closed form had
    /// taken the counter-clockwise radius for both: 55.4 mm for 24°, where
    /// 53.7 mm meets it clockwise).
    #[test]
    fn an_oscillating_roller_is_sized_for_its_own_sense() {
        let seg = |law, start: f64, span: f64, from, to| crate::engine::cam::Segment {
            law,
            start: start.to_radians(),
            span: span.to_radians(),
            from,
            to,
        };
        let h = 20f64.to_radians();
        let p = crate::engine::cam::Program::new(vec![
            seg(crate::engine::cam::Law::Cycloidal, 0.0, 120.0, 0.0, h),
            seg(crate::engine::cam::Law::Dwell, 120.0, 60.0, h, h),
            seg(crate::engine::cam::Law::Harmonic, 180.0, 90.0, h, 0.0),
            seg(crate::engine::cam::Law::Dwell, 270.0, 90.0, 0.0, 0.0),
        ])
        .expect("a turn");
        let (lift, breaks) = (|t: f64| p.lift(t), p.starts());
        for phi in [24f64.to_radians(), 30f64.to_radians()] {
            let radii = [false, true].map(|clockwise| {
                let cam = Cam {
                    follower: Follower::Roller(0.01),
                    guide: Guide::Oscillating { pivot: 0.12, arm: 0.09 },
                    base: 0.0,
                    clockwise,
                };
                let found = least_base(&cam, &lift, &breaks, Some(phi), None, 0.02);
                let Least::Base(base) = found else { panic!("{found:?}") };
                let (at, below) =
                    (drawn(&cam, base, &lift, &breaks).0, drawn(&cam, base * (1.0 - 1e-7), &lift, &breaks).0);
                assert!((at - phi).abs() < 1e-9 * phi && at <= phi, "{cam:?}: {} at {base}", at.to_degrees());
                assert!(below > phi, "{cam:?}: {} below {base}", below.to_degrees());
                base
            });
            assert!((radii[0] - radii[1]).abs() > 1e-3, "{radii:?}");
        }
    }

    /// The peer's case (a 10 mm roller, no offset, 30°): 25.0188906006 mm,
    /// the radius Brent's method found on the excess of the whole turn
    /// scanned and refined (docs/BENCHMARKS.md, issue 48), to 1e-12 m; the
    /// peer `mechanism` prints 25.018888 mm on its own grid.
    #[test]
    fn the_peers_roller_has_the_searched_radius() {
        let p = crate::engine::cam::sample::rise_dwell_fall();
        let lift = |t: f64| p.lift(t);
        let breaks = p.starts();
        let cam = crate::engine::cam::sample::roller();
        let found = least_base(&cam, &lift, &breaks, Some(30f64.to_radians()), None, 0.0);
        let Least::Base(base) = found else { panic!("{found:?}") };
        assert!((base - 0.0250188906006).abs() < 1e-12, "{base}");
    }

    /// An arm too short for the angle anywhere: none (|c| > m at the rise).
    #[test]
    fn an_oscillating_roller_that_no_radius_serves_is_unmet() {
        let p = crate::engine::cam::sample::rise_dwell_fall();
        let lift = |t: f64| {
            let s = p.eval(t);
            [s[0] * 40.0, s[1] * 40.0, s[2] * 40.0, s[3] * 40.0]
        };
        let breaks = p.starts();
        let cam = Cam {
            follower: Follower::Roller(0.01),
            guide: Guide::Oscillating { pivot: 0.15, arm: 0.1 },
            base: 0.0,
            clockwise: false,
        };
        let phi = 10f64.to_radians();
        assert_eq!(least_base(&cam, &lift, &breaks, Some(phi), None, 0.0), Least::Unmet);
        // The cam's own geometry agrees: every radius the arm can start from (0.04 to 0.24 m) exceeds it.
        for k in 1..50 {
            let base = 0.04 + 0.2 * k as f64 / 50.0;
            assert!(drawn(&cam, base, &lift, &breaks).0 > phi, "{base}");
        }
    }
}
