//! The worked solution of a spatial mechanism (`GET /v1/jobs/{id}/solution`
//! and its page and diagrams): every body alone with its six equations,
//! checked against a closed form and against the planar engine.

use crate::helpers::TestApp;
use crate::spatial_dynamics::four_bar;
use axum::http::StatusCode;
use serde_json::{Value, json};

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// A massless spatial slider-crank (crank r = 0.1 about z, a spherical pair
/// at A, a rod l = 0.35 to a universal pair at B on a slider along x at
/// y = e = 0.05, z = h = 0.08) holding P = 200 N on the slider: by virtual
/// work the crank's driving couple is τ = −P·dx_B/dθ with x_B = r·cos θ +
/// √(l² − (e − r·sin θ)² − h²) (closed form), to 1e-9 N·m; each body's six
/// sums vanish to 1e-9 of the largest force; the joints' reactions on their
/// two bodies are equal and opposite (R23 = −R32), to 1e-12.
#[tokio::test]
async fn a_spatial_slider_crank_balances_body_by_body() {
    let app = TestApp::new().await;
    let (r, l, e, h, p) = (0.1f64, 0.35f64, 0.05f64, 0.08f64, 200.0);
    let root = |t: f64| (l * l - (e - r * t.sin()).powi(2) - h * h).sqrt();
    let x_b = r + root(0.0);
    let rod = [x_b - r, e, h];
    let n = rod.iter().map(|c| c * c).sum::<f64>().sqrt();
    // The universal's second axis: y × rod, normalised.
    let cross = [rod[2] / n, 0.0, -rod[0] / n];
    let c = cross.iter().map(|c| c * c).sum::<f64>().sqrt();
    let body = |name: &str, cg: Value| json!({"name": name, "mass": 0, "cg": cg});
    let mechanism = json!({"space": "spatial",
        "points": {"O": [0, 0, 0], "A": [r, 0, 0], "B": [x_b, e, h]},
        "bodies": [body("crank", json!([r / 2.0, 0, 0])), body("rod", json!([(r + x_b) / 2.0, e / 2.0, h / 2.0])),
                   body("slider", json!("B"))],
        "joints": [
            {"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O", "axis": [0, 0, 1]},
            {"name": "A", "type": "spherical", "bodies": ["crank", "rod"], "at": "A"},
            {"name": "B", "type": "universal", "bodies": ["slider", "rod"], "at": "B",
             "axes": [[0, 1, 0], [cross[0] / c, 0, cross[2] / c]]},
            {"name": "guide", "type": "prismatic", "bodies": ["ground", "slider"], "at": "B", "axis": [1, 0, 0]}]});
    let request = json!({"mechanism": mechanism, "input": {"joint": "O", "speed": "10 rad/s", "steps": 12},
        "loads": [{"type": "force", "body": "slider", "at": "B", "direction": [1, 0, 0], "magnitude": p}]});
    let job = app.post("/v1/kinetostatics", &request).await;
    assert_eq!(job.status, StatusCode::CREATED, "{}", job.text);
    let id = job.json()["id"].as_str().unwrap().to_string();
    for step in [1, 5, 10] {
        let got = app.get(&format!("/v1/jobs/{id}/solution?step={step}")).await;
        assert_eq!(got.status, StatusCode::OK, "{}", got.text);
        let s = got.json();
        let t = number(&s["input"][0]);
        let rate = -r * t.sin() + (e - r * t.sin()) * r * t.cos() / root(t);
        let bodies = s["bodies"].as_array().unwrap();
        let crank = bodies.iter().find(|b| b["body"] == "crank").unwrap();
        let driving = crank["couples"].as_array().unwrap().iter().find(|c| c["name"] == "M_m").unwrap();
        assert!((number(&driving["moment"]) + p * rate).abs() < 1e-9, "τ at θ = {t}: {driving}");
        let forces = |b: &Value| b["forces"].as_array().unwrap().clone();
        let largest =
            bodies.iter().flat_map(forces).map(|f| number(&f["fx"]).hypot(number(&f["fy"])).hypot(number(&f["fz"])));
        let largest = largest.fold(0.0, f64::max);
        for b in bodies {
            for (key, sum) in b["equations"].as_object().unwrap() {
                assert!(number(sum).abs() < 1e-9 * largest, "{} {key} = {sum} at θ = {t}", b["body"]);
            }
        }
        let named = |name: &str| bodies.iter().flat_map(forces).find(|f| f["name"] == name).unwrap();
        for (a, b) in [("R23", "R32"), ("R34", "R43")] {
            for k in ["fx", "fy", "fz"] {
                assert!((number(&named(a)[k]) + number(&named(b)[k])).abs() < 1e-12, "{a} against {b} ({k})");
            }
        }
        assert!(number(&s["virtual_power"]["total"]).abs() < 1e-9 * p, "{}", s["virtual_power"]);
    }
    // Each body's diagram and the page in Spanish, with the six equations.
    let svg = app.get(&format!("/v1/jobs/{id}/plots/free-body-rod.svg?step=5")).await;
    assert_eq!(svg.status, StatusCode::OK, "{}", svg.text);
    assert!(svg.text.contains("isometric view, z up") || svg.text.contains("isometric view, y up"), "{}", svg.text);
    let page = app.get(&format!("/jobs/{id}/solution?step=5&lang=es")).await;
    assert_eq!(page.status, StatusCode::OK);
    assert!(page.text.contains("ΣF_z") && page.text.contains("ΣM_G3ᵧ"), "the page's equations");
}

