//! The dense form's common case, over storage kept from one evaluation to
//! the next: every joint row clearly independent, no rolling contact with
//! friction. A mechanism outside the sparse form for its masses (a point
//! mass, whose I_G = 0 leaves M singular; a contact, whose curve
//! parameters carry none) spends its run here; one with redundant joints,
//! whose rows are dependent everywhere, is left to the general form.
//!
//! The same equations as the general dense form (`equations.rs`), solved
//! for S⁻¹q̈:
//!
//! ```text
//! [ S M S    (Φ_q S)ᵀ ] [ S⁻¹q̈ ]   [ S Q ]
//! [ Φ_q S      0      ] [  λ   ] = [  γ  ]
//! ```
//!
//! S = diag(s_j) the columns' scale, M = diag(m_j). What the general form
//! decides by a QR (and an SVD) of R·Φ_q·S — whether a combination of rows
//! is within τ of dependence — is settled here, where it is plainly not,
//! by the Gram matrix G = (RΦ_qS)(RΦ_qS)ᵀ (r × r, R the rows' scale): with
//! λ_max ≤ B, B the largest row sum of |G| (Gershgorin), and λ_min ≥
//! det G / λ_max^(r−1), every σ² = λ(G) ≥ (10τ)²·σ²_max once det G ≥
//! (10τ)²·B^r (det G from G's Cholesky factor; ten times the margin the
//! general form keeps). Where the test fails — near a
//! singular position, or a long row vector that the bound overstates —
//! the general form decides, so the test chooses only how fast, never
//! what is solved. Measured on IFToMM A01 (a point mass on a massless link)
//! in docs/BENCHMARKS.md.

use super::MechanismProblem;
use crate::engine::constraints::{State, System, evaluate_into};
use crate::engine::dynamics::rows::TAU;
use crate::engine::kinetostatics::applied_forces_into;
use crate::engine::numeric::lu::Lu;
use nalgebra::DMatrix;

/// Room for one mechanism's evaluations.
#[derive(Debug, Default)]
pub(super) struct Plain {
    sys: System,
    a: DMatrix<f64>,
    lu: Lu,
    x: Vec<f64>,
    forces: Vec<f64>,
    size: Vec<f64>,
    gram: Vec<f64>,
    /// Φ_q·S, the joint rows (r × n, row-major).
    w: Vec<f64>,
    dq: Vec<f64>,
    zeros: Vec<[f64; 3]>,
}

/// A sample's view of an evaluation ([`Plain::reported`]).
pub(super) struct Reported {
    pub lambda: Vec<f64>,
    pub forces: Vec<f64>,
    pub inputs: Vec<[f64; 3]>,
    pub residual: f64,
}

/// The coordinates n, joint rows r, M's diagonal and the columns' scale S.
pub(super) struct Sizes<'a> {
    pub n: usize,
    pub r: usize,
    pub mass: &'a [f64],
    pub scale: &'a [f64],
}

impl Plain {
    /// q̈ into `qdd`, and the applied forces' power Qᵀq̇; None where the
    /// rows are not plainly independent or the solve fails (the general
    /// dense form then decides).
    pub fn accelerations(
        &mut self,
        p: &MechanismProblem,
        z: &Sizes,
        t: f64,
        y: [&[f64]; 2],
        qdd: &mut [f64],
    ) -> Option<f64> {
        let [q, qd] = y;
        let m = &p.mechanism;
        self.zeros.resize(m.drivers.len(), [0.0; 3]);
        evaluate_into(m, &State { q, qd: Some(qd), inputs: &self.zeros }, &mut self.sys);
        if !self.independent(z) {
            return None;
        }
        let (n, r) = (z.n, z.r);
        let jac = &self.sys.jacobian;
        let rows = jac.nrows();
        let at = |i: usize, j: usize| jac.as_slice()[j * rows + i];
        // The input's φ and ω: the first driver's row.
        let phi = self.sys.phi[r].rem_euclid(p.period);
        let omega: f64 = (0..n).map(|j| at(r, j) * qd[j]).sum();
        applied_forces_into(m, &p.loads, (q, self.sys.trig()), qd, phi, [omega, t], &mut self.forces);
        self.fill(z);
        if !self.lu.factor(&self.a) {
            return None;
        }
        self.x.clear();
        self.x.extend(self.forces.iter().zip(z.scale).map(|(f, s)| f * s));
        self.x.extend_from_slice(&self.sys.gamma.as_slice()[..r]);
        if !self.lu.solve(&mut self.x) {
            return None;
        }
        qdd.iter_mut().zip(self.x.iter().zip(z.scale)).for_each(|(a, (x, s))| *a = x * s);
        Some(self.forces.iter().zip(qd).map(|(f, v)| f * v).sum())
    }

