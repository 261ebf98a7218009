//! The pages in a real browser: Debian's Chromium, headless, driven by
//! tests/clients/browser.py over the DevTools protocol against the real
//! binary. Each page loads with no console message and no request outside
//! the service, has its elements, fits a phone's width and prints; the
//! template's form is filled in and submitted with real key and mouse
//! events; every plot opens as an SVG document. Screenshots (desktop and
//! phone) and PDFs are kept in target/screenshots/ (a CI artefact).
//!
//! Without Chromium the test says so and passes, unless
//! MECHDYN_REQUIRE_CHROMIUM is set (CI sets it).

use crate::crash::{free_port, http, start};
use crate::helpers::request;
use serde_json::{Value, json};
use std::process::Command;

const CHROMIUM: &str = "/usr/bin/chromium";

fn posted(port: u16, path: &str, body: &Value) -> String {
    let (status, text) = http(port, "POST", path, &body.to_string()).unwrap();
    assert_eq!(status, 201, "{text}");
    serde_json::from_str::<Value>(&text).unwrap()["id"].as_str().unwrap().to_string()
}

fn plots(port: u16, id: &str) -> Vec<String> {
    let (_, text) = http(port, "GET", &format!("/v1/jobs/{id}/plots"), "").unwrap();
    let list: Value = serde_json::from_str(&text).unwrap();
    list["plots"].as_array().unwrap().iter().map(|p| p["href"].as_str().unwrap().to_string()).collect()
}

/// The real binary on a fresh database, for Chromium; None (the test
/// skipped, saying so) without Chromium, unless CI requires it
/// (MECHDYN_REQUIRE_CHROMIUM), where it fails.
fn served() -> Option<(tempfile::TempDir, u16, std::process::Child)> {
    if !std::path::Path::new(CHROMIUM).exists() {
        assert!(std::env::var_os("MECHDYN_REQUIRE_CHROMIUM").is_none(), "Chromium is required");
        eprintln!("skipped: Debian's chromium is not installed");
        return None;
    }
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let service = start(&format!("sqlite://{}/pages.db", dir.path().display()), port);
    Some((dir, port, service))
}

/// tests/clients/browser.py run on `plan` (written in `dir`).
fn run_plan(dir: &std::path::Path, plan: &Value) -> std::process::Output {
    let plan_file = dir.join("plan.json");
    std::fs::write(&plan_file, plan.to_string()).unwrap();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/clients/browser.py");
    Command::new("python3").arg(script).arg(&plan_file).output().unwrap()
}

/// What the browser saw, once it ran.
fn report_of(run: &std::process::Output) -> Value {
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    serde_json::from_slice(&run.stdout).unwrap()
}

