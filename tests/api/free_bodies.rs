//! Free bodies and the worked solution (issue 74, contract part five): every
//! moving body's listed forces and couples balance at every step (K1, a
//! four-bar, a slider-crank with pin friction, a guide of given length, a
//! cam with its contact); each reaction is on both its bodies, opposite,
//! with the job's numbers; a static slider-crank's against its closed form;
//! the order is the Assur groups from the last; the virtual powers add to 0.

use crate::helpers::{TestApp, request, template_request};
use serde_json::{Value, json};

/// The solution of every step of the job `body` posts to `path`, checked:
/// each body's three sums zero to `tol` of its largest action, each
/// reaction opposite on its other body and equal to the job's, the
/// virtual powers' total zero to `tol` of their largest. Returns the solutions.
async fn checked(app: &TestApp, path: &str, body: &Value, tol: f64) -> Vec<Value> {
    let job = app.post(path, body).await;
    assert_eq!(job.status, 201, "{}", job.text);
    let job = job.json();
    let (id, steps) = (job["id"].as_str().unwrap(), job["result"]["steps"].as_array().unwrap());
    let mut solutions = vec![];
    for (k, step) in steps.iter().enumerate() {
        let got = app.get(&format!("/v1/jobs/{id}/solution?step={k}")).await;
        if got.status == 422 {
            // Only where the job solved nothing either: a singular position.
            assert!(step["driving"].is_null() && step["reduced_inertia"].is_null(), "step {k}: {}", got.text);
            continue;
        }
        assert_eq!(got.status, 200, "step {k}: {}", got.text);
        let s = got.json();
        balanced(&s, k, tol);
        opposite_and_the_jobs(&s, step, k, tol);
        solutions.push(s);
    }
    solutions
}

/// Each body's ΣF_x, ΣF_y and ΣM_G are zero to `tol` of its largest force (and moment).
fn balanced(s: &Value, k: usize, tol: f64) {
    let power = s["virtual_power"].clone();
    let largest_power =
        power["actions"].as_object().unwrap().values().map(|p| p.as_f64().unwrap().abs()).fold(0.0, f64::max);
    assert!(power["total"].as_f64().unwrap().abs() <= tol * largest_power.max(1.0), "step {k}: {power}");
    for b in s["bodies"].as_array().unwrap() {
        let forces = b["forces"].as_array().unwrap();
        let f = forces.iter().map(|f| f["fx"].as_f64().unwrap().hypot(f["fy"].as_f64().unwrap())).fold(0.0, f64::max);
        let arm = forces
            .iter()
            .map(|f| {
                let (x, y) = (
                    f["at"][0].as_f64().unwrap() - b["cg"][0].as_f64().unwrap(),
                    f["at"][1].as_f64().unwrap() - b["cg"][1].as_f64().unwrap(),
                );
                x.hypot(y)
            })
            .fold(0.0, f64::max);
        let couple =
            b["couples"].as_array().unwrap().iter().map(|c| c["moment"].as_f64().unwrap().abs()).fold(0.0, f64::max);
        let e = &b["equations"];
        let (fx, fy, m) =
            (e["sum_fx"].as_f64().unwrap(), e["sum_fy"].as_f64().unwrap(), e["sum_moment_about_cg"].as_f64().unwrap());
        assert!(fx.abs() <= tol * f.max(1.0) && fy.abs() <= tol * f.max(1.0), "step {k} {}: {e}", b["body"]);
        assert!(m.abs() <= tol * (f * arm + couple).max(1.0), "step {k} {}: {e}", b["body"]);
    }
}

