//! The states a run reports: n instants evenly spaced over [0, t_end], each
//! from the dense output of the first step that reaches it.
//!
//! Where t_end is known at the start (a duration) each step gives its
//! instants as it is accepted and is dropped: a run holds one step, however
//! long. Where the run ends at an angle, t_end is found only at the end, so
//! the steps are kept until then — up to [`KEPT_BYTES`]; a run with more
//! steps than that keeps none, and is made again to the end time found
//! ([`super::run`]), the second time as a duration.

use crate::engine::numeric::ode::Step;

/// The most memory of kept steps a run ending at an angle holds (bytes):
/// with DOPRI5's five vectors of coefficients, ~950 steps of A02's
/// (N = 40) 487 states, ~19 000 of a four-bar's 19.
pub const KEPT_BYTES: usize = 32 << 20;

pub(super) struct Sampler {
    n: usize,
    /// The end time where known at the start.
    t_end: Option<f64>,
    states: Vec<(f64, Vec<f64>)>,
    kept: Vec<Step>,
    kept_bytes: usize,
    /// The bytes of kept steps allowed; beyond them none are kept.
    limit: usize,
    overflowed: bool,
}

impl Sampler {
    /// n instants (at least 2), over [0, t_end] where the end time is known.
    pub fn new(n: usize, t_end: Option<f64>, limit: usize) -> Self {
        let n = n.max(2);
        Self { n, t_end, states: Vec::with_capacity(n), kept: Vec::new(), kept_bytes: 0, limit, overflowed: false }
    }

    /// An accepted step; `last` where the run ends in it. The step back
    /// where it was not kept (its storage can serve the next).
    pub fn accept(&mut self, step: Step, last: bool) -> Option<Step> {
        if let Some(t_end) = self.t_end {
            self.emit(&step, t_end, last);
            return Some(step);
        }
        if !self.overflowed {
            self.kept_bytes += bytes(&step);
            if self.kept_bytes > self.limit {
                self.overflowed = true;
                self.kept = Vec::new();
            } else {
                self.kept.push(step);
                return None;
            }
        }
        Some(step)
    }

    /// The states, once the run has ended at `t_end`; empty where the steps
    /// were too many to keep.
    pub fn finish(mut self, t_end: f64) -> Vec<(f64, Vec<f64>)> {
        if self.t_end.is_none() && !self.overflowed {
            let kept = std::mem::take(&mut self.kept);
            let last = kept.len().saturating_sub(1);
            kept.iter().enumerate().for_each(|(k, step)| self.emit(step, t_end, k == last));
        }
        self.states
    }

    /// The instants not given yet that `step` reaches (all of them where the
    /// run ends in it), each from its dense output. A run stopped before
    /// its end time (a contact opened) ends its states with the stop's
    /// own, and gives none after it.
    fn emit(&mut self, step: &Step, t_end: f64, last: bool) {
        while self.states.len() < self.n {
            let t = t_end * self.states.len() as f64 / (self.n - 1) as f64;
            if t > step.t1 && !last {
                break;
            }
            if t > step.t1 && step.t1 < t_end {
                if self.states.last().is_none_or(|s| s.0 < step.t1) {
                    self.states.push((step.t1, step.y1.clone()));
                }
                break;
            }
            self.states.push((t, step.at(t.min(step.t1))));
        }
    }
}

/// About what a step holds in memory: its vectors and their headers.
fn bytes(step: &Step) -> usize {
    let vectors = 4 + step.stages();
    std::mem::size_of::<Step>() + vectors * (24 + 8 * step.y0.len())
}

#[cfg(test)]
mod tests {
    use super::super::{End, Integrator, Model, Settings, run};
    use crate::engine::Deadline;

    /// φ̈ = φ̇ from φ = 0, φ̇ = 1: φ = eᵗ − 1, and W = ∫φ̈ φ̇ dt.
    struct Accelerating;

    impl Model for Accelerating {
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            (dy[0], dy[1], dy[2]) = (y[1], y[1], y[1] * y[1]);
        }
        fn angle(&self, y: &[f64]) -> f64 {
            y[0]
        }
        fn speed(&self, y: &[f64]) -> f64 {
            y[1]
        }
    }

    fn settings(end: End, kept_bytes: usize) -> Settings {
        let (integrator, deadline) = (Integrator::Dopri5, Deadline::none());
        Settings {
            end,
            samples: 11,
            kept_bytes,
            rtol: 1e-10,
            atol: vec![1e-10; 3],
            integrator,
            automatic: false,
            deadline,
        }
    }

    /// A run to an angle that may keep none of its steps is made again to
    /// the end time it found and reports the same states, bit for bit, as one
    /// that kept them all (the second run a duration: states gathered as the
    /// steps come); both on φ = eᵗ − 1, which reaches 200 rad at t = ln 201
    /// (closed form; the tolerance 1e-10 → 1e-8 relative).
    #[test]
    fn a_run_too_long_to_keep_is_made_again_to_the_same_states() {
        let end = End::UntilAngle { angle: 200.0, max_time: 100.0 };
        let kept = run(&Accelerating, vec![0.0, 1.0, 0.0], &settings(end, super::KEPT_BYTES)).unwrap();
        let again = run(&Accelerating, vec![0.0, 1.0, 0.0], &settings(end, 0)).unwrap();
        assert!(!kept.repeated && again.repeated);
        assert_eq!(again.attempted, 2 * kept.attempted, "the second run counts both");
        assert_eq!((kept.t_end, &kept.events), (again.t_end, &again.events));
        assert_eq!(kept.states, again.states);
        let t_end = 201f64.ln();
        assert!((kept.t_end - t_end).abs() < 1e-8 * t_end, "{} vs {t_end}", kept.t_end);
        assert_eq!(kept.states.len(), 11);
        for (k, (t, y)) in kept.states.iter().enumerate() {
            assert_eq!(*t, kept.t_end * k as f64 / 10.0);
            let phi = t.exp() - 1.0;
            assert!((y[0] - phi).abs() < 1e-8 * phi.max(1.0), "φ({t}) = {} vs {phi}", y[0]);
        }
    }
}
