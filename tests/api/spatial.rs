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
    // Nothing joined: a free body keeps its six freedoms, nothing at all has none (no SVD of an empty Φ_q).
    let free = json!({"mechanism": {"space": "spatial", "bodies": [{"name": "b"}], "joints": []}});
    assert_eq!(mobility(&app, &free).await["dof"], 6);
    let empty = json!({"mechanism": {"space": "spatial", "bodies": [], "joints": []}});
    assert_eq!(mobility(&app, &empty).await["dof"], 0);
    let r = mobility(&app, &json!({"mechanism": slider_crank})).await;
    assert_eq!((r["dof"].as_i64(), r["grubler"]["mobility"].as_i64()), (Some(1), Some(1)));
    assert_eq!((r["redundant_constraints"].as_i64(), r["candidate_inputs"].clone()), (Some(0), json!(["O"])));
}

/// Every field a spatial mechanism reads wrong is refused at its pointer,
/// in Spanish with `lang=es`; a planar mechanism given a point in space or
/// a spatial pair says how to ask for space.
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
    // Kinetostatics in space: an input is a joint's coordinate, a
    // cylindrical joint says which, and what the plane alone offers is refused.
    let mut cylinder = hooke();
    cylinder["joints"][1]["type"] = json!("cylindrical");
    let statics = json!({"mechanism": cylinder, "input": [{"joint": "B", "speed": 1}, {"point": "A", "speed": 1}],
        "outputs": ["driving", "energy"], "track": [{"name": "P", "body": "input", "at": [0, 0, 1]}],
        "loads": [{"type": "torque", "body": "output", "value": 1}]});
    let got = app.pointers("/v1/kinetostatics", &statics).await;
    assert_eq!(got, ["/track", "/outputs/1", "/input/0", "/input/1/point", "/input/1", "/loads/0"]);
}

async fn kinetostatics(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()
}

