//! A mechanism from its dimensions: rough points read off a figure (the
//! sketch, x₀) and the statement's dimensions c(x) = 0 (distances, the
//! direction of a line, a coordinate). The points found are the least
//! change from the sketch that satisfies every dimension,
//!
//! ```text
//! min ½ (x − x₀)ᵀ W (x − x₀)   subject to   c(x) = 0,
//! ```
//!
//! W the points' weights (a point on the ground weighs 10⁶ times another,
//! so a frame drawn to scale stays where it is drawn), so the sketch picks
//! the branch (which side of a line the coupler's joint lies on). Solved by
//! Gauss–Newton on the linearised constraint, each iterate the least
//! W-change from x₀: x = x₀ − W⁻¹Jᵀ(JW⁻¹Jᵀ)⁺(c(xₖ) + J(x₀ − xₖ)), the
//! pseudo-inverse (an SVD) taking repeated dimensions that agree. A
//! dimension still unmet at the end cannot hold with the others: it is
//! named, never met approximately in silence.

use super::Deadline;
use super::numeric::svd::svd;
use nalgebra::{DMatrix, DVector};

/// One dimension, between points by index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Dimension {
    /// |PQ| = value (m).
    Distance([usize; 2], f64),
    /// The direction of P→Q from +x, counter-clockwise (rad).
    Angle([usize; 2], f64),
    /// x of P (m).
    X(usize, f64),
    /// y of P (m).
    Y(usize, f64),
}

/// The points found.
#[derive(Clone, Debug, PartialEq)]
pub struct Solved {
    pub points: Vec<[f64; 2]>,
    pub iterations: usize,
    /// Largest |c| at the end (m; an angle's as its sine times the length).
    pub residual: f64,
    /// Some point is left free to move by the dimensions (the least change
    /// chose where it stays).
    pub underdetermined: bool,
}

/// Dimensions that cannot hold together, by index, and the largest residual.
#[derive(Clone, Debug, PartialEq)]
pub struct Contradiction {
    pub dimensions: Vec<usize>,
    pub residual: f64,
}

const MAX_ITERATIONS: usize = 60;

/// The least change from `sketch` (weights per point) meeting `dimensions`.
/// Only the points the dimensions name move (the others stay as sketched,
/// and leave the figure underdetermined); the `deadline` is read at every
/// iteration, and past it the dimensions still unmet are reported as if
/// they could not hold (the service answers the spent budget instead).
pub fn solve(
    sketch: &[[f64; 2]],
    weights: &[f64],
    dimensions: &[Dimension],
    deadline: &Deadline,
) -> Result<Solved, Contradiction> {
    if dimensions.is_empty() {
        return Ok(Solved { points: sketch.to_vec(), iterations: 0, residual: 0.0, underdetermined: false });
    }
    let size = sketch
        .iter()
        .flatten()
        .fold(0.0f64, |a, v| a.max(v.abs()))
        .max(dimensions.iter().map(scale).fold(0.0, f64::max));
    let mut used: Vec<usize> = dimensions.iter().flat_map(named).collect();
    used.sort_unstable();
    used.dedup();
    let mut local = vec![usize::MAX; sketch.len()];
    used.iter().enumerate().for_each(|(k, &p)| local[p] = k);
    let dims: Vec<Dimension> = dimensions.iter().map(|d| renamed(d, &local)).collect();
    let part: Vec<[f64; 2]> = used.iter().map(|&p| sketch[p]).collect();
    let part_weights: Vec<f64> = used.iter().map(|&p| weights[p]).collect();
    let mut solved = solve_used(&part, &part_weights, &dims, size, deadline)?;
    let mut points = sketch.to_vec();
    used.iter().zip(&solved.points).for_each(|(&p, x)| points[p] = *x);
    solved.points = points;
    solved.underdetermined |= used.len() < sketch.len();
    Ok(solved)
}

/// The points a dimension names.
fn named(d: &Dimension) -> Vec<usize> {
    match *d {
        Dimension::Distance([p, q], _) | Dimension::Angle([p, q], _) => vec![p, q],
        Dimension::X(p, _) | Dimension::Y(p, _) => vec![p],
    }
}

/// A dimension between points renumbered by `local`.
fn renamed(d: &Dimension, local: &[usize]) -> Dimension {
    match *d {
        Dimension::Distance([p, q], v) => Dimension::Distance([local[p], local[q]], v),
        Dimension::Angle([p, q], v) => Dimension::Angle([local[p], local[q]], v),
        Dimension::X(p, v) => Dimension::X(local[p], v),
        Dimension::Y(p, v) => Dimension::Y(local[p], v),
    }
}

