//! A turn of a cam sampled, and its smallest base radius searched: the
//! lift evaluated once at the samples' angles, the cam's geometry at each,
//! the job's budget read as they go.

use super::design::{Cam, CamError, Guide, Lift, Sample};
use super::least::Least;
use crate::engine::numeric::minimum::brent_min;
use crate::engine::numeric::roots::brent;
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

/// The smallest base radius the follower can start from whose `excess`
/// is at most 0 — a test of the cam with that radius (whose turn at the
/// samples can be made), continuous and decreasing in the radius, such as
/// its largest pressure angle less the largest allowed. First the
/// `closed` form's radius for the least radius the follower can start
/// from ([`least`](super::least)), kept where it passes the test; where it
/// fails, or where there is no closed form, the first of 64 radii from it
/// to the top of the range [`Cam::base_range`] that meets the test
/// ([`first_meeting`]) — where none does, for a translating follower the
/// first of the radii doubling above the range that does ([`beyond`]),
/// else the radius of the least excess ([`least_measure`]) if that meets
/// it — then the root of the excess in the cell below it by Brent's method
/// to 1e-12 of the radius (the radius returned meets it); None where none
/// does.
/// The `deadline` is read before each radius is tried.
pub fn smallest_base(
    cam: Cam,
    lifts: &[(f64, [f64; 4])],
    closed: impl Fn(f64) -> Least,
    excess: impl Fn(&Cam) -> f64,
    deadline: &Deadline,
) -> Result<Option<f64>, EngineError> {
    // The lift does not depend on the base radius: evaluated once, by the caller.
    let scale = lifts.iter().map(|(_, l)| l[0].abs()).fold(1e-6, f64::max);
    let tried = std::cell::Cell::new(0);
    let over = |base: f64| -> Result<f64, EngineError> {
        deadline.check(|| Progress::CamSize { tried: tried.get() })?;
        tried.set(tried.get() + 1);
        let cam = Cam { base, ..cam };
        Ok(if turn(&cam, lifts).is_ok() { excess(&cam) } else { f64::INFINITY })
    };
    let (lo, hi) = cam.base_range(scale);
    let lo = match closed(lo) {
        Least::Unmet => return Ok(None),
        Least::Base(base) if over(base)? <= 0.0 => return Ok(Some(base)),
        Least::Base(base) | Least::Search(base) => base.max(lo),
    };
    let grid = |k: usize| lo + (hi - lo) * k as f64 / GRID as f64;
    let first = match first_meeting(&|k| over(grid(k)))? {
        Some(meets) => Some((grid(meets - 1), grid(meets))),
        None => beyond(&cam, &over, (grid(GRID - 1), hi))?,
    };
    let (mut a, b) = match first {
        Some(cell) => cell,
        // The radii that meet it may be a stretch narrower than the grid's cell (an oscillating
        // follower's pressure angle near its least): where the least excess meets it, between
        // there and the grid's radius below it (which does not, or is the range's least).
        None => match least_measure(cam, lifts, &excess, deadline)? {
            Some([base, least]) if least <= 0.0 && base > lo => {
                let below = ((base - lo) / (hi - lo) * GRID as f64).floor() as usize;
                (grid(below.min(GRID - 1)), base)
            }
            _ => return Ok(None),
        },
    };
    // Brent needs a finite excess at both ends: bisect a turn that cannot be made out of the cell's lower end.
    let mut at_a = over(a)?;
    if at_a <= 0.0 {
        // The range's least radius (untried by the grid) meets it already.
        return Ok(Some(a));
    }
    while !at_a.is_finite() && b - a > 1e-12 * b {
        let mid = 0.5 * (a + b);
        match over(mid)? {
            x if x.is_finite() && x > 0.0 => (a, at_a) = (mid, x),
            x if x.is_finite() => return refine(&over, mid, a, deadline).map(Some),
            _ => a = mid,
        }
    }
    if !at_a.is_finite() {
        return Ok(Some(b));
    }
    refine(&over, b, a, deadline).map(Some)
}

/// Most doublings of the range's top tried by [`beyond`].
const DOUBLINGS: usize = 40;

/// A translating follower's radii past the grid, its `top` and then
/// doubling: a radius of curvature asked far above the lift (a profile's
/// radius of curvature grows as R_b + s + s″ with the base radius), or a
/// program that never rises. The first that meets the test and the one
/// below it (which does not), or None (an oscillating follower's range is
/// its arm's reach).
fn beyond(
    cam: &Cam,
    over: &dyn Fn(f64) -> Result<f64, EngineError>,
    (mut below, mut top): (f64, f64),
) -> Result<Option<(f64, f64)>, EngineError> {
    if !matches!(cam.guide, Guide::Translating { .. }) {
        return Ok(None);
    }
    for _ in 0..=DOUBLINGS {
        if over(top)? <= 0.0 {
            return Ok(Some((below, top)));
        }
        (below, top) = (top, 2.0 * top);
    }
    Ok(None)
}

