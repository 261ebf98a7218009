//! A class graded in one request: 500 students of `p103-class`, 3 answers
//! each, POSTed as CSV to the release service (a fresh SQLite file); wall
//! time of the request and how many reference jobs it computed, when
//! students share 50 variants, when the same class is graded again (every
//! reference stored), and when each student has a variant of their own.

use crate::http::start;
use std::fmt::Write as _;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Instant;

const STUDENTS: u64 = 500;

/// The class: student i has variant `variant(i)`, three answers (numbers
/// near P.103's magnitudes; grading costs the same whether they pass).
fn class(variant: impl Fn(u64) -> u64) -> String {
    let mut csv = String::from("student,variant,inertia_exact,inertia_approximate,omega_max\n");
    for i in 0..STUDENTS {
        let _ =
            writeln!(csv, "s{i:03},{},{},{},{}", variant(i), 300 + i % 97, 290 + i % 89, 6.0 + (i % 7) as f64 / 10.0);
    }
    csv
}

/// One POST over a fresh connection: status and body.
fn post(addr: &str, path: &str, body: &str) -> Result<(u16, String), String> {
    let mut s = TcpStream::connect(addr).map_err(|e| e.to_string())?;
    let head = format!(
        "POST {path} HTTP/1.1\r\nHost: bench\r\nContent-Type: text/csv\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    s.write_all(head.as_bytes()).and_then(|()| s.write_all(body.as_bytes())).map_err(|e| e.to_string())?;
    let mut raw = String::new();
    s.read_to_string(&mut raw).map_err(|e| e.to_string())?;
    let status = raw.get(9..12).and_then(|c| c.parse().ok()).ok_or("no status")?;
    Ok((status, raw.split_once("\r\n\r\n").map_or(String::new(), |(_, b)| b.to_string())))
}

/// Flywheel jobs stored so far (the list, a page of 100 at a time).
fn stored(addr: &str) -> usize {
    let mut count = 0;
    let mut next = Some("/v1/jobs?kind=flywheel&limit=100".to_string());
    while let Some(path) = next {
        let Ok(mut s) = TcpStream::connect(addr) else { return count };
        let _ = write!(s, "GET {path} HTTP/1.1\r\nHost: bench\r\nConnection: close\r\n\r\n");
        let mut raw = String::new();
        let _ = s.read_to_string(&mut raw);
        let body = raw.split_once("\r\n\r\n").map_or("", |(_, b)| b);
        let page: serde_json::Value = serde_json::from_str(body).unwrap_or_default();
        count += page["items"].as_array().map_or(0, Vec::len);
        next = page["next"].as_str().map(String::from);
    }
    count
}

pub fn section() -> String {
    let mut text = String::from("## Grading a class in one request\n\n");
    let service = match start() {
        Ok(s) => s,
        Err(why) => return format!("{text}Skipped: {why}.\n"),
    };
    let _ = writeln!(
        text,
        "{STUDENTS} students of `p103-class`, 3 answers each, one `POST /v1/templates/p103-class/grade` of CSV to \
         the release service on a fresh database (one request at a time; wall time of the request, client \
         included).\n\n| class | wall time | reference jobs computed | per student |\n|---|---|---|---|"
    );
    let runs = [
        ("50 variants shared (student i: variant i mod 50 + 1)", class(|i| i % 50 + 1)),
        ("the same class again (every reference stored)", class(|i| i % 50 + 1)),
        ("a variant each (1000 … 1499)", class(|i| 1000 + i)),
    ];
    for (what, csv) in runs {
        let before = stored(&service.addr);
        let start = Instant::now();
        let answer = post(&service.addr, "/v1/templates/p103-class/grade", &csv);
        let seconds = start.elapsed().as_secs_f64();
        match answer {
            Ok((200, body)) if body.lines().count() == STUDENTS as usize + 1 => {
                let computed = stored(&service.addr) - before;
                let per = seconds / STUDENTS as f64 * 1e3;
                let _ = writeln!(text, "| {what} | {seconds:.2} s | {computed} | {per:.2} ms |");
            }
            Ok((status, body)) => {
                let _ = writeln!(text, "| {what} | failed: {status} {} | | |", body.lines().next().unwrap_or(""));
            }
            Err(why) => {
                let _ = writeln!(text, "| {what} | failed: {why} | | |");
            }
        }
    }
    let (_, peak) = service.memory();
    let _ = writeln!(text, "\nThe service's peak resident memory: {peak:.0} MiB.");
    text
}
