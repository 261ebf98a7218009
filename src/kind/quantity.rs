//! Wire forms of quantities and functions of the cycle angle, and their
//! conversion to SI engine values with every error collected under its pointer.

use super::limits::Limits;
use super::problem::FieldError;
use crate::engine::expr::Expr;
use crate::engine::function::Function;
use crate::i18n::Msg;
use crate::units::{self, Dim, UnitError};
use serde::de::{self, Deserializer, MapAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use utoipa::openapi::RefOr;
use utoipa::openapi::schema::{ObjectBuilder, OneOfBuilder, Schema, Type};
use utoipa::{PartialSchema, ToSchema};

/// Longest quantity string, in characters (the schema's `maxLength`).
pub const QUANTITY_MAX_LENGTH: usize = 200;
/// Longest unit name of a function's `unit`, in characters.
pub const UNIT_MAX_LENGTH: usize = 100;

/// A number (SI) or a `"VALUE UNIT"` string.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Quantity {
    Number(f64),
    Text(String),
}

impl Quantity {
    /// As the request gave it: a number with the unit it is read in, or the text.
    pub fn as_given(&self, unit: &str) -> String {
        match self {
            Self::Number(x) => format!("{x} {unit}"),
            Self::Text(t) => t.clone(),
        }
    }

    /// Its value where it was given without a unit: a number, or a text
    /// with a number alone ("30", "25,5").
    pub fn bare(&self) -> Option<f64> {
        match self {
            Self::Number(v) => Some(*v),
            Self::Text(s) => units::number(s),
        }
    }
}

struct QuantityVisitor;

