//! Numbers as a Spanish lab writes them and reads them: a decimal comma
//! wherever a number is text (query parameters, quantity strings, CSV
//! cells), `°` and `Nm`, a unit's likely meaning, and `?decimal=comma` on
//! every text answer. Every reference is the same request written with
//! decimal points (the service's own answer, already checked against the
//! cases elsewhere), so the comma must change nothing but the writing.

use crate::helpers::{TestApp, request, template_request};
use axum::http::StatusCode;
use serde_json::json;

const PART: &str = "/v1/templates/p103-slider-flywheel/result/inertia_exact";

async fn text(app: &TestApp, path: &str) -> String {
    let r = app.get(path).await;
    assert_eq!(r.status, StatusCode::OK, "{path}: {}", r.text);
    r.text
}

/// `?eps=0,03` is `?eps=0.03`: the same stored job (its request's key), the
/// same double; `F=1200,5` likewise; a comma answer is the point answer
/// with its point as a comma, to every digit.
#[tokio::test]
async fn a_decimal_comma_in_the_query_is_the_same_job() {
    let app = TestApp::new().await;
    let job = |q: &str| format!("/v1/templates/p103-slider-flywheel/job?{q}");
    let point = app.get(&job("F=1200.5&eps=0.03")).await.json();
    let comma = app.get(&job("F=1200,5&eps=0,03")).await.json();
    assert_eq!(point["id"], comma["id"], "one job for both writings");
    let exact = text(&app, &format!("{PART}?eps=0.03")).await;
    assert_eq!(text(&app, &format!("{PART}?eps=0,03")).await, exact);
    let spanish = text(&app, &format!("{PART}?eps=0,03&decimal=comma")).await;
    assert_eq!(spanish, exact.replace('.', ","), "0,628… for VALOR()");
    assert_eq!(text(&app, &format!("{PART}?eps=0,03&decimal=point")).await, exact);
    let r = app.get(&format!("{PART}?decimal=semicolon")).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    assert_eq!(r.json()["errors"][0]["parameter"], "decimal");
    // Thousands separators are not decimals: a clear 400 at the parameter.
    let r = app.get(&format!("{PART}?F=1.200,5")).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["parameter"], "F");
}

/// Quantity strings in a body: `"0,04"`, `"60,0 rpm"`, `"20°"`, `"10 Nm"`
/// read as their point-and-name twins (P.103 and a flywheel torque).
#[tokio::test]
async fn quantities_with_commas_degrees_and_nm() {
    let app = TestApp::new().await;
    let plain = app.flywheel(&request("p103_slider")).await;
    let mut spanish = request("p103_slider");
    spanish["irregularity"] = json!("0,04");
    spanish["mean_speed"] = json!("60,0 rpm");
    spanish["torques"][0]["value"]["segments"][0]["to"] = json!("180°");
    let written = app.flywheel(&spanish).await;
    assert_eq!(written["result"]["inertia_exact"], plain["result"]["inertia_exact"]);
    for (degrees, nm) in [("180 °", "10 Nm"), ("180º", "10 N*m")] {
        let mut r = request("p103_slider");
        r["torques"][0]["value"]["segments"][0]["to"] = json!(degrees);
        r["torques"].as_array_mut().unwrap().insert(1, json!({"name": "friction", "value": nm}));
        let mut reference = request("p103_slider");
        reference["torques"].as_array_mut().unwrap().insert(1, json!({"name": "friction", "value": 10.0}));
        let (a, b) = (app.flywheel(&r).await, app.flywheel(&reference).await);
        assert_eq!(a["result"]["inertia_exact"], b["result"]["inertia_exact"], "{degrees}, {nm}");
    }
}

/// A unit close to a known one is named in the error; an expression
/// written where a quantity goes is told how to write it.
#[tokio::test]
async fn what_a_unit_probably_means() {
    let app = TestApp::new().await;
    for (field, value, words) in [
        ("/reduced_inertia", json!("5 kgm2"), "did you mean kg*m^2?"),
        ("/mean_speed", json!("60 rmp"), "did you mean rpm?"),
        ("/reduced_inertia", json!("5*sin(phi)^2"), "write it as {\"expr\": \"5*sin(phi)^2\"}"),
    ] {
        let mut r = request("p103_slider");
        r[field.trim_start_matches('/')] = value;
        let errors = app.flywheel_422(&r).await;
        assert!(errors.iter().any(|(p, m)| p == field && m.contains(words)), "{field}: {errors:?}");
    }
}

