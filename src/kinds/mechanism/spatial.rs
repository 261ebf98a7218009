//! A mechanism in space (`"space": "spatial"`) into the spatial engine's
//! model: points [x, y, z], inertia tensors, the spatial pairs, each error
//! under its pointer. A planar pair (pin in a slot, gear, contact), a
//! planar field (friction, a guide's length, curves) or `dimensions` is
//! refused at its pointer.

use super::{
    InputCoordinate, InputDto, JointDto, JointType, MAX_ITEMS, MechanismDto, NAME_MAX_LENGTH, PointRef, non_negative,
};
use crate::engine::spatial::{Body, BodyId, Input, Joint, JointKind, Mechanism};
use crate::i18n::Msg;
use crate::kind::problem::escape;
use crate::kind::quantity::Errors;
use crate::units::Dim;
use nalgebra::{Matrix3, Vector3};

/// Two axes of a universal joint are perpendicular within this cosine.
const PERPENDICULAR: f64 = 1e-6;

/// The spatial model (without inputs) and the names to read results back.
pub struct SpatialConverted {
    pub mechanism: Mechanism,
    /// The bodies' names, the ground's first.
    pub body_names: Vec<String>,
}

impl MechanismDto {
    /// Whether the mechanism says it is spatial.
    pub fn is_spatial(&self) -> bool {
        self.space == Some(super::MechanismSpace::Spatial)
    }

