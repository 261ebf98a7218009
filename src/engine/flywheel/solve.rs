//! The flywheel calculation from a validated problem to its solution.

use super::check::{Check, simulate};
use super::cycle::{Cycle, Samples, Term};
use super::lobes::{Lobes, crossings, lobes};
use super::wittenbauer::{Exact, exact};
use super::{
    Accuracy, Condition, Disk, DiskSize, DiskSpec, FlywheelProblem, FlywheelSolution, Load, Pair, SamplePoint,
};
use crate::engine::function::Side;
use crate::engine::numeric::minimum::brent_min;
use crate::engine::{EngineError, Phase, Progress};
use std::f64::consts::PI;

/// How closely I*'s least is found (relative to the cycle's period, in φ).
const LEAST_TOLERANCE: f64 = 1e-10;

/// min I*(φ) over the cycle: at a piece's ends, or where I*′ turns from
/// negative to positive between two samples (refined there by Brent's
/// method); I*(0) where I* is constant (no slopes sampled).
pub(crate) fn least_inertia(cycle: &Cycle, samples: &Samples) -> f64 {
    let at = |phi: f64, side: Side| cycle.inertia_at(phi, side);
    let mut least = f64::INFINITY;
    for ((angles, _), slopes) in samples.pieces.iter().zip(&samples.slopes) {
        let (Some(&first), Some(&last)) = (angles.first(), angles.last()) else { continue };
        least = least.min(at(first, Side::Right)).min(at(last, Side::Left));
        for (k, pair) in slopes.windows(2).enumerate() {
            if pair[0] < 0.0 && pair[1] >= 0.0 {
                let (a, b) = (angles[k], angles[k + 1]);
                let mid = 0.5 * (a + b);
                let f = |phi: f64| at(phi.clamp(a, b), Side::Right);
                least = least.min(brent_min(f, [a, b], mid, f(mid), LEAST_TOLERANCE * (b - a).max(1e-300)).1);
            }
        }
    }
    if least.is_finite() { least } else { at(0.0, Side::Right) }
}

/// Net cycle work tolerated without a balance torque, relative to the largest area.
pub const NET_WORK_TOLERANCE: f64 = 1e-6;

/// Solves a flywheel problem; see the module docs of [`super`] for the symbols.
/// A solution finished past the deadline is not returned: machine functions
/// answer NaN once it has passed.
pub fn solve(p: &FlywheelProblem) -> Result<FlywheelSolution, EngineError> {
    let phase = std::cell::Cell::new(Phase::Sampling);
    let d = &p.deadline;
    let progress = || Progress::Flywheel(phase.get());
    let solution = phases(p, &|next| {
        d.check(progress)?;
        phase.set(next);
        Ok(())
    });
    match solution {
        Ok(s) => d.check(|| Progress::Late).map(|()| s),
        Err(e) => Err(d.explain(e, progress)),
    }
}