/// [`solve`] on the points the dimensions name, all of them; `size` the figure's.
fn solve_used(
    sketch: &[[f64; 2]],
    weights: &[f64],
    dimensions: &[Dimension],
    size: f64,
    deadline: &Deadline,
) -> Result<Solved, Contradiction> {
    let x0 = DVector::from_iterator(2 * sketch.len(), sketch.iter().flatten().copied());
    let tol = 1e-13 * size.max(1e-3);
    let inverse_w = DVector::from_iterator(x0.len(), weights.iter().flat_map(|w| [1.0 / w, 1.0 / w]));
    let mut x = x0.clone();
    for iteration in 0..MAX_ITERATIONS {
        if deadline.expired() {
            break;
        }
        let (c, j) = evaluate(&x, dimensions);
        let residual = c.amax();
        if residual <= tol {
            let underdetermined = free(&j);
            return Ok(Solved { points: points(&x), iterations: iteration, residual, underdetermined });
        }
        let jw = DMatrix::from_fn(j.nrows(), j.ncols(), |r, k| j[(r, k)] * inverse_w[k]);
        let Some(s) = svd(&jw * j.transpose(), true, true) else { break };
        let rhs = &c + &j * (&x0 - &x);
        let Ok(mu) = s.solve(&rhs, 1e-12 * s.singular_values.max()) else { break };
        x = &x0 - jw.transpose() * mu;
    }
    let (c, j) = evaluate(&x, dimensions);
    let residual = c.amax();
    if residual <= tol {
        return Ok(Solved { points: points(&x), iterations: MAX_ITERATIONS, residual, underdetermined: free(&j) });
    }
    let worst: Vec<usize> = (0..c.len()).filter(|&k| c[k].abs() > 1e-6 * residual.max(tol)).collect();
    Err(Contradiction { dimensions: worst, residual })
}

/// Whether the dimensions leave some coordinate free: J's rank below the coordinates'.
fn free(j: &DMatrix<f64>) -> bool {
    let Some(s) = svd(j.clone(), false, false) else { return true };
    let top = s.singular_values.max();
    s.singular_values.iter().filter(|v| **v > 1e-10 * top).count() < j.ncols()
}

fn scale(d: &Dimension) -> f64 {
    match d {
        Dimension::Distance(_, v) | Dimension::X(_, v) | Dimension::Y(_, v) => v.abs(),
        Dimension::Angle(..) => 0.0,
    }
}

fn points(x: &DVector<f64>) -> Vec<[f64; 2]> {
    x.as_slice().chunks_exact(2).map(|p| [p[0], p[1]]).collect()
}

/// c(x) and its Jacobian.
fn evaluate(x: &DVector<f64>, dimensions: &[Dimension]) -> (DVector<f64>, DMatrix<f64>) {
    let mut c = DVector::zeros(dimensions.len());
    let mut j = DMatrix::zeros(dimensions.len(), x.len());
    let at = |p: usize| [x[2 * p], x[2 * p + 1]];
    for (r, d) in dimensions.iter().enumerate() {
        match *d {
            Dimension::Distance([p, q], value) => {
                let (a, b) = (at(p), at(q));
                let d = [b[0] - a[0], b[1] - a[1]];
                let length = d[0].hypot(d[1]);
                c[r] = length - value;
                let u = if length > 0.0 { [d[0] / length, d[1] / length] } else { [0.0, 0.0] };
                for k in 0..2 {
                    j[(r, 2 * q + k)] += u[k];
                    j[(r, 2 * p + k)] -= u[k];
                }
            }
            Dimension::Angle([p, q], value) => {
                // The component of P→Q across the wanted direction.
                let (a, b) = (at(p), at(q));
                let n = [-value.sin(), value.cos()];
                c[r] = n[0] * (b[0] - a[0]) + n[1] * (b[1] - a[1]);
                for k in 0..2 {
                    j[(r, 2 * q + k)] += n[k];
                    j[(r, 2 * p + k)] -= n[k];
                }
            }
            Dimension::X(p, value) => {
                c[r] = x[2 * p] - value;
                j[(r, 2 * p)] = 1.0;
            }
            Dimension::Y(p, value) => {
                c[r] = x[2 * p + 1] - value;
                j[(r, 2 * p + 1)] = 1.0;
            }
        }
    }
    (c, j)
}

