//! `POST /v1/kinetostatics` for a mechanism with `"space": "spatial"`:
//! swept over its inputs by the spatial engine, each step with the inputs'
//! efforts, every joint's reaction as a force and a moment, every body's
//! motion with its rotation matrix, and I* for one input (2T/θ̇²); what the
//! plane alone offers (`track`, `actuators`, `balance`, the outputs
//! condition, energy, points and shaking) refused at its pointer.

use super::inputs;
use super::request::{KinetostaticsRequest, OutputKind};
use super::result::{
    GrublerDto, InputInfo, Kinematics, KinetostaticsAccuracy, KinetostaticsResult, Scalars, StepDto, StepReactions,
    SummaryDto,
};
use crate::engine::spatial::free_body::free_bodies;
use crate::engine::spatial::{
    Actions, Load, Mechanism, Motion, Pose, assemble, inverse_dynamics, kinetic, mobility, motion,
};
use crate::i18n::Msg;
use crate::kind::constants;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Errors;
use crate::kind::solution::Solution;
use crate::kind::{engine_failure, validated};
use crate::kinds::mechanism::Inputs;
use crate::kinds::mechanism::motion3::{BodyMotion3, Reaction3};
use crate::kinds::mechanism::solution3::written;
use crate::kinds::mechanism::spatial_loads::spatial_loads;
use std::collections::BTreeMap;
use std::f64::consts::PI;

/// The validated spatial problem.
struct Problem {
    mechanism: Mechanism,
    body_names: Vec<String>,
    loads: Vec<crate::engine::spatial::LoadLaw>,
    /// Each step's inputs as the request counts them (from each `reference`).
    positions: Vec<Vec<[f64; 3]>>,
    /// Each input's value as drawn, where the engine counts it from.
    reference: Vec<f64>,
    linear: Vec<bool>,
    outputs: Vec<OutputKind>,
}

/// Reads, sweeps and writes a spatial kinetostatics job.
pub fn compute(
    r: &KinetostaticsRequest,
    unknown: Vec<FieldError>,
    limits: &Limits,
) -> Result<KinetostaticsResult, ApiError> {
    let deadline = limits.deadline();
    let mut e = Errors::new(limits);
    let read = read(r, &mut e);
    let p = validated(unknown, read.filter(|_| e.list.is_empty()).ok_or(e.list))?;
    let m = &p.mechanism;
    let found = mobility(m, &Pose::drawn(m)).map_err(|e| engine_failure(e, "/mechanism"))?;
    if found.dof != m.inputs.len() {
        let e = crate::engine::EngineError::DofMismatch { dof: found.dof, inputs: m.inputs.len() };
        return Err(engine_failure(e, "/input"));
    }
    let mut steps = Vec::with_capacity(p.positions.len());
    let mut worst = (0.0f64, 0.0f64);
    let iterations = swept(&p, p.positions.len(), &deadline, |x, now, actions, _| {
        worst.0 = worst.0.max(actions.virtual_power.abs() / actions.largest_power.max(f64::MIN_POSITIVE));
        worst.1 = worst.1.max(now.rows.phi.amax());
        steps.push(step(&p, x, now, actions));
    })?;
    Ok(result(&p, steps, &found, worst, iterations))
}

/// The first `count` steps of the sweep, each handed to `each` with its
/// inputs, motion, actions and loads; the most Newton iterations a step took.
fn swept(
    p: &Problem,
    count: usize,
    deadline: &crate::engine::Deadline,
    mut each: impl FnMut(&[[f64; 3]], &Motion, &Actions, &[Load]),
) -> Result<usize, ApiError> {
    let m = &p.mechanism;
    let (mut pose, mut iterations) = (Pose::drawn(m), 0);
    for (k, x) in p.positions.iter().take(count).enumerate() {
        deadline
            .check(|| crate::engine::Progress::Assembled { step: k, of: count })
            .map_err(|e| engine_failure(e, "/input"))?;
        let drawn: Vec<[f64; 3]> = x.iter().zip(&p.reference).map(|(v, r)| [v[0] - r, v[1], v[2]]).collect();
        let (assembled, taken) = assemble(m, &drawn, &pose, k).map_err(|e| engine_failure(e, "/input"))?;
        (pose, iterations) = (assembled, iterations.max(taken));
        let now = motion(m, pose.clone(), &drawn, k).map_err(|e| engine_failure(e, "/input"))?;
        let loads: Vec<_> = p.loads.iter().map(|l| l.at(x[0][0], [x[0][1], 0.0])).collect();
        each(x, &now, &inverse_dynamics(m, &loads, &now), &loads);
    }
    Ok(iterations)
}

