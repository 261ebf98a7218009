//! The connections: the service's own accept loop over hyper's HTTP/1.1
//! server (axum::serve gives hyper no timer, so no head ever had a bound,
//! and it has no cap on connections: 20 000 connections trickling a header
//! byte every 10 s took every file descriptor and every other client).
//!
//! - **Heads** (`header`): a connection's request head must be whole within
//!   `header` of the connection's start (its first request) or of the
//!   head's first byte (a later one), else the connection is closed.
//! - **Idle** (`idle`): a keep-alive connection that has sent no byte of a
//!   next request for `idle` since its last answer is closed.
//! - **Cap** (`max`): at most `max` connections are held (below the file
//!   descriptors the process may open); a connection beyond them is answered
//!   503 at once — a problem document, `Connection: close` — and closed.
//! - An accept that fails (descriptors exhausted by others) pauses the loop
//!   10 ms, never the second axum::serve waits, and is logged once a second.
//!
//! hyper's own `header_read_timeout` is not used: it runs from the moment
//! hyper starts reading a head, which on a keep-alive connection is the end
//! of the last answer, so it cannot tell a connection idle for 30 s (allowed
//! 60) from a head trickled for 30 s (allowed 10). Each connection's phase —
//! its first head awaited, a head arriving, a request in flight, idle — is
//! kept by its reader (a byte after idleness starts a head), its service (a
//! request starts) and its answer's body (dropped when sent), and a task per
//! connection closes it when its phase's bound passes. The answer's and the
//! body's pace are [`super::pace`]'s.

use super::metrics::Metrics;
use super::pace::{Pace, Paced};
use axum::Router;
use axum::body::Body;
use axum::http::{Request, Response};
use bytes::Bytes;
use http_body::{Body as HttpBody, Frame, SizeHint};
use hyper::body::Incoming;
use hyper_util::rt::TokioIo;
use std::convert::Infallible;
use std::future::Future;
use std::io;
use std::pin::Pin;
use std::sync::Arc;
use std::sync::atomic::{AtomicU8, AtomicU64, Ordering};
use std::task::{Context, Poll};
use std::time::Duration;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{Notify, Semaphore, watch};
use tokio::time::Instant;

