//! A disk cam designed for its follower — flat-faced, roller or
//! knife-edge; translating (its axis offset from the cam centre) or
//! oscillating about a pivot: its profile, pitch curve, pressure angle and
//! radii of curvature at every cam angle, and with the follower's dynamics
//! the contact force and cam torque.
//!
//! Frames and symbols (besides those of [`super`]): the ground frame has
//! its x axis through the follower (along a translating follower's motion
//! away from the cam; towards an oscillating follower's pivot A = (a, 0),
//! a the `pivot` distance); the cam turns counter-clockwise by θ (a
//! clockwise cam is the mirror image: computed with the mirrored follower,
//! σ = −1, and its y flipped). The follower's lift s moves it: a
//! translating one along x, an oscillating one turning its arm to
//! ψ = ψ₀ + s, ψ from the direction A→O, the arm on the side y > 0.
//! - A roller (radius r_r; 0 a knife): its centre P(s) — translating (d₀ +
//!   s, e), d₀ = √(R_p² − e²), e the offset; oscillating A + L(−cos ψ,
//!   σ sin ψ), L the `arm`, cos ψ₀ = (a² + L² − R_p²)/(2aL) — with R_p =
//!   R_b + r_r the pitch circle. In the cam's frame a ground point P is
//!   A(−θ)P, so the pitch curve's derivatives are A(−θ) applied to t = P′
//!   − J P and a = P″ − 2J P′ − P (′ = d/dθ, J the quarter turn): its
//!   curvature κ = (t × a)/|t|³ (the pitch curve runs clockwise in the
//!   cam: a convex stretch has κ < 0, ρ = −1/κ > 0; the profile's is ρ −
//!   r_r); the normal n = perp(t/|t|), out of the cam.
//! - A flat face: the line x·n̂ = p in the ground, n̂ at angle β —
//!   translating β = 0, p = R_b + s; oscillating n̂ = (sin ψ, σ cos ψ), p =
//!   a sin ψ − f, f the `arm` (the pivot's distance from the face's line),
//!   sin ψ₀ = (R_b + f)/a. In the cam's frame its normal is at α = β − θ,
//!   and the profile is the envelope of the lines: the contact
//!   x = p e(α) + p_α e⊥(α), its radius of curvature p + p_αα (p as a
//!   function of α, the support function).
//!
//! The pressure angle φ is the angle between the contact normal and the
//! velocity of the follower's point of contact (0 for a translating flat
//! face; tan φ = (s′ + e)/d for a translating roller). Forces (cam at
//! constant ω): the follower's generalised force from the cam
//! Q = m s″ω² + F₀ + k s − F (a force along the axis; for an oscillating follower a
//! moment about the pivot, with m its moment of inertia, k and F₀ its
//! spring's in N·m/rad and N·m, F the external moment); the contact force
//! N = Q/λ with λ = ∂x/∂s·n (1 for a translating face, cos φ for a
//! translating roller: the contact point's motion per unit lift along the
//! normal); the cam torque T = Q s′ (power), plus μ N v_s for a flat face
//! with friction μ, v_s the face's sliding speed per unit ω.

use crate::engine::numeric::plane::{cross, perp};

/// The follower's kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Follower {
    /// A flat face square to the axis (to the arm, oscillating).
    Flat,
    /// A roller of this radius (m; 0 a knife edge).
    Roller(f64),
}

/// How the follower moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Guide {
    /// Along its axis, offset e (m) from the cam centre.
    Translating { offset: f64 },
    /// Turning about a pivot `pivot` (m) from the cam centre; `arm` (m) to
    /// the roller's centre, or the pivot's distance from the face's line.
    Oscillating { pivot: f64, arm: f64 },
}

/// The follower's lift: [s, s′, s″, s‴] at θ (a program's, or a Function's).
pub type Lift<'a> = &'a dyn Fn(f64) -> [f64; 4];

/// A cam's geometry: follower, guide, base radius R_b, sense.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cam {
    pub follower: Follower,
    pub guide: Guide,
    pub base: f64,
    /// The cam turns clockwise.
    pub clockwise: bool,
}

/// The follower's dynamics (oscillating: moment of inertia, N·m/rad, N·m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Loads {
    pub mass: f64,
    pub stiffness: f64,
    pub preload: f64,
    /// Friction at a flat face.
    pub mu: f64,
}

