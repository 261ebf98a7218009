//! The pace a client must keep: a request's body must arrive, and an answer
//! must be taken, at a minimal rate once a grace period has passed. A client
//! that trickles a body or reads an answer a byte at a time would otherwise
//! hold what the service keeps for it (the body read so far, the answer's
//! memory, a place in admission control) for as long as it likes.
//!
//! The rule, in both directions: while the service waits on a client, by
//! `t` seconds into the wait it must have moved `rate × (t − grace)` bytes.
//! - **Bodies** ([`read_body`]): the wait starts with the request; a body
//!   behind the pace is answered `408` and its connection closed.
//! - **Answers** ([`Paced`], the connection's writing side, through
//!   [`PacedListener`]): a wait starts when the connection cannot take
//!   more (the kernel holds [`NOT_SENT`] bytes unsent) and ends when a
//!   write goes through whole; bytes the kernel took before the first wait
//!   do not count. A client behind the pace has its connection reset,
//!   which drops the answer and everything it held, the kernel's buffers
//!   included. An answer small enough for the kernel's buffers is never
//!   waited on: the kernel holds it, the service holds nothing.
//!
//! Headers are not paced here: a connection sending only headers holds no
//! body, no slot and no answer (3 000 such connections, in an attack on the
//! service, slowed nothing).

use super::admission::Admission;
use crate::i18n::Msg;
use crate::kind::problem::ApiError;
use axum::body::Body;
use bytes::{Bytes, BytesMut};
use http_body_util::BodyExt;
use std::future::Future;
use std::io;
use std::pin::Pin;
use std::task::{Context, Poll};
use std::time::Duration;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::OwnedSemaphorePermit;
use tokio::time::{Instant, Sleep};

/// The minimal pace of a client.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pace {
    /// Bytes per second, on average over a wait, after the grace.
    pub rate: u64,
    /// How long a wait may last before the rate applies.
    pub grace: Duration,
}

impl Default for Pace {
    /// 32 KiB/s (256 kbit/s, below any working link) after 5 s: a client
    /// that stops is let go within seconds, while others waiting for what
    /// it held (answer memory waits up to 10 s) are served.
    fn default() -> Self {
        Self { rate: 32 << 10, grace: Duration::from_secs(5) }
    }
}

impl Pace {
    /// How long a wait may last once `moved` bytes have moved in it.
    pub fn allowance(&self, moved: u64) -> Duration {
        self.grace + Duration::from_secs_f64(moved as f64 / self.rate.max(1) as f64)
    }
}

/// Reads a request's whole body, at most `limit` bytes, at `pace`, each
/// piece of it reserved in the bodies' budget as it arrives (a client that
/// sends nothing holds nothing): the bytes; 413 beyond the limit, 408 behind
/// the pace, 503 when the budget stays full. The rest of a refused body is
/// drained by [`super::body::drain_unread`].
pub async fn read_body(body: Body, limit: usize, pace: Pace, admission: &Admission) -> Result<Bytes, ApiError> {
    let started = Instant::now();
    let timer = tokio::time::sleep_until(started + pace.grace);
    tokio::pin!(timer);
    let mut body = body;
    let (mut buf, mut held) = (BytesMut::new(), None::<OwnedSemaphorePermit>);
    loop {
        let frame = tokio::select! {
            frame = body.frame() => frame,
            () = &mut timer => return Err(behind(buf.len(), started.elapsed(), pace)),
        };
        let Some(frame) = frame else { return Ok(buf.freeze()) };
        let frame = frame.map_err(|e| ApiError::MalformedJson(Msg::new("json-unreadable").arg("why", e)))?;
        if let Some(data) = frame.data_ref() {
            if buf.len() + data.len() > limit {
                return Err(ApiError::PayloadTooLarge(limit));
            }
            let more = admission.body(data.len()).await?;
            match held.as_mut() {
                Some(h) => h.merge(more),
                None => held = Some(more),
            }
            buf.extend_from_slice(data);
            timer.as_mut().reset(started + pace.allowance(buf.len() as u64));
        }
    }
}

/// The 408 of a body that fell behind the pace.
fn behind(read: usize, after: Duration, pace: Pace) -> ApiError {
    let said = Msg::new("detail-request-timeout")
        .count("read", read)
        .num("seconds", (after.as_secs_f64() * 10.0).round() / 10.0);
    ApiError::RequestTimeout(said.arg("rate", pace.rate).num("grace", pace.grace.as_secs_f64()))
}

