//! A free body drawn as the notes draw it, from a [`Solution`]: the body
//! alone (a bar between its joints, a plate through three or more), its G,
//! every force as an arrow from its point to one scale with its name and
//! value, every couple as an arc about G with its arrowhead (counter-
//! clockwise positive), and the three sums under the title.

use super::chart::{Arrow, Axis, Chart, Fill, Line, Mark, Pen};
use super::plots::sig;
use super::solution::{FreeBody, Solution};
use crate::i18n::Msg;

/// The longest force drawn as this fraction of the body's size.
const LONGEST: f64 = 0.6;
/// Segments of a couple's arc (more than the renderer marks as samples).
const ARC: u32 = 48;

/// Body `name`'s free body at the solution's step; None for no such body.
pub fn chart(s: &Solution, name: &str) -> Option<Chart> {
    let b = s.bodies.iter().find(|b| b.body == name)?;
    let title = Msg::new("plot-free-body").arg("body", name).arg("number", b.number).arg("step", s.step).text();
    let mut c = Chart::new(title, Axis::new("x", "m"), Axis::new("y", "m"));
    c.equal = true;
    let e = &b.equations;
    c = c.subtitle(
        Msg::new("plot-free-body-sums")
            .arg("fx", sig(e.sum_fx))
            .arg("fy", sig(e.sum_fy))
            .arg("moment", sig(e.sum_moment_about_cg))
            .text(),
    );
    let size = outline(&mut c, b);
    forces(&mut c, b, size);
    couples(&mut c, b, size);
    Some(c)
}

/// The body between the points its reactions act at (G where it has one
/// or none); its size, the largest distance from G to them.
fn outline(c: &mut Chart, b: &FreeBody) -> f64 {
    let g = (b.cg[0], b.cg[1]);
    let mut points: Vec<(f64, f64)> = Vec::new();
    for f in b.forces.iter().filter(|f| f.kind == "reaction") {
        let p = (f.at[0], f.at[1]);
        if !points.iter().any(|q| (q.0 - p.0).hypot(q.1 - p.1) < 1e-9) {
            points.push(p);
        }
    }
    let size = points.iter().map(|p| (p.0 - g.0).hypot(p.1 - g.1)).fold(0.0, f64::max);
    let size = if size > 0.0 { size } else { 0.05 };
    match points.len() {
        0 | 1 => {
            let mut line = vec![g];
            line.extend(points.iter().copied());
            c.lines.push(Line { label: None, points: line, pen: Pen { color: 7, dashed: false, width: 6 } });
        }
        2 => c.lines.push(Line { label: None, points: points.clone(), pen: Pen { color: 7, dashed: false, width: 6 } }),
        _ => {
            points.sort_by(|p, q| (p.1 - g.1).atan2(p.0 - g.0).total_cmp(&(q.1 - g.1).atan2(q.0 - g.0)));
            c.fills.push(Fill { points: points.clone(), color: 7, opacity: 0.35 });
        }
    }
    c.marks.push(Mark { at: g, text: format!("G{}", b.number), dot: true });
    size
}

/// Every force from its point, to one scale; the scale in the legend.
fn forces(c: &mut Chart, b: &FreeBody, size: f64) {
    let largest = b.forces.iter().map(|f| f.fx.hypot(f.fy)).fold(0.0, f64::max);
    if largest <= 0.0 || !largest.is_finite() {
        return;
    }
    let scale = LONGEST * size / largest;
    for f in b.forces.iter().filter(|f| f.fx.hypot(f.fy) > 1e-9 * largest) {
        let color = match f.kind.as_str() {
            "reaction" => 1,
            "inertia" => 3,
            "weight" => 4,
            "driving" => 2,
            _ => 5,
        };
        c.arrows.push(Arrow {
            from: (f.at[0], f.at[1]),
            to: (f.at[0] + f.fx * scale, f.at[1] + f.fy * scale),
            color,
            label: format!("{} = {} N", f.name, sig(f.fx.hypot(f.fy))),
        });
    }
    let note = Msg::new("plot-forces-to-scale").arg("force", sig(largest)).arg("length", sig(LONGEST * size)).text();
    c.lines.push(Line { label: Some(note), points: Vec::new(), pen: Pen::solid(6) });
}

/// Every couple as three quarters of a circle about G, each a little
/// larger than the last, its arrowhead the way it turns.
fn couples(c: &mut Chart, b: &FreeBody, size: f64) {
    let drawn = b.couples.iter().filter(|m| m.moment.abs() > 0.0 && m.moment.is_finite());
    for (k, m) in drawn.enumerate() {
        let radius = size * (0.25 + 0.1 * k as f64);
        let turn = m.moment.signum();
        let arc: Vec<(f64, f64)> = (0..=ARC)
            .map(|i| {
                let a = turn * 1.5 * std::f64::consts::PI * f64::from(i) / f64::from(ARC);
                (b.cg[0] + radius * a.cos(), b.cg[1] + radius * a.sin())
            })
            .collect();
        let (end, before) = (arc[ARC as usize], arc[ARC as usize - 1]);
        c.lines.push(Line { label: None, points: arc, pen: Pen::solid(2) });
        c.arrows.push(Arrow { from: before, to: end, color: 2, label: format!("{} = {} N·m", m.name, sig(m.moment)) });
    }
}
