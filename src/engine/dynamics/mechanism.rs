//! Direct dynamics of a planar mechanism of any DOF in dependent (body)
//! coordinates q, as the index-1 form of the equations of motion:
//!
//! ```text
//! [ M  Φ_qᵀ ] [ q̈ ]   [ Q(q, q̇, t) ]
//! [ Φ_q  0  ] [ λ ] = [ γ(q, q̇)    ]
//! ```
//!
//! with state y = (q, q̇, W), W the work of the applied loads (Ẇ = Qᵀq̇),
//! solved at each evaluation in the sparse range-space form or by the
//! dense LU ([`super::equations`]). Φ here holds the joints only: the
//! inputs named by the problem's drivers are free, and serve to report the
//! motion (coordinate φ, speed ω) and to set the initial state. After every accepted step the state is projected
//! back onto Φ = 0 and Φ_q q̇ = 0 (least Newton corrections), so
//! the drift stays at the step's local error instead of growing with time;
//! the largest violation removed is reported. The multipliers λ give the
//! joint reactions at the samples (−Φ_qᵀλ are the constraint forces).
//! Redundant constraints, and the nearly dependent rows at a singular
//! position, are handled by [`super::rows`]: those reactions are flagged.

pub(crate) mod equations;
mod grip;
mod ode;
mod plain;

use super::range_space::RangeSpace;
use super::{DynamicsError, DynamicsSolution, End, Failure, Integrator, Sample, Settings, Start, energy_residual, run};
use crate::engine::Deadline;
use crate::engine::constraints::{State, evaluate, evaluate_blocks, joint_offsets};
use crate::engine::kinematics::{Conditions, sweep};
use crate::engine::kinetostatics::{self, ContactState, Energy, Load, Motion, Reaction, potential, reactions};
use crate::engine::mobility::{Mobility, mobility};
use crate::engine::model::Mechanism;
use equations::{Equations, kinetic, masses};
use grip::{Grips, Mode};
use std::cell::RefCell;

/// A validated mechanism problem in SI units.
#[derive(Clone, Debug)]
pub struct MechanismProblem {
    /// The mechanism; its drivers name the input joints (free here).
    pub mechanism: Mechanism,
    pub loads: Vec<Load>,
    /// Period of the loads' functions in φ.
    pub period: f64,
    /// Coordinate and speed of every input at t = 0.
    pub initial: Vec<[f64; 2]>,
    pub end: End,
    pub tolerance: f64,
    /// The Runge–Kutta pair (None: [`Integrator::auto`] of the tolerance).
    pub integrator: Option<Integrator>,
    /// Hold the energy T + V to its initial value after every step (None:
    /// wherever the loads have a potential, see [`potential`]; Some(true)
    /// is ignored where they do not).
    pub conserve_energy: Option<bool>,
    pub samples: usize,
    /// The memory of kept steps a run ending at an angle may hold before it
    /// is made again for its samples (the service's: [`super::KEPT_BYTES`]).
    pub kept_bytes: usize,
    /// The job's compute budget.
    pub deadline: Deadline,
    /// Compute the joint reactions at the samples.
    pub reactions: bool,
    /// Keep q, q̇ and q̈ at the samples (for the motion of any point).
    pub motion: bool,
}

