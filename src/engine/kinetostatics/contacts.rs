//! What a contact does at a position, as a higher pair's questions ask it:
//! where the curves touch, the normal and tangential parts of the reaction,
//! the sliding velocity, each curve's radius of curvature there and, for a
//! follower, the pressure angle.
//!
//! Symbols: t the common unit tangent (the second curve's, or the first's
//! where the second is a point), n the normal pointing from the first body
//! into the second (out of the first curve where it is closed — into it
//! for `inside` — else into the second curve where that is closed, else
//! towards the second body's centre of mass); N = F·n with F the force on
//! the second body (N ≥ 0: they press on each other), F_t = F·t; the
//! sliding velocity (v₂ − v₁)·t of the two material points at the contact.

use super::Reaction;
use super::loads::point_motion_by;
use crate::engine::curves::{Curve, Domain, Local};
use crate::engine::model::{BodyId, JointKind, Mechanism, dot, perp, rotate_by};

/// A contact at one position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    pub joint: usize,
    /// Where the curves touch (ground frame).
    pub point: [f64; 2],
    pub normal: f64,
    pub tangential: f64,
    pub sliding_velocity: f64,
    /// The velocity of the material point at the contact of each body
    /// (the first's, the second's; ground frame).
    pub velocities: [[f64; 2]; 2],
    /// 1/κ of each curve there, signed as the curve turns (None: straight, or a point).
    pub curvature_radius: [Option<f64>; 2],
    /// The angle between the contact normal and the velocity of the
    /// follower's point there, where the second body turns or slides on
    /// the ground (rad, 0 to π/2; None otherwise or where it does not move).
    pub pressure_angle: Option<f64>,
    /// The contact has run off the end of an open curve (a spline's): the
    /// curves no longer touch as the equations say.
    pub off_end: bool,
    /// The curves overlap on both sides of the contact (their gap ½s²(k₂ −
    /// k₁)·n is negative, k the curvature vectors): a flat face on a
    /// concave stretch, a roller larger than the hollow it sits in. The
    /// bodies would touch elsewhere instead — another lobe — and the
    /// equations follow a contact that cannot be.
    pub overlap: bool,
    /// The contact jumped to this position from far off the point it was
    /// followed to (a sweep's continuation: [`crate::engine::kinematics::Configuration::jumped`]).
    pub jumped: bool,
    /// The bodies cut into each other here away from the contact, this
    /// deep (m): no contact outside both was found (a sweep's
    /// [`crate::engine::kinematics::Configuration::cuts`]).
    pub penetration: Option<f64>,
    /// Direct dynamics, a rolling contact with friction: whether it slips
    /// at this instant (None elsewhere: kinetostatics assumes it rolls).
    pub slipping: Option<bool>,
}

/// Contact joint k's frame at (q, q̇): where the curves touch, t, n, and
/// the velocities of both material points there (the first's, the second's).
pub struct Frame {
    pub point: [f64; 2],
    pub t: [f64; 2],
    pub n: [f64; 2],
    pub velocities: [[f64; 2]; 2],
}

impl Frame {
    pub fn of(m: &Mechanism, k: usize, q: &[f64], qd: &[f64]) -> Option<Self> {
        Self::from(m, &Touch::of(m, k, q, None)?, q, qd)
    }

    fn from(m: &Mechanism, touch: &Touch, q: &[f64], qd: &[f64]) -> Option<Self> {
        let t = touch.tangent()?;
        let motion = |side: usize| touch.motion(m, side, q, qd);
        let ((point, v2), (_, v1)) = (motion(1), motion(0));
        let n = normal_direction(m, q, touch, t, point);
        Some(Self { point, t, n, velocities: [v1, v2] })
    }

    /// (v₂ − v₁)·t.
    pub fn sliding(&self) -> f64 {
        let [v1, v2] = self.velocities;
        dot([v2[0] - v1[0], v2[1] - v1[1]], self.t)
    }

