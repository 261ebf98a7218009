//! Bracketed root finding (Brent) and sign-change scanning of a sampled function.

/// Brent's method on [a, b] with f(a)·f(b) ≤ 0; returns x with |bracket| ≤ xtol.
pub fn brent(mut f: impl FnMut(f64) -> f64, mut a: f64, mut b: f64, xtol: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, b, c) = (b, c, b);
            (fa, fb, fc) = (fb, fc, fb);
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return b;
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let (q0, r) = (fa / fc, fb / fc);
                (s * (2.0 * m * q0 * (q0 - r) - (b - a) * (r - 1.0)), (q0 - 1.0) * (r - 1.0) * (s - 1.0))
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
    }
    b
}

/// Golden-section search for the minimum of f on [a, b], to within `xtol`
/// or a few units in the last place of the bracket, whichever is larger: a
/// bracket cannot shrink below the spacing of the floating-point numbers
/// around it (the lobes' search asked 1e-12 of a bracket under 1e-3 rad
/// near φ = 6, where the doubles are 8.9e-16 apart, on a spline table of
/// 4 000 rows, and never ended).
pub fn golden_min(mut f: impl FnMut(f64) -> f64, mut a: f64, mut b: f64, xtol: f64) -> (f64, f64) {
    const R: f64 = 0.618_033_988_749_894_9;
    let tol = xtol.max(4.0 * f64::EPSILON * a.abs().max(b.abs()));
    let mut x1 = b - R * (b - a);
    let mut x2 = a + R * (b - a);
    let (mut f1, mut f2) = (f(x1), f(x2));
    // Each step keeps 0.618 of the bracket: 200 shrink it by 1e-42, more
    // than any search here needs, so the count only guards against a NaN.
    for _ in 0..200 {
        if (b - a).abs() <= tol {
            break;
        }
        if f1 < f2 {
            (b, x2, f2) = (x2, x1, f1);
            x1 = b - R * (b - a);
            f1 = f(x1);
        } else {
            (a, x1, f1) = (x1, x2, f2);
            x2 = a + R * (b - a);
            f2 = f(x2);
        }
    }
    if f1 < f2 { (x1, f1) } else { (x2, f2) }
}

/// A sign change of a function: where it is, and the sign after it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SignChange {
    pub at: f64,
    pub sign_after: f64,
}

/// Sign of `v` with values within `zero` of 0 counted as 0.
pub fn sign(v: f64, zero: f64) -> f64 {
    if v > zero {
        1.0
    } else if v < -zero {
        -1.0
    } else {
        0.0
    }
}

/// Finds where `f` changes sign on [a, b], given samples at `xs` (sorted,
/// spanning [a, b]) with values `ys`. Zero runs join the preceding sign.
/// `current` is the sign before `a` (0 when unknown). Pairs of close roots
/// between two samples are found by minimising ±f around local minima of |f|.
pub fn scan_sign_changes(
    f: &mut impl FnMut(f64) -> f64,
    xs: &[f64],
    ys: &[f64],
    zero: f64,
    current: &mut f64,
    out: &mut Vec<SignChange>,
) {
    let xtol = 1e-15 * xs.last().map_or(1.0, |x| x.abs().max(1.0));
    for j in 0..xs.len() {
        let s = sign(ys[j], zero);
        if s == 0.0 {
            continue;
        }
        if *current != 0.0 && s != *current && j > 0 {
            let at = if sign(ys[j - 1], zero) == 0.0 {
                // Leaving a zero run: find where f takes the new sign.
                let mut g = |x: f64| {
                    let v = f(x);
                    if sign(v, zero) == s { v } else { -s * f64::MIN_POSITIVE }
                };
                brent(&mut g, xs[j - 1], xs[j], xtol)
            } else {
                brent(&mut *f, xs[j - 1], xs[j], xtol)
            };
            out.push(SignChange { at, sign_after: s });
        } else if *current != 0.0 && s == *current && 0 < j && j + 1 < xs.len() {
            hidden_pair(f, xs, ys, j, s, zero, out);
        }
        *current = s;
    }
}

