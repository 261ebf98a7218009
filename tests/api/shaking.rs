//! A linkage's shaking of its frame and its counterweights (kinetostatics'
//! "shaking" and `balance`, issue 51), each checked by an independent
//! method: the shaking against the sum of what the links put on the frame
//! (the reactions of Φ_qᵀλ at the ground joints and the motor's torque),
//! the counterweights by the kinetostatics of the linkage that carries them
//! (a four-bar's shaking force then nil; a slider-crank's the fraction left,
//! against the closed form from its pins' accelerations) and by the
//! two-point equivalent of a coupler whose centre of mass is midway.

use crate::helpers::{TestApp, close, template_request};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// The library's four-bar with no gravity and no load: the links' inertia alone.
fn four_bar() -> Value {
    let mut r = template_request("four-bar");
    for key in ["constants", "loads"] {
        r.as_object_mut().unwrap().remove(key);
    }
    r["mechanism"].as_object_mut().unwrap().remove("gravity");
    r["outputs"] = json!(["driving", "reactions", "shaking"]);
    r
}

fn point(r: &Value, name: &str) -> [f64; 2] {
    let p = &r["mechanism"]["points"][name];
    [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()]
}

/// With no gravity and no load, −Σ m·a_G is what the links put on the frame:
/// the ground joints' reactions on the frame and the motor's reaction torque.
#[tokio::test]
async fn the_shaking_is_what_the_links_put_on_the_frame() {
    let app = TestApp::new().await;
    let request = four_bar();
    let result = app.result("/v1/kinetostatics", &request).await;
    let at = |joint: &str| point(&request, joint);
    let largest = result["summary"]["max_shaking_force"].as_f64().unwrap();
    assert!(largest > 10.0, "{}", result["summary"]);
    let mut moment_max = 0.0_f64;
    for s in result["steps"].as_array().unwrap() {
        let (mut f, mut m) = ([0.0; 2], -s["driving"].as_f64().unwrap());
        for r in s["reactions"].as_array().unwrap() {
            let sign = if r["on"] == "ground" {
                1.0
            } else if r["by"] == "ground" {
                -1.0
            } else {
                continue;
            };
            let [fx, fy] = [r["fx"].as_f64().unwrap() * sign, r["fy"].as_f64().unwrap() * sign];
            let [x, y] = at(r["joint"].as_str().unwrap());
            f = [f[0] + fx, f[1] + fy];
            m += x * fy - y * fx + sign * r["moment"].as_f64().unwrap();
        }
        // Two solutions of the same equations: rounding of forces of 10² N.
        for (k, f) in f.iter().enumerate() {
            let got = s["shaking"]["force"][k].as_f64().unwrap();
            assert!((got - f).abs() <= 1e-9 * largest, "F against the ground reactions: {got}, {f}");
        }
        let moment = s["shaking"]["moment"].as_f64().unwrap();
        assert!((moment - m).abs() <= 1e-9 * largest, "M {moment} against the frame's {m}");
        moment_max = moment_max.max(moment.abs());
    }
    close(&result["summary"]["max_shaking_moment"], moment_max, 1e-15, "the largest |M|");
}

/// The counterweights of `result` as point masses at `rho` from each
/// link's ground joint, folded into its body (mass, centre of mass, I_G).
fn carrying(request: &Value, result: &Value, rho: f64, ground: &[(&str, &str, &str)]) -> Value {
    let mut balanced = request.clone();
    for w in result["counterweights"].as_array().unwrap() {
        let name = w["body"].as_str().unwrap();
        let &(_, pivot, other) = ground.iter().find(|g| g.0 == name).unwrap();
        let (o, to) = (point(request, pivot), point(request, other));
        let line = (to[1] - o[1]).atan2(to[0] - o[0]) + w["angle"].as_f64().unwrap();
        let (mc, p) = (w["mass_radius"].as_f64().unwrap() / rho, [o[0] + rho * line.cos(), o[1] + rho * line.sin()]);
        let body = balanced["mechanism"]["bodies"].as_array_mut().unwrap().iter_mut().find(|b| b["name"] == name);
        let body = body.unwrap();
        let (m, i) = (body["mass"].as_f64().unwrap(), body["inertia"].as_f64().unwrap());
        let g = [body["cg"][0].as_f64().unwrap(), body["cg"][1].as_f64().unwrap()];
        let total = m + mc;
        let cg = [(m * g[0] + mc * p[0]) / total, (m * g[1] + mc * p[1]) / total];
        let d2 = |a: [f64; 2]| (a[0] - cg[0]).powi(2) + (a[1] - cg[1]).powi(2);
        *body = json!({"name": name, "mass": total, "inertia": i + m * d2(g) + mc * d2(p), "cg": cg});
    }
    balanced.as_object_mut().unwrap().remove("balance");
    balanced
}

