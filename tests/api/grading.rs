//! `POST /v1/check`: answers judged against the engine's, with units,
//! tolerances, slips named in the feedback, and the course platforms'
//! results documents.

use crate::helpers::{TestApp, case, request};
use axum::http::StatusCode;
use serde_json::{Value, json};
use std::f64::consts::PI;

/// 1 slug·ft² in kg·m² (NIST SP 811, B.9: 1.355818, exact from lbf·s²/ft·ft²).
pub const SLUG_FT2: f64 = 1.355_817_948_331_400_4;

async fn check(app: &TestApp, body: Value) -> Value {
    let r = app.post("/v1/check", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert!(r.location.as_deref().is_some_and(|l| l.starts_with("/v1/jobs/")));
    let job = r.json();
    assert_eq!(job["kind"], "check");
    job["result"].clone()
}

fn item<'a>(result: &'a Value, pointer: &str) -> &'a Value {
    result["items"]
        .as_array()
        .unwrap()
        .iter()
        .find(|i| i["pointer"] == pointer)
        .unwrap_or_else(|| panic!("{pointer}: {result}"))
}

/// P.103 (case F1): I_exact = 353.52 kg·m², I_approx = 348.99 kg·m². An
/// answer in slug·ft² 0.3 % off passes at the default 1 %, fails at 0.1 %;
/// the approximate inertia given for the exact one is named.
#[tokio::test]
async fn p103_answers_with_units_pass_within_their_tolerance() {
    let app = TestApp::new().await;
    let c = case("F1_p103_slider_flywheel");
    let exact = c["expected"]["I_exact_kg_m2"].as_f64().unwrap();
    let approx = c["expected"]["I_approx_kg_m2"].as_f64().unwrap();
    let us = format!("{} slug*ft^2", (exact * 1.003 / SLUG_FT2 * 1e4).round() / 1e4);
    let body = json!({"template": "p103-slider-flywheel", "answers": {
        "inertia_exact": us, "inertia_approximate": approx, "/flywheel_inertia/exact": approx}});
    let r = check(&app, body.clone()).await;
    assert_eq!((r["passed"].as_u64(), r["total"].as_u64()), (Some(2), Some(3)), "{r}");
    assert!((r["score"].as_f64().unwrap() - 2.0 / 3.0).abs() < 1e-15);
    let i = item(&r, "/inertia_exact");
    assert!((i["given"].as_f64().unwrap() / (exact * 1.003) - 1.0).abs() < 1e-6, "{i}");
    assert!((i["expected"].as_f64().unwrap() / exact - 1.0).abs() < 1e-6);
    assert!((i["relative_error"].as_f64().unwrap() - 0.003).abs() < 1e-5, "{i}");
    assert_eq!(i["unit"], "kg*m^2");
    let wrong = item(&r, "/flywheel_inertia/exact");
    assert_eq!(wrong["pass"], false);
    assert_eq!(wrong["slip"], "other_value:/flywheel_inertia/approximate", "{wrong}");
    assert!(wrong["feedback"].as_str().unwrap().contains("flywheel_inertia/approximate"), "{wrong}");

    let strict = json!({"tolerance": {"relative": 0.001}});
    let mut tight = body.clone();
    tight.as_object_mut().unwrap().extend(strict.as_object().unwrap().clone());
    let r = check(&app, tight).await;
    assert_eq!(item(&r, "/inertia_exact")["pass"], false);
    // Per answer, over the request's: 0.5 % for the exact inertia alone.
    tight = body;
    tight["tolerance"] = json!({"relative": 0.001});
    tight["tolerances"] = json!({"inertia_exact": {"relative": 0.005}});
    let r = check(&app, tight).await;
    assert_eq!(item(&r, "/inertia_exact")["pass"], true);
    assert_eq!(item(&r, "/inertia_approximate")["pass"], true);
}