#[test]
fn chromium_loads_every_page_submits_the_form_and_opens_every_plot() {
    let Some((dir, port, mut service)) = served() else { return };
    let flywheel = posted(port, "/v1/flywheel?label=%3Cscript%3Ealert(1)%3C%2Fscript%3E", &request("p103_slider"));
    let kinetostatics = posted(port, "/v1/kinetostatics", &request("k1_offset_slider_crank"));
    let dynamics = posted(port, "/v1/dynamics", &request("p68_two_link_arm"));
    let svgs: Vec<String> = [&flywheel, &kinetostatics, &dynamics].iter().flat_map(|id| plots(port, id)).collect();
    let out = concat!(env!("CARGO_MANIFEST_DIR"), "/target/screenshots");
    let pages = [
        ("home", "/".to_string(), 0),
        ("job-flywheel", format!("/jobs/{flywheel}"), 4),
        ("job-kinetostatics", format!("/jobs/{kinetostatics}?step=3"), plots(port, &kinetostatics).len()),
        ("job-dynamics", format!("/jobs/{dynamics}"), plots(port, &dynamics).len()),
        ("template-form", "/templates/p103-slider-flywheel".to_string(), 0),
        // K1's worked solution: its three bodies' free-body diagrams.
        ("solution-kinetostatics", format!("/jobs/{kinetostatics}/solution?step=3"), 3),
    ];
    let plan = json!({
        "base": format!("http://127.0.0.1:{port}"),
        "out": out,
        "pages": pages.iter().map(|(name, path, _)| json!({"name": name, "path": path,
            "selectors": ["h1", "table", "figure img", "form input"]})).collect::<Vec<_>>(),
        "forms": [{"name": "template-submitted", "path": "/templates/p103-slider-flywheel",
            "fill": {"F": "1200", "eps": "3 %"}, "submit": "button[type=submit]", "selectors": ["figure img"]}],
        "svgs": svgs,
    });
    let run = run_plan(dir.path(), &plan);
    let (_, same) = http(port, "GET", "/v1/templates/p103-slider-flywheel/job?F=1200&eps=3%20%25", "").unwrap();
    let _ = service.kill();
    let _ = service.wait();
    let report = report_of(&run);
    let base = format!("http://127.0.0.1:{port}/");
    let clean = |what: &str, r: &Value| {
        assert!(r.get("error").is_none(), "{what}: {}", r["error"]);
        assert_eq!(r["status"], 200, "{what}: {r}");
        assert_eq!(r["console"], json!([]), "{what}: no console message");
        for url in r["requests"].as_array().unwrap() {
            assert!(url.as_str().unwrap().starts_with(&base), "{what} asked outside the service: {url}");
        }
        assert_eq!(r["failed"], json!([]), "{what}");
        assert_eq!(r["bad_responses"], json!([]), "{what}");
    };
    for (name, _, figures) in &pages {
        let r = &report["pages"][name];
        clean(name, r);
        assert_eq!(r["counts"]["h1"], 1, "{name}");
        assert_eq!(r["counts"]["figure img"], *figures, "{name}: every plot shown");
        assert_eq!(r["broken_images"], json!([]), "{name}");
        assert_eq!(r["phone_inner_width"], 390, "{name}: laid out for a phone's width");
        assert_eq!(r["phone_overflow"], false, "{name}: no sideways scrolling on a phone");
        assert!(r["pdf_bytes"].as_u64().unwrap() > 1000, "{name} prints");
    }
    assert!(report["pages"]["home"]["counts"]["table"].as_u64().unwrap() >= 2, "templates and jobs");
    assert_eq!(report["pages"]["template-form"]["counts"]["form input"], 4, "P.103's four parameters");
    assert!(
        report["pages"]["job-flywheel"]["title"].as_str().unwrap().contains("<script>alert(1)</script>"),
        "the label, as text"
    );
    let form = &report["forms"]["template-submitted"];
    clean("the submitted form", form);
    assert_eq!(form["filled"], json!({"F": "1200", "eps": "3 %"}));
    assert!(form["url"].as_str().unwrap().starts_with(&format!("{base}jobs/")), "{form}");
    assert_eq!(form["counts"]["figure img"], 4, "the job's page with its plots");
    // The job the browser made is the one the JSON route gives for these parameters.
    let same: Value = serde_json::from_str(&same).unwrap();
    assert_eq!(form["url"], format!("{base}jobs/{}", same["id"].as_str().unwrap()));
    assert_eq!(report["svgs"].as_object().unwrap().len(), svgs.len());
    for (path, r) in report["svgs"].as_object().unwrap() {
        clean(path, r);
        assert_eq!(r["content_type"], "image/svg+xml", "{path}");
        assert_eq!(r["root"], "svg", "{path}");
        assert_eq!(r["parsererror"], false, "{path}");
    }
    eprintln!("Chromium {}: screenshots in {out}", report["chromium"]);
}

