//! Parts of a result by JSON pointer, in a unit of the client's choice, and
//! every value with its unit, as a spreadsheet reads them (plain text, CSV).

use crate::helpers::{TestApp, example, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use mechdyn::units::parse_unit;
use serde_json::{Value, json};

async fn get_accept(app: &TestApp, path: &str, accept: &str) -> crate::helpers::Reply {
    app.send(Request::get(path).header("accept", accept).body(Body::empty()).unwrap()).await
}

/// The P.103 flywheel (samples as asked) and its job's path.
async fn p103(app: &TestApp, samples: u32) -> (Value, String) {
    let mut body = request("p103_slider");
    body["samples"] = json!(samples);
    let job = app.flywheel(&body).await;
    let path = format!("/v1/jobs/{}", job["id"].as_str().unwrap());
    (job["result"].clone(), path)
}

#[tokio::test]
async fn a_number_is_answered_alone_as_plain_text_with_every_digit() {
    let app = TestApp::new().await;
    let (result, job) = p103(&app, 0).await;
    let r = app.get(&format!("{job}/result/inertia_exact")).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    assert_eq!(r.content_type, "text/plain; charset=utf-8");
    // The same double as the JSON result, bit for bit (shortest round-trip text).
    assert_eq!(r.text.parse::<f64>().unwrap(), result["inertia_exact"].as_f64().unwrap());
    assert_eq!(r.text, result["inertia_exact"].to_string());
    // Nested and indexed parts; an integer stays an integer.
    let nested = app.get(&format!("{job}/result/flywheel_inertia/exact")).await;
    assert_eq!(nested.text, r.text);
    let crossing = app.get(&format!("{job}/result/crossings/0")).await;
    assert_eq!(crossing.text.parse::<f64>().unwrap(), result["crossings"][0].as_f64().unwrap());
    let steps = app.get(&format!("{job}/result/check/steps")).await;
    assert_eq!(steps.text, result["check"]["steps"].to_string());
    // A text is answered without quotes.
    let method = app.get(&format!("{job}/result/accuracy/method")).await;
    assert_eq!(method.text, result["accuracy"]["method"].as_str().unwrap());
}

#[tokio::test]
async fn json_is_answered_for_objects_arrays_and_when_asked() {
    let app = TestApp::new().await;
    let (result, job) = p103(&app, 0).await;
    let object = app.get(&format!("{job}/result/flywheel_inertia")).await;
    assert_eq!(object.content_type, "application/json");
    assert_eq!(object.json(), result["flywheel_inertia"]);
    let array = app.get(&format!("{job}/result/crossings")).await;
    assert_eq!(array.json(), result["crossings"]);
    let number = get_accept(&app, &format!("{job}/result/inertia_exact"), "application/json").await;
    assert_eq!(number.content_type, "application/json");
    assert_eq!(number.json(), result["inertia_exact"]);
}

/// Conversions against the units' definitions: 1 slug·ft² = 1.355818 kg·m²
/// (NIST SP 811, B.9, to its 7 digits), 1 rpm = 2π/60 rad/s, 1 % = 0.01.
#[tokio::test]
async fn unit_converts_a_number_to_any_unit_of_its_dimension() {
    let app = TestApp::new().await;
    let (result, job) = p103(&app, 0).await;
    let number = |path: String| {
        let app = &app;
        async move {
            let r = app.get(&path).await;
            assert_eq!(r.status, StatusCode::OK, "{path}: {}", r.text);
            r.text.parse::<f64>().unwrap()
        }
    };
    let si = result["inertia_exact"].as_f64().unwrap();
    let us = number(format!("{job}/result/inertia_exact?unit=slug*ft%5E2")).await;
    assert!((us * 1.355818 / si - 1.0).abs() < 1e-6, "{us} slug*ft^2 for {si} kg*m^2");
    let rpm = number(format!("{job}/result/omega_max?unit=rpm")).await;
    let omega = result["omega_max"].as_f64().unwrap();
    assert!((rpm - omega * 60.0 / (2.0 * std::f64::consts::PI)).abs() < 1e-12 * rpm);
    let percent = number(format!("{job}/result/check/irregularity?unit=%25")).await;
    assert!((percent - 100.0 * result["check"]["irregularity"].as_f64().unwrap()).abs() < 1e-12);
    let deg = number(format!("{job}/result/crossings/0?unit=deg")).await;
    assert!((deg - result["crossings"][0].as_f64().unwrap().to_degrees()).abs() < 1e-12 * deg);
}

#[tokio::test]
async fn bad_units_and_missing_parts_are_named() {
    let app = TestApp::new().await;
    let (_, job) = p103(&app, 0).await;
    let wrong = app.get(&format!("{job}/result/inertia_exact?unit=rpm")).await;
    assert_eq!(wrong.status, StatusCode::BAD_REQUEST);
    assert_eq!(wrong.content_type, "application/problem+json");
    let e = &wrong.json()["errors"][0];
    assert_eq!(e["parameter"], "unit");
    assert!(e["message"].as_str().unwrap().contains("kg*m^2"), "{e}");
    let text = app.get(&format!("{job}/result/accuracy/method?unit=m")).await;
    assert_eq!(text.status, StatusCode::BAD_REQUEST, "{}", text.text);
    let unknown = app.get(&format!("{job}/result/inertia_exact?units=m")).await;
    assert_eq!(unknown.status, StatusCode::BAD_REQUEST);
    assert_eq!(unknown.json()["errors"][0]["parameter"], "units");
    for missing in ["inertia_exactly", "crossings/99", "crossings/01", "inertia_exact/0"] {
        let r = app.get(&format!("{job}/result/{missing}")).await;
        assert_eq!(r.status, StatusCode::NOT_FOUND, "{missing}: {}", r.text);
        assert_eq!(r.json()["type"], "/problems/no-such-part");
        assert!(r.json()["detail"].as_str().unwrap().contains(&format!("/{missing}")), "{}", r.text);
    }
    for query in ["angles=grad", "angles=", "format=xml"] {
        let r = app.get(&format!("{job}/values?{query}")).await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "{query}: {}", r.text);
    }
    assert_eq!(app.get(&format!("{job}?angles=null")).await.status, StatusCode::BAD_REQUEST);
    let no_job = app.get("/v1/jobs/0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41/result/inertia_exact").await;
    assert_eq!(no_job.status, StatusCode::NOT_FOUND);
}

