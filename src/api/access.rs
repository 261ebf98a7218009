//! Who may do what, where the service has an API token (`--api-token`).
//!
//! - **The token** is carried as `Authorization: Bearer <token>`, or, by a
//!   browser that signed in once (`/signin`), as the cookie [`COOKIE`]:
//!   the time of the sign-in and its signature by the token (HMAC-SHA-256
//!   of [`SALT`] and that time), `HttpOnly` (no script reads it) and
//!   `SameSite=Strict` (no other site's page sends it). The token itself is
//!   never stored in the browser; every replica with the same token reads
//!   the cookie; it is refused past [`COOKIE_SECONDS`] whatever the browser
//!   keeps, and all of them at once when the token changes.
//! - **Writes** (every POST and DELETE but the sign-in's) need it.
//! - **Stored jobs are the holders'**: the job list, a job, its parts, CSV,
//!   plots, files and page answer 401 without it, unless the service was
//!   started with `--public-jobs` (a public demonstration). A template's
//!   values, variants and form stay public: a spreadsheet's `WEBSERVICE()`
//!   cannot send a header; they compute within the anonymous share
//!   ([`super::admission`]).
//!
//! Whether the request being answered carries the token is held for its
//! task: [`super::create::may_store`] (a GET may store a new job) and
//! [`jobs_readable`] (the home page lists the recent jobs) read it.

use axum::http::{HeaderMap, HeaderValue, Method, header};
use hmac::{Hmac, KeyInit, Mac};
use sha2::Sha256;
use std::sync::Arc;

/// The sign-in cookie's name.
pub const COOKIE: &str = "mechdyn_session";

/// What a sign-in's signature is salted with: the cookie is worth nothing
/// elsewhere the same token may be used.
const SALT: &str = "mechdyn sign-in cookie v1\0";

/// How long a sign-in lasts, seconds (30 days).
pub const COOKIE_SECONDS: u64 = 30 * 86_400;

/// The token, and whether stored jobs are readable without it.
#[derive(Clone, Debug, Default)]
pub struct Access {
    token: Option<Arc<str>>,
    public_jobs: bool,
}

tokio::task_local! {
    /// Whether the request being answered may read stored jobs.
    static READABLE: bool;
    /// Whether it carries the token, where the service has one.
    static SIGNED: Option<bool>;
}

/// Whether the request being answered may read stored jobs (outside a
/// request — the command line, a deferred job — it may).
pub fn jobs_readable() -> bool {
    READABLE.try_with(|r| *r).unwrap_or(true)
}

/// Whether the request being answered carries the token (a page offers to
/// sign in, or out); None where the service has none.
pub fn signed_in() -> Option<bool> {
    SIGNED.try_with(|s| *s).unwrap_or(None)
}

/// What a request may do, by what it carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Allowed {
    /// It carries the token (or the service has none).
    pub carried: bool,
    /// It may read stored jobs.
    pub jobs: bool,
    /// The service has a token.
    pub token: bool,
}

/// Why a request is refused, if it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refused {
    /// A write without the token.
    Write,
    /// A read of stored jobs without the token.
    Read,
}

impl Access {
    /// `token` (none when empty), stored jobs public or not.
    pub fn new(token: Option<&str>, public_jobs: bool) -> Self {
        Self { token: token.filter(|t| !t.is_empty()).map(Arc::from), public_jobs }
    }

    /// Whether the service has a token at all.
    pub fn has_token(&self) -> bool {
        self.token.is_some()
    }

    /// What a request of `method` at `path` with `headers` may do, or why it is refused.
    pub fn allow(&self, method: &Method, path: &str, headers: &HeaderMap) -> Result<Allowed, Refused> {
        let carried = self.carries(headers);
        let jobs = carried || self.public_jobs;
        let signing = matches!(path, "/signin" | "/signout");
        if !carried && !matches!(*method, Method::GET | Method::HEAD | Method::OPTIONS) && !signing {
            return Err(Refused::Write);
        }
        if !jobs && is_private(path) {
            return Err(Refused::Read);
        }
        Ok(Allowed { carried, jobs, token: self.has_token() })
    }

