//! Balancing a rigid rotor (`POST /v1/balancing`, issue 51): every number
//! checked against an independent method — the corrections fed back as
//! masses leave nothing (the service's own sums, not its formula), the
//! bearing forces against the rotor kind's (Newton–Euler on the same body
//! built from the masses' inertia), the body form against the masses form,
//! and one mass by the lever rule.

use crate::helpers::{TestApp, close, example};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// The documented example: three masses (kg, m, deg, m), planes at 0 and
/// 0.4 m, bearings at −0.05 and 0.45 m, 1500 rpm.
const MASSES: [(f64, f64, f64, f64); 3] = [(0.2, 0.1, 30.0, 0.05), (0.15, 0.08, 150.0, 0.2), (0.1, 0.12, 270.0, 0.35)];
const BEARINGS: [f64; 2] = [-0.05, 0.45];

fn omega() -> f64 {
    1500.0 * std::f64::consts::TAU / 60.0
}

/// The corrections of `result` as masses of a request (SI numbers, angles in radians).
fn as_masses(result: &Value) -> Vec<Value> {
    let corrections = result["corrections"].as_array().unwrap();
    let mass = |c: &Value| json!({"mass": c["mass"], "radius": c["radius"], "angle": c["angle"], "plane": c["plane"]});
    corrections.iter().map(mass).collect()
}

