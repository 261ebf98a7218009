//! The `result` of a cam design job and how it is made from the engine's samples.

use super::request::{Motion, Problem};
use crate::engine::cam::design::{Cam, Follower, Guide, Loads, Sample};
use crate::engine::cam::extremes::{self, At, Extremes, scan};
use crate::engine::function::{Function, Side};
use crate::i18n::Msg;
use crate::kind::notes::Notes;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use utoipa::ToSchema;

/// Pressure angles beyond which a follower is warned of (translating,
/// oscillating; deg).
const PRESSURE_LIMIT: [f64; 2] = [30.0, 35.0];
/// Samples per segment for its peaks.
const PEAK_SAMPLES: usize = 2000;

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamSample {
    /// Cam angle, rad.
    pub theta: f64,
    /// s, m.
    pub lift: f64,
    /// s′ω, m/s.
    pub velocity: f64,
    /// s″ω², m/s².
    pub acceleration: f64,
    /// s‴ω³, m/s³.
    pub jerk: f64,
    /// s′ = ds/dθ, m/rad.
    pub dlift: f64,
    pub d2lift: f64,
    pub d3lift: f64,
    /// rad (0 for a flat face), signed.
    pub pressure_angle: f64,
    /// [x, y] (m) in the cam's frame (x: the follower's direction at θ = 0):
    /// a roller's centre, a knife's edge, a flat face's point on its axis.
    pub pitch_point: [f64; 2],
    /// The contact point on the profile, [x, y] (m) in the cam's frame.
    pub profile_point: [f64; 2],
    /// The profile's radius of curvature (m; > 0 convex, < 0 concave).
    pub curvature_radius: f64,
    /// A roller's pitch curve's radius of curvature (m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch_curvature_radius: Option<f64>,
    /// With `dynamics`: the force between cam and follower (N; < 0: they would separate).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_force: Option<f64>,
    /// With `dynamics`: the torque that turns the cam at `speed` (N·m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cam_torque: Option<f64>,
}

/// A value and the cam angle where it is.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, ToSchema)]
pub struct AtAngle {
    pub value: f64,
    pub theta: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamSummary {
    /// m (given, or the smallest meeting `size`).
    pub base_radius: f64,
    /// The lift's unit: "m" (translating), or "rad" (oscillating: then
    /// its velocity is rad/s, its acceleration rad/s², the preload N·m).
    pub lift_unit: String,
    /// The largest |pressure angle|, rad.
    pub max_pressure_angle: AtAngle,
    /// The profile's smallest radius of curvature where it is convex (m).
    pub min_curvature_radius: AtAngle,
    /// The profile folds on itself (a roller larger than the pitch curve's
    /// convex radius; a flat face on a concave stretch).
    pub undercut: bool,
    /// A flat face: the smallest width that keeps contact (m).
    pub face_width: Option<f64>,
    /// With `dynamics`: the angle ranges [from, to] (rad) where the contact force is negative (null: none).
    pub separation: Option<Vec<[f64; 2]>>,
    /// With `dynamics`: the cam speed above which the follower leaves the cam (rad/s; null: none).
    pub critical_speed: Option<f64>,
    /// With `dynamics`: the least spring preload that keeps contact at `speed` (N).
    pub min_preload: Option<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct SegmentPeaks {
    /// rad.
    pub from: f64,
    pub to: f64,
    pub law: String,
    /// The largest |s′|ω (m/s), |s″|ω² (m/s²), |s‴|ω³ (m/s³) in the segment.
    pub peak_velocity: f64,
    pub peak_acceleration: f64,
    pub peak_jerk: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamResult {
    pub samples: Vec<CamSample>,
    pub summary: CamSummary,
    /// A program's segments (empty for a lift Function).
    pub segments: Vec<SegmentPeaks>,
    /// How the numbers were made.
    pub method: String,
    #[serde(flatten)]
    pub notes: Notes,
}

impl crate::kind::JobResult for CamResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }

    /// A turn's samples set its size: a result too large says how many fit.
    fn rows(&self) -> Option<crate::kind::Rows> {
        let (field, count) = ("/samples".into(), self.samples.len());
        Some(crate::kind::Rows { field, count, also: "text-nothing" })
    }
}

/// The lift of a problem as the engine reads it.
pub fn lift_of(p: &Problem) -> impl Fn(f64) -> [f64; 4] + '_ {
    move |theta| match &p.motion {
        Motion::Program(program, _) => program.lift(theta),
        Motion::Function(f) => f.as_ref().each_ref().map(|f| f.eval(theta.rem_euclid(TAU), Side::Right)),
    }
}

