//! A canonical program shared by the cam's tests and the benchmark (the
//! engine's samples live in [`crate::engine::samples`], which the cam's
//! own tests cannot use without a cycle of modules).

use super::design::{Cam, Follower, Guide};
use super::{Law, Program, Segment};

/// The cam program of the peer `mechanism`'s sizing example
/// (bench/peers/cam_mechanism.py): dwell 60°, a cycloidal rise of 20 mm
/// over 90°, dwell 60°, a cycloidal fall over 90°, dwell 60°.
pub fn rise_dwell_fall() -> Program {
    let seg = |law, start: f64, span: f64, from, to| Segment {
        law,
        start: start.to_radians(),
        span: span.to_radians(),
        from,
        to,
    };
    let segments = vec![
        seg(Law::Dwell, 0.0, 60.0, 0.0, 0.0),
        seg(Law::Cycloidal, 60.0, 90.0, 0.0, 0.02),
        seg(Law::Dwell, 150.0, 60.0, 0.02, 0.02),
        seg(Law::Cycloidal, 210.0, 90.0, 0.02, 0.0),
        seg(Law::Dwell, 300.0, 60.0, 0.0, 0.0),
    ];
    Program::new(segments).expect("the segments make a turn")
}

/// The peer's follower: a 10 mm roller on an axis through the cam centre,
/// the cam turning counter-clockwise (its base radius 0: to be sized).
pub fn roller() -> Cam {
    Cam { follower: Follower::Roller(0.01), guide: Guide::Translating { offset: 0.0 }, base: 0.0, clockwise: false }
}
