//! One HTTP/1.1 exchange per connection and a free loopback port: what the
//! tests that drive real processes (and the soak bench, which includes this
//! file) speak to them with. No other module of the tests is named here.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::Duration;

/// One HTTP/1.1 exchange on a fresh connection: (status, body).
pub fn http(port: u16, method: &str, path: &str, body: &str) -> std::io::Result<(u16, String)> {
    http_with(port, method, path, "", body)
}

/// [`http`] with more header lines (`extra`: each ending in `\r\n`), an answer
/// awaited 10 s (the clients' timeout of the tests).
pub fn http_with(port: u16, method: &str, path: &str, extra: &str, body: &str) -> std::io::Result<(u16, String)> {
    exchange(port, method, path, extra, body, Duration::from_secs(10))
}

/// [`http_with`], the answer awaited `wait` at most.
pub fn exchange(
    port: u16,
    method: &str,
    path: &str,
    extra: &str,
    body: &str,
    wait: Duration,
) -> std::io::Result<(u16, String)> {
    let mut s = TcpStream::connect(("127.0.0.1", port))?;
    s.set_read_timeout(Some(wait))?;
    let head = format!(
        "{method} {path} HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n{extra}\
         Content-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    s.write_all(head.as_bytes())?;
    s.write_all(body.as_bytes())?;
    let mut raw = String::new();
    s.read_to_string(&mut raw)?;
    let status = raw.get(9..12).and_then(|c| c.parse().ok()).ok_or(std::io::ErrorKind::InvalidData)?;
    let body = raw.split_once("\r\n\r\n").map(|(_, b)| b.to_string()).ok_or(std::io::ErrorKind::InvalidData)?;
    Ok((status, body))
}

/// A GET's answer head: its status line and headers, as sent.
pub fn exchange_head(port: u16, method: &str, path: &str) -> std::io::Result<String> {
    let mut s = TcpStream::connect(("127.0.0.1", port))?;
    s.set_read_timeout(Some(Duration::from_secs(10)))?;
    s.write_all(format!("{method} {path} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n").as_bytes())?;
    let mut raw = String::new();
    s.read_to_string(&mut raw)?;
    Ok(raw.split_once("\r\n\r\n").map_or(raw.clone(), |(head, _)| head.to_string()))
}

/// A loopback port free now, below Linux's ephemeral range (32768–60999):
/// a port the kernel hands out for port 0 is also one it may give an
/// outgoing connection's local end, and the tests that stop a process and
/// start it again on its port (a replica killed, the database stopped)
/// could then not bind it while the clients' connections come and go.
/// Consecutive ports from an offset of this process's, each tried.
pub fn free_port() -> u16 {
    static NEXT: AtomicU32 = AtomicU32::new(0);
    let offset = std::process::id() * 97;
    loop {
        let port = 20_000 + ((offset + NEXT.fetch_add(1, Ordering::Relaxed)) % 12_000) as u16;
        if TcpListener::bind(("127.0.0.1", port)).is_ok() {
            return port;
        }
    }
}
