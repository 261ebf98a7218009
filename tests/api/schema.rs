//! The published schema accepts what the service accepts: every request of
//! the problem library, every built-in template's request, and every
//! example the document itself shows, each validated against the served
//! document by a JSON Schema validator (Python's `jsonschema`, from PyPI:
//! JSON Schema 2020-12, OpenAPI 3.1's dialect; `tests/clients/validate_schema.py`).
//! Before, three of the library's requests failed the document (a spring's
//! ends were documented as objects, a mechanism's points as required).
//!
//! Skipped with a message when no Python has `jsonschema`; `.ci/run`
//! installs it into `.venv` and sets `MECHDYN_REQUIRE_JSONSCHEMA`, which
//! makes a missing validator a failure.

use serde_json::{Value, json};
use std::process::Command;

/// The kind each request of `library/requests/` is POSTed to.
pub(crate) const LIBRARY_KINDS: &[(&str, &str)] = &[
    ("a01_pendulum", "/v1/dynamics"),
    ("a03_andrews_squeezer", "/v1/dynamics"),
    ("d1_scotch_yoke_machine", "/v1/dynamics"),
    ("k1_offset_slider_crank", "/v1/kinetostatics"),
    ("k5_differential", "/v1/kinetostatics"),
    ("p103_slider", "/v1/flywheel"),
    ("p103_slider_machine", "/v1/flywheel"),
    ("p107_two_stroke", "/v1/flywheel"),
    ("p113_pulley", "/v1/flywheel"),
    ("p68_two_link_arm", "/v1/dynamics"),
    ("punch_press_us", "/v1/flywheel"),
    ("slider_crank_startup", "/v1/dynamics"),
];

/// One token of a JSON pointer (RFC 6901).
fn token(key: &str) -> String {
    key.replace('~', "~0").replace('/', "~1")
}

/// The pointer of the request schema of the POST at `path`.
fn request_schema(doc: &Value, path: &str) -> String {
    let post = &doc["paths"][path]["post"];
    let schema = post["requestBody"]["content"]["application/json"]["schema"]["$ref"].as_str();
    schema.unwrap_or_else(|| panic!("no request schema for {path}")).to_string()
}

/// Every example the document shows, with the schema it illustrates: a
/// JSON request's or answer's (its media type's `schema`), a parameter's
/// (its `schema`), a schema's own (itself). Text and CSV examples are left
/// out (strings of a string schema).
fn examples(doc: &Value, at: &str, cases: &mut Vec<Value>) {
    match doc {
        Value::Object(map) => {
            let media = at.rsplit_once("/content/").map(|(_, mime)| mime);
            let schema = match media {
                Some(mime) if map.contains_key("schema") => mime.contains("json").then(|| format!("{at}/schema")),
                Some(_) => None,
                None if at.contains("/parameters/") => map.contains_key("schema").then(|| format!("{at}/schema")),
                None => Some(at.to_string()),
            };
            if let Some(schema) = schema {
                let shown = map.get("example").into_iter().map(|e| ("example".to_string(), e.clone()));
                let named = map.get("examples").and_then(Value::as_object).into_iter().flatten();
                let named = named.map(|(name, e)| (format!("example '{name}'"), e["value"].clone()));
                for (what, instance) in shown.chain(named) {
                    cases.push(json!({"what": format!("the {what} at {at}"), "schema": format!("#{schema}"), "instance": instance}));
                }
            }
            for (key, value) in map.iter().filter(|(k, _)| *k != "example" && *k != "examples") {
                examples(value, &format!("{at}/{}", token(key)), cases);
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                examples(item, &format!("{at}/{i}"), cases);
            }
        }
        _ => {}
    }
}

/// The Python that has `jsonschema`, or None.
fn python() -> Option<String> {
    let venv = format!("{}/.venv/bin/python", env!("CARGO_MANIFEST_DIR"));
    let candidates = [venv.as_str(), "python3"];
    let has = |p: &str| Command::new(p).args(["-c", "import jsonschema"]).output().is_ok_and(|o| o.status.success());
    candidates.into_iter().find(|p| has(p)).map(String::from)
}

#[test]
fn the_document_accepts_every_library_request_template_and_example() {
    let Some(python) = python() else {
        let required = std::env::var_os("MECHDYN_REQUIRE_JSONSCHEMA").is_some();
        assert!(!required, "MECHDYN_REQUIRE_JSONSCHEMA is set and no Python has jsonschema");
        eprintln!("skipped: no Python with jsonschema (`.venv/bin/pip install jsonschema`)");
        return;
    };
    let doc = mechdyn::registry().openapi();
    let mut cases = Vec::new();
    let root = env!("CARGO_MANIFEST_DIR");
    let files: Vec<String> = std::fs::read_dir(format!("{root}/library/requests"))
        .unwrap()
        .map(|e| e.unwrap().path().file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    for file in &files {
        let kind = LIBRARY_KINDS.iter().find(|(f, _)| f == file).unwrap_or_else(|| panic!("{file}: which kind?"));
        let instance: Value =
            serde_json::from_str(&std::fs::read_to_string(format!("{root}/library/requests/{file}.json")).unwrap())
                .unwrap();
        let what = format!("library/requests/{file}.json");
        cases.push(json!({"what": what, "schema": request_schema(&doc, kind.1), "instance": instance}));
    }
    for t in mechdyn::api::templates::builtin() {
        let kind = mechdyn::registry().find(&t.kind).unwrap();
        let what = format!("template {}'s request", t.id);
        cases.push(json!({"what": what, "schema": request_schema(&doc, kind.path()), "instance": t.request}));
    }
    let before = cases.len();
    examples(&doc, "", &mut cases);
    assert!(cases.len() - before > 50, "only {} examples found in the document", cases.len() - before);
    let dir = tempfile::tempdir().unwrap();
    let (doc_file, cases_file) = (dir.path().join("openapi.json"), dir.path().join("cases.json"));
    std::fs::write(&doc_file, serde_json::to_vec(&doc).unwrap()).unwrap();
    std::fs::write(&cases_file, serde_json::to_vec(&cases).unwrap()).unwrap();
    let out = Command::new(python)
        .arg(format!("{root}/tests/clients/validate_schema.py"))
        .args([&doc_file, &cases_file])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{said}{}", String::from_utf8_lossy(&out.stderr));
    eprintln!("{}", said.trim());
}
