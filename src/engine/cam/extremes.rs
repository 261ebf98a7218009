//! A cam's extremes over the whole turn, not only at its samples: a scan
//! fine for every piece of the motion (each segment of a program, or each
//! piece of a lift Function, split into [`PER_PIECE`] parts, and at least
//! [`LEAST`] angles a turn), each local extreme of the scan then refined
//! between its neighbours by Brent's method ([`brent_min`]: parabolas, and
//! golden section where they fail) to √ε of the scan's step. A plateau's
//! inner angles (a dwell's, equal to both neighbours) are not refined: its
//! ends are.
//!
//! A 20 mm rise over 1° has its pressure angle's peak found at the peak,
//! however few samples the user asked for; the scan's density is what
//! bounds an extreme narrower than a piece's 1/64 (no textbook law has
//! one).

use super::design::{Cam, Follower, Lift, Sample};
use crate::engine::numeric::minimum::brent_min;
use std::f64::consts::TAU;

/// Parts a piece of the motion is scanned in.
pub const PER_PIECE: usize = 64;
/// Fewest angles a turn is scanned at.
pub const LEAST: usize = 1024;
/// How closely a stretch's end is found (rad).
pub const TOLERANCE: f64 = 1e-12;
/// How closely an extreme's angle is found, relative to the scan's step:
/// √ε, where a smooth extreme's value is flat to rounding (its value is
/// then within ε of the extreme's, relative to its change over the step).
const REFINED: f64 = 1.5e-8;
/// Local extremes of the scan refined: those within this share of the
/// scan's extreme (a lower one cannot overtake it by more).
const CONTENDERS: f64 = 0.5;

/// A value and the cam angle where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct At {
    pub value: f64,
    pub theta: f64,
}

/// The angles a turn is scanned at: each piece between consecutive
/// `breaks` (angles in [0, 2π), the pieces' starts) in [`PER_PIECE`]
/// parts, the whole at least [`LEAST`] angles, sorted, in [0, 2π).
pub fn scan(breaks: &[f64]) -> Vec<f64> {
    let pieces = starts(breaks).len();
    self::pieces(breaks, PER_PIECE.max(LEAST.div_ceil(pieces)))
}

/// The angles of each piece between consecutive `breaks` in `per` parts, sorted, in [0, 2π).
pub fn pieces(breaks: &[f64], per: usize) -> Vec<f64> {
    let starts = starts(breaks);
    let mut out = Vec::with_capacity(starts.len() * per);
    for (k, &a) in starts.iter().enumerate() {
        let b = starts.get(k + 1).copied().unwrap_or(TAU);
        out.extend((0..per).map(|j| a + (b - a) * j as f64 / per as f64));
    }
    out
}

/// The pieces' starts: `breaks` and 0 in [0, 2π), sorted, each once.
fn starts(breaks: &[f64]) -> Vec<f64> {
    let mut starts: Vec<f64> = breaks.iter().map(|b| b.rem_euclid(TAU)).chain([0.0]).collect();
    starts.sort_by(f64::total_cmp);
    starts.dedup_by(|a, b| (*a - *b).abs() <= 1e-12);
    starts
}

/// The largest of `f` over the turn (None where `f` has no value: skipped),
/// from the scan at `grid` ([`scan`]) refined at each contending local
/// maximum; None where `f` has no value anywhere.
pub fn largest(f: &dyn Fn(f64) -> Option<f64>, grid: &[f64]) -> Option<At> {
    let values: Vec<f64> = grid.iter().map(|&t| f(t).unwrap_or(f64::NEG_INFINITY)).collect();
    refined(f, grid, &values)
}

