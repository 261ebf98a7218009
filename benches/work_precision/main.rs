//! Work-precision against peers: `cargo bench --bench work_precision` (or
//! `cargo bench`). For each reference problem it sweeps the requested
//! tolerance, measures the error against a trusted value and the engine's
//! wall time (under the service's allocator, mimalloc), runs the Python
//! peer (bench/peers/) on the same problem when Python with NumPy and
//! SciPy is at hand (skipped with a message
//! otherwise), and writes docs/BENCHMARKS.md with the tables and
//! docs/work_precision_*.svg. Direct dynamics here, kinetostatics and the
//! flywheel in their modules. No assertions: benchmarks are not tests.
//!
//! Problems: D1 (P.81's scotch yoke from rest, reduced form; error = the
//! largest |t − t_closed form| over the turns, s) and IFToMM A03 (Andrews'
//! squeezer, mechanism form, 0.03 s; error = |β − β_ref|, rad, β_ref from
//! bench/peers/andrews_scipy.py at rtol 1e-13, which agrees with the
//! service's own tightest run to 2e-14); IFToMM A01 in `pendulum.rs`, the
//! Exudyn slider-crank in `slider_crank.rs`, the spatial mechanisms against
//! Exudyn in `spatial.rs`.

mod contacts;
mod flywheel;
mod frozen;
mod gauge;
mod grading;
mod http;
mod http_targets;
mod isolation;
mod kinematics;
mod kinetostatics;
mod large;
mod pendulum;
mod slider_crank;
mod spatial;
mod statements;
mod stiff;

use mechdyn::kind::Kind;
use mechdyn::kind::Limits;
use mechdyn::kinds::dynamics::{Dynamics, DynamicsRequest, DynamicsResult, MachineResult};
use plotters::prelude::*;
use serde_json::{Value, json};
use std::fmt::Write as _;
use std::process::Command;
use std::time::Instant;

/// The service's allocator (src/main.rs), so that what is measured through
/// the API's compute allocates as the service does (K1 with the system's
/// malloc: 1.90 µs per position where mimalloc gives 1.51).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

pub const TOLERANCES: [f64; 5] = [1e-4, 1e-6, 1e-8, 1e-10, 1e-12];
/// The integrators the service offers, each measured on every problem.
pub const INTEGRATORS: [&str; 3] = ["dopri5", "dop853", "radau5"];
const BETA_REF: f64 = 15.810_771_195_153_972;

/// One point of a work-precision curve.
#[derive(Clone, Debug)]
pub struct Point {
    pub series: String,
    pub tolerance: f64,
    pub error: f64,
    pub seconds: f64,
    pub evaluations: u64,
}

pub fn fixture(path: &str) -> Value {
    // Requests live in the problem library; reference cases and seeds with the tests.
    let folder = if path.starts_with("requests/") { "library" } else { "tests/fixtures" };
    let full = format!("{}/{folder}/{path}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(full).expect("fixture")).expect("fixture JSON")
}

/// The best of `runs` wall times and the last result.
pub fn timed(request: &Value, runs: usize) -> (f64, DynamicsResult) {
    let request: DynamicsRequest = serde_json::from_value(request.clone()).expect("request");
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let start = Instant::now();
        let result = Dynamics::compute(&request, Vec::new(), &Limits::default()).expect("solved");
        best = best.min(start.elapsed().as_secs_f64());
        last = Some(result);
    }
    (best, last.expect("at least one run"))
}

fn d1(tolerance: f64, integrator: &str) -> Point {
    let case = fixture("cases/D1_scotch_yoke_from_rest_constant_torque.json");
    let turns: Vec<f64> =
        case["expected"]["at_angle"].as_array().unwrap()[5..7].iter().map(|r| r["time_s"].as_f64().unwrap()).collect();
    let request = json!({
        "torques": [{"name": "motor and yoke", "value": {"expr": "15 - 20*sin(phi)^2"}}],
        "reduced_inertia": {"expr": "sin(phi)^2/20 + 7/100"},
        "until_angle": "720 deg", "tolerance": tolerance, "samples": 2, "integrator": integrator
    });
    let (seconds, r) = timed(&request, 21);
    let got = r.events.iter().filter(|e| e.kind == "turn").map(|e| e.t);
    let error = got.zip(&turns).map(|(t, want)| (t - want).abs()).fold(0.0, f64::max);
    Point {
        series: format!("mechdyn D1 (reduced, {integrator})"),
        tolerance,
        error,
        seconds,
        evaluations: r.accuracy.function_evaluations as u64,
    }
}

