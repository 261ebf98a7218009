//! The plots of a kinetostatics job, from its stored steps: the driving
//! action and every joint's reaction against the input, each joint's polar
//! diagram (f_x against f_y over the sweep), I*(φ) and M*(φ), the shaking
//! force's polar diagram (before and after balancing) and moment, the
//! mechanism drawn at a step with its reactions to scale, and moving over
//! the sweep (SMIL).

use crate::i18n::{Msg, say};
use crate::kind::chart::{Axis, Chart, Level, Listed, Mark, Pen};
use crate::kind::plots::{Drawn, Job, Options, cursor, deg, magnitudes, no_step, num, reaction_series, rows, sig, xy};
use crate::kinds::mechanism::motion::{self, Still};
use crate::kinds::mechanism::{drawing, isometric};
use serde_json::Value;

pub fn list(job: &Job) -> Vec<Listed> {
    let steps = rows(job.result, "steps");
    let has = |key: &str| steps.iter().any(|s| s.get(key).is_some_and(|v| !v.is_null()));
    let mut out = Vec::new();
    if has("driving") {
        out.push(Listed::new("driving", say("plot-ks-driving")));
    }
    let spatial =
        steps.iter().any(|s| s["kinematics"][0].get("position").is_some() || s["reactions"][0].get("force").is_some());
    if has("reactions") {
        out.push(Listed::new("reactions", say("plot-ks-reactions")));
    }
    if has("reactions") && !spatial {
        out.extend(
            joints(job.result)
                .into_iter()
                .map(|j| Listed::new(format!("reaction-{j}"), Msg::new("plot-ks-polar").arg("joint", j).text())),
        );
    }
    if has("reduced_inertia") {
        out.push(Listed::new("reduced-inertia", say("plot-ks-reduced-inertia")));
    }
    if has("reduced_torque") {
        out.push(Listed::new("reduced-torque", say("plot-ks-reduced-torque")));
    }
    if has("shaking") {
        out.push(Listed::new("shaking", say("plot-ks-shaking")));
        out.push(Listed::new("shaking-moment", say("plot-ks-shaking-moment")));
    }
    if has("kinematics") && spatial && isometric::model(job.request, "/mechanism").is_some() {
        out.push(Listed::new("mechanism", say("plot-ks-mechanism")));
    }
    if has("kinematics") && !spatial && drawing::model(job.request, "/mechanism").is_some() {
        out.push(Listed::new("mechanism", say("plot-ks-mechanism")));
        if steps.len() > 1 {
            out.push(Listed::new("motion", say("plot-ks-motion")));
        }
    }
    out
}

pub fn draw(job: &Job, name: &str, options: &Options) -> Drawn {
    let Some(title) = list(job).into_iter().find(|p| p.name == name).map(|p| p.title) else { return Ok(None) };
    let r = job.result;
    let chart = match name {
        "mechanism" => return mechanism(job, title, options.step.unwrap_or(0)),
        "motion" => return motion(job, title),
        "shaking" => return Ok(Some(shaking(r, title))),
        polar if polar.starts_with("reaction-") => {
            return Ok(Some(self::polar(r, polar.trim_start_matches("reaction-"), title)));
        }
        "driving" => driving(r, title),
        "reactions" => reactions(r, title),
        "reduced-inertia" => Chart::new(title, input_axis(r), Axis::new("I*", "kg·m²")).line(
            "I*(φ)",
            along(r, "reduced_inertia"),
            Pen::solid(0),
        ),
        "reduced-torque" => Chart::new(title, input_axis(r), Axis::new("M*", "N·m"))
            .line(say("plot-ks-reduced-torque-line"), along(r, "reduced_torque"), Pen::solid(0))
            .rule(Level::Y(0.0), "", Pen::dashed(7)),
        _ => Chart::new(title, input_axis(r), Axis::new(say("plot-ks-shaking-moment-axis"), "N·m"))
            .line("M", xy(rows(r, "steps"), input(r), |s| num(s.get("shaking")?, "moment")), Pen::solid(0))
            .rule(Level::Y(0.0), "", Pen::dashed(7)),
    };
    // Against the input, the step the page draws the mechanism at.
    Ok(Some(match options.step {
        Some(k) => cursor(chart, rows(r, "steps").get(k).and_then(input(r)), k),
        None => chart,
    }))
}