/// A four-bar's crank and rocker counterweights balance its shaking force
/// fully: the linkage carrying them, solved again, shakes its frame with
/// nothing (rounding of the unbalanced 55 N), as the result's own
/// `balanced_force` says; and with the coupler's centre of mass midway
/// they are the two-point equivalent's: m·r opposite each pin, crank
/// 1 kg × 0.05 m + 2 kg/2 × 0.1 m = 0.15 kg·m, rocker 1.5 × 0.125 + 1 × 0.25 = 0.4375 kg·m.
#[tokio::test]
async fn a_four_bars_counterweights_leave_no_shaking_force() {
    let app = TestApp::new().await;
    let mut request = four_bar();
    request["balance"] = json!({"counterweights": ["rocker", "crank"]});
    let result = app.result("/v1/kinetostatics", &request).await;
    let weights = result["counterweights"].as_array().unwrap();
    assert_eq!((weights[0]["body"].as_str(), weights[1]["body"].as_str()), (Some("rocker"), Some("crank")));
    close(&weights[1]["mass_radius"], 0.15, 1e-12, "the crank's m·r");
    close(&weights[0]["mass_radius"], 0.4375, 1e-12, "the rocker's m·r");
    for w in weights {
        close(&w["angle"], std::f64::consts::PI, 1e-12, "opposite the pin");
    }
    let before = result["summary"]["max_shaking_force"].as_f64().unwrap();
    assert!(before > 10.0, "{}", result["summary"]);
    close(&result["summary"]["max_shaking_force_balanced"], 0.0, 1e-12 * before, "F once balanced, said");
    let ground = [("crank", "O2", "A"), ("rocker", "O4", "B")];
    let balanced = app.result("/v1/kinetostatics", &carrying(&request, &result, 0.08, &ground)).await;
    close(&balanced["summary"]["max_shaking_force"], 0.0, 1e-9 * before, "F of the linkage carrying them");
    let moment = balanced["summary"]["max_shaking_moment"].as_f64().unwrap();
    assert!(moment > 0.0, "a balanced force leaves the moment: {}", balanced["summary"]);
}