/// English words of the pages' frame and plots that a Spanish page must not
/// show (the catalogue's English for them: src/i18n/en.ftl).
const ENGLISH: [&str; 16] = [
    "Jobs and templates",
    "Recent jobs",
    "For programs",
    "Values",
    "Accuracy and time",
    "of engine time",
    "Plots",
    "The request as sent",
    "Compute",
    "The same job by URL",
    "reference shaft",
    "balance torque",
    "lobes",
    "Wittenbauer's diagram",
    "tangent of slope",
    "quantity (JSON pointer)",
];

/// The same browser set to Spanish (`Accept-Language: es` on every
/// request): the pages and the plots they show in Spanish (`lang="es"`, the
/// course's words, none of the frame's English), P.103's form filled in
/// with a decimal comma ("0,03") and the punch press's with a degree sign
/// ("20°"), each submitted and answered by the job of those values (the one
/// the JSON route gives for 0.03 and 20 deg), its page in Spanish.
#[test]
fn chromium_in_spanish_reads_and_fills_the_pages_with_decimal_commas() {
    let Some((dir, port, mut service)) = served() else { return };
    let flywheel = posted(port, "/v1/flywheel", &request("p103_slider"));
    let kinetostatics = posted(port, "/v1/kinetostatics", &request("k1_offset_slider_crank"));
    let svgs = plots(port, &flywheel);
    let out = concat!(env!("CARGO_MANIFEST_DIR"), "/target/screenshots/es");
    let selectors = ["h1", "figure img", "form input"];
    let plan = json!({
        "base": format!("http://127.0.0.1:{port}"), "out": out, "language": "es-ES,es;q=0.9",
        "pages": [
            {"name": "home", "path": "/", "selectors": selectors},
            {"name": "job-flywheel", "path": format!("/jobs/{flywheel}"), "selectors": selectors},
            {"name": "template-form", "path": "/templates/p103-slider-flywheel", "selectors": selectors},
            {"name": "solution", "path": format!("/jobs/{kinetostatics}/solution?step=3"), "selectors": selectors},
        ],
        "forms": [
            {"name": "p103-submitted", "path": "/templates/p103-slider-flywheel", "fill": {"eps": "0,03"},
                "submit": "button[type=submit]", "selectors": ["figure img"]},
            {"name": "punch-submitted", "path": "/templates/punch-press-us", "fill": {"theta": "20°"},
                "submit": "button[type=submit]", "selectors": ["figure img"]},
        ],
        "svgs": svgs,
    });
    let run = run_plan(dir.path(), &plan);
    let job_of = |path: &str| {
        let (_, text) = http(port, "GET", path, "").unwrap();
        serde_json::from_str::<Value>(&text).unwrap()["id"].as_str().unwrap().to_string()
    };
    let p103 = job_of("/v1/templates/p103-slider-flywheel/job?eps=0.03");
    let punch = job_of("/v1/templates/punch-press-us/job?theta=20%20deg");
    let _ = service.kill();
    let _ = service.wait();
    let report = report_of(&run);
    let spanish = |what: &str, r: &Value| {
        assert!(r.get("error").is_none(), "{what}: {}", r["error"]);
        assert_eq!(r["status"], 200, "{what}: {r}");
        assert_eq!(r["console"], json!([]), "{what}: no console message");
        let text = r["text"].as_str().unwrap();
        for english in ENGLISH {
            assert!(!text.contains(english), "{what}: '{english}' left in the Spanish page");
        }
        text.to_string()
    };
    for (name, words) in [
        ("home", &["Trabajos recientes", "Plantillas", "P.103: volante"][..]),
        ("job-flywheel", &["Valores", "Precisión y tiempo", "Gráficas", "353,5"]),
        ("template-form", &["Calcular", "Grado de irregularidad", "0,04"]),
        (
            "solution",
            &[
                "Solución desarrollada, paso 3",
                "Los sólidos, numerados",
                "sus ecuaciones dan",
                "Potencias virtuales",
                "reacción",
            ],
        ),
    ] {
        let r = &report["pages"][name];
        assert_eq!(r["lang"], "es", "{name}");
        let text = spanish(name, r);
        for w in words {
            assert!(text.contains(w), "{name}: '{w}' in {text}");
        }
    }
    assert_eq!(report["pages"]["job-flywheel"]["counts"]["figure img"], 4, "its plots shown");
    assert_eq!(report["pages"]["solution"]["counts"]["figure img"], 3, "each body's free-body diagram");
    let base = format!("http://127.0.0.1:{port}/");
    // P.103's I* varies (Wittenbauer's diagram too); the punch press's is constant (three plots).
    for (form, filled, job, figures) in
        [("p103-submitted", ("eps", "0,03"), &p103, 4), ("punch-submitted", ("theta", "20°"), &punch, 3)]
    {
        let r = &report["forms"][form];
        spanish(form, r);
        assert_eq!(r["filled"][filled.0], filled.1, "{form}: typed as a Spanish lab types it");
        assert_eq!(r["url"], format!("{base}jobs/{job}"), "{form}: the job of those values");
        assert_eq!(r["lang"], "es");
        assert_eq!(r["counts"]["figure img"], figures, "{form}: the job's page with its plots");
    }
    for (path, r) in report["svgs"].as_object().unwrap() {
        let text = spanish(path, r);
        assert!(text.contains("eje de reducción") || text.contains("inercia reducida"), "{path}: {text}");
    }
}

