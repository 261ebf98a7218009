//! Tokenizer and recursive-descent parser for the contract's expression grammar.
//!
//! ```text
//! sum     = product (("+" | "-") product)*
//! product = unary (("*" | "/") unary)*
//! unary   = ("-" | "+") unary | power
//! power   = primary ("^" unary)?          right-associative, binds tighter than unary minus
//! primary = number | name | name "(" sum ("," sum)* ")" | "(" sum ")"
//! ```

use super::ExprError;
use super::fault::{Arity, Fault, Tok};
use super::node::{Fn1, Fn2, Node};

struct Token {
    tok: Tok,
    pos: usize,
}

fn tokenize(src: &str) -> Result<Vec<Token>, ExprError> {
    let chars: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let start = i;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c.is_ascii_digit() || c == '.' {
            i = scan_number(&chars, i);
            let text: String = chars[start..i].iter().collect();
            let value = text
                .parse::<f64>()
                .map_err(|_| ExprError { position: start, fault: Fault::MalformedNumber(text.clone()) })?;
            out.push(Token { tok: Tok::Num(value), pos: start });
        } else if c.is_ascii_alphabetic() || c == '_' {
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let name = chars[start..i].iter().collect();
            out.push(Token { tok: Tok::Name(name), pos: start });
        } else if "+-*/^(),".contains(c) {
            out.push(Token { tok: Tok::Op(c), pos: start });
            i += 1;
        } else {
            return Err(ExprError { position: start, fault: Fault::UnexpectedCharacter(c) });
        }
    }
    Ok(out)
}

/// End index of the number starting at `i` (digits, one dot, optional exponent).
fn scan_number(chars: &[char], mut i: usize) -> usize {
    let digits = |i: &mut usize| {
        while *i < chars.len() && chars[*i].is_ascii_digit() {
            *i += 1;
        }
    };
    digits(&mut i);
    if i < chars.len() && chars[i] == '.' {
        i += 1;
        digits(&mut i);
    }
    if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
        let mut j = i + 1;
        if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
            j += 1;
        }
        if j < chars.len() && chars[j].is_ascii_digit() {
            i = j;
            digits(&mut i);
        }
    }
    i
}

pub(super) struct Parser<'a> {
    tokens: Vec<Token>,
    next: usize,
    depth: usize,
    max_depth: usize,
    variables: &'a [&'a str],
    /// Named values (a request's `constants`), read as numbers.
    constants: &'a [(String, f64)],
    end: usize,
}

