//! Bodies of answers and requests, with their memory in mind.
//!
//! - [`Chunks`]: an answer made of shared pieces (`Bytes`): a stored job's
//!   request and result are sent as they are stored, framed by a few bytes of
//!   JSON, never copied into one buffer.
//! - [`Guarded`]: any body holding a reservation (a semaphore permit) that is
//!   released when the body is dropped, i.e. once it has been sent or the
//!   client has gone, so admission control counts answers until they leave.
//! - [`drain`]: reads and discards what a client is still sending before a
//!   refusal (413, 503) is answered, so that clients that write their whole
//!   body before reading (Python's urllib) read the answer instead of a
//!   broken pipe. Bounded in bytes and time. [`drain_unread`] does it for
//!   every answer given before its request's body was read (401, 404, 405,
//!   415, a query's 400).

use axum::body::Body;
use axum::extract::Request;
use axum::http::header;
use axum::middleware::Next;
use axum::response::Response;
use bytes::Bytes;
use http_body::{Frame, SizeHint};
use http_body_util::BodyExt;
use std::collections::VecDeque;
use std::convert::Infallible;
use std::pin::Pin;
use std::sync::{Arc, Mutex};
use std::task::{Context, Poll};
use std::time::Duration;
use tokio::sync::OwnedSemaphorePermit;

/// Most bytes read and discarded from a refused request.
pub const DRAIN_MAX: u64 = 64 << 20;
/// Longest time spent discarding a refused request.
pub const DRAIN_TIME: Duration = Duration::from_secs(10);

/// An answer body of shared pieces, sent in order.
#[derive(Default)]
pub struct Chunks {
    parts: VecDeque<Bytes>,
    len: u64,
}

impl Chunks {
    pub fn push(&mut self, part: impl Into<Bytes>) {
        let part = part.into();
        self.len += part.len() as u64;
        if !part.is_empty() {
            self.parts.push_back(part);
        }
    }

    /// Bytes in all.
    pub fn len(&self) -> u64 {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl http_body::Body for Chunks {
    type Data = Bytes;
    type Error = Infallible;

    fn poll_frame(mut self: Pin<&mut Self>, _: &mut Context<'_>) -> Poll<Option<Result<Frame<Bytes>, Infallible>>> {
        let part = self.parts.pop_front();
        if let Some(p) = &part {
            self.len -= p.len() as u64;
        }
        Poll::Ready(part.map(|p| Ok(Frame::data(p))))
    }

    fn is_end_stream(&self) -> bool {
        self.parts.is_empty()
    }

    fn size_hint(&self) -> SizeHint {
        SizeHint::with_exact(self.len)
    }
}

/// A body that holds `permit` until it is dropped.
pub struct Guarded<B> {
    inner: B,
    _permit: OwnedSemaphorePermit,
}

impl<B> Guarded<B> {
    pub fn new(inner: B, permit: OwnedSemaphorePermit) -> Self {
        Self { inner, _permit: permit }
    }
}

impl<B: http_body::Body + Unpin> http_body::Body for Guarded<B> {
    type Data = B::Data;
    type Error = B::Error;

    fn poll_frame(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Option<Result<Frame<B::Data>, B::Error>>> {
        Pin::new(&mut self.inner).poll_frame(cx)
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

/// `body` holding `permit` until it is dropped.
pub fn guarded(body: Body, permit: OwnedSemaphorePermit) -> Body {
    Body::new(Guarded::new(body, permit))
}

/// Reads and discards the rest of a request body, up to [`DRAIN_MAX`] bytes
/// and [`DRAIN_TIME`]; a body announced larger than that is left alone.
pub async fn drain(mut body: Body, announced: Option<u64>) {
    if announced.is_some_and(|n| n > DRAIN_MAX) {
        return;
    }
    let discard = async {
        let mut read = 0u64;
        while read <= DRAIN_MAX {
            match body.frame().await {
                Some(Ok(frame)) => read += frame.data_ref().map_or(0, |d| d.len() as u64),
                _ => break,
            }
        }
    };
    let _ = tokio::time::timeout(DRAIN_TIME, discard).await;
}

/// A request body the middleware can still reach once the handler has
/// dropped its own handle ([`drain_unread`]).
struct Shared(Arc<Mutex<Option<Body>>>);

impl http_body::Body for Shared {
    type Data = Bytes;
    type Error = axum::Error;

    fn poll_frame(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Option<Result<Frame<Bytes>, axum::Error>>> {
        let mut kept = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let polled = kept.as_mut().map_or(Poll::Ready(None), |body| Pin::new(body).poll_frame(cx));
        if matches!(polled, Poll::Ready(None)) {
            // Read to its end: gone, so that nothing polls it again (some bodies panic if polled after their end).
            *kept = None;
        }
        polled
    }

    fn is_end_stream(&self) -> bool {
        self.0.lock().unwrap_or_else(|e| e.into_inner()).as_ref().is_none_or(http_body::Body::is_end_stream)
    }

    fn size_hint(&self) -> SizeHint {
        self.0
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .as_ref()
            .map_or_else(SizeHint::default, http_body::Body::size_hint)
    }
}

/// The middleware: a request answered before its body was read whole has
/// the rest drained ([`drain`]) before its answer is sent, unless the
/// answer closes the connection or the client waits for it before sending
/// (`Expect: 100-continue`).
pub async fn drain_unread(req: Request, next: Next) -> Response {
    // A client that asked `Expect: 100-continue` waits for the final answer
    // before it sends: reading its body would ask it to send what is refused.
    let expects = req.headers().get(header::EXPECT).is_some_and(|v| v.as_bytes().eq_ignore_ascii_case(b"100-continue"));
    if expects || http_body::Body::is_end_stream(req.body()) {
        return next.run(req).await;
    }
    let (parts, body) = req.into_parts();
    let kept = Arc::new(Mutex::new(Some(body)));
    let response = next.run(Request::from_parts(parts, Body::new(Shared(kept.clone())))).await;
    let rest = kept.lock().unwrap_or_else(|e| e.into_inner()).take();
    // An answer that closes the connection (a body too slow to wait for) is sent at once.
    let closing =
        response.headers().get(header::CONNECTION).is_some_and(|v| v.as_bytes().eq_ignore_ascii_case(b"close"));
    if let Some(body) = rest.filter(|b| !closing && !http_body::Body::is_end_stream(b)) {
        let left = http_body::Body::size_hint(&body).exact();
        drain(body, left).await;
    }
    response
}
