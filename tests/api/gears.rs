//! Gear calculators (and the equivalent-masses calculator) through the HTTP API.

use crate::helpers::{TestApp, case, close, example};
use axum::http::StatusCode;
use serde_json::json;

/// Involute geometry of reference case K5's question 3 (seed 002): module
/// 4 mm, 30 teeth, 20°: pitch radius 60 mm, tip 64 mm, thickness at the tip
/// e_T = R_T[e_A/R_A + 2(inv φ_A − inv φ_T)] = 2.9496 mm at φ_T = 28.2414°;
/// and the internal ring of K5 (module 2 mm, 120 teeth): tip circle 118 mm,
/// root 122.5 mm. Tolerance 1e-12 (the case's values are closed forms).
#[tokio::test]
async fn involute_gear_geometry_of_k5() {
    let (app, c) = (TestApp::new().await, case("K5_differential_gear_train"));
    let q3 = &c["expected"]["tooth_thickness_question3"];
    let r = app.post("/v1/gears/geometry", &json!({"module": "4 mm", "teeth": 30})).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let g = r.json()["result"].clone();
    close(&g["pitch_radius"], q3["pitch_radius_mm"].as_f64().unwrap() / 1000.0, 1e-12, "pitch radius");
    close(&g["tip_radius"], q3["tip_radius_mm"].as_f64().unwrap() / 1000.0, 1e-12, "tip radius");
    close(&g["thickness"], q3["thickness_at_tip_mm"].as_f64().unwrap() / 1000.0, 1e-12, "thickness at the tip");
    close(&g["thickness_pressure_angle"], q3["pressure_angle_at_tip_deg"].as_f64().unwrap().to_radians(), 1e-12, "φ_T");
    let ring = &c["expected"]["wheel4_internal"];
    let g = app.post("/v1/gears/geometry", &json!({"module": "2 mm", "teeth": 120, "internal": true})).await.json()["result"].clone();
    close(&g["tip_radius"], ring["addendum_circle_radius_mm"].as_f64().unwrap() / 1000.0, 1e-12, "ring tip circle");
    close(&g["root_radius"], ring["dedendum_circle_radius_mm"].as_f64().unwrap() / 1000.0, 1e-12, "ring root circle");
    close(&g["base_radius"], ring["base_radius_mm"].as_f64().unwrap() / 1000.0, 1e-12, "ring base circle");
    let r = app.post("/v1/gears/geometry", &json!({"module": "4 mm", "teeth": 30, "radius": "50 mm"})).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "below the base circle: {}", r.text);
}

