//! The course's answers as a teaching assistant meets them (issue 72): a
//! sheet's empty cell, a part that is a list read with a decimal comma, a
//! disk sized without a density. Each reference is the service's own
//! answer to the same problem written the plain way, or a closed form.

use crate::helpers::{TestApp, close};
use axum::http::StatusCode;
use serde_json::json;

const TEMPLATE: &str = "/v1/templates/p103-slider-flywheel";

/// A sheet's empty cell sent as `F=` is the parameter's default, not an
/// error: the same job as no `F` at all. An unknown name stays an error
/// even empty.
#[tokio::test]
async fn an_empty_parameter_is_its_default() {
    let app = TestApp::new().await;
    let plain = app.get(&format!("{TEMPLATE}/job?eps=0.03")).await;
    let empty = app.get(&format!("{TEMPLATE}/job?F=&eps=0.03")).await;
    assert_eq!(empty.status, StatusCode::OK, "{}", empty.text);
    assert_eq!(plain.json()["id"], empty.json()["id"], "one job");
    let typo = app.get(&format!("{TEMPLATE}/job?G=&eps=0.03")).await;
    assert_eq!(typo.status, StatusCode::BAD_REQUEST, "{}", typo.text);
}

/// A list part read with `decimal=comma` is text a Spanish sheet can
/// split: its numbers with a comma, separated by `; `, each the JSON
/// answer's number to every digit.
#[tokio::test]
async fn a_list_part_is_written_with_a_decimal_comma() {
    let app = TestApp::new().await;
    let json = app.get(&format!("{TEMPLATE}/result/crossings")).await.json();
    let r = app.get(&format!("{TEMPLATE}/result/crossings?decimal=comma")).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    assert!(r.content_type.starts_with("text/plain"), "{}", r.content_type);
    let read: Vec<f64> = r.text.split("; ").map(|x| x.replace(',', ".").parse().unwrap()).collect();
    let expected: Vec<f64> = json.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    assert!(expected.len() == 2 && read == expected, "{} against {json}", r.text);
}

/// A disk sized by its radius needs no density: its mass is M = 2I/R²
/// (I = ½MR², I the flywheel's exact inertia) and its thickness, which
/// would need ρ, is null; by its thickness the density is asked for.
#[tokio::test]
async fn a_disk_sized_by_its_radius_needs_no_density() {
    let app = TestApp::new().await;
    let mut job = app.get(&format!("{TEMPLATE}/job")).await.json()["request"].clone();
    job["flywheel"] = json!({"disk": {"radius": "0.5 m"}});
    let r = app.post("/v1/flywheel", &job).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    let (mass, inertia) =
        (result["disk"]["mass"].as_f64().unwrap(), result["flywheel_inertia"]["exact"].as_f64().unwrap());
    assert!((mass - 2.0 * inertia / 0.25).abs() <= 1e-12 * mass, "{mass} against 2I/R²");
    assert_eq!(result["disk"]["thickness"], json!(null));
    job["flywheel"] = json!({"disk": {"thickness": "0.1 m"}});
    let r = app.post("/v1/flywheel", &job).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/flywheel/disk/density", "{}", r.text);
}

/// A template read in Spanish has its Spanish title and descriptions where
/// the English ones were (its `es` object beside them); in English, the
/// English ones.
#[tokio::test]
async fn a_template_read_in_spanish_is_titled_in_spanish() {
    let app = TestApp::new().await;
    let english = app.get(TEMPLATE).await.json();
    let spanish = app.get(&format!("{TEMPLATE}?lang=es")).await.json();
    assert_eq!(spanish["title"], english["es"]["title"], "{spanish}");
    assert_eq!(spanish["parameters"]["F"]["description"], english["es"]["parameters"]["F"]);
    assert!(english["title"].as_str().unwrap().starts_with("P.103: flywheel"), "{english}");
    let listed = app.get("/v1/templates?lang=es").await.json();
    let p103 = listed["items"].as_array().unwrap().iter().find(|t| t["id"] == "p103-slider-flywheel").unwrap();
    assert_eq!(p103["title"], english["es"]["title"]);
}

