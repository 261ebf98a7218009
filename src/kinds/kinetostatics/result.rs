//! The `result` of a kinetostatics job, as stored and served, and its CSV table.

use super::request::Problem;
use super::shaking::{CounterweightDto, ShakingDto, largest};
use crate::engine::kinetostatics::{Motion, Step, Totals, energy};
use crate::engine::model::{Coordinate, Driver, Mechanism};
use crate::i18n::Msg;
use crate::kind::notes::Notes;
use crate::kinds::mechanism::motion3::{BodyMotion3, Reaction3};
use crate::kinds::mechanism::track::{PointState, states};
use crate::kinds::mechanism::{
    ByName, ContactDto, Coords, EnergyDto, Name, Names, ReactionDto, Reactions, contact_warnings,
};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::sync::Arc;
use utoipa::ToSchema;

/// A number for one input, a list (in input order) for several.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(untagged)]
pub enum Scalars {
    One(f64),
    Many(Vec<f64>),
}

impl Scalars {
    pub(crate) fn of(v: &[f64]) -> Self {
        if v.len() == 1 { Self::One(v[0]) } else { Self::Many(v.to_vec()) }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct GrublerDto {
    /// 3(N − 1) − 2·P_I − P_II, N counting the ground; in space Kutzbach's
    /// 6(N − 1) − Σ(6 − fᵢ).
    pub mobility: i64,
    /// 3(N − 1) equilibrium equations (in space 6(N − 1)).
    pub equations: i64,
    /// Reaction components 2·P_I + P_II plus one driving action per input;
    /// in space the reactions' Σ(6 − fᵢ) alone (equations − unknowns is
    /// then the mobility).
    pub unknowns: i64,
}

/// Position, velocity and acceleration of a body's centre of mass and
/// rotation. A massless body drawn without `cg` has no centre of mass:
/// its x, y, v and a are null (`track` follows any of its points).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BodyMotion {
    #[schema(value_type = String)]
    pub body: Name,
    pub x: Option<f64>,
    pub y: Option<f64>,
    /// Rotation from the drawn configuration, rad.
    pub theta: f64,
    pub vx: Option<f64>,
    pub vy: Option<f64>,
    pub omega: f64,
    pub ax: Option<f64>,
    pub ay: Option<f64>,
    pub alpha: f64,
    /// The resultant of the body's inertia forces at its centre of mass,
    /// −m·a_G (N): with `inertia_moment`, what d'Alembert adds to the loads.
    #[schema(value_type = Option<Coords>)]
    pub inertia_force: Option<[f64; 2]>,
    /// The moment of the body's inertia forces about its centre of mass, −I_G·α (N·m).
    pub inertia_moment: f64,
}

/// A step's bodies: planar (x, y, θ) or spatial (a mechanism with
/// `"space": "spatial"`).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[serde(untagged)]
pub enum Kinematics {
    Planar(Vec<BodyMotion>),
    Spatial(Vec<BodyMotion3>),
}

/// A step's reactions: planar, or spatial as forces and moments.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum StepReactions {
    Planar(Reactions),
    Spatial(Vec<Reaction3>),
}

/// [`StepReactions`] as the document states it.
#[derive(Serialize, ToSchema)]
#[serde(untagged)]
#[allow(dead_code)]
pub enum StepReactionsSchema<'a> {
    Planar(Vec<ReactionDto<'a>>),
    Spatial(Vec<Reaction3>),
}