/// A listener bound (with its name in the metrics) and how it serves.
pub type Operator = ((TcpListener, &'static str), (Bounds, Pace, Metrics));

/// The bounds of a listener's connections.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Longest a request head may take.
    pub header: Duration,
    /// Longest a keep-alive connection may stay idle.
    pub idle: Duration,
    /// Most connections held at once.
    pub max: usize,
}

impl Default for Bounds {
    fn default() -> Self {
        Self { header: Duration::from_secs(10), idle: Duration::from_secs(60), max: 1024 }
    }
}

/// Serves `app` on `listener` (named `name` in the metrics) within
/// `bounds`, each connection's writes held to `pace`, until `stop`
/// resolves; then accepts no more, closes the idle connections, and
/// returns once those with a request have answered.
pub async fn serve(
    (listener, name): (TcpListener, &'static str),
    app: Router,
    (bounds, pace, metrics): (Bounds, Pace, Metrics),
    stop: impl Future<Output = ()>,
) {
    metrics.listener(name);
    let places = Arc::new(Semaphore::new(bounds.max.clamp(1, Semaphore::MAX_PERMITS)));
    let (stopping, stopped) = watch::channel(false);
    let full = full_answer(bounds.max);
    let mut last_error = None::<Instant>;
    tokio::pin!(stop);
    loop {
        let accepted = tokio::select! {
            () = &mut stop => break,
            accepted = listener.accept() => accepted,
        };
        let stream = match accepted {
            Ok((stream, _)) => stream,
            Err(e) => {
                if last_error.is_none_or(|t| t.elapsed() > Duration::from_secs(1)) {
                    tracing::error!(error = %e, "accept failed; the service goes on accepting");
                    last_error = Some(Instant::now());
                }
                // Out of descriptors or buffers, another accept now would fail again.
                tokio::time::sleep(Duration::from_millis(10)).await;
                continue;
            }
        };
        let Ok(place) = places.clone().try_acquire_owned() else {
            metrics.connection_refused(name);
            refuse(&stream, &full);
            continue;
        };
        let (app, metrics, stopped) = (app.clone(), metrics.clone(), stopped.clone());
        tokio::spawn(async move {
            metrics.connections(name, 1);
            let closed = connection(stream, app, (bounds, pace), stopped).await;
            if let Some(why) = closed {
                metrics.connection_closed(name, why.reason());
            }
            metrics.connections(name, -1);
            drop(place);
        });
    }
    let _ = stopping.send(true);
    // Every place back: every connection closed.
    let _ = places.acquire_many(bounds.max.clamp(1, Semaphore::MAX_PERMITS) as u32).await;
}

/// Connections the kernel may hold for the accept loop (clamped to
/// `net.core.somaxconn`, 4096 on current Linux). tokio's own bind asks for
/// 1024: a burst beyond it is dropped at the handshake and its clients wait
/// for the SYN-ACK's retransmissions (1, 3, 7, 15 s), a loaded machine's
/// 2 000 connects arriving seconds late.
const BACKLOG: u32 = 4096;

/// Binds `addr` (a socket address or `host:port`, its first address) with
/// the [`BACKLOG`], SO_REUSEADDR set as tokio's bind does.
pub async fn bind(addr: &str) -> io::Result<TcpListener> {
    let mut last = io::Error::new(io::ErrorKind::InvalidInput, "no address");
    for at in tokio::net::lookup_host(addr).await? {
        let socket = if at.is_ipv4() { tokio::net::TcpSocket::new_v4()? } else { tokio::net::TcpSocket::new_v6()? };
        socket.set_reuseaddr(true)?;
        match socket.bind(at).and_then(|()| socket.listen(BACKLOG)) {
            Ok(listener) => return Ok(listener),
            Err(e) => last = e,
        }
    }
    Err(last)
}

/// The file descriptors the process may open, its soft limit first raised
/// to its hard one (as Go's runtime does; a container's is often 1 024 of
/// 1 048 576); None where it cannot be read, `u64::MAX` where unlimited.
pub fn open_files() -> Option<u64> {
    use rustix::process::{Resource, Rlimit, getrlimit, setrlimit};
    let limit = getrlimit(Resource::Nofile);
    let raised = Rlimit { current: limit.maximum, maximum: limit.maximum };
    let limit =
        if limit.current != limit.maximum && setrlimit(Resource::Nofile, raised).is_ok() { raised } else { limit };
    Some(limit.current.unwrap_or(u64::MAX))
}

/// The 503 of a connection beyond the cap, made once: a problem document.
fn full_answer(max: usize) -> Bytes {
    let problem = crate::kind::problem::ApiError::Saturated {
        reason: crate::i18n::Msg::new("saturated-connections").arg("max", max),
        retry_after: 1,
    }
    .problem();
    let body = serde_json::to_string(&problem).unwrap_or_default();
    let head = format!(
        "HTTP/1.1 503 Service Unavailable\r\ncontent-type: application/problem+json\r\nretry-after: 1\r\n\
         connection: close\r\ncontent-length: {}\r\n\r\n",
        body.len()
    );
    Bytes::from(head + &body)
}

/// A connection beyond the cap: what it has sent read (so its close is no
/// reset where it can be helped), the 503 written, and closed — at once, the
/// accept loop never waits on it.
fn refuse(stream: &TcpStream, full: &[u8]) {
    let mut sent = [0u8; 4096];
    let _ = stream.try_read(&mut sent);
    let _ = stream.try_write(full);
}

/// Where a connection is in its life, kept by its reader, service and answers.
struct Clock {
    /// [`FIRST`], [`IDLE`], [`HEAD`] or [`BUSY`].
    phase: AtomicU8,
    /// When the phase began, µs after `start`.
    since: AtomicU64,
    start: Instant,
    changed: Notify,
}

/// The first request's head awaited (since the connection began).
const FIRST: u8 = 0;
/// No byte of a next request since the last answer.
const IDLE: u8 = 1;
/// A later request's head arriving.
const HEAD: u8 = 2;
/// A request in flight: its body, its computation, its answer.
const BUSY: u8 = 3;

/// Why a connection was closed by its bounds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Closed {
    Header,
    Idle,
}

impl Closed {
    /// The reason as the metrics name it.
    pub fn reason(self) -> &'static str {
        match self {
            Self::Header => "header",
            Self::Idle => "idle",
        }
    }
}

impl Clock {
    fn new() -> Self {
        Self { phase: AtomicU8::new(FIRST), since: AtomicU64::new(0), start: Instant::now(), changed: Notify::new() }
    }

