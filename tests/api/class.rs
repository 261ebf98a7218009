//! A class: seeded variants, a class CSV graded in one request, labels on
//! jobs, retried POSTs with `Idempotency-Key`.

use crate::helpers::{TestApp, case};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use serde_json::{Value, json};

/// The generator is pinned: these parameter sets of `p103-class` are what
/// its documented draw gives (SplitMix64 seeded with the variant, one draw
/// per parameter in name order F, I0, eps, speed, multiply-shift onto the
/// grid) on every machine and every version; `examples/grading/variant.py`
/// computes them independently from that description (tests/api/offline.rs).
#[tokio::test]
async fn variants_are_the_same_forever() {
    let app = TestApp::new().await;
    let r = app.get("/v1/templates/p103-class/variants?seed=1&count=4").await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    let drawn: Vec<Value> = r.json()["variants"].as_array().unwrap().iter().map(|v| v["parameters"].clone()).collect();
    assert_eq!(
        drawn,
        [
            json!({"F": 600, "I0": 7, "eps": 0.05, "speed": 70}),
            json!({"F": 600, "I0": 7, "eps": 0.04, "speed": 100}),
            json!({"F": 350, "I0": 6, "eps": 0.04, "speed": 40}),
            json!({"F": 500, "I0": 8, "eps": 0.05, "speed": 80}),
        ]
    );
    // Variant v alone is the v-th of any list that holds it; nothing computed without values.
    let three = app.get("/v1/templates/p103-class/variants?seed=3&count=1").await.json();
    assert_eq!(three["variants"][0]["parameters"], drawn[2]);
    assert_eq!(app.get("/v1/jobs").await.json()["items"], json!([]));
    let csv = app
        .send(
            Request::get("/v1/templates/p103-class/variants?seed=1&count=2&values=inertia_approximate")
                .header("accept", "text/csv")
                .body(Body::empty())
                .unwrap(),
        )
        .await;
    let mut lines = csv.text.lines();
    assert_eq!(lines.next(), Some("variant,F [N*m],I0 [kg*m^2],eps,speed [rpm],inertia_approximate"));
    assert!(lines.next().unwrap().starts_with("1,600,7,0.05,70,"), "{}", csv.text);
    for bad in [
        "count=0",
        "count=1001",
        "seed=-1",
        "seed=9223372036854775808",
        "seed=9223372036854775807&count=2",
        "format=xml",
    ] {
        let r = app.get(&format!("/v1/templates/p103-class/variants?{bad}")).await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "{bad}: {}", r.text);
    }
}

/// I_approx = ΔE/(ε ω²) with ΔE ∝ F (case F1: 348.989 kg·m² at F = 500 N·m,
/// ε = 0.04, 60 rpm); I0 does not enter it.
fn approximate(f: f64, eps: f64, rpm: f64) -> f64 {
    let c = case("F1_p103_slider_flywheel");
    c["expected"]["I_approx_kg_m2"].as_f64().unwrap() * (f / 500.0) * (0.04 / eps) * (60.0 / rpm).powi(2)
}

