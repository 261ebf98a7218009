//! The plots of a dynamics job, from its stored samples: the angle and the
//! speed against time with the events marked, the phase portrait ω(φ), and
//! for a mechanism its joints' reactions, the path of each joint and the
//! mechanism drawn at a sample over those paths, and moving over the run (SMIL).

use crate::engine::model::Mechanism;
use crate::i18n::{Msg, say};
use crate::kind::chart::{Axis, Chart, Level, Listed, Pen};
use crate::kind::plots::{Drawn, Job, Options, cursor, deg, magnitudes, no_step, num, reaction_series, rows, sig, xy};
use crate::kinds::mechanism::motion::{self, Still};
use crate::kinds::mechanism::{drawing, isometric};
use serde_json::Value;

const MECHANISM: &str = "/machine/mechanism";

pub fn list(job: &Job) -> Vec<Listed> {
    if rows(job.result, "samples").len() < 2 {
        return Vec::new();
    }
    let mut out = vec![
        Listed::new("angle", say("plot-dyn-angle")),
        Listed::new("speed", say("plot-dyn-speed")),
        Listed::new("phase", say("plot-dyn-phase")),
        Listed::new("energy", say("plot-dyn-energy")),
    ];
    let machine = job.result.get("machine").unwrap_or(&Value::Null);
    let first = rows(machine, "samples").first();
    if first.is_some_and(|s| !rows(s, "reactions").is_empty()) {
        out.push(Listed::new("reactions", say("plot-dyn-reactions")));
    }
    if machine["space"] == "spatial" && isometric::model(job.request, MECHANISM).is_some() {
        out.push(Listed::new("mechanism", say("plot-dyn-mechanism-spatial")));
    }
    if first.is_some_and(|s| !rows(s, "bodies").is_empty())
        && let Some(m) = drawing::model(job.request, MECHANISM)
    {
        out.push(Listed::new("mechanism", say("plot-dyn-mechanism")));
        out.push(Listed::new("motion", say("plot-dyn-motion")));
        out.extend(
            moving(&m).map(|j| Listed::new(format!("path-{j}"), Msg::new("plot-dyn-path").arg("joint", j).text())),
        );
    }
    out
}

/// The joints of a mechanism that move (not between the ground and a body at the ground's pivot).
fn moving(m: &Mechanism) -> impl Iterator<Item = &str> {
    m.joints
        .iter()
        .filter(|j| j.bodies[0] != 0 || !matches!(j.kind, crate::engine::model::JointKind::Revolute))
        .map(|j| j.name.as_str())
}

pub fn draw(job: &Job, name: &str, options: &Options) -> Drawn {
    let Some(title) = list(job).into_iter().find(|p| p.name == name).map(|p| p.title) else { return Ok(None) };
    let r = job.result;
    let samples = rows(r, "samples");
    let time = || Axis::new(say("plot-time"), "s");
    let (angle, speed) = (|| Axis::new(say("plot-angle"), "deg"), || Axis::new(say("plot-speed"), "rad/s"));
    let chart = match name {
        "mechanism" => return mechanism(job, title, options.step.unwrap_or(0)),
        "motion" => return motion(job, title),
        "phase" => {
            return Ok(Some(Chart::new(title, angle(), speed()).line(
                say("plot-dyn-phase-line"),
                xy(samples, |s| num(s, "angle").map(deg), |s| num(s, "speed")),
                Pen::solid(0),
            )));
        }
        "angle" => events(r, inputs(job, Chart::new(title, time(), angle()), "angle", "φ")),
        "speed" => events(r, inputs(job, Chart::new(title, time(), speed()), "speed", "ω")),
        "energy" => Chart::new(title, time(), Axis::new(say("plot-dyn-residual"), "1"))
            .line(
                say("plot-dyn-residual-line"),
                xy(samples, |s| num(s, "t"), |s| num(s, "energy_residual")),
                Pen::solid(0),
            )
            .rule(Level::Y(0.0), "", Pen::dashed(7))
            .subtitle(
                Msg::new("plot-dyn-residual-note")
                    .arg("value", num(r, "energy_residual").map_or("-".into(), sig))
                    .text(),
            ),
        "reactions" => reactions(r, title),
        path => return Ok(paths(job, title, Some(path.trim_start_matches("path-")))),
    };
    // Against time, the sample the page draws the mechanism at.
    Ok(Some(match options.step {
        Some(k) => cursor(chart, samples.get(k).and_then(|s| num(s, "t")), k),
        None => chart,
    }))
}

