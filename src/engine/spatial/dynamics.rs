//! Direct dynamics in space: the index-1 Newton–Euler equations
//!
//! ```text
//! [ M    Φ_qᵀ ] [ a ]   [ Q − (0, ω × J·ω) ]
//! [ Φ_q   0   ] [ λ ] = [ γ                ]      M = diag(m·I, J) a body
//! ```
//!
//! integrated by the plane's runner (the same Runge–Kutta pairs, Radau IIA
//! for a stiff model, events and budget) over the state
//! y = (r, p, v, φ, W): every body's G, its quaternion (i, j, k, w), its
//! (ṙ, ω), the first input's coordinate φ (integrated, so that it runs on
//! past ±π) and W, the work of the applied actions (Ẇ = Q·v). The inputs
//! here are free: they set the start and report the motion. A redundant
//! row (Bricard's linkage) is left out once, at the start, where the rows
//! kept already span it. After every step the quaternions are made unit
//! and the state is projected back onto Φ = 0 and Φ_q·v = 0 (least-norm
//! Newton corrections), so the drift stays at the step's local error.
//! At each sample the accelerations are solved once more, every input's
//! coordinate, speed and acceleration read from its row (φ̈ = Φ_q,φ·a − γ_φ),
//! and, where asked, every joint's reaction from the kinetostatics of
//! that motion.

use super::constraints::{Rows, coordinate, evaluate};
use super::energy::energy;
use super::kinematics::{Motion, Scaled, assemble, motion};
use super::kinetostatics::{Actions, applied, inverse_dynamics};
use super::model::{Load, LoadLaw, Mechanism, Pose};
use super::range;
pub use super::setup::SpatialProblem;
use super::setup::{independent, settings};
use crate::engine::dynamics::{DynamicsError, DynamicsSolution, Failure, Model, Sample, Start, energy_residual, run};
use crate::engine::kinetostatics::Energy;
use nalgebra::{DMatrix, DVector, Quaternion, UnitQuaternion, Vector3, Vector4};
use std::borrow::Cow;

/// The mechanism at one sample.
#[derive(Clone, Debug)]
pub struct SpatialSample {
    pub pose: Pose,
    /// ṙ, ω of every body.
    pub v: DVector<f64>,
    /// r̈, α of every body.
    pub a: DVector<f64>,
    /// Every input's [coordinate, speed, acceleration]: the first's
    /// coordinate integrated (it runs on past ±π), the others' as the pose
    /// has them (an angle within ±π).
    pub inputs: Vec<[f64; 3]>,
    pub energy: Energy,
    /// The work of every applied action since the start (integrated).
    pub work: f64,
    /// Largest |Φ| of the joints, m (an angle's row times the drawing's size).
    pub constraint_residual: f64,
    /// The reactions, where asked (no efforts: the inputs are free).
    pub actions: Option<Actions>,
}

#[derive(Clone, Debug)]
pub struct SpatialSolution {
    /// The first input's motion, the events and the run's counts.
    pub solution: DynamicsSolution,
    /// The mechanism at each of `solution.samples`.
    pub details: Vec<SpatialSample>,
    /// Largest |Φ| (m) a projection removed.
    pub drift: f64,
    /// Rows left out as redundant at the start.
    pub redundant_rows: usize,
}

/// The equations the integrator sees.
struct Equations<'a> {
    p: &'a SpatialProblem,
    /// The mechanism without its inputs (they are free).
    joints: Mechanism,
    /// The joints and every input: their rows give the inputs' rates
    /// (built once, not at every evaluation).
    inputs: Mechanism,
    /// The joint rows kept: independent at the start.
    kept: Vec<usize>,
    n: usize,
    size: f64,
    /// The loads, where none varies.
    fixed: Option<Vec<Load>>,
    /// The inputs' [value, rate, second rate] given to `evaluate`: nothing
    /// (their rows are read, not prescribed).
    at_rest: Vec<[f64; 3]>,
}

