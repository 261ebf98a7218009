//! The service in Spanish: `Accept-Language: es` or `?lang=es` gives the
//! problem documents' title, detail and field messages and the pages in
//! Spanish (the course's words), with `type`, pointers, field names and
//! units unchanged; English stays the default. The Spanish texts are the
//! catalogue's (src/i18n/es/*.ftl); these tests check that they reach the
//! asker, where, and that nothing else moved.

use crate::helpers::{Reply, TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use serde_json::{Value, json};

pub async fn in_spanish(app: &TestApp, method: &str, path: &str, body: Option<&Value>) -> Reply {
    let req = Request::builder().method(method).uri(path).header("accept-language", "es-ES,es;q=0.9,en;q=0.5");
    let req = match body {
        Some(b) => req.header("content-type", "application/json").body(Body::from(b.to_string())),
        None => req.body(Body::empty()),
    };
    app.send(req.unwrap()).await
}

/// A bad parameter of a template's number: the same 400 in both
/// languages, its words Spanish with the header or `?lang=es`.
#[tokio::test]
async fn a_query_error_in_spanish() {
    let app = TestApp::new().await;
    let path = "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=mucho&G=1";
    let (en, es) = (app.get(path).await, in_spanish(&app, "GET", path, None).await);
    let by_query = app.get(&format!("{path}&lang=es")).await;
    assert_eq!(es.status, StatusCode::BAD_REQUEST);
    assert_eq!(es.headers["content-language"], "es");
    assert_eq!(en.headers["content-language"], "en");
    assert_eq!(by_query.json(), es.json(), "?lang=es is the header");
    let (en, es) = (en.json(), es.json());
    assert_eq!(en["type"], es["type"], "the type does not change");
    assert_eq!(en["title"], "Invalid query parameters");
    assert_eq!(es["title"], "Parámetros de consulta no válidos");
    assert_eq!(es["detail"], "parámetros de consulta no válidos");
    let message = |doc: &Value, name: &str| {
        let errors = doc["errors"].as_array().unwrap();
        errors.iter().find(|e| e["parameter"] == name).unwrap()["message"].as_str().unwrap().to_string()
    };
    assert!(message(&es, "F").starts_with("'mucho' no es ni un número ni una magnitud"), "{es}");
    assert!(message(&en, "F").starts_with("'mucho' is neither a number nor a quantity"), "{en}");
    assert!(message(&es, "G").contains("no tiene el parámetro G (sus parámetros: F, I0, eps, speed)"), "{es}");
}

/// A request that is not a valid problem: the 422's title, its count of
/// fields and each field's message in Spanish, at the same pointers.
#[tokio::test]
async fn a_422_in_spanish_at_the_same_pointers() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["mean_speed"] = json!("60 rmp");
    body["irregularity"] = json!("mucho");
    body["reduced_inertia"] = json!([1, 2]);
    body["colour"] = json!("red");
    let es = in_spanish(&app, "POST", "/v1/flywheel", Some(&body)).await;
    assert_eq!(es.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", es.text);
    let en = app.post("/v1/flywheel", &body).await.json();
    let es = es.json();
    assert_eq!(es["title"], "La petición no es un problema válido");
    let pointers = |doc: &Value| -> Vec<String> {
        doc["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect()
    };
    assert_eq!(pointers(&en), pointers(&es));
    let at = |p: &str| {
        let errors = es["errors"].as_array().unwrap();
        errors.iter().find(|e| e["pointer"] == p).map(|e| e["message"].as_str().unwrap().to_string())
    };
    // An unknown field is said with its neighbours' names (those of the contract).
    match at("/colour") {
        Some(m) => {
            assert!(m.starts_with("campo desconocido (los campos de aquí: ") && m.contains(" mean_speed, "), "{m}")
        }
        None => assert!(at("/reduced_inertia").is_some(), "{es}"),
    }
    let n = es["errors"].as_array().unwrap().len();
    assert_eq!(es["detail"], if n == 1 { "1 campo no válido".to_string() } else { format!("{n} campos no válidos") });
    // The wrong type is found first (serde stops there); then the units, each in Spanish.
    let mut units = request("p103_slider");
    units["mean_speed"] = json!("60 rmp");
    units["irregularity"] = json!("4 kg");
    let es = in_spanish(&app, "POST", "/v1/flywheel", Some(&units)).await.json();
    let at = |p: &str| es["errors"].as_array().unwrap().iter().find(|e| e["pointer"] == p).cloned().unwrap();
    assert!(at("/mean_speed")["message"].as_str().unwrap().starts_with("unidad desconocida 'rmp'; ¿quería decir rpm?"));
    assert_eq!(at("/irregularity")["message"], "un valor en kg donde se espera 1 (adimensional)");
    assert_eq!(es["detail"], "2 campos no válidos");
    // A field named in Spanish one level down: the names there (a trial's `disco` for `disk`).
    let mut nested = request("p103_slider");
    nested["flywheel"] = json!({"disco": {"density": "7200 kg/m^3"}});
    let said = field_messages(&app, "/v1/flywheel", &nested, true).await;
    let disco = said.iter().find(|(at, _)| at == "/flywheel/disco").map(|(_, m)| m.as_str()).unwrap_or_default();
    assert!(disco.starts_with("campo desconocido (los campos de aquí: ") && disco.contains("disk"), "{said:?}");
}

/// The pages in Spanish: `lang="es"`, the course's words, no English
/// left of the frame, numbers with a decimal comma; the form read with one.
#[tokio::test]
async fn the_pages_in_spanish() {
    let app = TestApp::new().await;
    let job = app.post("/v1/flywheel", &request("p103_slider")).await.json();
    let id = job["id"].as_str().unwrap();
    let home = in_spanish(&app, "GET", "/", None).await;
    let page = in_spanish(&app, "GET", &format!("/jobs/{id}"), None).await;
    let form = in_spanish(&app, "GET", "/templates/p103-slider-flywheel", None).await;
    for (r, words) in [
        (&home, &["Trabajos recientes", "Plantillas", "Para programas"][..]),
        (&page, &["<h1>trabajo volante</h1>", "Valores", "Precisión y tiempo", "de tiempo de cálculo", "Gráficas"]),
        (&form, &["Calcular", "coma decimal", "El mismo trabajo por URL"]),
    ] {
        assert_eq!(r.status, StatusCode::OK, "{}", r.text);
        assert!(r.text.contains("<html lang=\"es\">"), "the page says its language");
        for w in words {
            assert!(r.text.contains(w), "{w} in {}", r.text);
        }
        for english in ["Jobs and templates", "Recent jobs", "Values", "Accuracy and time", "Compute", "engine time"] {
            assert!(!r.text.contains(english), "'{english}' left in a Spanish page");
        }
    }
    let exact = job["result"]["inertia_exact"].as_f64().unwrap();
    assert!(page.text.contains(&format!(">{}</a>", format!("{exact:.1}").replace('.', ","))), "353,5 on the page");
    assert!(form.text.contains("value=\"0,04\""), "the default ε with a decimal comma");
    // Submitted with decimal commas: the job of ε = 0.03, its page in Spanish.
    let asked = in_spanish(&app, "GET", "/templates/p103-slider-flywheel?eps=0,03&F=1200,5", None).await;
    assert_eq!(asked.status, StatusCode::SEE_OTHER, "{}", asked.text);
    let same = app.get("/v1/templates/p103-slider-flywheel/job?eps=0.03&F=1200.5").await.json();
    assert_eq!(asked.location.as_deref(), Some(format!("/jobs/{}", same["id"].as_str().unwrap()).as_str()));
    let refused = in_spanish(&app, "GET", "/templates/p103-slider-flywheel?eps=mucho", None).await;
    assert_eq!(refused.status, StatusCode::BAD_REQUEST);
    assert!(refused.text.contains("no es ni un número ni una magnitud"), "{}", refused.text);
    let missing = in_spanish(&app, "GET", "/jobs/no-such", None).await;
    assert!(missing.text.contains("Trabajo no encontrado") && missing.text.contains("Volver a los trabajos"));
}

/// A plot in Spanish: its title, axes and notes in the course's words, its
/// numbers with decimal commas — P.103's balance torque M_b = F/π =
/// 159,2 N·m (the mean of 500 sin φ over half the cycle) — and the list of
/// plots titled in Spanish; without the header, English as before.
#[tokio::test]
async fn a_plot_in_spanish() {
    let app = TestApp::new().await;
    let id = app.post("/v1/flywheel", &request("p103_slider")).await.json()["id"].as_str().unwrap().to_string();
    let es = in_spanish(&app, "GET", &format!("/v1/jobs/{id}/plots/torque.svg"), None).await;
    assert_eq!(es.status, StatusCode::OK);
    for words in
        ["Par reducido M*(φ) y los lóbulos de trabajo", "eje de reducción", "par motor de equilibrio M_b = 159,2 N·m"]
    {
        assert!(es.text.contains(words), "{words} in the Spanish plot");
    }
    assert!(!es.text.contains("reference shaft") && !es.text.contains("balance torque"), "no English left");
    let en = app.get(&format!("/v1/jobs/{id}/plots/torque.svg")).await.text;
    assert!(en.contains("balance torque M_b = 159.2 N·m") && en.contains("angle of the reference shaft φ"));
    // Every plot of a kinetostatics job: a Spanish title, no English axis or note left.
    let k1 = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await.json();
    let k1 = k1["id"].as_str().unwrap();
    let listed = in_spanish(&app, "GET", &format!("/v1/jobs/{k1}/plots"), None).await.json();
    for p in listed["plots"].as_array().unwrap() {
        let svg = in_spanish(&app, "GET", p["href"].as_str().unwrap(), None).await.text;
        assert!(svg.contains(p["title"].as_str().unwrap()) || p["name"] == "mechanism", "{}", p["name"]);
        for english in ["against the input", "joint ", "reaction force", "input angle", "step "] {
            assert!(!svg.contains(english), "'{english}' in the Spanish plot {}", p["name"]);
        }
    }
    let list = in_spanish(&app, "GET", &format!("/v1/jobs/{id}/plots"), None).await.json();
    let titles: Vec<&str> = list["plots"].as_array().unwrap().iter().map(|p| p["title"].as_str().unwrap()).collect();
    assert!(
        titles.contains(&"Diagrama de Wittenbauer: W frente a I*(φ) y las tangentes que dan la inercia del volante")
    );
}

/// Every built-in template has its title, source and every parameter's
/// description in Spanish, and the pages use them; a client's template
/// may bring its own (a description of a parameter it has not is refused).
#[tokio::test]
async fn the_templates_in_spanish() {
    let app = TestApp::new().await;
    let list = app.get("/v1/templates").await.json();
    for t in list["items"].as_array().unwrap().iter().filter(|t| t["builtin"] == true) {
        let es = &t["es"];
        assert!(es["title"].is_string() && es["source"].is_string(), "{}: its Spanish", t["id"]);
        for name in t["parameters"].as_object().unwrap().keys() {
            assert!(es["parameters"][name].is_string(), "{}: {name} in Spanish", t["id"]);
        }
    }
    let home = in_spanish(&app, "GET", "/", None).await.text;
    assert!(home.contains("P.103: volante de una máquina"), "the Spanish title on the home page");
    let form = in_spanish(&app, "GET", "/templates/p103-slider-flywheel", None).await.text;
    assert!(form.contains("Grado de irregularidad ε") && form.contains("Problema P.103 del curso"));
    let mut t = json!({"kind": "gears", "name": "engranaje", "title": "A spur gear",
        "request": {"module": "4 mm", "teeth": 30},
        "parameters": {"z": {"pointer": "/teeth", "description": "Number of teeth", "min": 12}},
        "es": {"title": "Un engranaje recto", "parameters": {"z": "Número de dientes", "m": "módulo"}}});
    assert_eq!(app.pointers("/v1/templates", &t).await, ["/es/parameters/m"]);
    t["es"]["parameters"].as_object_mut().unwrap().remove("m");
    assert_eq!(app.post("/v1/templates", &t).await.status, StatusCode::CREATED);
    let form = in_spanish(&app, "GET", "/templates/engranaje", None).await.text;
    assert!(form.contains("Un engranaje recto") && form.contains("Número de dientes"), "{form}");
    assert!(app.get("/templates/engranaje").await.text.contains("Number of teeth"), "English by default");
}

/// The messages of each field of a bad request, by pointer, in the
/// language asked (`es`: the header) or in English.
async fn field_messages(app: &TestApp, path: &str, body: &Value, es: bool) -> Vec<(String, String)> {
    let r = if es { in_spanish(app, "POST", path, Some(body)).await } else { app.post(path, body).await };
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].as_array().unwrap().clone();
    let text = |e: &Value, k: &str| e[k].as_str().unwrap().to_string();
    errors.iter().map(|e| (text(e, "pointer"), text(e, "message"))).collect()
}

/// A bad mechanism and a bad cam asked in Spanish: every field's message
/// is the Spanish catalogue's (src/i18n/es/requests.ftl), at the pointer
/// of its English one and never equal to it; JSON fields, pointers and
/// enumerated values stay as they are, numbers take a decimal comma.
#[tokio::test]
async fn a_bad_mechanism_and_a_bad_cam_in_spanish() {
    let app = TestApp::new().await;
    let mut mechanism = request("k1_offset_slider_crank");
    mechanism["mechanism"]["bodies"][0]["mass"] = json!("-2 kg");
    mechanism["mechanism"]["joints"][2]["bodies"] = json!(["rod", "pistón"]);
    mechanism["mechanism"]["joints"][3].as_object_mut().unwrap().remove("axis");
    let cam = json!({
        "follower": {"type": "roller"},
        "program": [{"to": "90 deg", "law": "parabólica", "lift": "20 mm"}, {"to": "360 deg", "law": "dwell"}],
        "size": {"max_pressure_angle": "90 deg"},
        "speed": "-300 rpm", "samples": 2
    });
    let mut open = cam.clone();
    open["follower"] = json!({"type": "flat"});
    open["program"] = json!({"lift": {"expr": "0.01*theta"}});
    open["base_radius"] = json!("40 mm");
    open.as_object_mut().unwrap().remove("size");
    for (path, body, expected) in [
        (
            "/v1/kinetostatics",
            &mechanism,
            &[
                ("/mechanism/bodies/0/mass", "no debe ser negativo"),
                ("/mechanism/joints/2/bodies/1", "cuerpo desconocido 'pistón'"),
                ("/mechanism/joints/3", "\"axis\" es obligatorio para este tipo de par cinemático"),
            ][..],
        ),
        (
            "/v1/cams",
            &cam,
            &[
                ("/follower", "un seguidor de rodillo necesita su radio \"roller_radius\""),
                (
                    "/program/0/law",
                    "ley desconocida 'parabólica': una de dwell, harmonic, cycloidal, polynomial-345, polynomial-4567, modified-sine, modified-trapezoid",
                ),
                ("/size/max_pressure_angle", "debe estar entre 0 y 85°"),
                ("/speed", "debe ser mayor que 0 (el sentido lo da \"direction\")"),
                ("/samples", "debe estar entre 4 y 36000"),
            ],
        ),
        (
            "/v1/cams",
            &open,
            &[
                ("/program/lift", "debe volver a su valor inicial en una vuelta: s(0) = 0; s(360°) = 0,0628"),
                ("/speed", "debe ser mayor que 0 (el sentido lo da \"direction\")"),
                ("/samples", "debe estar entre 4 y 36000"),
            ],
        ),
    ] {
        let es = field_messages(&app, path, body, true).await;
        let en = field_messages(&app, path, body, false).await;
        let pointers = |list: &[(String, String)]| list.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>();
        assert_eq!(pointers(&es), pointers(&en), "the same fields in both languages");
        assert_eq!(es.len(), expected.len(), "{es:?}");
        for (pointer, text) in expected {
            let (_, message) = es.iter().find(|(p, _)| p == pointer).unwrap_or_else(|| panic!("{pointer}: {es:?}"));
            assert!(message.starts_with(text), "{pointer}: '{message}' is not the catalogue's '{text}'");
        }
        for ((pointer, spanish), (_, english)) in es.iter().zip(&en) {
            assert_ne!(spanish, english, "{pointer}: the English message left in Spanish");
        }
    }
}

/// The language sticks: a page asked with `?lang=es` gives the browser its
/// cookie, with which the template's form (no `lang`, no Accept-Language)
/// redirects to a job page in Spanish; a form sent with `?lang=es` carries
/// it into its redirect; without either, the same job page is English.
#[tokio::test]
async fn the_language_of_a_page_sticks_to_its_form_and_redirect() {
    let app = TestApp::new().await;
    let page = app.get("/templates/p103-slider-flywheel?lang=es").await;
    assert_eq!(page.status, StatusCode::OK, "{}", page.text);
    let cookie = page.headers.get("set-cookie").and_then(|v| v.to_str().ok()).unwrap_or_default().to_string();
    assert!(cookie.starts_with("mechdyn_lang=es;"), "{cookie}");
    let with_cookie = |path: &str| {
        let req = Request::get(path).header("cookie", "theme=dark; mechdyn_lang=es").body(Body::empty()).unwrap();
        app.send(req)
    };
    let sent = with_cookie("/templates/p103-slider-flywheel?F=1200").await;
    assert_eq!(sent.status, StatusCode::SEE_OTHER, "{}", sent.text);
    let job = sent.location.unwrap();
    let spanish = with_cookie(&job).await;
    assert_eq!(spanish.headers["content-language"], "es");
    assert!(spanish.text.contains("<html lang=\"es\""), "the job page in Spanish");
    let english = app.get(&job).await;
    assert_eq!(english.headers["content-language"], "en", "no cookie, no header: English");
    let asked = app.get("/templates/p103-slider-flywheel?F=1200&lang=es").await;
    assert_eq!(asked.location.as_deref(), Some(format!("{job}?lang=es").as_str()));
}

/// `?errors=text`, a spreadsheet's way to read why: the 400 of ε = 3 comes
/// back as 200 plain text, the parameter's message in the asker's language
/// (the same words as the problem document's field), its status in
/// `Mechdyn-Status`; an answer that is no error is unchanged.
#[tokio::test]
async fn an_error_read_as_text_says_why_with_its_status_aside() {
    let app = TestApp::new().await;
    let base = "/v1/templates/p103-slider-flywheel/result/inertia_exact?eps=3";
    let problem = app.get(&format!("{base}&lang=es")).await;
    assert_eq!(problem.status, StatusCode::BAD_REQUEST);
    let message = problem.json()["errors"][0]["message"].as_str().unwrap().to_string();
    let text = app.get(&format!("{base}&lang=es&errors=text")).await;
    assert_eq!(text.status, StatusCode::OK);
    assert_eq!(text.content_type, "text/plain; charset=utf-8");
    assert_eq!(text.headers["mechdyn-status"], "400");
    assert_eq!(text.text, format!("eps: {message}"));
    assert!(text.text.contains("por encima del valor máximo"), "{}", text.text);
    let fine = app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact?errors=text").await;
    assert_eq!(fine.status, StatusCode::OK);
    assert!(fine.headers.get("mechdyn-status").is_none());
    assert!(fine.text.parse::<f64>().is_ok(), "{}", fine.text);
}

/// A number written with a thousands separator ("1.200,5", as a Spanish
/// sheet formats it) is named as such, with the way to write it, in the
/// asker's language.
#[tokio::test]
async fn a_thousands_separator_is_named_as_such() {
    let app = TestApp::new().await;
    let path = "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1.200,5&lang=es&errors=text";
    let r = app.get(path).await;
    assert_eq!(r.headers["mechdyn-status"], "400", "{}", r.text);
    assert!(r.text.starts_with("F: "), "{}", r.text);
    assert!(r.text.ends_with("'1.200,5' lleva separador de miles, que no se lee: escriba 1200,5"), "{}", r.text);
}

/// serde's own words never reach a Spanish asker: a two-way choice ("o",
/// not "or"), and what the service's readers expect (a point by name or
/// coordinates), in the catalogue's Spanish.
#[tokio::test]
async fn the_readers_expectations_in_spanish() {
    let app = TestApp::new().await;
    let counts = json!({"counts": {"space": "esférico", "bodies": 4, "pairs": {"I": 4}}});
    let said = field_messages(&app, "/v1/mobility", &counts, true).await;
    assert_eq!(
        said,
        [("/counts/space".into(), "variante desconocida \"esférico\", se esperaba \"planar\" o \"spatial\"".into())]
    );
    let mut k1 = request("k1_offset_slider_crank");
    k1["mechanism"]["joints"][0]["at"] = json!({"x": 0});
    let said = field_messages(&app, "/v1/kinetostatics", &k1, true).await;
    let expected =
        "se esperaba el nombre de un punto o sus coordenadas [x, y] (en el espacio [x, y, z]) y llegó un objeto";
    assert_eq!(said, [("/mechanism/joints/0/at".into(), expected.into())]);
    let mut k1 = request("k1_offset_slider_crank");
    k1["input"]["start"] = json!(["0", "deg"]);
    let said = field_messages(&app, "/v1/kinetostatics", &k1, true).await;
    let expected = "se esperaba un número (SI) o un texto \"VALOR UNIDAD\" como \"300 rpm\" y llegó una lista";
    assert_eq!(said, [("/input/start".into(), expected.into())]);
}

/// Degrees written with another word ("20 grados", "20 gr", "20 g") are
/// refused with the way to write them; a bare 360 where degrees look meant
/// is read in radians, as the contract says, and the result says how to
/// write degrees, at the field; beside a refusal of the same field the
/// same words explain it, and every other field read so is said with it.
#[tokio::test]
async fn degrees_are_answered_with_the_way_to_write_them() {
    let app = TestApp::new().await;
    for (written, n) in [("20 grados", "20"), ("22,5 gr", "22,5"), ("20 g", "20")] {
        let mut k1 = request("k1_offset_slider_crank");
        k1["input"]["start"] = json!(written);
        let said = field_messages(&app, "/v1/kinetostatics", &k1, true).await;
        let expected =
            format!("'{written}' no es un ángulo tal como está escrito: los grados se escriben \"{n}°\" o \"{n} deg\"");
        assert_eq!(said, [("/input/start".to_string(), expected)], "{written}");
    }
    let mut k1 = request("k1_offset_slider_crank");
    k1["input"]["end"] = json!(360);
    let r = in_spanish(&app, "POST", "/v1/kinetostatics", Some(&k1)).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let warnings = r.json()["result"]["warnings"].clone();
    let expected = "/input/end: el número sin unidad 360 se lee en radianes (20626°); para grados escriba \"360°\"";
    assert!(warnings.as_array().unwrap().iter().any(|w| w == expected), "{warnings}");
    let english = app.get(&format!("/v1/jobs/{}", r.json()["id"].as_str().unwrap())).await.json();
    let warnings = english["result"]["warnings"].to_string();
    assert!(
        warnings.contains("the bare number 360 is read in radians (20626°); for degrees write \\\"360°\\\""),
        "{warnings}"
    );
    // An angle that is plainly radians (π/2) is not remarked on.
    k1["input"]["end"] = json!(std::f64::consts::FRAC_PI_2);
    let r = app.post("/v1/kinetostatics", &k1).await;
    assert!(!r.text.contains("bare number"), "{}", r.text);
    // A cam's largest pressure angle of 30 (radians): refused, and the reason said beside it.
    let mut cam = crate::helpers::example("CamRequest");
    cam["size"] = json!({"max_pressure_angle": 30});
    let r = app.post("/v1/cams", &cam).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].clone();
    let at = |e: &Value| e["pointer"] == "/size/max_pressure_angle";
    let said: Vec<&str> =
        errors.as_array().unwrap().iter().filter(|e| at(e)).filter_map(|e| e["message"].as_str()).collect();
    assert!(said.iter().any(|m| m.contains("for degrees write \"30°\"")), "{errors}");
    // A program's stretches ended at bare 60, 150, 210, 300 and 360: the one
    // refused and every other read so are said together, each at its field.
    let mut bare = crate::helpers::template_request("cam-design");
    for (k, to) in [60, 150, 210, 300, 360].into_iter().enumerate() {
        bare["program"][k]["to"] = json!(to);
    }
    let r = app.post("/v1/cams", &bare).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].clone();
    for (k, to) in [60, 150, 210, 300, 360].into_iter().enumerate() {
        let pointer = format!("/program/{k}/to");
        let hint = format!("for degrees write \"{to}°\"");
        let said = errors
            .as_array()
            .unwrap()
            .iter()
            .any(|e| e["pointer"] == pointer && e["message"].as_str().unwrap().contains(&hint));
        assert!(said, "{pointer}: {errors}");
    }
}

