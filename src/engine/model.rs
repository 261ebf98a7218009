//! A planar mechanism in body coordinates.
//!
//! Symbols:
//! - body b ≥ 1 has coordinates q_b = (x_G, y_G, θ): its centre of mass G and
//!   its rotation θ from the drawn reference configuration (θ = 0 there);
//!   body 0 is the ground and has none;
//! - A(θ) is the rotation matrix, B(θ) = dA/dθ;
//! - a point P of body b is r_b + A(θ_b)·s_b with s_b = P_ref − G_ref, its
//!   position relative to G in the reference configuration;
//! - Φ(q, φ) = 0 are the joint constraints and the driving constraints of the
//!   inputs (coordinates φ), Φ_q their Jacobian.

mod scale;

use super::curves::{Curve, Domain, Local};
pub use super::numeric::plane::{cross, dot, perp};

/// Index of a body; 0 is the ground.
pub type BodyId = usize;

/// A rigid body: mass m, inertia I_G about its centre of mass G.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub name: String,
    pub mass: f64,
    pub inertia: f64,
    /// G in the reference configuration.
    pub cg: [f64; 2],
}

/// Kinds of joint between bodies `[first, second]`.
#[derive(Clone, Debug, PartialEq)]
pub enum JointKind {
    /// The two bodies share the point `at`.
    Revolute,
    /// No relative rotation; `at` of the second body moves along `axis` (unit,
    /// reference configuration) fixed in the first.
    Prismatic { axis: [f64; 2] },
    /// `at` of the second body moves along `axis` fixed in the first; rotation free.
    PinSlot { axis: [f64; 2] },
    /// ω₂ − ω_c = k·(ω₁ − ω_c); with `pitch`, the reaction is the tooth force.
    Gear { ratio: f64, carrier: BodyId, pitch: Option<Pitch> },
    /// A higher pair: a curve of each body, touching (`contact.rs` in
    /// constraints); each curve's parameter is a coordinate of its own.
    Contact(Box<Contact>),
}

/// The curves of a higher pair, the first body's and the second's, in
/// reference coordinates. They touch: one point in common and, where both
/// have a parameter, a common tangent (sliding: one freedom removed);
/// rolling without slipping, the arc lengths run on each curve are equal
/// too (two removed).
#[derive(Clone, Debug)]
pub struct Contact {
    pub curves: [Curve; 2],
    pub rolling: bool,
    /// Each curve's parameter where they touch as drawn (0 for a point).
    pub drawn: [f64; 2],
    /// The body whose curve is a point is a particle (a ring threaded on a
    /// rim, with no inertia and no other joint): its rotation, which nothing
    /// determines, is held as drawn by one more row, and Grübler's count
    /// leaves it out too.
    pub particle: bool,
}

impl PartialEq for Contact {
    /// Curves hold Functions, which have no equality: contacts are the same
    /// when they are the same object.
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self, other)
    }
}

impl Contact {
    /// The contact of `curves` touching at `at` as drawn (each curve's
    /// parameter there: its point nearest to `at`).
    pub fn new(curves: [Curve; 2], rolling: bool, at: [f64; 2]) -> Self {
        let drawn = curves.each_ref().map(|c| c.nearest_anywhere(at, 16).unwrap_or(0.0));
        let rolling = rolling && curves.iter().all(|c| c.domain() != Domain::None);
        Self { curves, rolling, drawn, particle: false }
    }

    /// Rows of its constraint equations: the coincidence (2), the common
    /// tangent of two curves (1), equal arc lengths when rolling (1), a
    /// particle's rotation (1).
    pub fn rows(&self) -> usize {
        2 + usize::from(self.parameters() == 2) + usize::from(self.rolling) + usize::from(self.particle)
    }

    /// The side (0 the first body's curve, 1 the second's) of its first
    /// curve with a parameter: the one whose arc length is the joint's coordinate.
    pub fn measured_side(&self) -> Option<usize> {
        (0..2).find(|&k| self.curves[k].domain() != Domain::None)
    }

