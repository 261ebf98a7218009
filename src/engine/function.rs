//! Functions of the cycle angle φ: constant, expression, piecewise segments
//! (zero outside them) and periodic tables (linear, step or periodic cubic
//! spline interpolation).
//!
//! Every function is smooth between its *breakpoints* (segment bounds, table
//! angles); at a breakpoint it may jump, so values there are asked for from
//! one [`Side`]. Tables are integrated exactly (each interpolant is a
//! polynomial of degree ≤ 3 between nodes, so Simpson's rule is exact);
//! expressions by adaptive Gauss–Kronrod quadrature.

use super::expr::{Expr, Memo};
use super::numeric::quadrature::{Integral, integrate};
use std::sync::Arc;

/// Which one-sided limit to take at a breakpoint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    Left,
    Right,
}

/// What evaluations of functions at one set of points reuse
/// ([`Function::add_frozen_many`]): a buffer of values, and the functions
/// of φ alone already computed there.
#[derive(Clone, Debug, Default)]
pub struct Batch {
    values: Vec<f64>,
    memo: Memo,
}

/// Interpolation between the rows of a table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    Linear,
    /// The value of a row holds until the next row.
    Step,
    /// Periodic cubic spline (C² across the period).
    Spline,
}

/// A piece of a piecewise function: `expr` on [from, to].
#[derive(Clone, Debug)]
pub struct Segment {
    pub from: f64,
    pub to: f64,
    pub expr: Expr,
}

/// A periodic table; angles strictly increasing within one period.
#[derive(Clone, Debug)]
pub struct Table {
    angle: Vec<f64>,
    value: Vec<f64>,
    interpolation: Interpolation,
    period: f64,
    /// Spline second derivatives at the nodes (empty unless Spline).
    curvature: Vec<f64>,
    /// 0: the interpolant; 1: its derivative.
    order: u8,
    /// ∫ from the first node to each node over one period (n + 1 values,
    /// the last the period's), made at the first integral: an integral is
    /// then two look-ups, however many rows.
    cumulative: std::sync::OnceLock<Vec<f64>>,
}

/// A function of φ computed by other means than a formula or a table (e.g.
/// by assembling a mechanism at φ): only its values, slope and breakpoints
/// are seen here, so this module knows nothing of what computes them.
pub trait Curve: Send + Sync + std::fmt::Debug {
    /// Value at φ (NaN where it cannot be computed).
    fn eval(&self, phi: f64) -> f64;
    /// dF/dφ, when it is available.
    fn derivative(&self) -> Option<Arc<dyn Curve>>;
    /// Angles where the function or its slope may jump.
    fn breakpoints(&self) -> Vec<f64>;
}

/// A function of the cycle angle, in SI units.
#[derive(Clone, Debug)]
pub enum Function {
    Constant(f64),
    Expr(Expr),
    Segments(Vec<Segment>),
    Table(Table),
    /// A function computed elsewhere, seen only through its values (a
    /// mechanism's reduced inertia or torque, solved at each φ).
    Curve(Arc<dyn Curve>),
    /// The sum of several functions.
    Sum(Vec<Function>),
}

impl Table {
    /// A table over `period`; `angle` strictly increasing in [0, period),
    /// `value` of the same length (≥ 3 rows for a spline).
    pub fn new(angle: Vec<f64>, value: Vec<f64>, interpolation: Interpolation, period: f64) -> Self {
        let curvature = match interpolation {
            Interpolation::Spline => periodic_spline_curvature(&angle, &value, period),
            _ => Vec::new(),
        };
        Self { angle, value, interpolation, period, curvature, order: 0, cumulative: Default::default() }
    }

    fn node(&self, i: usize) -> (f64, f64) {
        let n = self.angle.len();
        (self.angle[i % n] + (i / n) as f64 * self.period, self.value[i % n])
    }

