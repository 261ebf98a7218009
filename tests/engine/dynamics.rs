//! Reference case D1 (tests/fixtures/cases): a scotch yoke started from rest
//! by a constant torque, in reduced form I* = 0.07 + 0.05 sin²φ,
//! M* = 15 − 20 sin²φ. The case's values come from the closed form
//! ω² = 10(φ + sin 2φ)/I*(φ) and t = ∫dφ/ω; tolerance 1e-9 (the case's; the
//! integration runs at 1e-11).

use mechdyn::engine::Deadline;
use mechdyn::engine::dynamics::{DynamicsError, End, EventKind, KEPT_BYTES, ReducedProblem, solve};
use mechdyn::engine::expr::Expr;
use mechdyn::engine::function::Function;
use serde_json::Value;
use std::f64::consts::PI;

fn case() -> Value {
    let path =
        concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/cases/D1_scotch_yoke_from_rest_constant_torque.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn problem(end: End, samples: usize) -> ReducedProblem {
    let f = |s: &str| Function::Expr(Expr::compile(s, &["phi"]).unwrap());
    ReducedProblem {
        torques: vec![(f("15 - 20*sin(phi)^2"), 1.0)],
        inertia: f("sin(phi)^2/20 + 7/100"),
        period: 2.0 * PI,
        angle0: 0.0,
        speed0: 0.0,
        end,
        tolerance: 1e-9,
        integrator: None,
        samples,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
    }
}

#[track_caller]
fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!((got - want).abs() <= tol * want.abs().max(1e-300), "{what}: {got} vs {want}");
}

/// Turn events at 2π and 4π (located on the dense output) against the case.
#[test]
fn d1_turns_are_reached_at_the_closed_form_times_and_speeds() {
    let c = case();
    let s = solve(&problem(End::UntilAngle { angle: 4.0 * PI, max_time: 10.0 }, 2)).unwrap();
    let turns: Vec<_> = s.events.iter().filter(|e| e.kind == EventKind::Turn).collect();
    assert_eq!(turns.len(), 2, "{:?}", s.events);
    for (event, row) in turns.iter().zip(&c["expected"]["at_angle"].as_array().unwrap()[5..7]) {
        close(event.t, row["time_s"].as_f64().unwrap(), 1e-9, "t at the turn");
        close(event.speed, row["omega_rad_s"].as_f64().unwrap(), 1e-9, "ω at the turn");
    }
    assert!(s.energy_residual.abs() < 1e-9, "{}", s.energy_residual);
    assert_eq!(s.events.last().unwrap().kind, EventKind::End);
}

/// State at given times: samples every 0.05 s up to 1 s.
#[test]
fn d1_state_at_given_times() {
    let c = case();
    let s = solve(&problem(End::Duration(1.0), 21)).unwrap();
    for row in c["expected"]["at_time"].as_array().unwrap() {
        let t = row["time_s"].as_f64().unwrap();
        let sample = s.samples.iter().find(|x| (x.t - t).abs() < 1e-12).unwrap();
        close(sample.angle, row["angle_rad"].as_f64().unwrap(), 1e-9, "angle");
        close(sample.speed, row["omega_rad_s"].as_f64().unwrap(), 1e-9, "speed");
        close(sample.acceleration, row["alpha_rad_s2"].as_f64().unwrap(), 1e-9, "acceleration");
    }
}

/// The budget is read before every evaluation of dy/dt, not every 64 steps
/// as before: a run whose budget has run out stops in its first step (one
/// step attempted at most), however much a step costs.
#[test]
fn a_spent_budget_stops_the_integration_within_its_first_step() {
    let mut p = problem(End::Duration(100.0), 11);
    p.deadline = Deadline::after(std::time::Duration::ZERO);
    std::thread::sleep(std::time::Duration::from_millis(2));
    match solve(&p) {
        Err(DynamicsError::Budget { t, steps, .. }) => assert!(t == 0.0 && steps <= 1, "t = {t}, steps = {steps}"),
        other => panic!("expected the budget to run out: {other:?}"),
    }
}
