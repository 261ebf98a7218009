//! Mathematical expressions of the cycle angle, compiled once and evaluated many times.
//!
//! Grammar and precedence follow the API contract: `^` binds tighter than unary
//! minus and is right-associative (`-x^2` = −(x²), `2^3^2` = 2⁹), then `* /`,
//! then `+ -`. Functions: `sin cos tan asin acos atan atan2 sqrt exp ln log10
//! abs min max sign floor` (and `sen`, the sine in Spanish notation);
//! constants `pi`, `e`; numbers with optional
//! exponent (`1.5e-3`). Variables are named by the caller (`phi`, `t`, `omega`).
//!
//! Limits keep hostile input cheap: at most [`MAX_LENGTH`] characters and
//! [`MAX_DEPTH`] levels of nesting.

mod fault;
mod node;
mod parse;
mod program;

pub use fault::{Arity, FUNCTIONS, Fault, Tok};
use node::Node;
pub use program::Memo;
use program::Program;

/// Longest accepted expression, in characters.
pub const MAX_LENGTH: usize = 2000;
/// Deepest accepted nesting of parentheses and unary operators.
pub const MAX_DEPTH: usize = 64;
/// Most nodes of a derivative the engine builds (some 50 MB of tree).
pub const MAX_DERIVATIVE_NODES: usize = 1_000_000;

/// Why an expression was rejected; `position` is a character index into the source.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{fault} (at character {position})")]
pub struct ExprError {
    pub position: usize,
    pub fault: Fault,
}

/// Whether `name` is taken by the expression language itself: a variable
/// of some job (`phi`, `t`, `omega`), a constant (`pi`, `e`) or a function.
pub fn is_reserved(name: &str) -> bool {
    ["phi", "t", "omega", "pi", "e"].contains(&name)
        || node::Fn1::from_name(name).is_some()
        || node::Fn2::from_name(name).is_some()
}

/// A compiled expression of named variables.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    root: Node,
    /// The same in postfix order, unless too deep for its stack.
    program: Option<Program>,
}

impl Expr {
    /// Parses `source` with the given variable names (their order is the order
    /// of the values passed to [`Expr::eval`]) and folds constant subtrees.
    pub fn compile(source: &str, variables: &[&str]) -> Result<Self, ExprError> {
        Self::compile_within(source, variables, MAX_LENGTH, MAX_DEPTH)
    }

    /// [`Expr::compile`] with other limits on the length (characters) and the
    /// nesting depth; the parser recurses once per level, so `max_depth`
    /// bounds its stack.
    pub fn compile_within(
        source: &str,
        variables: &[&str],
        max_length: usize,
        max_depth: usize,
    ) -> Result<Self, ExprError> {
        Self::compile_with(source, variables, &[], max_length, max_depth)
    }

    /// [`Expr::compile_within`] where `constants` name values too (a
    /// request's `constants`, in SI): each reads as its number.
    pub fn compile_with(
        source: &str,
        variables: &[&str],
        constants: &[(String, f64)],
        max_length: usize,
        max_depth: usize,
    ) -> Result<Self, ExprError> {
        let length = source.chars().count();
        if length > max_length {
            return Err(ExprError { position: max_length, fault: Fault::TooLong { length, max: max_length } });
        }
        Ok(Self::from_root(parse::Parser::parse(source, variables, constants, max_depth)?.fold()))
    }

    fn from_root(root: Node) -> Self {
        Self { program: Program::new(&root), root }
    }

    /// Value for the variable values `vars` (same order as at compilation).
    #[inline]
    pub fn eval(&self, vars: &[f64]) -> f64 {
        match &self.program {
            Some(p) => p.eval(vars),
            None => self.root.eval(vars),
        }
    }

    /// [`Self::eval`] at every x of `xs` for variable 0 (the others 0), into
    /// `out`; `memo` keeps the functions of the variable alone for the next
    /// expression at the same points ([`Memo`]).
    pub fn eval_many(&self, xs: &[f64], out: &mut [f64], memo: &mut Memo) {
        match &self.program {
            Some(p) => p.eval_many(xs, out, memo),
            None => xs.iter().zip(out).for_each(|(x, o)| *o = self.root.eval(&[*x])),
        }
    }

    /// Whether the expression reads variable number `var`.
    pub fn uses(&self, var: usize) -> bool {
        self.root.uses(var)
    }