/// A CSV's mistakes are named by the sheet's row and column, not as query
/// parameters, under their own problem type, in the asker's language.
#[tokio::test]
async fn a_csv_row_is_named_as_a_csv_row() {
    let app = TestApp::new().await;
    let path = "/v1/templates/p103-slider-flywheel/table?values=inertia_exact&lang=es";
    let r = app.post_raw(path, "text/csv", "F;eps\n500;0,04\n\n600;0,03;7\n").await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST, "{}", r.text);
    let p = r.json();
    assert_eq!(
        (p["type"].as_str(), p["title"].as_str()),
        (Some("/problems/invalid-table"), Some("La tabla CSV no es válida"))
    );
    assert_eq!(p["errors"][0]["row"], 4, "the blank row counts, as in the sheet: {p}");
    assert_eq!(p["errors"][0]["message"], "la fila 4 tiene 3 celdas para 2 columnas");
    assert!(p["errors"][0].get("parameter").is_none(), "{p}");
    let r = app.post_raw(path, "text/csv", "F;epsilon\n500;0,04\n").await;
    let e = &r.json()["errors"][0];
    assert_eq!((e["row"].clone(), e["column"].clone()), (json!(1), json!("epsilon")), "{}", r.text);
    assert!(
        e["message"].as_str().unwrap().starts_with("la plantilla p103-slider-flywheel no tiene el parámetro epsilon")
    );
}

