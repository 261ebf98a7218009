//! Direct dynamics in mechanism form (dependent coordinates, projected onto
//! the constraints after every step), each against an independent
//! reference: a closed form, the reduced form of the same mechanism, or the
//! Lagrange equations integrated here on their own.

use crate::elliptic::{complete_k, sn};
use mechdyn::engine::Deadline;
use mechdyn::engine::dynamics::mechanism::{MechanismProblem, solve, solve_in};
use mechdyn::engine::dynamics::{DynamicsError, End, EventKind, Integrator, KEPT_BYTES, ReducedProblem, Start};
use mechdyn::engine::expr::Expr;
use mechdyn::engine::function::Function;
use mechdyn::engine::kinetostatics::Load;
use mechdyn::engine::machine::{Machine, Reduced, ReducedCurve};
use mechdyn::engine::model::{Body, Driver, Joint, JointKind, Mechanism};
use mechdyn::engine::numeric::ode::Dopri5;
use mechdyn::engine::samples::{offset_slider_crank, scotch_yoke};
use serde_json::Value;
use std::f64::consts::PI;
use std::sync::Arc;

fn expr(s: &str) -> Function {
    Function::Expr(Expr::compile(s, &["phi", "omega", "t"]).unwrap())
}

fn problem(mechanism: Mechanism, loads: Vec<Load>, initial: Vec<[f64; 2]>, end: End) -> MechanismProblem {
    MechanismProblem {
        mechanism,
        loads,
        period: 2.0 * PI,
        initial,
        end,
        tolerance: 1e-10,
        integrator: None,
        conserve_energy: None,
        samples: 21,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
        reactions: true,
        motion: false,
    }
}

#[track_caller]
fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!((got - want).abs() <= tol * want.abs().max(1.0), "{what}: {got} vs {want}");
}

/// Reference case D1 built as a mechanism: the scotch yoke sample without
/// gravity (I* = 0.07 + 0.05 sin²φ), 15 N·m on the crank and a force
/// 200 sin φ N along +x on the yoke (its power −20 sin²φ·ω), from rest.
/// The case's closed-form turn times and speeds, tolerance 1e-8 relative,
/// with either integrator.
#[test]
fn d1_as_a_mechanism_reaches_its_turns_at_the_closed_form_times() {
    for integrator in [Integrator::Dopri5, Integrator::Dop853] {
        d1_as_a_mechanism(integrator);
    }
}

fn d1_as_a_mechanism(integrator: Integrator) {
    let path =
        concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/cases/D1_scotch_yoke_from_rest_constant_torque.json");
    let case: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut m = scotch_yoke();
    m.gravity = [0.0, 0.0];
    let loads = vec![
        Load::Torque { body: 1, value: Function::Constant(15.0) },
        Load::Force { body: 2, at: [0.3, 0.0], direction: [1.0, 0.0], magnitude: expr("200*sin(phi)") },
    ];
    let mut p = problem(m, loads, vec![[0.0, 0.0]], End::UntilAngle { angle: 4.0 * PI, max_time: 10.0 });
    p.integrator = Some(integrator);
    let s = solve(&p).unwrap();
    assert_eq!(s.solution.integrator, integrator);
    let turns: Vec<_> = s.solution.events.iter().filter(|e| e.kind == EventKind::Turn).collect();
    assert_eq!(turns.len(), 2, "{:?}", s.solution.events);
    for (event, row) in turns.iter().zip(&case["expected"]["at_angle"].as_array().unwrap()[5..7]) {
        close(event.t, row["time_s"].as_f64().unwrap(), 1e-8, "t at the turn");
        close(event.speed, row["omega_rad_s"].as_f64().unwrap(), 1e-8, "ω at the turn");
    }
    assert!(s.solution.energy_residual.abs() < 1e-8, "{}", s.solution.energy_residual);
    assert!(s.drift < 1e-9, "drift {}", s.drift);
}