#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct StepDto {
    #[schema(value_type = Scalars)]
    pub input: Scalars,
    /// Torque (N·m) or force (N) of each input on the second body of its joint.
    #[schema(value_type = Option<Scalars>)]
    pub driving: Option<Scalars>,
    #[schema(value_type = Option<StepReactionsSchema>)]
    pub reactions: Option<StepReactions>,
    /// I*(φ), one input only.
    pub reduced_inertia: Option<f64>,
    /// M*(φ) of every load, driver excluded.
    pub reduced_torque: Option<f64>,
    /// Quinn's energy-contribution coefficient T_body/T of each moving body (one input).
    #[schema(value_type = Option<BTreeMap<String, f64>>)]
    pub energy_contribution: Option<ByName>,
    /// Condition number of Φ_q (joints and inputs). The exact 2-norm κ₂ (an
    /// SVD) where `outputs` has "condition", or where the estimate below
    /// exceeds 100 (so every near-singular position is measured exactly);
    /// elsewhere the 1-norm κ₁ from Φ_q's LU: exact (Φ_q⁻¹ formed) up to
    /// 12 coordinates, estimated by Hager's method (LAPACK's xGECON) beyond;
    /// within a factor of the coordinates' number of κ₂.
    pub jacobian_condition: f64,
    /// The same of Φ_q scaled by the mechanism's size (each length
    /// coordinate in units of the drawing's size L, each row divided by its
    /// largest entry): free of the units and of the size of the drawing,
    /// it decides the singular (above 1e6) and near-singular (1e4) positions.
    pub scaled_condition: f64,
    /// A singular position (toggle, change point): nothing but the input is computed here.
    pub singular: bool,
    pub kinematics: Option<Kinematics>,
    /// Where `outputs` has "energy".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy: Option<EnergyDto>,
    /// The points of `track`, where given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub points: Option<Vec<PointState>>,
    /// Every contact joint's state, with the reactions.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contacts: Option<Vec<ContactDto>>,
    /// Where `outputs` has "shaking".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shaking: Option<ShakingDto>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct SummaryDto {
    #[schema(value_type = Option<Scalars>)]
    pub max_abs_driving: Option<Scalars>,
    #[schema(value_type = Option<Scalars>)]
    pub mean_driving: Option<Scalars>,
    #[schema(value_type = Option<Scalars>)]
    pub rms_driving: Option<Scalars>,
    /// Largest reaction force magnitude per joint (null when undetermined or not computed).
    pub max_reaction: BTreeMap<String, Option<f64>>,
    /// Largest |driving from multipliers − driving from virtual power| / max |driving|.
    pub virtual_power_residual: Option<f64>,
    /// Whether any sampled position is singular (scaled condition number above 1e6):
    /// its step has no driving action, reactions or reduced quantities.
    pub singular: bool,
    #[schema(value_type = Vec<Scalars>)]
    pub singular_inputs: Vec<Scalars>,
    /// Inputs where the scaled condition number exceeds 1e4 (results valid but sensitive).
    #[schema(value_type = Vec<Scalars>)]
    pub near_singular_inputs: Vec<Scalars>,
    pub max_jacobian_condition: f64,
    /// The largest `scaled_condition` of the regular steps.
    pub max_scaled_condition: f64,
    /// The largest |shaking force| over the sweep (N), where `outputs` has "shaking".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_shaking_force: Option<f64>,
    /// The largest |shaking moment| over the sweep (N·m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_shaking_moment: Option<f64>,
    /// The largest |shaking force| with the `counterweights` (N).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_shaking_force_balanced: Option<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct KinetostaticsAccuracy {
    /// Same as summary.virtual_power_residual: the two independent driving actions agree to this.
    pub virtual_power_residual: Option<f64>,
    /// Largest |Φ(q)| left by Newton–Raphson, m or rad.
    pub max_constraint_residual: f64,
    pub max_newton_iterations: usize,
    /// Largest number of fixed-point iterations of joint friction (0 without friction).
    pub max_friction_iterations: usize,
    pub method: String,
}

/// A driven input: its joint and the units of its coordinate and driving action.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct InputInfo {
    /// The input joint (absent for an input on a point or a body).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joint: Option<String>,
    /// The point whose displacement along a direction is the input.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<String>,
    /// The body the input's point belongs to, or whose rotation is the input.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub body: Option<String>,
    /// The joint where the driving effort acts (the input's own joint by default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub actuator: Option<String>,
    /// "rad" (a revolute joint, a body) or "m" (a prismatic joint, a point).
    pub coordinate_unit: String,
    /// "N*m" (a torque: at a revolute joint, on a body) or "N" (a force:
    /// along a prismatic joint, on a point).
    pub driving_unit: String,
}

