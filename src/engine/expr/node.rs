//! Expression tree: evaluation, constant folding and symbolic derivative.

/// Functions of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fn1 {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Exp,
    Ln,
    Log10,
    Abs,
    Sign,
    Floor,
}

/// Functions of two arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fn2 {
    Atan2,
    Min,
    Max,
}

impl Fn1 {
    pub(crate) fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            // `sen`: the sine as Spanish statements write it.
            "sin" | "sen" => Self::Sin,
            "cos" => Self::Cos,
            "tan" => Self::Tan,
            "asin" => Self::Asin,
            "acos" => Self::Acos,
            "atan" => Self::Atan,
            "sqrt" => Self::Sqrt,
            "exp" => Self::Exp,
            "ln" => Self::Ln,
            "log10" => Self::Log10,
            "abs" => Self::Abs,
            "sign" => Self::Sign,
            "floor" => Self::Floor,
            _ => return None,
        })
    }

    pub(crate) fn apply(self, x: f64) -> f64 {
        match self {
            Self::Sin => x.sin(),
            Self::Cos => x.cos(),
            Self::Tan => x.tan(),
            Self::Asin => x.asin(),
            Self::Acos => x.acos(),
            Self::Atan => x.atan(),
            Self::Sqrt => x.sqrt(),
            Self::Exp => x.exp(),
            Self::Ln => x.ln(),
            Self::Log10 => x.log10(),
            Self::Abs => x.abs(),
            Self::Sign => {
                if x > 0.0 {
                    1.0
                } else if x < 0.0 {
                    -1.0
                } else {
                    0.0
                }
            }
            Self::Floor => x.floor(),
        }
    }
}

impl Fn2 {
    pub(crate) fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "atan2" => Self::Atan2,
            "min" => Self::Min,
            "max" => Self::Max,
            _ => return None,
        })
    }

    pub(crate) fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Self::Atan2 => a.atan2(b),
            Self::Min => a.min(b),
            Self::Max => a.max(b),
        }
    }
}

/// A node of the expression tree. Variables are indices into the slice
/// passed to [`Node::eval`].
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    Const(f64),
    Var(usize),
    Neg(Box<Node>),
    Add(Box<Node>, Box<Node>),
    Sub(Box<Node>, Box<Node>),
    Mul(Box<Node>, Box<Node>),
    Div(Box<Node>, Box<Node>),
    Pow(Box<Node>, Box<Node>),
    Call1(Fn1, Box<Node>),
    Call2(Fn2, Box<Node>, Box<Node>),
    /// `if a < b { then } else { otherwise }`: only produced by derivatives of min/max.
    IfLess(Box<[Node; 4]>),
}

use Node::*;

fn b(n: Node) -> Box<Node> {
    Box::new(n)
}

impl Node {
    /// Value of the tree for the variable values `vars`.
    pub fn eval(&self, vars: &[f64]) -> f64 {
        match self {
            Const(c) => *c,
            Var(i) => vars.get(*i).copied().unwrap_or(0.0),
            Neg(a) => -a.eval(vars),
            Add(a, c) => a.eval(vars) + c.eval(vars),
            Sub(a, c) => a.eval(vars) - c.eval(vars),
            Mul(a, c) => a.eval(vars) * c.eval(vars),
            Div(a, c) => a.eval(vars) / c.eval(vars),
            Pow(a, c) => pow(a.eval(vars), c.eval(vars)),
            Call1(f, a) => f.apply(a.eval(vars)),
            Call2(f, a, c) => f.apply(a.eval(vars), c.eval(vars)),
            IfLess(n) => {
                if n[0].eval(vars) < n[1].eval(vars) {
                    n[2].eval(vars)
                } else {
                    n[3].eval(vars)
                }
            }
        }
    }

    /// Whether the tree reads variable `i`.
    pub fn uses(&self, i: usize) -> bool {
        match self {
            Const(_) => false,
            Var(j) => *j == i,
            Neg(a) | Call1(_, a) => a.uses(i),
            Add(a, c) | Sub(a, c) | Mul(a, c) | Div(a, c) | Pow(a, c) | Call2(_, a, c) => a.uses(i) || c.uses(i),
            IfLess(n) => n.iter().any(|x| x.uses(i)),
        }
    }