    fn set(&self, phase: u8) {
        let now = u64::try_from(self.start.elapsed().as_micros()).unwrap_or(u64::MAX);
        self.since.store(now, Ordering::Release);
        self.phase.store(phase, Ordering::Release);
        self.changed.notify_one();
    }

    /// When the present phase's bound passes, and why (none while busy).
    fn deadline(&self, b: &Bounds) -> Option<(Instant, Closed)> {
        let since = self.start + Duration::from_micros(self.since.load(Ordering::Acquire));
        match self.phase.load(Ordering::Acquire) {
            FIRST => Some((self.start + b.header, Closed::Header)),
            HEAD => Some((since + b.header, Closed::Header)),
            IDLE => Some((since + b.idle, Closed::Idle)),
            _ => None,
        }
    }
}

/// Serves one connection until it ends, or is closed by its bounds (why).
async fn connection(
    stream: TcpStream,
    app: Router,
    (bounds, pace): (Bounds, Pace),
    mut stopped: watch::Receiver<bool>,
) -> Option<Closed> {
    let clock = Arc::new(Clock::new());
    let io = Watched { inner: Paced::new(stream, pace), clock: clock.clone() };
    let service = Tracked { app, clock: clock.clone() };
    let conn = hyper::server::conn::http1::Builder::new().keep_alive(true).serve_connection(TokioIo::new(io), service);
    tokio::pin!(conn);
    let mut draining = false;
    loop {
        let deadline = clock.deadline(&bounds);
        let bound = async {
            match deadline {
                Some((at, _)) => tokio::time::sleep_until(at).await,
                None => std::future::pending().await,
            }
        };
        tokio::select! {
            _ = conn.as_mut() => return None,
            () = bound => {
                // Closed (dropped) unless the phase moved on meanwhile.
                if let Some((_, why)) = clock.deadline(&bounds).filter(|(at, _)| *at <= Instant::now()) {
                    return Some(why);
                }
            }
            () = clock.changed.notified() => {}
            _ = stopped.changed(), if !draining => {
                conn.as_mut().graceful_shutdown();
                draining = true;
            }
        }
    }
}

/// A connection's reading side: a byte after idleness starts a head.
struct Watched {
    inner: Paced,
    clock: Arc<Clock>,
}

impl AsyncRead for Watched {
    fn poll_read(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let before = buf.filled().len();
        let read = Pin::new(&mut this.inner).poll_read(cx, buf);
        if buf.filled().len() > before && this.clock.phase.load(Ordering::Acquire) == IDLE {
            this.clock.set(HEAD);
        }
        read
    }
}

impl AsyncWrite for Watched {
    fn poll_write(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        Pin::new(&mut self.get_mut().inner).poll_write(cx, buf)
    }
    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        Pin::new(&mut self.get_mut().inner).poll_write_vectored(cx, bufs)
    }
    fn is_write_vectored(&self) -> bool {
        self.inner.is_write_vectored()
    }
    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_flush(cx)
    }
    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_shutdown(cx)
    }
}

/// The router as a connection's service: a request makes the connection busy.
#[derive(Clone)]
struct Tracked {
    app: Router,
    clock: Arc<Clock>,
}

type Answer = Pin<Box<dyn Future<Output = Result<Response<Sent>, Infallible>> + Send>>;

impl hyper::service::Service<Request<Incoming>> for Tracked {
    type Response = Response<Sent>;
    type Error = Infallible;
    type Future = Answer;

    fn call(&self, req: Request<Incoming>) -> Self::Future {
        self.clock.set(BUSY);
        let (mut app, clock) = (self.app.clone(), self.clock.clone());
        Box::pin(async move {
            let response = tower_service::Service::call(&mut app, req.map(Body::new)).await?;
            Ok(response.map(|body| Sent { body, clock: Some(clock) }))
        })
    }
}

/// An answer's body: once sent (or dropped with its connection), the
/// connection is idle.
struct Sent {
    body: Body,
    clock: Option<Arc<Clock>>,
}

impl Drop for Sent {
    fn drop(&mut self) {
        if let Some(clock) = self.clock.take() {
            clock.set(IDLE);
        }
    }
}

impl HttpBody for Sent {
    type Data = Bytes;
    type Error = axum::Error;

    fn poll_frame(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Option<Result<Frame<Bytes>, Self::Error>>> {
        Pin::new(&mut self.get_mut().body).poll_frame(cx)
    }
    fn is_end_stream(&self) -> bool {
        self.body.is_end_stream()
    }
    fn size_hint(&self) -> SizeHint {
        self.body.size_hint()
    }
}