impl Equations<'_> {
    /// The pose held in y (quaternions made unit).
    fn pose(&self, y: &[f64]) -> Pose {
        let n = self.n;
        let r = (0..n).map(|b| Vector3::from_column_slice(&y[3 * b..3 * b + 3])).collect();
        let p = (0..n)
            .map(|b| {
                UnitQuaternion::new_normalize(Quaternion::from(Vector4::from_column_slice(&y[3 * n + 4 * b..][..4])))
            })
            .collect();
        Pose { r, p }
    }

    fn velocities(&self, y: &[f64]) -> DVector<f64> {
        DVector::from_column_slice(&y[7 * self.n..13 * self.n])
    }

    /// The loads at (t, y), the first input turning at `omega`.
    fn loads(&self, t: f64, y: &[f64], omega: f64) -> Cow<'_, [Load]> {
        if let Some(fixed) = &self.fixed {
            return Cow::Borrowed(fixed);
        }
        let phi = y[13 * self.n].rem_euclid(self.p.period);
        Cow::Owned(self.p.loads.iter().map(|l| l.at(phi, [omega, t])).collect())
    }

    /// Every row at (pose, v) with γ: the joints' (all, the redundant
    /// too), then the inputs' — one evaluation for the equations of motion
    /// and the inputs' rates.
    fn all_rows(&self, pose: &Pose, v: &DVector<f64>) -> Rows {
        evaluate(&self.inputs, pose, Some(v), &self.at_rest)
    }

    /// Input k's rate from `all`'s rows: its gradient times v.
    fn rate_in(&self, all: &Rows, k: usize, v: &DVector<f64>) -> f64 {
        all.jac.row(self.joints.joint_rows() + k).iter().zip(v.iter()).map(|(a, b)| a * b).sum()
    }

    /// The kept rows of Φ at `pose` (with γ at `v`).
    fn rows(&self, pose: &Pose, v: Option<&DVector<f64>>) -> Rows {
        let all = evaluate(&self.joints, pose, v, &[]);
        let k = &self.kept;
        Rows {
            phi: DVector::from_fn(k.len(), |r, _| all.phi[k[r]]),
            jac: DMatrix::from_fn(k.len(), all.jac.ncols(), |r, c| all.jac[(k[r], c)]),
            rate: DVector::zeros(k.len()),
            gamma: DVector::from_fn(k.len(), |r, _| all.gamma[k[r]]),
            length: k.iter().map(|&r| all.length[r]).collect(),
        }
    }

    /// (a, Q·v): the accelerations and the applied actions' power; None
    /// where the equations are singular.
    fn accelerations(
        &self,
        (pose, v): (&Pose, &DVector<f64>),
        loads: &[Load],
        all: &Rows,
    ) -> Option<(DVector<f64>, f64)> {
        let (n, m) = (6 * self.n, self.kept.len());
        let q = applied(&self.joints, loads, pose, v);
        let mut rhs = DVector::zeros(n + m);
        let mut blocks = Vec::with_capacity(self.n);
        for (b, body) in self.joints.bodies.iter().enumerate() {
            let rot = pose.rotation(b + 1);
            let j = rot * body.inertia * rot.transpose();
            let omega = Vector3::from(v.fixed_rows::<3>(6 * b + 3));
            let gyro = omega.cross(&(j * omega));
            rhs.fixed_rows_mut::<3>(6 * b).copy_from(&q.fixed_rows::<3>(6 * b));
            rhs.fixed_rows_mut::<3>(6 * b + 3).copy_from(&(q.fixed_rows::<3>(6 * b + 3) - gyro));
            blocks.push((body.mass, j));
        }
        let jac = DMatrix::from_fn(m, n, |i, c| all.jac[(self.kept[i], c)]);
        for (i, &r) in self.kept.iter().enumerate() {
            rhs[n + i] = all.gamma[r];
        }
        let forces = rhs.rows(0, n).into_owned();
        let a = match range::accelerations(&blocks, &jac, &forces, &rhs.rows(n, m).into_owned()) {
            Some(a) => a,
            None => self.whole(&blocks, &jac, &rhs)?,
        };
        a.iter().all(|x| x.is_finite()).then(|| (a, q.dot(v)))
    }

    /// The accelerations from the whole system [M Φ_qᵀ; Φ_q 0] by LU (a
    /// body without mass, rows near dependence).
    fn whole(
        &self,
        blocks: &[(f64, nalgebra::Matrix3<f64>)],
        jac: &DMatrix<f64>,
        rhs: &DVector<f64>,
    ) -> Option<DVector<f64>> {
        let (n, m) = (jac.ncols(), jac.nrows());
        let mut k = DMatrix::zeros(n + m, n + m);
        for (b, (mass, j)) in blocks.iter().enumerate() {
            k.view_mut((6 * b, 6 * b), (3, 3)).fill_diagonal(*mass);
            k.view_mut((6 * b + 3, 6 * b + 3), (3, 3)).copy_from(j);
        }
        k.view_mut((n, 0), (m, n)).copy_from(jac);
        k.view_mut((0, n), (n, m)).copy_from(&jac.transpose());
        Some(k.lu().solve(rhs)?.rows(0, n).into_owned())
    }

    /// Every input's [coordinate, speed, acceleration] at y with (v, a),
    /// from `all`'s rows (φ̈ = Φ_q,φ·a − γ_φ).
    fn inputs_at(&self, (y, pose): (&[f64], &Pose), all: &Rows, v: &DVector<f64>, a: &DVector<f64>) -> Vec<[f64; 3]> {
        let first = self.joints.joint_rows();
        let read = |(k, input): (usize, &super::model::Input)| {
            let joint = &self.joints.joints[input.joint];
            let now = || self.p.reference[k] + coordinate(&self.joints, pose, joint, input.coordinate);
            let x = if k == 0 { y[13 * self.n] } else { now() };
            [x, self.rate_in(all, k, v), self.rate_in(all, k, a) - all.gamma[first + k]]
        };
        self.inputs.inputs.iter().enumerate().map(read).collect()
    }
}

