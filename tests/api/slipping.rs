//! Rolling contacts with friction in direct dynamics: they roll while
//! |tangential| ≤ μ·normal and slip with kinetic friction otherwise, an
//! event at each change; a contact whose normal force reaches 0 stops the
//! run with a warning. Every number against the closed form of a uniform
//! disk (m = 2 kg, r = 0.1 m, I = ½mr², g = 9.81) on a straight track.

use crate::helpers::{TestApp, template_request};
use axum::http::StatusCode;
use serde_json::{Value, json};

const M: f64 = 2.0;
const R: f64 = 0.1;
const G: f64 = 9.81;

/// |actual − expected| ≤ tol.
#[track_caller]
fn near(actual: &Value, expected: f64, tol: f64, what: &str) {
    let a = actual.as_f64().unwrap_or_else(|| panic!("{what}: {actual} is not a number"));
    assert!((a - expected).abs() <= tol, "{what}: {a} vs {expected} (±{tol})");
}

async fn dynamics(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/dynamics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()["result"].clone()
}

/// The disk on a level track (gravity −y), friction μ, pushed at its
/// centre along +x (`push`) and up (`lift`), both Functions of t.
fn disk(mu: f64, push: &str, lift: &str, duration: f64) -> Value {
    let mut body = template_request("rolling-disk");
    let mechanism = &mut body["machine"]["mechanism"];
    mechanism["gravity"] = json!([0, -G]);
    mechanism["joints"][0]["friction"] = json!({"mu": mu});
    body["machine"]["loads"] = json!([
        {"type": "force", "body": "disk", "at": "C", "direction": [1, 0], "magnitude": {"expr": push}},
        {"type": "force", "body": "disk", "at": "C", "direction": [0, 1], "magnitude": {"expr": lift}}
    ]);
    body["duration"] = json!(duration);
    body["samples"] = json!(41);
    body
}

fn events(result: &Value) -> Vec<(String, f64)> {
    let list = result["events"].as_array().unwrap();
    list.iter().map(|e| (e["kind"].as_str().unwrap().to_string(), e["t"].as_f64().unwrap())).collect()
}

/// Down an incline of 30° (the template): with μ = 0.3 ≥ tan α/3 it rolls,
/// a = ⅔ g sin α, and no event; with μ = 0.1 below it, it slips from the
/// start: a = g(sin α − μ cos α), the disk spins up at 2μg cos α/r, the
/// friction is μN with N = m g cos α, the sliding velocity grows at
/// a − r·2μg cos α (1e-8); the energy balance holds with the friction's
/// work in it (1e-8). A slip is modelled, so it is no event at the start,
/// but it is said: a warning with its interval, `state` at every sample.
#[tokio::test]
async fn a_disk_slips_down_an_incline_below_the_least_friction_that_rolls_it() {
    let app = TestApp::new().await;
    let alpha = 30f64.to_radians();
    let (sin, cos) = alpha.sin_cos();
    for (mu, a, spin) in [(0.3, 2.0 / 3.0 * G * sin, None), (0.1, G * (sin - 0.1 * cos), Some(2.0 * 0.1 * G * cos / R))]
    {
        let mut body = template_request("rolling-disk");
        body["machine"]["mechanism"]["joints"][0]["friction"] = json!({"mu": mu});
        let result = dynamics(&app, &body).await;
        assert!(result["energy_residual"].as_f64().unwrap().abs() < 1e-8, "{}", result["energy_residual"]);
        assert_eq!(events(&result).iter().filter(|e| e.0 != "end").count(), 0, "{:?}", events(&result));
        let warnings: Vec<&str> = result["warnings"].as_array().unwrap().iter().map(|w| w.as_str().unwrap()).collect();
        match spin {
            Some(_) => assert_eq!(warnings.len(), 1, "{warnings:?}"),
            None => assert!(warnings.is_empty(), "{warnings:?}"),
        }
        assert!(warnings.iter().all(|w| w.contains("contact K slips from t = 0 s to t = 1 s")), "{warnings:?}");
        let state = if spin.is_some() { "slipping" } else { "rolling" };
        assert!(result["machine"]["samples"].as_array().unwrap().iter().all(|s| s["contacts"][0]["state"] == state));
        for sample in result["machine"]["samples"].as_array().unwrap() {
            let t = sample["t"].as_f64().unwrap();
            near(&sample["inputs"][0]["angle"], 0.5 * a * t * t, 1e-8, &format!("μ {mu}: s at {t}"));
            near(&sample["inputs"][0]["acceleration"], a, 1e-8, &format!("μ {mu}: a at {t}"));
            let contact = &sample["contacts"][0];
            near(&contact["normal"], M * G * cos, 1e-8, "N = m g cos α");
            if let Some(spin) = spin {
                near(&json!(contact["tangential"].as_f64().unwrap().abs()), mu * M * G * cos, 1e-8, "μN");
                near(&json!(contact["sliding_velocity"].as_f64().unwrap().abs()), (a - spin * R) * t, 1e-8, "v_s");
            } else {
                near(&contact["sliding_velocity"], 0.0, 1e-9, "rolling does not slide");
            }
        }
    }
}

