//! Templates: the built-in problems of the library, one number by URL as a
//! spreadsheet's WEBSERVICE() reads it, the stored job found again for the
//! same parameters, templates created by clients, and parameter studies.

use crate::helpers::{TestApp, case, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

const BUILTIN: [&str; 34] = [
    "p103-slider-flywheel",
    "p103-class",
    "p107-two-stroke-engine",
    "punch-press-us",
    "offset-slider-crank",
    "four-bar",
    "scotch-yoke-startup",
    "rotor-disk",
    "rotor-balancing",
    "scissor-lift",
    "bar-on-slider",
    "cam-flat-follower",
    "ring-on-rim",
    "rolling-disk",
    "cam-design",
    "exam-2010-march",
    "exam-2012-january",
    "exam-2012-march",
    "exam-2013-may",
    "exam-2014-may",
    "p113-pulley-flywheel",
    "grubler-count",
    "tooth-thickness",
    "p63-scotch-yoke",
    "p115-shaper",
    "p23-four-bar-statics",
    "p53-shaper-dynamics",
    "differential-train",
    "rotor-disk-angle",
    "rotor-disk-accelerating",
    "double-pendulum",
    "hooke-joint",
    "bricard-linkage",
    "flyball-governor",
];

async fn number(app: &TestApp, path: &str) -> f64 {
    let r = app.get(path).await;
    assert_eq!(r.status, StatusCode::OK, "{path}: {}", r.text);
    assert_eq!(r.content_type, "text/plain; charset=utf-8", "{path}");
    r.text.parse().unwrap_or_else(|_| panic!("{path}: {}", r.text))
}

#[tokio::test]
async fn the_library_is_listed_and_every_template_solves_at_its_defaults() {
    let app = TestApp::new().await;
    let list = app.get("/v1/templates").await.json();
    let ids: Vec<&str> = list["items"].as_array().unwrap().iter().map(|t| t["id"].as_str().unwrap()).collect();
    assert_eq!(ids, BUILTIN);
    // Every file of library/ is compiled in.
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("library");
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".json"))
        .collect();
    files.sort();
    let mut compiled: Vec<String> = mechdyn::api::templates::LIBRARY_FILES.iter().map(|(n, _)| n.to_string()).collect();
    compiled.sort();
    assert_eq!(files, compiled);
    for id in BUILTIN {
        let t = app.get(&format!("/v1/templates/{id}")).await.json();
        assert_eq!(t["builtin"], true);
        assert!(t["parameters"].as_object().unwrap().len() >= 2, "{id}: {t}");
        for (name, p) in t["parameters"].as_object().unwrap() {
            assert!(t["request"].pointer(p["pointer"].as_str().unwrap()).is_some(), "{id}: {name}");
        }
        let job = app.get(&format!("/v1/templates/{id}/job")).await;
        assert_eq!(job.status, StatusCode::OK, "{id}: {}", job.text);
        assert_eq!(job.json()["kind"], t["kind"]);
    }
}

/// P.103 (case F1, 1e-6): I_exact = 353.52 kg·m² at the defaults; with
/// F = 1200 and ε = 0.03 the approximate inertia ΔE/(ε ω²) scales as F/ε
/// (the crossings of −F sin φ + F/π do not move with F): 348.989·(1200/500)·(0.04/0.03).
#[tokio::test]
async fn one_number_by_url_as_webservice_reads_it() {
    let app = TestApp::new().await;
    let c = case("F1_p103_slider_flywheel");
    let base = "/v1/templates/p103-slider-flywheel/result";
    let exact = number(&app, &format!("{base}/inertia_exact")).await;
    let trusted = c["expected"]["I_exact_kg_m2"].as_f64().unwrap();
    assert!((exact / trusted - 1.0).abs() < 1e-6, "{exact} vs {trusted}");
    // The same doubles as the plain request POSTed.
    let posted = app.flywheel(&request("p103_slider")).await;
    assert_eq!(exact, posted["result"]["inertia_exact"].as_f64().unwrap());

    let approx = number(&app, &format!("{base}/inertia_approximate?F=1200&eps=0.03")).await;
    let expected = c["expected"]["I_approx_kg_m2"].as_f64().unwrap() * (1200.0 / 500.0) * (0.04 / 0.03);
    assert!((approx / expected - 1.0).abs() < 1e-9, "{approx} vs {expected}");
    // Units: of a parameter (rpm by default for speed; a quantity string) and of the answer.
    let rpm = number(&app, &format!("{base}/inertia_exact?speed=60")).await;
    let quantity = number(&app, &format!("{base}/inertia_exact?speed=6.283185307179586%20rad/s")).await;
    assert_eq!(rpm, exact);
    assert!((quantity / exact - 1.0).abs() < 1e-12);
    // 1 slug·ft² = 1.355818 kg·m² (NIST SP 811, B.9).
    let us = number(&app, &format!("{base}/inertia_exact?unit=slug*ft%5E2")).await;
    assert!((us * 1.355818 / exact - 1.0).abs() < 1e-6);
    let percent = number(&app, &format!("{base}/check/irregularity?eps=3%20%25")).await;
    assert!((percent - 0.03).abs() < 1e-6, "{percent}");
}

