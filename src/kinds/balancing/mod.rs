//! `POST /v1/balancing`: a rigid rotor's static and dynamic unbalance, from
//! point masses or from a rotor request's body, and the corrections that
//! remove it in one plane (static balancing) or two (dynamic), with the
//! bearing forces before and after at a given speed
//! ([`crate::engine::balancing`] has the symbols and equations).

mod plots;
mod wire;

pub use wire::{
    BalancingCorrectionDto, BalancingRequest, BalancingResult, CorrectionPlaneDto, PointMassDto, UnbalanceDto,
};

use crate::engine::balancing::{self, Mass, Plane, Unbalance, polar};
use crate::i18n::Msg;
use crate::kind::Kind;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::plots::Plots;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Errors;
use crate::kind::validated;
use crate::units::Dim;
use nalgebra::Vector2;
use wire::{BalancingResidualDto, BearingForcesDto};

/// Point masses a request may list.
const MAX_MASSES: usize = 1000;

/// Balancing: `POST /v1/balancing`.
pub struct Balancing;

impl Kind for Balancing {
    const NAME: &'static str = "balancing";
    const TITLE: &'static str = "kind-balancing";
    const PATH: &'static str = "/v1/balancing";
    const OPERATION_ID: &'static str = "create_balancing_job";
    const TAG: &'static str = "calculators";
    const SUMMARY: &'static str = "A rigid rotor's unbalance and its corrections in one plane (static) or two (dynamic), with the bearing forces.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/static_unbalance/value", "kg*m"),
        ("/static_unbalance/angle", "rad"),
        ("/dynamic_unbalance/value", "kg*m^2"),
        ("/dynamic_unbalance/angle", "rad"),
        ("/dynamic_unbalance/about", "m"),
        ("/corrections/*/plane", "m"),
        ("/corrections/*/radius", "m"),
        ("/corrections/*/mass", "kg"),
        ("/corrections/*/angle", "rad"),
        ("/corrections/*/mass_radius", "kg*m"),
        ("/residual/static", "kg*m"),
        ("/residual/dynamic", "kg*m^2"),
        ("/reactions/speed", "rad/s"),
        ("/reactions/bearings/*", "m"),
        ("/reactions/before/*/*", "N"),
        ("/reactions/after/*/*", "N"),
    ];
    type Request = BalancingRequest;
    type Result = BalancingResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };

    fn compute(request: &BalancingRequest, unknown: Vec<FieldError>, _: &Limits) -> Result<BalancingResult, ApiError> {
        let read = validated(unknown, request.read())?;
        Ok(result(&read))
    }
}

/// A request read in SI: the unbalance, the correction planes ordered by
/// z, and the speed and bearings where the reactions are asked.
struct Read {
    before: Unbalance,
    planes: Vec<Plane>,
    reactions: Option<(f64, [f64; 2])>,
    /// The rotor's length along z: its masses (or its bearings and G), the
    /// bearings asked and the planes.
    span: f64,
}

/// Two planes closer than this fraction of the rotor's length are said:
/// their corrections grow as 1/(z₂ − z₁).
const CLOSE_PLANES: f64 = 0.01;