/// The three-mass equivalent of a bar (course notes ch. 1 §5): m = 3 kg,
/// I_G = 0.09 kg·m², ends A and B 0.2 m and 0.4 m from G: m_A = 0.75,
/// m_B = 0.375, m_G = 1.875 kg (closed form). Two points alone cannot be
/// completely equivalent, and the answer says so.
#[tokio::test]
async fn equivalent_masses_of_a_bar() {
    let app = TestApp::new().await;
    let body =
        json!({"mass": "3 kg", "inertia": 0.09, "cg": [0.2, 0], "points": {"A": [0, 0], "B": [0.6, 0], "G": [0.2, 0]}});
    let r = app.post("/v1/equivalent-masses", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let m = r.json()["result"].clone();
    close(&m["masses"]["A"], 0.75, 1e-12, "m_A");
    close(&m["masses"]["B"], 0.375, 1e-12, "m_B");
    close(&m["masses"]["G"], 1.875, 1e-12, "m_G");
    assert_eq!((m["complete"].as_bool(), m["unique"].as_bool()), (Some(true), Some(true)));
    let two = json!({"mass": 3, "inertia": 0.09, "cg": [0.2, 0], "points": {"A": [0, 0], "B": [0.6, 0]}});
    let m = app.post("/v1/equivalent-masses", &two).await.json()["result"].clone();
    assert_eq!(m["complete"], false);
    assert!(!m["warnings"].as_array().unwrap().is_empty());
}

/// K5 (seed 002's differential): sun 1 (60 teeth), planets 3 (30) on
/// carrier 2, internal ring 4 (120); ω₁ = 100 rpm, ω₂ = 50 rpm, 15 N·m on 1.
/// The case's trusted values (closed forms, confirmed there by a
/// tooth-force method): ω₃ = −50 rpm, ω₄ = 25 rpm, T₄ = 30 N·m,
/// T₂ = −45 N·m, at 1e-12; the coaxial train's torques sum to zero.
#[tokio::test]
async fn k5_differential_train_speeds_and_torques() {
    let (app, c) = (TestApp::new().await, case("K5_differential_gear_train"));
    // The documented example of `TrainRequest` is this train.
    let body = example("TrainRequest");
    let r = app.post("/v1/gears/train", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    let x = &c["expected"];
    let rpm = std::f64::consts::PI / 30.0;
    let m = |k: usize| result["members"][k].clone();
    assert_eq!(result["dof"], 2);
    close(&m(2)["speed"], x["omega3_rpm"].as_f64().unwrap() * rpm, 1e-12, "ω₃");
    close(&m(3)["speed"], x["omega4_rpm"].as_f64().unwrap() * rpm, 1e-12, "ω₄");
    close(&m(3)["torque"], x["torque_on_wheel4_Nm"].as_f64().unwrap(), 1e-12, "T₄");
    close(&m(1)["torque"], x["torque_on_carrier2_Nm"].as_f64().unwrap(), 1e-12, "T₂");
    let sum: f64 = (0..4).map(|k| m(k)["torque"].as_f64().unwrap()).sum();
    assert!(sum.abs() < 1e-10, "torque balance {sum}");
    assert!(result["power_residual"].as_f64().unwrap().abs() < 1e-12);

    // One speed for a 2-DOF train, an unknown member: 422 at the field.
    let mut short = body.clone();
    short["speeds"].as_array_mut().unwrap().pop();
    let r = app.post("/v1/gears/train", &short).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/speeds");
    assert!(r.text.contains("2 degree(s) of freedom"), "{}", r.text);
    let mut typo = body.clone();
    typo["meshes"][1]["carrier"] = json!("carrier");
    let r = app.post("/v1/gears/train", &typo).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/meshes/1/carrier", "{}", r.text);
}

/// Teeth that cannot assemble: seed 002's differential assembles (sun 60 +
/// 2 × planet 30 = ring 120: no warning); with a ring of 118 teeth the
/// planet cannot sit as far from the axis in both meshes, and the answer
/// says so with the ring that would fit, 120 (z_ring = z_sun + 2 z_planet).
#[tokio::test]
async fn a_planetary_that_cannot_assemble_is_warned_with_the_count_that_fits() {
    let app = TestApp::new().await;
    let body = example("TrainRequest");
    let r = app.post("/v1/gears/train", &body).await;
    assert_eq!(r.json()["result"]["warnings"], json!([]), "{}", r.text);
    let mut odd = body;
    odd["meshes"][1]["teeth_b"] = json!(118);
    let r = app.post("/v1/gears/train", &odd).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let warnings = r.json()["result"]["warnings"].to_string();
    assert!(warnings.contains("118 teeth") && warnings.contains("a ring of 120"), "{warnings}");
}

/// A module near the largest double (found by schemathesis: 1.49e308 m)
/// overflows the radii: a 422 at /module, never a 201 holding nulls.
#[tokio::test]
async fn a_module_that_overflows_the_radii_is_refused() {
    let app = TestApp::new().await;
    let r = app.post("/v1/gears/geometry", &serde_json::json!({"module": 1.487557489289481e308, "teeth": 1.0})).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/module");
}

/// Points 1e200 m from G (found by schemathesis: their squares overflow):
/// never nulls. The conditions are written over the link's size, so the
/// fit is finite — and incomplete, which it says (the inertia 0.09 kg·m²
/// cannot come from 3 kg at 1e200 m): equal masses, the least-squares
/// compromise of Σm = 3 and Σm·r² ≈ 0 (each row over its size), 0.75 kg.
#[tokio::test]
async fn equivalent_masses_at_overflowing_distances_are_finite_and_incomplete() {
    let app = TestApp::new().await;
    let body = json!({"mass": 3, "inertia": 0.09, "cg": [0, 0], "points": {"A": [1e200, 0], "B": [-1e200, 0]}});
    let r = app.post("/v1/equivalent-masses", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let m = r.json()["result"].clone();
    close(&m["masses"]["A"], 0.75, 1e-12, "m_A");
    close(&m["masses"]["B"], 0.75, 1e-12, "m_B");
    assert_eq!(m["complete"], false);
    assert!(m["warnings"].to_string().contains("no masses at these points match"), "{m}");
}

/// A bare module is metres (SI): `"module": 4` is a 4 m gear, computed as
/// asked and warned of (a module over 0.1 m was most likely meant in mm);
/// `"4 mm"` and `0.004` are not warned of.
#[tokio::test]
async fn a_bare_module_in_millimetres_is_warned_of() {
    let app = TestApp::new().await;
    let r = app.post("/v1/gears/geometry", &json!({"module": 4, "teeth": 30})).await;
    let result = r.json()["result"].clone();
    assert_eq!(result["pitch_radius"], 60.0, "{}", r.text);
    assert!(result["warnings"][0].as_str().unwrap().contains("a bare number is SI"), "{result}");
    for module in [json!("4 mm"), json!(0.004)] {
        let r = app.post("/v1/gears/geometry", &json!({"module": module, "teeth": 30})).await;
        assert_eq!(r.json()["result"]["warnings"], json!([]), "{}", r.text);
    }
}