    /// How many of its curves have a parameter (a point has none).
    pub fn parameters(&self) -> usize {
        self.curves.iter().filter(|c| c.domain() != Domain::None).count()
    }
}

/// Pitch geometry of a mesh, for the tooth force at the pitch point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pitch {
    /// Centres of the two gears (reference coordinates, points of each gear).
    pub centers: [[f64; 2]; 2],
    /// Pitch radius of the second gear, m.
    pub radius: f64,
    pub pressure_angle: f64,
    /// The second gear is the ring of an internal mesh.
    pub second_is_ring: bool,
    /// The mesh is internal.
    pub internal: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
    pub bodies: [BodyId; 2],
    /// The joint's point in the reference configuration.
    pub at: [f64; 2],
    pub friction: Option<Friction>,
    /// A prismatic joint's guide of length L, centred on `at`: its reaction
    /// is then borne as two normal forces at the guide's ends, each with its
    /// own friction (None: one normal force).
    pub length: Option<Guide>,
}

/// Where a prismatic joint's two bearing ends are, L apart and centred on
/// the joint's point as drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Guide {
    /// On the first body, which carries the guide: the ends stay there
    /// while the second body slides (a stem in two bushings).
    Fixed(f64),
    /// On the second body: a block of that length sliding in a long guide (a piston).
    Block(f64),
}

impl Guide {
    /// L (m).
    pub fn length(self) -> f64 {
        match self {
            Self::Fixed(l) | Self::Block(l) => l,
        }
    }
}

/// Coulomb friction of a joint: a revolute joint resists with a couple
/// μ·r·|R| (r the pin radius, R the reaction force); a prismatic or
/// pin-in-slot joint with a force μ·|N| along the slide (N the normal
/// reaction; μ(|N₁| + |N₂|) for a guide of a given length).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Friction {
    pub mu: f64,
    /// Pin radius (revolute joints), m.
    pub radius: f64,
}

/// What an input coordinate φ measures: its change from the drawn
/// configuration, plus the driver's `reference`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Coordinate {
    /// A joint's relative rotation (revolute) or its second body's
    /// displacement along the axis (prismatic).
    Joint(usize),
    /// The displacement of point `at` (reference coordinates) of `body`
    /// along the ground's unit `direction`.
    Point { body: BodyId, at: [f64; 2], direction: [f64; 2] },
    /// The absolute rotation of `body`.
    Body(BodyId),
}

/// An input: its coordinate equals φ − `reference`. Its driving effort acts
/// at the `actuator` joint (a torque at a revolute joint, a force along a
/// prismatic one's axis); without one, the effort is the generalized force
/// of the coordinate itself (the input joint's torque or force, a force on
/// the point along the direction, a torque on the body).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Driver {
    pub coordinate: Coordinate,
    pub reference: f64,
    pub actuator: Option<usize>,
}

impl Driver {
    /// A driven joint, its own actuator.
    pub fn joint(joint: usize, reference: f64) -> Self {
        Self { coordinate: Coordinate::Joint(joint), reference, actuator: None }
    }

    /// The effort acts elsewhere than on the input's own coordinate.
    pub fn actuated_elsewhere(&self) -> bool {
        self.actuator.is_some_and(|a| self.coordinate != Coordinate::Joint(a))
    }
}

/// A mechanism: bodies (index 0 is the ground, with no coordinates), joints,
/// drivers and gravity.
#[derive(Clone, Debug, PartialEq)]
pub struct Mechanism {
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub drivers: Vec<Driver>,
    pub gravity: [f64; 2],
}

impl Mechanism {
    /// Number of coordinates: 3 per moving body, then one per curve
    /// parameter of every contact.
    pub fn n_coordinates(&self) -> usize {
        self.n_body_coordinates() + self.n_parameters()
    }

    /// The bodies' coordinates, 3 per moving body (the curve parameters follow).
    pub fn n_body_coordinates(&self) -> usize {
        3 * (self.bodies.len() - 1)
    }

    /// Where contact joint k touches at q, as a point of body b (one of its
    /// two) in reference coordinates; None for another joint.
    pub fn contact_point(&self, k: usize, b: BodyId, q: &[f64]) -> Option<[f64; 2]> {
        self.contact_local(k, b, q).map(|l| l.r)
    }