fn result(r: &Read) -> BalancingResult {
    let (corrections, after) = balancing::balance(r.before, &r.planes);
    let z1 = r.planes[0].z;
    let (u, d) = (polar(r.before.u), polar(r.before.about(z1)));
    let mut notes = Notes::default();
    let method = notes.say(
        "/method",
        Msg::new(if r.planes.len() == 1 { "accuracy-balancing-static" } else { "accuracy-balancing-dynamic" }),
    );
    // One plane leaves D(z₁) as it was: said unless it is rounding of D(0) − z₁U's terms.
    let left = polar(after.about(z1)).0;
    if r.planes.len() == 1 && left > 1e-12 * (polar(r.before.d0).0 + z1.abs() * u.0) {
        notes.warn(Msg::new("warning-balancing-couple-left").num("couple", left));
    }
    if let [p1, p2] = r.planes[..] {
        let gap = p2.z - p1.z;
        if gap < CLOSE_PLANES * r.span {
            let most = corrections.iter().map(|c| c.mass).fold(0.0, f64::max);
            notes.warn(
                Msg::new("warning-balancing-planes-close")
                    .fig("gap", gap)
                    .fig("span", r.span)
                    .fig("ratio", r.span / gap)
                    .fig("mass", most),
            );
        }
    }
    let reactions = r.reactions.map(|(speed, bearings)| BearingForcesDto {
        speed,
        bearings,
        before: balancing::bearing_forces(&r.before, speed, bearings).map(|f| [f.x, f.y]),
        after: balancing::bearing_forces(&after, speed, bearings).map(|f| [f.x, f.y]),
    });
    BalancingResult {
        static_unbalance: UnbalanceDto { value: u.0, angle: u.1 },
        dynamic_unbalance: wire::DynamicUnbalanceDto { value: d.0, angle: d.1, about: z1 },
        corrections: corrections.iter().map(BalancingCorrectionDto::from).collect(),
        residual: BalancingResidualDto { static_: polar(after.u).0, dynamic: left },
        reactions,
        method,
        notes,
    }
}

impl BalancingRequest {
    fn read(&self) -> Result<Read, Vec<FieldError>> {
        let mut e = Errors::default();
        let body = match (&self.masses, &self.rotor) {
            (Some(masses), None) => Some(Body::Masses(self.masses(&mut e, masses))),
            (None, Some(rotor)) => rotor_body(&mut e, rotor),
            _ => e.refuse("", Msg::new("balancing-masses-or-rotor")),
        };
        let planes = self.planes(&mut e);
        let reactions = self.reactions(&mut e, body.as_ref());
        match (body, planes, e.list.is_empty()) {
            (Some(body), Some(planes), true) => {
                let along = body.along().chain(planes.iter().map(|p| p.z)).chain(reactions.iter().flat_map(|r| r.1));
                let (lo, hi) = along.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| (lo.min(z), hi.max(z)));
                Ok(Read { before: body.unbalance(), planes, reactions, span: hi - lo })
            }
            _ => Err(e.list),
        }
    }

    fn masses(&self, e: &mut Errors, masses: &[PointMassDto]) -> Vec<Mass> {
        if masses.is_empty() || masses.len() > MAX_MASSES {
            e.say("/masses", Msg::new("balancing-masses-count").arg("max", MAX_MASSES));
        }
        let read = |e: &mut Errors, k: usize, p: &PointMassDto| {
            let at = |field: &str| format!("/masses/{k}/{field}");
            let m = e.quantity(&p.mass, Dim::MASS, &at("mass"));
            let m = e.require_said(m, |m| m >= 0.0, &at("mass"), Msg::new("field-finite-not-negative"));
            let r = e.quantity(&p.radius, Dim::LENGTH, &at("radius"));
            let r = e.require_said(r, |r| r >= 0.0, &at("radius"), Msg::new("field-finite-not-negative"));
            let theta = e.angle(&p.angle, &at("angle"));
            let z = e.quantity(&p.plane, Dim::LENGTH, &at("plane"));
            Some(Mass { m: m?, r: r?, theta: theta?, z: z? })
        };
        masses.iter().enumerate().filter_map(|(k, p)| read(e, k, p)).collect()
    }

    /// The planes ordered by z: one or two, distinct, each radius > 0.
    fn planes(&self, e: &mut Errors) -> Option<Vec<Plane>> {
        if !(1..=2).contains(&self.planes.len()) {
            return e.refuse("/planes", Msg::new("balancing-planes-count"));
        }
        let mut planes = Vec::new();
        for (k, p) in self.planes.iter().enumerate() {
            let z = e.quantity(&p.z, Dim::LENGTH, &format!("/planes/{k}/z"));
            let radius = e.positive(&p.radius, Dim::LENGTH, &format!("/planes/{k}/radius"));
            planes.push(Plane { z: z?, radius: radius? });
        }
        if planes.len() == 2 && planes[0].z == planes[1].z {
            return e.refuse("/planes/1/z", Msg::new("balancing-planes-apart"));
        }
        planes.sort_by(|a, b| a.z.total_cmp(&b.z));
        Some(planes)
    }

    /// The speed and bearings of the reactions: the request's, else the
    /// rotor's; none where both are missing, refused where one is.
    fn reactions(&self, e: &mut Errors, body: Option<&Body>) -> Option<(f64, [f64; 2])> {
        let rotor = match body {
            Some(Body::Rotor(r)) => Some(r),
            _ => None,
        };
        let speed = match &self.speed {
            Some(q) => Some(e.quantity(q, Dim::ANGULAR_SPEED, "/speed")?),
            None => rotor.map(|r| r.speed),
        };
        let bearings = match &self.bearings {
            Some([a, b]) => {
                let (za, zb) = (e.quantity(a, Dim::LENGTH, "/bearings/0"), e.quantity(b, Dim::LENGTH, "/bearings/1"));
                let [za, zb] = [za?, zb?];
                if za == zb {
                    return e.refuse("/bearings/1", Msg::new("rotor-bearings"));
                }
                Some([za, zb])
            }
            None => rotor.map(|r| r.bearings),
        };
        // One without the other asks for the forces: said, not left out in silence.
        match (speed, bearings, body) {
            (Some(_), None, Some(_)) => {
                e.refuse("/bearings", Msg::new("balancing-reactions-need").arg("field", "bearings"))
            }
            (None, Some(_), Some(_)) => e.refuse("/speed", Msg::new("balancing-reactions-need").arg("field", "speed")),
            _ => speed.zip(bearings),
        }
    }
}

