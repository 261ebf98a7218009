//! Spatial direct dynamics against Exudyn (`cargo bench --bench
//! work_precision -- spatial`): IFToMM A04 (Bricard's linkage falling for
//! 10 s; error = |P3(10) − P3_ref|, the tip of rod 2, m), A05 (the stiff
//! flyball governor, 10 s; error = |s(10) − s_ref| of the sleeve, m) and a
//! free Hooke's joint (2 s; error = |θ(2) − θ_ref| of the input shaft,
//! rad). θ_ref comes from neither integrator: T is held, so ω₁(θ) =
//! √(2T/(I₁ + I₂r²)) and t(θ) = ∫dθ/ω₁ (SciPy quad + brentq in
//! bench/peers/spatial_exudyn.py). A04's and A05's references are mechdyn's
//! own tightest run with another integrator (DOP853 at 1e-12 and 1e-10),
//! stated with how far Exudyn's finest run is from them. Each mechdyn time
//! is the whole job (validation, integration, samples and the global error
//! bound's second run), best of three.

use crate::{Point, run_peer, time_at, timed};
use mechdyn::kinds::dynamics::{DynamicsResult, MachineResult, SpatialMachineDynamics};
use serde_json::{Value, json};
use std::fmt::Write as _;

/// One problem: its request, the peer's model, what is measured.
struct Problem {
    name: &'static str,
    model: &'static str,
    request: fn() -> Value,
    /// The measured quantity of a result.
    value: fn(&DynamicsResult) -> Vec<f64>,
    integrator: &'static str,
    tolerances: &'static [f64],
    /// The integrator and tolerance of the reference run, where mechdyn's own.
    reference: Option<(&'static str, f64)>,
}

fn spatial(r: &DynamicsResult) -> &SpatialMachineDynamics {
    match r.machine.as_ref() {
        Some(MachineResult::Spatial(s)) => s,
        _ => panic!("a spatial machine"),
    }
}

/// The template's request, run to its end with two samples and no reactions.
fn template(id: &str) -> Value {
    let path = format!("{}/library/{id}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut t = serde_json::from_str::<Value>(&text).expect("a template")["request"].clone();
    t["samples"] = json!(2);
    t["machine"]["reactions"] = json!(false);
    t
}

/// Rod 2's tip: r + R·(0, −0.5, 0).
fn tip(r: &DynamicsResult) -> Vec<f64> {
    let rod = &spatial(r).samples.last().expect("a sample").bodies[1];
    (0..3).map(|i| rod.position[i] - 0.5 * rod.rotation[i][1]).collect()
}

fn sleeve(r: &DynamicsResult) -> Vec<f64> {
    vec![spatial(r).samples.last().expect("a sample").bodies[3].position[2]]
}

fn input_angle(r: &DynamicsResult) -> Vec<f64> {
    vec![r.samples.last().expect("a sample").angle]
}

/// A free Hooke's joint at β = 30°: I₁ = 0.01, I₂ = 0.02 kg·m², the input at 10 rad/s.
fn cardan() -> Value {
    let e2 = [0.866_025_403_784_438_6, 0.5, 0.0];
    let tensor: Vec<Vec<f64>> =
        (0..3).map(|i| (0..3).map(|j| if i == j { 0.05 } else { 0.0 } - 0.03 * e2[i] * e2[j]).collect()).collect();
    json!({"machine": {"mechanism": {"space": "spatial",
        "bodies": [{"name": "input", "mass": 1, "cg": [0, 0, 0], "inertia": [0.01, 0.05, 0.05]},
                   {"name": "output", "mass": 1, "cg": [0, 0, 0], "inertia": tensor}],
        "joints": [
            {"name": "A", "type": "revolute", "bodies": ["ground", "input"], "at": [0, 0, 0], "axis": [1, 0, 0]},
            {"name": "B", "type": "revolute", "bodies": ["ground", "output"], "at": [0, 0, 0], "axis": e2},
            {"name": "cross", "type": "universal", "bodies": ["input", "output"], "at": [0, 0, 0],
             "axes": [[0, 1, 0], [0, 0, 1]]}]},
        "input": {"joint": "A", "speed": "10 rad/s"}, "reactions": false},
        "duration": "2 s", "samples": 2})
}

const PROBLEMS: [Problem; 3] = [
    Problem {
        name: "A04 Bricard",
        model: "a04",
        request: || template("bricard-linkage"),
        value: tip,
        integrator: "dop853",
        tolerances: &[1e-4, 1e-6, 1e-8, 1e-10],
        reference: Some(("dop853", 1e-12)),
    },
    Problem {
        name: "A05 flyball governor",
        model: "a05",
        request: || {
            let mut t = template("flyball-governor");
            t["duration"] = json!("10 s");
            t
        },
        value: sleeve,
        integrator: "radau5",
        tolerances: &[1e-4, 1e-6, 1e-8],
        reference: Some(("dop853", 1e-10)),
    },
    Problem {
        name: "Cardan joint",
        model: "cardan",
        request: cardan,
        value: input_angle,
        integrator: "dop853",
        tolerances: &[1e-4, 1e-6, 1e-8, 1e-10],
        reference: None,
    },
];

fn run(p: &Problem, integrator: &str, tolerance: f64) -> (f64, Vec<f64>, u64) {
    let mut request = (p.request)();
    request["integrator"] = json!(integrator);
    request["tolerance"] = json!(tolerance);
    let (seconds, r) = timed(&request, 3);
    (seconds, (p.value)(&r), r.accuracy.function_evaluations as u64)
}

fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>().sqrt()
}

/// The peer's runs: (steps, seconds, value), or why there are none.
fn exudyn(model: &str) -> Result<Vec<(u64, f64, Vec<f64>)>, String> {
    let text = run_peer("spatial_exudyn.py", &[model, "--work-precision"])?;
    let values = |v: &Value| match &v["value"] {
        Value::Array(list) => list.iter().filter_map(Value::as_f64).collect(),
        other => other.as_f64().into_iter().collect(),
    };
    Ok(text
        .lines()
        .filter_map(|line| serde_json::from_str::<Value>(line).ok())
        .filter(|v| v.get("steps").is_some())
        .map(|v| (v["steps"].as_u64().unwrap_or(0), v["seconds"].as_f64().unwrap_or(f64::NAN), values(&v)))
        .collect())
}

/// The reference value of a problem, and where it comes from.
fn reference(p: &Problem) -> Result<(Vec<f64>, String), String> {
    if let Some((integrator, tolerance)) = p.reference {
        let (_, value, _) = run(p, integrator, tolerance);
        return Ok((value, format!("mechdyn {integrator} at {tolerance:.0e}")));
    }
    let text = run_peer("spatial_exudyn.py", &[p.model, "--reference"])?;
    let v: Value = text.lines().find_map(|l| serde_json::from_str(l).ok()).ok_or("no reference printed")?;
    Ok((vec![v["reference"].as_f64().ok_or("no reference")?], "SciPy quadrature of t(θ)".into()))
}

/// The markdown section and the points.
pub fn section() -> String {
    let mut text = String::from(
        "\n## Spatial mechanisms against Exudyn\n\nIFToMM A04 (Bricard's linkage from rest under gravity, 10 s; \
         error = |P3(10) − P3_ref| of rod 2's tip, m), A05 (the stiff flyball governor, 10 s; error = |s(10) − \
         s_ref| of the sleeve, m) and a free Hooke's joint at β = 30° (I₁ = 0.01, I₂ = 0.02 kg·m², 10 rad/s, 2 s; \
         error = |θ(2) − θ_ref| of the input shaft, rad; θ_ref by SciPy quadrature of t(θ) = ∫dθ/ω₁(θ), ω₁ from \
         the energy, independent of both integrators). mechdyn: the whole job, best of three; Exudyn 1.13 (PyPI) \
         with its default implicit generalized-alpha at fixed steps (bench/peers/spatial_exudyn.py).\n\n\
         | problem | series | tolerance or steps | error | wall time | Exudyn at this error |\n|---|---|---|---|---|---|\n",
    );
    let mut verdicts = Vec::new();
    for p in &PROBLEMS {
        let (reference, source) = match reference(p) {
            Ok(r) => r,
            Err(why) => {
                let _ = writeln!(text, "| {} | — | — | — | — | no reference: {why} |", p.name);
                continue;
            }
        };
        let peer = exudyn(p.model);
        let theirs: Vec<Point> = peer.as_ref().map_or(Vec::new(), |runs| {
            runs.iter()
                .map(|(steps, seconds, value)| Point {
                    series: "Exudyn".into(),
                    tolerance: f64::NAN,
                    error: distance(value, &reference),
                    seconds: *seconds,
                    evaluations: *steps,
                })
                .collect()
        });
        let mut ratios = Vec::new();
        for &tolerance in p.tolerances {
            let (seconds, value, evaluations) = run(p, p.integrator, tolerance);
            let error = distance(&value, &reference);
            let same = time_at(&theirs, error);
            ratios.extend(same.map(|t| t / seconds));
            let _ = writeln!(
                text,
                "| {} | mechdyn {} | {tolerance:.0e} ({evaluations} evaluations) | {error:.2e} | {:.3} ms | {} |",
                p.name,
                p.integrator,
                seconds * 1e3,
                same.map_or("—".into(), |t| format!("{:.3} s ({:.0}× mechdyn's time)", t, t / seconds))
            );
        }
        for q in &theirs {
            let _ = writeln!(
                text,
                "| {} | Exudyn | {} steps | {:.2e} | {:.3} ms | — |",
                p.name,
                q.evaluations,
                q.error,
                q.seconds * 1e3
            );
        }
        let said = match (&peer, ratios.iter().copied().reduce(f64::min)) {
            (Err(why), _) => format!("{}: the Exudyn peer was skipped ({why}).", p.name),
            (Ok(_), None) => format!("{}: no mechdyn point within the errors Exudyn reached.", p.name),
            (Ok(_), Some(lo)) => {
                let verdict = if lo >= 10.0 { "met" } else { "missed" };
                format!("{}: {lo:.1}× or more where Exudyn reaches the same error: {verdict}.", p.name)
            }
        };
        verdicts.push(format!("{said} Reference: {source}."));
    }
    let _ = writeln!(text, "\n**Target** (≥ 10× Exudyn at equal error):\n");
    for v in verdicts {
        let _ = writeln!(text, "- {v}");
    }
    text
}