    /// Converts a spatial mechanism at pointer `at`.
    pub fn spatial(&self, e: &mut Errors, at: &str) -> Option<SpatialConverted> {
        let before = e.list.len();
        if self.bodies.len() > MAX_ITEMS || self.joints.len() > MAX_ITEMS {
            e.say(at, Msg::new("mechanism-too-many").arg("max", MAX_ITEMS));
        }
        if self.dimensions.is_some() {
            e.say(&format!("{at}/dimensions"), Msg::new("mechanism-spatial-dimensions"));
        }
        let points = self.points.clone().unwrap_or_default();
        for (name, xy) in points.iter() {
            let ptr = format!("{at}/points/{}", escape(name));
            match points.xyz(name) {
                None => e.say(&ptr, Msg::new("mechanism-planar-point")),
                Some(p) if !p.iter().all(|v| v.is_finite()) || !xy.iter().all(|v| v.is_finite()) => {
                    e.say(&ptr, Msg::new("mechanism-coordinates"))
                }
                Some(_) => {}
            }
        }
        let point = |e: &mut Errors, p: &PointRef, ptr: &str| self.point_in_space(e, p, ptr);
        let mut names = vec!["ground".to_string()];
        let mut bodies = Vec::with_capacity(self.bodies.len());
        for (k, b) in self.bodies.iter().enumerate() {
            let ptr = format!("{at}/bodies/{k}");
            e.short(&b.name, NAME_MAX_LENGTH, &format!("{ptr}/name"));
            if names.contains(&b.name) {
                e.say(&format!("{ptr}/name"), Msg::new("mechanism-duplicate-body").arg("name", &b.name));
            }
            names.push(b.name.clone());
            let mass = non_negative(e, b.mass.as_ref(), Dim::MASS, &format!("{ptr}/mass"));
            let inertia = match &b.inertia {
                Some(i) => i.tensor(e, &format!("{ptr}/inertia")),
                None => Some(Matrix3::zeros()),
            };
            let cg = match &b.cg {
                Some(p) => point(e, p, &format!("{ptr}/cg")),
                None if mass.unwrap_or(0.0) > 0.0 => e.refuse(&ptr, Msg::new("mechanism-cg")),
                None => Some(self.first_joint_point_in_space(&b.name, e)),
            };
            bodies.push(Body {
                name: b.name.clone(),
                mass: mass.unwrap_or(0.0),
                inertia: inertia.unwrap_or_else(Matrix3::zeros),
                cg: cg.unwrap_or_else(Vector3::zeros),
            });
        }
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
            let body = |e: &mut Errors, b: usize| match super::body_id(&names, &j.bodies[b]) {
                Some(i) => Some(i as BodyId),
                None => e.refuse(&format!("{ptr}/bodies/{b}"), super::unknown_body(&names, &j.bodies[b])),
            };
            let (b0, b1) = (body(e, 0), body(e, 1));
            if j.bodies[0] == j.bodies[1] {
                e.say(&format!("{ptr}/bodies"), Msg::new("joint-same-body"));
            }
            let at_point = match &j.at {
                Some(p) => point(e, p, &format!("{ptr}/at")),
                None => e.refuse(&ptr, Msg::new("joint-at")),
            };
            not_spatial(e, j, &ptr);
            let kind = kind(e, j, &ptr);
            if let (Some(b0), Some(b1), Some(at_point), Some(kind)) = (b0, b1, at_point, kind) {
                joints.push(Joint { name: j.name.clone(), bodies: [b0, b1], at: at_point, kind });
            }
        }
        let gravity = match self.gravity.as_deref() {
            None => Some(Vector3::zeros()),
            Some([x, y, z]) if [x, y, z].iter().all(|v| v.is_finite()) => Some(Vector3::new(*x, *y, *z)),
            Some(_) => e.refuse(&format!("{at}/gravity"), Msg::new("mechanism-gravity-spatial")),
        };
        if e.list.len() > before {
            return None;
        }
        let mechanism = Mechanism { bodies, joints, inputs: Vec::new(), gravity: gravity? };
        Some(SpatialConverted { mechanism, body_names: names })
    }

    /// A point [x, y, z] given or named (a name given two coordinates is
    /// said at its own pointer under `points`, not here).
    pub fn point_in_space(&self, e: &mut Errors, p: &PointRef, ptr: &str) -> Option<Vector3<f64>> {
        let points = self.points.as_ref();
        match p {
            PointRef::Space(c) if c.iter().all(|v| v.is_finite()) => Some(Vector3::from(*c)),
            PointRef::Space(_) => e.refuse(ptr, Msg::new("mechanism-coordinates")),
            PointRef::Coords(_) => e.refuse(ptr, Msg::new("mechanism-planar-point")),
            PointRef::Name(n) if n.chars().count() > NAME_MAX_LENGTH => {
                e.refuse(ptr, Msg::new("field-at-most-characters").arg("max", NAME_MAX_LENGTH))
            }
            PointRef::Name(n) => match (points.and_then(|p| p.get(n)), points.and_then(|p| p.xyz(n))) {
                (_, Some(c)) => Some(Vector3::from(c)),
                (Some(_), None) => None,
                (None, _) => e.refuse(ptr, Msg::new("mechanism-unknown-point").arg("name", n)),
            },
        }
    }

    /// The point of the first joint that names this body (the cg of a massless link).
    fn first_joint_point_in_space(&self, body: &str, e: &mut Errors) -> Vector3<f64> {
        let at = self.joints.iter().filter(|j| j.bodies.iter().any(|b| b == body)).find_map(|j| j.at.as_ref());
        let mut quiet = Errors::new(&e.limits);
        at.and_then(|p| self.point_in_space(&mut quiet, p, "")).unwrap_or_else(Vector3::zeros)
    }
}

/// A unit vector from a finite, non-zero [x, y, z] at `at`.
pub fn unit(e: &mut Errors, v: &[f64], at: &str) -> Option<Vector3<f64>> {
    match v {
        [x, y, z] if [x, y, z].iter().all(|c| c.is_finite()) => {
            // Scaled by its largest component first: the norm of [1e300, 0, 0] is finite.
            let v = Vector3::new(*x, *y, *z);
            let largest = v.amax();
            if largest > 0.0 {
                Some((v / largest).normalize())
            } else {
                e.refuse(at, Msg::new("mechanism-vector-spatial"))
            }
        }
        _ => e.refuse(at, Msg::new("mechanism-vector-spatial")),
    }
}

