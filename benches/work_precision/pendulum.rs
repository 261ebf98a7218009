//! IFToMM A01: a 1 kg point mass on a massless 1 m link, released from the
//! horizontal under g = 9.81, for 2000 s (about 840 swings); error = the
//! largest |θ − θ_closed form| over 2001 samples, with sin(θ/2) =
//! k·sn(K − t√(g/L), k), k = sin(π/4) (θ from the bottom), from the file
//! tests/engine uses too.

#[path = "../../tests/engine/elliptic.rs"]
mod elliptic;

use crate::{Point, TOLERANCES, timed};
use elliptic::{complete_k, sn};
use serde_json::json;
use std::f64::consts::PI;

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