/// The offset slider-crank of K1 under 2 N·m and gravity, from rest: the
/// mechanism form against the reduced form of the same mechanism (I*, I*'
/// and M* by Zhukovsky from exact positions at every φ), both at 1e-10;
/// agreement 1e-7 in φ and ω over 1 s.
#[test]
fn slider_crank_matches_its_reduced_form() {
    let loads = vec![Load::Torque { body: 1, value: Function::Constant(2.0) }];
    let mech = solve(&problem(offset_slider_crank(), loads.clone(), vec![[0.0, 0.0]], End::Duration(1.0))).unwrap();
    let machine = Arc::new(Machine::new(offset_slider_crank(), loads, 0.0, 2.0 * PI, Deadline::none()).unwrap());
    let reduced = mechdyn::engine::dynamics::solve(&ReducedProblem {
        torques: vec![(ReducedCurve::function(machine.clone(), Reduced::Torque), 1.0)],
        inertia: ReducedCurve::function(machine, Reduced::Inertia),
        period: 2.0 * PI,
        angle0: 0.0,
        speed0: 0.0,
        end: End::Duration(1.0),
        tolerance: 1e-10,
        integrator: None,
        samples: 21,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
    })
    .unwrap();
    assert!(mech.solution.samples[20].angle > 4.0 * PI, "it turns: {:?}", mech.solution.samples[20]);
    for (a, b) in mech.solution.samples.iter().zip(&reduced.samples) {
        close(a.angle, b.angle, 1e-7, "φ");
        close(a.speed, b.speed, 1e-7, "ω");
        close(a.acceleration, b.acceleration, 1e-6, "α");
    }
    assert!(mech.solution.energy_residual.abs() < 1e-8, "{}", mech.solution.energy_residual);
    // Reactions along the way: the crank bearing carries the whole mechanism.
    assert_eq!(mech.details[5].reactions.len(), 4);
}

/// The two forms of the equations of motion (range-space with a sparse
/// LDLᵀ, and LU of the augmented matrix) on the same run of the K1
/// slider-crank under 2 N·m with every reaction: the same motion and
/// reactions to 1e-9 and 1e-8 (each integrates with its own rounding and
/// takes its own steps at a tolerance of 1e-10 per step; accelerations and
/// reactions are 300 times the speed's size here).
#[test]
fn the_sparse_and_dense_forms_agree() {
    let loads = vec![Load::Torque { body: 1, value: Function::Constant(2.0) }];
    let p = problem(offset_slider_crank(), loads, vec![[0.0, 0.0]], End::Duration(1.0));
    let (sparse, dense) = (solve_in(&p, true).unwrap(), solve_in(&p, false).unwrap());
    assert!(sparse.sparse && !dense.sparse);
    for (a, b) in sparse.details.iter().zip(&dense.details) {
        let ([phi, omega, alpha], [phi_d, omega_d, alpha_d]) = (a.inputs[0], b.inputs[0]);
        close(phi, phi_d, 1e-9, "φ");
        close(omega, omega_d, 1e-9, "ω");
        close(alpha, alpha_d, 1e-8, "α");
        for (x, y) in a.reactions.iter().zip(&b.reactions) {
            close(x.fx, y.fx, 1e-8, "Fx");
            close(x.fy, y.fy, 1e-8, "Fy");
            close(x.moment, y.moment, 1e-8, "M");
        }
    }
}

/// A simple pendulum (IFToMM A01: 1 kg point mass on a massless 1 m link,
/// released from the horizontal, g = 9.81) over 2000 s, about 840 swings:
/// the angle against the closed form sin(θ/2) = k·sn(K − t√(g/L), k),
/// k = sin(θ₀/2), θ measured from the bottom; the constraint drift stays at
/// the step's error and the energy is conserved.
#[test]
fn a01_pendulum_follows_the_elliptic_closed_form_for_2000_s() {
    let m = pendulum();
    let mut p = problem(m, Vec::new(), vec![[0.0, 0.0]], End::Duration(2000.0));
    p.samples = 2001;
    p.tolerance = 1e-10;
    let s = solve(&p).unwrap();
    let k = (PI / 4.0).sin();
    let kk = complete_k(k);
    let mut worst = 0.0f64;
    for x in &s.solution.samples {
        let theta = PI / 2.0 + x.angle;
        let want = 2.0 * (k * sn(kk - x.t * 9.81f64.sqrt(), k)).asin();
        worst = worst.max((theta - want).abs());
    }
    // Measured 5.7e-7 rad (398 131 steps, drift 1e-12).
    assert!(worst < 2e-6, "largest angle error over 2000 s: {worst} rad");
    assert!(s.solution.energy_residual.abs() < 1e-8, "{}", s.solution.energy_residual);
    assert!(s.drift < 1e-9, "drift {}", s.drift);
    let residual = s.details.iter().map(|d| d.constraint_residual).fold(0.0, f64::max);
    assert!(residual < 1e-9, "|Φ| at the samples {residual}");
    // The bearing holds the weight plus the centripetal force: with the
    // speed from energy, v² = 2gL·cos θ (θ from the downward vertical), the
    // rod's tension is 3mg·cos θ; cos θ = −sin φ (φ from the horizontal).
    for (d, x) in s.details.iter().zip(&s.solution.samples) {
        let tension = d.reactions[0].fx.hypot(d.reactions[0].fy);
        close(tension, -3.0 * 9.81 * x.angle.sin(), 1e-7, "bearing force");
    }
}

