//! Direct dynamics through the HTTP API: reference case D1 and clean endings.

use crate::helpers::{TestApp, case, close, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

fn d1(end: Value) -> Value {
    let mut body = json!({
        "torques": [{"name": "motor 15 N*m, yoke load 200 N", "value": {"expr": "15 - 20*sin(phi)^2"}}],
        "reduced_inertia": {"expr": "sin(phi)^2/20 + 7/100"},
        "initial": {"angle": 0, "speed": "0 rpm"}
    });
    for (k, v) in end.as_object().unwrap() {
        body[k] = v.clone();
    }
    body
}

/// D1 (scotch yoke from rest, constant torque): the turns at 2π and 4π, and
/// the state every 0.05 s, against the case's closed form at 1e-9 (and
/// within the reported error estimate); the
/// turns' times by the energy form (t = ∫dφ/ω by quadrature, the second
/// method) at 1e-10, and the difference of the two methods reported.
#[tokio::test]
async fn d1_scotch_yoke_start_up_through_the_api() {
    let (app, c) = (TestApp::new().await, case("D1_scotch_yoke_from_rest_constant_torque"));
    let r = app.post("/v1/dynamics", &d1(json!({"until_angle": "720 deg"}))).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let job = r.json();
    let events = job["result"]["events"].as_array().unwrap().clone();
    let rows = &c["expected"]["at_angle"].as_array().unwrap()[5..7];
    for (e, row) in events.iter().filter(|e| e["kind"] == "turn").zip(rows) {
        close(&e["t"], row["time_s"].as_f64().unwrap(), 1e-9, "t at the turn");
        close(&e["speed"], row["omega_rad_s"].as_f64().unwrap(), 1e-9, "ω at the turn");
        close(&e["t_energy_form"], row["time_s"].as_f64().unwrap(), 1e-10, "t at the turn, energy form");
    }
    assert_eq!(events.last().unwrap()["kind"], "end");
    // The end at a fixed address, as a spreadsheet's WEBSERVICE reads it: 4π reached at the case's time.
    assert_eq!(&job["result"]["end"], events.last().unwrap());
    let url = format!("/v1/jobs/{}/result/end/t", job["id"].as_str().unwrap());
    let end = app.get(&url).await.text.parse::<f64>().unwrap();
    close(&json!(end), c["expected"]["at_angle"][6]["time_s"].as_f64().unwrap(), 1e-9, "t at the end");
    let difference = job["result"]["accuracy"]["energy_form_time_difference"].as_f64().unwrap();
    assert!(difference < 1e-9, "{difference}");
    // Actions of φ only: their work is a quadrature over the angle (the brake of tests/api/stiff.rs, of ω: the integrated power).
    assert!(job["result"]["accuracy"]["method"].as_str().unwrap().ends_with("by adaptive quadrature over the angle"));
    assert!(job["result"]["energy_residual"].as_f64().unwrap().abs() < 1e-9);
    let r = app.post("/v1/dynamics", &d1(json!({"duration": "1 s", "samples": 21}))).await;
    let samples = r.json()["result"]["samples"].as_array().unwrap().clone();
    // The reported estimate (Σ of local error estimates) bounds the actual error here.
    let estimated = r.json()["result"]["accuracy"]["estimated_error"].as_f64().unwrap();
    assert!(estimated > 0.0 && estimated < 1e-7, "{estimated}");
    for row in c["expected"]["at_time"].as_array().unwrap() {
        let t = row["time_s"].as_f64().unwrap();
        let s = samples.iter().find(|s| (s["t"].as_f64().unwrap() - t).abs() < 1e-12).unwrap();
        let angle = row["angle_rad"].as_f64().unwrap();
        assert!((s["angle"].as_f64().unwrap() - angle).abs() <= estimated, "error over the estimate at t = {t}");
        close(&s["angle"], angle, 1e-9, "angle");
        close(&s["speed"], row["omega_rad_s"].as_f64().unwrap(), 1e-9, "speed");
    }
    let csv = app.get(&format!("/v1/jobs/{}/result.csv", job["id"].as_str().unwrap())).await.text;
    assert!(csv.starts_with("t_s,angle_rad,speed_rad_s,acceleration_rad_s2"));
}

/// A motor too weak to reach the next dead centre: M* = 5 − 20 sin²φ from rest
/// stops near φ = 0.948 (where sin 2φ = φ) and swings back. Asked for 2π, the run
/// ends cleanly at `max_duration` with the reason.
#[tokio::test]
async fn a_start_up_that_never_arrives_ends_with_the_reason() {
    let app = TestApp::new().await;
    let mut body = d1(json!({"until_angle": "2*pi", "max_duration": "5 s"}));
    body["torques"][0]["value"] = json!({"expr": "5 - 20*sin(phi)^2"});
    body["reduced_inertia"] = json!(0.1);
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    assert_eq!(result["warnings"][0], "the angle 2*pi was not reached within 5 s", "in the request's words");
    // The motion turned back: the energy form does not apply to its end.
    assert!(result["events"][0].get("t_energy_form").is_none(), "{}", result["events"]);
    let max_angle =
        result["samples"].as_array().unwrap().iter().map(|s| s["angle"].as_f64().unwrap()).fold(0.0, f64::max);
    assert!((max_angle - 0.9477).abs() < 0.01, "{max_angle}");
}

#[tokio::test]
async fn the_end_condition_and_the_inertia_are_checked() {
    let app = TestApp::new().await;
    // Each end condition a request gives too many or too few of, at its field.
    let pointers = |r: &crate::helpers::Reply| -> Vec<String> {
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect()
    };
    let both = d1(json!({"duration": 1, "until_angle": 3}));
    let r = app.post("/v1/dynamics", &both).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(pointers(&r), ["/duration", "/until_angle"], "{}", r.text);
    let r = app.post("/v1/dynamics", &d1(json!({}))).await;
    assert_eq!(pointers(&r), ["/duration"], "{}", r.text);
    assert!(r.text.contains("required: give \\\"duration\\\""), "{}", r.text);
    // A longest time for a run that ends at its duration would be ignored: it is refused.
    let r = app.post("/v1/dynamics", &d1(json!({"duration": 1, "max_duration": 5}))).await;
    assert_eq!(pointers(&r), ["/max_duration"], "{}", r.text);
    let mut negative = d1(json!({"duration": 1}));
    negative["reduced_inertia"] = json!({"expr": "sin(phi)"});
    let r = app.post("/v1/dynamics", &negative).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(r.json()["errors"][0]["pointer"], "/reduced_inertia");
    // One message per invalid field, the one that applies.
    let r = app.post("/v1/dynamics", &d1(json!({"duration": "-1 s", "period": "3 kg"}))).await;
    let errors = r.json()["errors"].clone();
    assert_eq!(errors.as_array().unwrap().len(), 2, "{errors}");
    assert_eq!((errors[0]["pointer"].as_str(), errors[1]["pointer"].as_str()), (Some("/period"), Some("/duration")));
    assert!(errors[1]["message"].as_str().unwrap().contains("greater than 0"), "{errors}");
}

/// Actions that depend on the speed and on time. From rest with I* = 2:
/// M* = 3 − 0.5·omega gives ω = 6(1 − e^(−t/4)), φ = 6(t − 4(1 − e^(−t/4)));
/// M* = 2t with I* = 1 gives ω = t², φ = t³/3 (closed forms), at t = 2 s.
#[tokio::test]
async fn actions_may_depend_on_speed_and_time() {
    let app = TestApp::new().await;
    let run = |torque: &str, inertia: f64| json!({"torques": [{"name": "m", "value": {"expr": torque}}], "reduced_inertia": inertia, "duration": 2, "samples": 3});
    let r = app.post("/v1/dynamics", &run("3 - 0.5*omega", 2.0)).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let end = r.json()["result"]["samples"][2].clone();
    let decay = (-0.5f64).exp();
    close(&end["speed"], 6.0 * (1.0 - decay), 1e-9, "ω(2)");
    close(&end["angle"], 6.0 * (2.0 - 4.0 * (1.0 - decay)), 1e-9, "φ(2)");
    assert!(r.json()["result"]["energy_residual"].as_f64().unwrap().abs() < 1e-9);
    let end = app.post("/v1/dynamics", &run("2*t", 1.0)).await.json()["result"]["samples"][2].clone();
    close(&end["speed"], 4.0, 1e-9, "ω(2) = t²");
    close(&end["angle"], 8.0 / 3.0, 1e-9, "φ(2) = t³/3");
}

/// D1's scotch yoke as a `machine` with its crank free (docs/course.md's
/// example): 15 N·m on the crank, 200 sin φ N along +x on the yoke, from
/// rest, with `end` replacing the fixture's end condition.
fn d1_machine(end: Value) -> Value {
    let mut body = request("d1_scotch_yoke_machine");
    if !end.as_object().unwrap().is_empty() {
        body.as_object_mut().unwrap().remove("until_angle");
    }
    for (k, v) in end.as_object().unwrap() {
        body[k] = v.clone();
    }
    body
}

/// The case's closed-form turn times at 1e-8 (the same physics as the
/// reduced form above), every sample's input state, the reactions, and the
/// constraint drift reported.
#[tokio::test]
async fn d1_as_a_machine_through_the_api() {
    let (app, c) = (TestApp::new().await, case("D1_scotch_yoke_from_rest_constant_torque"));
    let r = app.post("/v1/dynamics", &d1_machine(json!({}))).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    let rows = &c["expected"]["at_angle"].as_array().unwrap()[5..7];
    let turns: Vec<_> = result["events"].as_array().unwrap().iter().filter(|e| e["kind"] == "turn").cloned().collect();
    assert_eq!(turns.len(), 2);
    for (e, row) in turns.iter().zip(rows) {
        close(&e["t"], row["time_s"].as_f64().unwrap(), 1e-8, "t at the turn");
        close(&e["speed"], row["omega_rad_s"].as_f64().unwrap(), 1e-8, "ω at the turn");
    }
    let machine = &result["machine"];
    assert_eq!(machine["dof"], 1);
    let last = &machine["samples"][10];
    close(&last["inputs"][0]["angle"], 4.0 * std::f64::consts::PI, 1e-9, "the end angle");
    assert_eq!(last["reactions"].as_array().unwrap().len(), 3, "{last}");
    assert!(last["constraint_residual"].as_f64().unwrap() < 1e-9);
    assert!(result["accuracy"]["constraint_drift"].as_f64().unwrap() < 1e-9);
    assert!(result["energy_residual"].as_f64().unwrap().abs() < 1e-8);
    // The CSV has every body's position and every reaction beside the input's state: the
    // crank's centre A at 0.1·(cos φ, sin φ) m, the yoke's at 0.2 + 0.1·cos φ m (its drawn
    // 0.3 m with A at 0.1 m), to 1e-12 m (the positions are the integrated coordinates, held on
    // Φ = 0 to 1e-12·L by the projection), the reactions as in the JSON.
    let csv = app.get(&format!("/v1/jobs/{}/result.csv", r.json()["id"].as_str().unwrap())).await.text;
    let mut reader = csv::Reader::from_reader(csv.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("{name} in {header:?}"));
    let (phi, crank_x, crank_y, yoke_x) =
        (column("angle_rad"), column("crank_x_m"), column("crank_y_m"), column("yoke_x_m"));
    // t, φ, φ̇, φ̈; x, y, θ of the crank and the yoke; fx, fy, moment of O, slide and pin.
    assert_eq!(header.len(), 4 + 2 * 3 + 3 * 3, "{header:?}");
    for (k, row) in reader.records().map(|r| r.unwrap()).enumerate() {
        let x = |c: usize| row[c].parse::<f64>().unwrap();
        let (cos, sin) = (x(phi).cos(), x(phi).sin());
        assert!((x(crank_x) - 0.1 * cos).abs() < 1e-12 && (x(crank_y) - 0.1 * sin).abs() < 1e-12, "row {k}");
        assert!((x(yoke_x) - (0.2 + 0.1 * cos)).abs() < 1e-12, "row {k}");
        let reaction = &result["machine"]["samples"][k]["reactions"][2];
        let name = reaction["joint"].as_str().unwrap();
        assert_eq!(x(column(&format!("{name}_fx_N"))), reaction["fx"].as_f64().unwrap(), "row {k}");
    }
}

/// Machine-form mistakes answer 422 at the field: friction, a motion law as
/// the initial speed, a kinetostatic field, the first input's state given
/// twice, two forms at once, and a mechanism with more freedom than inputs.
#[tokio::test]
async fn machine_form_errors_point_at_the_field() {
    let app = TestApp::new().await;
    let mut body = d1_machine(json!({"duration": 1}));
    body["machine"]["mechanism"]["joints"][0]["friction"] = json!({"mu": 0.1, "radius": 0.01});
    body.as_object_mut().unwrap().remove("initial");
    body["machine"]["input"]["speed"] = json!({"expr": "10 + phi"});
    body["machine"]["input"]["steps"] = json!(10);
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let pointers: Vec<String> =
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect();
    for p in ["/machine/mechanism/joints/0/friction", "/machine/input/speed", "/machine/input/steps"] {
        assert!(pointers.contains(&p.to_string()), "{p} in {pointers:?}");
    }
    let mut twice = d1_machine(json!({"duration": 1}));
    twice["machine"]["input"]["start"] = json!("10 deg");
    let r = app.post("/v1/dynamics", &twice).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/initial", "{}", r.text);
    let mut both = d1_machine(json!({"duration": 1}));
    both["reduced_inertia"] = json!(0.1);
    let r = app.post("/v1/dynamics", &both).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/machine");
    assert_eq!(r.json()["errors"][1]["pointer"], "/reduced_inertia");
    let mut neither = d1_machine(json!({"duration": 1}));
    neither.as_object_mut().unwrap().remove("machine");
    let r = app.post("/v1/dynamics", &neither).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/machine", "{}", r.text);
    let mut loose = d1_machine(json!({"duration": 1}));
    loose["machine"]["mechanism"]["joints"].as_array_mut().unwrap().pop();
    let r = app.post("/v1/dynamics", &loose).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/machine/input", "{}", r.text);
    assert!(r.text.contains("2 degree(s) of freedom"), "{}", r.text);
    // The reason in the asker's language, as the rest of the message.
    let r = crate::spanish::in_spanish(&app, "POST", "/v1/dynamics", Some(&loose)).await;
    let said = r.json()["errors"][0]["message"].as_str().unwrap().to_string();
    let expected = "el estado inicial no se puede montar: el mecanismo tiene 2 grado(s) de libertad, pero 1 entrada(s) \
                    nombran sus coordenadas";
    assert_eq!(said, expected);
}

/// The integrator and the energy hold: chosen (`auto`: DOP853 in the reduced
/// form at 1e-9, Dormand–Prince above 1e-5 and for a machine), asked for,
/// reported, and either pair reaching D1's closed-form turn times (1e-9
/// reduced, 1e-8 machine, as above); the energy held by default where the
/// loads have a potential (a pendulum under gravity) and not otherwise (D1's
/// force varies with φ); an
/// unknown pair and a hold the loads cannot have answered 422 at the field.
#[tokio::test]
async fn the_integrator_and_the_energy_hold_are_chosen_and_reported() {
    let (app, c) = (TestApp::new().await, case("D1_scotch_yoke_from_rest_constant_torque"));
    let turn = &c["expected"]["at_angle"][5];
    let cases = [
        (d1(json!({"until_angle": "360 deg"})), "dop853", 1e-9),
        // At tolerance 1e-4 the turn is within 1e-6 (measured 2e-7, as D1's row in docs/BENCHMARKS.md).
        (d1(json!({"until_angle": "360 deg", "tolerance": 1e-4})), "dopri5", 1e-6),
        (d1(json!({"until_angle": "360 deg", "integrator": "dopri5"})), "dopri5", 1e-9),
        (d1_machine(json!({"until_angle": "360 deg"})), "dopri5", 1e-8),
        (d1_machine(json!({"until_angle": "360 deg", "integrator": "dop853"})), "dop853", 1e-8),
    ];
    for (body, integrator, tolerance) in cases {
        let r = app.post("/v1/dynamics", &body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let result = &r.json()["result"];
        assert_eq!(result["accuracy"]["integrator"], integrator, "{body}");
        let e = result["events"].as_array().unwrap().iter().find(|e| e["kind"] == "end").unwrap().clone();
        close(&e["t"], turn["time_s"].as_f64().unwrap(), tolerance, "t at 2π");
        let held = result["accuracy"]["energy_conserved"].clone();
        assert_eq!(held, if body.get("machine").is_some() { json!(false) } else { Value::Null }, "{body}");
    }
    let mut pendulum = request("a01_pendulum");
    pendulum["duration"] = json!(3);
    let r = app.post("/v1/dynamics", &pendulum).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let accuracy = &r.json()["result"]["accuracy"];
    assert_eq!(accuracy["energy_conserved"], true);
    let (held, steps) = (accuracy["energy_held_steps"].as_u64().unwrap(), accuracy["steps"].as_u64().unwrap());
    assert!(0 < held && held <= steps, "held after {held} of {steps} steps");
    assert!(r.json()["result"]["accuracy"]["method"].as_str().unwrap().contains("T + V"));
    let mut unknown = d1(json!({"duration": 1}));
    unknown["integrator"] = json!("rk4");
    let r = app.post("/v1/dynamics", &unknown).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/integrator", "{}", r.text);
    let mut forced = d1_machine(json!({"duration": 1}));
    forced["machine"]["conserve_energy"] = json!(true);
    let r = app.post("/v1/dynamics", &forced).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/machine/conserve_energy", "{}", r.text);
    assert!(r.text.contains("/machine/loads/1 is a force whose magnitude varies"), "{}", r.text);
}

/// A torque that grows without bound, T = 1/(0.5 − t) on I* = 1: ω =
/// 1 − ln(1 − 2t) runs away at t = 0.5 s (closed form), where no step can
/// follow it. The 422 says where once, to four significant figures (so
/// within 5e-5 s of 0.5, its trailing zeros dropped), and why, in the
/// asker's language.
#[tokio::test]
async fn a_run_away_motion_is_refused_saying_when_once() {
    let app = TestApp::new().await;
    let body = json!({
        "torques": [{"name": "m", "value": {"expr": "1/(0.5 - t)"}}],
        "reduced_inertia": 1,
        "initial": {"angle": 0, "speed": 1},
        "duration": 2
    });
    let (en, es) = (
        app.post("/v1/dynamics", &body).await,
        crate::spanish::in_spanish(&app, "POST", "/v1/dynamics", Some(&body)).await,
    );
    let said = |r: &crate::helpers::Reply| {
        assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
        r.json()["errors"][0]["message"].as_str().unwrap().to_owned()
    };
    let (en, es) = (said(&en), said(&es));
    assert!(en.starts_with("the integration failed at t = 0.5 s: the step size fell below round-off"), "{en}");
    assert!(es.starts_with("la integración falló en t = 0,5 s: el paso se hizo menor que el redondeo"), "{es}");
    assert_eq!(en.matches("t = ").count(), 1, "{en}");
}

/// A run whose result cannot fit is refused before it is computed (issue
/// 70): 100 000 samples of a slider-crank's start-up, under a budget of
/// 50 ms that the run would spend many times over, are answered
/// `/problems/result-too-large` at `/samples` (not the budget's 422: no
/// integration began), its least size per sample said; and that least size
/// is one: a run of 201 samples takes more per sample than it says.
#[tokio::test]
async fn a_run_that_cannot_fit_is_refused_before_it_is_computed() {
    let budget = std::time::Duration::from_millis(50);
    let app = TestApp::with_limits(mechdyn::kind::Limits { budget, ..Default::default() }).await;
    let mut run = request("slider_crank_startup");
    run["samples"] = json!(100_000);
    let r = app.post("/v1/dynamics", &run).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let problem = r.json();
    assert_eq!(problem["type"], "/problems/result-too-large", "{}", r.text);
    assert_eq!(problem["errors"][0]["pointer"], "/samples");
    let message = problem["errors"][0]["message"].as_str().unwrap();
    // "… at least 81.3 MB (81300000 bytes) …": the least bytes of 100 000 samples.
    let least: f64 = message.split(" (").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
    run["samples"] = json!(201);
    let app = TestApp::new().await;
    let done = app.post("/v1/dynamics", &run).await;
    assert_eq!(done.status, StatusCode::CREATED, "{}", done.text);
    let bytes = done.json()["result"].to_string().len() as f64;
    assert!(bytes / 201.0 > least / 100_000.0, "{bytes} bytes for 201 samples, said at least {least} for 100 000");
}
