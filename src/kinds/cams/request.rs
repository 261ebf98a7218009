//! The cam design request and its conversion, every error at its pointer.

use crate::engine::cam::design::{Cam, Follower, Guide, Loads};
use crate::engine::cam::{Law, Program, ProgramError, Segment};
use crate::engine::function::{Function, Side};
use crate::kind::limits::Limits;
use crate::kind::problem::FieldError;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use utoipa::ToSchema;

/// Most samples over a turn.
pub const MAX_SAMPLES: usize = 36_000;
/// Most segments of a program.
pub const MAX_SEGMENTS: usize = 100;

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
    /// The cam's sense of rotation; default ccw.
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
                f.write_str("a list of segments or {\"lift\": Function}")
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

/// A segment ending at `to` with the follower at `lift` by `law`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamSegmentDto {
    #[schema(value_type = Quantity)]
    pub to: Quantity,
    /// dwell, harmonic, cycloidal, polynomial-345, polynomial-4567, modified-sine or modified-trapezoid.
    pub law: String,
    /// m, or an angle for an oscillating follower (a dwell's may be left out: it holds).
    #[schema(value_type = Option<Quantity>)]
    pub lift: Option<Quantity>,
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
}

/// The wire name of each law.
pub const LAWS: [(&str, Law); 7] = [
    ("dwell", Law::Dwell),
    ("harmonic", Law::Harmonic),
    ("cycloidal", Law::Cycloidal),
    ("polynomial-345", Law::Poly345),
    ("polynomial-4567", Law::Poly4567),
    ("modified-sine", Law::ModifiedSine),
    ("modified-trapezoid", Law::ModifiedTrapezoid),
];

impl CamRequest {
    pub fn to_problem(&self, limits: &Limits) -> Result<Problem, Vec<FieldError>> {
        let mut e = Errors::new(limits);
        let cam = self.cam(&mut e);
        let motion = self.motion(&mut e);
        let size = match (&self.base_radius, &self.size) {
            (Some(_), Some(_)) => e.fail("/size", "give \"base_radius\" or \"size\", not both"),
            (None, None) => e.fail("", "give the cam's \"base_radius\", or \"size\" to find the smallest"),
            (Some(_), None) => Some(None),
            (None, Some(s)) => {
                let angle = s.max_pressure_angle.as_ref().and_then(|q| {
                    let v = e.angle(q, "/size/max_pressure_angle")?;
                    e.require(Some(v), |v| v > 0.0 && v < 1.5, "/size/max_pressure_angle", "must be between 0 and 85°")
                });
                let rho = s
                    .min_curvature_radius
                    .as_ref()
                    .and_then(|q| e.positive(q, Dim::LENGTH, "/size/min_curvature_radius"));
                if s.max_pressure_angle.is_none() && s.min_curvature_radius.is_none() {
                    e.push("/size", "give \"max_pressure_angle\" and/or \"min_curvature_radius\"");
                }
                Some(Some([angle, rho]))
            }
        };
        let speed = e.quantity(&self.speed, Dim::ANGULAR_SPEED, "/speed");
        let speed = e.require(speed, |w| w > 0.0, "/speed", "must be greater than 0 (the sense is \"direction\")");
        let loads = self.dynamics.as_ref().map(|d| loads(&mut e, d, cam.map(|c| c.follower), self.oscillating()));
        let samples = self.samples.unwrap_or(360);
        if !(4..=MAX_SAMPLES).contains(&samples) {
            e.push("/samples", format!("must be between 4 and {MAX_SAMPLES}"));
        }
        if !e.list.is_empty() {
            return Err(e.list);
        }
        let (cam, motion, size, speed) = (cam.unwrap(), motion.unwrap(), size.unwrap(), speed.unwrap());
        let loads = match loads {
            Some(Some(l)) => Some(l),
            _ => None,
        };
        Ok(Problem { cam, motion, size, speed, loads, samples })
    }

