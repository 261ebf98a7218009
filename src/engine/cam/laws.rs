//! The textbook follower motion laws, in normalized form: over a segment's
//! fraction x ∈ [0, 1] of its cam angle, the fraction y(x) ∈ [0, 1] of its
//! lift, with y′, y″, y‴ and y⁗ (d/dx) — all in closed form (the fourth,
//! the snap, for a cam profile's third derivative).
//!
//! Symbols: x = (θ − θ₀)/β the fraction of the segment's span β, y the
//! fraction of its lift h; the follower's s = s₀ + h·y, and its
//! derivatives in the cam angle are h·y′/β, h·y″/β², h·y‴/β³.
//!
//! The modified sine and the modified trapezoid are built from their
//! acceleration pulses (pieces of sines, cosines and constants, integrated
//! exactly piece by piece) and scaled so that y(1) = 1: their textbook
//! coefficients (peak y′ 1.7596 and 2, peak y″ 5.5280 and 4.8881) follow.

use std::f64::consts::PI;

/// A follower motion law.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Law {
    /// No motion (a segment whose lift must be 0).
    Dwell,
    /// Simple harmonic: y = (1 − cos πx)/2.
    Harmonic,
    /// Cycloidal: y = x − sin(2πx)/(2π).
    Cycloidal,
    /// The 3-4-5 polynomial: y = 10x³ − 15x⁴ + 6x⁵.
    Poly345,
    /// The 4-5-6-7 polynomial: y = 35x⁴ − 84x⁵ + 70x⁶ − 20x⁷.
    Poly4567,
    /// Modified sine: a sine pulse of acceleration in eighths 1/8–3/4–1/8.
    ModifiedSine,
    /// Modified trapezoid: sine ramps and constant acceleration in eighths.
    ModifiedTrapezoid,
}

impl Law {
    /// [y, y′, y″, y‴, y⁗] at x (clamped to [0, 1]).
    pub fn eval(self, x: f64) -> [f64; 5] {
        let x = x.clamp(0.0, 1.0);
        match self {
            Law::Dwell => [0.0; 5],
            Law::Harmonic => {
                let (s, c) = (PI * x).sin_cos();
                [(1.0 - c) / 2.0, PI / 2.0 * s, PI * PI / 2.0 * c, -PI.powi(3) / 2.0 * s, -PI.powi(4) / 2.0 * c]
            }
            Law::Cycloidal => {
                let (s, c) = (2.0 * PI * x).sin_cos();
                [x - s / (2.0 * PI), 1.0 - c, 2.0 * PI * s, 4.0 * PI * PI * c, -8.0 * PI.powi(3) * s]
            }
            Law::Poly345 => polynomial(&[0.0, 0.0, 0.0, 10.0, -15.0, 6.0], x),
            Law::Poly4567 => polynomial(&[0.0, 0.0, 0.0, 0.0, 35.0, -84.0, 70.0, -20.0], x),
            Law::ModifiedSine => pulses(&MODIFIED_SINE, x),
            Law::ModifiedTrapezoid => pulses(&MODIFIED_TRAPEZOID, x),
        }
    }
}

/// Σ c_k x^k and its first four derivatives.
fn polynomial(c: &[f64], x: f64) -> [f64; 5] {
    let mut out = [0.0; 5];
    for (k, &ck) in c.iter().enumerate() {
        let k = k as i32;
        // d^d/dx^d x^k = k(k−1)…(k−d+1) x^(k−d).
        let mut falling = 1;
        for (d, o) in out.iter_mut().enumerate() {
            let d = d as i32;
            if d > k {
                break;
            }
            *o += ck * f64::from(falling) * x.powi(k - d);
            falling *= k - d;
        }
    }
    out
}

/// A piece of an acceleration pulse from `from`: y″ = a sin(kt) + b cos(kt)
/// + c with t = x − from (k = 0: a constant c).
#[derive(Clone, Copy, Debug)]
struct Piece {
    from: f64,
    k: f64,
    a: f64,
    b: f64,
    c: f64,
}

const fn piece(from: f64, k: f64, a: f64, b: f64, c: f64) -> Piece {
    Piece { from, k, a, b, c }
}

/// Modified sine: y″ ∝ sin 4πx to 1/8, cos(4π/3·(x − 1/8)) to 7/8, −cos 4π(x − 7/8) to 1.
const MODIFIED_SINE: [Piece; 3] = [
    piece(0.0, 4.0 * PI, 1.0, 0.0, 0.0),
    piece(0.125, 4.0 * PI / 3.0, 0.0, 1.0, 0.0),
    piece(0.875, 4.0 * PI, 0.0, -1.0, 0.0),
];

/// Modified trapezoid: y″ ∝ sin 4πx to 1/8, 1 to 3/8, cos 4π(x − 3/8) to
/// 5/8, −1 to 7/8, −cos 4π(x − 7/8) to 1.
const MODIFIED_TRAPEZOID: [Piece; 5] = [
    piece(0.0, 4.0 * PI, 1.0, 0.0, 0.0),
    piece(0.125, 0.0, 0.0, 0.0, 1.0),
    piece(0.375, 4.0 * PI, 0.0, 1.0, 0.0),
    piece(0.625, 0.0, 0.0, 0.0, -1.0),
    piece(0.875, 4.0 * PI, 0.0, -1.0, 0.0),
];