impl InputInfo {
    /// What driver `d` names and its units; `point` its point's name.
    fn new(p: &Problem, d: &Driver, point: Option<&String>, joint_names: &[String]) -> Self {
        let m = &p.mechanism;
        let (joint, body) = match d.coordinate {
            Coordinate::Joint(k) => (Some(joint_names[k].clone()), None),
            Coordinate::Point { body, .. } | Coordinate::Body(body) => (None, Some(p.body_names[body].clone())),
        };
        let linear = m.is_length(d.coordinate);
        let effort_linear = d.actuator.map_or(linear, |a| m.is_length(Coordinate::Joint(a)));
        Self {
            actuator: d.actuator.map(|a| joint_names[a].clone()).or_else(|| joint.clone()),
            joint,
            point: point.filter(|_| matches!(d.coordinate, Coordinate::Point { .. })).cloned(),
            body,
            coordinate_unit: if linear { "m" } else { "rad" }.into(),
            driving_unit: if effort_linear { "N" } else { "N*m" }.into(),
        }
    }
}

/// Result of a kinetostatics job (SI units).
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct KinetostaticsResult {
    pub inputs: Vec<InputInfo>,
    /// Degrees of freedom from the rank of the constraint Jacobian.
    pub dof: usize,
    pub grubler: GrublerDto,
    pub redundant_constraints: usize,
    pub steps: Vec<StepDto>,
    pub summary: SummaryDto,
    pub accuracy: KinetostaticsAccuracy,
    #[serde(flatten)]
    pub notes: Notes,
    /// Where the points went, for a mechanism given by its `dimensions` (m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<BTreeMap<String, Vec<f64>>>)]
    pub assembled_points: Option<BTreeMap<String, [f64; 2]>>,
    /// The counterweights of `balance`, in its order.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub counterweights: Option<Vec<CounterweightDto>>,
}

impl crate::kind::JobResult for KinetostaticsResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
    fn rows(&self) -> Option<crate::kind::Rows> {
        let field = if self.inputs.len() > 1 { "/input/0/steps" } else { "/input/steps" };
        let also = "size-also-outputs";
        Some(crate::kind::Rows { field: field.into(), count: self.steps.len(), also })
    }
}

/// How the positions were found, then the rest.
fn method(closed_form: bool) -> Msg {
    let assembly = if closed_form { "accuracy-assembly-closed-form" } else { "accuracy-assembly-newton" };
    Msg::new("accuracy-kinetostatics").with("assembly", Msg::new(assembly))
}

impl KinetostaticsResult {
    /// The result of a sweep's `steps` (each from [`StepDto::new`]) and its totals.
    pub fn new(s: Totals, steps: Vec<StepDto>, p: &Problem, joint_names: &[String]) -> Self {
        let mob = &s.mobility;
        let mut notes = Notes::default();
        notes.extend(p.assembled.iter().flat_map(|a| a.warnings.iter().cloned()));
        if mob.redundant_constraints > 0 {
            let joints: Vec<&str> = mob.indeterminate_joints.iter().map(|&j| joint_names[j].as_str()).collect();
            notes.warn(
                Msg::new("warning-redundant-constraints")
                    .count("count", mob.redundant_constraints)
                    .arg("joints", joints.join(", ")),
            );
        }
        let first = |s: &StepDto| match &s.input {
            Scalars::One(v) => *v,
            Scalars::Many(v) => v[0],
        };
        let contacts = steps.iter().filter_map(|s| Some((first(s), s.contacts.as_deref()?)));
        notes.extend(contact_warnings(contacts, &p.mechanism, |v| p.written.said(v), false));
        let sum = &s.summary;
        let [max_shaking_force, max_shaking_moment, max_shaking_force_balanced] =
            largest(steps.iter().filter_map(|s| s.shaking.as_ref()));
        let driving = |v: &Vec<f64>| p.outputs.driving.then(|| Scalars::of(v));
        let inputs = (p.mechanism.drivers.iter().zip(&p.input_points))
            .map(|(d, point)| InputInfo::new(p, d, point.as_ref(), joint_names))
            .collect();
        Self {
            inputs,
            dof: mob.dof,
            grubler: GrublerDto {
                mobility: mob.grubler.mobility,
                equations: mob.grubler.equations,
                unknowns: mob.grubler.unknowns,
            },
            redundant_constraints: mob.redundant_constraints,
            steps,
            summary: SummaryDto {
                max_abs_driving: driving(&sum.max_abs_driving),
                mean_driving: driving(&sum.mean_driving),
                rms_driving: driving(&sum.rms_driving),
                max_reaction: joint_names
                    .iter()
                    .cloned()
                    .zip(sum.max_reaction.iter().copied())
                    .filter(|_| p.outputs.reactions)
                    .collect(),
                virtual_power_residual: sum.virtual_power_residual,
                singular: !sum.singular.is_empty(),
                singular_inputs: sum.singular.iter().map(|v| Scalars::of(v)).collect(),
                near_singular_inputs: sum.near_singular.iter().map(|v| Scalars::of(v)).collect(),
                max_jacobian_condition: sum.max_condition,
                max_scaled_condition: sum.max_scaled_condition,
                max_shaking_force,
                max_shaking_moment,
                max_shaking_force_balanced,
            },
            accuracy: KinetostaticsAccuracy {
                virtual_power_residual: sum.virtual_power_residual,
                max_constraint_residual: s.max_constraint_residual,
                max_newton_iterations: s.max_iterations,
                max_friction_iterations: s.max_friction_iterations,
                method: notes.say("/accuracy/method", method(s.closed_form)),
            },
            notes,
            assembled_points: p.assembled.as_ref().map(|a| a.points.clone()),
            counterweights: p
                .balance
                .as_ref()
                .map(|(_, w)| w.iter().map(|w| CounterweightDto::new(w, &p.body_names)).collect()),
        }
    }
}