    fn cam(&self, e: &mut Errors) -> Option<Cam> {
        let f = &self.follower;
        let guide = self.guide(e);
        let follower = match (f.kind, &f.roller_radius) {
            (CamFollowerType::Roller, Some(r)) => {
                e.positive(r, Dim::LENGTH, "/follower/roller_radius").map(Follower::Roller)
            }
            (CamFollowerType::Roller, None) => e.fail("/follower", "a roller follower needs its \"roller_radius\""),
            (_, Some(_)) => e.fail("/follower/roller_radius", "applies to a roller follower only"),
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
        let motion = if oscillating { "an oscillating" } else { "a translating" };
        for (field, given) in others {
            if given.is_some() {
                e.push(&format!("/follower/{field}"), format!("does not apply to {motion} follower"));
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
                None => e.fail(
                    "/follower",
                    format!(
                        "an oscillating follower needs its \"{field}\" ({})",
                        [
                            "the distance from the cam centre to its pivot",
                            "from its pivot to the roller's centre, or to the face's line"
                        ][k]
                    ),
                ),
                Some(q) if k == 1 && f.kind == CamFollowerType::Flat => {
                    let v = e.quantity(q, Dim::LENGTH, &at);
                    e.require(v, |v| v >= 0.0, &at, "must not be negative")
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
                    return e.fail(
                        "/program/lift",
                        format!("must return to its start over a turn: s(0) = {a}, s(360°) = {b}"),
                    );
                }
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

/// A program of segments at pointer `at` (`/program`), with each segment's law's name.
pub fn program(e: &mut Errors, list: &[CamSegmentDto], at: &str, lift: Dim) -> Option<(Program, Vec<&'static str>)> {
    let root = at;
    if list.is_empty() || list.len() > MAX_SEGMENTS {
        return e.fail(root, format!("must hold 1 to {MAX_SEGMENTS} segments"));
    }
    let (mut start, mut from, mut segments, mut names) = (0.0, 0.0, Vec::new(), Vec::new());
    for (k, s) in list.iter().enumerate() {
        let at = format!("{root}/{k}");
        let to = e.angle(&s.to, &format!("{at}/to"));
        let law = match LAWS.iter().find(|(name, _)| *name == s.law) {
            Some(&(name, law)) => Some((name, law)),
            None => e.fail(
                &format!("{at}/law"),
                format!("unknown law '{}': one of {}", s.law, LAWS.map(|(n, _)| n).join(", ")),
            ),
        };
        let lift = match (&s.lift, law) {
            (Some(q), _) if lift == Dim::ANGLE => e.angle(q, &format!("{at}/lift")),
            (Some(q), _) => e.quantity(q, lift, &format!("{at}/lift")),
            (None, Some((_, Law::Dwell))) => Some(from),
            (None, Some(_)) => e.fail(&at, "a segment that moves needs its \"lift\" at its end"),
            (None, None) => None,
        };
        let (Some(to), Some((name, law)), Some(lift)) = (to, law, lift) else { return None };
        segments.push(Segment { law, start, span: to - start, from, to: lift });
        names.push(name);
        (start, from) = (to, lift);
    }
    match Program::new(segments) {
        Ok(p) => Some((p, names)),
        Err(err) => {
            let last = list.len() - 1;
            let (at, message) = match err {
                ProgramError::Empty { segment, .. } => {
                    (format!("{root}/{segment}/to"), "must be after the end of the segment before".to_string())
                }
                ProgramError::MovingDwell { segment, .. } => {
                    (format!("{root}/{segment}/lift"), "a dwell holds the lift of the segment before".into())
                }
                ProgramError::NotATurn { .. } => {
                    (format!("/program/{last}/to"), "the last segment must end at 360°".into())
                }
                ProgramError::NotClosed { .. } => {
                    (format!("/program/{last}/lift"), "the last segment must end at lift 0".into())
                }
                other => ("/program".to_string(), other.to_string()),
            };
            e.fail(&at, message)
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
    let mass = e.require(mass, |m| m >= 0.0, "/dynamics/follower_mass", "must not be negative");
    let (stiffness, preload) = match &d.spring {
        None => (Some(0.0), Some(0.0)),
        Some(s) => {
            let k = e.quantity(&s.stiffness, stiffness, "/dynamics/spring/stiffness");
            let k = e.require(k, |k| k >= 0.0, "/dynamics/spring/stiffness", "must not be negative");
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
        (Some(_), Some(Follower::Flat)) => e.fail("/dynamics/friction/mu", "must be a finite number ≥ 0"),
        (Some(_), _) => {
            e.fail("/dynamics/friction", "applies to a flat face (a roller rolls; a knife's friction is not modelled)")
        }
    };
    Some((Loads { mass: mass?, stiffness: stiffness?, preload: preload?, mu: mu? }, force?))
}
