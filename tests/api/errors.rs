//! Bad input gets a clear 4xx problem+json naming the field; hard cases give
//! a right answer or a clear 422; never a 500, never NaN in a 201.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

fn with(mut body: Value, key: &str, value: Value) -> Value {
    body[key] = value;
    body
}

fn pointers(errors: &[(String, String)]) -> Vec<&str> {
    errors.iter().map(|e| e.0.as_str()).collect()
}

#[tokio::test]
async fn malformed_json_is_400_problem() {
    let app = TestApp::new().await;
    let r = app.post_raw("/v1/flywheel", "application/json", "{\"mean_speed\": ").await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    assert_eq!(r.content_type, "application/problem+json");
    assert_eq!(r.json()["status"], 400);
}

#[tokio::test]
async fn wrong_or_missing_content_type_is_415() {
    let app = TestApp::new().await;
    let body = request("p103_slider").to_string();
    for ct in ["text/plain", ""] {
        let r = app.post_raw("/v1/flywheel", ct, body.clone()).await;
        assert_eq!(r.status, StatusCode::UNSUPPORTED_MEDIA_TYPE, "{ct}");
        assert_eq!(r.content_type, "application/problem+json");
    }
}

#[tokio::test]
async fn a_body_over_the_limit_is_413() {
    let app = TestApp::with_limit(1000).await;
    let mut body = request("p103_slider");
    body["torques"][0]["name"] = json!("x".repeat(2000));
    let r = app.post("/v1/flywheel", &body).await;
    assert_eq!(r.status, StatusCode::PAYLOAD_TOO_LARGE, "{}", r.text);
    assert_eq!(r.content_type, "application/problem+json");
    assert!(r.json()["detail"].as_str().unwrap().contains("1000 bytes"));
}

#[tokio::test]
async fn every_invalid_field_is_reported_with_its_pointer() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["irregularity"] = json!(2.5);
    body["period"] = json!(-1);
    body["torques"][0]["value"]["segments"][0]["expr"] = json!("-500*sin(phi");
    body["reduced_inertia"] = json!("5 kg");
    body["torques"][1]["speling"] = json!(1);
    body["extra"] = json!(true);
    let errors = app.flywheel_422(&body).await;
    let p = pointers(&errors);
    for want in [
        "/irregularity",
        "/period",
        "/torques/0/value/segments/0/expr",
        "/reduced_inertia",
        "/torques/1/speling",
        "/extra",
    ] {
        assert!(p.contains(&want), "{want} missing from {errors:?}");
    }
}

#[tokio::test]
async fn a_field_of_the_wrong_type_is_422_with_its_pointer() {
    let app = TestApp::new().await;
    let errors = app.flywheel_422(&with(request("p103_slider"), "irregularity", json!("lots"))).await;
    assert_eq!(pointers(&errors), ["/irregularity"]);
    let errors = app.flywheel_422(&json!({"mean_speed": 1, "irregularity": 0.1})).await;
    assert_eq!(pointers(&errors), ["/torques"]);
    let r = app.post("/v1/kinetostatics", &json!({"input": {"joint": "O", "speed": 1}})).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(r.json()["errors"][0], json!({"pointer": "/mechanism", "message": "required field is missing"}));
}

/// Every structural error is listed, not only the first serde meets (the
/// reader sets each aside and reads on): K1 with a joint's name left out,
/// the input's joint given by its index, the steps in words and a joint
/// that is a number, in the asker's language; what a stand-in lacks (a
/// joint's own fields, where an object stands in for the number) is not the
/// client's error, and a body wrong only once is still one error.
#[tokio::test]
async fn every_field_of_the_wrong_type_or_left_out_is_listed() {
    let app = TestApp::new().await;
    let mut k1 = request("k1_offset_slider_crank");
    k1["mechanism"]["joints"][1].as_object_mut().unwrap().remove("name");
    k1["input"]["joint"] = json!(0);
    k1["input"]["steps"] = json!("muchos");
    k1["mechanism"]["joints"][3] = json!(7);
    k1["loads"][0]["colour"] = json!("red");
    let r = crate::spanish::in_spanish(&app, "POST", "/v1/kinetostatics", Some(&k1)).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].as_array().unwrap().clone();
    let at: Vec<&str> = errors.iter().map(|e| e["pointer"].as_str().unwrap()).collect();
    assert_eq!(
        at,
        ["/loads/0/colour", "/input/joint", "/input/steps", "/mechanism/joints/1/name", "/mechanism/joints/3"],
        "{}",
        r.text
    );
    assert_eq!(errors[3]["message"], "falta un campo obligatorio");
    assert!(errors[2]["message"].as_str().unwrap().contains("\"muchos\""), "{}", errors[2]);
    assert_eq!(r.json()["detail"], "5 campos no válidos");
    k1["mechanism"]["joints"][3] = request("k1_offset_slider_crank")["mechanism"]["joints"][3].clone();
    k1["mechanism"]["joints"][1]["name"] = json!("A");
    k1["loads"][0].as_object_mut().unwrap().remove("colour");
    k1["input"]["steps"] = json!(4);
    assert_eq!(app.pointers("/v1/kinetostatics", &k1).await, ["/input/joint"]);
}