fn a03(tolerance: f64, integrator: &str) -> Point {
    let mut request = fixture("requests/a03_andrews_squeezer.json");
    request["tolerance"] = json!(tolerance);
    request["integrator"] = json!(integrator);
    let (seconds, r) = timed(&request, 5);
    let beta0 = -0.061_713_890_014_276_45;
    let beta = r.machine.as_ref().and_then(MachineResult::planar).expect("planar machine form").samples[1].inputs[0]
        .angle
        + beta0;
    Point {
        series: format!("mechdyn A03 (mechanism, {integrator})"),
        tolerance,
        error: (beta - BETA_REF).abs(),
        seconds,
        evaluations: r.accuracy.function_evaluations as u64,
    }
}

/// A peer script's standard output, or why there is none.
pub fn run_peer(script: &str, args: &[&str]) -> Result<String, String> {
    let script = format!("{}/bench/peers/{script}", env!("CARGO_MANIFEST_DIR"));
    let venv = concat!(env!("CARGO_MANIFEST_DIR"), "/.venv/bin/python");
    let python = if std::path::Path::new(venv).exists() { venv } else { "python3" };
    let out = Command::new(python).arg(&script).args(args).output().map_err(|e| format!("{python}: {e}"))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(format!("{python} {script} failed: {}", err.lines().last().unwrap_or("")));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The SciPy peer's points, or why there are none.
fn scipy() -> Result<Vec<Point>, String> {
    let text = run_peer("andrews_scipy.py", &["--work-precision"])?;
    Ok(text
        .lines()
        .filter_map(|line| serde_json::from_str::<Value>(line).ok())
        .map(|v| Point {
            series: format!("{} A03", v["peer"].as_str().unwrap_or("?")),
            tolerance: v["rtol"].as_f64().unwrap_or(f64::NAN),
            error: v["error"].as_f64().unwrap_or(f64::NAN),
            seconds: v["seconds"].as_f64().unwrap_or(f64::NAN),
            evaluations: v["evaluations"].as_u64().unwrap_or(0),
        })
        .collect())
}

/// The peer's time at `error`, by log-log interpolation between its points
/// (None outside their range).
pub fn time_at(peer: &[Point], error: f64) -> Option<f64> {
    let mut pts: Vec<(f64, f64)> = peer.iter().map(|p| (p.error.ln(), p.seconds.ln())).collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let x = error.ln();
    pts.windows(2).find(|w| w[0].0 <= x && x <= w[1].0).map(|w| {
        let f = (x - w[0].0) / (w[1].0 - w[0].0);
        (w[0].1 + f * (w[1].1 - w[0].1)).exp()
    })
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    format!(
        "{cpu}, {cores} cores available (a shared virtual machine whose speed is not its own: the same run varies by ±30 % from one hour to the next, and by up to 4.6× from one day to the next — the library four-bar's kinetostatics, in the cams' section, took 1.37 µs a position on 2026-11-27 and 6.25 µs on 2026-11-28; an absolute target is read at that day's speed, against a fixed workload run in turn with what it reads and calibrated against that day's code (the median ratio of the pairs, `gauge.rs`); a ratio to a peer in the same run is not affected); release build; the service's allocator (mimalloc); single-threaded engine"
    )
}

/// A log-log plot of wall time against error, one line per series.
fn plot(points: &[Point], title: &str, path: &str) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (720, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let (emin, emax) = points.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.error), b.max(p.error)));
    let (tmin, tmax) = points.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.seconds), b.max(p.seconds)));
    let mut names: Vec<&str> = points.iter().map(|p| p.series.as_str()).collect();
    names.dedup();
    // Empty decades above the data for the legend (upper left): about half a decade a line.
    let headroom = 10f64.powf(0.45 * names.len() as f64).max(2.0);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (emin.max(1e-16) / 2.0..emax * 2.0).log_scale(),
            (tmin / 2.0..tmax * headroom).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("error")
        .y_desc("wall time, s")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (k, name) in names.iter().enumerate() {
        let color = Palette99::pick(k).to_rgba();
        let series: Vec<(f64, f64)> =
            points.iter().filter(|p| p.series == *name && p.error > 0.0).map(|p| (p.error, p.seconds)).collect();
        chart
            .draw_series(LineSeries::new(series.clone(), color.stroke_width(2)).point_size(3))?
            .label(*name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// A section of the document, made on its own.
type Section = fn() -> String;

fn main() {
    // `cargo bench --bench work_precision -- grading` (or spatial, contacts, large, flywheel, http, kinetostatics,
    // kinematics, stiff, statements, gauge, isolation): that section alone, printed, docs/ left as they are (the flywheel's plot in the
    // temporary folder).
    let alone: [(&str, Section); 12] = [
        ("spatial", spatial::section),
        ("gauge", gauge::section),
        ("contacts", contacts::section),
        ("kinematics", kinematics::section),
        ("stiff", stiff::section),
        ("grading", grading::section),
        ("kinetostatics", kinetostatics::section),
        ("large", large::section),
        ("flywheel", || flywheel::section(&std::env::var(PLOTS).unwrap_or_else(|_| temp_dir()))),
        ("http", || http::section(http_targets::targets)),
        ("isolation", isolation::section),
        ("statements", statements::section),
    ];
    if let Some((_, section)) = alone.iter().find(|(name, _)| std::env::args().any(|a| a == *name)) {
        print!("{}", section());
        return;
    }
    if std::env::args().any(|a| a == "dynamics") {
        // `… -- dynamics`: the direct-dynamics table alone.
        print!("{}", dynamics_section().0);
        return;
    }
    write_docs();
}

/// The work-precision table of the direct dynamics, its target lines, and
/// its points for the plot.
fn dynamics_section() -> (String, Vec<Point>) {
    let mut points = Vec::new();
    for integrator in INTEGRATORS {
        points.extend(TOLERANCES.iter().map(|t| d1(*t, integrator)));
        points.extend(TOLERANCES.iter().map(|t| a03(*t, integrator)));
    }
    let a01 = pendulum::points();
    points.extend(a01.iter().cloned());
    let peer = scipy();
    let mut doc = String::from(
        "# Benchmarks\n\nGenerated by `cargo bench --bench work_precision` (also run by `cargo bench`); do not edit by hand.\n\n",
    );
    let _ = writeln!(doc, "Machine: {}.\n", machine());
    doc.push_str("## Direct dynamics: work-precision\n\n");
    doc.push_str("D1: P.81's scotch yoke from rest (reduced form); error = the largest |t − t_closed form| of its two turns, s. ");
    doc.push_str(
        "A03: IFToMM's Andrews squeezer (mechanism form, 7 bodies, 0.03 s); error = |β − β_ref| of the crank, rad, ",
    );
    doc.push_str("β_ref from the test set's own equations by SciPy DOP853 at rtol 1e-13 (it agrees with mechdyn's tightest run to 2e-14). ");
    doc.push_str(
        "A01: IFToMM's pendulum (1 kg on a massless 1 m link from the horizontal, 2000 s); error = the largest \
         |θ − θ_closed form| over 2001 samples, rad, against the elliptic-function closed form (one run each). ",
    );
    doc.push_str(
        "Every mechdyn series names its integrator (`integrator` in the request; `auto` picks DOP853 in the reduced form at 1e-5 and \
         below, Dormand–Prince for a mechanism). A01's series hold the energy T + V after every step (the default for loads with a potential), \
         except the one marked \"energy free\". ",
    );
    doc.push_str("Times are the best of several runs of the whole job (validation, integration, sampling).\n\n");
    doc.push_str("![work-precision](work_precision_dynamics.svg)\n\n");
    doc.push_str("| series | tolerance | error | wall time | RHS evaluations | SciPy Radau at this error |\n|---|---|---|---|---|---|\n");
    let radau: Vec<Point> =
        peer.as_ref().map_or(Vec::new(), |p| p.iter().filter(|x| x.series.contains("Radau")).cloned().collect());
    match &peer {
        Ok(p) => points.extend(p.iter().cloned()),
        Err(why) => eprintln!("SciPy peer skipped: {why}"),
    }
    for p in &points {
        let ratio = (p.series.starts_with("mechdyn A03"))
            .then(|| time_at(&radau, p.error))
            .flatten()
            .map_or("—".to_string(), |t| format!("{t:.3} s ({:.0}× slower)", t / p.seconds));
        let _ = writeln!(
            doc,
            "| {} | {:.0e} | {:.2e} | {:.3} ms | {} | {ratio} |",
            p.series,
            p.tolerance,
            p.error,
            p.seconds * 1e3,
            p.evaluations
        );
    }
    let ratios: Vec<f64> = points
        .iter()
        .filter(|p| p.series.starts_with("mechdyn A03"))
        .filter_map(|p| time_at(&radau, p.error).map(|t| t / p.seconds))
        .collect();
    if let (Some(lo), Some(hi)) = (ratios.iter().copied().reduce(f64::min), ratios.iter().copied().reduce(f64::max)) {
        let verdict = if lo >= 20.0 { "met" } else { "missed" };
        let _ = writeln!(
            doc,
            "\n**Target** (≥ 20× SciPy Radau at equal error on A03): {lo:.0}–{hi:.0}× where Radau reaches the same \
             error: {verdict}."
        );
    }
    doc.push_str(&pendulum::target(&a01));
    if let Err(why) = &peer {
        let _ = writeln!(
            doc,
            "\nThe SciPy peer was skipped: {why}. Install it with `python3 -m venv .venv && .venv/bin/pip install numpy scipy`."
        );
    }
    (doc, points)
}

/// Where the flywheel section alone writes its plot (the environment
/// variable; unset, the temporary folder).
const PLOTS: &str = "MECHDYN_BENCH_PLOTS";

fn temp_dir() -> String {
    std::env::temp_dir().to_string_lossy().into_owned()
}

/// A section measured in a process of its own (this benchmark run again
/// with the section's name), so that none inherits the heap and caches
/// another left behind (measured once in one process: the flywheel's job
/// 0.071 ms before the long integrations, 0.100 ms after them). What is
/// left between runs is this shared host's own noise.
fn fresh(name: &str, plots: &str) -> String {
    let exe = std::env::current_exe().expect("the benchmark's own path");
    let mut run = Command::new(exe);
    run.arg(name).env(PLOTS, plots).stderr(std::process::Stdio::inherit());
    let out = run.output().expect("the benchmark runs a section");
    assert!(out.status.success(), "section {name} failed (its messages above)");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The whole of docs/BENCHMARKS.md and its plots, each section in a
/// process of its own ([`fresh`]) but the direct dynamics, whose points the
/// plot gathers.
fn write_docs() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/docs");
    let _ = std::fs::create_dir_all(dir);
    let names = [
        "large",
        "stiff",
        "spatial",
        "kinetostatics",
        "kinematics",
        "statements",
        "contacts",
        "flywheel",
        "http",
        "isolation",
        "grading",
    ];
    let sections: Vec<String> = names.iter().map(|name| fresh(name, dir)).collect();
    let (mut doc, mut points) = dynamics_section();
    let (text, slider_crank) = slider_crank::section();
    doc.push_str(&text);
    points.extend(slider_crank);
    for section in sections {
        doc.push('\n');
        doc.push_str(&section);
    }
    if let Err(e) =
        plot(&points, "Direct dynamics: error against wall time", &format!("{dir}/work_precision_dynamics.svg"))
    {
        eprintln!("plot: {e}");
    }
    std::fs::write(format!("{dir}/BENCHMARKS.md"), &doc).expect("write docs/BENCHMARKS.md");
    print!("{doc}");
}
