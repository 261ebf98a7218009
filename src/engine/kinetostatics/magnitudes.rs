//! The magnitudes of the joints' friction at a position: λ linear in
//! them (a solve per moving joint with friction), then a fixed point over
//! scalars ([`friction`]'s symbols).

use super::locking::{self, Pressing};
use super::multipliers::{Magnitudes, PerUnit, Scratch, driving_actions, multipliers, read_out, solve_transposed};
use super::reactions::reaction_of;
use super::{Reaction, friction};
use crate::engine::kinematics::Configuration;
use crate::engine::model::Mechanism;
use crate::engine::{Deadline, EngineError, Progress};

/// Moving joints with friction up to which λ is made linear in their
/// magnitudes (a solve each, then a fixed point over scalars); with more,
/// each pass of the fixed point is one solve for all of them.
const COUPLED_UNITS: usize = 4;

/// Adds the joints' friction to Q (`s.qv`) and takes it from M q̈ − Q
/// (`s.inertial`), with the driving actions and every reaction (each with
/// its friction) into `out` ([`friction`]): the fixed point's passes. The
/// passes read only what presses each joint with friction; every reaction
/// is read once, from the last λ.
pub(super) fn with_friction(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    indeterminate: &[usize],
    at: (usize, f64),
    deadline: &Deadline,
    out: (&mut Vec<f64>, &mut Vec<Reaction>),
) -> Result<usize, EngineError> {
    let scale = c.qdd.iter().enumerate().map(|(i, a)| (a * m.mass_of(i)).abs());
    let tol = 1e-13 * scale.chain(s.qv.iter().map(|q| q.abs())).fold(f64::MIN_POSITIVE, f64::max);
    // λ₀ of the loads alone; a_k of each moving joint with friction.
    solve_transposed(c, s.actuated.as_ref(), s.inertial.iter().map(|v| -v), &mut s.lambda0, at)?;
    let (mut units, mut per) = (std::mem::take(&mut s.units), std::mem::take(&mut s.per_unit));
    friction::units(m, c, &mut units);
    per.resize_with(units.len(), Default::default);
    for (unit, p) in units.iter().zip(per.iter_mut()) {
        p.a.clear();
        p.a.resize(s.qv.len(), 0.0);
        unit.add_generalized(m, c, 1.0, &mut p.a);
    }
    let mut loads = std::mem::take(&mut s.loads);
    unit_reactions(m, c, (&s.offsets, &units), &s.lambda0, &mut s.driving, &mut loads);
    let mut coupled = units.len() <= COUPLED_UNITS;
    let mut magnitudes = std::mem::take(&mut s.magnitudes);
    let passes = if coupled {
        linear(m, c, s, (&units, &mut per), &loads, (tol, deadline, &mut magnitudes), at)
    } else {
        iterated(m, c, s, (&units, &per), &loads, (tol, deadline, &mut magnitudes), at)
    };
    let passes = passes.and_then(|settled| match settled {
        Ok(passes) => Ok(passes),
        Err(passes) => {
            if !coupled {
                unit_solves(m, c, s, (&units, &mut per), at)?;
                coupled = true;
            }
            let pressing = Pressing { units: &units, loads: &loads, per: &per, sizes: &magnitudes.sizes };
            match locking::continued(&pressing, &mut magnitudes.f, (tol, deadline, at.0))? {
                Ok(iterations) => Ok(passes + iterations),
                Err(limit) => Err(EngineError::FrictionDiverged { step: at.0, input: at.1, limit }),
            }
        }
    });
    s.loads = loads;
    let f = &magnitudes.f;
    let result = passes.and_then(|passes| {
        for (p, f) in per.iter().zip(f) {
            s.qv.iter_mut().zip(&p.a).for_each(|(q, a)| *q += f * a);
            s.inertial.iter_mut().zip(&p.a).for_each(|(q, a)| *q -= f * a);
        }
        if coupled {
            // λ = λ₀ + Σ f_k y_k.
            s.lambda.clone_from(&s.lambda0);
            for (p, f) in per.iter().zip(f) {
                s.lambda.iter_mut().zip(&p.y).for_each(|(l, y)| *l += f * y);
            }
            read_out(m, c, s, Some(indeterminate), (&mut *out.0, &mut *out.1));
        } else {
            multipliers(m, c, s, Some(indeterminate), at, (&mut *out.0, &mut *out.1))?;
        }
        for (unit, f) in units.iter().zip(f) {
            unit.add_to(*f, &mut out.1[unit.joint]);
        }
        Ok(passes)
    });
    (s.units, s.per_unit, s.magnitudes) = (units, per, magnitudes);
    result
}

/// The normal reactions of the joints with friction (`units`, in their
/// order) from multipliers `lambda`, into `out`; `driving` is scratch.
fn unit_reactions(
    m: &Mechanism,
    c: &Configuration,
    (offsets, units): (&[usize], &[friction::Unit]),
    lambda: &[f64],
    driving: &mut Vec<f64>,
    out: &mut Vec<Reaction>,
) {
    driving_actions(m, lambda, driving);
    let efforts = (&c.jacobian, lambda, driving.as_slice());
    out.clear();
    out.extend(units.iter().map(|u| reaction_of(m, (&c.q, &c.trig), efforts, offsets, u.joint)));
}

