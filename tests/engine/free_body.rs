//! Every body's free-body diagram balances with the reactions as reported:
//! the forces and couples of its joints (the force on the second body at
//! the joint's point and its opposite on the first), the driving action at
//! its actuator (the input joint, or the joint named as the actuator), gravity, and d'Alembert's inertia forces −m a_G and
//! −I_G α, with Coulomb friction in every kind of joint (revolute,
//! prismatic, pin-in-slot). Independent of how the engine solves: the sums
//! are made here from the reported numbers and the bodies' motion only.
//! Tolerance 1e-9 of the largest force (or moment) in the diagram.

use mechdyn::engine::Deadline;
use mechdyn::engine::kinetostatics::{Outputs, Step, solve};
use mechdyn::engine::model::{Coordinate, Friction, JointKind, Mechanism, rotate};
use mechdyn::engine::samples::{offset_slider_crank, scotch_yoke};

/// The residual of body `b`'s equilibrium at `step`: (force, moment about
/// G), each relative to the largest term in it.
fn residual(m: &Mechanism, step: &Step, b: usize) -> (f64, f64) {
    let motion = step.kinematics.as_ref().unwrap();
    let pose = |k: usize| m.column(k).map_or([0.0; 3], |c| [motion.q[c], motion.q[c + 1], motion.q[c + 2]]);
    let [x, y, _] = pose(b);
    let col = m.column(b).unwrap();
    let (mass, inertia) = (m.bodies[b].mass, m.bodies[b].inertia);
    let mut terms: Vec<([f64; 2], [f64; 2], f64)> = vec![
        ([x, y], [mass * m.gravity[0], mass * m.gravity[1]], 0.0),
        ([x, y], [-mass * motion.qdd[col], -mass * motion.qdd[col + 1]], -inertia * motion.qdd[col + 2]),
    ];
    let point = |k: usize, at: [f64; 2]| {
        let [xk, yk, tk] = pose(k);
        let r = rotate(tk, m.local(k, at));
        [xk + r[0], yk + r[1]]
    };
    for r in &step.reactions {
        let joint = &m.joints[r.joint];
        // A contact's reaction acts where its curves touch now.
        let at = point(r.on, m.contact_point(r.joint, r.on, &motion.q).unwrap_or(joint.at));
        if r.on == b {
            terms.push((at, [r.fx, r.fy], r.moment));
        } else if r.by == b {
            terms.push((at, [-r.fx, -r.fy], -r.moment));
        }
    }
    for (driver, action) in m.drivers.iter().zip(&step.driving) {
        let own = match driver.coordinate {
            Coordinate::Joint(k) => Some(k),
            _ => None,
        };
        let joint = &m.joints[driver.actuator.or(own).expect("an actuator")];
        let [i, j] = joint.bodies;
        let sign = if j == b {
            1.0
        } else if i == b {
            -1.0
        } else {
            continue;
        };
        match joint.kind {
            JointKind::Revolute => terms.push((point(j, joint.at), [0.0, 0.0], sign * action)),
            JointKind::Prismatic { axis } => {
                let u = rotate(pose(i)[2], axis);
                terms.push((point(j, joint.at), [sign * action * u[0], sign * action * u[1]], 0.0));
            }
            _ => unreachable!("driven joints here are revolute or prismatic"),
        }
    }
    let (mut f, mut moment, mut f_scale, mut m_scale) = ([0.0; 2], 0.0, 0.0f64, 0.0f64);
    for (at, force, couple) in terms {
        let arm = [at[0] - x, at[1] - y];
        let about_g = arm[0] * force[1] - arm[1] * force[0] + couple;
        f = [f[0] + force[0], f[1] + force[1]];
        moment += about_g;
        f_scale = f_scale.max(force[0].hypot(force[1]));
        m_scale = m_scale.max(about_g.abs()).max(couple.abs());
    }
    (f[0].hypot(f[1]) / f_scale.max(1e-300), moment.abs() / m_scale.max(1e-300))
}

/// Solves `m` over a turn of its crank at ω = 10 rad/s, α = 30 rad/s² and
/// checks every moving body at every step; the friction must change the
/// driving action (or the test would not test it).
fn balances(m: Mechanism) {
    let positions: Vec<Vec<[f64; 3]>> =
        (0..24).map(|k| vec![[f64::from(k) * std::f64::consts::TAU / 24.0 + 0.1, 10.0, 30.0]]).collect();
    balances_over(m, &positions);
}

/// [`balances`] over the given positions of its input.
fn balances_over(mut m: Mechanism, positions: &[Vec<[f64; 3]>]) {
    let outputs = Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false };
    let without = solve(&m, &[], positions, outputs, &Deadline::none()).unwrap();
    for joint in &mut m.joints {
        joint.friction = Some(Friction { mu: 0.3, radius: 0.02 });
    }
    let with = solve(&m, &[], positions, outputs, &Deadline::none()).unwrap();
    let changed = with.steps.iter().zip(&without.steps).any(|(a, b)| (a.driving[0] - b.driving[0]).abs() > 1e-3);
    assert!(changed, "friction changes the driving torque");
    for step in &with.steps {
        assert!(step.friction_iterations > 0);
        for b in 1..m.bodies.len() {
            let (force, moment) = residual(&m, step, b);
            assert!(
                force < 1e-9 && moment < 1e-9,
                "{} at φ = {}: force {force:e}, moment {moment:e}",
                m.bodies[b].name,
                step.input[0]
            );
        }
    }
}

/// Revolute, prismatic and pin-in-slot joints, each with friction.
#[test]
fn every_body_balances_with_friction_in_every_joint_of_a_scotch_yoke() {
    balances(scotch_yoke());
}

/// Three revolute joints and a prismatic guide, each with friction, under gravity.
#[test]
fn every_body_balances_with_friction_in_every_joint_of_a_slider_crank() {
    balances(offset_slider_crank());
}

/// Seed 002's scissor lift as its statement puts it: the platform's point C
/// descending at 0.3 m/s is the input, the piston (a prismatic joint) the
/// actuator; friction in every joint, the platform lowered 0.2 m.
#[test]
fn every_body_balances_in_a_scissor_lift_driven_by_its_platform_with_the_piston_as_actuator() {
    let mut m = mechdyn::engine::samples::scissor_lift();
    let c = m.joints[2].at;
    m.drivers[0].coordinate = Coordinate::Point { body: 3, at: c, direction: [0.0, -1.0] };
    m.drivers[0].actuator = Some(5);
    let positions: Vec<Vec<[f64; 3]>> = (0..8).map(|k| vec![[0.025 * f64::from(k), 0.3, 0.0]]).collect();
    balances_over(m, &positions);
}

/// A higher pair: the eccentric cam under its flat follower, with friction
/// at the contact (against the sliding there), the pin and the guide.
#[test]
fn every_body_balances_with_friction_in_an_eccentric_cam() {
    balances(mechdyn::engine::samples::eccentric_cam());
}
