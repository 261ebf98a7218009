//! Position, velocity and acceleration of a driven mechanism.
//!
//! Position: Newton–Raphson on Φ(q, φ) = 0 from a predicted q (continuation
//! keeps the assembly branch). Velocity: Φ_q q̇ = ν (the input speeds).
//! Acceleration: Φ_q q̈ = γ. With one input, g = dq/dφ (velocity
//! coefficients) and h = d²q/dφ² give the predictor q + gΔφ + ½hΔφ².

use super::constraints::{State, System, evaluate, joint_offsets, nu};
use super::mobility::mobility;
use super::model::Mechanism;
use super::numeric::svd::{singular_values, svd};
use super::{Deadline, EngineError};
use nalgebra::{DMatrix, DVector, Dyn, LU};

/// Newton iterations allowed per position.
const MAX_ITERATIONS: usize = 30;
/// Φ_q is treated as singular beyond this condition number: velocities and
/// forces there are not computed (a regular position of a mechanism in SI
/// units has a condition number well below 1e4; at a toggle or change point
/// it is 1e6 or more, from round-off alone).
pub const SINGULAR_CONDITION: f64 = 1e6;

/// The mechanism at one input position.
#[derive(Clone, Debug)]
pub struct Configuration {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    /// Velocity coefficients g = dq/dφ (one input only).
    pub g: Option<Vec<f64>>,
    /// Φ_q here, kept for the reactions (empty at a singular position).
    pub jacobian: DMatrix<f64>,
    /// LU of Φ_q when it is square, for the multipliers (Φ_qᵀλ = b).
    pub lu: Option<LU<f64, Dyn, Dyn>>,
    /// Condition number of Φ_q: κ₂ (exact), or below [`ESTIMATE_LIMIT`] an
    /// estimate of κ₁ when the sweep did not ask for it exactly.
    pub condition: f64,
    pub iterations: usize,
    pub residual: f64,
    /// Φ_q is singular here (or Newton could not assemble this one position
    /// while its neighbours assemble): nothing but q (predicted) is valid.
    pub singular: bool,
}

/// Solves A x = b: LU when A is square and regular, else least squares (SVD).
pub fn solve_linear(a: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    if a.is_square()
        && let Some(x) = a.clone().lu().solve(b)
        && x.iter().all(|v| v.is_finite())
    {
        return Some(x);
    }
    if !b.iter().all(|v| v.is_finite()) {
        return None;
    }
    let svd = svd(a.clone(), true, true)?;
    let tol = 1e-12 * svd.singular_values.max();
    svd.solve(b, tol).ok()
}

/// y with Aᵀy = b from the LU of A (P A = L U, so Aᵀ = Uᵀ Lᵀ P): the
/// multipliers from the factors the velocities used, without factoring Aᵀ.
pub fn solve_transposed(lu: &LU<f64, Dyn, Dyn>, b: &DVector<f64>) -> Option<DVector<f64>> {
    let w = lu.u().tr_solve_upper_triangular(b)?;
    let mut y = lu.l().tr_solve_lower_triangular(&w)?;
    lu.p().inv_permute_rows(&mut y);
    y.iter().all(|v| v.is_finite()).then_some(y)
}

/// Estimates above this send a position to the exact κ₂ (an SVD): the
/// estimate is within a factor n (coordinates) of κ₂ either way in the
/// worst case, and Hager's method is rarely off by more than 3, so every
/// position whose κ₂ reaches the near-singular 1e4 is measured exactly for
/// mechanisms of up to 33 bodies; regular positions (κ₂ ~ 10) are not.
pub const ESTIMATE_LIMIT: f64 = 100.0;

/// κ₁ = ‖A‖₁·‖A⁻¹‖₁ of a square A from its LU, ‖A⁻¹‖₁ by Hager's estimator
/// (Higham, *Accuracy and Stability of Numerical Algorithms*, Alg. 15.1, as
/// LAPACK's xGECON): a few solves with the factors instead of an SVD. A
/// lower bound of κ₁, in practice within a factor 3 of it.
pub fn estimated_condition(a: &DMatrix<f64>, lu: &LU<f64, Dyn, Dyn>) -> f64 {
    let n = a.nrows();
    let norm1 = |v: &DVector<f64>| v.iter().map(|x| x.abs()).sum::<f64>();
    let a_norm = a.column_iter().map(|c| c.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max);
    let mut x = DVector::from_element(n, 1.0 / n as f64);
    let mut estimate = 0.0;
    for _ in 0..5 {
        let Some(y) = lu.solve(&x) else { return f64::INFINITY };
        estimate = norm1(&y);
        let sign = y.map(|v| if v >= 0.0 { 1.0 } else { -1.0 });
        let Some(z) = solve_transposed(lu, &sign) else { return f64::INFINITY };
        let j = z.iamax();
        if z[j].abs() <= z.dot(&x) {
            break;
        }
        x = DVector::zeros(n);
        x[j] = 1.0;
    }
    if estimate.is_finite() { a_norm * estimate } else { f64::INFINITY }
}

