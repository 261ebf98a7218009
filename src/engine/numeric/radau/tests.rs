use super::newton::radau_matrix;
use super::*;
use crate::engine::numeric::ode::Dopri5;

/// Runs `stepper` to `t_end`, checking every step's ends and its dense
/// output between them against `exact`: the largest error of each.
fn run_to<S: Stepper>(s: &mut S, f: &mut impl Rhs, t_end: f64, exact: impl Fn(f64) -> Vec<f64>) -> [f64; 2] {
    let mut worst = [0.0f64; 2];
    while s.time() < t_end {
        let step = s.step(f, 1_000_000).expect("step");
        for th in [0.0, 0.3, 0.7, 1.0] {
            let t = step.t0 + th * (step.t1 - step.t0);
            let (got, want) = (step.at(t), exact(t));
            let k = usize::from(th != 0.0 && th != 1.0);
            worst[k] = got.iter().zip(&want).fold(worst[k], |w, (g, e)| w.max((g - e).abs()));
        }
    }
    worst
}

/// The transcribed constants: T·T⁻¹ = I and T⁻¹A⁻¹T = [γ 0 0; 0 α β; 0 −β α],
/// A the Radau IIA matrix (Hairer & Wanner, Table IV.5.6) inverted here.
#[test]
fn the_transformation_block_diagonalises_the_inverse_of_a() {
    let s6 = 6f64.sqrt();
    let a = nalgebra::Matrix3::from_fn(|i, j| radau_matrix()[i][j]);
    // Collocation: row s of A integrates the Lagrange basis on the nodes up to cₛ, so A·cᵏ⁻¹ = cᵏ/k (k ≤ 3).
    for k in 1..=3 {
        let ck = nalgebra::Vector3::from_fn(|i, _| C[i].powi(k - 1));
        let want = nalgebra::Vector3::from_fn(|i, _| C[i].powi(k) / f64::from(k));
        assert!((a * ck - want).amax() < 1e-15, "order condition k = {k}");
    }
    let t = nalgebra::Matrix3::from_fn(|i, j| T[i][j]);
    let ti = nalgebra::Matrix3::from_fn(|i, j| TI[i][j]);
    let d = ti * a.try_inverse().unwrap() * t;
    let want = nalgebra::Matrix3::new(GAMMA, 0.0, 0.0, 0.0, ALPHA, BETA, 0.0, -BETA, ALPHA);
    assert!((d - want).amax() < 1e-13, "{d}");
    assert!((t * ti - nalgebra::Matrix3::identity()).amax() < 1e-15);
    assert!((C[0] - (4.0 - s6) / 10.0).abs() < 1e-16 && (C[1] - (4.0 + s6) / 10.0).abs() < 1e-16);
    assert!((E[0] + (13.0 + 7.0 * s6) / 3.0).abs() < 1e-14 && (E[1] - (-13.0 + 7.0 * s6) / 3.0).abs() < 1e-14);
}

/// Prothero–Robinson, y' = λ(y − cos t) − sin t, y(0) = 2, λ = −10⁶: the
/// closed form cos t + e^{λt}. Over 10 s at rtol 1e-8 in a few hundred
/// steps (an explicit method needs |hλ| < 3.3: ~3·10⁶ steps): to 1e-7 at
/// the step ends, and to 2e-3 between them — the collocation polynomial's
/// order reduction on a stiff problem (SciPy's Radau here: 151 steps,
/// 1.4e-8 at the ends, 9.1e-4 between). Dormand–Prince, tried on it, says
/// it is stiff.
#[test]
fn a_stiff_linear_problem_matches_its_closed_form_in_few_steps() {
    let lambda = -1e6;
    let mut f = |t: f64, y: &[f64], dy: &mut [f64]| dy[0] = lambda * (y[0] - t.cos()) - t.sin();
    let exact = |t: f64| vec![t.cos() + (lambda * t).exp()];
    let mut s = Radau5::start(&mut f, 0.0, vec![2.0], 1e-8, vec![1e-10]);
    let [ends, between] = run_to(&mut s, &mut f, 10.0, exact);
    assert!(ends < 1e-7 && between < 2e-3, "largest errors {ends}, {between}");
    assert!(s.accepted < 300, "{} steps, {} rejected", s.accepted, s.rejected);

    let mut explicit = Dopri5::new(&mut f, 0.0, vec![2.0], 1e-6, vec![1e-8], f64::INFINITY);
    while !explicit.stiff && explicit.accepted < 100 {
        explicit.step(&mut f, 100_000).expect("step");
    }
    assert!(explicit.stiff, "not detected in {} steps", explicit.accepted);
}

/// x'' = −4x over 6.6 s at rtol 1e-10: cos 2t to 1e-7 at the step ends
/// and on the collocation polynomial between them; Dormand–Prince on it
/// does not call it stiff.
#[test]
fn an_oscillator_matches_the_closed_form_on_the_dense_output() {
    let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| {
        dy[0] = y[1];
        dy[1] = -4.0 * y[0];
    };
    let exact = |t: f64| vec![(2.0 * t).cos(), -2.0 * (2.0 * t).sin()];
    let mut s = Radau5::start(&mut f, 0.0, vec![1.0, 0.0], 1e-10, vec![1e-12; 2]);
    let [ends, between] = run_to(&mut s, &mut f, 6.6, exact);
    assert!(ends < 1e-7 && between < 1e-7, "largest errors {ends}, {between}");
    let mut explicit = Dopri5::new(&mut f, 0.0, vec![1.0, 0.0], 1e-10, vec![1e-12; 2], f64::INFINITY);
    run_to(&mut explicit, &mut f, 6.6, exact);
    assert!(!explicit.stiff && explicit.accepted > 20);
}

