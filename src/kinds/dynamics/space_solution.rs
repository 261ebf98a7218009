//! A spatial run's worked solution at one sample: the bodies where the run
//! stored them (G, R, v, ω, a, α), the loads at the sample's φ, ω and t,
//! the reactions of that motion (Newton–Euler again, as the run's own), and
//! no driving effort (the inputs are free): each body's six sums are then
//! d'Alembert's check of the run itself.

use super::request::Problem;
use super::space::SpatialReport;
use crate::engine::spatial::dynamics::SpatialProblem;
use crate::engine::spatial::free_body::free_bodies;
use crate::engine::spatial::{Mechanism, Motion, Pose, evaluate, inverse_dynamics};
use crate::kind::plots::beyond_steps;
use crate::kind::problem::ApiError;
use crate::kind::solution::Solution;
use crate::kinds::mechanism::solution3::written;
use nalgebra::{DVector, Matrix3, Rotation3, UnitQuaternion, Vector3};
use serde_json::Value;

/// Sample `step` of a stored spatial run (`samples`, the result's).
pub(super) fn solution(
    (p, report): (&SpatialProblem, &SpatialReport),
    samples: &[Value],
    step: usize,
) -> Result<Solution, ApiError> {
    let sample = samples.get(step).ok_or_else(|| beyond_steps(step, samples.len()))?;
    let free = Mechanism { inputs: Vec::new(), ..p.mechanism.clone() };
    let now = stored_motion(&free, &report.body_names, sample)
        .ok_or_else(|| ApiError::Internal(format!("dynamics sample {step}: its bodies' motion is not stored")))?;
    let number = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    let first = &sample["inputs"][0];
    let (phi, omega, t) = (number(&first["angle"]), number(&first["speed"]), number(&sample["t"]));
    let loads: Vec<_> = p.loads.iter().map(|l| l.at(phi.rem_euclid(p.period), [omega, t])).collect();
    let actions = inverse_dynamics(&free, &loads, &now);
    let bodies = free_bodies(&free, &loads, &now, &actions);
    let input: Vec<f64> = sample["inputs"].as_array().into_iter().flatten().map(|i| number(&i["angle"])).collect();
    Ok(written(&p.mechanism, &report.body_names, &loads, (step, &input), &bodies, true))
}

/// The motion a sample stored, its rows evaluated there; None where a body's is missing.
fn stored_motion(m: &Mechanism, names: &[String], sample: &Value) -> Option<Motion> {
    let n = m.n();
    let (mut pose, mut v, mut a) = (Pose::drawn(m), DVector::zeros(6 * n), DVector::zeros(6 * n));
    let stored = sample["bodies"].as_array()?;
    for (b, name) in names.iter().enumerate().take(n + 1).skip(1) {
        let s = stored.iter().find(|s| s["body"].as_str() == Some(name.as_str()))?;
        let vector = |key: &str| vector_at(&s[key]);
        let rows: Vec<Vector3<f64>> = (0..3).map(|i| vector_at(&s["rotation"][i])).collect::<Option<_>>()?;
        let rotation = Matrix3::from_rows(&[rows[0].transpose(), rows[1].transpose(), rows[2].transpose()]);
        pose.r[b - 1] = vector("position")?;
        pose.p[b - 1] = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix(&rotation));
        for (k, key) in ["velocity", "angular_velocity"].iter().enumerate() {
            v.fixed_rows_mut::<3>(6 * b - 6 + 3 * k).copy_from(&vector(key)?);
        }
        for (k, key) in ["acceleration", "angular_acceleration"].iter().enumerate() {
            a.fixed_rows_mut::<3>(6 * b - 6 + 3 * k).copy_from(&vector(key)?);
        }
    }
    let rows = evaluate(m, &pose, Some(&v), &[]);
    Some(Motion { pose, v, a, rows, condition: f64::NAN })
}

fn vector_at(v: &Value) -> Option<Vector3<f64>> {
    let list = v.as_array()?;
    Some(Vector3::new(list.first()?.as_f64()?, list.get(1)?.as_f64()?, list.get(2)?.as_f64()?))
}

/// Whether the request is a spatial run's, with its problem.
pub(super) fn spatial(problem: &Problem) -> Option<(&SpatialProblem, &SpatialReport)> {
    match problem {
        Problem::Spatial(p, r) => Some((p, r)),
        _ => None,
    }
}