/// Every printed number of every exam template graded as printed: each
/// statement quantity that carries the solution's printed number passes
/// `/v1/check` at the default 1 %, given bare and as "VALUE UNIT" in the
/// unit the check names — among them the magnitudes printed positive
/// (March 2010's C_r = 35.8099 N·m, January 2012's work 509.117 J, May
/// 2014's M_r = 38.197 N·m, P.113's areas in the seed's sense), whose
/// signed field says "opposite sign"; and each print the template says is
/// wrong (May 2014's crossings, inertia and disk) fails. The quantity is
/// read as a value too, in another unit (1 N·m = 1e-3 kN·m).
#[tokio::test]
async fn every_printed_number_is_graded_as_printed() {
    let app = TestApp::new().await;
    let list = app.get("/v1/templates").await.json();
    let (mut right, mut wrong) = (0, 0);
    for t in list["items"].as_array().unwrap() {
        let Some(statement) = t["statement"].as_object() else { continue };
        for (name, s) in statement {
            let Some(printed) = s["printed"].as_f64() else { continue };
            let (id, pointer, of) =
                (t["id"].as_str().unwrap(), format!("/statement/{name}"), s["of"].as_str().unwrap());
            let r = app.post("/v1/check", &json!({"template": id, "answers": {&pointer: printed, of: printed}})).await;
            assert_eq!(r.status, StatusCode::CREATED, "{id}: {}", r.text);
            let items = r.json()["result"]["items"].clone();
            let item = |p: &str| items.as_array().unwrap().iter().find(|i| i["pointer"] == p).unwrap().clone();
            let passes = s.get("wrong").is_none();
            assert_eq!(item(&pointer)["pass"], passes, "{id} {name}: {}", item(&pointer));
            if s["sign"] == -1 {
                assert_eq!(item(of)["pass"], false, "{id} {name}: the signed field is the opposite");
            }
            if !passes {
                wrong += 1;
                continue;
            }
            let unit = item(&pointer)["unit"].as_str().unwrap_or_else(|| panic!("{id} {name}: no unit")).to_string();
            let with_unit = json!({"template": id, "answers": {&pointer: format!("{printed} {unit}")}});
            let r = app.post("/v1/check", &with_unit).await.json();
            assert_eq!(r["result"]["score"], 1.0, "{id} {name} in {unit}: {r}");
            right += 1;
        }
    }
    assert!(right >= 35 && wrong >= 4, "{right} printed numbers right, {wrong} wrong");
    let base = "/v1/templates/exam-2010-march/result/statement/resisting_torque";
    let newtons: f64 = app.get(base).await.text.parse().unwrap();
    let kilo: f64 = app.get(&format!("{base}?unit=kN*m")).await.text.parse().unwrap();
    assert!((newtons - 35.8099).abs() < 1e-4 && (kilo - newtons / 1000.0).abs() < 1e-15, "{newtons} {kilo}");
}

/// P.63 (the notes' Scotch yoke, by the energy theorem): (I_0 + mR² +
/// MR² sin²φ)·φ̈ + MR² sin φ cos φ·φ̇² = M_m − F_f·R·sin φ from rest at φ
/// = 0, integrated here by classical Runge–Kutta at h = 1e-4 s (its error
/// ~1e-13), against the template's mechanism (its four bodies and joints,
/// solved by the engine's DAE) at every sample to 1e-8 relative; at
/// M_m = 3 N·m too (a parameter).
#[tokio::test]
async fn p63_scotch_yoke_follows_the_notes_equation() {
    let app = TestApp::new().await;
    let (r, i0, m, big_m, ff) = (0.1, 0.05, 0.5, 2.0, 10.0);
    for mm in [2.0, 3.0] {
        let rate = |[phi, w]: [f64; 2]| {
            let (s, c) = phi.sin_cos();
            let inertia = i0 + m * r * r + big_m * r * r * s * s;
            [w, (mm - ff * r * s - big_m * r * r * s * c * w * w) / inertia]
        };
        let job = app.get(&format!("/v1/templates/p63-scotch-yoke/job?Mm={mm}")).await.json();
        let (mut y, mut t, h) = ([0.0f64, 0.0], 0.0, 1e-4);
        for sample in job["result"]["samples"].as_array().unwrap() {
            let until = sample["t"].as_f64().unwrap();
            while t < until - 1e-12 {
                let k1 = rate(y);
                let k2 = rate([y[0] + h / 2.0 * k1[0], y[1] + h / 2.0 * k1[1]]);
                let k3 = rate([y[0] + h / 2.0 * k2[0], y[1] + h / 2.0 * k2[1]]);
                let k4 = rate([y[0] + h * k3[0], y[1] + h * k3[1]]);
                for k in 0..2 {
                    y[k] += h / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
                }
                t += h;
            }
            let (angle, speed) = (sample["angle"].as_f64().unwrap(), sample["speed"].as_f64().unwrap());
            assert!(
                (angle - y[0]).abs() <= 1e-8 * y[0].abs().max(1.0),
                "M_m = {mm}, t = {until}: φ {angle} against {}",
                y[0]
            );
            assert!(
                (speed - y[1]).abs() <= 1e-8 * y[1].abs().max(1.0),
                "M_m = {mm}, t = {until}: φ̇ {speed} against {}",
                y[1]
            );
        }
    }
}