/// The result from the turn's samples of the designed cam, and its
/// extremes where they are `known` already (sizing tested the cam).
pub fn result(p: &Problem, cam: &Cam, turn: &[Sample], known: Option<Extremes>) -> CamResult {
    let w = p.speed;
    let external =
        |theta: f64| p.loads.as_ref().and_then(|(_, f)| f.as_ref()).map_or(0.0, |f| f.eval(theta, Side::Right));
    let forces: Vec<Option<[f64; 3]>> =
        turn.iter().map(|x| p.loads.as_ref().map(|(l, _)| cam.forces(x, l, w, external(x.theta)))).collect();
    let samples = turn
        .iter()
        .zip(&forces)
        .map(|(x, f)| {
            let [s, s1, s2, s3] = x.lift;
            CamSample {
                theta: x.theta,
                lift: s,
                velocity: s1 * w,
                acceleration: s2 * w * w,
                jerk: s3 * w * w * w,
                dlift: s1,
                d2lift: s2,
                d3lift: s3,
                pressure_angle: x.pressure_angle,
                pitch_point: x.pitch_point,
                profile_point: x.profile_point,
                curvature_radius: x.curvature_radius,
                pitch_curvature_radius: matches!(cam.follower, Follower::Roller(r) if r > 0.0)
                    .then_some(x.pitch_curvature_radius),
                contact_force: f.map(|f| f[1]),
                cam_torque: f.map(|f| f[2]),
            }
        })
        .collect();
    let mut notes = Notes::default();
    if p.sense_assumed {
        notes.warn(Msg::new("warning-cam-sense"));
    }
    let summary = summary(p, cam, known, &mut notes);
    let lift_unit = summary.lift_unit.clone();
    let segments = match &p.motion {
        Motion::Program(program, names) => {
            // A jump of the jerk keeps the acceleration continuous: only
            // velocity and acceleration jumps break the fundamental law.
            for b in program.breaks().into_iter().filter(|b| b.derivative <= 2) {
                let what = ["", "warning-cam-velocity", "warning-cam-acceleration"][b.derivative];
                notes.warn(
                    Msg::new("warning-cam-fundamental-law")
                        .fig("at", b.theta.to_degrees())
                        .with("what", Msg::new(what))
                        .fig("jump", b.jump)
                        .arg("unit", &lift_unit)
                        .count("order", b.derivative),
                );
            }
            program.segments().iter().zip(names).map(|(s, name)| peaks(s, name, w)).collect()
        }
        Motion::Function(_) => Vec::new(),
    };
    CamResult { samples, summary, segments, method: notes.say("/method", Msg::new("accuracy-cam")), notes }
}

fn peaks(s: &crate::engine::cam::Segment, name: &str, w: f64) -> SegmentPeaks {
    let mut peak = [0.0f64; 3];
    for k in 0..=PEAK_SAMPLES {
        let theta = s.start + s.span * k as f64 / PEAK_SAMPLES as f64;
        let v = s.eval(theta.min(s.start + s.span));
        for d in 0..3 {
            peak[d] = peak[d].max(v[d + 1].abs() * w.powi(d as i32 + 1));
        }
    }
    SegmentPeaks {
        from: s.start,
        to: s.start + s.span,
        law: name.to_string(),
        peak_velocity: peak[0],
        peak_acceleration: peak[1],
        peak_jerk: peak[2],
    }
}

