//! Kinetostatics in space: at a known motion, the multipliers λ of
//!
//! ```text
//! Φ_qᵀ·λ = Q − M·a − (0, ω × J·ω)   (Newton–Euler about each G, ground axes)
//! ```
//!
//! give every joint's reaction (the wrench −Φ_qᵀλ of its rows on its
//! second body, its moment taken about the joint's point as that body
//! carries it) and every input's effort (−λ of its row, which is its
//! coordinate less its value: a torque about the axis, a force along it). The
//! least-norm λ is the one taken where rows are redundant; the joints with
//! a row in Φ_q's left null space are flagged as indeterminate. The virtual
//! power of the applied actions, the inertia and the efforts at the actual
//! velocities is summed as a check, not forced to zero.

use super::constraints::Rows;
use super::kinematics::{Motion, Scaled};
use super::mobility::dependent_rows;
use super::model::{BodyId, Load, Mechanism, Pose};
use nalgebra::{DVector, Vector3};

/// A force and a couple.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wrench {
    pub force: Vector3<f64>,
    pub moment: Vector3<f64>,
}

/// A joint's reaction on its second body (`on`) by its first (`by`).
#[derive(Clone, Debug, PartialEq)]
pub struct Reaction {
    pub joint: usize,
    pub on: BodyId,
    pub by: BodyId,
    /// About `at`, the joint's point as the second body carries it.
    pub wrench: Wrench,
    pub at: Vector3<f64>,
    /// False where the joint's rows are redundant: equilibrium cannot tell
    /// its share (this is the share of least norm).
    pub determinate: bool,
}

/// What holds and drives the mechanism at one position.
#[derive(Clone, Debug, PartialEq)]
pub struct Actions {
    pub reactions: Vec<Reaction>,
    /// Each input's effort: a torque (N·m) or a force (N).
    pub efforts: Vec<f64>,
    /// Σ of the virtual powers (applied, inertia, efforts), W.
    pub virtual_power: f64,
    /// The largest of those powers' magnitudes, W: what the sum is small against.
    pub largest_power: f64,
    /// λ, the rows' multipliers (the joints' and then the inputs').
    pub lambda: DVector<f64>,
}

/// Each body's applied wrench about G (gravity and the loads) at `pose`
/// and velocities `v`, six a body.
pub fn applied(m: &Mechanism, loads: &[Load], pose: &Pose, v: &DVector<f64>) -> DVector<f64> {
    let mut q = DVector::zeros(6 * m.n());
    let add = |q: &mut DVector<f64>, b: BodyId, f: Vector3<f64>, n: Vector3<f64>| {
        if b > 0 {
            for k in 0..3 {
                q[6 * b - 6 + k] += f[k];
                q[6 * b - 3 + k] += n[k];
            }
        }
    };
    for (b, body) in m.bodies.iter().enumerate() {
        add(&mut q, b + 1, m.gravity * body.mass, Vector3::zeros());
    }
    for load in loads {
        match load {
            Load::Force { body, at, force } => {
                let (_, s) = pose.point(m, *body, at);
                add(&mut q, *body, *force, s.cross(force));
            }
            Load::Torque { body, torque } => add(&mut q, *body, Vector3::zeros(), *torque),
            Load::Spring { bodies, .. } => {
                for (b, (_, arm, f)) in bodies.iter().zip(spring_ends(m, load, pose, v).into_iter().flatten()) {
                    add(&mut q, *b, f, arm.cross(&f));
                }
            }
        }
    }
    q
}

/// A spring's (and its damper's) ends: each body's point, its arm from G
/// and the force on it, pulling the ends together when stretched (None
/// for another load).
pub fn spring_ends(m: &Mechanism, load: &Load, pose: &Pose, v: &DVector<f64>) -> Option<[End; 2]> {
    let Load::Spring { bodies, at, k, length, c } = load else { return None };
    let ends = [0, 1].map(|e| pose.point(m, bodies[e], &at[e]));
    let rates = [0, 1].map(|e| point_rate(v, bodies[e], &ends[e].1));
    let e = ends[1].0 - ends[0].0;
    let l = e.norm();
    let u = if l > 0.0 { e / l } else { Vector3::zeros() };
    let tension = k * (l - length) + c * u.dot(&(rates[1] - rates[0]));
    Some([(ends[0].0, ends[0].1, u * tension), (ends[1].0, ends[1].1, -u * tension)])
}

