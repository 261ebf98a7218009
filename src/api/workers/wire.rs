//! What the service and a worker process say to each other over the
//! worker's standard input and output: frames of two parts, each a
//! little-endian `u32` length and its bytes. A job is its header (the
//! kind's name and the limits it computes within, as JSON) and the request
//! as the client sent it; a reply is its header (the compute time, or the
//! error) and the result's JSON, the bytes the service stores. An error
//! crosses with the catalogue's message of each field, so that the service
//! says it in the asker's language as it would have in-process.

use crate::i18n::Msg;
use crate::kind::Limits;
use crate::kind::problem::{ApiError, FieldError};
use serde::{Deserialize, Serialize};
use std::io::{self, IoSlice, Read, Write};

/// The largest part of a frame: a request body, or a result with room to spare.
pub const MAX_PART: usize = 1 << 30;

/// A job for a worker: the kind to compute and the limits it computes within.
#[derive(Debug, Serialize, Deserialize)]
pub struct Job {
    pub kind: String,
    pub limits: Limits,
}

impl Job {
    pub fn new(kind: &str, limits: &Limits) -> Self {
        Self { kind: kind.into(), limits: Limits { started: None, ..limits.clone() } }
    }
}

/// A worker's reply: the result computed in `micros` (the result's JSON
/// follows), or why there is none.
#[derive(Debug, Serialize, Deserialize)]
pub enum Reply {
    Done { micros: u64 },
    Failed(Failure),
}

/// An [`ApiError`] a computation can end with, as it crosses the pipe.
#[derive(Debug, Serialize, Deserialize)]
pub enum Failure {
    Invalid(Vec<Field>),
    BadQuery(Vec<Field>),
    MalformedJson(Msg),
    OverBudget(Msg),
    ResultTooLarge { limit: usize, errors: Vec<Field> },
    Internal(String),
}

/// A [`FieldError`] with its catalogue message, which its own JSON leaves out.
#[derive(Debug, Serialize, Deserialize)]
pub struct Field {
    pointer: Option<String>,
    parameter: Option<String>,
    row: Option<u32>,
    column: Option<String>,
    message: String,
    text: Option<Msg>,
}

impl From<FieldError> for Field {
    fn from(f: FieldError) -> Self {
        let FieldError { pointer, parameter, row, column, message, text } = f;
        Self { pointer, parameter, row, column, message, text: text.map(|m| *m) }
    }
}

impl From<Field> for FieldError {
    fn from(f: Field) -> Self {
        let Field { pointer, parameter, row, column, message, text } = f;
        Self { pointer, parameter, row, column, message, text: text.map(Box::new) }
    }
}

fn fields<A: From<B>, B>(list: Vec<B>) -> Vec<A> {
    list.into_iter().map(A::from).collect()
}

impl From<ApiError> for Failure {
    fn from(e: ApiError) -> Self {
        match e {
            ApiError::Invalid(f) => Self::Invalid(fields(f)),
            ApiError::BadQuery(f) => Self::BadQuery(fields(f)),
            ApiError::MalformedJson(m) => Self::MalformedJson(m),
            ApiError::OverBudget(m) => Self::OverBudget(m),
            ApiError::ResultTooLarge { limit, errors } => Self::ResultTooLarge { limit, errors: fields(errors) },
            ApiError::Internal(why) => Self::Internal(why),
            other => Self::Internal(format!("{other:?}")),
        }
    }
}

impl From<Failure> for ApiError {
    fn from(f: Failure) -> Self {
        match f {
            Failure::Invalid(f) => Self::Invalid(fields(f)),
            Failure::BadQuery(f) => Self::BadQuery(fields(f)),
            Failure::MalformedJson(m) => Self::MalformedJson(m),
            Failure::OverBudget(m) => Self::OverBudget(m),
            Failure::ResultTooLarge { limit, errors } => Self::ResultTooLarge { limit, errors: fields(errors) },
            Failure::Internal(why) => Self::Internal(why),
        }
    }
}

/// The header of a frame as JSON and its length prefix, to be followed by a body's prefix and bytes.
pub fn head<T: Serialize>(header: &T, body: usize) -> io::Result<Vec<u8>> {
    let json = serde_json::to_vec(header).map_err(io::Error::other)?;
    let mut out = Vec::with_capacity(json.len() + 8);
    out.extend_from_slice(&part_len(json.len())?.to_le_bytes());
    out.extend_from_slice(&json);
    out.extend_from_slice(&part_len(body)?.to_le_bytes());
    Ok(out)
}