/// 2-norm condition number σ_max/σ_min of a matrix with at least as many rows as columns.
pub fn condition(a: &DMatrix<f64>) -> f64 {
    let Some(s) = singular_values(a) else { return f64::INFINITY };
    let (max, min) = (s.max(), s.min());
    if min > 0.0 { max / min } else { f64::INFINITY }
}

/// Newton–Raphson from `q` to Φ = 0 at the given inputs: the iterations,
/// the final |Φ|∞ and Φ, Φ_q there.
pub fn assemble(
    m: &Mechanism,
    q: &mut [f64],
    inputs: &[[f64; 3]],
    step: usize,
) -> Result<(usize, f64, System), EngineError> {
    let scale = 1.0 + q.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let tol = 1e-13 * scale;
    let mut residual = f64::INFINITY;
    for iteration in 0..=MAX_ITERATIONS {
        let sys = evaluate(m, &State { q, qd: None, inputs });
        residual = sys.phi.amax();
        if residual <= tol {
            return Ok((iteration, residual, sys));
        }
        let Some(dq) = solve_linear(&sys.jacobian, &(-&sys.phi)) else { break };
        for (v, d) in q.iter_mut().zip(dq.iter()) {
            *v += d;
        }
    }
    let joint = widest_gap(m, q, inputs);
    Err(EngineError::NewtonDiverged { step, input: inputs.first().map_or(0.0, |i| i[0]), residual, joint })
}

/// The joint (or input) whose constraint rows are violated most at `q`.
fn widest_gap(m: &Mechanism, q: &[f64], inputs: &[[f64; 3]]) -> String {
    let phi = evaluate(m, &State { q, qd: None, inputs }).phi;
    let offsets = joint_offsets(m);
    let Some(row) = (0..phi.len()).max_by(|&a, &b| phi[a].abs().total_cmp(&phi[b].abs())) else { return String::new() };
    match offsets.iter().rposition(|&o| o <= row) {
        Some(j) if row < offsets[j] + Mechanism::joint_rows(&m.joints[j].kind) => format!("joint {}", m.joints[j].name),
        _ => "the input".into(),
    }
}

/// The error of positions that cannot be reached, or, when the joints leave
/// the mechanism no freedom at all, that it is locked.
fn unreachable(m: &Mechanism, e: EngineError) -> EngineError {
    match e {
        EngineError::NewtonDiverged { .. } if !m.drivers.is_empty() && mobility(m, &m.reference_q()).dof == 0 => {
            EngineError::Locked { grubler: m.grubler().mobility }
        }
        e => e,
    }
}

/// Velocities and accelerations at an assembled q, with Φ_q's factorisation.
pub struct Solved {
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    pub sys: System,
    /// LU of Φ_q when it is square.
    pub lu: Option<LU<f64, Dyn, Dyn>>,
}

/// Velocities and accelerations at a q assembled by [`assemble`], which
/// gave `sys` there (Φ_q does not depend on the input speeds).
pub fn motion(m: &Mechanism, q: &[f64], inputs: &[[f64; 3]], sys: System) -> Option<Solved> {
    // One factorisation for the velocity and the acceleration.
    let lu = sys.jacobian.is_square().then(|| sys.jacobian.clone().lu());
    let solve = |b: &DVector<f64>| {
        lu.as_ref()
            .and_then(|lu| lu.solve(b))
            .filter(|x| x.iter().all(|v| v.is_finite()))
            .or_else(|| solve_linear(&sys.jacobian, b))
    };
    let qd: Vec<f64> = solve(&nu(m, inputs))?.iter().copied().collect();
    let with_speed = evaluate(m, &State { q, qd: Some(&qd), inputs });
    let qdd = solve(&with_speed.gamma)?.iter().copied().collect();
    Some(Solved { qd, qdd, sys: with_speed, lu })
}

/// The configurations along the given input positions, starting from the
/// reference configuration and continuing from each position to the next.
///
/// Each position's condition number is κ₂ exactly (an SVD) when `exact`
/// or where the estimate from Φ_q's LU exceeds [`ESTIMATE_LIMIT`]; else
/// the estimate ([`estimated_condition`]).
pub fn sweep(
    m: &Mechanism,
    positions: &[Vec<[f64; 3]>],
    deadline: &Deadline,
    exact: bool,
) -> Result<Vec<Configuration>, EngineError> {
    let mut out: Vec<Configuration> = Vec::with_capacity(positions.len());
    sweep_each(m, positions, deadline, exact, |_, c| {
        out.push(c);
        Ok(())
    })?;
    Ok(out)
}

