//! `POST /v1/mobility`: the course's counts (seed 002, question 1) and a
//! drawn mechanism's degrees of freedom from its Jacobian, where Grübler's
//! count and the rank differ, and the errors at their fields.

use crate::helpers::{TestApp, example};
use axum::http::StatusCode;
use serde_json::{Value, json};

async fn mobility(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/mobility", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()["result"].clone()
}

/// Seed 002, question 1 (the document's example): five links, five lower
/// pairs and one higher pair in the plane, 3(5 − 1) − 2·5 − 1 = 1 (the
/// seed's answer), 12 unknowns with the driving action as the notes count
/// them, and one input coordinate. In space, four links of four revolutes (Bennett's
/// linkage) count 6·3 − 5·4 = −2: locked by the count.
#[tokio::test]
async fn counts_as_the_course_writes_them() {
    let app = TestApp::new().await;
    let r = mobility(&app, &example("MobilityRequest")).await;
    assert_eq!((r["grubler"]["mobility"].as_i64(), r["grubler"]["equations"].as_i64()), (Some(1), Some(12)));
    assert_eq!(r["grubler"]["unknowns"], 11);
    // The notes' count (seed 000, "previsión del número de ecuaciones y de
    // incógnitas"): N_INC = G + 2P_I + P_II = 1 + 10 + 1 = 12, as many as the equations.
    assert_eq!(r["grubler"]["unknowns_with_actions"], 12);
    assert_eq!(r["grubler"]["formula"], "3(5 − 1) − (2·5 + 1·1) = 1");
    assert_eq!((r["dof"].clone(), r["locked"].clone()), (Value::Null, json!(false)));
    // The question's second half: one input coordinate, and what counts alone cannot tell.
    let said = r["input_coordinates"].as_str().unwrap_or_default();
    assert!(said.starts_with("one input coordinate describes the motion") && said.contains("drawing"), "{said}");
    let spatial = json!({"counts": {"space": "spatial", "bodies": 4, "pairs": {"I": 4}}});
    let r = mobility(&app, &spatial).await;
    assert_eq!((r["grubler"]["mobility"].as_i64(), r["locked"].as_bool()), (Some(-2), Some(true)));
    assert_eq!(r["grubler"]["formula"], "6(4 − 1) − 5·4 = -2");
}

fn bar(name: &str) -> Value {
    json!({"name": name, "mass": 1, "inertia": 0.01, "cg": [0, 0]})
}

fn pin(name: &str, a: &str, b: &str, at: [f64; 2]) -> Value {
    json!({"name": name, "type": "revolute", "bodies": [a, b], "at": at})
}

/// A parallelogram four-bar with a third parallel crank: Grübler counts
/// 3·4 − 2·6 = 0, the Jacobian's rank says it moves with 1 (one redundant
/// constraint), any crank drives it, and every joint's reaction is
/// indeterminate (the engine's own test of the same mechanism,
/// src/engine/mobility.rs). A triangle of bars is locked by both.
#[tokio::test]
async fn the_drawing_moves_where_the_count_says_it_cannot() {
    let app = TestApp::new().await;
    let body = json!({"mechanism": {
        "bodies": [bar("crank1"), bar("coupler"), bar("crank2"), bar("crank3")],
        "joints": [pin("O1", "ground", "crank1", [0.0, 0.0]), pin("A", "crank1", "coupler", [0.0, 1.0]),
            pin("B", "coupler", "crank2", [2.0, 1.0]), pin("O2", "ground", "crank2", [2.0, 0.0]),
            pin("O3", "ground", "crank3", [1.0, 0.0]), pin("C", "crank3", "coupler", [1.0, 1.0])],
    }});
    let r = mobility(&app, &body).await;
    assert_eq!((r["dof"].as_i64(), r["grubler"]["mobility"].as_i64()), (Some(1), Some(0)), "{r}");
    assert_eq!((r["redundant_constraints"].as_i64(), r["locked"].as_bool()), (Some(1), Some(false)));
    assert_eq!(r["candidate_inputs"], json!(["O1"]));
    assert_eq!(r["indeterminate_joints"], json!(["O1", "A", "B", "O2", "O3", "C"]));
    assert!(r["warnings"][0].as_str().unwrap().contains("Grübler's count gives 0"), "{r}");
    let triangle = json!({"mechanism": {
        "bodies": [bar("a"), bar("b")],
        "joints": [pin("O", "ground", "a", [0.0, 0.0]), pin("P", "ground", "b", [1.0, 0.0]), pin("C", "a", "b", [0.5, 0.8])],
    }});
    let r = mobility(&app, &triangle).await;
    assert_eq!((r["dof"].as_i64(), r["locked"].as_bool()), (Some(0), Some(true)), "{r}");
    assert_eq!(r["candidate_inputs"], json!([]));
}

/// A five-bar (ground and four links, five revolutes) has two freedoms,
/// 3·4 − 2·5 = 2 both ways, and two of its joints drive it together: the
/// first two, O1 and A (A's relative rotation with the crank held is the
/// second link's own turn).
#[tokio::test]
async fn a_five_bar_needs_two_inputs() {
    let app = TestApp::new().await;
    let body = json!({"mechanism": {
        "bodies": [bar("l1"), bar("l2"), bar("l3"), bar("l4")],
        "joints": [pin("O1", "ground", "l1", [0.0, 0.0]), pin("A", "l1", "l2", [0.0, 1.0]),
            pin("B", "l2", "l3", [1.0, 1.5]), pin("C", "l3", "l4", [2.0, 1.0]), pin("O2", "l4", "ground", [2.0, 0.0])],
    }});
    let r = mobility(&app, &body).await;
    assert_eq!((r["dof"].as_i64(), r["grubler"]["mobility"].as_i64()), (Some(2), Some(2)), "{r}");
    assert_eq!(r["candidate_inputs"], json!(["O1", "A"]));
}

/// Neither or both of `mechanism` and `counts`, an unknown class, a class
/// the plane has not, no bodies, an unknown body: each a 422 at its field.
#[tokio::test]
async fn mobility_errors_point_at_the_field() {
    let app = TestApp::new().await;
    assert_eq!(app.pointers("/v1/mobility", &json!({})).await, [""]);
    let counts = json!({"space": "planar", "bodies": 0, "pairs": {"I": 1, "III": 1, "X": 2}});
    let got = app.pointers("/v1/mobility", &json!({"counts": counts})).await;
    assert_eq!(got, ["/counts/bodies", "/counts/pairs/III", "/counts/pairs/X"]);
    let both =
        json!({"counts": {"space": "spatial", "bodies": 2, "pairs": {}}, "mechanism": {"bodies": [], "joints": []}});
    assert_eq!(app.pointers("/v1/mobility", &both).await, [""]);
    let unknown = json!({"mechanism": {"bodies": [bar("a")], "joints": [pin("O", "ground", "b", [0.0, 0.0])]}});
    let got = app.pointers("/v1/mobility", &unknown).await;
    assert!(got.iter().all(|p| p.starts_with("/mechanism/joints/0")), "{got:?}");
}
