//! The `result` of a dynamics job, as stored and served, and its CSV table.

use super::{IntegratorChoice, MachineDynamics};
use crate::engine::dynamics::{DynamicsSolution, EventKind, KEPT_BYTES};
use crate::kind::{list, names};
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// One sample of the motion.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(as = DynamicsSample)]
pub struct SampleDto {
    pub t: f64,
    pub angle: f64,
    pub speed: f64,
    pub acceleration: f64,
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T, T_peak) from the start to this sample, W the
    /// integrated power of the actions, T_peak the largest T sampled so far:
    /// the energy balance's drift.
    pub energy_residual: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct EventDto {
    /// "turn" (a multiple of 2π crossed, either direction), "slip" (a
    /// rolling contact with friction starts to slip, or its slip turns
    /// back), "roll" (a slipping contact rolls again) or "end".
    pub kind: String,
    /// The contact joint of a "slip" or "roll" event.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joint: Option<String>,
    pub angle: f64,
    pub t: f64,
    pub speed: f64,
    /// Reduced form with actions of φ only: the time of the event by the
    /// energy form t = ∫dφ/ω, ω from ½I*ω² = T₀ + ∫M*dφ (nested quadratures,
    /// no differential equation), while the motion has not turned back.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_energy_form: Option<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DynamicsAccuracy {
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T_end, T_peak): the work of the actions against
    /// the change of kinetic energy. W is a quadrature over the angle when the
    /// reduced actions depend on φ only, else the integrated power.
    pub energy_residual: f64,
    /// The largest |t − t_energy_form| over the events (s), when any has one:
    /// an independent measure of the integration's error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_form_time_difference: Option<f64>,
    /// Σ over the steps of the integrator's local error estimate of the angle,
    /// rad (for a mechanism, the largest over its bodies' angles): a
    /// first-order estimate of the global error that ignores its growth or
    /// decay along the motion.
    pub estimated_error: f64,
    pub steps: usize,
    pub function_evaluations: usize,
    /// Mechanism form: the largest constraint violation |Φ| (m or rad)
    /// removed by the projection after a step.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub constraint_drift: Option<f64>,
    /// The Runge–Kutta method that integrated (`dopri5`, `dop853` or `radau5`).
    pub integrator: IntegratorChoice,
    /// Chosen automatically, the explicit pair found the model stiff (its
    /// steps held by stability, not accuracy) at this time, s, and the run
    /// was made again from the start with Radau IIA; `steps` and
    /// `function_evaluations` count both runs (as they do where a run
    /// ending at an angle was made twice for its samples: see `method`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiff_at: Option<f64>,
    /// Mechanism form: whether the energy T + V was held to its initial
    /// value throughout the run (see `machine.conserve_energy`; skipped near
    /// turning points, as `energy_held_steps` says): false where the loads
    /// have no potential, where the hold was turned off, and where a
    /// singular position was met (the hold stops there).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_conserved: Option<bool>,
    /// Mechanism form: the steps after which T + V was E₀ (not near turning
    /// points, where the correction would exceed 1 %, nor after a singular
    /// position); compare with `steps`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_held_steps: Option<usize>,
    pub method: String,
}

/// Result of a dynamics job (SI units).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DynamicsResult {
    pub samples: Vec<SampleDto>,
    pub events: Vec<EventDto>,
    /// Where the run ended: the last of `events`, at an address that does
    /// not depend on how many turns came before (`/end/t`, `/end/speed`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end: Option<EventDto>,
    pub energy_residual: f64,
    pub accuracy: DynamicsAccuracy,
    /// Mechanism form: every input, the reactions and the constraint residual at the samples.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine: Option<MachineDynamics>,
    pub warnings: Vec<String>,
}

impl crate::kind::JobResult for DynamicsResult {
    fn warnings(&mut self) -> Option<&mut Vec<String>> {
        Some(&mut self.warnings)
    }
    fn rows(&self) -> Option<crate::kind::Rows> {
        let (field, count) = ("/samples".into(), self.samples.len());
        Some(crate::kind::Rows { field, count, also: " (events: one per turn, fewer with a shorter run)" })
    }
}