impl<'de> Visitor<'de> for QuantityVisitor {
    type Value = Quantity;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("json-expect-quantity")
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Quantity, E> {
        Ok(Quantity::Number(v))
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Quantity, E> {
        Ok(Quantity::Number(v as f64))
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Quantity, E> {
        Ok(Quantity::Number(v as f64))
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<Quantity, E> {
        Ok(Quantity::Text(v.to_string()))
    }
}

impl<'de> Deserialize<'de> for Quantity {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(QuantityVisitor)
    }
}

impl PartialSchema for Quantity {
    fn schema() -> RefOr<Schema> {
        OneOfBuilder::new()
            .item(ObjectBuilder::new().schema_type(Type::Number).description(Some("SI value")))
            .item(
                ObjectBuilder::new()
                    .schema_type(Type::String)
                    .max_length(Some(QUANTITY_MAX_LENGTH))
                    .description(Some("\"VALUE UNIT\", e.g. \"300 rpm\", \"3200 ft*lbf\", \"20 slug*ft^2\"; angle fields also take constant expressions such as \"7*pi/4\""))
                    .examples(["300 rpm"]),
            )
            .description(Some("A quantity: a number in SI units, or a string \"VALUE UNIT\""))
            .into()
    }
}
impl ToSchema for Quantity {}

/// Interpolation of a table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum InterpolationDto {
    Linear,
    Step,
    Spline,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct SegmentDto {
    /// Start angle: number (rad), angle quantity or constant expression.
    #[schema(value_type = Quantity)]
    pub from: Quantity,
    #[schema(value_type = Quantity)]
    pub to: Quantity,
    /// Expression of `phi`.
    #[schema(max_length = 2000, example = "-500*sin(phi)")]
    pub expr: String,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct TableDto {
    /// Angles (rad, or angle quantities), strictly increasing in [0, period).
    #[schema(value_type = Vec<Quantity>, min_items = 1, max_items = 100000)]
    pub angle: Vec<Quantity>,
    #[schema(min_items = 1, max_items = 100000)]
    pub value: Vec<f64>,
}

/// The object form of a function: exactly one of `expr`, `segments`, `table`.
#[derive(Clone, Debug, Default, Serialize, Deserialize, ToSchema)]
pub struct FunctionSpec {
    #[schema(max_length = 2000, example = "500/pi - 500*sin(phi)")]
    pub expr: Option<String>,
    #[schema(min_items = 1, max_items = 1000)]
    pub segments: Option<Vec<SegmentDto>>,
    pub table: Option<TableDto>,
    /// Table interpolation (default linear).
    pub interpolation: Option<InterpolationDto>,
    /// Unit of the values (default SI), e.g. "ft*lbf".
    #[schema(max_length = 100)]
    pub unit: Option<String>,
    /// Unit of a table's angles given as numbers (default rad), e.g. "deg".
    #[schema(max_length = 100)]
    pub angle_unit: Option<String>,
    /// The table as CSV text: two columns, angle and value, an optional
    /// header row (`,`, `;` or tab between columns; a decimal comma with `;`).
    #[schema(max_length = 1048576, example = "phi_deg,torque\n0,0\n90,-500\n180,0\n270,0")]
    pub csv: Option<String>,
}

/// A function of the cycle angle: a constant (number or quantity string) or an object.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum FunctionDto {
    Constant(Quantity),
    Spec(FunctionSpec),
}

struct FunctionVisitor;

impl<'de> Visitor<'de> for FunctionVisitor {
    type Value = FunctionDto;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("json-expect-function")
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<FunctionDto, E> {
        QuantityVisitor.visit_f64(v).map(FunctionDto::Constant)
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<FunctionDto, E> {
        QuantityVisitor.visit_i64(v).map(FunctionDto::Constant)
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<FunctionDto, E> {
        QuantityVisitor.visit_u64(v).map(FunctionDto::Constant)
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<FunctionDto, E> {
        QuantityVisitor.visit_str(v).map(FunctionDto::Constant)
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<FunctionDto, A::Error> {
        FunctionSpec::deserialize(de::value::MapAccessDeserializer::new(map)).map(FunctionDto::Spec)
    }
}

impl<'de> Deserialize<'de> for FunctionDto {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(FunctionVisitor)
    }
}

impl PartialSchema for FunctionDto {
    fn schema() -> RefOr<Schema> {
        OneOfBuilder::new()
            .item(Quantity::schema())
            .item(RefOr::Ref(utoipa::openapi::Ref::from_schema_name("FunctionSpec")))
            .description(Some(
                "A function of the cycle angle phi: a constant, {\"expr\"}, {\"segments\"} (zero outside them) or a periodic {\"table\"}; optional \"unit\" for its values",
            ))
            .into()
    }
}
impl ToSchema for FunctionDto {
    fn schemas(schemas: &mut Vec<(String, RefOr<Schema>)>) {
        schemas.push(("FunctionSpec".into(), FunctionSpec::schema()));
        <FunctionSpec as ToSchema>::schemas(schemas);
    }
}

/// A unit's error as the catalogue says it, with the unit it probably
/// means when one is close ([`units::suggestion`]).
pub fn unit_msg(e: &UnitError) -> Msg {
    match e {
        UnitError::Malformed(text) => {
            let (written, unit) = text.trim().split_once(' ').unwrap_or((text.trim(), ""));
            match crate::units::ungrouped(written) {
                Some(plain) => {
                    Msg::new("unit-thousands").arg("text", text).arg("plain", format!("{plain} {unit}").trim_end())
                }
                None => Msg::new("unit-malformed").arg("text", text),
            }
        }
        UnitError::Unknown(unit) => match units::suggestion(unit) {
            Some(hint) => Msg::new("unit-unknown-hint").arg("hint", hint),
            None => Msg::new("unit-unknown"),
        }
        .arg("unit", unit)
        .arg("known", units::known_units()),
        UnitError::WrongDimension { found, expected } => {
            // A pure number's name is words ("1 (dimensionless)"); the others are units.
            let name = |s: &String| match *s == Dim::NONE.si_name() {
                true => Msg::new("unit-none"),
                false => Msg::new("text-as-is").arg("why", s),
            };
            Msg::new("unit-wrong-dimension").with("found", name(found)).with("expected", name(expected))
        }
    }
}

/// An angle in degrees written with another word for them (`20 grados`,
/// `20 gr`, `20 g`): refused with the way to write it ("20°").
fn degrees_in_words(text: &str) -> Option<Msg> {
    let t = text.trim();
    let number_ends = t.find(|c: char| !(c.is_ascii_digit() || ".,+-eE".contains(c))).unwrap_or(t.len());
    let (n, unit) = (t[..number_ends].trim(), t[number_ends..].trim().trim_end_matches('.'));
    let degrees = ["g", "gr", "gra", "grad", "grd", "d", "dg", "dgr", "degree"];
    let meant = degrees.iter().any(|d| unit.eq_ignore_ascii_case(d))
        || units::suggestion(unit).is_some_and(|s| s == "deg")
        || unit.to_lowercase().starts_with("grado");
    (!n.is_empty() && meant).then(|| Msg::new("field-angle-degrees").arg("text", text).arg("n", n))
}

/// Collects (pointer, message) errors while converting a request, under
/// the limits in force.
/// Most nodes of a derivative of a request's expression (a few MB of tree).
pub const MAX_DERIVATIVE_NODES: usize = 100_000;

#[derive(Default)]
pub struct Errors {
    pub list: Vec<FieldError>,
    pub limits: Limits,
    /// The request's `constants` in SI ([`super::constants::read`]): every
    /// expression read afterwards may use them.
    pub constants: Vec<(String, f64)>,
}

impl Errors {
    /// No errors yet, under `limits`.
    pub fn new(limits: &Limits) -> Self {
        Self { list: Vec::new(), limits: limits.clone(), constants: Vec::new() }
    }

    /// An error at `pointer` said by the catalogue.
    pub fn say(&mut self, pointer: &str, msg: Msg) {
        self.list.push(FieldError::said(pointer, msg));
    }

    /// [`Self::say`], and None for the field.
    pub fn refuse<T>(&mut self, at: &str, msg: Msg) -> Option<T> {
        self.say(at, msg);
        None
    }

    /// Whether the derivatives of `f` up to `order` (what its use needs: a
    /// cam's lift three, a reduced inertia one) are of a size to compute: a
    /// product of many factors grows with each derivative like its factors
    /// to the order's power.
    pub fn differentiable(&mut self, f: &Function, order: usize, at: &str) -> Option<()> {
        match f.derivatives_fit(order, MAX_DERIVATIVE_NODES) {
            Ok(()) => Some(()),
            Err(k) => {
                let said = Msg::new("expression-derivative-too-large").count("order", k);
                self.refuse(at, said.count("max", MAX_DERIVATIVE_NODES))
            }
        }
    }

    /// A string of at most `max` characters (the schema's `maxLength`).
    pub fn short(&mut self, text: &str, max: usize, at: &str) -> Option<()> {
        let n = text.chars().count();
        if n <= max { Some(()) } else { self.refuse(at, Msg::new("field-too-long").arg("max", max).arg("has", n)) }
    }

    /// A quantity of the expected dimension, in SI.
    pub fn quantity(&mut self, q: &Quantity, dim: Dim, at: &str) -> Option<f64> {
        if let Quantity::Text(s) = q {
            self.short(s, QUANTITY_MAX_LENGTH, at)?;
        }
        let value = match q {
            Quantity::Number(v) => Ok(*v),
            Quantity::Text(s) => units::parse_as(s, dim),
        };
        match value {
            Ok(v) if v.is_finite() => Some(v),
            Ok(_) => self.refuse(at, Msg::new("field-finite")),
            Err(e) => self.refuse(at, unit_msg(&e)),
        }
    }

    /// An angle: number (rad), angle quantity, or constant expression (`"7*pi/4"`).
    pub fn angle(&mut self, q: &Quantity, at: &str) -> Option<f64> {
        if let Quantity::Text(s) = q {
            self.short(s, QUANTITY_MAX_LENGTH, at)?;
        }
        if let Quantity::Text(s) = q
            && units::parse_as(s, Dim::ANGLE).is_err()
            && let Some(said) = degrees_in_words(s)
        {
            return self.refuse(at, said);
        }
        if let Quantity::Text(s) = q
            && units::parse_quantity(s).is_err()
        {
            let (length, depth) = (self.limits.expression_length, self.limits.expression_depth);
            return match Expr::compile_with(s, &[], &self.constants, length, depth).map(|e| e.constant()) {
                Ok(Some(v)) if v.is_finite() => Some(v),
                _ => self.refuse(at, Msg::new("field-not-angle").arg("text", s)),
            };
        }
        // A bare number, or a text with a number alone ("30"), read in radians.
        if let Some(v) = q.bare() {
            super::noticed::bare_angle(v, at);
        }
        self.quantity(q, Dim::ANGLE, at)
    }

    /// Notices a bare number (no unit) for a length where `above` m or
    /// more is unlikely ([`super::noticed::bare_length`]): "25" for 25 mm.
    pub fn notice_bare_length(&self, q: &Quantity, at: &str, above: f64) {
        if let Some(v) = q.bare() {
            super::noticed::bare_length(v, above, at);
        }
    }

    /// A quantity that must be > 0.
    pub fn positive(&mut self, q: &Quantity, dim: Dim, at: &str) -> Option<f64> {
        let v = self.quantity(q, dim, at)?;
        if v > 0.0 { Some(v) } else { self.refuse(at, Msg::new("field-positive")) }
    }

    /// A value already read (None: its error is recorded) that must also
    /// pass `ok`, else `msg`; one message per field.
    pub fn require_said(&mut self, v: Option<f64>, ok: impl Fn(f64) -> bool, at: &str, msg: Msg) -> Option<f64> {
        match v? {
            v if ok(v) => Some(v),
            _ => self.refuse(at, msg),
        }
    }
}
