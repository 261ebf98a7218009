//! Structural rules of the crate, checked on every test run.

use std::path::Path;

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `src/engine` and `src/units.rs` are pure math: no transport, storage,
/// serialization or I/O crates.
#[test]
fn the_engine_is_pure() {
    let mut files = Vec::new();
    rust_files(&root().join("src/engine"), &mut files);
    files.push(root().join("src/units.rs"));
    let forbidden = ["axum", "sqlx", "tokio", "utoipa", "serde", "std::fs", "std::net", "tower"];
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for word in forbidden {
                let used = code.contains(&format!("{word}::"))
                    || code.contains(&format!("use {word}"))
                    || code.contains(&format!("{word}_json"));
                assert!(!used, "{}:{} uses {word}: {line}", file.display(), n + 1);
            }
        }
    }
}

/// Every schema of the OpenAPI document has a name of its own: utoipa names
/// a component after its type (or its `as = ...`), and two types of one
/// name silently share one schema (the flywheel's samples were documented
/// as the dynamics' ones).
#[test]
fn no_two_schemas_share_a_name() {
    let mut files = Vec::new();
    rust_files(&root().join("src/api"), &mut files);
    let mut names: Vec<(String, String)> = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for (n, line) in lines.iter().enumerate() {
            if !(line.contains("derive(") && line.contains("ToSchema")) {
                continue;
            }
            let after = &lines[n + 1..lines.len().min(n + 12)];
            let renamed = after
                .iter()
                .take_while(|l| l.trim_start().starts_with("#["))
                .find_map(|l| l.split("as = ").nth(1).map(|r| r.trim_end_matches([')', ']']).to_string()));
            let declared = after.iter().find_map(|l| {
                let rest =
                    l.trim_start().strip_prefix("pub struct ").or_else(|| l.trim_start().strip_prefix("pub enum "))?;
                Some(rest.split(|c: char| !c.is_alphanumeric() && c != '_').next()?.to_string())
            });
            if let Some(name) = renamed.or(declared) {
                names.push((name, format!("{}:{}", file.display(), n + 1)));
            }
        }
    }
    names.sort();
    for pair in names.windows(2) {
        assert_ne!(pair[0].0, pair[1].0, "two schemas named {}: {} and {}", pair[0].0, pair[0].1, pair[1].1);
    }
    assert!(names.len() > 30, "found only {} schemas", names.len());
}

/// The committed OpenAPI document is the one the code generates.
/// Regenerate with `cargo run -- openapi > openapi/openapi.json`.
#[test]
fn the_committed_openapi_document_is_up_to_date() {
    let generated = mechdyn::api::openapi().to_pretty_json().unwrap();
    let path = root().join("openapi/openapi.json");
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed.trim() == generated.trim(),
        "openapi/openapi.json is out of date: run `cargo run -- openapi > openapi/openapi.json`"
    );
}

/// Without a Docker engine here, check that the Dockerfile agrees with the
/// code: binary name, non-root user, listen port, health check, data volume.
#[test]
fn the_dockerfile_agrees_with_the_code() {
    use clap::CommandFactory;
    let docker = std::fs::read_to_string(root().join("Dockerfile")).unwrap();
    let name = env!("CARGO_PKG_NAME");
    assert!(docker.contains(&format!("--bin {name}")), "builds the binary {name}");
    assert!(docker.contains(&format!("ENTRYPOINT [\"/app/{name}\"]")));
    let cli = mechdyn::config::Cli::command();
    assert!(cli.get_subcommands().any(|c| c.get_name() == "healthcheck"), "the healthcheck subcommand exists");
    assert!(docker.contains(&format!("CMD [\"/app/{name}\", \"healthcheck\"]")));
    let user = docker.lines().find_map(|l| l.strip_prefix("USER ")).expect("a USER line");
    assert!(!user.starts_with("root") && !user.starts_with('0'), "runs as non-root, not {user}");
    let addr = docker.split("MECHDYN_ADDR=").nth(1).and_then(|s| s.split_whitespace().next()).expect("MECHDYN_ADDR");
    let port = addr.rsplit(':').next().unwrap();
    assert!(addr.starts_with("0.0.0.0:"), "listens on all interfaces in the container");
    assert!(docker.contains(&format!("EXPOSE {port}")), "EXPOSE matches MECHDYN_ADDR's port {port}");
    assert!(docker.contains("VOLUME [\"/data\"]") && docker.contains("DATABASE_URL=sqlite:///data/"));
    assert_eq!(mechdyn::api::HEALTH_PATH, "/healthz");
}