/// Every reaction on a body by a moving body is on that body too,
/// opposite, through the same joint; and the job's reaction of each joint
/// (on its `on` by its `by`) is the solution's force (summed over a
/// guide's two ends) to `tol`.
fn opposite_and_the_jobs(s: &Value, step: &Value, k: usize, tol: f64) {
    let body = |name: &str| s["bodies"].as_array().unwrap().iter().find(|b| b["body"] == name).cloned();
    let total = |b: &Value, joint: &Value, by: &Value| {
        let on = b["forces"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|f| f["kind"] == "reaction" && &f["joint"] == joint && &f["by"] == by);
        on.fold([0.0, 0.0], |a, f| [a[0] + f["fx"].as_f64().unwrap(), a[1] + f["fy"].as_f64().unwrap()])
    };
    for r in step["reactions"].as_array().into_iter().flatten() {
        let scale = r["fx"].as_f64().unwrap().hypot(r["fy"].as_f64().unwrap()).max(1.0);
        if let Some(on) = body(r["on"].as_str().unwrap()) {
            let f = total(&on, &r["joint"], &r["by"]);
            assert!((f[0] - r["fx"].as_f64().unwrap()).abs() <= tol * scale, "step {k} {r}: {f:?}");
            assert!((f[1] - r["fy"].as_f64().unwrap()).abs() <= tol * scale, "step {k} {r}: {f:?}");
        }
        if let Some(by) = body(r["by"].as_str().unwrap()) {
            let f = total(&by, &r["joint"], &r["on"]);
            assert!((f[0] + r["fx"].as_f64().unwrap()).abs() <= tol * scale, "step {k} opposite {r}: {f:?}");
            assert!((f[1] + r["fy"].as_f64().unwrap()).abs() <= tol * scale, "step {k} opposite {r}: {f:?}");
        }
    }
}

