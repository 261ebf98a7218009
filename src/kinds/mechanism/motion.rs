//! A mechanism in motion: its drawing ([`super::drawing`]) at each of the
//! result's steps as the frames of one animated chart, every frame to the
//! same sizes (the largest span of the joints over the motion, the largest
//! reaction drawn a quarter of it long) over what the frames share: the
//! paths of the moving joints and of the points followed.

use super::drawing::{self, Fixed, Pose, point_of};
use crate::engine::model::{JointKind, Mechanism};
use crate::kind::chart::{Animation, Axis, Chart, Frame, Line, Pen};
use crate::kind::plots::num;
use crate::kinds::mechanism::Name;
use serde::{Deserialize, Serialize};
use serde_json::Value;
use utoipa::ToSchema;

/// Where a body is: its centre of mass and its rotation from the drawn configuration.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BodyPosition {
    #[schema(value_type = String)]
    pub body: Name,
    /// m
    pub x: f64,
    /// m
    pub y: f64,
    /// rad
    pub theta: f64,
}

impl BodyPosition {
    /// The moving bodies' positions at `q` (body coordinates, three per
    /// moving body), named by `names` (the ground first).
    pub fn all(q: &[f64], names: &[Name]) -> Vec<Self> {
        (q.chunks_exact(3).zip(names.iter().skip(1)))
            .map(|(p, body)| Self { body: body.clone(), x: p[0], y: p[1], theta: p[2] })
            .collect()
    }
}

/// At most this many frames: a longer result is shown at evenly spaced
/// steps (every frame is a drawing of the whole mechanism).
pub const FRAMES: usize = 120;

/// One step of the result as a frame shows it.
pub struct Still<'a> {
    pub step: usize,
    /// When it is shown, a fraction of the loop.
    pub at: f64,
    pub caption: String,
    pub poses: Vec<Option<Pose>>,
    pub reactions: &'a [Value],
    pub contacts: &'a [Value],
}

/// The steps a motion of `count` steps shows: all, or [`FRAMES`] evenly spaced.
pub fn shown(count: usize) -> impl Iterator<Item = usize> {
    let every = count.div_ceil(FRAMES).max(1);
    (0..count).step_by(every)
}

/// The chart of the mechanism `m` moving through `stills` in `seconds`, over `paths`.
pub fn motion(m: &Mechanism, stills: &[Still], paths: Vec<Line>, seconds: f64, title: String) -> Chart {
    let span = stills.iter().map(|s| drawing::span(m, &s.poses)).fold(0.0, f64::max);
    let force = |r: &Value| Some(num(r, "fx")?.hypot(num(r, "fy")?));
    let largest = stills.iter().flat_map(|s| s.reactions.iter().filter_map(force)).fold(0.0, f64::max);
    let fixed = Fixed { span, force: largest };
    let mut chart = Chart::new(title, Axis::new("x", "m"), Axis::new("y", "m"));
    chart.equal = true;
    chart.lines = paths;
    let mut frames = Vec::with_capacity(stills.len());
    for s in stills {
        let mut c = drawing::draw_to(m, &s.poses, (s.reactions, s.contacts), String::new(), Some(fixed));
        if frames.is_empty() {
            let legend = c.lines.iter().filter(|l| l.label.is_some());
            chart.lines.extend(legend.map(|l| Line { label: l.label.clone(), points: Vec::new(), pen: l.pen }));
        }
        c.lines.iter_mut().for_each(|l| l.label = None);
        c.marks.iter_mut().for_each(|k| k.text.clear());
        let (fills, lines, arrows, marks) = (c.fills, c.lines, c.arrows, c.marks);
        frames.push(Frame { at: s.at, caption: s.caption.clone(), step: s.step, fills, lines, arrows, marks });
    }
    chart.animation = Some(Animation { seconds, frames });
    chart
}

/// The paths of the joints that move, over every pose in `poses`: thin grey
/// dashes under the frames.
pub fn joint_paths(m: &Mechanism, poses: &[Vec<Option<Pose>>]) -> Vec<Line> {
    let moves = |j: &&crate::engine::model::Joint| j.bodies[0] != 0 || !matches!(j.kind, JointKind::Revolute);
    m.joints
        .iter()
        .filter(moves)
        .map(|j| Line {
            label: None,
            points: poses.iter().filter_map(|p| point_of(m, p, j)).collect(),
            pen: Pen { color: 7, dashed: true, width: 1 },
        })
        .filter(|l| l.points.len() > 1)
        .collect()
}

/// The paths of the points followed (`points` of each step: `name`, `x`,
/// `y`), each named in the legend.
pub fn tracked_paths(steps: &[Value]) -> Vec<Line> {
    let first = steps.iter().find_map(|s| s.get("points")?.as_array()).map_or(&[][..], Vec::as_slice);
    first
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let name = p.get("name").and_then(Value::as_str).unwrap_or_default().to_string();
            let at = |s: &Value| {
                let q = s.get("points")?.get(k)?;
                Some((num(q, "x")?, num(q, "y")?))
            };
            Line { label: Some(name), points: steps.iter().filter_map(at).collect(), pen: Pen::dashed(k + 4) }
        })
        .collect()
}