/// P.115's I*(φ) of the slotted-lever shaper: with r = 0.1 m, d = 0.3 m,
/// the ram's pin at h = 0.6 m, θ = atan(r sin φ/(d + r cos φ)), θ′ =
/// r(r + d cos φ)/s², s² = r² + d² + 2dr cos φ, x = h tan θ:
/// I* = I_G2 + I_G4·θ′² + m6·h²θ′²/cos⁴θ (the notes' energy equation
/// differentiated here; at φ = π, 2 + 30/4 + 50·0.36/4 = 14 kg·m²), at
/// every step to 1e-10 relative, at the statement's masses and at m6 = 80.
#[tokio::test]
async fn p115_reduced_inertia_is_the_notes_energy_equation() {
    let app = TestApp::new().await;
    let (r, d, h) = (0.1f64, 0.3f64, 0.6f64);
    for m6 in [50.0, 80.0] {
        let job = app.get(&format!("/v1/templates/p115-shaper/job?m6={m6}")).await.json();
        let steps = job["result"]["steps"].as_array().unwrap_or_else(|| panic!("{job}")).clone();
        assert_eq!(steps.len(), 36);
        for step in steps {
            let phi = -step["input"].as_f64().unwrap();
            let s2 = r * r + d * d + 2.0 * d * r * phi.cos();
            let theta = (r * phi.sin()).atan2(d + r * phi.cos());
            let rate = r * (r + d * phi.cos()) / s2;
            let expected = 2.0 + 30.0 * rate * rate + m6 * h * h * rate * rate / theta.cos().powi(4);
            let got = step["reduced_inertia"].as_f64().unwrap();
            assert!((got - expected).abs() <= 1e-10 * expected, "m6 = {m6}, φ = {phi}: {got} against {expected}");
        }
    }
}

/// The statement's quantities read in Spanish carry their Spanish
/// descriptions (March 2010's C_r: "el par resistente").
#[tokio::test]
async fn the_statements_quantities_are_described_in_spanish() {
    let app = TestApp::new().await;
    let t = app.get("/v1/templates/exam-2010-march?lang=es").await.json();
    let said = t["statement"]["resisting_torque"]["description"].as_str().unwrap();
    assert!(said.starts_with("C_r, el par resistente"), "{said}");
}

/// A client's template names its statement's quantities too: stored and
/// read back as a value (−balance_torque of P.103's request: its motor
/// torque is 500/π N·m, the closed form of the template's test); a sign
/// other than ±1 or a pointer without its `/` is refused at its field.
#[tokio::test]
async fn a_clients_template_names_its_statements_quantities() {
    let app = TestApp::new().await;
    let request = app.get(&format!("{TEMPLATE}/job")).await.json()["request"].clone();
    let body = |stated: serde_json::Value| {
        json!({"kind": "flywheel", "name": "my-p103", "request": request, "parameters": {},
            "statement": {"motor": stated}})
    };
    let r = app.post("/v1/templates", &body(json!({"of": "balance_torque", "sign": 2}))).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].clone();
    let pointers: Vec<&str> = errors.as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap()).collect();
    assert_eq!(pointers, ["/statement/motor/of", "/statement/motor/sign"]);
    let r = app.post("/v1/templates", &body(json!({"of": "/balance_torque", "sign": -1}))).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let value: f64 = app.get("/v1/templates/my-p103/result/statement/motor").await.text.parse().unwrap();
    assert!((value + 500.0 / std::f64::consts::PI).abs() < 1e-9, "{value}");
}

