//! `POST /v1/rotor`: a rigid body on a frame turning about a fixed axis on
//! two bearings — momentum, kinetic energy, driving and gyroscopic moments,
//! and the bearing reactions (dynamic, static, total; rotating and fixed axes).

use crate::engine::rotor::{Rotor, RotorState, Support};
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
use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

const MAX_INSTANTS: usize = 10_000;

/// The body (about its centre of mass G, in the frame's axes x'y'z', x' the
/// bearings' axis), its spin relative to the frame, the bearings and the
/// frame's motion. Exactly one of `angles` and `times` (default: 12 angles
/// over a turn).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "mass": "1.5 kg",
    "inertia": {"xx": 0.00375, "yy": 0.0075, "zz": 0.00375},
    "cg": [0, -0.04, 0.1],
    "spin": [0, 20, 0],
    "bearings": [-0.15, 0.15],
    "gravity": [0, -9.8, 0],
    "frame": {"speed": "10 rad/s"},
    "angles": [0, "90 deg"]
}))]
pub struct RotorRequest {
    #[schema(value_type = Quantity)]
    pub mass: Quantity,
    pub inertia: InertiaDto,
    /// G from the origin O on the axis, m.
    #[schema(min_items = 3, max_items = 3)]
    pub cg: [f64; 3],
    /// The body's angular velocity relative to the frame, rad/s (default 0).
    /// The body must be symmetric about it (its inertia stays constant in the frame).
    #[schema(min_items = 3, max_items = 3)]
    pub spin: Option<[f64; 3]>,
    /// x' of bearing D and of bearing E (E takes the axial thrust), m.
    #[schema(min_items = 2, max_items = 2)]
    pub bearings: [f64; 2],
    /// Gravity in the fixed axes (which coincide with x'y'z' at angle 0), m/s² (default [0, −9.81, 0]).
    #[schema(min_items = 3, max_items = 3)]
    pub gravity: Option<[f64; 3]>,
    pub frame: FrameDto,
    /// Angles of the frame's turn at which to evaluate (not with `times`).
    #[schema(min_items = 1, max_items = 10000)]
    pub angles: Option<Vec<Quantity>>,
    /// Instants at which to evaluate (not with `angles`).
    #[schema(min_items = 1, max_items = 10000)]
    pub times: Option<Vec<Quantity>>,
}

/// Moments and products of inertia about G in the frame's axes, kg·m²; the
/// tensor is [[xx, −xy, −xz], [−xy, yy, −yz], [−xz, −yz, zz]] (products default 0).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct InertiaDto {
    pub xx: f64,
    pub yy: f64,
    pub zz: f64,
    pub xy: Option<f64>,
    pub xz: Option<f64>,
    pub yz: Option<f64>,
}

/// The frame's motion about x: speed Ω₀ and angle φ₀ at t = 0, constant acceleration γ.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct FrameDto {
    #[schema(value_type = Quantity)]
    pub speed: Quantity,
    #[schema(value_type = Option<Quantity>)]
    pub acceleration: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub angle: Option<Quantity>,
}

/// Forces on D and E (N) and the driving moment about the axis (N·m).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct SupportDto {
    pub d: [f64; 3],
    pub e: [f64; 3],
    pub driving_moment: f64,
}

/// The bearing forces in one set of axes: due to the motion, to the weight, and both.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct ReactionsDto {
    pub dynamic: SupportDto,
    #[serde(rename = "static")]
    pub static_: SupportDto,
    pub total: SupportDto,
}

/// One instant. Vectors are in the rotating axes x'y'z' except `reactions_fixed`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct RotorStateDto {
    pub t: f64,
    pub angle: f64,
    pub speed: f64,
    /// Q = m·V_G, N·s.
    pub momentum: [f64; 3],
    /// K about G and about O, kg·m²/s.
    pub angular_momentum_g: [f64; 3],
    pub angular_momentum_o: [f64; 3],
    pub kinetic_energy: f64,
    /// Ω i' × I_G·ω_r, N·m.
    pub gyroscopic_moment: [f64; 3],
    pub reactions: ReactionsDto,
    pub reactions_fixed: ReactionsDto,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct RotorResult {
    pub states: Vec<RotorStateDto>,
    pub method: String,
    #[serde(flatten)]
    pub notes: Notes,
}

impl crate::kind::JobResult for RotorResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
}

/// RigidRotor: `POST /v1/rotor`.
pub struct RigidRotor;