/// A class graded in one request: students by variant or by their own
/// parameters, answers with units in the header or the cell, a decimal
/// comma, a bad row; the answers' reference comes from the closed-form
/// scaling of case F1, not from the service.
#[tokio::test]
async fn a_class_is_graded_in_one_request() {
    a_class_is_graded_in_one_request_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn a_class_is_graded_in_one_request_on(app: TestApp) {
    let v1 = approximate(600.0, 0.05, 70.0); // variant 1: F 600, eps 0.05, 70 rpm
    let v3 = approximate(350.0, 0.04, 40.0);
    let own = approximate(700.0, 0.03, 90.0);
    let class = format!(
        "student,variant,F,eps,speed,inertia_approximate [kg*m^2],omega_max\n\
         ana,1,,,,{:.2},\n\
         ben,3,,,,\"{}\",\n\
         carla,,700,0.03,90,{} slug*ft^2,\n\
         dan,1,,,,{:.2},\n\
         eve,x,,,,1,\n",
        v1,
        format!("{:.1}", v3).replace('.', ","),
        own / crate::grading::SLUG_FT2,
        v1 * 1.05,
    );
    let r = app.post_raw("/v1/templates/p103-class/grade", "text/csv", class).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    let mut rows = csv::Reader::from_reader(r.text.as_bytes());
    let head: Vec<String> = rows.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(
        head,
        [
            "student",
            "score",
            "inertia_approximate pass",
            "inertia_approximate relative_error",
            "omega_max pass",
            "omega_max relative_error",
            "feedback",
            "error"
        ]
    );
    let rows: Vec<Vec<String>> = rows.records().map(|r| r.unwrap().iter().map(String::from).collect()).collect();
    let scores: Vec<(&str, &str, &str)> = rows.iter().map(|r| (r[0].as_str(), r[1].as_str(), r[2].as_str())).collect();
    assert_eq!(
        scores,
        [
            ("ana", "0.5", "true"),
            ("ben", "0.5", "true"),
            ("carla", "0.5", "true"),
            ("dan", "0", "false"),
            ("eve", "", "")
        ]
    );
    assert!(rows[3][6].contains("4.99"), "{:?}", rows[3]); // 5 % of the exact value, rounded to 2 decimals
    assert!(rows[0][6].contains("omega_max: no answer"), "{:?}", rows[0]);
    assert!(rows[4][7].contains("variant"), "{:?}", rows[4]);
    // ana and dan share variant 1: one reference job; with ben and carla, three in all.
    let jobs = app.get("/v1/jobs?kind=flywheel").await.json();
    assert_eq!(jobs["items"].as_array().unwrap().len(), 3, "{jobs}");
    // PrairieLearn's significant figures: 2 figures pass dan's 5 % only when it rounds alike (it does not).
    let strict = app
        .post_raw(
            "/v1/templates/p103-class/grade?sigfigs=2&reveal=false",
            "text/csv",
            "student,variant,inertia_approximate\nann,1,1\n",
        )
        .await;
    assert_eq!(strict.status, StatusCode::OK, "{}", strict.text);
    assert!(strict.text.contains("within 2 significant figures of the expected value"), "{}", strict.text);
    for (query, body) in [
        ("?relative=-1", "student,inertia_approximate\na,1\n"),
        ("", "name,inertia_approximate\na,1\n"),
        ("", "student,F\na,1\n"),
    ] {
        let r = app.post_raw(&format!("/v1/templates/p103-class/grade{query}"), "text/csv", body).await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "{query} {body}: {}", r.text);
    }
}

/// `?label=` on a POST is stored with its job and filters the list; a
/// template's shared jobs carry none.
#[tokio::test]
async fn labels_tag_jobs_and_filter_the_list() {
    labels_tag_jobs_and_filter_the_list_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn labels_tag_jobs_and_filter_the_list_on(app: TestApp) {
    let body = json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 353.5}});
    for student in ["ana", "ben", "ana"] {
        let r = app.post(&format!("/v1/check?label={student}"), &body).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        assert_eq!(r.json()["label"], student);
    }
    let ana = app.get("/v1/jobs?label=ana").await.json();
    let items = ana["items"].as_array().unwrap();
    assert_eq!(items.len(), 2);
    assert!(items.iter().all(|j| j["label"] == "ana" && j["kind"] == "check"));
    let reference = app.get("/v1/jobs?kind=flywheel").await.json();
    assert!(reference["items"][0].get("label").is_none(), "{reference}");
    let page = app.get("/v1/jobs?label=ana&limit=1").await.json();
    assert_eq!(page["next"].as_str().unwrap().split('&').next(), Some("/v1/jobs?label=ana"));
    let long = "x".repeat(201);
    assert_eq!(app.post(&format!("/v1/check?label={long}"), &body).await.status, StatusCode::BAD_REQUEST);
    assert_eq!(app.get("/v1/jobs?label=").await.status, StatusCode::BAD_REQUEST);
}

