//! The exam problems of the course notes' flywheel chapter (excerpts in
//! tests/fixtures/seeds/flywheel-exams.md), each a built-in template
//! (library/exam-*.json) solved at its defaults, with its printed answer.
//! Expected values are closed forms derived here, written next to each test;
//! where the printed answer is wrong the test says why.

use crate::helpers::{TestApp, close, template_request};
use serde_json::Value;
use std::f64::consts::PI;

fn result(job: Value) -> Value {
    job["result"].clone()
}

/// Examen Marzo 2010: 3FR sin φ₁ drives on (0, π) (F = 750 N, R = 0.1 m), a
/// constant resisting torque on a shaft turning twice as fast (ω₂ = 2ω₁),
/// 210 rpm, δ = 0.05, flywheel on shaft 2.
/// Closed form: C_r* = 450/(2π) = 71.6197 N·m on shaft 1, C_r = C_r*/2 =
/// 35.8099 N·m; φ₁ = asin(C_r*/225) = 0.323946; ΔE = A₂ = 450 cos φ₁ −
/// C_r*(π − 2φ₁) = 247.9959 J; I = ΔE/(δ ω²) = 10.2560 kg·m²; on shaft 2,
/// I/4 = 2.5640 kg·m². Printed: 35.8099, 0.32395, −11.498, 247.996, 10.256,
/// 2.564 — all agree. Printed power 1574.984 W uses the rounded 71.619 N·m;
/// exact C_r*·ω = 1575.00 W.
#[tokio::test]
async fn march_2010_flywheel_on_a_faster_shaft() {
    let app = TestApp::new().await;
    let r = result(app.flywheel(&template_request("exam-2010-march")).await);
    close(&r["balance_torque"], -450.0 / (4.0 * PI), 1e-12, "C_r on shaft 2 (printed 35.8099)");
    close(&r["crossings"][0], 0.3239461069319807, 1e-12, "φ₁ (printed 0.32395)");
    close(&r["areas"][0]["work"], -11.49794231003253, 1e-9, "A1 (printed −11.498)");
    close(&r["areas"][1]["work"], 247.9958846200651, 1e-9, "A2 (printed 247.996)");
    close(&r["inertia_approximate"], 10.256014925768827, 1e-9, "I (printed 10.256)");
    close(&r["flywheel_inertia"]["approximate"], 2.564003731442207, 1e-9, "I on shaft 2 (printed 2.564)");
    close(&r["mean_power"], 1575.0, 1e-12, "power (printed 1574.984 from a rounded C_r*)");
}

/// Examen Enero 2012: motor on a shaft turning 3× the reference (R = 0.3,
/// R_m = 0.1, n_m = 240 rpm → 80 rpm reference), resisting torque
/// F·l·cos(π − φ) = −360 cos φ for 3π/4 ≤ φ ≤ 5π/4, a 10 kg mass on l = 0.6 m
/// (I* = Ml² = 3.6 kg·m², already on the shaft). The irregularity is not
/// legible in the excerpt; the printed I = 54.405 matches ε = 0.1 exactly, so
/// it is used. Closed form: 6π M_m = 360√2 → M_m = 27.0095 N·m (printed 27);
/// ΔE = 360√2 − 3M_m·π/2 = 381.8377 J (printed 381.838); I = ΔE/(ε ω²) =
/// 54.40534 kg·m²; I_v = I − 3.6 = 50.80534 (printed 50.805).
#[tokio::test]
async fn january_2012_motor_on_a_faster_shaft_and_existing_inertia() {
    let app = TestApp::new().await;
    let r = result(app.flywheel(&template_request("exam-2012-january")).await);
    close(&r["balance_torque"], 360.0 * 2f64.sqrt() / (6.0 * PI), 1e-12, "M_m (printed 27)");
    close(&r["energy_fluctuation"], 381.8376618407357, 1e-12, "ΔE (printed 381.838)");
    close(&r["inertia_approximate"], 54.40534292380227, 1e-10, "I (printed 54.405)");
    close(&r["flywheel_inertia"]["approximate"], 50.80534292380227, 1e-10, "I_v (printed 50.805)");
    // Where M* is a jump (at 3π/4 the resisting torque starts at 254.6 N·m
    // against 81.03 N·m of motor) the sign change sits exactly at the jump.
    close(&r["crossings"][0], 0.75 * PI, 1e-15, "crossing at the jump");
}

