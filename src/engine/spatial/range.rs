//! The equations of motion [M Φ_qᵀ; Φ_q 0]·[a; λ] = [Q̃; γ] solved in the
//! range space of M. M = diag(m_b·I, J_b) is block diagonal; where every
//! body has a mass and an invertible J_b, a = M⁻¹(Q̃ − Φ_qᵀλ) with
//! (Φ_q M⁻¹ Φ_qᵀ)·λ = Φ_q M⁻¹ Q̃ − γ: one Cholesky factorization of an
//! m × m matrix (m the rows kept) instead of an LU of the (6n + m)² one —
//! A04's 29 rows against 59, about a sixth of the work. Q̃ is the applied
//! actions less the gyroscopic ω × J·ω. The projection's least-norm
//! corrections likewise, by Cholesky of Φ̂Φ̂ᵀ.

use super::constraints::Rows;
use super::kinematics::Scaled;
use nalgebra::{DMatrix, DMatrixView, DVector, Matrix3};

/// a, from each body's (m, J) in ground axes, the kept rows' Φ_q, Q̃ and γ;
/// None where a body has no mass or a singular J, or Φ_q M⁻¹ Φ_qᵀ is not
/// positive definite (rows dependent there): the caller then solves the
/// whole system.
pub fn accelerations(
    bodies: &[(f64, Matrix3<f64>)],
    jac: DMatrixView<'_, f64>,
    q: &DVector<f64>,
    gamma: &DVector<f64>,
) -> Option<DVector<f64>> {
    let inverse: Vec<(f64, Matrix3<f64>)> = bodies
        .iter()
        .map(|(m, j)| Some((1.0 / m.is_finite().then_some(*m).filter(|m| *m > 0.0)?, j.cholesky()?.inverse())))
        .collect::<Option<_>>()?;
    solve(&inverse, jac, q, gamma)
}

/// a as [`accelerations`], from each body's (1/m, J⁻¹) in ground axes
/// (J⁻¹ = R·J₀⁻¹·Rᵀ from the drawing's, inverted once for a run).
pub fn solve(
    inverse: &[(f64, Matrix3<f64>)],
    jac: DMatrixView<'_, f64>,
    q: &DVector<f64>,
    gamma: &DVector<f64>,
) -> Option<DVector<f64>> {
    // V = M⁻¹Φ_qᵀ, M⁻¹·x a body's three rows of translation over m, of rotation times J⁻¹.
    let inverse_mass = |x: &mut DMatrix<f64>| {
        for (b, (m1, j1)) in inverse.iter().enumerate() {
            x.rows_mut(6 * b, 3).scale_mut(*m1);
            let turned = j1 * x.fixed_rows::<3>(6 * b + 3);
            x.fixed_rows_mut::<3>(6 * b + 3).copy_from(&turned);
        }
    };
    let mut v = jac.transpose();
    inverse_mass(&mut v);
    let s = jac * &v;
    let lambda = s.cholesky()?.solve(&(v.tr_mul(q) - gamma));
    let mut a = DMatrix::from_column_slice(q.len(), 1, q.as_slice());
    inverse_mass(&mut a);
    Some(DVector::from_column_slice(a.as_slice()) - v * lambda)
}

/// The accelerations from the whole system [M Φ_qᵀ; Φ_q 0] by LU (a
/// body without mass, rows near dependence).
pub fn whole(
    blocks: &[(f64, Matrix3<f64>)],
    jac: &DMatrix<f64>,
    forces: &DVector<f64>,
    gamma: &DVector<f64>,
) -> Option<DVector<f64>> {
    let (n, m) = (jac.ncols(), jac.nrows());
    let mut rhs = DVector::zeros(n + m);
    rhs.rows_mut(0, n).copy_from(forces);
    rhs.rows_mut(n, m).copy_from(gamma);
    let mut k = DMatrix::zeros(n + m, n + m);
    for (b, (mass, j)) in blocks.iter().enumerate() {
        k.view_mut((6 * b, 6 * b), (3, 3)).fill_diagonal(*mass);
        k.view_mut((6 * b + 3, 6 * b + 3), (3, 3)).copy_from(j);
    }
    k.view_mut((n, 0), (m, n)).copy_from(jac);
    k.view_mut((0, n), (n, m)).copy_from(&jac.transpose());
    Some(k.lu().solve(&rhs)?.rows(0, n).into_owned())
}