    /// What a sample reports of the last [`Self::accelerations`] (q̇ and
    /// its q̈ given): the joints' λ, the applied forces Q, each input's
    /// coordinate, speed and acceleration, and the largest |Φ| of the joints.
    pub fn reported(&self, z: &Sizes, qd: &[f64], qdd: &[f64]) -> Reported {
        let (n, r) = (z.n, z.r);
        let (jac, phi, gamma) = (&self.sys.jacobian, &self.sys.phi, &self.sys.gamma);
        let dot = |k: usize, v: &[f64]| (0..n).map(|j| jac[(k, j)] * v[j]).sum::<f64>();
        Reported {
            lambda: self.x[n..n + r].to_vec(),
            forces: self.forces.clone(),
            inputs: (r..phi.len()).map(|k| [phi[k], dot(k, qd), dot(k, qdd) - gamma[k]]).collect(),
            residual: phi.as_slice()[..r].iter().fold(0.0f64, |a, v| a.max(v.abs())),
        }
    }

    /// [S M S, (Φ_q S)ᵀ; Φ_q S, 0] into `a`.
    fn fill(&mut self, z: &Sizes) {
        let (n, r) = (z.n, z.r);
        let k = n + r;
        if self.a.shape() != (k, k) {
            self.a = DMatrix::zeros(k, k);
        }
        let jac = &self.sys.jacobian;
        let rows = jac.nrows();
        let a = self.a.as_mut_slice();
        a.fill(0.0);
        for j in 0..n {
            a[j * k + j] = z.mass[j] * z.scale[j] * z.scale[j];
            for i in 0..r {
                let v = jac.as_slice()[j * rows + i] * z.scale[j];
                a[j * k + n + i] = v;
                a[(n + i) * k + j] = v;
            }
        }
    }

    /// Whether the joint rows of R·Φ_q·S are plainly independent: det G ≥
    /// (10τ)²·B^r (module docs; ten times the margin the general form
    /// keeps). Leaves Φ_q·S in `w` (r × n, row-major) and R in `size`.
    fn independent(&mut self, z: &Sizes) -> bool {
        let (n, r) = (z.n, z.r);
        let (jac, rows) = (self.sys.jacobian.as_slice(), self.sys.jacobian.nrows());
        self.w.clear();
        for i in 0..r {
            self.w.extend(z.scale.iter().enumerate().map(|(j, s)| jac[j * rows + i] * s));
        }
        self.size.clear();
        self.size.extend(self.w.chunks_exact(n.max(1)).map(|row| {
            let top = row.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            if top > 0.0 && top.is_finite() { 1.0 / top } else { f64::NAN }
        }));
        gram(&self.w, n, Some(&self.size), &mut self.gram);
        let bound =
            self.gram.chunks_exact(r.max(1)).map(|g| g.iter().map(|v| v.abs()).sum::<f64>()).fold(0.0, f64::max);
        let Some(det) = cholesky(&mut self.gram, r) else { return false };
        // Where B^r would overflow, the general form decides.
        let floor = (10.0 * TAU).powi(2) * bound.powi(r as i32);
        r == 0 || (floor.is_finite() && det >= floor)
    }