/// The solution phase by phase; `next` is called between them with the next
/// one and stops the solution when it fails.
fn phases(
    p: &FlywheelProblem,
    next: &dyn Fn(Phase) -> Result<(), EngineError>,
) -> Result<FlywheelSolution, EngineError> {
    let terms = p
        .torques
        .iter()
        .filter_map(|t| match &t.load {
            Load::Given(f) => Some(Term { f, ratio: t.ratio, label: &t.label }),
            Load::Balance => None,
        })
        .collect();
    let inertia = (&p.reduced_inertia, p.reduced_inertia_label.as_str());
    let mut cycle = Cycle::new(terms, inertia, p.period, 0.1 * p.tolerance, p.deadline);
    let mut samples = cycle.sample()?;
    cycle.abs_tol_per_rad = 0.1 * p.tolerance * samples.abs_work.max(f64::MIN_POSITIVE) / p.period;
    next(Phase::Work)?;
    let (item_work, balance_torque, mut evaluations) = item_works(p, &mut cycle, &mut samples);
    next(Phase::Crossings)?;
    let lobes = lobes(&cycle, crossings(&cycle, &samples));
    let mut warnings = Vec::new();
    check_steady_state(p, &item_work, &lobes, &mut warnings)?;
    let (omega_a, eps) = (p.mean_speed, p.irregularity);
    next(Phase::Exact)?;
    let ex = exact(&cycle, &samples, &lobes, eps, omega_a);
    let inertia_approximate = lobes.energy_fluctuation / (eps * omega_a * omega_a);
    // An irregularity or speed at the edge of double precision (ε = 1e-308) overflows
    // the inertia: said here, not carried into the time check.
    if !(inertia_approximate.is_finite() && ex.inertia.is_finite()) {
        return Err(EngineError::NotFiniteResult);
    }
    // I*'s least: the machine's inertia there at every angle (a pulley's), part of the total as
    // `existing_inertia` is, and taken off the total as it is for what the flywheel adds.
    let least = least_inertia(&cycle, &samples);
    let flywheel = |i: f64| (i - p.existing_inertia) / (p.flywheel_ratio * p.flywheel_ratio);
    let flywheel_inertia = Pair { approximate: flywheel(inertia_approximate - least), exact: flywheel(ex.inertia) };
    let speed = SpeedLaw { cycle: &cycle, ex: &ex, omega_a };
    let omega_at_start = speed.omega(0.0, 0.0, Side::Right);
    next(Phase::TimeCheck)?;
    let check = run_check(p, &cycle, &ex, omega_at_start, &mut warnings);
    if ex.degenerate {
        warnings.push(Condition::Degenerate);
    }
    let shaft_speed = p.flywheel_ratio.abs() * omega_a;
    let disk = p.disk.and_then(|d| size_disk(d, flywheel_inertia.exact, shaft_speed, &mut warnings));
    next(Phase::Table)?;
    let table = sample_table(p, &speed);
    let quadrature_error = lobes.quadrature.error + ex.quadrature.error + table.1;
    evaluations += lobes.quadrature.evaluations + ex.quadrature.evaluations;
    let scale = lobes.energy_fluctuation.max(lobes.areas.iter().map(|a| a.work.abs()).fold(0.0, f64::max));
    let (half, total_at_start) = (eps / 2.0, ex.inertia + cycle.inertia_at(0.0, Side::Right));
    let solution = FlywheelSolution {
        balance_torque,
        mean_power: omega_a / p.period * item_work.iter().filter(|w| **w > 0.0).sum::<f64>(),
        item_work,
        crossings: lobes.crossings.clone(),
        areas: lobes.areas.clone(),
        cumulative: lobes.cumulative.clone(),
        energy_fluctuation: lobes.energy_fluctuation,
        inertia_approximate,
        inertia_exact: ex.inertia + least,
        least_reduced_inertia: least,
        flywheel_inertia,
        omega_max: if ex.degenerate { omega_a } else { omega_a * (1.0 + half) },
        omega_min: if ex.degenerate { omega_a } else { omega_a * (1.0 - half) },
        phi_at_omega_max: ex.phi_omega_max,
        phi_at_omega_min: ex.phi_omega_min,
        omega_at_start,
        kinetic_energy_at_start: 0.5 * total_at_start * omega_at_start * omega_at_start,
        accuracy: Accuracy {
            estimated_relative_error: (if scale > 0.0 { quadrature_error / scale } else { 0.0 })
                .max(ex.rounding + ex.per_joule * (lobes.quadrature.error + ex.quadrature.error)),
            quadrature_error,
            function_evaluations: evaluations + check.map_or(0, |c| c.evaluations),
            check_relative_difference: check
                .map(|c| ((c.irregularity - eps).abs() / eps).max((c.mean_speed - omega_a).abs() / omega_a)),
        },
        check,
        disk,
        samples: table.0,
        warnings,
    };
    ensure_finite(&solution)?;
    Ok(solution)
}

/// Cycle work of every item (reduced), solving the balance torque if there is one.
fn item_works(p: &FlywheelProblem, cycle: &mut Cycle, samples: &mut Samples) -> (Vec<f64>, Option<f64>, usize) {
    let mut evaluations = 0;
    let mut works: Vec<Option<f64>> = p
        .torques
        .iter()
        .map(|t| match &t.load {
            Load::Given(f) => {
                let i = cycle.integrate(f, 0.0, p.period);
                evaluations += i.evaluations;
                Some(t.ratio * i.value)
            }
            Load::Balance => None,
        })
        .collect();
    let net: f64 = works.iter().flatten().sum();
    let mut balance_torque = None;
    for (w, t) in works.iter_mut().zip(&p.torques) {
        if w.is_none() {
            let reduced = -net / p.period;
            balance_torque = Some(reduced / t.ratio);
            *w = Some(-net);
            cycle.balance = reduced;
            for (_, ys) in &mut samples.pieces {
                ys.iter_mut().for_each(|y| *y += reduced);
            }
            samples.max_abs_torque = samples.pieces.iter().flat_map(|(_, ys)| ys).fold(0.0, |m, y| m.max(y.abs()));
        }
    }
    (works.into_iter().flatten().collect(), balance_torque, evaluations)
}

fn check_steady_state(
    p: &FlywheelProblem,
    item_work: &[f64],
    lobes: &Lobes,
    warnings: &mut Vec<Condition>,
) -> Result<(), EngineError> {
    if p.torques.iter().any(|t| matches!(t.load, Load::Balance)) {
        return Ok(());
    }
    let net: f64 = item_work.iter().sum();
    let largest = lobes.areas.iter().map(|a| a.work.abs()).fold(0.0, f64::max);
    if net.abs() > NET_WORK_TOLERANCE * largest {
        return Err(EngineError::NotSteady { net_work: net, largest_area: largest });
    }
    if net != 0.0 {
        warnings.push(Condition::NetWork { net });
    }
    Ok(())
}

