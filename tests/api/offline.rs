//! Grading without a network: the binary's `solve`, `check` and `grade`
//! give what the service answers (byte for byte), and the grading examples
//! (examples/grading, Python's standard library only) work against the real
//! service and the real binary.

use crate::crash::{free_port, start};
use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};
use std::collections::HashMap;
use std::io::Write;
use std::process::{Command, Output, Stdio};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn mechdyn(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_mechdyn"))
        .args(args)
        .current_dir(ROOT)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(stdin.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "mechdyn {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    out
}

/// stdout without its final newline.
fn printed(out: &Output) -> String {
    String::from_utf8(out.stdout.clone()).unwrap().strip_suffix('\n').unwrap().to_string()
}

/// The stored bytes of a job's `result`, as the service sent them.
fn result_text(job: &str) -> String {
    let fields: HashMap<String, Box<serde_json::value::RawValue>> = serde_json::from_str(job).unwrap();
    fields["result"].get().to_string()
}

fn python(args: &[&str]) -> Output {
    let out = Command::new("python3").args(args).current_dir(ROOT).output().expect("python3");
    assert!(out.status.success(), "python3 {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    out
}

#[tokio::test]
async fn solve_and_check_offline_print_what_the_service_stores() {
    let app = TestApp::new().await;
    let body = request("p103_slider");
    let posted = app.post("/v1/flywheel", &body).await;
    let offline = mechdyn(&["solve", "flywheel", "-"], &body.to_string());
    assert_eq!(printed(&offline), result_text(&posted.text));
    // One value, converted, as GET .../result/{pointer}?unit= answers it.
    let part = app.get(&format!("{}/result/inertia_exact?unit=slug*ft%5E2", posted.location.unwrap())).await;
    let value = mechdyn(
        &["solve", "flywheel", "library/requests/p103_slider.json", "--value", "/inertia_exact", "--unit", "slug*ft^2"],
        "",
    );
    assert_eq!(printed(&value), part.text);

    let check = json!({"template": "p103-class", "variant": 2, "answers": {"inertia_exact": "180 kg*m^2", "omega_max": 10},
        "format": "prairielearn"});
    let served = app.post("/v1/check", &check).await;
    assert_eq!(served.status, StatusCode::CREATED, "{}", served.text);
    assert_eq!(printed(&mechdyn(&["check", "-"], &check.to_string())), result_text(&served.text));
    // The service's own format names the reference job, a stored job's id: the rest is the same.
    let mut own = check.clone();
    own["format"] = json!("mechdyn");
    let served: Value = serde_json::from_str(&result_text(&app.post("/v1/check", &own).await.text)).unwrap();
    let mut offline: Value = serde_json::from_str(&printed(&mechdyn(&["check", "-"], &own.to_string()))).unwrap();
    assert!(offline["job"].is_string());
    offline["job"] = served["job"].clone();
    assert_eq!(offline, served);
}

/// The class of `examples/grading/class.csv` graded by the service (through
/// the example script, over HTTP) and by the offline binary: the same bytes.
/// The variants the service draws are those examples/grading/variant.py
/// computes from the written description of the generator.
#[test]
fn the_grading_examples_agree_with_the_service_and_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let _service = Stopped(start(&format!("sqlite://{}/grading.db", dir.path().display()), port));
    let base = format!("http://127.0.0.1:{port}");
    let class = "examples/grading/class.csv";
    let served = python(&["examples/grading/grade_class.py", &base, "p103-class", class, "--sigfigs", "3"]);
    let offline = mechdyn(&["grade", "p103-class", class, "--sigfigs", "3"], "");
    assert_eq!(String::from_utf8(served.stdout).unwrap(), printed(&offline) + "\n");
    assert!(String::from_utf8_lossy(&served.stderr).contains("students graded"));

    let independent = python(&["examples/grading/variant.py", "library/p103-class.json", "1", "50"]);
    let get = crate::crash::http(port, "GET", "/v1/templates/p103-class/variants?seed=1&count=50", "").unwrap();
    let served: Value = serde_json::from_str(&get.1).unwrap();
    for (line, v) in String::from_utf8(independent.stdout).unwrap().lines().zip(served["variants"].as_array().unwrap())
    {
        let mine: Value = serde_json::from_str(line).unwrap();
        assert_eq!((&mine["variant"], &mine["parameters"]), (&v["variant"], &v["parameters"]));
    }
}

/// A child process stopped when the test ends, passed or failed.
struct Stopped(std::process::Child);

impl Drop for Stopped {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The PrairieLearn-style grader writes results.json from a submission with
/// the offline binary: a correct answer scores, a malformed submission is
/// not gradable (no points, a reason).
#[test]
fn the_prairielearn_grader_writes_results_json_offline() {
    let root = tempfile::tempdir().unwrap();
    let dir = |d: &str| {
        std::fs::create_dir_all(root.path().join(d)).unwrap();
        root.path().join(d)
    };
    let required = ["inertia_exact", "inertia_approximate", "omega_max"];
    let data =
        json!({"params": {"template": "p103-slider-flywheel", "tolerance": {"relative": 0.005}, "required": required}});
    std::fs::write(dir("data").join("data.json"), data.to_string()).unwrap();
    // Case F1: I_exact = 353.52 kg·m² (353.5 is within 0.5 %); 342 is 2 % below I_approx = 348.99.
    let answers = json!({"inertia_exact": "353.5 kg*m^2", "inertia_approximate": 342.0});
    std::fs::write(dir("student").join("answers.json"), answers.to_string()).unwrap();
    let grader = |root: &std::path::Path| {
        python(&[
            "examples/grading/pl_grader.py",
            "--root",
            root.to_str().unwrap(),
            "--mechdyn",
            env!("CARGO_BIN_EXE_mechdyn"),
        ]);
        let text = std::fs::read_to_string(root.join("results").join("results.json")).unwrap();
        serde_json::from_str::<Value>(&text).unwrap()
    };
    // omega_max, required, is left out: it scores 0 (a third of the points).
    let results = grader(root.path());
    assert_eq!((results["gradable"].as_bool(), results["score"].as_f64()), (Some(true), Some(1.0 / 3.0)), "{results}");
    assert_eq!(results["tests"].as_array().unwrap().len(), 3);
    std::fs::write(dir("student").join("answers.json"), "[1, 2]").unwrap();
    let results = grader(root.path());
    assert_eq!((results["gradable"].as_bool(), results["score"].as_f64()), (Some(false), Some(0.0)), "{results}");
    assert!(results["message"].as_str().unwrap().contains("could not be read"));
}
