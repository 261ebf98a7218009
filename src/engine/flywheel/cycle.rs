//! The machine over one cycle: total reduced torque M*(φ), reduced inertia
//! I*(φ) and its slope, split into smooth pieces at every breakpoint, with
//! the work W(φ) = ∫₀^φ M* dφ integrated piece by piece.

use crate::engine::function::{Batch, Function, Side};
use crate::engine::numeric::quadrature::Integral;
use crate::engine::{Deadline, EngineError, Phase, Progress};

/// Samples per period used to bracket sign changes (at least 8 per piece).
const SAMPLES_PER_PERIOD: usize = 1024;

/// A reduced torque term k·f(φ), with the label of `f` for error messages.
pub(crate) struct Term<'a> {
    pub f: &'a Function,
    pub ratio: f64,
    pub label: &'a str,
}

pub(crate) struct Cycle<'a> {
    pub terms: Vec<Term<'a>>,
    /// Constant reduced torque added to the terms (the balance torque times its ratio).
    pub balance: f64,
    pub inertia: &'a Function,
    pub inertia_label: &'a str,
    /// dI*/dφ, absent when I* is constant.
    pub inertia_slope: Option<Function>,
    pub period: f64,
    /// 0, the breakpoints of every function, and the period, sorted.
    pub pieces: Vec<f64>,
    pub rel_tol: f64,
    /// Absolute quadrature tolerance per radian (set once the scale is known).
    pub abs_tol_per_rad: f64,
    /// The job's budget: past it the sampling stops and every work is NaN,
    /// which the solution reports as the spent budget.
    pub deadline: Deadline,
}

/// M* (and the slope of I*) sampled on a grid inside every piece.
pub(crate) struct Samples {
    /// Per piece: angles (ends included) and M* there (one-sided at the ends).
    pub pieces: Vec<(Vec<f64>, Vec<f64>)>,
    /// Per piece: I*'(φ) at the same angles (empty when I* is constant).
    pub slopes: Vec<Vec<f64>>,
    /// ∫|M*| dφ estimated from the samples: the scale of the works.
    pub abs_work: f64,
    pub max_abs_torque: f64,
}

