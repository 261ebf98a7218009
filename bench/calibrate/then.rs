//! Built by `bench/calibrate-gauge.sh` as an example of the code of
//! 2026-11-27 (14e2c9d), not of this tree: the library four-bar's
//! kinetostatics as `benches/work_precision/gauge.rs` times it (3600
//! positions, every output, best of 15, under mimalloc), then K1 with every
//! reaction and the library cam with friction, every output (3600
//! positions, best of 15 each), in µs a position: on 2026-11-27 the
//! four-bar took 1.37 µs and the cam 3.06 in one section, K1 1.07 in another.

use mechdyn::kind::{Kind, Limits};
use mechdyn::kinds::kinetostatics::{Kinetostatics, KinetostaticsRequest};
use serde_json::{Value, json};
use std::hint::black_box;
use std::time::Instant;

#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn read(path: &str) -> Value {
    let path = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("file")).expect("JSON")
}

fn per_position(body: Value) -> f64 {
    let request: KinetostaticsRequest = serde_json::from_value(body).expect("request");
    let limits = Limits::default();
    let best = (0..15)
        .map(|_| {
            let start = Instant::now();
            black_box(Kinetostatics::compute(&request, Vec::new(), &limits).expect("solved"));
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min);
    best / 3600.0 * 1e6
}

/// A library request swept over a turn in 3600 positions, every output.
fn swept(id: &str) -> Value {
    let mut body = read(&format!("library/{id}.json"))["request"].clone();
    body["input"]["start"] = json!("0 deg");
    body["input"]["end"] = json!("360 deg");
    body["input"]["steps"] = json!(3600);
    body["outputs"] = json!(["driving", "reactions", "kinematics", "reduced"]);
    body
}

fn main() {
    let four_bar = swept("four-bar");
    let mut k1 = read("library/requests/k1_offset_slider_crank.json");
    k1["input"]["steps"] = json!(3600);
    k1["outputs"] = json!(["driving", "reactions"]);
    println!(
        "four-bar {:.4} µs a position; k1 {:.4} µs a position; cam {:.4} µs a position",
        per_position(four_bar),
        per_position(k1),
        per_position(swept("cam-flat-follower"))
    );
}