/// The mechanism at one sample.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanismSample {
    /// Coordinate, speed and acceleration of every input.
    pub inputs: Vec<[f64; 3]>,
    /// (x_G, y_G, θ) of every moving body, in body order.
    pub poses: Vec<[f64; 3]>,
    pub reactions: Vec<Reaction>,
    /// The state of every contact joint whose reaction is determinate.
    pub contacts: Vec<ContactState>,
    /// |Φ| at the sample (dense output, before any projection).
    pub constraint_residual: f64,
    /// The kinetic energy of every body and the potential of gravity and the springs.
    pub energy: Energy,
    /// q, q̇ and q̈, where the problem asks for the motion.
    pub motion: Option<Motion>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct MechanismSolution {
    /// The first input's motion, events and checks.
    pub solution: DynamicsSolution,
    pub details: Vec<MechanismSample>,
    pub mobility: Mobility,
    /// Largest |Φ| removed by a projection after a step.
    pub drift: f64,
    /// Times at which the integration met Φ_q within τ of losing rank and
    /// held the fold motion (see [`super::rows`]): singular positions passed
    /// at close range (one time per cluster of evaluations).
    pub near_singular: Vec<f64>,
    /// The equations were solved in the sparse (range-space) form away
    /// from singular positions; else by the dense form throughout.
    pub sparse: bool,
    /// The sparse form held the folds at singular positions (false: it
    /// declined near them, and the dense form held them).
    pub sparse_hold: bool,
    /// Evaluations of the equations of motion in the dense form.
    pub dense_evaluations: usize,
    /// The energy T + V was held to its initial value throughout: the loads
    /// have a potential, the hold was not turned off, and no singular
    /// position stopped it ([`Self::energy_held_steps`] says after how many
    /// steps it was E₀; not near turning points, where the correction
    /// would exceed 1 %).
    pub energy_conserved: bool,
    /// Steps after which T + V was E₀ (0 when the energy was not held).
    pub energy_held_steps: usize,
    /// The rolling contacts with friction (joints) that slip from the
    /// start: μN does not cover the force rolling needs there.
    pub slipping_from_start: Vec<usize>,
    /// DOP853 or Radau IIA was asked and met a singular position at this
    /// time, s, where its steps leave the mechanism's branch (IFToMM A02's
    /// parallelograms folded into antiparallelograms at their first flat
    /// position: DOP853 at 1e-9 then ran to the budget); the run was made
    /// again from the start with Dormand–Prince, which holds the fold (the
    /// steps and evaluations are its run's).
    pub integrator_replaced_at: Option<f64>,
}

/// Integrates the mechanism from its initial state.
pub fn solve(p: &MechanismProblem) -> Result<MechanismSolution, DynamicsError> {
    solve_in(p, true)
}

/// [`solve`], in the sparse form where it applies only if `sparse` (the
/// dense form throughout otherwise: a cross-check of the two). The sparse
/// form holds the folds at singular positions itself; where its steps fail
/// there (the step size underflows) the run is made again with the dense
/// form near them, as before the hold. Where DOP853 or Radau IIA was asked
/// and meets a fold, the run is made again with Dormand–Prince
/// ([`Equations::stopped_at_fold`], [`MechanismSolution::integrator_replaced_at`]).
pub fn solve_in(p: &MechanismProblem, sparse: bool) -> Result<MechanismSolution, DynamicsError> {
    match held_or_dense(p, sparse) {
        Err(Short::Fold(t)) => {
            let again = MechanismProblem { integrator: Some(Integrator::Dopri5), ..p.clone() };
            let mut s = held_or_dense(&again, sparse).map_err(Short::error)?;
            s.integrator_replaced_at = Some(t);
            Ok(s)
        }
        other => other.map_err(Short::error),
    }
}

/// [`attempt`] holding the folds in the sparse form, else in the dense form.
fn held_or_dense(p: &MechanismProblem, sparse: bool) -> Result<MechanismSolution, Short> {
    match attempt(p, sparse, true) {
        Err(Short::Failed(DynamicsError::Integration { .. })) if sparse && !p.deadline.expired() => {
            attempt(p, sparse, false)
        }
        other => other,
    }
}

/// Why one run stopped short.
enum Short {
    Failed(DynamicsError),
    /// The integrator asked met a fold at this time, s ([`Equations::stopped_at_fold`]).
    Fold(f64),
}

impl From<DynamicsError> for Short {
    fn from(e: DynamicsError) -> Self {
        Self::Failed(e)
    }
}

