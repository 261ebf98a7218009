//! A prismatic joint with its guide's `length` (seed 000: a prismatic
//! pair's reaction is two forces at the ends of the pair), against the
//! drawer's closed form: a block of mass m slides at constant speed along
//! a horizontal guide of length L, against a force P applied at height h
//! above the guide. Moments about the guide's centre and the vertical
//! balance give N₁ = mg/2 + hP/L (rear end) and N₂ = mg/2 − hP/L (front);
//! the driving force is D = P + μ(|N₁| + |N₂|) — with hP/L > mg/2 the front
//! end pulls down (N₂ < 0) and the drawer needs P + 2μhP/L, not P + μmg.

use crate::helpers::{TestApp, close};
use axum::http::StatusCode;
use serde_json::{Value, json};

fn drawer(length: Option<f64>, mu: f64) -> Value {
    let mut guide = json!({"name": "guide", "type": "prismatic", "bodies": ["ground", "block"], "at": "O",
        "axis": [1, 0], "friction": {"mu": mu}});
    if let Some(l) = length {
        guide["length"] = json!(l);
    }
    json!({
        "mechanism": {
            "points": {"O": [0, 0], "H": [0, 0.3]},
            "bodies": [{"name": "block", "mass": 10, "inertia": 0.1, "cg": "O"}],
            "joints": [guide],
            "gravity": [0, -9.81]
        },
        "input": {"joint": "guide", "speed": 0.5, "start": 0, "end": 0.1, "steps": 2},
        "loads": [{"type": "force", "body": "block", "at": "H", "direction": [-1, 0], "magnitude": 100}]
    })
}

/// m = 10 kg, g = 9.81, P = 100 N, h = 0.3 m, L = 0.2 m, μ = 0.2: N₁ =
/// 199.05 N, N₂ = −100.95 N, D = 160 N; the reported reaction on the block
/// is (−μ(|N₁| + |N₂|), mg) with the couple (L/2)(N₂ − N₁) = −hP. Without a
/// length the one normal force gives D = P + μmg = 119.62 N (1e-12).
#[tokio::test]
async fn a_guide_with_its_length_bears_its_load_at_both_ends() {
    let app = TestApp::new().await;
    let (m, g, p, h, l, mu) = (10.0, 9.81, 100.0, 0.3, 0.2, 0.2);
    let (n1, n2) = (m * g / 2.0 + h * p / l, m * g / 2.0 - h * p / l);
    let r = app.post("/v1/kinetostatics", &drawer(Some(l), mu)).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let step = r.json()["result"]["steps"][1].clone();
    close(&step["driving"], p + mu * (n1.abs() + n2.abs()), 1e-12, "D = P + μ(|N₁| + |N₂|)");
    let reaction = &step["reactions"][0];
    close(&reaction["ends"][0], n1, 1e-12, "N₁ = mg/2 + hP/L");
    close(&reaction["ends"][1], n2, 1e-12, "N₂ = mg/2 − hP/L");
    close(&reaction["fx"], -mu * (n1.abs() + n2.abs()), 1e-12, "the guide's friction");
    close(&reaction["fy"], m * g, 1e-12, "N₁ + N₂ = mg");
    close(&reaction["moment"], -h * p, 1e-12, "(L/2)(N₂ − N₁) = −hP");
    let one = app.post("/v1/kinetostatics", &drawer(None, mu)).await.json()["result"]["steps"][1].clone();
    close(&one["driving"], p + mu * m * g, 1e-12, "one normal force: P + μmg");
    assert!(one["reactions"][0].get("ends").is_none());
    let mut pin = drawer(None, mu);
    pin["mechanism"]["joints"][0]["type"] = json!("revolute");
    pin["mechanism"]["joints"][0]["length"] = json!(0.2);
    pin["mechanism"]["joints"][0].as_object_mut().unwrap().remove("friction");
    let r = app.post("/v1/kinetostatics", &pin).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert!(r.text.contains("/mechanism/joints/0/length"), "{}", r.text);
}
