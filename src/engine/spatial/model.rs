//! The spatial mechanism: bodies, joints, inputs and loads, as drawn.

use crate::engine::function::{Function, Side};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// Index of a body; 0 is the ground, b ≥ 1 is `bodies[b − 1]`.
pub type BodyId = usize;

/// A rigid body: mass m, inertia J′ about G in the drawn (ground) axes.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub name: String,
    pub mass: f64,
    pub inertia: Matrix3<f64>,
    /// G as drawn.
    pub cg: Vector3<f64>,
}

/// The lower pairs. Each axis is a unit vector as drawn, fixed in the
/// first body; the joint's point `at` is carried by both bodies.
#[derive(Clone, Debug, PartialEq)]
pub enum JointKind {
    /// One rotation about `axis` (class I: 5 rows).
    Revolute { axis: Vector3<f64> },
    /// One slide along `axis` (class I: 5 rows).
    Prismatic { axis: Vector3<f64> },
    /// A rotation about `axis` and a slide along it (class II: 4 rows).
    Cylindrical { axis: Vector3<f64> },
    /// Three rotations about `at` (class III: 3 rows); an input may
    /// prescribe the rotation about `axis`, where the other joints hold
    /// that axis (a shaft's thrust bearing driven by its motor).
    Spherical { axis: Option<Vector3<f64>> },
    /// The second body's `at` on the first's line through `at` along `axis`
    /// (the course's sphere in a cylinder, class IV: 2 rows): a
    /// self-aligning radial bearing.
    SphereInCylinder { axis: Vector3<f64> },
    /// Hooke's (Cardan) joint: rotations about `axes[0]`, fixed in the
    /// first body, and `axes[1]`, fixed in the second, perpendicular as
    /// drawn (class II: 4 rows).
    Universal { axes: [Vector3<f64>; 2] },
}

impl JointKind {
    /// The relative freedoms the pair leaves (its class).
    pub fn freedoms(&self) -> usize {
        match self {
            Self::Revolute { .. } | Self::Prismatic { .. } => 1,
            Self::Cylindrical { .. } | Self::Universal { .. } => 2,
            Self::Spherical { .. } => 3,
            Self::SphereInCylinder { .. } => 4,
        }
    }

    /// The rows it adds to Φ: 6 − its freedoms.
    pub fn rows(&self) -> usize {
        6 - self.freedoms()
    }

    /// The axis of the pair (the first of a universal's; a spherical's if given).
    pub fn axis(&self) -> Option<Vector3<f64>> {
        match self {
            Self::Revolute { axis }
            | Self::Prismatic { axis }
            | Self::Cylindrical { axis }
            | Self::SphereInCylinder { axis } => Some(*axis),
            Self::Universal { axes } => Some(axes[0]),
            Self::Spherical { axis } => *axis,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    pub name: String,
    /// `[first, second]`; its reaction is the one on the second.
    pub bodies: [BodyId; 2],
    pub at: Vector3<f64>,
    pub kind: JointKind,
}

/// Which of a joint's coordinates an input prescribes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coordinate {
    /// θ, the second body's rotation about the axis relative to the first,
    /// right-handed, 0 as drawn (rad).
    Rotation,
    /// s, the second body's `at` from the first's along the axis, 0 as
    /// drawn (m).
    Slide,
}

/// An input: a joint's coordinate prescribed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Input {
    pub joint: usize,
    pub coordinate: Coordinate,
}

/// Applied actions besides gravity.
#[derive(Clone, Debug, PartialEq)]
pub enum Load {
    /// A force (ground axes) at a point of a body (as drawn).
    Force { body: BodyId, at: Vector3<f64>, force: Vector3<f64> },
    /// A couple (ground axes) on a body.
    Torque { body: BodyId, torque: Vector3<f64> },
    /// A linear spring k with free length l₀ and a damper c between a point
    /// of each body (as drawn); it pulls them together when stretched.
    Spring { bodies: [BodyId; 2], at: [Vector3<f64>; 2], k: f64, length: f64, c: f64 },
}

/// A load as given: a force's size or a torque's a Function of the first
/// input's coordinate φ (and of its speed ω and of t, in dynamics).
#[derive(Clone, Debug)]
pub enum LoadLaw {
    /// A force of `magnitude` along the unit `direction` (ground axes) at the
    /// body's point `at` (as drawn).
    Force { body: BodyId, at: Vector3<f64>, direction: Vector3<f64>, magnitude: Function },
    /// A couple of `value` about the unit `axis` (ground axes).
    Torque { body: BodyId, axis: Vector3<f64>, value: Function },
    /// A load that does not vary (a spring, a damper).
    Fixed(Load),
}

