//! Kinetostatics through the HTTP API: reference case K1 and invalid mechanisms.

use crate::helpers::{TestApp, case, close, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

async fn post(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()
}

async fn errors(app: &TestApp, body: &Value) -> Vec<String> {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect()
}

/// K1 (offset slider-crank with gravity and a gas force), 12 crank angles at
/// 150 rad/s: driving torque, every reaction and I* against the case at its
/// tolerance 1e-9 (relative to the largest force at each angle).
#[tokio::test]
async fn k1_offset_slider_crank_through_the_api() {
    let (app, c) = (TestApp::new().await, case("K1_offset_slider_crank"));
    let job = post(&app, &request("k1_offset_slider_crank")).await;
    let r = &job["result"];
    assert_eq!((r["dof"].as_u64(), r["redundant_constraints"].as_u64()), (Some(1), Some(0)));
    assert_eq!(r["grubler"], json!({"mobility": 1, "equations": 9, "unknowns": 9}));
    let rows = c["expected"]["table"].as_array().unwrap();
    for (row, step) in rows.iter().zip(r["steps"].as_array().unwrap()) {
        let scale = row["reactions"]
            .as_object()
            .unwrap()
            .values()
            .map(|v| v["magnitude_N"].as_f64().unwrap())
            .fold(1.0, f64::max);
        let t = 1e-9 * scale;
        close(&step["input"], row["phi_rad"].as_f64().unwrap(), 1e-12, "input");
        assert!((step["driving"].as_f64().unwrap() - row["T_drive_Nm"].as_f64().unwrap()).abs() < t, "{step}");
        close(&step["reduced_inertia"], row["I_star_kg_m2"].as_f64().unwrap(), 1e-9, "I*");
        for reaction in step["reactions"].as_array().unwrap() {
            let expected = &row["reactions"][reaction["joint"].as_str().unwrap()];
            assert_eq!(reaction["on"], expected["on"]);
            assert_eq!(reaction["by"], expected["from"]);
            for (got, want) in [("fx", "Fx_N"), ("fy", "Fy_N")] {
                let d = reaction[got].as_f64().unwrap() - expected[want].as_f64().unwrap();
                assert!(d.abs() < t, "{} {got}: {d}", reaction["joint"]);
            }
        }
        let piston = &step["kinematics"][2];
        close(&piston["x"], row["piston_x_m"].as_f64().unwrap(), 1e-11, "piston x");
        close(&piston["vx"], row["piston_v_m_s"].as_f64().unwrap(), 1e-9, "piston v");
        close(&piston["ax"], row["piston_a_m_s2"].as_f64().unwrap(), 1e-9, "piston a");
    }
    assert!(r["summary"]["virtual_power_residual"].as_f64().unwrap() < 1e-12);
    assert_eq!(r["summary"]["singular"], false);
}

/// Asking only for the driving torque leaves reactions, I* and kinematics out.
#[tokio::test]
async fn only_what_is_asked_is_computed() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["outputs"] = json!(["driving"]);
    let r = post(&app, &body).await["result"].clone();
    let step = &r["steps"][1];
    assert!(step["reactions"].is_null() && step["reduced_inertia"].is_null() && step["kinematics"].is_null());
    assert!((step["driving"].as_f64().unwrap() - -228.491215292969).abs() < 1e-6, "K1 at 30°: {step}");
}

/// The condition number: by default estimated (κ₁ by Hager's method, a
/// lower bound of κ₁ and within a factor 3 of it in practice; κ₁ is within
/// a factor n = 9 of κ₂ either way); with "condition" among the outputs,
/// the case's κ₂ (an SVD) to 1e-9.
#[tokio::test]
async fn the_exact_condition_number_where_asked() {
    let (app, c) = (TestApp::new().await, case("K1_offset_slider_crank"));
    let rows = c["expected"]["table"].as_array().unwrap();
    let kappa = |r: &Value| -> Vec<f64> {
        r["steps"].as_array().unwrap().iter().map(|s| s["jacobian_condition"].as_f64().unwrap()).collect()
    };
    let estimated = kappa(&post(&app, &request("k1_offset_slider_crank")).await["result"]);
    let mut body = request("k1_offset_slider_crank");
    body["outputs"] = json!(["driving", "condition"]);
    let exact = kappa(&post(&app, &body).await["result"]);
    for ((row, e), x) in rows.iter().zip(&estimated).zip(&exact) {
        let want = row["cond_constraint_jacobian"].as_f64().unwrap();
        assert!((x - want).abs() <= 1e-9 * want, "κ₂ {x} vs {want}");
        assert!(*e >= want / 27.0 && *e <= 9.0 * want, "estimate {e} against κ₂ {want}");
    }
}

