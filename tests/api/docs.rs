//! Every command of the README and of the guides in `docs/`, run as a reader
//! runs it: each ```sh block's commands, in the page's order, by bash with
//! the real binary listening (on a free port for 8080), in a folder that sees
//! the repository's `library/` and `examples/`. A value a command prints in
//! its comment (`# 353.5214273220119`) must be what it prints, byte for byte;
//! a comment that begins with a status (`# 422: …`) must be that error; the
//! CSV lines printed under a command (`# F,eps,…`) must begin its answer
//! (a cell with `…` stands for a job id); every other command must succeed.
//! `{id}` and `$ID` are the job the page created last. A command this test
//! cannot run (a container engine, `cargo test` itself) must be named in
//! [`ELSEWHERE`] with the file that runs it, which must hold it.

use crate::crash::start_with;
use crate::wire::free_port;
use std::path::Path;
use std::process::Command as Shell;

/// The pages a person reads, each with its commands.
const GUIDES: [&str; 6] =
    ["README.md", "docs/course.md", "docs/lab.md", "docs/grading.md", "docs/operators.md", "docs/api.md"];

/// Commands run elsewhere: (how the command begins, the file that runs it,
/// what that file holds to show it does).
const ELSEWHERE: [(&str, &str, &str); 12] = [
    // This test's service is that binary with its defaults (a fresh database, a free port).
    ("cargo run --release", "tests/api/crash.rs", "CARGO_BIN_EXE_mechdyn"),
    ("cargo test", ".ci/run", "cargo test"),
    // Measured, not tested: docs/BENCHMARKS.md says what it printed.
    ("cargo bench", "Cargo.toml", "[[bench]]"),
    ("docker build", ".ci/container", "podman build --format docker"),
    ("podman build", ".ci/container", "podman build --format docker"),
    ("docker run", "tests/api/container.rs", "--read-only"),
    ("docker exec", "tests/api/container.rs", "backup"),
    ("docker inspect", "tests/api/container.rs", "healthcheck"),
    ("MECHDYN_DB_PASSWORD=", ".ci/run", "docker-compose -f deploy/compose.yaml config"),
    ("pg_dump", "tests/api/postgres.rs", "server.client(\"pg_dump\")"),
    ("pg_restore", "tests/api/postgres.rs", "pg_restore"),
    ("pip install ./clients/python", "tests/api/python_client.rs", "\"pip\", \"install\""),
];

/// A command of a page: where it is, its text (continued lines joined), the
/// comment on its last line and the lines printed under it.
struct Command {
    at: String,
    text: String,
    comment: Option<String>,
    printed: Vec<String>,
}

/// The commands of every ```sh block of `page`.
fn commands(page: &str) -> Vec<Command> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(page)).unwrap();
    let (mut out, mut fence, mut open): (Vec<Command>, Option<usize>, Option<(usize, String)>) = (vec![], None, None);
    for (n, raw) in text.lines().enumerate() {
        let line = raw.trim_start();
        let Some(indent) = fence else {
            fence = (line == "```sh").then_some(raw.len() - line.len());
            continue;
        };
        if line == "```" {
            fence = None;
            continue;
        }
        let line = raw.get(indent..).unwrap_or(line);
        let (start, body) = match open.take() {
            Some((start, body)) => (start, body + "\n" + line),
            None if line.starts_with("# ") => {
                out.last_mut().into_iter().for_each(|last| last.printed.push(line[2..].to_string()));
                continue;
            }
            None if line.trim().is_empty() => continue,
            None => (n + 1, line.to_string()),
        };
        // A command goes on while a quote is open or a line ends with `\`.
        let (text, comment) = match body.rsplit_once("  # ") {
            Some((text, comment)) if text.matches('\'').count() % 2 == 0 => (text, Some(comment.trim().to_string())),
            _ => (body.as_str(), None),
        };
        if text.matches('\'').count() % 2 == 1 || text.ends_with('\\') {
            open = Some((start, body));
            continue;
        }
        out.push(Command { at: format!("{page}:{start}"), text: text.trim().to_string(), comment, printed: vec![] });
    }
    out
}

/// How a comment reads: a status it expects and the pointer its problem
/// names (`422: /mean_speed …`), or a value it prints (`353.52…, as plain
/// text`), or neither.
enum Expect {
    Status(u16, Option<String>),
    Value(String),
    Nothing,
}

fn expect(comment: Option<&str>) -> Expect {
    let mut words = comment.unwrap_or_default().split_whitespace();
    let Some(first) = words.next() else { return Expect::Nothing };
    if let Some(status) = first.strip_suffix(':').and_then(|s| s.parse::<u16>().ok()).filter(|s| *s >= 400) {
        let pointer = words.next().filter(|w| w.starts_with('/')).map(|w| w.trim_end_matches(',').to_string());
        return Expect::Status(status, pointer);
    }
    let value = first.trim_end_matches(',');
    match value.replace(',', ".").parse::<f64>() {
        Ok(_) => Expect::Value(value.to_string()),
        Err(_) => Expect::Nothing,
    }
}