/// Dimensions `Angle` whose line the solution draws backwards (P→Q at the
/// opposite direction): the sketch drew it the other way round.
pub fn reversed(points: &[[f64; 2]], dimensions: &[Dimension]) -> Vec<usize> {
    (0..dimensions.len())
        .filter(|&k| match dimensions[k] {
            Dimension::Angle([p, q], value) => {
                let d = [points[q][0] - points[p][0], points[q][1] - points[p][1]];
                d[0] * value.cos() + d[1] * value.sin() < 0.0
            }
            _ => false,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// "Crank 0.1 m at 60°, coupler 0.3 m, rocker 0.25 m, frame 0.3 m":
    /// O₂ = (0, 0) and O₄ on the x axis (dimensions too: without them the
    /// heavy frame would still move by 1e-6 of the sketch's error), A and
    /// B sketched roughly. A = 0.1(cos 60°, sin 60°); B the intersection of the
    /// circles (A, 0.3) and (O₄, 0.25) on the sketch's side (both sides
    /// sketched), to 1e-12.
    #[test]
    fn a_four_bar_from_its_lengths_is_the_circle_intersection_on_the_sketchs_side() {
        let a = [0.05, 3f64.sqrt() / 20.0];
        let o4 = [0.3, 0.0];
        let (d, r0, r1) = ((o4[0] - a[0]).hypot(o4[1] - a[1]), 0.3, 0.25);
        let along = (d * d + r0 * r0 - r1 * r1) / (2.0 * d);
        let h = (r0 * r0 - along * along).sqrt();
        let u = [(o4[0] - a[0]) / d, (o4[1] - a[1]) / d];
        let mid = [a[0] + along * u[0], a[1] + along * u[1]];
        let above = [mid[0] - h * u[1], mid[1] + h * u[0]];
        let below = [mid[0] + h * u[1], mid[1] - h * u[0]];
        let dims = [
            Dimension::Distance([0, 2], 0.1),
            Dimension::Angle([0, 2], 60f64.to_radians()),
            Dimension::Distance([2, 3], 0.3),
            Dimension::Distance([1, 3], 0.25),
            Dimension::Distance([0, 1], 0.3),
            Dimension::X(0, 0.0),
            Dimension::Y(0, 0.0),
            Dimension::Y(1, 0.0),
        ];
        let weights = [1e6, 1e6, 1.0, 1.0];
        for (b_sketch, expected) in [([0.3, 0.3], above), ([0.2, -0.15], below)] {
            let sketch = [[0.0, 0.0], [0.3, 0.0], [0.04, 0.1], b_sketch];
            let s = solve(&sketch, &weights, &dims, &Deadline::none()).unwrap();
            for k in 0..2 {
                assert!((s.points[2][k] - a[k]).abs() < 1e-12, "A: {:?}", s.points[2]);
                assert!((s.points[3][k] - expected[k]).abs() < 1e-12, "B: {:?} against {expected:?}", s.points[3]);
            }
            assert!(s.points[0][0].abs() < 1e-12 && (s.points[1][0] - 0.3).abs() < 1e-12, "the frame stays");
        }
    }

    /// No dimensions: the sketch as drawn (schemathesis sent `"dimensions": []`,
    /// and an SVD of the empty system panicked).
    #[test]
    fn no_dimensions_leave_the_sketch_as_drawn() {
        let s = solve(&[[0.0, 0.0], [1.0, 0.5]], &[1.0; 2], &[], &Deadline::none()).unwrap();
        assert_eq!(s.points, vec![[0.0, 0.0], [1.0, 0.5]]);
    }

    /// A triangle 1, 1, 3 does not close: the three distances are named.
    #[test]
    fn a_triangle_that_does_not_close_is_a_contradiction() {
        let dims =
            [Dimension::Distance([0, 1], 1.0), Dimension::Distance([1, 2], 1.0), Dimension::Distance([0, 2], 3.0)];
        let e = solve(&[[0.0, 0.0], [1.0, 0.0], [0.5, 0.5]], &[1.0; 3], &dims, &Deadline::none()).unwrap_err();
        assert_eq!(e.dimensions, vec![0, 1, 2]);
        let twice = [Dimension::Distance([0, 1], 1.0), Dimension::Distance([0, 1], 1.2)];
        assert!(
            solve(&[[0.0, 0.0], [1.0, 0.0]], &[1.0; 2], &twice, &Deadline::none()).is_err(),
            "two values for one distance"
        );
    }
}
