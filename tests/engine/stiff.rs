//! Stiff mechanisms: a spring so stiff that an explicit method's steps are
//! held by its period, integrated by Radau IIA (asked for, or handed over
//! to when the automatic choice finds the model stiff), each against a
//! closed form.

use crate::elliptic::{complete_k, sn};
use mechdyn::engine::Deadline;
use mechdyn::engine::dynamics::mechanism::{MechanismProblem, solve};
use mechdyn::engine::dynamics::{DynamicsError, End, Integrator, KEPT_BYTES};
use mechdyn::engine::kinetostatics::Load;
use mechdyn::engine::model::Mechanism;
use mechdyn::engine::samples;
use std::f64::consts::PI;

fn problem(mechanism: Mechanism, loads: Vec<Load>, duration: f64) -> MechanismProblem {
    let initial = vec![[0.0, 0.0]; mechanism.drivers.len()];
    MechanismProblem {
        mechanism,
        loads,
        period: 2.0 * PI,
        initial,
        end: End::Duration(duration),
        tolerance: 1e-6,
        integrator: None,
        conserve_energy: None,
        samples: 101,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
        reactions: false,
        motion: false,
    }
}

/// IFToMM A01's pendulum made elastic (`samples::elastic_pendulum`): the
/// bob on a slide along a massless arm, held at 1 m by k = 10¹⁰ N/m. The
/// radial mode (√(k/m) = 10⁵ rad/s) is the stiff one; the swing stretches
/// the spring by at most 3mg/k = 3 nm, so the swing is the rigid
/// pendulum's to ~1e-8: sin(θ/2) = k·sn(K − t√(g/L), k).
fn elastic_pendulum() -> (Mechanism, Vec<Load>) {
    let spring = Load::Spring { a: (1, [0.0, 0.0]), b: (2, [1.0, 0.0]), stiffness: 1e10, free_length: 1.0 };
    (samples::elastic_pendulum(), vec![spring])
}

/// The elastic pendulum over 5 s (about 2.4 swings) at tolerance 1e-6:
/// chosen automatically, Dormand–Prince finds it stiff within its first
/// steps and hands over to Radau IIA, which follows the swing in under
/// 3000 steps (measured 1658; Dormand–Prince asked for takes 665 300, 30×
/// the time) to 1e-6 rad of the rigid pendulum's closed form (measured
/// 3.2e-8, the elasticity's own share); the slide stays within the 3 nm
/// stretch; asked for by name, Radau IIA gives the same swing.
#[test]
fn an_elastic_pendulum_swings_as_the_rigid_one_with_radau() {
    let k = (PI / 4.0).sin();
    let kk = complete_k(k);
    let (mechanism, loads) = elastic_pendulum();
    let mut p = problem(mechanism, loads, 5.0);
    let auto = solve(&p).unwrap();
    p.integrator = Some(Integrator::Radau5);
    let asked = solve(&p).unwrap();
    assert_eq!(auto.solution.integrator, Integrator::Radau5);
    assert!(auto.solution.stiff_at.is_some_and(|t| t < 1e-2), "{:?}", auto.solution.stiff_at);
    assert_eq!((asked.solution.integrator, asked.solution.stiff_at), (Integrator::Radau5, None));
    for s in [&auto, &asked] {
        let mut worst = 0.0f64;
        for (x, d) in s.solution.samples.iter().zip(&s.details) {
            let want = 2.0 * (k * sn(kk - x.t * 9.81f64.sqrt(), k)).asin();
            worst = worst.max((PI / 2.0 + x.angle - want).abs());
            let stretch = d.inputs[1][0];
            assert!(stretch.abs() <= 3.0 * 9.81 / 1e10 * 1.01, "stretch {stretch} m at t = {}", x.t);
        }
        assert!(worst < 1e-6, "largest angle error {worst} rad");
        assert!(s.solution.steps < 3000, "{} steps", s.solution.steps);
    }
}

/// The same elastic pendulum over 0.2 s by Dormand–Prince, asked for (so
/// it does not hand over): its steps held to |hλ| < 3.3 (λ ≈ 10⁵ rad/s), it
/// takes tens of times Radau IIA's steps and lands on the same swing, to
/// 1e-8 rad at every sample (two methods, one model; measured 1.0e-9); with a 0.1 s budget
/// over 100 s it runs out of it with the reason.
#[test]
fn dormand_prince_agrees_on_the_elastic_pendulum_at_many_times_the_steps() {
    let (mechanism, loads) = elastic_pendulum();
    let mut p = problem(mechanism, loads, 0.2);
    p.integrator = Some(Integrator::Radau5);
    let radau = solve(&p).unwrap();
    p.integrator = Some(Integrator::Dopri5);
    let explicit = solve(&p).unwrap();
    for (a, b) in radau.solution.samples.iter().zip(&explicit.solution.samples) {
        assert!((a.angle - b.angle).abs() < 1e-8, "t = {}: {} vs {}", a.t, a.angle, b.angle);
    }
    let (r, e) = (radau.solution.steps, explicit.solution.steps);
    assert!(e > 20 * r, "Dormand–Prince {e} steps, Radau IIA {r}");

    (p.end, p.deadline) = (End::Duration(100.0), Deadline::after(std::time::Duration::from_millis(100)));
    match solve(&p) {
        Err(DynamicsError::Budget { t, steps, .. }) => assert!(t < 100.0 && steps > 0, "t = {t}, steps = {steps}"),
        other => panic!("expected the budget to run out: {other:?}"),
    }
}
