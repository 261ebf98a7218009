//! Curves fixed in a body, for higher pairs (cams, disks, tracks, rims):
//! each gives its point and the point's first three derivatives along its
//! parameter u exactly (analytic for points, lines, circles and polar
//! curves; a cubic spline's own derivatives), in the body's reference
//! coordinates (as drawn).
//!
//! Symbols: r(u) the curve's point, r′, r″, r‴ its derivatives in u; the
//! unit tangent t = r′/|r′| and normal n = perp(t) (t turned +90°); the
//! signed curvature κ = (r′ × r″)/|r′|³, positive where the curve turns
//! to the left of its tangent (a circle run counter-clockwise: 1/R).

mod cam;
mod spline;

use super::cam::Program;
use super::function::{Function, Side};
use super::numeric::plane::{cross, perp};
use super::numeric::quadrature::integrate;
pub use cam::Face;
pub use spline::Spline;
use std::f64::consts::TAU;

/// A curve's point and its derivatives in its parameter.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Local {
    pub r: [f64; 2],
    pub d1: [f64; 2],
    pub d2: [f64; 2],
    pub d3: [f64; 2],
}

impl Local {
    /// κ = (r′ × r″)/|r′|³ (0 where r′ vanishes: a point).
    pub fn curvature(&self) -> f64 {
        let speed = self.d1[0].hypot(self.d1[1]);
        if speed == 0.0 { 0.0 } else { cross(self.d1, self.d2) / speed.powi(3) }
    }

    /// The unit tangent t and normal n = perp(t).
    pub fn frame(&self) -> ([f64; 2], [f64; 2]) {
        let speed = self.d1[0].hypot(self.d1[1]);
        let t = if speed == 0.0 { [1.0, 0.0] } else { [self.d1[0] / speed, self.d1[1] / speed] };
        (t, perp(t))
    }
}

/// Where a curve's parameter lives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Domain {
    /// No parameter: a point.
    None,
    /// Any u (a line).
    Unbounded,
    /// u and u + period are the same point (closed curves).
    Periodic(f64),
    /// An open curve from one end to the other.
    Interval(f64, f64),
}

/// A curve of a body, in reference coordinates.
#[derive(Clone, Debug)]
pub enum Curve {
    /// A point (a knife edge, a pin in a groove).
    Point([f64; 2]),
    /// r(u) = at + u·d, d a unit direction.
    Line {
        at: [f64; 2],
        direction: [f64; 2],
    },
    /// r(u) = c + R(cos u, sin u); `inside`: the contact is on its inner side (a track, a ring).
    Circle {
        centre: [f64; 2],
        radius: f64,
        inside: bool,
    },
    /// r(ψ) = c + ρ(ψ)(cos(ψ + ψ₀), sin(ψ + ψ₀)), ψ from the direction ψ₀
    /// (`zero`, from +x as drawn), ρ > 0 a Function of ψ and its three derivatives.
    Polar {
        centre: [f64; 2],
        zero: f64,
        radius: Box<[Function; 4]>,
    },
    Spline(Spline),
    /// A disk cam's profile from its follower's motion program ([`cam`]):
    /// the follower's axis runs through `centre` at angle `zero` (as drawn),
    /// its face square to it at distance `base` + s, or its roller on it.
    Cam {
        centre: [f64; 2],
        zero: f64,
        base: f64,
        face: Face,
        program: Box<Program>,
    },
}

impl Curve {
    /// A polar curve r = ρ(ψ) about `centre`, ψ from the direction at angle
    /// `zero` (rad, from +x), its derivatives formed once.
    pub fn polar(centre: [f64; 2], zero: f64, rho: Function) -> Self {
        let d1 = rho.derivative();
        let d2 = d1.derivative();
        let d3 = d2.derivative();
        Curve::Polar { centre, zero, radius: Box::new([rho, d1, d2, d3]) }
    }

    pub fn domain(&self) -> Domain {
        match self {
            Curve::Point(_) => Domain::None,
            Curve::Line { .. } => Domain::Unbounded,
            Curve::Circle { .. } | Curve::Polar { .. } | Curve::Cam { .. } => Domain::Periodic(TAU),
            Curve::Spline(s) if s.closed => Domain::Periodic(s.segments() as f64),
            Curve::Spline(s) => Domain::Interval(0.0, s.segments() as f64),
        }
    }

