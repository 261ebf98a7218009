//! Turns at many turns (issue 46: a free rotor turning eleven times never
//! answered — the work across periods found its period again from an angle
//! rounding put a hair below 11·2π, and looped for ever). Every turn's event
//! against the closed form, at 10, 11, 100 and 10⁴ turns, forwards and
//! backwards, with each integrator, and the energy form's times.
//!
//! Free rotor, I = 1, M = 0, ω₀: φ = ω₀t, turn k at t = 2πk/|ω₀|.
//! Constant torque M on I: φ = ω₀t + ½(M/I)t², turn k at
//! t = (√(ω₀² + 2(M/I)·2πk) − ω₀)/(M/I).

use mechdyn::engine::Deadline;
use mechdyn::engine::dynamics::{End, EventKind, Integrator, KEPT_BYTES, MAX_TURN_EVENTS, ReducedProblem, solve};
use mechdyn::engine::expr::Expr;
use mechdyn::engine::function::Function;
use std::f64::consts::PI;

fn rotor(torque: &str, speed0: f64, end: End, integrator: Option<Integrator>) -> ReducedProblem {
    let torque = Function::Expr(Expr::compile(torque, &["phi"]).unwrap());
    ReducedProblem {
        torques: vec![(torque, 1.0)],
        inertia: Function::Constant(1.0),
        period: 2.0 * PI,
        angle0: 0.0,
        speed0,
        end,
        tolerance: 1e-9,
        integrator,
        samples: 3,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
    }
}

/// Every turn event's time against `at(k)`, k = 1.. (relative 1e-9: the
/// run's tolerance; the integration runs 100 times tighter).
#[track_caller]
fn turns_at(p: &ReducedProblem, n: usize, at: impl Fn(f64) -> f64) {
    let s = solve(p).unwrap_or_else(|e| panic!("{n} turns: {e}"));
    let turns: Vec<_> = s.events.iter().filter(|e| e.kind == EventKind::Turn).collect();
    assert_eq!(turns.len(), n, "{n} turns crossed");
    for (k, e) in turns.iter().enumerate() {
        let want = at((k + 1) as f64);
        assert!((e.t - want).abs() <= 1e-9 * want, "turn {} of {n}: t = {} vs {want}", k + 1, e.t);
        let angle = 2.0 * PI * (k + 1) as f64 * p.speed0.signum();
        assert!((e.angle - angle).abs() <= 1e-9 * angle.abs(), "turn {}: φ = {} vs {angle}", k + 1, e.angle);
    }
    // Energy form (actions of φ only): each event timed by t = ∫dφ/ω.
    for (e, t) in s.events.iter().zip(&s.energy_times).take(200) {
        let t = t.unwrap_or_else(|| panic!("event at {} untimed by the energy form", e.t));
        assert!((t - e.t).abs() <= 1e-8 * e.t.max(1.0), "energy form {t} vs {}", e.t);
    }
    assert!(s.energy_residual.abs() < 1e-9, "energy residual {}", s.energy_residual);
}

#[test]
fn a_free_rotor_crosses_each_turn_at_two_pi_k_over_its_speed() {
    for n in [10usize, 11, 100, 10_000] {
        let d = 2.0 * PI * n as f64 + 0.5;
        for integrator in [None, Some(Integrator::Dopri5), Some(Integrator::Dop853)] {
            turns_at(&rotor("0", 1.0, End::Duration(d), integrator), n, |k| 2.0 * PI * k);
        }
        turns_at(&rotor("0", -1.0, End::Duration(d), None), n, |k| 2.0 * PI * k);
        // Ending at an angle: the until_angle 70 (11 turns) and 100 (15).
        let angle = 2.0 * PI * n as f64 + 0.25;
        let until = End::UntilAngle { angle, max_time: 10.0 * angle };
        let s = solve(&rotor("0", 1.0, until, None)).unwrap();
        let end = s.events.last().unwrap();
        assert!((end.t - angle).abs() <= 1e-9 * angle, "end at {} vs {angle}", end.t);
    }
    for (angle, n) in [(70.0, 11), (100.0, 15)] {
        let s = solve(&rotor("0", 1.0, End::UntilAngle { angle, max_time: 200.0 }, None)).unwrap();
        assert_eq!(s.events.iter().filter(|e| e.kind == EventKind::Turn).count(), n);
    }
}

#[test]
fn a_constant_torque_crosses_each_turn_at_the_closed_form_time() {
    let (m, w0) = (3.0, 2.0);
    let at = |k: f64| ((w0 * w0 + 2.0 * m * 2.0 * PI * k).sqrt() - w0) / m;
    for n in [10usize, 11, 100] {
        let d = at(n as f64 + 0.5);
        turns_at(&rotor("3", w0, End::Duration(d), None), n, at);
    }
}

/// A torque that reads the angle, M = sin φ: over whole turns its work is
/// 0, so ω at every turn is ω₀ again and the turns are evenly spaced by
/// T = ∫₀^{2π} dφ/√(ω₀² + 2(1 − cos φ)) (the energy form; checked against
/// 11 periods of a turn's first time).
#[test]
fn a_torque_of_the_angle_over_many_turns_keeps_the_energy_of_each_turn() {
    let p = rotor("sin(phi)", 3.0, End::Duration(1.0), None);
    let first = solve(&ReducedProblem { end: End::Duration(2.3), ..p.clone() }).unwrap();
    let period = first.events.iter().find(|e| e.kind == EventKind::Turn).unwrap().t;
    let n = 10_000;
    let s = solve(&ReducedProblem { end: End::Duration(period * (n as f64 + 0.5)), ..p }).unwrap();
    let turns: Vec<_> = s.events.iter().filter(|e| e.kind == EventKind::Turn).collect();
    assert_eq!(turns.len(), n);
    for (k, e) in turns.iter().enumerate() {
        let want = period * (k + 1) as f64;
        assert!((e.t - want).abs() <= 1e-8 * want, "turn {}: {} vs {want}", k + 1, e.t);
        assert!((e.speed - 3.0).abs() <= 1e-8, "turn {}: ω = {}", k + 1, e.speed);
    }
}

/// A rotor at 2·10⁶ rad/s for 100 s crosses ⌊2·10⁸/2π⌋ = 31 830 988 turns,
/// most of them within single steps: the first [`MAX_TURN_EVENTS`] are
/// listed, each at 2πk/ω, and the rest counted, not listed (they were
/// 1.5 GB of events).
#[test]
fn turns_past_the_listed_ones_are_counted() {
    let (w, d) = (2e6, 100.0);
    let s = solve(&rotor("0", w, End::Duration(d), None)).unwrap();
    let turns: Vec<_> = s.events.iter().filter(|e| e.kind == EventKind::Turn).collect();
    assert_eq!(turns.len(), MAX_TURN_EVENTS);
    let total = (w * d / (2.0 * PI)).floor() as u64;
    assert_eq!(s.unlisted_turns, total - MAX_TURN_EVENTS as u64);
    for (k, e) in turns.iter().enumerate().step_by(997) {
        let want = 2.0 * PI * (k + 1) as f64 / w;
        assert!((e.t - want).abs() <= 1e-9 * want, "turn {}: {} vs {want}", k + 1, e.t);
    }
}
