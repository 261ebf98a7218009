//! Driving efforts at actuators other than the inputs' own coordinates.
//!
//! Input i's coordinate φ_i may be a point's displacement or a body's
//! rotation while its effort F_a acts at a joint a (the actuator), whose
//! coordinate c_a(q) is its relative rotation or displacement. F_a enters
//! the equilibrium as ∇c_a·F_a: in Φ_qᵀλ = Q − M q̈ the driver rows of Φ_q
//! are replaced by the rows ∇c_a (the matrix J_a here), whose multipliers
//! are then −F_a. Virtual power checks it independently: along each
//! virtual motion g_i = ∂q/∂φ_i, Σ_a K_ia F_a = T_i with K_ia = ∇c_a·g_i and
//! T_i = g_iᵀ(M q̈ − Q). Where J_a (equivalently K) is singular the
//! actuators cannot drive the inputs: their forces do no work on the motion.

use crate::engine::constraints::{State, System, evaluate_into};
use crate::engine::kinematics::SINGULAR_CONDITION;
use crate::engine::model::{Coordinate, Mechanism};
use crate::engine::numeric::lu::Lu;
use crate::engine::numeric::scaled::{estimated_condition, row_scales};
use nalgebra::{DMatrix, DVector};

/// J_a at the current position, and its LU.
pub(super) struct Actuated {
    /// The mechanism with each driver measuring its actuator's coordinate.
    m: Mechanism,
    sys: System,
    pub lu: Lu,
    /// The coordinates' length scales (`numeric::scaled`).
    cols: Vec<f64>,
    scratch: [Vec<f64>; 3],
}

impl Actuated {
    /// Where some input's effort acts elsewhere than on its coordinate.
    pub fn new(m: &Mechanism) -> Option<Self> {
        if !m.drivers.iter().any(|d| d.actuated_elsewhere()) {
            return None;
        }
        let mut by_actuators = m.clone();
        for d in &mut by_actuators.drivers {
            d.coordinate = d.actuator.map_or(d.coordinate, Coordinate::Joint);
        }
        let cols = m.column_lengths();
        Some(Self { m: by_actuators, sys: System::default(), lu: Lu::default(), cols, scratch: Default::default() })
    }

    /// J_a at q and its LU; false where it is singular.
    pub fn at(&mut self, q: &[f64], inputs: &[[f64; 3]]) -> bool {
        evaluate_into(&self.m, &State { q, qd: None, inputs }, &mut self.sys);
        let [x, y, rows] = &mut self.scratch;
        row_scales(&self.sys.jacobian, &self.cols, rows);
        self.lu.factor(&self.sys.jacobian)
            && estimated_condition(&self.sys.jacobian, &self.lu, [rows, &self.cols], [x, y]) <= SINGULAR_CONDITION
    }

    pub fn jacobian(&self) -> &DMatrix<f64> {
        &self.sys.jacobian
    }

    /// The efforts F from the inputs' generalized forces T (one per input,
    /// `g` their virtual motions g_i): K F = T, NaN where K is singular.
    pub fn efforts(&self, g: &[Vec<f64>], t: &[f64]) -> Vec<f64> {
        let j = &self.sys.jacobian;
        let first = j.nrows() - g.len();
        let k = DMatrix::from_fn(g.len(), g.len(), |i, a| (0..j.ncols()).map(|c| j[(first + a, c)] * g[i][c]).sum());
        match k.lu().solve(&DVector::from_column_slice(t)) {
            Some(f) if f.iter().all(|v| v.is_finite()) => f.iter().copied().collect(),
            _ => vec![f64::NAN; t.len()],
        }
    }
}
