//! Spatial mechanisms (contract part five) over HTTP: a mechanism with
//! `"space": "spatial"` read with its points, inertia tensors and spatial
//! pairs, its mobility from the drawing beside Kutzbach's count, and its
//! errors at their fields in the asker's language.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};

async fn mobility(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/mobility", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()["result"].clone()
}

/// IFToMM A04, Bricard's linkage, as the benchmark library draws it: five
/// 1 m rods of 1 kg (I = 0.001667 kg·m² along the rod, 0.084167 across),
/// six revolutes whose axes turn by 90° from one to the next.
pub fn bricard() -> Value {
    let at = [[0, 0, 0], [1, 0, 0], [1, -1, 0], [1, -1, 1], [0, -1, 1], [0, 0, 1]];
    let axes = [[0, 1, 0], [0, 0, 1], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 0, 0]];
    let bodies: Vec<Value> = (0..5)
        .map(|k| {
            let cg: Vec<f64> = (0..3).map(|c| f64::from(at[k][c] + at[k + 1][c]) / 2.0).collect();
            let along: Vec<f64> = (0..3).map(|c| if at[k][c] != at[k + 1][c] { 0.001667 } else { 0.084167 }).collect();
            json!({"name": format!("rod {}", k + 1), "mass": "1 kg", "cg": cg, "inertia": along})
        })
        .collect();
    let body = |k: usize| if k == 0 || k == 6 { "ground".to_string() } else { format!("rod {k}") };
    let joints: Vec<Value> = (0..6)
        .map(|k| {
            json!({"name": format!("J{}", k + 1), "type": "revolute", "bodies": [body(k), body(k + 1)],
                   "at": format!("P{k}"), "axis": axes[k]})
        })
        .collect();
    let points: serde_json::Map<String, Value> = (0..6).map(|k| (format!("P{k}"), json!(at[k]))).collect();
    json!({"space": "spatial", "points": points, "bodies": bodies, "joints": joints, "gravity": [0, -9.81, 0]})
}

/// Hooke's joint: two shafts on revolutes meeting at O at β = 30°, their
/// yokes joined by a universal joint (the cross's two axes).
fn hooke() -> Value {
    json!({"space": "spatial",
    "bodies": [{"name": "input"}, {"name": "output"}],
    "joints": [
        {"name": "A", "type": "revolute", "bodies": ["ground", "input"], "at": [0, 0, 0], "axis": [1, 0, 0]},
        {"name": "B", "type": "revolute", "bodies": ["ground", "output"], "at": [0, 0, 0],
         "axis": [0.8660254037844387, 0.5, 0]},
        {"name": "cross", "type": "universal", "bodies": ["input", "output"], "at": [0, 0, 0],
         "axes": [[0, 1, 0], [0, 0, 1]]}
    ]})
}

/// Bricard's linkage moves though Kutzbach's count says it cannot: 6(6 − 1)
/// − 5·6 = 0 by the count, 1 from the drawing (Bricard 1927; the IFToMM
/// library's A04 moves under gravity), its one redundant row shared by all
/// six joints, whose reactions equilibrium therefore cannot tell. Hooke's
/// joint, a spherical four-bar, counts 6·2 − (5 + 5 + 4) = −2 and moves with 1
/// (3 rows repeat: the three pairs hold O three times). A spatial
/// slider-crank (revolute, spherical, universal, prismatic) counts and moves
/// with 1, nothing redundant.
#[tokio::test]
async fn mobility_from_the_drawing_beside_the_count() {
    let app = TestApp::new().await;
    let r = mobility(&app, &json!({"mechanism": bricard()})).await;
    assert_eq!((r["dof"].as_i64(), r["grubler"]["mobility"].as_i64()), (Some(1), Some(0)));
    assert_eq!(r["grubler"]["formula"], "6(6 − 1) − 5·6 = 0");
    assert_eq!(r["redundant_constraints"], 1);
    assert_eq!(r["indeterminate_joints"], json!(["J1", "J2", "J3", "J4", "J5", "J6"]));
    assert_eq!(r["candidate_inputs"], json!(["J1"]));
    assert!(r["warnings"][0].as_str().unwrap().contains("gives 0 but the drawing moves with 1"), "{r}");
    let r = mobility(&app, &json!({"mechanism": hooke()})).await;
    assert_eq!((r["dof"].as_i64(), r["grubler"]["mobility"].as_i64()), (Some(1), Some(-2)));
    assert_eq!(
        (r["redundant_constraints"].as_i64(), r["grubler"]["formula"].as_str()),
        (Some(3), Some("6(3 − 1) − (5·2 + 4·1) = -2"))
    );
    let slider_crank = json!({"space": "spatial",
    "points": {"O": [0, 0, 0], "A": ["10 cm", 0, 0], "B": [0.4166, 0.05, 0.08]},
    "bodies": [{"name": "crank"}, {"name": "rod"}, {"name": "slider", "mass": 2, "cg": "B",
                "inertia": [[0.01, 0, 0], [0, 0.02, 0], [0, 0, 0.02]]}],
    "joints": [
        {"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O", "axis": [0, 0, 1]},
        {"name": "A", "type": "spherical", "bodies": ["crank", "rod"], "at": "A"},
        {"name": "B", "type": "universal", "bodies": ["slider", "rod"], "at": "B", "axes": [[0, 1, 0], [0.2, 0, -0.9]]},
        {"name": "guide", "type": "prismatic", "bodies": ["ground", "slider"], "at": "B", "axis": [1, 0, 0]}
    ]});
    let r = mobility(&app, &json!({"mechanism": slider_crank})).await;
    assert_eq!((r["dof"].as_i64(), r["grubler"]["mobility"].as_i64()), (Some(1), Some(1)));
    assert_eq!((r["redundant_constraints"].as_i64(), r["candidate_inputs"].clone()), (Some(0), json!(["O"])));
}