fn summary(p: &Problem, cam: &Cam, known: Option<Extremes>, notes: &mut Notes) -> CamSummary {
    let (lift, grid) = (lift_of(p), scan(&breaks(p)));
    let e = known.unwrap_or_else(|| extremes::of(cam, &lift, &grid));
    let at = |a: At| AtAngle { value: a.value, theta: a.theta };
    let max_angle = at(e.max_pressure_angle);
    let min_rho = e.min_curvature_radius.map_or(AtAngle { value: f64::INFINITY, theta: 0.0 }, at);
    let undercut = e.undercut();
    if undercut {
        let id = if cam.follower == Follower::Flat { "warning-cam-undercut-flat" } else { "warning-cam-undercut" };
        notes.warn(Msg::new(id).fig("at", min_rho.theta.to_degrees()).fig("rho", min_rho.value));
    }
    let oscillating = matches!(cam.guide, Guide::Oscillating { .. });
    let (limit, id) = match oscillating {
        true => (PRESSURE_LIMIT[1], "warning-cam-pressure-oscillating"),
        false => (PRESSURE_LIMIT[0], "warning-cam-pressure-translating"),
    };
    if max_angle.value > limit.to_radians() {
        let at = |x: f64| (x.to_degrees() * 100.0).round() / 100.0;
        notes.warn(Msg::new(id).num("max", at(max_angle.value)).num("at", at(max_angle.theta)).num("limit", limit));
    }
    let face_width = e.face.map(|(near, far)| far - near);
    let (separation, critical_speed, min_preload) = match &p.loads {
        Some((loads, external)) => dynamics(p, (loads, external.as_ref()), &grid),
        None => (None, None, None),
    };
    if let Some(ranges) = separation.as_ref().filter(|r| !r.is_empty()) {
        let deg =
            |x: f64| Msg::new("text-value-unit").num("value", (x.to_degrees() * 10.0).round() / 10.0).arg("unit", "°");
        let span = |[a, b]: &[f64; 2]| Msg::new("warning-span").with("from", deg(*a)).with("to", deg(*b));
        notes.warn(Msg::new("warning-cam-separation").list("at", ranges.iter().map(span).collect()));
    }
    CamSummary {
        base_radius: cam.base,
        lift_unit: if oscillating { "rad" } else { "m" }.into(),
        max_pressure_angle: max_angle,
        min_curvature_radius: min_rho,
        undercut,
        face_width,
        separation,
        critical_speed,
        min_preload,
    }
}

/// The angles a motion changes law at: a program's segments' starts, a
/// lift Function's pieces'.
pub fn breaks(p: &Problem) -> Vec<f64> {
    match &p.motion {
        Motion::Program(program, _) => program.starts(),
        Motion::Function(f) => f.iter().flat_map(|f| f.breakpoints(TAU)).collect(),
    }
}

type Dynamics = (Option<Vec<[f64; 2]>>, Option<f64>, Option<f64>);

/// Separation ranges, critical speed and least preload over the whole turn
/// (scanned at `grid` and refined, [`extremes`]): with the follower's force
/// from the cam Q = m s″ω² + G, G = F₀ + k s − F, contact holds while Q ≥ 0;
/// it fails first at ω_c = min √(G/(−m s″)) where s″ < 0 (0 where G < 0
/// somewhere); the least preload is the largest F₀ − Q.
fn dynamics(p: &Problem, (loads, external): (&Loads, Option<&Function>), grid: &[f64]) -> Dynamics {
    let lift = lift_of(p);
    let w = p.speed;
    let g = |t: f64| {
        let s = lift(t)[0];
        loads.preload + loads.stiffness * s - external.map_or(0.0, |f| f.eval(t, Side::Right))
    };
    let q = |t: f64| loads.mass * lift(t)[2] * w * w + g(t);
    let ranges = extremes::below_zero(&q, grid);
    let short = extremes::largest(&|t| Some(-g(t)), grid).is_some_and(|a| a.value > 0.0);
    let critical = match short {
        true => Some(0.0),
        false => {
            let speed = |t: f64| {
                let s2 = lift(t)[2];
                (s2 < 0.0 && loads.mass > 0.0).then(|| -(g(t) / (-loads.mass * s2)).sqrt())
            };
            extremes::largest(&speed, grid).map(|a| -a.value)
        }
    };
    let preload = extremes::largest(&|t| Some(loads.preload - q(t)), grid).map_or(0.0, |a| a.value.max(0.0));
    ((!ranges.is_empty()).then_some(ranges), critical, Some(preload))
}
