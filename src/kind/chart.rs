//! A chart as data: what a kind's plot says (its title, its axes with units,
//! its curves, shaded areas, reference lines and labelled points), built
//! from a stored result and drawn by one renderer ([`super::svg`]), so that
//! every plot of every kind looks and reads alike.

/// An axis: what it measures and in which unit.
#[derive(Clone, Debug)]
pub struct Axis {
    pub name: String,
    pub unit: String,
}

impl Axis {
    pub fn new(name: impl Into<String>, unit: impl Into<String>) -> Self {
        Self { name: name.into(), unit: unit.into() }
    }
    /// "crank angle φ (°)" (degrees as the course writes them); a
    /// dimensionless axis has no unit.
    pub fn label(&self) -> String {
        if self.unit.is_empty() || self.unit == "1" {
            self.name.clone()
        } else {
            let unit = if self.unit == "deg" { "°" } else { &self.unit };
            format!("{} ({unit})", self.name)
        }
    }
}

/// How a line is drawn: its colour (an index into the palette) and dash.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pen {
    pub color: usize,
    pub dashed: bool,
    pub width: u32,
}

impl Pen {
    /// A curve of the result: solid, 2 px.
    pub const fn solid(color: usize) -> Self {
        Self { color, dashed: false, width: 2 }
    }
    /// A construction line or a given value: dashed, 1 px.
    pub const fn dashed(color: usize) -> Self {
        Self { color, dashed: true, width: 1 }
    }
}

/// A polyline; `label` names it in the legend.
#[derive(Clone, Debug)]
pub struct Line {
    pub label: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub pen: Pen,
}

/// A shaded polygon (a lobe of work, a slider's box).
#[derive(Clone, Debug)]
pub struct Fill {
    pub points: Vec<(f64, f64)>,
    pub color: usize,
    /// Opacity of the fill, 0 to 1.
    pub opacity: f64,
}

/// A line across the whole plot at x or at y (a reference value, an event).
#[derive(Clone, Debug)]
pub struct Rule {
    pub at: Level,
    pub label: String,
    pub pen: Pen,
}

#[derive(Clone, Copy, Debug)]
pub enum Level {
    X(f64),
    Y(f64),
}

/// A point with a text next to it (a crossing, a lobe's area, an extreme).
#[derive(Clone, Debug)]
pub struct Mark {
    pub at: (f64, f64),
    pub text: String,
    /// Draw a dot at the point.
    pub dot: bool,
}

/// An arrow from `from` to `to` (a force to scale).
#[derive(Clone, Debug)]
pub struct Arrow {
    pub from: (f64, f64),
    pub to: (f64, f64),
    pub color: usize,
    pub label: String,
}

/// One plot.
#[derive(Clone, Debug)]
pub struct Chart {
    pub title: String,
    /// A second line under the title (the values the plot shows, e.g. ΔE).
    pub subtitle: Option<String>,
    pub x: Axis,
    pub y: Axis,
    /// Equal scales on both axes (a drawing, a polar diagram).
    pub equal: bool,
    pub fills: Vec<Fill>,
    pub lines: Vec<Line>,
    pub rules: Vec<Rule>,
    pub arrows: Vec<Arrow>,
    pub marks: Vec<Mark>,
    /// Pictures shown one after the other over what the chart draws (a
    /// mechanism in motion), on the same axes.
    pub animation: Option<Animation>,
}

/// A chart's frames, played in a loop.
#[derive(Clone, Debug)]
pub struct Animation {
    /// One loop, s.
    pub seconds: f64,
    pub frames: Vec<Frame>,
}

/// What one frame draws, from when it is shown (`at`, a fraction of the
/// loop, growing from 0 frame by frame) until the next.
#[derive(Clone, Debug)]
pub struct Frame {
    pub at: f64,
    /// What it shows (the input angle, the time), written at the top right.
    pub caption: String,
    /// The step of the result it draws.
    pub step: usize,
    pub fills: Vec<Fill>,
    pub lines: Vec<Line>,
    pub arrows: Vec<Arrow>,
    pub marks: Vec<Mark>,
}

impl Chart {
    pub fn new(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        Self {
            title: title.into(),
            subtitle: None,
            x,
            y,
            equal: false,
            fills: Vec::new(),
            lines: Vec::new(),
            rules: Vec::new(),
            arrows: Vec::new(),
            marks: Vec::new(),
            animation: None,
        }
    }
    pub fn line(mut self, label: impl Into<String>, points: Vec<(f64, f64)>, pen: Pen) -> Self {
        let label = Some(label.into()).filter(|l: &String| !l.is_empty());
        self.lines.push(Line { label, points, pen });
        self
    }
    pub fn rule(mut self, at: Level, label: impl Into<String>, pen: Pen) -> Self {
        self.rules.push(Rule { at, label: label.into(), pen });
        self
    }
    pub fn mark(mut self, at: (f64, f64), text: impl Into<String>) -> Self {
        self.marks.push(Mark { at, text: text.into(), dot: true });
        self
    }
    pub fn subtitle(mut self, text: impl Into<String>) -> Self {
        self.subtitle = Some(text.into());
        self
    }

    /// The smallest box holding every point, line, fill, arrow and rule, of
    /// every frame too.
    pub fn bounds(&self) -> Option<[f64; 4]> {
        let mut b = [f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY];
        let mut add = |(x, y): (f64, f64)| {
            if x.is_finite() && y.is_finite() {
                b = [b[0].min(x), b[1].max(x), b[2].min(y), b[3].max(y)];
            }
        };
        let frames = self.animation.iter().flat_map(|a| &a.frames);
        let lines = self.lines.iter().chain(frames.clone().flat_map(|f| &f.lines));
        lines.flat_map(|l| &l.points).for_each(|p| add(*p));
        let fills = self.fills.iter().chain(frames.clone().flat_map(|f| &f.fills));
        fills.flat_map(|f| &f.points).for_each(|p| add(*p));
        let arrows = self.arrows.iter().chain(frames.clone().flat_map(|f| &f.arrows));
        arrows.for_each(|a| [a.from, a.to].into_iter().for_each(&mut add));
        self.marks.iter().chain(frames.flat_map(|f| &f.marks)).for_each(|m| add(m.at));
        for r in &self.rules {
            match r.at {
                Level::X(x) if x.is_finite() => {
                    b[0] = b[0].min(x);
                    b[1] = b[1].max(x);
                }
                Level::Y(y) if y.is_finite() => {
                    b[2] = b[2].min(y);
                    b[3] = b[3].max(y);
                }
                _ => {}
            }
        }
        (b[0] <= b[1] && b[2] <= b[3]).then_some(b)
    }
}

/// A plot of a job: its name in URLs and its title.
#[derive(Clone, Debug, PartialEq)]
pub struct Listed {
    pub name: String,
    pub title: String,
}

impl Listed {
    pub fn new(name: impl Into<String>, title: impl Into<String>) -> Self {
        Self { name: name.into(), title: title.into() }
    }
}
