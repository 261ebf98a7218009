//! mechdyn's own Python client, `clients/python` (issue 73), as a grader
//! gets it: its generated layer is what openapi-python-client (pinned by
//! `.ci/run`) makes from the served document with the project's
//! configuration and templates, file for file (drift fails here, as
//! `openapi/openapi.json`'s does in tests/architecture.rs); `pip install`
//! installs it; `mypy --strict` finds nothing in the package, in the
//! docs' example and in the PrairieLearn-style grader; and those, with
//! `tests/clients/python_client.py` (every call a grader makes, against
//! closed forms and second paths), run against the real binary.
//!
//! Skipped without a `.venv` that has the generator and mypy, unless
//! MECHDYN_REQUIRE_GENERATORS is set (CI sets it).

use crate::crash::{free_port, start_with};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// `.venv`'s Python, when it has the generator and mypy.
fn python() -> Option<String> {
    let python = format!("{ROOT}/.venv/bin/python");
    let has = Command::new(&python).args(["-c", "import openapi_python_client, mypy, httpx, attrs"]).output();
    has.is_ok_and(|o| o.status.success()).then_some(python)
}

fn said(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

/// Every file under `dir` (no caches), by its path from `dir`.
fn files(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = vec![];
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() && !path.ends_with("__pycache__") {
                stack.push(path);
            } else if path.is_file() {
                out.push((path.strip_prefix(dir).unwrap().to_path_buf(), std::fs::read(&path).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn the_python_client_is_generated_installed_typed_and_graded_with() {
    let Some(python) = python() else {
        assert!(std::env::var_os("MECHDYN_REQUIRE_GENERATORS").is_none(), "no .venv with the generator and mypy");
        return eprintln!("skipped: `.venv/bin/pip install openapi-python-client==0.29.1 mypy`");
    };
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let mut child = start_with(&format!("sqlite://{}", dir.path().join("jobs.db").display()), port, &[]);
    let base = format!("http://127.0.0.1:{port}");
    let fresh = dir.path().join("generated");
    let out = Command::new(format!("{ROOT}/.venv/bin/openapi-python-client"))
        .args(["generate", "--url", &format!("{base}/openapi.json"), "--meta", "none"])
        .args(["--config", &format!("{ROOT}/openapi/openapi-python-client.yaml")])
        .args(["--custom-template-path", &format!("{ROOT}/clients/python/templates")])
        .arg("--output-path")
        .arg(&fresh)
        .output()
        .unwrap();
    assert!(out.status.success(), "the generator: {}", said(&out));
    let committed = files(Path::new(ROOT).join("clients/python/mechdyn_client/generated").as_path());
    let drift: Vec<_> = files(&fresh).into_iter().filter(|f| !committed.contains(f)).map(|f| f.0).collect();
    let gone = committed.len() != files(&fresh).len();
    assert!(
        drift.is_empty() && !gone,
        "clients/python is not what the document makes ({drift:?}): run clients/python/generate"
    );

    // Installed from a copy: pip builds in the source tree, whose leftovers would be installed next time.
    let (site, source) = (dir.path().join("site"), dir.path().join("source"));
    let copy = Command::new("cp").args(["-r", &format!("{ROOT}/clients/python")]).arg(&source).output().unwrap();
    assert!(copy.status.success(), "{}", said(&copy));
    let pip = Command::new(&python)
        .args(["-m", "pip", "install", "--quiet", "--no-deps", "--target"])
        .arg(&site)
        .arg(&source)
        .output()
        .unwrap();
    assert!(pip.status.success(), "pip install ./clients/python: {}", said(&pip));
    let mypy = Command::new(&python)
        .args(["-m", "mypy", "--strict", "--no-incremental"])
        .arg(site.join("mechdyn_client"))
        .args(["examples/grading/typed_client.py", "examples/grading/pl_client_grader.py"])
        .arg("tests/clients/python_client.py")
        .current_dir(ROOT)
        .env("MYPYPATH", &site)
        .output()
        .unwrap();
    assert!(mypy.status.success(), "mypy --strict: {}", said(&mypy));

    let run =
        |args: &[&str]| Command::new(&python).args(args).current_dir(ROOT).env("PYTHONPATH", &site).output().unwrap();
    let calls = run(&["tests/clients/python_client.py", &base, "examples/grading/class.csv"]);
    // docs/grading.md's example: P.103's answers as in its curl example, score 0.5 (260 slug·ft² =
    // 352.51 kg·m² within 1 % of I_exact = 353.52, case F1; 353.5 not within 1 % of I_approx = 348.99).
    let example = run(&["examples/grading/typed_client.py", &base, "s001", "260 slug*ft^2", "353.5"]);
    let grader = pl_grader(&run, dir.path(), &base);
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(calls.status.success() && said(&calls).contains("every call checked"), "{}", said(&calls));
    let printed = said(&example);
    assert!(example.status.success() && printed.contains("s001: score 0.5 (1 of 2)"), "{printed}");
    assert!(printed.contains("(label s001); I_exact = 353.5214273220119"), "{printed}");
    grader();
}

/// The PrairieLearn-style grader on a submission: P.103 at its defaults,
/// the exact inertia answered as case F1's closed form (passes) and the
/// approximate one 10 % off (fails): score 0.5. The checks run at once;
/// what they wrote is judged by the returned closure, after the service
/// has stopped.
fn pl_grader(run: &dyn Fn(&[&str]) -> Output, dir: &Path, base: &str) -> impl FnOnce() {
    let root = dir.join("grade");
    std::fs::create_dir_all(root.join("data")).unwrap();
    std::fs::create_dir_all(root.join("student")).unwrap();
    let data =
        r#"{"params": {"template": "p103-slider-flywheel", "required": ["inertia_exact", "inertia_approximate"]}}"#;
    std::fs::write(root.join("data/data.json"), data).unwrap();
    let answers = r#"{"inertia_exact": 353.52142732201185, "inertia_approximate": "383.9 kg*m^2"}"#;
    std::fs::write(root.join("student/answers.json"), answers).unwrap();
    let out = run(&["examples/grading/pl_client_grader.py", "--root", root.to_str().unwrap(), "--service", base]);
    let results = std::fs::read_to_string(root.join("results/results.json")).unwrap_or_default();
    move || {
        assert!(out.status.success(), "{}", said(&out));
        let doc: serde_json::Value = serde_json::from_str(&results).unwrap();
        assert_eq!((doc["gradable"].as_bool(), doc["score"].as_f64()), (Some(true), Some(0.5)), "{doc}");
        assert_eq!(doc["tests"].as_array().map(Vec::len), Some(2), "{doc}");
    }
}
