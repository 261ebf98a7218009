//! `POST /v1/gears/geometry`: involute spur gear radii and tooth thickness.

use crate::engine::gears::Gear;
mod plots;

use crate::i18n::Msg;
use crate::kind::Kind;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::plots::Plots;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::{Errors, Quantity};
use crate::kind::validated;
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A standard involute spur gear.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({"module": "4 mm", "teeth": 30}))]
pub struct GearRequest {
    /// m: a bare number is SI (`4` is 4 m; write `"4 mm"`); above 0.1 m a
    /// warning says so.
    #[schema(value_type = Quantity)]
    pub module: Quantity,
    #[schema(minimum = 1)]
    pub teeth: f64,
    /// Default 20°.
    #[schema(value_type = Option<Quantity>)]
    pub pressure_angle: Option<Quantity>,
    /// In modules (default 1).
    pub addendum: Option<f64>,
    /// In modules (default 1.25).
    pub dedendum: Option<f64>,
    /// An internal gear (ring), default false.
    pub internal: Option<bool>,
    /// Radius at which to give the tooth thickness (default: the tip circle).
    #[schema(value_type = Option<Quantity>)]
    pub radius: Option<Quantity>,
}

/// Radii and tooth thickness, m and rad.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct GearResult {
    pub pitch_radius: f64,
    pub base_radius: f64,
    /// Tip (addendum) circle: outside the pitch circle, inside it for an internal gear.
    pub tip_radius: f64,
    pub root_radius: f64,
    /// πm/2.
    pub thickness_at_pitch: f64,
    pub thickness_radius: f64,
    /// Pressure angle of the involute at `thickness_radius`.
    pub thickness_pressure_angle: f64,
    /// The tooth's arc on the circle of `thickness_radius`: e_T = R_T[e_A/R_A + 2(inv φ_A − inv φ_T)];
    /// a ring's tooth is the space between those teeth, 2πR_T/z − e_T.
    pub thickness: f64,
    #[serde(flatten)]
    pub notes: Notes,
}

impl crate::kind::JobResult for GearResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
}

/// The largest module (m) a gear usually has: a bare number above it was
/// most likely meant in millimetres, and is warned of.
const PLAUSIBLE_MODULE: f64 = 0.1;

/// Gears: `POST /v1/gears/geometry`.
pub struct Gears;

impl Kind for Gears {
    const NAME: &'static str = "gears";
    const TITLE: &'static str = "kind-gears";
    const PATH: &'static str = "/v1/gears/geometry";
    const OPERATION_ID: &'static str = "create_gear_geometry_job";
    const TAG: &'static str = "gears";
    const SUMMARY: &'static str = "Radii (pitch, base, tip, root) and the tooth thickness on any circle.";
    const UNITS: &'static [(&'static str, &'static str)] = &[("/thickness_pressure_angle", "rad"), ("/*", "m")];
    type Request = GearRequest;
    type Result = GearResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };

    fn compute(request: &GearRequest, unknown: Vec<FieldError>, _limits: &Limits) -> Result<GearResult, ApiError> {
        compute(request, unknown)
    }
}

/// Validates and computes a request.
fn compute(request: &GearRequest, unknown: Vec<FieldError>) -> Result<GearResult, ApiError> {
    let (gear, radius) = validated(unknown, request.to_gear())?;
    let radii = gear.radii();
    // A module near the largest double (1e308) overflows the radii: refused, not answered as nulls.
    let overflow = |v: f64| !(v.is_finite() && (v * 4.0).is_finite());
    if [radii.pitch, radii.base, radii.tip, radii.root].into_iter().any(overflow) {
        let msg = Msg::new("gear-overflow").num("module", gear.module);
        return Err(ApiError::Invalid(vec![FieldError::said("/module", msg)]));
    }
    let at = radius.unwrap_or(radii.tip);
    let Some(t) = gear.thickness_at(at) else {
        let msg = Msg::new("gear-inside-base").num("radius", at).num("base", radii.base);
        return Err(ApiError::Invalid(vec![FieldError::said(if radius.is_some() { "/radius" } else { "" }, msg)]));
    };
    if ![t.radius, t.thickness, t.pressure_angle].into_iter().all(f64::is_finite) {
        let msg = Msg::new("gear-thickness").num("radius", at);
        return Err(ApiError::Invalid(vec![FieldError::said(
            if radius.is_some() { "/radius" } else { "/module" },
            msg,
        )]));
    }
    let mut notes = Notes::default();
    if t.thickness <= 0.0 {
        notes.warn(Msg::new("warning-gear-pointed").num("radius", at).fig("thickness", t.thickness));
    }
    if let Quantity::Number(m) = request.module
        && m > PLAUSIBLE_MODULE
    {
        notes.warn(Msg::new("warning-gear-module-metres").num("module", m).num("plausible", PLAUSIBLE_MODULE));
    }
    Ok(GearResult {
        pitch_radius: radii.pitch,
        base_radius: radii.base,
        tip_radius: radii.tip,
        root_radius: radii.root,
        thickness_at_pitch: std::f64::consts::PI * gear.module / 2.0,
        thickness_radius: t.radius,
        thickness_pressure_angle: t.pressure_angle,
        thickness: t.thickness,
        notes,
    })
}

impl GearRequest {
    fn to_gear(&self) -> Result<(Gear, Option<f64>), Vec<FieldError>> {
        let mut e = Errors::default();
        let module = e.positive(&self.module, Dim::LENGTH, "/module");
        if !(self.teeth.is_finite() && self.teeth >= 1.0 && self.teeth <= 10_000.0) {
            e.say("/teeth", Msg::new("gear-teeth"));
        }
        let pressure_angle = match &self.pressure_angle {
            Some(q) => {
                let a = e.angle(q, "/pressure_angle");
                e.require_said(a, |a| a > 0.0 && a < 1.5, "/pressure_angle", Msg::new("gear-pressure-angle"))
            }
            None => Some(20f64.to_radians()),
        };
        let share = |e: &mut Errors, v: Option<f64>, default: f64, at: &str| match v {
            Some(x) if !(x.is_finite() && (0.0..=5.0).contains(&x)) => e.refuse(at, Msg::new("gear-share")),
            x => Some(x.unwrap_or(default)),
        };
        let addendum = share(&mut e, self.addendum, 1.0, "/addendum");
        let dedendum = share(&mut e, self.dedendum, 1.25, "/dedendum");
        let radius = self.radius.as_ref().map(|q| e.positive(q, Dim::LENGTH, "/radius"));
        match (module, pressure_angle, addendum, dedendum) {
            (Some(module), Some(pressure_angle), Some(addendum), Some(dedendum)) if e.list.is_empty() => Ok((
                Gear {
                    module,
                    teeth: self.teeth,
                    pressure_angle,
                    addendum,
                    dedendum,
                    internal: self.internal.unwrap_or(false),
                },
                radius.flatten(),
            )),
            _ => Err(e.list),
        }
    }
}
