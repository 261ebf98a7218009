//! The global error of a run, estimated by the same run at a tolerance a
//! hundred times tighter: the step-size control bounds each step's local
//! error, not how those errors grow along the motion (a double pendulum's
//! angle over 20 s is 1e5 times off its summed local estimate), while the
//! difference e₁ − e₂ of two runs whose errors scale as tol^(p/(p+1)) is
//! e₁ within a few percent (e₂ ≈ e₁/40 at p = 5, /60 at p = 8). The
//! estimate reported is [`SAFETY`] times that difference, or the summed
//! local estimate where larger.
//!
//! Made only where it fits: the first run took at most [`SHARE`] of the
//! budget (the tighter run costs 1.8 to 2.5 times as much), the tolerance can
//! be tightened (not below [`FLOOR`]), and the run ends at a time (a run to
//! an angle ends at another instant each time). Otherwise the local
//! estimate stands, and the result says why.

use crate::engine::Deadline;
use crate::engine::dynamics::DynamicsError;
use crate::engine::dynamics::{DynamicsSolution, End};
use std::time::Duration;

/// The tightened tolerance's ratio, its floor (double precision's useful
/// limit for these pairs) and the safety factor on the difference.
const TIGHTER: f64 = 100.0;
const FLOOR: f64 = 1e-13;
const SAFETY: f64 = 1.5;
/// The largest share of the budget the first run may have taken.
const SHARE: f64 = 0.25;

/// The estimate: Ok(max |Δ input coordinate| over the samples), or why none was made.
pub type Global = Result<f64, &'static str>;

/// The tighter run's budget: four times what the first took (it costs 1.8
/// to 2.5 times as much), within what is left of the job's.
pub fn deadline(job: &Deadline) -> Deadline {
    let left = (job.seconds() - job.elapsed()).max(0.0);
    Deadline::after(Duration::from_secs_f64(left.min(4.0 * job.elapsed() + 0.01)))
}

/// The tighter run's tolerance for `tolerance`, if it can be tightened.
fn tighter(tolerance: f64) -> Option<f64> {
    let t = (tolerance / TIGHTER).max(FLOOR);
    (t <= tolerance / 10.0).then_some(t)
}

/// The global error of `first` (a run at `tolerance` to `end`, after
/// `elapsed` of a budget of `budget` seconds), by `again` at the tighter
/// tolerance.
pub fn estimate(
    first: &DynamicsSolution,
    (tolerance, end, elapsed, budget): (f64, End, f64, f64),
    again: impl FnOnce(f64) -> Result<DynamicsSolution, DynamicsError>,
) -> Global {
    if matches!(end, End::UntilAngle { .. }) {
        return Err("accuracy-global-to-angle");
    }
    let Some(tight) = tighter(tolerance) else { return Err("accuracy-global-floor") };
    if elapsed > SHARE * budget {
        return Err("accuracy-global-budget");
    }
    let second = again(tight).map_err(|_| "accuracy-global-failed")?;
    let (a, b) = (&first.samples, &second.samples);
    let same = a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.t == y.t);
    if !same || first.stopped.is_some() || second.stopped.is_some() {
        return Err("accuracy-global-failed");
    }
    Ok(a.iter().zip(b).map(|(x, y)| (x.angle - y.angle).abs()).fold(0.0, f64::max))
}

/// The error bound reported: the summed `local` estimate, or [`SAFETY`]
/// times the `global` difference where made and larger.
pub fn bound(local: f64, global: &Global) -> f64 {
    global.as_ref().map_or(local, |d| local.max(SAFETY * d))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tolerance is tightened a hundredfold down to the floor, and not
    /// at all where that would gain less than a factor ten.
    #[test]
    fn the_tolerance_is_tightened_to_its_floor() {
        assert_eq!(tighter(1e-6), Some(1e-8));
        assert_eq!(tighter(5e-12), Some(FLOOR));
        assert_eq!(tighter(5e-13), None);
        assert_eq!(bound(1e-9, &Ok(1e-3)), 1.5e-3);
        assert_eq!(bound(1e-2, &Ok(1e-3)), 1e-2);
        assert_eq!(bound(1e-9, &Err("accuracy-global-budget")), 1e-9);
    }
}
