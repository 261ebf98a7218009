//! The dynamics request read: the settings both forms share, the reduced
//! form, the machine and how the run ends, every error at its pointer.

use super::machine::Report;
use super::space::SpatialReport;
use super::{DEFAULT_MAX_DURATION, DEFAULT_SAMPLES, DynamicsMachine, DynamicsRequest, IntegratorChoice, MAX_DURATION};
use crate::engine::Deadline;
use crate::engine::dynamics::mechanism::MechanismProblem;
use crate::engine::dynamics::{End, KEPT_BYTES, ReducedProblem};
use crate::engine::function::Function;
use crate::engine::spatial::dynamics::SpatialProblem;
use crate::i18n::Msg;
use crate::kind::constants;
use crate::kind::limits::Limits;
use crate::kind::problem::FieldError;
use crate::kind::quantity::{Errors, Quantity};
use crate::units::Dim;
use std::f64::consts::PI;

/// A validated request.
pub(super) enum Problem {
    Reduced(ReducedProblem),
    /// With the joint and body names.
    /// The mechanism problem, and what its result reports beside the solution.
    Machine(MechanismProblem, Report),
    /// A mechanism in space, and what its result reports.
    Spatial(SpatialProblem, SpatialReport),
}

/// The settings both forms share, validated (defaults stand in for invalid
/// values: the errors then discard the problem).
struct Common {
    period: f64,
    tolerance: f64,
    samples: usize,
    /// The job's compute budget, counted from the start of the conversion.
    deadline: Deadline,
}

impl DynamicsRequest {
    pub(super) fn to_problem(&self, limits: &Limits) -> Result<Problem, Vec<FieldError>> {
        let mut e = Errors::new(limits);
        constants::read(self.constants.as_ref(), &mut e);
        let c = self.common(&mut e);
        let reduced = !self.torques.is_empty() || self.reduced_inertia.is_some();
        let problem = match (&self.machine, reduced) {
            (Some(m), false) => self.machine_problem(&mut e, m, &c),
            (None, true) => self.reduced_problem(&mut e, &c),
            (Some(_), true) => {
                let form = if self.torques.is_empty() { "/reduced_inertia" } else { "/torques" };
                e.say("/machine", Msg::new("dynamics-machine-or-reduced"));
                e.refuse(form, Msg::new("dynamics-reduced-or-machine"))
            }
            (None, false) => e.refuse("/machine", Msg::new("dynamics-machine-required")),
        };
        match problem {
            Some(problem) if e.list.is_empty() => Ok(problem),
            _ => Err(e.list),
        }
    }

    fn common(&self, e: &mut Errors) -> Common {
        let period = match &self.period {
            Some(q) => {
                let p = e.angle(q, "/period");
                e.require_said(p, |p| p > 0.0, "/period", Msg::new("field-positive"))
            }
            None => None,
        };
        let tolerance = match self.tolerance {
            Some(t) if !(1e-14..=1e-2).contains(&t) => {
                e.refuse("/tolerance", Msg::new("field-between").arg("min", "1e-14").arg("max", "1e-2"))
            }
            t => t,
        };
        let max = e.limits.samples;
        let samples = match self.samples {
            Some(n) if !(2..=max).contains(&n) => e.refuse("/samples", Msg::new("dynamics-samples").arg("max", max)),
            n => n,
        };
        Common {
            period: period.unwrap_or(2.0 * PI),
            tolerance: tolerance.unwrap_or(1e-9),
            samples: samples.unwrap_or(DEFAULT_SAMPLES),
            deadline: e.limits.deadline(),
        }
    }

