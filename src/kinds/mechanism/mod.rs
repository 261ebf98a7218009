//! Wire form of a planar mechanism (named points, bodies, joints) and its
//! conversion into the engine's model, with every error under its pointer.

mod assembly;
mod bodies;
mod contact;
mod dimensions;
pub mod drawing;
mod energy;
mod inertia;
mod inputs;
pub mod isometric;
mod joints;
mod loads;
pub mod motion;
pub mod motion3;
mod points;
mod reactions;
pub mod solution;
pub mod solution3;
pub mod spatial;
pub mod spatial_loads;
pub mod track;

pub use bodies::{body_id, is_ground, unknown_body};
pub use contact::{CircleDto, CurveDto, LineDto, PolarDto, SplineDto};
pub use dimensions::{Assembled, DimensionDto};
pub use energy::{ByName, EnergyDto, NameOrder};
pub use inertia::BodyInertia;
pub use inputs::{InputCoordinate, InputDto, Inputs, coordinate, machine_parts, spatial_machine_parts};
pub use loads::{LoadDto, LoadType, MAX_LOADS, convert_loads};
pub use points::{BodyPoint, Coords, DrawnCoords, DrawnPoints, PointRef};
pub use reactions::{ContactDto, Name, Names, ReactionDto, Reactions, contact_warnings, names};

use crate::engine::model::{Body, BodyId, Joint, JointKind, Mechanism, Pitch};
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// Most bodies, joints or points in one mechanism.
pub const MAX_ITEMS: usize = 200;
/// Longest name of a point, body or joint, in characters.
pub const NAME_MAX_LENGTH: usize = 100;

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BodyDto {
    #[schema(max_length = 100)]
    pub name: String,
    /// kg (≥ 0; default 0)
    #[schema(value_type = Option<Quantity>)]
    pub mass: Option<Quantity>,
    /// Inertia about the centre of mass, kg·m² (≥ 0; default 0); in space
    /// the tensor in the drawn axes, [Ixx, Iyy, Izz] or the 3×3 matrix.
    #[schema(value_type = Option<BodyInertia>)]
    pub inertia: Option<BodyInertia>,
    /// Centre of mass: required when the mass is not 0.
    #[schema(value_type = Option<PointRef>)]
    pub cg: Option<PointRef>,
}

/// Joint types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum JointType {
    Revolute,
    Prismatic,
    PinSlot,
    Gear,
    /// A higher pair: a curve of each body touching (`curves`, `rolling`).
    Contact,
    /// In space: a rotation about `axis` and a slide along it.
    Cylindrical,
    /// In space: three rotations about `at` (a rotation input turns about `axis`, if given).
    Spherical,
    /// In space: Hooke's (Cardan) joint, rotations about `axes` [a, b], a
    /// fixed in the first body and b in the second, perpendicular as drawn.
    Universal,
    /// In space: the second body's `at` on the first's line along `axis`
    /// (sphere in a cylinder, class IV: a self-aligning radial bearing).
    SphereInCylinder,
}