impl Kind for RigidRotor {
    const NAME: &'static str = "rotor";
    const TITLE: &'static str = "kind-rotor";
    const PATH: &'static str = "/v1/rotor";
    const OPERATION_ID: &'static str = "create_rotor_job";
    const TAG: &'static str = "calculators";
    const SUMMARY: &'static str = "The rotor at the requested angles or times.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/states/*/t", "s"),
        ("/states/*/angle", "rad"),
        ("/states/*/speed", "rad/s"),
        ("/states/*/kinetic_energy", "J"),
        ("/states/*/momentum/*", "kg*m/s"),
        ("/states/*/angular_momentum_g/*", "kg*m^2/s"),
        ("/states/*/angular_momentum_o/*", "kg*m^2/s"),
        ("/states/*/gyroscopic_moment/*", "N*m"),
        ("/states/*/*/*/driving_moment", "N*m"),
        ("/states/*/*/*/d/*", "N"),
        ("/states/*/*/*/e/*", "N"),
    ];
    type Request = RotorRequest;
    type Result = RotorResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };

    fn compute(request: &RotorRequest, unknown: Vec<FieldError>, _limits: &Limits) -> Result<RotorResult, ApiError> {
        compute(request, unknown)
    }
}

/// Validates and computes a request.
fn compute(request: &RotorRequest, unknown: Vec<FieldError>) -> Result<RotorResult, ApiError> {
    let (rotor, times) = validated(unknown, request.to_rotor())?;
    let states: Vec<RotorStateDto> = times.iter().map(|t| state_dto(&rotor.at(*t))).collect();
    // Inputs near f64's limits overflow (every field of a state is a number:
    // a null in its JSON is one that is not finite): refused, never served as null.
    if serde_json::to_string(&states).map_or(true, |text| text.contains("null")) {
        return Err(crate::kind::engine_failure(crate::engine::EngineError::NotFiniteResult, ""));
    }
    let mut notes = Notes::default();
    let method = notes.say("/method", Msg::new("accuracy-rotor"));
    Ok(RotorResult { states, method, notes })
}

fn state_dto(s: &RotorState) -> RotorStateDto {
    let v = |x: Vector3<f64>| [x.x, x.y, x.z];
    let support = |s: &Support| SupportDto { d: v(s.d), e: v(s.e), driving_moment: s.driving_moment };
    let fixed =
        |f: &[Vector3<f64>; 2], s: &Support| SupportDto { d: v(f[0]), e: v(f[1]), driving_moment: s.driving_moment };
    RotorStateDto {
        t: s.t,
        angle: s.angle,
        speed: s.speed,
        momentum: v(s.momentum),
        angular_momentum_g: v(s.angular_momentum_g),
        angular_momentum_o: v(s.angular_momentum_o),
        kinetic_energy: s.kinetic_energy,
        gyroscopic_moment: v(s.gyroscopic_moment),
        reactions: ReactionsDto {
            dynamic: support(&s.dynamic),
            static_: support(&s.static_),
            total: support(&s.total),
        },
        reactions_fixed: ReactionsDto {
            dynamic: fixed(&s.dynamic_fixed, &s.dynamic),
            static_: fixed(&s.static_fixed, &s.static_),
            total: fixed(&s.total_fixed, &s.total),
        },
    }
}

impl RotorRequest {
    pub fn to_rotor(&self) -> Result<(Rotor, Vec<f64>), Vec<FieldError>> {
        let mut e = Errors::default();
        let mass = e.positive(&self.mass, Dim::MASS, "/mass");
        let inertia = self.inertia(&mut e);
        let spin = Vector3::from(self.spin.unwrap_or_default());
        let gravity = Vector3::from(self.gravity.unwrap_or([0.0, -9.81, 0.0]));
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        for (at, ok) in
            [("/cg", finite(&self.cg)), ("/spin", finite(spin.as_slice())), ("/gravity", finite(gravity.as_slice()))]
        {
            if !ok {
                e.say(at, Msg::new("rotor-components"));
            }
        }
        let [xd, xe] = self.bearings;
        if !(xd.is_finite() && xe.is_finite() && xd != xe) {
            e.say("/bearings", Msg::new("rotor-bearings"));
        }
        if let Some(i) = inertia
            && !symmetric_about(&i, &spin)
        {
            e.say("/spin", Msg::new("rotor-symmetric"));
        }
        let f = &self.frame;
        let speed = e.quantity(&f.speed, Dim::ANGULAR_SPEED, "/frame/speed");
        let acceleration = f
            .acceleration
            .as_ref()
            .map_or(Some(0.0), |q| e.quantity(q, Dim::ANGULAR_ACCELERATION, "/frame/acceleration"));
        let angle = f.angle.as_ref().map_or(Some(0.0), |q| e.angle(q, "/frame/angle"));
        let (Some(mass), Some(inertia), Some(speed), Some(acceleration), Some(angle)) =
            (mass, inertia, speed, acceleration, angle)
        else {
            return Err(e.list);
        };
        let rotor = Rotor {
            mass,
            inertia,
            cg: Vector3::from(self.cg),
            spin,
            bearings: self.bearings,
            gravity,
            speed,
            acceleration,
            angle,
        };
        let times = self.times(&mut e, &rotor);
        if !e.list.is_empty() {
            return Err(e.list);
        }
        Ok((rotor, times))
    }

