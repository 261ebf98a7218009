//! Gear trains, ordinary and epicyclic: speeds by Willis' formula, torques
//! by virtual power (steady motion, no friction, no inertia).
//!
//! Members are rigid bodies turning about their axes; member 0 is the frame
//! (ω₀ = 0). A mesh of wheel a (z_a teeth, on member a) with wheel b (z_b,
//! on member b), whose axes are held by carrier c (the frame for an
//! ordinary mesh), gives relative to the carrier
//!
//! ```text
//! (ω_b − ω_c)/(ω_a − ω_c) = ∓ z_a/z_b      (− external, + internal)
//! i.e.  z_b(ω_b − ω_c) ± z_a(ω_a − ω_c) = 0,
//! ```
//!
//! one row of the mesh matrix A (A ω = 0). The train has n − rank A degrees
//! of freedom; the given speeds fix the rest. Every ω* in the null space of
//! A is a virtual motion, and Σ T_i ω*_i = 0 for each gives the unknown
//! external torques T.

use super::numeric::svd::svd;
use nalgebra::{DMatrix, DVector};

/// One mesh between two wheels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mesh {
    /// Members carrying the wheels (0 = frame) and their teeth.
    pub a: usize,
    pub teeth_a: f64,
    pub b: usize,
    pub teeth_b: f64,
    /// The member holding both axes.
    pub carrier: usize,
    /// Wheel b is internal (a ring).
    pub internal: bool,
}

/// A train of `members` members (the frame included as member 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Train {
    pub members: usize,
    pub meshes: Vec<Mesh>,
}

/// What the train gives back.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainSolution {
    pub dof: usize,
    /// ω of every member (index 0 the frame), rad/s.
    pub speeds: Vec<f64>,
    /// External torque on every member (0 where none acts; the frame's is
    /// not computed and left 0).
    pub torques: Vec<f64>,
    /// Σ T_i ω_i / max |T_i ω_i| over the actual motion (0 in exact arithmetic).
    pub power_residual: f64,
}

/// Why the train cannot be solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TrainError {
    #[error("the train has {dof} degree(s) of freedom: give exactly {dof} speed(s) that fix it (given {given})")]
    Speeds { dof: usize, given: usize },
    #[error("the given speeds cannot all hold: the meshes contradict them (residual {residual:.3e} rad/s)")]
    Inconsistent { residual: f64 },
    #[error("the train has {dof} degree(s) of freedom: ask for exactly {dof} unknown torque(s) (asked {asked})")]
    Torques { dof: usize, asked: usize },
    #[error("the unknown torques cannot be found: those members do not take independent power")]
    TorquesSingular,
    #[error("the train's numbers overflow (teeth, ratios or speeds too large to compute with)")]
    Degenerate,
    /// No member can turn: the meshes lock the train (an odd loop of
    /// external meshes, three wheels meshing in a ring, say).
    #[error("the train cannot move: its meshes lock every member (an odd loop of external meshes, say)")]
    Locked,
}

impl Train {
    /// The mesh matrix over the moving members 1..n.
    fn matrix(&self) -> DMatrix<f64> {
        let n = self.members - 1;
        let mut a = DMatrix::zeros(self.meshes.len(), n);
        for (r, m) in self.meshes.iter().enumerate() {
            let s = if m.internal { -1.0 } else { 1.0 };
            let mut add = |member: usize, v: f64| {
                if member > 0 {
                    a[(r, member - 1)] += v;
                }
            };
            add(m.b, m.teeth_b);
            add(m.a, s * m.teeth_a);
            add(m.carrier, -(m.teeth_b + s * m.teeth_a));
        }
        a
    }

    /// Speeds from the given (member, ω) and the unknown torques on
    /// `unknown` from the given (member, T).
    pub fn solve(
        &self,
        given_speeds: &[(usize, f64)],
        given_torques: &[(usize, f64)],
        unknown: &[usize],
    ) -> Result<TrainSolution, TrainError> {
        let a = self.matrix();
        let n = a.ncols();
        let svd = svd(a.clone(), false, true).ok_or(TrainError::Degenerate)?;
        let scale = svd.singular_values.max().max(1.0);
        let rank = svd.singular_values.iter().filter(|s| **s > 1e-10 * scale).count();
        let dof = n - rank;
        if dof == 0 {
            return Err(TrainError::Locked);
        }
        let speeds = self.speeds(&a, dof, given_speeds)?;
        let mut torques = vec![0.0; self.members];
        for (m, t) in given_torques {
            torques[*m] += t;
        }
        if !unknown.is_empty() {
            self.torques(&null_space(&a, rank).ok_or(TrainError::Degenerate)?, unknown, &mut torques)?;
        }
        let powers: Vec<f64> = torques.iter().zip(&speeds).map(|(t, w)| t * w).collect();
        let largest = powers.iter().fold(0.0f64, |m, p| m.max(p.abs()));
        let power_residual = if largest > 0.0 { powers.iter().sum::<f64>() / largest } else { 0.0 };
        Ok(TrainSolution { dof, speeds, torques, power_residual })
    }

