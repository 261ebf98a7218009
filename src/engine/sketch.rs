//! A mechanism from its dimensions: rough points read off a figure (the
//! sketch, x₀) and the statement's dimensions c(x) = 0 (distances, the
//! direction of a line, a coordinate, a point at a fraction of a segment).
//! The points found are the least change from the sketch that satisfies
//! every dimension,
//!
//! ```text
//! min ½ (x − x₀)ᵀ W (x − x₀)   subject to   c(x) = 0,
//! ```
//!
//! W the points' weights (a point that cannot move weighs 10⁶ times
//! another, so a frame drawn to scale stays where it is drawn), so the
//! sketch picks the branch (which side of a line the coupler's joint lies
//! on). Solved in three stages, each step the least W-change that meets
//! the linearised dimensions (J the Jacobian of c, W⁻¹Jᵀ(JW⁻¹Jᵀ)⁺ its
//! pseudo-inverse by an SVD, which takes repeated dimensions that agree):
//! 1. onto the dimensions from the sketch: Newton steps
//!    x ← x − W⁻¹Jᵀ(JW⁻¹Jᵀ)⁺c(x), halved while they do not reduce |c|
//!    (a rough sketch is far from the figure: a full step may jump branch);
//! 2. the least change: Gauss–Newton, each iterate the least W-change from
//!    x₀ meeting the dimensions linearised at the last,
//!    x = x₀ − W⁻¹Jᵀ(JW⁻¹Jᵀ)⁺(c(xₖ) + J(x₀ − xₖ)), while it moves;
//! 3. Newton steps again until |c| stops falling (quadratically, to
//!    rounding: the Gauss–Newton iterates converge only linearly).
//!
//! A misfit within [`ROUNDING`] of the figure's size is met; a dimension
//! still unmet beyond it cannot hold with the others: it is named, never
//! met approximately in silence.

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
    /// M = A + r·(B − A): `on` M at the fraction `ratio` of A→B (two rows).
    Between { on: usize, a: usize, b: usize, ratio: f64 },
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

/// Most iterations of each stage.
const MAX_ITERATIONS: usize = 60;
/// A misfit this fraction of the figure's size is rounding, not a contradiction.
pub const ROUNDING: f64 = 1e-12;

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
        Dimension::Between { on, a, b, .. } => vec![on, a, b],
    }
}

/// A dimension between points renumbered by `local`.
fn renamed(d: &Dimension, local: &[usize]) -> Dimension {
    match *d {
        Dimension::Distance([p, q], v) => Dimension::Distance([local[p], local[q]], v),
        Dimension::Angle([p, q], v) => Dimension::Angle([local[p], local[q]], v),
        Dimension::X(p, v) => Dimension::X(local[p], v),
        Dimension::Y(p, v) => Dimension::Y(local[p], v),
        Dimension::Between { on, a, b, ratio } => Dimension::Between { on: local[on], a: local[a], b: local[b], ratio },
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
    let inverse_w = DVector::from_iterator(x0.len(), weights.iter().flat_map(|w| [1.0 / w, 1.0 / w]));
    let system = System { dimensions, inverse_w: &inverse_w, deadline };
    let mut iterations = 0;
    let x = system.newton(x0.clone(), &mut iterations, true);
    let x = system.least_change(&x0, x, 1e-9 * size.max(1e-300), &mut iterations);
    let x = system.newton(x, &mut iterations, false);
    let (c, j) = evaluate(&x, dimensions);
    let residual = c.amax();
    let tolerance = ROUNDING * size.max(1e-300);
    if residual <= tolerance {
        return Ok(Solved { points: points(&x), iterations, residual, underdetermined: free(&j) });
    }
    let rows = rows_of(dimensions);
    let mut worst: Vec<usize> =
        (0..c.len()).filter(|&k| c[k].abs() > 1e-6 * residual.max(tolerance)).map(|k| rows[k]).collect();
    worst.dedup();
    Err(Contradiction { dimensions: worst, residual })
}

/// The dimensions, their weights and the deadline: the stages of [`solve_used`].
struct System<'a> {
    dimensions: &'a [Dimension],
    inverse_w: &'a DVector<f64>,
    deadline: &'a Deadline,
}

