//! Reference case K1 (offset slider-crank, tests/fixtures/cases): driving
//! torque, every joint reaction and I* at 12 crank angles, with and without
//! crank acceleration. The case was computed by a numeric Newton–Euler
//! solution and a sympy closed-form energy method, agreeing to ~1e-15;
//! tolerance 1e-9 relative (the case's), on the scale of the largest force.

use mechdyn::engine::Deadline;
use mechdyn::engine::expr::Expr;
use mechdyn::engine::function::Function;
use mechdyn::engine::kinetostatics::{Load, Outputs, Step, solve, solve_each};
use mechdyn::engine::samples::offset_slider_crank;
use serde_json::Value;

fn case() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/cases/K1_offset_slider_crank.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn gas_force() -> Vec<Load> {
    let mechanism = offset_slider_crank();
    let b = mechanism.joints[2].at;
    let magnitude = Function::Expr(Expr::compile("-8000*exp(3*(cos(phi - 0.35) - 1))", &["phi"]).unwrap());
    vec![Load::Force { body: 3, at: b, direction: [1.0, 0.0], magnitude }]
}

fn run(rows: &[Value], outputs: Outputs) -> Vec<Step> {
    let positions: Vec<Vec<[f64; 3]>> = rows
        .iter()
        .map(|r| {
            vec![[
                r["phi_rad"].as_f64().unwrap(),
                r["omega_rad_s"].as_f64().unwrap(),
                r["alpha_rad_s2"].as_f64().unwrap(),
            ]]
        })
        .collect();
    solve(&offset_slider_crank(), &gas_force(), &positions, outputs, &Deadline::none()).unwrap().steps
}

/// Everything, the condition number exactly (the case gives κ₂).
fn all() -> Outputs {
    Outputs { driving: true, reactions: true, reduced: true, kinematics: false, condition: true }
}

#[track_caller]
fn close(got: f64, want: f64, scale: f64, what: &str) {
    assert!((got - want).abs() <= 1e-9 * scale.max(want.abs()), "{what}: {got} vs {want}");
}

fn check_rows(rows: &[Value], steps: &[Step]) {
    let names = ["O", "A", "B", "guide"];
    for (row, s) in rows.iter().zip(steps) {
        let at = format!("phi = {} deg", row["phi_deg"]);
        let scale = names.iter().map(|n| row["reactions"][n]["magnitude_N"].as_f64().unwrap()).fold(1.0, f64::max);
        close(s.driving[0], row["T_drive_Nm"].as_f64().unwrap(), scale * 0.1, &format!("{at}: T"));
        close(
            s.driving_virtual_power[0],
            row["T_drive_Nm"].as_f64().unwrap(),
            scale * 0.1,
            &format!("{at}: T by virtual power"),
        );
        close(s.reduced_inertia.unwrap(), row["I_star_kg_m2"].as_f64().unwrap(), 1e-3, &format!("{at}: I*"));
        for (k, name) in names.iter().enumerate() {
            let (r, e) = (&s.reactions[k], &row["reactions"][name]);
            close(r.fx, e["Fx_N"].as_f64().unwrap(), scale, &format!("{at}: {name} Fx"));
            close(r.fy, e["Fy_N"].as_f64().unwrap(), scale, &format!("{at}: {name} Fy"));
            let m = e["M_Nm"].as_f64().unwrap_or(0.0);
            close(r.moment, m, scale * 0.1, &format!("{at}: {name} moment"));
        }
        close(s.condition, row["cond_constraint_jacobian"].as_f64().unwrap(), 1.0, &format!("{at}: condition"));
    }
}

#[test]
fn k1_driving_torque_and_every_reaction_at_constant_speed() {
    let c = case();
    let rows = c["expected"]["table"].as_array().unwrap();
    check_rows(rows, &run(rows, all()));
}

#[test]
fn k1_with_crank_acceleration() {
    let c = case();
    let rows = c["expected"]["table_with_alpha"].as_array().unwrap();
    check_rows(rows, &run(rows, all()));
}

/// Asking only for the driving torque takes the virtual-power path (no
/// multipliers) and gives the same torque.
#[test]
fn driving_only_uses_virtual_power_and_agrees() {
    let c = case();
    let rows = c["expected"]["table"].as_array().unwrap();
    let steps =
        run(rows, Outputs { driving: true, reactions: false, reduced: false, kinematics: false, condition: false });
    for (row, s) in rows.iter().zip(&steps) {
        assert!(s.reactions.is_empty() && s.reduced_inertia.is_none());
        close(s.driving[0], row["T_drive_Nm"].as_f64().unwrap(), 1000.0, "T");
    }
}

