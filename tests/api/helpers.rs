//! A test app: the real router on a fresh SQLite file in a temporary folder.

use axum::body::Body;
use axum::http::{Request, StatusCode};
use http_body_util::BodyExt;
use mechdyn::api::{AppState, Settings, router};
use mechdyn::store::Store;
use serde_json::Value;
use tower::ServiceExt;

/// How the tests' services compute: in worker processes of the binary
/// under test, as the service does.
pub fn workers() -> mechdyn::api::workers::Settings {
    mechdyn::api::workers::Settings { program: env!("CARGO_BIN_EXE_mechdyn").into(), memory: None }
}

/// A service's state on `store`, its jobs computed by worker processes.
pub fn state(store: Store) -> AppState {
    AppState::new(store, mechdyn::registry()).with_workers(workers())
}

pub struct TestApp {
    pub app: axum::Router,
    pub url: String,
    _dir: tempfile::TempDir,
}

pub struct Reply {
    pub status: StatusCode,
    pub content_type: String,
    pub location: Option<String>,
    pub headers: axum::http::HeaderMap,
    pub text: String,
}

impl Reply {
    pub fn json(&self) -> Value {
        serde_json::from_str(&self.text).unwrap_or_else(|e| panic!("not JSON ({e}): {}", self.text))
    }
}

impl TestApp {
    pub async fn new() -> Self {
        Self::with_limit(mechdyn::api::DEFAULT_BODY_LIMIT).await
    }

    pub async fn with_limit(limit: usize) -> Self {
        Self::with_settings(&Settings::with_body_limit(limit)).await
    }

    /// A fresh app with this middleware configuration.
    pub async fn with_settings(settings: &Settings) -> Self {
        let dir = tempfile::tempdir().unwrap();
        let url = format!("sqlite://{}/sub/jobs.db", dir.path().display());
        let store = Store::open(&url).await.unwrap();
        Self { app: router(state(store), settings), url, _dir: dir }
    }

    /// A fresh app on the database at `url` (a test's PostgreSQL database).
    pub async fn on(url: &str, settings: &Settings) -> Self {
        let store = Store::open(url).await.unwrap();
        Self { app: router(state(store), settings), url: url.into(), _dir: tempfile::tempdir().unwrap() }
    }

    /// A router built by the test (its own state and settings), its
    /// database in `dir` (kept while the app is).
    pub fn serving(app: axum::Router, dir: tempfile::TempDir) -> Self {
        Self { app, url: String::new(), _dir: dir }
    }

    /// The same database opened again, as after a restart.
    pub async fn restart(self) -> Self {
        let store = Store::open(&self.url).await.unwrap();
        Self { app: router(state(store), &Settings::default()), ..self }
    }

    /// A fresh app whose jobs have this compute budget (and room for
    /// results of any size, so that the budget is what stops them).
    pub async fn with_job_budget(budget: std::time::Duration) -> Self {
        Self::with_limits(mechdyn::kind::Limits { budget, result_bytes: 1 << 30, ..Default::default() }).await
    }

    /// A fresh app with these limits on a request.
    pub async fn with_limits(limits: mechdyn::kind::Limits) -> Self {
        Self::new().await.reopened(|state| AppState { limits, ..state }).await
    }

    /// The same database served again with the state `change` makes of the default.
    pub async fn reopened(self, change: impl FnOnce(AppState) -> AppState) -> Self {
        let store = Store::open(&self.url).await.unwrap();
        Self { app: router(change(state(store)), &Settings::default()), ..self }
    }

    pub async fn send(&self, req: Request<Body>) -> Reply {
        let res = self.app.clone().oneshot(req).await.unwrap();
        let status = res.status();
        let header = |n: &str| res.headers().get(n).and_then(|v| v.to_str().ok()).map(str::to_string);
        let content_type = header("content-type").unwrap_or_default();
        let location = header("location");
        let headers = res.headers().clone();
        let bytes = res.into_body().collect().await.unwrap().to_bytes();
        Reply { status, content_type, location, headers, text: String::from_utf8_lossy(&bytes).into_owned() }
    }

    pub async fn post_raw(&self, path: &str, content_type: &str, body: impl Into<Body>) -> Reply {
        let req = Request::post(path).header("content-type", content_type).body(body.into()).unwrap();
        self.send(req).await
    }

