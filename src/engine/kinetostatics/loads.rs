//! Loads on a mechanism and their generalized forces Q.

use crate::engine::function::{Function, Side};
use crate::engine::model::{BodyId, Mechanism, cross, dot, rotate, rotate_by, rotate_d};
use nalgebra::DVector;

/// A load on a body; functions take the first input coordinate φ (and, in
/// direct dynamics, its speed ω and the time t).
#[derive(Clone, Debug)]
pub enum Load {
    /// A force of signed `magnitude` along the unit `direction` (fixed in the
    /// ground), applied at the body's point `at` (reference coordinates).
    Force { body: BodyId, at: [f64; 2], direction: [f64; 2], magnitude: Function },
    /// A couple on the body (counter-clockwise positive).
    Torque { body: BodyId, value: Function },
    /// A linear spring between point `a` of one body and `b` of another:
    /// tension k·(L − L₀) along the line between them.
    Spring { a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2]), stiffness: f64, free_length: f64 },
    /// A linear damper: tension c·dL/dt along the line between the points.
    Damper { a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2]), coefficient: f64 },
}

/// Generalized applied forces Q at a configuration (velocities `qd` for
/// dampers), with the loads' functions at φ and `[ω, t]`.
pub fn applied_forces(m: &Mechanism, loads: &[Load], q: &[f64], qd: &[f64], phi: f64, state: [f64; 2]) -> DVector<f64> {
    let (mut qv, mut trig) = (Vec::new(), Vec::new());
    m.turns_into(q, &mut trig);
    applied_forces_into(m, loads, (q, &trig), qd, phi, state, &mut qv);
    DVector::from_vec(qv)
}

/// [`applied_forces`] into `qv`, reusing its storage, with (sin θ, cos θ)
/// of every body at q (ground first) in `trig`.
pub fn applied_forces_into(
    m: &Mechanism,
    loads: &[Load],
    (q, trig): (&[f64], &[(f64, f64)]),
    qd: &[f64],
    phi: f64,
    state: [f64; 2],
    qv: &mut Vec<f64>,
) {
    qv.clear();
    qv.resize(m.n_coordinates(), 0.0);
    let mut apply = |b: BodyId, at: [f64; 2], f: [f64; 2], couple: f64| add_force(m, trig, qv, b, at, f, couple);
    for (b, body) in m.bodies.iter().enumerate() {
        apply(b, body.cg, [body.mass * m.gravity[0], body.mass * m.gravity[1]], 0.0);
    }
    for load in loads {
        match load {
            Load::Force { body, at, direction, magnitude } => {
                let f = magnitude.eval_at(phi, Side::Right, state);
                apply(*body, *at, [f * direction[0], f * direction[1]], 0.0);
            }
            Load::Torque { body, value } => {
                apply(*body, [0.0, 0.0], [0.0, 0.0], value.eval_at(phi, Side::Right, state))
            }
            Load::Spring { a, b, stiffness, free_length } => {
                let (u, length, _) = line(m, q, qd, *a, *b);
                let t = stiffness * (length - free_length);
                apply(a.0, a.1, [t * u[0], t * u[1]], 0.0);
                apply(b.0, b.1, [-t * u[0], -t * u[1]], 0.0);
            }
            Load::Damper { a, b, coefficient } => {
                let (u, _, rate) = line(m, q, qd, *a, *b);
                let t = coefficient * rate;
                apply(a.0, a.1, [t * u[0], t * u[1]], 0.0);
                apply(b.0, b.1, [-t * u[0], -t * u[1]], 0.0);
            }
        }
    }
}

/// Unit vector from point a to point b, their distance and its rate.
fn line(m: &Mechanism, q: &[f64], qd: &[f64], a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2])) -> ([f64; 2], f64, f64) {
    let (pa, va) = point_motion(m, q, qd, a);
    let (pb, vb) = point_motion(m, q, qd, b);
    let d = [pb[0] - pa[0], pb[1] - pa[1]];
    let length = d[0].hypot(d[1]);
    let u = if length > 0.0 { [d[0] / length, d[1] / length] } else { [0.0, 0.0] };
    (u, length, u[0] * (vb[0] - va[0]) + u[1] * (vb[1] - va[1]))
}