/// The spatial pair a joint is, with its axis or axes.
fn kind(e: &mut Errors, j: &JointDto, at: &str) -> Option<JointKind> {
    let axis = |e: &mut Errors| match j.axis.as_deref() {
        Some(v) => unit(e, v, &format!("{at}/axis")),
        None => e.refuse(at, Msg::new("joint-axis")),
    };
    match j.kind {
        JointType::Revolute => axis(e).map(|axis| JointKind::Revolute { axis }),
        JointType::Prismatic => axis(e).map(|axis| JointKind::Prismatic { axis }),
        JointType::Cylindrical => axis(e).map(|axis| JointKind::Cylindrical { axis }),
        JointType::SphereInCylinder => axis(e).map(|axis| JointKind::SphereInCylinder { axis }),
        JointType::Spherical => match j.axis.as_deref() {
            None => Some(JointKind::Spherical { axis: None }),
            Some(v) => unit(e, v, &format!("{at}/axis")).map(|a| JointKind::Spherical { axis: Some(a) }),
        },
        JointType::Universal => {
            if j.axis.is_some() {
                e.say(&format!("{at}/axis"), Msg::new("joint-universal-axes"));
            }
            let Some([a, b]) = j.axes.as_deref() else { return e.refuse(at, Msg::new("joint-universal-axes")) };
            let a = unit(e, a, &format!("{at}/axes/0"));
            let b = unit(e, b, &format!("{at}/axes/1"));
            let (a, b) = (a?, b?);
            if a.dot(&b).abs() > PERPENDICULAR {
                return e.refuse(&format!("{at}/axes"), Msg::new("joint-universal-perpendicular"));
            }
            Some(JointKind::Universal { axes: [a, b] })
        }
        JointType::PinSlot | JointType::Gear | JointType::Contact => {
            e.refuse(&format!("{at}/type"), Msg::new("joint-planar-type"))
        }
    }
}

/// The planar joints' fields, each refused at its pointer.
fn not_spatial(e: &mut Errors, j: &JointDto, at: &str) {
    let given = [
        ("ratio", j.ratio.is_some()),
        ("teeth", j.teeth.is_some()),
        ("internal", j.internal.is_some()),
        ("carrier", j.carrier.is_some()),
        ("module", j.module.is_some()),
        ("pressure_angle", j.pressure_angle.is_some()),
        ("friction", j.friction.is_some()),
        ("length", j.length.is_some()),
        ("slider_length", j.slider_length.is_some()),
        ("curves", j.curves.is_some()),
        ("rolling", j.rolling.is_some()),
    ];
    for (field, _) in given.iter().filter(|(_, g)| *g) {
        e.say(&format!("{at}/{field}"), Msg::new("joint-not-spatial"));
    }
}

/// The joint and coordinate an input names in space.
pub fn joint_coordinate(e: &mut Errors, m: &Mechanism, input: &InputDto, at: &str) -> Option<Input> {
    use crate::engine::spatial::Coordinate;
    for (field, given) in
        [("point", input.point.is_some()), ("body", input.body.is_some()), ("direction", input.direction.is_some())]
    {
        if given {
            e.say(&format!("{at}/{field}"), Msg::new("input-spatial-joint"));
        }
    }
    let Some(name) = &input.joint else { return e.refuse(at, Msg::new("input-spatial-joint")) };
    let Some(joint) = m.joints.iter().position(|j| &j.name == name) else {
        return e.refuse(&format!("{at}/joint"), Msg::new("mechanism-unknown-joint").arg("name", name));
    };
    let asked = input.coordinate.map(|c| match c {
        InputCoordinate::Rotation => Coordinate::Rotation,
        InputCoordinate::Slide => Coordinate::Slide,
    });
    let coordinate = match (&m.joints[joint].kind, asked) {
        (JointKind::Revolute { .. } | JointKind::Spherical { axis: Some(_) }, None | Some(Coordinate::Rotation)) => {
            Coordinate::Rotation
        }
        (JointKind::Prismatic { .. }, None | Some(Coordinate::Slide)) => Coordinate::Slide,
        (JointKind::Cylindrical { .. }, Some(c)) => c,
        (JointKind::Cylindrical { .. }, None) => return e.refuse(at, Msg::new("input-cylindrical-coordinate")),
        (_, Some(_)) => return e.refuse(&format!("{at}/coordinate"), Msg::new("input-spatial-coordinate")),
        (_, None) => return e.refuse(&format!("{at}/joint"), Msg::new("input-spatial-coordinate")),
    };
    Some(Input { joint, coordinate })
}
