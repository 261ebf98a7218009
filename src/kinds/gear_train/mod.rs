//! `POST /v1/gears/train`: speeds (Willis) and torques (virtual power) of an
//! ordinary or epicyclic gear train.

use crate::engine::gear_train::{Mesh, Train, TrainError};
use crate::engine::variants::round_sig;
use crate::i18n::Msg;
use crate::kind::Kind;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::{Errors, Quantity};
use crate::kind::validated;
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

const MAX_MEMBERS: usize = 100;

/// Seed 002's differential: sun 1 (60 teeth), planets 3 (30) on carrier 2,
/// ring 4 (120, internal); 1 and 2 turn at 100 and 50 rpm, 15 N·m on 1.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "members": ["1", "2", "3", "4"],
    "meshes": [
        {"a": "1", "teeth_a": 60, "b": "3", "teeth_b": 30, "carrier": "2"},
        {"a": "3", "teeth_a": 30, "b": "4", "teeth_b": 120, "carrier": "2", "internal": true}
    ],
    "speeds": [{"member": "1", "speed": "100 rpm"}, {"member": "2", "speed": "50 rpm"}],
    "torques": [{"member": "1", "torque": "15 N*m"}],
    "unknown_torques": ["2", "4"]
}))]
pub struct TrainRequest {
    /// Names of the moving members (shafts with their wheels, carriers);
    /// `ground` is the frame.
    #[schema(min_items = 1, max_items = 100)]
    pub members: Vec<String>,
    #[schema(min_items = 1, max_items = 100)]
    pub meshes: Vec<MeshDto>,
    /// As many as the train has degrees of freedom.
    pub speeds: Vec<GivenSpeed>,
    /// Known external torques (default none).
    pub torques: Option<Vec<GivenTorque>>,
    /// Members whose external torque keeps the motion steady, as many as the
    /// degrees of freedom (default none: speeds only).
    pub unknown_torques: Option<Vec<String>>,
}

/// Wheel a (on member `a`) meshing with wheel b, axes held by `carrier`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct MeshDto {
    pub a: String,
    #[schema(minimum = 1)]
    pub teeth_a: f64,
    pub b: String,
    #[schema(minimum = 1)]
    pub teeth_b: f64,
    /// The member holding both axes (default `ground`: an ordinary mesh).
    pub carrier: Option<String>,
    /// Wheel b is an internal gear (ring); default false.
    pub internal: Option<bool>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct GivenSpeed {
    pub member: String,
    #[schema(value_type = Quantity)]
    pub speed: Quantity,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct GivenTorque {
    pub member: String,
    #[schema(value_type = Quantity)]
    pub torque: Quantity,
}

/// One member's motion and load (SI: rad/s, N·m, W).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct MemberResult {
    pub member: String,
    pub speed: f64,
    /// The external torque on it (given, found, or 0).
    pub torque: f64,
    pub power: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct TrainResult {
    /// Moving members minus independent mesh equations.
    pub dof: usize,
    pub members: Vec<MemberResult>,
    /// Σ T·ω / max |T·ω| over the members (0 in exact arithmetic).
    pub power_residual: f64,
    pub method: String,
    #[serde(flatten)]
    pub notes: Notes,
}

impl crate::kind::JobResult for TrainResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
}

/// GearTrain: `POST /v1/gears/train`.
pub struct GearTrain;

impl Kind for GearTrain {
    const NAME: &'static str = "gear_train";
    const TITLE: &'static str = "kind-gear-train";
    const PATH: &'static str = "/v1/gears/train";
    const OPERATION_ID: &'static str = "create_gear_train_job";
    const TAG: &'static str = "gears";
    const SUMMARY: &'static str =
        "Speeds of every member (Willis) and the torques that keep it steady (virtual power).";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/dof", "1"),
        ("/members/*/power", "W"),
        ("/members/*/speed", "rad/s"),
        ("/members/*/torque", "N*m"),
        ("/power_residual", "1"),
    ];
    type Request = TrainRequest;
    type Result = TrainResult;

    fn compute(request: &TrainRequest, unknown: Vec<FieldError>, _limits: &Limits) -> Result<TrainResult, ApiError> {
        compute(request, unknown)
    }
}