    /// Whether `headers` carry the token, as a bearer or as the sign-in cookie.
    pub fn carries(&self, headers: &HeaderMap) -> bool {
        let Some(token) = &self.token else { return true };
        bearer_matches(headers.get(header::AUTHORIZATION), token)
            || cookie(headers).is_some_and(|c| signed_recently(token, &c, now()))
    }

    /// Whether `given` is the token (a sign-in form's field).
    pub fn is_token(&self, given: &str) -> bool {
        self.token.as_deref().is_some_and(|t| same(given.trim().as_bytes(), t.as_bytes()))
    }

    /// The `Set-Cookie` of a sign-in now (`secure`: the request came over HTTPS).
    pub fn sign_in_cookie(&self, secure: bool) -> Option<HeaderValue> {
        let token = self.token.as_deref()?;
        let secure = if secure { "; Secure" } else { "" };
        let value = signed(token, now());
        let text = format!("{COOKIE}={value}; Path=/; Max-Age={COOKIE_SECONDS}; HttpOnly; SameSite=Strict{secure}");
        HeaderValue::from_str(&text).ok()
    }
}

/// The `Set-Cookie` that ends a sign-in.
pub fn sign_out_cookie() -> HeaderValue {
    HeaderValue::from_static("mechdyn_session=; Path=/; Max-Age=0; HttpOnly; SameSite=Strict")
}

/// Runs `answer` with what its request may do held for its task.
pub async fn within<F: std::future::Future>(allowed: Allowed, answer: F) -> F::Output {
    let signed = allowed.token.then_some(allowed.carried);
    let answer = super::create::MAY_STORE.scope(allowed.carried, SIGNED.scope(signed, answer));
    READABLE.scope(allowed.jobs, answer).await
}

/// The routes of stored jobs: the list and everything under a job, the
/// job's pages, and a template's job (a stored job's id and result).
pub fn is_private(path: &str) -> bool {
    let path = path.trim_end_matches('/');
    path == "/v1/jobs"
        || path.starts_with("/v1/jobs/")
        || path.starts_with("/jobs/")
        || path.strip_prefix("/v1/templates/").is_some_and(|rest| rest.ends_with("/job"))
}

/// Whether a request arrived over HTTPS, as a proxy in front says.
pub fn over_https(headers: &HeaderMap) -> bool {
    headers.get("x-forwarded-proto").and_then(|v| v.to_str().ok()).is_some_and(|p| p.eq_ignore_ascii_case("https"))
}

/// Seconds since 1970, now.
fn now() -> u64 {
    std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs())
}

/// A sign-in at `at` (seconds since 1970) as the cookie carries it:
/// `at.signature`, the signature HMAC-SHA-256 by the token, in hexadecimal.
fn signed(token: &str, at: u64) -> String {
    format!("{at}.{}", signature(token, at))
}

fn signature(token: &str, at: u64) -> String {
    let mut mac = <Hmac<Sha256> as KeyInit>::new_from_slice(token.as_bytes()).expect("HMAC takes a key of any length");
    mac.update(SALT.as_bytes());
    mac.update(at.to_string().as_bytes());
    mac.finalize().into_bytes().iter().map(|b| format!("{b:02x}")).collect()
}

/// Whether `cookie` is a sign-in by `token` at most [`COOKIE_SECONDS`]
/// before `now` (and not more than a minute after it: replicas' clocks).
fn signed_recently(token: &str, cookie: &str, now: u64) -> bool {
    let Some((at, given)) = cookie.split_once('.') else { return false };
    let Ok(at) = at.parse::<u64>() else { return false };
    let fresh = at <= now.saturating_add(60) && now.saturating_sub(at) <= COOKIE_SECONDS;
    fresh && same(given.as_bytes(), signature(token, at).as_bytes())
}

/// The sign-in cookie's value among a request's cookies.
fn cookie(headers: &HeaderMap) -> Option<String> {
    headers.get_all(header::COOKIE).iter().filter_map(|v| v.to_str().ok()).flat_map(|v| v.split(';')).find_map(|c| {
        let (name, value) = c.trim().split_once('=')?;
        (name == COOKIE).then(|| value.trim().to_string())
    })
}

/// `a == b`, in time independent of where they differ.
fn same(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0u8, |acc, (x, y)| acc | (x ^ y)) == 0
}

