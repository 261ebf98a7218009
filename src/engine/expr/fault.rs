//! What is wrong with an expression, as a value: the service says it in
//! the asker's words; [`std::fmt::Display`] says it in English (the
//! engine's tests, logs).

/// A token of an expression: a number, a name, an operator or parenthesis.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    Num(f64),
    Name(String),
    Op(char),
}

/// The functions of the language, for a message naming an unknown one.
pub const FUNCTIONS: &str = "sin cos tan asin acos atan atan2 sqrt exp ln log10 abs min max sign floor";

/// How many arguments a function takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arity {
    One,
    Two,
    AtLeastTwo,
}

/// Why an expression was rejected.
#[derive(Clone, Debug, PartialEq)]
pub enum Fault {
    /// `length` characters, over `max`.
    TooLong {
        length: usize,
        max: usize,
    },
    MalformedNumber(String),
    UnexpectedCharacter(char),
    Empty,
    /// A token after a whole expression (`1 2`).
    AfterEnd(Tok),
    /// Parentheses and unary operators nested deeper than this.
    TooDeep(usize),
    /// The text ends where a value was expected (`2*`).
    EndsEarly,
    /// A token where a value was expected (`2*)`).
    Unexpected(Tok),
    /// A function named without its parentheses (`sin phi`).
    NeedsParentheses(String),
    /// A name that is no variable, constant or function here.
    UnknownName {
        name: String,
        variables: Vec<String>,
        constants: Vec<String>,
    },
    Arity {
        name: String,
        takes: Arity,
        got: usize,
    },
    UnknownFunction(String),
    /// This operator was expected (a closing parenthesis, say).
    Expected(char),
}

impl std::fmt::Display for Tok {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Tok::Num(v) => write!(f, "number {v}"),
            Tok::Name(n) => write!(f, "name '{n}'"),
            Tok::Op(c) => write!(f, "'{c}'"),
        }
    }
}

impl std::fmt::Display for Fault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Fault::TooLong { length, max } => write!(f, "expression has {length} characters; the maximum is {max}"),
            Fault::MalformedNumber(text) => write!(f, "malformed number '{text}'"),
            Fault::UnexpectedCharacter(c) => write!(f, "unexpected character '{c}'"),
            Fault::Empty => f.write_str("empty expression"),
            Fault::AfterEnd(t) => write!(f, "unexpected {t} after the end of the expression"),
            Fault::TooDeep(max) => write!(f, "expression nested deeper than {max} levels"),
            Fault::EndsEarly => f.write_str("expression ends where a value was expected"),
            Fault::Unexpected(t) => write!(f, "unexpected {t} where a value was expected"),
            Fault::NeedsParentheses(name) => write!(f, "function '{name}' needs parentheses"),
            Fault::UnknownName { name, variables, constants } => {
                let variables = if variables.is_empty() { "none".to_string() } else { variables.join(", ") };
                write!(f, "unknown name '{name}' (variables here: {variables}; constants: {})", constants.join(", "))
            }
            Fault::Arity { name, takes, got } => {
                let takes = match takes {
                    Arity::One => "1 argument",
                    Arity::Two => "2 arguments",
                    Arity::AtLeastTwo => "at least 2 arguments",
                };
                write!(f, "function '{name}' takes {takes}, got {got}")
            }
            Fault::UnknownFunction(name) => write!(f, "unknown function '{name}' (known: {FUNCTIONS})"),
            Fault::Expected(op) => write!(f, "expected '{op}'"),
        }
    }
}