/// Hooke's joint at β = 30° driven at 3 rad/s against a torque of 7 N·m
/// on the output: ω₂/ω₁ = cos β/(1 − sin²β·cos²θ) (the yoke drawn in the
/// shafts' plane at θ = 0) and, massless, the input torque T·ω₂/ω₁ — the
/// power through the joint — at every step, to 1e-9; the three pairs hold O
/// three times over, so their reactions are flagged and said.
#[tokio::test]
async fn hooke_joint_passes_its_power() {
    let app = TestApp::new().await;
    let (beta, w1, torque) = (std::f64::consts::PI / 6.0, 3.0, 7.0);
    let e2 = [beta.cos(), beta.sin(), 0.0];
    let request = json!({"mechanism": hooke(),
        "input": {"joint": "A", "speed": w1, "start": 0, "end": "360 deg", "steps": 24},
        "loads": [{"type": "torque", "body": "output", "direction": e2, "value": -torque}]});
    let job = kinetostatics(&app, &request).await;
    let r = &job["result"];
    assert_eq!((r["dof"].as_i64(), r["redundant_constraints"].as_i64()), (Some(1), Some(3)));
    assert!(r["warnings"][0].as_str().unwrap().contains("A, B, cross"), "{}", r["warnings"]);
    for s in r["steps"].as_array().unwrap() {
        let theta = s["input"].as_f64().unwrap();
        let ratio = beta.cos() / (1.0 - beta.sin().powi(2) * theta.cos().powi(2));
        let omega: Vec<f64> = (0..3).map(|k| s["kinematics"][1]["angular_velocity"][k].as_f64().unwrap()).collect();
        let along: f64 = omega.iter().zip(e2).map(|(a, b)| a * b).sum();
        assert!((along - ratio * w1).abs() < 1e-9, "ω₂ at θ = {theta}");
        assert!((s["driving"].as_f64().unwrap() - torque * ratio).abs() < 1e-9, "τ₁ at θ = {theta}");
        assert_eq!(s["reactions"][0]["determinate"], false);
    }
    // Its table has the vectors' components, its plots and page draw.
    let id = job["id"].as_str().unwrap();
    let csv = app.get(&format!("/v1/jobs/{id}/result.csv")).await.text;
    let header = csv.lines().next().unwrap();
    assert!(header.contains("cross_fz_N") && header.contains("output_omega_z_rad_s"), "{header}");
    let plots = app.get(&format!("/v1/jobs/{id}/plots")).await.json();
    let listed: Vec<&str> = plots["plots"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(listed, ["driving", "reactions", "reduced-inertia", "mechanism"]);
    for p in plots["plots"].as_array().unwrap() {
        let svg = app.get(p["href"].as_str().unwrap()).await;
        assert_eq!(svg.status, StatusCode::OK, "{p}: {}", svg.text);
        assert!(svg.text.contains("<svg"), "{p}");
    }
    // The isometric drawing names every joint and says which way is up.
    let drawn = app.get(&format!("/v1/jobs/{id}/plots/mechanism.svg?step=5")).await.text;
    for joint in [">\nA\n<", ">\nB\n<", ">\ncross\n<", "isometric view, y up"] {
        assert!(drawn.contains(joint), "{joint} not drawn");
    }
    assert_eq!(app.get(&format!("/jobs/{id}")).await.status, StatusCode::OK);
    assert_eq!(app.get(&format!("/v1/jobs/{id}/solution?step=0")).await.status, StatusCode::OK);
    let part = app.get(&format!("/v1/jobs/{id}/result/steps/3/reactions/2/moment/1?unit=N*cm")).await;
    assert_eq!(part.status, StatusCode::OK, "{}", part.text);
    // Counted from 30° as drawn: the steps say the request's angles, from
    // 30°, and the engine's θ is φ − 30°, so each driving torque is the
    // first run's at the same step.
    let mut from = request.clone();
    from["input"] =
        json!({"joint": "A", "speed": w1, "reference": "30 deg", "start": "30 deg", "end": "390 deg", "steps": 24});
    let shifted = kinetostatics(&app, &from).await;
    for (a, b) in r["steps"].as_array().unwrap().iter().zip(shifted["result"]["steps"].as_array().unwrap()) {
        let (x, y) = (a["input"].as_f64().unwrap(), b["input"].as_f64().unwrap());
        assert!((y - x - std::f64::consts::FRAC_PI_6).abs() < 1e-12, "input {y} against {x} + 30°");
        assert!((a["driving"].as_f64().unwrap() - b["driving"].as_f64().unwrap()).abs() < 1e-9, "τ₁ at θ = {x}");
    }
}

/// Seed 003's rotor posed as a spatial mechanism: a massless frame on a
/// thrust bearing E (a spherical pair, driven about x) and a radial bearing
/// D (a sphere in a cylinder), carrying a disk spinning at 40 rad/s about
/// its own axis on a revolute, the frame speeding up from 15 rad/s at
/// 4 rad/s². At t = 0.1 s and 0.25 s, its bearing forces and driving moment
/// are the rotor kind's (`POST /v1/rotor`, in the fixed axes), to 1e-9 of the largest.
#[tokio::test]
async fn seed_003_rotor_as_a_mechanism() {
    let app = TestApp::new().await;
    let axis = [0.0, 0.6, 0.8];
    // I_G = R·diag(0.01, 0.01, 0.02)·Rᵀ about the spin axis: 0.01·(I + a·aᵀ).
    let tensor: Vec<Vec<f64>> =
        (0..3).map(|i| (0..3).map(|j| 0.01 * (f64::from(u8::from(i == j)) + axis[i] * axis[j])).collect()).collect();
    let rotor = json!({"mass": 2, "cg": [0.3, 0.1, 0.05], "spin": axis.map(|a| 40.0 * a), "bearings": [0, 0.5],
        "inertia": {"xx": tensor[0][0], "yy": tensor[1][1], "zz": tensor[2][2],
                    "xy": -tensor[0][1], "xz": -tensor[0][2], "yz": -tensor[1][2]},
        "gravity": [0, 0, -9.81], "frame": {"speed": 15, "acceleration": 4}, "times": [0.1, 0.25]});
    let r = app.post("/v1/rotor", &rotor).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let expected = r.json()["result"]["states"].clone();
    let angle = |t: f64| 15.0 * t + 2.0 * t * t;
    let mechanism = json!({"space": "spatial",
        "bodies": [{"name": "frame"}, {"name": "disk", "mass": 2, "cg": [0.3, 0.1, 0.05], "inertia": tensor}],
        "joints": [
            {"name": "D", "type": "sphere_in_cylinder", "bodies": ["ground", "frame"], "at": [0, 0, 0], "axis": [1, 0, 0]},
            {"name": "E", "type": "spherical", "bodies": ["ground", "frame"], "at": [0.5, 0, 0], "axis": [1, 0, 0]},
            {"name": "spin", "type": "revolute", "bodies": ["frame", "disk"], "at": [0.3, 0.1, 0.05], "axis": axis}
        ],
        "gravity": [0, 0, -9.81]});
    let request = json!({"mechanism": mechanism, "input": [
        {"joint": "E", "speed": {"expr": "sqrt(225 + 8*phi)"}, "start": angle(0.1),
         "end": angle(0.1) + 2.0 * (angle(0.25) - angle(0.1)), "steps": 2},
        {"joint": "spin", "speed": 40, "start": 4, "end": 16}]});
    let job = kinetostatics(&app, &request).await;
    for (k, state) in expected.as_array().unwrap().iter().enumerate() {
        let step = &job["result"]["steps"][k];
        let total = &state["reactions_fixed"]["total"];
        let of = |v: &Value| -> Vec<f64> { (0..3).map(|c| v[c].as_f64().unwrap()).collect() };
        let largest = of(&total["d"]).iter().chain(&of(&total["e"])).fold(0.0f64, |a, x| a.max(x.abs()));
        for (joint, bearing) in [(0, "d"), (1, "e")] {
            let (got, want) = (of(&step["reactions"][joint]["force"]), of(&total[bearing]));
            let gap = got.iter().zip(&want).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
            assert!(gap < 1e-9 * largest, "{bearing} at step {k}: {got:?} against {want:?}");
        }
        let moment = state["reactions"]["total"]["driving_moment"].as_f64().unwrap();
        assert!((step["driving"][0].as_f64().unwrap() - moment).abs() < 1e-9 * largest, "M_x at step {k}");
    }
}
