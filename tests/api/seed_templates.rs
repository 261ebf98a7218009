//! Each built-in template agrees with its seed: its default answer is the
//! seed's printed one (or its reference case's) with the statement's
//! directions, and a changed parameter changes the answer as the seed's
//! formula says, read as a sheet reads it (`/v1/templates/{id}/result/…`).
//! P.103 is checked against case F1 in templates.rs, K1 and D1 in
//! cases.rs, the rotor of seed 003 in rotor.rs.

use crate::helpers::{TestApp, case};
use axum::http::StatusCode;

const G: f64 = 9.81;

/// The number at `pointer` of the template's result, with `query`.
async fn part(app: &TestApp, id: &str, pointer: &str, query: &str) -> f64 {
    let path = format!("/v1/templates/{id}/result{pointer}?{query}");
    let r = app.get(&path).await;
    assert_eq!(r.status, StatusCode::OK, "{path}: {}", r.text);
    r.text.parse().unwrap_or_else(|_| panic!("{path}: {}", r.text))
}

#[track_caller]
fn near(got: f64, expected: f64, tol: f64, what: &str) {
    assert!((got - expected).abs() <= tol * expected.abs().max(1e-12), "{what}: {got} against {expected}");
}

/// Seed 002, question 5: T = ½mv² + ⅔mω²L² − (√3/2)mvωL (2L = 1 m, v = 1
/// m/s, ω = 2 rad/s): 0.30064 J at m = 1 kg, 0.6013 J at m = 2 kg — the
/// bar's I_G = m(2L)²/12 follows its mass (1e-12).
#[tokio::test]
async fn the_bar_on_a_slider_has_the_seeds_kinetic_energy() {
    let app = TestApp::new().await;
    let t = |m: f64, v: f64, w: f64| {
        let l = 0.5;
        0.5 * m * v * v + 2.0 / 3.0 * m * w * w * l * l - 3f64.sqrt() / 2.0 * m * v * w * l
    };
    let pointer = "/steps/0/energy/kinetic/total";
    near(part(&app, "bar-on-slider", pointer, "").await, t(1.0, 1.0, 2.0), 1e-12, "m = 1");
    near(part(&app, "bar-on-slider", pointer, "m=2").await, t(2.0, 1.0, 2.0), 1e-12, "m = 2");
    near(part(&app, "bar-on-slider", pointer, "m=2&v=0.5&omega=3").await, t(2.0, 0.5, 3.0), 1e-12, "m = 2, v, ω");
}

/// Seed 002, question 4, with the figure's sense of v (to the right at the
/// top of the rim): v_P = (v − ωR, ωR/2), a_P = (−ω²R/2, 2ωv − ω²R − v²/R),
/// R = 0.1 m, ω = 2 rad/s, v = 0.5 m/s and then 1 m/s (1e-12).
#[tokio::test]
async fn the_ring_on_the_rim_has_the_seeds_velocity_and_acceleration() {
    let app = TestApp::new().await;
    let (r, w) = (0.1, 2.0);
    for (query, v) in [("", 0.5), ("v=1", 1.0)] {
        let expected = [v - w * r, w * r / 2.0, -w * w * r / 2.0, 2.0 * w * v - w * w * r - v * v / r];
        for (key, e) in ["vx", "vy", "ax", "ay"].into_iter().zip(expected) {
            let got = part(&app, "ring-on-rim", &format!("/steps/0/points/0/{key}"), query).await;
            near(got, e, 1e-12, &format!("v = {v}: {key}"));
        }
    }
}

/// Seed 002's scissor lift: the piston's force F_AB = −√3(10mg +
/// 8mv²/(27L)), m = 10 kg, L = 0.5 m: −1700.07 N at v = 0.3 m/s (printed),
/// and at v = 1 m/s (1e-9).
#[tokio::test]
async fn the_scissor_lift_has_the_seeds_piston_force() {
    let app = TestApp::new().await;
    let f = |v: f64| -(3f64.sqrt()) * (10.0 * 10.0 * G + 8.0 * 10.0 * v * v / (27.0 * 0.5));
    near(part(&app, "scissor-lift", "/steps/0/driving", "").await, f(0.3), 1e-9, "v = 0.3");
    assert!((f(0.3) + 1700.07).abs() < 0.005, "the printed −1700.07 N");
    near(part(&app, "scissor-lift", "/steps/0/driving", "v=1").await, f(1.0), 1e-9, "v = 1");
}