/// A01 over 2000 s at a loose tolerance (1e-3, IFToMM's accuracy for it),
/// each integrator with and without the energy held. Without it the
/// period's error accumulates into a phase error growing with time; held,
/// the error is only the phase's, and within 1e-3 rad. Measured
/// (docs/BENCHMARKS.md): held 1.2e-4 (DOPRI5), 7.4e-4 (DOP853); free
/// 1.9 rad (DOP853). Held, T + V is E₀ at the step ends; the samples lie on
/// the dense output between them, 2.6e-5 and 2.3e-5 of m·g·L off at this
/// tolerance (measured).
#[test]
fn holding_the_energy_keeps_a01_within_its_accuracy_at_a_loose_tolerance() {
    let k = (PI / 4.0).sin();
    let kk = complete_k(k);
    let error = |integrator: Integrator, held: bool| {
        let mut p = problem(pendulum(), Vec::new(), vec![[0.0, 0.0]], End::Duration(2000.0));
        (p.samples, p.tolerance, p.integrator, p.conserve_energy, p.reactions) =
            (2001, 1e-3, Some(integrator), Some(held), false);
        let s = solve(&p).unwrap();
        assert_eq!((s.energy_conserved, s.solution.integrator), (held, integrator));
        // Held after most steps (not near the turning points), after none when free.
        let steps = s.solution.steps;
        assert!(if held { 2 * s.energy_held_steps > steps } else { s.energy_held_steps == 0 }, "{steps} steps");
        let worst = s.solution.samples.iter().fold(0.0f64, |a, x| {
            a.max((PI / 2.0 + x.angle - 2.0 * (k * sn(kk - x.t * 9.81f64.sqrt(), k)).asin()).abs())
        });
        // E = T + V with V = m·g·y_G (y_G = sin φ): 0 at the start.
        let energy = s
            .solution
            .samples
            .iter()
            .zip(&s.details)
            .fold(0.0f64, |a, (x, d)| a.max((0.5 * x.speed * x.speed + 9.81 * d.poses[0][1]).abs() / 9.81));
        (worst, energy)
    };
    for integrator in [Integrator::Dopri5, Integrator::Dop853] {
        let (held, energy) = error(integrator, true);
        assert!(held < 1e-3, "{integrator:?} held: {held} rad");
        assert!(energy < 1e-4, "{integrator:?}: |T + V − E₀|/(m·g·L) {energy}");
    }
    let (free, _) = error(Integrator::Dop853, false);
    assert!(free > 0.1, "free: {free} rad");
}

/// The pendulum with a spring (k = 40 N/m, L₀ = 0.5 m) from (0, −2) to the
/// bob, over 5 s at 1e-10: with the energy held (V of gravity and of the
/// spring) and free (a second run that knows nothing of V) the angle agrees
/// to 1e-7 rad at every sample: the hold moves nothing but the error. (V
/// itself is checked against the forces in `kinetostatics::loads`.)
#[test]
fn the_held_energy_counts_the_springs() {
    let spring = Load::Spring { a: (0, [0.0, -2.0]), b: (1, [1.0, 0.0]), stiffness: 40.0, free_length: 0.5 };
    let run = |held: bool| {
        let mut p = problem(pendulum(), vec![spring.clone()], vec![[0.0, 0.0]], End::Duration(5.0));
        p.conserve_energy = Some(held);
        let s = solve(&p).unwrap();
        assert_eq!(s.energy_conserved, held);
        s.solution.samples
    };
    let (held, free) = (run(true), run(false));
    assert!(held.iter().any(|x| x.angle < -1.0), "it swings");
    for (a, b) in held.iter().zip(&free) {
        close(a.angle, b.angle, 1e-7, "φ held against free");
    }
}