    fn is_const(&self) -> bool {
        matches!(self, Const(_))
    }

    fn constant(&self) -> Option<f64> {
        match self {
            Const(c) => Some(*c),
            _ => None,
        }
    }

    /// Folds constant subtrees and removes neutral elements (`x*1`, `x+0`, `0*x`).
    pub fn fold(self) -> Node {
        let node = match self {
            Neg(a) => Neg(b(a.fold())),
            Add(a, c) => Add(b(a.fold()), b(c.fold())),
            Sub(a, c) => Sub(b(a.fold()), b(c.fold())),
            Mul(a, c) => Mul(b(a.fold()), b(c.fold())),
            Div(a, c) => Div(b(a.fold()), b(c.fold())),
            Pow(a, c) => Pow(b(a.fold()), b(c.fold())),
            Call1(f, a) => Call1(f, b(a.fold())),
            Call2(f, a, c) => Call2(f, b(a.fold()), b(c.fold())),
            IfLess(n) => {
                let [p, q, r, s] = *n;
                IfLess(Box::new([p.fold(), q.fold(), r.fold(), s.fold()]))
            }
            leaf => leaf,
        };
        node.simplify()
    }

    fn simplify(self) -> Node {
        let all_const = match &self {
            Neg(a) | Call1(_, a) => a.is_const(),
            Add(a, c) | Sub(a, c) | Mul(a, c) | Div(a, c) | Pow(a, c) | Call2(_, a, c) => a.is_const() && c.is_const(),
            IfLess(n) => n[..2].iter().all(Node::is_const),
            _ => false,
        };
        if all_const {
            if let IfLess(n) = self {
                let [p, q, r, s] = *n;
                return if p.eval(&[]) < q.eval(&[]) { r } else { s };
            }
            return Const(self.eval(&[]));
        }
        match self {
            Add(a, c) if a.constant() == Some(0.0) => *c,
            Add(a, c) | Sub(a, c) if c.constant() == Some(0.0) => *a,
            Sub(a, c) if a.constant() == Some(0.0) => Neg(c),
            Mul(a, c) if a.constant() == Some(0.0) || c.constant() == Some(0.0) => Const(0.0),
            Mul(a, c) if a.constant() == Some(1.0) => *c,
            Mul(a, c) | Div(a, c) if c.constant() == Some(1.0) => *a,
            Div(a, _) if a.constant() == Some(0.0) => Const(0.0),
            Pow(a, c) if c.constant() == Some(1.0) => *a,
            Neg(a) => match *a {
                Neg(inner) => *inner,
                other => Neg(b(other)),
            },
            other => other,
        }
    }

    /// Symbolic derivative with respect to variable `i` (not folded).
    pub fn derivative(&self, i: usize) -> Node {
        let d = |n: &Node| n.derivative(i);
        let c = |n: &Node| b(n.clone());
        match self {
            Const(_) => Const(0.0),
            Var(j) => Const(if *j == i { 1.0 } else { 0.0 }),
            Neg(a) => Neg(b(d(a))),
            Add(a, q) => Add(b(d(a)), b(d(q))),
            Sub(a, q) => Sub(b(d(a)), b(d(q))),
            Mul(a, q) => Add(b(Mul(b(d(a)), c(q))), b(Mul(c(a), b(d(q))))),
            Div(a, q) => Div(b(Sub(b(Mul(b(d(a)), c(q))), b(Mul(c(a), b(d(q)))))), b(Mul(c(q), c(q)))),
            Pow(a, q) if !q.uses(i) => Mul(b(Mul(c(q), b(Pow(c(a), b(Sub(c(q), b(Const(1.0)))))))), b(d(a))),
            Pow(a, q) => {
                Mul(c(self), b(Add(b(Mul(b(d(q)), b(Call1(Fn1::Ln, c(a))))), b(Div(b(Mul(c(q), b(d(a)))), c(a))))))
            }
            Call1(f, a) => Mul(b(d1(*f, a)), b(d(a))),
            Call2(Fn2::Atan2, y, x) => Div(
                b(Sub(b(Mul(c(x), b(d(y)))), b(Mul(c(y), b(d(x)))))),
                b(Add(b(Mul(c(x), c(x))), b(Mul(c(y), c(y))))),
            ),
            Call2(Fn2::Min, p, q) => IfLess(Box::new([(**p).clone(), (**q).clone(), d(p), d(q)])),
            Call2(Fn2::Max, p, q) => IfLess(Box::new([(**p).clone(), (**q).clone(), d(q), d(p)])),
            IfLess(n) => IfLess(Box::new([n[0].clone(), n[1].clone(), d(&n[2]), d(&n[3])])),
        }
    }
}