    /// Moves y = (q, q̇, …) onto Φ = 0 and Φ_q·q̇ = 0 as the general dense
    /// form does where every row is kept (Newton by the least corrections
    /// in the metric S⁻², each row of Φ within `tol` in its own size, then
    /// q̇): Ok(the largest |Φ| removed), or Err(that so far) where the rows
    /// are not plainly independent (y then as far as it got).
    pub fn project(&mut self, p: &MechanismProblem, z: &Sizes, tol: f64, y: &mut [f64]) -> Result<f64, f64> {
        let (n, r) = (z.n, z.r);
        let m = &p.mechanism;
        self.zeros.resize(m.drivers.len(), [0.0; 3]);
        let mut removed = 0.0f64;
        for _ in 0..8 {
            evaluate_into(m, &State { q: &y[..n], qd: None, inputs: &self.zeros }, &mut self.sys);
            removed = self.sys.phi.as_slice()[..r].iter().fold(removed, |a, v| a.max(v.abs()));
            if !self.independent(z) {
                return Err(removed);
            }
            let phi = &self.sys.phi.as_slice()[..r];
            let within = phi.iter().zip(&self.size).all(|(v, s)| (v * s).abs() <= tol);
            let (target, qd) = y.split_at_mut(n);
            self.x.clear();
            if within {
                self.x.extend(
                    self.w
                        .chunks_exact(n.max(1))
                        .map(|row| -row.iter().zip(&qd[..n]).zip(z.scale).map(|((w, v), s)| w * v / s).sum::<f64>()),
                );
            } else {
                self.x.extend(phi.iter().map(|v| -v));
            }
            let Some(()) = self.least(z) else { return Ok(removed) };
            let out = if within { &mut qd[..n] } else { target };
            out.iter_mut().zip(&self.dq).for_each(|(a, d)| *a += d);
            if within {
                break;
            }
        }
        Ok(removed)
    }

    /// The x of least |S⁻¹x| with Φ_q x = b (b in `x`) into `dq`:
    /// x = S·(Φ_qS)ᵀ·((Φ_qS)(Φ_qS)ᵀ)⁻¹·b, from `w` = Φ_q·S.
    fn least(&mut self, z: &Sizes) -> Option<()> {
        let (n, r) = (z.n, z.r);
        gram(&self.w, n, None, &mut self.gram);
        cholesky(&mut self.gram, r)?;
        let l = &self.gram;
        for i in 0..r {
            self.x[i] = (self.x[i] - (0..i).map(|k| l[i * r + k] * self.x[k]).sum::<f64>()) / l[i * r + i];
        }
        for i in (0..r).rev() {
            self.x[i] = (self.x[i] - (i + 1..r).map(|k| l[k * r + i] * self.x[k]).sum::<f64>()) / l[i * r + i];
        }
        self.dq.clear();
        self.dq.extend((0..n).map(|j| z.scale[j] * (0..r).map(|i| self.w[i * n + j] * self.x[i]).sum::<f64>()));
        self.dq.iter().all(|v| v.is_finite()).then_some(())
    }
}

/// G = (R W)(R W)ᵀ of W (r × n, row-major) into `g` (r × r, row-major);
/// R = diag(`rows`), or the identity.
fn gram(w: &[f64], n: usize, rows: Option<&[f64]>, g: &mut Vec<f64>) {
    let r = w.len().checked_div(n).unwrap_or(0);
    g.clear();
    g.resize(r * r, 0.0);
    let size = |i: usize| rows.map_or(1.0, |s| s[i]);
    for i in 0..r {
        for k in 0..=i {
            let v: f64 = w[i * n..(i + 1) * n].iter().zip(&w[k * n..(k + 1) * n]).map(|(a, b)| a * b).sum();
            g[i * r + k] = v * size(i) * size(k);
            g[k * r + i] = g[i * r + k];
        }
    }
}