/// A validated train with its given speeds, torques and unknown torques.
type Parts = (Train, Vec<(usize, f64)>, Vec<(usize, f64)>, Vec<usize>);

/// Validates and solves a request.
fn compute(request: &TrainRequest, unknown: Vec<FieldError>) -> Result<TrainResult, ApiError> {
    let (train, speeds, torques, asked) = validated(unknown, request.to_train())?;
    let s = train.solve(&speeds, &torques, &asked).map_err(|e| {
        let at = match e {
            TrainError::Speeds { .. } | TrainError::Inconsistent { .. } => "/speeds",
            TrainError::Torques { .. } | TrainError::TorquesSingular => "/unknown_torques",
            TrainError::Degenerate | TrainError::Locked => "/meshes",
        };
        ApiError::Invalid(vec![FieldError::said(at, msg(&e))])
    })?;
    let members = request
        .members
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let (w, t) = (s.speeds[k + 1], s.torques[k + 1]);
            MemberResult { member: name.clone(), speed: w, torque: t, power: t * w }
        })
        .collect();
    let mut notes = Notes::default();
    for msg in request.misassembled() {
        notes.warn(msg);
    }
    let method = notes.say("/method", Msg::new("accuracy-gear-train"));
    Ok(TrainResult { dof: s.dof, members, power_residual: s.power_residual, method, notes })
}

/// Why a train cannot be solved, as the catalogue says it.
fn msg(e: &TrainError) -> Msg {
    match *e {
        TrainError::Speeds { dof, given } => Msg::new("train-speeds").count("dof", dof).count("given", given),
        TrainError::Inconsistent { residual } => Msg::new("train-inconsistent").num("residual", round_sig(residual, 4)),
        TrainError::Torques { dof, asked } => Msg::new("train-torques").count("dof", dof).count("asked", asked),
        TrainError::TorquesSingular => Msg::new("train-torques-singular"),
        TrainError::Degenerate => Msg::new("train-degenerate"),
        TrainError::Locked => Msg::new("train-locked"),
    }
}

impl TrainRequest {
    /// Planets that cannot assemble with one module: a planet meshing a sun
    /// (externally) and a ring (internally) about one carrier sits as far
    /// from the axis in both meshes only where z_ring = z_sun + z_planet +
    /// z_planet′ (its wheel in each mesh); each that does not is said with
    /// the ring's count that would fit.
    fn misassembled(&self) -> Vec<Msg> {
        let carrier = |m: &MeshDto| m.carrier.as_deref().unwrap_or("ground").to_string();
        let mut out = Vec::new();
        for ring in self.meshes.iter().filter(|m| m.internal == Some(true)) {
            let suns = self.meshes.iter().filter(|m| m.internal != Some(true) && carrier(m) == carrier(ring));
            for sun in suns {
                // The planet is the ring mesh's first wheel; the sun its partner in this mesh.
                let (z_sun, z_planet) = if sun.b == ring.a {
                    (sun.teeth_a, sun.teeth_b)
                } else if sun.a == ring.a {
                    (sun.teeth_b, sun.teeth_a)
                } else {
                    continue;
                };
                let fits = z_sun + z_planet + ring.teeth_a;
                if (ring.teeth_b - fits).abs() > 1e-9 {
                    out.push(
                        Msg::new("warning-train-assembly")
                            .arg("planet", &ring.a)
                            .num("ring", ring.teeth_b)
                            .num("sun", z_sun)
                            .num("fits", fits),
                    );
                }
            }
        }
        out
    }

