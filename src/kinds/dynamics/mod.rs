//! `POST /v1/dynamics`: the motion of a machine under given actions, in
//! reduced form (1 DOF) or as a mechanism (any DOF, see [`machine`]).

mod global;
mod machine;
mod plots;
mod refused;
mod request;
mod result;
mod size;
mod solution;
mod space;
mod space_solution;
mod table;

use crate::engine::dynamics::mechanism::{self, MechanismProblem};
use crate::engine::dynamics::{Integrator, ReducedProblem, solve};
use crate::i18n::Msg;
use crate::kind::constants::Constants;
use crate::kind::limits::Limits;
use crate::kind::plots::Plots;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::{FunctionDto, Quantity};
use crate::kind::validated;
use crate::kind::{Kind, Table, unit_in};
use crate::kinds::mechanism::contact_warnings;
use refused::invalid;
use request::Problem;
use serde::{Deserialize, Serialize};
use serde_json::Value;
use utoipa::ToSchema;

pub use machine::{DynamicsMachine, InputState, MachineDynamics, MachineSample};
pub use result::{DynamicsAccuracy, DynamicsResult, EventDto, MachineResult, SampleDto};
pub use space::{SpatialMachineDynamics, SpatialMachineSample};
pub use table::csv_table;

/// Longest simulated time, s.
pub const MAX_DURATION: f64 = 1e5;
/// The longest a run to an angle takes when `max_duration` is not given, s.
const DEFAULT_MAX_DURATION: f64 = 60.0;
const DEFAULT_SAMPLES: usize = 201;

/// A machine — in reduced form (`torques` and `reduced_inertia`) or as a
/// mechanism (`machine`) — and its start: exactly one of `duration` and `until_angle`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "torques": [{"name": "motor and yoke", "value": {"expr": "15 - 20*sin(phi)^2"}}],
    "reduced_inertia": {"expr": "0.07 + 0.05*sin(phi)^2"},
    "initial": {"angle": 0, "speed": 0},
    "until_angle": "720 deg"
}))]
pub struct DynamicsRequest {
    /// Named values every expression of this request may read, e.g.
    /// `{"F": "1200 N", "r": "0.1 m"}`: each a number (SI) or a quantity,
    /// read in SI. A constant no expression reads is a warning.
    #[schema(value_type = Option<std::collections::BTreeMap<String, Quantity>>)]
    pub constants: Option<Constants>,
    /// Reduced form: torques on the machine, positive when they drive it:
    /// Functions whose expressions may read `phi` (reduced to the period),
    /// `omega` and `t`.
    #[serde(default)]
    #[schema(max_items = 100)]
    pub torques: Vec<DynamicsTorque>,
    /// Reduced form: I*(φ) > 0.
    #[schema(value_type = Option<FunctionDto>)]
    pub reduced_inertia: Option<FunctionDto>,
    /// Mechanism form, instead of `torques` and `reduced_inertia`.
    pub machine: Option<DynamicsMachine>,
    pub initial: Option<Initial>,
    /// Simulated time, s.
    #[schema(value_type = Option<Quantity>)]
    pub duration: Option<Quantity>,
    /// Stop when the angle reaches this value.
    #[schema(value_type = Option<Quantity>)]
    pub until_angle: Option<Quantity>,
    /// With `until_angle`: give up (cleanly, with the reason) after this time (default 60 s).
    #[schema(value_type = Option<Quantity>)]
    pub max_duration: Option<Quantity>,
    /// Period of the Functions in `phi` (default 2π).
    #[schema(value_type = Option<Quantity>)]
    pub period: Option<Quantity>,
    /// Requested relative accuracy (default 1e-9). With a `machine`, positions
    /// are held to it relative to the mechanism's size.
    #[schema(minimum = 1e-14, maximum = 1e-2)]
    pub tolerance: Option<f64>,
    /// The Runge–Kutta pair (default `auto`); the one used is in
    /// `accuracy.integrator`.
    pub integrator: Option<IntegratorChoice>,
    /// Output points, evenly spaced in time, both ends included (default 201).
    #[schema(minimum = 2, maximum = 100000)]
    pub samples: Option<usize>,
}

