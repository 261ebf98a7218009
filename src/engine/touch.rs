//! Where two curves touch as drawn: the point a contact joint starts from,
//! or why there is none (a gap, or curves that cross instead of touching).
//!
//! The distance from the first curve's point a(u) to the second curve,
//! d(u) = min_v |a(u) − b(v)|, is sampled over the first curve's domain
//! (a line's over the other curve's, the line then taken second), and each
//! of its smallest local minima refined by golden-section search: at a
//! tangent contact d ≈ ½|κ₁ − κ₂| δu², so u to 1e-13 puts the touching
//! point within rounding.

use super::curves::{Curve, Domain};
use super::numeric::plane::cross;

/// Samples of d(u) over the first curve.
const SAMPLES: usize = 96;
/// Local minima of the samples refined.
const MINIMA: usize = 4;
/// Largest angle between the tangents at a touching point (rad): beyond it
/// the curves cross (an overlap of about half this squared times the radius).
const CROSSING: f64 = 2e-3;

/// Why two curves do not make a contact as drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NoTouch {
    /// Their nearest points are `gap` apart (midway between them: `point`).
    Gap { gap: f64, point: [f64; 2] },
    /// They meet at `point` at `angle` (rad) between their tangents.
    Cross { point: [f64; 2], angle: f64 },
    /// Two lines: they touch along their length, or cross.
    Lines,
}

/// A candidate: the parameters on each curve and the distance.
#[derive(Clone, Copy, Debug)]
struct Near {
    u: [f64; 2],
    distance: f64,
}

