//! IFToMM A01: a 1 kg point mass on a massless 1 m link, released from the
//! horizontal under g = 9.81, for 2000 s (about 840 swings); error = the
//! largest |θ − θ_closed form| over 2001 samples, with sin(θ/2) =
//! k·sn(K − t√(g/L), k), k = sin(π/4) (θ from the bottom). The same closed
//! form as tests/engine/mechanism_dynamics.rs (each crate keeps its own copy).

use crate::{Point, TOLERANCES, timed};
use serde_json::json;
use std::f64::consts::PI;

/// K(k) = π / (2·AGM(1, √(1 − k²))); 8 rounds reach round-off.
fn complete_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..8 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// Jacobi's sn(u, k) by the descending Landen transformation (Abramowitz &
/// Stegun 16.4.2–3).
fn sn(u: f64, k: f64) -> f64 {
    let (mut a, mut b, mut c) = (vec![1.0f64], (1.0 - k * k).sqrt(), vec![k]);
    while c.last().is_some_and(|c| c.abs() > 1e-17) && c.len() < 12 {
        let an = a[a.len() - 1];
        c.push(0.5 * (an - b));
        a.push(0.5 * (an + b));
        b = (an * b).sqrt();
    }
    let n = a.len() - 1;
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for i in (1..=n).rev() {
        phi = 0.5 * (phi + (c[i] / a[i] * phi.sin()).asin());
    }
    phi.sin()
}

fn a01(tolerance: f64) -> Point {
    let request = json!({
        "machine": {
            "mechanism": {
                "bodies": [{"name": "bob", "mass": 1, "inertia": 0, "cg": [1, 0]}],
                "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "bob"], "at": [0, 0]}],
                "gravity": [0, -9.81]
            },
            "input": {"joint": "O", "speed": 0, "start": 0}
        },
        "duration": 2000, "samples": 2001, "tolerance": tolerance
    });
    let (seconds, r) = timed(&request, 1);
    let k = (PI / 4.0).sin();
    let kk = complete_k(k);
    let error = r
        .machine
        .as_ref()
        .expect("machine form")
        .samples
        .iter()
        .map(|s| {
            let theta = PI / 2.0 + s.inputs[0].angle;
            (theta - 2.0 * (k * sn(kk - s.t * 9.81f64.sqrt(), k)).asin()).abs()
        })
        .fold(0.0, f64::max);
    Point {
        series: "mechdyn A01 (mechanism)".into(),
        tolerance,
        error,
        seconds,
        evaluations: r.accuracy.function_evaluations as u64,
    }
}

pub fn points() -> Vec<Point> {
    TOLERANCES.iter().map(|t| a01(*t)).collect()
}