/// The numbers of attribute `name` of the root `<svg>`.
fn root_numbers(svg: &str, name: &str) -> Vec<f64> {
    let head = &svg[..svg.find('>').unwrap()];
    let at = head.find(&format!(" {name}=\"")).unwrap_or_else(|| panic!("no {name} in {head}")) + name.len() + 3;
    head[at..].split('"').next().unwrap().split(' ').map(|v| v.parse().unwrap()).collect()
}

/// The kinetostatics job's mechanism plays in Chromium (issue 51): paused
/// at two times of its loop, each shows the one frame of that time, the two
/// screenshots differ, and at each the crank pin's dot is drawn where the
/// result puts the point A it follows (the root's data-range and data-plot
/// map metres to the picture; the viewBox is twice the CSS size).
#[test]
fn chromium_plays_a_mechanisms_motion_where_the_result_puts_it() {
    let Some((dir, port, mut service)) = served() else { return };
    let mut body = request("k1_offset_slider_crank");
    body["track"] = json!(["A"]);
    let (status, text) = http(port, "POST", "/v1/kinetostatics", &body.to_string()).unwrap();
    assert_eq!(status, 201, "{text}");
    let job: Value = serde_json::from_str(&text).unwrap();
    let (id, steps) = (job["id"].as_str().unwrap(), job["result"]["steps"].as_array().unwrap());
    let path = format!("/v1/jobs/{id}/plots/motion.svg");
    let (_, svg) = http(port, "GET", &path, "").unwrap();
    let four = |name: &str| -> [f64; 4] { root_numbers(&svg, name).try_into().expect("four numbers") };
    let ([x0, x1, y0, y1], [left, top, right, bottom]) = (four("data-range"), four("data-plot"));
    let seconds: f64 = svg.split("dur=\"").nth(1).unwrap().split('s').next().unwrap().parse().unwrap();
    // Every step is a frame, shown for an equal share of the loop: the middle of frames 3 and 8.
    let shown = [3usize, 8];
    let time = |k: usize| (k as f64 + 0.5) / steps.len() as f64 * seconds;
    let on_screen = |k: usize| {
        let a = &steps[k]["points"][0];
        let (x, y) = (a["x"].as_f64().unwrap(), a["y"].as_f64().unwrap());
        let px = (left + (x - x0) / (x1 - x0) * (right - left)) / 2.0;
        let py = (top + (y1 - y) / (y1 - y0) * (bottom - top)) / 2.0;
        json!([px, py])
    };
    let out = concat!(env!("CARGO_MANIFEST_DIR"), "/target/screenshots");
    let plan = json!({
        "base": format!("http://127.0.0.1:{port}"), "out": out,
        "motions": [{"name": "motion-k1", "path": path, "times": shown.map(time),
                     "probes": shown.map(|k| json!([on_screen(k)]))}],
    });
    let run = run_plan(dir.path(), &plan);
    let _ = service.kill();
    let _ = service.wait();
    let report = report_of(&run);
    let r = &report["motions"]["motion-k1"];
    assert!(r.get("error").is_none(), "{}", r["error"]);
    assert_eq!(r["console"], json!([]), "no console message");
    let frames = r["frames"].as_array().unwrap();
    for (f, k) in frames.iter().zip(shown) {
        assert_eq!(f["visible"], json!([k]), "at {} s only frame {k} shows: {f}", f["time"]);
        assert_eq!(f["hits"][0], json!(["circle", k]), "A's dot of frame {k} where the result puts A: {f}");
    }
    assert_ne!(frames[0]["screenshot_sha256"], frames[1]["screenshot_sha256"], "the two frames differ");
}

