//! Each built-in template agrees with its seed: its default answer is the
//! seed's printed one (or its reference case's) with the statement's
//! directions, and a changed parameter changes the answer as the seed's
//! formula says, read as a sheet reads it (`/v1/templates/{id}/result/…`).
//! P.103 is also checked against case F1 in templates.rs, K1 and D1 in
//! cases.rs, the rotor of seed 003 in rotor.rs.

use crate::helpers::{TestApp, case};
use axum::http::StatusCode;

const G: f64 = 9.81;

/// The number at `pointer` of the template's result, with `query`.
pub async fn part(app: &TestApp, id: &str, pointer: &str, query: &str) -> f64 {
    let path = format!("/v1/templates/{id}/result{pointer}?{query}");
    let r = app.get(&path).await;
    assert_eq!(r.status, StatusCode::OK, "{path}: {}", r.text);
    r.text.parse().unwrap_or_else(|_| panic!("{path}: {}", r.text))
}

#[track_caller]
pub fn near(got: f64, expected: f64, tol: f64, what: &str) {
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

/// Seed 002's scissor lift, the inertia forces its statement asks for: each
/// bar's centre F accelerates at a_F = 2√3v²/(9L) to the left and the bars
/// turn at α = √3v²/(9L²), DE one way and BC the other; so −m·a_G =
/// (2√3mv²/(9L), 0) on each bar, −I_G·α = ∓(√3/27)mv² (I_G = m(2L)²/12),
/// and nothing on the platform descending at constant v (1e-9).
#[tokio::test]
async fn the_scissor_lift_has_the_seeds_inertia_forces() {
    let app = TestApp::new().await;
    let (m, l, v) = (10.0, 0.5, 0.3);
    let force = 2.0 * 3f64.sqrt() * m * v * v / (9.0 * l);
    let moment = 3f64.sqrt() / 27.0 * m * v * v;
    let at = |body: usize, field: &str| format!("/steps/0/kinematics/{body}/{field}");
    for (body, fx, couple) in [(0, force, -moment), (1, force, moment)] {
        near(part(&app, "scissor-lift", &at(body, "inertia_force/0"), "").await, fx, 1e-9, "a bar's force");
        let fy = part(&app, "scissor-lift", &at(body, "inertia_force/1"), "").await;
        assert!(fy.abs() < 1e-9 * force, "a bar's vertical force {fy}");
        near(part(&app, "scissor-lift", &at(body, "inertia_moment"), "").await, couple, 1e-9, "a bar's moment");
    }
    let platform = part(&app, "scissor-lift", &at(2, "inertia_force/1"), "").await;
    assert!(platform.abs() < 1e-9 * force, "the platform at constant speed: {platform}");
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

/// The library's four-bar (crank 0.1 m, coupler 0.3 m, rocker 0.25 m,
/// frame 0.3 m, each centre of mass at its bar's middle; a resisting
/// torque M on the rocker; gravity) against the power balance written by
/// hand over closed-form kinematics (the loop equations solved for ω₃, ω₄
/// and α₃, α₄): T·ω₂ − M·ω₄ − Σ m g v_Gy = Σ (m a_G·v_G + I_G α ω) at four
/// crank angles, at the defaults (M = 20 N·m, 100 rpm) and at M = 50 N·m,
/// 60 rpm (1e-9 of the largest term).
#[tokio::test]
async fn the_four_bar_balances_its_power() {
    let app = TestApp::new().await;
    for (query, m_load, rpm) in [("", 20.0, 100.0), ("M=50&speed=60", 50.0, 60.0)] {
        for step in [0, 3, 13, 27] {
            let (theta2, omega2) = (step as f64 * 10f64.to_radians(), rpm * std::f64::consts::TAU / 60.0);
            let (torque, scale) = four_bar_torque(theta2, omega2, m_load);
            let got = part(&app, "four-bar", &format!("/steps/{step}/driving"), query).await;
            let what = format!("{query}: θ₂ = {}°", step * 10);
            assert!((got - torque).abs() <= 1e-9 * scale, "{what}: {got} against {torque}");
        }
    }
}

/// The driving torque of the library's four-bar at crank angle θ₂ turning
/// at ω₂ (constant) against M on the rocker, by the power balance; and the
/// largest term of the balance, for the tolerance.
fn four_bar_torque(theta2: f64, omega2: f64, m_load: f64) -> (f64, f64) {
    type V = (f64, f64);
    let (a, b, c, d) = (0.1, 0.3, 0.25, 0.3);
    let e = |t: f64| (t.cos(), t.sin());
    let perp = |v: V| (-v.1, v.0);
    let sum = |p: V, q: V| (p.0 + q.0, p.1 + q.1);
    let times = |k: f64, v: V| (k * v.0, k * v.1);
    let dot = |p: V, q: V| p.0 * q.0 + p.1 * q.1;
    // Positions: B on the circles about A (b) and O₄ (c), above the line A–O₄.
    let r_a = times(a, e(theta2));
    let to_o4 = (d - r_a.0, -r_a.1);
    let l = dot(to_o4, to_o4).sqrt();
    let u = times(1.0 / l, to_o4);
    let along = (b * b - c * c + l * l) / (2.0 * l);
    let r_b = sum(r_a, sum(times(along, u), times((b * b - along * along).sqrt(), perp(u))));
    let (theta3, theta4) = ((r_b.1 - r_a.1).atan2(r_b.0 - r_a.0), r_b.1.atan2(r_b.0 - d));
    let (e2, e3, e4) = (e(theta2), e(theta3), e(theta4));
    // Loop: a e₂ + b e₃ = d + c e₄, differentiated once and twice; Cramer's rule on (x₃, x₄) with
    // b x₃ ⊥e₃ − c x₄ ⊥e₄ = rhs.
    let solve = |rhs: V| {
        let (p, q) = (times(b, perp(e3)), times(-c, perp(e4)));
        let det = p.0 * q.1 - p.1 * q.0;
        ((rhs.0 * q.1 - rhs.1 * q.0) / det, (p.0 * rhs.1 - p.1 * rhs.0) / det)
    };
    let (w3, w4) = solve(times(-a * omega2, perp(e2)));
    let centripetal = sum(sum(times(a * omega2 * omega2, e2), times(b * w3 * w3, e3)), times(-c * w4 * w4, e4));
    let (al3, al4) = solve(centripetal);
    // Each centre of mass at its bar's middle: (mass, I_G, v_G, a_G, ω, α).
    let (v_a, a_a) = (times(a * omega2, perp(e2)), times(-a * omega2 * omega2, e2));
    let tip = |l: f64, w: f64, al: f64, e: V| sum(times(l * al, perp(e)), times(-l * w * w, e));
    let bodies = [
        (1.0, 0.002, times(0.5, v_a), times(0.5, a_a), omega2, 0.0),
        (2.0, 0.015, sum(v_a, times(b / 2.0 * w3, perp(e3))), sum(a_a, tip(b / 2.0, w3, al3, e3)), w3, al3),
        (1.5, 0.008, times(c / 2.0 * w4, perp(e4)), tip(c / 2.0, w4, al4, e4), w4, al4),
    ];
    let terms: Vec<f64> = bodies
        .iter()
        .flat_map(|&(m, i, v, acc, w, al)| [m * dot(acc, v), i * al * w, m * G * v.1])
        .chain([m_load * w4])
        .collect();
    let torque = terms.iter().sum::<f64>() / omega2;
    (torque, terms.iter().fold(0.0f64, |s, t| s.max(t.abs())) / omega2)
}

/// P.103, alone and for a class, at its defaults and at F = 700 N·m, ε = 0.05: the
/// approximate inertia ΔE/(ε ω²) with the energy's swing over the cycle in
/// closed form — the motor's mean torque F/π against −F sin φ on [0, π]
/// swings by ΔE = F(2 cos s − 1 + 2s/π), s = asin(1/π) between its
/// extremes at φ = s and π − s — 348.99 kg·m² at the defaults (1e-6).
#[tokio::test]
async fn p103_for_a_class_has_the_closed_form_swing() {
    let app = TestApp::new().await;
    let s = (1.0 / std::f64::consts::PI).asin();
    let swing = 2.0 * s.cos() - 1.0 + 2.0 * s / std::f64::consts::PI;
    for id in ["p103-class", "p103-slider-flywheel"] {
        for (query, f, eps, rpm) in [("", 500.0, 0.04, 60.0), ("F=700&eps=0.05", 700.0, 0.05, 60.0)] {
            let omega = rpm * std::f64::consts::TAU / 60.0;
            let expected = f * swing / (eps * omega * omega);
            near(part(&app, id, "/inertia_approximate", query).await, expected, 1e-6, &format!("{id}: {query}"));
        }
    }
}