/// A joint between two bodies (`ground` is implicit). `axis` for prismatic and
/// pin_slot (in space also revolute, cylindrical and sphere_in_cylinder; a
/// spherical joint's optional `axis` is the one a rotation input turns
/// about: the angle about it from a perpendicular fixed in the first body
/// to the same perpendicular carried by the second), fixed in the first body: a prismatic joint's first body is the
/// guide and its second slides along it; a pin_slot's first body carries
/// the slot and its second the pin (swapping them is another mechanism).
/// `ratio` or `teeth` (and `internal`) and optional `carrier` for gears.
/// A contact's `curves` (the first body's, then the second's) must touch as
/// drawn; its `at` is where they do (optional: a hint where they touch at
/// several points).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct JointDto {
    #[schema(max_length = 100)]
    pub name: String,
    #[serde(rename = "type")]
    pub kind: JointType,
    #[schema(min_items = 2, max_items = 2)]
    pub bodies: Vec<String>,
    #[schema(value_type = Option<PointRef>)]
    pub at: Option<PointRef>,
    /// [x, y], in space [x, y, z]: any length (made unit).
    #[schema(min_items = 2, max_items = 3)]
    pub axis: Option<Vec<f64>>,
    /// A universal joint's axes [a, b] ([x, y, z] each): a fixed in the
    /// first body, b in the second, perpendicular as drawn.
    #[schema(min_items = 2, max_items = 2)]
    pub axes: Option<Vec<[f64; 3]>>,
    /// Gear: ω₂ − ω_c = ratio·(ω₁ − ω_c).
    pub ratio: Option<f64>,
    /// Gear: tooth numbers [z₁, z₂].
    #[schema(min_items = 2, max_items = 2)]
    pub teeth: Option<Vec<f64>>,
    /// Gear: internal mesh (default false).
    pub internal: Option<bool>,
    /// Gear: the carrier body (default ground).
    pub carrier: Option<String>,
    /// Gear module (m): with `teeth`, the reaction is the tooth force at the pitch point.
    #[schema(value_type = Option<Quantity>)]
    pub module: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub pressure_angle: Option<Quantity>,
    /// Coulomb friction: {"mu", "radius"} on a revolute joint, {"mu"} on a prismatic, pin-in-slot or contact joint.
    pub friction: Option<FrictionDto>,
    /// A prismatic joint's guide length, on the first body (which carries
    /// the guide), centred on `at` as drawn: its ends stay there while the
    /// second body slides (a stem in two bushings). The reaction is borne as
    /// two normal forces at the ends (the reaction's `ends`, N₁ behind `at`
    /// along the axis, N₂ ahead), each with its own friction μ|N₁| + μ|N₂|.
    #[schema(value_type = Option<Quantity>)]
    pub length: Option<Quantity>,
    /// Instead of `length`: a block of this length carried by the second
    /// body, centred on `at` as drawn, sliding in a long guide (a piston):
    /// its ends move with it.
    #[schema(value_type = Option<Quantity>)]
    pub slider_length: Option<Quantity>,
    /// Contact: the curve fixed in each body, in `bodies` order.
    #[schema(min_items = 2, max_items = 2)]
    pub curves: Option<Vec<CurveDto>>,
    /// Contact: rolling without slipping (equal arc lengths; default false, sliding).
    pub rolling: Option<bool>,
}

/// Coulomb friction of a joint.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct FrictionDto {
    /// Friction coefficient μ ≥ 0.
    #[schema(minimum = 0.0)]
    pub mu: f64,
    /// Pin radius (revolute joints only), m.
    #[schema(value_type = Option<Quantity>)]
    pub radius: Option<Quantity>,
}

/// A mechanism drawn in one assembled configuration, planar (see the
/// example of KinetostaticsRequest) or, with `"space": "spatial"`, in
/// three dimensions.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct MechanismDto {
    /// `planar` (the default) or `spatial`: points, axes and gravity with
    /// three coordinates, an inertia tensor, the spatial pairs.
    pub space: Option<MechanismSpace>,
    /// Named points in the drawn configuration: `{NAME: [x, y]}` (in space
    /// `[x, y, z]`), each coordinate in m or a length with its unit (`"8 cm"`).
    #[schema(value_type = Option<BTreeMap<String, DrawnCoords>>)]
    #[serde(default, deserialize_with = "points::drawn")]
    pub points: Option<DrawnPoints>,
    #[schema(min_items = 1, max_items = 200)]
    pub bodies: Vec<BodyDto>,
    #[schema(min_items = 1, max_items = 200)]
    pub joints: Vec<JointDto>,
    /// Gravitational acceleration [gx, gy] (in space [gx, gy, gz]), m/s² (default none).
    #[schema(min_items = 2, max_items = 3)]
    pub gravity: Option<Vec<f64>>,
    /// The statement's dimensions: `points` are then a sketch, moved as
    /// little as they can be (a point that cannot move — a pivot with the
    /// ground, a point of no moving body — weighs 10⁶ times another, and
    /// the sketch picks the branch) until every dimension holds; a body's
    /// `cg` given as [x, y] moves with its body; the result's
    /// `assembled_points` says where the points went.
    #[schema(max_items = 400)]
    pub dimensions: Option<Vec<DimensionDto>>,
}

/// The plane or space.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum MechanismSpace {
    #[default]
    Planar,
    Spatial,
}

/// The model and the names needed to read results back.
pub struct Converted {
    pub mechanism: Mechanism,
    pub body_names: Vec<String>,
}

