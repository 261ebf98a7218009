//! Cams: a follower's motion program over a turn of the cam, its segments
//! each a textbook law ([`laws`]).
//!
//! Symbols: θ the cam angle (rad, from 0 to 2π over the program), s(θ) the
//! follower's lift (m, or rad for an oscillating follower), and its
//! derivatives in θ: s′ (velocity per unit cam speed), s″ (acceleration
//! per unit cam speed squared) and s‴ (jerk). At cam speed ω (constant):
//! v = s′ω, a = s″ω², j = s‴ω³.

pub mod design;
pub mod extremes;
pub mod laws;
pub mod least;
pub mod sample;
pub mod sizing;

pub use laws::Law;
use std::f64::consts::TAU;

/// One segment of a program: over [start, start + span) the follower goes
/// from `from` to `to` by `law` (a dwell holds `from`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub law: Law,
    pub start: f64,
    pub span: f64,
    pub from: f64,
    pub to: f64,
}

impl Segment {
    /// [s, s′, s″, s‴, s⁗] at θ within the segment.
    pub fn eval(&self, theta: f64) -> [f64; 5] {
        let y = self.law.eval((theta - self.start) / self.span);
        let h = self.to - self.from;
        let mut out = [0.0; 5];
        for (d, o) in out.iter_mut().enumerate() {
            *o = h * y[d] / self.span.powi(d as i32);
        }
        out[0] += self.from;
        out
    }
}

/// Why segments do not make a program: the segment at fault and what.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProgramError {
    #[error("segment {segment} starts at {start} rad where the one before ends at {expected} rad")]
    Gap { segment: usize, start: f64, expected: f64 },
    #[error("segment {segment} starts at lift {from} where the one before ends at {expected}")]
    Jump { segment: usize, from: f64, expected: f64 },
    #[error("segment {segment} is a dwell but moves from {from} to {to}")]
    MovingDwell { segment: usize, from: f64, to: f64 },
    #[error("segment {segment} has span {span} rad: it must be greater than 0")]
    Empty { segment: usize, span: f64 },
    #[error("the program ends at {end} rad: its segments must cover one turn, 0 to 2π")]
    NotATurn { end: f64 },
    #[error("the program ends at lift {end} where it started at {start}: a cam returns to its start")]
    NotClosed { end: f64, start: f64 },
}

/// A change of the follower's motion between two segments: the derivative
/// that jumps (1 velocity, 2 acceleration, 3 jerk), at θ, and by how much.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Break {
    pub theta: f64,
    pub derivative: usize,
    pub jump: f64,
}

/// A follower's motion over one turn: segments end to end from 0 to 2π,
/// returning to the lift they started from.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    segments: Vec<Segment>,
}

impl Program {
    /// The program of `segments`, or what is wrong with them (angles and
    /// lifts to 1e-9 of a turn and of the largest lift).
    pub fn new(segments: Vec<Segment>) -> Result<Self, ProgramError> {
        let scale = segments.iter().flat_map(|s| [s.from.abs(), s.to.abs()]).fold(1e-300, f64::max);
        let (mut end, mut lift) = (0.0, segments.first().map_or(0.0, |s| s.from));
        for (k, s) in segments.iter().enumerate() {
            if s.span.is_nan() || s.span <= 0.0 {
                return Err(ProgramError::Empty { segment: k, span: s.span });
            }
            if (s.start - end).abs() > 1e-9 * TAU {
                return Err(ProgramError::Gap { segment: k, start: s.start, expected: end });
            }
            if (s.from - lift).abs() > 1e-9 * scale {
                return Err(ProgramError::Jump { segment: k, from: s.from, expected: lift });
            }
            if s.law == Law::Dwell && (s.to - s.from).abs() > 1e-9 * scale {
                return Err(ProgramError::MovingDwell { segment: k, from: s.from, to: s.to });
            }
            (end, lift) = (s.start + s.span, if s.law == Law::Dwell { s.from } else { s.to });
        }
        if (end - TAU).abs() > 1e-9 * TAU {
            return Err(ProgramError::NotATurn { end });
        }
        let start = segments.first().map_or(0.0, |s| s.from);
        if (lift - start).abs() > 1e-9 * scale {
            return Err(ProgramError::NotClosed { end: lift, start });
        }
        Ok(Self { segments })
    }

    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// The segment that holds θ (reduced to one turn).
    pub fn segment_at(&self, theta: f64) -> usize {
        let theta = theta.rem_euclid(TAU);
        self.segments.iter().rposition(|s| s.start <= theta).unwrap_or(0)
    }

    /// [s, s′, s″, s‴, s⁗] at θ (any angle: the program repeats every turn).
    pub fn eval(&self, theta: f64) -> [f64; 5] {
        let theta = theta.rem_euclid(TAU);
        self.segments[self.segment_at(theta)].eval(theta)
    }

    /// The lift [s, s′, s″, s‴] at θ, as a cam reads it ([`design::Lift`]).
    pub fn lift(&self, theta: f64) -> [f64; 4] {
        let [s, s1, s2, s3, _] = self.eval(theta);
        [s, s1, s2, s3]
    }

    /// The angles its segments start at.
    pub fn starts(&self) -> Vec<f64> {
        self.segments.iter().map(|s| s.start).collect()
    }

