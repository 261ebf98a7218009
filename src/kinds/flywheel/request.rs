//! `POST /v1/flywheel` request and its conversion into an engine problem.

use crate::engine::Deadline;
use crate::engine::flywheel::{DiskSize, DiskSpec, FlywheelProblem, Load, TorqueItem};
use crate::engine::function::Function;
use crate::engine::machine::{Machine, Reduced, ReducedCurve, Reduces};
use crate::engine::spatial::machine::SpatialMachine;
use crate::i18n::Msg;
use crate::kind::constants::{self, Constants};
use crate::kind::limits::Limits;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use crate::kinds::mechanism::MechanismDto;
use crate::kinds::mechanism::{InputDto, LoadDto, machine_parts, spatial_machine_parts};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::sync::Arc;
use utoipa::ToSchema;

/// A flywheel's machine: in the plane (its poses drawn on the page) or in space.
#[derive(Clone, Debug)]
pub enum MachineModel {
    Planar(Arc<Machine>),
    Spatial(Arc<SpatialMachine>),
}

impl MachineModel {
    /// I*, dI*/dφ and M* of either.
    fn reduces(&self) -> Arc<dyn Reduces> {
        match self {
            Self::Planar(m) => m.clone(),
            Self::Spatial(m) => m.clone(),
        }
    }
}

/// Most torque items in one request.
pub const MAX_TORQUES: usize = 100;
/// Longest torque name, in characters.
pub const MAX_NAME: usize = 200;
const DEFAULT_SAMPLES: usize = 361;

/// A flywheel design problem. Give the speeds as exactly one of:
/// `mean_speed` + `irregularity`, `mean_speed` + `min_speed`, or `min_speed` + `max_speed`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "mean_speed": "60 rpm",
    "irregularity": 0.04,
    "torques": [
        {"name": "slider load", "value": {"segments": [{"from": 0, "to": "pi", "expr": "-500*sin(phi)"}]}},
        {"name": "motor", "balance": true}
    ],
    "reduced_inertia": {"expr": "5*sin(phi)^2"}
}))]
pub struct FlywheelRequest {
    /// Named values every expression of this request may read, e.g.
    /// `{"F": "1200 N", "r": "0.1 m"}`: each a number (SI) or a quantity,
    /// read in SI. A constant no expression reads is a warning.
    #[schema(value_type = Option<std::collections::BTreeMap<String, Quantity>>)]
    pub constants: Option<Constants>,
    /// Cycle length in rad of the reference shaft (default 2π; 4π for a four-stroke engine).
    #[schema(value_type = Option<Quantity>)]
    pub period: Option<Quantity>,
    /// ω_a = (ω_max + ω_min)/2 of the reference shaft.
    #[schema(value_type = Option<Quantity>)]
    pub mean_speed: Option<Quantity>,
    /// ε = (ω_max − ω_min)/ω_a, in (0, 2): a number (0.04) or a percentage ("4 %").
    #[schema(value_type = Option<Quantity>)]
    pub irregularity: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub min_speed: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub max_speed: Option<Quantity>,
    /// Torques on the machine, positive when they drive it (at least one item, or a `machine`).
    #[schema(max_items = 100)]
    pub torques: Option<Vec<TorqueDto>>,
    /// I*(φ) of the machine reduced to the reference shaft, without flywheel (default 0).
    #[schema(value_type = Option<FunctionDto>)]
    pub reduced_inertia: Option<FunctionDto>,
    /// Constant inertia already on the reference shaft, subtracted from the flywheel (default 0).
    #[schema(value_type = Option<Quantity>)]
    pub existing_inertia: Option<Quantity>,
    pub flywheel: Option<FlywheelDto>,
    /// Requested relative accuracy (default 1e-9).
    #[schema(minimum = 1e-14, maximum = 1e-2)]
    pub tolerance: Option<f64>,
    /// Run the independent time-simulation check (default true).
    pub check: Option<bool>,
    /// Rows of the sampled table in the result and its CSV (default 361; 0 for none).
    #[schema(minimum = 0, maximum = 100000)]
    pub samples: Option<usize>,
    /// A mechanism whose loads and inertias give M*(φ) and I*(φ) (added to
    /// `torques` and `reduced_inertia`); its input joint is the reference shaft.
    pub machine: Option<MachineDto>,
}

