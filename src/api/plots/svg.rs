//! Draws a [`Chart`] as SVG with plotters: title and subtitle above, the
//! axes with their names and units, the legend below the plot (never over a
//! curve), labels of marks and reference lines placed where they overlap
//! nothing already drawn (a label that fits nowhere is left out, its value
//! being in the legend or the subtitle), and long curves thinned to what the
//! pixels can show (the smallest and largest value of every pixel column
//! kept, so no peak is lost).

use crate::kind::chart::{Chart, Level, Line, Pen};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::series::DashedLineSeries;

/// Size of every plot, px.
pub const SIZE: (u32, u32) = (820, 520);
/// Drawn at this many times the size, then scaled down by the SVG's
/// `viewBox`: plotters places everything on whole pixels, which made
/// curves visibly stepped at 1×.
pub(super) const S: i32 = 2;

/// `v` px of the plot in the backend's pixels.
pub(super) const fn px(v: i32) -> i32 {
    v * S
}
/// Okabe and Ito's palette (told apart with any colour vision), yellow left out.
const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(230, 159, 0),
    RGBColor(204, 121, 167),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
    RGBColor(136, 136, 136),
];
pub(super) const FONT: &str = "sans-serif";
/// A curve of at most this many points has each drawn as a dot.
const FEW: usize = 40;
/// Approximate width of a character of the labels, in font sizes.
const CHAR_WIDTH: f64 = 0.56;

pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
pub(super) type Failure = Box<dyn std::error::Error>;

pub fn color(k: usize) -> RGBColor {
    PALETTE[k % PALETTE.len()]
}

/// The chart as an SVG document with a `<title>` (an animated chart's
/// frames left to [`super::animate`]).
pub fn render(chart: &Chart) -> Result<String, String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (SIZE.0 * S as u32, SIZE.1 * S as u32)).into_drawing_area();
        draw(&root, chart).map_err(|e| format!("plot '{}': {e}", chart.title))?;
        root.present().map_err(|e| e.to_string())?;
    }
    let (w, h) = SIZE;
    let open = format!(
        r#"<svg width="{w}" height="{h}" viewBox="0 0 {} {}" xmlns="http://www.w3.org/2000/svg" role="img"><title>{}</title>"#,
        w * S as u32,
        h * S as u32,
        xml_escape(&clean(&chart.title))
    );
    Ok(match svg.find('>') {
        Some(end) => format!("{open}{}", &svg[end + 1..]),
        None => svg,
    })
}

/// What plotters wrote before its closing `</svg>`.
pub(super) fn inner_end(body: &str) -> &str {
    body.trim_end().strip_suffix("</svg>").unwrap_or(body)
}

fn draw(root: &Area, chart: &Chart) -> Result<(), Failure> {
    root.fill(&WHITE)?;
    let (top, plot, foot) = areas(root, chart);
    top.draw(&Text::new(clean(&chart.title), (px(16), px(10)), (FONT, px(19)).into_font().color(&BLACK)))?;
    if let Some(sub) = &chart.subtitle {
        top.draw(&Text::new(clean(sub), (px(16), px(36)), (FONT, px(14)).into_font().color(&RGBColor(60, 60, 60))))?;
    }
    let range = ranges(chart, plot.dim_in_pixel());
    let mut c = axes(&plot, chart, range)?;
    data(root, &mut c, chart, range, plot.dim_in_pixel().0 as usize / S as usize)?;
    labels(root, &c, chart, range, plot.dim_in_pixel().0 as usize / S as usize)?;
    draw_legend(&foot, &chart.lines.iter().filter(|l| l.label.is_some()).collect::<Vec<_>>())
}

/// The title's band, the plot's and the legend's below.
pub(super) fn areas<'a>(root: &Area<'a>, chart: &Chart) -> (Area<'a>, Area<'a>, Area<'a>) {
    let legend: Vec<&Line> = chart.lines.iter().filter(|l| l.label.is_some()).collect();
    let head = if chart.subtitle.is_some() { 58 } else { 36 };
    let (top, rest) = root.split_vertically(px(head));
    let (plot, foot) = rest.split_vertically(px(SIZE.1 as i32 - head - 22 * legend_rows(&legend) as i32 - 6));
    (top, plot, foot)
}