/// `printed` CSV lines (`,` or `;` between cells, a cell with `…` any text)
/// against the first lines of `answer`.
fn begins_with(answer: &str, printed: &[String]) -> bool {
    let cells = |line: &str| -> Vec<String> {
        let sep = if line.contains(';') { ';' } else { ',' };
        line.split(sep).map(str::to_string).collect()
    };
    printed.len() <= answer.lines().count()
        && printed.iter().zip(answer.lines()).all(|(want, got)| {
            let (want, got) = (cells(want), cells(got.trim_end()));
            want.len() == got.len() && want.iter().zip(&got).all(|(w, g)| w.contains('…') || w == g)
        })
}

/// Whether `printed` is an answer's CSV rather than words about it.
fn is_csv(printed: &[String]) -> bool {
    printed.first().is_some_and(|l| !l.contains(' ') && (l.contains(',') || l.contains(';')))
}

/// The job a command's answer created: a job's JSON, or its Location.
fn created(answer: &str) -> Option<String> {
    if let Ok(job) = serde_json::from_str::<serde_json::Value>(answer) {
        return (job.get("kind").is_some() && job.get("builtin").is_none())
            .then(|| job["id"].as_str().map(str::to_string))?;
    }
    let at = answer.to_ascii_lowercase().find("location: /v1/jobs/")?;
    Some(answer[at + "location: /v1/jobs/".len()..].trim().to_string())
}

/// bash, the command's `curl` failing on an error status with its body.
const PRELUDE: &str = r#"set -o pipefail
curl() { command curl --silent --show-error --fail-with-body --max-time 120 "$@"; }
mechdyn() { "$MECHDYN_BIN" "$@"; }
cargo() { if [ "$1 $2 $3" = "run --release --" ]; then shift 3; "$MECHDYN_BIN" "$@"; else return 99; fi; }
"#;

/// Runs `command` in `dir` with the service at `port`: its exit status and output.
fn run(command: &str, dir: &Path, port: u16) -> (i32, String) {
    let script = command
        .replace("http://127.0.0.1:8080", &format!("http://127.0.0.1:{port}"))
        .replace("localhost:8080", &format!("127.0.0.1:{port}"));
    let out = Shell::new("bash")
        .args(["-c", &format!("{PRELUDE}{script}")])
        .current_dir(dir)
        .env("MECHDYN_BIN", env!("CARGO_BIN_EXE_mechdyn"))
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    (out.status.code().unwrap_or(-1), text)
}

/// Whether this test runs `text` itself.
fn runs_here(text: &str) -> bool {
    ["curl ", "printf ", "mechdyn ", "cargo run --release -- "].iter().any(|p| text.starts_with(p))
}

/// What was wrong with one command's run, if anything.
fn judge(command: &Command, status: i32, answer: &str) -> Option<String> {
    match expect(command.comment.as_deref()) {
        Expect::Status(code, pointer) => {
            let named = pointer.as_ref().is_none_or(|p| answer.contains(&format!("\"pointer\":\"{p}\"")));
            let right = status == 22 && answer.contains(&format!("\"status\":{code}")) && named;
            (!right).then(|| format!("expected a {code} at {pointer:?}, got exit {status}: {answer}"))
        }
        _ if status != 0 => Some(format!("exit {status}: {answer}")),
        Expect::Value(value) if answer.trim() != value => Some(format!("prints {value}, answered {}", answer.trim())),
        _ if is_csv(&command.printed) && !begins_with(answer, &command.printed) => {
            Some(format!("prints {:?}, answered {answer}", command.printed))
        }
        _ => None,
    }
}

#[test]
fn every_command_of_the_guides_does_what_the_guide_says() {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for folder in ["library", "examples"] {
        std::os::unix::fs::symlink(root.join(folder), dir.path().join(folder)).unwrap();
    }
    let port = free_port();
    let mut service = start_with(&format!("sqlite://{}/jobs.db", dir.path().display()), port, &[]);
    let (mut failures, mut ran) = (vec![], 0);
    for page in GUIDES {
        let mut id = String::new();
        for command in commands(page) {
            if !runs_here(&command.text) {
                let elsewhere = ELSEWHERE.iter().find(|(start, ..)| command.text.starts_with(start));
                match elsewhere {
                    Some((_, file, holds)) if std::fs::read_to_string(root.join(file)).unwrap().contains(holds) => {}
                    _ => failures.push(format!("{}: `{}` is run by no test", command.at, command.text)),
                }
                continue;
            }
            let (status, answer) = run(&command.text.replace("{id}", &id).replace("$ID", &id), dir.path(), port);
            ran += 1;
            if let Some(wrong) = judge(&command, status, &answer) {
                let wrong: String = wrong.chars().take(600).collect();
                failures.push(format!("{}: `{}`: {wrong}", command.at, command.text));
            }
            if command.text.contains("POST") && status == 0 {
                id = created(&answer).unwrap_or(id);
            }
        }
    }
    let _ = service.kill();
    let _ = service.wait();
    assert!(ran >= 40, "only {ran} commands found in the guides");
    assert!(failures.is_empty(), "{} commands of the guides:\n{}", failures.len(), failures.join("\n\n"));
}
