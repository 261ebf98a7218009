//! The points of a mechanism's wire form: a point named or given by its
//! coordinates, a body's point, coordinates, as the document states them.

use super::NAME_MAX_LENGTH;
use crate::kind::quantity::Quantity;
use crate::units::{self, Dim};
use serde::de::{self, Deserializer, SeqAccess, Unexpected, Visitor};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;
use utoipa::openapi::RefOr;
use utoipa::openapi::schema::{ArrayBuilder, ObjectBuilder, OneOfBuilder, Schema, Type};
use utoipa::{PartialSchema, ToSchema};

/// A point: the name of a point of `points`, or coordinates [x, y] (in
/// space [x, y, z]), each in m or a length with its unit (as `points`' are read).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum PointRef {
    Name(String),
    Coords([f64; 2]),
    /// A spatial mechanism's point.
    Space([f64; 3]),
}

struct PointVisitor;

impl<'de> Visitor<'de> for PointVisitor {
    type Value = PointRef;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("json-expect-point")
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<PointRef, E> {
        Ok(PointRef::Name(v.to_string()))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<PointRef, A::Error> {
        match Coordinates::deserialize(de::value::SeqAccessDeserializer::new(seq))? {
            Coordinates::Plane(c) => Ok(PointRef::Coords(c)),
            Coordinates::Space(c) => Ok(PointRef::Space(c)),
        }
    }
}

impl<'de> Deserialize<'de> for PointRef {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(PointVisitor)
    }
}

impl PartialSchema for PointRef {
    fn schema() -> RefOr<Schema> {
        OneOfBuilder::new()
            .item(
                ObjectBuilder::new()
                    .schema_type(Type::String)
                    .max_length(Some(NAME_MAX_LENGTH))
                    .description(Some("name of a point")),
            )
            .item(drawn_schema())
            .into()
    }
}
impl ToSchema for PointRef {}

/// `[body, point]`, a body's name and one of its points (a spring's or a
/// damper's end), as the document states it; read as `(String, PointRef)`.
/// Its `items` (what may follow the two, which `maxItems` forbids) are
/// either kind of entry rather than `false`: valid 3.1 either way, but
/// openapi-python-client refuses `items: false` and with it the document.
pub struct BodyPoint;

impl PartialSchema for BodyPoint {
    fn schema() -> RefOr<Schema> {
        let body = ObjectBuilder::new().schema_type(Type::String).max_length(Some(NAME_MAX_LENGTH));
        let point = || {
            OneOfBuilder::new()
                .item(ObjectBuilder::new().schema_type(Type::String).max_length(Some(NAME_MAX_LENGTH)))
                .item(drawn_schema())
        };
        ArrayBuilder::new()
            .prefix_items([Schema::from(body.description(Some("a body's name"))), point().into()])
            .items(point())
            .min_items(Some(2))
            .max_items(Some(2))
            .description(Some("[body, point]: a body's name, and one of its points (a name, or [x, y])"))
            .into()
    }
}
impl ToSchema for BodyPoint {}

/// A coordinate of a mechanism's `points`: a number (m), or a length with
/// its unit as a statement writes it (`"8 cm"`, `"0,08 m"`), read in m;
/// read as a [`Quantity`], and its text as a length.
struct Length(f64);

impl<'de> Deserialize<'de> for Length {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match Quantity::deserialize(d)? {
            Quantity::Number(v) => Ok(Length(v)),
            Quantity::Text(text) => match units::parse_as(&text, Dim::LENGTH) {
                Ok(m) if m.is_finite() => Ok(Length(m)),
                _ => Err(de::Error::invalid_value(Unexpected::Str(&text), &"json-expect-length")),
            },
        }
    }
}

/// Two coordinates or three, each a [`Length`].
enum Coordinates {
    Plane([f64; 2]),
    Space([f64; 3]),
}

impl<'de> Deserialize<'de> for Coordinates {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = Vec::<Length>::deserialize(d)?;
        match c[..] {
            [Length(x), Length(y)] => Ok(Self::Plane([x, y])),
            [Length(x), Length(y), Length(z)] => Ok(Self::Space([x, y, z])),
            // Four numbers or more: most likely [x, y] written with decimal commas.
            _ if c.len() > 3 => Err(de::Error::invalid_length(c.len(), &"json-expect-fewer")),
            _ => Err(de::Error::invalid_length(c.len(), &"json-expect-point")),
        }
    }
}

/// A mechanism's `points` as drawn: [x, y] of each (what a planar
/// mechanism reads, by `Deref`), and z of those given three coordinates
/// (a spatial mechanism's).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawnPoints {
    pub xy: BTreeMap<String, [f64; 2]>,
    pub z: BTreeMap<String, f64>,
}

impl std::ops::Deref for DrawnPoints {
    type Target = BTreeMap<String, [f64; 2]>;
    fn deref(&self) -> &Self::Target {
        &self.xy
    }
}

impl DrawnPoints {
    /// A point's [x, y, z], where it was given three coordinates.
    pub fn xyz(&self, name: &str) -> Option<[f64; 3]> {
        Some(self.xy.get(name).zip(self.z.get(name)).map(|([x, y], z)| [*x, *y, *z])).flatten()
    }
}

impl Serialize for DrawnPoints {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(self.xy.len()))?;
        for (name, [x, y]) in &self.xy {
            match self.z.get(name) {
                Some(z) => map.serialize_entry(name, &[x, y, z])?,
                None => map.serialize_entry(name, &[x, y])?,
            }
        }
        map.end()
    }
}

/// A mechanism's `points`, each coordinate a number (m) or a length with
/// its unit, read in m.
pub fn drawn<'de, D: Deserializer<'de>>(d: D) -> Result<Option<DrawnPoints>, D::Error> {
    let points: Option<BTreeMap<String, Coordinates>> = Option::deserialize(d)?;
    Ok(points.map(|p| {
        let mut drawn = DrawnPoints::default();
        for (name, c) in p {
            let [x, y] = match c {
                Coordinates::Plane(c) => c,
                Coordinates::Space([x, y, z]) => {
                    drawn.z.insert(name.clone(), z);
                    [x, y]
                }
            };
            drawn.xy.insert(name, [x, y]);
        }
        drawn
    }))
}

/// `points`' coordinates `[x, y]` as the document states them: each a
/// number in m, or a length with its unit.
pub struct DrawnCoords;

impl PartialSchema for DrawnCoords {
    fn schema() -> RefOr<Schema> {
        drawn_schema().into()
    }
}
impl ToSchema for DrawnCoords {}

/// Coordinates `[x, y]` in m, as the document states them.
pub struct Coords;

impl PartialSchema for Coords {
    fn schema() -> RefOr<Schema> {
        coords_schema().into()
    }
}
impl ToSchema for Coords {}

fn drawn_schema() -> ArrayBuilder {
    let length = OneOfBuilder::new()
        .item(ObjectBuilder::new().schema_type(Type::Number))
        .item(ObjectBuilder::new().schema_type(Type::String).description(Some("a length with its unit, \"8 cm\"")));
    ArrayBuilder::new()
        .items(length)
        .min_items(Some(2))
        .max_items(Some(3))
        .description(Some("[x, y], in space [x, y, z]: each in m, or a length with its unit (\"8 cm\", \"0,08 m\")"))
}

fn coords_schema() -> ArrayBuilder {
    ArrayBuilder::new()
        .items(ObjectBuilder::new().schema_type(Type::Number))
        .min_items(Some(2))
        .max_items(Some(2))
        .description(Some("[x, y] in m"))
}