/// Each slip of the issue, given as a student would make it, from the
/// reference values of P.103 (flywheel) and K1 (kinetostatics).
#[tokio::test]
async fn common_slips_are_named() {
    let app = TestApp::new().await;
    let job = app.flywheel(&request("p103_slider")).await;
    let v = |p: &str| job["result"].pointer(p).unwrap().as_f64().unwrap();
    let answers = json!({
        "inertia_exact": v("/inertia_approximate"),
        "omega_max": v("/omega_max") * 60.0 / (2.0 * PI),
        "phi_at_omega_max": v("/phi_at_omega_max").to_degrees(),
        "balance_torque": -v("/balance_torque"),
        "energy_fluctuation": v("/energy_fluctuation") * 2.0 * PI,
        "mean_power": v("/mean_power") * 1000.0,
    });
    let r = check(&app, json!({"job": job["id"], "answers": answers})).await;
    for (pointer, slip, says) in [
        ("/inertia_exact", "other_value:/inertia_approximate", "inertia_approximate"),
        ("/omega_max", "rpm", "rpm"),
        ("/phi_at_omega_max", "degrees", "degrees"),
        ("/balance_torque", "opposite_sign", "opposite sign"),
        ("/energy_fluctuation", "times_2pi", "2π"),
        ("/mean_power", "power_of_ten:3", "unit prefix"),
    ] {
        let i = item(&r, pointer);
        assert_eq!((i["pass"].as_bool(), i["slip"].as_str()), (Some(false), Some(slip)), "{i}");
        assert!(i["feedback"].as_str().unwrap().contains(says), "{i}");
    }
    assert_eq!(r["score"], 0.0);

    // The machine's total inertia given for the flywheel's own: with 100 kg·m²
    // already on the shaft, I_flywheel = I − 100 (case F1: 353.52 − 100).
    let mut with_shaft = request("p103_slider");
    with_shaft["existing_inertia"] = json!("100 kg*m^2");
    let shaft = app.flywheel(&with_shaft).await;
    let total = shaft["result"]["inertia_exact"].as_f64().unwrap();
    let r = check(&app, json!({"job": shaft["id"], "answers": {"flywheel_inertia/exact": total}})).await;
    let i = item(&r, "/flywheel_inertia/exact");
    assert!((i["expected"].as_f64().unwrap() - (total - 100.0)).abs() < 1e-9 * total, "{i}");
    assert_eq!(i["slip"], "other_value:/inertia_exact", "{i}");

    // K1: the reaction at a joint with its sign reversed is the reaction on the joint's other body.
    let k1 = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await.json();
    let reaction = k1["result"]["steps"][1]["reactions"][0].clone();
    let fx = reaction["fx"].as_f64().unwrap();
    let r = check(&app, json!({"job": k1["id"], "answers": {"steps/1/reactions/0/fx": -fx}})).await;
    let i = item(&r, "/steps/1/reactions/0/fx");
    assert_eq!(i["slip"], "opposite_sign", "{i}");
    assert!(i["feedback"].as_str().unwrap().contains("other body"), "{i}");
}

/// An answer that cannot be read fails its item with a message; the
/// request is still a 201. Hiding the expected value hides the relative error too.
#[tokio::test]
async fn unreadable_answers_fail_their_item_only() {
    let app = TestApp::new().await;
    let answers = json!({"inertia_exact": "5 m", "inertia_approximate": "lots", "energy_fluctuation": null,
        "omega_min": "6,15"});
    let r = check(&app, json!({"template": "p103-slider-flywheel", "answers": answers, "reveal": false})).await;
    let said = |p: &str| item(&r, p)["feedback"].as_str().unwrap().to_string();
    assert!(said("/inertia_exact").contains("'5 m' is in m, where the answer is in kg*m^2"), "{r}");
    assert!(said("/inertia_approximate").contains("not a number or a quantity"), "{r}");
    assert!(said("/energy_fluctuation").contains("no answer"), "{r}");
    // A quantity is echoed as written, with its SI value.
    let answers = json!({"inertia_exact": "260 slug*ft^2", "check/irregularity": 0.04});
    let shown = check(&app, json!({"template": "p103-slider-flywheel", "answers": answers})).await;
    assert!(
        item(&shown, "/inertia_exact")["feedback"].as_str().unwrap().contains("(260 slug*ft^2 = 352.51 kg*m^2,"),
        "{shown}"
    );
    assert!(!item(&shown, "/check/irregularity")["feedback"].as_str().unwrap().contains(" 1,"), "{shown}");
    // A decimal comma reads as a point: 6,15 rad/s is 6.15.
    assert_eq!(item(&r, "/omega_min")["given"], 6.15);
    for i in r["items"].as_array().unwrap() {
        assert!(i["expected"].is_null() && i["relative_error"].is_null(), "revealed: {i}");
        assert!(!i["feedback"].as_str().unwrap().contains("expected 3"), "{i}");
    }
}