    /// N and F_t of a force F on the second body.
    pub fn parts(&self, f: [f64; 2]) -> [f64; 2] {
        [dot(f, self.n), dot(f, self.t)]
    }
}

/// Contact joint k's two curves at q, each evaluated once: `local[side]`
/// the curve's point and derivatives in its body's reference coordinates,
/// `trig[side]` the body's (sin θ, cos θ) ((0, 1) for the ground): a
/// contact's state needs them ~8 times a position and its friction's unit
/// 3 times, each a sine and a cosine for a circle or a cam.
pub struct Touch<'a> {
    curves: &'a [Curve; 2],
    bodies: [BodyId; 2],
    local: [Local; 2],
    trig: [(f64, f64); 2],
}

impl<'a> Touch<'a> {
    /// None for a joint that is not a contact. `trig`: every body's (sin θ,
    /// cos θ) at q where known (ground first, [`Mechanism::turns_into`]).
    pub fn of(m: &'a Mechanism, k: usize, q: &[f64], trig: Option<&[(f64, f64)]>) -> Option<Self> {
        let JointKind::Contact(c) = &m.joints[k].kind else { return None };
        let bodies = m.joints[k].bodies;
        let side = |s: usize| c.curves[s].at(m.contact_parameter(k, s, q).unwrap_or(0.0));
        let turn = |b: BodyId| match trig {
            Some(trig) => trig[b],
            None => m.column(b).map_or((0.0, 1.0), |col| q[col + 2].sin_cos()),
        };
        Some(Self { curves: &c.curves, bodies, local: [side(0), side(1)], trig: bodies.map(turn) })
    }

    /// The common unit tangent t (ground frame): the second curve's, or the
    /// first's where the second is a point.
    pub fn tangent(&self) -> Option<[f64; 2]> {
        let side = if self.local[1].d1 != [0.0, 0.0] { 1 } else { 0 };
        let t = self.along(side);
        let n = t[0].hypot(t[1]);
        (n > 0.0).then(|| [t[0] / n, t[1] / n])
    }

    /// Curve `side`'s direction of rising parameter (ground frame, not unit).
    fn along(&self, side: usize) -> [f64; 2] {
        rotate_by(self.trig[side], self.local[side].d1)
    }

    /// Where the curves touch as a point of body `side`, in its reference coordinates.
    pub fn point(&self, side: usize) -> [f64; 2] {
        self.local[side].r
    }

    /// (v₂ − v₁)·u, v the velocities of the material points at the contact.
    pub fn sliding(&self, m: &Mechanism, u: [f64; 2], q: &[f64], qd: &[f64]) -> f64 {
        let ((_, v2), (_, v1)) = (self.motion(m, 1, q, qd), self.motion(m, 0, q, qd));
        dot(u, [v2[0] - v1[0], v2[1] - v1[1]])
    }

    /// The ground position and velocity of body `side`'s material point at the contact.
    fn motion(&self, m: &Mechanism, side: usize, q: &[f64], qd: &[f64]) -> ([f64; 2], [f64; 2]) {
        point_motion_by(m, q, qd, (self.bodies[side], self.local[side].r), self.trig[side])
    }
}

