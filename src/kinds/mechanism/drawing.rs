//! A planar mechanism drawn at one instant, to scale: each body as lines
//! between its joints (a polygon for a body of three or more), sliders as
//! boxes on their guides, the ground's pivots as dots, and the joints'
//! reactions as arrows to one scale (a contact's at its contact point);
//! a contact's curves (cams, disks, tracks, faces) as drawn on their
//! bodies. The geometry comes from the stored
//! request (the drawn configuration) and the stored poses (x_G, y_G, θ) of
//! the bodies; a point P of body b is at r_b + A(θ_b)(P_ref − G_ref).

use super::MechanismDto;
use crate::engine::curves::{Curve, Domain};
use crate::engine::model::{JointKind, Mechanism};
use crate::i18n::Msg;
use crate::kind::chart::{Arrow, Axis, Chart, Fill, Line, Pen};
use crate::kind::limits::Limits;
use crate::kind::plots::{num, sig};
use crate::kind::quantity::Errors;
use serde_json::Value;

/// The model of the stored request's mechanism (at `pointer`), without drivers.
pub fn model(request: &Value, pointer: &str) -> Option<Mechanism> {
    let dto: MechanismDto = serde_json::from_value(request.pointer(pointer)?.clone()).ok()?;
    let mut e = Errors::new(&Limits::default());
    let (dto, _) = dto.assembled(&mut e, pointer)?;
    dto.convert(&mut e, pointer).map(|c| c.mechanism)
}

/// A body's pose: centre of mass and rotation from the drawn configuration.
pub type Pose = (f64, f64, f64);

/// The poses of the bodies (index: the body's; the ground has none) from
/// a stored list of (`body`, `x`, `y`, `theta`), stored in body order.
pub fn poses(m: &Mechanism, list: &[Value]) -> Vec<Option<Pose>> {
    let pose = |b: &Value| Some((num(b, "x")?, num(b, "y")?, num(b, "theta")?));
    let named = |b: &Value, name: &str| b.get("body").and_then(Value::as_str) == Some(name);
    let mut out = vec![None; m.bodies.len()];
    for (k, body) in m.bodies.iter().enumerate().skip(1) {
        let stored =
            list.get(k - 1).filter(|b| named(b, &body.name)).or_else(|| list.iter().find(|b| named(b, &body.name)));
        out[k] = stored.and_then(pose);
    }
    out
}

/// Where the reference point `p` of body `b` is at the poses.
fn place(m: &Mechanism, poses: &[Option<Pose>], b: usize, p: [f64; 2]) -> Option<(f64, f64)> {
    if b == 0 {
        return Some((p[0], p[1]));
    }
    let body = &m.bodies[b];
    let (x, y, th) = (*poses.get(b)?)?;
    let (s, c) = th.sin_cos();
    let (dx, dy) = (p[0] - body.cg[0], p[1] - body.cg[1]);
    Some((x + c * dx - s * dy, y + s * dx + c * dy))
}

/// Where joint `j` is at the poses (its point on its moving body).
pub fn point_of(m: &Mechanism, poses: &[Option<Pose>], j: &crate::engine::model::Joint) -> Option<(f64, f64)> {
    if matches!(j.kind, JointKind::Gear { .. }) {
        return None;
    }
    place(m, poses, if j.bodies[1] != 0 { j.bodies[1] } else { j.bodies[0] }, j.at)
}

/// The mechanism at the poses, with the reactions (`joint`, `fx`, `fy`) as
/// arrows, a contact's from its `point` in `contacts`.
pub fn draw(m: &Mechanism, poses: &[Option<Pose>], reactions: &[Value], contacts: &[Value], title: String) -> Chart {
    draw_to(m, poses, (reactions, contacts), title, None)
}

/// The sizes a drawing is made to: the mechanism's span (what sliders and
/// lines are drawn in proportion to) and the force drawn a quarter of it long.
#[derive(Clone, Copy, Debug)]
pub struct Fixed {
    pub span: f64,
    pub force: f64,
}

