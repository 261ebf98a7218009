//! A result's texts in the asker's language: its warnings and how its
//! accuracy was estimated are stored once, in English with the catalogue's
//! message beside each (`messages`), and read in Spanish wherever a result
//! is read (the POST's answer, the job, a part of it, its page), every
//! number and every other byte as they were. The Spanish expected here is
//! the catalogue's text (src/i18n/es/results.ftl) written out by hand.

use crate::helpers::{Reply, TestApp, request, template_request};
use crate::spanish::in_spanish;
use axum::body::Body;
use axum::http::{Request, StatusCode};
use serde_json::{Value, json};

/// P.113's pulley with more inertia than it needs (no disk: a warning
/// naming the negative inertia) and a constant nothing reads (a warning).
fn warned() -> Value {
    let mut body = request("p113_pulley");
    body["existing_inertia"] = json!("100 kg*m^2");
    body["flywheel"] = json!({"disk": {"density": "7850 kg/m^3", "radius": "0.3 m"}});
    body["constants"] = json!({"k": 2});
    body
}

#[tokio::test]
async fn a_results_warnings_and_method_in_spanish() {
    let app = TestApp::new().await;
    let posted = in_spanish(&app, "POST", "/v1/flywheel", Some(&warned())).await;
    assert_eq!(posted.status, StatusCode::CREATED, "{}", posted.text);
    let job = posted.json();
    let id = job["id"].as_str().unwrap();
    let es = &job["result"];
    let en = app.get(&format!("/v1/jobs/{id}")).await.json()["result"].clone();

    // The warnings: the same conditions, said in each language.
    assert_eq!(en["warnings"].as_array().unwrap().len(), 2, "{}", en["warnings"]);
    let (disk_en, disk_es) = (en["warnings"][0].as_str().unwrap(), es["warnings"][0].as_str().unwrap());
    assert!(disk_en.starts_with("no disk: the flywheel inertia needed is -"), "{disk_en}");
    let number = disk_es
        .strip_prefix("sin disco: la inercia de volante necesaria es ")
        .and_then(|s| {
            s.strip_suffix(
                " kg*m^2 (la inercia propia de la máquina ya mantiene el grado de irregularidad dentro de lo pedido)",
            )
        })
        .unwrap_or_else(|| panic!("{disk_es}"));
    // Four figures with a decimal comma: the result's own number (its `flywheel_inertia.exact`).
    assert!(number.contains(',') && !number.contains('.'), "{number}");
    let said: f64 = number.replace(',', ".").parse().unwrap();
    let exact = en["flywheel_inertia"]["exact"].as_f64().unwrap();
    assert!((said - exact).abs() <= 5e-4 * exact.abs(), "{said} for {exact}");
    assert_eq!(en["warnings"][1], "the constant k is not used by any expression of the request");
    assert_eq!(es["warnings"][1], "la constante k no la usa ninguna expresión de la petición");

    // How the accuracy was estimated.
    let method = es["accuracy"]["method"].as_str().unwrap();
    assert!(method.starts_with("M* integrado a trozos entre sus puntos de ruptura"), "{method}");
    assert!(en["accuracy"]["method"].as_str().unwrap().starts_with("M* integrated piecewise"));

    // The messages a client may match by id, the same in both.
    assert_eq!(es["messages"], en["messages"]);
    assert_eq!(en["messages"]["/warnings/0"]["id"], "warning-flywheel-no-disk");
    assert_eq!(en["messages"]["/warnings/1"]["args"], json!({"name": "k"}));
    assert_eq!(en["messages"]["/accuracy/method"]["id"], "accuracy-flywheel");

    // Nothing else moved.
    let without_texts = |r: &Value| {
        let mut r = r.clone();
        r["warnings"] = Value::Null;
        r["accuracy"]["method"] = Value::Null;
        r
    };
    assert_eq!(without_texts(es), without_texts(&en));

    // Every read of the job says it in the language asked for.
    let read = in_spanish(&app, "GET", &format!("/v1/jobs/{id}"), None).await.json();
    assert_eq!(&read["result"], es, "the job read in Spanish is the POST's Spanish answer");
    assert_eq!(app.get(&format!("/v1/jobs/{id}?lang=es")).await.json()["result"], *es, "?lang=es is the header");
    let part = app.get(&format!("/v1/jobs/{id}/result/warnings/1?lang=es")).await;
    assert_eq!(part.text, es["warnings"][1].as_str().unwrap(), "a part");
    let page = in_spanish(&app, "GET", &format!("/jobs/{id}"), None).await;
    assert!(page.text.contains("la constante k no la usa ninguna expresión de la petición"), "the page");
    assert!(!page.text.contains("is not used by any expression"), "no English warning on the page");
}

