//! Points to follow (`track`): a name from `points` (on the body its joints
//! or centre of mass put it on), or `{"name", "body", "at"}` for a point of
//! one body; and each tracked point's motion at a step, as results say it.

use super::{JointType, MechanismDto, PointRef, body_id};
use crate::engine::kinetostatics::{point_acceleration, point_motion};
use crate::engine::model::{BodyId, Mechanism};
use crate::i18n::Msg;
use crate::kind::quantity::Errors;
use serde::de::{self, Deserializer, MapAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use utoipa::openapi::RefOr;
use utoipa::openapi::schema::{ObjectBuilder, OneOfBuilder, Schema, Type};
use utoipa::{PartialSchema, ToSchema};

/// Most points one request may follow.
pub const MAX_TRACKED: usize = 100;

/// A point to follow: the name of a point of `points`, or a point of one body.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum TrackDto {
    Name(String),
    Point(TrackPoint),
}

/// A point of one body: `at` (a name from `points` or [x, y] in m, as drawn;
/// default the point called `name`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrackPoint {
    pub name: String,
    pub body: String,
    pub at: Option<PointRef>,
}

struct TrackVisitor;

impl<'de> Visitor<'de> for TrackVisitor {
    type Value = TrackDto;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("json-expect-track")
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<TrackDto, E> {
        Ok(TrackDto::Name(v.to_string()))
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<TrackDto, A::Error> {
        TrackPoint::deserialize(de::value::MapAccessDeserializer::new(map)).map(TrackDto::Point)
    }
}

impl<'de> Deserialize<'de> for TrackDto {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(TrackVisitor)
    }
}

impl PartialSchema for TrackDto {
    fn schema() -> RefOr<Schema> {
        let name = || ObjectBuilder::new().schema_type(Type::String).max_length(Some(super::NAME_MAX_LENGTH));
        let point = ObjectBuilder::new()
            .property("name", name())
            .property("body", name())
            .property("at", PointRef::schema())
            .required("name")
            .required("body")
            .description(Some("a point of one body; `at` defaults to the point called `name`"));
        OneOfBuilder::new().item(name().description(Some("the name of a point of `points`"))).item(point).into()
    }
}
impl ToSchema for TrackDto {}

/// A point resolved: its name, its body and where it was drawn.
#[derive(Clone, Debug)]
pub struct Tracked {
    pub name: String,
    pub body: BodyId,
    pub at: [f64; 2],
}

/// The tracked points of `dto`, each error at `at/K`.
pub fn resolve(dto: &MechanismDto, track: &[TrackDto], names: &[String], e: &mut Errors, at: &str) -> Vec<Tracked> {
    if track.len() > MAX_TRACKED {
        e.say(at, Msg::new("track-too-many").arg("max", MAX_TRACKED));
        return Vec::new();
    }
    let points = dto.points.clone().unwrap_or_default();
    let drawn = |e: &mut Errors, p: &PointRef, ptr: &str| match p {
        PointRef::Coords(c) if c.iter().all(|v| v.is_finite()) => Some(*c),
        PointRef::Coords(_) => e.refuse(ptr, Msg::new("mechanism-coordinates")),
        PointRef::Space(_) => e.refuse(ptr, Msg::new("mechanism-spatial-point")),
        PointRef::Name(n) => {
            points.get(n).copied().or_else(|| e.refuse(ptr, Msg::new("mechanism-unknown-point").arg("name", n)))
        }
    };
    let mut out = Vec::with_capacity(track.len());
    for (k, t) in track.iter().enumerate() {
        let ptr = format!("{at}/{k}");
        let found = match t {
            TrackDto::Name(n) => drawn(e, &PointRef::Name(n.clone()), &ptr)
                .and_then(|p| body_of(dto, n, names, e, &ptr).map(|b| Tracked { name: n.clone(), body: b, at: p })),
            TrackDto::Point(p) => {
                let unknown = super::unknown_body(names, &p.body);
                let body = body_id(names, &p.body).or_else(|| e.refuse(&format!("{ptr}/body"), unknown));
                let place = p.at.clone().unwrap_or_else(|| PointRef::Name(p.name.clone()));
                let pointer = if p.at.is_some() { format!("{ptr}/at") } else { format!("{ptr}/name") };
                let place = drawn(e, &place, &pointer);
                body.zip(place).map(|(body, at)| Tracked { name: p.name.clone(), body, at })
            }
        };
        out.extend(found);
    }
    out
}

/// The body a named point moves with: a moving body whose joint or centre
/// of mass is at it; a pin in a slot (two motions) must be told which.
pub(super) fn body_of(dto: &MechanismDto, point: &str, names: &[String], e: &mut Errors, ptr: &str) -> Option<BodyId> {
    let named = |p: &Option<PointRef>| matches!(p, Some(PointRef::Name(n)) if n == point);
    let joints: Vec<_> = dto.joints.iter().filter(|j| named(&j.at)).collect();
    if let Some(slot) = joints.iter().find(|j| matches!(j.kind, JointType::PinSlot)) {
        return e.refuse(ptr, Msg::new("track-pin").arg("point", point).arg("slot", &slot.name));
    }
    let on_joints = joints.iter().flat_map(|j| j.bodies.iter());
    let at_cg = dto.bodies.iter().filter(|b| named(&b.cg)).map(|b| &b.name);
    let moving = on_joints.chain(at_cg).filter_map(|b| body_id(names, b)).find(|b| *b != 0);
    let on_ground = joints.iter().any(|j| j.bodies.iter().any(|b| super::is_ground(b)));
    match moving {
        Some(b) => Some(b),
        None if on_ground => Some(0),
        None => e.refuse(ptr, Msg::new("track-no-body").arg("point", point)),
    }
}

/// A tracked point's motion at a step (m, m/s, m/s²).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct PointState {
    pub name: String,
    pub body: String,
    pub x: f64,
    pub y: f64,
    pub vx: f64,
    pub vy: f64,
    pub ax: f64,
    pub ay: f64,
}

/// Every tracked point's motion at (q, q̇, q̈).
pub fn states(m: &Mechanism, tracked: &[Tracked], [q, qd, qdd]: [&[f64]; 3]) -> Vec<PointState> {
    tracked
        .iter()
        .map(|t| {
            let (p, v) = point_motion(m, q, qd, (t.body, t.at));
            let a = point_acceleration(m, q, qd, qdd, (t.body, t.at));
            let body = m.bodies[t.body].name.clone();
            PointState { name: t.name.clone(), body, x: p[0], y: p[1], vx: v[0], vy: v[1], ax: a[0], ay: a[1] }
        })
        .collect()
}