/// The worked solution of step `step` of a stored spatial job: the sweep
/// run again up to it (the same branch), its free bodies written.
pub fn solution(r: &KinetostaticsRequest, step: usize, limits: &Limits) -> Result<Solution, ApiError> {
    let mut e = Errors::new(limits);
    let read = read(r, &mut e);
    let p = validated(vec![], read.filter(|_| e.list.is_empty()).ok_or(e.list))?;
    let count = p.positions.len();
    if step >= count {
        return Err(crate::kind::plots::beyond_steps(step, count));
    }
    let mut found = None;
    swept(&p, step + 1, &limits.deadline(), |x, now, actions, loads| {
        found = Some((x[0][0], free_bodies(&p.mechanism, loads, now, actions)));
    })?;
    let (_, bodies) = found.ok_or_else(|| ApiError::Internal(format!("step {step} was not solved again")))?;
    let input: Vec<f64> = p.positions[step].iter().map(|v| v[0]).collect();
    let loads: Vec<Load> = p.loads.iter().map(|l| l.at(input[0], [p.positions[step][0][1], 0.0])).collect();
    Ok(written(&p.mechanism, &p.body_names, &loads, (step, &input), &bodies, false))
}

fn read(r: &KinetostaticsRequest, e: &mut Errors) -> Option<Problem> {
    constants::read(r.constants.as_ref(), e);
    let c = r.mechanism.spatial(e, "/mechanism")?;
    for (field, given) in
        [("track", r.track.is_some()), ("actuators", r.actuators.is_some()), ("balance", r.balance.is_some())]
    {
        if given {
            e.say(&format!("/{field}"), Msg::new("kinetostatics-not-spatial"));
        }
    }
    let served = [OutputKind::Driving, OutputKind::Reactions, OutputKind::Kinematics, OutputKind::Reduced];
    let outputs = r.outputs.clone().unwrap_or_else(|| served.to_vec());
    for (k, _) in outputs.iter().enumerate().filter(|(_, o)| !served.contains(o)) {
        e.say(&format!("/outputs/{k}"), Msg::new("kinetostatics-not-spatial"));
    }
    let (list, many) = match &r.input {
        Inputs::One(i) => (vec![(**i).clone()], false),
        Inputs::Many(v) => (v.clone(), true),
    };
    let (chosen, positions, linear) = inputs::spatial(e, &c.mechanism, &list, many);
    let period = if linear.first().copied().unwrap_or(false) { 1.0 } else { 2.0 * PI };
    let loads =
        spatial_loads(e, r.loads.as_deref().unwrap_or_default(), (&r.mechanism, &c), period, "/loads", &["phi"]);
    let reference = chosen.iter().map(|d| d.reference).collect();
    let mechanism = Mechanism { inputs: chosen.into_iter().map(|d| d.input).collect(), ..c.mechanism };
    Some(Problem { mechanism, body_names: c.body_names, loads, positions, reference, linear, outputs })
}

/// One step as the result says it.
fn step(p: &Problem, x: &[[f64; 3]], now: &Motion, actions: &Actions) -> StepDto {
    let m = &p.mechanism;
    let wants = |o: OutputKind| p.outputs.contains(&o);
    let reactions = actions.reactions.iter().map(|r| Reaction3::new(r, m, &p.body_names)).collect();
    let kinematics = (1..=m.n()).map(|b| BodyMotion3::new(&p.body_names[b], b, &now.pose, &now.v, &now.a)).collect();
    let rate = x[0][1];
    let reduced = (wants(OutputKind::Reduced) && x.len() == 1 && rate != 0.0)
        .then(|| 2.0 * kinetic(m, &now.pose, &now.v) / (rate * rate));
    StepDto {
        input: Scalars::of(&x.iter().map(|v| v[0]).collect::<Vec<_>>()),
        driving: wants(OutputKind::Driving).then(|| Scalars::of(&actions.efforts)),
        reactions: wants(OutputKind::Reactions).then_some(StepReactions::Spatial(reactions)),
        reduced_inertia: reduced,
        reduced_torque: None,
        energy_contribution: None,
        jacobian_condition: now.condition,
        scaled_condition: now.condition,
        singular: false,
        kinematics: wants(OutputKind::Kinematics).then_some(Kinematics::Spatial(kinematics)),
        energy: None,
        points: None,
        contacts: None,
        shaking: None,
    }
}

