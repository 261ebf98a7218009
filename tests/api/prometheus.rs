//! `/metrics` read by its real clients: Prometheus's own linter (`promtool
//! check metrics`) and a Prometheus server that scrapes the real binary and
//! answers queries over what it scraped. Debian's `prometheus` package has
//! both; without it the test says it is skipped, unless
//! MECHDYN_REQUIRE_PROMETHEUS is set (CI sets it).

use crate::crash::{free_port, http, start};
use serde_json::Value;
use std::io::Write;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

fn available() -> bool {
    ["prometheus", "promtool"]
        .iter()
        .all(|p| Command::new(p).arg("--version").output().is_ok_and(|o| o.status.success()))
}

/// Stops a child process when the test ends, however it ends.
struct Killed(Child);

impl Drop for Killed {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The instant vector of a PromQL query, as Prometheus's HTTP API answers it.
fn query(port: u16, promql: &str) -> Vec<Value> {
    let q = percent_encoding::utf8_percent_encode(promql, percent_encoding::NON_ALPHANUMERIC);
    let (status, body) = http(port, "GET", &format!("/api/v1/query?query={q}"), "").unwrap_or_default();
    if status != 200 {
        return Vec::new();
    }
    let answer: Value = serde_json::from_str(&body).unwrap_or_default();
    answer["data"]["result"].as_array().cloned().unwrap_or_default()
}

/// The value of the one series a query returns.
fn value(series: &[Value]) -> f64 {
    assert_eq!(series.len(), 1, "{series:?}");
    series[0]["value"][1].as_str().unwrap().parse().unwrap()
}

/// Three flywheel jobs stored, one refused (an irregularity of 3), a read of
/// a job that does not exist: the text passes `promtool check metrics`, and a
/// Prometheus server scraping the service counts each of them under its
/// route and status, and the jobs under their kind and outcome.
#[test]
fn prometheus_scrapes_and_counts_what_the_service_did() {
    if !available() {
        assert!(std::env::var_os("MECHDYN_REQUIRE_PROMETHEUS").is_none(), "Prometheus and promtool are required");
        eprintln!("skipped: Prometheus (Debian's prometheus package) is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let _service = Killed(start(&format!("sqlite://{}/jobs.db", dir.path().display()), port));
    let mut body = crate::helpers::request("p103_slider");
    for _ in 0..3 {
        assert_eq!(http(port, "POST", "/v1/flywheel", &body.to_string()).unwrap().0, 201);
    }
    body["irregularity"] = 3.into();
    assert_eq!(http(port, "POST", "/v1/flywheel", &body.to_string()).unwrap().0, 422);
    assert_eq!(http(port, "GET", "/v1/jobs/no-such-job", "").unwrap().0, 404);

    let (status, text) = http(port, "GET", "/metrics", "").unwrap();
    assert_eq!(status, 200);
    let mut lint = Command::new("promtool")
        .args(["check", "metrics"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    lint.stdin.take().unwrap().write_all(text.as_bytes()).unwrap();
    let linted = lint.wait_with_output().unwrap();
    let said = String::from_utf8_lossy(&linted.stdout).to_string() + &String::from_utf8_lossy(&linted.stderr);
    assert!(linted.status.success() && said.trim().is_empty(), "promtool: {said}\n{text}");

    let config = dir.path().join("prometheus.yml");
    let target = format!("127.0.0.1:{port}");
    let yaml = format!(
        "scrape_configs:\n  - job_name: mechdyn\n    scrape_interval: 1s\n    static_configs:\n      - targets: ['{target}']\n"
    );
    std::fs::write(&config, yaml).unwrap();
    let web = free_port();
    let _prometheus = Killed(
        Command::new("prometheus")
            .arg(format!("--config.file={}", config.display()))
            .arg(format!("--storage.tsdb.path={}", dir.path().join("tsdb").display()))
            .arg(format!("--web.listen-address=127.0.0.1:{web}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    let started = Instant::now();
    let done = r#"mechdyn_jobs_total{kind="flywheel",status="done"}"#;
    while query(web, done).is_empty() {
        assert!(started.elapsed() < Duration::from_secs(60), "Prometheus scraped nothing in 60 s");
        std::thread::sleep(Duration::from_millis(200));
    }
    assert_eq!(value(&query(web, done)), 3.0);
    assert_eq!(value(&query(web, r#"mechdyn_jobs_total{kind="flywheel",status="failed"}"#)), 1.0);
    let created = r#"mechdyn_http_requests_total{method="POST",route="/v1/flywheel",status="201"}"#;
    assert_eq!(value(&query(web, created)), 3.0);
    let missing = r#"mechdyn_http_requests_total{route="/v1/jobs/{id}",status="404"}"#;
    assert_eq!(value(&query(web, missing)), 1.0);
    assert_eq!(value(&query(web, r#"mechdyn_engine_seconds_count{kind="flywheel"}"#)), 4.0);
    assert_eq!(value(&query(web, r#"up{job="mechdyn"}"#)), 1.0, "the scrape itself succeeded");
}