impl From<DynamicsSolution> for DynamicsResult {
    fn from(s: DynamicsSolution) -> Self {
        let events: Vec<EventDto> = s
            .events
            .iter()
            .enumerate()
            .map(|(k, v)| EventDto {
                kind: match v.kind {
                    EventKind::Turn => "turn",
                    EventKind::Slip => "slip",
                    EventKind::Roll => "roll",
                    EventKind::End => "end",
                }
                .into(),
                joint: None,
                angle: v.angle,
                t: v.t,
                speed: v.speed,
                t_energy_form: s.energy_times.get(k).copied().flatten(),
            })
            .collect();
        Self {
            samples: s
                .samples
                .iter()
                .map(|x| SampleDto {
                    t: x.t,
                    angle: x.angle,
                    speed: x.speed,
                    acceleration: x.acceleration,
                    energy_residual: x.energy_residual,
                })
                .collect(),
            end: events.iter().rev().find(|e| e.kind == "end").cloned(),
            events,
            energy_residual: s.energy_residual,
            accuracy: DynamicsAccuracy {
                energy_residual: s.energy_residual,
                energy_form_time_difference: s
                    .events
                    .iter()
                    .zip(&s.energy_times)
                    .filter_map(|(e, t)| t.map(|t| (e.t - t).abs()))
                    .reduce(f64::max),
                estimated_error: s.estimated_error,
                steps: s.steps,
                function_evaluations: s.evaluations,
                constraint_drift: None,
                integrator: s.integrator.into(),
                stiff_at: s.stiff_at,
                energy_conserved: None,
                energy_held_steps: None,
                method: format!(
                    "{} with dense output, events located by Brent's method on it; work {}{}",
                    integrator_text(&s),
                    if s.work_by_quadrature {
                        "by adaptive quadrature over the angle"
                    } else {
                        "as the integrated power"
                    },
                    repeated_text(&s)
                ),
            },
            machine: None,
            warnings: s.stopped.into_iter().collect(),
        }
    }
}

/// The integrator's name, and why it was chosen when an explicit pair handed over.
pub(super) fn integrator_text(s: &DynamicsSolution) -> String {
    match s.stiff_at {
        Some(t) => format!(
            "{} (the explicit pair chosen first found the model stiff at t = {t:.3e} s: its steps were held \
             by stability, not accuracy; the run was made again from the start)",
            s.integrator.name()
        ),
        None => s.integrator.name().to_string(),
    }
}

/// The end of the method's text where the run was made twice for its samples.
pub(super) fn repeated_text(s: &DynamicsSolution) -> String {
    if !s.repeated {
        return String::new();
    }
    format!(
        "; the run ended at its angle after more steps than a job keeps ({} MiB of them) and was made again \
         to the end time it found, for the samples (the steps and evaluations count both runs)",
        KEPT_BYTES >> 20
    )
}

/// CSV of a stored dynamics result: one row per sample; for a mechanism
/// also every body's position and every joint's reaction at the sample.
pub fn csv_table(result: &serde_json::Value) -> (Vec<String>, Vec<Vec<String>>) {
    let columns =
        [("t", "t_s"), ("angle", "angle_rad"), ("speed", "speed_rad_s"), ("acceleration", "acceleration_rad_s2")];
    let mut header: Vec<String> = columns.iter().map(|c| c.1.to_string()).collect();
    let samples: &[serde_json::Value] = result["samples"].as_array().map_or(&[], Vec::as_slice);
    let machine = result["machine"]["samples"].as_array().filter(|m| m.len() == samples.len());
    let rows = machine.map_or(&[][..], Vec::as_slice);
    let (bodies, joints) = (names(rows, "bodies", "body"), names(rows, "reactions", "joint"));
    for b in &bodies {
        header.extend([format!("{b}_x_m"), format!("{b}_y_m"), format!("{b}_theta_rad")]);
    }
    for j in &joints {
        header.extend([format!("{j}_fx_N"), format!("{j}_fy_N"), format!("{j}_moment_N_m")]);
    }
    let rows = samples
        .iter()
        .enumerate()
        .map(|(k, row)| {
            let mut cells: Vec<String> = columns.iter().map(|c| row[c.0].to_string()).collect();
            if let Some(m) = machine {
                cells.extend(list(&m[k]["bodies"], bodies.len(), &["x", "y", "theta"]));
                cells.extend(list(&m[k]["reactions"], joints.len(), &["fx", "fy", "moment"]));
            }
            cells
        })
        .collect();
    (header, rows)
}
