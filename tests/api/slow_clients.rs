//! Slow clients cannot take the service down: the real binary, with a
//! grace of 1 s and the default minimal rate (32 KiB/s), against clients
//! that trickle their bodies or read their answers a kilobyte at a time.
//! Those are let go within seconds (408, or their connection closed), and
//! meanwhile every other client is served: a trickled body holds no job
//! slot, and an answer's memory is not held for ever.

use crate::crash::{free_port, http, start_with};
use crate::helpers::request;
use serde_json::Value;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::process::Child;
use std::time::{Duration, Instant};

/// The grace given to the service under test, seconds.
const GRACE: &str = "1";

/// The service on a fresh database (its folder kept while it runs) with a
/// 1 s grace and `env`; killed on drop.
struct Service(Child, u16, #[allow(dead_code)] tempfile::TempDir);

impl Service {
    fn start(env: &[(&str, &str)]) -> Self {
        let dir = tempfile::tempdir().unwrap();
        let db = format!("sqlite://{}/jobs.db", dir.path().display());
        let port = free_port();
        let env: Vec<_> = [("MECHDYN_CLIENT_GRACE_SECONDS", GRACE)].into_iter().chain(env.iter().copied()).collect();
        Self(start_with(&db, port, &env), port, dir)
    }
}

impl Drop for Service {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// A POST whose head and first bytes are sent at once, then a byte every
/// 200 ms (5 bytes/s) until the service answers: its status, the answer and
/// how long it took.
fn trickle(port: u16, body: &str) -> (u16, String, Duration) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_millis(200))).unwrap();
    let head = format!(
        "POST /v1/flywheel HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\r\n",
        body.len()
    );
    let started = Instant::now();
    s.write_all(head.as_bytes()).unwrap();
    let mut raw = Vec::new();
    for byte in body.as_bytes() {
        let _ = s.write_all(&[*byte]);
        let mut buf = [0u8; 4096];
        match s.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => {
                raw.extend_from_slice(&buf[..n]);
                // The answer has come: read its rest.
                s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
                let _ = s.read_to_end(&mut raw);
                break;
            }
            Err(_) => assert!(started.elapsed() < Duration::from_secs(30), "no answer to a trickled body"),
        }
    }
    let text = String::from_utf8_lossy(&raw).to_string();
    let status = text.get(9..12).and_then(|c| c.parse().ok()).unwrap_or(0);
    (status, text, started.elapsed())
}

/// Twenty clients trickle bodies at 5 bytes/s into a service of two job
/// slots (one computing, one waiting). Each is answered 408, with the
/// connection closed, about a grace after it began; meanwhile a POST sent
/// by another client is answered 201 each time (a trickled body holds no
/// slot: before, the first two took both and every other POST was 503).
#[test]
fn trickled_bodies_hold_no_slot_and_are_let_go() {
    let service = Service::start(&[("MECHDYN_JOBS", "1"), ("MECHDYN_QUEUE", "1")]);
    let port = service.1;
    let body = request("p103_slider").to_string();
    let trickling: Vec<_> = (0..20)
        .map(|_| {
            let body = body.clone();
            std::thread::spawn(move || trickle(port, &body))
        })
        .collect();
    std::thread::sleep(Duration::from_millis(300));
    for _ in 0..5 {
        let (status, text) = http(port, "POST", "/v1/flywheel", &body).unwrap();
        assert_eq!(status, 201, "a POST while 20 bodies trickle: {text}");
    }
    for t in trickling {
        let (status, text, took) = t.join().unwrap();
        assert_eq!(status, 408, "{text}");
        assert!(text.to_ascii_lowercase().contains("connection: close"), "{text}");
        assert!(text.contains("/problems/request-timeout"), "{text}");
        // The grace (1 s) and the 30-odd bytes sent in it at 32 KiB/s, with the machine's margin
        // (a trickle through, at 5 bytes/s, would take hours).
        assert!(took < Duration::from_secs(8), "let go after {took:?}");
    }
}

/// A connection whose receive buffer is `bytes`, so that the service's
/// writes wait on it as on a slow network.
fn narrow(port: u16, bytes: u32) -> TcpStream {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let stream = rt.block_on(async {
        let socket = tokio::net::TcpSocket::new_v4().unwrap();
        socket.set_recv_buffer_size(bytes).unwrap();
        socket.connect(([127, 0, 0, 1], port).into()).await.unwrap()
    });
    let stream = stream.into_std().unwrap();
    stream.set_nonblocking(false).unwrap();
    stream
}