/// Position and velocity of a body point (reference coordinates `p`).
pub fn point_motion(m: &Mechanism, q: &[f64], qd: &[f64], (b, p): (BodyId, [f64; 2])) -> ([f64; 2], [f64; 2]) {
    let trig = m.column(b).map_or((0.0, 1.0), |c| q[c + 2].sin_cos());
    point_motion_by(m, q, qd, (b, p), trig)
}

/// The same with the body's (sin θ, cos θ) known.
pub fn point_motion_by(
    m: &Mechanism,
    q: &[f64],
    qd: &[f64],
    (b, p): (BodyId, [f64; 2]),
    trig: (f64, f64),
) -> ([f64; 2], [f64; 2]) {
    let Some(c) = m.column(b) else { return (p, [0.0, 0.0]) };
    let s = m.local(b, p);
    let (a, ds) = (rotate_by(trig, s), rotate_by(trig, [-s[1], s[0]]));
    ([q[c] + a[0], q[c + 1] + a[1]], [qd[c] + ds[0] * qd[c + 2], qd[c + 1] + ds[1] * qd[c + 2]])
}

/// Acceleration of a body point (reference coordinates `p`): a_G + α k×s − ω² s,
/// s the point from G in the ground's axes.
pub fn point_acceleration(m: &Mechanism, q: &[f64], qd: &[f64], qdd: &[f64], (b, p): (BodyId, [f64; 2])) -> [f64; 2] {
    let Some(c) = m.column(b) else { return [0.0, 0.0] };
    let local = m.local(b, p);
    let (s, ds) = (rotate(q[c + 2], local), rotate_d(q[c + 2], local));
    let (omega, alpha) = (qd[c + 2], qdd[c + 2]);
    [qdd[c] + ds[0] * alpha - s[0] * omega * omega, qdd[c + 1] + ds[1] * alpha - s[1] * omega * omega]
}

/// Adds to Q a force f at point `at` (reference coordinates) of body b,
/// plus a couple; `trig` holds (sin θ, cos θ) of every body, ground first.
pub fn add_force(
    m: &Mechanism,
    trig: &[(f64, f64)],
    qv: &mut [f64],
    b: BodyId,
    at: [f64; 2],
    f: [f64; 2],
    couple: f64,
) {
    if let Some(c) = m.column(b) {
        let arm = rotate_by(trig[b], m.local(b, at));
        qv[c] += f[0];
        qv[c + 1] += f[1];
        qv[c + 2] += cross(arm, f) + couple;
    }
}

impl Load {
    /// Whether the load has a potential energy: a spring, and a force or a
    /// torque of constant value (not one that varies with φ, ω or t, nor a damper).
    pub fn has_potential(&self) -> bool {
        match self {
            Load::Spring { .. } => true,
            Load::Force { magnitude: f, .. } | Load::Torque { value: f, .. } => f.constant().is_some(),
            Load::Damper { .. } => false,
        }
    }
}

/// The potential energy V(q) = −Σ m·g·r_G + Σ ½k(L − L₀)² − Σ F·r_P − Σ τ·θ
/// of gravity, the springs and the constant forces and torques, when every
/// load has one (None otherwise).
pub fn potential(m: &Mechanism, loads: &[Load], q: &[f64]) -> Option<f64> {
    let zeros = vec![0.0; q.len()];
    let at = |b: BodyId, p: [f64; 2]| point_motion(m, q, &zeros, (b, p)).0;
    let mut v = 0.0;
    for (b, body) in m.bodies.iter().enumerate() {
        v -= body.mass * dot(m.gravity, at(b, body.cg));
    }
    for load in loads {
        v += match load {
            Load::Spring { a, b, stiffness, free_length } => {
                0.5 * stiffness * (line(m, q, &zeros, *a, *b).1 - free_length).powi(2)
            }
            Load::Force { body, at: p, direction, magnitude } => {
                -magnitude.constant()? * dot(*direction, at(*body, *p))
            }
            Load::Torque { body, value } => -value.constant()? * m.column(*body).map_or(0.0, |c| q[c + 2]),
            Load::Damper { .. } => return None,
        };
    }
    Some(v)
}

