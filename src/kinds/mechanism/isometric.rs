//! A spatial mechanism drawn at one instant in isometric projection: the
//! axis against gravity (y without gravity) upright, the other two 30°
//! below the horizontal to either side, as a draughtsman's isometric view
//! has them. Each body is drawn as lines between its joints (to its centre
//! of mass where it has one joint), each joint's axis as a dashed line
//! through it (a universal joint's two), the joints named, the ground's
//! axes as a triad in the lower left and the reactions as arrows to one
//! scale. The geometry comes from the stored request (the drawing) and
//! the stored motion of each body (`position`, `rotation`): a point P of
//! body b is at r_b + R_b·(P − G_b), as drawn.

use super::MechanismDto;
use crate::engine::spatial::{JointKind, Mechanism, Pose};
use crate::i18n::Msg;
use crate::kind::chart::{Arrow, Axis, Chart, Line, Mark, Pen};
use crate::kind::isometric_view::View;
use crate::kind::limits::Limits;
use crate::kind::quantity::Errors;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use serde_json::Value;

/// The spatial model of the stored request's mechanism at `pointer`.
pub fn model(request: &Value, pointer: &str) -> Option<Mechanism> {
    let dto: MechanismDto = serde_json::from_value(request.pointer(pointer)?.clone()).ok()?;
    let mut e = Errors::new(&Limits::default());
    dto.is_spatial().then(|| dto.spatial(&mut e, pointer))?.map(|c| c.mechanism)
}

/// The pose stored as each body's `position` and `rotation` (in body order,
/// one entry a moving body); None where one is missing.
pub fn pose(m: &Mechanism, bodies: &[Value]) -> Option<Pose> {
    let vector = |v: &Value| Some(Vector3::new(v[0].as_f64()?, v[1].as_f64()?, v[2].as_f64()?));
    let mut pose = Pose { r: Vec::new(), p: Vec::new() };
    for k in 0..m.n() {
        let b = bodies.get(k)?;
        let rows = [0, 1, 2].map(|i| vector(&b["rotation"][i]));
        let [r0, r1, r2] = rows;
        let rot = Matrix3::from_rows(&[r0?.transpose(), r1?.transpose(), r2?.transpose()]);
        pose.r.push(vector(&b["position"])?);
        pose.p.push(UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix(&rot)));
    }
    Some(pose)
}

/// The spatial mechanism of the stored request at `pointer` drawn at a
/// stored step or sample: its bodies' motion and its joints' reactions.
pub fn drawn(
    request: &Value,
    pointer: &str,
    (bodies, reactions): (&[Value], &[Value]),
    title: String,
) -> Option<Chart> {
    let m = model(request, pointer)?;
    Some(draw(&m, &pose(&m, bodies)?, reactions, title))
}

/// A note, then what the isometric drawing `c` says of its view.
pub fn noted(mut c: Chart, note: String) -> Chart {
    c.subtitle = Some(c.subtitle.map_or_else(|| note.clone(), |view| format!("{note}; {view}")));
    c
}