impl StepDto {
    /// The engine's step with the joints' and bodies' names.
    pub fn new(s: &Step, p: &Problem, n: &Arc<Names>) -> Self {
        let (joint_names, names) = (&n.joints[..], &n.bodies[..]);
        let reactions =
            (p.outputs.reactions && !s.singular).then(|| Reactions::new(n, &s.reactions, &s.contacts, &p.mechanism));
        let reactions = reactions.map(StepReactions::Planar);
        let contacts = (reactions.is_some() && !s.contacts.is_empty())
            .then(|| s.contacts.iter().map(|c| ContactDto::new(c, joint_names)).collect());
        StepDto {
            input: Scalars::of(&s.input),
            driving: (p.outputs.driving && !s.singular).then(|| Scalars::of(&s.driving)),
            reactions,
            reduced_inertia: s.reduced_inertia,
            reduced_torque: s.reduced_torque,
            energy_contribution: s.energy_shares.as_ref().map(|v| ByName::ordered(&n.moving, &names[1..], v)),
            jacobian_condition: s.condition,
            scaled_condition: s.scaled_condition,
            singular: s.singular,
            kinematics: s
                .kinematics
                .as_ref()
                .filter(|_| p.kinematics)
                .map(|m| Kinematics::Planar(motion(m, &p.mechanism, names, &p.centred))),
            energy: s
                .kinematics
                .as_ref()
                .filter(|_| p.energy)
                .map(|m| EnergyDto::new(energy(&p.mechanism, &p.loads, &m.q, &m.qd), names, &n.moving)),
            points: s
                .kinematics
                .as_ref()
                .filter(|_| !p.tracked.is_empty())
                .map(|m| states(&p.mechanism, &p.tracked, [&m.q, &m.qd, &m.qdd])),
            contacts,
            shaking: s.kinematics.as_ref().filter(|_| !s.singular).and_then(|m| ShakingDto::new(p, m)),
        }
    }
}

/// Every moving body's motion; `centred[b]` says whether moving body b has
/// a centre of mass to report.
fn motion(m: &Motion, mechanism: &Mechanism, names: &[Name], centred: &[bool]) -> Vec<BodyMotion> {
    (0..names.len() - 1)
        .map(|b| {
            let c = 3 * b;
            let at = |v: &[f64], k: usize| centred[b].then_some(v[c + k]);
            let body = &mechanism.bodies[b + 1];
            BodyMotion {
                body: names[b + 1].clone(),
                x: at(&m.q, 0),
                y: at(&m.q, 1),
                theta: m.q[c + 2],
                vx: at(&m.qd, 0),
                vy: at(&m.qd, 1),
                omega: m.qd[c + 2],
                ax: at(&m.qdd, 0),
                ay: at(&m.qdd, 1),
                alpha: m.qdd[c + 2],
                inertia_force: centred[b].then(|| [-body.mass * m.qdd[c], -body.mass * m.qdd[c + 1]]),
                inertia_moment: -body.inertia * m.qdd[c + 2],
            }
        })
        .collect()
}