/// A study written by a Spanish sheet (`;`, decimal commas) answers the
/// values of the same rows written with points; `?decimal=comma` answers
/// with `;` and decimal commas; a quoted comma in a `,` file reads, an
/// unquoted one is a row error saying how to write it.
#[tokio::test]
async fn a_study_from_a_spanish_sheet() {
    let app = TestApp::new().await;
    let path = "/v1/templates/p103-slider-flywheel/table?values=inertia_exact";
    let english = app.post_raw(path, "text/csv", "F,eps\n1200.5,0.03\n800,0.05\n").await;
    let spanish = app.post_raw(&format!("{path}&decimal=comma"), "text/csv", "F;eps\n1200,5;0,03\n800;0,05\n").await;
    assert_eq!(spanish.status, StatusCode::OK, "{}", spanish.text);
    let values = |text: &str, delimiter: u8| -> Vec<String> {
        let mut r = csv::ReaderBuilder::new().delimiter(delimiter).from_reader(text.as_bytes());
        r.records().map(|row| row.unwrap()[2].to_string()).collect()
    };
    let (en, es) = (values(&english.text, b','), values(&spanish.text, b';'));
    assert_eq!(es, en.iter().map(|v| v.replace('.', ",")).collect::<Vec<_>>(), "{}", spanish.text);
    assert!(spanish.text.starts_with("F;eps;inertia_exact;job;error\n1200,5;0,03;"), "{}", spanish.text);
    let quoted = app.post_raw(path, "text/csv", "F,eps\n\"1200,5\",\"0,03\"\n800,0.05\n").await;
    assert_eq!(values(&quoted.text, b','), en);
    let unquoted = app.post_raw(path, "text/csv", "F,eps\n1200,5,0.03\n").await;
    assert_eq!(unquoted.status, StatusCode::BAD_REQUEST, "{}", unquoted.text);
    let error = &unquoted.json()["errors"][0];
    assert_eq!((error["row"].clone(), unquoted.json()["type"].clone()), (json!(2), json!("/problems/invalid-table")));
    let message = error["message"].as_str().unwrap().to_string();
    assert!(message.contains("row 2 has 3 cells for 2 columns") && message.contains("in quotes"), "{message}");
    // A `;`-separated sheet is answered in its own way without `?decimal=comma`;
    // `?decimal=point` still says otherwise.
    let as_sent = app.post_raw(path, "text/csv", "F;eps\n1200,5;0,03\n800;0,05\n").await;
    assert_eq!(values(&as_sent.text, b';'), es, "{}", as_sent.text);
    let point = app.post_raw(&format!("{path}&decimal=point"), "text/csv", "F;eps\n1200,5;0,03\n800;0,05\n").await;
    assert_eq!(values(&point.text, b','), en, "{}", point.text);
    // One cell too many in a `;`-separated sheet is not a decimal comma: the hint is not given.
    let long = app.post_raw(path, "text/csv", "F;eps\n1200,5;0,03;9\n").await;
    let message = long.json()["errors"][0]["message"].as_str().unwrap().to_string();
    assert!(message.contains("row 2 has 3 cells for 2 columns") && !message.contains("quotes"), "{message}");
}

/// Every other text answer with `?decimal=comma`: the values and the job's
/// CSV (`;`, the same numbers), the variants and a class's grades.
#[tokio::test]
async fn every_text_answer_writes_decimal_commas() {
    let app = TestApp::new().await;
    let id = app.flywheel(&request("p103_slider")).await["id"].as_str().unwrap().to_string();
    for path in [format!("/v1/jobs/{id}/values?format=csv"), format!("/v1/jobs/{id}/result.csv?angles=rad")] {
        let (en, es) = (text(&app, &path).await, text(&app, &format!("{path}&decimal=comma")).await);
        let mut point = csv::Reader::from_reader(en.as_bytes());
        let mut comma = csv::ReaderBuilder::new().delimiter(b';').from_reader(es.as_bytes());
        let (a, b): (Vec<_>, Vec<_>) = (point.records().collect(), comma.records().collect());
        assert_eq!(a.len(), b.len(), "{path}");
        for (a, b) in a.iter().zip(&b) {
            let (a, b) = (a.as_ref().unwrap(), b.as_ref().unwrap());
            let same = a.iter().zip(b.iter()).all(|(x, y)| match x.parse::<f64>() {
                Ok(_) => y == x.replacen('.', ",", 1),
                Err(_) => y == x,
            });
            assert!(same, "{path}: {a:?} vs {b:?}");
        }
    }
    let variants = "/v1/templates/p103-class/variants?seed=1&count=2&values=inertia_approximate&format=csv";
    let (en, es) = (text(&app, variants).await, text(&app, &format!("{variants}&decimal=comma")).await);
    assert_eq!(es, en.replace(',', ";").replace('.', ","), "no text cell holds a comma or a point here");
    let class = "student;variant;inertia_approximate\nana;1;1000,5\n";
    let graded = app.post_raw("/v1/templates/p103-class/grade?decimal=comma", "text/csv", class).await;
    assert_eq!(graded.status, StatusCode::OK, "{}", graded.text);
    let mut rows = csv::ReaderBuilder::new().delimiter(b';').from_reader(graded.text.as_bytes());
    let row = rows.records().next().unwrap().unwrap();
    assert_eq!(&row[0], "ana");
    assert!(row[3].contains(',') && !row[3].contains('.'), "relative error with a comma: {:?}", &row[3]);
}

