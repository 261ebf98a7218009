//! Constraint equations Φ(q, φ) = 0 of the joints and drivers, their
//! Jacobian Φ_q and the acceleration right-hand side γ (Φ_q q̈ = γ).
//!
//! Rows: the joints in order (revolute 2, prismatic 2, pin-in-slot 1, gear 1),
//! then one row per driver (a joint's coordinate, a point's displacement
//! along a direction of the ground, or a body's rotation). With d = P_j − P_i the separation of the joint
//! point on the second and first body and e = A(θ_i)e' a direction fixed in
//! the first body, a "projection" row is eᵀd: the normal of a slide
//! (prismatic, pin-in-slot) or the axis of a driven prismatic joint.

mod contact;

use super::model::{BodyId, Coordinate, Driver, JointKind, Mechanism, dot, perp, rotate_by};
use nalgebra::{DMatrix, DVector};

/// Φ, Φ_q and γ at one state; [`evaluate_into`] refills one in place.
#[derive(Clone, Debug, Default)]
pub struct System {
    pub phi: DVector<f64>,
    pub jacobian: DMatrix<f64>,
    /// Φ_q q̈ = γ (only when velocities were given).
    pub gamma: DVector<f64>,
    /// (sin θ, cos θ) of every body, ground first: the evaluation's scratch.
    trig: Vec<(f64, f64)>,
}

impl System {
    /// (sin θ, cos θ) of every body (ground first) at the q of the last [`evaluate_into`].
    pub fn trig(&self) -> &[(f64, f64)] {
        &self.trig
    }
}

/// Coordinates, velocities and the drivers' values at one instant.
pub struct State<'a> {
    pub q: &'a [f64],
    pub qd: Option<&'a [f64]>,
    /// Input coordinate, speed and acceleration of every driver.
    pub inputs: &'a [[f64; 3]],
}

/// Number of constraint rows (joints and drivers).
pub fn n_rows(m: &Mechanism) -> usize {
    m.joints.iter().map(|j| Mechanism::joint_rows(&j.kind)).sum::<usize>() + m.drivers.len()
}

/// First row of every joint.
pub fn joint_offsets(m: &Mechanism) -> Vec<usize> {
    let mut row = 0;
    m.joints
        .iter()
        .map(|j| {
            let r = row;
            row += Mechanism::joint_rows(&j.kind);
            r
        })
        .collect()
}

/// Φ_q by blocks: row k touches at most three bodies, each a block
/// (column of the body's x, [∂/∂x, ∂/∂y, ∂/∂θ]). Direct dynamics of large
/// mechanisms works on this form; its cost grows with the rows, not with
/// rows × coordinates.
#[derive(Clone, Debug, Default)]
pub struct Blocks {
    pub rows: Vec<RowBlocks>,
}

/// The blocks of one row of Φ_q: up to three bodies' (x, y, θ), and up to
/// two single entries (a contact's curve parameters).
#[derive(Clone, Copy, Debug, Default)]
pub struct RowBlocks {
    pub len: usize,
    pub col: [usize; 3],
    pub val: [[f64; 3]; 3],
    pub singles: usize,
    pub single: [(usize, f64); 2],
}

impl RowBlocks {
    /// The bodies' blocks (the single entries apart: the sparse range-space
    /// form, which reads these, is not used for mechanisms with contacts).
    pub fn iter(&self) -> impl Iterator<Item = (usize, &[f64; 3])> {
        self.col[..self.len].iter().copied().zip(&self.val[..self.len])
    }

    /// Σ Φ_q,k·v over the row's blocks and single entries.
    pub fn dot(&self, v: &[f64]) -> f64 {
        let blocks: f64 = self.iter().map(|(c, d)| d[0] * v[c] + d[1] * v[c + 1] + d[2] * v[c + 2]).sum();
        blocks + self.single[..self.singles].iter().map(|&(c, d)| d * v[c]).sum::<f64>()
    }
}

/// Where the Builder writes Φ_q: a dense matrix or [`Blocks`].
trait Jacobian {
    /// A body's block (x, y, θ) from column `col`.
    fn add(&mut self, row: usize, col: usize, d: [f64; 3]);
    /// One entry (a curve parameter's column).
    fn add_one(&mut self, row: usize, col: usize, d: f64);
}

