//! The rigid rotor of seed 003 (Ercoli–Azurmendi, "Mecánica Racional",
//! chapter 4 worked example): a disk of R = 0.1 m and 1.5 kg spinning at
//! ω₂ = 20 rad/s about its axis y', on an arm turning at ω₁ = 10 rad/s about
//! the bearings' axis x; centre A at r = −0.04 j' + 0.1 k' from the axis,
//! bearings D and E at x = ∓0.15 m; g = 9.8 m/s² along −Y (the seed's
//! weight is 14.7 N). Printed answers quoted in each test; all are exact
//! decimals of closed forms, so the tolerance is 1e-12.

use mechdyn::engine::rotor::Rotor;
use nalgebra::{Matrix3, Vector3};
use std::f64::consts::PI;

fn seed_disk(acceleration: f64) -> Rotor {
    let (m, r) = (1.5, 0.1);
    Rotor {
        mass: m,
        inertia: Matrix3::from_diagonal(&Vector3::new(m * r * r / 4.0, m * r * r / 2.0, m * r * r / 4.0)),
        cg: Vector3::new(0.0, -0.04, 0.1),
        spin: Vector3::new(0.0, 20.0, 0.0),
        bearings: [-0.15, 0.15],
        gravity: Vector3::new(0.0, -9.8, 0.0),
        speed: 10.0,
        acceleration,
        angle: 0.0,
    }
}

#[track_caller]
fn close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "{what}: {got} vs {want}");
}

/// Q = −1.5 j' − 0.6 k' N·s; T = 0.87 + 1.69 = 2.56 J (printed rounded;
/// exactly 0.87 + 0.016875·100 = 2.5575); gyroscopic moment
/// I_y'y'·ψ̇ i' × φ̇ j' = 1.5 k' N·m; driving moment (5)
/// M_x = −mg(0.1 cos φ − 0.04 sin φ), −0.1 mg at φ = 0 and 0 at φ = 1.19029.
#[test]
fn momentum_energy_gyroscopic_and_driving_moments() {
    let rotor = seed_disk(0.0);
    let s = rotor.at(0.0);
    close(s.momentum.y, -1.5, "Q_y'");
    close(s.momentum.z, -0.6, "Q_z'");
    close(s.kinetic_energy, 0.87 + 0.016875 * 100.0, "T");
    close(s.gyroscopic_moment.z, 1.5, "gyroscopic moment");
    let mg = 1.5 * 9.8;
    for phi in [0.0, PI / 6.0, 1.19029, 5.9027] {
        let s = rotor.at(phi / 10.0);
        close(s.total.driving_moment, -mg * (0.1 * phi.cos() - 0.04 * phi.sin()), "M_x");
        close(s.dynamic.driving_moment, 0.0, "no dynamic M_x at constant speed");
    }
}

/// Dynamic reactions R_Dy = −2, R_Ey = 8, R_Dz = R_Ez = −7.5 N (rotating
/// axes, any φ); totals at φ = 0 (both axes): Y_D = 5.35, Y_E = 15.35,
/// Z = −7.5; at φ = π/2, fixed axes: Z_D = −2, Z_E = 8 and Y_D = Y_E
/// printed 14.35 — wrong: the seed's own formulas Y_D = 7.35 − 2 cos φ +
/// 7.5 sin φ and Y_E = 7.35 + 8 cos φ + 7.5 sin φ give 7.35 + 7.5 = 14.85
/// (the rotating Z' = −7.5 − 7.35 = −14.85 printed next to it agrees);
/// rotating: Y'_D = −2, Y'_E = 8, Z' = −14.85.
#[test]
fn bearing_reactions_dynamic_static_and_total() {
    let rotor = seed_disk(0.0);
    let s = rotor.at(0.0);
    let (d, e) = (s.dynamic.d, s.dynamic.e);
    close(d.y, -2.0, "R_Dy");
    close(e.y, 8.0, "R_Ey");
    close(d.z, -7.5, "R_Dz");
    close(e.z, -7.5, "R_Ez");
    close(e.x, 0.0, "R_Ex");
    close(s.total.d.y, 5.35, "Y'_D at 0");
    close(s.total.e.y, 15.35, "Y'_E at 0");
    close(s.total_fixed[1].y, 15.35, "Y_E at 0");
    let s = rotor.at(PI / 2.0 / 10.0);
    let [d, e] = s.total_fixed;
    close(d.y, 7.35 + 7.5, "Y_D at π/2");
    close(e.y, 7.35 + 7.5, "Y_E at π/2");
    close(d.z, -2.0, "Z_D at π/2");
    close(e.z, 8.0, "Z_E at π/2");
    close(s.total.d.y, -2.0, "Y'_D at π/2");
    close(s.total.e.z, -14.85, "Z'_E at π/2");
}

/// Part 8, γ = 3 rad/s² from ω₁ = 10: R_Dz = R_Ez = −0.075 ω₁(t)² − 0.09,
/// R_Dy = 0.03 ω₁² − 0.025 ω₂ω₁ − 0.225, R_Ey = 0.03 ω₁² + 0.025 ω₂ω₁ −
/// 0.225 (the seed's results). The seed's first Euler equation puts the
/// axial moment 0.01125 N·m on the bearings, which cannot carry it (it
/// contradicts its Newton equations): the driving moment does, and it is
/// γ·(I_x + m·d²) = 3·(0.00375 + 1.5·0.0116) = 0.06345 N·m about the axis.
#[test]
fn an_accelerating_frame() {
    let rotor = seed_disk(3.0);
    for t in [0.0, 0.5, 2.0] {
        let s = rotor.at(t);
        let w1 = 10.0 + 3.0 * t;
        close(s.dynamic.d.z, -0.075 * w1 * w1 - 0.09, "R_Dz");
        close(s.dynamic.e.z, -0.075 * w1 * w1 - 0.09, "R_Ez");
        close(s.dynamic.d.y, 0.03 * w1 * w1 - 0.025 * 20.0 * w1 - 0.225, "R_Dy");
        close(s.dynamic.e.y, 0.03 * w1 * w1 + 0.025 * 20.0 * w1 - 0.225, "R_Ey");
        close(s.dynamic.driving_moment, 3.0 * (0.00375 + 1.5 * 0.0116), "dynamic M_x");
    }
}