/// Case K1 (gravity, a gas force on the piston, 150 rad/s) at its 12
/// steps; solved from the last dyad: rod and piston (R23, R34, R14 and the
/// guide's couple), then the crank (R12 and M_m), as P.23 narrates.
#[tokio::test]
async fn k1_s_bodies_balance_at_every_step_and_are_solved_from_the_last_dyad() {
    let app = TestApp::new().await;
    let solutions = checked(&app, "/v1/kinetostatics", &request("k1_offset_slider_crank"), 1e-9).await;
    assert_eq!(solutions.len(), 12);
    let s = &solutions[3];
    assert_eq!(s["numbering"], json!({"ground": 1, "crank": 2, "rod": 3, "piston": 4}));
    assert_eq!(s["order"], json!(["rod", "piston", "crank"]));
    assert_eq!(s["groups"][0]["unknowns"], json!(["R23", "R34", "R14"]));
    assert_eq!(s["groups"][1]["unknowns"], json!(["R12", "M_m"]));
    let rod = s["bodies"].as_array().unwrap().iter().find(|b| b["body"] == "rod").unwrap();
    let names: Vec<&str> = rod["forces"].as_array().unwrap().iter().map(|f| f["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["F_I3", "W3", "R23", "R43"], "{rod}");
}

/// A slider-crank at rest (no speed, no mass but the slider's load): a
/// statics problem with a closed form. Crank r = 0.1 m at θ = 60°, rod l =
/// 0.3 m, a force P = −1000 N along x on the slider: sin β = r sin θ/l, the
/// rod a two-force member, so its force on the slider is along B − A,
/// R34 = (−P, P·tan β); the guide's normal force −P·tan β; and the motor
/// torque M = P·r·sin(θ + β)/cos β (virtual work: M·δθ + P·δx = 0, with
/// δx = −r sin(θ + β)/cos β·δθ).
#[tokio::test]
async fn a_static_slider_crank_s_free_bodies_are_its_closed_form() {
    let (r, l, theta, p) = (0.1_f64, 0.3_f64, 60f64.to_radians(), -1000.0_f64);
    let beta = (r * theta.sin() / l).asin();
    let (ax, ay) = (r * theta.cos(), r * theta.sin());
    let bx = ax + l * beta.cos();
    let body = json!({
        "mechanism": {
            "points": {"O": [0, 0], "A": [ax, ay], "B": [bx, 0]},
            "bodies": [
                {"name": "crank", "mass": 0, "inertia": 0, "cg": "O"},
                {"name": "rod", "mass": 0, "inertia": 0, "cg": "A"},
                {"name": "slider", "mass": 0, "inertia": 0, "cg": "B"}
            ],
            "joints": [
                {"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                {"name": "A", "type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
                {"name": "B", "type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
                {"name": "guide", "type": "prismatic", "bodies": ["ground", "slider"], "at": "B", "axis": [1, 0]}
            ]
        },
        "input": {"joint": "O", "speed": 0, "reference": theta, "start": theta, "end": theta, "steps": 1},
        "loads": [{"type": "force", "body": "slider", "at": "B", "direction": [1, 0], "magnitude": p}]
    });
    let app = TestApp::new().await;
    let s = &checked(&app, "/v1/kinetostatics", &body, 1e-9).await[0];
    let force = |b: &str, name: &str| -> [f64; 2] {
        let body = s["bodies"].as_array().unwrap().iter().find(|x| x["body"] == b).unwrap();
        let f = body["forces"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["name"] == name)
            .unwrap_or_else(|| panic!("{name} on {b}: {body}"));
        [f["fx"].as_f64().unwrap(), f["fy"].as_f64().unwrap()]
    };
    let close = |got: f64, want: f64, what: &str| {
        assert!((got - want).abs() <= 1e-9 * want.abs().max(1.0), "{what}: {got} vs {want}")
    };
    let r34 = force("slider", "R34");
    close(r34[0], -p, "R34_x balances P");
    close(r34[1], p * beta.tan(), "R34_y, along the rod");
    close(force("slider", "R14")[1], -p * beta.tan(), "the guide's normal force");
    // The rod's two ends: the crank's force on it opposite to the slider's.
    let (r23, r43) = (force("rod", "R23"), force("rod", "R43"));
    close(r23[0], -r43[0], "a two-force member, x");
    close(r23[1], -r43[1], "a two-force member, y");
    let crank = s["bodies"].as_array().unwrap().iter().find(|b| b["body"] == "crank").unwrap();
    let motor =
        crank["couples"].as_array().unwrap().iter().find(|c| c["name"] == "M_m").unwrap_or_else(|| panic!("{crank}"));
    close(motor["moment"].as_f64().unwrap(), p * r * (theta + beta).sin() / beta.cos(), "M_m, by virtual work");
}

/// The library's four-bar (gravity and its load), the cam and flat
/// follower of seed 002 (its contact), the scissor lift (a point input
/// with the piston as actuator), P.115's shaper (pins in slots), the ring
/// driven along the rim (an effort along a contact), the bar on a slider
/// (two inputs); K1 with
/// friction at every pin (μ = 0.1 on 10 mm pins) and with a 60 mm guide
/// with friction (its two ends): every body balances at every step.
#[tokio::test]
async fn bodies_with_friction_a_guide_s_ends_and_a_cam_s_contact_balance() {
    let app = TestApp::new().await;
    for id in ["four-bar", "cam-flat-follower", "scissor-lift", "p115-shaper", "ring-on-rim", "bar-on-slider"] {
        checked(&app, "/v1/kinetostatics", &template_request(id), 1e-8).await;
    }
    let mut friction = request("k1_offset_slider_crank");
    for joint in friction["mechanism"]["joints"].as_array_mut().unwrap() {
        if joint["type"] == "revolute" {
            joint["friction"] = json!({"mu": 0.1, "radius": "10 mm"});
        }
    }
    checked(&app, "/v1/kinetostatics", &friction, 1e-8).await;
    let mut guide = request("k1_offset_slider_crank");
    guide["mechanism"]["joints"][3]["length"] = json!("60 mm");
    guide["mechanism"]["joints"][3]["friction"] = json!({"mu": 0.15});
    let s = checked(&app, "/v1/kinetostatics", &guide, 1e-8).await;
    let piston = s[2]["bodies"].as_array().unwrap().iter().find(|b| b["body"] == "piston").unwrap().clone();
    let ends = piston["forces"].as_array().unwrap().iter().filter(|f| f["name"] == "R14").count();
    assert_eq!(ends, 2, "a guide's two ends: {piston}");
}

/// Central difference of `f` at x (h = 1e-6: an error of order 1e-12 for these smooth positions).
fn derivative(f: impl Fn(f64) -> [f64; 2], x: f64) -> [f64; 2] {
    let h = 1e-6;
    let (a, b) = (f(x + h), f(x - h));
    [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h)]
}

/// P.23's template: every body balances at its 36 positions, the coupler
/// and rocker are solved before the crank, and the crank's torque is the
/// closed form of virtual work, T₂ = −(F₃·dM₃/dθ + F₄·dM₄/dθ), with the
/// loads' points M₃ (the coupler's middle) and M₄ (the rocker's) placed by
/// circle intersection (O₂A = 0.1, AB = 0.3, CB = 0.2, O₂C = 0.35, the
/// branch drawn) and differentiated numerically: to 1e-7 of the largest.
#[tokio::test]
async fn p23_s_crank_torque_is_virtual_work_on_its_free_bodies() {
    let app = TestApp::new().await;
    let body = template_request("p23-four-bar-statics");
    let solutions = checked(&app, "/v1/kinetostatics", &body, 1e-9).await;
    assert_eq!(solutions[0]["order"], json!(["coupler", "rocker", "crank"]));
    assert_eq!(solutions[0]["groups"][1]["unknowns"], json!(["R12", "M_m"]));
    let (r, l3, l4, c) = (0.1_f64, 0.3_f64, 0.2_f64, [0.35_f64, 0.0]);
    let b_at = |t: f64| {
        let a = [r * t.cos(), r * t.sin()];
        let (dx, dy) = (c[0] - a[0], c[1] - a[1]);
        let d = dx.hypot(dy);
        let along = (l3 * l3 - l4 * l4 + d * d) / (2.0 * d);
        let h = (l3 * l3 - along * along).sqrt();
        (a, [a[0] + along * dx / d - h * dy / d, a[1] + along * dy / d + h * dx / d])
    };
    let m3 = |t: f64| {
        let (a, b) = b_at(t);
        [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]
    };
    let m4 = |t: f64| {
        let (_, b) = b_at(t);
        [(b[0] + c[0]) / 2.0, (b[1] + c[1]) / 2.0]
    };
    let job = app.post("/v1/kinetostatics", &body).await.json();
    let steps = job["result"]["steps"].as_array().unwrap();
    let torque = |t: f64| {
        let (d3, d4) = (derivative(m3, t), derivative(m4, t));
        -(-500.0 * d3[1] + -300.0 * d4[0])
    };
    let largest = steps.iter().map(|s| s["driving"].as_f64().unwrap().abs()).fold(0.0, f64::max);
    for s in steps {
        let t = s["input"].as_f64().unwrap();
        let (got, want) = (s["driving"].as_f64().unwrap(), torque(t));
        assert!((got - want).abs() <= 1e-7 * largest, "θ = {t}: T₂ {got}, virtual work {want}");
    }
}

/// P.53's template: at its defaults (inertia, gravity, the cutting force)
/// every body balances, the virtual powers add to zero, and the groups are
/// solved as the notes solve them — block 5 and the ram, then block 3 and
/// the lever, then the crank. Without masses, at rest: the crank's torque
/// is F·dx_B/dφ, x_B = 0.6·A_x/|A| with A = (0.1 cos φ, 0.3 + 0.1 sin φ)
/// (the lever through A), to 1e-7 of the largest.
#[tokio::test]
async fn p53_s_shaper_is_solved_from_the_ram_to_the_crank() {
    let app = TestApp::new().await;
    let mut body = template_request("p53-shaper-dynamics");
    let solutions = checked(&app, "/v1/kinetostatics", &body, 1e-8).await;
    assert_eq!(solutions.len(), 36, "a full turn in 36 steps");
    assert_eq!(solutions[5]["order"], json!(["block5", "ram", "block3", "lever", "crank"]));
    let unknowns: Vec<Value> =
        solutions[5]["groups"].as_array().unwrap().iter().map(|g| g["unknowns"].clone()).collect();
    assert_eq!(unknowns, [json!(["R45", "R65", "R16"]), json!(["R23", "R43", "R14"]), json!(["R12", "M_m"])]);
    for b in body["mechanism"]["bodies"].as_array_mut().unwrap() {
        (b["mass"], b["inertia"]) = (json!(0), json!(0));
    }
    body["mechanism"].as_object_mut().unwrap().remove("gravity");
    body["input"]["speed"] = json!(0);
    let job = app.post("/v1/kinetostatics", &body).await.json();
    let x_b = |phi: f64| {
        let a = [0.1 * phi.cos(), 0.3 + 0.1 * phi.sin()];
        [0.6 * a[0] / a[0].hypot(a[1]), 0.0]
    };
    let steps = job["result"]["steps"].as_array().unwrap();
    let largest = steps.iter().map(|s| s["driving"].as_f64().unwrap().abs()).fold(0.0, f64::max);
    for s in steps {
        let phi = s["input"].as_f64().unwrap();
        let (got, want) = (s["driving"].as_f64().unwrap(), 1000.0 * derivative(x_b, phi)[0]);
        assert!((got - want).abs() <= 1e-7 * largest, "φ = {phi}: T₂ {got}, virtual work {want}");
    }
}

/// What cannot be solved says why: a flywheel job has no free bodies
/// (404 naming its kind), a step beyond the job's is a 422 at `step`, a
/// body the job has not is a 404 listing the free-body plots it has; a
/// body's diagram is an SVG drawn to scale with its name.
#[tokio::test]
async fn a_solution_that_cannot_be_had_says_why() {
    let app = TestApp::new().await;
    let flywheel = app.post("/v1/flywheel", &request("p103_slider")).await.json();
    let got = app.get(&format!("/v1/jobs/{}/solution", flywheel["id"].as_str().unwrap())).await;
    assert_eq!(
        (got.status.as_u16(), got.json()["type"].as_str()),
        (404, Some("/problems/no-such-solution")),
        "{}",
        got.text
    );
    assert!(got.json()["detail"].as_str().unwrap().contains("flywheel"), "{}", got.text);
    let k1 = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await.json();
    let id = k1["id"].as_str().unwrap();
    let beyond = app.get(&format!("/v1/jobs/{id}/solution?step=12")).await;
    assert_eq!(beyond.status, 422, "{}", beyond.text);
    assert_eq!(beyond.json()["errors"][0]["parameter"], "step", "{}", beyond.text);
    let none = app.get(&format!("/v1/jobs/{id}/plots/free-body-wheel.svg?step=2")).await;
    assert_eq!(none.status, 404, "{}", none.text);
    assert!(none.text.contains("free-body-rod"), "{}", none.text);
    let svg = app.get(&format!("/v1/jobs/{id}/plots/free-body-rod.svg?step=2")).await;
    assert_eq!(svg.status, 200, "{}", svg.text);
    assert!(svg.text.contains("R23") && svg.text.contains("F_I3") && svg.text.contains("M_I3"), "{}", svg.text);
}

/// A run's sample: D1's scotch yoke from rest with its crank free, and
/// P.68's two-link arm (two free inputs, a motor's torque at each joint
/// as a load): the reactions the run stored, the loads at the sample's
/// time and the bodies' inertia balance every body at every tenth sample,
/// to 1e-6 of its largest action — d'Alembert's check of the run itself;
/// the free inputs have no effort, their accelerations are what the
/// crank's group gives. A run in reduced form has no free bodies (404).
#[tokio::test]
async fn a_run_s_samples_balance_with_the_reactions_it_stored() {
    let app = TestApp::new().await;
    for name in ["d1_scotch_yoke_machine", "p68_two_link_arm"] {
        let job = app.post("/v1/dynamics", &request(name)).await;
        assert_eq!(job.status, 201, "{name}: {}", job.text);
        let job = job.json();
        let id = job["id"].as_str().unwrap();
        let samples = job["result"]["machine"]["samples"].as_array().unwrap();
        for k in (0..samples.len()).step_by(10) {
            let got = app.get(&format!("/v1/jobs/{id}/solution?step={k}")).await;
            assert_eq!(got.status, 200, "{name} sample {k}: {}", got.text);
            let s = got.json();
            balanced(&s, k, 1e-6);
            opposite_and_the_jobs(&s, &samples[k], k, 1e-12);
            let efforts = s["bodies"].as_array().unwrap().iter().flat_map(|b| b["couples"].as_array().unwrap().clone());
            assert!(efforts.filter(|c| c["kind"] == "driving").count() == 0, "{name} {k}: a free input has no effort");
        }
        let solution = app.get(&format!("/v1/jobs/{id}/solution?step=0")).await.json();
        let last = solution["groups"].as_array().unwrap().last().unwrap()["unknowns"].clone();
        assert!(last.as_array().unwrap().iter().any(|u| u.as_str().unwrap().starts_with("φ̈")), "{name}: {last}");
    }
    let reduced = json!({"reduced_inertia": 1, "torques": [{"name": "t", "value": 1}], "duration": 1});
    let job = app.post("/v1/dynamics", &reduced).await.json();
    let got = app.get(&format!("/v1/jobs/{}/solution", job["id"].as_str().unwrap())).await;
    assert_eq!(got.status, 404, "{}", got.text);
}