/// Two planes remove the whole unbalance: the example's masses with the
/// corrections added as three more masses balance to rounding (1e-15 kg·m
/// against an unbalance of 2e-2), the residual says so, and the bearing
/// forces after are nil.
#[tokio::test]
async fn two_planes_leave_nothing_when_the_corrections_are_added_as_masses() {
    let app = TestApp::new().await;
    let r = app.post("/v1/balancing", &example("BalancingRequest")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    assert_eq!(result["corrections"].as_array().unwrap().len(), 2, "{result}");
    assert!(result["static_unbalance"]["value"].as_f64().unwrap() > 1e-3, "{result}");
    close(&result["residual"]["static"], 0.0, 1e-15, "residual |U|");
    close(&result["residual"]["dynamic"], 0.0, 1e-15, "residual |D|");
    let mut balanced = example("BalancingRequest");
    balanced["masses"].as_array_mut().unwrap().extend(as_masses(&result));
    let again = app.post("/v1/balancing", &balanced).await.json()["result"].clone();
    close(&again["static_unbalance"]["value"], 0.0, 1e-15, "|U| of the balanced rotor");
    close(&again["dynamic_unbalance"]["value"], 0.0, 1e-15, "|D| of the balanced rotor");
    for c in again["corrections"].as_array().unwrap() {
        close(&c["mass"], 0.0, 1e-13, "a correction of the balanced rotor");
    }
    let before = result["reactions"]["before"].as_array().unwrap();
    assert!(before.iter().flat_map(|f| f.as_array().unwrap()).any(|v| v.as_f64().unwrap().abs() > 10.0), "{result}");
    for v in result["reactions"]["after"].as_array().unwrap().iter().flat_map(|f| f.as_array().unwrap()) {
        close(v, 0.0, 1e-9, "a bearing force after balancing");
    }
}

/// The point masses as one rigid body, in the rotor kind's axes (x' the
/// rotor's axis = the balancing z, y' = x, z' = y): mass, G and the
/// inertia about G with its products ∫(x' − x'_G)(y' − y'_G) dm.
fn rotor_of_masses() -> Value {
    let points: Vec<(f64, [f64; 3])> = MASSES
        .iter()
        .map(|&(m, r, deg, z)| {
            let (s, c) = deg.to_radians().sin_cos();
            (m, [z, r * c, r * s])
        })
        .collect();
    let total: f64 = points.iter().map(|p| p.0).sum();
    let g: Vec<f64> = (0..3).map(|k| points.iter().map(|(m, p)| m * p[k]).sum::<f64>() / total).collect();
    let product = |a: usize, b: usize| points.iter().map(|(m, p)| m * (p[a] - g[a]) * (p[b] - g[b])).sum::<f64>();
    let moment = |a: usize| product((a + 1) % 3, (a + 1) % 3) + product((a + 2) % 3, (a + 2) % 3);
    json!({
        "mass": total,
        "inertia": {"xx": moment(0), "yy": moment(1), "zz": moment(2),
                    "xy": product(0, 1), "xz": product(0, 2), "yz": product(1, 2)},
        "cg": g, "bearings": BEARINGS, "gravity": [0, 0, 0],
        "frame": {"speed": omega()}, "angles": [0]
    })
}

/// The bearing forces before balancing are the rotor kind's dynamic
/// reactions of the same body at angle 0 (Newton–Euler in the frame, its
/// own closed form; 1e-9 N of forces near 100 N), and the body given as a
/// rotor request has the masses' unbalance (1e-15).
#[tokio::test]
async fn the_bearing_forces_are_the_rotor_kind_s_and_the_body_form_agrees() {
    let app = TestApp::new().await;
    let balanced = app.post("/v1/balancing", &example("BalancingRequest")).await.json()["result"].clone();
    let rotor = app.post("/v1/rotor", &rotor_of_masses()).await;
    assert_eq!(rotor.status, StatusCode::CREATED, "{}", rotor.text);
    let dynamic = rotor.json()["result"]["states"][0]["reactions"]["dynamic"].clone();
    for (k, bearing) in ["d", "e"].into_iter().enumerate() {
        for (axis, component) in [(0, 1), (1, 2)] {
            let expected = dynamic[bearing][component].as_f64().unwrap();
            close(
                &balanced["reactions"]["before"][k][axis],
                expected,
                1e-9,
                &format!("bearing {bearing}, axis {axis}"),
            );
        }
    }
    let body = json!({"rotor": rotor_of_masses(), "planes": example("BalancingRequest")["planes"]});
    let r = app.post("/v1/balancing", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let of_body = r.json()["result"].clone();
    for field in ["static_unbalance", "dynamic_unbalance"] {
        let (value, angle) = (&balanced[field]["value"], balanced[field]["angle"].as_f64().unwrap());
        close(&of_body[field]["value"], value.as_f64().unwrap(), 1e-15, field);
        close(&of_body[field]["angle"], angle, 1e-12, field);
    }
    // The rotor's frame speed and bearings give the same reactions.
    close(&of_body["reactions"]["speed"], omega(), 1e-12, "the rotor's speed");
    close(
        &of_body["reactions"]["before"][1][0],
        balanced["reactions"]["before"][1][0].as_f64().unwrap(),
        1e-9,
        "R_B x",
    );
}

/// One mass in one plane (static balancing): the correction m·r opposite it
/// (1e-15), and where the plane is not the mass's the couple left is
/// m·r·(z − z₁) (closed form), with a warning that says two planes remove it.
#[tokio::test]
async fn one_plane_balances_the_static_unbalance_and_says_the_couple_is_left() {
    let app = TestApp::new().await;
    let body = json!({
        "masses": [{"mass": "50 g", "radius": "40 mm", "angle": "60 deg", "plane": "100 mm"}],
        "planes": [{"z": "0 mm", "radius": "20 mm"}]
    });
    let r = app.post("/v1/balancing", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    let c = &result["corrections"][0];
    close(&c["mass_radius"], 0.05 * 0.04, 1e-15, "m·R = m·r");
    close(&c["mass"], 0.05 * 0.04 / 0.02, 1e-14, "m = m·r/R");
    close(&c["angle"], 240f64.to_radians(), 1e-12, "opposite the mass");
    close(&result["residual"]["static"], 0.0, 1e-17, "no static unbalance left");
    close(&result["residual"]["dynamic"], 0.05 * 0.04 * 0.1, 1e-15, "the couple left");
    assert!(result.get("reactions").is_none(), "no speed: no reactions: {result}");
    assert_eq!(result["messages"]["/warnings/0"]["id"], "warning-balancing-couple-left", "{result}");
}

/// Bad requests: both forms, three planes, planes at one z, a negative
/// mass, a length with an angle's unit and a speed without bearings —
/// each at its field, in Spanish where asked.
#[tokio::test]
async fn balancing_errors_point_at_each_field_in_the_user_s_language() {
    let app = TestApp::new().await;
    let mut body = example("BalancingRequest");
    body["rotor"] = rotor_of_masses();
    let r = app.post("/v1/balancing", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "", "{}", r.text);
    let mut body = example("BalancingRequest");
    body["planes"] = json!([{"z": 0, "radius": 0.1}, {"z": 0, "radius": 0.1}]);
    body["masses"][1]["mass"] = json!("-1 kg");
    body["masses"][2]["plane"] = json!("3 deg");
    let r = app.post("/v1/balancing?lang=es", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].as_array().unwrap().clone();
    let at = |p: &str| errors.iter().find(|e| e["pointer"] == p).map(|e| e["message"].as_str().unwrap().to_string());
    assert!(at("/planes/1/z").is_some_and(|m| m.contains("z distintas")), "{errors:?}");
    assert!(at("/masses/1/mass").is_some_and(|m| m.contains("≥ 0")), "{errors:?}");
    assert!(at("/masses/2/plane").is_some(), "{errors:?}");
    body["planes"] = json!([{"z": 0, "radius": 0.1}, {"z": 1, "radius": 0.1}, {"z": 2, "radius": 0.1}]);
    let r = app.post("/v1/balancing", &body).await;
    assert!(r.json()["errors"].as_array().unwrap().iter().any(|e| e["pointer"] == "/planes"), "{}", r.text);
    // A speed without bearings asks for the forces: refused at the missing field, not answered without them.
    let mut body = example("BalancingRequest");
    body.as_object_mut().unwrap().remove("bearings");
    let r = app.post("/v1/balancing", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/bearings", "{}", r.text);
}

/// The job has its plot: U and each correction as arrows from the axis, as SVG.
#[tokio::test]
async fn a_balancing_job_draws_its_vectors() {
    let app = TestApp::new().await;
    let r = app.post("/v1/balancing", &example("BalancingRequest")).await;
    let id = r.json()["id"].as_str().unwrap().to_string();
    let svg = app.get(&format!("/v1/jobs/{id}/plots/vectors.svg")).await;
    assert_eq!(svg.status, StatusCode::OK, "{}", svg.text);
    assert!(
        svg.text.contains("<svg") && svg.text.contains("static unbalance U"),
        "{}",
        &svg.text[..300.min(svg.text.len())]
    );
}