/// The whole result: the inputs, the counts, the steps and their summary.
fn result(
    p: &Problem,
    steps: Vec<StepDto>,
    found: &crate::engine::spatial::Mobility,
    (virtual_power, residual): (f64, f64),
    iterations: usize,
) -> KinetostaticsResult {
    let m = &p.mechanism;
    let mut notes = Notes::default();
    if found.redundant_constraints > 0 {
        let joints: Vec<&str> = found.indeterminate_joints.iter().map(|&j| m.joints[j].name.as_str()).collect();
        notes.warn(
            Msg::new("warning-redundant-constraints-spatial")
                .count("count", found.redundant_constraints)
                .arg("joints", joints.join(", ")),
        );
    }
    let inputs = m
        .inputs
        .iter()
        .zip(&p.linear)
        .map(|(i, linear)| InputInfo {
            joint: Some(m.joints[i.joint].name.clone()),
            point: None,
            body: None,
            actuator: Some(m.joints[i.joint].name.clone()),
            coordinate_unit: if *linear { "m" } else { "rad" }.into(),
            driving_unit: if *linear { "N" } else { "N*m" }.into(),
        })
        .collect();
    let efforts: Vec<Vec<f64>> =
        (0..m.inputs.len()).map(|k| steps.iter().filter_map(|s| driving(s, k)).collect()).collect();
    let summary = |f: fn(&[f64]) -> f64| {
        p.outputs.contains(&OutputKind::Driving).then(|| Scalars::of(&efforts.iter().map(|v| f(v)).collect::<Vec<_>>()))
    };
    let conditions = steps.iter().map(|s| s.jacobian_condition).fold(0.0, f64::max);
    let mut max_reaction: BTreeMap<String, Option<f64>> = BTreeMap::new();
    if p.outputs.contains(&OutputKind::Reactions) {
        for s in &steps {
            if let Some(StepReactions::Spatial(list)) = &s.reactions {
                for r in list {
                    let entry = max_reaction.entry(r.joint.clone()).or_insert(Some(0.0));
                    *entry = entry.filter(|_| r.determinate).map(|x| x.max(r.magnitude));
                }
            }
        }
    }
    let g = found.kutzbach;
    KinetostaticsResult {
        inputs,
        dof: found.dof,
        grubler: GrublerDto { mobility: g.mobility, equations: g.equations, unknowns: g.unknowns },
        redundant_constraints: found.redundant_constraints,
        steps,
        summary: SummaryDto {
            max_abs_driving: summary(|v| v.iter().fold(0.0, |a, x| a.max(x.abs()))),
            mean_driving: summary(|v| v.iter().sum::<f64>() / v.len().max(1) as f64),
            rms_driving: summary(|v| (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt()),
            max_reaction,
            virtual_power_residual: Some(virtual_power),
            singular: false,
            singular_inputs: Vec::new(),
            near_singular_inputs: Vec::new(),
            max_jacobian_condition: conditions,
            max_scaled_condition: conditions,
            max_shaking_force: None,
            max_shaking_moment: None,
            max_shaking_force_balanced: None,
        },
        accuracy: KinetostaticsAccuracy {
            virtual_power_residual: Some(virtual_power),
            max_constraint_residual: residual,
            max_newton_iterations: iterations,
            max_friction_iterations: 0,
            method: notes.say("/accuracy/method", Msg::new("accuracy-kinetostatics-spatial")),
        },
        notes,
        assembled_points: None,
        counterweights: None,
    }
}

/// Input k's effort at a step.
fn driving(s: &StepDto, k: usize) -> Option<f64> {
    match s.driving.as_ref()? {
        Scalars::One(v) => Some(*v),
        Scalars::Many(v) => v.get(k).copied(),
    }
}