    fn to_train(&self) -> Result<Parts, Vec<FieldError>> {
        let mut e = Errors::default();
        if self.members.is_empty() || self.members.len() > MAX_MEMBERS {
            e.say("/members", Msg::new("train-members-count").arg("max", MAX_MEMBERS));
        }
        for (k, name) in self.members.iter().enumerate() {
            if name == "ground" || self.members[..k].contains(name) {
                e.say(&format!("/members/{k}"), Msg::new("train-frame-or-repeat").arg("name", name));
            }
        }
        let member = |e: &mut Errors, name: &str, at: &str| -> Option<usize> {
            if name == "ground" {
                return Some(0);
            }
            match self.members.iter().position(|m| m == name) {
                Some(k) => Some(k + 1),
                None => e.refuse(at, Msg::new("train-unknown-member").arg("name", name)),
            }
        };
        if self.meshes.is_empty() || self.meshes.len() > MAX_MEMBERS {
            e.say("/meshes", Msg::new("train-meshes-count").arg("max", MAX_MEMBERS));
        }
        let mut meshes = Vec::new();
        for (k, m) in self.meshes.iter().enumerate() {
            let at = format!("/meshes/{k}");
            let teeth = |e: &mut Errors, z: f64, field: &str| {
                (z.is_finite() && (1.0..=100_000.0).contains(&z))
                    .then_some(z)
                    .or_else(|| e.refuse(&format!("{at}/{field}"), Msg::new("train-teeth")))
            };
            let (a, za) = (member(&mut e, &m.a, &format!("{at}/a")), teeth(&mut e, m.teeth_a, "teeth_a"));
            let (b, zb) = (member(&mut e, &m.b, &format!("{at}/b")), teeth(&mut e, m.teeth_b, "teeth_b"));
            let carrier = member(&mut e, m.carrier.as_deref().unwrap_or("ground"), &format!("{at}/carrier"));
            if let (Some(a), Some(teeth_a), Some(b), Some(teeth_b), Some(carrier)) = (a, za, b, zb, carrier) {
                if a == b || a == carrier || b == carrier {
                    e.say(&at, Msg::new("train-mesh-wheels"));
                }
                meshes.push(Mesh { a, teeth_a, b, teeth_b, carrier, internal: m.internal.unwrap_or(false) });
            }
        }
        let speeds = self.speeds.iter().map(|s| (&s.member, &s.speed));
        let speeds = given(&mut e, "/speeds", speeds, Dim::ANGULAR_SPEED, &member);
        let torques = self.torques.as_deref().unwrap_or_default().iter().map(|t| (&t.member, &t.torque));
        let torques = given(&mut e, "/torques", torques, Dim::TORQUE, &member);
        let asked: Vec<usize> = (self.unknown_torques.as_deref().unwrap_or_default().iter().enumerate())
            .filter_map(|(k, name)| member(&mut e, name, &format!("/unknown_torques/{k}")))
            .collect();
        if asked.contains(&0) {
            e.say("/unknown_torques", Msg::new("train-frame-torque"));
        }
        if !e.list.is_empty() {
            return Err(e.list);
        }
        Ok((Train { members: self.members.len() + 1, meshes }, speeds, torques, asked))
    }
}

/// (member, value) pairs under `at`, in SI.
fn given<'a>(
    e: &mut Errors,
    at: &str,
    items: impl Iterator<Item = (&'a String, &'a Quantity)>,
    dim: Dim,
    member: &dyn Fn(&mut Errors, &str, &str) -> Option<usize>,
) -> Vec<(usize, f64)> {
    let field = if dim == Dim::TORQUE { "torque" } else { "speed" };
    items
        .enumerate()
        .filter_map(|(k, (name, q))| {
            let m = member(e, name, &format!("{at}/{k}/member"));
            let v = e.quantity(q, dim, &format!("{at}/{k}/{field}"));
            Some((m?, v?))
        })
        .collect()
}