impl MechanismDto {
    /// Converts to the engine model (without drivers), at pointer `at`.
    pub fn convert(&self, e: &mut Errors, at: &str) -> Option<Converted> {
        let before = e.list.len();
        if self.is_spatial() {
            return e.refuse(&format!("{at}/space"), Msg::new("mechanism-spatial-not-here"));
        }
        if self.bodies.len() > MAX_ITEMS || self.joints.len() > MAX_ITEMS {
            e.say(at, Msg::new("mechanism-too-many").arg("max", MAX_ITEMS));
        }
        let points = self.points.clone().unwrap_or_default();
        if let Some((name, _)) = points.iter().find(|(_, p)| !p.iter().all(|v| v.is_finite())) {
            e.say(&format!("{at}/points/{}", crate::kind::problem::escape(name)), Msg::new("mechanism-coordinates"));
        }
        for name in points.z.keys() {
            e.say(&format!("{at}/points/{}", crate::kind::problem::escape(name)), Msg::new("mechanism-spatial-point"));
        }
        let point = |e: &mut Errors, p: &PointRef, ptr: &str| match p {
            PointRef::Coords(c) if c.iter().all(|v| v.is_finite()) => Some(*c),
            PointRef::Coords(_) => e.refuse(ptr, Msg::new("mechanism-coordinates")),
            PointRef::Space(_) => e.refuse(ptr, Msg::new("mechanism-spatial-point")),
            PointRef::Name(n) if n.chars().count() > NAME_MAX_LENGTH => {
                e.refuse(ptr, Msg::new("field-at-most-characters").arg("max", NAME_MAX_LENGTH))
            }
            PointRef::Name(n) => match points.get(n) {
                Some(c) => Some(*c),
                None => e.refuse(ptr, Msg::new("mechanism-unknown-point").arg("name", n)),
            },
        };
        let mut names = vec!["ground".to_string()];
        let mut bodies = vec![Body { name: "ground".into(), mass: 0.0, inertia: 0.0, cg: [0.0, 0.0] }];
        for (k, b) in self.bodies.iter().enumerate() {
            let ptr = format!("{at}/bodies/{k}");
            e.short(&b.name, NAME_MAX_LENGTH, &format!("{ptr}/name"));
            if names.contains(&b.name) {
                e.say(&format!("{ptr}/name"), Msg::new("mechanism-duplicate-body").arg("name", &b.name));
            }
            names.push(b.name.clone());
            let mass = non_negative(e, b.mass.as_ref(), Dim::MASS, &format!("{ptr}/mass"));
            let given = b.inertia.as_ref().map(|i| i.scalar(e, &format!("{ptr}/inertia")));
            let inertia = match given {
                Some(None) => None,
                Some(q) => non_negative(e, q, Dim::INERTIA, &format!("{ptr}/inertia")),
                None => Some(0.0),
            };
            let cg = match &b.cg {
                Some(p) => point(e, p, &format!("{ptr}/cg")),
                None if mass.unwrap_or(0.0) > 0.0 => e.refuse(&ptr, Msg::new("mechanism-cg")),
                None => Some(self.first_joint_point(&b.name, &points).unwrap_or([0.0, 0.0])),
            };
            bodies.push(Body {
                name: b.name.clone(),
                mass: mass.unwrap_or(0.0),
                inertia: inertia.unwrap_or(0.0),
                cg: cg.unwrap_or([0.0; 2]),
            });
        }
        let body = |e: &mut Errors, n: &str, ptr: &str| match body_id(&names, n) {
            Some(i) => Some(i),
            None => e.refuse(ptr, unknown_body(&names, n)),
        };
        let size = self.size(&points);
        let mut joints = Vec::with_capacity(self.joints.len());
        for (k, j) in self.joints.iter().enumerate() {
            let ptr = format!("{at}/joints/{k}");
            e.short(&j.name, NAME_MAX_LENGTH, &format!("{ptr}/name"));
            if self.joints[..k].iter().any(|o| o.name == j.name) {
                e.say(&format!("{ptr}/name"), Msg::new("mechanism-duplicate-joint").arg("name", &j.name));
            }
            if j.bodies.len() != 2 {
                e.say(&format!("{ptr}/bodies"), Msg::new("joint-two-bodies"));
                continue;
            }
            let b0 = body(e, &j.bodies[0], &format!("{ptr}/bodies/0"));
            let b1 = body(e, &j.bodies[1], &format!("{ptr}/bodies/1"));
            if j.bodies[0] == j.bodies[1] {
                e.say(&format!("{ptr}/bodies"), Msg::new("joint-same-body"));
            }
            let at_point = match &j.at {
                Some(p) => point(e, p, &format!("{ptr}/at")),
                None if matches!(j.kind, JointType::Gear | JointType::Contact) => Some([0.0, 0.0]),
                None => e.refuse(&ptr, Msg::new("joint-at")),
            };
            let hint = j.at.as_ref().and(at_point);
            let (kind, at_point) = match j.kind {
                JointType::Contact => match contact::contact(e, j, hint, &point, size, &ptr) {
                    Some((kind, touching)) => (Some(kind), Some(touching)),
                    None => (None, at_point),
                },
                _ => (joints::joint_kind(e, j, &names, &ptr), at_point),
            };
            joints::not_for_others(e, j, &ptr);
            if let (Some(b0), Some(b1), Some(at_point), Some(kind)) = (b0, b1, at_point, kind) {
                let friction = joints::friction(e, j, &ptr);
                let length = joints::guide_length(e, j, &ptr);
                joints.push(Joint { name: j.name.clone(), kind, bodies: [b0, b1], at: at_point, friction, length });
            }
        }
        contact::mark_particles(&mut joints, |b| bodies[b].inertia);
        for (k, j) in self.joints.iter().enumerate() {
            if j.module.is_some() {
                self.pitch(e, k, &mut joints, &format!("{at}/joints/{k}"));
            }
        }
        let gravity = match self.gravity.as_deref() {
            None => [0.0, 0.0],
            Some([gx, gy]) if gx.is_finite() && gy.is_finite() => [*gx, *gy],
            Some(_) => e.refuse(&format!("{at}/gravity"), Msg::new("mechanism-gravity")).unwrap_or([0.0; 2]),
        };
        (e.list.len() == before).then(|| Converted {
            mechanism: Mechanism { bodies, joints, drivers: Vec::new(), gravity },
            body_names: names,
        })
    }