#[tokio::test]
async fn units_of_the_wrong_dimension_or_unknown_are_named() {
    let app = TestApp::new().await;
    let errors = app.flywheel_422(&with(request("p103_slider"), "mean_speed", json!("60 1/s"))).await;
    assert_eq!(errors[0].0, "/mean_speed");
    assert!(errors[0].1.contains("rad/s"), "{errors:?}");
    let errors = app.flywheel_422(&with(request("p103_slider"), "mean_speed", json!("60 rmp"))).await;
    assert!(errors[0].1.contains("unknown unit 'rmp'"), "{errors:?}");
}

#[tokio::test]
async fn speeds_must_be_positive_and_given_one_way() {
    let app = TestApp::new().await;
    for (speed, eps, pointer) in [
        (json!(0), json!(0.04), "/mean_speed"),
        (json!(-3), json!(0.04), "/mean_speed"),
        (json!(6.0), json!(2.0), "/irregularity"),
        (json!(6.0), json!(0), "/irregularity"),
    ] {
        let body = with(with(request("p103_slider"), "mean_speed", speed), "irregularity", eps);
        assert_eq!(pointers(&app.flywheel_422(&body).await), [pointer]);
    }
    let both = with(request("p103_slider"), "min_speed", json!("50 rpm"));
    assert_eq!(pointers(&app.flywheel_422(&both).await), [""]);
    let mut inverted = request("punch_press_us");
    inverted["min_speed"] = json!("320 rpm");
    assert_eq!(pointers(&app.flywheel_422(&inverted).await), ["/min_speed"]);
}

#[tokio::test]
async fn period_must_be_positive() {
    let app = TestApp::new().await;
    for period in [json!(0), json!("-2*pi"), json!("0 deg")] {
        assert_eq!(pointers(&app.flywheel_422(&with(request("p103_slider"), "period", period)).await), ["/period"]);
    }
}

#[tokio::test]
async fn overlapping_segments_are_refused() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["torques"][0]["value"]["segments"] = json!([
        {"from": 0, "to": 2, "expr": "1"}, {"from": 1.5, "to": 3, "expr": "2"}
    ]);
    let errors = app.flywheel_422(&body).await;
    assert_eq!(pointers(&errors), ["/torques/0/value/segments/1"]);
    assert!(errors[0].1.contains("overlaps"));
}

#[tokio::test]
async fn table_angles_must_increase() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["torques"][0]["value"] = json!({"table": {"angle": [0, 2, 1], "value": [1, 2, 3]}});
    assert_eq!(pointers(&app.flywheel_422(&body).await), ["/torques/0/value/table/angle/2"]);
}

#[tokio::test]
async fn an_unbalanced_cycle_is_422_with_its_net_work() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["torques"][1] = json!({"name": "motor", "value": "100 N*m"});
    let errors = app.flywheel_422(&body).await;
    assert_eq!(pointers(&errors), ["/torques"]);
    // Net work: 100·2π − 1000 = −371.68 J.
    assert!(errors[0].1.contains("-371.68"), "{errors:?}");
}

#[tokio::test]
async fn a_function_that_is_not_finite_is_named() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["reduced_inertia"] = json!({"expr": "1/(phi - 1)"});
    let errors = app.flywheel_422(&body).await;
    assert_eq!(pointers(&errors), ["/reduced_inertia"], "{errors:?}");
}

#[tokio::test]
async fn zero_torque_gives_zero_inertia_not_nan() {
    let app = TestApp::new().await;
    let body = json!({"mean_speed": 10, "irregularity": 0.01, "torques": [{"name": "none", "value": 0}]});
    let r = app.flywheel(&body).await["result"].clone();
    assert_eq!(r["inertia_approximate"], 0.0);
    assert_eq!(r["inertia_exact"], 0.0);
    assert!(!r["warnings"].as_array().unwrap().is_empty());
}

#[tokio::test]
async fn unknown_routes_and_jobs_are_404_problems() {
    let app = TestApp::new().await;
    for path in ["/v1/jobs/00000000-0000-4000-8000-000000000000", "/v1/jobs/not-a-uuid", "/nope"] {
        let r = app.get(path).await;
        assert_eq!(r.status, StatusCode::NOT_FOUND, "{path}");
        assert_eq!(r.content_type, "application/problem+json");
    }
}

#[tokio::test]
async fn invalid_query_parameters_are_400_with_their_names() {
    let app = TestApp::new().await;
    let r = app.get("/v1/jobs?kind=boat&limit=0&color=red").await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    let names: Vec<String> =
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["parameter"].as_str().unwrap().to_string()).collect();
    for want in ["kind", "limit", "color"] {
        assert!(names.iter().any(|n| n == want), "{names:?}");
    }
}