/// The mechanism at `pose`, with each joint's reaction (`force`, on the
/// joint's second body) as an arrow.
pub fn draw(m: &Mechanism, pose: &Pose, reactions: &[Value], title: String) -> Chart {
    let view = View::against(&m.gravity);
    let mut c = Chart::new(title, Axis::new("u", "m"), Axis::new("v", "m"));
    c.equal = true;
    let up = view.up_name();
    c.subtitle = Some(Msg::new("plot-isometric").arg("up", up).text());
    let at: Vec<Vector3<f64>> = m
        .joints
        .iter()
        .map(|j| pose.point(m, if j.bodies[1] != 0 { j.bodies[1] } else { j.bodies[0] }, &j.at).0)
        .collect();
    let span = extent(&at.iter().map(|p| view.project(p)).collect::<Vec<_>>()).max(m.size() * 0.1);
    for b in 1..=m.n() {
        let mut points: Vec<(f64, f64)> =
            (m.joints.iter().zip(&at)).filter(|(j, _)| j.bodies.contains(&b)).map(|(_, p)| view.project(p)).collect();
        points.dedup_by(|p, q| (p.0 - q.0).hypot(p.1 - q.1) < 1e-12);
        if points.len() < 2 {
            points.push(view.project(&pose.origin(b)));
            points.dedup_by(|p, q| (p.0 - q.0).hypot(p.1 - q.1) < 1e-12);
        }
        if let (1, Some(shaft)) = (points.len(), shaft(m, pose, b)) {
            // A body drawn at one point (a shaft in a Hooke's joint): along its own axis.
            let from = pose.origin(b);
            points = vec![view.project(&(from - shaft * 0.3 * span)), view.project(&(from + shaft * 0.3 * span))];
        }
        if points.len() >= 3 {
            points.push(points[0]);
        }
        let label = Some(m.bodies[b - 1].name.clone());
        c.lines.push(Line { label, points, pen: Pen { color: b, dashed: false, width: 4 } });
    }
    for (j, p) in m.joints.iter().zip(&at) {
        let axes = match j.kind {
            JointKind::Universal { axes } => vec![(j.bodies[0], axes[0]), (j.bodies[1], axes[1])],
            _ => j.kind.axis().map(|a| (j.bodies[0], a)).into_iter().collect(),
        };
        for (b, axis) in axes {
            let u = pose.rotation(b) * axis * (0.12 * span);
            c.lines.push(Line {
                label: None,
                points: vec![view.project(&(p - u)), view.project(&(p + u))],
                pen: Pen::dashed(7),
            });
        }
        c.marks.push(Mark { at: view.project(p), text: j.name.clone(), dot: true });
    }
    arrows(&mut c, m, view, (&at, reactions), span);
    triad(&mut c, view, span);
    c
}

/// The axis of the first joint that turns or slides body b, now.
fn shaft(m: &Mechanism, pose: &Pose, b: usize) -> Option<Vector3<f64>> {
    let j = m.joints.iter().find(|j| j.bodies.contains(&b) && j.kind.axis().is_some())?;
    Some(pose.rotation(j.bodies[0]) * j.kind.axis()?)
}

/// Each reaction's force as an arrow from its joint, the largest a quarter
/// of the span long.
fn arrows(c: &mut Chart, m: &Mechanism, view: View, (at, reactions): (&[Vector3<f64>], &[Value]), span: f64) {
    let force =
        |r: &Value| Some(Vector3::new(r["force"][0].as_f64()?, r["force"][1].as_f64()?, r["force"][2].as_f64()?));
    let largest = reactions.iter().filter_map(force).map(|f| f.norm()).fold(0.0, f64::max);
    if largest <= 0.0 {
        return;
    }
    for r in reactions {
        let joint = m.joints.iter().position(|j| Some(j.name.as_str()) == r["joint"].as_str());
        let (Some(k), Some(f)) = (joint, force(r)) else { continue };
        let to = at[k] + f * (0.25 * span / largest);
        c.arrows.push(Arrow { from: view.project(&at[k]), to: view.project(&to), color: 3, label: String::new() });
    }
}

/// The ground's x, y and z in the lower left of the drawing.
fn triad(c: &mut Chart, view: View, span: f64) {
    let Some([x0, _, y0, _]) = c.bounds() else { return };
    let origin = (x0 - 0.05 * span, y0 - 0.05 * span);
    let o = view.project(&Vector3::zeros());
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let tip = view.project(&(Vector3::ith(k, 0.12 * span)));
        let end = (origin.0 + tip.0 - o.0, origin.1 + tip.1 - o.1);
        c.lines.push(Line { label: None, points: vec![origin, end], pen: Pen { color: 7, dashed: false, width: 1 } });
        c.marks.push(Mark { at: end, text: name.to_string(), dot: false });
    }
}

/// The larger of the points' u and v ranges.
fn extent(points: &[(f64, f64)]) -> f64 {
    let range = |f: fn(&(f64, f64)) -> f64| {
        let (lo, hi) = points.iter().map(f).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
        if hi >= lo { hi - lo } else { 0.0 }
    };
    range(|p| p.0).max(range(|p| p.1))
}
