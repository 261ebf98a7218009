//! `POST /v1/cams`: a disk cam designed for its follower and motion
//! program — the follower's lift, velocity, acceleration and jerk (SVAJ),
//! the pitch curve and profile, pressure angle and radii of curvature,
//! undercut, a flat face's width, the smallest base radius meeting a
//! pressure angle or a radius of curvature, and with the follower's
//! dynamics the contact force, cam torque, separation, critical speed and
//! least preload. The symbols are the engine's ([`crate::engine::cam`]).

mod dxf;
mod plots;
mod program;
mod request;
mod result;

pub use program::program;
pub use request::{CamFollowerDto, CamFollowerMotion, CamFollowerType, CamProgramDto, CamRequest, CamSense};
pub use result::CamResult;

use crate::engine::Deadline;
use crate::engine::cam::design::{Cam, CamError, Follower, Guide};
use crate::engine::cam::extremes::{self, Extremes, scan};
use crate::engine::cam::least::least_base;
use crate::engine::cam::sizing::{least_measure, lifts, smallest_base, turn};
use crate::i18n::Msg;
use crate::kind::limits::Limits;
use crate::kind::plots::Plots;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::{Kind, Table, cell, engine_failure, unit_in, validated};
use request::Problem;
use serde_json::Value;

/// Cam design: `POST /v1/cams`.
pub struct Cams;

