//! A cam's plots as chart data: its SVAJ diagram (s, v, a, j each over
//! its peak on one axis, the segments' ends marked), its profile (base
//! circle, pitch curve, profile, the follower at the largest pressure
//! angle), the pressure angle and radius of curvature against the cam
//! angle, and with dynamics the contact force and cam torque.

use crate::i18n::{Msg, say};
use crate::kind::chart::{Axis, Chart, Level, Listed, Pen, Rule};
use crate::kind::plots::{Drawn, Job, Options, num, sig};
use serde_json::Value;

pub fn list(job: &Job) -> Vec<Listed> {
    let mut out = vec![
        Listed::new("svaj", say("plot-cam-svaj")),
        Listed::new("profile", say("plot-cam-profile")),
        Listed::new("pressure", say("plot-cam-pressure")),
    ];
    if samples(job).first().is_some_and(|s| s.get("contact_force").is_some()) {
        out.push(Listed::new("forces", say("plot-cam-forces")));
    }
    out
}

fn samples<'a>(job: &Job<'a>) -> &'a [Value] {
    job.result["samples"].as_array().map_or(&[], Vec::as_slice)
}

/// (θ in degrees, field) of every sample.
fn curve(rows: &[Value], field: &str, scale: f64) -> Vec<(f64, f64)> {
    rows.iter().filter_map(|r| Some((num(r, "theta")?.to_degrees(), num(r, field)? * scale))).collect()
}

fn angle_axis() -> Axis {
    Axis::new(say("plot-cam-angle"), "deg")
}

pub fn draw(job: &Job, name: &str, _: &Options) -> Drawn {
    let rows = samples(job);
    if rows.is_empty() {
        return Ok(None);
    }
    Ok(match name {
        "svaj" => Some(svaj(job, rows)),
        "profile" => Some(profile(job, rows)),
        "pressure" => Some(
            Chart::new(say("plot-cam-pressure-title"), angle_axis(), Axis::new("φ (°), ρ (mm)", ""))
                .line(
                    say("plot-cam-pressure-line"),
                    curve(rows, "pressure_angle", 180.0 / std::f64::consts::PI),
                    Pen::solid(0),
                )
                .line(say("plot-cam-curvature-line"), curve(rows, "curvature_radius", 1e3), Pen::solid(1)),
        ),
        "forces" if rows[0].get("contact_force").is_some() => Some(
            Chart::new(say("plot-cam-forces-title"), angle_axis(), Axis::new("N, N·m", ""))
                .line(say("plot-cam-contact-force"), curve(rows, "contact_force", 1.0), Pen::solid(0))
                .line(say("plot-cam-torque"), curve(rows, "cam_torque", 1.0), Pen::solid(1)),
        ),
        _ => None,
    })
}

fn svaj(job: &Job, rows: &[Value]) -> Chart {
    let mut c = Chart::new(say("plot-cam-svaj-title"), angle_axis(), Axis::new(say("plot-cam-over-peak"), "1"));
    for (k, (field, name, unit)) in
        [("lift", "s", "m"), ("velocity", "v", "m/s"), ("acceleration", "a", "m/s²"), ("jerk", "j", "m/s³")]
            .into_iter()
            .enumerate()
    {
        let peak = rows.iter().filter_map(|r| num(r, field)).fold(0.0f64, |m, v| m.max(v.abs()));
        let scale = if peak > 0.0 { 1.0 / peak } else { 1.0 };
        c = c.line(format!("{name} / {} {unit}", sig(peak)), curve(rows, field, scale), Pen::solid(k));
    }
    for s in job.result["segments"].as_array().into_iter().flatten() {
        if let (Some(to), Some(law)) = (num(s, "to"), s["law"].as_str()) {
            c.rules.push(Rule {
                at: Level::X(to.to_degrees()),
                label: Msg::new("plot-cam-law-ends").with("law", super::program::law_words(law)).text(),
                pen: Pen::dashed(7),
            });
        }
    }
    c
}

fn profile(job: &Job, rows: &[Value]) -> Chart {
    let mm = |r: &Value, key: &str| Some((1e3 * r[key][0].as_f64()?, 1e3 * r[key][1].as_f64()?));
    let closed = |key: &str| {
        let mut pts: Vec<(f64, f64)> = rows.iter().filter_map(|r| mm(r, key)).collect();
        pts.extend(pts.first().copied());
        pts
    };
    let base = num(&job.result["summary"], "base_radius").unwrap_or(0.0);
    let circle = (0..=180)
        .map(|k| (std::f64::consts::TAU * f64::from(k) / 180.0).sin_cos())
        .map(|(s, c)| (1e3 * base * c, 1e3 * base * s));
    // An oscillating follower's pivot is on the cam frame's x axis; a translating one moves along it at θ = 0.
    let oscillating = job.result["summary"]["lift_unit"] == "rad";
    let title = say(if oscillating { "plot-cam-profile-title-pivot" } else { "plot-cam-profile-title" });
    let mut c = Chart::new(title, Axis::new("x", "mm"), Axis::new("y", "mm"))
        .line(say("plot-cam-profile-line"), closed("profile_point"), Pen::solid(0))
        .line(Msg::new("plot-cam-base").arg("value", sig(1e3 * base)).text(), circle.collect(), Pen::dashed(2));
    if rows[0].get("pitch_curvature_radius").is_some() {
        c = c.line(say("plot-cam-pitch"), closed("pitch_point"), Pen::dashed(1));
    }
    c.equal = true;
    let worst = &job.result["summary"]["max_pressure_angle"];
    if let Some(row) = num(worst, "theta").and_then(|t| {
        rows.iter().min_by(|a, b| {
            let d = |r: &Value| (num(r, "theta").unwrap_or(0.0) - t).abs();
            d(a).total_cmp(&d(b))
        })
    }) && let (Some(p), Some(q)) = (mm(row, "profile_point"), mm(row, "pitch_point"))
    {
        c = c.line(say("plot-cam-follower-worst"), vec![(0.0, 0.0), q, p], Pen::solid(3)).mark(
            p,
            Msg::new("plot-cam-worst-at")
                .arg("phi", sig(num(worst, "value").unwrap_or(0.0).to_degrees()))
                .arg("theta", sig(num(row, "theta").unwrap_or(0.0).to_degrees()))
                .text(),
        );
    }
    c
}
