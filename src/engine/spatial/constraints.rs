//! Φ, Φ_q, −Φ_t and γ of the joints and inputs, built from two products:
//! u_i·w_j (a vector of the first body with one of the second) and u_i·d
//! (a vector of the first body with d = P_j − P_i, the second body's point
//! from the first's). For each product its gradient on the increments and
//! h, its second time derivative at zero accelerations, are exact:
//!
//! ```text
//! u̇ = ω × u,  ü = α × u + ω × (ω × u)
//! ḋ = ṙ_j + ω_j × s_j − ṙ_i − ω_i × s_i,  d̈ = … + ω_j × (ω_j × s_j) − ω_i × (ω_i × s_i)
//! ```
//!
//! Rows of a joint, with (a, b, c) its axis and two perpendiculars as
//! drawn, each carried by the first body (index i) or the second (j):
//! spherical eₖᵢ·d = 0 (k = x, y, z); revolute those and aᵢ·bⱼ = aᵢ·cⱼ = 0;
//! universal (axes a, b) the three and aᵢ·bⱼ = 0; cylindrical aᵢ·bⱼ = aᵢ·cⱼ = 0,
//! bᵢ·d = cᵢ·d = 0; prismatic those and bᵢ·cⱼ = 0; a sphere in a cylinder
//! bᵢ·d = cᵢ·d = 0 alone. An input's row: a slide
//! aᵢ·d − s*(t); a rotation θ − θ*(t), θ = atan2(B, A) with A = bᵢ·bⱼ,
//! B = cᵢ·bⱼ. Each is its coordinate less its value, so −λ is the effort.

use super::model::{BodyId, Coordinate, Joint, JointKind, Mechanism, Pose, perpendiculars};
use nalgebra::{DMatrix, DVector, Vector3};
use std::f64::consts::PI;

/// Φ and its derivatives at one configuration.
#[derive(Clone, Debug)]
pub struct Rows {
    pub phi: DVector<f64>,
    /// Φ_q on the increments, rows × 6n.
    pub jac: DMatrix<f64>,
    /// −Φ_t: Φ_q·v = `rate`.
    pub rate: DVector<f64>,
    /// γ at the velocities given (zeros without them): Φ_q·a = γ.
    pub gamma: DVector<f64>,
    /// Whether each row is a length (a point's or a slide's) rather than a
    /// cosine: its scale in the drawing's size.
    pub length: Vec<bool>,
}

/// A body's state as the rows read it.
struct Frame {
    r: Vector3<f64>,
    rot: nalgebra::Matrix3<f64>,
    rdot: Vector3<f64>,
    omega: Vector3<f64>,
}

/// One product's value, gradient on the two bodies' increments and h.
struct Product {
    f: f64,
    gi: [f64; 6],
    gj: [f64; 6],
    h: f64,
}

impl Product {
    fn rate(&self, fi: &Frame, fj: &Frame) -> f64 {
        let dot = |g: &[f64; 6], f: &Frame| {
            g[0] * f.rdot.x + g[1] * f.rdot.y + g[2] * f.rdot.z + g[3] * f.omega.x + g[4] * f.omega.y + g[5] * f.omega.z
        };
        dot(&self.gi, fi) + dot(&self.gj, fj)
    }
}

fn six(t: Vector3<f64>, r: Vector3<f64>) -> [f64; 6] {
    [t.x, t.y, t.z, r.x, r.y, r.z]
}

/// u_i·w_j, u′ drawn in the first body and w′ in the second.
fn vectors(fi: &Frame, fj: &Frame, u: &Vector3<f64>, w: &Vector3<f64>) -> Product {
    let (u, w) = (fi.rot * u, fj.rot * w);
    let (ud, wd) = (fi.omega.cross(&u), fj.omega.cross(&w));
    let h = fi.omega.cross(&ud).dot(&w) + 2.0 * ud.dot(&wd) + u.dot(&fj.omega.cross(&wd));
    Product { f: u.dot(&w), gi: six(Vector3::zeros(), u.cross(&w)), gj: six(Vector3::zeros(), w.cross(&u)), h }
}