pub(super) type Context<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The plot's coordinates over `plot`, its axes' room left around it.
pub(super) fn builder<'a, 'b>(plot: &'a Area<'b>, [x0, x1, y0, y1]: [f64; 4]) -> Result<Context<'a, 'b>, Failure> {
    Ok(ChartBuilder::on(plot)
        .margin_right(px(24))
        .margin_top(px(6))
        .x_label_area_size(px(46))
        .y_label_area_size(px(78))
        .build_cartesian_2d(x0..x1, y0..y1)?)
}

/// The plot's frame: axes with their names and ticks, a light grid.
fn axes<'a, 'b>(plot: &'a Area<'b>, chart: &Chart, range: [f64; 4]) -> Result<Context<'a, 'b>, Failure> {
    let mut c = builder(plot, range)?;
    let [x0, x1, y0, y1] = range;
    let (fx, fy) = (ticks(x1 - x0), ticks(y1 - y0));
    c.configure_mesh()
        .x_desc(clean(&chart.x.label()))
        .y_desc(clean(&chart.y.label()))
        .axis_desc_style((FONT, px(15)))
        .label_style((FONT, px(13)))
        .x_label_formatter(&|v| fx(*v))
        .y_label_formatter(&|v| fy(*v))
        .light_line_style(RGBColor(240, 240, 240))
        .bold_line_style(RGBColor(215, 215, 215))
        .axis_style(BLACK.stroke_width(S as u32))
        .draw()?;
    Ok(c)
}

/// Shaded areas, reference lines, curves (thinned to `columns`), arrows and dots.
pub(super) fn data(
    root: &Area,
    c: &mut Context,
    chart: &Chart,
    [x0, x1, y0, y1]: [f64; 4],
    columns: usize,
) -> Result<(), Failure> {
    for f in &chart.fills {
        let style = color(f.color).mix(f.opacity).filled();
        c.draw_series(std::iter::once(Polygon::new(thin(&f.points, columns), style)))?;
    }
    for r in &chart.rules {
        let pts = match r.at {
            Level::X(x) => vec![(x, y0), (x, y1)],
            Level::Y(y) => vec![(x0, y), (x1, y)],
        };
        stroke(c, &pts, r.pen)?;
    }
    for l in &chart.lines {
        stroke(c, &thin(&l.points, columns), l.pen)?;
    }
    for a in &chart.arrows {
        arrow(root, c.backend_coord(&a.from), c.backend_coord(&a.to), color(a.color))?;
    }
    for m in chart.marks.iter().filter(|m| m.dot) {
        c.plotting_area().draw(&Circle::new(m.at, px(4), BLACK.filled()))?;
    }
    Ok(())
}

/// The labels of reference lines, arrows and marks, each where it overlaps
/// no other label and no dot.
pub(super) fn labels(
    root: &Area,
    c: &Context,
    chart: &Chart,
    [x0, x1, y0, y1]: [f64; 4],
    columns: usize,
) -> Result<(), Failure> {
    let mut placed = Placed::new(c.plotting_area().get_pixel_range());
    for m in chart.marks.iter().filter(|m| m.dot) {
        let p = c.backend_coord(&m.at);
        placed.taken.push((p.0 - px(4), p.1 - px(4), p.0 + px(4), p.1 + px(4)));
    }
    for l in &chart.lines {
        placed.avoid(thin(&l.points, columns).iter().map(|p| c.backend_coord(p)));
    }
    for r in &chart.rules {
        let anchors: Vec<_> = match r.at {
            // Along a horizontal line: at its right end, its left end, then between.
            Level::Y(y) => [1.0, 0.0, 0.5, 0.25, 0.75]
                .iter()
                .flat_map(|f| {
                    let at = c.backend_coord(&(x0 + f * (x1 - x0), y));
                    let dx = if *f > 0.5 { -4 } else { 4 };
                    [(at, (dx, -18)), (at, (dx, 4))]
                })
                .collect(),
            // Along a vertical line: at its top, its middle, its bottom.
            Level::X(x) => [(0.0, 4), (0.5, -8), (1.0, -22)]
                .iter()
                .map(|(f, dy)| (c.backend_coord(&(x, y1 - f * (y1 - y0))), (4, *dy)))
                .collect(),
        };
        placed.label(root, &anchors, &r.label, color(r.pen.color))?;
    }
    for a in chart.arrows.iter().filter(|a| !a.label.is_empty()) {
        placed.label(root, &around(c.backend_coord(&a.to)), &a.label, color(a.color))?;
    }
    for m in &chart.marks {
        placed.label(root, &around(c.backend_coord(&m.at)), &m.text, BLACK)?;
    }
    Ok(())
}