/// The span of the joints at the poses (the largest of their x and y ranges).
pub fn span(m: &Mechanism, poses: &[Option<Pose>]) -> f64 {
    extent(&m.joints.iter().map(|j| point_of(m, poses, j)).collect::<Vec<_>>())
}

/// [`draw`] to the sizes `fixed` (every frame of a motion alike), or to its own.
pub fn draw_to(
    m: &Mechanism,
    poses: &[Option<Pose>],
    (reactions, contacts): (&[Value], &[Value]),
    title: String,
    fixed: Option<Fixed>,
) -> Chart {
    let mut c = Chart::new(title, Axis::new("x", "m"), Axis::new("y", "m"));
    c.equal = true;
    let mut joints: Vec<Option<(f64, f64)>> = m.joints.iter().map(|j| point_of(m, poses, j)).collect();
    let span = fixed.map_or_else(|| extent(&joints), |f| f.span);
    for b in 1..m.bodies.len() {
        body(&mut c, m, poses, &joints, b);
    }
    for (k, j) in m.joints.iter().enumerate() {
        if let JointKind::Contact(contact) = &j.kind {
            for (side, curve) in contact.curves.iter().enumerate() {
                draw_curve(&mut c, m, poses, (j.bodies[side], curve), j.at, span);
            }
            let named = |v: &&Value| v.get("joint").and_then(Value::as_str) == Some(j.name.as_str());
            let stored = contacts.iter().find(named).and_then(|v| v.get("point")?.as_array().cloned());
            joints[k] = stored.and_then(|p| Some((p.first()?.as_f64()?, p.get(1)?.as_f64()?))).or(joints[k]);
        }
    }
    for (k, j) in m.joints.iter().enumerate() {
        let Some(at) = joints[k] else { continue };
        if let JointKind::Prismatic { axis } | JointKind::PinSlot { axis } = j.kind {
            let turned = place(m, poses, j.bodies[0], [j.at[0] + axis[0], j.at[1] + axis[1]])
                .zip(place(m, poses, j.bodies[0], j.at))
                .map(|(a, b)| (a.0 - b.0, a.1 - b.1));
            if let Some(u) = turned {
                slider(&mut c, at, u, span, matches!(j.kind, JointKind::Prismatic { .. }).then_some(j.bodies[1]));
            }
        }
        c = c.mark(at, j.name.clone());
    }
    arrows(&mut c, m, &joints, reactions, (span, fixed.map(|f| f.force)));
    c
}

/// Curve `curve` of body `b` at the poses: a closed curve whole, an open
/// one over its length, a line as long as the mechanism about `at`.
fn draw_curve(
    c: &mut Chart,
    m: &Mechanism,
    poses: &[Option<Pose>],
    (b, curve): (usize, &Curve),
    at: [f64; 2],
    span: f64,
) {
    let (from, to) = match (curve.domain(), curve) {
        (Domain::None, _) => return,
        (Domain::Unbounded, Curve::Line { at: p, direction: d }) => {
            let u = (at[0] - p[0]) * d[0] + (at[1] - p[1]) * d[1];
            (u - 0.6 * span, u + 0.6 * span)
        }
        (Domain::Unbounded, _) => return,
        (Domain::Periodic(p), _) => (0.0, p),
        (Domain::Interval(a, z), _) => (a, z),
    };
    let n = 180;
    let points =
        (0..=n).filter_map(|k| place(m, poses, b, curve.at(from + (to - from) * f64::from(k) / f64::from(n)).r));
    c.lines.push(Line { label: None, points: points.collect(), pen: Pen { color: b, dashed: false, width: 2 } });
}

fn extent(points: &[Option<(f64, f64)>]) -> f64 {
    let pts: Vec<(f64, f64)> = points.iter().flatten().copied().collect();
    let span = |f: fn(&(f64, f64)) -> f64| {
        let v = pts.iter().map(f);
        v.clone().fold(f64::NEG_INFINITY, f64::max) - v.fold(f64::INFINITY, f64::min)
    };
    let s = span(|p| p.0).max(span(|p| p.1));
    if s.is_finite() && s > 0.0 { s } else { 1.0 }
}