/// What the instructor got wrong is a 422 at its field; nothing is stored.
#[tokio::test]
async fn bad_checks_are_422_at_their_fields() {
    let app = TestApp::new().await;
    for (body, pointer) in [
        (json!({"answers": {"x": 1}}), ""),
        (json!({"template": "p103-slider-flywheel", "job": "x", "answers": {"x": 1}}), "/job"),
        (json!({"template": "nope", "answers": {"inertia_exact": 1}}), "/template"),
        (json!({"template": "p103-slider-flywheel", "answers": {"inertia_exakt": 1}}), "/answers/inertia_exakt"),
        (json!({"template": "p103-slider-flywheel", "answers": {"warnings": 1}}), "/answers/warnings"),
        (json!({"template": "p103-slider-flywheel", "answers": {}}), "/answers"),
        (
            json!({"template": "p103-slider-flywheel", "parameters": {"G": 1}, "answers": {"inertia_exact": 1}}),
            "/parameters/G",
        ),
        (
            json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 1}, "tolerance": {"relative": -1}}),
            "/tolerance/relative",
        ),
        (
            json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 1}, "tolerances": {"omega_max": {}}}),
            "/tolerances/omega_max",
        ),
        (
            json!({"kind": "flywheel", "request": {"mean_speed": "60 rpm"}, "answers": {"inertia_exact": 1}}),
            "/request/torques",
        ),
        (json!({"job": "0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41", "answers": {"x": 1}}), "/job"),
    ] {
        let r = app.post("/v1/check", &body).await;
        assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{body}: {}", r.text);
        let pointers: Vec<Value> =
            r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].clone()).collect();
        assert!(pointers.contains(&json!(pointer)), "{body}: {pointers:?}");
    }
    assert_eq!(app.get("/v1/jobs?kind=check").await.json()["items"], json!([]));
}

/// A student cannot score by answering one value twice (with and without
/// its `/`), nor by leaving out what the instructor requires: a required
/// answer not given fails as "no answer".
#[tokio::test]
async fn the_score_counts_the_required_answers_once() {
    let app = TestApp::new().await;
    let twice =
        json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 353.5, "/inertia_exact": 353.5}});
    let r = app.post("/v1/check", &twice).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert!(r.text.contains("answered twice"), "{}", r.text);
    let required = json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 353.5},
        "required": ["/inertia_exact", "omega_max"]});
    let r = check(&app, required).await;
    assert_eq!((r["passed"].as_u64(), r["total"].as_u64()), (Some(1), Some(2)), "{r}");
    assert!(item(&r, "/omega_max")["feedback"].as_str().unwrap().contains("no answer"));
    let unknown = json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 1}, "required": ["nope"]});
    let r = app.post("/v1/check", &unknown).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/required/0", "{}", r.text);
}

/// The platforms' results documents, checked against their published field
/// lists: PrairieLearn's external grader (docs/externalGrading.md: `score`
/// 0–1 required when gradable, `gradable`, `message`, `tests` with `name`,
/// `points`, `max_points`, `message`) and Gradescope's autograder
/// (autograder_samples docs/specs.md: `score`, `max_score`, `tests` with
/// `score`, `max_score`, `status` passed|failed, `visibility` hidden|
/// after_due_date|after_published|visible).
#[tokio::test]
async fn platform_documents_have_the_published_fields() {
    let app = TestApp::new().await;
    let answers = json!({"inertia_exact": 353.5, "inertia_approximate": 1});
    let pl =
        check(&app, json!({"template": "p103-slider-flywheel", "answers": answers, "format": "prairielearn"})).await;
    assert_eq!((pl["gradable"].as_bool(), pl["score"].as_f64()), (Some(true), Some(0.5)), "{pl}");
    assert!(pl["message"].is_string());
    let tests = pl["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 2);
    for t in tests {
        let keys: Vec<&String> = t.as_object().unwrap().keys().collect();
        let published = ["name", "description", "points", "max_points", "message", "output", "images"];
        assert!(keys.iter().all(|k| published.contains(&k.as_str())), "{keys:?}");
        assert!(t["points"].as_f64().unwrap() <= t["max_points"].as_f64().unwrap());
    }
    let gs = check(&app, json!({"template": "p103-slider-flywheel", "answers": answers, "format": "gradescope"})).await;
    assert_eq!((gs["score"].as_f64(), gs["max_score"].as_f64()), (Some(1.0), Some(2.0)), "{gs}");
    let published = [
        "score",
        "max_score",
        "status",
        "name",
        "name_format",
        "number",
        "output",
        "output_format",
        "tags",
        "visibility",
        "extra_data",
    ];
    for t in gs["tests"].as_array().unwrap() {
        assert!(t.as_object().unwrap().keys().all(|k| published.contains(&k.as_str())), "{t}");
        assert!(["passed", "failed"].contains(&t["status"].as_str().unwrap()));
        assert_eq!(t["status"] == "passed", t["score"] == t["max_score"]);
        assert!(
            ["hidden", "after_due_date", "after_published", "visible"].contains(&t["visibility"].as_str().unwrap())
        );
    }
    assert!(
        ["hidden", "after_due_date", "after_published", "visible"].contains(&gs["stdout_visibility"].as_str().unwrap())
    );
}