    /// Sets the pitch geometry of gear joint `k` (given a module): pitch radius of the
    /// second gear m·z₂/2 and the gears' centres, the points of their bearings.
    fn pitch(&self, e: &mut Errors, k: usize, joints: &mut [Joint], at: &str) {
        let dto = &self.joints[k];
        let Some(index) = joints.iter().position(|j| j.name == dto.name) else { return };
        let JointKind::Gear { carrier, .. } = joints[index].kind else { return };
        let module = dto.module.as_ref().and_then(|q| e.positive(q, Dim::LENGTH, &format!("{at}/module")));
        let Some(&[z1, z2]) = dto.teeth.as_deref() else {
            e.say(at, Msg::new("joint-gear-teeth"));
            return;
        };
        let alpha = match &dto.pressure_angle {
            Some(q) => e.angle(q, &format!("{at}/pressure_angle")),
            None => Some(20f64.to_radians()),
        };
        // A gear's centre: its revolute joint to the carrier, else to the ground, else any.
        let centre = |gear: BodyId| {
            let bearing = |other: Option<BodyId>| {
                joints.iter().find_map(|j| {
                    let mine = j.bodies.contains(&gear) && other.is_none_or(|o| j.bodies.contains(&o));
                    (j.kind == JointKind::Revolute && mine).then_some(j.at)
                })
            };
            bearing(Some(carrier)).or_else(|| bearing(Some(0))).or_else(|| bearing(None))
        };
        let bodies = joints[index].bodies;
        let (Some(c1), Some(c2)) = (centre(bodies[0]), centre(bodies[1])) else {
            e.say(at, Msg::new("joint-gear-bearings"));
            return;
        };
        let (Some(module), Some(alpha)) = (module, alpha) else { return };
        let internal = dto.internal.unwrap_or(false);
        let pitch = Pitch {
            centers: [c1, c2],
            radius: module * z2 / 2.0,
            pressure_angle: alpha,
            second_is_ring: internal && z2 > z1,
            internal,
        };
        if let JointKind::Gear { pitch: p, .. } = &mut joints[index].kind {
            *p = Some(pitch);
        }
    }

    /// The mechanism's size (m): the diagonal of the box holding its named
    /// points, for the tolerance of a drawing (1 m where it has none).
    fn size(&self, points: &BTreeMap<String, [f64; 2]>) -> f64 {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points.values().filter(|p| p.iter().all(|v| v.is_finite())) {
            for k in 0..2 {
                (lo[k], hi[k]) = (lo[k].min(p[k]), hi[k].max(p[k]));
            }
        }
        let diagonal = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
        if diagonal.is_finite() && diagonal > 0.0 { diagonal } else { 1.0 }
    }

    /// The point of the first joint that names this body (the cg of a massless link).
    fn first_joint_point(&self, body: &str, points: &BTreeMap<String, [f64; 2]>) -> Option<[f64; 2]> {
        self.joints.iter().filter(|j| j.bodies.iter().any(|b| b == body)).find_map(|j| match &j.at {
            Some(PointRef::Coords(c)) => Some(*c),
            Some(PointRef::Name(n)) => points.get(n).copied(),
            Some(PointRef::Space(_)) | None => None,
        })
    }
}

fn non_negative(e: &mut Errors, q: Option<&Quantity>, dim: Dim, at: &str) -> Option<f64> {
    let v = q.map_or(Some(0.0), |q| e.quantity(q, dim, at))?;
    if v >= 0.0 { Some(v) } else { e.refuse(at, Msg::new("mechanism-not-negative")) }
}
