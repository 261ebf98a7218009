//! Radau IIA's Newton iterations on the stage increments Z: the simplified
//! one on the transformed stages W = T⁻¹Z with one Jacobian J (RADAU5),
//! and the full one with each stage's Jacobian; J by forward differences.

use super::{ALPHA, BETA, C, FULL_NEWTON_MAXITER, Factors, GAMMA, NEWTON_MAXITER, Newton, Radau5, Stages, T, TI};
use crate::engine::numeric::ode::Rhs;
use nalgebra::{Complex, DMatrix, DVector};

impl Radau5 {
    /// J by forward differences at the current state.
    pub(super) fn jacobian(&mut self, f: &mut impl Rhs) {
        let (y, fy) = (self.y.clone(), self.f.clone());
        self.jac = self.difference_jacobian(f, self.t, &y, &fy);
        self.simplified_fails = false;
        self.jac_current = true;
    }

    /// ∂f/∂y at (t, y) by forward differences, f(t, y) = fy, each column
    /// stepped by √ε times the component's size (its value, or its
    /// tolerance's scale).
    fn difference_jacobian(&mut self, f: &mut impl Rhs, t: f64, y0: &[f64], fy: &[f64]) -> DMatrix<f64> {
        let n = y0.len();
        let (mut y, mut df, mut jac) = (y0.to_vec(), vec![0.0; n], DMatrix::zeros(n, n));
        for j in 0..n {
            let size = if self.atol[j].is_finite() { self.atol[j] / self.rtol } else { 1.0 };
            y[j] = y0[j] + f64::EPSILON.sqrt() * y0[j].abs().max(size).max(f64::MIN_POSITIVE);
            let delta = y[j] - y0[j];
            f(t, &y, &mut df);
            for i in 0..n {
                jac[(i, j)] = (df[i] - fy[i]) / delta;
            }
            y[j] = y0[j];
        }
        self.evaluations += n;
        self.jacobians += 1;
        jac
    }

    /// LU of γ/h − J and (α − iβ)/h − J (None when either is singular).
    pub(super) fn factor(&self, h: f64) -> Option<Factors> {
        let n = self.y.len();
        let real = DMatrix::from_diagonal_element(n, n, GAMMA / h) - &self.jac;
        let mu = Complex::new(ALPHA / h, -BETA / h);
        let complex = DMatrix::from_diagonal_element(n, n, mu) - self.jac.map(|v| Complex::new(v, 0.0));
        let (real, complex) = (real.lu(), complex.lu());
        (real.is_invertible() && complex.is_invertible()).then_some((real, complex))
    }

    /// Z extrapolated from the last step's polynomial (zero on the first step).
    pub(super) fn start_values(&self, h: f64) -> Stages {
        match &self.previous {
            Some(p) => C.map(|c| p.at(self.t + c * h).iter().zip(&self.y).map(|(a, b)| a - b).collect()),
            None => [0, 1, 2].map(|_| vec![0.0; self.y.len()]),
        }
    }

    /// The simplified Newton iteration for Z, started from the last step's
    /// polynomial (zero on the first step).
    pub(super) fn newton(&mut self, f: &mut impl Rhs, h: f64) -> Newton {
        let lu = self.lu.take().expect("factored");
        let outcome = self.iterate(f, h, &lu);
        self.lu = Some(lu);
        outcome
    }

    fn iterate(&mut self, f: &mut impl Rhs, h: f64, (lu_real, lu_complex): &Factors) -> Newton {
        let n = self.y.len();
        let mut z = self.start_values(h);
        let mut w = transform(&TI, &z);
        let scale: Vec<f64> = (0..n).map(|i| self.atol[i] + self.rtol * self.y[i].abs()).collect();
        let (mut stage, mut fs) = (vec![0.0; n], [vec![0.0; n], vec![0.0; n], vec![0.0; n]]);
        let (mut norm_old, mut rate) = (None::<f64>, f64::NAN);
        self.contraction = self.contraction.max(f64::EPSILON).powf(0.8);
        for k in 0..NEWTON_MAXITER {
            for (s, fs) in fs.iter_mut().enumerate() {
                stage.iter_mut().enumerate().for_each(|(i, v)| *v = self.y[i] + z[s][i]);
                f(self.t + C[s] * h, &stage, fs);
            }
            self.evaluations += 3;
            if fs.iter().flatten().any(|v| !v.is_finite()) {
                return Newton::NotFinite;
            }
            let g = transform(&TI, &fs);
            let mut real = DVector::from_fn(n, |i, _| g[0][i] - GAMMA / h * w[0][i]);
            let mu = Complex::new(ALPHA / h, -BETA / h);
            let mut complex =
                DVector::from_fn(n, |i, _| Complex::new(g[1][i], g[2][i]) - mu * Complex::new(w[1][i], w[2][i]));
            lu_real.solve_mut(&mut real);
            lu_complex.solve_mut(&mut complex);
            let dw = [
                real.as_slice().to_vec(),
                complex.iter().map(|c| c.re).collect(),
                complex.iter().map(|c| c.im).collect(),
            ];
            let norm = rms3(&dw, &scale);
            if let Some(old) = norm_old {
                rate = norm / old;
                if rate >= 0.99 {
                    return Newton::Failed;
                }
                self.contraction = rate / (1.0 - rate);
                let remaining = rate.powi((NEWTON_MAXITER - 1 - k) as i32);
                if self.contraction * norm * remaining > self.newton_tol {
                    return Newton::Failed;
                }
            }
            for s in 0..3 {
                w[s].iter_mut().zip(&dw[s]).for_each(|(w, d)| *w += d);
            }
            z = transform(&T, &w);
            if self.contraction * norm <= self.newton_tol {
                return Newton::Converged { z, iterations: k + 1, rate };
            }
            norm_old = Some(norm);
        }
        Newton::Failed
    }