/// det G of a symmetric positive definite G (r × r, row-major, overwritten
/// by its Cholesky factor L, G = L Lᵀ, on and below the diagonal); None where a pivot is not positive or not finite.
fn cholesky(g: &mut [f64], r: usize) -> Option<f64> {
    let mut det = 1.0;
    for j in 0..r {
        let mut d = g[j * r + j];
        for k in 0..j {
            d -= g[j * r + k] * g[j * r + k];
        }
        if !(d > 0.0 && d.is_finite()) {
            return None;
        }
        det *= d;
        let l = d.sqrt();
        g[j * r + j] = l;
        for i in j + 1..r {
            let mut v = g[i * r + j];
            for k in 0..j {
                v -= g[i * r + k] * g[j * r + k];
            }
            g[i * r + j] = v / l;
        }
    }
    Some(det)
}

#[cfg(test)]
mod tests {
    use super::{Plain, Sizes, cholesky};
    use crate::engine::Deadline;
    use crate::engine::constraints::{State, evaluate};
    use crate::engine::dynamics::mechanism::MechanismProblem;
    use crate::engine::dynamics::{End, KEPT_BYTES};
    use crate::engine::kinematics::{Conditions, sweep};
    use crate::engine::samples::parallelogram_chain;
    use std::f64::consts::FRAC_PI_2;

    /// det of a 3 × 3 SPD matrix against its cofactor expansion; a singular
    /// one refused.
    #[test]
    fn the_determinant_is_the_cofactor_expansion_s() {
        let g = [4.0, 2.0, 0.6, 2.0, 5.0, 1.0, 0.6, 1.0, 3.0];
        let cofactors = 4.0 * (5.0 * 3.0 - 1.0) - 2.0 * (2.0 * 3.0 - 0.6) + 0.6 * (2.0 * 1.0 - 5.0 * 0.6);
        let det = cholesky(&mut g.clone(), 3).expect("positive definite");
        assert!((det - cofactors).abs() <= 1e-12 * cofactors, "{det} vs {cofactors}");
        assert!(cholesky(&mut [1.0, 2.0, 2.0, 4.0], 2).is_none(), "rank 1");
    }

    /// A02's chain with N = 1 (two cranks and a coupler, 1 m and 1 kg bars).
    fn chain() -> (MechanismProblem, Vec<f64>, Vec<f64>) {
        let mechanism = parallelogram_chain(1);
        let p = MechanismProblem {
            mechanism,
            loads: Vec::new(),
            period: std::f64::consts::TAU,
            initial: vec![[FRAC_PI_2, 1.0]],
            end: End::Duration(1.0),
            tolerance: 1e-9,
            integrator: None,
            conserve_energy: None,
            samples: 2,
            kept_bytes: KEPT_BYTES,
            deadline: Deadline::none(),
            reactions: false,
            motion: false,
        };
        let (mass, scale) = ((0..9).map(|k| p.mechanism.mass_of(k)).collect(), vec![1.0; 9]);
        (p, mass, scale)
    }

    /// At θ = 1 rad turning at 2 rad/s, the cranks' θ̈ is the energy's
    /// closed form (I* constant: I*θ̈ = −dV/dθ, I* = 2/3 + 1 kg·m², V =
    /// (1 + 1)·g·sin θ, the cranks' and the coupler's weights; large.rs in
    /// the benchmarks derives it), to 1e-12 of it.
    #[test]
    fn the_cranks_accelerate_as_the_energy_says() {
        let (p, mass, scale) = chain();
        let z = Sizes { n: 9, r: 8, mass: &mass, scale: &scale };
        let c =
            sweep(&p.mechanism, &[vec![[1.0, 2.0, 0.0]]], &Deadline::none(), Conditions::Estimated).unwrap().remove(0);
        let (mut plain, mut qdd) = (Plain::default(), vec![0.0; 9]);
        let power = plain.accelerations(&p, &z, 0.0, [&c.q, &c.qd], &mut qdd).expect("not singular");
        let want = -2.0 * 9.81 * 1.0f64.cos() / (2.0 / 3.0 + 1.0);
        for crank in [2, 5] {
            assert!((qdd[crank] - want).abs() <= 1e-12 * want.abs(), "θ̈ {} vs {want}", qdd[crank]);
        }
        // The weights' power −dV/dθ·θ̇.
        let weights = -2.0 * 9.81 * 1.0f64.cos() * 2.0;
        assert!((power - weights).abs() <= 1e-12 * weights.abs(), "{power} vs {weights}");
        // A sample's view: the input's speed and acceleration, and λ with M q̈ + Φ_qᵀλ = Q (to 1e-12 N).
        let seen = plain.reported(&z, &c.qd, &qdd);
        assert!((seen.inputs[0][1] - 2.0).abs() <= 1e-12 && (seen.inputs[0][2] - want).abs() <= 1e-12 * want.abs());
        let jac =
            evaluate(&p.mechanism, &State { q: &c.q, qd: None, inputs: &[[0.0; 3]] }).jacobian.rows(0, 8).into_owned();
        let held = jac.transpose() * nalgebra::DVector::from_column_slice(&seen.lambda);
        for k in 0..9 {
            let left = mass[k] * qdd[k] + held[k] - seen.forces[k];
            assert!(left.abs() <= 1e-12, "coordinate {k}: {left}");
        }
    }

