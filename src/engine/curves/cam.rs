//! A disk cam's profile as a curve of the cam, from its follower's motion
//! program: at the cam's angle u (from +x, counter-clockwise, in the cam)
//! the follower's axis, at angle `zero` as drawn, lies at u when the cam
//! has turned by θ = zero − u, so every derivative in u of the lift is
//! (−1)^k s^(k)(zero − u).
//!
//! - Under a flat face at distance P(u) = R_b + s from the centre: the
//!   envelope of the faces r = c + P e + P′ e⊥ (e = (cos u, sin u), e⊥ =
//!   perp(e)).
//! - Under a roller of radius r_r (0: a knife edge) on an axis offset e:
//!   the pitch curve X = c + A(u) p, p = (d₀ + s, e), d₀ = √(R_p² − e²),
//!   R_p = R_b + r_r, whose derivatives are A(u) applied to (D + J)^k p (D
//!   = d/du, J the quarter turn, J² = −1); the profile Q = X + r_r n, n =
//!   perp(X′/|X′|) the inward normal (the curve runs counter-clockwise).
//!   With κ the pitch curve's curvature and v = |X′|: n′ = −κ v t, so Q′ =
//!   (1 − r_r κ) X′, Q″ = (1 − r_r κ) X″ − r_r κ′ X′, Q‴ = (1 − r_r κ) X‴ −
//!   2 r_r κ′ X″ − r_r κ″ X′, κ′ and κ″ from X′ to X⁗.

use super::Local;
use crate::engine::cam::Program;
use crate::engine::numeric::plane::{cross, perp};

/// The follower a cam curve is made for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Face {
    /// A flat face square to the axis.
    Flat,
    /// A roller of this radius (0: a knife edge) on an axis offset from the centre.
    Roller { radius: f64, offset: f64 },
}

/// The profile of a cam with `base` radius R_b, its program, at u.
pub fn at(centre: [f64; 2], zero: f64, base: f64, face: Face, program: &Program, u: f64) -> Local {
    let s = program.eval(zero - u);
    let sign = [1.0, -1.0, 1.0, -1.0, 1.0];
    let ds: [f64; 5] = std::array::from_fn(|k| sign[k] * s[k]);
    match face {
        Face::Flat => flat(centre, base, ds, u),
        Face::Roller { radius, offset } => roller(centre, base, radius, offset, ds, u),
    }
}

/// [s, s′, s″, s‴, s⁗] in u.
fn flat(c: [f64; 2], base: f64, s: [f64; 5], u: f64) -> Local {
    // r = P e + P′ e⊥ and, with e⊥′ = −e: r′ = (P + P″) e⊥,
    // r″ = (P′ + P‴) e⊥ − (P + P″) e, r‴ = (P⁗ − P) e⊥ − 2(P′ + P‴) e.
    let p = [base + s[0], s[1], s[2], s[3], s[4]];
    let (sn, co) = u.sin_cos();
    let (e, f) = ([co, sn], [-sn, co]);
    let comb = |a: f64, b: f64| [a * e[0] + b * f[0], a * e[1] + b * f[1]];
    let r = comb(p[0], p[1]);
    Local {
        r: [c[0] + r[0], c[1] + r[1]],
        d1: comb(0.0, p[0] + p[2]),
        d2: comb(-(p[0] + p[2]), p[1] + p[3]),
        d3: comb(-2.0 * (p[1] + p[3]), p[4] - p[0]),
    }
}

