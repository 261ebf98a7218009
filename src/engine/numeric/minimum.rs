//! A function's least value on an interval by Brent's method (R. P. Brent,
//! *Algorithms for Minimization without Derivatives*, 1973, ch. 5: the
//! procedure `localmin`): a parabola through the three best points where
//! it steps inside the bracket and shrinks it fast enough, a golden-section
//! step where it does not. On a smooth minimum it converges superlinearly
//! — some ten evaluations where golden section alone takes fifty — and it
//! is never much slower than golden section on a kink.
//!
//! Symbols: [a, b] the bracket; x the best point so far, w the second
//! best, v the previous w; f_x, f_w, f_v their values; d the step taken
//! and e the one before the last (a parabola's step must be under half of
//! it); τ the tolerance on x.

/// (3 − √5)/2: the golden section's smaller part.
const C: f64 = 0.381_966_011_250_105_1;
/// Steps at most: a bracket shrinks at least by golden section every two
/// steps, so 200 takes any f64 bracket to its last bit.
const MOST: usize = 200;

/// The least of `f` on [a, b] from `x0` inside it, whose value `f0` is known:
/// (x, f(x)) with x within `tol` of the minimiser (absolute, > 0). A value
/// NaN or +∞ counts as larger than any other, so `f` may be undefined on
/// parts of the bracket; ties keep the point found first.
pub fn brent_min(mut f: impl FnMut(f64) -> f64, [mut a, mut b]: [f64; 2], x0: f64, f0: f64, tol: f64) -> (f64, f64) {
    let value = |y: f64| if y.is_nan() { f64::INFINITY } else { y };
    let (mut x, mut w, mut v) = (x0, x0, x0);
    let f0 = value(f0);
    let (mut fx, mut fw, mut fv) = (f0, f0, f0);
    let (mut d, mut e) = (0.0_f64, 0.0_f64);
    for _ in 0..MOST {
        let m = 0.5 * (a + b);
        let (tol1, tol2) = (tol, 2.0 * tol);
        if (x - m).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let parabola = (e.abs() > tol1).then(|| {
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let p = (x - v) * q - (x - w) * r;
            let q = 2.0 * (q - r);
            if q > 0.0 { (-p, q) } else { (p, -q) }
        });
        // The parabola's step where it is finite, inside the bracket and under half the step before last.
        let step = parabola.filter(|&(p, q)| p.abs() < (0.5 * q * e).abs() && p > q * (a - x) && p < q * (b - x));
        if let Some((p, q)) = step {
            e = d;
            d = p / q;
            if (x + d) - a < tol2 || b - (x + d) < tol2 {
                d = tol1.copysign(m - x);
            }
        } else {
            e = if x >= m { a - x } else { b - x };
            d = C * e;
        }
        let u = if d.abs() >= tol1 { x + d } else { x + tol1.copysign(d) };
        let fu = value(f(u));
        if fu <= fx && fu < f64::INFINITY {
            if u >= x {
                a = x
            } else {
                b = x
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u
            } else {
                b = u
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    (x, fx)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::numeric::roots::golden_min;

    /// A smooth minimum: cos on [2, 4] has its least at π, -1 (closed
    /// form), found to the tolerance in far fewer evaluations than golden
    /// section takes (its count is log(2/τ)/log(1.618) ≈ 40 for τ = 1e-8).
    #[test]
    fn a_smooth_minimum_is_found_in_few_evaluations() {
        let mut n = 0;
        let (x, fx) = brent_min(
            |t: f64| {
                n += 1;
                t.cos()
            },
            [2.0, 4.0],
            3.0,
            3f64.cos(),
            1e-8,
        );
        assert!((x - std::f64::consts::PI).abs() < 1e-8, "{x}");
        assert_eq!(fx, x.cos());
        assert!((fx + 1.0).abs() < 1e-15, "{fx}");
        assert!(n <= 12, "{n} evaluations");
    }

    /// A kink (|t − 0.3| + 1 on [0, 1]) and a minimum at the bracket's end
    /// (t² on [0.5, 2]): both to the tolerance, as golden section finds them.
    #[test]
    fn a_kink_and_an_end_are_found_as_golden_section_finds_them() {
        let kink = |t: f64| (t - 0.3).abs() + 1.0;
        let (x, _) = brent_min(kink, [0.0, 1.0], 0.5, kink(0.5), 1e-10);
        assert!((x - 0.3).abs() < 1e-9, "{x}");
        let (g, _) = golden_min(kink, 0.0, 1.0, 1e-10);
        assert!((x - g).abs() < 1e-9, "{x} against golden section's {g}");
        let (x, fx) = brent_min(|t| t * t, [0.5, 2.0], 1.0, 1.0, 1e-10);
        assert!((x - 0.5).abs() < 3e-10 && (fx - 0.25).abs() < 1e-9, "{x} {fx}");
    }

    /// Where f has no value (NaN, +∞) on part of the bracket, the least of
    /// the rest: (t − 1.5)² defined only on t > 1, bracket [0, 2], from 1.9.
    #[test]
    fn points_without_a_value_are_never_the_least() {
        let f = |t: f64| if t > 1.0 { (t - 1.5).powi(2) } else { f64::NAN };
        let (x, fx) = brent_min(f, [0.0, 2.0], 1.9, f(1.9), 1e-10);
        assert!((x - 1.5).abs() < 1e-9 && fx < 1e-17, "{x} {fx}");
        let g = |t: f64| if t > 1.0 { (t - 1.5).powi(2) } else { f64::INFINITY };
        let (x, _) = brent_min(g, [0.0, 2.0], 0.5, f64::INFINITY, 1e-10);
        assert!((x - 1.5).abs() < 1e-9, "{x}");
    }
}
