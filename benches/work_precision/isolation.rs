//! What the worker boundary costs (issue 70): the light job over HTTP, in
//! one run, on two release services side by side — one computing in worker
//! processes (the default), one on its own threads (`--in-process`) — taken
//! in turn, so that the machine's speed of the moment is the same for both.

use crate::http::{LIGHT, jobs, start_with, wrk};
use std::fmt::Write as _;

/// Pairs of runs, each service in turn.
const PAIRS: usize = 3;

pub fn section() -> String {
    let mut text = String::from("## The worker boundary: what it costs\n\n");
    if std::process::Command::new("wrk").arg("--version").output().is_err() {
        let _ = writeln!(text, "Skipped: `wrk` is not installed (`apt-get install wrk`).");
        return text;
    }
    let (workers, in_process) = match (start_with(&[]), start_with(&[("MECHDYN_IN_PROCESS", "1")])) {
        (Ok(w), Ok(i)) => (w, i),
        (Err(why), _) | (_, Err(why)) => return format!("{text}Skipped: {why}.\n"),
    };
    let (_, path, body) = jobs().into_iter().find(|(name, ..)| *name == LIGHT).expect("the light job");
    let _ = writeln!(
        text,
        "The light job ({LIGHT}) at 1, 16 and 64 connections, {PAIRS} pairs of 5 s runs on two release services \
         started together, each in turn: jobs computed by worker processes (the service's default), and the same \
         on the service's own threads (`--in-process`). The medians of the pairs.\n\n\
         | connections | workers: jobs/s | p99 | in-process: jobs/s | p99 | rate, workers / in-process |\n\
         |---|---|---|---|---|---|"
    );
    let mut at_64 = None;
    for c in [1, 16, 64] {
        let (mut w, mut i) = (Vec::new(), Vec::new());
        for _ in 0..PAIRS {
            if let (Ok(a), Ok(b)) = (wrk(&workers, path, &body, c), wrk(&in_process, path, &body, c)) {
                w.push((a.0, a.2));
                i.push((b.0, b.2));
            }
        }
        let (Some((wr, w99)), Some((ir, i99))) = (median(&mut w), median(&mut i)) else {
            let _ = writeln!(text, "| {c} | failed | | | | |");
            continue;
        };
        let _ = writeln!(text, "| {c} | {wr:.0} | {w99:.2} ms | {ir:.0} | {i99:.2} ms | {:.2} |", wr / ir);
        if c == 64 {
            at_64 = Some(wr / ir);
        }
    }
    if let Some(ratio) = at_64 {
        let _ = writeln!(
            text,
            "\n**Target** (issue 70: the light job's rate through the boundary ≥ 0.8× the in-process rate, at 64 \
             connections): {ratio:.2}×: {}. A job crosses a pipe each way (its request to a worker and its result \
             back, one write each, the service's thread waiting where it would have computed) and is read twice \
             (by the service, for its 400s and 422s at once, and by the worker); in exchange any job can be \
             stopped from outside, its memory bounded and its crash its own. Before the exchange blocked that \
             thread, awaited on the runtime's own I/O, it cost four thread wakeups a job: 0.68× at 64 \
             connections (2026-12-07).",
            if ratio >= 0.8 { "met" } else { "missed" }
        );
    }
    text
}

/// The pair of the median rate, and its p99.
fn median(runs: &mut [(f64, f64)]) -> Option<(f64, f64)> {
    runs.sort_by(|a, b| a.0.total_cmp(&b.0));
    runs.get(runs.len() / 2).copied()
}