/// Every number of every kind's result has a unit the service can convert
/// from (or is dimensionless, or is said to be in "m or rad"): the POSTs'
/// examples of the OpenAPI document, each computed and flattened.
#[tokio::test]
async fn every_number_of_every_kind_has_a_unit() {
    let app = TestApp::new().await;
    let doc = serde_json::to_value(mechdyn::registry().openapi()).unwrap();
    for kind in mechdyn::registry().iter() {
        let mut body = example(&kind.request_schema());
        if kind.name() == "kinetostatics" {
            body = request("k1_offset_slider_crank");
        }
        let r = app.post(kind.path(), &body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}: {}", kind.name(), r.text);
        let values = app.get(&format!("{}/values", r.location.unwrap())).await.json();
        let values = values["values"].as_array().unwrap();
        assert!(values.len() > 3, "{}: {values:?}", kind.name());
        for v in values.iter().filter(|v| v["value"].is_number()) {
            let unit = v["unit"].as_str().unwrap_or_else(|| panic!("{}: no unit for {v}", kind.name()));
            assert!(unit == "1" || unit == "m or rad" || parse_unit(unit).is_ok(), "{}: {v}", kind.name());
        }
        for v in values.iter().filter(|v| !v["value"].is_number()) {
            assert!(v["unit"].is_null(), "{}: a unit for a non-number: {v}", kind.name());
        }
        let units = &doc["components"]["schemas"][kind.result_schema()]["x-units"];
        assert!(units.as_object().is_some_and(|u| !u.is_empty()), "{}: units documented", kind.name());
    }
}