/// A template that asks for `distinct` variants draws them without
/// repetition: p103-class's problem and ranges stored as a client's
/// template with `"distinct": true` gives 40 different questions of its
/// 11·7·4·9 = 2 772 (seeds 1 to 40, and 40 from a seed near 2^63), each on
/// its parameters' grids. p103-class itself keeps the draws it has always
/// had (the contract: the same on every version), where 30 students got
/// 28 distinct questions.
#[tokio::test]
async fn a_distinct_template_gives_a_class_distinct_variants() {
    let app = TestApp::new().await;
    let class = app.get("/v1/templates/p103-class").await.json();
    let body = json!({"kind": "flywheel", "name": "p103-distinct", "request": class["request"],
        "parameters": class["parameters"], "distinct": true});
    let r = app.post("/v1/templates", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    for seed in [1u64, 9_223_372_036_854_775_000] {
        let list = app.get(&format!("/v1/templates/p103-distinct/variants?seed={seed}&count=40")).await.json();
        let drawn: Vec<String> =
            list["variants"].as_array().unwrap().iter().map(|v| v["parameters"].to_string()).collect();
        let distinct: std::collections::HashSet<&String> = drawn.iter().collect();
        assert_eq!((drawn.len(), distinct.len()), (40, 40), "seed {seed}: {drawn:?}");
        for v in list["variants"].as_array().unwrap() {
            let f = v["parameters"]["F"].as_f64().unwrap();
            assert!((300.0..=800.0).contains(&f) && f % 50.0 == 0.0, "{v}");
        }
    }
}

/// March 2012's C_m* (printed 69.923 N·m): the motor's mean torque on the
/// reference shaft balances the load's work over the cycle, closed form
/// F·R·(1 − sin π/4)/2π for the load −F·R·cos φ on π/4 < φ < π/2; at F =
/// 12 000 N (not the statement's) to 1e-9, with the load's mean the
/// opposite. Over a period of 720° an item's mean torque is its work over
/// 4π (a −10 N·m load on half a turn: −2.5 N·m, the motor +2.5).
#[tokio::test]
async fn an_items_mean_torque_is_its_work_over_the_period() {
    let app = TestApp::new().await;
    let (f, r) = (12_000.0_f64, 0.15);
    let expected = f * r * (1.0 - std::f64::consts::FRAC_PI_4.sin()) / std::f64::consts::TAU;
    let got = |path: &str| {
        let app = &app;
        let path = path.to_string();
        async move { app.get(&path).await.text.parse::<f64>().unwrap() }
    };
    let base = "/v1/templates/exam-2012-march/result";
    let motor = got(&format!("{base}/statement/motor_reduced_torque?F=12000")).await;
    assert!((motor - expected).abs() < 1e-9 * expected, "C_m* {motor}, closed form {expected}");
    let load = got(&format!("{base}/item_work/0/mean_torque?F=12000")).await;
    assert!((load + expected).abs() < 1e-9 * expected, "the load's mean {load}");
    // Over 720°: a load of −10 N·m on 0 < φ < π does −10π J, a mean of −2.5 N·m; the motor +2.5.
    let four_stroke = json!({"mean_speed": "60 rpm", "irregularity": 0.05, "period": "720 deg", "samples": 0,
        "torques": [{"name": "load", "value": {"segments": [{"from": 0, "to": "pi", "expr": "-10"}]}},
                    {"name": "motor", "balance": true}]});
    let result = app.result("/v1/flywheel", &four_stroke).await;
    close(&result["item_work"][0]["mean_torque"], -2.5, 1e-12, "the load's mean over 4π");
    close(&result["item_work"][1]["mean_torque"], 2.5, 1e-12, "the motor's, the balance torque");
    close(&result["balance_torque"], 2.5, 1e-12, "balance torque");
}