/// The four-bar of `spatial_dynamics` falling for 0.5 s, run by the planar
/// engine and posed in space: at each sample the worked solution's in-plane
/// forces on every body (its reactions, inertia forces and weights) are
/// the plane's to 1e-6 N and its couples about z to 1e-6 N·m, though the
/// space's are found again from the stored motion; the spatial sums are
/// the run's d'Alembert check, nothing to 1e-6.
#[tokio::test]
async fn a_planar_run_in_space_has_the_plane_free_bodies() {
    let app = TestApp::new().await;
    let run = |spatial: bool| {
        json!({"machine": {"mechanism": four_bar(spatial), "input": {"joint": "O2"}},
               "duration": "0.5 s", "samples": 6, "tolerance": 1e-10})
    };
    let mut ids = Vec::new();
    for spatial in [false, true] {
        let r = app.post("/v1/dynamics", &run(spatial)).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        ids.push(r.json()["id"].as_str().unwrap().to_string());
    }
    for step in [0, 3, 5] {
        let [plane, space] = [0, 1].map(|k| format!("/v1/jobs/{}/solution?step={step}", ids[k]));
        let (plane, space) = (app.get(&plane).await.json(), app.get(&space).await.json());
        for (a, b) in plane["bodies"].as_array().unwrap().iter().zip(space["bodies"].as_array().unwrap()) {
            assert_eq!(a["body"], b["body"]);
            for f in a["forces"].as_array().unwrap() {
                let g = b["forces"].as_array().unwrap().iter().find(|g| g["name"] == f["name"]);
                let g = g.unwrap_or_else(|| panic!("{} on {} not in space", f["name"], a["body"]));
                for k in ["fx", "fy"] {
                    assert!(
                        (number(&f[k]) - number(&g[k])).abs() < 1e-6,
                        "{} {k} on {}: {f} {g}",
                        f["name"],
                        a["body"]
                    );
                }
            }
            for c in a["couples"].as_array().unwrap() {
                let sum: f64 = b["couples"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .filter(|d| d["name"] == c["name"])
                    .map(|d| number(&d["moment"]))
                    .sum();
                assert!((number(&c["moment"]) - sum).abs() < 1e-6, "{} on {}", c["name"], a["body"]);
            }
            for (key, sum) in b["equations"].as_object().unwrap() {
                assert!(number(sum).abs() < 1e-6, "{} {key} = {sum}", b["body"]);
            }
        }
    }
}