    pub async fn post(&self, path: &str, body: &Value) -> Reply {
        self.post_raw(path, "application/json", body.to_string()).await
    }

    /// The pointers of a POST's 422 errors, in order (asserting the 422).
    pub async fn pointers(&self, path: &str, body: &Value) -> Vec<String> {
        let r = self.post(path, body).await;
        assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect()
    }

    pub async fn get(&self, path: &str) -> Reply {
        self.send(Request::get(path).body(Body::empty()).unwrap()).await
    }

    /// A GET carrying the API token `token` as a bearer.
    pub async fn get_as(&self, path: &str, token: &str) -> Reply {
        let req = Request::get(path).header("authorization", format!("Bearer {token}"));
        self.send(req.body(Body::empty()).unwrap()).await
    }

    /// POSTs a request that must be answered 201; returns the job's result.
    pub async fn result(&self, path: &str, body: &Value) -> Value {
        let r = self.post(path, body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        r.json()["result"].clone()
    }

    /// POSTs a flywheel request that must succeed; returns the job.
    pub async fn flywheel(&self, body: &Value) -> Value {
        let r = self.post("/v1/flywheel", body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        r.json()
    }

    /// POSTs a flywheel request that must be refused with 422; returns the errors.
    pub async fn flywheel_422(&self, body: &Value) -> Vec<(String, String)> {
        let r = self.post("/v1/flywheel", body).await;
        assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
        assert_eq!(r.content_type, "application/problem+json");
        r.json()["errors"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| (e["pointer"].as_str().unwrap().to_string(), e["message"].as_str().unwrap().to_string()))
            .collect()
    }
}

/// A request of the problem library (library/requests).
pub fn request(name: &str) -> Value {
    fixture(&format!("requests/{name}.json"))
}

/// The example of a component schema in the served OpenAPI document (what
/// a user of the interactive docs sends first).
pub fn example(schema: &str) -> Value {
    let doc = serde_json::to_value(mechdyn::registry().openapi()).unwrap();
    let found = doc["components"]["schemas"][schema]["example"].clone();
    assert!(found.is_object(), "the schema {schema} has no example");
    found
}

/// A reference case from tests/fixtures/cases.
pub fn case(name: &str) -> Value {
    fixture(&format!("cases/{name}.json"))
}

fn fixture(path: &str) -> Value {
    // Requests live in the problem library; reference cases and seeds with the tests.
    let folder = if path.starts_with("requests/") { "library" } else { "tests/fixtures" };
    let full = format!("{}/{folder}/{path}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(&full).unwrap()).unwrap()
}

/// Asserts |actual − expected| ≤ tol·|expected| (or ≤ tol when expected is 0).
#[track_caller]
pub fn close(actual: &Value, expected: f64, tol: f64, what: &str) {
    let a = actual.as_f64().unwrap_or_else(|| panic!("{what}: {actual} is not a number"));
    let bound = if expected == 0.0 { tol } else { tol * expected.abs() };
    assert!((a - expected).abs() <= bound, "{what}: {a} vs {expected} (tolerance {tol})");
}

/// Element-wise [`close`] of a JSON array against expected values.
#[track_caller]
pub fn all_close(actual: &Value, expected: &Value, tol: f64, what: &str) {
    let (a, e) = (actual.as_array().unwrap(), expected.as_array().unwrap());
    assert_eq!(a.len(), e.len(), "{what}: {actual} vs {expected}");
    for (i, (x, y)) in a.iter().zip(e).enumerate() {
        close(x, y.as_f64().unwrap(), tol, &format!("{what}[{i}]"));
    }
}

/// The request of built-in template `id` (library/`id`.json) at its defaults.
pub fn template_request(id: &str) -> Value {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("library/{id}.json"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str::<Value>(&text).unwrap()["request"].clone()
}

/// `bytes` letters and digits that do not compress (an xorshift's), `seed`
/// apart: the stored results of storage tests whose premise is the bytes a
/// job takes on disk (the store compresses results of 4 KB and more).
pub fn noise(bytes: usize, seed: u64) -> String {
    const ALPHABET: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    (0..bytes)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            ALPHABET[(x % ALPHABET.len() as u64) as usize] as char
        })
        .collect()
}