fn part_len(n: usize) -> io::Result<u32> {
    u32::try_from(n).ok().filter(|&n| n as usize <= MAX_PART).ok_or_else(|| io::Error::other("a part over 1 GiB"))
}

/// A part's length from its prefix, refused beyond [`MAX_PART`].
pub fn length(prefix: [u8; 4]) -> io::Result<usize> {
    let n = u32::from_le_bytes(prefix) as usize;
    if n > MAX_PART { Err(io::Error::other("a part over 1 GiB")) } else { Ok(n) }
}

/// Writes a frame (blocking: the worker's side), its parts gathered in one
/// write where the pipe takes them: a reply written in pieces woke the
/// service once a piece, and on a virtual machine a wakeup costs some 30 µs.
pub fn write<T: Serialize>(out: &mut impl Write, header: &T, body: &[u8]) -> io::Result<()> {
    let head = head(header, body.len())?;
    let mut parts = [IoSlice::new(&head), IoSlice::new(body)];
    let mut parts = &mut parts[..];
    while !parts.is_empty() {
        match out.write_vectored(parts) {
            Ok(0) => return Err(io::ErrorKind::WriteZero.into()),
            Ok(n) => IoSlice::advance_slices(&mut parts, n),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    out.flush()
}

/// A descriptor written with the system's own calls, unbuffered (standard
/// output's own writer flushes at every newline byte, which a frame's
/// lengths may hold).
pub struct Unbuffered<F>(pub F);

impl<F: std::os::fd::AsFd> Write for Unbuffered<F> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        Ok(rustix::io::write(&self.0, buf)?)
    }

    fn write_vectored(&mut self, bufs: &[IoSlice<'_>]) -> io::Result<usize> {
        Ok(rustix::io::writev(&self.0, bufs)?)
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// Reads a frame (blocking: the worker's side); None at the end of input
/// before a frame begins (the service has gone).
pub fn read(input: &mut impl Read) -> io::Result<Option<(Vec<u8>, Vec<u8>)>> {
    let mut prefix = [0u8; 4];
    loop {
        match input.read(&mut prefix[..1]) {
            Ok(0) => return Ok(None),
            Ok(_) => break,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        }
    }
    input.read_exact(&mut prefix[1..])?;
    let header = part(input, length(prefix)?)?;
    input.read_exact(&mut prefix)?;
    let body = part(input, length(prefix)?)?;
    Ok(Some((header, body)))
}

fn part(input: &mut impl Read, n: usize) -> io::Result<Vec<u8>> {
    let mut buf = vec![0u8; n];
    input.read_exact(&mut buf)?;
    Ok(buf)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::Lang;
    use std::time::Duration;

    /// A refusal crosses the pipe whole: its fields, their pointers and
    /// their catalogue messages, said again in Spanish on the other side.
    #[test]
    fn a_refusal_crosses_with_its_messages() {
        let msg = Msg::new("parameter-below").arg("text", "-3").num("min", 2.0).arg("unit", " N*m");
        let e = ApiError::Invalid(vec![FieldError::said("/torques/0", msg.clone())]);
        let mut pipe = Vec::new();
        write(&mut pipe, &Reply::Failed(e.into()), b"").unwrap();
        let (header, body) = read(&mut pipe.as_slice()).unwrap().unwrap();
        assert!(body.is_empty());
        let Reply::Failed(f) = serde_json::from_slice(&header).unwrap() else { panic!("not a failure") };
        let ApiError::Invalid(errors) = ApiError::from(f) else { panic!("not invalid") };
        assert_eq!(errors[0].pointer.as_deref(), Some("/torques/0"));
        assert_eq!(errors[0].clone().in_lang(Lang::Es).message, msg.render(Lang::Es));
    }

    /// A job's limits are read back as they were sent, and a frame's end
    /// before it begins is the end of the conversation, not an error.
    #[test]
    fn a_job_and_its_limits_cross_the_pipe() {
        let limits = Limits { budget: Duration::from_millis(1500), steps: 7, ..Limits::default() };
        let mut pipe = Vec::new();
        write(&mut pipe, &Job::new("flywheel", &limits), b"{}").unwrap();
        let (header, body) = read(&mut pipe.as_slice()).unwrap().unwrap();
        let job: Job = serde_json::from_slice(&header).unwrap();
        assert_eq!((job.kind.as_str(), job.limits, body.as_slice()), ("flywheel", limits, &b"{}"[..]));
        assert!(read(&mut &b""[..]).unwrap().is_none());
        assert!(read(&mut &b"\x05\0"[..]).is_err(), "a frame cut short");
    }
}