impl Model for Equations<'_> {
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let n = self.n;
        let pose = self.pose(y);
        let v = self.velocities(y);
        let all = self.all_rows(&pose, &v);
        let speed = self.rate_in(&all, 0, &v);
        let loads = self.loads(t, y, speed);
        let Some((a, power)) = self.accelerations((&pose, &v), &loads, &all) else { return dy.fill(f64::NAN) };
        for b in 0..n {
            dy[3 * b..3 * b + 3].copy_from_slice(&y[7 * n + 6 * b..][..3]);
            let omega = Quaternion::from_imag(Vector3::from(v.fixed_rows::<3>(6 * b + 3)));
            let pd = omega * Quaternion::from(Vector4::from_column_slice(&y[3 * n + 4 * b..][..4])) * 0.5;
            dy[3 * n + 4 * b..][..4].copy_from_slice(pd.coords.as_slice());
        }
        dy[7 * n..13 * n].copy_from_slice(a.as_slice());
        dy[13 * n] = speed;
        dy[13 * n + 1] = power;
    }

    fn angle(&self, y: &[f64]) -> f64 {
        y[13 * self.n]
    }

    fn speed(&self, y: &[f64]) -> f64 {
        let v = self.velocities(y);
        self.rate_in(&self.all_rows(&self.pose(y), &v), 0, &v)
    }

    /// Unit quaternions, then Φ = 0 and Φ_q·v = 0 by least-norm corrections.
    fn project(&self, y: &mut [f64]) -> f64 {
        let n = self.n;
        let mut pose = self.pose(y);
        let mut removed = 0.0f64;
        for _ in 0..3 {
            let rows = self.rows(&pose, None);
            let gap = self.gap(&rows);
            removed = removed.max(gap);
            if gap < 1e-14 * self.size {
                break;
            }
            pose.apply(Scaled::new(&rows, rows.phi.len(), self.size).solve(&-&rows.phi).0.as_slice());
        }
        let rows = self.rows(&pose, None);
        let v = self.velocities(y);
        let (dv, _) = Scaled::new(&rows, rows.phi.len(), self.size).solve(&(&rows.jac * &v));
        let v = v - dv;
        for b in 0..n {
            y[3 * b..3 * b + 3].copy_from_slice(pose.r[b].as_slice());
            y[3 * n + 4 * b..][..4].copy_from_slice(pose.p[b].coords.as_slice());
        }
        y[7 * n..13 * n].copy_from_slice(v.as_slice());
        let input = &self.p.mechanism.inputs[0];
        let now =
            self.p.reference[0] + coordinate(&self.joints, &pose, &self.joints.joints[input.joint], input.coordinate);
        let phi = &mut y[13 * n];
        *phi += (now - *phi + std::f64::consts::PI).rem_euclid(2.0 * std::f64::consts::PI) - std::f64::consts::PI;
        removed
    }
}

impl Equations<'_> {
    /// |Φ| as a length: a cosine's row times the drawing's size.
    fn gap(&self, rows: &Rows) -> f64 {
        let scale = |k: usize| if rows.length[k] { 1.0 } else { self.size };
        (0..rows.phi.len()).map(|k| rows.phi[k].abs() * scale(k)).fold(0.0, f64::max)
    }

    /// The mechanism at a sample (t, y): its motion, energies and reactions.
    fn detail(&self, t: f64, y: &[f64]) -> Result<SpatialSample, DynamicsError> {
        let (pose, v) = (self.pose(y), self.velocities(y));
        let all = self.all_rows(&pose, &v);
        let loads = self.loads(t, y, self.rate_in(&all, 0, &v));
        let singular = DynamicsError::Integration { t, reason: Failure::SingularMotion };
        let (a, _) = self.accelerations((&pose, &v), &loads, &all).ok_or(singular)?;
        let rows = evaluate(&self.joints, &pose, Some(&v), &[]);
        let constraint_residual = self.gap(&rows);
        let actions = self.p.reactions.then(|| {
            let now = Motion { pose: pose.clone(), v: v.clone(), a: a.clone(), rows, condition: 0.0 };
            inverse_dynamics(&self.joints, &loads, &now)
        });
        Ok(SpatialSample {
            inputs: self.inputs_at((y, &pose), &all, &v, &a),
            energy: energy(&self.joints, &loads, &pose, &v),
            work: y[13 * self.n + 1],
            constraint_residual,
            actions,
            pose,
            v,
            a,
        })
    }
}