fn keyed(path: &str, key: &str, content_type: &str, body: &str) -> Request<Body> {
    let req = Request::post(path).header("content-type", content_type).header("idempotency-key", key);
    req.body(Body::from(body.to_string())).unwrap()
}

/// A retried POST with the same `Idempotency-Key` gets the first answer
/// again, byte for byte, and stores nothing twice; another body under the
/// same key is a 422.
#[tokio::test]
async fn a_retried_post_is_answered_once() {
    a_retried_post_is_answered_once_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn a_retried_post_is_answered_once_on(app: TestApp) {
    let body = json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 353.5}}).to_string();
    let first = app.send(keyed("/v1/check", "grader-7", "application/json", &body)).await;
    assert_eq!(first.status, StatusCode::CREATED, "{}", first.text);
    let again = app.send(keyed("/v1/check", "grader-7", "application/json", &body)).await;
    assert_eq!((again.status, &again.text, &again.location), (first.status, &first.text, &first.location));
    assert_eq!(again.headers.get("idempotent-replayed").unwrap(), "true");
    assert_eq!(app.get("/v1/jobs?kind=check").await.json()["items"].as_array().unwrap().len(), 1);
    let other = app.send(keyed("/v1/check", "grader-7", "application/json", &body.replace("353.5", "353"))).await;
    assert_eq!(other.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", other.text);
    assert_eq!(other.json()["errors"][0]["parameter"], "Idempotency-Key");
    // Any POST: a kind's, and a class CSV (its answer kept as bytes).
    let flywheel = crate::helpers::request("p103_slider").to_string();
    let a = app.send(keyed("/v1/flywheel", "f-1", "application/json", &flywheel)).await;
    let b = app.send(keyed("/v1/flywheel", "f-1", "application/json", &flywheel)).await;
    assert_eq!((a.status, a.location.clone(), &a.text), (b.status, b.location, &b.text));
    let class = "student,variant,inertia_exact\nana,1,255\n";
    let a = app.send(keyed("/v1/templates/p103-class/grade", "g-1", "text/csv", class)).await;
    let b = app.send(keyed("/v1/templates/p103-class/grade", "g-1", "text/csv", class)).await;
    assert_eq!((a.status, &a.text, &a.content_type), (StatusCode::OK, &b.text, &b.content_type));
    // A failure is not kept: the retry is tried again (and fails again, with its own answer).
    let bad = app.send(keyed("/v1/flywheel", "f-2", "application/json", "{}")).await;
    assert_eq!(bad.status, StatusCode::UNPROCESSABLE_ENTITY);
    let ok = app.send(keyed("/v1/flywheel", "f-2", "application/json", "{}")).await;
    assert!(ok.headers.get("idempotent-replayed").is_none());
    let empty = app.send(keyed("/v1/flywheel", " ", "application/json", &flywheel)).await;
    assert_eq!(empty.status, StatusCode::BAD_REQUEST);
}

/// Two copies of one POST sent at once under one key (a client's retry
/// racing its first try): one job stored; the other copy is the first's
/// answer again or a 409 to retry, never a second job.
#[tokio::test]
async fn a_retry_racing_its_first_try_stores_one_job() {
    let app = TestApp::new().await;
    let mut k1 = crate::helpers::request("k1_offset_slider_crank");
    k1["input"]["steps"] = json!(2000);
    let body = k1.to_string();
    let (a, b) = tokio::join!(
        app.send(keyed("/v1/kinetostatics", "race", "application/json", &body)),
        app.send(keyed("/v1/kinetostatics", "race", "application/json", &body))
    );
    let mut statuses = [a.status, b.status];
    statuses.sort();
    assert!(
        statuses == [StatusCode::CREATED, StatusCode::CREATED]
            || statuses == [StatusCode::CREATED, StatusCode::CONFLICT]
    );
    if let Some(busy) = [&a, &b].into_iter().find(|r| r.status == StatusCode::CONFLICT) {
        assert_eq!(busy.headers.get("retry-after").unwrap(), "1");
        assert_eq!(busy.json()["type"], "/problems/in-progress");
    }
    assert_eq!(app.get("/v1/jobs?kind=kinetostatics").await.json()["items"].as_array().unwrap().len(), 1);
}

