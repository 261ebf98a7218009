//! Inputs where the statement puts them (a point along a direction, a
//! body's rotation) with the effort at another joint, checked against the
//! same mechanism driven at that joint: a second method on the same
//! positions. A crank-driven sweep gives the other coordinate's motion
//! (position, speed, acceleration); the mechanism driven by that coordinate,
//! its actuator the crank, must reach the same configurations and need the
//! same crank torque and reactions (to 1e-9 of the largest force).

use mechdyn::engine::kinetostatics::{Motion, Outputs, Solution, point_acceleration, point_motion, solve};
use mechdyn::engine::model::{Coordinate, Driver, Mechanism, dot};
use mechdyn::engine::samples::{elastic_pendulum, four_bar};
use mechdyn::engine::{Deadline, EngineError};

fn all() -> Outputs {
    Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false }
}

/// The crank (joint 0) turning at 10 rad/s, speeding up at 30 rad/s², over `angles`.
fn crank_driven(m: &Mechanism, angles: &[f64]) -> Solution {
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, 10.0, 30.0]]).collect();
    solve(m, &[], &positions, all(), &Deadline::none()).unwrap()
}

/// `m` driven by `driver` through the positions (coordinate, speed,
/// acceleration) that `coordinate` reads off each step of `by_crank`.
fn driven_by(m: &Mechanism, driver: Driver, by_crank: &Solution, coordinate: impl Fn(&Motion) -> [f64; 3]) -> Solution {
    let positions: Vec<Vec<[f64; 3]>> =
        by_crank.steps.iter().map(|s| vec![coordinate(s.kinematics.as_ref().unwrap())]).collect();
    let m = Mechanism { drivers: vec![driver], ..m.clone() };
    solve(&m, &[], &positions, all(), &Deadline::none()).unwrap()
}

/// Crank angles from the drawing to before the rocker's first extreme
/// (near 0.72 rad): B's position across the rocker says where the crank is.
const BEFORE_THE_ROCKER_TURNS: [f64; 5] = [0.1, 0.2, 0.3, 0.4, 0.5];

/// The four-bar's joint B on the rocker (body 3), and the direction
/// across the rocker there as drawn (B's motion is along it at first).
fn rocker_point(m: &Mechanism) -> (Coordinate, impl Fn(&Motion) -> [f64; 3]) {
    let (b, o4) = (m.joints[2].at, m.joints[3].at);
    let r = (b[0] - o4[0]).hypot(b[1] - o4[1]);
    let u = [-(b[1] - o4[1]) / r, (b[0] - o4[0]) / r];
    let along = move |k: &Motion| {
        let (p, v) = point_motion(m, &k.q, &k.qd, (3, b));
        let a = point_acceleration(m, &k.q, &k.qd, &k.qdd, (3, b));
        [dot(u, [p[0] - b[0], p[1] - b[1]]), dot(u, v), dot(u, a)]
    };
    (Coordinate::Point { body: 3, at: b, direction: u }, along)
}

fn assert_same(a: &Solution, b: &Solution, what: &str) {
    for (k, (x, y)) in a.steps.iter().zip(&b.steps).enumerate() {
        let scale = x.reactions.iter().map(|r| r.fx.hypot(r.fy)).fold(1.0, f64::max);
        let (qx, qy) = (&x.kinematics.as_ref().unwrap().q, &y.kinematics.as_ref().unwrap().q);
        assert!(qx.iter().zip(qy).all(|(u, v)| (u - v).abs() < 1e-10), "{what}, step {k}: q {qx:?} vs {qy:?}");
        let close = |u: f64, v: f64| (u - v).abs() <= 1e-9 * scale;
        assert!(close(x.driving[0], y.driving[0]), "{what}, step {k}: torque {} vs {}", x.driving[0], y.driving[0]);
        assert!(close(y.driving_virtual_power[0], y.driving[0]), "{what}, step {k}: by virtual power");
        for (r, s) in x.reactions.iter().zip(&y.reactions) {
            assert!(
                close(r.fx, s.fx) && close(r.fy, s.fy) && close(r.moment, s.moment),
                "{what}, step {k}: {r:?} vs {s:?}"
            );
        }
    }
}

/// The four-bar's coupler rotation as the input, the crank's joint O2 the
/// actuator (the coupler's angle is column 5: body 2's θ, 0 as drawn).
#[test]
fn a_body_input_with_the_crank_as_actuator_needs_the_crank_driven_torque() {
    let m = four_bar();
    let by_crank = crank_driven(&m, &[0.3, 0.45, 0.6, 0.75, 0.9]);
    let driver = Driver { coordinate: Coordinate::Body(2), reference: 0.0, actuator: Some(0) };
    let by_coupler = driven_by(&m, driver, &by_crank, |k| [k.q[5], k.qd[5], k.qdd[5]]);
    assert_same(&by_crank, &by_coupler, "coupler rotation");
}

/// The four-bar's point B of the rocker moving across the rocker as the
/// input, the crank's joint O2 the actuator.
#[test]
fn a_point_input_with_the_crank_as_actuator_needs_the_crank_driven_torque() {
    let m = four_bar();
    let by_crank = crank_driven(&m, &BEFORE_THE_ROCKER_TURNS);
    let (on_rocker, along) = rocker_point(&m);
    let by_point = driven_by(&m, Driver { coordinate: on_rocker, reference: 0.0, actuator: Some(0) }, &by_crank, along);
    assert_same(&by_crank, &by_point, "rocker point");
}

/// Without an actuator a point input's effort is the force along its
/// direction at the point: it delivers the crank-driven power, F·v = T·ω.
#[test]
fn a_point_input_alone_is_driven_by_a_force_of_the_same_power() {
    let m = four_bar();
    let by_crank = crank_driven(&m, &BEFORE_THE_ROCKER_TURNS);
    let (on_rocker, along) = rocker_point(&m);
    let by_force = driven_by(&m, Driver { coordinate: on_rocker, reference: 0.0, actuator: None }, &by_crank, &along);
    for (x, y) in by_crank.steps.iter().zip(&by_force.steps) {
        let v = along(y.kinematics.as_ref().unwrap())[1];
        let (power, by_torque) = (y.driving[0] * v, x.driving[0] * 10.0);
        assert!((power - by_torque).abs() < 1e-9 * by_torque.abs().max(1.0), "{power} vs {by_torque}");
        assert!((y.driving_virtual_power[0] - y.driving[0]).abs() < 1e-9 * y.driving[0].abs().max(1.0));
    }
}

/// Two inputs sharing one actuator: the joint O alone cannot hold both the
/// swing and the stretch of the elastic pendulum, which is said, not solved.
#[test]
fn actuators_that_cannot_drive_the_inputs_are_an_error() {
    let mut m = elastic_pendulum();
    m.drivers[1].actuator = Some(0);
    let positions = vec![vec![[0.1, 1.0, 0.0], [0.0, 0.1, 0.0]]];
    match solve(&m, &[], &positions, all(), &Deadline::none()) {
        Err(EngineError::Unactuated { step: 0, actuators, .. }) => assert_eq!(actuators, "O"),
        other => panic!("{other:?}"),
    }
}