impl Short {
    /// The error to report; a fold is never one (Dormand–Prince goes on through it).
    fn error(self) -> DynamicsError {
        match self {
            Self::Failed(e) => e,
            Self::Fold(t) => DynamicsError::Integration { t, reason: Failure::SingularMotion },
        }
    }
}

/// One run, the sparse form holding folds if `hold`.
fn attempt(p: &MechanismProblem, sparse: bool, hold: bool) -> Result<MechanismSolution, Short> {
    let m = &p.mechanism;
    let initial = |reason: Start| DynamicsError::Initial { reason };
    let inputs: Vec<[f64; 3]> = p.initial.iter().map(|[a, w]| [*a, *w, 0.0]).collect();
    let over = |t: f64, steps: usize| DynamicsError::Budget { seconds: p.deadline.seconds(), t, steps };
    // Only whether the start is singular is read: the scaled condition alone.
    let start = sweep(m, &[inputs], &p.deadline, Conditions::Scaled)
        .map_err(|e| if p.deadline.expired() { over(0.0, 0) } else { initial(Start::Engine(e)) })?
        .remove(0);
    if start.singular {
        return Err(initial(Start::SingularInputs).into());
    }
    let mobility = mobility(m, &start.q);
    if mobility.dof != m.drivers.len() {
        return Err(initial(Start::Dof { dof: mobility.dof, inputs: m.drivers.len() }).into());
    }
    let n = m.n_coordinates();
    let mass = masses(m);
    let (length, lengths) = (m.size(), m.column_lengths());
    let (phi, _, jac) = evaluate_blocks(m, &State { q: &start.q, qd: None, inputs: &vec![[0.0; 3]; m.drivers.len()] });
    let r = phi.len() - m.drivers.len();
    let energy = energy(p, &mass, &start.q, &start.qd);
    // The range-space form needs M⁻¹ and reads the bodies' blocks only: not
    // for contacts, whose curve parameters carry no mass (the dense LU takes them).
    let sparse = (sparse && mobility.redundant_constraints == 0 && m.n_parameters() == 0)
        .then(|| RangeSpace::new(&jac, r, &mass, hold))
        .flatten();
    // Friction may dissipate: the energy is not held where a contact has it.
    let grips = grip::grips(m);
    let mut dae = Equations {
        p,
        n,
        r,
        mass,
        scale: lengths.iter().map(|c| c / length).collect(),
        tol: 1e-12 * length,
        // Redundant rows are dependent at every position: the plain test would fail each time.
        plain: (sparse.is_none() && grips.is_empty() && mobility.redundant_constraints == 0).then(Default::default),
        sparse: sparse.map(RefCell::new),
        held_at: RefCell::new(Vec::new()),
        dense: Default::default(),
        energy: energy.filter(|_| grips.is_empty()),
        energy_held: Default::default(),
        held: RefCell::new(Grips { modes: vec![Mode::Roll; grips.len()], slipped: vec![0.0; grips.len()] }),
        start: Grips { modes: vec![Mode::Roll; grips.len()], slipped: vec![0.0; grips.len()] },
        history: RefCell::new(Vec::new()),
        one_sided: grip::one_sided(m, &grips),
        grips,
    };
    if dae.motion(0.0, &start.q, &start.qd, false).is_none() {
        return Err(initial(Start::MovesNoMass).into());
    }
    let settings = settings(p, &start.qd, &lengths);
    let mut y0 = start.q.clone();
    y0.extend(&start.qd);
    y0.push(0.0);
    dae.settle(&y0);
    let run = run(&dae, y0, &settings);
    if let Some(t) = dae.stopped_at_fold() {
        return Err(Short::Fold(t));
    }
    let run = run?;
    let states = &run.states;
    let t0 = states.first().map_or(0.0, |(_, y)| dae.kinetic(&y[n..2 * n]));
    // W: −ΔV where the loads have a potential and nothing dissipates (no
    // quadrature error, which over a long run would dwarf the motion's),
    // else the integrated power.
    let v0 = potential(m, &p.loads, &start.q).filter(|_| dae.grips.is_empty());
    let work = |y: &[f64]| v0.and_then(|v0| Some(v0 - potential(m, &p.loads, &y[..n])?)).unwrap_or(y[2 * n]);
    let mut details = Vec::with_capacity(states.len());
    let mut samples = Vec::with_capacity(states.len());
    let mut peak = 0.0f64;
    for (t, y) in states {
        if p.deadline.expired() {
            return Err(over(run.t_end, run.attempted).into());
        }
        *dae.held.borrow_mut() = dae.grips_at(*t);
        let detail = sample(&dae, &mobility, *t, y)?;
        let [angle, speed, acceleration] = detail.inputs[0];
        let kinetic = dae.kinetic(&y[n..2 * n]);
        peak = peak.max(kinetic);
        let energy_residual = energy_residual(work(y), t0, kinetic, peak);
        samples.push(Sample { t: *t, angle, speed, acceleration, energy_residual });
        details.push(detail);
    }
    let (first, last) = (&states[0].1, &states[states.len() - 1].1);
    let solution = DynamicsSolution {
        samples,
        events: run.events,
        energy_times: Vec::new(),
        work_by_quadrature: false,
        energy_residual: energy_residual(work(last), dae.kinetic(&first[n..2 * n]), dae.kinetic(&last[n..2 * n]), peak),
        steps: run.attempted,
        evaluations: run.evaluations,
        integrator: run.integrator,
        stiff_at: run.stiff_at,
        repeated: run.repeated,
        estimated_error: estimated_error(&dae, last, &run.local_errors),
        stopped: run.stopped,
        unlisted_turns: run.unlisted_turns,
    };
    let near_singular = clusters(&dae.held_at.borrow(), run.t_end);
    let (sparse, sparse_hold) = (dae.sparse.is_some(), dae.sparse.is_some() && hold);
    let (dense_evaluations, energy_held_steps) = (dae.dense.get(), dae.energy_held.get());
    let energy_conserved = dae.energy.is_some() && near_singular.is_empty();
    Ok(MechanismSolution {
        solution,
        details,
        mobility,
        drift: run.drift,
        near_singular,
        sparse,
        sparse_hold,
        dense_evaluations,
        energy_conserved,
        energy_held_steps,
        integrator_replaced_at: None,
        slipping_from_start: (dae.grips.iter().zip(&dae.start.modes))
            .filter(|(_, mode)| **mode != Mode::Roll)
            .map(|(g, _)| g.joint)
            .collect(),
    })
}