    /// Interval index k with φ in [x_k, x_{k+1}] (one-sided at nodes) and φ
    /// shifted into [x_0, x_0 + period].
    fn locate(&self, phi: f64, side: Side) -> (usize, f64) {
        let x0 = self.angle[0];
        let mut u = x0 + (phi - x0).rem_euclid(self.period);
        if side == Side::Left && u == x0 {
            u += self.period;
        }
        let k = match side {
            Side::Right => self.angle.partition_point(|&a| a <= u),
            Side::Left => self.angle.partition_point(|&a| a < u),
        };
        (k.max(1) - 1, u)
    }

    fn eval(&self, phi: f64, side: Side) -> f64 {
        let (k, u) = self.locate(phi, side);
        self.eval_in(k, u)
    }

    /// The interpolant of interval k at the (shifted) angle u.
    fn eval_in(&self, k: usize, u: f64) -> f64 {
        let ((xa, va), (xb, vb)) = (self.node(k), self.node(k + 1));
        let h = xb - xa;
        let t = u - xa;
        match (self.interpolation, self.order) {
            (Interpolation::Step, 0) => va,
            (Interpolation::Step, _) => 0.0,
            (Interpolation::Linear, 0) => va + (vb - va) * t / h,
            (Interpolation::Linear, _) => (vb - va) / h,
            (Interpolation::Spline, order) => {
                let n = self.angle.len();
                let (ma, mb) = (self.curvature[k % n], self.curvature[(k + 1) % n]);
                let slope = (vb - va) / h - h * (2.0 * ma + mb) / 6.0;
                if order == 0 {
                    va + t * (slope + t * (ma / 2.0 + t * (mb - ma) / (6.0 * h)))
                } else {
                    slope + t * (ma + t * (mb - ma) / (2.0 * h))
                }
            }
        }
    }

    /// The polynomial of the interval holding `anchor`, evaluated at φ (may extrapolate).
    fn eval_frozen(&self, phi: f64, anchor: f64) -> f64 {
        let (k, u) = self.locate(anchor, Side::Right);
        self.eval_in(k, u + (phi - anchor))
    }

    fn breakpoints(&self) -> impl Iterator<Item = f64> + '_ {
        self.angle.iter().copied()
    }

    /// Exact integral over [a, b] (Simpson on every polynomial piece, cubic
    /// at most): the primitive at b less the primitive at a.
    fn integral(&self, a: f64, b: f64) -> f64 {
        let ((pa, ka, ua), (pb, kb, ub)) = (self.placed(a), self.placed(b));
        let c = self.cumulative();
        let whole = (pb - pa) * c[self.angle.len()];
        whole + (c[kb] + self.piece(kb, ub)) - (c[ka] + self.piece(ka, ua))
    }

    /// φ as whole periods from the first node, its interval and its angle shifted into that period.
    fn placed(&self, phi: f64) -> (f64, usize, f64) {
        let (k, u) = self.locate(phi, Side::Right);
        (((phi - u) / self.period).round(), k, u)
    }

    /// ∫ of interval k's polynomial from its first node to u.
    fn piece(&self, k: usize, u: f64) -> f64 {
        let x = self.node(k).0;
        let m = 0.5 * (x + u);
        (u - x) / 6.0 * (self.eval_in(k, x) + 4.0 * self.eval_in(k, m) + self.eval_in(k, u))
    }

    fn cumulative(&self) -> &[f64] {
        self.cumulative.get_or_init(|| {
            let n = self.angle.len();
            let mut c = Vec::with_capacity(n + 1);
            c.push(0.0);
            for k in 0..n {
                c.push(c[k] + self.piece(k, self.node(k + 1).0));
            }
            c
        })
    }
}

/// Second derivatives M_i of the periodic cubic spline through (x_i, v_i):
/// h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6(δ_i − δ_{i−1}),
/// δ_i = (v_{i+1} − v_i)/h_i, indices modulo n; solved as a cyclic
/// tridiagonal system by Sherman–Morrison.
fn periodic_spline_curvature(x: &[f64], v: &[f64], period: f64) -> Vec<f64> {
    let n = x.len();
    let h: Vec<f64> = (0..n).map(|i| if i + 1 < n { x[i + 1] - x[i] } else { x[0] + period - x[i] }).collect();
    let delta: Vec<f64> = (0..n).map(|i| (v[(i + 1) % n] - v[i]) / h[i]).collect();
    let prev = |i: usize| (i + n - 1) % n;
    let lower: Vec<f64> = (0..n).map(|i| h[prev(i)]).collect();
    let diag: Vec<f64> = (0..n).map(|i| 2.0 * (h[prev(i)] + h[i])).collect();
    let upper: Vec<f64> = h.clone();
    let rhs: Vec<f64> = (0..n).map(|i| 6.0 * (delta[i] - delta[prev(i)])).collect();
    crate::engine::numeric::tridiagonal::cyclic(&lower, &diag, &upper, &rhs)
}