/// A polar cam's radius typed as a Spanish sheet writes it, "0,05 +
/// 0,006*cos(3*psi)": refused at the expression, naming the number with its
/// decimal comma (not "an unexpected ','"), in Spanish; a comma between a
/// function's arguments, max(0,5), still reads as two arguments.
#[tokio::test]
async fn a_decimal_comma_in_an_expression_is_named() {
    let app = TestApp::new().await;
    let mut body = template_request("cam-flat-follower");
    body["mechanism"]["points"]["F"] = json!([0, 0.056]);
    let curve = &mut body["mechanism"]["joints"][2]["curves"][0];
    *curve = json!({"polar": {"center": "O", "zero": [0, 1], "radius": {"expr": "0,05 + 0,006*cos(3*psi)"}}});
    let r = app.post("/v1/kinetostatics?lang=es", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let error = &r.json()["errors"][0];
    assert_eq!(error["pointer"], "/mechanism/joints/2/curves/0/polar/radius/expr");
    assert!(error["message"].as_str().unwrap().contains("'0,05' está escrito con coma decimal"), "{error}");
    body["mechanism"]["joints"][2]["curves"][0]["polar"]["radius"]["expr"] = json!("max(0,5)*0.01 + 0.006*cos(3*psi)");
    assert_eq!(app.post("/v1/kinetostatics", &body).await.status, StatusCode::CREATED);
}

/// A mechanism's points as a statement gives them: K1's coordinates, and a
/// body's centre of mass, in cm and mm and with a decimal comma (`"8 cm"`,
/// `"0,02 m"`) answer K1's driving
/// torque as its coordinates in m do, to 1e-12 of it (rounding: 8 × 0.01
/// is not 0.08 to the bit); a coordinate that is not a length is a 422 at its pointer,
/// saying what a coordinate may be, in Spanish.
#[tokio::test]
async fn points_are_read_in_the_statement_s_units() {
    let app = TestApp::new().await;
    let mut k1 = request("k1_offset_slider_crank");
    k1["input"]["steps"] = json!(6);
    let in_m = app.result("/v1/kinetostatics", &k1).await;
    k1["mechanism"]["points"]["A"] = json!(["8 cm", 0]);
    k1["mechanism"]["points"]["B"] = json!(["379,33259094191533 mm", "0,02 m"]);
    k1["mechanism"]["bodies"][1]["cg"] = json!(["16,97997772825746 cm", "6 mm"]);
    let in_units = app.result("/v1/kinetostatics", &k1).await;
    for k in 0..6 {
        let [a, b] = [&in_m, &in_units].map(|r| r["steps"][k]["driving"].as_f64().unwrap());
        // A coordinate read from a unit is within an ulp of its value in m
        // (8 × 0.01 against 0.08), which moves the torque by rounding only.
        assert!((a - b).abs() <= 1e-12 * a.abs().max(1.0), "step {k}: {a} in m, {b} in units");
    }
    k1["mechanism"]["points"]["A"] = json!(["8 kg", 0]);
    let r = crate::spanish::in_spanish(&app, "POST", "/v1/kinetostatics", Some(&k1)).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let error = &r.json()["errors"][0];
    assert_eq!(error["pointer"], "/mechanism/points/A/0");
    assert_eq!(
        error["message"],
        "se esperaba una longitud: un número en m, o con su unidad (\"8 cm\") y llegó el texto \"8 kg\""
    );
}
