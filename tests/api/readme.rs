//! The README's first example, as a reader runs it: its flywheel request is
//! posted as printed, and every `result/…` line that prints a value in its
//! comment answers exactly that text. A change of the engine's last digits
//! fails here, on every machine, not only in the container test that reads
//! the same request.

use crate::helpers::TestApp;

/// The README's first request (the flywheel of P.103) and its `result/…`
/// reads with the values printed after `#`: (path with `{id}`, value).
pub fn readme_job() -> (String, Vec<(String, String)>) {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let start = readme.find("curl -s -X POST http://127.0.0.1:8080/v1/flywheel").unwrap();
    let body = readme[start..].split("-d '").nth(1).unwrap().split('\'').next().unwrap();
    let reads = readme
        .lines()
        .filter_map(|line| {
            let (command, comment) = line.split_once("  # ")?;
            let path = command.split("http://127.0.0.1:8080").nth(1)?.trim().trim_end_matches('\'');
            let value = comment.split(',').next()?.trim();
            (path.contains("/result/") && value.parse::<f64>().is_ok()).then(|| (path.to_string(), value.to_string()))
        })
        .collect();
    (body.to_string(), reads)
}

#[tokio::test]
async fn the_readme_example_answers_what_the_readme_prints() {
    let (body, reads) = readme_job();
    assert!(reads.len() >= 2, "the README's printed reads: {reads:?}");
    let t = TestApp::new().await;
    let created = t.post("/v1/flywheel", &serde_json::from_str(&body).unwrap()).await;
    assert_eq!(created.status, 201, "{}", created.text);
    let id = created.json()["id"].as_str().unwrap().to_string();
    // Case F1's closed form, 353.52142732201185 kg·m² (tests/fixtures/cases, nested brentq), to 1e-15.
    let exact = &reads.iter().find(|(p, _)| p.ends_with("/inertia_exact")).unwrap().1;
    assert!((exact.parse::<f64>().unwrap() - 353.521_427_322_011_85).abs() < 1e-15 * 353.52, "README: {exact}");
    for (path, value) in &reads {
        let got = t.get(&path.replace("{id}", &id)).await;
        assert_eq!(
            (got.status.as_u16(), got.text.trim()),
            (200, value.as_str()),
            "GET {path}: the README says {value}"
        );
    }
}
