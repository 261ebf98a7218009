//! A free body drawn as the notes draw it, from a [`Solution`]: the body
//! alone (a bar between its joints, a plate through three or more), its G,
//! every force as an arrow from its point to one scale with its name and
//! value, every couple as an arc about G with its arrowhead (counter-
//! clockwise positive), and the three sums under the title. A body in
//! space is drawn in the isometric view (up against its weight), each
//! couple as its moment vector with a double head, and its six sums.

use super::chart::{Arrow, Axis, Chart, Fill, Line, Mark, Pen};
use super::isometric_view::View;
use super::plots::sig;
use super::solution::{Force, FreeBody, Solution};
use crate::i18n::Msg;

/// The longest force drawn as this fraction of the body's size.
const LONGEST: f64 = 0.6;
/// Segments of a couple's arc (more than the renderer marks as samples).
const ARC: u32 = 48;

/// Body `name`'s free body at the solution's step; None for no such body.
pub fn chart(s: &Solution, name: &str) -> Option<Chart> {
    let b = s.bodies.iter().find(|b| b.body == name)?;
    let title = Msg::new("plot-free-body").arg("body", name).arg("number", b.number).arg("step", s.step).text();
    let page = Page::of(b);
    let (u, v) = if matches!(page, Page::Plane) { ("x", "y") } else { ("u", "v") };
    let mut c = Chart::new(title, Axis::new(u, "m"), Axis::new(v, "m"));
    c.equal = true;
    let e = &b.equations;
    let sums = match (page, e.sum_fz, e.sum_mx_about_cg, e.sum_my_about_cg) {
        (Page::Space(view), Some(fz), Some(mx), Some(my)) => Msg::new("plot-free-body-sums-spatial")
            .arg("forces", [e.sum_fx, e.sum_fy, fz].map(sig).join(", "))
            .arg("moments", [mx, my, e.sum_moment_about_cg].map(sig).join(", "))
            .arg("up", view.up_name()),
        _ => Msg::new("plot-free-body-sums")
            .arg("fx", sig(e.sum_fx))
            .arg("fy", sig(e.sum_fy))
            .arg("moment", sig(e.sum_moment_about_cg)),
    };
    c = c.subtitle(sums.text());
    let size = outline(&mut c, b, page);
    forces(&mut c, b, size, page);
    match page {
        Page::Plane => couples(&mut c, b, size),
        Page::Space(_) => moment_vectors(&mut c, b, size, page),
    }
    Some(c)
}

/// How the body's points reach the page: as they are (the plane) or in
/// the isometric view (space).
#[derive(Clone, Copy)]
enum Page {
    Plane,
    Space(View),
}

impl Page {
    /// Space where the body's G has three coordinates, up against its weight.
    fn of(b: &FreeBody) -> Self {
        if b.cg.len() < 3 {
            return Self::Plane;
        }
        let weight = b.forces.iter().find(|f| f.kind == "weight").map_or([0.0; 3], vector);
        Self::Space(View::against(&weight))
    }

    fn at(self, p: &[f64]) -> (f64, f64) {
        match self {
            Self::Plane => (p[0], p[1]),
            Self::Space(view) => view.project(&[p[0], p[1], p.get(2).copied().unwrap_or(0.0)]),
        }
    }
}

/// A force's [fx, fy, fz] (fz 0 in the plane).
fn vector(f: &Force) -> [f64; 3] {
    [f.fx, f.fy, f.fz.unwrap_or(0.0)]
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// `p` moved by `v` times `scale`, on the page.
fn tip(page: Page, p: &[f64], v: [f64; 3], scale: f64) -> (f64, f64) {
    let q: Vec<f64> = (0..p.len()).map(|k| p[k] + v[k] * scale).collect();
    page.at(&q)
}

/// The body between the points its reactions act at (G where it has one
/// or none); its size, the largest distance from G to them.
fn outline(c: &mut Chart, b: &FreeBody, page: Page) -> f64 {
    let g = page.at(&b.cg);
    let mut points: Vec<(f64, f64)> = Vec::new();
    for f in b.forces.iter().filter(|f| f.kind == "reaction") {
        let p = page.at(&f.at);
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
fn forces(c: &mut Chart, b: &FreeBody, size: f64, page: Page) {
    let largest = b.forces.iter().map(|f| norm(vector(f))).fold(0.0, f64::max);
    if largest <= 0.0 || !largest.is_finite() {
        return;
    }
    let scale = LONGEST * size / largest;
    for f in b.forces.iter().filter(|f| norm(vector(f)) > 1e-9 * largest) {
        let color = match f.kind.as_str() {
            "reaction" => 1,
            "inertia" => 3,
            "weight" => 4,
            "driving" => 2,
            _ => 5,
        };
        c.arrows.push(Arrow {
            from: page.at(&f.at),
            to: tip(page, &f.at, vector(f), scale),
            color,
            label: format!("{} = {} N", f.name, sig(norm(vector(f)))),
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

/// Every couple in space as its moment vector from G, to one scale (the
/// longest half the longest force's), with a double head.
fn moment_vectors(c: &mut Chart, b: &FreeBody, size: f64, page: Page) {
    let moment = |m: &super::solution::Couple| [m.mx.unwrap_or(0.0), m.my.unwrap_or(0.0), m.moment];
    let largest = b.couples.iter().map(|m| norm(moment(m))).fold(0.0, f64::max);
    if largest <= 0.0 || !largest.is_finite() {
        return;
    }
    let scale = 0.5 * LONGEST * size / largest;
    for m in b.couples.iter().filter(|m| norm(moment(m)) > 1e-9 * largest) {
        let (from, to) = (page.at(&b.cg), tip(page, &b.cg, moment(m), scale));
        let inner = tip(page, &b.cg, moment(m), 0.85 * scale);
        let label = format!("{} = {} N·m", m.name, sig(norm(moment(m))));
        c.arrows.push(Arrow { from, to, color: 2, label });
        c.arrows.push(Arrow { from, to: inner, color: 2, label: String::new() });
    }
    let note = Msg::new("plot-moments-to-scale").arg("moment", sig(largest)).arg("length", sig(scale * largest)).text();
    c.lines.push(Line { label: Some(note), points: Vec::new(), pen: Pen::solid(2) });
}
