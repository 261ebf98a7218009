//! The binary's helpers: `solve` without a server, `healthcheck`, `openapi`.

use std::process::Command;

fn mechdyn(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_mechdyn")).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

/// `solve` prints the same result as the API: P.103's 348.99 kg·m² (textbook).
#[test]
fn solve_prints_the_result_without_a_server() {
    let out = mechdyn(&["solve", "flywheel", "library/requests/p103_slider.json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let r: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let i = r["inertia_approximate"].as_f64().unwrap();
    assert!((i - 348.98939677963364).abs() < 1e-9 * i, "{i}");
}

#[test]
fn solve_reports_invalid_requests_as_problems() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bad.json");
    std::fs::write(&file, r#"{"mean_speed": "60 rpm", "irregularity": 5, "torques": []}"#).unwrap();
    let out = mechdyn(&["solve", "flywheel", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let problem: serde_json::Value = serde_json::from_slice(&out.stderr).unwrap();
    assert_eq!(problem["status"], 422);
}

#[test]
fn healthcheck_fails_when_nothing_listens() {
    let port = std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    let out = mechdyn(&["healthcheck", "--addr", &format!("127.0.0.1:{port}"), "--operator-addr", "off"]);
    assert!(!out.status.success());
}

#[test]
fn openapi_prints_the_committed_document() {
    let out = mechdyn(&["openapi"]);
    let committed = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/openapi/openapi.json")).unwrap();
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), committed.trim());
}

/// `solve kinetostatics` prints K1's driving torque at 30° (−228.4912 N·m, reference case).
#[test]
fn solve_kinetostatics_prints_the_result() {
    let out = mechdyn(&["solve", "kinetostatics", "library/requests/k1_offset_slider_crank.json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let r: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let t = r["steps"][1]["driving"].as_f64().unwrap();
    assert!((t - -228.491215292969).abs() < 1e-6, "{t}");
}

/// Every calculator is solvable offline: docs/grading.md's mechanism-dynamics
/// example reaches 4π (its `until_angle`), to the printed digits of the API.
#[test]
fn solve_knows_every_job_kind() {
    let out = mechdyn(&["solve", "dynamics", "library/requests/d1_scotch_yoke_machine.json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let r: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let end = r["events"].as_array().unwrap().last().unwrap()["angle"].as_f64().unwrap();
    assert!((end - 4.0 * std::f64::consts::PI).abs() < 1e-9, "{end}");
    let out = mechdyn(&["solve", "rotr", "library/requests/p103_slider.json"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("gear_train, equivalent_masses, rotor"));
}

/// `mechdyn openapi | head` closes the pipe after a few bytes: the binary
/// stops quietly (it panicked with a backtrace on the broken pipe).
#[test]
fn openapi_into_a_closed_pipe_is_no_failure() {
    use std::io::Read;
    let mut child = Command::new(env!("CARGO_BIN_EXE_mechdyn"))
        .arg("openapi")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut head = [0u8; 10];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    // The read end dropped: the rest of the document (over 64 KiB) meets a closed pipe.
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{:?}: {}", out.status, String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(&head[..1], b"{");
}