/// The cam at one angle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sample {
    pub theta: f64,
    /// [s, s′, s″, s‴].
    pub lift: [f64; 4],
    /// φ (rad), signed as tan φ = (s′ + e)/d for a translating roller.
    pub pressure_angle: f64,
    /// The roller's centre (the knife's edge; a face's foot on its axis,
    /// or from the pivot) in the cam's frame.
    pub pitch_point: [f64; 2],
    /// The contact point in the cam's frame.
    pub profile_point: [f64; 2],
    /// The profile's radius of curvature there (m; > 0 convex, < 0 concave).
    pub curvature_radius: f64,
    /// The pitch curve's (a roller's), else the profile's.
    pub pitch_curvature_radius: f64,
    /// Where the contact lies along a flat face from its foot (m).
    pub face_offset: f64,
    /// λ = ∂x/∂s·n: N = Q/λ.
    pub lever: f64,
    /// A flat face's sliding speed at the contact per unit cam speed (m).
    pub slip: f64,
}

/// Why a cam cannot be made.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum CamError {
    #[error(
        "the offset {offset} m is not inside the pitch circle (radius {pitch} m): the follower's axis misses the cam"
    )]
    Offset { offset: f64, pitch: f64 },
    #[error(
        "an arm of {arm} m pivoted {pivot} m from the cam centre cannot start the follower on the circle of \
         radius {radius} m (the base circle, plus a roller's radius, or a face's distance from the pivot)"
    )]
    Reach { radius: f64, pivot: f64, arm: f64 },
    #[error("the lift goes below the base circle: s = {lift} at θ = {theta} rad")]
    Negative { lift: f64, theta: f64 },
}

impl Cam {
    /// The cam at θ for the lift's values there.
    pub fn at(&self, theta: f64, lift: [f64; 4]) -> Result<Sample, CamError> {
        let side = if self.clockwise { -1.0 } else { 1.0 };
        let mut out = match self.follower {
            Follower::Flat => self.flat(theta, lift, side)?,
            Follower::Roller(r) => self.roller(theta, lift, side, r)?,
        };
        if lift[0] < -1e-12 * self.base.max(1e-300) {
            return Err(CamError::Negative { lift: lift[0], theta });
        }
        out.theta = theta;
        out.lift = lift;
        if self.clockwise {
            out.pitch_point[1] = -out.pitch_point[1];
            out.profile_point[1] = -out.profile_point[1];
            out.pressure_angle = -out.pressure_angle;
            out.face_offset = -out.face_offset;
        }
        Ok(out)
    }

    /// A roller's (knife's) centre P and its first two derivatives in s.
    fn pitch(&self, s: f64, side: f64, r: f64) -> Result<[[f64; 2]; 3], CamError> {
        let radius = self.base + r;
        match self.guide {
            Guide::Translating { offset } => {
                let e = side * offset;
                if e.abs() >= radius {
                    return Err(CamError::Offset { offset, pitch: radius });
                }
                Ok([[(radius * radius - e * e).sqrt() + s, e], [1.0, 0.0], [0.0, 0.0]])
            }
            Guide::Oscillating { pivot: a, arm: l } => {
                let c0 = (a * a + l * l - radius * radius) / (2.0 * a * l);
                if c0.is_nan() || c0.abs() >= 1.0 {
                    return Err(CamError::Reach { radius, pivot: a, arm: l });
                }
                let (sn, cs) = (c0.acos() + s).sin_cos();
                Ok([[a - l * cs, side * l * sn], [l * sn, side * l * cs], [l * cs, -side * l * sn]])
            }
        }
    }

    fn roller(&self, theta: f64, [s, s1, s2, _]: [f64; 4], side: f64, r: f64) -> Result<Sample, CamError> {
        let [p, ps, pss] = self.pitch(s, side, r)?;
        let d1 = [ps[0] * s1, ps[1] * s1];
        let d2 = [pss[0] * s1 * s1 + ps[0] * s2, pss[1] * s1 * s1 + ps[1] * s2];
        let t = [d1[0] + p[1], d1[1] - p[0]]; // P′ − JP
        let a = [d2[0] + 2.0 * d1[1] - p[0], d2[1] - 2.0 * d1[0] - p[1]]; // P″ − 2JP′ − P
        let speed = t[0].hypot(t[1]);
        let rho = -speed.powi(3) / cross(t, a);
        let n = perp([t[0] / speed, t[1] / speed]);
        Ok(Sample {
            pressure_angle: angle_between(ps, n),
            pitch_point: rotate(-theta, p),
            profile_point: rotate(-theta, [p[0] - r * n[0], p[1] - r * n[1]]),
            curvature_radius: rho - r,
            pitch_curvature_radius: rho,
            lever: ps[0] * n[0] + ps[1] * n[1],
            ..Sample::default()
        })
    }