/// Robertson's chemical kinetics (rates 0.04, 10⁴, 3·10⁷) from (1, 0, 0) to
/// t = 40: Hairer & Wanner's reference (*Solving ODEs II*, §IV.10;
/// 0.7158270687193, 0.9185534764557e-5, 0.2841637457460 — SciPy's LSODA
/// and BDF at rtol 1e-12 give the same) to 1e-6 relative at rtol 1e-9, and
/// y₁ + y₂ + y₃ = 1 kept (a linear invariant every Runge–Kutta method
/// keeps), in about SciPy's number of steps (its Radau: 471).
#[test]
fn robertson_reaches_the_published_reference() {
    let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| {
        dy[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        dy[1] = 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] * y[1];
        dy[2] = 3e7 * y[1] * y[1];
    };
    let mut s = Radau5::start(&mut f, 0.0, vec![1.0, 0.0, 0.0], 1e-9, vec![1e-12, 1e-16, 1e-12]);
    let mut y = vec![];
    while s.time() < 40.0 {
        let step = s.step(&mut f, 100_000).expect("step");
        y = step.at(40f64.min(step.t1));
    }
    let want = [0.7158270687193, 0.9185534764557e-5, 0.2841637457460];
    for (got, want) in y.iter().zip(want) {
        assert!((got / want - 1.0).abs() < 1e-6, "{y:?}");
    }
    assert!((y.iter().sum::<f64>() - 1.0).abs() < 1e-12, "{y:?}");
    assert!(s.accepted < 600, "{} steps", s.accepted);
}

/// A stiff direction that turns: y' = R(Ωt)·diag(−10⁴, −1)·R(Ωt)ᵀ·(y − g) + g′,
/// Ω = 2π, g = (cos t, sin 2t), from g(0) + (0.1, 0.1) over 2 s at rtol
/// 1e-8. In the turning frame u = Rᵀ(y − g) the equation is constant,
/// u′ = (D − ΩS)·u (S the quarter turn), so y = g + R·exp((D − ΩS)t)·u₀
/// by nalgebra's matrix exponential, a second method: to 1e-7 at the step
/// ends, as the Prothero–Robinson problem above (1.3e-10 measured, in
/// 264 steps). One J for the three
/// stages does not contract here once hΩ·10⁴·h/γ passes 1 (h past 0.02 s,
/// with the smooth g asking for steps about ten times that); the stages'
/// own Jacobians do, through GMRES. An explicit method needs h < 3.3·10⁻⁴
/// (6000 steps): a few hundred are the implicit method's.
#[test]
fn a_turning_stiff_direction_matches_its_closed_form() {
    use nalgebra::{Matrix2, Vector2};
    let omega = 2.0 * std::f64::consts::PI;
    let d = Matrix2::new(-1e4, 0.0, 0.0, -1.0);
    let turn = |t: f64| nalgebra::Rotation2::new(omega * t).into_inner();
    let g = |t: f64| Vector2::new(t.cos(), (2.0 * t).sin());
    let mut f = |t: f64, y: &[f64], dy: &mut [f64]| {
        let r = turn(t);
        let v =
            r * d * r.transpose() * (Vector2::new(y[0], y[1]) - g(t)) + Vector2::new(-t.sin(), 2.0 * (2.0 * t).cos());
        dy.copy_from_slice(v.as_slice());
    };
    let quarter = Matrix2::new(0.0, -1.0, 1.0, 0.0);
    let u0 = Vector2::new(0.1, 0.1);
    let exact = |t: f64| (g(t) + turn(t) * ((d - quarter * omega) * t).exp() * u0).as_slice().to_vec();
    let mut s = Radau5::start(&mut f, 0.0, vec![1.1, 0.1], 1e-8, vec![1e-10; 2]);
    let [ends, _] = run_to(&mut s, &mut f, 2.0, exact);
    assert!(ends < 1e-7, "largest error {ends}");
    assert!(s.accepted < 600, "{} steps, {} rejected, {} evaluations", s.accepted, s.rejected, s.evaluations);
}

/// An f that turns non-finite (as after a spent budget) ends the step with
/// an error instead of looping.
#[test]
fn a_non_finite_derivative_is_an_error() {
    let mut f = |t: f64, y: &[f64], dy: &mut [f64]| dy[0] = if t > 1.0 { f64::NAN } else { -y[0] };
    let mut s = Radau5::start(&mut f, 0.0, vec![1.0], 1e-6, vec![1e-8]);
    let result = (0..1000).map(|_| s.step(&mut f, 100_000)).find(|r| r.is_err());
    assert!(matches!(result, Some(Err(OdeError::NotFinite { .. } | OdeError::StepTooSmall { .. }))), "{result:?}");
}
