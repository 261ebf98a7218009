//! Templates: a complete request of a kind, with named parameters that
//! point into it (RFC 6901), so that a spreadsheet varies a load or a speed
//! by name. The built-in ones are the course's problems, kept in the
//! repository's `library/` folder and compiled into the binary.

use crate::i18n::{Lang, Msg};
use crate::kind::problem::{ApiError, FieldError};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::collections::BTreeMap;
use utoipa::ToSchema;

pub use super::statement::Stated;

/// Query names a parameter may not take (they mean something else in a template's URL).
pub const RESERVED: &[&str] =
    &["unit", "values", "angles", "label", "format", "seed", "count", "decimal", "lang", "errors"];

/// One parameter of a template: where it goes in the request, its unit and range.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct Parameter {
    /// JSON pointer into `request`; the value there is the parameter's default.
    #[schema(example = "/constants/F", max_length = 1000)]
    pub pointer: String,
    /// Unit of a bare number given for this parameter (default SI), e.g. "rpm".
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(max_length = 100)]
    pub unit: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(max_length = 2000)]
    pub description: Option<String>,
    /// Least value, in `unit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min: Option<f64>,
    /// Largest value, in `unit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
    /// Grid of the values a variant draws, in `unit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// The only values allowed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub choices: Option<Vec<Value>>,
}

/// A problem with parameters.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Template {
    /// The template's name (a slug) or a random UUID.
    #[schema(example = "p103-slider-flywheel")]
    pub id: String,
    /// The kind of job it gives, e.g. `flywheel`.
    pub kind: String,
    pub title: Option<String>,
    /// Where the problem comes from (built-in templates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source: Option<String>,
    /// A complete, valid request of that kind.
    #[schema(value_type = Object)]
    pub request: Value,
    pub parameters: BTreeMap<String, Parameter>,
    /// Fields of `request` that follow the parameters: `{pointer:
    /// expression}`, each expression of the parameters' names (their values
    /// in SI), e.g. a bar's inertia `"m*1^2/12"` as its mass m changes.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub derived: BTreeMap<String, String>,
    /// The statement's quantities, by name: where the statement prints a
    /// magnitude (a resisting torque C_r), the field it comes from and its
    /// sign, so that `/statement/NAME` of the template's job is that number
    /// as printed (see [`Stated`]).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub statement: BTreeMap<String, Stated>,
    /// Variants drawn without repetition: variant v is the (v mod M)-th of
    /// a fixed shuffle of the M combinations of the parameters' values, so
    /// any M consecutive variants differ (the generator is written down in
    /// the service's `engine/variants.rs`). Default false: each parameter
    /// drawn on its own, as before.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub distinct: bool,
    /// Shipped with the service (true) or created by a client.
    #[serde(default)]
    pub builtin: bool,
    /// The title, source and parameters' descriptions in Spanish, for
    /// pages asked in Spanish.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub es: Option<InSpanish>,
}

/// A template's texts in Spanish (each optional: the English stands in).
#[derive(Clone, Debug, Default, Serialize, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct InSpanish {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(max_length = 2000)]
    pub title: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(max_length = 2000)]
    pub source: Option<String>,
    /// A description per parameter, by its name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub parameters: BTreeMap<String, String>,
    /// A description per statement quantity, by its name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub statement: BTreeMap<String, String>,
}

impl Template {
    /// Its title in `lang` (Spanish where it has one), else its id.
    pub fn title_in(&self, lang: Lang) -> String {
        let es = self.es.as_ref().filter(|_| lang == Lang::Es).and_then(|e| e.title.clone());
        es.or_else(|| self.title.clone()).unwrap_or_else(|| self.id.clone())
    }

    /// Where it comes from, in `lang`.
    pub fn source_in(&self, lang: Lang) -> Option<&str> {
        let es = self.es.as_ref().filter(|_| lang == Lang::Es).and_then(|e| e.source.as_deref());
        es.or(self.source.as_deref())
    }

    /// The template as a reader in `lang` reads it: its title, source and
    /// parameters' descriptions in that language where it has them (the
    /// `es` object stays beside them).
    pub fn in_language(mut self, lang: Lang) -> Self {
        if lang == Lang::Es {
            self.title = Some(self.title_in(lang));
            self.source = self.source_in(lang).map(String::from);
            let names: Vec<String> = self.parameters.keys().cloned().collect();
            for name in names {
                let text = self.description_in(&name, lang).map(String::from);
                if let Some(p) = self.parameters.get_mut(&name) {
                    p.description = text;
                }
            }
            let spanish = self.es.as_ref().map(|es| es.statement.clone()).unwrap_or_default();
            for (name, text) in spanish {
                if let Some(s) = self.statement.get_mut(&name) {
                    s.description = Some(text);
                }
            }
        }
        self
    }

    /// Parameter `name`'s description in `lang`.
    pub fn description_in(&self, name: &str, lang: Lang) -> Option<&str> {
        let es = self.es.as_ref().filter(|_| lang == Lang::Es).and_then(|e| e.parameters.get(name));
        es.map(String::as_str).or_else(|| self.parameters.get(name)?.description.as_deref())
    }
}