impl Function {
    /// Value at φ; at a breakpoint, the limit from `side`.
    pub fn eval(&self, phi: f64, side: Side) -> f64 {
        self.eval_at(phi, side, [0.0, 0.0])
    }

    /// Value at φ with the expression variables `omega` and `t` (variables 1
    /// and 2, where a job integrates in time) set to `state`.
    pub fn eval_at(&self, phi: f64, side: Side, state: [f64; 2]) -> f64 {
        let vars = [phi, state[0], state[1]];
        match self {
            Self::Constant(c) => *c,
            Self::Expr(e) => e.eval(&vars),
            Self::Segments(segs) => segs
                .iter()
                .find(|s| match side {
                    Side::Right => s.from <= phi && phi < s.to,
                    Side::Left => s.from < phi && phi <= s.to,
                })
                .map_or(0.0, |s| s.expr.eval(&vars)),
            Self::Table(t) => t.eval(phi, side),
            Self::Curve(c) => c.eval(phi),
            Self::Sum(fs) => fs.iter().map(|f| f.eval_at(phi, side, state)).sum(),
        }
    }

    /// The formula that holds at `anchor` (inside a smooth piece), evaluated
    /// at φ, extrapolating past the piece's ends. Lets an integrator step
    /// across a breakpoint and locate it without seeing the jump.
    pub fn eval_frozen(&self, phi: f64, anchor: f64) -> f64 {
        match self {
            Self::Constant(c) => *c,
            Self::Expr(e) => e.eval(&[phi]),
            Self::Segments(segs) => {
                segs.iter().find(|s| s.from <= anchor && anchor < s.to).map_or(0.0, |s| s.expr.eval(&[phi]))
            }
            Self::Table(t) => t.eval_frozen(phi, anchor),
            Self::Curve(c) => c.eval(phi),
            Self::Sum(fs) => fs.iter().map(|f| f.eval_frozen(phi, anchor)).sum(),
        }
    }

    /// [`Self::eval_frozen`] at every x of `xs`, added to `out` times `k`
    /// (expressions evaluated a block of points at a time, through `batch`).
    pub fn add_frozen_many(&self, k: f64, xs: &[f64], anchor: f64, out: &mut [f64], batch: &mut Batch) {
        let mut expr = |e: &Expr| {
            batch.values.resize(xs.len(), 0.0);
            e.eval_many(xs, &mut batch.values, &mut batch.memo);
            out.iter_mut().zip(&batch.values).for_each(|(o, v)| *o += k * v);
        };
        match self {
            Self::Expr(e) => expr(e),
            Self::Segments(segs) => {
                if let Some(s) = segs.iter().find(|s| s.from <= anchor && anchor < s.to) {
                    expr(&s.expr);
                }
            }
            Self::Sum(fs) => fs.iter().for_each(|f| f.add_frozen_many(k, xs, anchor, out, batch)),
            _ => out.iter_mut().zip(xs).for_each(|(o, x)| *o += k * self.eval_frozen(*x, anchor)),
        }
    }

    /// Whether the function reads `omega` or `t` (then it is not a function of φ alone).
    pub fn uses_state(&self) -> bool {
        let expr = |e: &Expr| e.uses(1) || e.uses(2);
        match self {
            Self::Expr(e) => expr(e),
            Self::Segments(segs) => segs.iter().any(|s| expr(&s.expr)),
            Self::Sum(fs) => fs.iter().any(Function::uses_state),
            _ => false,
        }
    }

