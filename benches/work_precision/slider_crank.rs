//! Direct dynamics against Exudyn: a slider-crank started from rest by a
//! constant torque (library/requests/slider_crank_startup.json), 2 s;
//! error = |φ(2 s) − φ_ref| of the crank, rad. φ_ref = 22.08917156994341 rad
//! from the energy balance (bench/peers/slider_crank_exudyn.py: t(φ) = ∫dφ/ω
//! with the closed-form I*, SciPy quad + brentq), independent of both
//! integrators. Exudyn: its default implicit generalized-alpha at fixed steps.

use crate::{Point, TOLERANCES, fixture, run_peer, time_at, timed};
use mechdyn::kinds::dynamics::MachineResult;
use serde_json::{Value, json};
use std::fmt::Write as _;

const PHI_REF: f64 = 22.089_171_569_943_41;

fn mechdyn(tolerance: f64) -> Point {
    let mut request = fixture("requests/slider_crank_startup.json");
    request["tolerance"] = json!(tolerance);
    let (seconds, r) = timed(&request, 5);
    let phi = r
        .machine
        .as_ref()
        .and_then(MachineResult::planar)
        .expect("planar machine form")
        .samples
        .last()
        .expect("a sample")
        .inputs[0]
        .angle;
    Point {
        series: "mechdyn slider-crank".into(),
        tolerance,
        error: (phi - PHI_REF).abs(),
        seconds,
        evaluations: r.accuracy.function_evaluations as u64,
    }
}

fn exudyn() -> Result<Vec<Point>, String> {
    let text = run_peer("slider_crank_exudyn.py", &["--work-precision"])?;
    Ok(text
        .lines()
        .filter_map(|line| serde_json::from_str::<Value>(line).ok())
        .map(|v| Point {
            series: "Exudyn slider-crank".into(),
            tolerance: f64::NAN,
            error: (v["angle"].as_f64().unwrap_or(f64::NAN) - PHI_REF).abs(),
            seconds: v["seconds"].as_f64().unwrap_or(f64::NAN),
            evaluations: v["steps"].as_u64().unwrap_or(0),
        })
        .collect())
}

/// The markdown table and the points for the dynamics plot.
pub fn section() -> (String, Vec<Point>) {
    let ours: Vec<Point> = TOLERANCES.iter().map(|t| mechdyn(*t)).collect();
    let theirs = exudyn();
    let peer = theirs.as_ref().map_or(Vec::new(), Clone::clone);
    let mut text = String::from(
        "\n### Slider-crank start-up against Exudyn\n\nA slider-crank (crank 0.5 m, rod 1 m, 2 + 4 + 1 kg) started \
         from rest at its dead centre by 10 N·m, 2 s; error = |φ(2 s) − φ_ref| of the crank, φ_ref from the energy \
         balance (SciPy quad + brentq on t(φ) = ∫dφ/ω with the closed-form I*). Exudyn 1.13 (PyPI) with its default \
         implicit generalized-alpha at fixed steps (the \"evaluations\" column holds its steps).\n\n\
         | series | tolerance | error | wall time | evaluations / steps | Exudyn at this error |\n|---|---|---|---|---|---|\n",
    );
    let mut ratios = Vec::new();
    for p in ours.iter().chain(&peer) {
        let same = p.series.starts_with("mechdyn").then(|| time_at(&peer, p.error)).flatten();
        if let Some(t) = same {
            ratios.push(t / p.seconds);
        }
        let _ = writeln!(
            text,
            "| {} | {} | {:.2e} | {:.3} ms | {} | {} |",
            p.series,
            if p.tolerance.is_nan() { "—".into() } else { format!("{:.0e}", p.tolerance) },
            p.error,
            p.seconds * 1e3,
            p.evaluations,
            same.map_or("—".into(), |t| format!("{:.3} s ({:.0}× slower)", t, t / p.seconds))
        );
    }
    match &theirs {
        Err(why) => {
            let _ = writeln!(text, "\nThe Exudyn peer was skipped: {why} (`.venv/bin/pip install exudyn`).");
        }
        Ok(_) => {
            let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
            let verdict = if lo >= 2.0 { "met" } else { "missed" };
            let _ = writeln!(
                text,
                "\n**Target** (≥ 2× Exudyn at equal error): {lo:.0}× or more where Exudyn reaches the same error: \
                 {verdict}. Beyond its finest run (128 000 steps) Exudyn was not run; mechdyn's tighter points have \
                 no Exudyn time to compare with."
            );
        }
    }
    let mut points = ours;
    points.extend(peer);
    (text, points)
}