/// A driven mechanism with its loads, as in kinetostatics, in the plane or
/// in space (`"space": "spatial"`: the input a revolute's rotation or a
/// cylindrical's). The input's `speed`, `start`, `end` and `steps` do not
/// apply: the flywheel's mean speed and period rule.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct MachineDto {
    pub mechanism: MechanismDto,
    pub input: InputDto,
    #[schema(max_items = 500)]
    pub loads: Option<Vec<LoadDto>>,
}

/// A torque item: `value` (a Function), or `"balance": true`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct TorqueDto {
    #[schema(max_length = 200)]
    pub name: String,
    #[schema(value_type = Option<FunctionDto>)]
    pub value: Option<FunctionDto>,
    /// A constant torque solved so that the cycle work is zero (at most one item).
    pub balance: Option<bool>,
    /// ω of the shaft it acts on / ω of the reference shaft (default 1).
    pub ratio: Option<f64>,
}

/// Where the flywheel sits and how to size it.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct FlywheelDto {
    /// ω of the flywheel's shaft / ω of the reference shaft (default 1).
    pub ratio: Option<f64>,
    pub disk: Option<DiskDto>,
}

/// A solid disk holding `flywheel_inertia.exact` (I = ½MR²): exactly one
/// of `rim_speed`, `radius`, `thickness`, and its `density` (needed with a
/// thickness; without one, a disk sized by its radius or rim speed has its
/// mass M = 2I/R² and no thickness).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DiskDto {
    /// ρ, e.g. `"7800 kg/m^3"`.
    #[serde(default)]
    #[schema(value_type = Option<Quantity>)]
    pub density: Option<Quantity>,
    /// The rim's speed R·k·ω_a, k the flywheel shaft's `ratio` and ω_a the
    /// reference shaft's mean speed.
    #[schema(value_type = Option<Quantity>)]
    pub rim_speed: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub radius: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub thickness: Option<Quantity>,
}