    /// Newton's method on the collocation equations Z = h(A⊗I)F(Z) with
    /// each stage's own Jacobian (one 3n system, 3n more evaluations an
    /// iteration), where the simplified iteration and the Krylov one both
    /// stall with a fresh J: a stiff spring that turns with its link turns
    /// the stiff direction within the step, and one J for the three stages
    /// contracts only while (hω)²·(hΩ) stays small (ω the spring's, Ω the
    /// link's rate). The last stage's Jacobian (at y₁) is kept for the next step.
    pub(super) fn full_newton(&mut self, f: &mut impl Rhs, h: f64) -> Newton {
        let n = self.y.len();
        let a = radau_matrix();
        let scale: Vec<f64> = (0..n).map(|i| self.atol[i] + self.rtol * self.y[i].abs()).collect();
        let mut z = self.start_values(h);
        let mut norm_old = None::<f64>;
        let mut jacobians = [DMatrix::zeros(0, 0), DMatrix::zeros(0, 0), DMatrix::zeros(0, 0)];
        for k in 0..FULL_NEWTON_MAXITER {
            let mut fs = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
            for s in 0..3 {
                let stage: Vec<f64> = self.y.iter().zip(&z[s]).map(|(y, z)| y + z).collect();
                f(self.t + C[s] * h, &stage, &mut fs[s]);
                self.evaluations += 1;
                jacobians[s] = self.difference_jacobian(f, self.t + C[s] * h, &stage, &fs[s]);
            }
            if fs.iter().flatten().chain(jacobians.iter().flatten()).any(|v| !v.is_finite()) {
                return Newton::NotFinite;
            }
            let g = DMatrix::from_fn(3 * n, 3 * n, |row, col| {
                let (s, i, r, j) = (row / n, row % n, col / n, col % n);
                f64::from(u8::from(row == col)) - h * a[s][r] * jacobians[r][(i, j)]
            });
            let mut dz = DVector::from_fn(3 * n, |row, _| {
                let (s, i) = (row / n, row % n);
                h * (0..3).map(|r| a[s][r] * fs[r][i]).sum::<f64>() - z[s][i]
            });
            if !g.lu().solve_mut(&mut dz) {
                return Newton::Failed;
            }
            let dz: Stages = [0, 1, 2].map(|s| dz.as_slice()[s * n..(s + 1) * n].to_vec());
            let norm = rms3(&dz, &scale);
            (0..3).for_each(|s| z[s].iter_mut().zip(&dz[s]).for_each(|(z, d)| *z += d));
            let rate = norm_old.map_or(f64::NAN, |old| norm / old);
            if rate >= 1.0 {
                return Newton::Failed;
            }
            if norm <= self.newton_tol * 1e-2 || rate / (1.0 - rate) * norm <= self.newton_tol {
                self.pending_jac = Some(std::mem::replace(&mut jacobians[2], DMatrix::zeros(0, 0)));
                return Newton::Converged { z, iterations: k + 1, rate: 0.0 };
            }
            norm_old = Some(norm);
        }
        Newton::Failed
    }
}

/// Newton's convergence test on W (scaled RMS), RADAU5's: from its
/// transformed tolerance rtol' = 0.1·rtol^⅔, max(10ε/rtol', min(0.03, √rtol')).
/// SciPy's, from rtol itself, sits below the rounding of a stiff f at tight
/// tolerances: a position's last bit times 10¹⁰ N/m moves a stiff mode's
/// velocity by ε·L·√(k/m) ≈ 10⁻¹¹ m/s, 3 % of the velocity tolerance at
/// rtol 10⁻¹⁰, and Newton stalls there at every step size.
pub(super) fn newton_tolerance(rtol: f64) -> f64 {
    let transformed = 0.1 * rtol.powf(2.0 / 3.0);
    (10.0 * f64::EPSILON / transformed).max(0.03f64.min(transformed.sqrt()))
}

/// The Radau IIA matrix A (Hairer & Wanner, Table IV.5.6).
pub(super) fn radau_matrix() -> [[f64; 3]; 3] {
    let s6 = 6f64.sqrt();
    [
        [(88.0 - 7.0 * s6) / 360.0, (296.0 - 169.0 * s6) / 1800.0, (-2.0 + 3.0 * s6) / 225.0],
        [(296.0 + 169.0 * s6) / 1800.0, (88.0 + 7.0 * s6) / 360.0, (-2.0 - 3.0 * s6) / 225.0],
        [(16.0 - s6) / 36.0, (16.0 + s6) / 36.0, 1.0 / 9.0],
    ]
}

/// M·Z for a 3×3 M acting on the three stages.
pub(super) fn transform(m: &[[f64; 3]; 3], z: &Stages) -> Stages {
    let n = z[0].len();
    m.map(|row| (0..n).map(|i| row[0] * z[0][i] + row[1] * z[1][i] + row[2] * z[2][i]).collect())
}

/// RMS over all the vectors' components, each over its scale (infinite scales count as zero).
pub(super) fn rms3(v: &[Vec<f64>], scale: &[f64]) -> f64 {
    let count = (v.len() * scale.len()).max(1) as f64;
    (v.iter().flat_map(|x| x.iter().zip(scale).map(|(a, s)| (a / s).powi(2))).sum::<f64>() / count).sqrt()
}
