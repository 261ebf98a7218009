//! A disk cam designed for a translating follower (flat-faced, roller or
//! knife-edge, its axis offset from the cam centre): its profile, pitch
//! curve, pressure angle and radii of curvature at every cam angle, and
//! with the follower's dynamics the contact force and cam torque.
//!
//! Frames and symbols (besides those of [`super`]): the ground frame has x
//! along the follower's motion away from the cam, the axis y = e (e the
//! offset); the cam turns counter-clockwise by θ (a clockwise cam is the
//! mirror image). For a roller (radius r_r; r_r = 0 a knife) its centre is
//! P = (d, e) with d = d₀ + s, d₀ = √(R_p² − e²), R_p = R_b + r_r the
//! pitch circle. In the cam's frame a ground point P is A(−θ)P, so the
//! pitch curve's derivatives are A(−θ) applied to t = P′ − J P and
//! a = P″ − 2J P′ − P (J the quarter turn): the pressure angle φ, between
//! the normal J⁻¹t and the follower's motion x, has tan φ = (s′ + e)/d,
//! and the curvature κ = (t × a)/|t|³ (the pitch curve runs clockwise in
//! the cam: a convex stretch has κ < 0, its radius ρ = −1/κ > 0; the
//! profile's is ρ − r_r). A flat face x = h, h = R_b + s, touches the
//! envelope at (h, −s′): the profile there is A(−θ)(h, −s′), its radius of
//! curvature R_b + s + s″, its pressure angle 0.
//! Forces (cam at constant ω, the follower of mass m pressed by a spring
//! F₀ + k s and an external force F(θ) along +x): the follower's axial
//! force from the cam N_x = m s″ω² + F₀ + k s − F; the contact force N =
//! N_x / cos φ; the cam torque T = N_x s′ (power), plus μ N h for a
//! flat face with friction μ (the face slides on the cam).

use crate::engine::numeric::plane::{cross, perp};
use std::f64::consts::TAU;

/// The follower's kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Follower {
    /// A flat face square to the axis.
    Flat,
    /// A roller of this radius (m; 0 a knife edge).
    Roller(f64),
}

/// The follower's lift: [s, s′, s″, s‴] at θ (a program's, or a Function's).
pub type Lift<'a> = &'a dyn Fn(f64) -> [f64; 4];

/// A cam's geometry: follower, offset e, base radius R_b, sense.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cam {
    pub follower: Follower,
    pub offset: f64,
    pub base: f64,
    /// The cam turns clockwise.
    pub clockwise: bool,
}

/// The follower's dynamics.
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
    /// φ (rad), signed as tan φ = (s′ + e)/d (0 for a flat face).
    pub pressure_angle: f64,
    /// The roller's centre (the knife's edge, the face's point on the axis) in the cam's frame.
    pub pitch_point: [f64; 2],
    /// The contact point in the cam's frame.
    pub profile_point: [f64; 2],
    /// The profile's radius of curvature there (m; > 0 convex, < 0 concave).
    pub curvature_radius: f64,
    /// The pitch curve's (a roller's), else the profile's.
    pub pitch_curvature_radius: f64,
    /// Where the contact lies along a flat face from the axis (m).
    pub face_offset: f64,
}

/// Why a cam cannot be made.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum CamError {
    #[error(
        "the offset {offset} m is not inside the pitch circle (radius {pitch} m): the follower's axis misses the cam"
    )]
    Offset { offset: f64, pitch: f64 },
    #[error("the lift goes below the base circle: s = {lift} m at θ = {theta} rad")]
    Negative { lift: f64, theta: f64 },
}

