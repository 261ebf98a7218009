//! The `contact` joint's wire form (a higher pair: a curve of each body,
//! touching) and its conversion: the curves read in the drawing's frame,
//! where they touch found from the drawing (a 422 at the joint naming the
//! gap, or the crossing, where they do not), and a particle recognised.

use super::joints::unit;
use super::{JointDto, PointRef};
use crate::engine::curves::{Curve, Face, Spline};
use crate::engine::function::Side;
use crate::engine::model::{Contact, Joint, JointKind};
use crate::engine::touch::{NoTouch, touching};
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use crate::kinds::cams::{CamFollowerDto, CamFollowerMotion, CamFollowerType, CamProgramDto, CamSense, program};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use utoipa::ToSchema;

/// Most points of a spline curve.
pub const MAX_SPLINE_POINTS: usize = 2000;
/// The drawing must show a contact's curves within this share of the
/// mechanism's size of each other.
const TOUCH_TOLERANCE: f64 = 1e-6;

/// A curve fixed in a body, in the drawn configuration: exactly one of
/// `point`, `line`, `circle`, `polar`, `spline`, `cam`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CurveDto {
    /// A knife edge, a ring, a pin: a point (its name or [x, y]).
    #[schema(value_type = PointRef)]
    Point(PointRef),
    /// A flat face, a straight track, a slot's side.
    Line(LineDto),
    /// A roller, a disk, an eccentric cam, a rim, a circular track.
    Circle(CircleDto),
    /// A disk cam's profile r(ψ).
    Polar(PolarDto),
    /// A C² cubic spline through points.
    Spline(SplineDto),
    /// A disk cam's profile generated from its follower's program.
    Cam(CamCurveDto),
}

