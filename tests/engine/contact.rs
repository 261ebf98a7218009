//! A higher pair against its closed form: the eccentric circular cam under
//! a flat-faced follower (`samples::eccentric_cam`: disk R = 0.05 m, its
//! centre e = 0.02 m from the pivot O, the follower 2 kg on a vertical
//! guide, gravity 9.81 m/s²) is a Scotch yoke: the lift is e(1 − cos θ),
//! the contact lies e·sin θ along the face, and at constant ω the normal
//! force is N = m(g + eω² cos θ), the driving torque N·e·sin θ (the cam's
//! centre of mass on its pivot does not load it), the contact's reaction on
//! the follower (0, N) with no couple about the contact point.

use mechdyn::engine::Deadline;
use mechdyn::engine::kinetostatics::{Outputs, solve};
use mechdyn::engine::samples::eccentric_cam;

#[test]
fn an_eccentric_cam_under_a_flat_follower_is_a_scotch_yoke() {
    let (e, m, g, w) = (0.02, 2.0, 9.81, 10.0);
    let mechanism = eccentric_cam();
    let angles: Vec<f64> = (0..12).map(|k| 0.1 + 0.5 * f64::from(k)).collect();
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, w, 0.0]]).collect();
    let outputs = Outputs { driving: true, reactions: true, reduced: true, kinematics: true, condition: false };
    let solution = solve(&mechanism, &[], &positions, outputs, &Deadline::none()).unwrap();
    assert_eq!(solution.totals.mobility.dof, 1);
    for (theta, step) in angles.iter().zip(&solution.steps) {
        let k = step.kinematics.as_ref().unwrap();
        let (s, c) = theta.sin_cos();
        let n = m * (g + e * w * w * c);
        let close = |got: f64, want: f64, scale: f64, what: &str| {
            assert!((got - want).abs() < 1e-9 * scale, "θ = {theta}: {what} {got} vs {want}");
        };
        close(k.q[4] - 0.1, e * (1.0 - c), e, "lift");
        close(k.qd[4], e * w * s, e * w, "follower speed");
        close(k.qdd[4], e * w * w * c, e * w * w, "follower acceleration");
        close(k.q[7], e * s, e, "the contact along the face");
        close(step.driving[0], n * e * s, m * g * e, "driving torque");
        close(step.driving_virtual_power[0], n * e * s, m * g * e, "driving torque by virtual power");
        let contact = &step.reactions[2];
        close(contact.fx, 0.0, m * g, "tangential reaction");
        close(contact.fy, n, m * g, "normal reaction");
        close(contact.moment, 0.0, m * g * e, "couple about the contact point");
    }
}

/// The same cam left free: the follower's weight turns it from 0.5 rad at
/// rest, through the contact alone. Only gravity works, so every sample's
/// T + V is the first's (1e-8 of m g e: tolerance 1e-10, the energy not
/// held by projection), while T grows past a tenth of that scale; the
/// follower stays on the cam (its lift is e(1 − cos θ) of the cam's angle).
#[test]
fn a_free_cam_turned_by_its_follower_keeps_its_energy() {
    use mechdyn::engine::dynamics::mechanism::{MechanismProblem, solve as integrate};
    use mechdyn::engine::dynamics::{End, KEPT_BYTES};
    let (e, m, g) = (0.02, 2.0, 9.81);
    let problem = MechanismProblem {
        mechanism: eccentric_cam(),
        loads: Vec::new(),
        period: std::f64::consts::TAU,
        initial: vec![[0.5, 0.0]],
        end: End::Duration(0.5),
        tolerance: 1e-10,
        integrator: None,
        conserve_energy: Some(false),
        samples: 11,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
        reactions: true,
        motion: true,
    };
    let run = integrate(&problem).unwrap();
    let energy = |k: usize| {
        let d = &run.details[k].energy;
        d.kinetic + d.gravity + d.springs
    };
    let scale = m * g * e;
    let mut moved = 0.0f64;
    for k in 0..run.details.len() {
        assert!((energy(k) - energy(0)).abs() < 1e-8 * scale, "sample {k}: {} vs {}", energy(k), energy(0));
        moved = moved.max(run.details[k].energy.kinetic);
        let q = &run.details[k].motion.as_ref().unwrap().q;
        assert!((q[4] - 0.1 - e * (1.0 - q[2].cos())).abs() < 1e-9 * e, "sample {k}: off the cam");
    }
    assert!(moved > 0.1 * scale, "it turns: T reached {moved} J");
}