/// A part asked before is answered from memory (a sheet's recalculation):
/// with its job deleted in between, the second GET still answers the same
/// bytes and computes and stores nothing; another unit, decimal mark or
/// parameter is its own answer.
#[tokio::test]
async fn a_part_asked_again_is_answered_from_memory() {
    let app = TestApp::new().await;
    let path = "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=900";
    let first = app.get(path).await;
    let id = app.get("/v1/jobs").await.json()["items"][0]["id"].as_str().unwrap().to_string();
    let deleted =
        app.send(axum::http::Request::delete(format!("/v1/jobs/{id}")).body(axum::body::Body::empty()).unwrap());
    assert_eq!(deleted.await.status, StatusCode::NO_CONTENT);
    let again = app.get(path).await;
    assert_eq!((again.status, &again.text, &again.content_type), (first.status, &first.text, &first.content_type));
    assert_eq!(app.get("/v1/jobs").await.json()["items"], json!([]), "nothing computed or stored again");
    let other = number(&app, &format!("{path}&unit=slug*ft%5E2")).await;
    assert!((other * 1.355818 / first.text.parse::<f64>().unwrap() - 1.0).abs() < 1e-6, "its own unit");
}

#[tokio::test]
async fn the_same_parameters_reuse_the_stored_job() {
    the_same_parameters_reuse_the_stored_job_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn the_same_parameters_reuse_the_stored_job_on(app: TestApp) {
    let path = "/v1/templates/p103-slider-flywheel/job?F=800&speed=90";
    let first = app.get(path).await;
    let again = app.get(path).await;
    let reordered = app.get("/v1/templates/p103-slider-flywheel/job?speed=90&F=800.0").await;
    assert_eq!(first.json()["id"], again.json()["id"]);
    assert_eq!(first.json()["id"], reordered.json()["id"]);
    assert_eq!(first.headers["content-location"], format!("/v1/jobs/{}", first.json()["id"].as_str().unwrap()));
    let other = app.get("/v1/templates/p103-slider-flywheel/job?F=801&speed=90").await;
    assert_ne!(first.json()["id"], other.json()["id"]);
    let jobs = app.get("/v1/jobs?kind=flywheel").await.json();
    assert_eq!(jobs["items"].as_array().unwrap().len(), 2, "one job per distinct parameters");
}

#[tokio::test]
async fn bad_parameters_are_named() {
    let app = TestApp::new().await;
    let base = "/v1/templates/p103-slider-flywheel/result/inertia_exact";
    for (query, parameter, words) in [
        ("G=1", "G", "its parameters: F, I0, eps, speed"),
        ("F=-3", "F", "below the least value, 0 N*m"),
        ("speed=3%20kg", "speed", "where rad/s is expected"),
        ("eps=lots", "eps", "neither a number nor a quantity"),
    ] {
        let r = app.get(&format!("{base}?{query}")).await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "{query}: {}", r.text);
        let e = &r.json()["errors"][0];
        assert_eq!(e["parameter"], parameter, "{query}");
        assert!(e["message"].as_str().unwrap().contains(words), "{query}: {e}");
    }
    // Valid values that give no valid problem: a 422 that names the parameter.
    let r = app.get("/v1/templates/p103-slider-flywheel/job?eps=0").await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["parameter"], "eps", "{}", r.text);
    let missing = app.get("/v1/templates/no-such/job").await;
    assert_eq!(missing.status, StatusCode::NOT_FOUND);
}

