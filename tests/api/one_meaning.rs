//! One problem, one set of numbers (contract, part five; issue 72): a
//! flywheel's `inertia_exact` and `inertia_approximate` are the total
//! inertia on the reduction shaft and `flywheel_inertia` what the flywheel
//! adds, whichever form the problem is posed in. A pulley written as
//! `existing_inertia` and the same pulley written as a body of the
//! `machine` (a disk turning with the input, I*(φ) ≡ its inertia) are one
//! problem: every flywheel template is posed both ways and the numbers
//! must agree (1e-9 relative: the two forms go through different code,
//! the machine's I* from its mechanism at every angle). Before, the two
//! forms swapped the exact and approximate figures (P.113: 40.204 and
//! 39.204 against 39.204 and 40.204).

use crate::helpers::TestApp;
use serde_json::{Value, json};

/// The numbers that mean the same in every form.
const SAME: [&str; 4] =
    ["/inertia_exact", "/inertia_approximate", "/flywheel_inertia/exact", "/flywheel_inertia/approximate"];

/// A pulley of inertia `inertia` on the reduction shaft, as a machine.
fn pulley(inertia: f64) -> Value {
    json!({
        "mechanism": {
            "points": {"O": [0, 0]},
            "bodies": [{"name": "pulley", "mass": 1, "inertia": inertia, "cg": "O"}],
            "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "pulley"], "at": "O"}]
        },
        "input": {"joint": "O"}
    })
}

/// `existing_inertia` of a template's request, kg·m² (written "1 kg*m^2" or 1).
fn existing(request: &Value) -> f64 {
    match &request["existing_inertia"] {
        Value::Number(n) => n.as_f64().unwrap(),
        Value::String(s) if s.ends_with("kg*m^2") => s.trim_end_matches("kg*m^2").trim().parse().unwrap(),
        Value::Null => 0.0,
        other => panic!("existing_inertia {other}"),
    }
}

async fn solved(app: &TestApp, request: &Value, what: &str) -> Value {
    let r = app.post("/v1/flywheel", request).await;
    assert_eq!(r.status, 201, "{what}: {}", r.text);
    r.json()["result"].clone()
}

fn agree(a: &Value, b: &Value, what: &str) {
    for pointer in SAME {
        let (x, y) = (a.pointer(pointer).unwrap().as_f64().unwrap(), b.pointer(pointer).unwrap().as_f64().unwrap());
        assert!((x - y).abs() <= 1e-9 * x.abs().max(y.abs()), "{what}, {pointer}: {x} against {y}");
    }
}

/// Every flywheel template with 1.5 kg·m² more on its shaft, as
/// `existing_inertia` and as a pulley in a `machine`; and a template with
/// an existing inertia E (P.113's pulley, January 2012's) against E moved
/// into the machine.
#[tokio::test]
async fn a_pulley_is_the_same_inertia_in_every_form() {
    let app = TestApp::new().await;
    let list = app.get("/v1/templates").await.json();
    let templates: Vec<&Value> = list["items"].as_array().unwrap().iter().filter(|t| t["kind"] == "flywheel").collect();
    assert!(templates.len() >= 8, "{} flywheel templates", templates.len());
    let extra = 1.5;
    let mut moved = 0;
    for t in templates {
        let (id, request) = (t["id"].as_str().unwrap(), &t["request"]);
        let e = existing(request);
        let mut a = request.clone();
        a["existing_inertia"] = json!(e + extra);
        let mut b = request.clone();
        b["existing_inertia"] = json!(e);
        b["machine"] = pulley(extra);
        agree(&solved(&app, &a, id).await, &solved(&app, &b, id).await, &format!("{id} + {extra} kg·m²"));
        if e > 0.0 {
            let mut c = request.clone();
            c["existing_inertia"] = json!(0);
            c["machine"] = pulley(e);
            agree(&solved(&app, request, id).await, &solved(&app, &c, id).await, &format!("{id}, its {e} kg·m² moved"));
            moved += 1;
        }
    }
    assert!(moved >= 2, "P.113 and January 2012 have a pulley");
}