    fn speeds(&self, a: &DMatrix<f64>, dof: usize, given: &[(usize, f64)]) -> Result<Vec<f64>, TrainError> {
        let n = a.ncols();
        let moving: Vec<_> = given.iter().filter(|(m, _)| *m > 0).collect();
        let mut m = DMatrix::zeros(a.nrows() + moving.len(), n);
        m.rows_mut(0, a.nrows()).copy_from(a);
        let mut rhs = DVector::zeros(m.nrows());
        for (k, (member, w)) in moving.iter().enumerate() {
            m[(a.nrows() + k, member - 1)] = 1.0;
            rhs[a.nrows() + k] = *w;
        }
        let fail = TrainError::Speeds { dof, given: given.len() };
        let svd = svd(m.clone(), true, true).ok_or(TrainError::Degenerate)?;
        let scale = svd.singular_values.max().max(1.0);
        if svd.singular_values.iter().filter(|s| **s > 1e-10 * scale).count() < n {
            return Err(fail);
        }
        let w = svd.solve(&rhs, 1e-10 * scale).map_err(|_| fail)?;
        let speed_scale = rhs.amax().max(1e-300);
        let residual = (&m * &w - &rhs).amax();
        if residual > 1e-9 * speed_scale || given.iter().any(|(member, w)| *member == 0 && *w != 0.0) {
            return Err(TrainError::Inconsistent { residual });
        }
        Ok(std::iter::once(0.0).chain(w.iter().copied()).collect())
    }

    /// Σ_i N_ik T_i = 0 for every virtual motion k, solved for T on `unknown`.
    fn torques(&self, null: &DMatrix<f64>, unknown: &[usize], torques: &mut [f64]) -> Result<(), TrainError> {
        let dof = null.ncols();
        if unknown.len() != dof {
            return Err(TrainError::Torques { dof, asked: unknown.len() });
        }
        let row = |member: usize, k: usize| if member == 0 { 0.0 } else { null[(member - 1, k)] };
        let m = DMatrix::from_fn(dof, dof, |k, j| row(unknown[j], k));
        let known = DVector::from_fn(dof, |k, _| -(1..self.members).map(|i| row(i, k) * torques[i]).sum::<f64>());
        let t = m.lu().solve(&known).filter(|t| t.iter().all(|v| v.is_finite())).ok_or(TrainError::TorquesSingular)?;
        for (j, member) in unknown.iter().enumerate() {
            torques[*member] += t[j];
        }
        Ok(())
    }
}

/// An orthonormal basis of the null space of A (n × (n − rank)): the rows
/// of Vᵀ past the rank (nalgebra sorts the singular values, largest first);
/// A is padded with zero rows so that the SVD gives all n of them.
fn null_space(a: &DMatrix<f64>, rank: usize) -> Option<DMatrix<f64>> {
    let n = a.ncols();
    let mut square = DMatrix::zeros(n.max(a.nrows()), n);
    square.rows_mut(0, a.nrows()).copy_from(a);
    let v_t = svd(square, false, true)?.v_t?;
    Some(DMatrix::from_fn(n, n - rank, |i, k| v_t[(rank + k, i)]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A simple planetary train with the ring fixed: sun s, planet p, ring r
    /// (the frame), carrier c. Closed form: ω_c/ω_s = z_s/(z_s + z_r).
    #[test]
    fn a_fixed_ring_gives_the_textbook_ratio() {
        let (zs, zp, zr) = (20.0, 30.0, 80.0);
        let train = Train {
            members: 4, // frame = ring, sun 1, planet 2, carrier 3
            meshes: vec![
                Mesh { a: 1, teeth_a: zs, b: 2, teeth_b: zp, carrier: 3, internal: false },
                Mesh { a: 2, teeth_a: zp, b: 0, teeth_b: zr, carrier: 3, internal: true },
            ],
        };
        let s = train.solve(&[(1, 100.0)], &[(1, 10.0)], &[3]).unwrap();
        assert_eq!(s.dof, 1);
        assert!((s.speeds[3] - 100.0 * zs / (zs + zr)).abs() < 1e-12, "{:?}", s.speeds);
        // Power through: T_c = −T_s·ω_s/ω_c = −10·(zs + zr)/zs.
        assert!((s.torques[3] + 10.0 * (zs + zr) / zs).abs() < 1e-10, "{:?}", s.torques);
        assert!(s.power_residual.abs() < 1e-12);
    }
}
