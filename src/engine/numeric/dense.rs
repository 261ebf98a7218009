//! LU factorisation with partial pivoting of a small square matrix, for the
//! per-position solves of kinematics and kinetostatics.
//!
//! Why not nalgebra's `LU` on a `DMatrix`: for the 6–20 coordinates of a
//! planar mechanism its generic code spends most of its time outside the
//! arithmetic (callgrind, 9×9: 3.1k instructions to factor)
//! and it has no transposed solve (the multipliers need Φ_qᵀλ = b). Here the factors live in one buffer and
//! the solves are slice loops; `tests` checks them against nalgebra.

use nalgebra::DMatrix;

/// P A = L U, with L unit lower triangular and U upper triangular stored
/// together in `lu` (column-major, as nalgebra stores A, so every inner loop
/// runs down a contiguous column), and P as the row order `perm`:
/// row k of P A is row `perm[k]` of A.
#[derive(Clone, Debug)]
pub struct Lu {
    n: usize,
    lu: Vec<f64>,
    perm: Vec<usize>,
}

impl Lu {
    /// Factors a square matrix; `None` when a pivot is exactly zero or not finite.
    pub fn new(a: &DMatrix<f64>) -> Option<Self> {
        let n = a.nrows();
        debug_assert_eq!(n, a.ncols());
        let mut lu = a.as_slice().to_vec();
        let mut perm: Vec<usize> = (0..n).collect();
        for k in 0..n {
            let column = &lu[k * n..(k + 1) * n];
            let p = (k..n).fold(k, |p, i| if column[i].abs() > column[p].abs() { i } else { p });
            let pivot = column[p];
            if pivot == 0.0 || !pivot.is_finite() {
                return None;
            }
            if p != k {
                perm.swap(p, k);
                for c in 0..n {
                    lu.swap(c * n + p, c * n + k);
                }
            }
            let (left, right) = lu.split_at_mut((k + 1) * n);
            let l = &mut left[k * n + k + 1..];
            l.iter_mut().for_each(|v| *v /= pivot);
            for column in right.chunks_exact_mut(n) {
                let u = column[k];
                if u != 0.0 {
                    column[k + 1..].iter_mut().zip(l.iter()).for_each(|(v, l)| *v -= l * u);
                }
            }
        }
        Some(Self { n, lu, perm })
    }

    /// Overwrites `x` (holding P b) with the solution of L U x = P b.
    fn substitute(&self, x: &mut [f64]) {
        let n = self.n;
        for (k, column) in self.lu.chunks_exact(n).enumerate() {
            let xk = x[k];
            if xk != 0.0 {
                x[k + 1..].iter_mut().zip(&column[k + 1..]).for_each(|(v, l)| *v -= l * xk);
            }
        }
        for (k, column) in self.lu.chunks_exact(n).enumerate().rev() {
            x[k] /= column[k];
            let xk = x[k];
            x[..k].iter_mut().zip(&column[..k]).for_each(|(v, u)| *v -= u * xk);
        }
    }

    /// x with A x = b.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let mut x: Vec<f64> = self.perm.iter().map(|&p| b[p]).collect();
        self.substitute(&mut x);
        x
    }

    /// y with Aᵀ y = b (Uᵀ w = b, Lᵀ z = w, y = Pᵀ z).
    pub fn solve_transposed(&self, b: &[f64]) -> Vec<f64> {
        let n = self.n;
        let mut w = b.to_vec();
        for (i, column) in self.lu.chunks_exact(n).enumerate() {
            let s: f64 = column[..i].iter().zip(&w[..i]).map(|(u, v)| u * v).sum();
            w[i] = (w[i] - s) / column[i];
        }
        for (i, column) in self.lu.chunks_exact(n).enumerate().rev() {
            let s: f64 = column[i + 1..].iter().zip(&w[i + 1..]).map(|(l, v)| l * v).sum();
            w[i] -= s;
        }
        let mut y = vec![0.0; n];
        for (k, &p) in self.perm.iter().enumerate() {
            y[p] = w[k];
        }
        y
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// A fixed, well-mixed 7×7 matrix that needs row exchanges (a zero on the diagonal).
    fn sample() -> DMatrix<f64> {
        DMatrix::from_fn(7, 7, |i, j| if i == j { 0.0 } else { ((3 * i + 5 * j) as f64).sin() + (i as f64) * 0.1 })
    }

    #[test]
    fn solves_and_transposed_solves_match_nalgebra() {
        let a = sample();
        let b: Vec<f64> = (0..7).map(|k| (k as f64).cos()).collect();
        let lu = Lu::new(&a).unwrap();
        let reference = a.clone().lu().solve(&DVector::from_column_slice(&b)).unwrap();
        let transposed = a.transpose().lu().solve(&DVector::from_column_slice(&b)).unwrap();
        for (x, r) in lu.solve(&b).iter().zip(reference.iter()) {
            assert!((x - r).abs() < 1e-12 * r.abs().max(1.0), "{x} vs {r}");
        }
        for (x, r) in lu.solve_transposed(&b).iter().zip(transposed.iter()) {
            assert!((x - r).abs() < 1e-12 * r.abs().max(1.0), "{x} vs {r}");
        }
    }

    #[test]
    fn a_singular_matrix_has_no_factors() {
        let mut a = sample();
        let row = a.row(2).into_owned();
        a.row_mut(4).copy_from(&(row * 2.0));
        // Exact dependence may leave a round-off pivot; a zero column cannot.
        a.column_mut(3).fill(0.0);
        assert!(Lu::new(&a).is_none());
    }
}
