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
    let generated = mechdyn::registry().openapi_json().to_string();
    let path = root().join("openapi/openapi.json");
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed.trim() == generated.trim(),
        "openapi/openapi.json is out of date: run `cargo run -- openapi > openapi/openapi.json`"
    );
}

/// Every `$ref` of the generated document points at a schema it defines
/// (issue 49: `DecimalMark`, the `decimal` parameter of eight operations,
/// was referenced and never defined; openapi-core and the generators
/// refuse such a document).
#[test]
fn every_reference_of_the_document_resolves() {
    fn refs<'a>(v: &'a serde_json::Value, out: &mut Vec<&'a str>) {
        match v {
            serde_json::Value::Object(map) => {
                if let Some(serde_json::Value::String(r)) = map.get("$ref") {
                    out.push(r);
                }
                map.values().for_each(|v| refs(v, out));
            }
            serde_json::Value::Array(items) => items.iter().for_each(|v| refs(v, out)),
            _ => {}
        }
    }
    let doc: serde_json::Value = serde_json::from_str(mechdyn::registry().openapi_json()).unwrap();
    let mut found = Vec::new();
    refs(&doc, &mut found);
    assert!(found.len() > 50, "found only {} references", found.len());
    for r in found {
        let name = r.strip_prefix("#/components/schemas/").unwrap_or_else(|| panic!("a reference elsewhere: {r}"));
        assert!(doc["components"]["schemas"][name].is_object(), "{r} is referenced and never defined");
    }
}

/// No schema of the generated document says `"items": false` (issue 49:
/// valid 3.1, but openapi-python-client refuses the whole document on it —
/// `BodyPoint`, a spring's end — and generates no client).
#[test]
fn no_schema_forbids_items_with_false() {
    fn walk(v: &serde_json::Value, at: &str, out: &mut Vec<String>) {
        match v {
            serde_json::Value::Object(map) => {
                if map.get("items") == Some(&serde_json::Value::Bool(false)) {
                    out.push(at.to_string());
                }
                map.iter().for_each(|(k, v)| walk(v, &format!("{at}/{k}"), out));
            }
            serde_json::Value::Array(items) => {
                items.iter().enumerate().for_each(|(k, v)| walk(v, &format!("{at}/{k}"), out))
            }
            _ => {}
        }
    }
    let doc: serde_json::Value = serde_json::from_str(mechdyn::registry().openapi_json()).unwrap();
    let mut found = Vec::new();
    walk(&doc, "", &mut found);
    assert!(found.is_empty(), "items: false at {found:?}");
}

/// The Dockerfile agrees with the code, checked without building it (CI
/// builds and runs the image with podman: tests/api/container.rs): binary
/// name, non-root user, listen port, health check, data volume.
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
    // Every folder the code compiles in (include_str!) is copied into the build.
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for included in text.split("include_str!(\"").skip(1).filter_map(|s| s.split('"').next()) {
            let path = file.parent().unwrap().join(included).canonicalize().unwrap();
            let top =
                path.strip_prefix(root().canonicalize().unwrap()).unwrap().iter().next().unwrap().to_string_lossy();
            assert!(
                docker.contains(&format!("COPY {top} ./{top}")),
                "{} includes {included}: COPY {top}",
                file.display()
            );
        }
    }
}

