//! Plots as data: what a kind hands the service to draw. A kind lists the
//! plots a stored job has and builds each as a [`Chart`] from the stored
//! result (and the stored request where the geometry lives); the service
//! renders every chart the same way. The helpers read a stored result's
//! rows and series.

use super::chart::{self, Chart, Listed};
use super::problem::{ApiError, FieldError};
use crate::i18n::Msg;
use serde_json::Value;
use std::collections::HashMap;

/// A kind's plots: how a stored job lists them and how one is drawn.
#[derive(Clone, Copy)]
pub struct Plots {
    pub list: fn(&Job) -> Vec<Listed>,
    pub draw: fn(&Job, &str, &Options) -> Drawn,
}

/// A kind without curves.
pub const NONE: Plots = Plots { list: |_| Vec::new(), draw: |_, _, _| Ok(None) };

/// A stored job as the plots read it.
pub struct Job<'a> {
    pub request: &'a Value,
    pub result: &'a Value,
}

/// What a plot's query may choose.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// The step (kinetostatics) or sample (dynamics) a drawing of the mechanism shows.
    pub step: Option<usize>,
}

/// What a kind's `plot` answers: the chart, none of that name, or a 400.
pub type Drawn = Result<Option<Chart>, ApiError>;

/// A step beyond the result's `count` steps, as a 400 at `?step=`.
pub fn no_step(step: usize, count: usize) -> ApiError {
    ApiError::BadQuery(vec![FieldError::parameter_said("step", steps_said(step, count))])
}

/// A step beyond the job's `count` steps of a request well formed (a
/// worked solution's), as a 422 at `?step=`.
pub fn beyond_steps(step: usize, count: usize) -> ApiError {
    ApiError::Invalid(vec![FieldError::parameter_said("step", steps_said(step, count))])
}

/// "12: the job has 12 steps (0 to 11)".
fn steps_said(step: usize, count: usize) -> crate::i18n::Msg {
    match count {
        0 => crate::i18n::Msg::new("plot-no-steps").count("step", step),
        n => crate::i18n::Msg::new("plot-steps").count("step", step).count("count", n).count("last", n - 1),
    }
}

/// A step at a singular position, where no force is solved, as a 422 at `?step=`.
pub fn singular_step(step: usize) -> ApiError {
    let message = crate::i18n::Msg::new("plot-singular-step").count("step", step);
    ApiError::Invalid(vec![FieldError::parameter_said("step", message)])
}

/// The plots' cursor: `chart` with a line across it at x (the input or
/// the time of step `step`, the step a page's drawing of the mechanism
/// shows), where the step exists.
pub fn cursor(chart: Chart, x: Option<f64>, step: usize) -> Chart {
    match x {
        Some(x) => {
            chart.rule(chart::Level::X(x), Msg::new("plot-cursor").arg("step", step).text(), chart::Pen::dashed(6))
        }
        None => chart,
    }
}

/// The number at `key` of `row`.
pub fn num(row: &Value, key: &str) -> Option<f64> {
    row.get(key).and_then(Value::as_f64)
}

/// The rows of the array at `key` of `v`.
pub fn rows<'a>(v: &'a Value, key: &str) -> &'a [Value] {
    v.get(key).and_then(Value::as_array).map_or(&[], Vec::as_slice)
}

/// (x, y) of every row where both are numbers.
pub fn xy(rows: &[Value], x: impl Fn(&Value) -> Option<f64>, y: impl Fn(&Value) -> Option<f64>) -> Vec<(f64, f64)> {
    rows.iter().filter_map(|r| Some((x(r)?, y(r)?))).collect()
}

/// A joint's reaction over the rows: its name, the bodies it acts on and
/// by, and (x, f_x, f_y) wherever it is determinate.
pub struct Series {
    pub joint: String,
    pub on: String,
    pub by: String,
    pub points: Vec<(f64, f64, f64)>,
}

/// Every joint's reaction over the rows (each row's `reactions`, x from
/// `x`), in one pass; joints in the order first met.
pub fn reaction_series(rows: &[Value], x: impl Fn(&Value) -> Option<f64>) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    let mut index: HashMap<String, usize> = HashMap::new();
    let text = |r: &Value, k: &str| r.get(k).and_then(Value::as_str).unwrap_or("").to_string();
    for row in rows {
        let Some(x) = x(row) else { continue };
        for r in self::rows(row, "reactions") {
            let Some(joint) = r.get("joint").and_then(Value::as_str) else { continue };
            let k = *index.entry(joint.to_string()).or_insert_with(|| {
                out.push(Series { joint: joint.to_string(), on: text(r, "on"), by: text(r, "by"), points: Vec::new() });
                out.len() - 1
            });
            if let (Some(fx), Some(fy)) = (num(r, "fx"), num(r, "fy")) {
                out[k].points.push((x, fx, fy));
            } else if let Some(magnitude) = num(r, "magnitude") {
                // In space: |F| alone (a polar diagram of it is the plane's).
                out[k].points.push((x, magnitude, 0.0));
            }
        }
    }
    out
}

/// The most joints a plot of every joint's reaction draws (the largest);
/// each joint has its own plot besides.
pub const MOST_JOINTS: usize = 12;

/// |R| of every joint against x, the [`MOST_JOINTS`] largest, into `c`.
pub fn magnitudes(mut c: Chart, mut series: Vec<Series>) -> Chart {
    let largest = |s: &Series| s.points.iter().map(|p| p.1.hypot(p.2)).fold(0.0, f64::max);
    let total = series.len();
    series.sort_by(|a, b| largest(b).total_cmp(&largest(a)));
    for (k, s) in series.iter().take(MOST_JOINTS).enumerate() {
        let points = s.points.iter().map(|p| (p.0, p.1.hypot(p.2))).collect();
        // Beyond the palette's eight colours, the same colours dashed.
        let pen =
            if k < 8 { chart::Pen::solid(k) } else { chart::Pen { dashed: true, width: 2, ..chart::Pen::solid(k) } };
        c = c.line(Msg::new("plot-joint").arg("joint", &s.joint).text(), points, pen);
    }
    if total > MOST_JOINTS {
        c = c.subtitle(Msg::new("plot-most-joints").arg("most", MOST_JOINTS).arg("total", total).text());
    }
    c
}

/// `v` with four significant figures, for labels, in the language of the
/// request (a decimal comma in Spanish).
pub fn sig(v: f64) -> String {
    // −0 (a product with a zero) written as 0.
    crate::i18n::current().figures(if v == 0.0 { 0.0 } else { v })
}

/// Radians to degrees, for the angle axes.
pub fn deg(rad: f64) -> f64 {
    rad.to_degrees()
}
