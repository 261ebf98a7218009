//! The balancing plot: the static unbalance U and each plane's correction
//! C_k as m·r vectors from the axis, seen along z (a polar diagram to one scale).

use crate::i18n::{Msg, say};
use crate::kind::chart::{Arrow, Axis, Chart, Level, Listed, Pen};
use crate::kind::plots::{Drawn, Job, Options, num, rows, sig};
use serde_json::Value;

pub fn list(job: &Job) -> Vec<Listed> {
    if job.result.get("static_unbalance").is_none() {
        return Vec::new();
    }
    vec![Listed::new("vectors", say("plot-balancing-vectors"))]
}

/// The tip of a vector of size `value` at `angle` (rad).
fn tip(v: &Value, value: &str) -> Option<(f64, f64)> {
    let (size, angle) = (num(v, value)?, num(v, "angle")?);
    Some((size * angle.cos(), size * angle.sin()))
}

pub fn draw(job: &Job, name: &str, _: &Options) -> Drawn {
    if name != "vectors" || list(job).is_empty() {
        return Ok(None);
    }
    let mut c = Chart::new(say("plot-balancing-vectors"), Axis::new("x", "kg·m"), Axis::new("y", "kg·m"));
    c.equal = true;
    let unbalance = job.result.get("static_unbalance").and_then(|u| tip(u, "value"));
    if let Some(to) = unbalance {
        c.arrows.push(Arrow { from: (0.0, 0.0), to, color: 0, label: say("plot-balancing-unbalance") });
    }
    for (k, correction) in rows(job.result, "corrections").iter().enumerate() {
        let Some(to) = tip(correction, "mass_radius") else { continue };
        let plane = num(correction, "plane").unwrap_or(0.0);
        let label = Msg::new("plot-balancing-correction").arg("z", sig(plane)).text();
        c.arrows.push(Arrow { from: (0.0, 0.0), to, color: k + 1, label });
    }
    // The axis' point, so that a vector of zero still has a place.
    c = c.rule(Level::X(0.0), "", Pen::dashed(7)).rule(Level::Y(0.0), "", Pen::dashed(7));
    Ok(Some(c.subtitle(say("plot-balancing-note"))))
}
