//! Seeded variants of a template: per-student parameter sets drawn from the
//! parameters' `choices` or `min`/`max`/`step` by the generator written
//! down in [`crate::engine::variants`]; variant `v` is the single draw with
//! seed `v`, so a class list names a student's variant by its number.

use super::model::{Parameter, Template};
use super::table::{bad, run};
use crate::api::AppState;
use crate::api::tables::{Csv, Decimal};
use crate::engine::variants::{Draw, Range, distinct, variant};
use crate::i18n::Msg;
use crate::kind::cell;
use crate::kind::problem::ApiError;
use serde::Serialize;
use serde_json::Value;
use std::collections::{BTreeMap, HashMap};
use utoipa::ToSchema;

/// Most variants in one list.
pub const MAX_COUNT: u64 = 1000;

/// The largest variant number, 2^63 − 1 (an int64 in every client's JSON).
pub const MAX_SEED: u64 = i64::MAX as u64;

/// One variant with its reference values.
#[derive(Serialize, ToSchema)]
pub struct Variant {
    /// Its seed.
    pub variant: u64,
    /// The drawn parameters, each in its parameter's unit (those without a range are absent: at their defaults).
    pub parameters: BTreeMap<String, Value>,
    /// The values asked for (`values=`), by pointer as given.
    pub values: BTreeMap<String, Value>,
    /// The reference job, when values were asked for (null otherwise).
    #[schema(required = true)]
    pub job: Option<String>,
    /// Why its job failed, or which values its result does not have (with
    /// the job's warnings); null when every value is there.
    #[schema(required = true)]
    pub error: Option<String>,
}

#[derive(Serialize, ToSchema)]
pub struct Variants {
    pub variants: Vec<Variant>,
}

/// Where a parameter's values are drawn from, if anywhere.
fn range(p: &Parameter) -> Option<Range> {
    match (&p.choices, p.min, p.max, p.step) {
        (Some(c), ..) if !c.is_empty() => Some(Range::Choices(c.len())),
        (_, Some(min), Some(max), Some(step)) => Range::grid(min, max, step),
        // min and max alone bound what a user may ask; they are no class's range.
        _ => None,
    }
}

/// Whether `t` has a parameter to draw (choices, or min, max and step);
/// why not, when it has none.
pub fn drawable(t: &Template) -> Result<(), Msg> {
    if t.parameters.values().any(|p| range(p).is_some()) {
        return Ok(());
    }
    Err(Msg::new("template-not-drawable").arg("id", &t.id))
}

/// The parameters of variant `seed` of `t`: one draw per parameter in name
/// order (those without a range draw too, and keep their default), or the
/// combination of the shuffle where `t` asks for `distinct` variants.
pub fn draw(t: &Template, seed: u64) -> BTreeMap<String, Value> {
    let ranges: Vec<Option<Range>> = t.parameters.values().map(range).collect();
    // A parameter without a range draws from a one-choice list, so that each takes its draw.
    let all: Vec<Range> = ranges.iter().map(|r| r.unwrap_or(Range::Choices(1))).collect();
    let drawn = if t.distinct { distinct(seed, &all) } else { variant(seed, &all) };
    t.parameters
        .iter()
        .zip(ranges.iter().zip(drawn))
        .filter_map(|((name, p), (r, d))| {
            r.as_ref()?;
            let value = match d {
                Draw::Choice(i) => p.choices.as_ref()?.get(i)?.clone(),
                Draw::Value(x) => number(x)?,
            };
            Some((name.clone(), value))
        })
        .collect()
}

/// The variants `seed … seed + count − 1`, each with the `values` of its job.
pub async fn list(
    state: &AppState,
    t: &Template,
    seed: u64,
    count: u64,
    values: &[String],
) -> Result<Variants, ApiError> {
    if count == 0 || count > MAX_COUNT {
        return Err(bad("count", Msg::new("field-between").num("min", 1.0).num("max", MAX_COUNT as f64)));
    }
    drawable(t).map_err(|why| bad("seed", why))?;
    if seed.checked_add(count - 1).is_none_or(|last| last > MAX_SEED) {
        return Err(bad("seed", Msg::new("template-seed-range")));
    }
    let drawn: Vec<(u64, BTreeMap<String, Value>)> = (seed..seed + count).map(|v| (v, draw(t, v))).collect();
    let given: Vec<HashMap<String, String>> = drawn.iter().map(|(_, p)| super::texts(p)).collect();
    let computed = if values.is_empty() {
        vec![(Vec::new(), None, None); given.len()]
    } else {
        run(state, t, given, (values, super::Want::Values)).await?
    };
    let variants = drawn
        .into_iter()
        .zip(computed)
        .map(|((variant, parameters), (found, job, error))| {
            let values = values.iter().cloned().zip(found).collect();
            Variant { variant, parameters, values, job, error }
        })
        .collect();
    Ok(Variants { variants })
}

/// The variants as CSV: `variant`, a column per drawn parameter (`name [unit]`), a column per value.
pub fn csv(t: &Template, v: &Variants, values: &[String], decimal: Decimal) -> Result<String, ApiError> {
    let names: Vec<&String> = t.parameters.iter().filter(|(_, p)| range(p).is_some()).map(|(n, _)| n).collect();
    let heading = |n: &String| t.parameters[n].unit.as_ref().map_or_else(|| n.clone(), |u| format!("{n} [{u}]"));
    let mut out = Csv::new(decimal);
    let head = ["variant".to_string()].into_iter().chain(names.iter().map(|n| heading(n)));
    out.record(head.chain(values.iter().map(|p| p.trim_start_matches('/').to_string())))?;
    for row in &v.variants {
        let cells = [row.variant.to_string()].into_iter();
        let cells = cells.chain(names.iter().map(|n| row.parameters.get(*n).map(cell).unwrap_or_default()));
        out.record(cells.chain(values.iter().map(|p| row.values.get(p).map(cell).unwrap_or_default())))?;
    }
    out.text()
}

/// A drawn number as JSON: whole numbers without a fraction (`600`, not `600.0`).
fn number(x: f64) -> Option<Value> {
    if x.fract() == 0.0 && x.abs() < 9.0e15 {
        return Some(Value::from(x as i64));
    }
    serde_json::Number::from_f64(x).map(Value::Number)
}