/// [`largest`] from the scan's `values` at `grid` already computed (−∞ where `f` has none).
fn refined(f: &dyn Fn(f64) -> Option<f64>, grid: &[f64], values: &[f64]) -> Option<At> {
    let n = grid.len();
    let top = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if top == f64::NEG_INFINITY {
        return None;
    }
    let floor = if top > 0.0 { top * CONTENDERS } else { top / CONTENDERS };
    let angle = |k: isize| grid[k.rem_euclid(n as isize) as usize] + TAU * k.div_euclid(n as isize) as f64;
    // The scan's largest, where no local maximum is refined (a plateau all round).
    let first = values.iter().position(|&v| v == top).unwrap_or(0);
    let mut best = At { value: top, theta: grid[first] };
    for k in 0..n {
        let (before, after) = (values[(k + n - 1) % n], values[(k + 1) % n]);
        let inner = values[k] == before && values[k] == after;
        if values[k] < floor || values[k] < before || values[k] < after || inner {
            continue;
        }
        let (a, b) = (angle(k as isize - 1), angle(k as isize + 1));
        let at = peak(f, a, b, At { value: values[k], theta: grid[k] });
        if at.value > best.value {
            best = at;
        }
    }
    Some(At { value: best.value, theta: best.theta.rem_euclid(TAU) })
}

/// The largest of `f` on [a, b] by Brent's method ([`brent_min`]) to
/// [`REFINED`] of the bracket, from the scan's `best` at its middle (kept
/// if nothing better is found).
fn peak(f: &dyn Fn(f64) -> Option<f64>, a: f64, b: f64, best: At) -> At {
    let tol = (REFINED * (b - a)).max(4.0 * f64::EPSILON * best.theta.abs());
    let (theta, least) = brent_min(|t| f(t).map_or(f64::INFINITY, |v| -v), [a, b], best.theta, -best.value, tol);
    if -least > best.value { At { value: -least, theta } } else { best }
}

/// The stretches of the turn where `f` < 0, as [from, to] angles, their
/// ends found by bisection between the scan's angles at `grid` to
/// [`TOLERANCE`]; a stretch across 2π ends past it.
pub fn below_zero(f: &dyn Fn(f64) -> f64, grid: &[f64]) -> Vec<[f64; 2]> {
    let f = |t: f64| f(t.rem_euclid(TAU));
    let (grid, values) = &with_dips(&f, grid);
    let n = grid.len();
    let negative: Vec<bool> = values.iter().map(|&v| v < 0.0).collect();
    if negative.iter().all(|&b| b) {
        return vec![[0.0, TAU]];
    }
    let next = |k: usize| if k + 1 < n { grid[k + 1] } else { TAU + grid[0] };
    let edge = |a: f64, b: f64| {
        let (mut a, mut b) = (a, b);
        let inside = f(a) < 0.0;
        while b - a > TOLERANCE {
            let m = 0.5 * (a + b);
            if (f(m) < 0.0) == inside { a = m } else { b = m }
        }
        0.5 * (a + b)
    };
    // Start from an angle outside every stretch, so that each is whole.
    let first = negative.iter().position(|&b| !b).unwrap_or(0);
    let mut out: Vec<[f64; 2]> = Vec::new();
    for j in 0..n {
        let k = (first + j) % n;
        let (now, then) = (negative[k], negative[(k + 1) % n]);
        let lap = if k < first { TAU } else { 0.0 };
        match (now, then) {
            (false, true) => out.push([edge(grid[k], next(k)) + lap, f64::NAN]),
            (true, false) => {
                if let Some(last) = out.last_mut() {
                    last[1] = edge(grid[k], next(k)) + lap;
                }
            }
            _ => {}
        }
    }
    out.into_iter().map(|[a, b]| [a.rem_euclid(TAU), if a.rem_euclid(TAU) < a { b - TAU } else { b }]).collect()
}