impl Cam {
    /// The cam at θ for the lift's values there.
    pub fn at(&self, theta: f64, lift: [f64; 4]) -> Result<Sample, CamError> {
        let [s, s1, s2, _] = lift;
        let e = if self.clockwise { -self.offset } else { self.offset };
        let mut out = match self.follower {
            Follower::Flat => {
                let h = self.base + s;
                let rho = h + s2;
                let point = [h, -s1];
                Sample {
                    pitch_point: rotate(-theta, [h, e]),
                    profile_point: rotate(-theta, point),
                    curvature_radius: rho,
                    pitch_curvature_radius: rho,
                    face_offset: -s1 - e,
                    ..Sample::default()
                }
            }
            Follower::Roller(r) => {
                let pitch = self.base + r;
                if e.abs() >= pitch {
                    return Err(CamError::Offset { offset: self.offset, pitch });
                }
                let d = (pitch * pitch - e * e).sqrt() + s;
                let p = [d, e];
                let t = [s1 + e, -d]; // P′ − JP with P′ = (s′, 0)
                let a = [s2 - d, -2.0 * s1 - e]; // P″ − 2JP′ − P
                let speed = t[0].hypot(t[1]);
                let rho = -speed.powi(3) / cross(t, a);
                let n = perp([t[0] / speed, t[1] / speed]); // outward (the curve runs clockwise)
                Sample {
                    pressure_angle: (s1 + e).atan2(d),
                    pitch_point: rotate(-theta, p),
                    profile_point: rotate(-theta, [p[0] - r * n[0], p[1] - r * n[1]]),
                    curvature_radius: rho - r,
                    pitch_curvature_radius: rho,
                    ..Sample::default()
                }
            }
        };
        if s < -1e-12 * self.base.max(1e-300) {
            return Err(CamError::Negative { lift: s, theta });
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

    /// The follower's axial force from the cam N_x, the contact force N and
    /// the cam torque T at a sample, cam speed ω, external force F.
    pub fn forces(&self, x: &Sample, loads: &Loads, omega: f64, external: f64) -> [f64; 3] {
        let [s, s1, s2, _] = x.lift;
        let axial = loads.mass * s2 * omega * omega + loads.preload + loads.stiffness * s - external;
        let contact = axial / x.pressure_angle.cos();
        let friction = match self.follower {
            Follower::Flat => loads.mu * contact.abs() * (self.base + s) * omega.signum(),
            Follower::Roller(_) => 0.0,
        };
        [axial, contact, axial * s1 + friction]
    }
}

/// A ground vector in the cam's frame at angle φ: A(φ)v.
fn rotate(phi: f64, v: [f64; 2]) -> [f64; 2] {
    let (s, c) = phi.sin_cos();
    [c * v[0] - s * v[1], s * v[0] + c * v[1]]
}

/// The samples of a turn, n angles 2πk/n.
pub fn turn(cam: &Cam, lift: Lift, n: usize) -> Result<Vec<Sample>, CamError> {
    (0..n).map(|k| TAU * k as f64 / n as f64).map(|t| cam.at(t, lift(t))).collect()
}

/// The smallest base radius (to 1e-9 of the lift's scale) in (0, 100·scale]
/// whose turn meets `ok` (a test that holds for every base radius above
/// the smallest that meets it, such as a largest pressure angle or a
/// smallest radius of curvature), or None where even 100·scale does not.
pub fn smallest_base(cam: Cam, lift: Lift, n: usize, ok: impl Fn(&[Sample]) -> bool) -> Option<f64> {
    let scale = (0..n).map(|k| lift(TAU * k as f64 / n as f64)[0].abs()).fold(1e-6, f64::max);
    let meets = |base: f64| turn(&Cam { base, ..cam }, lift, n).is_ok_and(|s| ok(&s));
    let (mut lo, mut hi) = (0.0, 100.0 * scale + cam.offset.abs());
    if !meets(hi) {
        return None;
    }
    while hi - lo > 1e-9 * scale {
        let mid = 0.5 * (lo + hi);
        if meets(mid) { hi = mid } else { lo = mid }
    }
    Some(hi)
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
    /// follower; the pitch point lies r_r from the profile point.
    #[test]
    fn the_radius_of_curvature_is_that_of_the_profile_drawn() {
        let p = program(0.02);
        let lift = |t: f64| {
            let s = p.eval(t);
            [s[0], s[1], s[2], s[3]]
        };
        for (follower, offset, clockwise) in
            [(Follower::Flat, 0.0, false), (Follower::Roller(0.01), 0.005, false), (Follower::Roller(0.0), -0.01, true)]
        {
            let cam = Cam { follower, offset, base: 0.04, clockwise };
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