impl Kind for Cams {
    const NAME: &'static str = "cams";
    const TITLE: &'static str = "kind-cams";
    const PATH: &'static str = "/v1/cams";
    const OPERATION_ID: &'static str = "create_cam_job";
    const TAG: &'static str = "calculators";
    const SUMMARY: &'static str = "A disk cam for its follower and motion program: SVAJ, profile, pressure angle, curvature, undercut, size, and the follower's dynamics.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/samples/*/theta", "rad"),
        ("/samples/*/lift", "m"),
        ("/samples/*/velocity", "m/s"),
        ("/samples/*/acceleration", "m/s^2"),
        ("/samples/*/jerk", "m/s^3"),
        ("/samples/*/dlift", "m"),
        ("/samples/*/d2lift", "m"),
        ("/samples/*/d3lift", "m"),
        ("/samples/*/pressure_angle", "rad"),
        ("/samples/*/pitch_point/*", "m"),
        ("/samples/*/profile_point/*", "m"),
        ("/samples/*/curvature_radius", "m"),
        ("/samples/*/pitch_curvature_radius", "m"),
        ("/samples/*/contact_force", "N"),
        ("/samples/*/cam_torque", "N*m"),
        ("/summary/base_radius", "m"),
        ("/summary/max_pressure_angle/*", "rad"),
        ("/summary/min_curvature_radius/value", "m"),
        ("/summary/min_curvature_radius/theta", "rad"),
        ("/summary/face_width", "m"),
        ("/summary/separation/*/*", "rad"),
        ("/summary/critical_speed", "rad/s"),
        ("/summary/min_preload", "N"),
        ("/segments/*/from", "rad"),
        ("/segments/*/to", "rad"),
        ("/segments/*/peak_velocity", "m/s"),
        ("/segments/*/peak_acceleration", "m/s^2"),
        ("/segments/*/peak_jerk", "m/s^3"),
    ];
    type Request = CamRequest;
    type Result = CamResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };
    const FILES: &'static [(&'static str, &'static str)] = &[("profile.dxf", "application/dxf")];

    /// An oscillating follower's lift is an angle: its lift, velocity,
    /// acceleration and jerk are in rad, rad/s, rad/s², rad/s³, its preload N·m.
    fn unit(result: &Value, pointer: &[&str]) -> Option<String> {
        let unit = unit_in(Self::UNITS, pointer)?;
        if result["summary"]["lift_unit"] != "rad" {
            return Some(unit.into());
        }
        let field = pointer.last().copied().unwrap_or_default();
        let angular = ["lift", "velocity", "acceleration", "jerk", "dlift", "d2lift", "d3lift"];
        let peaks = ["peak_velocity", "peak_acceleration", "peak_jerk"];
        Some(match field {
            "min_preload" => "N*m".into(),
            f if (angular.contains(&f) && pointer[0] == "samples") || peaks.contains(&f) => {
                unit.replacen('m', "rad", 1)
            }
            _ => unit.into(),
        })
    }

    fn file(result: &Value, name: &str) -> Option<Vec<u8>> {
        (name == "profile.dxf").then(|| dxf::profile(result)).flatten()
    }

    fn has_file(result: &Value, name: &str) -> bool {
        name == "profile.dxf" && dxf::has_profile(result)
    }

    fn compute(request: &CamRequest, unknown: Vec<FieldError>, limits: &Limits) -> Result<CamResult, ApiError> {
        let deadline = limits.deadline();
        let problem = validated(unknown, request.to_problem(limits))?;
        let lift = result::lift_of(&problem);
        let lifts = lifts(&lift, problem.samples, &deadline).map_err(|e| engine_failure(e, "/program"))?;
        let (base, known) = match problem.size {
            None => (problem.cam.base, None),
            Some(size) => sized(&problem, &lifts, size, &deadline)?,
        };
        let cam = Cam { base, ..problem.cam };
        let samples = turn(&cam, &lifts).map_err(|e| refused(&e))?;
        Ok(result::result(&problem, &cam, &samples, known))
    }

    /// The samples, one row each, each column's header with its unit
    /// (`theta_rad`, `lift_m`: an angle's column in degrees with
    /// `?angles=deg`, an oscillating follower's lift and its derivatives
    /// by θ among them, as [`Kind::unit`] gives their units).
    fn table(result: &Value) -> Option<Table> {
        let rows = result["samples"].as_array()?;
        let lift = if result["summary"]["lift_unit"] == "rad" { "rad" } else { "m" };
        // ds/dθ… per rad of the cam: in the lift's unit (as `unit` gives them).
        let per_rad = format!("_{lift}");
        let fields = [
            ("theta", "_rad".to_string()),
            ("lift", format!("_{lift}")),
            ("velocity", format!("_{lift}_s")),
            ("acceleration", format!("_{lift}_s2")),
            ("jerk", format!("_{lift}_s3")),
            ("dlift", per_rad.clone()),
            ("d2lift", per_rad.clone()),
            ("d3lift", per_rad),
            ("pressure_angle", "_rad".to_string()),
            ("curvature_radius", "_m".to_string()),
            ("pitch_curvature_radius", "_m".to_string()),
            ("contact_force", "_N".to_string()),
            ("cam_torque", "_N_m".to_string()),
        ];
        let mut header: Vec<String> = fields.iter().map(|(f, unit)| format!("{f}{unit}")).collect();
        header.extend(["pitch_x_m", "pitch_y_m", "profile_x_m", "profile_y_m"].map(String::from));
        let body = rows
            .iter()
            .map(|r| {
                let mut row: Vec<String> = fields.iter().map(|(f, _)| cell(&r[*f])).collect();
                row.extend(
                    [&r["pitch_point"][0], &r["pitch_point"][1], &r["profile_point"][0], &r["profile_point"][1]]
                        .map(cell),
                );
                row
            })
            .collect();
        Some((header, body))
    }
}