/// Pushed at its centre by F = k t (k = 20 N/s, μ = 0.2) the disk rolls
/// while the friction it needs, F/3, is at most μmg: s = k t³/(9m); it
/// starts to slip at t* = 3μmg/k (an event "slip" at the contact, 1e-8 s),
/// then a = (kt − μmg)/m (1e-7).
#[tokio::test]
async fn a_disk_pushed_ever_harder_slips_when_rolling_needs_more_than_mu_n() {
    let app = TestApp::new().await;
    let (k, mu) = (20.0, 0.2);
    let t_slip = 3.0 * mu * M * G / k;
    let result = dynamics(&app, &disk(mu, &format!("{k}*t"), "0", 1.0)).await;
    let list = events(&result);
    assert_eq!(list.iter().map(|e| e.0.as_str()).collect::<Vec<_>>(), ["slip", "end"], "{list:?}");
    near(&json!(list[0].1), t_slip, 1e-8, "t* = 3μmg/k");
    assert_eq!(result["events"][0]["joint"], "K");
    for sample in result["machine"]["samples"].as_array().unwrap() {
        let t = sample["t"].as_f64().unwrap();
        let expected = if t < t_slip { 2.0 / 3.0 * k * t / M } else { (k * t - mu * M * G) / M };
        near(&sample["inputs"][0]["acceleration"], expected, 1e-7, &format!("a at {t}"));
        if t < t_slip {
            near(&sample["inputs"][0]["angle"], k * t.powi(3) / (9.0 * M), 1e-9, &format!("s at {t}"));
        }
    }
}

/// Pushed by F₀ = 40 N until T = 0.3 s (μ = 0.2), the disk slips from the
/// start (F₀/3 > μmg): v = (F₀/m − μg)t, rω = 2μg t. Left alone after T,
/// friction slows the slip v − rω at 3μg until it rolls again at t_r (an
/// event "roll", 1e-7 s), then at v_r = v(T) − μg(t_r − T) for ever
/// (the moment of momentum about the contact kept: v_r = (v(T) + ½rω(T))·⅔).
#[tokio::test]
async fn a_slipping_disk_left_alone_rolls_again_when_its_slip_stops() {
    let app = TestApp::new().await;
    let (f0, mu, end) = (40.0, 0.2, 0.3);
    let (v_end, spin_end) = ((f0 / M - mu * G) * end, 2.0 * mu * G * end);
    let t_roll = end + (v_end - spin_end) / (3.0 * mu * G);
    let v_roll = v_end - mu * G * (t_roll - end);
    assert!((v_roll - (v_end + 0.5 * spin_end) * 2.0 / 3.0).abs() < 1e-12, "the two closed forms agree");
    let push = format!("{f0}*(1 - sign(t - {end}))/2");
    let result = dynamics(&app, &disk(mu, &push, "0", 1.5)).await;
    let list = events(&result);
    assert_eq!(list.iter().map(|e| e.0.as_str()).collect::<Vec<_>>(), ["roll", "end"], "{list:?}");
    near(&json!(list[0].1), t_roll, 1e-7, "t_r");
    for sample in result["machine"]["samples"].as_array().unwrap() {
        let t = sample["t"].as_f64().unwrap();
        if t > t_roll + 1e-3 {
            near(&sample["inputs"][0]["speed"], v_roll, 1e-7, &format!("v at {t}"));
            near(&sample["contacts"][0]["sliding_velocity"], 0.0, 1e-7, &format!("rolls at {t}"));
        } else if t < end - 1e-3 {
            near(&sample["inputs"][0]["speed"], v_end / end * t, 1e-7, &format!("v at {t}"));
        }
    }
}

/// Lifted at its centre by F = k t (k = 10 N/s) the disk presses on its
/// track with N = mg − kt. Pushed along by 1 N it rolls while μN covers
/// the 1/3 N rolling needs, and slips from t = (mg − 1/(3μ))/k (μ = 0.5);
/// the run stops where N reaches 0, at t = mg/k (1e-8 s), with a
/// `separation` event and a warning naming the contact. Not pushed, it
/// rolls until then.
#[tokio::test]
async fn a_contact_whose_normal_force_reaches_zero_stops_the_run() {
    let app = TestApp::new().await;
    let (k, mu) = (10.0, 0.5);
    let t_open = M * G / k;
    for push in [1.0, 0.0] {
        let result = dynamics(&app, &disk(mu, &push.to_string(), &format!("{k}*t"), 5.0)).await;
        let list = events(&result);
        let kinds: Vec<&str> = list.iter().map(|e| e.0.as_str()).collect();
        if push > 0.0 {
            assert_eq!(kinds, ["slip", "separation", "end"], "{list:?}");
            near(&json!(list[0].1), (M * G - push / (3.0 * mu)) / k, 1e-8, "μN = F/3");
        } else {
            assert_eq!(kinds, ["separation", "end"], "{list:?}");
        }
        near(&json!(list[list.len() - 1].1), t_open, 1e-8, "t = mg/k");
        let warnings = result["warnings"].to_string();
        assert!(warnings.contains("'K' opens") && warnings.contains("normal force"), "{warnings}");
    }
}

/// Friction at a contact that slides is refused in dynamics, at its field.
#[tokio::test]
async fn friction_at_a_sliding_contact_is_refused_in_dynamics() {
    let app = TestApp::new().await;
    let mut body = disk(0.2, "1", "0", 1.0);
    body["machine"]["mechanism"]["joints"][0]["rolling"] = json!(false);
    let pointers = app.pointers("/v1/dynamics", &body).await;
    assert!(pointers.contains(&"/machine/mechanism/joints/0/friction".to_string()), "{pointers:?}");
}