/// Examen Marzo 2012: load F·R·cos φ (F = 10 kN, R = 0.15 m) on π/4 < φ < π/2;
/// the motor turns 10× the reference (1000 rpm vs 100 rpm); ε = 0.05;
/// flywheel on the motor shaft. Closed form: C_m* = 1500(1 − sin π/4)/(2π) =
/// 69.9231 N·m on the reference, C_m = 6.99231 N·m on the motor;
/// φ₁ = acos(C_m*/1500) = 1.524164; ΔE = 386.0524 J; on the motor shaft
/// I = ΔE/(ε ω_m²) = 0.704075 kg·m². Printed 69.923, 6.9923, 1.524,
/// 54.917, −386.052, 0.7041, 732.233 W — all agree.
#[tokio::test]
async fn march_2012_flywheel_on_the_motor_shaft() {
    let app = TestApp::new().await;
    let r = result(app.flywheel(&template_request("exam-2012-march")).await);
    close(&r["balance_torque"], 6.992310535838563, 1e-12, "C_m (printed 6.9923)");
    close(&r["crossings"][1], 1.5241640241796346, 1e-12, "φ₁ (printed 1.524)");
    close(&r["areas"][0]["work"], 54.91747852752235, 1e-12, "A1 (printed 54.917)");
    close(&r["areas"][1]["work"], -386.0523918923199, 1e-9, "A2 (printed −386.052)");
    close(&r["flywheel_inertia"]["exact"], 0.7040751353007388, 1e-9, "I (printed 0.7041)");
    close(&r["mean_power"], 732.2330470336314, 1e-12, "P (printed 732.233)");
}

/// Examen Mayo 2013: a force drives through x = (r/d)L sin θ on π < θ < 3π/2,
/// M* = C_m − 20 cos θ there; the motor brakes (C_m = −10/π); 60 rpm, ε = 0.05;
/// solid steel disk, ρ = 7200 kg/m³, rim speed 1.5 m/s. The load starts with a
/// jump at θ = π, where M* jumps across zero: that is the first crossing.
/// Closed form: θ₁ = 2π − acos(C_m/20) = 4.552554; A = −10, 15.253842,
/// −5.253842 J; I = 15.253842/(0.05·4π²) = 7.727687 kg·m²; R = 1.5/2π =
/// 0.238732 m, M = 2I/R² = 271.1794 kg, e = M/(ρπR²) = 0.210354 m. Printed
/// −10/π, 4.5526, −10, 15.2538, −5.2538, 7.72767, 0.2387, 271.179, 0.21035:
/// all agree.
#[tokio::test]
async fn may_2013_jump_across_zero_and_disk_sizing() {
    let app = TestApp::new().await;
    let r = result(app.flywheel(&template_request("exam-2013-may")).await);
    close(&r["balance_torque"], -10.0 / PI, 1e-12, "C_m (printed −10/π)");
    close(&r["crossings"][0], PI, 1e-15, "crossing at the jump θ = π");
    close(&r["crossings"][1], 4.552554353999552, 1e-12, "θ₁ (printed 4.5526)");
    for (i, a) in [-10.0, 15.253841755402593, -5.253841755402593].iter().enumerate() {
        close(&r["areas"][i]["work"], *a, 1e-9, "A_i (printed −10, 15.2538, −5.2538)");
    }
    close(&r["inertia_exact"], 7.727686508751531, 1e-9, "I (printed 7.72767)");
    close(&r["disk"]["radius"], 1.5 / (2.0 * PI), 1e-12, "R (printed 0.2387)");
    close(&r["disk"]["mass"], 271.179408984935, 1e-9, "M (printed 271.179)");
    close(&r["disk"]["thickness"], 0.21035438001775153, 1e-9, "e (printed 0.21035)");
    close(&r["disk"]["rim_speed"], 1.5, 1e-12, "rim speed");
}

