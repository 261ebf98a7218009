//! A closed or open C² cubic spline through points, for a curve drawn by
//! its points (a cam's profile from a table, a track).

use super::Local;
use crate::engine::numeric::tridiagonal;

/// A C² cubic spline through points, its parameter the knots' index (u = k
/// at point k), closed (periodic) or open (natural: r″ = 0 at both ends).
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    pub(super) points: Vec<[f64; 2]>,
    /// r″ at every knot.
    second: Vec<[f64; 2]>,
    pub(super) closed: bool,
}

impl Spline {
    /// The spline through `points` (at least 4, every one finite), or None.
    pub fn new(points: Vec<[f64; 2]>, closed: bool) -> Option<Self> {
        let n = points.len();
        if n < 4 || points.iter().flatten().any(|v| !v.is_finite()) {
            return None;
        }
        // M_{k−1} + 4 M_k + M_{k+1} = 6 (P_{k+1} − 2 P_k + P_{k−1}) at uniform unit spacing;
        // closed: the indices wrap (a cyclic system); open: M = 0 at both ends.
        // Tridiagonal: solved in O(n) (a dense LU of 2000 points took 4 s).
        let end = |k: usize| !closed && (k == 0 || k == n - 1);
        let (mut lower, mut diag, mut upper) = (vec![1.0; n], vec![4.0; n], vec![1.0; n]);
        for k in (0..n).filter(|&k| end(k)) {
            (lower[k], diag[k], upper[k]) = (0.0, 1.0, 0.0);
        }
        let coordinate = |d: usize| -> Vec<f64> {
            let rhs: Vec<f64> = (0..n)
                .map(|k| {
                    let (prev, next) = ((k + n - 1) % n, (k + 1) % n);
                    if end(k) { 0.0 } else { 6.0 * (points[next][d] - 2.0 * points[k][d] + points[prev][d]) }
                })
                .collect();
            if closed {
                tridiagonal::cyclic(&lower, &diag, &upper, &rhs)
            } else {
                tridiagonal::solve(&lower, &diag, &upper, &rhs)
            }
        };
        let (x, y) = (coordinate(0), coordinate(1));
        if x.iter().chain(&y).any(|v| !v.is_finite()) {
            return None;
        }
        let second = (0..n).map(|k| [x[k], y[k]]).collect();
        Some(Self { points, second, closed })
    }

    pub(super) fn segments(&self) -> usize {
        if self.closed { self.points.len() } else { self.points.len() - 1 }
    }

    pub(super) fn at(&self, u: f64) -> Local {
        let n = self.points.len();
        let segments = self.segments();
        let u = if self.closed { u.rem_euclid(segments as f64) } else { u.clamp(0.0, segments as f64) };
        let k = (u.floor() as usize).min(segments - 1);
        let t = u - k as f64;
        let (p0, p1, m0, m1) = (self.points[k], self.points[(k + 1) % n], self.second[k], self.second[(k + 1) % n]);
        let s = 1.0 - t;
        let each = |d: usize| {
            [
                s * p0[d] + t * p1[d] + ((s * s * s - s) * m0[d] + (t * t * t - t) * m1[d]) / 6.0,
                p1[d] - p0[d] + ((1.0 - 3.0 * s * s) * m0[d] + (3.0 * t * t - 1.0) * m1[d]) / 6.0,
                s * m0[d] + t * m1[d],
                m1[d] - m0[d],
            ]
        };
        let (x, y) = (each(0), each(1));
        Local { r: [x[0], y[0]], d1: [x[1], y[1]], d2: [x[2], y[2]], d3: [x[3], y[3]] }
    }
}