/// Seed 002, question 2's eccentric disk (e = 20 mm, R = 50 mm, ω = 10
/// rad/s, μ = 0.1, the follower's m = 2 kg): N = m(g + eω² cos θ), torque
/// N(e sin θ + μ(R − e cos θ)) at θ = 10°, 90° and 200°; and with m = 3 kg (1e-9).
#[tokio::test]
async fn the_cam_with_a_flat_follower_has_its_closed_form() {
    let app = TestApp::new().await;
    let (e, r, w, mu) = (0.02, 0.05, 10.0, 0.1);
    for (query, m) in [("", 2.0), ("m=3", 3.0)] {
        for step in [1, 9, 20] {
            let theta = (10.0 * step as f64).to_radians();
            let n = m * (G + e * w * w * theta.cos());
            let torque = n * (e * theta.sin() + mu * (r - e * theta.cos()));
            let got = part(&app, "cam-flat-follower", &format!("/steps/{step}/contacts/0/normal"), query).await;
            near(got, n, 1e-9, &format!("m = {m}, θ = {theta}: N"));
            let got = part(&app, "cam-flat-follower", &format!("/steps/{step}/driving"), query).await;
            near(got, torque, 1e-9, &format!("m = {m}, θ = {theta}: torque"));
        }
    }
}

/// The rolling disk (seed 000, rodadura): a = g sin α/(1 + I_G/(mR²)), α =
/// 30°, m = 2 kg, R = 0.1 m; its speed after 1 s is a·1 s, with I_G = 0.01
/// (a = ⅔ g sin α) and 0.02 kg·m² (a = ½ g sin α) (1e-8).
#[tokio::test]
async fn the_rolling_disk_has_the_seeds_acceleration() {
    let app = TestApp::new().await;
    let a = |i: f64| G * 0.5 / (1.0 + i / (2.0 * 0.01));
    near(part(&app, "rolling-disk", "/end/speed", "").await, a(0.01), 1e-8, "I_G = 0.01");
    near(part(&app, "rolling-disk", "/end/speed", "I=0.02").await, a(0.02), 1e-8, "I_G = 0.02");
}

/// The course's cam design: a cycloidal rise h over β = 90° at 300 rpm
/// peaks at 2hω/β (velocity) and 2πhω²/β² (acceleration) — the textbook's
/// peaks — at h = 20 mm and 30 mm (1e-9).
#[tokio::test]
async fn the_cam_design_has_the_textbooks_peaks() {
    let app = TestApp::new().await;
    let (beta, w) = (std::f64::consts::FRAC_PI_2, 10.0 * std::f64::consts::PI);
    for (query, h) in [("", 0.02), ("h=30", 0.03)] {
        let v = part(&app, "cam-design", "/segments/1/peak_velocity", query).await;
        near(v, 2.0 * h * w / beta, 1e-9, &format!("h = {h}: velocity"));
        let a = part(&app, "cam-design", "/segments/1/peak_acceleration", query).await;
        near(a, std::f64::consts::TAU * h * w * w / (beta * beta), 1e-9, &format!("h = {h}: acceleration"));
    }
}

/// P.107 (case F2): I = 13 355.6 kg·m² at ε = the template's; the
/// approximate inertia ΔE/(εω²) at half that ε is twice it (1e-9).
#[tokio::test]
async fn the_two_stroke_engine_has_case_f2s_inertia() {
    let app = TestApp::new().await;
    let trusted = case("F2_p107_two_stroke_engine")["expected"]["I_approx_kg_m2"].as_f64().unwrap();
    let at = part(&app, "p107-two-stroke-engine", "/inertia_approximate", "").await;
    near(at, trusted, 1e-9, "the default");
    let template = app.get("/v1/templates/p107-two-stroke-engine").await.json();
    let eps = template["request"]["irregularity"].as_f64().unwrap();
    let half = part(&app, "p107-two-stroke-engine", "/inertia_approximate", &format!("eps={}", eps / 2.0)).await;
    near(half, 2.0 * trusted, 1e-9, "half the irregularity");
}

/// Seed 004's punch press (case F9, the textbook's reading): I = 27.4746
/// kg·m²; the energy to store is W(1 − θ/360°), so I follows W (1e-9).
#[tokio::test]
async fn the_punch_press_has_case_f9s_inertia() {
    let app = TestApp::new().await;
    let c = case("F9_punch_press_us_units");
    let trusted = c["expected"]["textbook_interpretation"]["I_kg_m2"].as_f64().unwrap();
    near(part(&app, "punch-press-us", "/inertia_approximate", "").await, trusted, 1e-9, "the default");
    let w = c["problem"]["energy_per_revolution_ft_lbf"].as_f64().unwrap();
    let doubled = part(&app, "punch-press-us", "/inertia_approximate", &format!("W={}", 2.0 * w)).await;
    near(doubled, 2.0 * trusted, 1e-9, "twice the work");
}