/// The point where `curves` touch (within `tolerance`), the one nearest to
/// `hint` where several do; else why they do not.
pub fn touching(curves: &[Curve; 2], tolerance: f64, hint: Option<[f64; 2]>) -> Result<[f64; 2], NoTouch> {
    let (none, line) = (|c: &Curve| c.domain() == Domain::None, |c: &Curve| matches!(c, Curve::Line { .. }));
    let candidates = match (&curves[0], &curves[1]) {
        (a, b) if none(a) || none(b) => {
            let (p, other, flip) = if none(a) { (a.at(0.0).r, b, false) } else { (b.at(0.0).r, a, true) };
            let u = other.nearest_anywhere(p, 32).unwrap_or(0.0);
            let distance = dist(other.at(u).r, p);
            vec![Near { u: if flip { [u, 0.0] } else { [0.0, u] }, distance }]
        }
        (a, b) if line(a) && line(b) => return Err(NoTouch::Lines),
        (a, b) if line(a) => minima(b, a).into_iter().map(|n| Near { u: [n.u[1], n.u[0]], ..n }).collect(),
        (a, b) => minima(a, b),
    };
    let midpoint = |n: &Near| {
        let (p, q) = (curves[0].at(n.u[0]).r, curves[1].at(n.u[1]).r);
        [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0]
    };
    let closest = candidates.iter().min_by(|x, y| x.distance.total_cmp(&y.distance)).ok_or(NoTouch::Lines)?;
    let touching = candidates.iter().filter(|n| n.distance <= tolerance);
    let chosen = match hint {
        Some(h) => touching.min_by(|x, y| dist(midpoint(x), h).total_cmp(&dist(midpoint(y), h))),
        None => touching.min_by(|x, y| x.distance.total_cmp(&y.distance)),
    };
    let Some(n) = chosen else { return Err(NoTouch::Gap { gap: closest.distance, point: midpoint(closest) }) };
    let point = midpoint(n);
    if curves.iter().all(|c| !none(c)) {
        let (t1, t2) = (curves[0].at(n.u[0]).frame().0, curves[1].at(n.u[1]).frame().0);
        let angle = cross(t1, t2).abs().asin();
        if angle > CROSSING {
            return Err(NoTouch::Cross { point, angle });
        }
    }
    Ok(point)
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// The smallest local minima of d(u) over curve `a` (not a line), each refined.
fn minima(a: &Curve, b: &Curve) -> Vec<Near> {
    let (lo, hi, periodic) = match a.domain() {
        Domain::Periodic(p) => (0.0, p, true),
        Domain::Interval(x, y) => (x, y, false),
        Domain::None | Domain::Unbounded => return Vec::new(),
    };
    let h = (hi - lo) / SAMPLES as f64;
    let mut guess = None;
    let samples: Vec<Near> = (0..=SAMPLES)
        .map(|k| {
            let near = to(a, b, lo + h * k as f64, guess);
            guess = Some(near.u[1]);
            near
        })
        .collect();
    let n = if periodic { SAMPLES } else { SAMPLES + 1 };
    let at = |k: isize| samples[k.rem_euclid(n as isize) as usize].distance;
    let mut lows: Vec<usize> = (0..n)
        .filter(|&k| {
            let k = k as isize;
            let (left, right) = if periodic || (k > 0 && k < n as isize - 1) {
                (at(k - 1), at(k + 1))
            } else if k == 0 {
                (f64::INFINITY, at(1))
            } else {
                (at(k - 1), f64::INFINITY)
            };
            at(k) <= left && at(k) <= right
        })
        .collect();
    lows.sort_by(|x, y| samples[*x].distance.total_cmp(&samples[*y].distance));
    lows.truncate(MINIMA);
    lows.into_iter()
        .map(|k| {
            let u = lo + h * k as f64;
            let (from, to_) = if periodic { (u - h, u + h) } else { ((u - h).max(lo), (u + h).min(hi)) };
            golden(a, b, from, to_, samples[k].u[1])
        })
        .collect()
}

/// a(u) and the nearest point of b to it (Newton from `guess`, else from
/// anywhere on b).
fn to(a: &Curve, b: &Curve, u: f64, guess: Option<f64>) -> Near {
    let p = a.at(u).r;
    let v = guess.and_then(|g| b.nearest(p, g)).or_else(|| b.nearest_anywhere(p, 16));
    v.map_or(Near { u: [u, 0.0], distance: f64::INFINITY }, |v| Near { u: [u, v], distance: dist(b.at(v).r, p) })
}

/// The minimum of d(u) in [x, y] by golden-section search.
fn golden(a: &Curve, b: &Curve, mut x: f64, mut y: f64, guess: f64) -> Near {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut best = to(a, b, (x + y) / 2.0, Some(guess));
    let (mut c, mut d) = (y - r * (y - x), x + r * (y - x));
    let (mut fc, mut fd) = (to(a, b, c, Some(best.u[1])), to(a, b, d, Some(best.u[1])));
    while (y - x).abs() > 1e-13 * (1.0 + x.abs()) {
        if fc.distance < fd.distance {
            (y, d, fd) = (d, c, fc);
            c = y - r * (y - x);
            fc = to(a, b, c, Some(fd.u[1]));
        } else {
            (x, c, fc) = (c, d, fd);
            d = x + r * (y - x);
            fd = to(a, b, d, Some(fc.u[1]));
        }
        for n in [fc, fd] {
            if n.distance < best.distance {
                best = n;
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle(c: [f64; 2], r: f64) -> Curve {
        Curve::Circle { centre: c, radius: r, inside: false }
    }

    /// A disk on a flat face touches at its lowest point; raised by 1 mm
    /// it leaves a 1 mm gap; lowered by 1 mm the two cross at
    /// acos(0.049/0.05) (closed forms, 1e-9).
    #[test]
    fn a_disk_on_a_face_touches_or_says_why_not() {
        let face = Curve::Line { at: [0.0, 0.0], direction: [1.0, 0.0] };
        let on = touching(&[circle([0.3, 0.05], 0.05), face.clone()], 1e-9, None).unwrap();
        assert!((on[0] - 0.3).abs() < 1e-7 && on[1].abs() < 1e-9, "{on:?}");
        let Err(NoTouch::Gap { gap, .. }) = touching(&[circle([0.3, 0.051], 0.05), face.clone()], 1e-9, None) else {
            panic!("a gap")
        };
        assert!((gap - 0.001).abs() < 1e-9, "{gap}");
        let Err(NoTouch::Cross { angle, .. }) = touching(&[face, circle([0.3, 0.049], 0.05)], 1e-9, None) else {
            panic!("crossing")
        };
        assert!((angle - (0.049f64 / 0.05).acos()).abs() < 1e-9, "{angle}");
    }

    /// A roller of 10 mm on a 40 mm disk, their centres 50 mm apart,
    /// touches on the line of centres; a ring (a point) on a rim is where it
    /// is drawn; a small disk inside a track touches it from within.
    #[test]
    fn curved_curves_and_points_touch_where_drawn() {
        let p = touching(&[circle([0.0, 0.0], 0.04), circle([0.03, 0.04], 0.01)], 1e-9, None).unwrap();
        assert!((p[0] - 0.024).abs() < 1e-9 && (p[1] - 0.032).abs() < 1e-9, "{p:?}");
        let ring = touching(&[circle([0.05, 0.0], 0.1), Curve::Point([0.05, 0.1])], 1e-9, None).unwrap();
        assert!((ring[0] - 0.05).abs() < 1e-12 && (ring[1] - 0.1).abs() < 1e-12);
        let track = Curve::Circle { centre: [0.0, 0.0], radius: 0.5, inside: true };
        let p = touching(&[track, circle([0.0, -0.4], 0.1)], 1e-9, Some([0.0, -0.5])).unwrap();
        assert!(p[0].abs() < 1e-7 && (p[1] + 0.5).abs() < 1e-9, "{p:?}");
    }
}