/// What an instructor's class file gets wrong: a short row, a student twice,
/// a variant with parameters, a missing variant each fail their own row; a
/// misspelled answer column is one 400 naming it; a template without class
/// ranges has no variants; a semicolon-separated export (European Excel) with
/// decimal commas reads as well.
#[tokio::test]
async fn a_class_file_s_mistakes_are_said_where_they_are() {
    let app = TestApp::new().await;
    let v1 = approximate(600.0, 0.05, 70.0);
    let class = format!("student,variant,F,inertia_approximate\nana,1,,{v1}\nbob,2\nana,3,,1\ncid,1,500,1\ndee,,,1\n");
    let r = app.post_raw("/v1/templates/p103-class/grade", "text/csv", class).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    let rows: Vec<csv::StringRecord> =
        csv::Reader::from_reader(r.text.as_bytes()).records().map(Result::unwrap).collect();
    let errors: Vec<(&str, &str, &str)> = rows.iter().map(|r| (&r[0], &r[1], &r[5])).collect();
    assert_eq!(errors[0], ("ana", "1", ""));
    // Rows as the sheet counts them: the header is row 1, bob's row 3.
    assert!(errors[1].2.contains("row 3 has 2 cells for 4 columns"), "{errors:?}");
    assert!(errors[2].2.contains("student ana appears twice"), "{errors:?}");
    assert!(errors[3].2.contains("not both"), "{errors:?}");
    assert!(errors[4].2.contains("no variant"), "{errors:?}");

    let typo = app
        .post_raw("/v1/templates/p103-class/grade", "text/csv", "student,variant,inertia_exakt\nana,1,3\nbob,2,4\n")
        .await;
    assert_eq!(typo.status, StatusCode::BAD_REQUEST, "{}", typo.text);
    // Named as the CSV's column in its header row, not as a query parameter.
    assert_eq!(typo.json()["type"], "/problems/invalid-table", "{}", typo.text);
    let errors = typo.json()["errors"].clone();
    assert_eq!(errors.as_array().unwrap().len(), 1, "{errors}");
    assert_eq!(errors[0]["column"], "inertia_exakt");
    assert_eq!(errors[0]["row"], 1);
    assert!(errors[0].get("parameter").is_none(), "{errors}");

    let no_ranges = app
        .post_raw("/v1/templates/p103-slider-flywheel/grade", "text/csv", "student,variant,inertia_exact\nana,1,3\n")
        .await;
    assert_eq!(no_ranges.status, StatusCode::BAD_REQUEST, "{}", no_ranges.text);
    assert!(no_ranges.text.contains("every variant would be its defaults"), "{}", no_ranges.text);
    assert_eq!(no_ranges.json()["errors"][0]["column"], "variant", "{}", no_ranges.text);
    assert_eq!(app.get("/v1/templates/p103-slider-flywheel/variants").await.status, StatusCode::BAD_REQUEST);

    let european = format!("student;variant;inertia_approximate\nana;1;{}\n", format!("{v1:.3}").replace('.', ","));
    let r = app.post_raw("/v1/templates/p103-class/grade", "text/csv", european).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    // Answered in the sheet's own way: `;` and decimal commas.
    assert!(r.text.lines().nth(1).unwrap().starts_with("ana;1;true;"), "{}", r.text);
}

/// A CSV over the limit on a request body is the same 413 problem as a JSON
/// body's (a class or a study; axum's own answer was plain text).
#[tokio::test]
async fn a_csv_over_the_body_limit_is_a_413_problem() {
    let app = TestApp::with_limit(1024).await;
    for path in ["/v1/templates/p103-class/grade", "/v1/templates/p103-class/table?values=inertia_exact"] {
        let r = app.post_raw(path, "text/csv", "student,variant,inertia_exact\n".repeat(100)).await;
        assert_eq!(r.status, StatusCode::PAYLOAD_TOO_LARGE, "{path}: {}", r.text);
        assert_eq!(r.content_type, "application/problem+json", "{path}");
    }
}