impl<'a> Parser<'a> {
    pub(super) fn parse(
        src: &str,
        variables: &'a [&'a str],
        constants: &'a [(String, f64)],
        max_depth: usize,
    ) -> Result<Node, ExprError> {
        let tokens = tokenize(src)?;
        let mut p = Parser { tokens, next: 0, depth: 0, max_depth, variables, constants, end: src.chars().count() };
        if p.tokens.is_empty() {
            return Err(ExprError { position: 0, fault: Fault::Empty });
        }
        let node = p.sum()?;
        if let Some(t) = p.tokens.get(p.next) {
            return Err(ExprError { position: t.pos, fault: Fault::AfterEnd(t.tok.clone()) });
        }
        Ok(node)
    }

    fn peek_op(&self) -> Option<char> {
        match self.tokens.get(self.next) {
            Some(Token { tok: Tok::Op(c), .. }) => Some(*c),
            _ => None,
        }
    }

    fn pos(&self) -> usize {
        self.tokens.get(self.next).map_or(self.end, |t| t.pos)
    }

    fn err<T>(&self, fault: Fault) -> Result<T, ExprError> {
        Err(ExprError { position: self.pos(), fault })
    }

    fn enter(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > self.max_depth {
            return self.err(Fault::TooDeep(self.max_depth));
        }
        Ok(())
    }

    fn sum(&mut self) -> Result<Node, ExprError> {
        let mut lhs = self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek_op() {
            self.next += 1;
            let rhs = Box::new(self.product()?);
            lhs = if op == '+' { Node::Add(Box::new(lhs), rhs) } else { Node::Sub(Box::new(lhs), rhs) };
        }
        Ok(lhs)
    }

    fn product(&mut self) -> Result<Node, ExprError> {
        let mut lhs = self.unary()?;
        while let Some(op @ ('*' | '/')) = self.peek_op() {
            self.next += 1;
            let rhs = Box::new(self.unary()?);
            lhs = if op == '*' { Node::Mul(Box::new(lhs), rhs) } else { Node::Div(Box::new(lhs), rhs) };
        }
        Ok(lhs)
    }

    fn unary(&mut self) -> Result<Node, ExprError> {
        let negate = match self.peek_op() {
            Some('-') => true,
            Some('+') => false,
            _ => return self.power(),
        };
        self.next += 1;
        let operand = self.nested(Self::unary)?;
        Ok(if negate { Node::Neg(Box::new(operand)) } else { operand })
    }

    /// Runs `f` one nesting level deeper, failing past the depth limit.
    fn nested(&mut self, f: fn(&mut Self) -> Result<Node, ExprError>) -> Result<Node, ExprError> {
        self.enter()?;
        let node = f(self)?;
        self.depth -= 1;
        Ok(node)
    }

    fn power(&mut self) -> Result<Node, ExprError> {
        let base = self.primary()?;
        if self.peek_op() == Some('^') {
            self.next += 1;
            let exponent = self.nested(Self::unary)?;
            return Ok(Node::Pow(Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<Node, ExprError> {
        let Some(token) = self.tokens.get(self.next) else {
            return self.err(Fault::EndsEarly);
        };
        let pos = token.pos;
        match token.tok.clone() {
            Tok::Num(v) => {
                self.next += 1;
                Ok(Node::Const(v))
            }
            Tok::Op('(') => {
                self.next += 1;
                let inner = self.nested(Self::sum)?;
                self.expect(')')?;
                Ok(inner)
            }
            Tok::Name(name) => {
                self.next += 1;
                if self.peek_op() == Some('(') { self.call(&name, pos) } else { self.name(&name, pos) }
            }
            other => self.err(Fault::Unexpected(other)),
        }
    }

    fn name(&self, name: &str, pos: usize) -> Result<Node, ExprError> {
        if let Some(i) = self.variables.iter().position(|v| *v == name) {
            return Ok(Node::Var(i));
        }
        if let Some((_, value)) = self.constants.iter().find(|(n, _)| n == name) {
            return Ok(Node::Const(*value));
        }
        match name {
            "pi" => Ok(Node::Const(std::f64::consts::PI)),
            "e" => Ok(Node::Const(std::f64::consts::E)),
            _ if Fn1::from_name(name).is_some() || Fn2::from_name(name).is_some() => {
                Err(ExprError { position: pos, fault: Fault::NeedsParentheses(name.to_string()) })
            }
            _ => Err(ExprError {
                position: pos,
                fault: Fault::UnknownName {
                    name: name.to_string(),
                    variables: self.variables.iter().map(|v| v.to_string()).collect(),
                    constants: self
                        .constants
                        .iter()
                        .map(|(n, _)| n.as_str())
                        .chain(["pi", "e"])
                        .map(String::from)
                        .collect(),
                },
            }),
        }
    }

    fn call(&mut self, name: &str, pos: usize) -> Result<Node, ExprError> {
        self.expect('(')?;
        let mut args = vec![self.nested(Self::sum)?];
        while self.peek_op() == Some(',') {
            self.next += 1;
            args.push(self.nested(Self::sum)?);
        }
        self.expect(')')?;
        let got = args.len();
        let arity_error =
            |takes| ExprError { position: pos, fault: Fault::Arity { name: name.to_string(), takes, got } };
        if let Some(f) = Fn1::from_name(name) {
            let [a] = <[Node; 1]>::try_from(args.clone()).map_err(|_| arity_error(Arity::One))?;
            return Ok(Node::Call1(f, Box::new(a)));
        }
        if let Some(f) = Fn2::from_name(name) {
            if f == Fn2::Atan2 && args.len() != 2 {
                return Err(arity_error(Arity::Two));
            }
            if args.len() < 2 {
                return Err(arity_error(Arity::AtLeastTwo));
            }
            let mut it = args.into_iter();
            let first = it.next().unwrap_or(Node::Const(0.0));
            return Ok(it.fold(first, |acc, x| Node::Call2(f, Box::new(acc), Box::new(x))));
        }
        Err(ExprError { position: pos, fault: Fault::UnknownFunction(name.to_string()) })
    }

    fn expect(&mut self, op: char) -> Result<(), ExprError> {
        if self.peek_op() == Some(op) {
            self.next += 1;
            Ok(())
        } else {
            self.err(Fault::Expected(op))
        }
    }
}