    /// The constant value, when the function is one.
    pub fn constant(&self) -> Option<f64> {
        match self {
            Self::Constant(c) => Some(*c),
            Self::Expr(e) => e.constant(),
            Self::Sum(fs) => fs.iter().map(Function::constant).sum(),
            _ => None,
        }
    }

    /// dF/dφ as a function (jumps of step tables are not included).
    pub fn derivative(&self) -> Function {
        match self {
            Self::Constant(_) => Self::Constant(0.0),
            Self::Expr(e) => Self::Expr(e.derivative(0)),
            Self::Segments(segs) => Self::Segments(
                segs.iter().map(|s| Segment { from: s.from, to: s.to, expr: s.expr.derivative(0) }).collect(),
            ),
            Self::Table(t) => Self::Table(Table { order: t.order + 1, cumulative: Default::default(), ..t.clone() }),
            // Only I* is differentiated (for the equation of motion); others have no use for it.
            Self::Curve(c) => c.derivative().map_or(Self::Constant(f64::NAN), Self::Curve),
            Self::Sum(fs) => Self::Sum(fs.iter().map(Function::derivative).collect()),
        }
    }

    /// Whether its derivatives up to `order` stay within `max` nodes each
    /// (an expression's; other functions are differentiated without trees):
    /// Err(the first order that would not).
    pub fn derivatives_fit(&self, order: usize, max: usize) -> Result<(), usize> {
        match self {
            Self::Expr(e) => e.derivatives_fit(0, order, max),
            Self::Segments(segs) => segs.iter().try_for_each(|s| s.expr.derivatives_fit(0, order, max)),
            Self::Sum(fs) => fs.iter().try_for_each(|f| f.derivatives_fit(order, max)),
            Self::Constant(_) | Self::Table(_) | Self::Curve(_) => Ok(()),
        }
    }

    /// Angles in (0, period) where the function or its slope may jump.
    pub fn breakpoints(&self, period: f64) -> Vec<f64> {
        let mut b: Vec<f64> = match self {
            Self::Constant(_) | Self::Expr(_) => vec![],
            Self::Segments(segs) => segs.iter().flat_map(|s| [s.from, s.to]).collect(),
            Self::Table(t) => t.breakpoints().collect(),
            Self::Curve(c) => c.breakpoints(),
            Self::Sum(fs) => fs.iter().flat_map(|f| f.breakpoints(period)).collect(),
        };
        b.retain(|x| *x > 0.0 && *x < period);
        b
    }

    /// ∫ₐᵇ F dφ with a ≤ b: exact for constants and tables, adaptive
    /// quadrature (tolerances `abs_tol`, `rel_tol`) for expressions.
    pub fn integral(&self, a: f64, b: f64, abs_tol: f64, rel_tol: f64) -> Integral {
        match self {
            Self::Constant(c) => Integral { value: c * (b - a), ..Integral::default() },
            Self::Table(t) => Integral { value: t.integral(a, b), ..Integral::default() },
            Self::Curve(c) => integrate(|x| c.eval(x), a, b, abs_tol, rel_tol, MAX_EVALUATIONS),
            Self::Sum(fs) => {
                let mut total = Integral::default();
                for f in fs {
                    total += f.integral(a, b, abs_tol / fs.len() as f64, rel_tol);
                }
                total
            }
            Self::Expr(e) => integrate_expr(e, a, b, abs_tol, rel_tol),
            Self::Segments(segs) => {
                let mut total = Integral::default();
                for s in segs {
                    let (lo, hi) = (a.max(s.from), b.min(s.to));
                    if lo < hi {
                        let share = abs_tol * (hi - lo) / (b - a);
                        total += integrate_expr(&s.expr, lo, hi, share, rel_tol);
                    }
                }
                total
            }
        }
    }
}

/// Evaluations allowed for one adaptive integral.
const MAX_EVALUATIONS: usize = 200_000;