/// The joint's point on each body now: d = P_j − P_i, its rate ḋ, the
/// arms s_i and s_j, and d̈ at zero accelerations.
struct Gap {
    d: Vector3<f64>,
    rate: Vector3<f64>,
    si: Vector3<f64>,
    sj: Vector3<f64>,
    curl: Vector3<f64>,
}

fn gap(m: &Mechanism, joint: &Joint, fi: &Frame, fj: &Frame) -> Gap {
    let [i, j] = joint.bodies;
    let si = fi.rot * (joint.at - m.drawn_cg(i));
    let sj = fj.rot * (joint.at - m.drawn_cg(j));
    let d = fj.r + sj - fi.r - si;
    let rate = fj.rdot + fj.omega.cross(&sj) - fi.rdot - fi.omega.cross(&si);
    let curl = fj.omega.cross(&fj.omega.cross(&sj)) - fi.omega.cross(&fi.omega.cross(&si));
    Gap { d, rate, si, sj, curl }
}

/// u_i·d, u′ drawn in the first body.
fn along(fi: &Frame, g: &Gap, u: &Vector3<f64>) -> Product {
    let u = fi.rot * u;
    let ud = fi.omega.cross(&u);
    let h = fi.omega.cross(&ud).dot(&g.d) + 2.0 * ud.dot(&g.rate) + u.dot(&g.curl);
    let gi = six(-u, u.cross(&g.d) - g.si.cross(&u));
    Product { f: u.dot(&g.d), gi, gj: six(u, g.sj.cross(&u)), h }
}

/// The joint's products, in the order of the module's rows.
fn joint_rows(m: &Mechanism, joint: &Joint, fi: &Frame, fj: &Frame) -> Vec<(Product, bool)> {
    let g = gap(m, joint, fi, fj);
    let point = |rows: &mut Vec<(Product, bool)>| {
        for k in 0..3 {
            let mut e = Vector3::zeros();
            e[k] = 1.0;
            rows.push((along(fi, &g, &e), true));
        }
    };
    let mut rows = Vec::with_capacity(5);
    match &joint.kind {
        JointKind::Spherical { .. } => point(&mut rows),
        JointKind::SphereInCylinder { axis } => {
            let (b, c) = perpendiculars(axis);
            rows.push((along(fi, &g, &b), true));
            rows.push((along(fi, &g, &c), true));
        }
        JointKind::Revolute { axis } => {
            point(&mut rows);
            let (b, c) = perpendiculars(axis);
            rows.push((vectors(fi, fj, axis, &b), false));
            rows.push((vectors(fi, fj, axis, &c), false));
        }
        JointKind::Universal { axes } => {
            point(&mut rows);
            rows.push((vectors(fi, fj, &axes[0], &axes[1]), false));
        }
        JointKind::Cylindrical { axis } | JointKind::Prismatic { axis } => {
            let (b, c) = perpendiculars(axis);
            rows.push((vectors(fi, fj, axis, &b), false));
            rows.push((vectors(fi, fj, axis, &c), false));
            rows.push((along(fi, &g, &b), true));
            rows.push((along(fi, &g, &c), true));
            if matches!(joint.kind, JointKind::Prismatic { .. }) {
                rows.push((vectors(fi, fj, &b, &c), false));
            }
        }
    }
    rows
}

/// A joint's coordinate now: θ (rad) or s (m) from the drawing.
pub fn coordinate(m: &Mechanism, pose: &Pose, joint: &Joint, c: Coordinate) -> f64 {
    let still = Vector3::zeros();
    let frame = |b: BodyId| Frame { r: pose.origin(b), rot: pose.rotation(b), rdot: still, omega: still };
    let (fi, fj) = (frame(joint.bodies[0]), frame(joint.bodies[1]));
    let axis = joint.kind.axis().unwrap_or_else(Vector3::x);
    match c {
        Coordinate::Slide => along(&fi, &gap(m, joint, &fi, &fj), &axis).f,
        Coordinate::Rotation => {
            let (b, c) = perpendiculars(&axis);
            vectors(&fi, &fj, &c, &b).f.atan2(vectors(&fi, &fj, &b, &b).f)
        }
    }
}

