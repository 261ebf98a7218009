//! The joint rows the equations of motion can use at a configuration.
//!
//! Φ_q of the joints may lose rank: for ever when constraints repeat each
//! other (a redundant crank), or for an instant at a singular position — a
//! parallelogram four-bar lying flat, where it could fold into an
//! antiparallelogram. There the equations Φ_q q̈ = γ and Φ_q q̇ = 0 amplify
//! the tiny violation Φ ≈ ε left by the integrator by 1/σ_min: the
//! constrained motion of the level set Φ = ε cannot pass the point at all
//! (a hyperbola around it), the accelerations blow up and the step size
//! underflows.
//!
//! So the rows are replaced by their combinations along the left singular
//! vectors uᵢ of the scaled R·Φ_q·S (its SVD; S the columns' scale, R each
//! row's own size, `numeric::scaled`: the same matrix at any size of
//! the mechanism). Those with
//! σᵢ ≥ τ·σ_max (τ = [`TAU`]) are used as they are. The nearly dependent
//! ones are *held*: the row uᵢᵀΦ_q/σᵢ (a unit vector vᵢᵀ, the fold's
//! direction) gets a zero right-hand side in the velocity and acceleration
//! equations instead of the amplified uᵢᵀγ/σᵢ, so the mechanism keeps its
//! fold velocity through the point — exact for a parallelogram, whose
//! branch has no fold motion at all — and the position correction leaves
//! them alone. Combinations dependent to rounding (σᵢ ≤ 1e-10·σ_max) are
//! redundant constraints and are dropped. The joints these combinations
//! touch have indeterminate reactions. A column-pivoted QR tells first,
//! cheaply, whether any singular value can be that small; the SVD runs
//! only then.

use crate::engine::numeric::scaled::{row_scales, scaled};
use crate::engine::numeric::svd::svd;
use nalgebra::{DMatrix, DVector};

/// Relative singular value below which a combination of rows is held.
pub const TAU: f64 = 1e-5;
/// Relative singular value below which a combination is redundant (the rows
/// are dependent to rounding: a repeated constraint).
const REDUNDANT: f64 = 1e-10;

/// How the joint rows are combined at one configuration.
pub(crate) enum Rows {
    /// All rows, independent to within τ.
    All,
    /// `kept` (k × r): orthonormal combinations of the rows used as they
    /// are; `held` (h × r): the nearly dependent ones, uᵢ/σᵢ, which hold the
    /// motion they constrain (zero right-hand side). The multipliers of the
    /// rows outside the span of `kept` are not determinate.
    /// `basis` (k × r): the kept uᵢ themselves (the combinations of R·Φ_q).
    Reduced { kept: DMatrix<f64>, held: DMatrix<f64>, basis: DMatrix<f64> },
}

impl Rows {
    /// Decides for the joint Jacobian `jac` (r × n); `scale` multiplies
    /// each column so that all are alike in units (angles by 1/length).
    pub fn of(jac: &DMatrix<f64>, scale: &[f64]) -> Self {
        if jac.nrows() == 0 {
            return Self::All;
        }
        let mut size = Vec::new();
        row_scales(jac, scale, &mut size);
        let scaled = self::scaled(jac, [&size, scale]);
        let r = scaled.clone().col_piv_qr().r();
        let diag: Vec<f64> = (0..r.nrows().min(r.ncols())).map(|i| r[(i, i)].abs()).collect();
        let (lo, hi) = diag.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), d| (lo.min(*d), hi.max(*d)));
        // |R_ii| brackets the singular values within a modest factor.
        if diag.len() == jac.nrows() && lo >= 10.0 * TAU * hi {
            return Self::All;
        }
        // Left singular vectors: the thin SVD has them for every non-zero σ
        // (with more rows than coordinates the missing ones have σ = 0).
        // A Jacobian that is not finite (a state gone to NaN): keep every row, and the
        // solve's NaN rejects the step.
        let Some((Some(u), sigma)) = svd(scaled, true, false).map(|s| (s.u, s.singular_values)) else {
            return Self::All;
        };
        let top = sigma.max();
        let keep: Vec<usize> = (0..sigma.len()).filter(|&i| sigma[i] >= TAU * top).collect();
        let held: Vec<usize> =
            (0..sigma.len()).filter(|&i| sigma[i] < TAU * top && sigma[i] > REDUNDANT * top).collect();
        if keep.len() == jac.nrows() {
            return Self::All;
        }
        let rows = |idx: &[usize], unit: bool, r: &[f64]| {
            DMatrix::from_fn(idx.len(), jac.nrows(), |i, j| {
                u[(j, idx[i])] * r.get(j).unwrap_or(&1.0) / if unit { 1.0 } else { sigma[idx[i]] }
            })
        };
        Self::Reduced { kept: rows(&keep, true, &size), held: rows(&held, false, &size), basis: rows(&keep, true, &[]) }
    }

    /// Whether a nearly dependent combination is held here (a singular position).
    pub fn holds(&self) -> bool {
        matches!(self, Self::Reduced { held, .. } if held.nrows() > 0)
    }

    /// The rows a position correction uses: P·Φ_q (or P·Φ).
    pub fn positions(&self, a: DMatrix<f64>) -> DMatrix<f64> {
        match self {
            Self::All => a,
            Self::Reduced { kept, .. } => kept * a,
        }
    }

    pub fn position_residual(&self, phi: DVector<f64>) -> DVector<f64> {
        match self {
            Self::All => phi,
            Self::Reduced { kept, .. } => kept * phi,
        }
    }

    /// The rows of the velocity and acceleration equations: [P; H]·Φ_q.
    pub fn motion(&self, jac: DMatrix<f64>) -> DMatrix<f64> {
        match self {
            Self::All => jac,
            Self::Reduced { kept, held, .. } => {
                let (k, h) = (kept.nrows(), held.nrows());
                let mut out = DMatrix::zeros(k + h, jac.ncols());
                out.rows_mut(0, k).copy_from(&(kept * &jac));
                out.rows_mut(k, h).copy_from(&(held * &jac));
                out
            }
        }
    }

    /// The right-hand side of the acceleration equations: [P·γ; 0].
    pub fn gamma(&self, gamma: DVector<f64>) -> DVector<f64> {
        match self {
            Self::All => gamma,
            Self::Reduced { kept, held, .. } => {
                let mut out = DVector::zeros(kept.nrows() + held.nrows());
                out.rows_mut(0, kept.nrows()).copy_from(&(kept * gamma));
                out
            }
        }
    }

    /// The multipliers of the original rows from those of [`Self::motion`]'s.
    pub fn multipliers(&self, lambda: DVector<f64>) -> DVector<f64> {
        match self {
            Self::All => lambda,
            Self::Reduced { kept, held, .. } => {
                let k = kept.nrows();
                kept.transpose() * lambda.rows(0, k) + held.transpose() * lambda.rows(k, held.nrows())
            }
        }
    }

    /// Whether original row `row` takes part in a combination not kept:
    /// its unit vector is not in the span of `kept` (1 − Σ kₖ² > 1e-12).
    pub fn touches_loose(&self, row: usize) -> bool {
        match self {
            Self::All => false,
            Self::Reduced { basis, .. } => 1.0 - basis.column(row).norm_squared() > 1e-12,
        }
    }
}