/// A connection whose writing side is held to a [`Pace`].
pub struct Paced {
    inner: TcpStream,
    pace: Pace,
    /// The wait now: when it began and the bytes the client took since.
    waiting: Option<(Instant, u64)>,
    timer: Pin<Box<Sleep>>,
}

impl Paced {
    pub fn new(inner: TcpStream, pace: Pace) -> Self {
        Self { inner, pace, waiting: None, timer: Box::pin(tokio::time::sleep(Duration::ZERO)) }
    }

    /// `n` bytes written of the `asked`.
    fn wrote(&mut self, n: usize, asked: usize) {
        match &mut self.waiting {
            _ if n == asked => self.waiting = None,
            Some((_, taken)) => *taken += n as u64,
            None => {}
        }
    }

    /// The connection cannot take more now: within the pace, wait (woken by
    /// the socket or the deadline); behind it, the connection's end.
    fn wait(&mut self, cx: &mut Context<'_>) -> Poll<io::Result<usize>> {
        let now = Instant::now();
        let (since, taken) = *self.waiting.get_or_insert((now, 0));
        let deadline = since + self.pace.allowance(taken);
        if now < deadline {
            self.timer.as_mut().reset(deadline);
            if self.timer.as_mut().poll(cx).is_pending() {
                return Poll::Pending;
            }
        }
        let why = format!(
            "the client took {taken} bytes of its answer in {:.1} s, under {} bytes/s once {} s had passed",
            (now - since).as_secs_f64(),
            self.pace.rate,
            self.pace.grace.as_secs_f64()
        );
        tracing::warn!("{why}: connection closed");
        // Closed with a reset: what the kernel still holds for the client goes too.
        let _ = self.inner.set_zero_linger();
        Poll::Ready(Err(io::Error::new(io::ErrorKind::TimedOut, why)))
    }
}

impl AsyncRead for Paced {
    fn poll_read(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_read(cx, buf)
    }
}

impl AsyncWrite for Paced {
    fn poll_write(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        match Pin::new(&mut this.inner).poll_write(cx, buf) {
            Poll::Ready(Ok(n)) => {
                this.wrote(n, buf.len());
                Poll::Ready(Ok(n))
            }
            Poll::Pending => this.wait(cx),
            failed => failed,
        }
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        match Pin::new(&mut this.inner).poll_write_vectored(cx, bufs) {
            Poll::Ready(Ok(n)) => {
                this.wrote(n, bufs.iter().map(|b| b.len()).sum());
                Poll::Ready(Ok(n))
            }
            Poll::Pending => this.wait(cx),
            failed => failed,
        }
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

/// Bytes of an answer the kernel holds unsent for a connection
/// (`TCP_NOTSENT_LOWAT`): a write waits once that much is queued, so a
/// reader's progress is seen every few KB. Without it Linux wakes a writer
/// only when half of a send buffer, autotuned up to 4 MiB, has drained:
/// on a slow network link that can be longer than the grace for a client
/// reading above the pace. And a reader behind the pace holds little in
/// the kernel.
const NOT_SENT: u32 = 64 << 10;

/// A TCP listener whose connections are [`Paced`].
pub struct PacedListener {
    inner: TcpListener,
    pace: Pace,
}

impl PacedListener {
    pub fn new(inner: TcpListener, pace: Pace) -> Self {
        Self { inner, pace }
    }
}

impl axum::serve::Listener for PacedListener {
    type Io = Paced;
    type Addr = std::net::SocketAddr;

    async fn accept(&mut self) -> (Self::Io, Self::Addr) {
        let (stream, addr) = axum::serve::Listener::accept(&mut self.inner).await;
        #[cfg(any(target_os = "linux", target_os = "android"))]
        if let Err(e) = socket2::SockRef::from(&stream).set_tcp_notsent_lowat(NOT_SENT) {
            tracing::warn!(error = %e, "TCP_NOTSENT_LOWAT not set: a slow reader is seen only once its send buffer drains");
        }
        (Paced::new(stream, self.pace), addr)
    }

    fn local_addr(&self) -> io::Result<Self::Addr> {
        self.inner.local_addr()
    }
}