#[tokio::test]
async fn kinetostatics_driving_actions_are_in_their_inputs_units() {
    let app = TestApp::new().await;
    let r = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await;
    let job = r.location.unwrap();
    let values = app.get(&format!("{job}/values")).await.json();
    let unit_of = |pointer: &str| {
        values["values"].as_array().unwrap().iter().find(|v| v["pointer"] == pointer).unwrap()["unit"].clone()
    };
    assert_eq!(unit_of("/steps/1/driving"), "N*m");
    assert_eq!(unit_of("/steps/1/input"), "rad");
    assert_eq!(unit_of("/steps/1/reactions/0/fx"), "N");
    assert_eq!(unit_of("/steps/1/reduced_inertia"), "kg*m^2");
    // 1 lbf·ft = 1.355818 N·m (NIST SP 811, B.9).
    let si: f64 = app.get(&format!("{job}/result/steps/1/driving")).await.text.parse().unwrap();
    let us: f64 = app.get(&format!("{job}/result/steps/1/driving?unit=lbf*ft")).await.text.parse().unwrap();
    assert!((us * 1.355818 / si - 1.0).abs() < 1e-6, "{us} lbf*ft for {si} N*m");
}

#[tokio::test]
async fn values_come_as_csv_with_angles_in_degrees_on_request() {
    let app = TestApp::new().await;
    let (result, job) = p103(&app, 0).await;
    let csv = get_accept(&app, &format!("{job}/values"), "text/csv").await;
    assert_eq!(csv.content_type, "text/csv; charset=utf-8");
    let mut lines = csv.text.lines();
    assert_eq!(lines.next(), Some("pointer,value,unit"));
    let row = |text: &str, pointer: &str| -> Vec<String> {
        let line = text.lines().find(|l| l.starts_with(&format!("{pointer},"))).unwrap().to_string();
        line.split(',').map(String::from).collect()
    };
    let inertia = row(&csv.text, "/inertia_exact");
    assert_eq!(
        (inertia[1].parse::<f64>().unwrap(), inertia[2].as_str()),
        (result["inertia_exact"].as_f64().unwrap(), "kg*m^2")
    );
    let deg = app.get(&format!("{job}/values?format=csv&angles=deg")).await;
    let crossing = row(&deg.text, "/crossings/0");
    assert_eq!(crossing[2], "deg");
    let expected = result["crossings"][0].as_f64().unwrap().to_degrees();
    assert!((crossing[1].parse::<f64>().unwrap() - expected).abs() < 1e-12 * expected);
    let bad = app.get(&format!("{job}/values?angles=grad")).await;
    assert_eq!(bad.status, StatusCode::BAD_REQUEST);
    assert_eq!(bad.json()["errors"][0]["parameter"], "angles");
}

/// `Accept: text/csv` on a job answers its table; a job with no table (a
/// gear, a flywheel asked for no samples) answers its values, never nothing.
#[tokio::test]
async fn csv_of_a_job_is_its_table_or_its_values_never_empty() {
    let app = TestApp::new().await;
    let (result, job) = p103(&app, 13).await;
    let table = app.get(&format!("{job}/result.csv")).await;
    let negotiated = get_accept(&app, &job, "text/csv").await;
    assert_eq!(negotiated.text, table.text);
    assert!(table.text.starts_with("angle_rad,"), "{}", table.text);
    assert_eq!(table.text.lines().count(), 14);
    let deg = app.get(&format!("{job}/result.csv?angles=deg")).await;
    assert!(deg.text.starts_with("angle_deg,"), "{}", deg.text);
    let angle =
        |text: &str, row: usize| text.lines().nth(row).unwrap().split(',').next().unwrap().parse::<f64>().unwrap();
    let last = result["samples"][12]["angle"].as_f64().unwrap();
    assert!((angle(&deg.text, 13) - last.to_degrees()).abs() < 1e-12 * last.to_degrees());
    assert_eq!(angle(&table.text, 13), last);

    let (_, no_samples) = p103(&app, 0).await;
    let values = app.get(&format!("{no_samples}/result.csv")).await;
    assert!(values.text.starts_with("pointer,value,unit\n"), "{}", values.text);
    assert!(values.text.contains("/inertia_exact,"), "{}", values.text);
    let gear = app.post("/v1/gears/geometry", &json!({"module": "4 mm", "teeth": 30})).await;
    let csv = app.get(&format!("{}/result.csv", gear.location.unwrap())).await;
    assert!(csv.text.contains("/pitch_radius,0.06,m"), "{}", csv.text);
}
