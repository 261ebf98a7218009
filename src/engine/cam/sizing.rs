//! A turn of a cam sampled, and its smallest base radius searched: the
//! lift evaluated once at the samples' angles, the cam's geometry at each,
//! the job's budget read as they go.

use super::design::{Cam, CamError, Lift, Sample};
use crate::engine::{Deadline, EngineError, Progress};
use std::f64::consts::TAU;

/// The lift and its derivatives at n angles 2πk/n, the `deadline` read
/// every 256 angles (a lift Function is what a turn's samples cost).
pub fn lifts(lift: Lift, n: usize, deadline: &Deadline) -> Result<Vec<(f64, [f64; 4])>, EngineError> {
    let mut out = Vec::with_capacity(n);
    for k in 0..n {
        if k % 256 == 0 {
            deadline.check(|| Progress::CamLift { angle: k, of: n })?;
        }
        let t = TAU * k as f64 / n as f64;
        out.push((t, lift(t)));
    }
    Ok(out)
}

/// The samples of a turn at the angles of `lifts` ([`lifts`]).
pub fn turn(cam: &Cam, lifts: &[(f64, [f64; 4])]) -> Result<Vec<Sample>, CamError> {
    lifts.iter().map(|&(t, l)| cam.at(t, l)).collect()
}

/// The smallest base radius the follower can start from that meets `ok`
/// (a test that holds for every base radius above the smallest that meets
/// it, such as a largest pressure angle or a smallest radius of
/// curvature): the first of 64 radii over the range [`Cam::base_range`]
/// that meets it, then bisected to 1e-9 of the range; None where none does.
/// The `deadline` is read before each radius is tried.
pub fn smallest_base(
    cam: Cam,
    lifts: &[(f64, [f64; 4])],
    ok: impl Fn(&[Sample]) -> bool,
    deadline: &Deadline,
) -> Result<Option<f64>, EngineError> {
    // The lift does not depend on the base radius: evaluated once, by the caller.
    let scale = lifts.iter().map(|(_, l)| l[0].abs()).fold(1e-6, f64::max);
    let tried = std::cell::Cell::new(0);
    let meets = |base: f64| -> Result<bool, EngineError> {
        deadline.check(|| Progress::CamSize { tried: tried.get() })?;
        tried.set(tried.get() + 1);
        let cam = Cam { base, ..cam };
        Ok(turn(&cam, lifts).is_ok_and(|s| ok(&s)))
    };
    let (lo, hi) = cam.base_range(scale);
    let grid = |k: usize| lo + (hi - lo) * k as f64 / 64.0;
    let mut first = None;
    for k in 1..64 {
        if meets(grid(k))? {
            first = Some(k);
            break;
        }
    }
    let Some(first) = first else { return Ok(None) };
    let (mut lo, mut hi) = (grid(first - 1), grid(first));
    let tolerance = 1e-9 * (hi - lo) * 64.0;
    while hi - lo > tolerance {
        let mid = 0.5 * (lo + hi);
        if meets(mid)? { hi = mid } else { lo = mid }
    }
    Ok(Some(hi))
}