/// Two roots between samples j−1 and j+1 hidden by a local minimum of |f| at j.
fn hidden_pair(
    f: &mut impl FnMut(f64) -> f64,
    xs: &[f64],
    ys: &[f64],
    j: usize,
    s: f64,
    zero: f64,
    out: &mut Vec<SignChange>,
) {
    let local_min = s * ys[j] < s * ys[j - 1] && s * ys[j] < s * ys[j + 1];
    if !local_min || sign(ys[j + 1], zero) != s {
        return;
    }
    let span = xs[j + 1] - xs[j - 1];
    let (xm, fm) = golden_min(|x| s * f(x), xs[j - 1], xs[j + 1], 1e-12 * span);
    if fm < -zero {
        let xtol = 1e-15 * xs[j + 1].abs().max(1.0);
        let r1 = brent(&mut *f, xs[j - 1], xm, xtol);
        let r2 = brent(&mut *f, xm, xs[j + 1], xtol);
        out.push(SignChange { at: r1, sign_after: -s });
        out.push(SignChange { at: r2, sign_after: s });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tolerance below the spacing of the doubles around the bracket, or
    /// a function that is NaN, ends the search (it looped for ever); the
    /// minimum of (x − 6.00004)² is found to that spacing (closed form).
    #[test]
    fn golden_section_ends_below_the_spacing_of_the_doubles() {
        let (x, _) = golden_min(|x| (x - 6.000_04).powi(2), 6.0, 6.0001, 1e-18);
        assert!((x - 6.000_04).abs() < 1e-6, "{x}");
        let (x, _) = golden_min(|_| f64::NAN, 6.0, 6.0001, 0.0);
        assert!((6.0..=6.0001).contains(&x));
    }

    #[test]
    fn brent_finds_the_root_of_sin_inside_a_bracket() {
        let r = brent(f64::sin, 3.0, 3.3, 1e-15);
        assert!((r - std::f64::consts::PI).abs() < 1e-15);
    }

    #[test]
    fn brent_converges_to_a_jump_across_zero() {
        let r = brent(|x| if x < 0.3 { -1.0 } else { 2.0 }, 0.0, 1.0, 1e-14);
        assert!((r - 0.3).abs() < 1e-13);
    }

    #[test]
    fn a_pair_of_close_roots_between_samples_is_found() {
        // f = (x−0.52)(x−0.53): both roots lie between the samples 0.5 and 0.6.
        let mut f = |x: f64| (x - 0.52) * (x - 0.53);
        let xs: Vec<f64> = (0..=10).map(|i| i as f64 / 10.0).collect();
        let ys: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let (mut cur, mut out) = (0.0, vec![]);
        scan_sign_changes(&mut f, &xs, &ys, 0.0, &mut cur, &mut out);
        assert_eq!(out.len(), 2, "{out:?}");
        assert!((out[0].at - 0.52).abs() < 1e-14 && (out[1].at - 0.53).abs() < 1e-14);
        assert_eq!((out[0].sign_after, out[1].sign_after), (-1.0, 1.0));
    }

    #[test]
    fn zero_runs_join_the_preceding_sign() {
        let mut f = |x: f64| {
            if x < 0.3 {
                1.0
            } else if x < 0.6 {
                0.0
            } else {
                -1.0
            }
        };
        let xs: Vec<f64> = (0..=10).map(|i| i as f64 / 10.0).collect();
        let ys: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let (mut cur, mut out) = (0.0, vec![]);
        scan_sign_changes(&mut f, &xs, &ys, 0.0, &mut cur, &mut out);
        assert_eq!(out.len(), 1);
        assert!((out[0].at - 0.6).abs() < 1e-14, "{out:?}");
    }
}