impl Jacobian for DMatrix<f64> {
    fn add(&mut self, row: usize, col: usize, d: [f64; 3]) {
        for (k, v) in d.into_iter().enumerate() {
            self[(row, col + k)] += v;
        }
    }
    fn add_one(&mut self, row: usize, col: usize, d: f64) {
        self[(row, col)] += d;
    }
}

/// Φ_q not written: [`evaluate_gamma`] at a q whose Φ_q is known.
impl Jacobian for () {
    fn add(&mut self, _: usize, _: usize, _: [f64; 3]) {}
    fn add_one(&mut self, _: usize, _: usize, _: f64) {}
}

impl Jacobian for Blocks {
    fn add(&mut self, row: usize, col: usize, d: [f64; 3]) {
        let r = &mut self.rows[row];
        let k = r.col[..r.len].iter().position(|&c| c == col).unwrap_or_else(|| {
            r.len += 1;
            r.col[r.len - 1] = col;
            r.val[r.len - 1] = [0.0; 3];
            r.len - 1
        });
        (0..3).for_each(|i| r.val[k][i] += d[i]);
    }
    fn add_one(&mut self, row: usize, col: usize, d: f64) {
        let r = &mut self.rows[row];
        match r.single[..r.singles].iter().position(|&(c, _)| c == col) {
            Some(k) => r.single[k].1 += d,
            None => {
                r.single[r.singles] = (col, d);
                r.singles += 1;
            }
        }
    }
}

struct Builder<'a, 'w, J> {
    m: &'a Mechanism,
    s: &'a State<'a>,
    /// (sin θ, cos θ) of every body, ground first: one evaluation each.
    trig: &'w [(f64, f64)],
    phi: &'w mut [f64],
    gamma: &'w mut [f64],
    jacobian: &'w mut J,
}

impl<J: Jacobian> Builder<'_, '_, J> {
    /// A(θ_b)·s.
    fn rot(&self, b: BodyId, s: [f64; 2]) -> [f64; 2] {
        rotate_by(self.trig[b], s)
    }

    /// B(θ_b)·s = A(θ_b)·(−s_y, s_x).
    fn rot_d(&self, b: BodyId, s: [f64; 2]) -> [f64; 2] {
        self.rot(b, [-s[1], s[0]])
    }

    fn pose(&self, b: BodyId) -> ([f64; 2], f64) {
        match self.m.column(b) {
            Some(c) => ([self.s.q[c], self.s.q[c + 1]], self.s.q[c + 2]),
            None => ([0.0, 0.0], 0.0),
        }
    }

    fn rates(&self, b: BodyId) -> ([f64; 2], f64) {
        match (self.m.column(b), self.s.qd) {
            (Some(c), Some(qd)) => ([qd[c], qd[c + 1]], qd[c + 2]),
            _ => ([0.0, 0.0], 0.0),
        }
    }

    fn add(&mut self, row: usize, b: BodyId, dr: [f64; 2], dtheta: f64) {
        if let Some(c) = self.m.column(b) {
            self.jacobian.add(row, c, [dr[0], dr[1], dtheta]);
        }
    }

    /// Point `s` of body b: position, velocity.
    fn point(&self, b: BodyId, s: [f64; 2]) -> ([f64; 2], [f64; 2]) {
        let ((r, _), (rd, thd)) = (self.pose(b), self.rates(b));
        let (a, bs) = (self.rot(b, s), self.rot_d(b, s));
        ([r[0] + a[0], r[1] + a[1]], [rd[0] + bs[0] * thd, rd[1] + bs[1] * thd])
    }

    /// Rows 2: P_i − P_j = 0.
    fn revolute(&mut self, row: usize, [i, j]: [BodyId; 2], at: [f64; 2]) {
        let (si, sj) = (self.m.local(i, at), self.m.local(j, at));
        let ((pi, _), (pj, _)) = (self.point(i, si), self.point(j, sj));
        let ((_, wi), (_, wj)) = (self.rates(i), self.rates(j));
        let (bi, bj) = (self.rot_d(i, si), self.rot_d(j, sj));
        let (ai, aj) = (self.rot(i, si), self.rot(j, sj));
        for k in 0..2 {
            self.phi[row + k] = pi[k] - pj[k];
            let e = if k == 0 { [1.0, 0.0] } else { [0.0, 1.0] };
            self.add(row + k, i, e, bi[k]);
            self.add(row + k, j, [-e[0], -e[1]], -bj[k]);
            self.gamma[row + k] = ai[k] * wi * wi - aj[k] * wj * wj;
        }
    }