    /// r, r′, r″, r‴ at u.
    pub fn at(&self, u: f64) -> Local {
        match self {
            Curve::Point(p) => Local { r: *p, ..Local::default() },
            Curve::Line { at, direction: d } => {
                Local { r: [at[0] + u * d[0], at[1] + u * d[1]], d1: *d, ..Local::default() }
            }
            Curve::Circle { centre: c, radius, .. } => {
                let (s, co) = u.sin_cos();
                let k = *radius;
                Local {
                    r: [c[0] + k * co, c[1] + k * s],
                    d1: [-k * s, k * co],
                    d2: [-k * co, -k * s],
                    d3: [k * s, -k * co],
                }
            }
            Curve::Polar { centre: c, zero, radius } => {
                let [p0, p1, p2, p3] = radius.as_ref().each_ref().map(|f| f.eval(u, Side::Right));
                let (s, co) = (u + zero).sin_cos();
                // r = c + ρ e, e = (cos(ψ + ψ₀), sin(ψ + ψ₀)), e′ = perp(e): Leibniz on ρ·e.
                let (e, f) = ([co, s], [-s, co]);
                let comb = |a: f64, b: f64| [a * e[0] + b * f[0], a * e[1] + b * f[1]];
                let r = comb(p0, 0.0);
                Local {
                    r: [c[0] + r[0], c[1] + r[1]],
                    d1: comb(p1, p0),
                    d2: comb(p2 - p0, 2.0 * p1),
                    d3: comb(p3 - 3.0 * p1, 3.0 * p2 - p0),
                }
            }
            Curve::Spline(s) => s.at(u),
            Curve::Cam { centre, zero, base, face, program } => cam::at(*centre, *zero, *base, *face, program, u),
        }
    }

    /// For a closed curve, +1 where its parameter runs counter-clockwise
    /// (its outward normal is then −perp(t)), −1 clockwise; None for an
    /// open curve or a point. A circle's and a polar curve's run
    /// counter-clockwise; a closed spline's as its points are drawn.
    pub fn orientation(&self) -> Option<f64> {
        match self {
            Curve::Circle { .. } | Curve::Polar { .. } | Curve::Cam { .. } => Some(1.0),
            Curve::Spline(s) if s.closed => {
                let n = s.points.len();
                let area: f64 = (0..n).map(|k| cross(s.points[k], s.points[(k + 1) % n])).sum();
                Some(if area >= 0.0 { 1.0 } else { -1.0 })
            }
            _ => None,
        }
    }

    /// |r′(u)|: the arc length run per unit of u.
    pub fn speed(&self, u: f64) -> f64 {
        let d = self.at(u).d1;
        d[0].hypot(d[1])
    }

    /// The arc length from u = 0 to u (negative below 0): exact for lines
    /// and circles, by adaptive Gauss–Kronrod quadrature (1e-13 relative)
    /// for polar curves and splines.
    pub fn arc(&self, u: f64) -> f64 {
        match self {
            Curve::Point(_) => 0.0,
            Curve::Line { .. } => u,
            Curve::Circle { radius, .. } => radius * u,
            Curve::Polar { .. } | Curve::Spline(_) | Curve::Cam { .. } => {
                integrate(|v| self.speed(v), 0.0, u, 0.0, 1e-13, 20_000).value
            }
        }
    }

    /// The parameter of the curve's point nearest to p, by Newton on
    /// (r(u) − p)·r′(u) = 0 from `guess` (None where it does not settle).
    pub fn nearest(&self, p: [f64; 2], guess: f64) -> Option<f64> {
        if self.domain() == Domain::None {
            return Some(0.0);
        }
        let mut u = guess;
        for _ in 0..50 {
            let l = self.at(u);
            let d = [l.r[0] - p[0], l.r[1] - p[1]];
            let g = d[0] * l.d1[0] + d[1] * l.d1[1];
            let dg = l.d1[0] * l.d1[0] + l.d1[1] * l.d1[1] + d[0] * l.d2[0] + d[1] * l.d2[1];
            if dg <= 0.0 || !dg.is_finite() {
                return None;
            }
            let step = g / dg;
            u -= step;
            if step.abs() <= 1e-14 * (1.0 + u.abs()) {
                return Some(u);
            }
        }
        None
    }