/// Units as a student writes them (`kg·m²`, `kg m^2`, `kg.m2`, `r.p.m.`,
/// `CV`) are the table's; a count of pairs needs no `space` (the course's
/// are planar).
#[tokio::test]
async fn units_and_counts_as_a_student_writes_them() {
    let app = TestApp::new().await;
    let clean = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await.json();
    let i = clean["request"]["mechanism"]["bodies"][1]["inertia"].clone();
    let si = i.as_f64().unwrap_or_else(|| panic!("a number in the library's K1: {i}"));
    for unit in ["kg·m²", "kg*m²", "kg m^2", "kg.m2"] {
        let mut k1 = request("k1_offset_slider_crank");
        k1["mechanism"]["bodies"][1]["inertia"] = json!(format!("{} {unit}", si.to_string().replace('.', ",")));
        let r = app.post("/v1/kinetostatics", &k1).await;
        assert_eq!(r.status, StatusCode::CREATED, "{unit}: {}", r.text);
        assert_eq!(r.json()["result"]["steps"], clean["result"]["steps"], "{unit}");
    }
    let r = app.post("/v1/mobility", &json!({"counts": {"bodies": 5, "pairs": {"I": 5, "II": 1}}})).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert_eq!(r.json()["result"]["grubler"]["mobility"], 1);
    // A speed in r.p.m. is the one in rpm; a power in CV (caballos de
    // vapor, 735,49875 W) the one in W; "vueltas" are named as rev.
    let flywheel = |speed: &str, power: &str| {
        let mut f = request("p103_slider");
        f["mean_speed"] = json!(speed);
        f["constants"] = json!({"P": power});
        f["torques"][0]["value"]["segments"][0]["expr"] = json!("-(P/735.49875)*500*sin(phi)");
        f
    };
    let clean = app.result("/v1/flywheel", &flywheel("60 rpm", "1 CV")).await;
    for (speed, power) in [("60 r.p.m.", "1 CV"), ("60 R.P.M.", "1 cv")] {
        let r = app.result("/v1/flywheel", &flywheel(speed, power)).await;
        assert_eq!(r["inertia_exact"], clean["inertia_exact"], "{speed}, {power}");
    }
    let watts = app.result("/v1/flywheel", &flywheel("60 rpm", "735,49875 W")).await["inertia_exact"].as_f64().unwrap();
    let cv = clean["inertia_exact"].as_f64().unwrap();
    assert!((cv - watts).abs() <= 1e-12 * watts, "1 CV = 75 kgf·m/s = 735,49875 W: {cv} vs {watts}");
    // A ratio as a fraction ("1/4"), as a statement gives a gear's.
    let geared = |ratio: Value| {
        let mut f = request("p103_slider");
        f["flywheel"] = json!({"ratio": ratio});
        f
    };
    let quarter = app.result("/v1/flywheel", &geared(json!(0.25))).await["flywheel_inertia"].clone();
    assert_eq!(app.result("/v1/flywheel", &geared(json!("1/4"))).await["flywheel_inertia"], quarter);
    assert_ne!(app.result("/v1/flywheel", &geared(json!(1))).await["flywheel_inertia"], quarter, "the ratio counts");
    let said = field_messages(&app, "/v1/flywheel", &flywheel("60 vueltas/min", "1 CV"), true).await;
    assert_eq!(said.len(), 1, "{said:?}");
    assert!(said[0].0 == "/mean_speed" && said[0].1.contains("'vueltas'; ¿quería decir rev?"), "{said:?}");
}

/// A torque written as a Spanish sheet writes its numbers: the decimal
/// comma is named as such wherever the reader stumbles on it (after a
/// whole expression, inside a parenthesis it kept from closing, or in a
/// function's argument it split in two), at the expression's pointer.
#[tokio::test]
async fn a_decimal_comma_in_an_expression_is_named() {
    let app = TestApp::new().await;
    for expr in ["5 - 20*sin(phi)^2 + 0,5", "1/(0,5 + t)", "cos(phi - 0,5)"] {
        let body = json!({
            "torques": [{"name": "m", "value": {"expr": expr}}],
            "reduced_inertia": 1,
            "initial": {"angle": 0, "speed": 1},
            "duration": 1
        });
        let r = in_spanish(&app, "POST", "/v1/dynamics", Some(&body)).await;
        assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
        let error = &r.json()["errors"][0];
        assert_eq!(error["pointer"], "/torques/0/value/expr", "{expr}: {}", r.text);
        assert!(
            error["message"].as_str().unwrap().contains("'0,5' está escrito con coma decimal"),
            "{expr}: {}",
            r.text
        );
    }
}