/// Φ, Φ_q, −Φ_t and γ at `pose` with the inputs at `inputs` (each its
/// value, rate and second rate) and the bodies at `v` (six a body: ṙ, ω;
/// None: at rest, where γ is the inputs' own).
pub fn evaluate(m: &Mechanism, pose: &Pose, v: Option<&DVector<f64>>, inputs: &[[f64; 3]]) -> Rows {
    let rows = m.joint_rows() + m.inputs.len();
    let n = m.n();
    let mut out = Rows {
        phi: DVector::zeros(rows),
        jac: DMatrix::zeros(rows, 6 * n),
        rate: DVector::zeros(rows),
        gamma: DVector::zeros(rows),
        length: Vec::with_capacity(rows),
    };
    let frame = |b: BodyId| {
        let (rdot, omega) = match (b, v) {
            (0, _) | (_, None) => (Vector3::zeros(), Vector3::zeros()),
            (b, Some(v)) => (v.fixed_rows::<3>(6 * b - 6).into(), v.fixed_rows::<3>(6 * b - 3).into()),
        };
        Frame { r: pose.origin(b), rot: pose.rotation(b), rdot, omega }
    };
    let mut k = 0;
    for joint in &m.joints {
        let [i, j] = joint.bodies;
        let (fi, fj) = (frame(i), frame(j));
        for (p, length) in joint_rows(m, joint, &fi, &fj) {
            put(&mut out, k, [i, j], &p, length);
            out.gamma[k] = -p.h;
            k += 1;
        }
    }
    for (input, x) in m.inputs.iter().zip(inputs) {
        let joint = &m.joints[input.joint];
        let [i, j] = joint.bodies;
        let (fi, fj) = (frame(i), frame(j));
        let axis = joint.kind.axis().unwrap_or_else(Vector3::x);
        match input.coordinate {
            Coordinate::Slide => {
                let p = along(&fi, &gap(m, joint, &fi, &fj), &axis);
                put(&mut out, k, [i, j], &Product { f: p.f - x[0], ..p }, true);
                out.rate[k] = x[1];
                out.gamma[k] = x[2] - p.h;
            }
            Coordinate::Rotation => rotation_row(&mut out, k, joint, &fi, &fj, x),
        }
        k += 1;
    }
    out
}

/// The rotation input's row θ − θ*, θ = atan2(B, A) (wrapped to the
/// nearest turn: one root, where sin(θ − θ*) would have a second at θ* + π),
/// with ∇θ = (A·∇B − B·∇A)/D and θ̈ at zero accelerations
/// (A·h_B − B·h_A)/D − 2N·(A·Ȧ + B·Ḃ)/D², N = A·Ḃ − B·Ȧ, D = A² + B².
fn rotation_row(out: &mut Rows, k: usize, joint: &Joint, fi: &Frame, fj: &Frame, x: &[f64; 3]) {
    let (b, c) = perpendiculars(&joint.kind.axis().unwrap_or_else(Vector3::x));
    let (a, bb) = (vectors(fi, fj, &b, &b), vectors(fi, fj, &c, &b));
    let d = a.f * a.f + bb.f * bb.f;
    let mix = |p: &[f64; 6], q: &[f64; 6]| std::array::from_fn(|n| (a.f * p[n] - bb.f * q[n]) / d);
    let (a_rate, b_rate) = (a.rate(fi, fj), bb.rate(fi, fj));
    let n = a.f * b_rate - bb.f * a_rate;
    let h = (a.f * bb.h - bb.f * a.h) / d - 2.0 * n * (a.f * a_rate + bb.f * b_rate) / (d * d);
    let f = (bb.f.atan2(a.f) - x[0] + PI).rem_euclid(2.0 * PI) - PI;
    put(out, k, joint.bodies, &Product { f, gi: mix(&bb.gi, &a.gi), gj: mix(&bb.gj, &a.gj), h }, false);
    out.rate[k] = x[1];
    out.gamma[k] = x[2] - h;
}

fn put(out: &mut Rows, k: usize, [i, j]: [BodyId; 2], p: &Product, length: bool) {
    out.phi[k] = p.f;
    out.length.push(length);
    for (b, g) in [(i, &p.gi), (j, &p.gj)] {
        if b > 0 {
            for (c, value) in g.iter().enumerate() {
                out.jac[(k, 6 * (b - 1) + c)] += value;
            }
        }
    }
}