/// Body `b` as lines between its joints (to its centre of mass when it has one joint).
fn body(c: &mut Chart, m: &Mechanism, poses: &[Option<Pose>], joints: &[Option<(f64, f64)>], b: usize) {
    let mut pts: Vec<(f64, f64)> =
        m.joints.iter().zip(joints).filter(|(j, _)| j.bodies.contains(&b)).filter_map(|(_, p)| *p).collect();
    pts.dedup_by(|p, q| (p.0 - q.0).hypot(p.1 - q.1) < 1e-12);
    let g = place(m, poses, b, m.bodies[b].cg);
    if pts.len() == 1 {
        pts.extend(g);
    }
    if pts.len() >= 3 {
        let (cx, cy) = (pts.iter().map(|p| p.0).sum::<f64>(), pts.iter().map(|p| p.1).sum::<f64>());
        let n = pts.len() as f64;
        pts.sort_by(|p, q| (p.1 - cy / n).atan2(p.0 - cx / n).total_cmp(&(q.1 - cy / n).atan2(q.0 - cx / n)));
        c.fills.push(Fill { points: pts.clone(), color: b, opacity: 0.15 });
        pts.push(pts[0]);
    }
    let label = Some(m.bodies[b].name.clone());
    c.lines.push(Line { label, points: pts, pen: Pen { color: b, dashed: false, width: 4 } });
}

/// A slider: a box (in the colour of body `boxed`) along the axis `u` at
/// `at`, on a dashed guide; a pin in a slot has the guide alone.
fn slider(c: &mut Chart, at: (f64, f64), u: (f64, f64), span: f64, boxed: Option<usize>) {
    let n = u.0.hypot(u.1).max(1e-300);
    let (ux, uy) = (u.0 / n, u.1 / n);
    let (a, h) = (0.08 * span, 0.045 * span);
    let guide = vec![(at.0 - 1.5 * a * ux, at.1 - 1.5 * a * uy), (at.0 + 1.5 * a * ux, at.1 + 1.5 * a * uy)];
    c.lines.push(Line { label: None, points: guide, pen: Pen::dashed(7) });
    if let Some(b) = boxed {
        let corner =
            |s: f64, t: f64| (at.0 + s * a / 2.0 * ux - t * h / 2.0 * uy, at.1 + s * a / 2.0 * uy + t * h / 2.0 * ux);
        let pts = vec![corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0), corner(-1.0, -1.0)];
        c.fills.push(Fill { points: pts.clone(), color: b, opacity: 0.35 });
        c.lines.push(Line { label: None, points: pts, pen: Pen { color: b, dashed: false, width: 1 } });
    }
}

/// The reactions at the joints: the force on the second body of each (as
/// stored: `on` by `by`), the largest (or `largest`) drawn as long as a
/// quarter of the mechanism; the scale in the legend.
fn arrows(
    c: &mut Chart,
    m: &Mechanism,
    joints: &[Option<(f64, f64)>],
    reactions: &[Value],
    (span, largest): (f64, Option<f64>),
) {
    let forces: Vec<((f64, f64), (f64, f64))> = reactions
        .iter()
        .filter_map(|r| {
            let k = m.joints.iter().position(|j| Some(j.name.as_str()) == r.get("joint").and_then(Value::as_str))?;
            Some((joints[k]?, (num(r, "fx")?, num(r, "fy")?)))
        })
        .collect();
    let largest = largest.unwrap_or_else(|| forces.iter().map(|(_, f)| f.0.hypot(f.1)).fold(0.0, f64::max));
    if largest <= 0.0 || !largest.is_finite() {
        return;
    }
    let scale = 0.25 * span / largest;
    for (at, f) in &forces {
        c.arrows.push(Arrow {
            from: *at,
            to: (at.0 + f.0 * scale, at.1 + f.1 * scale),
            color: 1,
            label: String::new(),
        });
    }
    let note = Msg::new("plot-reactions-to-scale").arg("force", sig(largest)).arg("length", sig(0.25 * span)).text();
    c.lines.push(Line { label: Some(note), points: Vec::new(), pen: Pen::solid(6) });
}
