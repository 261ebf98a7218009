//! Positions, velocities and accelerations: Φ = 0 by Newton's method on
//! the increments, then Φ_q·v = −Φ_t and Φ_q·a = γ. Every solve is the
//! least-squares solution of least norm by an SVD of Φ_q scaled free of
//! units (a length row divided by the drawing's size L, a translation
//! column multiplied by it), so a redundant row (Bricard's linkage, a
//! Cardan joint's bearings) costs nothing and the rank is read with one
//! tolerance at any size.

use super::constraints::{Rows, evaluate};
use super::model::{Mechanism, Pose};
use crate::engine::{Deadline, EngineError, Progress};
use nalgebra::{DMatrix, DVector};

/// Newton's iterations at one position before it is said not to assemble.
const NEWTON_ITERATIONS: usize = 40;
/// |Φ| (lengths in L) at which a position is assembled.
const ASSEMBLED: f64 = 1e-12;
/// A singular value below this fraction of the largest is a lost rank.
pub const RANK_TOLERANCE: f64 = 1e-9;

/// The mechanism at one position of its inputs.
#[derive(Clone, Debug)]
pub struct Motion {
    pub pose: Pose,
    /// ṙ, ω of every body (six a body).
    pub v: DVector<f64>,
    /// r̈, α of every body.
    pub a: DVector<f64>,
    /// Φ_q and γ at this pose and velocity (the reactions' rows).
    pub rows: Rows,
    /// σ₁/σ₆ₙ of the unit-free Φ_q (the joints' rows and the inputs'):
    /// how near the position is to a singular one.
    pub condition: f64,
}

/// Φ_q scaled free of units, with what undoes it.
pub struct Scaled {
    pub jac: DMatrix<f64>,
    row: Vec<f64>,
    col: Vec<f64>,
}

impl Scaled {
    /// Φ_q (or its first `rows` rows) scaled by the drawing's size `size`.
    pub fn new(r: &Rows, rows: usize, size: f64) -> Self {
        let row: Vec<f64> = r.length[..rows].iter().map(|&l| if l { size } else { 1.0 }).collect();
        let col: Vec<f64> = (0..r.jac.ncols()).map(|c| if c % 6 < 3 { size } else { 1.0 }).collect();
        let jac = DMatrix::from_fn(rows, r.jac.ncols(), |k, c| r.jac[(k, c)] * col[c] / row[k]);
        Self { jac, row, col }
    }

    /// The least-squares solution of least norm of Φ_q·x = `rhs`, and how
    /// far (in scaled rows) the rows are from holding at it.
    pub fn solve(&self, rhs: &DVector<f64>) -> (DVector<f64>, f64) {
        let b = DVector::from_fn(self.row.len(), |k, _| rhs[k] / self.row[k]);
        let y = least_norm(self.jac.clone(), &b);
        let miss = (&self.jac * &y - &b).amax();
        (DVector::from_fn(self.col.len(), |c, _| y[c] * self.col[c]), miss)
    }

    /// λ with Φ_qᵀ·λ = `q` (six a body), of least norm.
    pub fn solve_transposed(&self, q: &DVector<f64>) -> DVector<f64> {
        let b = DVector::from_fn(self.col.len(), |c, _| q[c] * self.col[c]);
        let mu = least_norm(self.jac.transpose(), &b);
        DVector::from_fn(self.row.len(), |k, _| mu[k] / self.row[k])
    }

    /// Its singular values, largest first; none converging (numbers out of range) an error.
    pub fn singular_values(&self) -> Result<Vec<f64>, EngineError> {
        // No rows (no joints) or no columns (no bodies): no singular value, rank 0.
        if self.jac.is_empty() {
            return Ok(Vec::new());
        }
        let finite = self.jac.iter().all(|v| v.is_finite());
        let svd = finite.then(|| self.jac.clone().try_svd(false, false, SVD_EPSILON, SVD_ITERATIONS)).flatten();
        Ok(svd.ok_or(EngineError::NotFiniteResult)?.singular_values.iter().copied().collect())
    }

    /// The rank of the scaled Φ_q (0 where its SVD does not converge: numbers out of range).
    pub fn rank(&self) -> usize {
        self.checked_rank().unwrap_or(0)
    }

    /// The rank, or why there is none: a Φ_q of numbers out of range
    /// (a drawing of 1e300 m), whose SVD does not converge.
    pub fn checked_rank(&self) -> Result<usize, EngineError> {
        let s = self.singular_values()?;
        let tolerance = RANK_TOLERANCE * s.first().copied().unwrap_or(0.0);
        Ok(s.iter().filter(|&&v| v > tolerance).count())
    }
}

