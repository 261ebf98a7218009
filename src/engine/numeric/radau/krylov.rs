//! Newton's method on the collocation equations with each stage's own
//! Jacobian, its linear systems solved by GMRES instead of formed: a
//! product Jₛ·v is one evaluation (a forward difference along v), and the
//! simplified iteration's solve with the one J already factored (γ/h − J,
//! (α − iβ)/h − J) is the preconditioner. Where the stages' Jacobians
//! differ from J in a few directions only (a stiff spring turning with its
//! link turns its stiff direction within the step), the preconditioned
//! system is the identity but for those few, and GMRES finds them in as
//! many products — three evaluations each, against 3n for the three
//! difference Jacobians and a 3n × 3n LU for the formed system.

use super::newton::{radau_matrix, rms3};
use super::{ALPHA, BETA, C, FULL_NEWTON_MAXITER, Factors, GAMMA, Newton, Radau5, Stages, T, TI};
use crate::engine::numeric::ode::Rhs;
use nalgebra::{Complex, DMatrix, DVector};

/// GMRES's most products an iteration, and the residual reduction it stops at.
const KRYLOV_MAXITER: usize = 30;
const KRYLOV_REDUCTION: f64 = 1e-3;

/// The stages at one Newton iterate: their values Yₛ = y + zₛ and F there.
struct Iterate {
    t: [f64; 3],
    stages: Stages,
    fs: Stages,
}

impl Radau5 {
    /// Newton's iteration on Z = h(A⊗I)F(Z), each step's system (I − h(A⊗I)Ĵ)·ΔZ = r
    /// with Ĵ the stages' Jacobians, solved by GMRES preconditioned with J's factors.
    pub(super) fn krylov_newton(&mut self, f: &mut impl Rhs, h: f64) -> Newton {
        let lu = self.lu.take().expect("factored");
        let outcome = self.krylov_iterate(f, h, &lu);
        self.lu = Some(lu);
        outcome
    }

    fn krylov_iterate(&mut self, f: &mut impl Rhs, h: f64, lu: &Factors) -> Newton {
        let n = self.y.len();
        let a = radau_matrix();
        let scale: Vec<f64> = (0..n).map(|i| self.atol[i] + self.rtol * self.y[i].abs()).collect();
        // GMRES's weights: a component without a tolerance weighed by its size.
        let weight: Vec<f64> = (0..n)
            .map(|i| if scale[i].is_finite() { 1.0 / scale[i] } else { 1.0 / (self.rtol * self.y[i].abs().max(1.0)) })
            .collect();
        let mut z = self.start_values(h);
        let mut norm_old = None::<f64>;
        let mut products = 0;
        for k in 0..FULL_NEWTON_MAXITER {
            let Some((dz, m)) = self.increment(f, (h, &a, lu), &z, &weight) else { return Newton::NotFinite };
            products += m;
            let norm = rms3(&dz, &scale);
            (0..3).for_each(|s| z[s].iter_mut().zip(&dz[s]).for_each(|(z, d)| *z += d));
            let rate = norm_old.map_or(f64::NAN, |old| norm / old);
            if rate >= 1.0 {
                return Newton::Failed;
            }
            if norm <= self.newton_tol * 1e-2 || rate / (1.0 - rate) * norm <= self.newton_tol {
                self.krylov = Some((products, k + 1));
                return Newton::Converged { z, iterations: k + 1, rate: 0.0 };
            }
            norm_old = Some(norm);
        }
        Newton::Failed
    }

    /// Newton's increment ΔZ at Z and GMRES's products (None where f is not
    /// finite): the residual r = h(A⊗I)F(Z) − Z preconditioned, then GMRES.
    fn increment(
        &mut self,
        f: &mut impl Rhs,
        system: (f64, &[[f64; 3]; 3], &Factors),
        z: &Stages,
        weight: &[f64],
    ) -> Option<(Stages, usize)> {
        let (n, (h, a, lu)) = (self.y.len(), system);
        let t = C.map(|c| self.t + c * h);
        let stages: Stages = [0, 1, 2].map(|s| self.y.iter().zip(&z[s]).map(|(y, z)| y + z).collect());
        let mut fs = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        (0..3).for_each(|s| f(t[s], &stages[s], &mut fs[s]));
        self.evaluations += 3;
        if fs.iter().flatten().any(|v| !v.is_finite()) {
            return None;
        }
        let here = Iterate { t, stages, fs };
        let combined = |s: usize, i: usize| h * (0..3).map(|q| a[s][q] * here.fs[q][i]).sum::<f64>();
        let r: Stages = [0, 1, 2].map(|s| (0..n).map(|i| combined(s, i) - z[s][i]).collect());
        let b = precondition(lu, h, &r);
        let b: Vec<f64> = (0..3 * n).map(|k| b[k / n][k % n] * weight[k % n]).collect();
        let (x, m) = self.gmres(f, system, &here, &b, weight)?;
        Some(([0, 1, 2].map(|s| (0..n).map(|i| x[s * n + i] / weight[i]).collect()), m))
    }

