//! Every operation's documented request example works: a user who presses
//! "Try it out" in the interactive docs gets a computed, stored job.

use crate::helpers::{TestApp, example};
use axum::http::StatusCode;
use serde_json::Value;

/// Each POST of a job of the OpenAPI document, with the component schema of its body.
fn operations() -> Vec<(String, String)> {
    let doc = serde_json::to_value(mechdyn::registry().openapi()).unwrap();
    let mut ops = Vec::new();
    let kinds: Vec<&str> = mechdyn::registry().iter().map(|k| k.path()).collect();
    for (path, item) in doc["paths"].as_object().unwrap() {
        let Some(post) = item.get("post").filter(|_| kinds.contains(&path.as_str())) else { continue };
        let schema = &post["requestBody"]["content"]["application/json"]["schema"]["$ref"];
        let name = schema.as_str().unwrap().trim_start_matches("#/components/schemas/");
        ops.push((path.clone(), name.to_string()));
    }
    ops
}

#[tokio::test]
async fn every_request_example_is_computed_and_stored() {
    let app = TestApp::new().await;
    let ops = operations();
    assert!(ops.len() >= 7, "expected every job kind, found {ops:?}");
    for (path, schema) in ops {
        let body = example(&schema);
        let r = app.post(&path, &body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{path} with the {schema} example: {}", r.text);
        let job = r.json();
        assert!(job["result"].is_object(), "{path}: no result in {job}");
        let stored = app.get(r.location.as_deref().unwrap()).await;
        assert_eq!(stored.status, StatusCode::OK, "{path}: {}", stored.text);
        assert_eq!(stored.json()["result"], job["result"], "{path}: the stored result differs");
        assert_eq!(stored.json()["request"], body, "{path}: the stored request differs");
        let warnings: Vec<&Value> = job["result"]["warnings"].as_array().into_iter().flatten().collect();
        assert!(warnings.is_empty(), "{path}: the example warns {warnings:?}");
        // The documented 201 shows this very result (its long arrays shortened).
        let doc = serde_json::to_value(mechdyn::registry().openapi()).unwrap();
        let shown = &doc["paths"][&path]["post"]["responses"]["201"]["content"]["application/json"]["example"];
        assert_eq!(shown["request"], body, "{path}");
        assert_eq!(shown["kind"], job["kind"], "{path}");
        let mut result = job["result"].clone();
        shorten(&mut result, 3);
        if let Some(reference) = result.get_mut("job") {
            // A check names its reference job: a stored job's id, shown as the example's own.
            assert!(reference.is_string(), "{path}: {reference}");
            *reference = shown["result"]["job"].clone();
        }
        assert_eq!(shown["result"], result, "{path}: the documented result is not the computed one");
    }
}

fn shorten(v: &mut Value, keep: usize) {
    match v {
        Value::Array(items) => {
            items.truncate(keep);
            items.iter_mut().for_each(|i| shorten(i, keep));
        }
        Value::Object(map) => map.values_mut().for_each(|i| shorten(i, keep)),
        _ => {}
    }
}

/// Each error status of a POST has an example of its own, of its status.
#[test]
fn every_error_status_has_its_own_example() {
    let doc = serde_json::to_value(mechdyn::registry().openapi()).unwrap();
    let responses = &doc["paths"]["/v1/flywheel"]["post"]["responses"];
    for status in ["400", "401", "413", "415", "422", "503", "507"] {
        let example = &responses[status]["content"]["application/problem+json"]["example"];
        assert_eq!(example["status"].to_string(), status, "{status}: {example}");
        if let Some(errors) = example["errors"].as_array() {
            let detail = example["detail"].as_str().unwrap();
            assert!(detail.starts_with(&errors.len().to_string()), "{detail} lists {} errors", errors.len());
        }
    }
}

/// The root (the home page) links the docs, and the docs ask no outside validator.
#[tokio::test]
async fn the_root_leads_to_the_docs_which_need_no_outside_validator() {
    let app = TestApp::new().await;
    let root = app.get("/").await;
    assert_eq!(root.status, StatusCode::OK);
    assert!(root.text.contains("href=\"/docs/\""), "{}", root.text);
    let page = app.get("/docs/").await;
    assert_eq!(page.status, StatusCode::OK);
    let init = app.get("/docs/swagger-initializer.js").await;
    assert!(init.text.contains("\"validatorUrl\": \"none\""), "{}", init.text);
}

/// Client generators name a method after each operationId: they must differ.
#[test]
fn operation_ids_are_unique() {
    let doc = serde_json::to_value(mechdyn::registry().openapi()).unwrap();
    let mut ids: Vec<&str> = doc["paths"]
        .as_object()
        .unwrap()
        .values()
        .flat_map(|item| item.as_object().unwrap().values())
        .map(|op| op["operationId"].as_str().expect("every operation has an operationId"))
        .collect();
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n, "repeated operationIds among {ids:?}");
}

/// The template example of the docs creates a template that answers.
#[tokio::test]
async fn the_template_example_creates_a_template() {
    let app = TestApp::new().await;
    let r = app.post("/v1/templates", &example("NewTemplate")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let job = app.get(&format!("{}/job", r.location.unwrap())).await;
    assert_eq!(job.status, StatusCode::OK, "{}", job.text);
}

/// The served document is the post-processed one (a failed round trip once
/// served the bare one silently): every POST's 201 has its example, every
/// result its units, and a route taking the rest of the path is documented
/// with an ordinary parameter.
#[tokio::test]
async fn the_served_document_has_what_the_registry_adds() {
    let app = TestApp::new().await;
    let doc = app.get("/openapi.json").await.json();
    assert_eq!(doc, mechdyn::registry().openapi());
    for kind in mechdyn::registry().iter() {
        let created = &doc["paths"][kind.path()]["post"]["responses"]["201"]["content"]["application/json"];
        assert!(created["example"]["result"].is_object(), "{}: no example", kind.name());
        assert!(doc["components"]["schemas"][kind.result_schema()]["x-units"].is_object(), "{}", kind.name());
    }
    let paths: Vec<&String> = doc["paths"].as_object().unwrap().keys().collect();
    assert!(paths.iter().any(|p| *p == "/v1/jobs/{id}/result/{pointer}"), "{paths:?}");
    assert!(paths.iter().all(|p| !p.contains("{*")), "{paths:?}");
}