impl System<'_> {
    /// The least W-change δ with J δ = −r (None where the SVD fails).
    fn step(&self, j: &DMatrix<f64>, r: &DVector<f64>) -> Option<DVector<f64>> {
        let jw = DMatrix::from_fn(j.nrows(), j.ncols(), |row, k| j[(row, k)] * self.inverse_w[k]);
        let s = svd(&jw * j.transpose(), true, true)?;
        let mu = s.solve(r, 1e-12 * s.singular_values.max()).ok()?;
        Some(-(jw.transpose() * mu))
    }

    /// Newton steps from `x` while |c| falls (`damped`: each step halved
    /// until it does, at most 30 times; else the first step that does not
    /// reduce |c| ends them).
    fn newton(&self, mut x: DVector<f64>, iterations: &mut usize, damped: bool) -> DVector<f64> {
        let (mut c, mut j) = evaluate(&x, self.dimensions);
        for _ in 0..MAX_ITERATIONS {
            if self.deadline.expired() || c.amax() == 0.0 {
                break;
            }
            *iterations += 1;
            let Some(delta) = self.step(&j, &c) else { break };
            let mut t = 1.0;
            let next = loop {
                let y = &x + t * &delta;
                let (cy, jy) = evaluate(&y, self.dimensions);
                if cy.amax() < c.amax() {
                    break Some((y, cy, jy));
                }
                t *= 0.5;
                if !damped || t < 1e-9 {
                    break None;
                }
            };
            let Some((y, cy, jy)) = next else { break };
            (x, c, j) = (y, cy, jy);
        }
        x
    }

    /// Gauss–Newton towards the least W-change from `x0`, from `x` on the
    /// dimensions, until an iterate moves less than `still` (m).
    fn least_change(&self, x0: &DVector<f64>, mut x: DVector<f64>, still: f64, iterations: &mut usize) -> DVector<f64> {
        for _ in 0..MAX_ITERATIONS {
            if self.deadline.expired() {
                break;
            }
            *iterations += 1;
            let (c, j) = evaluate(&x, self.dimensions);
            let Some(delta) = self.step(&j, &(&c + &j * (x0 - &x))) else { break };
            let next = x0 + delta;
            let moved = (&next - &x).amax();
            // A step that leaves the dimensions far behind is not taken (the Newton stage's point stands).
            if !moved.is_finite() || evaluate(&next, self.dimensions).0.amax() > 1e3 * c.amax().max(still) {
                break;
            }
            x = next;
            if moved <= still {
                break;
            }
        }
        x
    }
}

/// The dimension of each row of c.
fn rows_of(dimensions: &[Dimension]) -> Vec<usize> {
    dimensions
        .iter()
        .enumerate()
        .flat_map(|(k, d)| std::iter::repeat_n(k, if matches!(d, Dimension::Between { .. }) { 2 } else { 1 }))
        .collect()
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
        Dimension::Angle(..) | Dimension::Between { .. } => 0.0,
    }
}

fn points(x: &DVector<f64>) -> Vec<[f64; 2]> {
    x.as_slice().chunks_exact(2).map(|p| [p[0], p[1]]).collect()
}

/// c(x) and its Jacobian.
fn evaluate(x: &DVector<f64>, dimensions: &[Dimension]) -> (DVector<f64>, DMatrix<f64>) {
    let rows = rows_of(dimensions).len();
    let mut c = DVector::zeros(rows);
    let mut j = DMatrix::zeros(rows, x.len());
    let at = |p: usize| [x[2 * p], x[2 * p + 1]];
    let mut r = 0;
    for d in dimensions {
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
            Dimension::Between { on, a, b, ratio } => {
                for k in 0..2 {
                    c[r] = x[2 * on + k] - (1.0 - ratio) * x[2 * a + k] - ratio * x[2 * b + k];
                    j[(r, 2 * on + k)] += 1.0;
                    j[(r, 2 * a + k)] -= 1.0 - ratio;
                    j[(r, 2 * b + k)] -= ratio;
                    r += 1;
                }
                continue;
            }
        }
        r += 1;
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