/// `grid` with the angle of each dip of `f` below zero between its angles
/// (every local minimum of the scan at or above zero refined by Brent's
/// method, kept where it is below), sorted, and `f` at each.
fn with_dips(f: &dyn Fn(f64) -> f64, grid: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = grid.len();
    let values: Vec<f64> = grid.iter().map(|&t| f(t)).collect();
    let angle = |k: isize| grid[k.rem_euclid(n as isize) as usize] + TAU * k.div_euclid(n as isize) as f64;
    let mut out: Vec<(f64, f64)> = grid.iter().copied().zip(values.iter().copied()).collect();
    for k in 0..n {
        let (before, after) = (values[(k + n - 1) % n], values[(k + 1) % n]);
        let inner = values[k] == before && values[k] == after;
        if values[k] < 0.0 || values[k] > before || values[k] > after || inner {
            continue;
        }
        let lowest = peak(
            &|t| Some(-f(t)),
            angle(k as isize - 1),
            angle(k as isize + 1),
            At { value: -values[k], theta: grid[k] },
        );
        if lowest.value > 0.0 {
            out.push((lowest.theta.rem_euclid(TAU), -lowest.value));
        }
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out.into_iter().unzip()
}

/// The turn's extremes of a cam's geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extremes {
    /// The largest |φ|.
    pub max_pressure_angle: At,
    /// The profile's smallest radius of curvature where it is convex (a
    /// roller's: where its pitch curve is); None where it nowhere is.
    pub min_curvature_radius: Option<At>,
    /// A flat face's contact, least and furthest from its foot (m).
    pub face: Option<(f64, f64)>,
}

impl Extremes {
    /// The profile folds: a convex radius of curvature below zero (a roller
    /// larger than the pitch curve's, a flat face on a concave stretch).
    pub fn undercut(&self) -> bool {
        self.min_curvature_radius.is_some_and(|r| r.value < 0.0)
    }
}

/// Where the profile is convex (a flat face's must be everywhere; a
/// roller's where its pitch curve is).
pub fn convex(follower: Follower, x: &Sample) -> bool {
    follower == Follower::Flat || x.pitch_curvature_radius > 0.0
}