/// The body of `POST /v1/templates`.
#[derive(Clone, Debug, Deserialize, ToSchema)]
#[schema(example = json!({
    "kind": "gears", "name": "my-gear", "title": "A spur gear",
    "request": {"module": "4 mm", "teeth": 30},
    "parameters": {"z": {"pointer": "/teeth", "description": "Number of teeth", "min": 12, "max": 200}}
}))]
pub struct NewTemplate {
    #[schema(example = "flywheel")]
    pub kind: String,
    #[schema(value_type = Object)]
    pub request: Value,
    pub parameters: BTreeMap<String, Parameter>,
    /// Fields of `request` that follow the parameters (see Template).
    #[serde(default)]
    pub derived: BTreeMap<String, String>,
    /// The statement's quantities (see Template).
    #[serde(default)]
    pub statement: BTreeMap<String, Stated>,
    /// Variants without repetition (see Template).
    #[serde(default)]
    pub distinct: bool,
    #[schema(max_length = 200)]
    pub title: Option<String>,
    /// A slug (lower-case letters, digits, `-`), unique: the template's id.
    #[schema(max_length = 64, pattern = "^[a-z0-9][a-z0-9-]*$")]
    pub name: Option<String>,
    /// Its texts in Spanish.
    pub es: Option<InSpanish>,
}

/// Every template, the built-in ones first.
#[derive(Serialize, ToSchema)]
pub struct TemplateList {
    pub items: Vec<Template>,
}

/// The built-in templates, from `library/`.
pub fn builtin() -> &'static [Template] {
    static LIBRARY: std::sync::OnceLock<Vec<Template>> = std::sync::OnceLock::new();
    LIBRARY.get_or_init(|| {
        LIBRARY_FILES
            .iter()
            .filter_map(|(name, text)| match serde_json::from_str::<Template>(text) {
                Ok(t) => Some(Template { builtin: true, ..t }),
                Err(e) => {
                    tracing::error!(file = name, error = %e, "a built-in template does not read");
                    None
                }
            })
            .collect()
    })
}

/// The library's files, compiled in (a test checks that none is missing).
pub const LIBRARY_FILES: &[(&str, &str)] = &[
    ("p103-slider-flywheel.json", include_str!("../../../library/p103-slider-flywheel.json")),
    ("p103-class.json", include_str!("../../../library/p103-class.json")),
    ("p107-two-stroke-engine.json", include_str!("../../../library/p107-two-stroke-engine.json")),
    ("punch-press-us.json", include_str!("../../../library/punch-press-us.json")),
    ("offset-slider-crank.json", include_str!("../../../library/offset-slider-crank.json")),
    ("four-bar.json", include_str!("../../../library/four-bar.json")),
    ("scotch-yoke-startup.json", include_str!("../../../library/scotch-yoke-startup.json")),
    ("rotor-disk.json", include_str!("../../../library/rotor-disk.json")),
    ("rotor-balancing.json", include_str!("../../../library/rotor-balancing.json")),
    ("scissor-lift.json", include_str!("../../../library/scissor-lift.json")),
    ("bar-on-slider.json", include_str!("../../../library/bar-on-slider.json")),
    ("cam-flat-follower.json", include_str!("../../../library/cam-flat-follower.json")),
    ("ring-on-rim.json", include_str!("../../../library/ring-on-rim.json")),
    ("rolling-disk.json", include_str!("../../../library/rolling-disk.json")),
    ("cam-design.json", include_str!("../../../library/cam-design.json")),
    ("exam-2010-march.json", include_str!("../../../library/exam-2010-march.json")),
    ("exam-2012-january.json", include_str!("../../../library/exam-2012-january.json")),
    ("exam-2012-march.json", include_str!("../../../library/exam-2012-march.json")),
    ("exam-2013-may.json", include_str!("../../../library/exam-2013-may.json")),
    ("exam-2014-may.json", include_str!("../../../library/exam-2014-may.json")),
    ("p113-pulley-flywheel.json", include_str!("../../../library/p113-pulley-flywheel.json")),
    ("grubler-count.json", include_str!("../../../library/grubler-count.json")),
    ("tooth-thickness.json", include_str!("../../../library/tooth-thickness.json")),
    ("p63-scotch-yoke.json", include_str!("../../../library/p63-scotch-yoke.json")),
    ("p115-shaper.json", include_str!("../../../library/p115-shaper.json")),
    ("p23-four-bar-statics.json", include_str!("../../../library/p23-four-bar-statics.json")),
    ("p53-shaper-dynamics.json", include_str!("../../../library/p53-shaper-dynamics.json")),
    ("differential-train.json", include_str!("../../../library/differential-train.json")),
    ("rotor-disk-angle.json", include_str!("../../../library/rotor-disk-angle.json")),
    ("rotor-disk-accelerating.json", include_str!("../../../library/rotor-disk-accelerating.json")),
    ("double-pendulum.json", include_str!("../../../library/double-pendulum.json")),
    ("hooke-joint.json", include_str!("../../../library/hooke-joint.json")),
    ("bricard-linkage.json", include_str!("../../../library/bricard-linkage.json")),
    ("flyball-governor.json", include_str!("../../../library/flyball-governor.json")),
];

