//! The host's speed, measured in the run that reads an absolute target
//! against it. This machine's speed is not its own (the document's
//! header): the library four-bar's kinetostatics (3600 positions, every
//! output, through the API's compute) took 1.37 µs a position on
//! 2026-11-27, when issue 50's absolute targets were set. A time t
//! measured here is read at that speed as t · 1.37 / (the four-bar's time
//! in this run). The four-bar is this crate's own code: where it gets
//! faster, the reading gets harsher, never kinder.

use crate::http::library;
use crate::kinematics::best;
use mechdyn::kind::{Kind, Limits};
use mechdyn::kinds::kinetostatics::{Kinetostatics, KinetostaticsRequest};
use serde_json::json;
use std::hint::black_box;

/// The four-bar's µs a position on 2026-11-27.
const REFERENCE: f64 = 1.37;

/// A library request swept over a turn in `steps` positions, every output.
pub fn swept(id: &str, steps: usize) -> KinetostaticsRequest {
    let mut body = library(id);
    body["input"]["start"] = json!("0 deg");
    body["input"]["end"] = json!("360 deg");
    body["input"]["steps"] = json!(steps);
    body["outputs"] = json!(["driving", "reactions", "kinematics", "reduced"]);
    serde_json::from_value(body).expect("request")
}

/// µs a position of a kinetostatics request swept in `steps` positions
/// (best of 15).
pub fn per_position(request: &KinetostaticsRequest, steps: usize) -> f64 {
    let limits = Limits::default();
    let seconds = best(15, || {
        black_box(Kinetostatics::compute(request, Vec::new(), &limits).expect("solved"));
    });
    seconds / steps as f64 * 1e6
}

/// A time measured in turn with the gauge: `pairs` pairs (the gauge, then
/// the time), each pair's ratio taken, and the median ratio read at the
/// reference speed (pairing keeps the ratio meaningful while the host's
/// speed drifts; one reading before and one after did not: ±30 %).
pub struct Reading {
    /// The median of the times measured, s.
    pub here: f64,
    /// The median of the gauge's readings, µs a position.
    pub gauge: f64,
    /// The median of time × REFERENCE / gauge over the pairs, s.
    pub at_reference: f64,
}

impl Reading {
    /// `measure` (one time, s, each call) in turn with the gauge.
    pub fn paired(pairs: usize, mut measure: impl FnMut() -> f64) -> Self {
        let four_bar = swept("four-bar", 3600);
        let (mut here, mut gauges, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..pairs {
            let gauge = per_position(&four_bar, 3600);
            let t = measure();
            here.push(t);
            gauges.push(gauge);
            ratios.push(t * REFERENCE / gauge);
        }
        Self { here: median(&mut here), gauge: median(&mut gauges), at_reference: median(&mut ratios) }
    }

    /// "… s on this host, where the four-bar took … µs a position …: … s at
    /// that speed", in `unit` (its name, and its size in seconds' terms).
    pub fn words(&self, unit: (&str, f64)) -> String {
        let (name, scale) = unit;
        format!(
            "{:.3} {name} on this host, where the library four-bar's kinetostatics took {:.2} µs a position (the host's \
             gauge, run in turn with it; {REFERENCE} µs on 2026-11-27, when the target was set): {:.3} {name} at that \
             speed (the median ratio of the pairs)",
            self.here * scale,
            self.gauge,
            self.at_reference * scale
        )
    }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}
