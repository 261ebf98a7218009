//! The rotor's plot: its bearing reactions over its states in fixed axes.

use crate::i18n::{Msg, say};
use crate::kind::chart::{Axis, Chart, Level, Listed, Pen};
use crate::kind::plots::{Drawn, Job, Options, deg, num, rows};
use serde_json::Value;

pub fn list(job: &Job) -> Vec<Listed> {
    if rows(job.result, "states").len() < 2 {
        return Vec::new();
    }
    vec![Listed::new("bearings", say("plot-rotor-bearings"))]
}

pub fn draw(job: &Job, name: &str, _: &Options) -> Drawn {
    if name != "bearings" || list(job).is_empty() {
        return Ok(None);
    }
    let states = rows(job.result, "states");
    let component = |bearing: &'static str, k: usize| {
        move |s: &Value| s.pointer(&format!("/reactions_fixed/total/{bearing}/{k}")).and_then(Value::as_f64)
    };
    let angle = |s: &Value| num(s, "angle").map(deg);
    let lines: Vec<(String, Vec<(f64, f64)>)> = ["d", "e"]
        .into_iter()
        .flat_map(|b| (0..3).map(move |k| (b, k)))
        .map(|(b, k)| {
            (
                format!("{}_{}", b.to_uppercase(), ["x", "y", "z"][k]),
                crate::kind::plots::xy(states, angle, component(b, k)),
            )
        })
        .collect();
    let largest = lines.iter().flat_map(|l| &l.1).map(|p| p.1.abs()).fold(0.0, f64::max);
    let mut c = Chart::new(
        say("plot-rotor-bearings"),
        Axis::new(say("plot-rotor-frame-angle"), "deg"),
        Axis::new(say("plot-rotor-force"), "N"),
    );
    let mut shown = 0;
    for (name, points) in lines {
        if points.iter().any(|p| p.1.abs() > 1e-9 * largest) {
            c = c.line(Msg::new("plot-rotor-bearing").arg("name", name).text(), points, Pen::solid(shown));
            shown += 1;
        }
    }
    Ok(Some(c.rule(Level::Y(0.0), "", Pen::dashed(7)).subtitle(say("plot-rotor-note"))))
}