/// Derivative of `f(u)` with respect to `u`.
impl Node {
    /// The nodes of this tree and an upper bound on those of its derivative
    /// with respect to variable `i` before folding, found without building it
    /// (saturating): each rule of [`Node::derivative`] copies its operands a
    /// known number of times.
    pub fn sizes(&self, i: usize) -> (usize, usize) {
        let s = |n: &Node| n.sizes(i);
        let sum = |terms: &[usize]| terms.iter().fold(0usize, |a, t| a.saturating_add(*t));
        let times = |k: usize, n: usize| n.saturating_mul(k);
        match self {
            Const(_) | Var(_) => (1, 1),
            Neg(a) => {
                let (sa, da) = s(a);
                (sa.saturating_add(1), da.saturating_add(1))
            }
            Add(a, q) | Sub(a, q) | Mul(a, q) | Div(a, q) | Pow(a, q) | Call2(_, a, q) => {
                let ((sa, da), (sq, dq)) = (s(a), s(q));
                let d = match self {
                    Add(..) | Sub(..) => sum(&[da, dq, 1]),
                    Mul(..) => sum(&[da, dq, sa, sq, 3]),
                    Div(..) => sum(&[da, dq, sa, times(3, sq), 4]),
                    Pow(_, q) if !q.uses(i) => sum(&[da, sa, times(2, sq), 5]),
                    Pow(..) => sum(&[da, dq, times(3, sa), times(2, sq), 8]),
                    Call2(Fn2::Atan2, ..) => sum(&[da, dq, times(3, sa), times(3, sq), 7]),
                    _ => sum(&[da, dq, sa, sq, 1]),
                };
                (sum(&[sa, sq, 1]), d)
            }
            Call1(_, a) => {
                let (sa, da) = s(a);
                (sa.saturating_add(1), sum(&[times(2, sa), da, 9]))
            }
            IfLess(n) => {
                let [(s0, _), (s1, _), (s2, d2), (s3, d3)] = [s(&n[0]), s(&n[1]), s(&n[2]), s(&n[3])];
                (sum(&[s0, s1, s2, s3, 1]), sum(&[s0, s1, d2, d3, 1]))
            }
        }
    }
}

fn d1(f: Fn1, u: &Node) -> Node {
    let u = || b(u.clone());
    let one = || b(Const(1.0));
    let one_minus_sq = || b(Sub(one(), b(Mul(u(), u()))));
    match f {
        Fn1::Sin => Call1(Fn1::Cos, u()),
        Fn1::Cos => Neg(b(Call1(Fn1::Sin, u()))),
        Fn1::Tan => Add(one(), b(Pow(b(Call1(Fn1::Tan, u())), b(Const(2.0))))),
        Fn1::Asin => Div(one(), b(Call1(Fn1::Sqrt, one_minus_sq()))),
        Fn1::Acos => Neg(b(Div(one(), b(Call1(Fn1::Sqrt, one_minus_sq()))))),
        Fn1::Atan => Div(one(), b(Add(one(), b(Mul(u(), u()))))),
        Fn1::Sqrt => Div(b(Const(0.5)), b(Call1(Fn1::Sqrt, u()))),
        Fn1::Exp => Call1(Fn1::Exp, u()),
        Fn1::Ln => Div(one(), u()),
        Fn1::Log10 => Div(one(), b(Mul(u(), b(Const(std::f64::consts::LN_10))))),
        Fn1::Abs => Call1(Fn1::Sign, u()),
        Fn1::Sign | Fn1::Floor => Const(0.0),
    }
}

/// `a^b` with integer powers computed exactly (so `(-2)^3 = -8`).
pub(crate) fn pow(a: f64, e: f64) -> f64 {
    if e == e.trunc() && e.abs() <= 64.0 { a.powi(e as i32) } else { a.powf(e) }
}
