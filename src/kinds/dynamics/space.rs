//! The `machine` form of `POST /v1/dynamics` for a mechanism with
//! `"space": "spatial"`: its free inputs (a joint's rotation or slide) set
//! the start and report the motion, integrated by the spatial engine with
//! the plane's integrators, events, budget and global error estimate. Each
//! sample has every input, every body's motion (as kinetostatics' steps
//! have it), the reactions where asked, the energies and the work done, and
//! the joints' residual. `track`, `conserve_energy: true` and a Function
//! of the inputs' speeds other than a constant are refused at their pointers.

use super::global;
use super::machine::{InputState, input_state};
use super::refused::invalid;
use super::result::{DynamicsResult, MachineResult};
use super::{DynamicsMachine, DynamicsRequest, Initial, said_global};
use crate::engine::dynamics::Integrator;
use crate::engine::spatial::dynamics::{SpatialProblem, SpatialSolution, solve};
use crate::engine::spatial::{LoadLaw, Mechanism};
use crate::i18n::Msg;
use crate::kind::problem::ApiError;
use crate::kind::quantity::Errors;
use crate::kinds::mechanism::motion3::{BodyMotion3, Reaction3};
use crate::kinds::mechanism::spatial::joint_coordinate;
use crate::kinds::mechanism::spatial_loads::spatial_loads;
use crate::kinds::mechanism::{EnergyDto, Inputs, MechanismSpace, Names};
use serde::Serialize;
use utoipa::ToSchema;

/// What the result says beside the engine's solution.
pub(super) struct SpatialReport {
    pub joint_names: Vec<String>,
    pub body_names: Vec<String>,
    /// Each input is a slide (m), not a rotation (rad).
    pub linear: Vec<bool>,
}

/// The converted spatial machine.
pub(super) struct SpatialParts {
    pub mechanism: Mechanism,
    pub loads: Vec<LoadLaw>,
    pub reference: Vec<f64>,
    pub initial: Vec<[f64; 2]>,
    pub report: SpatialReport,
}

impl DynamicsMachine {
    /// Reads a spatial machine, every error at its pointer under `/machine`.
    pub(super) fn spatial(&self, e: &mut Errors, initial: Option<&Initial>, period: f64) -> Option<SpatialParts> {
        let c = self.mechanism.spatial(e, "/machine/mechanism")?;
        if self.track.is_some() {
            e.say("/machine/track", Msg::new("kinetostatics-not-spatial"));
        }
        if self.conserve_energy == Some(true) {
            e.say("/machine/conserve_energy", Msg::new("kinetostatics-not-spatial"));
        }
        let (list, many) = match &self.input {
            Inputs::One(i) => (vec![(**i).clone()], false),
            Inputs::Many(v) => (v.clone(), true),
        };
        if list.is_empty() || list.len() > 10 {
            e.say("/machine/input", Msg::new("input-count"));
        }
        let (mut inputs, mut reference, mut states, mut linear) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for (k, input) in list.iter().enumerate() {
            let at = if many { format!("/machine/input/{k}") } else { "/machine/input".into() };
            let Some(chosen) = joint_coordinate(e, &c.mechanism, input, &at) else { continue };
            let length = chosen.coordinate == crate::engine::spatial::Coordinate::Slide;
            let given = if k == 0 { initial } else { None };
            if let Some((r, state)) = input_state(e, input, given, length, &at) {
                inputs.push(chosen);
                reference.push(r);
                states.push(state);
                linear.push(length);
            }
        }
        let variables = ["phi", "omega", "t"];
        let loads = self.loads.as_deref().unwrap_or_default();
        let loads = spatial_loads(e, loads, (&self.mechanism, &c), period, "/machine/loads", &variables);
        let joint_names = c.mechanism.joints.iter().map(|j| j.name.clone()).collect();
        let report = SpatialReport { joint_names, body_names: c.body_names, linear };
        let mechanism = Mechanism { inputs, ..c.mechanism };
        Some(SpatialParts { mechanism, loads, reference, initial: states, report })
    }
}