/// A slider-crank balanced with the rotating masses and half the
/// reciprocating one: the linkage carrying its counterweight shakes its
/// frame with F = −m_rec·a_B + f·m_rec·a_A (m_rec = the piston and 0.3 of
/// the rod, whose centre of mass is on its line 0.3 of the way to B), from
/// the same job's pins' accelerations; the result's `balanced_force` and
/// the carrying linkage's shaking agree with it.
#[tokio::test]
async fn a_slider_cranks_counterweight_leaves_the_fraction_it_does_not_balance() {
    let app = TestApp::new().await;
    let mut request = template_request("offset-slider-crank");
    request["mechanism"]["bodies"][0]["mass"] = json!(2.0); // "2 kg", as a number to add to
    request["outputs"] = json!(["shaking"]);
    request["track"] = json!(["A", "B"]);
    // Half the reciprocating mass, as a Spanish sheet writes it.
    request["balance"] = json!({"counterweights": ["crank"], "reciprocating_fraction": "50 %"});
    let result = app.result("/v1/kinetostatics", &request).await;
    // m₂p₂ + m₃r₂(1 − 0.3) + f·m_rec·r₂ = 2·0.02 + 1.2·0.08·0.7 + 0.5·(0.9 + 0.36)·0.08, opposite A.
    close(&result["counterweights"][0]["mass_radius"], 0.1576, 1e-12, "the crank's m·r");
    let (m_rec, f) = (0.9 + 0.3 * 1.2, 0.5);
    let before = result["summary"]["max_shaking_force"].as_f64().unwrap();
    for s in result["steps"].as_array().unwrap() {
        let a = |k: usize, key: &str| s["points"][k][key].as_f64().unwrap();
        let expected = [-m_rec * a(1, "ax") + f * m_rec * a(0, "ax"), -m_rec * a(1, "ay") + f * m_rec * a(0, "ay")];
        for (k, e) in expected.iter().enumerate() {
            let got = s["shaking"]["balanced_force"][k].as_f64().unwrap();
            assert!((got - e).abs() <= 1e-9 * before, "F once balanced: {got} against {e}");
        }
    }
    let balanced_max = result["summary"]["max_shaking_force_balanced"].as_f64().unwrap();
    assert!(balanced_max < 0.5 * before, "{}", result["summary"]);
    let ground = [("crank", "O", "A")];
    let balanced = app.result("/v1/kinetostatics", &carrying(&request, &result, 0.05, &ground)).await;
    close(&balanced["summary"]["max_shaking_force"], balanced_max, 1e-9, "F of the linkage carrying it");
}

/// What cannot be balanced is said at its field, in the asker's language.
#[tokio::test]
async fn counterweights_refused_are_said_at_their_field() {
    let app = TestApp::new().await;
    let cases = [
        ("offset-slider-crank", json!({"counterweights": ["rod"]}), "/balance/counterweights/0", "no está articulado"),
        ("offset-slider-crank", json!({"counterweights": []}), "/balance/counterweights", "va en su manivela"),
        ("four-bar", json!({"counterweights": ["crank"]}), "/balance/counterweights", "«rocker»"),
        ("four-bar", json!({"counterweights": ["manivela"]}), "/balance/counterweights/0", "«manivela»"),
        ("four-bar", json!({"counterweights": ["crank", "crank"]}), "/balance/counterweights/1", "dos veces"),
        ("scissor-lift", json!({"counterweights": ["DE"]}), "/balance", "ninguno de los dos"),
        (
            "offset-slider-crank",
            json!({"counterweights": ["crank"], "reciprocating_fraction": 1.5}),
            "/balance/reciprocating_fraction",
            "1,5",
        ),
    ];
    for (template, balance, pointer, words) in cases {
        let mut request = template_request(template);
        request["balance"] = balance;
        let r = app
            .send(
                axum::http::Request::post("/v1/kinetostatics")
                    .header("content-type", "application/json")
                    .header("accept-language", "es")
                    .body(request.to_string().into())
                    .unwrap(),
            )
            .await;
        assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
        let errors = r.json()["errors"].clone();
        assert_eq!(errors[0]["pointer"], pointer, "{errors}");
        assert!(errors[0]["message"].as_str().unwrap().contains(words), "{errors}");
    }
}

/// The job draws the shaking force's polar diagram, before and after, and its moment.
#[tokio::test]
async fn a_shaking_job_draws_its_polar_diagram() {
    let app = TestApp::new().await;
    let mut request = four_bar();
    request["balance"] = json!({"counterweights": ["crank", "rocker"]});
    let r = app.post("/v1/kinetostatics", &request).await;
    let id = r.json()["id"].as_str().unwrap().to_string();
    for (plot, words) in [("shaking", "with the counterweights"), ("shaking-moment", "shaking moment")] {
        let svg = app.get(&format!("/v1/jobs/{id}/plots/{plot}.svg")).await;
        assert_eq!(svg.status, StatusCode::OK, "{}", svg.text);
        assert!(svg.text.contains(words), "{plot}: {}", &svg.text[..400.min(svg.text.len())]);
    }
    let csv = app.get(&format!("/v1/jobs/{id}/result.csv")).await;
    assert!(csv.text.lines().next().unwrap().contains("shaking_fx_N,shaking_fy_N,shaking_moment_N_m,balanced_fx_N"));
}