/// Private jobs in a real browser (issue 70): with a token, a job's page
/// without it is the sign-in form (401); the token typed into it once
/// signs the browser in — its cookie HttpOnly, unseen by the page's script
/// — and the browser lands on the job's page with its plots, whose SVGs it
/// then opens; the page is kept in a screenshot (`private/`).
#[test]
fn chromium_signs_in_once_and_reads_the_private_jobs() {
    if !std::path::Path::new(CHROMIUM).exists() {
        assert!(std::env::var_os("MECHDYN_REQUIRE_CHROMIUM").is_none(), "Chromium is required");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let db = format!("sqlite://{}/private.db", dir.path().display());
    let mut service = crate::crash::start_with(&db, port, &[("MECHDYN_API_TOKEN", "cl4ss-t0ken")]);
    let (status, text) = crate::wire::http_with(
        port,
        "POST",
        "/v1/kinetostatics",
        "Authorization: Bearer cl4ss-t0ken\r\n",
        &request("k1_offset_slider_crank").to_string(),
    )
    .unwrap();
    assert_eq!(status, 201, "{text}");
    let id = serde_json::from_str::<Value>(&text).unwrap()["id"].as_str().unwrap().to_string();
    let page = format!("/jobs/{id}?step=3");
    let svg = format!("/v1/jobs/{id}/plots/mechanism.svg?step=3");
    let out = concat!(env!("CARGO_MANIFEST_DIR"), "/target/screenshots/private");
    let plan = json!({
        "base": format!("http://127.0.0.1:{port}"), "out": out,
        "pages": [{"name": "refused", "path": page, "selectors": ["form input[name=token]"]}],
        "forms": [{"name": "signed-in", "path": page, "fill": {"token": "cl4ss-t0ken"},
            "submit": "form[action='/signin'] button[type=submit]", "selectors": ["figure img"],
            "evaluate": ["document.cookie"]}],
        "svgs": [svg],
    });
    let run = run_plan(dir.path(), &plan);
    let _ = service.kill();
    let _ = service.wait();
    let report = report_of(&run);
    let refused = &report["pages"]["refused"];
    assert_eq!(refused["status"], 401, "{refused}");
    assert_eq!(refused["counts"]["form input[name=token]"], 1, "the sign-in form: {refused}");
    let signed = &report["forms"]["signed-in"];
    assert!(signed.get("error").is_none(), "{signed}");
    assert_eq!(signed["status"], 200, "{signed}");
    assert_eq!(signed["url"], format!("http://127.0.0.1:{port}{page}"), "back on the page asked");
    assert!(signed["counts"]["figure img"].as_u64().unwrap() >= 4, "the job's plots: {signed}");
    assert_eq!(signed["evaluated"]["document.cookie"], "", "the cookie is HttpOnly");
    let plot = &report["svgs"][&svg];
    assert_eq!((plot["status"].as_u64(), plot["root"].as_str()), (Some(200), Some("svg")), "{plot}");
}
