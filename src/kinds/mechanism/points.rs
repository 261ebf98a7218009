//! The points of a mechanism's wire form: a point named or given by its
//! coordinates, a body's point, coordinates, as the document states them.

use super::NAME_MAX_LENGTH;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use utoipa::openapi::RefOr;
use utoipa::openapi::schema::{ArrayBuilder, ObjectBuilder, OneOfBuilder, Schema, Type};
use utoipa::{PartialSchema, ToSchema};

/// A point: the name of a point of `points`, or coordinates [x, y] in m.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum PointRef {
    Name(String),
    Coords([f64; 2]),
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
        <[f64; 2]>::deserialize(de::value::SeqAccessDeserializer::new(seq)).map(PointRef::Coords)
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
            .item(coords_schema())
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
                .item(coords_schema())
        };
        ArrayBuilder::new()
            .prefix_items([Schema::from(body.description(Some("a body's name"))), point().into()])
            .items(point())
            .min_items(Some(2))
            .max_items(Some(2))
            .description(Some("[body, point]: a body's name, and one of its points (a name, or [x, y] in m)"))
            .into()
    }
}
impl ToSchema for BodyPoint {}

/// Coordinates `[x, y]` in m, as the document states them.
pub struct Coords;

impl PartialSchema for Coords {
    fn schema() -> RefOr<Schema> {
        coords_schema().into()
    }
}
impl ToSchema for Coords {}

fn coords_schema() -> ArrayBuilder {
    ArrayBuilder::new()
        .items(ObjectBuilder::new().schema_type(Type::Number))
        .min_items(Some(2))
        .max_items(Some(2))
        .description(Some("[x, y] in m"))
}