/// `Authorization: Bearer <token>`, compared in time independent of where it differs.
/// The scheme's name is case-insensitive and may be followed by several
/// spaces (RFC 9110, 11.1 and 11.4).
fn bearer_matches(value: Option<&HeaderValue>, token: &str) -> bool {
    let Some((scheme, given)) = value.and_then(|v| v.to_str().ok()).and_then(|v| v.split_once(' ')) else {
        return false;
    };
    scheme.eq_ignore_ascii_case("bearer") && same(given.trim_start_matches(' ').as_bytes(), token.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_exact_bearer_token_matches() {
        let v = |s: &str| HeaderValue::from_str(s).unwrap();
        assert!(bearer_matches(Some(&v("Bearer s3cret")), "s3cret"));
        assert!(!bearer_matches(Some(&v("Bearer s3creT")), "s3cret"));
        assert!(!bearer_matches(Some(&v("Bearer s3cret2")), "s3cret"));
        assert!(!bearer_matches(Some(&v("Basic s3cret")), "s3cret"));
        // The scheme in any case, and more than one space after it (RFC 9110).
        assert!(bearer_matches(Some(&v("bearer s3cret")), "s3cret"));
        assert!(bearer_matches(Some(&v("BEARER  s3cret")), "s3cret"));
        assert!(!bearer_matches(Some(&v("Bearers3cret")), "s3cret"));
        assert!(!bearer_matches(Some(&v("Bearer")), "s3cret"));
        assert!(!bearer_matches(None, "s3cret"));
    }

    /// The cookie a sign-in sets carries its time and its signature by the
    /// token, not the token, and is read back among other cookies; another
    /// value is not, nor one signed by another token, nor one of 31 days ago.
    #[test]
    fn the_sign_in_cookie_is_signed_by_the_token_and_expires() {
        let access = Access::new(Some("s3cret"), false);
        let set = access.sign_in_cookie(false).unwrap();
        let set = set.to_str().unwrap();
        assert!(!set.contains("s3cret") && set.contains("HttpOnly") && set.contains("SameSite=Strict"), "{set}");
        let value = set.split(';').next().unwrap();
        let mut headers = HeaderMap::new();
        headers.insert(header::COOKIE, HeaderValue::from_str(&format!("lang=es; {value}")).unwrap());
        assert!(access.carries(&headers));
        headers.insert(header::COOKIE, HeaderValue::from_static("mechdyn_session=s3cret"));
        assert!(!access.carries(&headers));
        let day = 86_400;
        assert!(signed_recently("s3cret", &signed("s3cret", now() - 29 * day), now()));
        assert!(!signed_recently("s3cret", &signed("s3cret", now() - 31 * day), now()));
        assert!(!signed_recently("s3cret", &signed("other", now()), now()), "another token's");
        assert!(!signed_recently("s3cret", &signed("s3cret", now() + day), now()), "from the future");
        assert!(Access::new(Some(""), false).carries(&HeaderMap::new()), "an empty token is none");
    }

    /// Without the token a write is refused, a stored job's read too unless
    /// jobs are public; a template's value and the sign-in are not.
    #[test]
    fn stored_jobs_are_the_token_holders() {
        let (get, post) = (Method::GET, Method::POST);
        let none = HeaderMap::new();
        let private = Access::new(Some("t"), false);
        assert_eq!(private.allow(&post, "/v1/flywheel", &none), Err(Refused::Write));
        assert_eq!(private.allow(&post, "/signin", &none), Ok(Allowed { carried: false, jobs: false, token: true }));
        for path in ["/v1/jobs", "/v1/jobs/x/result/a", "/jobs/x", "/v1/templates/p103/job", "/v1/jobs/"] {
            assert_eq!(private.allow(&get, path, &none), Err(Refused::Read), "{path}");
        }
        for path in ["/", "/v1/templates/p103/result/inertia_exact", "/templates/p103", "/v1/templates"] {
            assert!(private.allow(&get, path, &none).is_ok(), "{path}");
        }
        let public = Access::new(Some("t"), true);
        assert_eq!(public.allow(&get, "/jobs/x", &none), Ok(Allowed { carried: false, jobs: true, token: true }));
    }
}