    /// The value when the expression reads no variable.
    pub fn constant(&self) -> Option<f64> {
        match self.root {
            Node::Const(c) => Some(c),
            _ => None,
        }
    }

    /// Derivative with respect to variable number `var`. A derivative of
    /// more than [`MAX_DERIVATIVE_NODES`] nodes is never built (a product of
    /// many factors grows like its factors to the power of the order): it is
    /// NaN instead, which the service refuses beforehand with the field's
    /// words ([`Expr::derivatives_fit`]).
    pub fn derivative(&self, var: usize) -> Self {
        if self.derivative_size(var) > MAX_DERIVATIVE_NODES {
            return Self::from_root(Node::Const(f64::NAN));
        }
        Self::from_root(self.root.derivative(var).fold())
    }

    /// An upper bound on the nodes of the derivative with respect to `var`.
    pub fn derivative_size(&self, var: usize) -> usize {
        self.root.sizes(var).1
    }

    /// Whether the derivatives up to `order` with respect to `var` stay
    /// within `max` nodes each: Err(the first order that would not).
    pub fn derivatives_fit(&self, var: usize, order: usize, max: usize) -> Result<(), usize> {
        let mut e = self.clone();
        for k in 1..=order {
            if e.derivative_size(var) > max.min(MAX_DERIVATIVE_NODES) {
                return Err(k);
            }
            if k < order {
                e = e.derivative(var);
            }
        }
        Ok(())
    }

