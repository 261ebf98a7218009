//! The rest of the course's problem book as built-in templates (issue 51):
//! P.113, seed 002's mobility, tooth thickness and differential train, seed
//! 003's disk at any angle and accelerating, seed 004's double pendulum.
//! Each default answer is checked against a closed form written here from
//! the statement, with the seed's printed value beside it; where the print
//! is wrong the test says why. Numbers are read as a sheet reads them.

use crate::helpers::TestApp;
use crate::seed_templates::{near, part};
use std::f64::consts::PI;

/// P.113: M* = −FR cos φ on (0, π/2) and (3π/2, 2π), FR = 1000 N·m; the motor
/// C_m = FR/π (printed 318.3099); crossings at cos φ = 1/π (printed
/// 1.24685); A₁ = FR sin φ₁ − C_m φ₁ (printed 551.102, the seed's sign the
/// opposite), ΔE = 2A₁; I = ΔE/(ε ω²) at 500 rpm, ε = 0.01 (printed 40.204),
/// the flywheel I − 1 kg·m² of the pulley (printed 39.204). 1e-9.
#[tokio::test]
async fn p113_has_the_printed_flywheel() {
    let app = TestApp::new().await;
    let id = "p113-pulley-flywheel";
    let (fr, omega) = (1000.0, 500.0 * PI / 30.0);
    let cm = fr / PI;
    let phi1 = (1.0 / PI).acos();
    let de = 2.0 * (fr * phi1.sin() - cm * phi1);
    near(part(&app, id, "/balance_torque", "").await, cm, 1e-12, "C_m (printed 318,3099)");
    near(part(&app, id, "/mean_power", "").await, cm * omega, 1e-12, "P (printed 16666,667 W)");
    near(part(&app, id, "/crossings/0", "").await, phi1, 1e-9, "φ₁ (printed 1.24685)");
    near(part(&app, id, "/energy_fluctuation", "").await, de, 1e-9, "ΔE (printed 2 × 551,102)");
    let i = de / (0.01 * omega * omega);
    near(part(&app, id, "/inertia_exact", "").await, i, 1e-9, "I (printed 40,204)");
    near(part(&app, id, "/flywheel_inertia/exact", "").await, i - 1.0, 1e-9, "I_V (printed 39'204)");
    // ΔE ∝ F and the crossings stay: twice the force, twice I.
    near(part(&app, id, "/inertia_exact", "F=10000").await, 2.0 * i, 1e-9, "I at F = 10 kN");
}

/// Seed 002, question 1: Grübler's G = 3(n − 1) − 2P_I − P_II = 3·4 − 10 − 1
/// = 1 (printed 1); one more lower pair locks it: −1.
#[tokio::test]
async fn the_grubler_count_is_the_seeds() {
    let app = TestApp::new().await;
    assert_eq!(part(&app, "grubler-count", "/grubler/mobility", "").await, 1.0, "printed G = 1");
    assert_eq!(part(&app, "grubler-count", "/grubler/mobility", "p1=6").await, -1.0);
}

/// Seed 002, question 3: m = 4 mm, z = 30, φ_A = 20°: R_A = 60 mm, R_T =
/// 64 mm, cos φ_T = R_A cos φ_A / R_T, e_T = R_T[e_A/R_A + 2(inv φ_A − inv
/// φ_T)] with e_A = πm/2. Printed φ_T = 28'24'' and e_T = 2'95 mm, the
/// apostrophe a decimal comma (28.2414°, 2.9496 mm; read as 28° 24′ it
/// would not give 2.95).
#[tokio::test]
async fn the_tooth_thickness_is_the_seeds() {
    let app = TestApp::new().await;
    let inv = |a: f64| a.tan() - a;
    let (ra, rt, pa) = (0.060, 0.064, 20f64.to_radians());
    let pt = (ra * pa.cos() / rt).acos();
    let et = rt * (PI * 0.004 / 2.0 / ra + 2.0 * (inv(pa) - inv(pt)));
    let id = "tooth-thickness";
    near(part(&app, id, "/thickness_pressure_angle", "unit=deg").await, pt.to_degrees(), 1e-9, "φ_T (28,24°)");
    near(part(&app, id, "/thickness", "unit=mm").await, et * 1e3, 1e-9, "e_T (printed 2,95 mm)");
    assert!((et * 1e3 - 2.95).abs() < 0.005, "the printed 2.95 mm is e_T rounded: {et}");
}

/// Seed 002, question 7: Willis for the sun 1 (60) and the ring 4 (120) on
/// the carrier 2: (ω₁ − ω₂)/(ω₄ − ω₂) = −120/60, so ω₄ = 25 rpm (printed);
/// the planet 3 (30): (ω₃ − ω₂)/(ω₁ − ω₂) = −60/30, ω₃ = −50 rpm (printed).
/// Torques: ΣT = 0 and ΣTω = 0 with T₁ = 15 N·m give T₄ = 30, T₂ = −45 N·m
/// (printed P4 = 30, P2 = −45).
#[tokio::test]
async fn the_differential_train_is_the_seeds() {
    let app = TestApp::new().await;
    let id = "differential-train";
    let (w1, w2, t1) = (100.0, 50.0, 15.0);
    let w4 = w2 - (w1 - w2) / 2.0;
    let w3 = w2 - 2.0 * (w1 - w2);
    let t4 = -(t1 * w1 - t1 * w2) / (w4 - w2);
    near(part(&app, id, "/members/3/speed", "unit=rpm").await, w4, 1e-12, "ω4 (printed 25 rpm)");
    near(part(&app, id, "/members/2/speed", "unit=rpm").await, w3, 1e-12, "ω3 (printed −50 rpm)");
    near(part(&app, id, "/members/3/torque", "").await, t4, 1e-12, "T4 (printed 30)");
    near(part(&app, id, "/members/1/torque", "").await, -t1 - t4, 1e-12, "T2 (printed −45)");
}

