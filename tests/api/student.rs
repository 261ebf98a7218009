//! Errors a student meets: positions quoted as written and pointed at the
//! field that asked for them, a locked structure called locked, units as
//! people type them, JSON mistakes said in words, and every invalid field of
//! a request in one answer.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// A non-Grashof four-bar (s + l = 0.5 + 1.0 > p + q = 0.6 + 0.7): its crank
/// cannot turn fully. Geometry: O2 (0, 0), O4 (1, 0), A (0.6, 0),
/// B = (1.1, √0.24) so that AB = 0.7 and O4B = 0.5.
pub fn non_grashof(input: Value) -> Value {
    json!({
        "mechanism": {
            "points": {"O2": [0, 0], "O4": [1, 0], "A": [0.6, 0], "B": [1.1, 0.24f64.sqrt()]},
            "bodies": [{"name": "crank"}, {"name": "coupler"}, {"name": "rocker"}],
            "joints": [
                {"name": "O2", "type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                {"name": "A", "type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                {"name": "B", "type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                {"name": "O4", "type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}
            ]
        },
        "input": input
    })
}

async fn the_error(app: &TestApp, path: &str, body: &Value) -> (String, String) {
    let r = app.post(path, body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let e = &r.json()["errors"][0];
    (e["pointer"].as_str().unwrap().to_string(), e["message"].as_str().unwrap().to_string())
}

/// A start the crank cannot reach: the message quotes "180 deg" as written,
/// points at /input/start and names the joint where the loop stays open.
#[tokio::test]
async fn an_unreachable_start_is_quoted_as_written_at_its_field() {
    let app = TestApp::new().await;
    let input = json!({"joint": "O2", "speed": "60 rpm", "start": "180 deg", "end": "200 deg", "steps": 4});
    let (pointer, message) = the_error(&app, "/v1/kinetostatics", &non_grashof(input)).await;
    assert_eq!(pointer, "/input/start");
    assert!(message.contains("at input 180 deg (step 1 of 4, the start)"), "{message}");
    assert!(message.contains("the loop through joint"), "{message}");
    assert!(!message.contains("3.14159"), "no radians the user did not write: {message}");
}

/// A triangle of links (two bodies and the ground, three pin joints): no
/// freedom at all (Grübler 3·2 − 2·3 = 0), so it is a structure.
#[tokio::test]
async fn a_structure_is_called_locked_not_unassemblable() {
    let app = TestApp::new().await;
    let body = json!({
        "mechanism": {
            "points": {"O": [0, 0], "A": [1, 0], "B": [0.5, 0.8]},
            "bodies": [{"name": "a"}, {"name": "b"}],
            "joints": [
                {"name": "O", "type": "revolute", "bodies": ["ground", "a"], "at": "O"},
                {"name": "A", "type": "revolute", "bodies": ["ground", "b"], "at": "A"},
                {"name": "B", "type": "revolute", "bodies": ["a", "b"], "at": "B"}
            ]
        },
        "input": {"joint": "O", "speed": "60 rpm", "steps": 4}
    });
    let (pointer, message) = the_error(&app, "/v1/kinetostatics", &body).await;
    assert_eq!(pointer, "/mechanism");
    assert!(message.contains("locked") && message.contains("Grübler's count") && message.contains("= 0"), "{message}");
}

/// "60 RPM", "60rpm" and "4 %" mean 60 rpm and 0.04: P.103 gives the same
/// result to the last bit as with "60 rpm" and 0.04.
#[tokio::test]
async fn units_are_read_as_people_write_them() {
    let app = TestApp::new().await;
    let plain = app.flywheel(&request("p103_slider")).await["result"].clone();
    for (speed, irregularity) in [("60 RPM", json!("4 %")), ("60rpm", json!("4%")), ("60 Rpm", json!(0.04))] {
        let mut body = request("p103_slider");
        body["mean_speed"] = json!(speed);
        body["irregularity"] = irregularity.clone();
        assert_eq!(app.flywheel(&body).await["result"], plain, "{speed}, {irregularity}");
    }
}

/// An array where an object belongs, at the top or inside, and a NaN: said
/// in words, with the pointer.
#[tokio::test]
async fn json_mistakes_are_said_in_words() {
    let app = TestApp::new().await;
    let r = app.post_raw("/v1/flywheel", "application/json", "[60, 0.04]").await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "");
    assert_eq!(r.json()["errors"][0]["message"], "expected an object {...} with named fields, got an array");
    let mut body = request("d1_scotch_yoke_machine");
    body["initial"] = json!([0, 0]);
    let (pointer, message) = the_error(&app, "/v1/dynamics", &body).await;
    assert_eq!(
        (pointer.as_str(), message.as_str()),
        ("/initial", "expected an object {...} with named fields, got an array")
    );
    let r =
        app.post_raw("/v1/flywheel", "application/json", "{\"mean_speed\": \"60 rpm\", \"irregularity\": NaN}").await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    let detail = r.json()["detail"].as_str().unwrap().to_string();
    assert!(detail.contains("near `NaN}`") && detail.contains("not JSON numbers"), "{detail}");
    // In Spanish, every word of it (serde_json's own words mapped by the catalogue).
    let req = axum::http::Request::post("/v1/flywheel?lang=es")
        .header("content-type", "application/json")
        .body(axum::body::Body::from("{\"mean_speed\": \"60 rpm\", \"irregularity\": NaN}"))
        .unwrap();
    let r = app.send(req).await;
    assert_eq!(
        r.json()["detail"],
        "el cuerpo no es JSON válido: se esperaba un valor en la línea 1, columna 42, junto a `NaN}`; NaN e Infinity no \
         son números de JSON: dé un número finito"
    );
}

/// Every invalid field in one answer: the speed's unknown unit does not hide
/// the irregularity out of range.
#[tokio::test]
async fn every_error_of_a_request_comes_in_one_answer() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["mean_speed"] = json!("60 furlongs");
    body["irregularity"] = json!(2.5);
    let errors = app.flywheel_422(&body).await;
    let pointers: Vec<&str> = errors.iter().map(|e| e.0.as_str()).collect();
    assert_eq!(pointers, ["/mean_speed", "/irregularity"], "{errors:?}");
}