/// [`sweep`], handing each position's configuration to `each` as soon as
/// it is known (with its index) instead of keeping them all: what is done
/// with a position stays in the cache, and a long sweep holds one
/// configuration (Φ_q, its LU, q, q̇, q̈) at a time. An error of `each`
/// stops the sweep.
pub fn sweep_each(
    m: &Mechanism,
    positions: &[Vec<[f64; 3]>],
    deadline: &Deadline,
    exact: bool,
    mut each: impl FnMut(usize, Configuration) -> Result<(), EngineError>,
) -> Result<(), EngineError> {
    let mut base = m.reference_q();
    if let Some(first) = positions.first() {
        approach(m, &mut base, first).map_err(|e| unreachable(m, e))?;
    }
    // Velocity coefficients at the last regular position, for the predictor.
    let mut coefficients: Option<(Vec<f64>, Vec<f64>, f64)> = None;
    let mut failure: Option<EngineError> = None;
    for (step, inputs) in positions.iter().enumerate() {
        deadline.check(|| format!("the mechanism was assembled at {step} of {} positions", positions.len()))?;
        let mut q = base.clone();
        if let Some((g, h, from)) = &coefficients {
            let d = inputs[0][0] - from;
            q.iter_mut().enumerate().for_each(|(k, v)| *v += g[k] * d + 0.5 * h[k] * d * d);
        }
        let (iterations, residual, sys) = match assemble(m, &mut q, inputs, step) {
            Ok(r) => r,
            // One position that will not assemble between two that do is a
            // singular point passed; two in a row is a position out of reach.
            Err(e) if failure.is_none() => {
                failure = Some(e);
                each(step, Configuration::singular_at(q, f64::INFINITY))?;
                continue;
            }
            Err(_) => {
                return Err(unreachable(m, failure.unwrap_or(EngineError::Singular { step, input: inputs[0][0] })));
            }
        };
        failure = None;
        // One input: g = dq/dφ and h = d²q/dφ² give q̇ = gω and q̈ = gα + hω²
        // (γ is quadratic in q̇), and they are the next step's predictor.
        let single = m.drivers.len() == 1;
        let solved = if single { motion(m, &q, &[[inputs[0][0], 1.0, 0.0]], sys) } else { motion(m, &q, inputs, sys) };
        let cond = solved.as_ref().map_or(f64::INFINITY, |s| {
            let estimate = s.lu.as_ref().filter(|_| !exact).map(|lu| estimated_condition(&s.sys.jacobian, lu));
            match estimate {
                Some(e) if e <= ESTIMATE_LIMIT => e,
                _ => condition(&s.sys.jacobian),
            }
        });
        match solved {
            Some(Solved { qd: a, qdd: b, sys, lu }) if cond <= SINGULAR_CONDITION => {
                let (qd, qdd, g) = if single {
                    let [_, w, alpha] = inputs[0];
                    let qd = a.iter().map(|g| g * w).collect();
                    let qdd = a.iter().zip(&b).map(|(g, h)| g * alpha + h * w * w).collect();
                    coefficients = Some((a.clone(), b, inputs[0][0]));
                    (qd, qdd, Some(a))
                } else {
                    (a, b, None)
                };
                base = q.clone();
                let jacobian = sys.jacobian;
                each(
                    step,
                    Configuration {
                        q,
                        qd,
                        qdd,
                        g,
                        jacobian,
                        lu,
                        condition: cond,
                        iterations,
                        residual,
                        singular: false,
                    },
                )?;
            }
            _ => each(step, Configuration { iterations, residual, ..Configuration::singular_at(q, cond) })?,
        }
    }
    match failure {
        Some(e) => Err(unreachable(m, e)),
        None => Ok(()),
    }
}

impl Configuration {
    fn singular_at(q: Vec<f64>, condition: f64) -> Self {
        let n = q.len();
        let (qd, qdd) = (vec![0.0; n], vec![0.0; n]);
        let jacobian = DMatrix::zeros(0, 0);
        Self { q, qd, qdd, g: None, jacobian, lu: None, condition, iterations: 0, residual: f64::NAN, singular: true }
    }
}

/// Largest change of an input coordinate per continuation step on the way
/// from the drawn configuration to the first position (rad or m).
const APPROACH_STEP: f64 = 0.05;

