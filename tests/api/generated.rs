//! The document as a grading script's author uses it (issue 49): a Python
//! client generated from the served `/openapi.json` by openapi-python-client
//! (PyPI) with `openapi/openapi-python-client.yaml`, without a warning, then
//! `tests/clients/generated_client.py` on the real binary: every kind's
//! documented example, every request of `library/requests` and every built-in
//! template's request posted typed and read back typed as its kind's job;
//! parts, CSV, a plot, a DXF and a class's CSV grade through the generated
//! calls; and openapi-core (PyPI) validating every answer received (errors,
//! HTML, CSV, SVG, DXF included) against the document.
//!
//! Skipped without a `.venv` that has both, unless MECHDYN_REQUIRE_GENERATORS
//! is set (CI sets it).

use crate::crash::{free_port, start_with};
use serde_json::{Value, json};
use std::process::Command;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// `.venv`'s Python and generator, when both are there with openapi-core.
fn tools() -> Option<(String, String)> {
    let (python, generator) = (format!("{ROOT}/.venv/bin/python"), format!("{ROOT}/.venv/bin/openapi-python-client"));
    let has = Command::new(&python).args(["-c", "import openapi_core, openapi_python_client, requests"]).output();
    has.is_ok_and(|o| o.status.success()).then_some((python, generator))
}

/// The library's requests and the built-in templates' requests: {what, path, body}.
fn cases() -> Vec<Value> {
    let mut cases: Vec<Value> = crate::schema::LIBRARY_KINDS
        .iter()
        .map(|(file, path)| {
            let body = crate::helpers::request(file);
            json!({"what": format!("library/requests/{file}.json"), "path": path, "body": body})
        })
        .collect();
    for t in mechdyn::api::templates::builtin() {
        let path = mechdyn::registry().find(&t.kind).unwrap().path();
        cases.push(json!({"what": format!("template {}", t.id), "path": path, "body": t.request}));
    }
    cases
}

#[test]
fn a_client_generated_from_the_document_reads_every_answer_typed_and_openapi_core_finds_no_mismatch() {
    let Some((python, generator)) = tools() else {
        assert!(std::env::var_os("MECHDYN_REQUIRE_GENERATORS").is_none(), "no .venv with the generators");
        return eprintln!("skipped: `.venv/bin/pip install openapi-python-client openapi-core requests`");
    };
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let mut child = start_with(&format!("sqlite://{}", dir.path().join("jobs.db").display()), port, &[]);
    let base = format!("http://127.0.0.1:{port}");
    let out = Command::new(generator)
        .args(["generate", "--url", &format!("{base}/openapi.json"), "--meta", "none"])
        .args(["--config", &format!("{ROOT}/openapi/openapi-python-client.yaml")])
        .args(["--custom-template-path", &format!("{ROOT}/clients/python/templates")])
        .arg("--output-path")
        .arg(dir.path().join("mechdyn_client"))
        .output()
        .unwrap();
    let said = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success() && !said.to_lowercase().contains("warning"), "the generator said: {said}");
    let cases_file = dir.path().join("cases.json");
    std::fs::write(&cases_file, serde_json::to_vec(&cases()).unwrap()).unwrap();
    let run = Command::new(&python)
        .arg(format!("{ROOT}/tests/clients/generated_client.py"))
        .arg(&base)
        .arg(dir.path())
        .arg(&cases_file)
        .output()
        .unwrap();
    child.kill().unwrap();
    child.wait().unwrap();
    let said = format!("{}{}", String::from_utf8_lossy(&run.stdout), String::from_utf8_lossy(&run.stderr));
    assert!(run.status.success(), "{said}");
    assert!(said.contains("openapi-core validated"), "{said}");
    eprintln!("{}", said.trim());
}