    /// A flat face's line in the ground at lift s.
    fn face(&self, s: f64, side: f64) -> Result<FaceLine, CamError> {
        match self.guide {
            Guide::Translating { offset } => {
                let h = self.base + s;
                Ok(FaceLine { n: [1.0, 0.0], beta_s: 0.0, p: [h, 1.0, 0.0], foot: [h, side * offset], pivot: None })
            }
            Guide::Oscillating { pivot: a, arm: f } => {
                let s0 = (self.base + f) / a;
                if !(s0 > 0.0 && s0 < 1.0) {
                    return Err(CamError::Reach { radius: self.base, pivot: a, arm: f });
                }
                let (sn, cs) = (s0.asin() + s).sin_cos();
                let n = [sn, side * cs];
                let foot = [a - f * n[0], -f * n[1]];
                Ok(FaceLine { n, beta_s: -side, p: [a * sn - f, a * cs, -a * sn], foot, pivot: Some((a, side)) })
            }
        }
    }

    fn flat(&self, theta: f64, [s, s1, s2, _]: [f64; 4], side: f64) -> Result<Sample, CamError> {
        let face = self.face(s, side)?;
        let (n, beta_s, [p, p_s, p_ss], foot) = (face.n, face.beta_s, face.p, face.foot);
        let alpha = n[1].atan2(n[0]) - theta;
        let (alpha_t, alpha_tt) = (beta_s * s1 - 1.0, beta_s * s2);
        let (p_t, p_tt) = (p_s * s1, p_ss * s1 * s1 + p_s * s2);
        let p_a = p_t / alpha_t;
        let p_aa = (p_tt * alpha_t - p_t * alpha_tt) / alpha_t.powi(3);
        let (sa, ca) = alpha.sin_cos();
        let x = [p * ca - p_a * sa, p * sa + p_a * ca];
        let ground = rotate(theta, x);
        let along = perp(n);
        let mv = face.motion(ground);
        let cam = [-ground[1], ground[0]]; // J x: the cam's point moving at unit ω
        let slip = (cam[0] - s1 * mv[0]) * along[0] + (cam[1] - s1 * mv[1]) * along[1];
        Ok(Sample {
            pressure_angle: angle_between(mv, n),
            pitch_point: rotate(-theta, foot),
            profile_point: x,
            curvature_radius: p + p_aa,
            pitch_curvature_radius: p + p_aa,
            face_offset: (ground[0] - foot[0]) * along[0] + (ground[1] - foot[1]) * along[1],
            lever: mv[0] * n[0] + mv[1] * n[1],
            slip,
            ..Sample::default()
        })
    }

    /// The follower's generalised force from the cam Q, the contact force N
    /// and the cam torque T at a sample, cam speed ω, external force F.
    pub fn forces(&self, x: &Sample, loads: &Loads, omega: f64, external: f64) -> [f64; 3] {
        let [s, s1, s2, _] = x.lift;
        let axial = loads.mass * s2 * omega * omega + loads.preload + loads.stiffness * s - external;
        let contact = axial / x.lever;
        let friction = match self.follower {
            Follower::Flat => loads.mu * contact.abs() * x.slip.abs() * omega.signum(),
            Follower::Roller(_) => 0.0,
        };
        [axial, contact, axial * s1 + friction]
    }

    /// The base radii the follower can start from, as (lo, hi): any up to
    /// 100 times the largest lift `scale` (m) for a translating follower
    /// (the search's first range: it goes on above, `sizing::beyond`);
    /// where the arm reaches for an oscillating one.
    pub(super) fn base_range(&self, scale: f64) -> (f64, f64) {
        let r = match self.follower {
            Follower::Flat => 0.0,
            Follower::Roller(r) => r,
        };
        match (self.guide, self.follower) {
            (Guide::Translating { offset }, _) => (0.0, 100.0 * scale + offset.abs()),
            (Guide::Oscillating { pivot, arm }, Follower::Flat) => ((-arm).max(0.0), pivot - arm),
            (Guide::Oscillating { pivot, arm }, Follower::Roller(_)) => {
                (((pivot - arm).abs() - r).max(0.0), pivot + arm - r)
            }
        }
    }
}