/// Every input's `key` (angle or speed) against time: the first input from
/// `samples`, the others from the mechanism's samples; each named by its joint.
fn inputs(job: &Job, mut c: Chart, key: &str, symbol: &str) -> Chart {
    let value = |v: &Value| num(v, key).map(|x| if key == "angle" { deg(x) } else { x });
    let machine = machine_samples(job.result);
    let many = machine.first().map_or(1, |s| rows(s, "inputs").len());
    let joints: Vec<String> = match job.request.pointer("/machine/input") {
        Some(Value::Array(list)) => {
            list.iter().map(|i| i.get("joint").and_then(Value::as_str).unwrap_or("").into()).collect()
        }
        Some(one) => vec![one.get("joint").and_then(Value::as_str).unwrap_or("").into()],
        None => Vec::new(),
    };
    let name = |k: usize| match joints.get(k) {
        Some(j) => Msg::new("plot-dyn-input-at").arg("symbol", symbol).arg("joint", j).text(),
        None => format!("{symbol}(t)"),
    };
    c = c.line(name(0), xy(rows(job.result, "samples"), |s| num(s, "t"), value), Pen::solid(0));
    for k in 1..many {
        let points = xy(machine, |s| num(s, "t"), |s| rows(s, "inputs").get(k).and_then(value));
        c = c.line(name(k), points, Pen::solid(k));
    }
    c
}

/// Fewer samples than this and the plots say the lines between them are straight.
const FEW_SAMPLES: usize = 50;

/// The events as vertical lines: "turn 1", "turn 2", …, "slip K", "roll K", "end".
fn events(r: &Value, mut c: Chart) -> Chart {
    let mut turns = 0;
    for e in rows(r, "events") {
        let Some(t) = num(e, "t") else { continue };
        let label = match e.get("kind").and_then(Value::as_str) {
            Some("turn") => {
                turns += 1;
                Msg::new("plot-dyn-turn").arg("n", turns).text()
            }
            Some(kind @ ("slip" | "roll")) => {
                let joint = e.get("joint").and_then(Value::as_str).unwrap_or("");
                Msg::new(if kind == "slip" { "plot-dyn-slip" } else { "plot-dyn-roll" }).arg("joint", joint).text()
            }
            _ => say("plot-dyn-end"),
        };
        c = c.rule(Level::X(t), label, Pen::dashed(7));
    }
    let estimated = r.get("accuracy").and_then(|a| num(a, "estimated_error"));
    let n = rows(r, "samples").len();
    let note = Msg::new(if n < FEW_SAMPLES { "plot-dyn-note-few" } else { "plot-dyn-note" }).count("turns", turns);
    let note = note.arg("residual", num(r, "energy_residual").map_or("-".into(), sig)).count("samples", n);
    c.subtitle(note.arg("error", estimated.map_or("-".into(), sig)).text())
}

fn machine_samples(r: &Value) -> &[Value] {
    rows(r.get("machine").unwrap_or(&Value::Null), "samples")
}

fn reactions(r: &Value, title: String) -> Chart {
    let c = Chart::new(title, Axis::new(say("plot-time"), "s"), Axis::new(say("plot-ks-reaction-force"), "N"));
    magnitudes(c, reaction_series(machine_samples(r), |s| num(s, "t")))
}

