//! The expression tree flattened into postfix order and run on a small
//! stack: the loop over a flat array avoids a recursive call and a pointer
//! chase per node (the flywheel evaluates each expression thousands of times
//! per job). Trees deeper than the stack (long chains of `^`) stay with the
//! tree walk.

use super::node::{Fn1, Fn2, Node, pow};

/// Largest stack a program may need.
const STACK: usize = 32;
/// Points a batch evaluation carries through each operation at once.
const LANES: usize = 64;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Const(f64),
    Var(usize),
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Call1(Fn1),
    Call2(Fn2),
    /// Pops a, b, then, otherwise; pushes `then` if a < b.
    IfLess,
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Program {
    ops: Vec<Op>,
}

impl Program {
    /// The postfix program of `root`, or None when it needs more than the stack.
    pub fn new(root: &Node) -> Option<Self> {
        let mut ops = Vec::new();
        let depth = emit(root, &mut ops);
        (depth <= STACK).then_some(Self { ops })
    }

    pub fn eval(&self, vars: &[f64]) -> f64 {
        let mut stack = [0.0f64; STACK];
        let mut top = 0;
        for op in &self.ops {
            let value = match *op {
                Op::Const(c) => c,
                Op::Var(i) => vars.get(i).copied().unwrap_or(0.0),
                Op::Neg => -stack[top - 1],
                Op::Call1(f) => f.apply(stack[top - 1]),
                Op::IfLess => {
                    top -= 3;
                    let s = &stack[top - 1..top + 3];
                    if s[0] < s[1] { s[2] } else { s[3] }
                }
                binary => {
                    top -= 1;
                    let (a, b) = (stack[top - 1], stack[top]);
                    match binary {
                        Op::Add => a + b,
                        Op::Sub => a - b,
                        Op::Mul => a * b,
                        Op::Div => a / b,
                        Op::Pow => pow(a, b),
                        Op::Call2(f) => f.apply(a, b),
                        _ => unreachable!("every other operation is matched above"),
                    }
                }
            };
            match op {
                Op::Const(_) | Op::Var(_) => {
                    stack[top] = value;
                    top += 1;
                }
                _ => stack[top - 1] = value,
            }
        }
        stack[0]
    }

    /// The values at every x of `xs` for variable 0 (the others 0), into
    /// `out`: bit for bit [`Self::eval`]'s, but each operation runs over a
    /// block of points (the per-point dispatch is what a sampled cycle of a
    /// thousand points spends most of its interpreting on), and a function
    /// of the variable alone is read from `memo` where an expression before
    /// this one at the same points computed it.
    pub fn eval_many(&self, all: &[f64], out: &mut [f64], memo: &mut Memo) {
        memo.at(all);
        let mut stack = [[0.0f64; LANES]; STACK];
        for (block, (xs, out)) in all.chunks(LANES).zip(out.chunks_mut(LANES)).enumerate() {
            let len = xs.len();
            let mut top = 0;
            for (k, op) in self.ops.iter().enumerate() {
                match *op {
                    Op::Const(c) => stack[top][..len].fill(c),
                    Op::Var(0) => stack[top][..len].copy_from_slice(xs),
                    Op::Var(_) => stack[top][..len].fill(0.0),
                    Op::Neg => stack[top - 1][..len].iter_mut().for_each(|a| *a = -*a),
                    Op::Call1(f) if k > 0 && self.ops[k - 1] == Op::Var(0) => {
                        memo.apply(f, block * LANES, xs, &mut stack[top - 1][..len]);
                    }
                    Op::Call1(f) => stack[top - 1][..len].iter_mut().for_each(|a| *a = f.apply(*a)),
                    Op::IfLess => {
                        top -= 3;
                        let [a, b, then, otherwise] = &mut stack[top - 1..top + 3] else {
                            unreachable!("four operands")
                        };
                        for k in 0..len {
                            a[k] = if a[k] < b[k] { then[k] } else { otherwise[k] };
                        }
                    }
                    binary => {
                        top -= 1;
                        let [a, b] = &mut stack[top - 1..=top] else { unreachable!("two operands") };
                        let (a, b) = (&mut a[..len], &b[..len]);
                        match binary {
                            Op::Add => a.iter_mut().zip(b).for_each(|(a, b)| *a += b),
                            Op::Sub => a.iter_mut().zip(b).for_each(|(a, b)| *a -= b),
                            Op::Mul => a.iter_mut().zip(b).for_each(|(a, b)| *a *= b),
                            Op::Div => a.iter_mut().zip(b).for_each(|(a, b)| *a /= b),
                            Op::Pow => a.iter_mut().zip(b).for_each(|(a, b)| *a = pow(*a, *b)),
                            Op::Call2(f) => a.iter_mut().zip(b).for_each(|(a, b)| *a = f.apply(*a, *b)),
                            _ => unreachable!("every other operation is matched above"),
                        }
                    }
                }
                if matches!(op, Op::Const(_) | Op::Var(_)) {
                    top += 1;
                }
            }
            out.copy_from_slice(&stack[0][..len]);
        }
    }
}

/// f(x) at a batch's points for each function f met applied to the
/// variable itself (`sin(phi)`), kept for the next batch at the same points:
/// a cycle's M*, I* and I*' are evaluated on one grid, and their sines and
/// cosines were half of a flywheel job's time (perf, P.103's slider).
#[derive(Clone, Debug, Default)]
pub struct Memo {
    /// The points (compared bit for bit: sin(−0) is not sin(+0)).
    xs: Vec<u64>,
    /// f, its values at the points and how many of them, from the first, are known.
    values: Vec<(Fn1, Vec<f64>, usize)>,
}