/// Where no radius meets a test: the radius of the range
/// [`Cam::base_range`] whose `measure` (such as the largest pressure angle)
/// is least, and that least, [radius, measure]: the range's radii 0..=64,
/// then Brent's method between the best one's neighbours to 1e-9 of the
/// range. None where no turn at any of them can be made. The `deadline`
/// is read before each radius.
pub fn least_measure(
    cam: Cam,
    lifts: &[(f64, [f64; 4])],
    measure: impl Fn(&Cam) -> f64,
    deadline: &Deadline,
) -> Result<Option<[f64; 2]>, EngineError> {
    let scale = lifts.iter().map(|(_, l)| l[0].abs()).fold(1e-6, f64::max);
    let (lo, hi) = cam.base_range(scale);
    let failed = std::cell::Cell::new(None);
    let at = |base: f64| {
        if let Err(e) = deadline.check(|| Progress::CamSize { tried: 0 }) {
            failed.set(Some(e));
            return f64::INFINITY;
        }
        let cam = Cam { base, ..cam };
        if turn(&cam, lifts).is_ok() { measure(&cam) } else { f64::INFINITY }
    };
    let grid = |k: usize| lo + (hi - lo) * k as f64 / GRID as f64;
    let values: Vec<f64> = (0..=GRID).map(|k| at(grid(k))).collect();
    let best = (0..=GRID).filter(|&k| values[k].is_finite()).min_by(|&a, &b| values[a].total_cmp(&values[b]));
    let found = best.map(|k| {
        let bracket = [grid(k.saturating_sub(1)), grid((k + 1).min(GRID))];
        let (base, value) = brent_min(at, bracket, grid(k), values[k], 1e-9 * (hi - lo).max(f64::MIN_POSITIVE));
        [base, value]
    });
    match failed.take() {
        Some(e) => Err(e),
        None => Ok(found),
    }
}

/// Radii the range is divided in, and every how many of them the search
/// looks first ([`first_meeting`]).
const GRID: usize = 64;
const COARSE: usize = 8;

/// The first of the grid's radii 1..[`GRID`] whose `excess` meets the test
/// (≤ 0), searched from below: an oscillating arm's reach may fail again
/// near the range's top. The excess decreases with the radius wherever the
/// cam can be made, so the radii that meet it are one stretch: every
/// [`COARSE`]th radius and the last first, then the radii below the first
/// of those that meets; where none does (a stretch narrower than the
/// coarse step), every radius in turn.
fn first_meeting(excess: &dyn Fn(usize) -> Result<f64, EngineError>) -> Result<Option<usize>, EngineError> {
    let coarse: Vec<usize> = (COARSE..GRID).step_by(COARSE).chain([GRID - 1]).collect();
    let mut top = None;
    for &k in &coarse {
        if excess(k)? <= 0.0 {
            top = Some(k);
            break;
        }
    }
    let below = match top {
        Some(k) => (k.saturating_sub(COARSE) + 1).max(1)..k,
        None => 1..GRID,
    };
    for k in below.filter(|k| !coarse.contains(k)) {
        if excess(k)? <= 0.0 {
            return Ok(Some(k));
        }
    }
    Ok(top)
}

/// The smallest radius that meets the test between `a` (fails) and `b`
/// (meets), to 1e-12 of it.
fn refine(
    over: &dyn Fn(f64) -> Result<f64, EngineError>,
    b: f64,
    a: f64,
    deadline: &Deadline,
) -> Result<f64, EngineError> {
    let tolerance = 1e-12 * b;
    let mut failed = None;
    let root = brent(
        |r| match over(r) {
            Ok(x) if x.is_finite() => x,
            Ok(_) => f64::MAX,
            Err(e) => {
                failed = Some(e);
                0.0
            }
        },
        a,
        b,
        tolerance,
    );
    if let Some(e) = failed {
        return Err(e);
    }
    deadline.check(|| Progress::CamSize { tried: 0 })?;
    // Brent's answer may sit a hair below the root: the radius returned meets the test.
    let mut r = root;
    for _ in 0..4 {
        if over(r)? <= 0.0 {
            return Ok(r);
        }
        r += tolerance;
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every stretch of meeting radii [from, to] in the grid: the first
    /// found is the linear search's (the first k in 1..64 within it), or
    /// none where none is; a stretch from 58 to the top costs 8 coarse
    /// radii, then 57 and 58 (10, not the linear 58).
    #[test]
    fn the_first_meeting_radius_is_the_linear_searchs() {
        for from in 1..GRID {
            for to in from..GRID {
                let calls = std::cell::Cell::new(0);
                let excess = |k: usize| {
                    calls.set(calls.get() + 1);
                    Ok(if (from..=to).contains(&k) { -1.0 } else { 1.0 })
                };
                assert_eq!(first_meeting(&excess).unwrap(), Some(from), "[{from}, {to}]");
                if (from, to) == (58, 63) {
                    assert_eq!(calls.get(), 10);
                }
            }
        }
        assert_eq!(first_meeting(&|_| Ok(1.0)).unwrap(), None);
        assert_eq!(first_meeting(&|_| Ok(f64::INFINITY)).unwrap(), None);
    }

    /// A test met only within 0.1 mm of 0.5 m, a stretch far narrower than
    /// the grid's 31 mm cell (the peer's roller, up to 100 times its 20 mm
    /// lift): the least radius that meets it, 0.4999 m to 1e-12 of it; a
    /// dip that never meets it, none.
    #[test]
    fn a_stretch_narrower_than_the_grid_s_cell_is_found() {
        let p = super::super::sample::rise_dwell_fall();
        let lifts = lifts(&|t| p.lift(t), 256, &Deadline::none()).unwrap();
        let cam = super::super::sample::roller();
        let search = |_: f64| Least::Search(0.0);
        let narrow = |depth: f64| move |c: &Cam| (c.base - 0.5).abs() - depth;
        let found = smallest_base(cam, &lifts, search, narrow(1e-4), &Deadline::none()).unwrap();
        assert!(found.is_some_and(|r| (r - 0.4999).abs() <= 1e-12 * 0.5), "{found:?}");
        assert_eq!(smallest_base(cam, &lifts, search, narrow(-1e-4), &Deadline::none()).unwrap(), None);
    }
}
