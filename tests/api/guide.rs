//! A prismatic joint's two bearing ends (seed 000: a prismatic pair's
//! reaction is two forces at the ends of the pair; contract, part four: "A
//! guide's length"). The drawer, a block of length L (`slider_length`: its
//! ends ride with it) that slides at constant speed along a long horizontal
//! guide against a force P applied at height h above the guide, in closed form. Moments about the guide's centre and the vertical
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
        guide["slider_length"] = json!(l);
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
    pin["mechanism"]["joints"][0]["slider_length"] = json!(0.2);
    pin["mechanism"]["joints"][0].as_object_mut().unwrap().remove("friction");
    let r = app.post("/v1/kinetostatics", &pin).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert!(r.text.contains("/mechanism/joints/0/slider_length"), "{}", r.text);
}

/// A translating follower's stem in two bushings fixed to the frame
/// (`length` 0.1 m on the ground, the guide's body, centred on G = (0, 0),
/// axis +y), pushed at its tip T = (0, −0.05 m) + s·ŷ by a cam's force F =
/// (30, 100) N and held by the driving force along the axis, at lifts s =
/// 0, 10 and 20 mm. The follower's free body, written by hand: the guide
/// pushes N₁ at E₁ = G − (L/2)ŷ and N₂ at E₂ = G + (L/2)ŷ along n = (−1, 0)
/// (the axis turned 90°), so N₁ + N₂ = −F·n and, about G (the driving force
/// acts along the axis through it), (L/2)(N₂ − N₁) + (T − G) × F = 0:
/// N₁ = −F·n/2 + (T − G) × F / L, N₂ = −F·n/2 − (T − G) × F / L, which
/// change with the lift. A block of that length on the stem
/// (`slider_length`) carries its ends up with it: T − centre stays
/// (0, −0.05) and N₁, N₂ stay those of s = 0 (1e-9 N).
#[tokio::test]
async fn a_guides_ends_stay_on_the_frame_while_a_blocks_ride_with_it() {
    let app = TestApp::new().await;
    let (l, f, n) = (0.1, [30.0, 100.0], [-1.0, 0.0]);
    let ends = |t: [f64; 2]| {
        let (along, turn) = (f[0] * n[0] + f[1] * n[1], t[0] * f[1] - t[1] * f[0]);
        [-along / 2.0 + turn / l, -along / 2.0 - turn / l]
    };
    for (field, fixed) in [("length", true), ("slider_length", false)] {
        let request = json!({
            "mechanism": {
                "points": {"G": [0, 0], "T": [0, -0.05]},
                "bodies": [{"name": "follower"}],
                "joints": [{"name": "stem", "type": "prismatic", "bodies": ["ground", "follower"], "at": "G",
                    "axis": [0, 1], field: l}]
            },
            "input": {"joint": "stem", "speed": 0, "start": 0, "end": "30 mm", "steps": 3},
            "loads": [{"type": "force", "body": "follower", "at": "T", "direction": [0.3, 1], "magnitude": f[0].hypot(f[1])}]
        });
        let r = app.post("/v1/kinetostatics", &request).await;
        assert_eq!(r.status, StatusCode::CREATED, "{field}: {}", r.text);
        for (k, step) in r.json()["result"]["steps"].as_array().unwrap().iter().enumerate() {
            let s = 0.01 * k as f64;
            let expected = ends(if fixed { [0.0, -0.05 + s] } else { [0.0, -0.05] });
            let got = &step["reactions"][0]["ends"];
            close(&got[0], expected[0], 1e-9, &format!("{field}, s = {s}: N₁"));
            close(&got[1], expected[1], 1e-9, &format!("{field}, s = {s}: N₂"));
        }
    }
}
