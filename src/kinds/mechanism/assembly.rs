//! What assembling a sketch needs to know of the mechanism: which points
//! cannot move (they weigh more in the least change), and a body's `cg`
//! given as coordinates carried from the sketch to the assembled figure
//! with its body.

use super::contact::CurveDto;
use super::{JointType, MechanismDto, PointRef};
use std::collections::{BTreeMap, BTreeSet};

/// How much more a point that cannot move weighs in the least change.
pub const FIXED_WEIGHT: f64 = 1e6;

impl MechanismDto {
    /// The weight of each of `names`: [`FIXED_WEIGHT`] for a point that
    /// cannot move — a revolute joint's with the ground, or a point of no
    /// moving body (named by no joint, centre of mass, load or moving
    /// curve) — and 1 for every other (a slider's pin on its guide, a pin
    /// in a slot, a point on a contact move like any other).
    pub(super) fn weights(&self, names: &[&String]) -> Vec<f64> {
        let pivot = |name: &str| {
            self.joints.iter().any(|j| {
                j.kind == JointType::Revolute
                    && named(j.at.as_ref(), name)
                    && j.bodies.iter().any(|b| super::is_ground(b))
            })
        };
        let moving = self.moving_points();
        names.iter().map(|n| if pivot(n) || !moving.contains(n.as_str()) { FIXED_WEIGHT } else { 1.0 }).collect()
    }

    /// The names of points some moving body holds.
    fn moving_points(&self) -> BTreeSet<&str> {
        fn name(p: Option<&PointRef>) -> Option<&str> {
            match p {
                Some(PointRef::Name(n)) => Some(n.as_str()),
                _ => None,
            }
        }
        let joints = self.joints.iter().filter_map(|j| name(j.at.as_ref()));
        let cgs = self.bodies.iter().filter_map(|b| name(b.cg.as_ref()));
        let curves = self.joints.iter().flat_map(|j| {
            let curves = j.curves.iter().flatten();
            curves.zip(&j.bodies).filter(|(_, b)| *b != "ground").filter_map(|(c, _)| name(curve_point(c)))
        });
        joints.chain(cgs).chain(curves).collect()
    }

    /// The names of body `body`'s points: where its joints are, the points of its curves.
    fn points_of(&self, body: &str) -> Vec<&str> {
        let mut out = Vec::new();
        for j in self.joints.iter().filter(|j| j.bodies.iter().any(|b| b == body)) {
            if let Some(PointRef::Name(n)) = &j.at {
                out.push(n.as_str());
            }
            let curves = j.curves.iter().flatten().zip(&j.bodies).filter(|(_, b)| *b == body);
            out.extend(curves.filter_map(|(c, _)| match curve_point(c) {
                Some(PointRef::Name(n)) => Some(n.as_str()),
                _ => None,
            }));
        }
        out
    }

    /// A copy whose bodies' `cg` given as [x, y] are carried from the
    /// `sketch` to the `assembled` points by their body's rigid motion: the rotation and
    /// translation that best carry the body's named points from one to the
    /// other (least squares; a translation alone for a body of one point).
    pub(super) fn carried(
        mut self,
        sketch: &BTreeMap<String, [f64; 2]>,
        assembled: &BTreeMap<String, [f64; 2]>,
    ) -> Self {
        let motion = |body: &str| {
            let pairs: Vec<([f64; 2], [f64; 2])> =
                self.points_of(body).iter().filter_map(|n| Some((*sketch.get(*n)?, *assembled.get(*n)?))).collect();
            Rigid::fit(&pairs)
        };
        let cgs: Vec<Option<Rigid>> = self.bodies.iter().map(|b| motion(&b.name)).collect();
        for (b, m) in self.bodies.iter_mut().zip(cgs) {
            if let (Some(PointRef::Coords(c)), Some(m)) = (&mut b.cg, m) {
                *c = m.apply(*c);
            }
        }
        self
    }
}

/// The point that places a curve in its body (a point's, a line's, a centre).
pub(super) fn curve_point(c: &CurveDto) -> Option<&PointRef> {
    match c {
        CurveDto::Point(p) => Some(p),
        CurveDto::Line(l) => Some(&l.through),
        CurveDto::Circle(c) => Some(&c.center),
        CurveDto::Polar(p) => Some(&p.center),
        CurveDto::Cam(c) => Some(&c.center),
        CurveDto::Spline(_) => None,
    }
}

fn named(p: Option<&PointRef>, name: &str) -> bool {
    matches!(p, Some(PointRef::Name(n)) if n == name)
}

/// A plane rigid motion: x ↦ R(θ)(x − from) + to.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rigid {
    from: [f64; 2],
    to: [f64; 2],
    cos: f64,
    sin: f64,
}

impl Rigid {
    /// The least-squares motion carrying each pair's first point to its
    /// second (Kabsch in the plane: the centroids, and the angle of
    /// Σ p′ × q′ against Σ p′ · q′); None for no pairs.
    pub(super) fn fit(pairs: &[([f64; 2], [f64; 2])]) -> Option<Self> {
        let n = pairs.len() as f64;
        if pairs.is_empty() {
            return None;
        }
        let mean = |k: usize, side: usize| pairs.iter().map(|p| [p.0, p.1][side][k]).sum::<f64>() / n;
        let (from, to) = ([mean(0, 0), mean(1, 0)], [mean(0, 1), mean(1, 1)]);
        let (mut cross, mut dot) = (0.0, 0.0);
        for (p, q) in pairs {
            let (p, q) = ([p[0] - from[0], p[1] - from[1]], [q[0] - to[0], q[1] - to[1]]);
            cross += p[0] * q[1] - p[1] * q[0];
            dot += p[0] * q[0] + p[1] * q[1];
        }
        let angle = if cross == 0.0 && dot == 0.0 { 0.0 } else { cross.atan2(dot) };
        Some(Self { from, to, cos: angle.cos(), sin: angle.sin() })
    }

    pub(super) fn apply(&self, x: [f64; 2]) -> [f64; 2] {
        let d = [x[0] - self.from[0], x[1] - self.from[1]];
        [self.to[0] + self.cos * d[0] - self.sin * d[1], self.to[1] + self.sin * d[0] + self.cos * d[1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two points turned by 30° about (1, 2) and moved by (0.5, −1): the
    /// fit is that motion, and carries a third point as it (closed form).
    #[test]
    fn a_rigid_motion_is_recovered_from_two_points() {
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        let truth = |p: [f64; 2]| {
            let d = [p[0] - 1.0, p[1] - 2.0];
            [1.5 + c * d[0] - s * d[1], 1.0 + s * d[0] + c * d[1]]
        };
        let (a, b, g) = ([0.0, 0.0], [2.0, 1.0], [0.7, 0.4]);
        let fit = Rigid::fit(&[(a, truth(a)), (b, truth(b))]).unwrap();
        let (got, want) = (fit.apply(g), truth(g));
        assert!((got[0] - want[0]).abs() < 1e-14 && (got[1] - want[1]).abs() < 1e-14, "{got:?} against {want:?}");
    }
}