/// The extremes of `cam` with `lift` over the turn scanned at `grid`.
pub fn of(cam: &Cam, lift: Lift, grid: &[f64]) -> Extremes {
    let at = |t: f64| cam.at(t, lift(t)).ok();
    // The scan's samples once; each quantity reads them, and refines on its own.
    let scanned: Vec<Option<Sample>> = grid.iter().map(|&t| at(t)).collect();
    let extreme = |q: &dyn Fn(&Sample) -> Option<f64>| {
        let values: Vec<f64> = scanned.iter().map(|x| x.as_ref().and_then(q).unwrap_or(f64::NEG_INFINITY)).collect();
        refined(&|t| at(t).as_ref().and_then(q), grid, &values)
    };
    let pressure = |x: &Sample| Some(x.pressure_angle.abs());
    let concave = |x: &Sample| convex(cam.follower, x).then_some(-x.curvature_radius);
    let min_rho = extreme(&concave).map(|a| At { value: -a.value, ..a });
    let face = (cam.follower == Follower::Flat).then(|| {
        let far = extreme(&|x| Some(x.face_offset));
        let near = extreme(&|x| Some(-x.face_offset));
        (near.map_or(0.0, |a| -a.value), far.map_or(0.0, |a| a.value))
    });
    Extremes {
        max_pressure_angle: extreme(&pressure).unwrap_or(At { value: 0.0, theta: 0.0 }),
        min_curvature_radius: min_rho,
        face,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::cam::design::Guide;
    use crate::engine::cam::{Law, Program, Segment};
    use std::f64::consts::PI;

    /// A rise of `h` over `beta` by `law` from 0, then a dwell, a return
    /// over the same span and a dwell to the end of the turn.
    fn program(law: Law, h: f64, beta: f64) -> Program {
        let seg = |law, start, span, from, to| Segment { law, start, span, from, to };
        let rest = (TAU - 2.0 * beta) / 2.0;
        Program::new(vec![
            seg(law, 0.0, beta, 0.0, h),
            seg(Law::Dwell, beta, rest, h, h),
            seg(law, beta + rest, beta, h, 0.0),
            seg(Law::Dwell, 2.0 * beta + rest, rest, 0.0, 0.0),
        ])
        .unwrap()
    }

    fn lift(p: &Program) -> impl Fn(f64) -> [f64; 4] + '_ {
        |t| {
            let s = p.eval(t);
            [s[0], s[1], s[2], s[3]]
        }
    }

    /// A 20 mm cycloidal rise over 1° under a knife edge (R_b = 40 mm, no
    /// offset): tan φ = s′/(R_b + s), its largest found to 1e-9 rad
    /// against a scan of the rise alone at 10⁶ angles (whose step, 1.7e-8
    /// rad, bounds its own error to about 1e-12 of φ near the peak).
    #[test]
    fn a_steep_rise_has_its_true_largest_pressure_angle() {
        let beta = 1f64.to_radians();
        let p = program(Law::Cycloidal, 0.02, beta);
        let cam = Cam {
            follower: Follower::Roller(0.0),
            guide: Guide::Translating { offset: 0.0 },
            base: 0.04,
            clockwise: false,
        };
        let l = lift(&p);
        let starts: Vec<f64> = p.segments().iter().map(|s| s.start).collect();
        let found = of(&cam, &l, &scan(&starts)).max_pressure_angle;
        let reference = (0..=1_000_000)
            .map(|k| beta * k as f64 / 1e6)
            .map(|t| {
                let [s, s1, ..] = l(t);
                (s1 / (0.04 + s)).atan()
            })
            .fold(0.0f64, f64::max);
        assert!((found.value - reference).abs() < 1e-9, "{} against {reference}", found.value);
        assert!(found.value.to_degrees() > 88.0, "the peak is near 90°, not the samples' {}", found.value.to_degrees());
        assert!(found.theta > 0.0 && found.theta < beta);
    }

    /// A flat face on a harmonic rise: the profile's radius of curvature is
    /// R_b + s + s″ (the support function's), smallest in closed form where
    /// s + s″ is — at the rise's end, s = h and s″ = −π²h/(2β²), a limit
    /// the dwell after it does not reach (1e-12 of R_b).
    #[test]
    fn a_flat_faces_smallest_radius_is_the_closed_forms() {
        let (h, beta, base) = (0.01, PI / 2.0, 0.03);
        let p = program(Law::Harmonic, h, beta);
        let cam = Cam { follower: Follower::Flat, guide: Guide::Translating { offset: 0.0 }, base, clockwise: false };
        let l = lift(&p);
        let starts: Vec<f64> = p.segments().iter().map(|s| s.start).collect();
        let e = of(&cam, &l, &scan(&starts));
        let least = base + h - PI * PI * h / (2.0 * beta * beta);
        let found = e.min_curvature_radius.unwrap();
        assert!((found.value - least).abs() < 1e-12 * base, "{} against {least}", found.value);
        assert!(!e.undercut());
    }

    /// A plateau is refined at its ends only, and a plateau all round is
    /// its own largest: on a dwell-rise-dwell-return program (the lift,
    /// 1024 angles scanned), the largest of s is h at every angle of the
    /// upper dwell (the program's value there), found in fewer than the
    /// scan's 1024 and 60 for each of the dwell's two ends refined (without
    /// the plateau rule each of the dwell's ~450 angles is: 10 019
    /// evaluations); a constant's largest is itself.
    #[test]
    fn a_plateau_is_refined_at_its_ends_only() {
        let p = program(Law::Cycloidal, 0.02, PI / 2.0);
        let starts: Vec<f64> = p.segments().iter().map(|s| s.start).collect();
        let grid = scan(&starts);
        let calls = std::cell::Cell::new(0);
        let s = |t: f64| {
            calls.set(calls.get() + 1);
            Some(p.eval(t)[0])
        };
        let top = largest(&s, &grid).unwrap();
        assert_eq!(top.value, 0.02);
        assert!(calls.get() < grid.len() + 120, "{} evaluations", calls.get());
        let constant = largest(&|_| Some(0.5), &grid).unwrap();
        assert_eq!(constant, At { value: 0.5, theta: 0.0 });
    }
}