/// The axes' ranges: the chart's bounds with a margin, never empty; with
/// equal scales, the shorter range widened so a metre is as long either way.
pub(super) fn ranges(chart: &Chart, (w, h): (u32, u32)) -> [f64; 4] {
    let [mut x0, mut x1, mut y0, mut y1] = chart.bounds().unwrap_or([0.0, 1.0, 0.0, 1.0]);
    for (lo, hi) in [(&mut x0, &mut x1), (&mut y0, &mut y1)] {
        let span = *hi - *lo;
        let pad = if span > 0.0 { 0.05 * span } else { (0.1 * lo.abs()).max(1e-9) };
        (*lo, *hi) = (*lo - pad, *hi + pad);
    }
    if chart.equal {
        let (pw, ph) =
            (f64::from(w.saturating_sub(px(110) as u32).max(1)), f64::from(h.saturating_sub(px(60) as u32).max(1)));
        let scale = ((x1 - x0) / pw).max((y1 - y0) / ph);
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        (x0, x1, y0, y1) = (cx - scale * pw / 2.0, cx + scale * pw / 2.0, cy - scale * ph / 2.0, cy + scale * ph / 2.0);
    }
    [x0, x1, y0, y1]
}

/// A tick formatter for an axis spanning `span`: as many decimals as the
/// ticks (about ten of them) need, powers of ten beyond 10⁶ or below 10⁻³.
fn ticks(span: f64) -> impl Fn(f64) -> String {
    let step = span / 10.0;
    let decimals = if step > 0.0 { (-step.log10().floor()).clamp(0.0, 12.0) as usize } else { 2 };
    let scientific = span > 0.0 && !(1e-3..1e6).contains(&span);
    let lang = crate::i18n::current();
    move |v: f64| {
        if v.abs() < step * 1e-6 {
            "0".into()
        } else if scientific {
            lang.decimal(format!("{v:.2e}"))
        } else {
            lang.decimal(format!("{v:.decimals$}"))
        }
    }
}

fn stroke(c: &mut Context, points: &[(f64, f64)], pen: Pen) -> Result<(), Failure> {
    let style = color(pen.color).stroke_width(pen.width * S as u32);
    let pts: Vec<(f64, f64)> = points.iter().copied().filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
    if pen.dashed {
        c.draw_series(DashedLineSeries::new(pts, px(7), px(5), style))?;
    } else if pts.len() <= FEW && pen.width >= 2 {
        // Few samples: each one shown, so a straight segment is not read as data between them.
        let dots: Vec<Circle<(f64, f64), i32>> =
            pts.iter().map(|p| Circle::new(*p, px(3), color(pen.color).filled())).collect();
        c.draw_series(LineSeries::new(pts, style))?;
        c.draw_series(dots)?;
    } else {
        c.draw_series(LineSeries::new(pts, style))?;
    }
    Ok(())
}