#[tokio::test]
async fn the_csv_has_one_row_per_step_with_units() {
    let app = TestApp::new().await;
    let job = post(&app, &request("k1_offset_slider_crank")).await;
    let csv = app.get(&format!("/v1/jobs/{}/result.csv", job["id"].as_str().unwrap())).await.text;
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 13);
    assert!(
        lines[0]
            .starts_with("input_rad,driving_N_m,reduced_inertia_kg_m2,reduced_torque_N_m,jacobian_condition,O_fx_N"),
        "{}",
        lines[0]
    );
}

#[tokio::test]
async fn invalid_mechanisms_are_named_field_by_field() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["mechanism"]["bodies"][0]["mass"] = json!(-2);
    body["mechanism"]["joints"][1]["bodies"] = json!(["crank", "crank"]);
    body["mechanism"]["joints"][2]["bodies"][0] = json!("rood");
    body["mechanism"]["joints"][3]["axis"] = json!([0, 0]);
    body["mechanism"]["joints"][0]["at"] = json!("Q");
    body["input"]["joint"] = json!("O");
    let p = errors(&app, &body).await;
    for want in [
        "/mechanism/bodies/0/mass",
        "/mechanism/joints/1/bodies",
        "/mechanism/joints/2/bodies/0",
        "/mechanism/joints/3/axis",
        "/mechanism/joints/0/at",
    ] {
        assert!(p.iter().any(|x| x == want), "{want} missing from {p:?}");
    }
    let mut body = request("k1_offset_slider_crank");
    body["input"]["joint"] = json!("crankshaft");
    assert_eq!(errors(&app, &body).await, ["/input/joint"]);
    let mut body = request("k1_offset_slider_crank");
    body["loads"][0]["body"] = json!("ground");
    assert_eq!(errors(&app, &body).await, ["/loads/0/body"]);
}

/// A non-Grashof four-bar (s + l = 0.5 + 1.0 > p + q = 0.6 + 0.7): the crank
/// cannot turn fully; asked for a full turn the answer is a 422 naming the
/// input value where the links stop closing, not garbage. Geometry: O2 (0, 0),
/// O4 (1, 0), A (0.6, 0), B = (1.1, √0.24) so that AB = 0.7 and O4B = 0.5.
#[tokio::test]
async fn a_non_grashof_crank_asked_for_a_full_turn_is_422() {
    let app = TestApp::new().await;
    let body = crate::student::non_grashof(json!({"joint": "O2", "speed": "60 rpm", "steps": 360}));
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let e = &r.json()["errors"][0];
    assert_eq!(e["pointer"], "/input/end", "a position along the range, short of its end");
    let message = e["message"].as_str().unwrap();
    assert!(
        message.contains("at input") && (message.contains("cannot be assembled") || message.contains("singular")),
        "{message}"
    );
}

/// Reference case K5 (seed 002): differential train, sun z1 = 60, planet
/// z3 = 30, ring z4 = 120, carrier at 50 rpm, ring at 25 rpm (Willis), 15 N·m
/// on the sun. Two inputs (carrier, ring) give the other members' speeds and
/// the torques the carrier and ring need: T2 = −45 N·m, T4 = +30 N·m
/// (virtual power; checked in the case by the tooth force 250 N).
#[tokio::test]
async fn k5_differential_gear_train_with_two_inputs() {
    let (app, c) = (TestApp::new().await, case("K5_differential_gear_train"));
    let e = &c["expected"];
    let r = post(&app, &request("k5_differential")).await["result"].clone();
    assert_eq!((r["dof"].as_u64(), r["grubler"]["mobility"].as_i64()), (Some(2), Some(2)));
    let rpm = std::f64::consts::PI / 30.0;
    for step in r["steps"].as_array().unwrap() {
        let driving = step["driving"].as_array().unwrap();
        close(&driving[0], e["torque_on_carrier2_Nm"].as_f64().unwrap(), 1e-9, "T on the carrier");
        close(&driving[1], e["torque_on_wheel4_Nm"].as_f64().unwrap(), 1e-9, "T on the ring");
        let bodies = step["kinematics"].as_array().unwrap();
        close(&bodies[0]["omega"], 100.0 * rpm, 1e-12, "ω sun (given in the case: 100 rpm)");
        close(&bodies[2]["omega"], e["omega3_rpm"].as_f64().unwrap() * rpm, 1e-12, "ω planet");
        assert!(step["reduced_inertia"].is_null(), "I* is defined for one DOF only");
    }
    // Virtual power, one equation per input's virtual motion, gives both
    // torques again, independently of the multipliers.
    let residual = r["summary"]["virtual_power_residual"].as_f64().expect("reported for two inputs");
    assert!(residual < 1e-9, "virtual power residual {residual}");
}