    /// Row eᵀd − target with e = A(θ_i)e'.
    fn projection(&mut self, row: usize, [i, j]: [BodyId; 2], at: [f64; 2], e0: [f64; 2], target: f64) {
        let (si, sj) = (self.m.local(i, at), self.m.local(j, at));
        let ((pi, vi), (pj, vj)) = (self.point(i, si), self.point(j, sj));
        let ((_, wi), (_, wj)) = (self.rates(i), self.rates(j));
        let (d, dd) = ([pj[0] - pi[0], pj[1] - pi[1]], [vj[0] - vi[0], vj[1] - vi[1]]);
        let (e, de) = (self.rot(i, e0), self.rot_d(i, e0));
        self.phi[row] = dot(e, d) - target;
        self.add(row, i, [-e[0], -e[1]], dot(de, d) - dot(e, self.rot_d(i, si)));
        self.add(row, j, e, dot(e, self.rot_d(j, sj)));
        let (ai, aj) = (self.rot(i, si), self.rot(j, sj));
        let centripetal = [ai[0] * wi * wi - aj[0] * wj * wj, ai[1] * wi * wi - aj[1] * wj * wj];
        self.gamma[row] = dot(e, d) * wi * wi - 2.0 * wi * dot(de, dd) - dot(e, centripetal);
    }

    /// Row c_k(q) − target, c_k joint k's coordinate: its relative rotation
    /// (revolute), its displacement along the axis (prismatic), or the arc
    /// length run along its first curve (contact).
    fn joint_coordinate(&mut self, row: usize, k: usize, target: f64) {
        let m = self.m;
        let joint = &m.joints[k];
        let [i, j] = joint.bodies;
        match &joint.kind {
            JointKind::Prismatic { axis } => self.projection(row, joint.bodies, joint.at, *axis, target),
            JointKind::Contact(c) => self.contact_arc(row, k, c, target),
            _ => self.angles(row, &[(j, 1.0), (i, -1.0)], target),
        }
    }

    /// Row f(q) − (φ − reference) of driver `d` at its input (φ, φ̇, φ̈).
    fn driver(&mut self, row: usize, d: &Driver, input: [f64; 3]) {
        let value = input[0] - d.reference;
        match d.coordinate {
            Coordinate::Joint(k) => self.joint_coordinate(row, k, value),
            Coordinate::Point { body, at, direction } => self.projection(row, [0, body], at, direction, value),
            Coordinate::Body(body) => self.angles(row, &[(body, 1.0)], value),
        }
        // Φ_d = f(q) − φ(t): Φ_q q̈ = γ_f + φ̈.
        self.gamma[row] += input[2];
    }

    /// Row a·θ_i + b·θ_j + c·θ_c − target.
    fn angles(&mut self, row: usize, terms: &[(BodyId, f64)], target: f64) {
        self.phi[row] = terms.iter().map(|&(b, k)| k * self.pose(b).1).sum::<f64>() - target;
        for &(b, k) in terms {
            self.add(row, b, [0.0, 0.0], k);
        }
    }
}

/// Φ, Φ_q and γ at a state.
pub fn evaluate(m: &Mechanism, s: &State) -> System {
    let mut sys = System::default();
    evaluate_into(m, s, &mut sys);
    sys
}

/// [`evaluate`] into `sys`, reusing its storage (nothing is allocated once
/// it has held this mechanism's system).
pub fn evaluate_into(m: &Mechanism, s: &State, sys: &mut System) {
    let (rows, n) = (n_rows(m), m.n_coordinates());
    // (Over the storage: nalgebra's `fill` goes entry by entry, the most of an evaluation.)
    if sys.jacobian.shape() == (rows, n) {
        sys.jacobian.as_mut_slice().fill(0.0);
    } else {
        sys.jacobian = DMatrix::zeros(rows, n);
    }
    zeroed(&mut sys.phi, rows);
    zeroed(&mut sys.gamma, rows);
    let System { phi, jacobian, gamma, trig } = sys;
    m.turns_into(s.q, trig);
    build(m, s, trig, phi.as_mut_slice(), gamma.as_mut_slice(), jacobian);
}