/// The state of contact joint `r.joint` at (q, q̇) with its reaction `r`;
/// `trig` as [`Touch::of`] takes it.
pub fn contact_state(
    m: &Mechanism,
    (q, qd): (&[f64], &[f64]),
    trig: Option<&[(f64, f64)]>,
    r: &Reaction,
) -> Option<ContactState> {
    let k = r.joint;
    let JointKind::Contact(c) = &m.joints[k].kind else { return None };
    let touch = Touch::of(m, k, q, trig)?;
    let frame = Frame::from(m, &touch, q, qd)?;
    let [normal, tangential] = frame.parts([r.fx, r.fy]);
    let radius = |side: usize| {
        let kappa = touch.local[side].curvature();
        (kappa != 0.0).then(|| 1.0 / kappa)
    };
    Some(ContactState {
        joint: k,
        point: frame.point,
        normal,
        tangential,
        sliding_velocity: frame.sliding(),
        velocities: frame.velocities,
        curvature_radius: [radius(0), radius(1)],
        pressure_angle: follower(m, m.joints[k].bodies[1])
            .then(|| pressure_angle(frame.n, frame.velocities[1]))
            .flatten(),
        off_end: (0..2).any(|side| match (c.curves[side].domain(), m.contact_parameter(k, side, q)) {
            (Domain::Interval(a, b), Some(u)) => u < a - 1e-9 || u > b + 1e-9,
            _ => false,
        }),
        overlap: overlap(&touch, c.particle, frame.n),
        jumped: false,
        penetration: None,
        slipping: None,
    })
}

/// Whether the contact's curves overlap around it: (k₂ − k₁)·n < 0 beyond
/// rounding, k = κ·perp(t) each curve's curvature vector in the ground
/// (none for a point, nor for a particle, which is held on its curve both
/// ways).
fn overlap(touch: &Touch, particle: bool, n: [f64; 2]) -> bool {
    if particle || touch.curves.iter().any(|curve| curve.domain() == Domain::None) {
        return false;
    }
    let bend = |side: usize| {
        let l = &touch.local[side];
        let speed = l.d1[0].hypot(l.d1[1]);
        let t = rotate_by(touch.trig[side], [l.d1[0] / speed, l.d1[1] / speed]);
        let (kappa, left) = (l.curvature(), perp(t));
        [kappa * left[0], kappa * left[1]]
    };
    let (k1, k2) = (bend(0), bend(1));
    let scale = k1[0].hypot(k1[1]).max(k2[0].hypot(k2[1]));
    dot([k2[0] - k1[0], k2[1] - k1[1]], n) < -1e-9 * scale
}

/// n from the first body into the second (see the module's symbols).
fn normal_direction(m: &Mechanism, q: &[f64], touch: &Touch, t: [f64; 2], point: [f64; 2]) -> [f64; 2] {
    let (curves, j) = (touch.curves, touch.bodies[1]);
    let left = perp(t);
    // The tangent t is the second curve's unless it is a point; flip it into each curve's own direction.
    let along = |side: usize| if dot(touch.along(side), t) >= 0.0 { 1.0 } else { -1.0 };
    let inside = |c: &Curve| if matches!(c, Curve::Circle { inside: true, .. }) { -1.0 } else { 1.0 };
    let sign = if let Some(o) = curves[0].orientation() {
        // Out of the first curve: −perp(t′) for a counter-clockwise t′.
        -o * along(0) * inside(&curves[0])
    } else if let Some(o) = curves[1].orientation() {
        // Into the second curve: perp(t′) for a counter-clockwise t′.
        o * along(1) * inside(&curves[1])
    } else {
        let g = m.column(j).map_or(point, |col| [q[col], q[col + 1]]);
        if dot(left, [g[0] - point[0], g[1] - point[1]]) >= 0.0 { 1.0 } else { -1.0 }
    };
    [sign * left[0], sign * left[1]]
}

/// The second body turns or slides on the ground (a follower).
fn follower(m: &Mechanism, b: BodyId) -> bool {
    m.joints.iter().any(|joint| {
        joint.bodies.contains(&0)
            && joint.bodies.contains(&b)
            && matches!(joint.kind, JointKind::Revolute | JointKind::Prismatic { .. })
    })
}

/// The angle between the normal line and the velocity v (0 to π/2).
fn pressure_angle(n: [f64; 2], v: [f64; 2]) -> Option<f64> {
    let speed = v[0].hypot(v[1]);
    (speed > 0.0).then(|| (dot(n, v).abs() / speed).clamp(0.0, 1.0).acos())
}