/// Seed 003, item 3: the moment that keeps the frame at 10 rad/s against
/// the weight, M_x = −mg(0.1 cos φ − 0.04 sin φ) (m = 1.5 kg, g = 9.8):
/// −0.0666 mg at 30° (printed −0.066, truncated), and zero at tan φ = 2.5
/// (printed 1.19029 rad).
#[tokio::test]
async fn the_disk_at_any_angle_needs_the_seeds_moment() {
    let app = TestApp::new().await;
    let id = "rotor-disk-angle";
    let mx = |phi: f64| -1.5 * 9.8 * (0.1 * phi.cos() - 0.04 * phi.sin());
    let pointer = "/states/0/reactions/total/driving_moment";
    near(part(&app, id, pointer, "").await, mx(PI / 6.0), 1e-9, "M_x at 30° (printed −0.066 mg)");
    let zero = 2.5f64.atan();
    assert!((zero - 1.19029).abs() < 1e-5, "printed 1.19029 rad");
    let at_zero = part(&app, id, pointer, &format!("phi={}", zero.to_degrees())).await;
    assert!(at_zero.abs() < 1e-12, "no moment where tan φ = 2.5: {at_zero}");
}

/// Seed 003, item 8: the frame accelerated at γ = 3 rad/s² from 10 rad/s,
/// the disk spinning at ω₂ = 20 rad/s: R_Dz = R_Ez = −0.075ω₁² − 0.09,
/// R_Dy = 0.03ω₁² − 0.025ω₂ω₁ − 0.225, R_Ey = 0.03ω₁² + 0.025ω₂ω₁ − 0.225 N
/// (printed), ω₁ = 10 + 3t; and the driving moment γ(I_x'x' + m·d²) =
/// 0.06345 N·m that the seed's axial equation leaves out (d² = 0.04² + 0.1²).
#[tokio::test]
async fn the_accelerating_disk_has_the_seeds_reactions() {
    let app = TestApp::new().await;
    let id = "rotor-disk-accelerating";
    for (t, query) in [(0.0, ""), (1.0, "t=1")] {
        let w1: f64 = 10.0 + 3.0 * t;
        let r = |end: &str| format!("/states/0/reactions/dynamic/{end}");
        near(part(&app, id, &r("d/2"), query).await, -0.075 * w1 * w1 - 0.09, 1e-9, "R_Dz");
        near(part(&app, id, &r("e/2"), query).await, -0.075 * w1 * w1 - 0.09, 1e-9, "R_Ez");
        near(part(&app, id, &r("d/1"), query).await, 0.03 * w1 * w1 - 0.5 * w1 - 0.225, 1e-9, "R_Dy");
        near(part(&app, id, &r("e/1"), query).await, 0.03 * w1 * w1 + 0.5 * w1 - 0.225, 1e-9, "R_Ey");
        let moment = 3.0 * (0.00375 + 1.5 * (0.04f64.powi(2) + 0.1f64.powi(2)));
        near(part(&app, id, &r("driving_moment"), query).await, moment, 1e-9, "γ(I + md²), left out by the seed");
    }
}

/// Seed 004, the double pendulum by Lagrange (the seed's equations are
/// symbolic and have slips; these are the corrected ones):
/// (m₁+m₂)l₁²θ̈₁ + m₂l₁l₂ cos(θ₁−θ₂)θ̈₂ = −m₂l₁l₂θ̇₂² sin(θ₁−θ₂) − (m₁+m₂)gl₁ sin θ₁,
/// m₂l₁l₂ cos(θ₁−θ₂)θ̈₁ + m₂l₂²θ̈₂ = m₂l₁l₂θ̇₁² sin(θ₁−θ₂) − m₂gl₂ sin θ₂,
/// solved at the template's start (2 kg, 1 kg, 1 m, 0.5 m, 30°, 60°, 1 and
/// −1 rad/s): the run's first accelerations (1e-9).
#[tokio::test]
async fn the_double_pendulum_starts_as_lagrange_says() {
    let app = TestApp::new().await;
    let (m1, m2, l1, l2, g) = (2.0, 1.0, 1.0, 0.5, 9.81);
    let (t1, t2, w1, w2): (f64, f64, f64, f64) = (PI / 6.0, PI / 3.0, 1.0, -1.0);
    let (c, s) = ((t1 - t2).cos(), (t1 - t2).sin());
    let [a, b, d] = [(m1 + m2) * l1 * l1, m2 * l1 * l2 * c, m2 * l2 * l2];
    let f1 = -m2 * l1 * l2 * w2 * w2 * s - (m1 + m2) * g * l1 * t1.sin();
    let f2 = m2 * l1 * l2 * w1 * w1 * s - m2 * g * l2 * t2.sin();
    let det = a * d - b * b;
    let (e1, e2) = ((f1 * d - b * f2) / det, (a * f2 - b * f1) / det);
    let id = "double-pendulum";
    near(part(&app, id, "/machine/samples/0/inputs/0/acceleration", "").await, e1, 1e-9, "θ̈₁");
    near(part(&app, id, "/machine/samples/0/inputs/1/acceleration", "").await, e2, 1e-9, "θ̈₂");
}