/// A flat face's line in the ground: x·n̂ = p, n̂ at angle β; β's and
/// p's derivatives in the lift; the face's foot (on the axis, or nearest
/// the pivot); the pivot A = (a, 0) and σ of an oscillating follower.
struct FaceLine {
    n: [f64; 2],
    beta_s: f64,
    /// [p, p_s, p_ss].
    p: [f64; 3],
    foot: [f64; 2],
    pivot: Option<(f64, f64)>,
}

impl FaceLine {
    /// ∂x/∂s of the face's point x: along the axis, or −σ J(x − A) about the pivot.
    fn motion(&self, x: [f64; 2]) -> [f64; 2] {
        match self.pivot {
            None => [1.0, 0.0],
            Some((a, side)) => [side * x[1], -side * (x[0] - a)],
        }
    }
}

/// The signed angle from the direction of u to n (rad).
fn angle_between(u: [f64; 2], n: [f64; 2]) -> f64 {
    cross(u, n).atan2(u[0] * n[0] + u[1] * n[1])
}

/// A vector turned by φ: A(φ)v.
fn rotate(phi: f64, v: [f64; 2]) -> [f64; 2] {
    let (s, c) = phi.sin_cos();
    [c * v[0] - s * v[1], s * v[0] + c * v[1]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::cam::{Law, Program, Segment};
    use std::f64::consts::PI;

    /// A cycloidal rise of h over β = π/2, dwell, cycloidal return, dwell.
    fn program(h: f64) -> Program {
        let seg = |law, start, span, from, to| Segment { law, start, span, from, to };
        Program::new(vec![
            seg(Law::Cycloidal, 0.0, PI / 2.0, 0.0, h),
            seg(Law::Dwell, PI / 2.0, PI / 2.0, h, h),
            seg(Law::Cycloidal, PI, PI / 2.0, h, 0.0),
            seg(Law::Dwell, 1.5 * PI, PI / 2.0, 0.0, 0.0),
        ])
        .unwrap()
    }

    /// The profile's point and its radius of curvature against the
    /// profile drawn by differences: the curvature of three neighbouring
    /// profile points (the circle through them) within 1e-5, for every
    /// follower, translating or oscillating, in either sense; the pitch point lies r_r from the profile point.
    #[test]
    fn the_radius_of_curvature_is_that_of_the_profile_drawn() {
        let p = program(0.02);
        let lift = |t: f64| {
            let s = p.eval(t);
            [s[0], s[1], s[2], s[3]]
        };
        let translating = |offset| Guide::Translating { offset };
        let oscillating = |arm| Guide::Oscillating { pivot: 0.12, arm };
        for (follower, guide, clockwise) in [
            (Follower::Flat, translating(0.0), false),
            (Follower::Roller(0.01), translating(0.005), false),
            (Follower::Roller(0.0), translating(-0.01), true),
            (Follower::Roller(0.012), oscillating(0.09), false),
            (Follower::Roller(0.012), oscillating(0.09), true),
            (Follower::Flat, oscillating(0.01), true),
        ] {
            let cam = Cam { follower, guide, base: 0.04, clockwise };
            for theta in [0.3, 0.9, 2.0, 3.5, 4.0] {
                let h = 1e-4;
                let [a, b, c] = [theta - h, theta, theta + h].map(|t| cam.at(t, lift(t)).unwrap().profile_point);
                let area = cross([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
                let sides = [(a, b), (b, c), (a, c)].map(|(x, y)| (x[0] - y[0]).hypot(x[1] - y[1]));
                // Circumradius abc/(4·area), signed: convex where the profile runs clockwise.
                let drawn = -sides[0] * sides[1] * sides[2] / (2.0 * area);
                let x = cam.at(theta, lift(theta)).unwrap();
                let drawn = if clockwise { -drawn } else { drawn };
                assert!(
                    (x.curvature_radius - drawn).abs() < 1e-5,
                    "{follower:?} θ {theta}: {} vs {drawn}",
                    x.curvature_radius
                );
                if let Follower::Roller(r) = follower {
                    let gap = (x.pitch_point[0] - x.profile_point[0]).hypot(x.pitch_point[1] - x.profile_point[1]);
                    assert!((gap - r).abs() < 1e-12);
                }
            }
        }
    }
}