/// The SVD's sweeps before it is said not to converge (it does in tens;
/// a matrix of non-finite numbers never does).
pub const SVD_ITERATIONS: usize = 10_000;
/// The SVD's convergence threshold, nalgebra's own (5 ε).
pub const SVD_EPSILON: f64 = 5.0 * f64::EPSILON;

/// The least-squares solution of least norm of a·x = b (zeros where the SVD fails).
fn least_norm(a: DMatrix<f64>, b: &DVector<f64>) -> DVector<f64> {
    let cols = a.ncols();
    if a.is_empty() {
        return DVector::zeros(cols);
    }
    let solved = a.try_svd(true, true, SVD_EPSILON, SVD_ITERATIONS).and_then(|svd| {
        let tolerance = RANK_TOLERANCE * svd.singular_values.max();
        svd.solve(b, tolerance).ok()
    });
    solved.unwrap_or_else(|| DVector::zeros(cols))
}

/// The pose where Φ = 0 with the inputs at `inputs` (their values; rates
/// unused), by Newton's method from `start`, and the iterations it took;
/// at `step` of a sweep for the error's words.
pub fn assemble(m: &Mechanism, inputs: &[[f64; 3]], start: &Pose, step: usize) -> Result<(Pose, usize), EngineError> {
    let size = m.size();
    let mut pose = start.clone();
    let mut residual = f64::INFINITY;
    for iterations in 0..NEWTON_ITERATIONS {
        let rows = evaluate(m, &pose, None, inputs);
        let scaled = Scaled::new(&rows, rows.phi.len(), size);
        residual = (0..rows.phi.len()).map(|k| (rows.phi[k] / scaled.row[k]).abs()).fold(0.0, f64::max);
        if residual < ASSEMBLED {
            return Ok((pose, iterations));
        }
        let (delta, _) = scaled.solve(&-&rows.phi);
        pose.apply(delta.as_slice());
    }
    let rows = evaluate(m, &pose, None, inputs);
    let worst = worst_joint(m, &rows, size);
    Err(EngineError::NewtonDiverged { step, input: inputs.first().map_or(0.0, |x| x[0]), residual, joint: worst })
}

/// The joint whose rows are furthest from holding (an input's name if it is an input's row).
fn worst_joint(m: &Mechanism, rows: &Rows, size: f64) -> String {
    let (offsets, inputs) = m.offsets();
    let scale = |k: usize| if rows.length[k] { size } else { 1.0 };
    let k =
        (0..rows.phi.len()).max_by(|&a, &b| (rows.phi[a] / scale(a)).abs().total_cmp(&(rows.phi[b] / scale(b)).abs()));
    let joint = match k {
        Some(k) if k >= inputs => m.inputs[k - inputs].joint,
        Some(k) => offsets.iter().rposition(|&o| o <= k).unwrap_or(0),
        None => 0,
    };
    m.joints.get(joint).map_or_else(String::new, |j| j.name.clone())
}

/// Velocities and accelerations at an assembled `pose`; a singular
/// position (the rows with the inputs' short of 6n) is an error.
pub fn motion(m: &Mechanism, pose: Pose, inputs: &[[f64; 3]], step: usize) -> Result<Motion, EngineError> {
    let size = m.size();
    let at_rest = evaluate(m, &pose, None, inputs);
    let scaled = Scaled::new(&at_rest, at_rest.phi.len(), size);
    let singular = || EngineError::Singular { step, input: inputs.first().map_or(0.0, |x| x[0]) };
    let values = scaled.singular_values()?;
    let tolerance = RANK_TOLERANCE * values.first().copied().unwrap_or(0.0);
    let columns = 6 * m.n();
    if values.len() < columns || values[columns - 1] <= tolerance {
        return Err(singular());
    }
    let condition = values[0] / values[columns - 1];
    let (v, miss) = scaled.solve(&at_rest.rate);
    if miss > 1e-8 * at_rest.rate.amax().max(1.0) {
        return Err(singular());
    }
    let rows = evaluate(m, &pose, Some(&v), inputs);
    let (a, _) = Scaled::new(&rows, rows.phi.len(), size).solve(&rows.gamma);
    Ok(Motion { pose, v, a, rows, condition })
}

/// The mechanism at every step of its inputs, each position from the
/// last (the first from the drawing), within `deadline`.
pub fn sweep(m: &Mechanism, steps: &[Vec<[f64; 3]>], deadline: &Deadline) -> Result<Vec<Motion>, EngineError> {
    let mut pose = Pose::drawn(m);
    let mut out = Vec::with_capacity(steps.len());
    for (k, inputs) in steps.iter().enumerate() {
        deadline.check(|| Progress::Assembled { step: k, of: steps.len() })?;
        pose = assemble(m, inputs, &pose, k)?.0;
        out.push(motion(m, pose.clone(), inputs, k)?);
    }
    Ok(out)
}