/// Adaptive quadrature of an expression of φ (exact when it is constant).
fn integrate_expr(e: &Expr, a: f64, b: f64, abs_tol: f64, rel_tol: f64) -> Integral {
    match e.constant() {
        Some(c) => Integral { value: c * (b - a), ..Integral::default() },
        None => integrate(|x| e.eval(&[x]), a, b, abs_tol, rel_tol, MAX_EVALUATIONS),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn table(angle: &[f64], value: &[f64], interp: Interpolation) -> Function {
        Function::Table(Table::new(angle.to_vec(), value.to_vec(), interp, 2.0 * PI))
    }

    #[test]
    fn step_tables_hold_values_and_jump_at_rows() {
        let f = table(&[0.0, 1.0, 3.0], &[1.0, -2.0, 5.0], Interpolation::Step);
        assert_eq!(f.eval(0.5, Side::Right), 1.0);
        assert_eq!(f.eval(1.0, Side::Right), -2.0);
        assert_eq!(f.eval(1.0, Side::Left), 1.0);
        assert_eq!(f.eval(0.0, Side::Left), 5.0);
        assert_eq!(f.eval(2.0 * PI + 0.5, Side::Right), 1.0);
        // ∫₀^{2π} = 1·1 − 2·2 + 5·(2π − 3), exactly.
        let i = f.integral(0.0, 2.0 * PI, 0.0, 0.0).value;
        assert!((i - (1.0 - 4.0 + 5.0 * (2.0 * PI - 3.0))).abs() < 1e-13);
    }

    #[test]
    fn linear_tables_wrap_around_the_period() {
        let f = table(&[1.0, 2.0], &[0.0, 1.0], Interpolation::Linear);
        // From φ = 2 (value 1) back to φ = 1 + 2π (value 0): slope −1/(2π − 1).
        let x = 0.5;
        let expected = 1.0 - (x + 2.0 * PI - 2.0) / (2.0 * PI - 1.0);
        assert!((f.eval(x, Side::Right) - expected).abs() < 1e-15);
        // Integral over a period of a periodic linear table = trapezoids = (0+1)/2·1 + (1+0)/2·(2π−1).
        let i = f.integral(0.3, 0.3 + 2.0 * PI, 0.0, 0.0).value;
        assert!((i - PI).abs() < 1e-13, "{i}");
    }

    /// A periodic spline through samples of sin φ reproduces sin to the
    /// interpolation error O(h⁴) and its integral over the period is 0.
    #[test]
    fn periodic_spline_reproduces_a_sine() {
        let n = 64;
        let angle: Vec<f64> = (0..n).map(|i| 2.0 * PI * i as f64 / n as f64).collect();
        let value: Vec<f64> = angle.iter().map(|a| a.sin()).collect();
        let f = table(&angle, &value, Interpolation::Spline);
        for x in [0.05, 1.0, 3.3, 6.2] {
            assert!((f.eval(x, Side::Right) - x.sin()).abs() < 1e-6);
            assert!((f.derivative().eval(x, Side::Right) - x.cos()).abs() < 1e-4);
        }
        assert!(f.integral(0.0, 2.0 * PI, 0.0, 0.0).value.abs() < 1e-14);
        let half = f.integral(0.0, PI, 0.0, 0.0).value;
        assert!((half - 2.0).abs() < 1e-6, "{half}");
    }

    #[test]
    fn segments_are_zero_outside_and_one_sided_at_bounds() {
        let seg = |a: f64, b: f64, s: &str| Segment { from: a, to: b, expr: Expr::compile(s, &["phi"]).unwrap() };
        let f = Function::Segments(vec![seg(0.0, PI, "-500*sin(phi)"), seg(PI, 1.5 * PI, "7")]);
        assert_eq!(f.eval(PI, Side::Left), -500.0 * PI.sin());
        assert_eq!(f.eval(PI, Side::Right), 7.0);
        assert_eq!(f.eval(1.6 * PI, Side::Right), 0.0);
        assert_eq!(f.breakpoints(2.0 * PI), vec![PI, PI, 1.5 * PI]);
        let i = f.integral(0.0, 2.0 * PI, 1e-12, 1e-12).value;
        assert!((i - (-1000.0 + 3.5 * PI)).abs() < 1e-9, "{i}");
    }
}