/// A contact's warnings name where they hold in the request's own unit,
/// the runs of positions as the language writes them: the flat follower
/// on an eccentric turned fast enough to leave it (tests/api/contact.rs).
#[tokio::test]
async fn a_contacts_warning_in_spanish() {
    let app = TestApp::new().await;
    let mut body = template_request("cam-flat-follower");
    body["input"]["speed"] = json!(30);
    let en = app.post("/v1/kinetostatics", &body).await.json()["result"].clone();
    let es = in_spanish(&app, "POST", "/v1/kinetostatics", Some(&body)).await.json()["result"].clone();
    let warning = |r: &Value, start: &str| {
        let all = r["warnings"].as_array().unwrap().iter().filter_map(Value::as_str);
        all.into_iter().find(|w| w.starts_with(start)).map(String::from)
    };
    let english = warning(&en, "contact K: the normal force is negative at 130 deg to 230 deg").unwrap();
    let spanish = warning(&es, "contacto K: la fuerza normal es negativa en 130 deg a 230 deg").unwrap();
    assert!(english.ends_with("unless something holds them together"), "{english}");
    assert!(spanish.ends_with("salvo que algo los mantenga juntos"), "{spanish}");
    let kinetostatics = es["accuracy"]["method"].as_str().unwrap();
    assert!(kinetostatics.starts_with("coordenadas de los sólidos; "), "{kinetostatics}");
}

/// A check's feedback in Spanish (the course's students read it): the same
/// verdicts and numbers, each answer's words Spanish with decimal commas,
/// the slip named in Spanish; the stored check read in English says it in
/// English; a platform's document (Gradescope's) too, and a class's CSV.
#[tokio::test]
async fn a_checks_feedback_in_spanish() {
    let app = TestApp::new().await;
    // P.103 (case F1): I_exact = 353.52 kg·m²; 260 slug·ft² = 352.51 kg·m² is within 1 %; the
    // approximate inertia, 348.99 kg·m², given for the exact one is 1.3 % off, a slip the check names.
    let answers =
        json!({"inertia_exact": "260 slug*ft^2", "inertia_approximate": "lots", "/flywheel_inertia/exact": 348.99});
    let body = json!({"template": "p103-slider-flywheel", "answers": answers});
    let posted = in_spanish(&app, "POST", "/v1/check", Some(&body)).await;
    assert_eq!(posted.status, StatusCode::CREATED, "{}", posted.text);
    let job = posted.json();
    let es = &job["result"];
    let en = app.get(&format!("/v1/jobs/{}", job["id"].as_str().unwrap())).await.json()["result"].clone();
    let feedback = |r: &Value, i: usize| r["items"][i]["feedback"].as_str().unwrap().to_string();
    // BTreeMap order of the answers: /flywheel_inertia/exact, inertia_approximate, inertia_exact.
    let (given, expected) = (es["items"][2]["given"].as_f64().unwrap(), es["items"][2]["expected"].as_f64().unwrap());
    let comma = |x: f64| format!("{x:.2}").replace('.', ",");
    assert_eq!(
        feedback(es, 2),
        format!(
            "inertia_exact: correcto (260 slug*ft^2 = {} kg*m^2, dentro de 1 % de {} kg*m^2).",
            comma(given),
            comma(expected)
        )
    );
    assert_eq!(
        feedback(&en, 2),
        format!("inertia_exact: correct (260 slug*ft^2 = {given:.2} kg*m^2, within 1 % of {expected:.2} kg*m^2).")
    );
    let unread = feedback(es, 1);
    assert!(unread.starts_with("inertia_approximate: 'lots' no es un número ni una magnitud ("), "{unread}");
    let slip = feedback(es, 0);
    assert!(
        slip.starts_with("flywheel_inertia/exact: 348,99 kg*m^2 no está dentro de 1 % del valor esperado, "),
        "{slip}"
    );
    assert!(
        slip.ends_with(
            " Coincide con flywheel_inertia/approximate del resultado: ¿se dio ese valor como flywheel_inertia/exact?"
        ),
        "{slip}"
    );
    assert!(feedback(&en, 0).ends_with(
        "It matches flywheel_inertia/approximate of the result: that value was given for flywheel_inertia/exact?"
    ));
    let verdicts = |r: &Value| r["items"].as_array().unwrap().iter().map(|i| i["pass"].clone()).collect::<Vec<_>>();
    assert_eq!(verdicts(es), verdicts(&en));
    assert_eq!(es["messages"]["/items/2/feedback"]["id"], "check-correct-revealed");

    let mut platform = body.clone();
    platform["format"] = json!("gradescope");
    let gs = in_spanish(&app, "POST", "/v1/check", Some(&platform)).await.json()["result"].clone();
    let output = gs["output"].as_str().unwrap();
    assert!(output.starts_with("1 de 3 respuestas dentro de la tolerancia (corregido por mechdyn "), "{output}");
    assert_eq!(gs["tests"][2]["output"].as_str().unwrap(), feedback(es, 2));

    let class = "student,variant,inertia_exact\nana,1,5 m\n";
    let req = Request::builder()
        .method("POST")
        .uri("/v1/templates/p103-class/grade?lang=es")
        .header("content-type", "text/csv")
        .body(Body::from(class))
        .unwrap();
    let graded = app.send(req).await;
    assert_eq!(graded.status, StatusCode::OK, "{}", graded.text);
    assert!(graded.text.contains("inertia_exact: '5 m' está en m, y la respuesta va en kg*m^2."), "{}", graded.text);
}

