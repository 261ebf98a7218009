//! Every operation's documented request example works: a user who presses
//! "Try it out" in the interactive docs gets a computed, stored job.

use crate::helpers::{TestApp, example};
use axum::http::StatusCode;
use serde_json::Value;

/// Each POST operation of the OpenAPI document, with the component schema of its body.
fn operations() -> Vec<(String, String)> {
    let doc = serde_json::to_value(mechdyn::api::openapi()).unwrap();
    let mut ops = Vec::new();
    for (path, item) in doc["paths"].as_object().unwrap() {
        let Some(post) = item.get("post") else { continue };
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
    }
}

/// Client generators name a method after each operationId: they must differ.
#[test]
fn operation_ids_are_unique() {
    let doc = serde_json::to_value(mechdyn::api::openapi()).unwrap();
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
