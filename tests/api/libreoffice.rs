//! A real LibreOffice Calc (Debian's libreoffice-calc-nogui with python3-uno,
//! installed by .ci/run) fetches the P.103 answers with WEBSERVICE() from the
//! real binary: tests/clients/calc_webservice.py builds the sheet through
//! UNO, Calc recalculates and calls the service itself.
//!
//! Without LibreOffice the test says so and passes, unless
//! MECHDYN_REQUIRE_LIBREOFFICE is set (CI sets it).

use crate::crash::{free_port, http, start};
use crate::helpers::{TestApp, case};
use serde_json::Value;
use std::process::Command;

/// The Debian Python that has the `uno` module.
const PYTHON: &str = "/usr/bin/python3";

fn calc_available() -> bool {
    let uno = Command::new(PYTHON).args(["-c", "import uno"]).output().is_ok_and(|o| o.status.success());
    let soffice = Command::new("soffice").arg("--version").output().is_ok_and(|o| o.status.success());
    uno && soffice
}

/// P.103 at F = 1200 N·m, ε = 0.03: I_approx = 348.989…·(1200/500)·(0.04/0.03)
/// (case F1; ΔE scales with F), I_exact as the engine computes it in-process,
/// and 1 slug·ft² = 1.355818 kg·m² (NIST SP 811, B.9).
#[tokio::test]
async fn libreoffice_calc_fetches_answers_with_webservice() {
    if !calc_available() {
        assert!(std::env::var_os("MECHDYN_REQUIRE_LIBREOFFICE").is_none(), "LibreOffice with python3-uno is required");
        eprintln!("skipped: LibreOffice Calc with python3-uno is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let mut service = start(&format!("sqlite://{}/calc.db", dir.path().display()), port);
    let profile = dir.path().join("profile");
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/clients/calc_webservice.py");
    let out = Command::new(PYTHON)
        .args([script, &format!("http://127.0.0.1:{port}"), profile.to_str().unwrap()])
        .output()
        .unwrap();
    let (_, jobs) = http(port, "GET", "/v1/jobs?kind=flywheel", "").unwrap();
    let _ = service.kill();
    let _ = service.wait();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let cells: Value = serde_json::from_slice(&out.stdout).unwrap();
    eprintln!("Calc's cells: {cells}");
    for (name, error) in cells["errors"].as_object().unwrap() {
        assert_eq!(error, 0, "cell {name} holds an error");
    }
    let app = TestApp::new().await;
    let exact: f64 =
        app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1200&eps=0.03").await.text.parse().unwrap();
    assert_eq!(cells["B5"].as_f64().unwrap(), exact, "every digit reaches the cell");
    assert_eq!(cells["B8"].as_str().unwrap().parse::<f64>().unwrap(), exact);
    let approx = case("F1_p103_slider_flywheel")["expected"]["I_approx_kg_m2"].as_f64().unwrap() * 2.4 * (4.0 / 3.0);
    assert!((cells["B6"].as_f64().unwrap() / approx - 1.0).abs() < 1e-9, "{cells}");
    assert!((cells["B7"].as_f64().unwrap() * 1.355818 / exact - 1.0).abs() < 1e-6, "{cells}");
    // Calc itself called the service: the job of its parameters is stored there.
    let jobs: Value = serde_json::from_str(&jobs).unwrap();
    let asked = jobs["items"].as_array().unwrap().iter().any(|j| {
        j["request"]["constants"]["F"].as_f64() == Some(1200.0) && j["request"]["irregularity"].as_f64() == Some(0.03)
    });
    assert!(asked, "no job of F = 1200, ε = 0.03 in the service Calc called: {jobs}");
}

/// The example sheet a lab opens (examples/p103-flywheel.fods, saved by the
/// script above from a real Calc) calls the service at its default address,
/// and only templates, results and parameters that exist.
#[tokio::test]
async fn the_example_sheet_calls_what_the_service_has() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/p103-flywheel.fods")).unwrap();
    assert!(text.contains(&format!("http://{}", mechdyn::config::DEFAULT_ADDR)), "the default address in B1");
    let app = TestApp::new().await;
    let calls: Vec<&str> = text.split("WEBSERVICE(").skip(1).collect();
    assert!(calls.len() >= 8, "{} calls", calls.len());
    for call in calls {
        let call = call.split(')').next().unwrap().replace("&quot;", "\"").replace("&amp;", "&");
        let path = call.split("/v1/templates/").nth(1).unwrap();
        let (id, rest) = path.split_once("/result/").unwrap();
        let (pointer, query) = rest.split_once('?').unwrap();
        let names: Vec<&str> =
            query.split('&').filter_map(|p| p.split_once('=').map(|(n, _)| n.trim_matches('"'))).collect();
        let t = app.get(&format!("/v1/templates/{id}")).await.json();
        for name in names.iter().filter(|n| **n != "unit") {
            assert!(t["parameters"].get(*name).is_some(), "{call}: no parameter {name}");
        }
        let answer = app.get(&format!("/v1/templates/{id}/result/{pointer}")).await;
        assert_eq!(answer.content_type, "text/plain; charset=utf-8", "{call}: {}", answer.text);
    }
}
