//! Kinematics only: the library's four-bar, positions per second, against
//! pylinkage's numba path in the same run.

use crate::run_peer;
use mechdyn::engine::kinematics::{Dyads, Trig};
use mechdyn::engine::model::rotate;
use mechdyn::kind::Kind;
use mechdyn::kind::Limits;
use mechdyn::kinds::kinetostatics::{self, KinetostaticsRequest};
use serde_json::{Value, json};
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

/// Positions over a turn, as pylinkage's peer steps.
const STEPS: usize = 3600;

/// The library's four-bar request at `STEPS` positions, kinematics only.
fn request() -> KinetostaticsRequest {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/library/four-bar.json");
    let library: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("library")).expect("JSON");
    let mut body = library["request"].clone();
    body["input"]["steps"] = json!(STEPS);
    body["outputs"] = json!(["kinematics"]);
    serde_json::from_value(body).expect("request")
}

/// The best of `runs` wall times of `f`, s.
pub fn best(runs: usize, mut f: impl FnMut()) -> f64 {
    (0..runs)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// A markdown paragraph: the closed-form positions (engine), the whole
/// kinematics-only job (API), and pylinkage, with their agreement.
pub fn section() -> String {
    let request = request();
    let problem = request.to_problem(&Limits::default()).expect("valid");
    let m = &problem.mechanism;
    let dyads = Dyads::new(m).expect("a crank and a dyad");
    let phis: Vec<f64> = problem.positions.iter().map(|p| p[0][0]).collect();
    let (mut q, mut trig, mut poses) = (m.reference_q(), Trig::default(), vec![Vec::new(); phis.len()]);
    let placing = best(50, || {
        for (&phi, pose) in phis.iter().zip(&mut poses) {
            dyads.place(m, phi, &mut q, &mut trig);
            pose.clone_from(&q);
        }
        black_box(&poses);
    });
    // B of every position, from the coupler's pose (body 2), after the timing.
    let b_ref = m.local(2, m.joints[2].at);
    let b: Vec<[f64; 2]> = poses
        .iter()
        .map(|q| {
            let s = rotate(q[5], b_ref);
            [q[3] + s[0], q[4] + s[1]]
        })
        .collect();
    let job = best(9, || {
        black_box(kinetostatics::Kinetostatics::compute(&request, Vec::new(), &Limits::default()).expect("solved"));
    });
    let per = |seconds: f64| seconds * 1e6 / STEPS as f64;
    let mut text = format!(
        "## Kinematics only: a four-bar's positions\n\nThe library's crank-rocker four-bar over a turn of {STEPS} \
         positions. Placed in closed form (engine: the crank, then the dyad by a circle-circle intersection on the \
         side of the last position, `kinematics::Dyads`, what a sweep does before Newton confirms it): {:.3} ms, \
         {:.3} µs per position ({:.1} M positions/s). The whole kinematics-only job (`\"outputs\": [\"kinematics\"]`: \
         every body's position, velocity and acceleration and Φ_q's condition number at each position, through the \
         API's compute): {:.3} ms, {:.2} µs per position.\n",
        placing * 1e3,
        per(placing),
        STEPS as f64 / placing / 1e6,
        job * 1e3,
        per(job)
    );
    let peer = run_peer("four_bar_pylinkage.py", &[&STEPS.to_string()])
        .and_then(|t| serde_json::from_str::<Value>(&t).map_err(|e| e.to_string()));
    match peer {
        Ok(peer) => {
            let seconds = peer["seconds"].as_f64().unwrap_or(f64::NAN);
            let want = peer["b"].as_array().cloned().unwrap_or_default();
            let gap = (0..STEPS.min(want.len()))
                .map(|k| {
                    let w = &want[(k + STEPS - 1) % STEPS];
                    let (x, y) = (w[0].as_f64().unwrap_or(f64::NAN), w[1].as_f64().unwrap_or(f64::NAN));
                    (b[k][0] - x).hypot(b[k][1] - y)
                })
                .fold(0.0, f64::max);
            let _ = writeln!(
                text,
                "pylinkage 1.3.0 (`Linkage.step_fast`, its {} path, compiled before timing, positions only): {:.3} ms, \
                 {:.3} µs per position ({:.1} M positions/s); the closed form is {:.1}× as fast; largest distance \
                 between the two B's {gap:.1e} m. Target (be ahead of pylinkage): {}.",
                peer["path"].as_str().unwrap_or("?"),
                seconds * 1e3,
                per(seconds),
                STEPS as f64 / seconds / 1e6,
                seconds / placing,
                if placing < seconds { "met" } else { "missed" }
            );
        }
        Err(why) => {
            let _ = writeln!(text, "The pylinkage peer was skipped: {why}.");
        }
    }
    text
}
