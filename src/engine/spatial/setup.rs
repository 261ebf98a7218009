//! What a spatial run starts from: the joints' rows it keeps (those that
//! raise the rank, so that a redundant one, as in Bricard's linkage, is
//! left out once) and the integrator's tolerances, each state component's;
//! and the problem itself.

use super::constraints::Rows;
use super::kinematics::Scaled;
use super::model::{LoadLaw, Mechanism};
use crate::engine::Deadline;
use crate::engine::dynamics::End;
use crate::engine::dynamics::{Integrator, Settings};
use nalgebra::DVector;

/// A validated spatial dynamics problem in SI.
#[derive(Clone, Debug)]
pub struct SpatialProblem {
    /// Its inputs name the free coordinates that set the start and report the motion.
    pub mechanism: Mechanism,
    /// Their Functions read φ (the first input's coordinate reduced to
    /// `period`), ω (its speed) and t.
    pub loads: Vec<LoadLaw>,
    pub period: f64,
    /// Each input's coordinate as drawn: the coordinates read and
    /// reported are it plus the change from the drawing.
    pub reference: Vec<f64>,
    /// Coordinate and speed of every input at t = 0.
    pub initial: Vec<[f64; 2]>,
    pub end: End,
    pub tolerance: f64,
    pub integrator: Option<Integrator>,
    pub samples: usize,
    pub deadline: Deadline,
    /// Solve every joint's reaction at the samples.
    pub reactions: bool,
}

/// The rows of Φ_q (scaled) that raise its rank, in order (Gram–Schmidt, twice).
pub(super) fn independent(rows: &Rows, size: f64) -> Vec<usize> {
    let scaled = Scaled::new(rows, rows.phi.len(), size);
    let mut basis: Vec<DVector<f64>> = Vec::new();
    let mut kept = Vec::new();
    for k in 0..rows.phi.len() {
        let mut row = scaled.jac.row(k).transpose();
        let norm = row.norm();
        for _ in 0..2 {
            for e in &basis {
                row -= e * e.dot(&row);
            }
        }
        if row.norm() > 1e-8 * norm.max(f64::MIN_POSITIVE) {
            basis.push(row.normalize());
            kept.push(k);
        }
    }
    kept
}

/// Tolerances: positions to rtol·L, quaternions to rtol, velocities to
/// those times the fastest rate (gravity's √(g/L), the initial spins).
pub(super) fn settings(p: &SpatialProblem, v: &DVector<f64>, size: f64) -> Settings {
    let n = p.mechanism.n();
    let g = p.mechanism.gravity.norm();
    let spin = (0..n).map(|b| v.fixed_rows::<3>(6 * b + 3).norm()).fold(0.0, f64::max);
    let rate = 1.0f64.max((g / size).sqrt()).max(spin);
    let rtol = (0.01 * p.tolerance).clamp(1e-13, 1e-4);
    let mut atol = vec![rtol * size; 3 * n];
    atol.extend(vec![rtol; 4 * n]);
    for _ in 0..n {
        atol.extend([rtol * size * rate; 3]);
        atol.extend([rtol * rate; 3]);
    }
    atol.extend([rtol, f64::INFINITY]);
    let integrator = p.integrator.unwrap_or_else(|| Integrator::auto(p.tolerance, true));
    let automatic = p.integrator.is_none();
    let kept_bytes = crate::engine::dynamics::KEPT_BYTES;
    Settings { end: p.end, samples: p.samples, kept_bytes, rtol, atol, integrator, automatic, deadline: p.deadline }
}