/// A disk cam's profile made for a translating follower from its program
/// (the fields of `POST /v1/cams` that shape it): the envelope of a flat
/// face, or the pitch curve of a roller (its `roller_radius`; a knife edge
/// has none) on an axis `offset` from the centre moved in by the roller's
/// radius; lift s(θ) at the cam's counter-clockwise turn θ from the drawing.
/// Draw the follower's face, roller or edge touching it at θ = 0.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamCurveDto {
    /// The cam's centre (its pivot).
    #[schema(value_type = PointRef)]
    pub center: PointRef,
    /// The follower's direction (from the centre towards it) as drawn, at
    /// θ = 0, [x, y]; default [1, 0].
    #[schema(min_items = 2, max_items = 2)]
    pub zero: Option<Vec<f64>>,
    #[schema(value_type = crate::kinds::cams::CamFollowerDto)]
    pub follower: CamFollowerDto,
    #[schema(value_type = crate::kinds::cams::CamProgramDto)]
    pub program: CamProgramDto,
    /// m.
    #[schema(value_type = Quantity)]
    pub base_radius: Quantity,
    /// Default ccw (the only sense a cam curve is made for).
    pub direction: Option<CamSense>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct LineDto {
    #[schema(value_type = PointRef)]
    pub through: PointRef,
    /// Its direction as drawn, [x, y] (any length but 0).
    #[schema(min_items = 2, max_items = 2)]
    pub direction: Vec<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CircleDto {
    #[schema(value_type = PointRef)]
    pub center: PointRef,
    /// m (> 0).
    #[schema(value_type = Quantity)]
    pub radius: Quantity,
    /// The other curve touches it from within (a track, a ring's inside); default false.
    pub inside: Option<bool>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct PolarDto {
    #[schema(value_type = PointRef)]
    pub center: PointRef,
    /// r(ψ) > 0 (m), a Function of `psi` (rad, counter-clockwise from `zero`).
    #[schema(value_type = FunctionDto)]
    pub radius: FunctionDto,
    /// The body-fixed direction ψ = 0 as drawn, [x, y]; default [1, 0].
    #[schema(min_items = 2, max_items = 2)]
    pub zero: Option<Vec<f64>>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct SplineDto {
    /// At least 4 points [x, y] (m), as drawn, in order.
    #[schema(value_type = Vec<super::Coords>, min_items = 4, max_items = 2000)]
    pub points: Vec<[f64; 2]>,
    /// Periodic through the last point back to the first; default false.
    pub closed: Option<bool>,
}

/// Reads a point of the drawing (a name or coordinates) at a pointer.
pub type PointReader<'a> = dyn Fn(&mut Errors, &PointRef, &str) -> Option<[f64; 2]> + 'a;

/// The contact joint `j` at pointer `at`: its kind and where its curves
/// touch (the joint's point), in a mechanism of size `size` (m).
pub fn contact(
    e: &mut Errors,
    j: &JointDto,
    hint: Option<[f64; 2]>,
    point: &PointReader,
    size: f64,
    at: &str,
) -> Option<(JointKind, [f64; 2])> {
    let Some(list) = j.curves.as_deref() else { return e.refuse(at, Msg::new("contact-needs-curves")) };
    if list.len() != 2 {
        return e.refuse(&format!("{at}/curves"), Msg::new("contact-two-curves"));
    }
    let read: Vec<Option<Curve>> =
        list.iter().enumerate().map(|(k, c)| curve(e, c, point, &format!("{at}/curves/{k}"))).collect();
    let [Some(a), Some(b)] = <[Option<Curve>; 2]>::try_from(read).ok()? else { return None };
    let curves = [a, b];
    let tolerance = TOUCH_TOLERANCE * size;
    // A circle inside another of its own radius touches it all round: it cannot roll or slide.
    if let [Curve::Circle { radius: r, inside: i, .. }, Curve::Circle { radius: q, inside: k, .. }] = &curves
        && i != k
        && (r - q).abs() <= tolerance
    {
        return e.refuse(&format!("{at}/curves"), Msg::new("contact-circle-fills").fig("radius", *r));
    }
    match touching(&curves, tolerance, hint) {
        Ok(p) => {
            let rolling = j.rolling.unwrap_or(false);
            if rolling && list.iter().any(|c| matches!(c, CurveDto::Point(_))) {
                return e.refuse(&format!("{at}/rolling"), Msg::new("contact-point-rolling"));
            }
            Some((JointKind::Contact(Box::new(Contact::new(curves, rolling, p))), p))
        }
        Err(NoTouch::Gap { gap, point }) => {
            // A coordinate that is rounding off zero (1e-18 where the figure is 0.1 m) is 0.
            let [x, y] = point.map(|v| if v.abs() < 1e-12 * size { 0.0 } else { v });
            let msg = Msg::new("contact-gap").fig("gap", gap).fig("x", x).fig("y", y).fig("tolerance", tolerance);
            e.refuse(&format!("{at}/curves"), msg)
        }
        Err(NoTouch::Cross { point, angle }) => {
            let msg = Msg::new("contact-cross")
                .written("x", format!("{:.6}", point[0]))
                .written("y", format!("{:.6}", point[1]))
                .written("angle", format!("{:.3}", angle.to_degrees()));
            e.refuse(&format!("{at}/curves"), msg)
        }
        Err(NoTouch::Lines) => e.refuse(&format!("{at}/curves"), Msg::new("contact-lines")),
    }
}

/// One curve, at pointer `at`.
fn curve(e: &mut Errors, c: &CurveDto, point: &PointReader, at: &str) -> Option<Curve> {
    match c {
        CurveDto::Point(p) => point(e, p, &format!("{at}/point")).map(Curve::Point),
        CurveDto::Line(l) => {
            let at = format!("{at}/line");
            let through = point(e, &l.through, &format!("{at}/through"));
            let direction = unit(e, &l.direction, &format!("{at}/direction"));
            Some(Curve::Line { at: through?, direction: direction? })
        }
        CurveDto::Circle(c) => {
            let at = format!("{at}/circle");
            let centre = point(e, &c.center, &format!("{at}/center"));
            let radius = e.positive(&c.radius, Dim::LENGTH, &format!("{at}/radius"));
            Some(Curve::Circle { centre: centre?, radius: radius?, inside: c.inside.unwrap_or(false) })
        }
        CurveDto::Polar(p) => polar(e, p, point, &format!("{at}/polar")),
        CurveDto::Cam(c) => cam(e, c, point, &format!("{at}/cam")),
        CurveDto::Spline(s) => {
            let at = format!("{at}/spline");
            if !(4..=MAX_SPLINE_POINTS).contains(&s.points.len()) {
                let msg = Msg::new("contact-spline-points").arg("max", MAX_SPLINE_POINTS);
                return e.refuse(&format!("{at}/points"), msg);
            }
            if let Some(k) = s.points.iter().position(|p| !p.iter().all(|v| v.is_finite())) {
                return e.refuse(&format!("{at}/points/{k}"), Msg::new("mechanism-coordinates"));
            }
            if let Some((k, other)) = repeated(&s.points, s.closed.unwrap_or(false)) {
                return e.refuse(&format!("{at}/points/{k}"), Msg::new("contact-spline-repeated").arg("other", other));
            }
            match Spline::new(s.points.clone(), s.closed.unwrap_or(false)) {
                Some(spline) => Some(Curve::Spline(spline)),
                None => e.refuse(&format!("{at}/points"), Msg::new("contact-no-spline")),
            }
        }
    }
}

/// A point of a spline that repeats the one before it (a closed spline's
/// first, the last): (its index, the other's), within 1e-9 of the
/// points' extent — a spline through a point twice draws a loop nobody drew.
fn repeated(points: &[[f64; 2]], closed: bool) -> Option<(usize, usize)> {
    let extent = points.iter().flat_map(|p| p.iter()).fold(0.0f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let same = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) <= 1e-9 * extent;
    let n = points.len();
    let pairs = (1..n).map(|k| (k, k - 1)).chain(closed.then_some((n - 1, 0)));
    pairs.into_iter().find(|&(k, j)| same(points[k], points[j]))
}

/// A polar curve: r(ψ) read as a Function of `psi` over a turn, positive
/// at every degree (sampled).
fn polar(e: &mut Errors, p: &PolarDto, point: &PointReader, at: &str) -> Option<Curve> {
    let centre = point(e, &p.center, &format!("{at}/center"));
    let zero = match p.zero.as_deref() {
        None => Some([1.0, 0.0]),
        Some(z) => unit(e, z, &format!("{at}/zero")),
    };
    let rho = e.function_of(&p.radius, Dim::LENGTH, TAU, &format!("{at}/radius"), &["psi"]);
    let (centre, zero, rho) = (centre?, zero?, rho?);
    e.differentiable(&rho, 3, &format!("{at}/radius"))?;
    if let Some(bad) = (0..360)
        .map(|k| f64::from(k).to_radians())
        .find(|&psi| !matches!(rho.eval(psi, Side::Right).partial_cmp(&0.0), Some(std::cmp::Ordering::Greater)))
    {
        let msg = Msg::new("contact-polar-positive")
            .num("angle", bad.to_degrees().round())
            .num("value", rho.eval(bad, Side::Right));
        return e.refuse(&format!("{at}/radius"), msg);
    }
    Some(Curve::polar(centre, zero[1].atan2(zero[0]), rho))
}

/// A cam curve for a translating follower, from a program of segments, counter-clockwise.
fn cam(e: &mut Errors, c: &CamCurveDto, point: &PointReader, at: &str) -> Option<Curve> {
    let centre = point(e, &c.center, &format!("{at}/center"));
    let zero = match c.zero.as_deref() {
        None => Some([1.0, 0.0]),
        Some(z) => unit(e, z, &format!("{at}/zero")),
    };
    let face = face(e, &c.follower, &format!("{at}/follower"));
    if c.direction == Some(CamSense::Cw) {
        e.say(&format!("{at}/direction"), Msg::new("contact-cam-ccw"));
    }
    let base = e.positive(&c.base_radius, Dim::LENGTH, &format!("{at}/base_radius"));
    let program = match &c.program {
        CamProgramDto::Segments(list) => program(e, list, &format!("{at}/program"), Dim::LENGTH).map(|(p, _)| p),
        CamProgramDto::Lift(_) => e.refuse(&format!("{at}/program"), Msg::new("contact-cam-segments")),
    };
    let (centre, zero, base, program, face) = (centre?, zero?, base?, program?, face?);
    if let Face::Roller { radius, offset } = face
        && offset.abs() >= base + radius
    {
        return e.refuse(&format!("{at}/follower/offset"), Msg::new("contact-cam-offset"));
    }
    Some(Curve::Cam { centre, zero: zero[1].atan2(zero[0]), base, face, program: Box::new(program) })
}

/// The translating follower a cam curve is made for: a flat face, a roller
/// (its radius) or a knife edge, on an axis offset from the centre.
fn face(e: &mut Errors, f: &CamFollowerDto, at: &str) -> Option<Face> {
    if f.motion == Some(CamFollowerMotion::Oscillating) {
        return e.refuse(&format!("{at}/motion"), Msg::new("contact-cam-oscillating"));
    }
    let offset = f.offset.as_ref().map_or(Some(0.0), |q| e.quantity(q, Dim::LENGTH, &format!("{at}/offset")));
    let radius = match (f.kind, &f.roller_radius) {
        (CamFollowerType::Roller, Some(r)) => e.positive(r, Dim::LENGTH, &format!("{at}/roller_radius")),
        (CamFollowerType::Roller, None) => e.refuse(at, Msg::new("cam-roller-radius")),
        (_, Some(_)) => e.refuse(&format!("{at}/roller_radius"), Msg::new("cam-roller-only")),
        (_, None) => Some(0.0),
    };
    match f.kind {
        CamFollowerType::Flat => offset.map(|_| Face::Flat),
        _ => Some(Face::Roller { radius: radius?, offset: offset? }),
    }
}

/// Marks as particles the bodies that have no inertia and whose only joint
/// is a contact where their curve is a point (a ring threaded on a rim):
/// nothing determines their rotation.
pub fn mark_particles(joints: &mut [Joint], inertia: impl Fn(usize) -> f64) {
    for k in 0..joints.len() {
        let JointKind::Contact(c) = &joints[k].kind else { continue };
        let Some(side) = (0..2).find(|&s| matches!(c.curves[s], Curve::Point(_))) else { continue };
        let body = joints[k].bodies[side];
        let alone = joints.iter().filter(|j| j.bodies.contains(&body)).count() == 1;
        if body != 0
            && alone
            && inertia(body) == 0.0
            && let JointKind::Contact(c) = &mut joints[k].kind
        {
            c.particle = true;
        }
    }
}