/// Φ and γ into `sys` at a state whose q is the one `sys` was evaluated
/// at by [`evaluate_into`] (its Φ_q and the bodies' sines and cosines,
/// unchanged, are not computed again): γ once the velocities are known.
pub fn evaluate_gamma(m: &Mechanism, s: &State, sys: &mut System) {
    debug_assert_eq!(sys.trig.len(), m.bodies.len(), "evaluate_into first");
    let rows = n_rows(m);
    zeroed(&mut sys.phi, rows);
    zeroed(&mut sys.gamma, rows);
    let System { phi, gamma, trig, .. } = sys;
    build(m, s, trig, phi.as_mut_slice(), gamma.as_mut_slice(), &mut ());
}

/// `v` as `rows` zeros, in its own storage where it has that length.
fn zeroed(v: &mut DVector<f64>, rows: usize) {
    if v.len() == rows {
        v.as_mut_slice().fill(0.0);
    } else {
        *v = DVector::zeros(rows);
    }
}

/// Φ, γ and Φ_q by blocks at a state (as [`evaluate`], without the dense matrix).
pub fn evaluate_blocks(m: &Mechanism, s: &State) -> (Vec<f64>, Vec<f64>, Blocks) {
    let rows = n_rows(m);
    let (mut phi, mut gamma, mut blocks) =
        (vec![0.0; rows], vec![0.0; rows], Blocks { rows: vec![RowBlocks::default(); rows] });
    let mut trig = Vec::new();
    m.turns_into(s.q, &mut trig);
    build(m, s, &trig, &mut phi, &mut gamma, &mut blocks);
    (phi, gamma, blocks)
}

/// Fills Φ, γ and Φ_q (all zero on entry) at a state whose sines and
/// cosines are `trig`.
fn build<J: Jacobian>(
    m: &Mechanism,
    s: &State,
    trig: &[(f64, f64)],
    phi: &mut [f64],
    gamma: &mut [f64],
    jacobian: &mut J,
) {
    let mut b = Builder { m, s, trig, phi, gamma, jacobian };
    let (mut row, mut parameter) = (0, m.n_body_coordinates());
    for joint in &m.joints {
        let [i, j] = joint.bodies;
        match &joint.kind {
            JointKind::Revolute => b.revolute(row, joint.bodies, joint.at),
            JointKind::Prismatic { axis } => {
                b.angles(row, &[(j, 1.0), (i, -1.0)], 0.0);
                b.projection(row + 1, joint.bodies, joint.at, perp(*axis), 0.0);
            }
            JointKind::PinSlot { axis } => b.projection(row, joint.bodies, joint.at, perp(*axis), 0.0),
            JointKind::Gear { ratio, carrier, .. } => {
                b.angles(row, &[(j, 1.0), (i, -ratio), (*carrier, ratio - 1.0)], 0.0);
            }
            JointKind::Contact(c) => {
                b.contact(row, joint.bodies, c, parameter);
                parameter += c.parameters();
            }
        }
        row += Mechanism::joint_rows(&joint.kind);
    }
    for (d, input) in m.drivers.iter().zip(s.inputs) {
        b.driver(row, d, *input);
        row += 1;
    }
}

/// Driver `k`'s Φ and its row of Φ_q alone at a state (the joints' rows
/// not built): what the integrator asks of the input at each step's ends.
pub fn evaluate_driver(m: &Mechanism, s: &State, k: usize) -> (f64, RowBlocks) {
    let (mut phi, mut gamma, mut blocks) = ([0.0], [0.0], Blocks { rows: vec![RowBlocks::default()] });
    let mut trig = Vec::new();
    m.turns_into(s.q, &mut trig);
    let mut b = Builder { m, s, trig: &trig, phi: &mut phi, gamma: &mut gamma, jacobian: &mut blocks };
    b.driver(0, &m.drivers[k], s.inputs[k]);
    (phi[0], blocks.rows[0])
}

/// The right-hand side ν of the velocity equation Φ_q q̇ = ν: the input speeds.
pub fn nu(m: &Mechanism, inputs: &[[f64; 3]]) -> DVector<f64> {
    let mut v = DVector::zeros(n_rows(m));
    let first = n_rows(m) - m.drivers.len();
    for (k, input) in inputs.iter().enumerate() {
        v[first + k] = input[1];
    }
    v
}

#[cfg(test)]
mod tests;