/// The mechanism's energies at (q, q̇), J.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Energy {
    /// T_b = ½(m v_G² + I_G ω²) of each moving body, in body order.
    pub bodies: Vec<f64>,
    /// T = Σ T_b.
    pub kinetic: f64,
    /// V_g = −Σ m g·r_G, r_G from the drawing's origin.
    pub gravity: f64,
    /// V_s = Σ ½k(l − l₀)² of the springs.
    pub springs: f64,
}

/// [`Energy`] at (q, q̇): q holds (x_G, y_G, θ) of every moving body, so v_G
/// and ω are q̇'s own entries.
pub fn energy(m: &Mechanism, loads: &[Load], q: &[f64], qd: &[f64]) -> Energy {
    let bodies: Vec<f64> = m.bodies[1..]
        .iter()
        .zip(qd.chunks_exact(3))
        .map(|(b, v)| 0.5 * (b.mass * (v[0] * v[0] + v[1] * v[1]) + b.inertia * v[2] * v[2]))
        .collect();
    let gravity =
        -m.bodies[1..].iter().zip(q.chunks_exact(3)).map(|(b, g)| b.mass * dot(m.gravity, [g[0], g[1]])).sum::<f64>();
    let springs = loads
        .iter()
        .filter_map(|load| match load {
            Load::Spring { a, b, stiffness, free_length } => {
                Some(0.5 * stiffness * (line(m, q, qd, *a, *b).1 - free_length).powi(2))
            }
            _ => None,
        })
        .sum::<f64>();
    // + 0.0: an empty sum is −0.0 (Rust's float sum starts there), shown as "-0.0".
    Energy { kinetic: bodies.iter().sum::<f64>() + 0.0, bodies, gravity: gravity + 0.0, springs: springs + 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::samples::offset_slider_crank;

    /// V's gradient is −Q (a second method: the generalized forces of
    /// gravity, two springs, one to the ground, a constant force and a
    /// constant torque), by central differences at an arbitrary q off the
    /// constraints, to 1e-7 of |Q|.
    #[test]
    fn the_potential_is_the_forces_integral() {
        let mut m = offset_slider_crank();
        m.gravity = [1.5, -9.81];
        let loads = vec![
            Load::Spring { a: (1, [0.0, 0.0]), b: (2, [0.2, 0.1]), stiffness: 300.0, free_length: 0.1 },
            Load::Spring { a: (0, [0.0, -0.2]), b: (3, [0.3, 0.0]), stiffness: 50.0, free_length: 0.0 },
            Load::Force { body: 2, at: [0.1, 0.05], direction: [0.6, -0.8], magnitude: Function::Constant(40.0) },
            Load::Torque { body: 1, value: Function::Constant(-7.0) },
        ];
        let q: Vec<f64> = (0..m.n_coordinates()).map(|k| 0.1 + 0.37 * k as f64).collect();
        let forces = applied_forces(&m, &loads, &q, &vec![0.0; q.len()], 0.0, [0.0, 0.0]);
        let h = 1e-6;
        for k in 0..q.len() {
            let at = |d: f64| {
                let mut x = q.clone();
                x[k] += d;
                potential(&m, &loads, &x).expect("springs and gravity")
            };
            let slope = (at(h) - at(-h)) / (2.0 * h);
            assert!((slope + forces[k]).abs() <= 1e-7 * forces.amax(), "∂V/∂q{k} = {slope}, Q = {}", forces[k]);
        }
        let damper = Load::Damper { a: (1, [0.0, 0.0]), b: (2, [0.2, 0.1]), coefficient: 1.0 };
        let phi = crate::engine::expr::Expr::compile("10*phi", &["phi"]).expect("expression");
        let varying = Load::Torque { body: 1, value: Function::Expr(phi) };
        for load in [damper, varying] {
            assert!(!load.has_potential());
            assert_eq!(potential(&m, &[load], &q), None);
        }
    }

    /// No gravity, no spring, at rest: every energy is +0 (an empty float
    /// sum is −0.0, which a result would show as "-0.0").
    #[test]
    fn energies_of_nothing_are_plus_zero() {
        let mut m = offset_slider_crank();
        m.gravity = [0.0, 0.0];
        let q = m.reference_q();
        let e = energy(&m, &[], &q, &vec![0.0; q.len()]);
        assert!([e.kinetic, e.gravity, e.springs].iter().all(|v| *v == 0.0 && v.is_sign_positive()), "{e:?}");
    }
}