/// The least-norm x with Φ_q·x = `rhs` on the kept rows (independent),
/// unit-free as [`Scaled`] has it: x = Φ̂ᵀ(Φ̂Φ̂ᵀ)⁻¹b̂ by Cholesky, a tenth
/// of the SVD's work; the SVD's own where Φ̂Φ̂ᵀ is near singular (its
/// factor's diagonal spread past 10⁶, Φ̂'s condition near 10⁶ or worse).
pub fn least_norm(rows: &Rows, rhs: &DVector<f64>, size: f64) -> DVector<f64> {
    let (m, cols) = rows.jac.shape();
    let row: Vec<f64> = rows.length.iter().map(|&l| if l { size } else { 1.0 }).collect();
    let col = |c: usize| if c % 6 < 3 { size } else { 1.0 };
    let scaled = DMatrix::from_fn(m, cols, |k, c| rows.jac[(k, c)] * col(c) / row[k]);
    let b = DVector::from_fn(m, |k, _| rhs[k] / row[k]);
    let factor = (&scaled * scaled.transpose()).cholesky().filter(|ch| {
        let d = ch.l_dirty().diagonal();
        d.min() > 1e-6 * d.max()
    });
    match factor {
        Some(ch) => {
            let y = scaled.tr_mul(&ch.solve(&b));
            DVector::from_fn(cols, |c, _| y[c] * col(c))
        }
        None => Scaled::new(rows, m, size).solve(rhs).0,
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{DMatrix, DVector, Matrix3};

    /// The range-space solution equals the LU of the whole system
    /// [M Φᵀ; Φ 0] (a second method) to 1e-12, on three bodies with full
    /// inertia tensors and seven independent rows; a body without mass is
    /// left to the whole system.
    #[test]
    fn the_range_space_agrees_with_the_whole_system() {
        let tensor = |k: f64| Matrix3::new(2.0 + k, 0.3, -0.1, 0.3, 1.5, 0.2 * k, -0.1, 0.2 * k, 1.0 + k);
        let bodies = [(2.0, tensor(0.1)), (0.5, tensor(0.7)), (3.0, tensor(1.3))];
        let jac = DMatrix::from_fn(7, 18, |i, c| {
            ((i * 31 + c * 17) % 13) as f64 / 6.0 - 1.0 + if i == c { 3.0 } else { 0.0 }
        });
        let q = DVector::from_fn(18, |i, _| (i as f64 * 0.7).sin());
        let gamma = DVector::from_fn(7, |i, _| (i as f64 * 1.3).cos());
        let a = super::accelerations(&bodies, jac.as_view(), &q, &gamma).expect("positive definite");
        let mut k = DMatrix::zeros(25, 25);
        for (b, (m, j)) in bodies.iter().enumerate() {
            k.view_mut((6 * b, 6 * b), (3, 3)).fill_diagonal(*m);
            k.view_mut((6 * b + 3, 6 * b + 3), (3, 3)).copy_from(j);
        }
        k.view_mut((18, 0), (7, 18)).copy_from(&jac);
        k.view_mut((0, 18), (18, 7)).copy_from(&jac.transpose());
        let mut rhs = DVector::zeros(25);
        rhs.rows_mut(0, 18).copy_from(&q);
        rhs.rows_mut(18, 7).copy_from(&gamma);
        let whole = k.lu().solve(&rhs).unwrap().rows(0, 18).into_owned();
        assert!((&a - &whole).amax() < 1e-12 * whole.amax(), "{a} against {whole}");
        let massless = [(0.0, tensor(0.1)), bodies[1], bodies[2]];
        assert!(super::accelerations(&massless, jac.as_view(), &q, &gamma).is_none());
    }
    /// The projection's least-norm correction by Cholesky equals the SVD's
    /// least-squares solution of least norm (kinematics::Scaled, a second
    /// method) to 1e-12, on seven independent rows, lengths and cosines, in
    /// a drawing of 2.5 m; it solves the rows exactly and is orthogonal to
    /// their null space (x in the range of the scaled Φ̂ᵀ).
    #[test]
    fn the_least_norm_correction_agrees_with_the_svd() {
        use super::super::constraints::Rows;
        use super::super::kinematics::Scaled;
        let jac = DMatrix::from_fn(7, 18, |i, c| {
            ((i * 31 + c * 17) % 13) as f64 / 6.0 - 1.0 + if i == c { 3.0 } else { 0.0 }
        });
        let rows = Rows {
            phi: DVector::zeros(7),
            jac,
            rate: DVector::zeros(7),
            gamma: DVector::zeros(7),
            length: (0..7).map(|i| i % 3 != 2).collect(),
        };
        let rhs = DVector::from_fn(7, |i, _| (i as f64 * 0.9).sin());
        let x = super::least_norm(&rows, &rhs, 2.5);
        let (svd, _) = Scaled::new(&rows, 7, 2.5).solve(&rhs);
        assert!((&x - &svd).amax() < 1e-12 * svd.amax(), "{x} against {svd}");
        assert!((&rows.jac * &x - &rhs).amax() < 1e-12);
    }
}