/// Every field a spatial mechanism reads wrong is refused at its pointer,
/// in Spanish with `lang=es`; a planar mechanism given a point in space or
/// a spatial pair says how to ask for space; a kind that does not take a
/// spatial mechanism yet says so at `/mechanism/space`.
#[tokio::test]
async fn spatial_errors_point_at_the_field() {
    let app = TestApp::new().await;
    let wrong = json!({"mechanism": {"space": "spatial", "points": {"A": [0, 0]},
        "bodies": [{"name": "b", "inertia": 0.3}, {"name": "c", "inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 3]]}],
        "joints": [
            {"name": "J", "type": "pin_slot", "bodies": ["ground", "b"], "at": "A", "axis": [1, 0]},
            {"name": "U", "type": "universal", "bodies": ["ground", "b"], "at": [0, 0, 0], "axes": [[1, 0, 0], [1, 1, 0]]},
            {"name": "R", "type": "revolute", "bodies": ["b", "c"], "at": [0, 0, 1], "axis": [0, 0], "friction": {"mu": 0.1}}
        ],
        "gravity": [0, -9.81]}});
    let r = app.post("/v1/mobility?lang=es", &wrong).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].clone();
    let at: Vec<&str> = errors.as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap()).collect();
    assert_eq!(
        at,
        [
            "/mechanism/points/A",
            "/mechanism/bodies/0/inertia",
            "/mechanism/bodies/1/inertia",
            "/mechanism/joints/0/type",
            "/mechanism/joints/1/axes",
            "/mechanism/joints/2/friction",
            "/mechanism/joints/2/axis",
            "/mechanism/gravity"
        ]
    );
    assert_eq!(errors[0]["message"], "un punto de un mecanismo espacial tiene tres coordenadas [x, y, z]");
    assert!(errors[2]["message"].as_str().unwrap().contains("ningún sólido rígido"), "{errors}");
    let planar = json!({"mechanism": {"points": {"A": [0, 0, 1]}, "bodies": [{"name": "b"}],
        "joints": [{"name": "S", "type": "spherical", "bodies": ["ground", "b"], "at": "A"}]}});
    let r = app.post("/v1/mobility", &planar).await;
    let errors = r.json()["errors"].clone();
    assert_eq!(errors[0]["pointer"], "/mechanism/points/A");
    assert!(errors[0]["message"].as_str().unwrap().contains("\"space\": \"spatial\""), "{errors}");
    assert_eq!(errors[1]["pointer"], "/mechanism/joints/0/type");
    let mut statics =
        json!({"mechanism": bricard(), "input": {"joint": "J1", "start": 0, "end": "30 deg", "steps": 3}});
    statics["mechanism"]["bodies"][0]["mass"] = json!(1);
    let got = app.pointers("/v1/kinetostatics", &statics).await;
    assert!(got.contains(&"/mechanism/space".to_string()), "{got:?}");
}