/// The run's error estimate in the first input's unit: its Σ of local
/// errors bounded through the input's row (a slider's travel as much as a
/// crank's angle), and where the input is an angle, the largest over the
/// bodies' angles too.
fn estimated_error(dae: &Equations, last: &[f64], local_errors: &[f64]) -> f64 {
    let m = &dae.p.mechanism;
    let input = dae.input_error(&last[..dae.n], local_errors);
    if m.drivers.first().is_some_and(|d| m.is_length(d.coordinate)) {
        return input;
    }
    (0..m.bodies.len() - 1).map(|b| local_errors[3 * b + 2]).fold(input, f64::max)
}

/// The first time of each cluster of held evaluations (gaps over t_end/1000 apart).
fn clusters(held_at: &[f64], t_end: f64) -> Vec<f64> {
    let mut times = held_at.to_vec();
    times.sort_by(f64::total_cmp);
    let mut out: Vec<f64> = Vec::new();
    for (k, t) in times.iter().enumerate() {
        if k == 0 || t - times[k - 1] > t_end / 1000.0 {
            out.push(*t);
        }
    }
    out
}

/// Tolerances: relative `tolerance`/100 on every component; absolute on
/// each coordinate relative to its length scale c_j (the mechanism's size
/// L, or 1 rad; `model::scale`), on velocities relative to c_j·Ω with Ω
/// the largest of 1 rad/s, √(|g|/L) and the initial angular speeds.
fn settings(p: &MechanismProblem, qd: &[f64], lengths: &[f64]) -> Settings {
    let g = p.mechanism.gravity[0].hypot(p.mechanism.gravity[1]);
    let spin = (0..p.mechanism.bodies.len() - 1).map(|b| qd[3 * b + 2].abs()).fold(0.0, f64::max);
    let rate = 1.0f64.max((g / p.mechanism.size()).sqrt()).max(spin);
    let rtol = (0.01 * p.tolerance).clamp(1e-13, 1e-4);
    let positions = lengths.iter().map(|c| rtol * c);
    let mut atol: Vec<f64> = positions.clone().chain(positions.map(|a| a * rate)).collect();
    atol.push(f64::INFINITY);
    let integrator = p.integrator.unwrap_or_else(|| Integrator::auto(p.tolerance, false));
    let (end, samples, automatic, deadline) = (p.end, p.samples, p.integrator.is_none(), p.deadline);
    Settings { end, samples, kept_bytes: p.kept_bytes, rtol, atol, integrator, automatic, deadline }
}