    /// The direction along which a force on contact joint k's second body,
    /// at the contact, works on the joint's coordinate (the arc length run
    /// on its measured curve): that curve's unit tangent at q (ground frame,
    /// its parameter rising) where it is the first body's, the opposite
    /// where it is the second's (the curve then runs under the contact).
    pub fn contact_arc_direction(&self, k: usize, q: &[f64]) -> Option<[f64; 2]> {
        let JointKind::Contact(c) = &self.joints[k].kind else { return None };
        let side = c.measured_side()?;
        let b = self.joints[k].bodies[side];
        let theta = self.column(b).map_or(0.0, |c| q[c + 2]);
        let t = rotate(theta, self.contact_local(k, b, q)?.d1);
        let n = t[0].hypot(t[1]) * if side == 0 { 1.0 } else { -1.0 };
        (n != 0.0).then(|| [t[0] / n, t[1] / n])
    }

    /// The parameter of contact joint k's curve `side` (0 the first body's,
    /// 1 the second's) at q (0 for a point); None for another joint.
    pub fn contact_parameter(&self, k: usize, side: usize, q: &[f64]) -> Option<f64> {
        let JointKind::Contact(_) = &self.joints[k].kind else { return None };
        Some(self.contact_column(k, side).map_or(0.0, |c| q[c]))
    }

    /// The column of contact joint k's curve parameter `side` (None for a
    /// point, or another joint).
    pub fn contact_column(&self, k: usize, side: usize) -> Option<usize> {
        let JointKind::Contact(c) = &self.joints[k].kind else { return None };
        let before: usize = self.joints[..k].iter().map(|j| parameters_of(&j.kind)).sum();
        let column =
            self.n_body_coordinates() + before + usize::from(side == 1 && c.curves[0].domain() != Domain::None);
        (c.curves[side].domain() != Domain::None).then_some(column)
    }

    /// Contact joint k's curve of body b at q: its point and derivatives.
    fn contact_local(&self, k: usize, b: BodyId, q: &[f64]) -> Option<Local> {
        let JointKind::Contact(c) = &self.joints[k].kind else { return None };
        let side = usize::from(self.joints[k].bodies[1] == b);
        Some(c.curves[side].at(self.contact_parameter(k, side, q)?))
    }

    /// The contacts' curve parameters.
    pub fn n_parameters(&self) -> usize {
        self.joints.iter().map(|j| parameters_of(&j.kind)).sum()
    }

    /// The period of every curve parameter, in column order (None: a line's
    /// or an open curve's).
    pub fn parameter_periods(&self) -> Vec<Option<f64>> {
        let curves = self.joints.iter().filter_map(|j| match &j.kind {
            JointKind::Contact(c) => Some(c.curves.iter()),
            _ => None,
        });
        let period = |c: &Curve| match c.domain() {
            Domain::None => None,
            Domain::Periodic(p) => Some(Some(p)),
            _ => Some(None),
        };
        curves.flatten().filter_map(period).collect()
    }

    /// Coordinate k's entry of the mass matrix M = diag(m, m, I_G, …, 0 for
    /// the curve parameters, which carry no mass).
    pub fn mass_of(&self, k: usize) -> f64 {
        let Some(body) = self.bodies.get(k / 3 + 1).filter(|_| k < self.n_body_coordinates()) else { return 0.0 };
        if k % 3 == 2 { body.inertia } else { body.mass }
    }

    /// (sin θ, cos θ) of every body at q, ground first, into `out`.
    pub fn turns_into(&self, q: &[f64], out: &mut Vec<(f64, f64)>) {
        out.clear();
        out.extend((0..self.bodies.len()).map(|b| self.column(b).map_or((0.0, 1.0), |c| q[c + 2].sin_cos())));
    }

    /// Column of the first coordinate of body b (None for the ground).
    pub fn column(&self, b: BodyId) -> Option<usize> {
        (b > 0).then(|| 3 * (b - 1))
    }