/// Moves q from the drawn configuration (inputs at their `reference`) to the
/// first requested position in small steps, so the assembly branch drawn is
/// the branch solved.
fn approach(m: &Mechanism, q: &mut [f64], target: &[[f64; 3]]) -> Result<(), EngineError> {
    let from: Vec<f64> = m.drivers.iter().map(|d| d.reference).collect();
    let span = from.iter().zip(target).map(|(a, t)| (t[0] - a).abs()).fold(0.0, f64::max);
    let n = (span / APPROACH_STEP).ceil().min(10_000.0) as usize;
    for k in 1..n {
        let f = k as f64 / n as f64;
        let inputs: Vec<[f64; 3]> = from.iter().zip(target).map(|(a, t)| [a + f * (t[0] - a), 0.0, 0.0]).collect();
        assemble(m, q, &inputs, 0)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Positions reach `each` in order, one at a time, and its error stops
    /// the sweep there: the slider-crank over 8 positions, stopped at the 4th.
    #[test]
    fn a_sweep_hands_over_each_position_and_stops_on_an_error() {
        let m = crate::engine::samples::offset_slider_crank();
        let positions: Vec<Vec<[f64; 3]>> = (0..8).map(|k| vec![[0.5 * k as f64, 1.0, 0.0]]).collect();
        let all = sweep(&m, &positions, &Deadline::none(), false).unwrap();
        let mut seen = Vec::new();
        let stopped = sweep_each(&m, &positions, &Deadline::none(), false, |k, c| {
            seen.push((k, c.q));
            if k == 3 { Err(EngineError::Singular { step: k, input: 0.0 }) } else { Ok(()) }
        });
        assert!(matches!(stopped, Err(EngineError::Singular { step: 3, .. })));
        assert_eq!(seen.iter().map(|(k, _)| *k).collect::<Vec<_>>(), [0, 1, 2, 3]);
        assert!(seen.iter().all(|(k, q)| *q == all[*k].q), "the same configurations as the whole sweep");
    }

    /// A system holding NaN (a state gone bad) has no solution and returns at
    /// once: nalgebra's own SVD never returns on it.
    #[test]
    fn a_system_with_nan_is_unsolvable_not_endless() {
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, f64::NAN, 1.0, 0.0, 2.0]);
        assert!(solve_linear(&a, &DVector::from_element(3, 1.0)).is_none());
        assert_eq!(condition(&a), f64::INFINITY);
    }

    /// Hager's estimate is a lower bound of κ₁ = ‖A‖₁‖A⁻¹‖₁ (the inverse
    /// formed here) and, on these matrices, equal to it or within a factor 3:
    /// K1's Φ_q at 36 crank angles (κ ~ 10), a nearly singular 2×2
    /// (κ₁ = (2 + 1e-6)²/1e-6) and a 7×7 with row exchanges.
    #[test]
    fn the_estimated_condition_bounds_the_1_norm_one() {
        let m = crate::engine::samples::offset_slider_crank();
        let positions: Vec<Vec<[f64; 3]>> = (0..36).map(|k| vec![[k as f64 * 0.17, 1.0, 0.0]]).collect();
        let mut matrices: Vec<DMatrix<f64>> =
            sweep(&m, &positions, &Deadline::none(), true).unwrap().into_iter().map(|c| c.jacobian).collect();
        matrices.push(DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0 + 1e-6]));
        matrices.push(DMatrix::from_fn(7, 7, |i, j| if i == j { 0.0 } else { ((3 * i + 5 * j) as f64).sin() }));
        let norm1 = |a: &DMatrix<f64>| a.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
        for a in matrices {
            let kappa1 = norm1(&a) * norm1(&a.clone().try_inverse().unwrap());
            let estimate = estimated_condition(&a, &a.clone().lu());
            assert!(estimate <= kappa1 * (1.0 + 1e-9) && estimate >= kappa1 / 3.0, "{estimate} vs κ₁ {kappa1}");
        }
    }

    /// The transposed solve from A's factors equals a solve with Aᵀ's own
    /// (a 7×7 matrix with zeros on the diagonal, so rows are exchanged).
    #[test]
    fn the_transposed_solve_matches_factoring_the_transpose() {
        let a =
            DMatrix::from_fn(7, 7, |i, j| if i == j { 0.0 } else { ((3 * i + 5 * j) as f64).sin() + 0.1 * i as f64 });
        let b = DVector::from_fn(7, |k, _| (k as f64).cos());
        let ours = solve_transposed(&a.clone().lu(), &b).unwrap();
        let reference = a.transpose().lu().solve(&b).unwrap();
        assert!((&ours - &reference).amax() < 1e-12 * reference.amax(), "{ours} vs {reference}");
        assert!((a.transpose() * &ours - &b).amax() < 1e-12);
    }
}