    /// `k · self`.
    pub fn scaled(self, k: f64) -> Self {
        if k == 1.0 {
            return self;
        }
        Self::from_root(Node::Mul(Box::new(Node::Const(k)), Box::new(self.root)).fold())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A constant reads as its value, folded: `F*sin(phi)` with F = 1200 is
    /// 1200·sin φ (closed form at φ = π/6: 600); a variable of the same name wins.
    #[test]
    fn constants_read_as_their_values() {
        let constants = [("F".to_string(), 1200.0), ("phi0".to_string(), 0.5)];
        let e = Expr::compile_with("F*sin(phi) + 0*phi0", &["phi"], &constants, 100, 10).unwrap();
        assert!((e.eval(&[std::f64::consts::PI / 6.0]) - 600.0).abs() < 1e-12);
        assert_eq!(Expr::compile_with("F/2", &[], &constants, 100, 10).unwrap().constant(), Some(600.0));
        let unknown = Expr::compile_with("G", &["phi"], &constants, 100, 10).unwrap_err();
        assert!(unknown.fault.to_string().contains("constants: F, phi0, pi, e"), "{}", unknown.fault);
        assert!(is_reserved("sin") && is_reserved("omega") && !is_reserved("F"));
    }

    fn value(src: &str, x: f64) -> f64 {
        Expr::compile(src, &["x"]).unwrap().eval(&[x])
    }

    #[test]
    fn unary_minus_binds_looser_than_power() {
        assert_eq!(value("-x^2", 3.0), -9.0);
        assert_eq!(value("-2^2", 0.0), -4.0);
        assert_eq!(value("2^-1", 0.0), 0.5);
        assert_eq!(value("-x^-2", 2.0), -0.25);
    }

    #[test]
    fn power_is_right_associative() {
        assert_eq!(value("2^3^2", 0.0), 512.0);
    }

    #[test]
    fn products_bind_tighter_than_sums_and_associate_left() {
        assert_eq!(value("1 - 2 - 3", 0.0), -4.0);
        assert_eq!(value("8 / 4 / 2", 0.0), 1.0);
        assert_eq!(value("1 + 2 * 3", 0.0), 7.0);
        assert_eq!(value("2 * -x", 3.0), -6.0);
        assert_eq!(value("x - -x", 3.0), 6.0);
    }

    /// `sen` is the sine, bit for bit, and reserved as `sin` is.
    #[test]
    fn the_spanish_sine_is_the_sine() {
        for x in [0.3, 2.0, -7.5] {
            assert_eq!(value("3*sen(x)^2", x).to_bits(), value("3*sin(x)^2", x).to_bits());
        }
        let d = Expr::compile("sen(x)", &["x"]).unwrap().derivative(0);
        assert_eq!(d.eval(&[0.4]), 0.4f64.cos(), "d/dx sen x = cos x");
        assert!(is_reserved("sen"));
    }

    #[test]
    fn numbers_constants_and_functions() {
        assert_eq!(value("1.5e-3 * 2E3", 0.0), 3.0);
        assert_eq!(value(".5", 0.0), 0.5);
        assert_eq!(value("pi", 0.0), std::f64::consts::PI);
        assert_eq!(value("e", 0.0), std::f64::consts::E);
        assert_eq!(value("atan2(1, -1)", 0.0), (1.0f64).atan2(-1.0));
        assert_eq!(value("min(3, x, 1)", 2.0), 1.0);
        assert_eq!(value("max(3, x)", 4.0), 4.0);
        assert_eq!(value("sign(x) + floor(x)", -1.5), -3.0);
        assert_eq!(value("log10(1000) + ln(e) + sqrt(4) + abs(-1) + exp(0)", 0.0), 8.0);
        assert!((value("sin(x)^2 + cos(x)^2", 0.7) - 1.0).abs() < 1e-15);
        assert!((value("tan(x) - sin(x)/cos(x)", 0.3)).abs() < 1e-15);
        assert!((value("asin(x) + acos(x)", 0.3) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert!((value("atan(x)", 1.0) - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    }

    #[test]
    fn negative_base_with_integer_power_is_real() {
        assert_eq!(value("x^3", -2.0), -8.0);
    }

    #[test]
    fn constant_subtrees_are_folded() {
        let e = Expr::compile("7*pi/4", &[]).unwrap();
        assert_eq!(e.constant(), Some(7.0 * std::f64::consts::PI / 4.0));
        assert_eq!(Expr::compile("x*1 + 0", &["x"]).unwrap(), Expr::compile("x", &["x"]).unwrap());
    }

    #[test]
    fn errors_say_where_and_what() {
        let err = |s: &str| Expr::compile(s, &["phi"]).unwrap_err();
        assert!(err("2*").fault.to_string().contains("ends where a value"));
        assert!(err("sin phi").fault.to_string().contains("needs parentheses"));
        assert!(err("foo(1)").fault.to_string().contains("unknown function"));
        assert!(err("theta").fault.to_string().contains("unknown name 'theta'"));
        assert_eq!(err("1 + $").position, 4);
        assert!(err("(1").fault.to_string().contains("expected ')'"));
        assert!(err("atan2(1)").fault.to_string().contains("2 arguments"));
        assert!(err("").fault.to_string().contains("empty"));
        assert!(err("1 2").fault.to_string().contains("after the end"));
    }

    #[test]
    fn hostile_inputs_are_rejected_cheaply() {
        let deep = format!("{}1{}", "(".repeat(20_000), ")".repeat(20_000));
        assert!(Expr::compile(&deep, &[]).unwrap_err().fault.to_string().contains("characters"));
        let nested = format!("{}1{}", "(".repeat(100), ")".repeat(100));
        assert!(Expr::compile(&nested, &[]).unwrap_err().fault.to_string().contains("nested deeper"));
        let minus = format!("{}1", "-".repeat(500));
        assert!(Expr::compile(&minus, &[]).is_err());
    }

    /// Symbolic derivatives against central finite differences, h = 1e-6
    /// (truncation error ~h²·f''' ≈ 1e-12, round-off ~1e-16/h ≈ 1e-10).
    #[test]
    fn derivatives_match_finite_differences() {
        let cases = [
            "5*sin(x)^2",
            "x^3 - 2*x",
            "exp(-x)*cos(3*x)",
            "sqrt(1 + x^2)",
            "ln(2 + x) + log10(3 + x)",
            "tan(x/3) + asin(x/4) + acos(x/5) + atan(x)",
            "atan2(sin(x), 2 + cos(x))",
            "x^x",
            "abs(x - 0.1) + min(x, 0.2) + max(x^2, 0.3)",
            "1/(1 + x)",
        ];
        for src in cases {
            let e = Expr::compile(src, &["x"]).unwrap();
            let d = e.derivative(0);
            for x in [0.35, 0.7, 1.1] {
                let h = 1e-6;
                let fd = (e.eval(&[x + h]) - e.eval(&[x - h])) / (2.0 * h);
                let an = d.eval(&[x]);
                assert!((fd - an).abs() < 1e-8 * (1.0 + an.abs()), "{src} at {x}: {an} vs {fd}");
            }
        }
    }
}