/// A flywheel already provided by existing inertia: no disk, and a warning why.
#[tokio::test]
async fn no_disk_when_the_existing_inertia_suffices() {
    let app = TestApp::new().await;
    let mut body = request("p113_pulley");
    body["existing_inertia"] = json!("100 kg*m^2");
    body["flywheel"] = json!({"disk": {"density": "7850 kg/m^3", "radius": "0.3 m"}});
    let r = app.flywheel(&body).await["result"].clone();
    assert!(r["flywheel_inertia"]["exact"].as_f64().unwrap() < 0.0);
    assert!(r["disk"].is_null());
    assert!(r["warnings"][0].as_str().unwrap().contains("no disk"), "{}", r["warnings"]);
}

/// A name of the contract's lists written in another case is read as the
/// name it matches, for a field and for an object's `type`: K1 with a
/// joint "Revolute" gives the driving torque of the one written
/// "revolute", bit for bit, and A01 asked of "DOPRI5" answers that
/// `dopri5` integrated. A name that matches none in any case is refused as
/// before, naming the list.
#[tokio::test]
async fn a_name_in_another_case_is_read_as_the_name() {
    let app = TestApp::new().await;
    let as_written = k1_driving(&app, "revolute").await;
    assert!(as_written.is_number() && as_written == k1_driving(&app, "Revolute").await);

    let a01 = with(with(request("a01_pendulum"), "duration", json!("2 s")), "integrator", json!("DOPRI5"));
    let r = app.post("/v1/dynamics", &a01).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert_eq!(r.json()["result"]["accuracy"]["integrator"], "dopri5");
    let r = app.post("/v1/dynamics", &with(a01, "integrator", json!("DOPRI"))).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let error = &r.json()["errors"][0];
    assert_eq!(error["pointer"], "/integrator");
    assert!(error["message"].as_str().unwrap().contains(r#""auto", "dopri5", "dop853", "radau5""#), "{error}");
}

/// The lab's first request written in Spanish words (i18n/names.rs): a cam
/// with a follower "Rodillo" "de traslación", its laws "Cicloidal" and
/// "reposo", sized for 30°, is answered as the same request in the
/// contract's names, bit for bit (its summary); K1 with a joint
/// "Revolución" gives the driving torque of "revolute". A word of another
/// list ("reposo" as a follower) is refused as before, naming the list.
#[tokio::test]
async fn a_name_written_in_spanish_is_read_as_the_name() {
    let app = TestApp::new().await;
    let cam = |follower: &str, motion: &str, [rise, dwell]: [&str; 2]| {
        json!({
            "follower": {"type": follower, "motion": motion, "roller_radius": "10 mm", "offset": "5 mm"},
            "program": [{"to": "90 deg", "law": rise, "lift": "20 mm"}, {"to": "180 deg", "law": dwell},
                        {"to": "270 deg", "law": rise, "lift": 0}, {"to": "360 deg", "law": dwell}],
            "size": {"max_pressure_angle": "30 deg"}, "speed": "100 rpm"
        })
    };
    let english = app.post("/v1/cams", &cam("roller", "translating", ["cycloidal", "dwell"])).await;
    let spanish = app.post("/v1/cams?lang=es", &cam("Rodillo", "de traslación", ["Cicloidal", "reposo"])).await;
    assert_eq!((english.status, spanish.status), (StatusCode::CREATED, StatusCode::CREATED), "{}", spanish.text);
    let summary = |r: &crate::helpers::Reply| r.json()["result"]["summary"].clone();
    assert!(summary(&english)["base_radius"].is_number());
    assert_eq!(summary(&english), summary(&spanish));

    let as_written = k1_driving(&app, "revolute").await;
    assert!(as_written.is_number() && as_written == k1_driving(&app, "Revolución").await);

    let r = app.post("/v1/cams?lang=es", &cam("reposo", "translating", ["cycloidal", "dwell"])).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let error = &r.json()["errors"][0];
    assert_eq!(error["pointer"], "/follower/type");
    assert!(error["message"].as_str().unwrap().contains(r#""flat", "roller", "knife""#), "{error}");
}

/// K1 over 4 steps with its first joint's type written `first`: the
/// driving torque at its second step (the job must be created).
async fn k1_driving(app: &TestApp, first: &str) -> Value {
    let mut k1 = request("k1_offset_slider_crank");
    k1["input"]["steps"] = json!(4);
    k1["mechanism"]["joints"][0]["type"] = json!(first);
    let r = app.post("/v1/kinetostatics", &k1).await;
    assert_eq!(r.status, StatusCode::CREATED, "{first}: {}", r.text);
    r.json()["result"]["steps"][1]["driving"].clone()
}
