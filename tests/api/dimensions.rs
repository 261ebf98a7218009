//! A mechanism from its dimensions: "crank 0.1 m at 60°, coupler 0.3 m,
//! rocker 0.25 m, frame 0.3 m" with rough points, against the four-bar
//! placed by hand (B the intersection of two circles), and the errors of
//! dimensions that cannot hold.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};

/// B: the intersection of the circles (A, 0.3) and (O₄, 0.25), above or
/// below the line A–O₄; A = 0.1(cos 60°, sin 60°), O₄ = (0.3, 0).
fn b(above: bool) -> [f64; 2] {
    let a = [0.05, 3f64.sqrt() / 20.0];
    let d = (0.3 - a[0]).hypot(a[1]);
    let along = (d * d + 0.09 - 0.0625) / (2.0 * d);
    let h = (0.09 - along * along).sqrt() * if above { 1.0 } else { -1.0 };
    let u = [(0.3 - a[0]) / d, -a[1] / d];
    [a[0] + along * u[0] - h * u[1], a[1] + along * u[1] + h * u[0]]
}

fn four_bar(points: Value, dimensions: Option<Value>) -> Value {
    let body = |name: &str, cg: &str| json!({"name": name, "mass": 1, "inertia": 0.01, "cg": cg});
    let pin = |name: &str, a: &str, b: &str| json!({"name": name, "type": "revolute", "bodies": [a, b], "at": name});
    let mut mechanism = json!({
        "points": points,
        "bodies": [body("crank", "A"), body("coupler", "B"), body("rocker", "B")],
        "joints": [pin("O2", "ground", "crank"), pin("A", "crank", "coupler"), pin("B", "coupler", "rocker"), pin("O4", "rocker", "ground")],
        "gravity": [0, -9.81]
    });
    if let Some(d) = dimensions {
        mechanism["dimensions"] = d;
    }
    json!({"mechanism": mechanism,
        "input": {"joint": "O2", "speed": 10, "reference": "60 deg", "start": "60 deg", "end": "120 deg", "steps": 6}})
}

fn statement() -> Value {
    json!([
        {"distance": ["O2", "A"], "value": "100 mm"}, {"angle": ["O2", "A"], "value": "60 deg"},
        {"distance": ["A", "B"], "value": 0.3}, {"distance": ["O4", "B"], "value": "250 mm"},
        {"distance": ["O2", "O4"], "value": 0.3}, {"x": "O2", "value": 0}, {"y": "O2", "value": 0}, {"y": "O4", "value": 0}
    ])
}

/// Sketched above and below: the assembled points are the hand-placed
/// ones on the sketch's side (1e-12 m), and every reaction at every step
/// is that of the hand-placed four-bar (1e-9 relative: the same mechanism).
#[tokio::test]
async fn a_four_bar_from_its_dimensions_is_the_hand_placed_one() {
    let app = TestApp::new().await;
    for (above, b_sketch) in [(true, [0.3, 0.3]), (false, [0.2, -0.15])] {
        let sketch = json!({"O2": [0, 0], "O4": [0.3, 0], "A": [0.04, 0.1], "B": b_sketch});
        let r = app.post("/v1/kinetostatics", &four_bar(sketch, Some(statement()))).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let result = r.json()["result"].clone();
        let expected = b(above);
        for k in 0..2 {
            let got = result["assembled_points"]["B"][k].as_f64().unwrap();
            assert!((got - expected[k]).abs() < 1e-12, "B[{k}] {got} against {}", expected[k]);
        }
        let drawn = json!({"O2": [0, 0], "O4": [0.3, 0], "A": [0.05, 3f64.sqrt() / 20.0], "B": expected});
        let by_hand = app.post("/v1/kinetostatics", &four_bar(drawn, None)).await.json()["result"].clone();
        assert!(by_hand["assembled_points"].is_null(), "no dimensions, no assembly");
        for (s, h) in result["steps"].as_array().unwrap().iter().zip(by_hand["steps"].as_array().unwrap()) {
            for (rs, rh) in s["reactions"].as_array().unwrap().iter().zip(h["reactions"].as_array().unwrap()) {
                for key in ["fx", "fy"] {
                    let (a, b) = (rs[key].as_f64().unwrap(), rh[key].as_f64().unwrap());
                    assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{} {key}: {a} against {b}", rs["joint"]);
                }
            }
        }
    }
}