/// Scotch yoke (course notes P.81 in closed form): crank R = 0.1 m (2 kg at its
/// pin, I_G = 0.05 kg·m²), yoke 5 kg driven by the pin in its vertical slot,
/// load −100 sin φ N along x on the yoke, ω = 10 rad/s:
/// I* = I_G + mR² + MR² sin²φ = 0.07 + 0.05 sin²φ, M* = F·dx/dφ = 10 sin²φ,
/// T = ½ dI*/dφ ω² − M* = 5 sin φ cos φ − 10 sin²φ; mean T = −5 N·m, which
/// is the energy balance: the driver's work over a turn equals −∫M* dφ = −10π J.
fn scotch_yoke() -> Value {
    json!({
        "mechanism": {
            "points": {"O": [0, 0], "A": [0.1, 0]},
            "bodies": [
                {"name": "crank", "mass": 2, "inertia": 0.05, "cg": "A"},
                {"name": "yoke", "mass": 5, "inertia": 0.3, "cg": [0.3, 0]}
            ],
            "joints": [
                {"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                {"name": "slide", "type": "prismatic", "bodies": ["ground", "yoke"], "at": [0.3, 0], "axis": [1, 0]},
                {"name": "pin", "type": "pin_slot", "bodies": ["yoke", "crank"], "at": "A", "axis": [0, 1]}
            ]
        },
        "input": {"joint": "O", "speed": 10, "steps": 16},
        "loads": [{"type": "force", "body": "yoke", "at": "A", "direction": [1, 0], "magnitude": {"expr": "-100*sin(phi)"}}]
    })
}

#[tokio::test]
async fn scotch_yoke_matches_its_closed_form() {
    let app = TestApp::new().await;
    let r = post(&app, &scotch_yoke()).await["result"].clone();
    for step in r["steps"].as_array().unwrap() {
        let phi = step["input"].as_f64().unwrap();
        let (s, c) = phi.sin_cos();
        let t = (step["driving"].as_f64().unwrap() - (5.0 * s * c - 10.0 * s * s)).abs();
        assert!(t < 1e-10, "T at {phi}: off by {t}");
        assert!((step["reduced_inertia"].as_f64().unwrap() - (0.07 + 0.05 * s * s)).abs() < 1e-12);
        assert!((step["reduced_torque"].as_f64().unwrap() - 10.0 * s * s).abs() < 1e-10);
        // Quinn: the yoke's share of the kinetic energy is MR² sin²φ / I*.
        let share = step["energy_contribution"]["yoke"].as_f64().unwrap();
        assert!((share - 0.05 * s * s / (0.07 + 0.05 * s * s)).abs() < 1e-12);
    }
    close(&r["summary"]["mean_driving"], -5.0, 1e-12, "mean T (energy balance)");
}

/// Starting far from the drawn configuration keeps the drawn assembly branch:
/// the slider-crank drawn at φ = 0 and started at φ = 170° (continued there in
/// small steps) gives the same answer as the sweep that passes 170° (K1 at
/// 180° from the case, the row computed with the piston on the +x side).
#[tokio::test]
async fn a_start_far_from_the_drawing_keeps_the_assembly_branch() {
    let (app, c) = (TestApp::new().await, case("K1_offset_slider_crank"));
    let mut body = request("k1_offset_slider_crank");
    body["input"]["start"] = json!("180 deg");
    body["input"]["end"] = json!("540 deg");
    let r = post(&app, &body).await["result"].clone();
    let row = &c["expected"]["table"][6];
    assert_eq!(row["phi_deg"], 180);
    let t = r["steps"][0]["driving"].as_f64().unwrap() - row["T_drive_Nm"].as_f64().unwrap();
    assert!(t.abs() < 1e-8, "{t}");
    close(&r["steps"][0]["kinematics"][2]["x"], row["piston_x_m"].as_f64().unwrap(), 1e-11, "piston on the +x side");
}

/// A parallelogram four-bar, cranks 0.5 m (1 kg, I_G 0.02 kg·m², G at mid),
/// coupler 1 m (2 kg), drawn with the cranks vertical (input 0 there): a
/// Grashof change-point linkage (s + l = p + q), singular where all links are
/// collinear, at inputs π/2 and 3π/2. Closed form on the parallelogram branch:
/// every crank turns with the input, I* is constant, and with gravity
/// M* = 9.81·(0.25 + 0.25 + 2·0.5)·sin φ, so at constant speed T = −14.715 sin φ.
fn parallelogram(third_crank: bool) -> Value {
    let crank = |name: &str, x: f64| json!({"name": name, "mass": 1, "inertia": 0.02, "cg": [x, 0.25]});
    let rev =
        |name: &str, a: &str, b: &str, at: &str| json!({"name": name, "type": "revolute", "bodies": [a, b], "at": at});
    let mut bodies = vec![
        crank("crank", 0.0),
        json!({"name": "coupler", "mass": 2, "inertia": 0.2, "cg": [0.5, 0.5]}),
        crank("rocker", 1.0),
    ];
    let mut joints = vec![
        rev("O2", "ground", "crank", "O2"),
        rev("A", "crank", "coupler", "A"),
        rev("B", "coupler", "rocker", "B"),
        rev("O4", "rocker", "ground", "O4"),
    ];
    if third_crank {
        bodies.push(crank("crank3", 0.5));
        joints.push(rev("O3", "ground", "crank3", "O3"));
        joints.push(rev("C", "crank3", "coupler", "C"));
    }
    json!({
        "mechanism": {
            "points": {"O2": [0, 0], "O4": [1, 0], "A": [0, 0.5], "B": [1, 0.5], "O3": [0.5, 0], "C": [0.5, 0.5]},
            "bodies": bodies, "joints": joints, "gravity": [0, -9.81]
        },
        "input": {"joint": "O2", "speed": 10, "start": "-80 deg", "end": "280 deg", "steps": 36}
    })
}

#[tokio::test]
async fn a_change_point_four_bar_passes_its_singular_positions() {
    let app = TestApp::new().await;
    let r = post(&app, &parallelogram(false)).await["result"].clone();
    let mut singular = Vec::new();
    for step in r["steps"].as_array().unwrap() {
        let phi = step["input"].as_f64().unwrap();
        if step["singular"] == true {
            assert!(step["driving"].is_null() && step["reactions"].is_null(), "no garbage at a singular position");
            singular.push(phi);
            continue;
        }
        let t = step["driving"].as_f64().unwrap() + 14.715 * phi.sin();
        assert!(t.abs() < 1e-9, "T at {phi}: off by {t}");
        close(&step["kinematics"][2]["omega"], 10.0, 1e-9, "the rocker turns with the crank (parallelogram branch)");
    }
    assert_eq!(singular.len(), 2, "{singular:?}");
    assert!(
        (singular[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-12
            && (singular[1] - 1.5 * std::f64::consts::PI).abs() < 1e-12
    );
    assert_eq!(r["summary"]["singular"], true);
}

/// The CSV of a sweep through singular positions (reactions null there) and
/// of a kinematics-only job: every row as long as the header, the singular
/// rows' reactions empty, each body's motion in its own columns with units.
#[tokio::test]
async fn the_csv_keeps_its_columns_at_singular_positions_and_gives_the_motion() {
    let app = TestApp::new().await;
    let mut kinematics_only = request("k1_offset_slider_crank");
    kinematics_only["outputs"] = json!(["kinematics"]);
    for body in [parallelogram(false), kinematics_only] {
        let job = post(&app, &body).await;
        let r = app.get(&format!("/v1/jobs/{}/result.csv", job["id"].as_str().unwrap())).await;
        assert_eq!(r.status, StatusCode::OK, "{}", r.text);
        let rows: Vec<Vec<&str>> = r.text.lines().map(|l| l.split(',').collect()).collect();
        assert!(rows.iter().all(|row| row.len() == rows[0].len()), "ragged rows:\n{}", r.text);
        let motion = job["result"]["steps"][1]["kinematics"][0].clone();
        let column = rows[0].iter().position(|h| *h == format!("{}_omega_rad_s", motion["body"].as_str().unwrap()));
        let column = column.unwrap_or_else(|| panic!("no ω column in {:?}", rows[0]));
        close(&json!(rows[2][column].parse::<f64>().unwrap()), motion["omega"].as_f64().unwrap(), 1e-12, "ω");
    }
}

/// The same with a third, parallel crank: one redundant constraint; the
/// reactions are indeterminate (null, flagged), the driving torque is still
/// right: T = −(14.715 + 9.81·0.25)·sin φ = −17.1675 sin φ.
#[tokio::test]
async fn a_redundant_crank_flags_the_reactions_and_keeps_the_driving_torque() {
    let app = TestApp::new().await;
    let r = post(&app, &parallelogram(true)).await["result"].clone();
    assert_eq!(
        (r["dof"].as_u64(), r["redundant_constraints"].as_u64(), r["grubler"]["mobility"].as_i64()),
        (Some(1), Some(1), Some(0))
    );
    assert!(r["warnings"][0].as_str().unwrap().contains("redundant"));
    let step = &r["steps"][3];
    let phi = step["input"].as_f64().unwrap();
    assert!((step["driving"].as_f64().unwrap() + 17.1675 * phi.sin()).abs() < 1e-9, "{step}");
    for reaction in step["reactions"].as_array().unwrap() {
        assert_eq!(reaction["determinate"], false, "{}", step["reactions"]);
        assert!(reaction["fx"].is_null());
    }
}

/// Coulomb friction, scotch yoke with gravity. In the guide (μ = 0.2) the
/// normal force is the yoke's weight (the slot's force is horizontal), so the
/// driver supplies μ·M·g·|v|/ω = 0.2·5·9.81·0.1·|sin φ| more. At the crank
/// bearing (μ = 0.1, pin radius 0.02 m) a couple μ·r·|R_O| opposes the turn;
/// it leaves R_O unchanged, so T grows by 0.002·|R_O| of the frictionless run.
#[tokio::test]
async fn joint_friction_adds_the_work_it_dissipates() {
    let app = TestApp::new().await;
    let mut plain = scotch_yoke();
    plain["mechanism"]["gravity"] = json!([0, -9.81]);
    let mut guide = plain.clone();
    guide["mechanism"]["joints"][1]["friction"] = json!({"mu": 0.2});
    let mut bearing = plain.clone();
    bearing["mechanism"]["joints"][0]["friction"] = json!({"mu": 0.1, "radius": "20 mm"});
    let (p, g, b) = (post(&app, &plain).await, post(&app, &guide).await, post(&app, &bearing).await);
    let steps = |j: &Value| j["result"]["steps"].as_array().unwrap().clone();
    for ((sp, sg), sb) in steps(&p).iter().zip(steps(&g)).zip(steps(&b)) {
        let phi = sp["input"].as_f64().unwrap();
        let t = |s: &Value| s["driving"].as_f64().unwrap();
        let extra = t(&sg) - t(sp);
        assert!((extra - 0.981 * phi.sin().abs()).abs() < 1e-9, "guide friction at {phi}: {extra}");
        let r_o = sp["reactions"][0]["fx"].as_f64().unwrap().hypot(sp["reactions"][0]["fy"].as_f64().unwrap());
        assert!((t(&sb) - t(sp) - 0.002 * r_o).abs() < 1e-9, "bearing friction at {phi}");
    }
    assert!(g["result"]["accuracy"]["max_friction_iterations"].as_u64().unwrap() >= 1);
    assert!(g["result"]["summary"]["virtual_power_residual"].as_f64().unwrap() < 1e-12);
}

/// Scissor lift of seed 002 (exam problem, excerpt in the seed): platform 9m,
/// two bars of mass m and length 2L crossed at their midpoints F, bar DE at
/// α = 30° to the horizontal, the platform descending at constant v, driven by
/// the horizontal piston AB at B. Printed answer (virtual power):
/// F_AB = −√3·(10mg + 8mv²/(27L)). With m = 10 kg, L = 0.5 m, v = 0.3 m/s:
/// −1700.0718 N. The piston's motion follows from y_G = 2L sin α, x_B = 2L cos α:
/// ẋ_B = v tan α = v/√3, ẍ_B = −v²/(2L cos³α).
#[tokio::test]
async fn scissor_lift_piston_force_matches_the_printed_answer() {
    let app = TestApp::new().await;
    let (m, l, v, g) = (10.0f64, 0.5f64, 0.3f64, 9.81f64);
    let c30 = 30f64.to_radians().cos();
    let bar = |name: &str| json!({"name": name, "mass": m, "inertia": m * l * l / 3.0, "cg": "F"});
    let body = json!({
        "mechanism": {
            "points": {"D": [0, 0], "E": [2.0 * l * c30, l], "B": [2.0 * l * c30, 0], "C": [0, l], "F": [l * c30, l / 2.0]},
            "bodies": [bar("DE"), bar("BC"), {"name": "platform", "mass": 9.0 * m, "inertia": 1.0, "cg": [l * c30, l]}, {"name": "block"}],
            "joints": [
                {"name": "D", "type": "revolute", "bodies": ["ground", "DE"], "at": "D"},
                {"name": "F", "type": "revolute", "bodies": ["DE", "BC"], "at": "F"},
                {"name": "C", "type": "revolute", "bodies": ["BC", "platform"], "at": "C"},
                {"name": "E", "type": "pin_slot", "bodies": ["platform", "DE"], "at": "E", "axis": [1, 0]},
                {"name": "B", "type": "revolute", "bodies": ["block", "BC"], "at": "B"},
                {"name": "piston", "type": "prismatic", "bodies": ["ground", "block"], "at": "B", "axis": [1, 0]}
            ],
            "gravity": [0, -g]
        },
        "input": {"joint": "piston", "speed": v / 3f64.sqrt(), "acceleration": -v * v / (2.0 * l * c30.powi(3)), "start": 0, "end": 0.01, "steps": 1}
    });
    let r = post(&app, &body).await["result"].clone();
    assert_eq!(r["dof"], 1);
    let expected = -(3f64.sqrt()) * (10.0 * m * g + 8.0 * m * v * v / (27.0 * l));
    close(&r["steps"][0]["driving"], expected, 1e-12, "F_AB (printed −√3(10mg + 8mv²/27L))");
    close(&r["steps"][0]["kinematics"][2]["vy"], -v, 1e-12, "the platform descends at v");
    close(&r["steps"][0]["kinematics"][2]["ay"], 0.0, 1e-12, "at constant speed");
}

/// Hard case: a centred slider-crank with r/l = 0.95 (rod at 72° to the
/// stroke at φ = 90°), only the piston massive (M = 3 kg), ω = 100 rad/s.
/// Closed form: x = r cos φ + √(l² − r² sin²φ), I* = M (dx/dφ)², and
/// T = ½ ω² dI*/dφ (dI*/dφ by a central difference of the closed form,
/// h = 1e-6, error ~1e-9 relative).
#[tokio::test]
async fn a_slider_crank_with_r_over_l_095_matches_its_closed_form() {
    let app = TestApp::new().await;
    let (r, l, m, w) = (0.095f64, 0.1f64, 3.0f64, 100.0f64);
    let body = json!({
        "mechanism": {
            "points": {"O": [0, 0], "A": [r, 0], "B": [r + l, 0]},
            "bodies": [{"name": "crank"}, {"name": "rod"}, {"name": "piston", "mass": m, "cg": "B"}],
            "joints": [
                {"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                {"name": "A", "type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
                {"name": "B", "type": "revolute", "bodies": ["rod", "piston"], "at": "B"},
                {"name": "guide", "type": "prismatic", "bodies": ["ground", "piston"], "at": "B", "axis": [1, 0]}
            ]
        },
        "input": {"joint": "O", "speed": w, "steps": 72}
    });
    let res = post(&app, &body).await["result"].clone();
    let dx = |p: f64| -r * p.sin() - r * r * p.sin() * p.cos() / (l * l - r * r * p.sin().powi(2)).sqrt();
    let istar = |p: f64| m * dx(p).powi(2);
    // I* to 1e-9 of its largest value: at the dead centres it is rounding
    // (~1e-36 kg·m² from sin π ≠ 0), where no relative bound holds.
    let i_max = (0..72).map(|k| istar(k as f64 * std::f64::consts::PI / 36.0)).fold(0.0, f64::max);
    for step in res["steps"].as_array().unwrap() {
        let p = step["input"].as_f64().unwrap();
        let i = step["reduced_inertia"].as_f64().unwrap();
        assert!((i - istar(p)).abs() <= 1e-9 * i_max, "I* at {p}: {i} vs {}", istar(p));
        let t = 0.5 * w * w * (istar(p + 1e-6) - istar(p - 1e-6)) / 2e-6;
        let scale = 0.5 * w * w * 0.05;
        assert!((step["driving"].as_f64().unwrap() - t).abs() < 1e-6 * scale, "T at {p}: {} vs {t}", step["driving"]);
    }
    assert_eq!(res["summary"]["singular"], false);
}

/// Hard case: the non-Grashof four-bar above driven up to 1e-4 rad before its
/// toggle (the crank's limit φ_max = acos(−1/15), where A, B and O4 align):
/// the answers stay consistent (multipliers and virtual power agree) while the
/// condition number, reported at every step, rises steeply in the last steps
/// (16.8 at φ = 0, 58 at δ = 1e-4 here).
#[tokio::test]
async fn a_four_bar_approaching_its_toggle_reports_it() {
    let app = TestApp::new().await;
    let limit = (-1.0f64 / 15.0).acos();
    let body = json!({
        "mechanism": {
            "points": {"O2": [0, 0], "O4": [1, 0], "A": [0.6, 0], "B": [1.1, 0.24f64.sqrt()]},
            "bodies": [
                {"name": "crank", "mass": 1, "inertia": 0.03, "cg": [0.3, 0]},
                {"name": "coupler", "mass": 1, "inertia": 0.04, "cg": [0.85, 0.245]},
                {"name": "rocker", "mass": 1, "inertia": 0.02, "cg": [1.05, 0.245]}
            ],
            "joints": [
                {"name": "O2", "type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                {"name": "A", "type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                {"name": "B", "type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                {"name": "O4", "type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}
            ]
        },
        "input": {"joint": "O2", "speed": 1, "start": 0, "end": limit - 1e-4, "steps": 200}
    });
    let r = post(&app, &body).await["result"].clone();
    assert!(r["summary"]["virtual_power_residual"].as_f64().unwrap() < 1e-9, "{}", r["summary"]);
    let conditions: Vec<f64> =
        r["steps"].as_array().unwrap().iter().map(|s| s["jacobian_condition"].as_f64().unwrap()).collect();
    assert!(
        conditions.last().unwrap() > &(3.0 * conditions[0]),
        "{:?} from {}",
        &conditions[conditions.len() - 3..],
        conditions[0]
    );
    assert!(conditions.windows(2).rev().take(20).all(|w| w[1] > w[0]), "rising towards the toggle");
}

/// A spring (k = 2000 N/m, free length 0.15 m) and a damper (c = 30 N·s/m)
/// between the tip A of a massless crank r = 0.1 m and the ground point
/// S = (0, 0.2), ω = 5 rad/s. With L = |A − S| and L' = dL/dφ = −r·d·cos φ / L
/// (d = 0.2), the driving torque is T = k(L − L₀)L' + c·ω·L'² (closed form).
#[tokio::test]
async fn springs_and_dampers_load_the_driver() {
    let app = TestApp::new().await;
    let (r, d, k, l0, c, w) = (0.1f64, 0.2f64, 2000.0f64, 0.15f64, 30.0f64, 5.0f64);
    let body = json!({
        "mechanism": {
            "points": {"O": [0, 0], "A": [r, 0], "S": [0, d]},
            "bodies": [{"name": "crank"}],
            "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O"}]
        },
        "input": {"joint": "O", "speed": w, "steps": 24},
        "loads": [
            {"type": "spring", "a": ["crank", "A"], "b": ["ground", "S"], "stiffness": "2 kN/m", "free_length": "150 mm"},
            {"type": "damper", "a": ["crank", "A"], "b": ["ground", "S"], "coefficient": c}
        ]
    });
    let res = post(&app, &body).await["result"].clone();
    for step in res["steps"].as_array().unwrap() {
        let p = step["input"].as_f64().unwrap();
        let length = (r * p.cos()).hypot(r * p.sin() - d);
        let dl = -r * d * p.cos() / length;
        let t = k * (length - l0) * dl + c * w * dl * dl;
        assert!((step["driving"].as_f64().unwrap() - t).abs() < 1e-9, "T at {p}: {} vs {t}", step["driving"]);
    }
}

/// A motion law: the crank's speed given as a Function of its angle,
/// ω(φ) = 10 + 2 sin φ, so α = ω·dω/dφ = 2(10 + 2 sin φ) cos φ. A disk of
/// 0.5 kg·m² on the crank needs T = 0.5·α (closed form).
#[tokio::test]
async fn a_speed_law_gives_the_acceleration_omega_domega_dphi() {
    let app = TestApp::new().await;
    let body = json!({
        "mechanism": {
            "points": {"O": [0, 0]},
            "bodies": [{"name": "disk", "mass": 4, "inertia": 0.5, "cg": "O"}],
            "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "disk"], "at": "O"}]
        },
        "input": {"joint": "O", "speed": {"expr": "10 + 2*sin(phi)"}, "steps": 12}
    });
    let res = post(&app, &body).await["result"].clone();
    for step in res["steps"].as_array().unwrap() {
        let p = step["input"].as_f64().unwrap();
        let t = 0.5 * 2.0 * (10.0 + 2.0 * p.sin()) * p.cos();
        assert!((step["driving"].as_f64().unwrap() - t).abs() < 1e-12, "T at {p}");
        close(&step["kinematics"][0]["omega"], 10.0 + 2.0 * p.sin(), 1e-12, "ω(φ)");
    }
}

/// The two-loop crank / slotted lever / slider mechanism of the course notes
/// (P.77): crank O1B = r about O1 = (d, 0), block 3 at B sliding along the
/// lever O2A (pivot O2 at the origin, length a), block 5 at A sliding in a
/// horizontal slot of body 6, which slides vertically (y = a sin θ). P.77's
/// closed form (Zhukovsky), with s² = r² + d² + 2rd cos φ and
/// tan θ = r sin φ/(d + r cos φ):
/// I* = I_G2 + r²m₃ + (r²/s²)(I_G3 + I_G4 + m₆x² + a²(m₄/4 + m₅))·cos²(θ − φ),
/// M* = −F·x·(r/s)·cos(θ − φ) for a weight F on body 6, x = a cos θ.
/// (The printed ẏ line omits the factor x that its M* formula has; the formula
/// also neglects block 5's own rotary inertia, so I_G5 = 0 here.)
#[tokio::test]
async fn the_two_loop_mechanism_of_p77_matches_its_closed_form() {
    let app = TestApp::new().await;
    let (d, r, a) = (0.3f64, 0.1f64, 0.5f64);
    let (i2, m3, i3, m4, i4, m5, m6, f) = (0.02, 0.5, 0.001, 2.0, 2.0 * a * a / 12.0, 0.3, 4.0, 100.0);
    let body = json!({
        "mechanism": {
            "points": {"O1": [d, 0], "O2": [0, 0], "B": [d + r, 0], "A": [a, 0]},
            "bodies": [
                {"name": "crank", "mass": 1, "inertia": i2, "cg": "O1"},
                {"name": "block3", "mass": m3, "inertia": i3, "cg": "B"},
                {"name": "lever", "mass": m4, "inertia": i4, "cg": [a / 2.0, 0]},
                {"name": "block5", "mass": m5, "inertia": 0, "cg": "A"},
                {"name": "slider6", "mass": m6, "inertia": 0.1, "cg": [a, 0.2]}
            ],
            "joints": [
                {"name": "O1", "type": "revolute", "bodies": ["ground", "crank"], "at": "O1"},
                {"name": "B", "type": "revolute", "bodies": ["crank", "block3"], "at": "B"},
                {"name": "slot4", "type": "prismatic", "bodies": ["lever", "block3"], "at": "B", "axis": [1, 0]},
                {"name": "O2", "type": "revolute", "bodies": ["ground", "lever"], "at": "O2"},
                {"name": "A", "type": "revolute", "bodies": ["lever", "block5"], "at": "A"},
                {"name": "slot6", "type": "prismatic", "bodies": ["slider6", "block5"], "at": "A", "axis": [1, 0]},
                {"name": "guide6", "type": "prismatic", "bodies": ["ground", "slider6"], "at": [a, 0.2], "axis": [0, 1]}
            ]
        },
        "input": {"joint": "O1", "speed": 10, "steps": 24},
        "loads": [{"type": "force", "body": "slider6", "at": [a, 0.2], "direction": [0, -1], "magnitude": f}]
    });
    let res = post(&app, &body).await["result"].clone();
    assert_eq!((res["dof"].as_u64(), res["grubler"]["mobility"].as_i64()), (Some(1), Some(1)));
    for step in res["steps"].as_array().unwrap() {
        let p = step["input"].as_f64().unwrap();
        let s = (r * r + d * d + 2.0 * r * d * p.cos()).sqrt();
        let th = (r * p.sin()).atan2(d + r * p.cos());
        let x = a * th.cos();
        let c2 = (th - p).cos().powi(2);
        let istar = i2 + r * r * m3 + r * r / (s * s) * (i3 + i4 + m6 * x * x + a * a * (m4 / 4.0 + m5)) * c2;
        close(&step["reduced_inertia"], istar, 1e-9, "I* (P.77)");
        let mstar = -f * x * r / s * (th - p).cos();
        assert!((step["reduced_torque"].as_f64().unwrap() - mstar).abs() < 1e-9 * f * a, "M* at {p}");
    }
}

/// K5 with the module (2 mm) given: the gear reactions become tooth forces at
/// the pitch points. Both meshes of the massless planet carry the case's
/// tangential force T1/R1 = 15/0.06 = 250 N, so with 20° teeth each tooth
/// force is 250/cos 20° = 266.04 N, and it acts at the pitch radius (its
/// moment about the planet's centre is 250 N × 0.03 m).
#[tokio::test]
async fn gear_reactions_are_tooth_forces_when_the_module_is_given() {
    let (app, c) = (TestApp::new().await, case("K5_differential_gear_train"));
    let ft = c["expected"]["tangential_tooth_force_N"].as_f64().unwrap();
    let mut body = request("k5_differential");
    body["mechanism"]["joints"][4]["module"] = json!("2 mm");
    body["mechanism"]["joints"][5]["module"] = json!("2 mm");
    let r = post(&app, &body).await["result"].clone();
    for step in r["steps"].as_array().unwrap() {
        for mesh in [4, 5] {
            let reaction = &step["reactions"][mesh];
            let f = reaction["fx"].as_f64().unwrap().hypot(reaction["fy"].as_f64().unwrap());
            assert!((f - ft / 20f64.to_radians().cos()).abs() < 1e-9, "{reaction}");
            assert_eq!(reaction["moment"], 0.0);
        }
    }
    // At the first step the planet's centre is at (0.09, 0) and the sun-planet
    // pitch point at (0.06, 0): the tooth force on the planet is 250 N along y
    // and 250·tan 20° = 90.99 N along +x (pushing the planet off the sun).
    let first = &r["steps"][0]["reactions"][4];
    assert!((first["fy"].as_f64().unwrap().abs() - ft).abs() < 1e-9, "{first}");
    assert!((first["fx"].as_f64().unwrap() - ft * 20f64.to_radians().tan()).abs() < 1e-9, "{first}");
    let mut missing = request("k5_differential");
    missing["mechanism"]["joints"][4]["module"] = json!("2 mm");
    missing["mechanism"]["joints"][4].as_object_mut().unwrap().remove("teeth");
    missing["mechanism"]["joints"][4]["ratio"] = json!(-2);
    assert_eq!(errors(&app, &missing).await, ["/mechanism/joints/4"]);
}

/// Without the rod–piston pin the rod swings on the crank and the piston slides
/// on its own: 3 DOF for 1 input. A 422 says so, not a least-squares answer.
#[tokio::test]
async fn inputs_must_match_the_degrees_of_freedom() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    let joints = body["mechanism"]["joints"].as_array_mut().unwrap();
    joints.retain(|j| j["name"] != "B");
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let message = r.json()["errors"][0]["message"].as_str().unwrap().to_string();
    assert!(message.contains("3 degree(s) of freedom but 1 input"), "{message}");
}

/// The method says how the positions were found: K1 (a crank and an RRP
/// dyad) in closed form, which Newton confirms without an iteration; K5's
/// gears have no dyads, and Newton assembles them from the continuation.
#[tokio::test]
async fn the_method_says_where_positions_are_placed_in_closed_form() {
    let app = TestApp::new().await;
    let k1 = post(&app, &request("k1_offset_slider_crank")).await["result"]["accuracy"].clone();
    assert!(k1["method"].as_str().unwrap().contains("positions in closed form (a crank and dyads"), "{k1}");
    assert_eq!(k1["max_newton_iterations"], 0, "{k1}");
    let k5 = post(&app, &request("k5_differential")).await["result"]["accuracy"].clone();
    assert!(
        k5["method"].as_str().unwrap().contains("Newton-Raphson assembly with continuation of up to third order"),
        "{k5}"
    );
}