impl<'a> Cycle<'a> {
    pub fn new(
        terms: Vec<Term<'a>>,
        (inertia, inertia_label): (&'a Function, &'a str),
        period: f64,
        rel_tol: f64,
        deadline: Deadline,
    ) -> Self {
        let mut pieces = vec![0.0, period];
        for t in &terms {
            pieces.extend(t.f.breakpoints(period));
        }
        pieces.extend(inertia.breakpoints(period));
        pieces.sort_by(f64::total_cmp);
        pieces.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * period);
        let inertia_slope = inertia.constant().is_none().then(|| inertia.derivative());
        Self {
            terms,
            balance: 0.0,
            inertia,
            inertia_label,
            inertia_slope,
            period,
            pieces,
            rel_tol,
            abs_tol_per_rad: 0.0,
            deadline,
        }
    }

    /// M*(φ), one-sided at breakpoints.
    pub fn torque(&self, phi: f64, side: Side) -> f64 {
        self.balance + self.terms.iter().map(|t| t.ratio * t.f.eval(phi, side)).sum::<f64>()
    }

    /// M* as the formula of the piece holding `anchor`, evaluated at φ.
    pub fn torque_frozen(&self, phi: f64, anchor: f64) -> f64 {
        self.balance + self.terms.iter().map(|t| t.ratio * t.f.eval_frozen(phi, anchor)).sum::<f64>()
    }

    pub fn inertia_at(&self, phi: f64, side: Side) -> f64 {
        self.inertia.eval(phi, side)
    }

    /// Samples M* inside every piece (each piece's own formulas, so one-sided
    /// at its ends); fails on a non-finite value (naming the function) or a
    /// negative reduced inertia.
    pub fn sample(&self) -> Result<Samples, EngineError> {
        let mut pieces = Vec::with_capacity(self.pieces.len());
        let mut slopes = Vec::with_capacity(self.pieces.len());
        let (mut abs_work, mut max_abs_torque) = (0.0, 0.0f64);
        let mut batch = Batch::default();
        for w in self.pieces.windows(2) {
            self.deadline.check(|| Progress::Flywheel(Phase::Sampling))?;
            let (a, b) = (w[0], w[1]);
            let n = ((SAMPLES_PER_PERIOD as f64 * (b - a) / self.period).ceil() as usize).max(8);
            let xs: Vec<f64> = (0..=n).map(|j| a + (b - a) * j as f64 / n as f64).collect();
            let anchor = 0.5 * (a + b);
            let frozen = |f: &Function, batch: &mut Batch| {
                let mut out = vec![0.0; n + 1];
                f.add_frozen_many(1.0, &xs, anchor, &mut out, batch);
                out
            };
            let mut ys = vec![0.0; n + 1];
            for t in &self.terms {
                t.f.add_frozen_many(t.ratio, &xs, anchor, &mut ys, &mut batch);
            }
            ys.iter_mut().for_each(|y| *y += self.balance);
            let side = |j: usize| if j == n { Side::Left } else { Side::Right };
            if let Some(j) = ys.iter().position(|m| !m.is_finite()) {
                return Err(self.not_finite(xs[j], side(j)));
            }
            let inertia = frozen(self.inertia, &mut batch);
            let ss = self.inertia_slope.as_ref().map_or_else(Vec::new, |f| frozen(f, &mut batch));
            let finite = |j: usize| inertia[j].is_finite() && ss.get(j).is_none_or(|s| s.is_finite());
            if let Some(j) = (0..=n).find(|&j| !finite(j)) {
                return Err(EngineError::NotFinite { function: self.inertia_label.into(), phi: xs[j] });
            }
            if let Some(j) = inertia.iter().position(|i| *i < 0.0) {
                let (function, phi, value) = (self.inertia_label.into(), xs[j], inertia[j]);
                return Err(EngineError::NegativeInertia { function, phi, value });
            }
            max_abs_torque = ys.iter().fold(max_abs_torque, |m, y| m.max(y.abs()));
            abs_work += ys.windows(2).map(|p| 0.5 * (p[0].abs() + p[1].abs())).sum::<f64>() * (b - a) / n as f64;
            pieces.push((xs, ys));
            slopes.push(ss);
        }
        Ok(Samples { pieces, slopes, abs_work, max_abs_torque })
    }

    fn not_finite(&self, phi: f64, side: Side) -> EngineError {
        let bad = self.terms.iter().find(|t| !t.f.eval(phi, side).is_finite());
        EngineError::NotFinite { function: bad.map_or("reduced torque", |t| t.label).into(), phi }
    }

    /// ∫ₐᵇ k·f dφ for one function, split at the pieces (those inside
    /// found by bisection: a table of 80 000 rows has as many).
    pub fn integrate(&self, f: &Function, a: f64, b: f64) -> Integral {
        let mut total = Integral::default();
        let mut lo = a;
        let start = self.pieces.partition_point(|&p| p <= a);
        let inside = start..self.pieces.partition_point(|&p| p < b).max(start);
        for &p in self.pieces[inside].iter().chain(std::iter::once(&b)) {
            total += f.integral(lo, p, self.abs_tol_per_rad * (p - lo), self.rel_tol);
            lo = p;
        }
        total
    }

    /// Work of M* over [a, b]; NaN past the budget.
    pub fn work(&self, a: f64, b: f64) -> Integral {
        if self.deadline.expired() {
            return Integral { value: f64::NAN, error: f64::NAN, evaluations: 0 };
        }
        let mut total = Integral { value: self.balance * (b - a), ..Integral::default() };
        for t in &self.terms {
            let i = self.integrate(t.f, a, b);
            total += Integral { value: t.ratio * i.value, error: t.ratio.abs() * i.error, ..i };
        }
        total
    }

    /// W at sorted angles in [0, period] (W(0) = 0), and the summed quadrature error.
    pub fn work_at(&self, points: &[f64]) -> (Vec<f64>, Integral) {
        let mut acc = Integral::default();
        let mut prev = 0.0;
        let values = points
            .iter()
            .map(|&x| {
                acc += self.work(prev, x);
                prev = x;
                acc.value
            })
            .collect();
        (values, acc)
    }
}