/// The smallest base radius meeting `size` ([largest pressure angle, smallest
/// radius of curvature]) without undercut, with the extremes of the cam
/// tested last (those of the radius returned, for its summary).
fn sized(
    p: &Problem,
    lifts: &[(f64, [f64; 4])],
    [angle, rho]: [Option<f64>; 2],
    deadline: &Deadline,
) -> Result<(f64, Option<Extremes>), ApiError> {
    let (lift, breaks) = (result::lift_of(p), result::breaks(p));
    let grid = scan(&breaks);
    // How far the cam is from meeting the size (≤ 0: met): the largest of
    // its pressure angle over the allowed, the radius of curvature under
    // the least allowed, and under 0 (an undercut), each relative.
    let last = std::cell::Cell::new(None);
    let excess = |cam: &Cam| {
        let e = extremes::of(cam, &lift, &grid);
        last.set(Some((cam.base, e)));
        let rho_min = e.min_curvature_radius.map_or(f64::INFINITY, |m| m.value);
        let over_angle = angle.map_or(f64::NEG_INFINITY, |a| e.max_pressure_angle.value / a - 1.0);
        let under_rho = rho.map_or(f64::NEG_INFINITY, |r| 1.0 - rho_min / r);
        let undercut = -rho_min / cam.base.max(f64::MIN_POSITIVE);
        over_angle.max(under_rho).max(undercut)
    };
    let closed = |lo: f64| least_base(&p.cam, &lift, &breaks, angle, rho, lo);
    let base = smallest_base(p.cam, lifts, closed, excess, deadline).map_err(|e| engine_failure(e, "/size"))?;
    let Some(base) = base else {
        let least_angle = |cam: &Cam| extremes::of(cam, &lift, &grid).max_pressure_angle.value;
        let best = match angle {
            Some(asked) => least_measure(p.cam, lifts, least_angle, deadline)
                .map_err(|e| engine_failure(e, "/size"))?
                .filter(|[_, least]| *least > asked),
            None => None,
        };
        return Err(unmet(p.cam.guide, [angle, rho], best));
    };
    if base <= NO_BODY * sizes(p, lifts) {
        return Err(ApiError::Invalid(vec![FieldError::said("/size", Msg::new("cam-size-any"))]));
    }
    Ok((base, last.get().filter(|(tested, _)| *tested == base).map(|(_, e)| e)))
}

/// A base radius this fraction of the cam's other lengths ([`sizes`]) is
/// none: every radius meets the size (a program that never rises sized by
/// a pressure angle), and a cam of radius 0 has no body.
const NO_BODY: f64 = 1e-9;

/// The largest of the cam's lengths but its base radius: its lift, roller,
/// offset, pivot and arm (m).
fn sizes(p: &Problem, lifts: &[(f64, [f64; 4])]) -> f64 {
    let roller = match p.cam.follower {
        Follower::Roller(r) => r,
        Follower::Flat => 0.0,
    };
    let guide = match p.cam.guide {
        // A translating follower's lift is a length (an oscillating one's an angle).
        Guide::Translating { offset } => lifts.iter().map(|(_, l)| l[0].abs()).fold(offset.abs(), f64::max),
        Guide::Oscillating { pivot, arm } => pivot.max(arm),
    };
    roller.max(guide)
}

/// No base radius meets the size: a translating follower is tried up to
/// 2⁴⁰ × 100 times its lift, an oscillating one wherever its arm reaches. Where
/// the pressure angle asked is under the least any radius gives, that
/// least ([radius, angle]), rounded up to 0.01° so that asking for it is
/// met, and the radius that gives it; else what to loosen of what was
/// `asked` ([largest pressure angle, least radius of curvature]).
fn unmet(guide: Guide, asked: [Option<f64>; 2], best: Option<[f64; 2]>) -> ApiError {
    let oscillating = matches!(guide, Guide::Oscillating { .. });
    let msg = match best {
        Some([base, angle]) => Msg::new(if oscillating { "cam-no-base-arm-best" } else { "cam-no-base-best" })
            .num("angle", (angle.to_degrees() * 100.0).ceil() / 100.0)
            .num("base", (base * 1e4).round() / 10.0),
        None => Msg::new(if oscillating { "cam-no-base-arm" } else { "cam-no-base" }).arg(
            "asked",
            match asked {
                [Some(_), None] => "angle",
                [None, Some(_)] => "rho",
                _ => "both",
            },
        ),
    };
    ApiError::Invalid(vec![FieldError::said("/size", msg)])
}

/// A cam that cannot be made, at its field.
fn refused(e: &CamError) -> ApiError {
    let at = match e {
        CamError::Offset { .. } => "/follower/offset",
        CamError::Reach { .. } => "/follower/arm",
        CamError::Negative { .. } => "/program",
    };
    ApiError::Invalid(vec![FieldError::said(at, msg(e))])
}

/// Why a cam cannot be made, as the catalogue says it.
fn msg(e: &CamError) -> Msg {
    match *e {
        CamError::Offset { offset, pitch } => Msg::new("cam-offset").num("offset", offset).num("pitch", pitch),
        CamError::Reach { radius, pivot, arm } => {
            Msg::new("cam-reach").num("arm", arm).num("pivot", pivot).num("radius", radius)
        }
        CamError::Negative { lift, theta } => Msg::new("cam-below-base").num("lift", lift).num("theta", theta),
    }
}
