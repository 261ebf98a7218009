//! The anonymous share (issue 70; contract part five, "Budget, memory and
//! crashes"): with a token, what a request without it computes — a
//! template's value for new parameters, as a spreadsheet's WEBSERVICE()
//! asks it — has one slot and a budget of 2 s of its own, on a worker of its
//! own at a lower priority. Loops of the costliest such request do not
//! delay a token holder's jobs, and a sheet's value is still answered.

use crate::crash::start_with;
use crate::wire::{exchange, free_port, http, http_with};
use std::time::{Duration, Instant};

/// A template's value that computes for as long as it may: the rolling
/// disk's accuracy over 99 999 s (each its own duration: nothing is stored
/// for a request without the token, so nothing is found again either).
fn costly(k: usize) -> String {
    format!("/v1/templates/rolling-disk/result/accuracy?duration={}", 99_999 - k)
}

/// Four clients loop on [`costly`] without the token while a token holder
/// POSTs light jobs one after the other: each of those is answered in under
/// a second (on two cores shared with the clients), none is refused; each
/// anonymous request is answered within its wait for the share (the
/// budgets of the four that may be ahead of it), its own budget (2 s), the
/// grace (0.5 s) and a margin, as a 422 of its budget or a 503 for want of
/// the share; after them, a sheet's value is answered without the token.
#[test]
fn loops_without_the_token_do_not_delay_a_token_holders_jobs() {
    let dir = tempfile::tempdir().unwrap();
    let db = format!("sqlite://{}", dir.path().join("jobs.db").display());
    let port = free_port();
    let mut child = start_with(&db, port, &[("MECHDYN_API_TOKEN", "t0ken")]);
    let until = Instant::now() + Duration::from_secs(8);
    let loops: Vec<_> = (0..4)
        .map(|c| {
            std::thread::spawn(move || {
                let mut seen = Vec::new();
                let mut k = c;
                while Instant::now() < until {
                    let started = Instant::now();
                    let answer = exchange(port, "GET", &costly(k), "", "", Duration::from_secs(30)).unwrap();
                    seen.push((answer, started.elapsed().as_secs_f64()));
                    k += 4;
                }
                seen
            })
        })
        .collect();
    std::thread::sleep(Duration::from_millis(300));
    let mut holder = Vec::new();
    let body = crate::crash::flywheel_job(0);
    while Instant::now() < until {
        let started = Instant::now();
        let (status, text) = http_with(port, "POST", "/v1/flywheel", "Authorization: Bearer t0ken\r\n", &body).unwrap();
        assert_eq!(status, 201, "a token holder's job: {text}");
        holder.push(started.elapsed().as_secs_f64());
    }
    let anonymous: Vec<_> = loops.into_iter().flat_map(|l| l.join().unwrap()).collect();
    let slowest = holder.iter().copied().fold(0.0, f64::max);
    assert!(holder.len() >= 20, "{} jobs of the token holder in 8 s", holder.len());
    assert!(slowest < 1.0, "a token holder's job waited {slowest:.2} s beside the anonymous loops");
    let budget = anonymous.iter().filter(|((s, t), _)| *s == 422 && t.contains("/problems/compute-budget")).count();
    let saturated = anonymous.iter().filter(|((s, t), _)| *s == 503 && t.contains("without the token")).count();
    assert!(budget >= 2, "the share computed some: {anonymous:?}");
    assert_eq!(budget + saturated, anonymous.len(), "each is its budget's 422 or the share's 503: {anonymous:?}");
    // A wait for the share (at most the budgets and graces of the four ahead), the budget, the grace, a margin.
    for ((status, _), took) in &anonymous {
        assert!(*took < 4.0 * 2.5 + 2.5 + 1.5, "a request without the token answered after {took:.2} s ({status})");
    }
    let (status, value) =
        http(port, "GET", "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1111", "").unwrap();
    assert_eq!(status, 200, "{value}");
    assert!(value.trim().parse::<f64>().is_ok(), "{value}");
    child.kill().unwrap();
    child.wait().unwrap();
}

/// Without the token, one request computes, four wait for it (for as long
/// as those ahead may take, 1 s each here), and a sixth is answered 503 at
/// once, saying when to come back; the four are computed in turn.
#[test]
fn the_share_taken_is_a_503_with_retry_after() {
    let dir = tempfile::tempdir().unwrap();
    let db = format!("sqlite://{}", dir.path().join("jobs.db").display());
    let port = free_port();
    let env = [("MECHDYN_API_TOKEN", "t0ken"), ("MECHDYN_ANONYMOUS_JOB_SECONDS", "1")];
    let mut child = start_with(&db, port, &env);
    let ahead: Vec<_> =
        (0..5).map(|k| std::thread::spawn(move || http(port, "GET", &costly(k), "").unwrap())).collect();
    std::thread::sleep(Duration::from_millis(300));
    let started = Instant::now();
    let head = crate::wire::exchange_head(port, "GET", &costly(5)).unwrap();
    let took = started.elapsed().as_secs_f64();
    assert!(head.starts_with("HTTP/1.1 503"), "{head}");
    assert!(head.to_ascii_lowercase().contains("retry-after: 1"), "{head}");
    assert!(took < 0.5, "the sixth waited {took:.2} s");
    let answers: Vec<(u16, String)> = ahead.into_iter().map(|a| a.join().unwrap()).collect();
    assert!(answers.iter().all(|(s, _)| *s == 422), "each computed for its budget: {answers:?}");
    child.kill().unwrap();
    child.wait().unwrap();
}
