//! The host's speed, measured in the run that reads an absolute target
//! against it. This machine's speed is not its own (the document's
//! header): issue 50's absolute targets were set on 2026-11-27, when the
//! library four-bar's kinetostatics (3600 positions, every output, through
//! the API's compute) took 1.37 µs a position. A time t measured here is
//! read at that day's speed as t · REFERENCE / g, g the fixed workload of
//! `frozen.rs` timed in turn with it and REFERENCE its time at that speed.
//!
//! Until 2026-11-30 the gauge was the four-bar as this tree has it. But it
//! is this crate's code, and it changed: on 2026-11-30 it took 1.23× as
//! long as the code of 2026-11-27 (14e2c9d) run in turn with it, under the
//! bench's allocator (the scaled condition number and its row scales, added
//! for the hard cases after that day, most of it), so readings against it
//! were kinder than the targets by that much. `frozen.rs` depends on
//! nothing of the crate; REFERENCE was found by running it in turn with
//! 14e2c9d's four-bar (`bench/calibrate-gauge.sh`: 0.467 µs, the median
//! of 30 pairs in two runs, its quartiles 0.448 and 0.475; a third run
//! gave 0.479). That day's figures do not agree to better than ±10 %: read
//! against 14e2c9d's cam with friction (3.06 µs that day, in the four-bar's
//! section) REFERENCE would be 0.501, against its K1 (1.07 µs, in another
//! section) 0.413; the four-bar, the figure the targets were read against
//! since, is between them.

use crate::frozen;
use crate::http::library;
use crate::kinematics::best;
use mechdyn::kind::{Kind, Limits};
use mechdyn::kinds::kinetostatics::{Kinetostatics, KinetostaticsRequest};
use serde_json::json;
use std::hint::black_box;

/// `frozen.rs`'s µs a position at the speed of 2026-11-27 (at which the
/// four-bar took 1.37 µs): its time × 1.37 / 14e2c9d's four-bar's, the
/// median of 30 pairs on 2026-11-30.
const REFERENCE: f64 = 0.467;

/// REFERENCE as that day's other figures give it: K1's and the cam's
/// (above), the least and the most.
const REFERENCE_SPREAD: [f64; 2] = [0.413, 0.501];

/// µs a position of `frozen.rs` (best of 15 passes).
pub fn frozen_per_position() -> f64 {
    best(15, || {
        black_box(frozen::pass());
    }) / frozen::POSITIONS as f64
        * 1e6
}

/// `… -- gauge`: the gauge's time and the four-bar's as this code has it,
/// one pass each (what `bench/calibrate-gauge.sh` reads).
pub fn section() -> String {
    let gauge = frozen_per_position();
    let four_bar = per_position(&swept("four-bar", 3600), 3600);
    format!("gauge {gauge:.4} µs a position; four-bar {four_bar:.4} µs a position\n")
}

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
        let (mut here, mut gauges, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..pairs {
            let gauge = frozen_per_position();
            let t = measure();
            here.push(t);
            gauges.push(gauge);
            ratios.push(t * REFERENCE / gauge);
        }
        Self { here: median(&mut here), gauge: median(&mut gauges), at_reference: median(&mut ratios) }
    }

    /// "… s on this host, where the gauge took … µs a position …: … s at
    /// that speed", in `unit` (its name, and its size in seconds' terms),
    /// with the reading at the speeds that day's other figures give.
    pub fn words(&self, unit: (&str, f64)) -> String {
        let (name, scale) = unit;
        let [low, high] = REFERENCE_SPREAD.map(|r| self.at_reference * scale * r / REFERENCE);
        format!(
            "{:.3} {name} on this host, where the host's gauge (a fixed workload, `frozen.rs`, run in turn with it) took \
             {:.3} µs a position ({REFERENCE} µs at the speed of 2026-11-27, when the target was set, by that day's \
             four-bar): {:.3} {name} at that speed (the median ratio of the pairs; {low:.3} to {high:.3} at the speeds \
             that day's K1 and cam give, `gauge.rs`)",
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