/// Mean and RMS of the driving torque over a cycle: the case's periodic
/// trapezoid rule on 4096 points equals the mean over 4096 evenly spaced steps.
/// The multipliers and virtual power agree to round-off at every step.
#[test]
fn k1_cycle_mean_and_rms_torque_and_the_virtual_power_residual() {
    let c = case();
    let n = 4096;
    let positions: Vec<Vec<[f64; 3]>> =
        (0..n).map(|k| vec![[2.0 * std::f64::consts::PI * k as f64 / n as f64, 150.0, 0.0]]).collect();
    let solution = solve(&offset_slider_crank(), &gas_force(), &positions, all(), &Deadline::none()).unwrap();
    let s = &solution.totals.summary;
    close(s.mean_driving[0], c["expected"]["cycle_mean_torque_Nm"].as_f64().unwrap(), 1.0, "mean T");
    close(s.rms_driving[0], c["expected"]["cycle_rms_torque_Nm"].as_f64().unwrap(), 1.0, "rms T");
    assert!(s.virtual_power_residual.unwrap() < 1e-12, "{:?}", s.virtual_power_residual);
    assert_eq!((solution.totals.mobility.dof, solution.totals.mobility.redundant_constraints), (1, 0));
    assert!(solution.totals.max_constraint_residual < 1e-12);
}

/// `solve_each` refills one step: from the second position on, its lists
/// (inputs, driving actions both ways, reactions, the motion, the energy
/// shares) keep the
/// storage they had (nothing allocated per position), and every step it
/// hands over equals `solve`'s, whose totals it returns too.
#[test]
fn solve_each_refills_one_step_and_agrees_with_solve() {
    let positions: Vec<Vec<[f64; 3]>> = (0..360).map(|k| vec![[k as f64 * 0.0175, 150.0, 10.0]]).collect();
    let (m, loads, outputs) = (offset_slider_crank(), gas_force(), Outputs { kinematics: true, ..all() });
    let whole = solve(&m, &loads, &positions, outputs, &Deadline::none()).unwrap();
    let mut storage = Vec::new();
    let totals = solve_each(&m, &loads, &positions, outputs, &Deadline::none(), |step| {
        assert_eq!(*step, whole.steps[storage.len()], "step {}", storage.len());
        let motion = step.kinematics.as_ref().expect("asked");
        storage.push([
            step.input.as_ptr() as usize,
            step.driving.as_ptr() as usize,
            step.driving_virtual_power.as_ptr() as usize,
            step.reactions.as_ptr() as usize,
            motion.q.as_ptr() as usize,
            motion.qdd.as_ptr() as usize,
            step.energy_shares.as_ref().expect("asked").as_ptr() as usize,
        ]);
        Ok(())
    })
    .unwrap();
    assert_eq!(totals, whole.totals);
    assert_eq!(storage.len(), positions.len());
    assert!(storage[1..].iter().all(|s| *s == storage[1]), "a list moved to new storage");
}

/// Energy balance over a cycle for the sample four-bar at constant speed
/// under gravity: ∫T dφ = ½ω²∮dI* − ∮M* dφ = 0 (gravity is conservative), so
/// the mean of T over evenly spaced steps (spectrally accurate for a periodic
/// function) vanishes to round-off relative to max |T|.
#[test]
fn four_bar_driving_work_over_a_cycle_is_zero_under_gravity() {
    let n = 512;
    let positions: Vec<Vec<[f64; 3]>> =
        (0..n).map(|k| vec![[2.0 * std::f64::consts::PI * k as f64 / n as f64, 30.0, 0.0]]).collect();
    let s =
        solve(&mechdyn::engine::samples::four_bar(), &[], &positions, all(), &Deadline::none()).unwrap().totals.summary;
    assert!(s.mean_driving[0].abs() < 1e-10 * s.max_abs_driving[0], "{s:?}");
    assert!(s.virtual_power_residual.unwrap() < 1e-12);
}

/// A linear actuator (prismatic input) lifting an arm: the driving force from
/// the multipliers and from virtual power agree at every stroke position, at
/// rest and in motion.
#[test]
fn a_prismatic_input_gives_the_same_force_both_ways() {
    let positions: Vec<Vec<[f64; 3]>> = (0..20).map(|k| vec![[0.005 * k as f64, 0.2, 0.5]]).collect();
    let solution = solve(&mechdyn::engine::samples::actuated_arm(), &[], &positions, all(), &Deadline::none()).unwrap();
    assert!(solution.totals.summary.virtual_power_residual.unwrap() < 1e-12, "{:?}", solution.totals.summary);
    assert!(solution.steps.iter().all(|s| s.driving[0] > 0.0), "the actuator pushes the arm up");
}

/// The scissor-lift sample (seed 002) solved at the engine level: the piston
/// force is the printed −√3(10mg + 8mv²/(27L)) with m = 10 kg, L = 0.5 m,
/// v = 0.3 m/s (same problem as the API test, built from the shared sample).
#[test]
fn scissor_lift_sample_gives_the_printed_piston_force() {
    let (m, l, v, g) = (10.0f64, 0.5f64, 0.3f64, 9.81f64);
    let c30 = 3f64.sqrt() / 2.0;
    let positions = vec![vec![[0.0, v / 3f64.sqrt(), -v * v / (2.0 * l * c30.powi(3))]]];
    let s = solve(&mechdyn::engine::samples::scissor_lift(), &[], &positions, all(), &Deadline::none()).unwrap();
    let expected = -(3f64.sqrt()) * (10.0 * m * g + 8.0 * m * v * v / (27.0 * l));
    close(s.steps[0].driving[0], expected, 1.0, "F_AB");
}
