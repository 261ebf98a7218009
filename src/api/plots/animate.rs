//! An animated chart's frames as SMIL, with no script: each frame drawn by
//! plotters on the chart's own axes (the same areas and ranges as what the
//! frames share), in a group `<g data-step>` whose visibility an
//! `<animate calcMode="discrete">` turns on from the frame's time to the
//! next one's, looping. It plays in a browser, an `<img>` and a course
//! page alike; a viewer without SMIL shows the first frame.
//!
//! The root `<svg>` says where the data are: `data-range` (x₀ x₁ y₀ y₁, the
//! axes' ranges in the data's units) and `data-plot` (the plotting area's
//! left, top, right and bottom in the viewBox's units), so that a reader
//! can find a point of the data on the picture.

use super::svg::{self, Area, FONT, Failure, S, px};
use crate::kind::chart::{Animation, Chart, Frame};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::fmt::Write;

/// The chart as SVG ([`svg::render`]), its frames after what they share.
pub fn render(chart: &Chart) -> Result<String, String> {
    let shared = svg::render(chart)?;
    let Some(a) = &chart.animation else { return Ok(shared) };
    let (frames, map) = frames(chart, a)?;
    let tag = shared.find('>').unwrap_or(0);
    Ok(format!("{}{map}{}{frames}</svg>", &shared[..tag], svg::inner_end(&shared[tag..])))
}

/// The frames' groups, and the root's attributes that map the data.
fn frames(chart: &Chart, a: &Animation) -> Result<(String, String), String> {
    let mut out = String::new();
    let mut map = String::new();
    for (k, f) in a.frames.iter().enumerate() {
        let until = a.frames.get(k + 1).map(|n| n.at);
        let (body, plot) = frame(chart, f).map_err(|e| format!("plot '{}', frame {k}: {e}", chart.title))?;
        if k == 0 {
            map = plot;
        }
        let _ = write!(out, r#"<g data-step="{}" visibility="{}">"#, f.step, if k == 0 { "visible" } else { "hidden" });
        let (values, times) = match (k, until) {
            (_, None) if k == 0 => (String::new(), String::new()),
            (0, Some(b)) => ("visible;hidden".into(), format!("0;{b}")),
            (_, Some(b)) => ("hidden;visible;hidden".into(), format!("0;{};{b}", f.at)),
            (_, None) => ("hidden;visible".into(), format!("0;{}", f.at)),
        };
        if !values.is_empty() {
            let _ = write!(
                out,
                r#"<animate attributeName="visibility" calcMode="discrete" values="{values}" keyTimes="{times}" dur="{}s" repeatCount="indefinite"/>"#,
                a.seconds
            );
        }
        let _ = write!(out, "{}</g>", svg::inner_end(&body));
    }
    Ok((out, map))
}

/// Frame `f` drawn alone (what plotters wrote after its `<svg>` tag), and
/// the root's attributes mapping the data onto the picture.
fn frame(chart: &Chart, f: &Frame) -> Result<(String, String), Failure> {
    let mut svg = String::new();
    let map;
    {
        let root =
            SVGBackend::with_string(&mut svg, (svg::SIZE.0 * S as u32, svg::SIZE.1 * S as u32)).into_drawing_area();
        let (top, plot, _) = svg::areas(&root, chart);
        let range = svg::ranges(chart, plot.dim_in_pixel());
        let mut c = svg::builder(&plot, range)?;
        let mut content = Chart::new("", chart.x.clone(), chart.y.clone());
        (content.fills, content.lines) = (f.fills.clone(), f.lines.clone());
        (content.arrows, content.marks) = (f.arrows.clone(), f.marks.clone());
        let columns = plot.dim_in_pixel().0 as usize / S as usize;
        svg::data(&root, &mut c, &content, range, columns)?;
        svg::labels(&root, &c, &content, range, columns)?;
        caption(&top, &f.caption)?;
        let (xs, ys) = c.plotting_area().get_pixel_range();
        map = format!(
            r#" data-range="{} {} {} {}" data-plot="{} {} {} {}""#,
            range[0], range[1], range[2], range[3], xs.start, ys.start, xs.end, ys.end
        );
        root.present()?;
    }
    let body = svg.find('>').map_or(String::new(), |end| svg[end + 1..].to_string());
    Ok((body, map))
}

/// The frame's caption at the title band's right end.
fn caption(top: &Area, text: &str) -> Result<(), Failure> {
    let style = (FONT, px(15)).into_font().color(&BLACK).pos(Pos::new(HPos::Right, VPos::Top));
    top.draw(&Text::new(svg::clean(text), (px(svg::SIZE.0 as i32 - 16), px(12)), style))?;
    Ok(())
}