/// The engine's top-level modules (`src/engine/X.rs` or `src/engine/X/`)
/// depend on each other without a cycle, so each can be read and tested
/// from the bottom up (a function of φ knows nothing of mechanisms).
#[test]
fn the_engine_modules_have_no_cycle() {
    let engine = root().join("src/engine");
    let mut files = Vec::new();
    rust_files(&engine, &mut files);
    let mut edges: std::collections::BTreeMap<String, std::collections::BTreeSet<String>> = Default::default();
    for file in &files {
        let rel = file.strip_prefix(&engine).unwrap().with_extension("");
        let mut module: Vec<String> = rel.iter().map(|c| c.to_string_lossy().into_owned()).collect();
        if module.last().is_some_and(|m| m == "mod") {
            module.pop();
        }
        let Some(top) = module.first().cloned().filter(|t| t != "mod") else { continue };
        let text = std::fs::read_to_string(file).unwrap();
        let code: String = text.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n");
        for target in engine_references(&code, &module) {
            let is_module = engine.join(format!("{target}.rs")).exists() || engine.join(&target).is_dir();
            if target != top && is_module {
                edges.entry(top.clone()).or_default().insert(target);
            }
        }
    }
    // Depth-first search for a back edge.
    fn visit<'a>(
        node: &'a str,
        edges: &'a std::collections::BTreeMap<String, std::collections::BTreeSet<String>>,
        path: &mut Vec<&'a str>,
        done: &mut std::collections::BTreeSet<&'a str>,
    ) {
        if let Some(at) = path.iter().position(|n| *n == node) {
            panic!("engine modules form a cycle: {} -> {node}", path[at..].join(" -> "));
        }
        if !done.insert(node) {
            return;
        }
        path.push(node);
        for next in edges.get(node).into_iter().flatten() {
            visit(next, edges, path, done);
        }
        path.pop();
    }
    let mut done = std::collections::BTreeSet::new();
    for node in edges.keys() {
        visit(node, &edges, &mut Vec::new(), &mut done);
    }
    assert!(edges.contains_key("machine"), "the scan found the machine's dependencies: {edges:?}");
}

/// Top-level engine modules that `code` (in engine module `module`) names
/// through `super::…` or `crate::engine::…`, braces expanded one level.
fn engine_references(code: &str, module: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    let ident = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
    for (i, _) in code.match_indices("super::").chain(code.match_indices("crate::engine::")) {
        if i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b':') {
            continue; // the tail of a longer path, counted from its start
        }
        let mut rest = &code[i..];
        let mut depth = module.len();
        if let Some(r) = rest.strip_prefix("crate::engine::") {
            rest = r;
            depth = 0;
        }
        while let Some(r) = rest.strip_prefix("super::") {
            rest = r;
            depth = depth.saturating_sub(1);
        }
        let heads: Vec<String> = if let Some(group) = rest.strip_prefix('{') {
            let group = &group[..group.find('}').unwrap_or(group.len())];
            group.split(',').map(|s| ident(s.trim())).collect()
        } else {
            vec![ident(rest)]
        };
        for head in heads.into_iter().filter(|h| !h.is_empty()) {
            match depth {
                0 => out.push(head),
                _ => out.push(module[0].clone()),
            }
        }
    }
    out
}

#[path = "architecture/imports.rs"]
mod imports;

/// No two files of `src/` use each other, directly or through others: each
/// can be read knowing only what it uses, and the wings stay apart. A
/// submodule's use of its parent (`super::`, where it sees the parent's
/// private items) is the one way back left out.
#[test]
fn no_file_of_the_crate_is_in_an_import_cycle() {
    let edges = imports::Crate::read(&root().join("src")).edges();
    let machine = &edges["engine/machine.rs"];
    assert!(machine.contains("engine/kinematics.rs"), "the scan sees the machine's uses: {machine:?}");
    let uses = |from: &str, to: &str| {
        let found: Vec<String> = edges
            .iter()
            .filter(|(file, _)| file.starts_with(from))
            .flat_map(|(file, targets)| {
                targets.iter().filter(|t| t.starts_with(to)).map(move |t| format!("{file} uses {t}"))
            })
            .collect();
        found
    };
    // The wings: the contract knows neither; the kinds know nothing of the
    // service; the service never names a kind; a check uses templates, not
    // the other way.
    for (from, to) in [
        ("kind/", "api/"),
        ("kind/", "kinds/"),
        ("kinds/", "api/"),
        ("api/", "kinds/"),
        ("api/templates/", "api/check/"),
    ] {
        let found = uses(from, to);
        assert!(found.is_empty(), "{from} must not use {to}: {found:?}");
    }
    assert!(!uses("api/check/", "api/templates/").is_empty(), "the scan sees a check's use of templates");
    let cycles = imports::cycles(&edges);
    let shown: Vec<String> = cycles.iter().map(|c| format!("{} files: {}", c.len(), c.join(", "))).collect();
    assert!(cycles.is_empty(), "files in import cycles:\n{}", shown.join("\n"));
}
