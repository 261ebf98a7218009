//! A kinetostatics job's worked solution at one step: the stored request
//! solved again up to that step (the same sweep, so the same branch and the
//! same numbers as the job's), its free bodies (`engine::kinetostatics::
//! free_bodies`) written by [`crate::kinds::mechanism::solution`].

use super::request::{KinetostaticsRequest, Problem};
use crate::engine::kinetostatics::{Outputs, Step, free_bodies, solve_each};
use crate::kind::limits::Limits;
use crate::kind::plots::{self, beyond_steps};
use crate::kind::problem::ApiError;
use crate::kind::solution::Solution;
use crate::kind::validated;
use crate::kinds::mechanism::solution::written;

/// Step `step` of a stored planar kinetostatics job, solved again, with its problem.
fn solved_step(request: &KinetostaticsRequest, step: usize, limits: &Limits) -> Result<(Problem, Step), ApiError> {
    let mut problem = validated(vec![], request.to_problem(limits))?;
    let count = problem.positions.len();
    if step >= count {
        return Err(beyond_steps(step, count));
    }
    problem.outputs = Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false };
    let (mut k, mut found) = (0, None);
    solve_each(
        &problem.mechanism,
        &problem.loads,
        &problem.positions[..=step],
        problem.outputs,
        &limits.deadline(),
        |s| {
            if k == step {
                found = Some(s.clone());
            }
            k += 1;
            Ok(())
        },
    )
    .map_err(|e| problem.written.explain(e))?;
    let found = found.ok_or_else(|| ApiError::Internal(format!("step {step} was not solved again")))?;
    Ok((problem, found))
}

/// The worked solution of step `step` of a stored kinetostatics job (a
/// spatial one's by `space::solution`); a singular step has none (422 at `?step=`).
pub fn solution(job: &plots::Job, step: usize, limits: &Limits) -> Result<Solution, ApiError> {
    let request: KinetostaticsRequest = serde_json::from_value(job.request.clone())
        .map_err(|e| ApiError::Internal(format!("stored kinetostatics request: {e}")))?;
    if request.mechanism.is_spatial() {
        return super::space::solution(&request, step, limits);
    }
    let (problem, solved) = solved_step(&request, step, limits)?;
    let inputs = &problem.positions[step];
    let Some(bodies) = free_bodies(&problem.mechanism, &problem.loads, &solved, (inputs, 0.0)) else {
        return Err(crate::kind::plots::singular_step(step));
    };
    Ok(written(&problem.mechanism, &problem.body_names, &problem.loads, (step, &solved.input), &bodies, false))
}