    /// Lying flat, the chain's rows lose rank (a singular position): the
    /// general form must decide there, and the plain one declines. Placed
    /// by hand (the cranks turned −π/2 about their pins, the coupler moved
    /// with their tips), checked by Φ = 0.
    #[test]
    fn a_flat_parallelogram_is_left_to_the_general_form() {
        let (p, mass, scale) = chain();
        let z = Sizes { n: 9, r: 8, mass: &mass, scale: &scale };
        let q = [0.5, 0.0, -FRAC_PI_2, 1.5, 0.0, -FRAC_PI_2, 1.5, 0.0, 0.0];
        let qd = [0.0, 0.5, 1.0, 0.0, 0.5, 1.0, 0.0, 1.0, 0.0];
        let phi = evaluate(&p.mechanism, &State { q: &q, qd: None, inputs: &[[0.0; 3]] }).phi;
        assert!(phi.rows(0, 8).amax() <= 1e-15, "placed: {phi}");
        let mut plain = Plain::default();
        assert!(plain.accelerations(&p, &z, 0.0, [&q, &qd], &mut [0.0; 9]).is_none());
        let mut y: Vec<f64> = q.iter().chain(&qd).copied().collect();
        assert!(plain.project(&p, &z, 1e-12, &mut y).is_err());
    }

    /// A state moved off the constraints comes back onto Φ = 0 and
    /// Φ_q·q̇ = 0 (to 1e-12 m and m/s); a state on them stays as it was.
    #[test]
    fn the_projection_lands_on_the_constraints() {
        let (p, mass, scale) = chain();
        let z = Sizes { n: 9, r: 8, mass: &mass, scale: &scale };
        let c =
            sweep(&p.mechanism, &[vec![[1.0, 2.0, 0.0]]], &Deadline::none(), Conditions::Estimated).unwrap().remove(0);
        let on: Vec<f64> = c.q.iter().chain(&c.qd).copied().collect();
        let mut y = on.clone();
        Plain::default().project(&p, &z, 1e-12, &mut y).expect("not singular");
        assert!(y.iter().zip(&on).all(|(a, b)| (a - b).abs() <= 1e-12), "{y:?} vs {on:?}");
        y.iter_mut().enumerate().for_each(|(k, v)| *v += 1e-3 * (k as f64).sin());
        let removed = Plain::default().project(&p, &z, 1e-12, &mut y).expect("not singular");
        assert!(removed > 1e-4, "the offset was seen: {removed}");
        let sys = evaluate(&p.mechanism, &State { q: &y[..9], qd: None, inputs: &[[0.0; 3]] });
        let speeds = sys.jacobian.rows(0, 8) * nalgebra::DVector::from_column_slice(&y[9..]);
        assert!(sys.phi.rows(0, 8).amax() <= 1e-12 && speeds.amax() <= 1e-12, "Φ {} Φ_q·q̇ {}", sys.phi, speeds);
    }
}