/// y_k of every unit (Φ_qᵀ y_k = a_k) and what it presses the joints with.
fn unit_solves(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    (units, per): (&[friction::Unit], &mut [PerUnit]),
    at: (usize, f64),
) -> Result<(), EngineError> {
    for p in per.iter_mut() {
        solve_transposed(c, s.actuated.as_ref(), p.a.iter().copied(), &mut p.y, at)?;
        unit_reactions(m, c, (&s.offsets, units), &p.y, &mut s.driving, &mut p.reactions);
    }
    Ok(())
}

/// The magnitudes with λ linear in them: y_k and what it presses the joints
/// with solved once per joint, then f_k = g_k(R_k(λ₀) + Σ_j f_j R_k(y_j))
/// over scalars.
fn linear(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    (units, per): (&[friction::Unit], &mut [PerUnit]),
    loads: &[Reaction],
    (tol, deadline, magnitudes): (f64, &Deadline, &mut Magnitudes),
    at: (usize, f64),
) -> Result<Settled, EngineError> {
    unit_solves(m, c, s, (units, per), at)?;
    let pressing = Pressing { units, loads, per, sizes: &[] };
    fixed_point(per, (tol, deadline, magnitudes), at.0, |f, next| {
        units.iter().enumerate().for_each(|(k, unit)| next[k] = unit.magnitude(&pressing.on(k, f, 1.0)));
        Ok(())
    })
}

/// The magnitudes where each pass solves for λ with the last pass's
/// friction (the first is the loads' alone, solved already).
fn iterated(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    (units, per): (&[friction::Unit], &[PerUnit]),
    loads: &[Reaction],
    (tol, deadline, magnitudes): (f64, &Deadline, &mut Magnitudes),
    at: (usize, f64),
) -> Result<Settled, EngineError> {
    let (mut b, mut reactions) = (Vec::new(), Vec::new());
    fixed_point(per, (tol, deadline, magnitudes), at.0, |f, next| {
        let solved = if f.iter().all(|f| *f == 0.0) {
            loads
        } else {
            // Φ_qᵀλ = −(M q̈ − Q − Σ f_k a_k).
            b.clear();
            b.extend(s.inertial.iter().map(|v| -v));
            for (p, f) in per.iter().zip(f) {
                b.iter_mut().zip(&p.a).for_each(|(b, a)| *b += f * a);
            }
            solve_transposed(c, s.actuated.as_ref(), b.iter().copied(), &mut s.lambda, at)?;
            unit_reactions(m, c, (&s.offsets, units), &s.lambda, &mut s.driving, &mut reactions);
            &reactions[..]
        };
        units.iter().zip(solved).zip(next.iter_mut()).for_each(|((unit, r), next)| *next = unit.magnitude(r));
        Ok(())
    })
}

/// Ok(passes) where the fixed point settled, Err(passes) where it does not
/// contract fast enough to.
type Settled = Result<usize, usize>;

/// A pass that shrinks the change by less than this hands the magnitudes
/// to [`locking`] (the passes to 1e-13 would be too many, or diverge).
const SLOW: f64 = 0.5;

/// f from 0 by `pass` (g(f) into its second argument) until no f_k·|a_k|∞
/// changes by more than `tol`: f in `magnitudes.f`, and the passes.
fn fixed_point(
    per: &[PerUnit],
    (tol, deadline, magnitudes): (f64, &Deadline, &mut Magnitudes),
    step: usize,
    mut pass: impl FnMut(&[f64], &mut [f64]) -> Result<(), EngineError>,
) -> Result<Settled, EngineError> {
    let Magnitudes { f, next, sizes } = magnitudes;
    sizes.clear();
    sizes.extend(per.iter().map(|p| p.a.iter().fold(0.0f64, |a, v| a.max(v.abs()))));
    for v in [&mut *f, &mut *next] {
        v.clear();
        v.resize(per.len(), 0.0);
    }
    let mut last = f64::INFINITY;
    for passes in 1..=friction::MAX_ITERATIONS {
        // The clock read every 8th pass (most positions take one or two;
        // a read was 1.4 % of the library cam's position).
        if passes % 8 == 0 {
            deadline.check(|| Progress::Friction { step })?;
        }
        pass(f, next)?;
        let change =
            f.iter().zip(next.iter()).zip(sizes.iter()).map(|((a, b), s)| (a - b).abs() * s).fold(0.0, f64::max);
        std::mem::swap(f, next);
        if change <= tol {
            return Ok(Ok(passes));
        }
        // A NaN change (a diverging pass) is slow too.
        if passes >= 3 && (change >= SLOW * last || change.is_nan()) {
            return Ok(Err(passes));
        }
        last = change;
    }
    Ok(Err(friction::MAX_ITERATIONS))
}