/// The joints' names, in the order of the first step that has reactions.
fn joints(r: &Value) -> Vec<String> {
    let first = rows(r, "steps").iter().find_map(|s| s.get("reactions").and_then(Value::as_array));
    first.into_iter().flatten().filter_map(|x| x.get("joint")?.as_str().map(String::from)).collect()
}

fn angular(r: &Value) -> bool {
    rows(r, "inputs").first().and_then(|i| i.get("coordinate_unit")).and_then(Value::as_str) == Some("rad")
}

/// The first input of a step, in degrees for an angle.
fn input(r: &Value) -> impl Fn(&Value) -> Option<f64> {
    let angular = angular(r);
    move |s: &Value| {
        let v = s.get("input")?;
        let x = v.as_f64().or_else(|| v.get(0)?.as_f64())?;
        Some(if angular { deg(x) } else { x })
    }
}

fn input_axis(r: &Value) -> Axis {
    let joint = rows(r, "inputs").first().and_then(|i| i.get("joint")).and_then(Value::as_str).unwrap_or("");
    if angular(r) {
        Axis::new(Msg::new("plot-ks-input-angle").arg("joint", joint).text(), "deg")
    } else {
        Axis::new(Msg::new("plot-ks-input").arg("joint", joint).text(), "m")
    }
}

fn along(r: &Value, key: &str) -> Vec<(f64, f64)> {
    xy(rows(r, "steps"), input(r), |s| num(s, key))
}

fn driving(r: &Value, title: String) -> Chart {
    let inputs = rows(r, "inputs");
    let unit = inputs.first().and_then(|i| i.get("driving_unit")).and_then(Value::as_str).unwrap_or("N*m");
    let what = if unit == "N" { "plot-ks-driving-force" } else { "plot-ks-driving-torque" };
    let mut c = Chart::new(title, input_axis(r), Axis::new(say(what), unit.replace('*', "·")));
    for (k, i) in inputs.iter().enumerate().filter(|(_, i)| i.get("driving_unit").and_then(Value::as_str) == Some(unit))
    {
        let at = |s: &Value| s.get("driving").and_then(|d| d.as_f64().or_else(|| d.get(k)?.as_f64()));
        let joint = i.get("joint").and_then(Value::as_str).unwrap_or("");
        c = c.line(
            Msg::new("plot-ks-at-joint").arg("joint", joint).text(),
            xy(rows(r, "steps"), input(r), at),
            Pen::solid(k),
        );
    }
    let summary = r.get("summary");
    let mean = summary.and_then(|s| s.get("mean_driving")).and_then(|m| m.as_f64().or_else(|| m.get(0)?.as_f64()));
    match mean {
        Some(m) => c.rule(Level::Y(m), Msg::new("plot-ks-mean").arg("value", sig(m)).text(), Pen::dashed(7)),
        None => c,
    }
}

fn reactions(r: &Value, title: String) -> Chart {
    let c = Chart::new(title, input_axis(r), Axis::new(say("plot-ks-reaction-force"), "N"));
    magnitudes(c, reaction_series(rows(r, "steps"), input(r)))
}

/// f_x against f_y of one joint's reaction over the sweep, from the origin.
fn polar(r: &Value, joint: &str, title: String) -> Chart {
    let steps = rows(r, "steps");
    let series = reaction_series(steps, input(r)).into_iter().find(|s| s.joint == joint);
    let (on, by, points) = series.map(|s| (s.on, s.by, s.points)).unwrap_or_default();
    let points: Vec<(f64, f64)> = points.iter().map(|p| (p.1, p.2)).collect();
    let mut c = Chart::new(title, Axis::new("f_x", "N"), Axis::new("f_y", "N")).line(
        Msg::new("plot-ks-force-on-by").arg("on", on).arg("by", by).text(),
        points.clone(),
        Pen::solid(0),
    );
    c.equal = true;
    c.marks.push(Mark { at: (0.0, 0.0), text: say("plot-ks-origin"), dot: true });
    if let Some(&first) = points.first() {
        let first_step = match input(r)(&steps[0]) {
            Some(x) => Msg::new("plot-ks-first-step-at").arg("value", sig(x)),
            None => Msg::new("plot-ks-first-step"),
        };
        c = c.mark(first, first_step.text());
    }
    let largest = points.iter().map(|p| p.0.hypot(p.1)).fold(0.0, f64::max);
    c.subtitle(Msg::new("plot-ks-polar-note").arg("value", sig(largest)).text())
}

