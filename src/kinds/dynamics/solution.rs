//! A mechanism's worked solution at one sample of its motion: the bodies
//! placed again along the run's samples (the same branch) with the run's
//! velocities and accelerations, the reactions the run stored, the loads at
//! the sample's time, and no driving effort (the inputs are free): each
//! body's three sums are then d'Alembert's check of the run itself.

use super::DynamicsRequest;
use super::request::Problem;
use crate::engine::kinetostatics::{Outputs, Reaction, free_bodies, solve_each};
use crate::engine::model::Mechanism;
use crate::kind::limits::Limits;
use crate::kind::plots::{self, beyond_steps, singular_step};
use crate::kind::problem::ApiError;
use crate::kind::solution::Solution;
use crate::kind::validated;
use crate::kinds::mechanism::solution::written;
use serde_json::Value;

/// Sample `step` of a stored dynamics job of a mechanism; a run in reduced
/// form has no bodies (404).
pub fn solution(job: &plots::Job, step: usize, limits: &Limits) -> Result<Solution, ApiError> {
    let request: DynamicsRequest = serde_json::from_value(job.request.clone())
        .map_err(|e| ApiError::Internal(format!("stored dynamics request: {e}")))?;
    let problem = validated(vec![], request.to_problem(limits))?;
    let samples = job.result["machine"]["samples"].as_array().map(Vec::as_slice).unwrap_or_default();
    if let Some(spatial) = super::space_solution::spatial(&problem) {
        return super::space_solution::solution(spatial, samples, step);
    }
    let Problem::Machine(p, report) = problem else {
        return Err(ApiError::NoSolution { id: String::new(), kind: "dynamics".into() });
    };
    if step >= samples.len() {
        return Err(beyond_steps(step, samples.len()));
    }
    let state = |s: &Value| -> Vec<[f64; 3]> {
        let inputs = s["inputs"].as_array().map(Vec::as_slice).unwrap_or_default();
        inputs.iter().map(|i| ["angle", "speed", "acceleration"].map(|k| i[k].as_f64().unwrap_or(f64::NAN))).collect()
    };
    let positions: Vec<Vec<[f64; 3]>> = samples[..=step].iter().map(state).collect();
    let kinematics = Outputs { driving: false, reactions: false, reduced: false, kinematics: true, condition: false };
    let (mut k, mut found) = (0, None);
    solve_each(&p.mechanism, &p.loads, &positions, kinematics, &limits.deadline(), |s| {
        if k == step {
            found = Some(s.clone());
        }
        k += 1;
        Ok(())
    })
    .map_err(|e| ApiError::Internal(format!("dynamics sample {step} placed again: {e}")))?;
    let mut placed = found.ok_or_else(|| ApiError::Internal(format!("sample {step} was not placed again")))?;
    placed.reactions = stored_reactions(&p.mechanism, &report.body_names, &samples[step]["reactions"]);
    placed.driving = vec![0.0; p.mechanism.drivers.len()];
    let time = samples[step]["t"].as_f64().unwrap_or(0.0);
    let Some(bodies) = free_bodies(&p.mechanism, &p.loads, &placed, (&positions[step], time)) else {
        return Err(singular_step(step));
    };
    let input: Vec<f64> = positions[step].iter().map(|i| i[0]).collect();
    Ok(written(&p.mechanism, &report.body_names, &p.loads, (step, &input), &bodies, true))
}

/// The reactions a sample stored (`on` by `by`, by name), as the engine's;
/// the undetermined ones (null) left out.
fn stored_reactions(m: &Mechanism, bodies: &[String], stored: &Value) -> Vec<Reaction> {
    let body = |v: &Value| bodies.iter().position(|b| Some(b.as_str()) == v.as_str());
    let stored = stored.as_array().map(Vec::as_slice).unwrap_or_default();
    stored
        .iter()
        .filter_map(|r| {
            let joint = m.joints.iter().position(|j| Some(j.name.as_str()) == r["joint"].as_str())?;
            let ends = r["ends"].as_array().and_then(|e| Some([e.first()?.as_f64()?, e.get(1)?.as_f64()?]));
            Some(Reaction {
                joint,
                on: body(&r["on"])?,
                by: body(&r["by"])?,
                fx: r["fx"].as_f64()?,
                fy: r["fy"].as_f64()?,
                moment: r["moment"].as_f64()?,
                ends,
                determinate: r["determinate"].as_bool().unwrap_or(true),
            })
        })
        .collect()
}