/// Runs a spatial machine and writes its result.
pub(super) fn compute(
    request: &DynamicsRequest,
    p: &SpatialProblem,
    report: &SpatialReport,
) -> Result<DynamicsResult, ApiError> {
    let dopri5 = p.integrator.unwrap_or_else(|| Integrator::auto(p.tolerance, true)) == Integrator::Dopri5;
    let s = solve(p).map_err(|e| invalid(e, dopri5))?;
    let run = (p.tolerance, p.end, p.deadline.elapsed(), p.deadline.seconds());
    let again = |tolerance| {
        let tight =
            SpatialProblem { tolerance, reactions: false, deadline: global::deadline(&p.deadline), ..p.clone() };
        solve(&tight).map(|s| s.solution)
    };
    let global = global::estimate(&s.solution, run, again);
    let mut result = request.in_its_words(DynamicsResult::from(s.solution.clone()));
    said_global(&mut result, &global);
    result.accuracy.constraint_drift = Some(s.drift);
    result.accuracy.method = result.notes.say("/accuracy/method", Msg::new("accuracy-dynamics-spatial"));
    if s.redundant_rows > 0 {
        let said = Msg::new("warning-dynamics-redundant-spatial").count("count", s.redundant_rows);
        result.notes.warn(said);
    }
    result.machine = Some(MachineResult::Spatial(SpatialMachineDynamics::new(&s, p, report)));
    Ok(result)
}

/// What a spatial machine adds to a dynamics result.
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct SpatialMachineDynamics {
    /// `spatial`.
    pub space: MechanismSpace,
    /// Degrees of freedom at the start (one input each).
    pub dof: usize,
    /// Constraint rows that repeat others at the start (Bricard's linkage
    /// has one), left out of the equations; the reactions they share are
    /// then not determinate.
    pub redundant_constraints: usize,
    /// Each input's coordinate unit: "rad" (a rotation) or "m" (a slide);
    /// speeds and accelerations per second.
    pub input_units: Vec<String>,
    pub samples: Vec<SpatialMachineSample>,
}

/// The spatial mechanism at one sample (the same instants as `samples`).
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct SpatialMachineSample {
    pub t: f64,
    /// Every input, in the order given: the first's coordinate runs on past
    /// ±π (it is integrated), the others' are read from the position.
    pub inputs: Vec<InputState>,
    /// Every moving body's motion, vectors in ground axes.
    pub bodies: Vec<BodyMotion3>,
    /// Every joint's reaction on its second body, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reactions: Option<Vec<Reaction3>>,
    /// Largest |Φ| of the joints at the sample, m (an angle's row times the
    /// drawing's size).
    pub constraint_residual: f64,
    pub energy: EnergyDto,
    /// W, the work of every applied action since t = 0, gravity's and the
    /// springs' and dampers' included (J): W − (T − T₀) is the energy
    /// balance's residual.
    pub work: f64,
}

impl SpatialMachineDynamics {
    fn new(s: &SpatialSolution, p: &SpatialProblem, report: &SpatialReport) -> Self {
        let names = Names::new(&report.joint_names, &report.body_names);
        let m = &p.mechanism;
        let samples = (s.details.iter().zip(&s.solution.samples))
            .map(|(d, x)| SpatialMachineSample {
                t: x.t,
                inputs: d
                    .inputs
                    .iter()
                    .map(|&[angle, speed, acceleration]| InputState { angle, speed, acceleration })
                    .collect(),
                bodies: (1..=m.n()).map(|b| BodyMotion3::new(&report.body_names[b], b, &d.pose, &d.v, &d.a)).collect(),
                reactions: d
                    .actions
                    .as_ref()
                    .map(|a| a.reactions.iter().map(|r| Reaction3::new(r, m, &report.body_names)).collect()),
                constraint_residual: d.constraint_residual,
                energy: EnergyDto::new(d.energy.clone(), &names.bodies, &names.moving),
                work: d.work,
            })
            .collect();
        Self {
            space: MechanismSpace::Spatial,
            dof: m.inputs.len(),
            redundant_constraints: s.redundant_rows,
            input_units: report.linear.iter().map(|&l| if l { "m" } else { "rad" }.into()).collect(),
            samples,
        }
    }
}