/// The paths of the joints (one, or all) over the run.
fn paths(job: &Job, title: String, only: Option<&str>) -> Option<Chart> {
    let m = drawing::model(job.request, MECHANISM)?;
    let samples = machine_samples(job.result);
    let poses: Vec<_> = samples.iter().map(|s| drawing::poses(&m, rows(s, "bodies"))).collect();
    let mut c = Chart::new(title, Axis::new("x", "m"), Axis::new("y", "m"));
    c.equal = true;
    for (k, name) in moving(&m).enumerate().filter(|(_, n)| only.is_none_or(|o| o == *n)) {
        let j = m.joints.iter().find(|j| j.name == name)?;
        let points: Vec<(f64, f64)> = poses.iter().filter_map(|p| drawing::point_of(&m, p, j)).collect();
        if let (Some(&a), Some(&b)) = (points.first(), points.last()) {
            let mark = |id| Msg::new(id).arg("joint", name).text();
            c = c.mark(a, mark("plot-dyn-at-start")).mark(b, mark("plot-dyn-at-end"));
        }
        c = c.line(
            Msg::new("plot-dyn-path-line").arg("joint", name).text(),
            points,
            if only.is_some() { Pen::solid(0) } else { Pen::dashed(k) },
        );
    }
    Some(c)
}

/// The mechanism moving over the run, each sample shown at its time: the
/// run played in its own time, slowed or sped into 2 to 20 s.
fn motion(job: &Job, title: String) -> Drawn {
    let Some(m) = drawing::model(job.request, MECHANISM) else { return Ok(None) };
    let samples = machine_samples(job.result);
    let poses: Vec<_> = samples.iter().map(|s| drawing::poses(&m, rows(s, "bodies"))).collect();
    let t = |k: usize| samples.get(k).and_then(|s| num(s, "t")).unwrap_or(0.0);
    let (t0, run) = (t(0), t(samples.len().saturating_sub(1)) - t(0));
    let stills: Vec<Still> = motion::shown(samples.len())
        .map(|k| Still {
            step: k,
            at: if run > 0.0 { ((t(k) - t0) / run).clamp(0.0, 1.0) } else { 0.0 },
            caption: Msg::new("plot-dyn-motion-at").arg("t", sig(t(k))).arg("step", k).text(),
            poses: poses[k].clone(),
            reactions: rows(&samples[k], "reactions"),
            contacts: rows(&samples[k], "contacts"),
        })
        .collect();
    let mut paths = motion::joint_paths(&m, &poses);
    paths.extend(motion::tracked_paths(samples));
    let seconds = run.clamp(2.0, 20.0);
    let mut c = motion::motion(&m, &stills, paths, seconds, title);
    c.subtitle = Some(Msg::new("plot-motion-note").arg("seconds", sig(seconds)).text());
    Ok(Some(c))
}

fn mechanism(job: &Job, title: String, step: usize) -> Drawn {
    let samples = machine_samples(job.result);
    let s = samples.get(step).ok_or_else(|| no_step(step, samples.len()))?;
    let t = num(s, "t").map_or(String::new(), sig);
    let spatial = job.result["machine"]["space"] == "spatial";
    let note = Msg::new(if spatial { "plot-dyn-sample-spatial" } else { "plot-dyn-sample" });
    let note = note.arg("step", step).arg("last", samples.len() - 1).arg("t", t).text();
    if spatial {
        let drawn = isometric::drawn(job.request, MECHANISM, (rows(s, "bodies"), rows(s, "reactions")), title);
        return Ok(drawn.map(|c| isometric::noted(c, note)));
    }
    let Some(m) = drawing::model(job.request, MECHANISM) else { return Ok(None) };
    let mut c =
        drawing::draw(&m, &drawing::poses(&m, rows(s, "bodies")), rows(s, "reactions"), rows(s, "contacts"), title);
    if let Some(p) = paths(job, String::new(), None) {
        c.lines.extend(p.lines.into_iter().map(|mut l| {
            l.label = None;
            l.pen = Pen { color: 7, dashed: true, width: 1 };
            l
        }));
    }
    Ok(Some(c.subtitle(note)))
}