/// `dopri5`: Dormand–Prince 5(4), 6 evaluations a step; `dop853`: Hairer's
/// DOP853, order 8, 15 evaluations a step and far fewer steps at tight
/// tolerances and over long smooth runs; `radau5`: Radau IIA, order 5,
/// implicit, for stiff models (a stiff spring): its steps follow the slow
/// motion and damp a mode far faster than it — on a model that is not
/// stiff each of its steps solves a Newton system, and a run takes 20 to 30
/// times as long as with `dop853` for an error far below the tolerance, so
/// ask for it only for a stiff model, or leave it to `auto`; `auto`: in the reduced form
/// DOP853 at a tolerance of 1e-5 or less, Dormand–Prince above; for a
/// `machine` Dormand–Prince (its accelerations jump near singular
/// positions, where a high order gains nothing); either, finding its steps
/// held by stability (15 steps beyond its stability interval), hands the
/// run to `radau5` from the start (`accuracy.stiff_at` says when). A
/// `machine` asked to run with `dop853` or `radau5` that meets a singular
/// position (a parallelogram lying flat) is run again with `dopri5`, whose
/// steps the fold's hold keeps on the mechanism's branch
/// (`accuracy.integrator_replaced_at` and a warning say when). See
/// docs/BENCHMARKS.md.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum IntegratorChoice {
    Auto,
    Dopri5,
    Dop853,
    Radau5,
}

impl IntegratorChoice {
    fn engine(choice: Option<Self>) -> Option<Integrator> {
        match choice? {
            Self::Auto => None,
            Self::Dopri5 => Some(Integrator::Dopri5),
            Self::Dop853 => Some(Integrator::Dop853),
            Self::Radau5 => Some(Integrator::Radau5),
        }
    }
}

