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

/// Whether a test is skipped because `what` is not installed: it says so,
/// unless CI requires LibreOffice (MECHDYN_REQUIRE_LIBREOFFICE), where it fails.
fn skipped(present: bool, what: &str) -> bool {
    if !present {
        assert!(std::env::var_os("MECHDYN_REQUIRE_LIBREOFFICE").is_none(), "{what} is required");
        eprintln!("skipped: {what} is not installed");
    }
    !present
}

/// tests/clients/calc_webservice.py (with `flags`) run against the real
/// binary on a fresh database: the cells Calc computed (none holding an
/// error) and the flywheel jobs the service stored meanwhile.
fn calc_cells(flags: &[&str]) -> (Value, Value) {
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let mut service = start(&format!("sqlite://{}/calc.db", dir.path().display()), port);
    let profile = dir.path().join("profile");
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/clients/calc_webservice.py");
    let out = Command::new(PYTHON)
        .arg(script)
        .args(flags)
        .args([&format!("http://127.0.0.1:{port}"), profile.to_str().unwrap()])
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
    (cells, serde_json::from_str(&jobs).unwrap())
}

/// P.103 at F = 1200 N·m, ε = 0.03: I_approx = 348.989…·(1200/500)·(0.04/0.03)
/// (case F1; ΔE scales with F), I_exact as the engine computes it in-process,
/// and 1 slug·ft² = 1.355818 kg·m² (NIST SP 811, B.9).
#[tokio::test]
async fn libreoffice_calc_fetches_answers_with_webservice() {
    if skipped(calc_available(), "LibreOffice Calc with python3-uno") {
        return;
    }
    let (cells, jobs) = calc_cells(&[]);
    let app = TestApp::new().await;
    let exact: f64 =
        app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1200&eps=0.03").await.text.parse().unwrap();
    assert_eq!(cells["B5"].as_f64().unwrap(), exact, "every digit reaches the cell");
    assert_eq!(cells["B8"].as_str().unwrap().parse::<f64>().unwrap(), exact);
    let approx = case("F1_p103_slider_flywheel")["expected"]["I_approx_kg_m2"].as_f64().unwrap() * 2.4 * (4.0 / 3.0);
    assert!((cells["B6"].as_f64().unwrap() / approx - 1.0).abs() < 1e-9, "{cells}");
    assert!((cells["B7"].as_f64().unwrap() * 1.355818 / exact - 1.0).abs() < 1e-6, "{cells}");
    // Calc itself called the service: the job of its parameters is stored there.
    let asked = jobs["items"].as_array().unwrap().iter().any(|j| {
        j["request"]["constants"]["F"].as_f64() == Some(1200.0) && j["request"]["irregularity"].as_f64() == Some(0.03)
    });
    assert!(asked, "no job of F = 1200, ε = 0.03 in the service Calc called: {jobs}");
}