    /// The parameter nearest to p over the whole curve: the best of Newton
    /// from `starts` points spread over its domain.
    pub fn nearest_anywhere(&self, p: [f64; 2], starts: usize) -> Option<f64> {
        let (a, b) = match self.domain() {
            Domain::None => return Some(0.0),
            Domain::Unbounded => {
                let Curve::Line { at, direction: d } = self else { return None };
                return Some((p[0] - at[0]) * d[0] + (p[1] - at[1]) * d[1]);
            }
            Domain::Periodic(period) => (0.0, period),
            Domain::Interval(a, b) => (a, b),
        };
        let distance = |u: f64| {
            let r = self.at(u).r;
            (r[0] - p[0]).hypot(r[1] - p[1])
        };
        (0..starts)
            .filter_map(|k| self.nearest(p, a + (b - a) * (k as f64 + 0.5) / starts as f64))
            .min_by(|x, y| distance(*x).total_cmp(&distance(*y)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::expr::Expr;

    fn expr(text: &str) -> Function {
        Function::Expr(Expr::compile(text, &["phi"]).unwrap())
    }

    /// A cam whose follower's axis is at π/2: a cycloidal rise of 10 mm
    /// over [0, π] of the program, a return over [π, 2π]; base 40 mm.
    fn cam() -> Curve {
        use crate::engine::cam::{Law, Program, Segment};
        let seg = |start: f64, from, to| Segment { law: Law::Cycloidal, start, span: std::f64::consts::PI, from, to };
        let program = Program::new(vec![seg(0.0, 0.0, 0.01), seg(std::f64::consts::PI, 0.01, 0.0)]).unwrap();
        cam_for(Face::Flat, program)
    }

    fn cam_for(face: Face, program: Program) -> Curve {
        Curve::Cam {
            centre: [0.0, 0.0],
            zero: std::f64::consts::FRAC_PI_2,
            base: 0.04,
            face,
            program: Box::new(program),
        }
    }

    /// The same cam under a 10 mm roller offset 5 mm, and under a knife edge.
    fn cams() -> [(&'static str, Curve, f64); 2] {
        let program = match cam() {
            Curve::Cam { program, .. } => *program,
            _ => unreachable!(),
        };
        [
            (
                "cam for a roller (offset 5 mm)",
                cam_for(Face::Roller { radius: 0.01, offset: 0.005 }, program.clone()),
                0.9,
            ),
            ("cam for a knife edge", cam_for(Face::Roller { radius: 0.0, offset: 0.0 }, program), 2.4),
        ]
    }

    fn curves() -> Vec<(&'static str, Curve, f64)> {
        let circle: Vec<[f64; 2]> =
            (0..12).map(|k| (TAU * f64::from(k) / 12.0).sin_cos()).map(|(s, c)| [c, s]).collect();
        let wavy = vec![[0.0, 0.0], [1.0, 0.5], [2.0, -0.2], [3.0, 0.4], [4.0, 0.0]];
        vec![
            ("line", Curve::Line { at: [0.2, -0.1], direction: [0.6, 0.8] }, 0.7),
            ("circle", Curve::Circle { centre: [0.1, 0.2], radius: 0.05, inside: false }, 1.1),
            ("polar ellipse-like, ψ from 0.3 rad", Curve::polar([0.0, 0.0], 0.3, expr("0.04 + 0.01*cos(2*phi)")), 0.9),
            (
                "polar eccentric",
                Curve::polar([0.0, 0.0], 0.0, expr("0.03*cos(phi) + sqrt(0.05^2 - (0.03*sin(phi))^2)")),
                2.3,
            ),
            ("closed spline", Curve::Spline(Spline::new(circle, true).unwrap()), 4.3),
            ("open spline", Curve::Spline(Spline::new(wavy, false).unwrap()), 2.6),
            ("cam for a flat follower (a cycloidal rise under u)", cam(), 0.9),
        ]
        .into_iter()
        .chain(cams())
        .collect()
    }

    /// Each derivative is the central difference of the one before (h =
    /// 1e-5 in u; within a spline's segment, where it is a cubic).
    #[test]
    fn every_curve_s_derivatives_are_its_differences() {
        for (name, c, u) in curves() {
            let h = 1e-5;
            let (p, m, at) = (c.at(u + h), c.at(u - h), c.at(u));
            let rows = |l: Local| [l.r, l.d1, l.d2, l.d3];
            let (p, m, at) = (rows(p), rows(m), rows(at));
            for d in 0..3 {
                for k in 0..2 {
                    let fd = (p[d][k] - m[d][k]) / (2.0 * h);
                    assert!((fd - at[d + 1][k]).abs() < 1e-7, "{name}: d{} [{k}] {} vs {fd}", d + 1, at[d + 1][k]);
                }
            }
        }
    }

    /// A circle's curvature is 1/R; a polar curve of constant ρ is that
    /// circle; the eccentric circle written as a polar curve about a point
    /// 0.03 from its centre has curvature 1/0.05 everywhere (1e-12).
    #[test]
    fn circles_have_curvature_one_over_their_radius() {
        let circle = Curve::Circle { centre: [0.0, 0.0], radius: 0.05, inside: false };
        let constant = Curve::polar([0.0, 0.0], 0.0, Function::Constant(0.05));
        let eccentric = &curves()[3].1;
        for u in [0.0, 0.4, 1.9, 3.5, 5.0] {
            for c in [&circle, &constant, eccentric] {
                assert!((c.at(u).curvature() - 20.0).abs() < 1e-9, "{c:?} at {u}: {}", c.at(u).curvature());
            }
        }
    }

    /// A spline passes through its points; a closed one is C² across every
    /// knot (r, r′, r″ from both sides), an open one has r″ = 0 at its ends;
    /// 64 points of a unit circle give curvature 1 within 1e-3 (a cubic
    /// spline's curvature errs by O(h²), h = 2π/64: 4e-4 here).
    #[test]
    fn splines_interpolate_and_are_smooth() {
        let ring: Vec<[f64; 2]> = (0..64).map(|k| (TAU * f64::from(k) / 64.0).sin_cos()).map(|(s, c)| [c, s]).collect();
        let closed = Spline::new(ring.clone(), true).unwrap();
        for (k, p) in ring.iter().enumerate() {
            let u = k as f64;
            let (l, r) = (closed.at(u - 1e-12), closed.at(u + 1e-12));
            assert!((closed.at(u).r[0] - p[0]).abs() < 1e-14 && (closed.at(u).r[1] - p[1]).abs() < 1e-14);
            for (a, b) in [(l.d1, r.d1), (l.d2, r.d2)] {
                assert!((a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9, "knot {k}");
            }
            // Curvature is geometric: the parameter's scale (a knot per point) does not change it.
            let curvature = Curve::Spline(closed.clone()).at(u + 0.5).curvature();
            assert!((curvature - 1.0).abs() < 1e-3, "knot {k}: {curvature}");
        }
        let open = Spline::new(ring[..10].to_vec(), false).unwrap();
        assert_eq!(open.at(0.0).d2, [0.0, 0.0]);
        assert!(open.at(9.0).d2.iter().all(|v| v.abs() < 1e-12));
        assert!(Spline::new(ring[..3].to_vec(), false).is_none(), "under 4 points");
    }

    /// The nearest point of a circle to an outside point is on the ray
    /// from the centre; of a line, the foot of the perpendicular.
    #[test]
    fn the_nearest_point_is_found() {
        let circle = Curve::Circle { centre: [1.0, 1.0], radius: 0.5, inside: false };
        let u = circle.nearest_anywhere([3.0, 1.0 + 2.0 * 3f64.sqrt()], 8).unwrap();
        assert!((u.rem_euclid(TAU) - TAU / 6.0).abs() < 1e-12, "{u}");
        let line = Curve::Line { at: [0.0, 0.0], direction: [1.0, 0.0] };
        assert_eq!(line.nearest_anywhere([0.3, 2.0], 1), Some(0.3));
    }
}
