//! Adaptive Gauss–Kronrod (7–15) quadrature with QUADPACK's error estimate.
//!
//! Written here rather than taken from a crate: the flywheel splits every
//! integral at the load's breakpoints itself and needs the error estimate and
//! the evaluation count back (see ARCHITECTURE.md).

/// An integral with its estimated absolute error and the work it took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Integral {
    pub value: f64,
    pub error: f64,
    pub evaluations: usize,
}

impl std::ops::AddAssign for Integral {
    fn add_assign(&mut self, o: Self) {
        self.value += o.value;
        self.error += o.error;
        self.evaluations += o.evaluations;
    }
}

const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights for the nodes XGK[1], XGK[3], XGK[5], XGK[7].
const WG: [f64; 4] =
    [0.129_484_966_168_869_7, 0.279_705_391_489_276_7, 0.381_830_050_505_118_9, 0.417_959_183_673_469_4];

/// Kronrod 15-point value and QUADPACK error estimate on [a, b].
fn gk15(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut k = WGK[7] * fc;
    let mut g = WG[3] * fc;
    let mut fv = [(0.0, 0.0); 7];
    for (j, x) in XGK[..7].iter().enumerate() {
        let (f1, f2) = (f(c - h * x), f(c + h * x));
        fv[j] = (f1, f2);
        k += WGK[j] * (f1 + f2);
        if j % 2 == 1 {
            g += WG[j / 2] * (f1 + f2);
        }
    }
    let mean = 0.5 * k;
    let mut asc = WGK[7] * (fc - mean).abs();
    for (j, (f1, f2)) in fv.iter().enumerate() {
        asc += WGK[j] * ((f1 - mean).abs() + (f2 - mean).abs());
    }
    let (k, asc) = (k * h, asc * h.abs());
    let mut err = (k - g * h).abs();
    if asc != 0.0 && err != 0.0 {
        err = asc * (200.0 * err / asc).powf(1.5).min(1.0);
    }
    (k, err.max(roundoff(k)))
}

/// The error below which a panel cannot be refined: rounding in its 15 terms.
fn roundoff(value: f64) -> f64 {
    50.0 * f64::EPSILON * value.abs()
}

/// ∫ₐᵇ f dx to `abs_tol` (absolute) or `rel_tol` (relative), whichever is
/// looser, bisecting the worst interval first; stops after `max_evaluations`,
/// or when even the worst interval is down to its rounding error (a tolerance
/// below what double precision can give), and then reports the error it reached.
pub fn integrate(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    abs_tol: f64,
    rel_tol: f64,
    max_evaluations: usize,
) -> Integral {
    if a == b {
        return Integral::default();
    }
    let (v, e) = gk15(&mut f, a, b);
    let mut parts = vec![(a, b, v, e)];
    let mut evaluations = 15;
    loop {
        let value: f64 = parts.iter().map(|p| p.2).sum();
        let error: f64 = parts.iter().map(|p| p.3).sum();
        let done = error <= abs_tol.max(rel_tol * value.abs()) || !error.is_finite();
        let worst = (0..parts.len()).max_by(|&i, &j| parts[i].3.total_cmp(&parts[j].3));
        let width = worst.map_or(0.0, |w| (parts[w].1 - parts[w].0).abs());
        let at_roundoff = worst.is_none_or(|w| parts[w].3 <= roundoff(parts[w].2));
        if done || at_roundoff || evaluations + 30 > max_evaluations || width < 1e-13 * (b - a).abs() {
            return Integral { value, error, evaluations };
        }
        let (lo, hi, _, _) = parts.swap_remove(worst.unwrap_or(0));
        let mid = 0.5 * (lo + hi);
        let (v1, e1) = gk15(&mut f, lo, mid);
        let (v2, e2) = gk15(&mut f, mid, hi);
        parts.push((lo, mid, v1, e1));
        parts.push((mid, hi, v2, e2));
        evaluations += 30;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn low_degree_polynomials_are_exact_in_one_panel() {
        // G7 and K15 both integrate degree 13 exactly, so one panel is accepted: ∫₀¹ x¹³ dx = 1/14.
        let r = integrate(|x| x.powi(13), 0.0, 1.0, 1e-15, 1e-15, 10_000);
        assert!((r.value - 1.0 / 14.0).abs() < 1e-16);
        assert_eq!(r.evaluations, 15);
        // K15 alone is exact to degree 22: ∫₀¹ x²² dx = 1/23 however the panels are split.
        let r = integrate(|x| x.powi(22), 0.0, 1.0, 1e-15, 1e-15, 10_000);
        assert!((r.value - 1.0 / 23.0).abs() < 1e-16);
    }

    #[test]
    fn smooth_and_kinked_integrands_reach_the_tolerance() {
        // ∫₀^π sin = 2 (closed form).
        let r = integrate(f64::sin, 0.0, std::f64::consts::PI, 0.0, 1e-12, 10_000);
        assert!((r.value - 2.0).abs() < 1e-13, "{r:?}");
        // ∫₋₁¹ |x| dx = 1: a kink inside forces subdivision.
        let r = integrate(f64::abs, -1.0, 1.0 + 1e-9, 0.0, 1e-10, 100_000);
        assert!((r.value - (1.0 + 1e-9 + 0.5e-18)).abs() < 1e-9, "{r:?}");
        assert!(r.error >= (r.value - 1.0 - 1e-9).abs() * 0.1);
    }

    #[test]
    fn reversed_limits_change_the_sign() {
        let r = integrate(|x| x * x, 1.0, 0.0, 0.0, 1e-12, 1000);
        assert!((r.value + 1.0 / 3.0).abs() < 1e-15);
    }

    /// A tolerance below double precision's reach (here 1e-16 relative) stops
    /// once every panel is down to its rounding error, instead of bisecting
    /// until the evaluation cap: ∫₀^π 5 sin² = 5π/2 (closed form).
    #[test]
    fn a_tolerance_below_roundoff_stops_at_roundoff() {
        let r = integrate(|x| 5.0 * x.sin().powi(2), 0.0, std::f64::consts::PI, 0.0, 1e-16, 200_000);
        assert!((r.value - 2.5 * std::f64::consts::PI).abs() < 1e-14, "{r:?}");
        assert!(r.evaluations < 1_000, "{r:?}");
        assert!(r.error <= 1e-13, "{r:?}");
    }
}