impl Memo {
    /// Forgets what it holds unless it was for the points `xs`.
    fn at(&mut self, xs: &[f64]) {
        if !self.xs.iter().copied().eq(xs.iter().map(|x| x.to_bits())) {
            self.xs.clear();
            self.xs.extend(xs.iter().map(|x| x.to_bits()));
            self.values.clear();
        }
    }

    /// f at the points `xs`, the block of the batch's points from `from`,
    /// into `out`: read where known, else computed (and kept, block after block).
    fn apply(&mut self, f: Fn1, from: usize, xs: &[f64], out: &mut [f64]) {
        let to = from + xs.len();
        let k = self.values.iter().position(|(g, ..)| *g == f).unwrap_or_else(|| {
            self.values.push((f, vec![0.0; self.xs.len()], 0));
            self.values.len() - 1
        });
        let (_, values, known) = &mut self.values[k];
        if *known >= to {
            out.copy_from_slice(&values[from..to]);
            return;
        }
        out.iter_mut().zip(xs).for_each(|(o, x)| *o = f.apply(*x));
        if *known == from {
            values[from..to].copy_from_slice(out);
            *known = to;
        }
    }
}

/// Appends the postfix form of `n`; returns the stack depth it needs.
fn emit(n: &Node, ops: &mut Vec<Op>) -> usize {
    let children = |nodes: &[&Node], op: Op, ops: &mut Vec<Op>| {
        // The k-th operand waits on the stack under the later ones.
        let depth = nodes.iter().enumerate().map(|(k, c)| k + emit(c, ops)).max().unwrap_or(0);
        ops.push(op);
        depth
    };
    match n {
        Node::Const(c) => {
            ops.push(Op::Const(*c));
            1
        }
        Node::Var(i) => {
            ops.push(Op::Var(*i));
            1
        }
        Node::Neg(a) => children(&[a], Op::Neg, ops),
        Node::Call1(f, a) => children(&[a], Op::Call1(*f), ops),
        Node::Add(a, b) => children(&[a, b], Op::Add, ops),
        Node::Sub(a, b) => children(&[a, b], Op::Sub, ops),
        Node::Mul(a, b) => children(&[a, b], Op::Mul, ops),
        Node::Div(a, b) => children(&[a, b], Op::Div, ops),
        Node::Pow(a, b) => children(&[a, b], Op::Pow, ops),
        Node::Call2(f, a, b) => children(&[a, b], Op::Call2(*f), ops),
        Node::IfLess(x) => children(&[&x[0], &x[1], &x[2], &x[3]], Op::IfLess, ops),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::expr::parse::Parser;

    fn tree(source: &str) -> Node {
        Parser::parse(source, &["phi", "t"], &[], 64).unwrap().fold()
    }

    /// The program gives the tree walk's value bit for bit, for every kind
    /// of node (the derivatives of min and max bring in IfLess).
    #[test]
    fn programs_agree_with_the_tree_walk() {
        let sources = [
            "-500*sin(phi) + 500/pi",
            "5*sin(phi)^2",
            "-2^2 + (phi - t)/(1 + phi^2) - atan2(phi, t)",
            "min(phi, 2*t) + max(sin(phi), cos(t))",
            "exp(-t)*sqrt(abs(phi)) + sign(phi - 1)*floor(3*t) + ln(2 + phi) - log10(5 + t)",
            "((((phi + 1)*(t + 2))*((phi - 3)*(t - 4)))*(((phi + 5)*(t + 6))*((phi - 7)*(t - 8))))",
        ];
        // A batch over more than one block of points, t = 0, −0 among them.
        let xs: Vec<f64> = (0..150).map(|k| 0.07 * k as f64 - 5.0).chain([-0.0, 0.0]).collect();
        let mut memo = Memo::default();
        for source in sources {
            for root in [tree(source), tree(source).derivative(0).fold(), tree(source).derivative(1).fold()] {
                let program = Program::new(&root).expect("shallow enough");
                for k in 0..40 {
                    let vars = [0.37 * k as f64 - 3.0, 0.11 * k as f64 - 1.0];
                    let (a, b) = (program.eval(&vars), root.eval(&vars));
                    assert!(
                        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                        "{source} at {vars:?}: {a} vs {b}"
                    );
                }
                // Twice: computing the functions of φ, then reading them from
                // the memo, which the sources before this one filled too.
                for _ in 0..2 {
                    let mut many = vec![0.0; xs.len()];
                    program.eval_many(&xs, &mut many, &mut memo);
                    for (x, a) in xs.iter().zip(&many) {
                        let b = root.eval(&[*x, 0.0]);
                        let same = a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
                        assert!(same, "{source} at {x}: {a} vs {b}");
                    }
                }
            }
        }
    }

    /// The memo is for the points it was filled at, to the bit: sin(−0) is −0.
    #[test]
    fn the_memo_holds_for_its_own_points() {
        let program = Program::new(&tree("sin(phi)")).expect("shallow");
        let (mut memo, mut out) = (Memo::default(), [1.0]);
        for x in [0.0, -0.0, 0.5, -0.0] {
            program.eval_many(&[x], &mut out, &mut memo);
            assert_eq!(out[0].to_bits(), x.sin().to_bits(), "at {x}");
        }
    }

    /// A chain of powers nests to the right without parentheses: deeper than
    /// the stack, it keeps the tree walk.
    #[test]
    fn a_long_power_chain_is_too_deep_for_a_program() {
        let chain = vec!["1"; 40].join("^");
        assert!(Program::new(&Parser::parse(&chain, &["phi"], &[], 64).unwrap()).is_none());
        assert!(Program::new(&tree(&["phi"; 10].join("^"))).is_some());
    }
}