    fn reduced_problem(&self, e: &mut Errors, c: &Common) -> Option<Problem> {
        let period = c.period;
        if self.torques.is_empty() || self.torques.len() > 100 {
            e.say("/torques", Msg::new("dynamics-torques-count").arg("max", 100));
        }
        let torques: Vec<Option<(Function, f64)>> = self
            .torques
            .iter()
            .enumerate()
            .map(|(i, t)| {
                e.short(&t.name, 200, &format!("/torques/{i}/name"));
                let ratio = match t.ratio {
                    Some(k) if !(k.is_finite() && k != 0.0) => {
                        e.refuse(&format!("/torques/{i}/ratio"), Msg::new("field-finite-nonzero"))
                    }
                    k => Some(k.unwrap_or(1.0)),
                };
                let f = e.function_of(
                    &t.value,
                    Dim::TORQUE,
                    period,
                    &format!("/torques/{i}/value"),
                    &["phi", "omega", "t"],
                );
                Some((f?, ratio?))
            })
            .collect();
        let inertia = match &self.reduced_inertia {
            Some(f) => e
                .function(f, Dim::INERTIA, period, "/reduced_inertia")
                .and_then(|f| e.differentiable(&f, 1, "/reduced_inertia").map(|()| f)),
            None => e.refuse("/reduced_inertia", Msg::new("dynamics-inertia-required")),
        };
        let initial = self.initial.as_ref();
        let angle0 = initial.and_then(|i| i.angle.as_ref()).map_or(Some(0.0), |q| e.angle(q, "/initial/angle"));
        let speed0 = initial
            .and_then(|i| i.speed.as_ref())
            .map_or(Some(0.0), |q| e.quantity(q, Dim::ANGULAR_SPEED, "/initial/speed"));
        let end = self.end(e, angle0.unwrap_or(0.0));
        let torques: Option<Vec<_>> = torques.into_iter().collect();
        Some(Problem::Reduced(ReducedProblem {
            torques: torques?,
            inertia: inertia?,
            period,
            angle0: angle0?,
            speed0: speed0?,
            end: end?,
            tolerance: c.tolerance,
            integrator: IntegratorChoice::engine(self.integrator),
            samples: c.samples,
            kept_bytes: KEPT_BYTES,
            deadline: c.deadline,
        }))
    }

    fn machine_problem(&self, e: &mut Errors, m: &DynamicsMachine, c: &Common) -> Option<Problem> {
        if m.mechanism.is_spatial() {
            return self.spatial_problem(e, m, c);
        }
        let parts = m.convert(e, self.initial.as_ref(), c.period);
        let angle0 = parts.as_ref().and_then(|p| p.initial.first()).map_or(0.0, |s| s[0]);
        let end = self.end(e, angle0)?;
        let parts = parts?;
        let problem = MechanismProblem {
            mechanism: parts.mechanism,
            loads: parts.loads,
            period: c.period,
            initial: parts.initial,
            end,
            tolerance: c.tolerance,
            integrator: IntegratorChoice::engine(self.integrator),
            conserve_energy: m.conserve_energy,
            samples: c.samples,
            kept_bytes: KEPT_BYTES,
            deadline: c.deadline,
            reactions: m.reactions.unwrap_or(true),
            motion: !parts.report.tracked.is_empty(),
        };
        Some(Problem::Machine(problem, parts.report))
    }

    fn spatial_problem(&self, e: &mut Errors, m: &DynamicsMachine, c: &Common) -> Option<Problem> {
        let parts = m.spatial(e, self.initial.as_ref(), c.period);
        let angle0 = parts.as_ref().and_then(|p| p.initial.first()).map_or(0.0, |s| s[0]);
        let end = self.end(e, angle0)?;
        let parts = parts?;
        let problem = SpatialProblem {
            mechanism: parts.mechanism,
            loads: parts.loads,
            period: c.period,
            reference: parts.reference,
            initial: parts.initial,
            end,
            tolerance: c.tolerance,
            integrator: IntegratorChoice::engine(self.integrator),
            samples: c.samples,
            deadline: c.deadline,
            reactions: m.reactions.unwrap_or(true),
        };
        Some(Problem::Spatial(problem, parts.report))
    }

    fn end(&self, e: &mut Errors, angle0: f64) -> Option<End> {
        let time = |e: &mut Errors, q: &Quantity, at: &str| {
            let t = e.positive(q, Dim::TIME, at);
            e.require_said(t, |t| t <= MAX_DURATION, at, Msg::new("dynamics-at-most-seconds").num("max", MAX_DURATION))
        };
        match (&self.duration, &self.until_angle) {
            (Some(_), None) if self.max_duration.is_some() => {
                e.refuse("/max_duration", Msg::new("dynamics-max-duration"))
            }
            (Some(d), None) => time(e, d, "/duration").map(End::Duration),
            (None, Some(a)) => {
                let angle = e.angle(a, "/until_angle")?;
                if angle == angle0 {
                    return e.refuse("/until_angle", Msg::new("dynamics-until-initial"));
                }
                let max_time = match &self.max_duration {
                    Some(q) => time(e, q, "/max_duration")?,
                    None => DEFAULT_MAX_DURATION,
                };
                Some(End::UntilAngle { angle, max_time })
            }
            (Some(_), Some(_)) => {
                e.say("/duration", Msg::new("dynamics-duration-or-angle"));
                e.refuse("/until_angle", Msg::new("dynamics-angle-or-duration"))
            }
            (None, None) => e.refuse("/duration", Msg::new("dynamics-duration-required")),
        }
    }
}