/// The shaking force's polar diagram over the sweep, and once balanced.
fn shaking(r: &Value, title: String) -> Chart {
    let steps = rows(r, "steps");
    let curve = |key: &str| -> Vec<(f64, f64)> {
        let at = |s: &Value| {
            let v = s.get("shaking")?.get(key)?;
            Some((v.get(0)?.as_f64()?, v.get(1)?.as_f64()?))
        };
        steps.iter().filter_map(at).collect()
    };
    let mut c = Chart::new(title, Axis::new("F_x", "N"), Axis::new("F_y", "N")).line(
        say("plot-ks-shaking-force"),
        curve("force"),
        Pen::solid(0),
    );
    let balanced = curve("balanced_force");
    if !balanced.is_empty() {
        c = c.line(say("plot-ks-shaking-balanced"), balanced, Pen::solid(1));
    }
    c.equal = true;
    c.marks.push(Mark { at: (0.0, 0.0), text: say("plot-ks-origin"), dot: true });
    let largest = r.get("summary").and_then(|s| num(s, "max_shaking_force")).unwrap_or(0.0);
    c.subtitle(Msg::new("plot-ks-polar-note").arg("value", sig(largest)).text())
}

/// The mechanism moving over the sweep, one loop in [`SWEEP_SECONDS`].
fn motion(job: &Job, title: String) -> Drawn {
    let Some(m) = drawing::model(job.request, "/mechanism") else { return Ok(None) };
    let steps = rows(job.result, "steps");
    let poses: Vec<_> = steps.iter().map(|s| drawing::poses(&m, rows(s, "kinematics"))).collect();
    let shown: Vec<usize> = motion::shown(steps.len()).collect();
    let unit = if angular(job.result) { "°" } else { " m" };
    let stills: Vec<Still> = (shown.iter().enumerate())
        .map(|(i, &k)| Still {
            step: k,
            at: i as f64 / shown.len() as f64,
            caption: Msg::new("plot-ks-motion-at")
                .arg("value", input(job.result)(&steps[k]).map_or(String::new(), |x| format!("{}{unit}", sig(x))))
                .arg("step", k)
                .text(),
            poses: poses[k].clone(),
            reactions: rows(&steps[k], "reactions"),
            contacts: rows(&steps[k], "contacts"),
        })
        .collect();
    let mut paths = motion::joint_paths(&m, &poses);
    paths.extend(motion::tracked_paths(steps));
    let mut c = motion::motion(&m, &stills, paths, SWEEP_SECONDS, title);
    c.subtitle = Some(Msg::new("plot-motion-note").arg("seconds", SWEEP_SECONDS).text());
    Ok(Some(c))
}

/// How long the motion takes to play the sweep once, s.
const SWEEP_SECONDS: f64 = 4.0;

fn mechanism(job: &Job, title: String, step: usize) -> Drawn {
    let steps = rows(job.result, "steps");
    let s = steps.get(step).ok_or_else(|| no_step(step, steps.len()))?;
    let x = input(job.result)(s).map_or(String::new(), sig);
    let unit = if angular(job.result) { "°" } else { " m" };
    let note = Msg::new("plot-ks-step").arg("step", step).arg("last", steps.len() - 1);
    let note = note.arg("value", format!("{x}{unit}")).text();
    if s["kinematics"][0].get("position").is_some() {
        let drawn = isometric::drawn(job.request, "/mechanism", (rows(s, "kinematics"), rows(s, "reactions")), title);
        return Ok(drawn.map(|c| isometric::noted(c, note)));
    }
    let Some(m) = drawing::model(job.request, "/mechanism") else { return Ok(None) };
    let poses = drawing::poses(&m, rows(s, "kinematics"));
    let reactions = s.get("reactions").and_then(Value::as_array).map_or(&[][..], Vec::as_slice);
    Ok(Some(drawing::draw(&m, &poses, reactions, rows(s, "contacts"), title).subtitle(note)))
}