/// At most about four points per pixel column: for a curve whose x only
/// grows, the first, smallest, largest and last point of each column; for
/// any other, every k-th point (and the last).
pub fn thin(points: &[(f64, f64)], width: usize) -> Vec<(f64, f64)> {
    let most = 4 * width.max(1);
    if points.len() <= most {
        return points.to_vec();
    }
    let (a, b) = (points[0].0, points[points.len() - 1].0);
    if !points.windows(2).all(|w| w[1].0 >= w[0].0) || b <= a {
        let k = points.len().div_ceil(most);
        let mut out: Vec<_> = points.iter().step_by(k).copied().collect();
        out.push(points[points.len() - 1]);
        return out;
    }
    let column = |x: f64| (((x - a) / (b - a)) * width as f64) as usize;
    let mut out = Vec::with_capacity(most);
    for group in points.chunk_by(|p, q| column(p.0) == column(q.0)) {
        let lo = group.iter().min_by(|p, q| p.1.total_cmp(&q.1)).copied();
        let hi = group.iter().max_by(|p, q| p.1.total_cmp(&q.1)).copied();
        let mut four = [Some(group[0]), lo, hi, Some(group[group.len() - 1])];
        four[1..3].sort_by(|p, q| p.map(|p| p.0).partial_cmp(&q.map(|q| q.0)).unwrap_or(std::cmp::Ordering::Equal));
        for p in four.into_iter().flatten() {
            if out.last() != Some(&p) {
                out.push(p);
            }
        }
    }
    out
}

fn arrow(root: &Area, from: (i32, i32), to: (i32, i32), c: RGBColor) -> Result<(), Failure> {
    let (dx, dy) = (f64::from(to.0 - from.0), f64::from(to.1 - from.1));
    let len = dx.hypot(dy);
    root.draw(&PathElement::new(vec![from, to], c.stroke_width(2 * S as u32)))?;
    if len >= 1.0 {
        let (ux, uy) = (dx / len, dy / len);
        let head = f64::from(px(10)).min(len);
        let base = (f64::from(to.0) - head * ux, f64::from(to.1) - head * uy);
        let half = f64::from(px(4));
        let side = |s: f64| ((base.0 - s * half * uy) as i32, (base.1 + s * half * ux) as i32);
        root.draw(&Polygon::new(vec![to, side(1.0), side(-1.0)], c.filled()))?;
    }
    Ok(())
}

/// Rectangles already drawn on (labels, dots), the curves' pixels, and
/// the plot's area, in pixels.
struct Placed {
    taken: Vec<(i32, i32, i32, i32)>,
    curves: Vec<(i32, i32)>,
    area: (std::ops::Range<i32>, std::ops::Range<i32>),
}

type Rect = (i32, i32, i32, i32);
/// Where a label may go: a point and the text's offset from it, px of the plot.
type Anchor = ((i32, i32), (i32, i32));

impl Placed {
    /// Labels stay within the plot, or up to 12 px above it (into its top
    /// margin: a line at the top of the range still has its label above it).
    fn new((x, y): (std::ops::Range<i32>, std::ops::Range<i32>)) -> Self {
        Self { taken: Vec::new(), curves: Vec::new(), area: (x, y.start - px(12)..y.end) }
    }

    /// The pixels of a curve (a point every 6 px along it), for labels to avoid.
    fn avoid(&mut self, pixels: impl Iterator<Item = (i32, i32)>) {
        let mut last: Option<(i32, i32)> = None;
        for p in pixels {
            if let Some(a) = last {
                let n = ((p.0 - a.0).abs().max((p.1 - a.1).abs()) / px(6)).max(1);
                self.curves.extend((1..=n).map(|k| (a.0 + (p.0 - a.0) * k / n, a.1 + (p.1 - a.1) * k / n)));
            } else {
                self.curves.push(p);
            }
            last = Some(p);
        }
    }

    fn inside(&self, r: Rect) -> bool {
        r.0 >= self.area.0.start && r.2 <= self.area.0.end && r.1 >= self.area.1.start && r.3 <= self.area.1.end
    }

    fn clear_of_labels(&self, r: Rect) -> bool {
        !self.taken.iter().any(|t| r.0 < t.2 && t.0 < r.2 && r.1 < t.3 && t.1 < r.3)
    }

    fn clear_of_curves(&self, r: Rect) -> bool {
        let m = px(2);
        !self.curves.iter().any(|p| p.0 >= r.0 - m && p.0 <= r.2 + m && p.1 >= r.1 - m && p.1 <= r.3 + m)
    }

