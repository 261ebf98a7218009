//! A cam's plots as chart data: its SVAJ diagram (s, v, a, j each over
//! its peak on one axis, the segments' ends marked), its profile (base
//! circle, pitch curve, profile, the follower at the largest pressure
//! angle), the pressure angle and radius of curvature against the cam
//! angle, and with dynamics the contact force and cam torque.

use crate::kind::chart::{Axis, Chart, Level, Listed, Pen, Rule};
use crate::kind::plots::{Drawn, Job, Options, num, sig};
use serde_json::Value;

pub fn list(job: &Job) -> Vec<Listed> {
    let mut out = vec![
        Listed::new("svaj", "Lift, velocity, acceleration and jerk against the cam angle (each over its peak)"),
        Listed::new(
            "profile",
            "The cam's profile, pitch curve and base circle, the follower at the largest pressure angle",
        ),
        Listed::new("pressure", "Pressure angle and radius of curvature against the cam angle"),
    ];
    if samples(job).first().is_some_and(|s| s.get("contact_force").is_some()) {
        out.push(Listed::new("forces", "Contact force and cam torque against the cam angle"));
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
    Axis::new("cam angle θ", "deg")
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
            Chart::new("Pressure angle and radius of curvature", angle_axis(), Axis::new("φ (deg), ρ (mm)", ""))
                .line(
                    "pressure angle φ (deg)",
                    curve(rows, "pressure_angle", 180.0 / std::f64::consts::PI),
                    Pen::solid(0),
                )
                .line("profile's radius of curvature ρ (mm)", curve(rows, "curvature_radius", 1e3), Pen::solid(1)),
        ),
        "forces" if rows[0].get("contact_force").is_some() => Some(
            Chart::new("Contact force and cam torque", angle_axis(), Axis::new("N, N·m", ""))
                .line("contact force (N)", curve(rows, "contact_force", 1.0), Pen::solid(0))
                .line("cam torque (N·m)", curve(rows, "cam_torque", 1.0), Pen::solid(1)),
        ),
        _ => None,
    })
}

fn svaj(job: &Job, rows: &[Value]) -> Chart {
    let mut c = Chart::new("SVAJ diagram", angle_axis(), Axis::new("each over its peak", "1"));
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
            c.rules.push(Rule { at: Level::X(to.to_degrees()), label: format!("{law} ends"), pen: Pen::dashed(7) });
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
    let mut c = Chart::new(
        "Cam profile (cam's frame, x: the follower's direction at θ = 0)",
        Axis::new("x", "mm"),
        Axis::new("y", "mm"),
    )
    .line("profile", closed("profile_point"), Pen::solid(0))
    .line(format!("base circle R_b = {} mm", sig(1e3 * base)), circle.collect(), Pen::dashed(2));
    if rows[0].get("pitch_curvature_radius").is_some() {
        c = c.line("pitch curve", closed("pitch_point"), Pen::dashed(1));
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
        c = c.line("follower at the largest pressure angle", vec![(0.0, 0.0), q, p], Pen::solid(3)).mark(
            p,
            format!(
                "φ = {}° at θ = {}°",
                sig(num(worst, "value").unwrap_or(0.0).to_degrees()),
                sig(num(row, "theta").unwrap_or(0.0).to_degrees())
            ),
        );
    }
    c
}
