//! The cam design request and its conversion, every error at its pointer.

use super::program::{BARE_MM, CamSegmentDto, program};
use crate::engine::cam::Program;
use crate::engine::cam::design::{Cam, Follower, Guide, Loads};
use crate::engine::function::{Function, Side};
use crate::i18n::Msg;
use crate::kind::limits::Limits;
use crate::kind::problem::FieldError;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use utoipa::ToSchema;

/// Most samples over a turn.
pub const MAX_SAMPLES: usize = 36_000;

/// A disk cam to design (see the example).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "follower": {"type": "roller", "motion": "translating", "offset": "0 mm", "roller_radius": "10 mm"},
    "program": [
        {"to": "90 deg", "law": "cycloidal", "lift": "20 mm"},
        {"to": "180 deg", "law": "dwell", "lift": "20 mm"},
        {"to": "270 deg", "law": "polynomial-345", "lift": "0 mm"},
        {"to": "360 deg", "law": "dwell", "lift": "0 mm"}
    ],
    "size": {"max_pressure_angle": "30 deg"},
    "speed": "300 rpm",
    "dynamics": {"follower_mass": "0.5 kg", "spring": {"stiffness": "2000 N/m", "preload": "20 N"}},
    "samples": 360
}))]
pub struct CamRequest {
    pub follower: CamFollowerDto,
    /// The follower's motion over one turn from lift 0 at angle 0: segments
    /// `{"to", "law", "lift"}` end to end, the last ending at 360° at lift 0;
    /// or `{"lift": Function of theta}`.
    pub program: CamProgramDto,
    /// The profile's smallest radius (a roller's cam: base + roller radius is the pitch circle), m.
    #[schema(value_type = Option<Quantity>)]
    pub base_radius: Option<Quantity>,
    /// Instead of `base_radius`: the smallest base radius meeting these.
    pub size: Option<CamSizeDto>,
    /// The cam's angular speed (constant), rad/s.
    #[schema(value_type = Quantity)]
    pub speed: Quantity,
    /// The cam's sense of rotation; default ccw, said in a warning where
    /// the sense changes the answer (an offset or oscillating follower).
    pub direction: Option<CamSense>,
    pub dynamics: Option<CamDynamicsDto>,
    /// Angles evenly spaced over the turn (default 360).
    #[schema(minimum = 4, maximum = 36000)]
    pub samples: Option<usize>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum CamSense {
    Ccw,
    Cw,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum CamFollowerType {
    Flat,
    Roller,
    Knife,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum CamFollowerMotion {
    Translating,
    Oscillating,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamFollowerDto {
    #[serde(rename = "type")]
    pub kind: CamFollowerType,
    /// Default translating.
    pub motion: Option<CamFollowerMotion>,
    /// Signed distance of the follower's axis from the cam centre (m; > 0
    /// to the left of its motion seen from the cam centre); default 0.
    #[schema(value_type = Option<Quantity>)]
    pub offset: Option<Quantity>,
    /// A roller's radius, m.
    #[schema(value_type = Option<Quantity>)]
    pub roller_radius: Option<Quantity>,
    /// Oscillating: distance from the cam centre to the follower's pivot, m
    /// (the pivot on the cam frame's x axis, the arm reaching back towards
    /// the cam on its +y side; the lift turns the arm away from the cam).
    #[schema(value_type = Option<Quantity>)]
    pub pivot: Option<Quantity>,
    /// Oscillating: pivot to the roller's centre or to the face's line, m.
    #[schema(value_type = Option<Quantity>)]
    pub arm: Option<Quantity>,
}

/// Segments end to end (a list), or a lift Function of `theta` (an object).
#[derive(Clone, Debug, Serialize, ToSchema)]
#[serde(untagged)]
pub enum CamProgramDto {
    Segments(Vec<CamSegmentDto>),
    Lift(CamLiftDto),
}

/// Read by its JSON type (a list or an object), not by trying each variant
/// in turn: serde's untagged enums would take `[0]` as a lift of 0 (a
/// struct from a sequence) and lose every field's pointer.
impl<'de> Deserialize<'de> for CamProgramDto {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Program;
        impl<'de> serde::de::Visitor<'de> for Program {
            type Value = CamProgramDto;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("json-expect-program")
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, seq: A) -> Result<CamProgramDto, A::Error> {
                Vec::deserialize(serde::de::value::SeqAccessDeserializer::new(seq)).map(CamProgramDto::Segments)
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<CamProgramDto, A::Error> {
                CamLiftDto::deserialize(serde::de::value::MapAccessDeserializer::new(map)).map(CamProgramDto::Lift)
            }
        }
        d.deserialize_any(Program)
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamLiftDto {
    /// s(θ) in m (rad for an oscillating follower), a Function of `theta`, periodic over a turn, ≥ 0.
    #[schema(value_type = FunctionDto)]
    pub lift: FunctionDto,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamSizeDto {
    #[schema(value_type = Option<Quantity>)]
    pub max_pressure_angle: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub min_curvature_radius: Option<Quantity>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamDynamicsDto {
    /// kg; an oscillating follower's moment of inertia about its pivot, kg·m².
    #[schema(value_type = Quantity)]
    pub follower_mass: Quantity,
    pub spring: Option<CamSpringDto>,
    /// An external force on the follower along its motion away from the cam
    /// (N; an oscillating follower's moment about its pivot, N·m), a Function of `theta`.
    #[schema(value_type = Option<FunctionDto>)]
    pub force: Option<FunctionDto>,
    /// Friction at a flat face.
    pub friction: Option<CamFrictionDto>,
}

/// Coulomb friction at a flat face.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamFrictionDto {
    /// μ ≥ 0.
    #[schema(minimum = 0.0)]
    pub mu: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamSpringDto {
    /// N/m (an oscillating follower's: N·m/rad).
    #[schema(value_type = Quantity)]
    pub stiffness: Quantity,
    /// The spring's force at lift 0, N (its moment, N·m).
    #[schema(value_type = Option<Quantity>)]
    pub preload: Option<Quantity>,
}

/// The lift as the engine takes it.
pub enum Motion {
    Program(Program, Vec<&'static str>),
    Function(Box<[Function; 4]>),
}

/// A validated request, SI.
pub struct Problem {
    pub cam: Cam,
    pub motion: Motion,
    pub size: Option<[Option<f64>; 2]>,
    pub speed: f64,
    pub loads: Option<(Loads, Option<Function>)>,
    pub samples: usize,
    /// No `direction` was given where the sense changes the answer (an
    /// offset or an oscillating follower): ccw was taken, and said so.
    pub sense_assumed: bool,
}

impl CamRequest {
    pub fn to_problem(&self, limits: &Limits) -> Result<Problem, Vec<FieldError>> {
        let mut e = Errors::new(limits);
        let f = &self.follower;
        let lengths =
            [(&f.roller_radius, "roller_radius"), (&f.offset, "offset"), (&f.pivot, "pivot"), (&f.arm, "arm")];
        for (q, field) in lengths.into_iter().filter_map(|(q, field)| Some((q.as_ref()?, field))) {
            e.notice_bare_length(q, &format!("/follower/{field}"), BARE_MM);
        }
        if let Some(q) = &self.base_radius {
            e.notice_bare_length(q, "/base_radius", BARE_MM);
        }
        let cam = self.cam(&mut e);
        let motion = self.motion(&mut e);
        let size = match (&self.base_radius, &self.size) {
            (Some(_), Some(_)) => e.refuse("/size", Msg::new("cam-base-or-size")),
            (None, None) => e.refuse("", Msg::new("cam-base-required")),
            (Some(_), None) => Some(None),
            (None, Some(s)) => {
                let angle = s.max_pressure_angle.as_ref().and_then(|q| {
                    let v = e.angle(q, "/size/max_pressure_angle")?;
                    let between = Msg::new("field-between").num("min", 0.0).arg("max", "85°");
                    e.require_said(Some(v), |v| v > 0.0 && v < 1.5, "/size/max_pressure_angle", between)
                });
                let rho = s
                    .min_curvature_radius
                    .as_ref()
                    .and_then(|q| e.positive(q, Dim::LENGTH, "/size/min_curvature_radius"));
                if s.max_pressure_angle.is_none() && s.min_curvature_radius.is_none() {
                    e.say("/size", Msg::new("cam-size"));
                }
                Some(Some([angle, rho]))
            }
        };
        let speed = e.quantity(&self.speed, Dim::ANGULAR_SPEED, "/speed");
        let speed = e.require_said(speed, |w| w > 0.0, "/speed", Msg::new("cam-speed"));
        let loads = self.dynamics.as_ref().map(|d| loads(&mut e, d, cam.map(|c| c.follower), self.oscillating()));
        let samples = self.samples.unwrap_or(360);
        if !(4..=MAX_SAMPLES).contains(&samples) {
            e.say("/samples", Msg::new("field-between").arg("min", 4).arg("max", MAX_SAMPLES));
        }
        if !e.list.is_empty() {
            return Err(e.list);
        }
        let (cam, motion, size, speed) = (cam.unwrap(), motion.unwrap(), size.unwrap(), speed.unwrap());
        let loads = match loads {
            Some(Some(l)) => Some(l),
            _ => None,
        };
        let offset = matches!(cam.guide, Guide::Translating { offset } if offset != 0.0);
        let sense_assumed = self.direction.is_none() && (offset || self.oscillating());
        Ok(Problem { cam, motion, size, speed, loads, samples, sense_assumed })
    }

    fn cam(&self, e: &mut Errors) -> Option<Cam> {
        let f = &self.follower;
        let guide = self.guide(e);
        let follower = match (f.kind, &f.roller_radius) {
            (CamFollowerType::Roller, Some(r)) => {
                e.positive(r, Dim::LENGTH, "/follower/roller_radius").map(Follower::Roller)
            }
            (CamFollowerType::Roller, None) => e.refuse("/follower", Msg::new("cam-roller-radius")),
            (_, Some(_)) => e.refuse("/follower/roller_radius", Msg::new("cam-roller-only")),
            (CamFollowerType::Flat, None) => Some(Follower::Flat),
            (CamFollowerType::Knife, None) => Some(Follower::Roller(0.0)),
        };
        let base = match &self.base_radius {
            Some(q) => e.positive(q, Dim::LENGTH, "/base_radius"),
            None => Some(0.0),
        };
        let clockwise = self.direction == Some(CamSense::Cw);
        Some(Cam { follower: follower?, guide: guide?, base: base?, clockwise })
    }

    /// Translating (offset) or oscillating (pivot, arm), each field for its motion only.
    fn guide(&self, e: &mut Errors) -> Option<Guide> {
        let f = &self.follower;
        let oscillating = self.oscillating();
        let (mine, others) = if oscillating {
            ([("pivot", &f.pivot), ("arm", &f.arm)].to_vec(), [("offset", &f.offset)].to_vec())
        } else {
            ([("offset", &f.offset)].to_vec(), [("pivot", &f.pivot), ("arm", &f.arm)].to_vec())
        };
        let id = if oscillating { "cam-not-oscillating" } else { "cam-not-translating" };
        for (field, given) in others {
            if given.is_some() {
                e.say(&format!("/follower/{field}"), Msg::new(id));
            }
        }
        if !oscillating {
            let offset = mine[0].1.as_ref().map_or(Some(0.0), |q| e.quantity(q, Dim::LENGTH, "/follower/offset"));
            return Some(Guide::Translating { offset: offset? });
        }
        let [pivot, arm] = [0, 1].map(|k| {
            let (field, q) = mine[k];
            let at = format!("/follower/{field}");
            match q {
                None => e.refuse("/follower", Msg::new(["cam-needs-pivot", "cam-needs-arm"][k])),
                Some(q) if k == 1 && f.kind == CamFollowerType::Flat => {
                    let v = e.quantity(q, Dim::LENGTH, &at);
                    e.require_said(v, |v| v >= 0.0, &at, Msg::new("cam-not-negative"))
                }
                Some(q) => e.positive(q, Dim::LENGTH, &at),
            }
        });
        Some(Guide::Oscillating { pivot: pivot?, arm: arm? })
    }

    fn oscillating(&self) -> bool {
        self.follower.motion == Some(CamFollowerMotion::Oscillating)
    }

    /// The lift's dimension: a length, or an angle for an oscillating follower.
    pub fn lift_dim(&self) -> Dim {
        if self.oscillating() { Dim::ANGLE } else { Dim::LENGTH }
    }

    fn motion(&self, e: &mut Errors) -> Option<Motion> {
        match &self.program {
            CamProgramDto::Lift(l) => {
                let s = e.function_of(&l.lift, self.lift_dim(), TAU, "/program/lift", &["theta"])?;
                let (a, b) = (s.eval(0.0, Side::Right), s.eval(TAU, Side::Left));
                if (a - b).abs() > 1e-9 * a.abs().max(b.abs()).max(1e-3) {
                    return e.refuse("/program/lift", Msg::new("cam-lift-closed").num("start", a).num("end", b));
                }
                e.differentiable(&s, 3, "/program/lift")?;
                let d1 = s.derivative();
                let d2 = d1.derivative();
                let d3 = d2.derivative();
                Some(Motion::Function(Box::new([s, d1, d2, d3])))
            }
            CamProgramDto::Segments(list) => {
                program(e, list, "/program", self.lift_dim()).map(|(p, names)| Motion::Program(p, names))
            }
        }
    }
}

/// The follower's dynamics (None inside: in error); an oscillating
/// follower's are about its pivot: moment of inertia, N·m/rad, N·m.
fn loads(
    e: &mut Errors,
    d: &CamDynamicsDto,
    follower: Option<Follower>,
    oscillating: bool,
) -> Option<(Loads, Option<Function>)> {
    let [inertia, stiffness, force] = if oscillating {
        [Dim::INERTIA, Dim::TORSIONAL_STIFFNESS, Dim::TORQUE]
    } else {
        [Dim::MASS, Dim::STIFFNESS, Dim::FORCE]
    };
    let mass = e.quantity(&d.follower_mass, inertia, "/dynamics/follower_mass");
    let mass = e.require_said(mass, |m| m >= 0.0, "/dynamics/follower_mass", Msg::new("cam-not-negative"));
    let (stiffness, preload) = match &d.spring {
        None => (Some(0.0), Some(0.0)),
        Some(s) => {
            let k = e.quantity(&s.stiffness, stiffness, "/dynamics/spring/stiffness");
            let k = e.require_said(k, |k| k >= 0.0, "/dynamics/spring/stiffness", Msg::new("cam-not-negative"));
            let f0 = s.preload.as_ref().map_or(Some(0.0), |q| e.quantity(q, force, "/dynamics/spring/preload"));
            (k, f0)
        }
    };
    let force = match &d.force {
        None => Some(None),
        Some(f) => e.function_of(f, force, TAU, "/dynamics/force", &["theta"]).map(Some),
    };
    let mu = match (&d.friction, follower) {
        (None, _) => Some(0.0),
        (Some(f), Some(Follower::Flat)) if f.mu.is_finite() && f.mu >= 0.0 => Some(f.mu),
        (Some(_), Some(Follower::Flat)) => e.refuse("/dynamics/friction/mu", Msg::new("cam-mu")),
        (Some(_), _) => e.refuse("/dynamics/friction", Msg::new("cam-friction-flat")),
    };
    Some((Loads { mass: mass?, stiffness: stiffness?, preload: preload?, mu: mu? }, force?))
}