    /// Rows of a joint's constraint equations.
    pub fn joint_rows(kind: &JointKind) -> usize {
        match kind {
            JointKind::Revolute | JointKind::Prismatic { .. } => 2,
            JointKind::PinSlot { .. } | JointKind::Gear { .. } => 1,
            JointKind::Contact(c) => c.rows(),
        }
    }

    /// s_b of a point given in reference coordinates.
    pub fn local(&self, b: BodyId, p: [f64; 2]) -> [f64; 2] {
        let g = self.bodies[b].cg;
        [p[0] - g[0], p[1] - g[1]]
    }

    /// The reference configuration q₀: every G where drawn, every θ = 0.
    /// A contact's curve parameters there are where its curves touch as drawn.
    pub fn reference_q(&self) -> Vec<f64> {
        let mut q: Vec<f64> = self.bodies[1..].iter().flat_map(|b| [b.cg[0], b.cg[1], 0.0]).collect();
        for j in &self.joints {
            if let JointKind::Contact(c) = &j.kind {
                let has = |k: &usize| c.curves[*k].domain() != Domain::None;
                q.extend((0..2).filter(has).map(|k| c.drawn[k]));
            }
        }
        q
    }

    /// Grübler's count for a planar mechanism: G = 3(N − 1) − 2·P_I − P_II,
    /// N counting the ground (a particle counting 2, not 3); P_I joints
    /// remove 2 freedoms, P_II joints 1.
    pub fn grubler(&self) -> Grubler {
        let [p1, p2] = self.pairs();
        let particles = self.joints.iter().filter(|j| matches!(&j.kind, JointKind::Contact(c) if c.particle)).count();
        let equations = 3 * (self.bodies.len() as i64 - 1) - particles as i64;
        let reactions = 2 * p1 + p2;
        Grubler { mobility: equations - reactions, equations, unknowns: reactions + self.drivers.len() as i64 }
    }
}

impl Mechanism {
    /// A coordinate is a length (a prismatic joint's, a point's), not an angle.
    pub fn is_length(&self, c: Coordinate) -> bool {
        match c {
            Coordinate::Joint(k) => matches!(self.joints[k].kind, JointKind::Prismatic { .. } | JointKind::Contact(_)),
            Coordinate::Point { .. } => true,
            Coordinate::Body(_) => false,
        }
    }

    /// The joints by class, [P_I, P_II]: a class-I pair (revolute,
    /// prismatic, a rolling contact) removes 2 freedoms, a class-II pair
    /// (pin in a slot, gears, a sliding contact) 1.
    pub fn pairs(&self) -> [i64; 2] {
        let first = |k: &JointKind| match k {
            JointKind::Revolute | JointKind::Prismatic { .. } => true,
            JointKind::Contact(c) => c.rolling,
            _ => false,
        };
        let p1 = self.joints.iter().filter(|j| first(&j.kind)).count() as i64;
        [p1, self.joints.len() as i64 - p1]
    }
}

/// Counting formulas: mobility, equilibrium equations 3(N − 1), and unknowns
/// (reaction components 2·P_I + P_II plus one driving action per input).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grubler {
    pub mobility: i64,
    pub equations: i64,
    pub unknowns: i64,
}

/// The curve parameters a joint adds as coordinates (a contact's).
fn parameters_of(kind: &JointKind) -> usize {
    if let JointKind::Contact(c) = kind { c.parameters() } else { 0 }
}

/// A(θ)·s.
pub fn rotate(theta: f64, s: [f64; 2]) -> [f64; 2] {
    rotate_by(theta.sin_cos(), s)
}

/// A(θ)·s with (sin θ, cos θ) known.
pub fn rotate_by((sn, cs): (f64, f64), s: [f64; 2]) -> [f64; 2] {
    [cs * s[0] - sn * s[1], sn * s[0] + cs * s[1]]
}

/// B(θ)·s = dA/dθ·s = A(θ)·(−s_y, s_x).
pub fn rotate_d(theta: f64, s: [f64; 2]) -> [f64; 2] {
    rotate(theta, [-s[1], s[0]])
}