impl Piece {
    /// [y, y′, y″, y‴, y⁗] at t from the piece's start, given y and y′ there.
    fn at(&self, t: f64, [y0, v0]: [f64; 2]) -> [f64; 5] {
        let Piece { k, a, b, c, .. } = *self;
        if k == 0.0 {
            return [y0 + v0 * t + c * t * t / 2.0, v0 + c * t, c, 0.0, 0.0];
        }
        let (s, co) = (k * t).sin_cos();
        [
            y0 + v0 * t + a * (t / k - s / (k * k)) + b * (1.0 - co) / (k * k) + c * t * t / 2.0,
            v0 + a * (1.0 - co) / k + b * s / k + c * t,
            a * s + b * co + c,
            a * k * co - b * k * s,
            -k * k * (a * s + b * co),
        ]
    }
}

/// [y, y′, y″, y‴] of a law given by its pulses, integrated exactly from
/// rest at 0 and scaled to y(1) = 1.
fn pulses(pieces: &[Piece], x: f64) -> [f64; 5] {
    let raw = |x: f64| {
        let mut state = [0.0, 0.0];
        for (i, p) in pieces.iter().enumerate() {
            let end = pieces.get(i + 1).map_or(1.0, |n| n.from);
            if x <= end {
                return p.at(x - p.from, state);
            }
            let at_end = p.at(end - p.from, state);
            state = [at_end[0], at_end[1]];
        }
        let last = pieces[pieces.len() - 1];
        last.at(1.0 - last.from, state)
    };
    let scale = raw(1.0)[0];
    raw(x).map(|v| v / scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAWS: [Law; 6] =
        [Law::Harmonic, Law::Cycloidal, Law::Poly345, Law::Poly4567, Law::ModifiedSine, Law::ModifiedTrapezoid];

    /// Every law rises from 0 to 1 at rest at both ends, and each derivative
    /// is the central difference of the one before (h = 1e-6, away from
    /// the pulses' joints: error ~h² of the next derivative).
    #[test]
    fn every_law_rises_from_rest_to_rest_and_its_derivatives_agree() {
        for law in LAWS {
            let [y0, v0, ..] = law.eval(0.0);
            let [y1, v1, ..] = law.eval(1.0);
            assert!(y0.abs() < 1e-15 && (y1 - 1.0).abs() < 1e-14, "{law:?}: y {y0} → {y1}");
            assert!(v0.abs() < 1e-14 && v1.abs() < 1e-12, "{law:?}: y′ {v0} → {v1}");
            let h = 1e-6;
            for x in [0.05, 0.2, 0.33, 0.5, 0.7, 0.93] {
                let (p, m, at) = (law.eval(x + h), law.eval(x - h), law.eval(x));
                for d in 0..4 {
                    let fd = (p[d] - m[d]) / (2.0 * h);
                    assert!((fd - at[d + 1]).abs() < 1e-6 * (1.0 + at[d + 1].abs()), "{law:?} at {x}: d{d}");
                }
            }
        }
    }

    /// The peak velocity and acceleration coefficients: the polynomials' and
    /// the trigonometric laws' from their closed forms (harmonic π/2, π²/2;
    /// cycloidal 2, 2π; 3-4-5 15/8, 10/√3 at x = (3 − √3)/6; 4-5-6-7 35/16,
    /// 84√5/25 at x = (5 − √5)/10), the modified laws' as cam-design texts
    /// quote them to 4 decimals (Norton, Design of Machinery, ch. 8:
    /// modified sine 1.7596, 5.5280; modified trapezoid 2, 4.8881). Sampled
    /// at 10⁵ + 1 points: within 6e-5.
    #[test]
    fn peak_coefficients_are_the_textbook_ones() {
        let printed = [
            (Law::Harmonic, PI / 2.0, PI * PI / 2.0),
            (Law::Cycloidal, 2.0, 2.0 * PI),
            (Law::Poly345, 15.0 / 8.0, 10.0 / 3f64.sqrt()),
            (Law::Poly4567, 35.0 / 16.0, 84.0 * 5f64.sqrt() / 25.0),
            (Law::ModifiedSine, 1.7596, 5.5280),
            (Law::ModifiedTrapezoid, 2.0, 4.8881),
        ];
        for (law, v, a) in printed {
            let (mut vmax, mut amax) = (0.0f64, 0.0f64);
            for k in 0..=100_000 {
                let [_, dv, da, ..] = law.eval(f64::from(k) / 100_000.0);
                (vmax, amax) = (vmax.max(dv.abs()), amax.max(da.abs()));
            }
            assert!((vmax - v).abs() < 6e-5, "{law:?}: peak y′ {vmax} vs {v}");
            assert!((amax - a).abs() < 6e-5, "{law:?}: peak y″ {amax} vs {a}");
        }
    }

    /// The harmonic law's acceleration jumps at its ends (π²/2); the others
    /// start and end at zero acceleration.
    #[test]
    fn only_the_harmonic_law_breaks_the_acceleration_at_its_ends() {
        for law in LAWS {
            let [a0, a1] = [law.eval(0.0)[2], law.eval(1.0)[2]];
            if law == Law::Harmonic {
                assert!((a0 - PI * PI / 2.0).abs() < 1e-12 && (a1 + PI * PI / 2.0).abs() < 1e-12);
            } else {
                assert!(a0.abs() < 1e-12 && a1.abs() < 1e-9, "{law:?}: {a0} {a1}");
            }
        }
    }
}
