//! The document's ranges are the service's (issue 70): every numeric
//! parameter of the served document is probed at each bound it states
//! (and, for an integer without a maximum, at its format's largest) and
//! just beyond: at the bound the service does not refuse the parameter,
//! beyond it answers 400 naming it. A parameter added with a range and no
//! probe fails the test.

use crate::helpers::TestApp;
use axum::body::Body;
use axum::http::{Request, StatusCode};
use serde_json::{Value, json};

/// How a parameter of an operation is asked: the method, the path with
/// its ids, the other query parameters, and the body.
struct Probe {
    method: &'static str,
    path: String,
    query: String,
    body: Option<(&'static str, String)>,
}

/// What the probes ask of: a dynamics job with the most samples (100 000,
/// whose last step is the largest `step` any job has), a kinetostatics job
/// with the most steps (a pendulum driven at its pin, its driving torque
/// only) for the worked solution, and a class's CSV.
struct Setting {
    job: String,
    steps: String,
    class: String,
}

async fn setting(app: &TestApp) -> Setting {
    let run = json!({"reduced_inertia": 1, "torques": [{"name": "t", "value": {"expr": "1 - sin(phi)"}}],
        "initial": {"speed": "5 rad/s"}, "duration": 1, "samples": 100_000, "tolerance": 1e-6});
    let r = app.post("/v1/dynamics", &run).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let pendulum = json!({
        "mechanism": {"points": {"O": [0, 0], "G": [0.1, 0]},
            "bodies": [{"name": "bar", "mass": 1, "inertia": 0.01, "cg": "G"}],
            "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "bar"], "at": "O"}],
            "gravity": [0, -9.81]},
        "input": {"joint": "O", "speed": 1, "start": 0, "end": "360 deg", "steps": 100_000},
        "outputs": ["driving"]});
    let k = app.post("/v1/kinetostatics", &pendulum).await;
    assert_eq!(k.status, StatusCode::CREATED, "{}", k.text);
    let class = "student,variant,inertia_exact\nana,1,459.6\n".to_string();
    let id = |r: &crate::helpers::Reply| r.json()["id"].as_str().unwrap().to_string();
    Setting { job: id(&r), steps: id(&k), class }
}

fn probe(path: &str, name: &str, Setting { job, steps, class }: &Setting) -> Probe {
    let get = |path: String, query: &str| Probe { method: "GET", path, query: query.into(), body: None };
    match path {
        "/jobs/{id}" => get(format!("/jobs/{job}"), ""),
        "/v1/jobs/{id}/solution" => get(format!("/v1/jobs/{steps}/solution"), ""),
        "/jobs/{id}/solution" => get(format!("/jobs/{steps}/solution"), ""),
        "/v1/jobs/{id}/plots/{name}.svg" => get(format!("/v1/jobs/{job}/plots/speed.svg"), ""),
        "/v1/jobs" => get("/v1/jobs".into(), ""),
        "/v1/templates/{id}/variants" => {
            // The last seed with one variant; a count from the first seed.
            get("/v1/templates/p103-class/variants".into(), if name == "seed" { "count=1&" } else { "" })
        }
        "/v1/templates/{id}/grade" => Probe {
            method: "POST",
            path: "/v1/templates/p103-class/grade".into(),
            query: String::new(),
            body: Some(("text/csv", class.clone())),
        },
        other => panic!("no probe for the parameter '{name}' of {other}: add one"),
    }
}

/// The answer to `probe` with `name=value`: whether it refused the parameter.
async fn refuses(app: &TestApp, p: &Probe, name: &str, value: &str) -> bool {
    let uri = format!("{}?{}{name}={value}", p.path, p.query);
    let req = Request::builder().method(p.method).uri(&uri);
    let req = match &p.body {
        Some((kind, body)) => req.header("content-type", *kind).body(Body::from(body.clone())),
        None => req.body(Body::empty()),
    };
    let r = app.send(req.unwrap()).await;
    if r.status != StatusCode::BAD_REQUEST {
        assert!(r.status.is_success(), "{uri}: {} {}", r.status, r.text);
        return false;
    }
    if r.content_type.starts_with("text/html") {
        return r.text.contains(&format!("{name}:"));
    }
    let errors = r.json()["errors"].as_array().cloned().unwrap_or_default();
    errors.iter().any(|e| e["parameter"] == name)
}

/// A number beside `x`: the next integer, or a step of a millionth.
fn beside(x: &Value, integer: bool, up: bool) -> String {
    let sign: i32 = if up { 1 } else { -1 };
    match (integer, x.as_i64(), x.as_u64()) {
        (true, Some(i), _) => (i128::from(i) + i128::from(sign)).to_string(),
        (true, None, Some(u)) => (i128::from(u) + i128::from(sign)).to_string(),
        _ => {
            let x = x.as_f64().unwrap();
            (x + f64::from(sign) * 1e-6 * (1.0 + x.abs())).to_string()
        }
    }
}

#[tokio::test]
async fn every_range_of_the_document_is_the_services() {
    // Room for the kinetostatics job of 100 000 steps (26 MB).
    let app = TestApp::with_limits(mechdyn::kind::Limits { result_bytes: 64 << 20, ..Default::default() }).await;
    let doc = app.get("/openapi.json").await.json();
    let setting = setting(&app).await;
    let mut probed = 0;
    for (path, item) in doc["paths"].as_object().unwrap() {
        for op in item.as_object().unwrap().values() {
            for param in op["parameters"].as_array().into_iter().flatten().filter(|p| p["in"] == "query") {
                let (name, schema) = (param["name"].as_str().unwrap(), &param["schema"]);
                let integer = schema["type"] == "integer";
                if !integer && schema["type"] != "number" {
                    continue;
                }
                let largest = match schema["format"].as_str() {
                    Some("int64") => Some(json!(i64::MAX)),
                    Some("int32") => Some(json!(i32::MAX)),
                    _ => None,
                };
                let p = probe(path, name, &setting);
                if let Some(min) = schema.get("minimum") {
                    let at = if integer { min.to_string() } else { min.as_f64().unwrap().to_string() };
                    assert!(!refuses(&app, &p, name, &at).await, "{path}: {name}={at} (its minimum) refused");
                    let below = beside(min, integer, false);
                    assert!(
                        refuses(&app, &p, name, &below).await,
                        "{path}: {name}={below} (below its minimum) not refused"
                    );
                    probed += 1;
                }
                if let Some(max) = schema.get("maximum").cloned().or(largest) {
                    let at = max.to_string();
                    assert!(!refuses(&app, &p, name, &at).await, "{path}: {name}={at} (its maximum) refused");
                    let above = beside(&max, integer, true);
                    assert!(
                        refuses(&app, &p, name, &above).await,
                        "{path}: {name}={above} (above its maximum) not refused"
                    );
                    probed += 1;
                }
            }
        }
    }
    assert!(probed >= 16, "{probed} bounds probed");
}