/// What is balanced: point masses, or a rotor kind's body.
enum Body {
    Masses(Vec<Mass>),
    Rotor(crate::engine::rotor::Rotor),
}

impl Body {
    /// Where the body is along z: its masses' planes, or a rotor's bearings and G.
    fn along(&self) -> Box<dyn Iterator<Item = f64> + '_> {
        match self {
            Body::Masses(masses) => Box::new(masses.iter().map(|m| m.z)),
            Body::Rotor(r) => Box::new(r.bearings.into_iter().chain([r.cg.x])),
        }
    }

    /// U and D(0). A rotor's axis is its x'; the balancing planes' (x, y)
    /// are its (y', z'): U = m(y_G, z_G), D(0) = ∫x'(y', z') dm =
    /// (P_x'y' + m x_G y_G, P_x'z' + m x_G z_G), P the products of inertia about G.
    fn unbalance(&self) -> Unbalance {
        match self {
            Body::Masses(masses) => Unbalance::of(masses),
            Body::Rotor(r) => {
                let (m, g) = (r.mass, r.cg);
                let (pxy, pxz) = (-r.inertia[(0, 1)], -r.inertia[(0, 2)]);
                let u = Vector2::new(m * g.y, m * g.z);
                Unbalance { u, d0: Vector2::new(pxy, pxz) + g.x * u }
            }
        }
    }
}

/// A rotor request's body, read as the rotor kind reads it (its errors under `/rotor`).
fn rotor_body(e: &mut Errors, rotor: &crate::kinds::rotor::RotorRequest) -> Option<Body> {
    match rotor.to_rotor() {
        Ok((r, _)) => Some(Body::Rotor(r)),
        Err(list) => {
            let under = ApiError::Invalid(list).under("/rotor");
            e.list.extend(under.fields().iter().cloned());
            None
        }
    }
}

impl From<&balancing::Correction> for BalancingCorrectionDto {
    fn from(c: &balancing::Correction) -> Self {
        BalancingCorrectionDto {
            plane: c.plane.z,
            radius: c.plane.radius,
            mass: c.mass,
            angle: c.angle,
            mass_radius: c.mass_radius,
        }
    }
}