fn gear_template(name: &str) -> Value {
    json!({"kind": "gears", "name": name, "title": "A spur gear", "request": {"module": "4 mm", "teeth": 30},
        "parameters": {"z": {"pointer": "/teeth", "min": 12, "max": 200}, "m": {"pointer": "/module", "unit": "mm"}}})
}

/// Pitch radius R = m·z/2 (closed form): 5 mm × 40 / 2 = 0.1 m.
#[tokio::test]
async fn a_client_creates_a_template_and_uses_it() {
    a_client_creates_a_template_and_uses_it_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn a_client_creates_a_template_and_uses_it_on(app: TestApp) {
    let r = app.post("/v1/templates", &gear_template("my-gear")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert_eq!(r.location.as_deref(), Some("/v1/templates/my-gear"));
    let radius = number(&app, "/v1/templates/my-gear/result/pitch_radius?z=40&m=5").await;
    assert!((radius - 0.1).abs() < 1e-15, "{radius}");
    let listed = app.get("/v1/templates").await.json();
    assert!(listed["items"].as_array().unwrap().iter().any(|t| t["id"] == "my-gear" && t["builtin"] == false));
    assert_eq!(app.post("/v1/templates", &gear_template("my-gear")).await.status, StatusCode::CONFLICT);
    assert_eq!(app.post("/v1/templates", &gear_template("four-bar")).await.status, StatusCode::CONFLICT);
    let unnamed = app
        .post("/v1/templates", &json!({"kind": "gears", "request": {"module": "4 mm", "teeth": 30}, "parameters": {}}))
        .await;
    assert_eq!(unnamed.status, StatusCode::CREATED);
    assert_eq!(unnamed.json()["id"].as_str().unwrap().len(), 36, "a UUID");
}

/// A derived value follows the parameters: a gear whose module is 0.12 m/z
/// keeps its pitch radius m·z/2 = 60 mm whatever its teeth (closed form,
/// 1e-15); a derived value at a field the request lacks, or of a name that
/// is no parameter, is refused at `/derived/…`.
#[tokio::test]
async fn a_derived_value_follows_the_parameters() {
    let app = TestApp::new().await;
    let mut t = gear_template("fixed-radius");
    t["parameters"].as_object_mut().unwrap().remove("m");
    t["derived"] = json!({"/module": "0.12/z"});
    let r = app.post("/v1/templates", &t).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    for z in [30, 48, 120] {
        let radius = number(&app, &format!("/v1/templates/fixed-radius/result/pitch_radius?z={z}")).await;
        assert!((radius - 0.06).abs() < 1e-15, "z = {z}: {radius}");
    }
    t["name"] = json!("broken");
    t["derived"] = json!({"/nothing": "z", "/module": "q*2"});
    let r = app.post("/v1/templates", &t).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let pointers: Vec<String> =
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect();
    assert_eq!(pointers, ["/derived/~1module", "/derived/~1nothing"], "{}", r.text);
}

#[tokio::test]
async fn a_bad_template_is_refused_at_its_fields() {
    let app = TestApp::new().await;
    let mut bad = gear_template("Not A Slug");
    bad["parameters"]["unit"] = json!({"pointer": "/teeth"});
    bad["parameters"]["r"] = json!({"pointer": "/radius"});
    bad["parameters"]["k"] = json!({"pointer": "/teeth", "unit": "furlongs"});
    let r = app.post("/v1/templates", &bad).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let pointers: Vec<String> =
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect();
    for p in ["/name", "/parameters/unit", "/parameters/r/pointer", "/parameters/k/unit"] {
        assert!(pointers.contains(&p.to_string()), "{p} in {pointers:?}");
    }
    let unsolvable = json!({"kind": "gears", "request": {"module": "-4 mm", "teeth": 30}, "parameters": {}});
    let r = app.post("/v1/templates", &unsolvable).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(r.json()["errors"][0]["pointer"], "/request/module");
}

#[tokio::test]
async fn a_parameter_study_is_one_csv_in_one_csv_out() {
    let app = TestApp::new().await;
    let path = "/v1/templates/p103-slider-flywheel/table?values=inertia_exact,/flywheel_inertia/approximate";
    let body = "F,eps\n1000,0.03\n1200,0.03\n-5,0.03\n1200,\n";
    let r = app.post_raw(path, "text/csv", body).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    assert_eq!(r.content_type, "text/csv; charset=utf-8");
    let mut reader = csv::Reader::from_reader(r.text.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(header, ["F", "eps", "inertia_exact", "flywheel_inertia/approximate", "job", "error"]);
    let rows: Vec<Vec<String>> = reader.records().map(|r| r.unwrap().iter().map(String::from).collect()).collect();
    assert_eq!(rows.len(), 4);
    for (row, query) in [(0, "F=1000&eps=0.03"), (1, "F=1200&eps=0.03"), (3, "F=1200")] {
        let single = number(&app, &format!("/v1/templates/p103-slider-flywheel/result/inertia_exact?{query}")).await;
        assert_eq!(rows[row][2].parse::<f64>().unwrap(), single, "row {row}");
        assert!(rows[row][5].is_empty() && rows[row][4].len() == 36, "row {row}: {:?}", rows[row]);
    }
    assert!(rows[2][5].contains("F: -5 is below the least value"), "{:?}", rows[2]);
    assert!(rows[2][2].is_empty() && rows[2][4].is_empty());
    // A column in other units; the JSON form.
    let kn = app.post_raw(path, "text/csv", "F [kN*m],eps\n1.2,0.03\n").await;
    assert_eq!(kn.text.lines().nth(1).unwrap().split(',').nth(2), rows[1].get(2).map(String::as_str));
    let json_body = json!({"rows": [{"F": 1200, "eps": 0.03}, {"F": "nope"}], "values": ["inertia_exact"]});
    let j = app.post("/v1/templates/p103-slider-flywheel/table", &json_body).await.json();
    assert_eq!(j["rows"][0]["values"]["inertia_exact"].as_f64().unwrap(), rows[1][2].parse::<f64>().unwrap());
    assert!(j["rows"][1]["error"].as_str().unwrap().contains("F:"), "{j}");
    // A value its job's result does not have: the row says which, beside the values it has.
    let json_body = json!({"rows": [{"F": 1200, "eps": 0.03}], "values": ["inertia_exact", "events/1/t"]});
    let j = app.post("/v1/templates/p103-slider-flywheel/table", &json_body).await.json();
    assert_eq!(j["rows"][0]["values"]["inertia_exact"].as_f64().unwrap(), rows[1][2].parse::<f64>().unwrap());
    assert_eq!(j["rows"][0]["error"], "this job's result has no events/1/t", "{j}");
    for body in ["G\n1\n", "G\n", "true"] {
        let unknown = app.post_raw(path, "text/csv", body).await;
        assert_eq!(unknown.status, StatusCode::BAD_REQUEST, "{body}: {}", unknown.text);
        assert!(unknown.json()["errors"][0]["message"].as_str().unwrap().contains("no parameter"), "{body}");
    }
    let nameless = app.get("/v1/templates/p103-slider-flywheel/job?=1").await;
    assert_eq!(nameless.status, StatusCode::BAD_REQUEST);
}

/// An integer parameter is set by an integer: `?steps=72` gives the job of
/// 72 positions (before: 422 "got the number 72.0"), by URL, in a study's
/// CSV and on the form; 72.5 is still refused at its field.
#[tokio::test]
async fn an_integer_parameter_is_set_by_an_integer() {
    let app = TestApp::new().await;
    let r = app.get("/v1/templates/offset-slider-crank/job?steps=72").await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    assert_eq!(r.json()["request"]["input"]["steps"], 72, "{}", r.json()["request"]);
    let study =
        app.post_raw("/v1/templates/offset-slider-crank/table?values=summary", "text/csv", "steps\n72\n24\n").await;
    assert_eq!(study.status, StatusCode::OK, "{}", study.text);
    assert!(study.text.lines().skip(1).all(|l| l.ends_with(',')), "a row failed: {}", study.text);
    let form = app.get("/templates/offset-slider-crank?steps=24").await;
    assert_eq!(form.status, StatusCode::SEE_OTHER, "{}", form.text);
    let half = app.get("/v1/templates/offset-slider-crank/job?steps=72.5").await;
    assert_eq!(half.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", half.text);
    assert_eq!(half.json()["errors"][0]["parameter"], "steps", "{}", half.text);
}