/// The same in a Spanish Calc (es-ES locale, Spanish interface from
/// Debian's libreoffice-l10n-es): formulas typed as VALOR(SERVICIOWEB(…)),
/// the sheet writing F = 1200,5 and ε = 0,03 (and 0,025, every digit) itself, the
/// answers asked with `decimal=comma` and read by VALOR equal to the
/// English run's (the service's own answer for 1200.5 and 0.03) to every
/// digit; without `decimal=comma`, VALOR cannot read the answer (why the
/// parameter exists). The closed-form scaling of case F1 checks I_approx.
/// An error (ε = 3) reaches its cell as the service's Spanish reason with
/// `lang=es&errors=text`, where Calc shows only #¡VALOR! for a 4xx; and
/// through docs/lab.md's SI.ERROR(VALOR(x); x), not as Err:502.
#[tokio::test]
async fn a_spanish_calc_reads_decimal_commas() {
    let spanish = std::path::Path::new("/usr/lib/libreoffice/program/resource/es").exists();
    if skipped(calc_available() && spanish, "LibreOffice Calc with python3-uno and libreoffice-l10n-es") {
        return;
    }
    let (cells, _) = calc_cells(&["--es"]);
    assert_eq!(cells["decimal_separator"], "0,03", "the sheet's locale writes decimal commas");
    let app = TestApp::new().await;
    let base = "/v1/templates/p103-slider-flywheel/result/inertia_exact";
    let english = |q: String| {
        let app = &app;
        async move { app.get(&format!("{base}?{q}")).await.text.parse::<f64>().unwrap() }
    };
    let exact = english("F=1200.5&eps=0.03".into()).await;
    assert_eq!(cells["B5"].as_f64().unwrap(), exact, "every digit reaches the cell");
    assert_eq!(cells["B8"].as_str().unwrap(), exact.to_string().replace('.', ","), "the text VALOR read");
    let approx = case("F1_p103_slider_flywheel")["expected"]["I_approx_kg_m2"].as_f64().unwrap();
    let approx = approx * (1200.5 / 500.0) * (0.04 / 0.03);
    assert!((cells["B6"].as_f64().unwrap() / approx - 1.0).abs() < 1e-9, "{cells}");
    assert!((cells["B7"].as_f64().unwrap() * 1.355818 / exact - 1.0).abs() < 1e-6, "{cells}");
    for (k, f) in [500, 750, 1000, 1250, 1500].into_iter().enumerate() {
        assert_eq!(cells["study"][k].as_f64().unwrap(), english(format!("F={f}&eps=0.03")).await, "F = {f}");
    }
    assert_ne!(cells["B9_error"], 0, "VALOR of a decimal point in es-ES is an error: {cells}");
    let kept = cells["B17"].as_f64().unwrap();
    assert!((kept - 0.025).abs() < 1e-6, "ε = 0,025 reached the service with every digit: {kept}");
    let reason = app.get(&format!("{base}?F=1200,5&eps=3&decimal=comma&lang=es&errors=text")).await.text;
    assert!(reason.starts_with("eps: 3 está por encima del valor máximo"), "{reason}");
    assert_eq!(cells["B18"].as_str().unwrap(), reason, "the cell shows the reason in Spanish, not #¡VALOR!");
    // docs/lab.md's recipe, SI.ERROR(VALOR(x); x): the number where there is one, else the reason.
    assert_eq!(cells["B19"].as_str().unwrap(), reason, "SI.ERROR gives the reason, not Err:502");
}

/// The example sheets a lab opens (examples/p103-flywheel.fods and its
/// Spanish copy p103-flywheel-es.fods, saved by the script above from a
/// real Calc) call the service at its default address, and only templates,
/// results and parameters that exist; the Spanish one is an es-ES sheet
/// that asks for decimal commas.
#[tokio::test]
async fn the_example_sheets_call_what_the_service_has() {
    let app = TestApp::new().await;
    for (file, spanish) in [("p103-flywheel.fods", false), ("p103-flywheel-es.fods", true)] {
        let text = std::fs::read_to_string(format!("{}/examples/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        assert!(text.contains(&format!("http://{}", mechdyn::config::DEFAULT_ADDR)), "{file}: the address in B1");
        if spanish {
            assert!(text.contains("fo:language=\"es\" fo:country=\"ES\""), "{file}: an es-ES sheet");
            let formulas: Vec<&str> =
                text.split("table:formula=\"").skip(1).filter_map(|f| f.split('"').next()).collect();
            let commas = formulas.iter().filter(|f| f.contains("decimal=comma")).count();
            assert_eq!(commas, formulas.len() - 1, "{file}: every call asks for decimal commas but B9's");
            // A parameter is concatenated with every digit (TEXT(B3;"0,00") sent ε = 0,025 as 0,03).
            let rounded = formulas.iter().filter(|f| f.contains("TEXT(")).count();
            assert!(rounded <= 1, "{file}: {rounded} formulas round a parameter with TEXT (B9 shows why not)");
        }
        calls_exist(&app, &text).await;
    }
}

async fn calls_exist(app: &TestApp, text: &str) {
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
        // The query's own names (a unit, the decimal mark, the language, errors as text) are no parameters.
        let own = ["unit", "decimal", "lang", "errors"];
        for name in names.iter().filter(|n| !own.contains(n)) {
            assert!(t["parameters"].get(*name).is_some(), "{call}: no parameter {name}");
        }
        let answer = app.get(&format!("/v1/templates/{id}/result/{pointer}")).await;
        assert_eq!(answer.content_type, "text/plain; charset=utf-8", "{call}: {}", answer.text);
    }
}