/// Examen Mayo 2014: four-stroke single-cylinder engine, F = 1500 N on
/// r_m = 0.04 m during expansion (ψ_m from 2π to 3π), motor shaft 4× the
/// reference (650 rpm), so M* = 240 sin 4φ on [π/2, 3π/4] and [3π/2, 7π/4],
/// minus a constant resisting torque M = 120/π = 38.197 N·m; ε = 0.05;
/// disk R = 0.2 m.
/// **The printed answer is wrong.** Its crossings φ₁ = 1.5724, φ₂ = 2.3546 do
/// not solve 240 sin 4φ = M (at 1.5724, 240 sin 4φ = 1.5 N·m); the true ones
/// are π/2 + a/4 = 1.610755 and 3π/4 − a/4 = 2.316236 with a = asin(M/240).
/// Its second solution drops the small lobe areas altogether (A₂ ≈ 120 − πM/4
/// = 90). Exactly, ΔE = A₂ = 120 cos a − M(π − 2a)/4 = 91.5231 J, so
/// I = ΔE/(ε ω²) = 0.395072 kg·m² (printed 0.389, and 0.8885 — a typo for
/// 0.3885 — in the second solution) and M_disk = 2I/R² = 19.754 kg (printed
/// 19.451 and 19.425). The printed values are 1.5 % low.
#[tokio::test]
async fn may_2014_four_stroke_engine_printed_answer_is_wrong() {
    let app = TestApp::new().await;
    let r = result(app.flywheel(&template_request("exam-2014-may")).await);
    close(&r["balance_torque"], -120.0 / PI, 1e-12, "M (printed 38,197)");
    close(&r["crossings"][0], 1.6107549833911807, 1e-12, "φ₁ (printed 1.5724: wrong)");
    close(&r["crossings"][1], 2.3162358335960604, 1e-12, "φ₂ (printed 2.3546: wrong)");
    close(&r["energy_fluctuation"], 91.52305053241557, 1e-9, "ΔE (printed 90.119: wrong)");
    close(&r["inertia_approximate"], 0.39507225701546295, 1e-9, "I (printed 0.389: wrong)");
    close(&r["disk"]["mass"], 19.75361285077315, 1e-9, "disk mass (printed 19.451: wrong)");
    assert!((r["inertia_approximate"].as_f64().unwrap() - 0.389).abs() > 0.005, "the printed value is not reproduced");
}

/// A Spanish sheet's WEBSERVICE() reads each exam's answer from its
/// template, with a decimal comma; March 2010's inertia scales as F (the
/// resisting torque balances F, so the crossings stay: 10.256 × 1500/750),
/// and May 2014's is the corrected one, not the printed 0.389.
#[tokio::test]
async fn a_sheet_reads_the_exams_answers_from_their_templates() {
    let app = TestApp::new().await;
    let read = |path: String| {
        let app = &app;
        async move {
            let r = app.get(&path).await;
            assert_eq!(r.status, axum::http::StatusCode::OK, "{path}: {}", r.text);
            r.text.replace(',', ".").parse::<f64>().unwrap_or_else(|_| panic!("{path}: {}", r.text))
        }
    };
    let base = "/v1/templates/exam-2010-march/result/inertia_approximate?decimal=comma";
    let once = read(base.to_string()).await;
    assert!((once - 10.256014925768827).abs() < 1e-6, "{once}");
    let twice = read(format!("{base}&F=1500")).await;
    assert!((twice - 2.0 * 10.256014925768827).abs() < 1e-6, "I ∝ F: {twice}");
    let r = app.get("/v1/templates/exam-2014-may/result/inertia_approximate?decimal=comma&lang=es").await;
    assert!(r.text.starts_with("0,395"), "the corrected inertia: {}", r.text);
    let t = app.get("/v1/templates/exam-2014-may?lang=es").await.json();
    assert!(t.to_string().contains("está mal"), "the template says the print is wrong: {t}");
}