fn roller(c: [f64; 2], base: f64, radius: f64, offset: f64, s: [f64; 5], u: f64) -> Local {
    let pitch = base + radius;
    let d0 = (pitch * pitch - offset * offset).sqrt();
    // p^(k) = (d^(k), 0) for k ≥ 1.
    let p: [[f64; 2]; 5] = std::array::from_fn(|k| if k == 0 { [d0 + s[0], offset] } else { [s[k], 0.0] });
    let j = |v: [f64; 2]| [-v[1], v[0]];
    let lin = |terms: &[(f64, [f64; 2])]| terms.iter().fold([0.0, 0.0], |a, (w, v)| [a[0] + w * v[0], a[1] + w * v[1]]);
    // (D + J)^k p with J² = −1.
    let q = [
        p[0],
        lin(&[(1.0, p[1]), (1.0, j(p[0]))]),
        lin(&[(1.0, p[2]), (2.0, j(p[1])), (-1.0, p[0])]),
        lin(&[(1.0, p[3]), (3.0, j(p[2])), (-3.0, p[1]), (-1.0, j(p[0]))]),
        lin(&[(1.0, p[4]), (4.0, j(p[3])), (-6.0, p[2]), (-4.0, j(p[1])), (1.0, p[0])]),
    ];
    let (sn, co) = u.sin_cos();
    let x = q.map(|v| [co * v[0] - sn * v[1], sn * v[0] + co * v[1]]);
    let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
    let v = dot(x[1], x[1]).sqrt();
    let (w, c1, c2) = (dot(x[1], x[2]) / v, cross(x[1], x[2]), cross(x[1], x[3]));
    let kappa = c1 / v.powi(3);
    // κ = c v⁻³: κ′ = c′v⁻³ − 3c v⁻⁴ v′, κ″ = c″v⁻³ − 6c′v⁻⁴v′ + 12c v⁻⁵v′² − 3c v⁻⁴ v″.
    let (dv, ddv) = (w, (dot(x[2], x[2]) + dot(x[1], x[3])) / v - w * w / v);
    let ddc = cross(x[2], x[3]) + cross(x[1], x[4]);
    let k1 = c2 / v.powi(3) - 3.0 * c1 * dv / v.powi(4);
    let k2 = ddc / v.powi(3) - 6.0 * c2 * dv / v.powi(4) + 12.0 * c1 * dv * dv / v.powi(5) - 3.0 * c1 * ddv / v.powi(4);
    let n = perp([x[1][0] / v, x[1][1] / v]);
    let a = 1.0 - radius * kappa;
    Local {
        r: [c[0] + x[0][0] + radius * n[0], c[1] + x[0][1] + radius * n[1]],
        d1: lin(&[(a, x[1])]),
        d2: lin(&[(a, x[2]), (-radius * k1, x[1])]),
        d3: lin(&[(a, x[3]), (-2.0 * radius * k1, x[2]), (-radius * k2, x[1])]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::cam::design::{Cam, Follower, Guide};
    use crate::engine::cam::{Law, Segment};
    use std::f64::consts::PI;

    /// The curve under a roller (12 mm, offset 6 mm) or a knife edge is
    /// the profile the cam design draws (its derivation by t = P′ − JP and
    /// the normal, not by (D + J)^k p): at u = −θ (zero 0, centre O), the
    /// same point to 1e-12 m and the same radius of curvature to 1e-9 m.
    #[test]
    fn the_cam_curve_is_the_designed_profile() {
        let seg = |law, start: f64, from, to| Segment { law, start, span: PI, from, to };
        let program =
            Program::new(vec![seg(Law::Cycloidal, 0.0, 0.0, 0.015), seg(Law::Poly345, PI, 0.015, 0.0)]).unwrap();
        for (radius, offset) in [(0.012, 0.006), (0.0, -0.004)] {
            let design = Cam {
                follower: Follower::Roller(radius),
                guide: Guide::Translating { offset },
                base: 0.03,
                clockwise: false,
            };
            for theta in [0.2, 1.0, 2.5, 3.3, 4.4, 6.0] {
                let s = program.eval(theta);
                let sample = design.at(theta, [s[0], s[1], s[2], s[3]]).unwrap();
                let l = at([0.0, 0.0], 0.0, 0.03, Face::Roller { radius, offset }, &program, -theta);
                let gap = (l.r[0] - sample.profile_point[0]).hypot(l.r[1] - sample.profile_point[1]);
                assert!(gap < 1e-12, "r {radius}, θ {theta}: {gap}");
                let rho = 1.0 / l.curvature();
                assert!(
                    (rho - sample.curvature_radius).abs() < 1e-9,
                    "θ {theta}: ρ {rho} vs {}",
                    sample.curvature_radius
                );
            }
        }
    }
}