/// A new template checked: its kind, name, parameters' names, pointers,
/// units and ranges (every error at its pointer in the body).
pub fn checked(
    kinds: &crate::api::kind::Registry,
    t: NewTemplate,
    mut errors: Vec<FieldError>,
) -> Result<Template, ApiError> {
    if kinds.find(&t.kind).is_none() {
        let names = kinds.names().join(", ");
        errors.push(FieldError::said(
            "/kind",
            Msg::new("template-kind-unknown").arg("kind", &t.kind).arg("known", names),
        ));
    }
    if !t.request.is_object() {
        errors.push(FieldError::said("/request", Msg::new("template-request-object")));
    }
    let slug = |n: &str| {
        n.len() <= 64
            && n.starts_with(|c: char| c.is_ascii_lowercase() || c.is_ascii_digit())
            && n.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
    };
    if let Some(n) = t.name.as_deref().filter(|n| !slug(n)) {
        errors.push(FieldError::said("/name", Msg::new("template-name-slug").arg("name", n)));
    }
    if t.title.as_ref().is_some_and(|s| s.chars().count() > 200) {
        errors.push(FieldError::said("/title", Msg::new("field-at-most-characters").arg("max", 200)));
    }
    if t.parameters.len() > 100 {
        errors.push(FieldError::said("/parameters", Msg::new("template-parameters-too-many").count("max", 100)));
    }
    for (name, p) in &t.parameters {
        let at = format!("/parameters/{}", name.replace('~', "~0").replace('/', "~1"));
        errors.extend(parameter_errors(name, p, &t.request, &at));
    }
    let names: Vec<&str> = t.parameters.keys().map(String::as_str).collect();
    errors.extend(super::derived::errors(&t.derived, &names, &t.request));
    errors.extend(super::statement::errors(&t.statement));
    for name in t.es.iter().flat_map(|es| es.parameters.keys()).filter(|n| !t.parameters.contains_key(*n)) {
        let at = format!("/es/parameters/{}", crate::kind::problem::escape(name));
        errors.push(FieldError::said(at, Msg::new("template-no-parameter").arg("name", name)));
    }
    for name in t.es.iter().flat_map(|es| es.statement.keys()).filter(|n| !t.statement.contains_key(*n)) {
        let at = format!("/es/statement/{}", crate::kind::problem::escape(name));
        errors.push(FieldError::said(at, Msg::new("template-no-statement").arg("name", name)));
    }
    if !errors.is_empty() {
        return Err(ApiError::Invalid(errors));
    }
    let id = t.name.clone().unwrap_or_else(|| uuid::Uuid::new_v4().to_string());
    Ok(Template {
        id,
        kind: t.kind,
        title: t.title,
        source: None,
        request: t.request,
        parameters: t.parameters,
        derived: t.derived,
        statement: t.statement,
        distinct: t.distinct,
        builtin: false,
        es: t.es,
    })
}

fn parameter_errors(name: &str, p: &Parameter, request: &Value, at: &str) -> Vec<FieldError> {
    let mut errors = Vec::new();
    let word = !name.is_empty()
        && name.len() <= 64
        && name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !word {
        errors.push(FieldError::said(at, Msg::new("template-parameter-name").arg("name", name)));
    } else if RESERVED.contains(&name) {
        let reserved = Msg::new("template-parameter-reserved").arg("name", name).arg("reserved", RESERVED.join(", "));
        errors.push(FieldError::said(at, reserved));
    }
    match request.pointer(&p.pointer) {
        Some(v) if v.is_number() || v.is_string() => {}
        Some(_) => errors.push(FieldError::said(format!("{at}/pointer"), Msg::new("template-pointer-scalar"))),
        None => errors.push(FieldError::said(
            format!("{at}/pointer"),
            Msg::new("template-pointer-missing").arg("pointer", &p.pointer),
        )),
    }
    if let Some(u) = &p.unit
        && let Err(e) = crate::units::parse_unit(u)
    {
        errors.push(FieldError::said(format!("{at}/unit"), crate::kind::quantity::unit_msg(&e)));
    }
    if let (Some(lo), Some(hi)) = (p.min, p.max)
        && lo > hi
    {
        errors.push(FieldError::said(at, Msg::new("template-min-above-max").num("min", lo).num("max", hi)));
    }
    if p.step.is_some_and(|s| !(s > 0.0 && s.is_finite())) {
        errors.push(FieldError::said(format!("{at}/step"), Msg::new("field-positive")));
    }
    errors
}

/// A 422 of the template's request: its pointers under `/request`.
pub fn under_request(e: ApiError) -> ApiError {
    e.under("/request")
}