/// The grading and template requests' own errors in Spanish at the same
/// pointers as in English: a check naming no reference and no answer, a
/// part asked in a unit of another dimension.
#[tokio::test]
async fn a_checks_and_a_parts_errors_in_spanish() {
    let app = TestApp::new().await;
    let body = json!({"answers": {}});
    let (en, es) = (app.post("/v1/check", &body).await, in_spanish(&app, "POST", "/v1/check", Some(&body)).await);
    assert_eq!((en.status, es.status), (StatusCode::UNPROCESSABLE_ENTITY, StatusCode::UNPROCESSABLE_ENTITY));
    let said = |r: &Reply| {
        let errors = r.json()["errors"].as_array().unwrap().clone();
        errors.iter().map(|e| (e["pointer"].as_str().unwrap().to_string(), e["message"].clone())).collect::<Vec<_>>()
    };
    let (en, es) = (said(&en), said(&es));
    assert_eq!(en.iter().map(|e| &e.0).collect::<Vec<_>>(), es.iter().map(|e| &e.0).collect::<Vec<_>>());
    assert!(
        es.contains(&(
            "".into(),
            json!("indique la referencia: template (con parameters o variant), kind con request, o job")
        )),
        "{es:?}"
    );
    assert!(es.contains(&("/answers".into(), json!("al menos una respuesta: {\"PUNTERO\": valor}"))), "{es:?}");
    assert!(en.contains(&("/answers".into(), json!("at least one answer: {\"POINTER\": value}"))), "{en:?}");

    let part = "/v1/templates/p103-slider-flywheel/result/inertia_exact?unit=rpm&lang=es";
    let r = app.get(part).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST, "{}", r.text);
    let message = r.json()["errors"][0]["message"].as_str().unwrap().to_string();
    assert_eq!(message, "'rpm' es una unidad de rad/s; la parte en /inertia_exact está en kg*m^2");
}

/// A student's expression with a function the language does not have
/// (`seno`) is refused at its field, the language's functions named and
/// the place counted from 1 (the 11th character), in Spanish too; `sen`,
/// the sine in Spanish notation, is read as `sin`, to the same result.
#[tokio::test]
async fn an_expression_refused_in_spanish() {
    let app = TestApp::new().await;
    let mut body = request("p113_pulley");
    let expr = |body: &mut Value, e: &str| body["torques"][0]["value"]["segments"][0]["expr"] = json!(e);
    assert_eq!(body["torques"][0]["value"]["segments"][0]["expr"], "-5000*0.2*cos(phi)");
    let cosine = app.result("/v1/flywheel", &body).await["inertia_exact"].as_f64().unwrap();
    expr(&mut body, "-5000*0.2*sin(phi + pi/2)");
    let sine = app.result("/v1/flywheel", &body).await;
    expr(&mut body, "-5000*0.2*sen(phi + pi/2)");
    let sen = app.result("/v1/flywheel", &body).await;
    assert_eq!(sen["inertia_exact"], sine["inertia_exact"], "the same expression, bit for bit");
    // sin(φ + π/2) = cos φ: the same flywheel to the rounding of φ + π/2.
    assert!((sen["inertia_exact"].as_f64().unwrap() - cosine).abs() <= 1e-9 * cosine, "{sen} vs {cosine}");
    expr(&mut body, "-5000*0.2*seno(phi)");
    let es = in_spanish(&app, "POST", "/v1/flywheel", Some(&body)).await;
    let en = app.post("/v1/flywheel", &body).await;
    assert_eq!((en.status, es.status), (StatusCode::UNPROCESSABLE_ENTITY, StatusCode::UNPROCESSABLE_ENTITY));
    let (en, es) = (en.json()["errors"][0].clone(), es.json()["errors"][0].clone());
    assert_eq!(en["pointer"], es["pointer"]);
    assert_eq!(es["pointer"], "/torques/0/value/segments/0/expr");
    let functions = "sin cos tan asin acos atan atan2 sqrt exp ln log10 abs min max sign floor";
    assert_eq!(
        es["message"],
        format!(
            "la expresión no se puede leer: función desconocida 'seno' (las conocidas: {functions}) (en el carácter 11)"
        )
    );
    assert!(en["message"].as_str().unwrap().contains("unknown function 'seno' (known: sin cos"), "{en}");
}