/// A spring's end: the point, its arm from G and the force there.
pub type End = (Vector3<f64>, Vector3<f64>, Vector3<f64>);

/// The velocity of a body's point at arm s from G.
fn point_rate(v: &DVector<f64>, b: BodyId, s: &Vector3<f64>) -> Vector3<f64> {
    if b == 0 {
        return Vector3::zeros();
    }
    let rdot = Vector3::from(v.fixed_rows::<3>(6 * b - 6));
    let omega = Vector3::from(v.fixed_rows::<3>(6 * b - 3));
    rdot + omega.cross(s)
}

/// Each body's inertia wrench about G: m·r̈ and J·α + ω × J·ω.
pub fn inertia(m: &Mechanism, motion: &Motion) -> DVector<f64> {
    let mut out = DVector::zeros(6 * m.n());
    for (k, body) in m.bodies.iter().enumerate() {
        let rot = motion.pose.rotation(k + 1);
        let j = rot * body.inertia * rot.transpose();
        let omega = Vector3::from(motion.v.fixed_rows::<3>(6 * k + 3));
        let alpha = Vector3::from(motion.a.fixed_rows::<3>(6 * k + 3));
        let linear = Vector3::from(motion.a.fixed_rows::<3>(6 * k)) * body.mass;
        let angular = j * alpha + omega.cross(&(j * omega));
        out.fixed_rows_mut::<3>(6 * k).copy_from(&linear);
        out.fixed_rows_mut::<3>(6 * k + 3).copy_from(&angular);
    }
    out
}

/// The reactions and efforts at `motion` under gravity and `loads`.
pub fn inverse_dynamics(m: &Mechanism, loads: &[Load], motion: &Motion) -> Actions {
    let q = applied(m, loads, &motion.pose, &motion.v);
    let inertial = inertia(m, motion);
    let rows = &motion.rows;
    let scaled = Scaled::new(rows, rows.phi.len(), m.size());
    let lambda = scaled.solve_transposed(&(&q - &inertial));
    let dependent = dependent_rows(&scaled);
    let (offsets, first_input) = m.offsets();
    let reactions = m
        .joints
        .iter()
        .enumerate()
        .map(|(k, joint)| {
            let span = offsets[k]..offsets[k] + joint.kind.rows();
            let determinate = !span.clone().any(|r| dependent[r]);
            let (wrench, at) = reaction(m, motion, rows, &lambda, span, joint.bodies, &joint.at);
            Reaction { joint: k, on: joint.bodies[1], by: joint.bodies[0], wrench, at, determinate }
        })
        .collect();
    let efforts: Vec<f64> = (0..m.inputs.len()).map(|k| -lambda[first_input + k]).collect();
    let powers = [
        q.dot(&motion.v),
        -inertial.dot(&motion.v),
        (0..m.inputs.len()).map(|k| -lambda[first_input + k] * rows.rate[first_input + k]).sum(),
    ];
    Actions {
        reactions,
        efforts,
        virtual_power: powers.iter().sum(),
        largest_power: powers.iter().fold(0.0, |a, p| a.max(p.abs())),
        lambda,
    }
}

/// The wrench of rows `span` on the second body, about the joint's point
/// as that body carries it (the first body's, reversed, where the second
/// is the ground), and that point.
fn reaction(
    m: &Mechanism,
    motion: &Motion,
    rows: &Rows,
    lambda: &DVector<f64>,
    span: std::ops::Range<usize>,
    [i, j]: [BodyId; 2],
    at: &Vector3<f64>,
) -> (Wrench, Vector3<f64>) {
    let on = |b: BodyId| {
        let mut w = [0.0; 6];
        for r in span.clone() {
            for (c, x) in w.iter_mut().enumerate() {
                *x -= rows.jac[(r, 6 * (b - 1) + c)] * lambda[r];
            }
        }
        (Vector3::new(w[0], w[1], w[2]), Vector3::new(w[3], w[4], w[5]))
    };
    let (point, _) = motion.pose.point(m, j, at);
    let (b, sign) = if j > 0 { (j, 1.0) } else { (i, -1.0) };
    let (force, about_g) = on(b);
    let g = motion.pose.origin(b);
    let moment = about_g + (g - point).cross(&force);
    (Wrench { force: force * sign, moment: moment * sign }, point)
}