    /// The preconditioned operator's product P⁻¹(I − h(A⊗I)Ĵ)·v, Ĵₛ·vₛ by a
    /// forward difference of f along vₛ (None where f is not finite there).
    fn operator(
        &mut self,
        f: &mut impl Rhs,
        (h, a, lu): (f64, &[[f64; 3]; 3], &Factors),
        here: &Iterate,
        v: &Stages,
    ) -> Option<Stages> {
        let n = self.y.len();
        let mut jv: Stages = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        for s in 0..3 {
            let size = |i: usize| if self.atol[i].is_finite() { self.atol[i] / self.rtol } else { 1.0 };
            let largest = (0..n).map(|i| v[s][i].abs() / here.stages[s][i].abs().max(size(i))).fold(0.0, f64::max);
            if largest == 0.0 {
                continue;
            }
            let sigma = f64::EPSILON.sqrt() / largest;
            let moved: Vec<f64> = (0..n).map(|i| here.stages[s][i] + sigma * v[s][i]).collect();
            f(here.t[s], &moved, &mut jv[s]);
            self.evaluations += 1;
            jv[s].iter_mut().zip(&here.fs[s]).for_each(|(d, f0)| *d = (*d - f0) / sigma);
        }
        if jv.iter().flatten().any(|x| !x.is_finite()) {
            return None;
        }
        let product: Stages =
            [0, 1, 2].map(|s| (0..n).map(|i| v[s][i] - h * (0..3).map(|q| a[s][q] * jv[q][i]).sum::<f64>()).collect());
        Some(precondition(lu, h, &product))
    }

    /// GMRES on B·x = b, B the preconditioned operator, in the weighted
    /// norm, from zero to a residual [`KRYLOV_REDUCTION`] of |b|; its
    /// products kept as the deflation for the next iterates.
    fn gmres(
        &mut self,
        f: &mut impl Rhs,
        system: (f64, &[[f64; 3]; 3], &Factors),
        here: &Iterate,
        b: &[f64],
        weight: &[f64],
    ) -> Option<(Vec<f64>, usize)> {
        let n = weight.len();
        let to_flat = |x: &Stages| -> Vec<f64> { (0..3 * n).map(|k| x[k / n][k % n] * weight[k % n]).collect() };
        let from_flat = |u: &[f64]| -> Stages { [0, 1, 2].map(|s| (0..n).map(|i| u[s * n + i] / weight[i]).collect()) };
        let mut products = 0;
        let mut apply = |v: &[f64]| -> Option<Vec<f64>> {
            products += 1;
            Some(to_flat(&self.operator(f, system, here, &from_flat(v))?))
        };
        let x = arnoldi(&mut apply, b, KRYLOV_REDUCTION * norm(b))?;
        Some((x, products))
    }
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// GMRES from zero on B·x = r (Arnoldi by modified Gram–Schmidt, Givens
/// rotations), until the residual is below `target` or after
/// [`KRYLOV_MAXITER`] products; None where a product is not finite.
fn arnoldi(apply: &mut impl FnMut(&[f64]) -> Option<Vec<f64>>, r: &[f64], target: f64) -> Option<Vec<f64>> {
    let beta = norm(r);
    if beta <= target {
        return Some(vec![0.0; r.len()]);
    }
    let dot = |p: &[f64], q: &[f64]| p.iter().zip(q).map(|(x, y)| x * y).sum::<f64>();
    let mut basis: Vec<Vec<f64>> = vec![r.iter().map(|x| x / beta).collect()];
    let mut hess = DMatrix::<f64>::zeros(KRYLOV_MAXITER + 1, KRYLOV_MAXITER);
    let (mut cs, mut sn): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    let mut g = vec![0.0; KRYLOV_MAXITER + 1];
    g[0] = beta;
    let mut m = 0;
    while m < KRYLOV_MAXITER {
        let mut w = apply(&basis[m])?;
        for (j, q) in basis.iter().enumerate() {
            let c = dot(&w, q);
            hess[(j, m)] = c;
            w.iter_mut().zip(q).for_each(|(w, q)| *w -= c * q);
        }
        let size = norm(&w);
        hess[(m + 1, m)] = size;
        for j in 0..m {
            let (x, y) = (hess[(j, m)], hess[(j + 1, m)]);
            hess[(j, m)] = cs[j] * x + sn[j] * y;
            hess[(j + 1, m)] = -sn[j] * x + cs[j] * y;
        }
        let (x, y) = (hess[(m, m)], hess[(m + 1, m)]);
        let rho = x.hypot(y);
        let (c, s) = if rho == 0.0 { (1.0, 0.0) } else { (x / rho, y / rho) };
        cs.push(c);
        sn.push(s);
        hess[(m, m)] = rho;
        hess[(m + 1, m)] = 0.0;
        g[m + 1] = -s * g[m];
        g[m] *= c;
        m += 1;
        if g[m].abs() <= target || size <= f64::EPSILON * beta {
            break;
        }
        basis.push(w.iter().map(|x| x / size).collect());
    }
    let mut coef = DVector::from_fn(m, |j, _| g[j]);
    if !hess.view((0, 0), (m, m)).upper_triangle().solve_upper_triangular_mut(&mut coef) {
        return None;
    }
    Some((0..r.len()).map(|k| (0..m).map(|j| coef[j] * basis[j][k]).sum()).collect())
}

/// P⁻¹·u with P = I − h(A⊗J): through T, (γ/h − J)⁻¹(γ/h)·x₀ and
/// ((α − iβ)/h − J)⁻¹((α − iβ)/h)·(x₁ + i x₂), x = T⁻¹u, and back by T.
fn precondition((lu_real, lu_complex): &Factors, h: f64, u: &Stages) -> Stages {
    let n = u[0].len();
    let x = super::newton::transform(&TI, u);
    let mut real = DVector::from_fn(n, |i, _| GAMMA / h * x[0][i]);
    let mu = Complex::new(ALPHA / h, -BETA / h);
    let mut complex = DVector::from_fn(n, |i, _| mu * Complex::new(x[1][i], x[2][i]));
    lu_real.solve_mut(&mut real);
    lu_complex.solve_mut(&mut complex);
    let w = [real.as_slice().to_vec(), complex.iter().map(|c| c.re).collect(), complex.iter().map(|c| c.im).collect()];
    super::newton::transform(&T, &w)
}