/// The energy T + V to hold, when asked or by default and the loads have a potential.
fn energy(p: &MechanismProblem, mass: &[f64], q: &[f64], qd: &[f64]) -> Option<f64> {
    if p.conserve_energy == Some(false) {
        return None;
    }
    potential(&p.mechanism, &p.loads, q).map(|v| v + kinetic(mass, qd))
}

/// Inputs, reactions and constraint residual at a sampled state.
fn sample(dae: &Equations, mobility: &Mobility, t: f64, y: &[f64]) -> Result<MechanismSample, DynamicsError> {
    let (n, r) = (dae.n, dae.r);
    let (q, qd) = (&y[..n], &y[n..2 * n]);
    let singular = || DynamicsError::Integration { t, reason: Failure::SingularMotion };
    let motion = dae.motion(t, q, qd, dae.p.reactions).ok_or_else(singular)?;
    let reactions = if dae.p.reactions {
        let m = &dae.p.mechanism;
        let zeros = vec![[0.0; 3]; m.drivers.len()];
        let jac = evaluate(m, &State { q, qd: None, inputs: &zeros }).jacobian.rows(0, r).into_owned();
        let offsets = joint_offsets(m);
        let indeterminate: Vec<usize> = (0..m.joints.len())
            .filter(|&j| {
                mobility.indeterminate_joints.contains(&j)
                    || (offsets[j]..offsets[j] + Mechanism::joint_rows(&m.joints[j].kind))
                        .any(|row| motion.loose.get(row) == Some(&true))
            })
            .collect();
        reactions(m, q, &jac, &motion.lambda, &offsets, &indeterminate)
    } else {
        Vec::new()
    };
    let states = reactions.iter().filter(|r| r.determinate);
    let held = dae.held.borrow();
    let slipping = |joint: usize| {
        let grip = dae.grips.iter().position(|g| g.joint == joint)?;
        Some(held.modes[grip] != Mode::Roll)
    };
    let contacts = states
        .filter_map(|r| kinetostatics::contact_state(&dae.p.mechanism, (q, qd), None, r))
        .map(|c| ContactState { slipping: slipping(c.joint), ..c })
        .collect();
    let poses = q[..dae.p.mechanism.n_body_coordinates()].chunks_exact(3).map(|b| [b[0], b[1], b[2]]).collect();
    let energy = kinetostatics::energy(&dae.p.mechanism, &dae.p.loads, q, qd);
    let kept = dae.p.motion.then(|| Motion { q: q.to_vec(), qd: qd.to_vec(), qdd: motion.qdd.clone() });
    Ok(MechanismSample {
        inputs: motion.inputs,
        poses,
        reactions,
        contacts,
        constraint_residual: motion.residual,
        energy,
        motion: kept,
    })
}