    /// Writes `text` at the first of `anchors` (a point and an offset, px of
    /// the plot) where it stays in the plot and overlaps no label and no
    /// curve; failing that, the first where it overlaps no label (crossing
    /// a curve, on a white ground); nowhere if none is free.
    fn label(&mut self, root: &Area, anchors: &[Anchor], text: &str, c: RGBColor) -> Result<(), Failure> {
        if text.is_empty() {
            return Ok(());
        }
        let text = clean(text);
        let (w, h) = (px((text.chars().count() as f64 * 13.0 * CHAR_WIDTH) as i32), px(15));
        let rects: Vec<Rect> = anchors
            .iter()
            .map(|&(at, (dx, dy))| {
                let (x, y) = (at.0 + px(dx), at.1 + px(dy));
                let x = if dx < 0 { x - w } else { x };
                (x, y, x + w, y + h)
            })
            .filter(|r| self.inside(*r) && self.clear_of_labels(*r))
            .collect();
        let Some(&r) = rects.iter().find(|r| self.clear_of_curves(**r)).or(rects.first()) else { return Ok(()) };
        let ground = [(r.0 - px(2), r.1 - px(1)), (r.2 + px(2), r.3 + px(1))];
        root.draw(&Rectangle::new(ground, WHITE.mix(0.85).filled()))?;
        root.draw(&Text::new(text, (r.0, r.1), (FONT, px(13)).into_font().color(&c)))?;
        self.taken.push(r);
        Ok(())
    }
}

/// Around a point: right above, right below, left above, left below, then
/// further out (a negative x offset puts the text's right end there).
fn around(at: (i32, i32)) -> Vec<Anchor> {
    [(7, -18), (7, 4), (-7, -18), (-7, 4), (7, -34), (-7, -34), (7, 20), (-7, 20)].map(|o| (at, o)).to_vec()
}

/// Where each entry of the legend goes: (x, y) in px of the plot, entries
/// left to right, a new row when the next would pass the right edge.
fn legend_layout(legend: &[&Line]) -> Vec<(f64, i32)> {
    let (mut x, mut y) = (80.0, 4);
    let mut out = Vec::with_capacity(legend.len());
    for l in legend {
        let w = entry_width(l);
        if x + w > f64::from(SIZE.0) - 10.0 && x > 80.0 {
            (x, y) = (80.0, y + 22);
        }
        out.push((x, y));
        x += w;
    }
    out
}

fn legend_rows(legend: &[&Line]) -> usize {
    legend_layout(legend).last().map_or(0, |(_, y)| (*y as usize - 4) / 22 + 1)
}

fn entry_width(l: &Line) -> f64 {
    l.label.as_deref().map_or(0.0, |t| 36.0 + t.chars().count() as f64 * 13.0 * CHAR_WIDTH + 18.0)
}

/// The legend below the plot: a short stroke and the curve's name, in rows.
fn draw_legend(foot: &Area, legend: &[&Line]) -> Result<(), Failure> {
    for (l, (x, y)) in legend.iter().zip(legend_layout(legend)) {
        let style = color(l.pen.color).stroke_width(l.pen.width.max(2) * S as u32);
        let (xi, yi) = (x as i32, y + 8);
        let at = |x: i32, y: i32| (px(x), px(y));
        if l.pen.dashed {
            foot.draw(&PathElement::new(vec![at(xi, yi), at(xi + 10, yi)], style))?;
            foot.draw(&PathElement::new(vec![at(xi + 16, yi), at(xi + 26, yi)], style))?;
        } else {
            foot.draw(&PathElement::new(vec![at(xi, yi), at(xi + 26, yi)], style))?;
        }
        let text = clean(l.label.as_deref().unwrap_or(""));
        foot.draw(&Text::new(text, at(xi + 34, y), (FONT, px(13)).into_font().color(&BLACK)))?;
    }
    Ok(())
}

/// Text as a person may safely read it: control characters (which XML 1.0
/// forbids even escaped) and the invisible marks that reverse the direction
/// of text (which would show "evil" as "live") become U+FFFD.
pub fn clean(text: &str) -> String {
    let hidden = |c: char| {
        c.is_control() || matches!(c, '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
    };
    text.chars().map(|c| if hidden(c) { '\u{FFFD}' } else { c }).collect()
}

fn xml_escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}