impl FlywheelRequest {
    /// Validates the request, collecting every error under its pointer; a
    /// machine is assembled within `deadline`, which the problem keeps, and
    /// given beside it (its poses for the plots).
    pub fn to_problem(
        &self,
        limits: &Limits,
        deadline: Deadline,
    ) -> Result<(FlywheelProblem, Option<MachineModel>), Vec<crate::kind::problem::FieldError>> {
        let mut e = Errors::new(limits);
        constants::read(self.constants.as_ref(), &mut e);
        let period = match &self.period {
            Some(q) => e
                .angle(q, "/period")
                .and_then(|p| if p > 0.0 { Some(p) } else { e.refuse("/period", Msg::new("field-positive")) }),
            None => Some(2.0 * PI),
        };
        let speeds = self.speeds(&mut e);
        let tolerance = match self.tolerance {
            Some(t) if !(1e-14..=1e-2).contains(&t) => {
                e.refuse("/tolerance", Msg::new("field-between").arg("min", "1e-14").arg("max", "1e-2"))
            }
            t => Some(t.unwrap_or(1e-9)),
        };
        let samples = match self.samples {
            Some(n) if n > limits.samples => e.refuse("/samples", Msg::new("field-at-most").arg("max", limits.samples)),
            Some(1) => e.refuse("/samples", Msg::new("field-samples")),
            n => Some(n.unwrap_or(DEFAULT_SAMPLES)),
        };
        let p = period.unwrap_or(2.0 * PI);
        let machine = self.machine(&mut e, p, speeds.map_or(0.0, |s| s.0), deadline);
        let mut torques = self.torques(&mut e, p, machine.is_some());
        let mut inertia = match &self.reduced_inertia {
            Some(f) => e
                .function(f, Dim::INERTIA, p, "/reduced_inertia")
                .and_then(|f| e.differentiable(&f, 1, "/reduced_inertia").map(|()| f)),
            None => Some(Function::Constant(0.0)),
        };
        if let (Some(m), Some(t), Some(i)) =
            (machine.as_ref().map(MachineModel::reduces), torques.as_mut(), inertia.as_mut())
        {
            let label = "/machine".to_string();
            t.push(TorqueItem {
                name: "machine".into(),
                load: Load::Given(ReducedCurve::function(m.clone(), Reduced::Torque)),
                ratio: 1.0,
                label,
            });
            *i = Function::Sum(vec![i.clone(), ReducedCurve::function(m, Reduced::Inertia)]);
        }
        let existing = match &self.existing_inertia {
            Some(q) => e.quantity(q, Dim::INERTIA, "/existing_inertia"),
            None => Some(0.0),
        };
        let (flywheel_ratio, disk) = self.flywheel(&mut e);
        match (period, speeds, tolerance, samples, torques, inertia, existing, flywheel_ratio, disk) {
            (
                Some(period),
                Some((mean_speed, irregularity)),
                Some(tolerance),
                Some(samples),
                Some(torques),
                Some(reduced_inertia),
                Some(existing_inertia),
                Some(flywheel_ratio),
                Some(disk),
            ) if e.list.is_empty() => Ok((
                FlywheelProblem {
                    period,
                    mean_speed,
                    irregularity,
                    torques,
                    reduced_inertia,
                    reduced_inertia_label: "/reduced_inertia".into(),
                    existing_inertia,
                    flywheel_ratio,
                    disk,
                    tolerance,
                    check: self.check.unwrap_or(true),
                    samples,
                    deadline,
                },
                machine,
            )),
            _ => Err(e.list),
        }
    }

    /// (ω_a, ε) from exactly one of the three accepted pairs.
    fn speeds(&self, e: &mut Errors) -> Option<(f64, f64)> {
        let q =
            |e: &mut Errors, q: &Option<Quantity>, at: &str| q.as_ref().map(|q| e.positive(q, Dim::ANGULAR_SPEED, at));
        let mean = q(e, &self.mean_speed, "/mean_speed");
        let min = q(e, &self.min_speed, "/min_speed");
        let max = q(e, &self.max_speed, "/max_speed");
        // Read (and checked) before the others can end the reading early.
        let irregularity = self.irregularity.as_ref().map(|q| {
            let eps = e.quantity(q, Dim::NONE, "/irregularity");
            let between = Msg::new("field-between-open").num("min", 0.0).num("max", 2.0);
            e.require_said(eps, |v| v > 0.0 && v < 2.0, "/irregularity", between)
        });
        let (mean, eps) = match (mean, irregularity, min, max) {
            (Some(m), Some(eps), None, None) => (m?, eps?),
            (Some(m), None, Some(lo), None) => {
                let (m, lo) = (m?, lo?);
                if lo >= m {
                    return e.refuse("/min_speed", Msg::new("field-less-than").arg("other", "mean_speed"));
                }
                (m, 2.0 * (m - lo) / m)
            }
            (None, None, Some(lo), Some(hi)) => {
                let (lo, hi) = (lo?, hi?);
                if lo >= hi {
                    return e.refuse("/min_speed", Msg::new("field-less-than").arg("other", "max_speed"));
                }
                let m = 0.5 * (lo + hi);
                (m, (hi - lo) / m)
            }
            _ => {
                return e.refuse("", Msg::new("flywheel-speeds"));
            }
        };
        Some((mean, eps))
    }

    fn torques(&self, e: &mut Errors, period: f64, machine: bool) -> Option<Vec<TorqueItem>> {
        let list = self.torques.as_deref().unwrap_or_default();
        if (list.is_empty() && !machine) || list.len() > MAX_TORQUES {
            return e.refuse("/torques", Msg::new("flywheel-torques-count").arg("max", MAX_TORQUES));
        }
        if list.iter().filter(|t| t.balance == Some(true)).count() > 1 {
            e.say("/torques", Msg::new("flywheel-one-balance"));
        }
        let items: Vec<Option<TorqueItem>> = list.iter().enumerate().map(|(i, t)| torque(e, t, i, period)).collect();
        items.into_iter().collect()
    }