fn pendulum() -> Mechanism {
    Mechanism {
        bodies: vec![
            Body { name: "ground".into(), mass: 0.0, inertia: 0.0, cg: [0.0, 0.0] },
            Body { name: "bob".into(), mass: 1.0, inertia: 0.0, cg: [1.0, 0.0] },
        ],
        joints: vec![Joint {
            name: "O".into(),
            kind: JointKind::Revolute,
            bodies: [0, 1],
            at: [0.0, 0.0],
            friction: None,
            length: None,
        }],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// Seed 004's double pendulum (point masses m₁, m₂ on massless rods l₁, l₂)
/// with m₁ = 1 kg, m₂ = 2 kg, l₁ = 1 m, l₂ = 0.5 m, released from rest at
/// 30° and 60° below the horizontal. Reference: the Lagrange equations in the
/// absolute angles θ from the downward vertical, integrated here on their own
/// at 1e-13. The seed's printed equations drop g and flip the sign of the
/// velocity term; the correct ones are
/// (m₁+m₂)l₁θ̈₁ + m₂l₂θ̈₂cos(θ₁−θ₂) + m₂l₂θ̇₂² sin(θ₁−θ₂) + (m₁+m₂)g sin θ₁ = 0,
/// l₂θ̈₂ + l₁θ̈₁cos(θ₁−θ₂) − l₁θ̇₁² sin(θ₁−θ₂) + g sin θ₂ = 0.
/// Agreement 1e-6 rad over 3 s; the energy is conserved.
#[test]
fn double_pendulum_matches_its_lagrange_equations() {
    let (m1, m2, l1, l2, g) = (1.0, 2.0, 1.0, 0.5, 9.81);
    let point = |name: &str, mass: f64, x: f64| Body { name: name.into(), mass, inertia: 0.0, cg: [x, 0.0] };
    let pin = |name: &str, bodies: [usize; 2], x: f64| Joint {
        name: name.into(),
        kind: JointKind::Revolute,
        bodies,
        at: [x, 0.0],
        friction: None,
        length: None,
    };
    let m = Mechanism {
        bodies: vec![point("ground", 0.0, 0.0), point("m1", m1, l1), point("m2", m2, l1 + l2)],
        joints: vec![pin("O", [0, 1], 0.0), pin("A", [1, 2], l1)],
        // φ₁ the first rod's absolute angle from +x, φ₂ the second's relative to the first.
        drivers: vec![Driver::joint(0, 0.0), Driver::joint(1, 0.0)],
        gravity: [0.0, -g],
    };
    let (phi1, phi2) = (-PI / 6.0, -PI / 6.0);
    let mut p = problem(m, Vec::new(), vec![[phi1, 0.0], [phi2, 0.0]], End::Duration(3.0));
    p.samples = 31;
    let s = solve(&p).unwrap();

    let mut lagrange = |_t: f64, y: &[f64], dy: &mut [f64]| {
        let (t1, t2, w1, w2) = (y[0], y[1], y[2], y[3]);
        let (c, sn) = ((t1 - t2).cos(), (t1 - t2).sin());
        // [a b; c d] [θ̈₁; θ̈₂] = [e; f]
        let (a, b, e) = ((m1 + m2) * l1, m2 * l2 * c, -m2 * l2 * w2 * w2 * sn - (m1 + m2) * g * t1.sin());
        let (cc, d, f) = (l1 * c, l2, l1 * w1 * w1 * sn - g * t2.sin());
        let det = a * d - b * cc;
        dy[0] = w1;
        dy[1] = w2;
        dy[2] = (e * d - b * f) / det;
        dy[3] = (a * f - cc * e) / det;
    };
    let y0 = vec![PI / 2.0 + phi1, PI / 2.0 + phi1 + phi2, 0.0, 0.0];
    let mut ode = Dopri5::new(&mut lagrange, 0.0, y0, 1e-13, vec![1e-13; 4], f64::INFINITY);
    let mut k = 0;
    while k < s.details.len() {
        let step = ode.step(&mut lagrange, 1_000_000).unwrap();
        while k < s.details.len() && s.solution.samples[k].t <= step.t1 {
            let want = step.at(s.solution.samples[k].t);
            let [[f1, w1, _], [f2, w2, _]] = [s.details[k].inputs[0], s.details[k].inputs[1]];
            close(PI / 2.0 + f1, want[0], 1e-6, "θ₁");
            close(PI / 2.0 + f1 + f2, want[1], 1e-6, "θ₂");
            close(w1, want[2], 1e-5, "θ̇₁");
            close(w1 + w2, want[3], 1e-5, "θ̇₂");
            k += 1;
        }
    }
    assert!(s.solution.energy_residual.abs() < 1e-8, "{}", s.solution.energy_residual);
    assert_eq!(s.mobility.dof, 2);
}

/// A stiff spring (IFToMM A05-like): the pendulum's bob tied to the ground by
/// k = 10¹⁰ N/m, a mode at 4.5·10⁴ rad/s. Here the start excites it: the bob
/// rings about θₑ = −4.9 nrad with a speed of 2.2e-4 rad/s, far above the
/// tolerance, so every method must follow it (Radau IIA too: the automatic
/// choice does not find its steps held by stability, they are held by
/// accuracy). With a 0.3 s budget the 100 s run stops with the reason
/// instead of hanging. A stiff mode that is not excited: tests/engine/stiff.rs.
#[test]
fn a_stiff_spring_runs_out_of_its_budget_with_the_reason() {
    let mut p = problem(pendulum(), Vec::new(), vec![[0.0, 0.0]], End::Duration(100.0));
    p.loads = vec![Load::Spring { a: (1, [1.0, 0.0]), b: (0, [2.0, 0.0]), stiffness: 1e10, free_length: 0.9 }];
    p.deadline = Deadline::after(std::time::Duration::from_millis(300));
    match solve(&p) {
        Err(DynamicsError::Budget { t, steps, .. }) => assert!(t < 100.0 && steps > 0, "t = {t}, steps = {steps}"),
        other => panic!("expected the budget to run out: {other:?}"),
    }
}

/// A massless arm pinned at O carrying a point mass on a second arm pinned
/// at A, the two in line at the start: turning them opposite ways (the
/// elbow) moves the mass only radially, to first order not at all, so the
/// mass matrix is singular on the mechanism's motions. Answered at once
/// that the start is singular (it used to spend the whole budget halving
/// steps on a non-finite q̈).
#[test]
fn a_start_whose_motions_move_no_mass_is_refused_at_once() {
    let body = |name: &str, mass: f64, cg: [f64; 2]| Body { name: name.into(), mass, inertia: 0.0, cg };
    let revolute = |name: &str, bodies: [usize; 2], at: [f64; 2]| Joint {
        name: name.into(),
        kind: JointKind::Revolute,
        bodies,
        at,
        friction: None,
        length: None,
    };
    let m = Mechanism {
        bodies: vec![body("ground", 0.0, [0.0, 0.0]), body("arm", 0.0, [0.5, 0.0]), body("bob", 1.0, [2.0, 0.0])],
        joints: vec![revolute("O", [0, 1], [0.0, 0.0]), revolute("A", [1, 2], [1.0, 0.0])],
        drivers: vec![Driver::joint(0, 0.0), Driver::joint(1, 0.0)],
        gravity: [0.0, -9.81],
    };
    let mut p = problem(m, Vec::new(), vec![[0.0, 0.0]; 2], End::Duration(1.0));
    p.deadline = Deadline::after(std::time::Duration::from_secs(5));
    match solve(&p) {
        Err(DynamicsError::Initial { reason }) => assert_eq!(reason, Start::MovesNoMass),
        other => panic!("expected the start to be refused: {other:?}"),
    }
}

/// A mechanism whose budget is spent before it starts answers that the
/// budget ran out (not that its start cannot be assembled).
#[test]
fn a_spent_budget_is_reported_as_such_before_the_first_step() {
    let mut p = problem(pendulum(), Vec::new(), vec![[0.5, 0.0]], End::Duration(100.0));
    p.deadline = Deadline::after(std::time::Duration::ZERO);
    std::thread::sleep(std::time::Duration::from_millis(2));
    match solve(&p) {
        Err(DynamicsError::Budget { t, steps, .. }) => assert!(t == 0.0 && steps == 0, "t = {t}, steps = {steps}"),
        other => panic!("expected the budget to run out: {other:?}"),
    }
}

/// IFToMM A02's chain of N = 10 parallelograms (1 m, 1 kg bars; see
/// tests/api/four_bars.rs) from upright at 1.1 rad/s, tolerance 1e-9, 10 s.
/// The sparse form holding the folds itself takes ever smaller steps at a
/// flat position until they underflow; the run is then made again with the
/// dense form near the flat positions, and it is right: θ̇ at every sample
/// within 5e-7 rad/s of the energy closed form
/// θ̇² = ω₀² + 2(V(π/2) − V(θ))/I*, I* = (N+1)/3 + N, V = ((N+1)/2 + N)·g·sin θ.
/// From 6 rad/s the hold goes through. Which start needs the rerun depends
/// on rounding (from 1 rad/s it did until the start was assembled in
/// closed form, from 1.1 until the dense form's rows were scaled by the
/// mechanism's size; measured today from 0.5 to 6 rad/s, 0.5, 0.7 and
/// 1.15 do, the last two within 5.4e-7 rad/s — the sparse hold is within
/// 1e-7 wherever it goes through, but for 0.9 rad/s: 5.0e-7): a better
/// hold would make this fail for a good reason and want another case.
/// From 0.5 rad/s the chain comes out of a flat position folded (θ̇ off by
/// 4.7 rad/s, as it was before the scaling, by 13.6): a hard case still
/// open (issue 48).
#[test]
fn a02_gets_its_answer_where_the_sparse_hold_fails() {
    let n = 10.0;
    let speed = |theta: f64, w0: f64| {
        let v = |t: f64| ((n + 1.0) / 2.0 + n) * 9.81 * t.sin();
        (w0 * w0 + 2.0 * (v(PI / 2.0) - v(theta)) / ((n + 1.0) / 3.0 + n)).sqrt()
    };
    for (w0, hold) in [(1.15, false), (6.0, true)] {
        let mut p = problem(
            mechdyn::engine::samples::parallelogram_chain(10),
            Vec::new(),
            vec![[PI / 2.0, w0]],
            End::Duration(10.0),
        );
        (p.tolerance, p.samples, p.reactions) = (1e-9, 101, false);
        let s = solve(&p).expect("the chain turns");
        assert_eq!((s.sparse, s.sparse_hold), (true, hold), "from {w0} rad/s");
        for d in &s.details {
            let [theta, omega, _] = d.inputs[0];
            assert!(
                (omega - speed(theta, w0)).abs() < 5e-7,
                "from {w0} rad/s, θ = {theta}: θ̇ {omega} vs {}",
                speed(theta, w0)
            );
        }
    }
}

/// A run ending at an angle after more steps than it may keep is made again
/// to the end time it found, and reports what a run that kept them reports:
/// A02's chain of N = 4 from upright at 6 rad/s until it has turned once
/// (θ = π/2 + 2π), through both flat positions — where the held energy
/// may stop, so the second run must start as the first did. Each sample's θ̇
/// is also checked against the energy closed form (as in the test above,
/// within 1e-7 rad/s).
#[test]
fn a_run_to_an_angle_made_again_for_its_samples_reports_the_same_motion() {
    let n = 4.0;
    let speed = |theta: f64| {
        let v = |t: f64| ((n + 1.0) / 2.0 + n) * 9.81 * t.sin();
        // θ̇² = ω₀² + 2(V(π/2) − V(θ))/I*, ω₀ = 6 rad/s.
        (36.0 + 2.0 * (v(PI / 2.0) - v(theta)) / ((n + 1.0) / 3.0 + n)).sqrt()
    };
    let run = |kept_bytes: usize| {
        let end = End::UntilAngle { angle: PI / 2.0 + 2.0 * PI, max_time: 10.0 };
        let mut p = problem(mechdyn::engine::samples::parallelogram_chain(4), Vec::new(), vec![[PI / 2.0, 6.0]], end);
        (p.tolerance, p.reactions, p.kept_bytes) = (1e-9, false, kept_bytes);
        solve(&p).expect("the chain turns")
    };
    let (kept, again) = (run(KEPT_BYTES), run(0));
    assert!(!kept.solution.repeated && again.solution.repeated);
    let angles = || kept.details.iter().map(|d| d.inputs[0][0]);
    for flat in [PI, 2.0 * PI] {
        assert!(angles().any(|t| t < flat) && angles().any(|t| t > flat), "it passes the flat position {flat}");
    }
    assert_eq!(again.solution.steps, 2 * kept.solution.steps, "the steps of both runs");
    assert_eq!(kept.solution.samples, again.solution.samples);
    assert_eq!(kept.details, again.details);
    assert_eq!((kept.near_singular, kept.energy_conserved), (again.near_singular, again.energy_conserved));
    for d in &kept.details {
        let [theta, omega, _] = d.inputs[0];
        assert!((omega - speed(theta)).abs() < 1e-7, "θ = {theta}: θ̇ {omega} vs {}", speed(theta));
    }
}