    fn inertia(&self, e: &mut Errors) -> Option<Matrix3<f64>> {
        let d = &self.inertia;
        let (xy, xz, yz) = (d.xy.unwrap_or(0.0), d.xz.unwrap_or(0.0), d.yz.unwrap_or(0.0));
        let i = Matrix3::new(d.xx, -xy, -xz, -xy, d.yy, -yz, -xz, -yz, d.zz);
        if !i.iter().all(|v| v.is_finite()) {
            return e.refuse("/inertia", Msg::new("rotor-inertia-finite"));
        }
        let eig = i.symmetric_eigenvalues();
        let scale = i.trace().abs().max(f64::MIN_POSITIVE);
        // Principal moments of a body: non-negative and each at most the sum of the other two.
        let physical = eig.iter().all(|l| *l >= -1e-12 * scale)
            && (0..3).all(|k| eig[k] <= eig[(k + 1) % 3] + eig[(k + 2) % 3] + 1e-12 * scale);
        if !physical {
            let msg = Msg::new("rotor-principal").num("first", eig[0]).num("second", eig[1]).num("third", eig[2]);
            return e.refuse("/inertia", msg);
        }
        Some(i)
    }

    /// The instants asked for: `times`, or the times the frame reaches `angles`.
    fn times(&self, e: &mut Errors, r: &Rotor) -> Vec<f64> {
        let default: Vec<Quantity> = (0..12).map(|k| Quantity::Number(k as f64 * std::f64::consts::PI / 6.0)).collect();
        let (list, field) = match (&self.angles, &self.times) {
            (Some(a), None) => (a, "angles"),
            (None, Some(t)) => (t, "times"),
            (None, None) => (&default, "angles"),
            _ => return e.refuse("", Msg::new("rotor-angles-or-times")).unwrap_or_default(),
        };
        if list.is_empty() || list.len() > MAX_INSTANTS {
            e.say(&format!("/{field}"), Msg::new("rotor-instants").arg("max", MAX_INSTANTS));
        }
        let mut out = Vec::new();
        for (k, q) in list.iter().enumerate() {
            let at = format!("/{field}/{k}");
            let t = if field == "times" {
                e.quantity(q, Dim::TIME, &at)
            } else {
                e.angle(q, &at).and_then(|phi| time_at(r, phi).or_else(|| e.refuse(&at, never(r, phi))))
            };
            out.extend(t);
        }
        out
    }
}

/// An angle the frame never reaches, and where it is at that position
/// first: φ + 2πk, k within 64 turns (a frame turning backwards reaches
/// 90° as −270°).
fn never(r: &Rotor, phi: f64) -> Msg {
    let first = (-64..=64)
        .map(|k| phi + std::f64::consts::TAU * f64::from(k))
        .filter_map(|alias| time_at(r, alias).map(|t| (t, alias)))
        .min_by(|a, b| a.0.total_cmp(&b.0));
    match first {
        Some((_, alias)) => Msg::new("rotor-never-alias").fig("degrees", alias.to_degrees()).fig("radians", alias),
        None => Msg::new("rotor-never"),
    }
}

/// The first t ≥ 0 with φ₀ + Ω₀t + ½γt² = φ.
fn time_at(r: &Rotor, phi: f64) -> Option<f64> {
    let (w, g, d) = (r.speed, r.acceleration, phi - r.angle);
    if g == 0.0 {
        return (w != 0.0 && d / w >= 0.0).then(|| d / w);
    }
    let disc = w * w + 2.0 * g * d;
    if disc < 0.0 {
        return None;
    }
    [(-w + disc.sqrt()) / g, (-w - disc.sqrt()) / g].into_iter().filter(|t| *t >= 0.0).reduce(f64::min)
}

/// I·s ∥ s and I isotropic in the plane normal to s (true when s = 0).
fn symmetric_about(i: &Matrix3<f64>, spin: &Vector3<f64>) -> bool {
    if spin.norm() == 0.0 {
        return true;
    }
    let s = spin.normalize();
    let p = Matrix3::identity() - s * s.transpose();
    let lambda = s.dot(&(i * s));
    let mu = 0.5 * (i.trace() - lambda);
    let tol = 1e-9 * i.trace().abs().max(f64::MIN_POSITIVE);
    (i * s - lambda * s).norm() <= tol && (p * i * p - mu * p).norm() <= tol
}