    /// The machine's reduced quantities, solved around the period at the mean speed.
    fn machine(&self, e: &mut Errors, period: f64, mean_speed: f64, deadline: Deadline) -> Option<MachineModel> {
        let m = self.machine.as_ref()?;
        let loads = m.loads.as_deref().unwrap_or_default();
        let built = if m.mechanism.is_spatial() {
            let (mechanism, loads, reference) =
                spatial_machine_parts(e, &m.mechanism, &m.input, loads, period, "/machine")?;
            SpatialMachine::new(mechanism, loads, (mean_speed, period, reference), deadline)
                .map(|m| MachineModel::Spatial(Arc::new(m)))
        } else {
            let (mechanism, loads) = machine_parts(e, &m.mechanism, &m.input, loads, period, "/machine")?;
            Machine::new(mechanism, loads, mean_speed, period, deadline).map(|m| MachineModel::Planar(Arc::new(m)))
        };
        match built {
            Ok(m) => Some(m),
            Err(err) => e.refuse("/machine", crate::kind::refused::engine_msg(&err)),
        }
    }

    fn flywheel(&self, e: &mut Errors) -> (Option<f64>, Option<Option<DiskSpec>>) {
        let Some(f) = &self.flywheel else { return (Some(1.0), Some(None)) };
        let ratio = ratio(e, f.ratio, "/flywheel/ratio");
        let disk = match &f.disk {
            None => Some(None),
            Some(d) => disk(e, d).map(Some),
        };
        (ratio, disk)
    }
}

fn ratio(e: &mut Errors, r: Option<f64>, at: &str) -> Option<f64> {
    match r {
        Some(k) if k == 0.0 || !k.is_finite() => e.refuse(at, Msg::new("field-finite-nonzero")),
        k => Some(k.unwrap_or(1.0)),
    }
}

fn torque(e: &mut Errors, t: &TorqueDto, i: usize, period: f64) -> Option<TorqueItem> {
    let at = format!("/torques/{i}");
    if t.name.chars().count() > MAX_NAME {
        e.say(&format!("{at}/name"), Msg::new("field-at-most-characters").arg("max", MAX_NAME));
    }
    let ratio = ratio(e, t.ratio, &format!("{at}/ratio"));
    let load = match (&t.value, t.balance.unwrap_or(false)) {
        (Some(v), false) => e.function(v, Dim::TORQUE, period, &format!("{at}/value")).map(Load::Given),
        (None, true) => Some(Load::Balance),
        _ => e.refuse(&at, Msg::new("flywheel-value-or-balance")),
    };
    Some(TorqueItem { name: t.name.clone(), load: load?, ratio: ratio?, label: format!("{at}/value") })
}

fn disk(e: &mut Errors, d: &DiskDto) -> Option<DiskSpec> {
    let density = match &d.density {
        Some(q) => Some(Some(e.positive(q, Dim::DENSITY, "/flywheel/disk/density")?)),
        None if d.thickness.is_some() => e.refuse("/flywheel/disk/density", Msg::new("flywheel-disk-density")),
        None => Some(None),
    };
    let size = match (&d.rim_speed, &d.radius, &d.thickness) {
        (Some(v), None, None) => e.positive(v, Dim::SPEED, "/flywheel/disk/rim_speed").map(DiskSize::RimSpeed),
        (None, Some(r), None) => e.positive(r, Dim::LENGTH, "/flywheel/disk/radius").map(DiskSize::Radius),
        (None, None, Some(t)) => e.positive(t, Dim::LENGTH, "/flywheel/disk/thickness").map(DiskSize::Thickness),
        _ => e.refuse("/flywheel/disk", Msg::new("flywheel-disk")),
    };
    Some(DiskSpec { density: density?, size: size? })
}
