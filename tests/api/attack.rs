//! A client that holds connections as an attacker does: heads started and
//! never ended, answers taken and the connection kept idle, each watched for
//! when the service closes it. Nothing else of the tests is used here, so
//! the soak bench includes this file too.

use std::io::{ErrorKind, Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

/// The client's own descriptors raised to its hard limit (thousands of
/// connections), as the service raises its own.
pub fn more_files() {
    mechdyn::api::serve::open_files();
}

/// A connection that has sent the start of a head and no end of it.
pub fn slow_head(port: u16) -> TcpStream {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Slow: ").unwrap();
    s.set_nonblocking(true).unwrap();
    s
}

/// A kept-alive connection that has had its answer and says nothing more.
pub fn idle(port: u16) -> TcpStream {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n").unwrap();
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    let mut got = Vec::new();
    let mut buf = [0u8; 1024];
    while !String::from_utf8_lossy(&got).contains("\"status\"") {
        let n = s.read(&mut buf).unwrap();
        assert!(n > 0, "answered: {}", String::from_utf8_lossy(&got));
        got.extend_from_slice(&buf[..n]);
    }
    assert!(got.starts_with(b"HTTP/1.1 200"));
    s.set_nonblocking(true).unwrap();
    s
}

/// Whether the service has closed `s` (an end of stream or a reset; what it
/// sent before is read and dropped).
pub fn closed(s: &mut TcpStream) -> bool {
    let mut buf = [0u8; 4096];
    loop {
        match s.read(&mut buf) {
            Ok(0) => return true,
            Ok(_) => continue,
            Err(e) if e.kind() == ErrorKind::WouldBlock => return false,
            Err(_) => return true,
        }
    }
}

/// Trickles a byte into each open slow head every `every`, and notes when
/// each connection is seen closed, until all are or `limit` passes: the
/// seconds after `since` at which each was closed (None: still open).
pub fn watch(conns: &mut [TcpStream], since: Instant, every: Duration, limit: Duration) -> Vec<Option<f64>> {
    let mut at = vec![None; conns.len()];
    let mut last_trickle = Instant::now();
    while at.iter().any(Option::is_none) && since.elapsed() < limit {
        let trickle = last_trickle.elapsed() >= every;
        for (k, s) in conns.iter_mut().enumerate() {
            if at[k].is_some() {
                continue;
            }
            if trickle {
                let _ = s.write(b"a");
            }
            if closed(s) {
                at[k] = Some(since.elapsed().as_secs_f64());
            }
        }
        if trickle {
            last_trickle = Instant::now();
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    at
}