    /// Where the fundamental law of cam design breaks: at each joint
    /// between segments (the last one's end meeting the first's start),
    /// the lowest derivative among s′, s″, s‴ that jumps by more than 1e-9
    /// of its scale (an infinite next derivative there).
    pub fn breaks(&self) -> Vec<Break> {
        let n = self.segments.len();
        let scales: Vec<f64> = (1..4)
            .map(|d| {
                let peak = (0..3600).map(|k| self.eval(TAU * f64::from(k) / 3600.0)[d].abs());
                peak.fold(0.0, f64::max).max(1e-300)
            })
            .collect();
        (0..n)
            .filter_map(|k| {
                let (before, after) = (&self.segments[(k + n - 1) % n], &self.segments[k]);
                let (left, right) = (before.eval(before.start + before.span), after.eval(after.start));
                (1..4).find(|&d| (right[d] - left[d]).abs() > 1e-9 * scales[d - 1]).map(|d| Break {
                    theta: after.start,
                    derivative: d,
                    jump: right[d] - left[d],
                })
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Dwell 90°, rise h = 25 mm over 90°, dwell 90°, return over 90°.
    fn drdr(law: Law) -> Result<Program, ProgramError> {
        let (q, h) = (PI / 2.0, 0.025);
        let seg = |law, start: f64, from, to| Segment { law, start, span: q, from, to };
        Program::new(vec![
            seg(Law::Dwell, 0.0, 0.0, 0.0),
            seg(law, q, 0.0, h),
            seg(Law::Dwell, 2.0 * q, h, h),
            seg(law, 3.0 * q, h, 0.0),
        ])
    }

    /// The cycloidal rise's s, v, a and jerk in closed form (β = π/2, h =
    /// 25 mm): s = h(x − sin 2πx/2π), s′ = (h/β)(1 − cos 2πx), s″ =
    /// (2πh/β²) sin 2πx, s‴ = (4π²h/β³) cos 2πx, x = (θ − π/2)/β.
    #[test]
    fn a_cycloidal_rise_is_its_closed_form() {
        let p = drdr(Law::Cycloidal).unwrap();
        let (b, h) = (PI / 2.0, 0.025);
        for theta in [1.7, 2.0, 2.5, 3.0] {
            let x = (theta - b) / b;
            let (s2, c2) = (2.0 * PI * x).sin_cos();
            let want = [
                h * (x - s2 / (2.0 * PI)),
                h / b * (1.0 - c2),
                2.0 * PI * h / (b * b) * s2,
                4.0 * PI * PI * h / b.powi(3) * c2,
            ];
            let got = p.eval(theta);
            for d in 0..4 {
                assert!((got[d] - want[d]).abs() < 1e-15 * (1.0 + want[d].abs()), "θ {theta} d{d}: {:?}", got);
            }
        }
    }

    /// A cycloidal program meets the fundamental law except for the jerk
    /// (infinite jerk is not a break of s, v or a: its jerk jumps at the
    /// four joints); a harmonic one breaks the acceleration at all four.
    #[test]
    fn breaks_of_the_fundamental_law_are_found_at_the_joints() {
        let cycloidal = drdr(Law::Cycloidal).unwrap().breaks();
        assert_eq!(cycloidal.iter().map(|b| b.derivative).collect::<Vec<_>>(), [3, 3, 3, 3], "{cycloidal:?}");
        let harmonic = drdr(Law::Harmonic).unwrap().breaks();
        assert_eq!(harmonic.iter().map(|b| b.derivative).collect::<Vec<_>>(), [2, 2, 2, 2], "{harmonic:?}");
        let first = harmonic[1];
        assert!(
            (first.theta - PI / 2.0).abs() < 1e-15
                && (first.jump - PI * PI / 2.0 * 0.025 / (PI / 2.0).powi(2)).abs() < 1e-12
        );
    }

    /// Segments that leave a gap, jump in lift, move in a dwell, or do not
    /// close the turn are refused, naming the segment.
    #[test]
    fn segments_that_are_not_a_program_are_named() {
        let seg = |law, start: f64, span: f64, from, to| Segment { law, start, span, from, to };
        let cases = [
            (vec![seg(Law::Cycloidal, 0.0, PI, 0.0, 1.0), seg(Law::Cycloidal, 3.2, PI, 1.0, 0.0)], "Gap"),
            (vec![seg(Law::Cycloidal, 0.0, PI, 0.0, 1.0), seg(Law::Cycloidal, PI, PI, 0.5, 0.0)], "Jump"),
            (vec![seg(Law::Dwell, 0.0, PI, 0.0, 1.0), seg(Law::Cycloidal, PI, PI, 1.0, 0.0)], "MovingDwell"),
            (vec![seg(Law::Cycloidal, 0.0, PI, 0.0, 1.0), seg(Law::Cycloidal, PI, 0.5, 1.0, 0.0)], "NotATurn"),
            (vec![seg(Law::Cycloidal, 0.0, PI, 0.0, 1.0), seg(Law::Dwell, PI, PI, 1.0, 1.0)], "NotClosed"),
            (vec![seg(Law::Cycloidal, 0.0, 0.0, 0.0, 1.0)], "Empty"),
        ];
        for (segments, what) in cases {
            let e = Program::new(segments).unwrap_err();
            assert!(format!("{e:?}").starts_with(what), "{what}: {e:?}");
        }
    }
}