/// A quantity string longer than the schema's maxLength (200) is refused at
/// its field, wherever it is.
#[tokio::test]
async fn a_quantity_longer_than_its_schema_allows_is_refused_at_its_field() {
    let app = TestApp::new().await;
    let long = format!("{} rpm", "0".repeat(200));
    let mut body = request("d1_scotch_yoke_machine");
    body["initial"]["speed"] = json!(long);
    let (pointer, message) = the_error(&app, "/v1/dynamics", &body).await;
    assert_eq!(pointer, "/initial/speed");
    assert!(message.contains("at most 200 characters"), "{message}");
    let mut body = request("p103_slider");
    body["reduced_inertia"] = json!(format!("{} kg*m^2", "0".repeat(200)));
    assert_eq!(app.flywheel_422(&body).await[0].0, "/reduced_inertia");
}

/// An irregularity at the edge of double precision (1e-308, found by the
/// fuzz test) overflows the inertia. Before, the NaN went on into the time
/// check, where one SVD of a NaN Jacobian never returned; now the answer is
/// a 422 at once. (A watchdog fails the test instead of hanging it.)
#[test]
fn an_irregularity_that_overflows_the_inertia_is_refused_not_hung() {
    let (done, answer) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut body = request("p103_slider_machine");
        body["irregularity"] = json!(1e-308);
        let b = mechdyn::api::json::parse::<mechdyn::kinds::flywheel::FlywheelRequest>(body.to_string()).unwrap();
        let _ = done.send(
            <mechdyn::kinds::flywheel::Flywheel as mechdyn::kind::Kind>::compute(
                &b.value,
                b.unknown,
                &Default::default(),
            )
            .map(|_| ())
            .map_err(|e| e.problem()),
        );
    });
    let outcome = answer.recv_timeout(std::time::Duration::from_secs(120)).expect("answered, not hung");
    let problem = outcome.expect_err("refused");
    assert_eq!(problem.status, 422);
    assert!(problem.errors[0].message.contains("non-finite"), "{problem:?}");
}