/// ω(φ) = ω_a·√z with z = (F + C)/(I + I*), F = (2/ω_a²)·W.
struct SpeedLaw<'a> {
    cycle: &'a Cycle<'a>,
    ex: &'a Exact,
    omega_a: f64,
}

impl SpeedLaw<'_> {
    fn omega(&self, phi: f64, work: f64, side: Side) -> f64 {
        if self.ex.degenerate {
            return self.omega_a;
        }
        let f = 2.0 * work / (self.omega_a * self.omega_a);
        let z = (f + self.ex.c) / (self.ex.inertia + self.cycle.inertia_at(phi, side));
        self.omega_a * z.max(0.0).sqrt()
    }
}

fn run_check(
    p: &FlywheelProblem,
    cycle: &Cycle,
    ex: &Exact,
    omega0: f64,
    warnings: &mut Vec<Condition>,
) -> Option<Check> {
    if !p.check || ex.degenerate {
        return None;
    }
    let rtol = (0.01 * p.tolerance).clamp(1e-13, 1e-6);
    match simulate(cycle, (ex.inertia, omega0, p.mean_speed), rtol, &p.deadline) {
        Ok(c) => Some(c),
        Err(e) => {
            warnings.push(Condition::CheckIncomplete(e));
            None
        }
    }
}

/// Sizes a solid disk holding `inertia` on a shaft turning at `omega` (mean).
fn size_disk(spec: DiskSpec, inertia: f64, omega: f64, warnings: &mut Vec<Condition>) -> Option<Disk> {
    if inertia <= 0.0 {
        warnings.push(Condition::NoDisk { inertia });
        return None;
    }
    let radius = match (spec.size, spec.density) {
        (DiskSize::RimSpeed(v), _) => v / omega,
        (DiskSize::Radius(r), _) => r,
        (DiskSize::Thickness(e), Some(rho)) => (2.0 * inertia / (rho * PI * e)).powf(0.25),
        // The request asks a density with a thickness.
        (DiskSize::Thickness(_), None) => return None,
    };
    let mass = 2.0 * inertia / (radius * radius);
    let thickness = spec.density.map(|rho| mass / (rho * PI * radius * radius));
    Some(Disk { mass, radius, thickness, rim_speed: radius * omega })
}

/// The sampled table (angle, M*, I*, W, ω) and its quadrature error.
fn sample_table(p: &FlywheelProblem, speed: &SpeedLaw) -> (Vec<SamplePoint>, f64) {
    if p.samples == 0 {
        return (Vec::new(), 0.0);
    }
    let n = p.samples.max(2);
    let angles: Vec<f64> = (0..n).map(|i| p.period * i as f64 / (n - 1) as f64).collect();
    let (works, q) = speed.cycle.work_at(&angles);
    // Past the budget the rest are not made (the solution is then refused as late).
    let rows = angles
        .iter()
        .zip(works)
        .enumerate()
        .take_while(|(i, _)| i % 256 != 0 || !p.deadline.expired())
        .map(|(_, (&angle, work))| {
            // The last row closes the cycle: values as φ → period from below.
            let side = if angle < p.period { Side::Right } else { Side::Left };
            SamplePoint {
                angle,
                reduced_torque: speed.cycle.torque(angle, side),
                reduced_inertia: speed.cycle.inertia_at(angle, side),
                work,
                speed: speed.omega(angle, work, side),
            }
        })
        .collect();
    (rows, q.error)
}

fn ensure_finite(s: &FlywheelSolution) -> Result<(), EngineError> {
    let scalars = [
        s.mean_power,
        s.energy_fluctuation,
        s.inertia_approximate,
        s.inertia_exact,
        s.least_reduced_inertia,
        s.flywheel_inertia.approximate,
        s.flywheel_inertia.exact,
        s.omega_max,
        s.omega_min,
        s.omega_at_start,
        s.kinetic_energy_at_start,
        s.balance_torque.unwrap_or(0.0),
        s.accuracy.estimated_relative_error,
    ];
    let lists = s.cumulative.iter().chain(&s.crossings).chain(&s.item_work);
    let rows = s.samples.iter().flat_map(|r| [r.reduced_torque, r.reduced_inertia, r.work, r.speed]);
    let disk = s.disk.iter().flat_map(|d| [d.mass, d.radius, d.thickness.unwrap_or(0.0), d.rim_speed]);
    if scalars.iter().chain(lists).copied().chain(rows).chain(disk).all(f64::is_finite) {
        Ok(())
    } else {
        Err(EngineError::NotFiniteResult)
    }
}
