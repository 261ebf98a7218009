//! The singular value decomposition, always returning: nalgebra's `svd()`
//! iterates until it converges, and on a matrix holding NaN or infinity it
//! never does (found by the fuzz test: a flywheel whose exact inertia came
//! out NaN ran its time check for ever inside one SVD). Here a non-finite
//! matrix, or one that does not converge in a bounded number of sweeps, is
//! `None`, and the caller says why.

use nalgebra::{DMatrix, DVector, Dyn, SVD};

/// Sweeps allowed; a finite matrix of the sizes met here converges in tens.
const MAX_ITERATIONS: usize = 10_000;

/// The SVD of `m` (singular values sorted, largest first), or None.
pub fn svd(m: DMatrix<f64>, compute_u: bool, compute_v: bool) -> Option<SVD<f64, Dyn, Dyn>> {
    // nalgebra panics on an empty matrix (found by schemathesis: a sketch with no dimensions).
    if m.is_empty() || !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    // 5 ε: the tolerance of nalgebra's own `svd()`, so results are the same where it returns.
    m.try_svd(compute_u, compute_v, 5.0 * f64::EPSILON, MAX_ITERATIONS)
}

/// The singular values of `m`, largest first, or None.
pub fn singular_values(m: &DMatrix<f64>) -> Option<DVector<f64>> {
    svd(m.clone(), false, false).map(|s| s.singular_values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_matrix_with_nan_has_no_svd_and_does_not_hang() {
        let m = DMatrix::from_row_slice(2, 2, &[1.0, f64::NAN, 0.0, 1.0]);
        assert!(svd(m, true, true).is_none());
        assert!(svd(DMatrix::zeros(0, 3), true, true).is_none(), "an empty matrix has none either");
        let s = singular_values(&DMatrix::from_row_slice(2, 2, &[3.0, 0.0, 0.0, 4.0])).unwrap();
        assert_eq!(s.as_slice(), &[4.0, 3.0]);
    }
}
