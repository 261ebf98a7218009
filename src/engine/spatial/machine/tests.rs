//! The spatial machine's I*, dI*/dφ and M* against the closed forms of a
//! Hooke's joint and against differences of its own I*.

use super::SpatialMachine;
use crate::engine::Deadline;
use crate::engine::function::Function;
use crate::engine::machine::{Reduced, Reduces};
use crate::engine::spatial::{Body, Coordinate, Input, Joint, JointKind, LoadLaw, Mechanism};
use nalgebra::{Matrix3, Vector3};
use std::f64::consts::PI;

/// Two shafts at β = 0.5 rad joined by a cross at O: the input (I₁ about
/// its axis x, 2 kg on it) and the output (I₂ about e₂ = (cos β, sin β, 0),
/// 3 kg on it), each with some inertia across its axis (which must not
/// count), gravity along −y (its centres on the axes: no work), and a
/// torque T = 7 N·m against the output.
fn shafts(reference: f64) -> SpatialMachine {
    let (beta, i1, i2): (f64, f64, f64) = (0.5, 0.02, 0.05);
    let e2 = Vector3::new(beta.cos(), beta.sin(), 0.0);
    let across = |axis: Vector3<f64>, along: f64| Matrix3::identity() * 0.3 + axis * axis.transpose() * (along - 0.3);
    let body = |name: &str, mass: f64, inertia, cg| Body { name: name.into(), mass, inertia, cg };
    let joint = |name: &str, bodies, kind| Joint { name: name.into(), bodies, at: Vector3::zeros(), kind };
    let m = Mechanism {
        bodies: vec![
            body("input", 2.0, across(Vector3::x(), i1), Vector3::new(-0.1, 0.0, 0.0)),
            body("output", 3.0, across(e2, i2), e2 * 0.1),
        ],
        joints: vec![
            joint("A", [0, 1], JointKind::Revolute { axis: Vector3::x() }),
            joint("B", [0, 2], JointKind::Revolute { axis: e2 }),
            joint("cross", [1, 2], JointKind::Universal { axes: [Vector3::y(), Vector3::z()] }),
        ],
        inputs: vec![Input { joint: 0, coordinate: Coordinate::Rotation }],
        gravity: Vector3::new(0.0, -9.81, 0.0),
    };
    let torque = LoadLaw::Torque { body: 2, axis: -e2, value: Function::Constant(7.0) };
    SpatialMachine::new(m, vec![torque], (10.0, 2.0 * PI, reference), Deadline::none()).unwrap()
}

/// ω₂/ω₁ = r(θ) = cos β / (1 − sin²β·cos²θ) (θ the input's rotation from
/// the drawing) and its slope r′ = −cos β·sin²β·sin 2θ / (1 − sin²β·cos²θ)²:
/// I* = I₁ + I₂·r², dI*/dφ = 2·I₂·r·r′, M* = −T·r (the output's torque's
/// power per unit input speed). To 1e-9 of the values' size, with the
/// drawing at φ = 0 and at φ = 0.3 (the closed form then at θ = φ − 0.3).
#[test]
fn a_hooke_joint_reduces_as_its_closed_form() {
    let (beta, i1, i2, t): (f64, f64, f64, f64) = (0.5, 0.02, 0.05, 7.0);
    let (sb, cb) = (beta.sin(), beta.cos());
    for reference in [0.0, 0.3] {
        let m = shafts(reference);
        for k in 0..24 {
            let phi = 0.1 + k as f64 * PI / 12.0;
            let theta = phi - reference;
            let d = 1.0 - sb * sb * theta.cos().powi(2);
            let (r, slope) = (cb / d, -cb * sb * sb * (2.0 * theta).sin() / (d * d));
            let expected = [i1 + i2 * r * r, 2.0 * i2 * r * slope, -t * r];
            let got = [Reduced::Inertia, Reduced::InertiaSlope, Reduced::Torque].map(|w| m.eval(phi, w));
            for (g, x) in got.iter().zip(expected) {
                assert!((g - x).abs() < 1e-9 * x.abs().max(0.1), "φ = {phi}, ρ = {reference}: {got:?} vs {expected:?}");
            }
        }
    }
}

/// dI*/dφ against a central difference of I* (h = 1e-5, error O(h²·I‴) ≈ 1e-11),
/// past a full turn too (φ = 7 is φ = 7 − 2π).
#[test]
fn the_slope_matches_a_difference_of_the_inertia() {
    let m = shafts(0.3);
    for phi in [0.2, 1.3, 2.9, 4.4, 7.0] {
        let h = 1e-5;
        let difference = (m.eval(phi + h, Reduced::Inertia) - m.eval(phi - h, Reduced::Inertia)) / (2.0 * h);
        let slope = m.eval(phi, Reduced::InertiaSlope);
        assert!((difference - slope).abs() < 1e-8, "φ = {phi}: {slope} vs {difference}");
    }
}
