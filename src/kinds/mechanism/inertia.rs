//! A body's `inertia` as written: a number or a quantity about the cg (in
//! the plane), or in space the tensor about the cg in the drawn axes, as
//! [Ixx, Iyy, Izz] for principal axes along x, y, z or as the 3×3 matrix.

use crate::i18n::Msg;
use crate::kind::quantity::{Errors, Quantity};
use crate::units::Dim;
use nalgebra::Matrix3;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use utoipa::openapi::RefOr;
use utoipa::openapi::schema::{ArrayBuilder, ObjectBuilder, OneOfBuilder, Schema, Type};
use utoipa::{PartialSchema, ToSchema};

/// The moments of inertia, as written.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum BodyInertia {
    /// I_G about the cg, kg·m² (a planar body's).
    Scalar(Quantity),
    /// [Ixx, Iyy, Izz] about the cg, each kg·m² or a quantity.
    Principal([Quantity; 3]),
    /// The symmetric tensor about the cg, kg·m².
    Tensor([[f64; 3]; 3]),
}

/// One entry of `[…]`: a quantity (a principal moment) or a row of numbers.
#[derive(Deserialize)]
#[serde(untagged)]
enum Entry {
    Row([f64; 3]),
    Moment(Quantity),
}

struct InertiaVisitor;

impl<'de> Visitor<'de> for InertiaVisitor {
    type Value = BodyInertia;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("json-expect-inertia")
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<BodyInertia, E> {
        Ok(BodyInertia::Scalar(Quantity::Number(v)))
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<BodyInertia, E> {
        self.visit_f64(v as f64)
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<BodyInertia, E> {
        self.visit_f64(v as f64)
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<BodyInertia, E> {
        Quantity::deserialize(de::value::StrDeserializer::<E>::new(v)).map(BodyInertia::Scalar)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<BodyInertia, A::Error> {
        let entries = Vec::<Entry>::deserialize(de::value::SeqAccessDeserializer::new(seq))?;
        match entries.as_slice() {
            [Entry::Row(a), Entry::Row(b), Entry::Row(c)] => Ok(BodyInertia::Tensor([*a, *b, *c])),
            [Entry::Moment(a), Entry::Moment(b), Entry::Moment(c)] => {
                Ok(BodyInertia::Principal([a.clone(), b.clone(), c.clone()]))
            }
            _ => Err(de::Error::invalid_length(entries.len(), &"json-expect-inertia")),
        }
    }
}

impl<'de> Deserialize<'de> for BodyInertia {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(InertiaVisitor)
    }
}

impl PartialSchema for BodyInertia {
    /// One array form whose items are moments or rows (generators type two
    /// array forms of one union as one list, and then contradict themselves).
    fn schema() -> RefOr<Schema> {
        let number = || ObjectBuilder::new().schema_type(Type::Number);
        let text = || ObjectBuilder::new().schema_type(Type::String).description(Some("with its unit, \"0,02 kg m2\""));
        let row = ArrayBuilder::new().items(number()).min_items(Some(3)).max_items(Some(3));
        let item = OneOfBuilder::new().item(number()).item(text()).item(row.description(Some("a row of the tensor")));
        OneOfBuilder::new()
            .item(number().description(Some("I_G about the cg, kg·m² (a planar body)")))
            .item(text().description(Some("I_G with its unit (a planar body)")))
            .item(ArrayBuilder::new().items(item).min_items(Some(3)).max_items(Some(3)).description(Some(
                "in space: [Ixx, Iyy, Izz] about the cg (principal axes along x, y, z), or the symmetric tensor's three rows, kg·m²",
            )))
            .into()
    }
}
impl ToSchema for BodyInertia {}

impl BodyInertia {
    /// A planar body's I_G (a tensor refused at `at`).
    pub fn scalar<'a>(&'a self, e: &mut Errors, at: &str) -> Option<&'a Quantity> {
        match self {
            Self::Scalar(q) => Some(q),
            _ => e.refuse(at, Msg::new("mechanism-inertia-planar")),
        }
    }

    /// A spatial body's tensor about its cg: symmetric, its principal
    /// moments non-negative and each at most the sum of the other two.
    pub fn tensor(&self, e: &mut Errors, at: &str) -> Option<Matrix3<f64>> {
        let j = match self {
            Self::Scalar(_) => return e.refuse(at, Msg::new("mechanism-inertia-spatial")),
            Self::Principal(q) => {
                let moments: Vec<Option<f64>> =
                    q.iter().enumerate().map(|(k, q)| e.quantity(q, Dim::INERTIA, &format!("{at}/{k}"))).collect();
                let [Some(a), Some(b), Some(c)] = moments[..] else { return None };
                Matrix3::from_diagonal(&nalgebra::Vector3::new(a, b, c))
            }
            Self::Tensor(rows) => Matrix3::from_fn(|r, c| rows[r][c]),
        };
        let size = j.amax();
        let symmetric = (j - j.transpose()).amax() <= 1e-9 * size;
        if !(j.iter().all(|v| v.is_finite()) && symmetric) {
            return e.refuse(at, Msg::new("mechanism-inertia-symmetric"));
        }
        let p = j.symmetric_eigenvalues();
        let sum = p.sum();
        if p.iter().any(|&m| m < -1e-12 * size || m > sum - m + 1e-9 * size) {
            return e.refuse(at, Msg::new("mechanism-inertia-physical"));
        }
        Some(j)
    }
}