impl From<Integrator> for IntegratorChoice {
    fn from(i: Integrator) -> Self {
        match i {
            Integrator::Dopri5 => Self::Dopri5,
            Integrator::Dop853 => Self::Dop853,
            Integrator::Radau5 => Self::Radau5,
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DynamicsTorque {
    #[schema(max_length = 200)]
    pub name: String,
    #[schema(value_type = FunctionDto)]
    pub value: FunctionDto,
    /// ω of its shaft / ω of the reference shaft (default 1).
    pub ratio: Option<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Initial {
    #[schema(value_type = Option<Quantity>)]
    pub angle: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub speed: Option<Quantity>,
}

/// Dynamics: `POST /v1/dynamics`.
pub struct Dynamics;

impl Kind for Dynamics {
    const NAME: &'static str = "dynamics";
    const TITLE: &'static str = "kind-dynamics";
    const PATH: &'static str = "/v1/dynamics";
    const OPERATION_ID: &'static str = "create_dynamics_job";
    const TAG: &'static str = "dynamics";
    const SUMMARY: &'static str =
        "Integrates I*(φ)φ̈ + ½I*'(φ)φ̇² = M*(φ, ω, t), or a mechanism's equations of motion, from the initial state.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/accuracy/constraint_drift", "m or rad"),
        ("/accuracy/energy_form_time_difference", "s"),
        ("/accuracy/energy_held_steps", "1"),
        ("/accuracy/energy_residual", "1"),
        ("/accuracy/estimated_error", "rad"),
        ("/accuracy/function_evaluations", "1"),
        ("/accuracy/integrator_replaced_at", "s"),
        ("/accuracy/steps", "1"),
        ("/end/angle", "rad"),
        ("/end/speed", "rad/s"),
        ("/end/t", "s"),
        ("/end/t_energy_form", "s"),
        ("/energy_residual", "1"),
        ("/events/*/angle", "rad"),
        ("/events/*/speed", "rad/s"),
        ("/events/*/t", "s"),
        ("/events/*/t_energy_form", "s"),
        ("/machine/dof", "1"),
        ("/machine/near_singular/*", "s"),
        ("/machine/redundant_constraints", "1"),
        ("/machine/samples/*/bodies/*/theta", "rad"),
        ("/machine/samples/*/bodies/*/x", "m"),
        ("/machine/samples/*/bodies/*/y", "m"),
        ("/machine/samples/*/constraint_residual", "m or rad"),
        ("/machine/samples/*/energy/kinetic/total", "J"),
        ("/machine/samples/*/energy/kinetic/bodies/*", "J"),
        ("/machine/samples/*/energy/potential/gravity", "J"),
        ("/machine/samples/*/energy/potential/springs", "J"),
        ("/machine/samples/*/inputs/*/angle", "rad"),
        ("/machine/samples/*/inputs/*/speed", "rad/s"),
        ("/machine/samples/*/inputs/*/acceleration", "rad/s^2"),
        ("/machine/samples/*/points/*/x", "m"),
        ("/machine/samples/*/points/*/y", "m"),
        ("/machine/samples/*/points/*/vx", "m/s"),
        ("/machine/samples/*/points/*/vy", "m/s"),
        ("/machine/samples/*/points/*/ax", "m/s^2"),
        ("/machine/samples/*/points/*/ay", "m/s^2"),
        ("/machine/assembled_points/*/*", "m"),
        ("/machine/samples/*/reactions/*/fx", "N"),
        ("/machine/samples/*/reactions/*/fy", "N"),
        ("/machine/samples/*/reactions/*/moment", "N*m"),
        ("/machine/samples/*/reactions/*/ends/*", "N"),
        ("/machine/samples/*/reactions/*/normal", "N"),
        ("/machine/samples/*/reactions/*/tangential", "N"),
        ("/machine/samples/*/reactions/*/mu_required", "1"),
        ("/machine/samples/*/contacts/*/point/*", "m"),
        ("/machine/samples/*/contacts/*/sliding_velocity", "m/s"),
        ("/machine/samples/*/contacts/*/velocities/*/*", "m/s"),
        ("/machine/samples/*/contacts/*/normal", "N"),
        ("/machine/samples/*/contacts/*/tangential", "N"),
        ("/machine/samples/*/contacts/*/curvature_radius/*", "m"),
        ("/machine/samples/*/contacts/*/pressure_angle", "rad"),
        ("/machine/samples/*/contacts/*/penetration", "m"),
        ("/machine/samples/*/t", "s"),
        ("/machine/samples/*/work", "J"),
        ("/machine/samples/*/bodies/*/position/*", "m"),
        ("/machine/samples/*/bodies/*/rotation/*/*", "1"),
        ("/machine/samples/*/bodies/*/velocity/*", "m/s"),
        ("/machine/samples/*/bodies/*/angular_velocity/*", "rad/s"),
        ("/machine/samples/*/bodies/*/acceleration/*", "m/s^2"),
        ("/machine/samples/*/bodies/*/angular_acceleration/*", "rad/s^2"),
        ("/machine/samples/*/reactions/*/force/*", "N"),
        ("/machine/samples/*/reactions/*/moment/*", "N*m"),
        ("/machine/samples/*/reactions/*/magnitude", "N"),
        ("/samples/*/acceleration", "rad/s^2"),
        ("/samples/*/angle", "rad"),
        ("/samples/*/energy_residual", "1"),
        ("/samples/*/speed", "rad/s"),
        ("/samples/*/t", "s"),
    ];
    type Request = DynamicsRequest;
    type Result = DynamicsResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };
    const SOLUTION: Option<crate::kind::solution::Solve> = Some(solution::solution);

    /// A mechanism's run has its bodies' free bodies; one in reduced form has none.
    fn has_solution(result: &Value) -> bool {
        result["machine"].is_object()
    }

    fn compute(
        request: &DynamicsRequest,
        unknown: Vec<FieldError>,
        limits: &Limits,
    ) -> Result<DynamicsResult, ApiError> {
        compute(request, unknown, limits)
    }

    fn table(result: &Value) -> Option<Table> {
        Some(csv_table(result))
    }

    /// A machine's input in metres (a prismatic joint, a point) has its
    /// coordinate in m, its speed in m/s; the table says rad otherwise. The
    /// first input's is also the motion's (`samples`, `events`, `end`) and
    /// its estimated error's.
    fn unit(result: &Value, pointer: &[&str]) -> Option<String> {
        let metres = |k: &str| k.parse::<usize>().is_ok_and(|k| result["machine"]["input_units"][k] == "m");
        let linear = |field: &str| match field {
            "angle" | "estimated_error" => Some("m".to_string()),
            "speed" => Some("m/s".into()),
            "acceleration" => Some("m/s^2".into()),
            _ => None,
        };
        let field = match pointer {
            ["machine", "samples", _, "inputs", k, field] if metres(k) => Some(*field),
            ["samples" | "events", _, field] | ["end" | "accuracy", field] if metres("0") => Some(*field),
            _ => None,
        };
        field.and_then(linear).or_else(|| unit_in(Self::UNITS, pointer).map(String::from))
    }
}

/// The global error found (or why not) in `result`'s accuracy: the bound
/// `estimated_error` and how it was found.
fn said_global(result: &mut DynamicsResult, global: &global::Global) {
    let a = &mut result.accuracy;
    a.estimated_error = global::bound(a.estimated_error, global);
    a.global_error = global.as_ref().ok().copied();
    let msg = match global {
        Ok(_) => Msg::new("accuracy-global-made"),
        Err(why) => Msg::new("accuracy-global-none").with("why", Msg::new(why)),
    };
    a.error_estimate = result.notes.say("/accuracy/error_estimate", msg);
}

/// Validates and solves a request within `limits`, stopping the integration
/// when the compute budget runs out.
fn compute(request: &DynamicsRequest, unknown: Vec<FieldError>, limits: &Limits) -> Result<DynamicsResult, ApiError> {
    let problem = validated(unknown, request.to_problem(limits))?;
    size::refuse_if_it_cannot_fit(&problem, limits.result_bytes)?;
    match problem {
        Problem::Reduced(p) => {
            let dopri5 = p.integrator.unwrap_or_else(|| Integrator::auto(p.tolerance, true)) == Integrator::Dopri5;
            let s = solve(&p).map_err(|e| invalid(e, dopri5))?;
            let run = (p.tolerance, p.end, p.deadline.elapsed(), p.deadline.seconds());
            let again =
                |tolerance| solve(&ReducedProblem { tolerance, deadline: global::deadline(&p.deadline), ..p.clone() });
            let global = global::estimate(&s, run, again);
            let mut result = DynamicsResult::from(s);
            said_global(&mut result, &global);
            Ok(request.in_its_words(result))
        }
        Problem::Machine(p, report) => {
            let dopri5 = p.integrator.unwrap_or_else(|| Integrator::auto(p.tolerance, false)) == Integrator::Dopri5;
            let s = mechanism::solve(&p).map_err(|e| invalid(e, dopri5))?;
            let run = (p.tolerance, p.end, p.deadline.elapsed(), p.deadline.seconds());
            let again = |tolerance| {
                let deadline = global::deadline(&p.deadline);
                let tight = MechanismProblem { tolerance, reactions: false, motion: false, deadline, ..p.clone() };
                mechanism::solve(&tight).map(|s| s.solution)
            };
            let global = global::estimate(&s.solution, run, again);
            let mut result = request.in_its_words(DynamicsResult::from(s.solution.clone()));
            said_global(&mut result, &global);
            for (dto, event) in result.events.iter_mut().zip(&s.solution.events) {
                dto.joint = event.joint.map(|k| p.mechanism.joints[k].name.clone());
            }
            result.accuracy.constraint_drift = Some(s.drift);
            result.accuracy.energy_conserved = Some(s.energy_conserved);
            result.accuracy.energy_held_steps = Some(s.energy_held_steps);
            result.accuracy.integrator_replaced_at = s.integrator_replaced_at;
            result.accuracy.method = result.notes.say("/accuracy/method", result::machine_method(&s));
            if let Some(said) = result::replaced(&s, p.integrator) {
                result.notes.warn(said);
            }
            if let Some(said) = result::singular(&s, p.tolerance) {
                result.notes.warn(said);
            }
            if let Some(a) = &report.assembled {
                result.notes.extend(a.warnings.iter().cloned());
            }
            let machine = MachineDynamics::new(&s, &p.mechanism, report);
            let contacts = machine.samples.iter().filter_map(|x| Some((x.t, x.contacts.as_deref()?)));
            result.notes.extend(contact_warnings(contacts, &p.mechanism, result::at_time, true));
            result.notes.extend(result::slipping(&s, &p.mechanism));
            result.machine = Some(MachineResult::Planar(machine));
            Ok(result)
        }
        Problem::Spatial(p, report) => space::compute(request, &p, &report),
    }
}

impl DynamicsRequest {
    /// The result with its "not reached" warning (the first a solution
    /// carries) in the request's words: `until_angle` and `max_duration` as
    /// given ("720 deg", not 12.566370614359172 rad).
    fn in_its_words(&self, mut result: DynamicsResult) -> DynamicsResult {
        let not_reached = result.notes.messages.get("/warnings/0").is_some_and(|m| m.id() == result::NOT_REACHED);
        if let (true, Some(angle)) = (not_reached, &self.until_angle) {
            let time =
                self.max_duration.as_ref().map_or_else(|| format!("{DEFAULT_MAX_DURATION} s"), |q| q.as_given("s"));
            let said = Msg::new(result::NOT_REACHED).arg("angle", angle.as_given("rad")).arg("time", time);
            result.notes.reword(0, said);
        }
        result
    }
}