/// Reads a GET of `path` at about 1 KB/s: the bytes read before the
/// service closed the connection, and how long it took (None: it was still
/// open after `limit`).
fn read_slowly(port: u16, path: &str, limit: Duration) -> (usize, Option<Duration>) {
    let mut s = narrow(port, 4096);
    s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
    write!(s, "GET {path} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n").unwrap();
    let started = Instant::now();
    let mut read = 0;
    while started.elapsed() < limit {
        let mut buf = [0u8; 100];
        match s.read(&mut buf) {
            Ok(0) | Err(_) => return (read, Some(started.elapsed())),
            Ok(n) => read += n,
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    (read, None)
}

/// Ten clients read a 6 MB job at 1 KB/s from a service whose answer memory
/// holds four such reads (`MECHDYN_ANSWER_MEMORY_BYTES`). Each is let go
/// within seconds, long before its answer could end (100 minutes at that
/// rate), and meanwhile a POST and the jobs list are answered (before, the
/// ten held the answer memory and both were 503 for as long as they read).
#[test]
fn slow_readers_are_let_go_and_others_are_served() {
    let service = Service::start(&[("MECHDYN_ANSWER_MEMORY_BYTES", "80000000")]);
    let port = service.1;
    let mut large = request("p113_pulley");
    large["samples"] = 60_000.into();
    let (status, text) = http(port, "POST", "/v1/flywheel", &large.to_string()).unwrap();
    assert_eq!(status, 201, "{text}");
    let job: Value = serde_json::from_str(&text).unwrap();
    assert!(text.len() > 5_000_000, "the job is {} bytes, not large", text.len());
    let path = format!("/v1/jobs/{}", job["id"].as_str().unwrap());
    let readers: Vec<_> = (0..10)
        .map(|_| {
            let path = path.clone();
            std::thread::spawn(move || read_slowly(port, &path, Duration::from_secs(60)))
        })
        .collect();
    std::thread::sleep(Duration::from_millis(500));
    let light = request("p103_slider").to_string();
    for _ in 0..3 {
        let (status, text) = http(port, "POST", "/v1/flywheel", &light).unwrap();
        assert_eq!(status, 201, "a POST while ten clients read slowly: {text}");
        let (status, text) = http(port, "GET", "/v1/jobs?limit=2", "").unwrap();
        assert_eq!(status, 200, "the jobs list while ten clients read slowly: {}", &text[..text.len().min(300)]);
    }
    for r in readers {
        let (read, closed) = r.join().unwrap();
        let took = closed.expect("a slow reader still connected after 60 s");
        assert!(read < text.len(), "a slow reader read the whole answer ({read} bytes)");
        // The kernel's buffers fill first, then the grace (1 s) and what the client took at 32 KiB/s.
        assert!(took < Duration::from_secs(20), "let go after {took:?}");
    }
}

/// A client that takes its answer faster than the pace gets all of it,
/// however slow beside loopback: here 4 times the minimal rate (set to
/// 64 KiB/s), on a connection that buffers 64 KiB, a 3.5 MB answer over
/// about 14 s. (The service's sockets hold at most 64 KiB unsent,
/// `TCP_NOTSENT_LOWAT`, so that it sees such a reader's progress often; on
/// loopback the kernel's send buffer stays small and wakes it often anyway,
/// so this guards the rule, not that setting.)
#[test]
fn a_reader_above_the_pace_gets_its_whole_answer() {
    let service = Service::start(&[("MECHDYN_CLIENT_MIN_RATE", "65536")]);
    let port = service.1;
    let mut large = request("p113_pulley");
    large["samples"] = 25_000.into();
    let (status, text) = http(port, "POST", "/v1/flywheel", &large.to_string()).unwrap();
    assert_eq!(status, 201, "{text}");
    let id = serde_json::from_str::<Value>(&text).unwrap()["id"].as_str().unwrap().to_string();
    let mut s = narrow(port, 64 << 10);
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    write!(s, "GET /v1/jobs/{id} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n").unwrap();
    // 25.6 kB every 100 ms: 256 kB/s.
    let mut raw = Vec::new();
    loop {
        let mut chunk = vec![0u8; 25_600];
        match s.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => raw.extend_from_slice(&chunk[..n]),
            Err(e) => panic!("the reader was let go after {} bytes: {e}", raw.len()),
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let answer = String::from_utf8_lossy(&raw);
    let body = answer.split_once("\r\n\r\n").map(|(_, b)| b).unwrap_or_default();
    assert!(body.len() > 2_000_000, "a large answer: {} bytes", body.len());
    let job: Value =
        serde_json::from_str(body).unwrap_or_else(|e| panic!("the answer ends early ({e}): {} bytes", body.len()));
    assert_eq!(job["id"], id.as_str());
}