/// A coupler too short to close the loop contradicts the others (each named
/// at its pointer); an unknown point and a dimension naming two kinds are
/// refused at their fields.
#[tokio::test]
async fn dimensions_that_cannot_hold_are_named() {
    let app = TestApp::new().await;
    let sketch = json!({"O2": [0, 0], "O4": [0.3, 0], "A": [0.04, 0.1], "B": [0.3, 0.3]});
    let mut short = statement();
    short[2]["value"] = json!(0.01);
    let r = app.post("/v1/kinetostatics", &four_bar(sketch.clone(), Some(short))).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].as_array().unwrap().clone();
    assert!(errors.iter().any(|e| e["pointer"] == "/mechanism/dimensions/2"), "{errors:?}");
    let mut bad = statement();
    bad[0] = json!({"distance": ["O2", "Z"], "value": 0.1});
    bad[1] = json!({"x": "A", "y": "A", "value": 0});
    let r = app.post("/v1/kinetostatics", &four_bar(sketch, Some(bad))).await;
    let pointers: Vec<String> =
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect();
    assert_eq!(pointers, ["/mechanism/dimensions/0/distance/1", "/mechanism/dimensions/1"], "{}", r.text);
}

/// `"dimensions": []` (sent by schemathesis, which found a panic there): the
/// drawing as drawn, the same job as without the field.
#[tokio::test]
async fn no_dimensions_are_the_drawing_as_drawn() {
    let app = TestApp::new().await;
    let drawn = json!({"O2": [0, 0], "O4": [0.3, 0], "A": [0.05, 3f64.sqrt() / 20.0], "B": b(true)});
    let with = app.post("/v1/kinetostatics", &four_bar(drawn.clone(), Some(json!([])))).await;
    assert_eq!(with.status, StatusCode::CREATED, "{}", with.text);
    let without = app.post("/v1/kinetostatics", &four_bar(drawn, None)).await.json();
    assert_eq!(with.json()["result"]["steps"], without["result"]["steps"]);
}

/// The same statement in a flywheel's and a dynamics job's `machine`: each
/// result says where the points went (B above, as sketched: 1e-12 m of the
/// circles' intersection), and a sketch whose dimensions leave a point free
/// (O4's y not given) is solved and says so in the dynamics job's warnings.
#[tokio::test]
async fn every_machine_reports_its_assembled_points() {
    let app = TestApp::new().await;
    let sketch = json!({"O2": [0, 0], "O4": [0.3, 0], "A": [0.04, 0.1], "B": [0.3, 0.3]});
    let mechanism = four_bar(sketch, Some(statement()))["mechanism"].clone();
    let input = json!({"joint": "O2", "reference": "60 deg"});
    let torque = json!({"type": "torque", "body": "rocker", "value": {"expr": "5*sin(phi)"}});
    let flywheel = json!({"mean_speed": "60 rpm", "irregularity": 0.04, "torques": [{"name": "motor", "balance": true}],
        "machine": {"mechanism": mechanism, "input": input, "loads": [torque]}});
    let dynamics = json!({"machine": {"mechanism": mechanism, "input": input}, "duration": "0.1 s", "samples": 2});
    for (path, body, at) in [("/v1/flywheel", flywheel, ""), ("/v1/dynamics", dynamics.clone(), "/machine")] {
        let r = app.post(path, &body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{path}: {}", r.text);
        let points = r.json()["result"].pointer(&format!("{at}/assembled_points/B")).cloned().unwrap();
        let expected = b(true);
        for k in 0..2 {
            let got = points[k].as_f64().unwrap();
            assert!((got - expected[k]).abs() < 1e-12, "{path}: B[{k}] {got} against {}", expected[k]);
        }
    }
    let mut loose = dynamics;
    loose["machine"]["mechanism"]["dimensions"].as_array_mut().unwrap().pop();
    let r = app.post("/v1/dynamics", &loose).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let warnings = r.json()["result"]["warnings"].to_string();
    assert!(warnings.contains("free to move"), "{warnings}");
}