/// Integrates the mechanism from its inputs' initial coordinates and speeds.
pub fn solve(p: &SpatialProblem) -> Result<SpatialSolution, DynamicsError> {
    let m = &p.mechanism;
    let initial = |reason: Start| DynamicsError::Initial { reason };
    let inputs: Vec<[f64; 3]> = p.initial.iter().zip(&p.reference).map(|([a, w], r)| [a - r, *w, 0.0]).collect();
    let (pose, _) = assemble(m, &inputs, &Pose::drawn(m), 0).map_err(|e| initial(Start::Engine(e)))?;
    let start = motion(m, pose, &inputs, 0).map_err(|_| initial(Start::SingularInputs))?;
    let joints = Mechanism { inputs: Vec::new(), ..m.clone() };
    let size = m.size();
    let all = evaluate(&joints, &start.pose, None, &[]);
    let kept = independent(&all, size);
    let dof = 6 * m.n() - kept.len();
    // The first input reports the motion: a mechanism with none does not move.
    let given = p.initial.len() == m.inputs.len() && p.reference.len() == m.inputs.len();
    if dof != m.inputs.len() || m.inputs.is_empty() || !given {
        return Err(initial(Start::Dof { dof, inputs: m.inputs.len() }));
    }
    let n = m.n();
    let fixed = p.loads.iter().map(LoadLaw::fixed).collect();
    let at_rest = vec![[0.0; 3]; m.inputs.len()];
    let dae = Equations { p, joints, inputs: m.clone(), kept: kept.clone(), n, size, fixed, at_rest };
    let mut y0 = Vec::with_capacity(13 * n + 2);
    (0..n).for_each(|b| y0.extend(start.pose.r[b].iter()));
    (0..n).for_each(|b| y0.extend(start.pose.p[b].coords.iter()));
    y0.extend(start.v.iter());
    y0.extend([p.initial[0][0], 0.0]);
    let moving = dae.all_rows(&start.pose, &start.v);
    let loads = dae.loads(0.0, &y0, dae.rate_in(&moving, 0, &start.v));
    if dae.accelerations((&start.pose, &start.v), &loads, &moving).is_none() {
        return Err(initial(Start::MovesNoMass));
    }
    let settings = settings(p, &start.v, size);
    let run = run(&dae, y0, &settings)?;
    let details = run.states.iter().map(|(t, y)| dae.detail(*t, y)).collect::<Result<Vec<_>, _>>()?;
    let t0 = details.first().map_or(0.0, |d| d.energy.kinetic);
    let mut peak = 0.0f64;
    let samples = (run.states.iter().zip(&details))
        .map(|((t, _), d)| {
            peak = peak.max(d.energy.kinetic);
            let [angle, speed, acceleration] = d.inputs[0];
            Sample {
                t: *t,
                angle,
                speed,
                acceleration,
                energy_residual: energy_residual(d.work, t0, d.energy.kinetic, peak),
            }
        })
        .collect();
    // The first input's error: its own integrated coordinate's, or the
    // orientation's (2× a quaternion component's), whichever is larger.
    let orientation = (3 * n..7 * n).map(|k| 2.0 * run.local_errors[k]).fold(0.0, f64::max);
    let last = details.last();
    let solution = DynamicsSolution {
        samples,
        events: run.events,
        energy_times: Vec::new(),
        work_by_quadrature: false,
        energy_residual: last.map_or(0.0, |d| energy_residual(d.work, t0, d.energy.kinetic, peak)),
        steps: run.attempted,
        evaluations: run.evaluations,
        integrator: run.integrator,
        stiff_at: run.stiff_at,
        repeated: run.repeated,
        estimated_error: orientation.max(run.local_errors[13 * n]),
        stopped: run.stopped,
        unlisted_turns: run.unlisted_turns,
    };
    Ok(SpatialSolution { solution, details, drift: run.drift, redundant_rows: all.phi.len() - kept.len() })
}