impl LoadLaw {
    /// The load at φ and [ω, t].
    pub fn at(&self, phi: f64, state: [f64; 2]) -> Load {
        match self {
            Self::Force { body, at, direction, magnitude } => {
                Load::Force { body: *body, at: *at, force: direction * magnitude.eval_at(phi, Side::Right, state) }
            }
            Self::Torque { body, axis, value } => {
                Load::Torque { body: *body, torque: axis * value.eval_at(phi, Side::Right, state) }
            }
            Self::Fixed(load) => load.clone(),
        }
    }

    /// The load, where it does not vary (a constant force or torque, a spring, a damper).
    pub fn fixed(&self) -> Option<Load> {
        let constant = match self {
            Self::Force { magnitude: f, .. } | Self::Torque { value: f, .. } => f.constant().is_some(),
            Self::Fixed(_) => true,
        };
        constant.then(|| self.at(0.0, [0.0, 0.0]))
    }

    /// Whether it reads ω or t.
    pub fn uses_state(&self) -> bool {
        match self {
            Self::Force { magnitude: f, .. } | Self::Torque { value: f, .. } => f.uses_state(),
            Self::Fixed(_) => false,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Mechanism {
    /// The moving bodies, body b at `bodies[b − 1]`.
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub inputs: Vec<Input>,
    pub gravity: Vector3<f64>,
}

impl Mechanism {
    /// The moving bodies' count.
    pub fn n(&self) -> usize {
        self.bodies.len()
    }

    /// Rows of the joints (without the inputs').
    pub fn joint_rows(&self) -> usize {
        self.joints.iter().map(|j| j.kind.rows()).sum()
    }

    /// The first row of each joint in Φ, and the first of the inputs'.
    pub fn offsets(&self) -> (Vec<usize>, usize) {
        let mut at = 0;
        let offsets = self
            .joints
            .iter()
            .map(|j| {
                at += j.kind.rows();
                at - j.kind.rows()
            })
            .collect();
        (offsets, at)
    }

    /// G as drawn (the ground's origin for body 0).
    pub fn drawn_cg(&self, b: BodyId) -> Vector3<f64> {
        if b == 0 { Vector3::zeros() } else { self.bodies[b - 1].cg }
    }

    /// The drawing's size: the largest distance of a joint's point or a G
    /// from their centroid (1 m for a drawing of one point): the length
    /// that makes rotations and translations comparable in Φ_q.
    pub fn size(&self) -> f64 {
        let points: Vec<Vector3<f64>> =
            self.joints.iter().map(|j| j.at).chain(self.bodies.iter().map(|b| b.cg)).collect();
        let centroid = points.iter().sum::<Vector3<f64>>() / points.len().max(1) as f64;
        let size = points.iter().map(|p| (p - centroid).norm()).fold(0.0, f64::max);
        if size > 0.0 { size } else { 1.0 }
    }
}

/// Two unit vectors perpendicular to the unit `a` and to each other, (b, c)
/// with b × c = a: the first along the ground axis least aligned with a.
pub fn perpendiculars(a: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let mut e = Vector3::zeros();
    e[a.iamin()] = 1.0;
    let b = (e - a * a.dot(&e)).normalize();
    (b, a.cross(&b))
}

/// The mechanism's configuration: every moving body's G and orientation
/// (body b at index b − 1).
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    pub r: Vec<Vector3<f64>>,
    pub p: Vec<UnitQuaternion<f64>>,
}

impl Pose {
    /// As drawn: G where it is drawn, R = I.
    pub fn drawn(m: &Mechanism) -> Self {
        Self { r: m.bodies.iter().map(|b| b.cg).collect(), p: vec![UnitQuaternion::identity(); m.n()] }
    }

    /// R_b (I for the ground).
    pub fn rotation(&self, b: BodyId) -> Matrix3<f64> {
        if b == 0 { Matrix3::identity() } else { *self.p[b - 1].to_rotation_matrix().matrix() }
    }

    /// r_b (the origin for the ground).
    pub fn origin(&self, b: BodyId) -> Vector3<f64> {
        if b == 0 { Vector3::zeros() } else { self.r[b - 1] }
    }

    /// Where the point of body `b` drawn at `drawn` is now, and its arm s from G.
    pub fn point(&self, m: &Mechanism, b: BodyId, drawn: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let s = self.rotation(b) * (drawn - m.drawn_cg(b));
        (self.origin(b) + s, s)
    }

    /// The increments δ (six a body: δr, δθ) applied: r ← r + δr, p ← exp(δθ)·p.
    pub fn apply(&mut self, delta: &[f64]) {
        for (b, d) in delta.chunks_exact(6).enumerate() {
            self.r[b] += Vector3::new(d[0], d[1], d[2]);
            self.p[b] = UnitQuaternion::from_scaled_axis(Vector3::new(d[3], d[4], d[5])) * self.p[b];
        }
    }
}
