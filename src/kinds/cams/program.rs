//! A cam's program of segments, each a law to its angle and lift, read
//! into the engine's [`Program`], every error at its pointer.

use crate::engine::cam::{Law, Program, ProgramError, Segment};
use crate::i18n::{Msg, names};
use crate::kind::quantity::{Errors, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A cam's length given as a bare number this large (m) or larger is
/// noticed as likely meant in mm ("25" for a 25 mm lift).
pub const BARE_MM: f64 = 1.0;

/// Most segments of a program.
pub const MAX_SEGMENTS: usize = 100;

/// A segment ending at `to` with the follower at `lift` by `law`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CamSegmentDto {
    #[schema(value_type = Quantity)]
    pub to: Quantity,
    /// dwell, harmonic, cycloidal, polynomial-345, polynomial-4567, modified-sine or modified-trapezoid
    /// (in any case, or in Spanish: "cicloidal", "reposo", "armónico"…).
    pub law: String,
    /// m, or an angle for an oscillating follower (a dwell's may be left out: it holds).
    #[schema(value_type = Option<Quantity>)]
    pub lift: Option<Quantity>,
}

/// Each law: its wire name, the engine's law, and the catalogue's words for it.
pub const LAWS: [(&str, Law, &str); 7] = [
    ("dwell", Law::Dwell, "cam-law-dwell"),
    ("harmonic", Law::Harmonic, "cam-law-harmonic"),
    ("cycloidal", Law::Cycloidal, "cam-law-cycloidal"),
    ("polynomial-345", Law::Poly345, "cam-law-polynomial-345"),
    ("polynomial-4567", Law::Poly4567, "cam-law-polynomial-4567"),
    ("modified-sine", Law::ModifiedSine, "cam-law-modified-sine"),
    ("modified-trapezoid", Law::ModifiedTrapezoid, "cam-law-modified-trapezoid"),
];

/// The law of wire name `name` as the asker's language says it (the name
/// itself where it is none of [`LAWS`]).
pub fn law_words(name: &str) -> Msg {
    match LAWS.iter().find(|l| l.0 == name) {
        Some(&(_, _, words)) => Msg::new(words),
        None => Msg::new("text-as-is").arg("why", name),
    }
}

/// A program of segments at pointer `at` (`/program`), with each segment's law's name.
pub fn program(e: &mut Errors, list: &[CamSegmentDto], at: &str, lift: Dim) -> Option<(Program, Vec<&'static str>)> {
    let root = at;
    if list.is_empty() || list.len() > MAX_SEGMENTS {
        return e.refuse(root, Msg::new("cam-segments-count").arg("max", MAX_SEGMENTS));
    }
    let (mut start, mut from, mut segments, mut names) = (0.0, 0.0, Vec::new(), Vec::new());
    for (k, s) in list.iter().enumerate() {
        let at = format!("{root}/{k}");
        let to = e.angle(&s.to, &format!("{at}/to"));
        let named = names::read(&s.law, &LAWS.map(|l| l.0));
        let law = match LAWS.iter().find(|l| Some(l.0) == named) {
            Some(&(name, law, _)) => Some((name, law)),
            None => {
                let msg = Msg::new("cam-unknown-law").arg("law", &s.law).arg("laws", LAWS.map(|l| l.0).join(", "));
                e.refuse(&format!("{at}/law"), msg)
            }
        };
        let lift = match (&s.lift, law) {
            (Some(q), _) if lift == Dim::ANGLE => e.angle(q, &format!("{at}/lift")),
            (Some(q), _) => {
                e.notice_bare_length(q, &format!("{at}/lift"), BARE_MM);
                e.quantity(q, lift, &format!("{at}/lift"))
            }
            (None, Some((_, Law::Dwell))) => Some(from),
            (None, Some(_)) => e.refuse(&at, Msg::new("cam-needs-lift")),
            (None, None) => None,
        };
        let (Some(to), Some((name, law)), Some(lift)) = (to, law, lift) else { return None };
        segments.push(Segment { law, start, span: to - start, from, to: lift });
        names.push(name);
        (start, from) = (to, lift);
    }
    let starts: Vec<f64> = segments.iter().map(|s| s.start).collect();
    match Program::new(segments) {
        Ok(p) => Some((p, names)),
        Err(err) => {
            let last = list.len() - 1;
            let (at, id) = match err {
                ProgramError::Empty { segment, .. } => {
                    // Where the segment before ends, in rad and degrees: a bare "120" read as 120 rad shows.
                    let end = starts.get(segment).copied().unwrap_or(0.0);
                    let msg = Msg::new("cam-after-previous").num("end", end).fig("degrees", end.to_degrees());
                    return e.refuse(&format!("{root}/{segment}/to"), msg);
                }
                ProgramError::MovingDwell { segment, .. } => (format!("{root}/{segment}/lift"), "cam-dwell"),
                ProgramError::NotATurn { .. } => (format!("/program/{last}/to"), "cam-full-turn"),
                ProgramError::NotClosed { .. } => (format!("/program/{last}/lift"), "cam-closed"),
                ProgramError::Gap { segment, start, expected } => {
                    let msg = Msg::new("cam-gap").arg("segment", segment).num("start", start).num("expected", expected);
                    return e.refuse("/program", msg);
                }
                ProgramError::Jump { segment, from, expected } => {
                    let msg = Msg::new("cam-jump").arg("segment", segment).num("from", from).num("expected", expected);
                    return e.refuse("/program", msg);
                }
            };
            e.refuse(&at, Msg::new(id))
        }
    }
}
