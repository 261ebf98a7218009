//! Plots of stored jobs: every kind with a curve lists its plots, every SVG
//! parses as XML with its title and named axes, and what the plots state
//! agrees with the stored result and with independent constructions.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// The job's plots (name, title, href) after a POST to `path`.
async fn plots_of(app: &TestApp, path: &str, body: &Value) -> (String, Vec<(String, String, String)>) {
    let r = app.post(path, body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let id = r.json()["id"].as_str().unwrap().to_string();
    let list = app.get(&format!("/v1/jobs/{id}/plots")).await;
    assert_eq!(list.status, StatusCode::OK, "{}", list.text);
    let plots = list.json()["plots"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            (
                p["name"].as_str().unwrap().into(),
                p["title"].as_str().unwrap().into(),
                p["href"].as_str().unwrap().into(),
            )
        })
        .collect();
    (id, plots)
}

/// The SVG at `href`: parsed as XML, its `<title>` the listed title, and every text it draws.
pub async fn svg_texts(app: &TestApp, href: &str, title: &str) -> Vec<String> {
    let r = app.get(href).await;
    assert_eq!(r.status, StatusCode::OK, "{href}: {}", r.text);
    assert_eq!(r.content_type, "image/svg+xml", "{href}");
    let doc = roxmltree::Document::parse(&r.text).unwrap_or_else(|e| panic!("{href} is not XML: {e}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    let svg_title = root.children().find(|n| n.has_tag_name("title")).and_then(|n| n.text());
    assert_eq!(svg_title, Some(title), "{href}");
    root.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(|t| t.trim().to_string())
        .collect()
}

/// Every plot listed draws, with its title and both axes named with a unit.
async fn every_plot_draws(app: &TestApp, plots: &[(String, String, String)]) {
    for (name, title, href) in plots {
        let texts = svg_texts(app, href, title).await;
        assert!(texts.iter().any(|t| t == title), "{name}: its title is drawn");
        let axes = texts.iter().filter(|t| t.ends_with(')') && t.contains(" (")).count();
        assert!(axes >= 2, "{name}: two axis names with units among {texts:?}");
    }
}

#[tokio::test]
async fn a_flywheel_has_its_four_plots_and_their_numbers_are_the_results() {
    let app = TestApp::new().await;
    let (id, plots) = plots_of(&app, "/v1/flywheel", &request("p103_slider")).await;
    let names: Vec<&str> = plots.iter().map(|p| p.0.as_str()).collect();
    assert_eq!(names, ["torque", "work", "speed", "wittenbauer"]);
    every_plot_draws(&app, &plots).await;
    let result = app.get(&format!("/v1/jobs/{id}")).await.json()["result"].clone();
    // ΔE as the plot writes it: four significant figures of the stored value.
    let texts = svg_texts(&app, &plots[1].2, &plots[1].1).await;
    let de = result["energy_fluctuation"].as_f64().unwrap();
    assert!(texts.iter().any(|t| t == &format!("ΔE = {} J", mechdyn::kind::plots::sig(de))), "{texts:?}");
    assert_eq!(mechdyn::kind::plots::sig(de), "551.1", "four figures of case F1's ΔE = 551.10 J");
    // Its extremes, each labelled at its line (S_max is at the top of the range, S_min at the bottom).
    let sums: Vec<f64> = result["cumulative"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    let (lo, hi) = sums.iter().fold((0.0_f64, 0.0_f64), |(a, b), &x| (a.min(x), b.max(x)));
    // ΔE = S_max − S_min by definition; 1e-9 of ΔE: the rounding of a few sums.
    assert!((hi - lo - de).abs() < 1e-9 * de, "ΔE = S_max − S_min");
    for label in
        [format!("S_max = {} J", mechdyn::kind::plots::sig(hi)), format!("S_min = {} J", mechdyn::kind::plots::sig(lo))]
    {
        assert!(texts.contains(&label), "{label} in {texts:?}");
    }
    let texts = svg_texts(&app, &plots[2].2, &plots[2].1).await;
    for (name, key) in [("ω_max", "omega_max"), ("ω_min", "omega_min")] {
        let label = format!("{name} = {}", mechdyn::kind::plots::sig(result[key].as_f64().unwrap()));
        assert!(texts.contains(&label), "{label} in {texts:?}");
    }
    // Each lobe's area A_i is labelled with its stored work.
    let texts = svg_texts(&app, &plots[0].2, &plots[0].1).await;
    for (k, a) in result["areas"].as_array().unwrap().iter().enumerate() {
        let w = a["work"].as_f64().unwrap();
        let label = format!("A{} = {}{} J", k + 1, if w > 0.0 { "+" } else { "" }, mechdyn::kind::plots::sig(w));
        assert!(texts.contains(&label), "{label} in {texts:?}");
    }
}

/// Wittenbauer's construction, independently of the engine's method: the
/// lines of slope ω²/2 through (−I, −T₀) bound the curve (I*(φ), W(φ)) and
/// touch it, ω_max's from above and ω_min's from below (T = T₀ + W =
/// ½(I + I*)ω²). Touching is to the sampling's resolution: 361 samples of a
/// smooth curve, so the gap at the nearest sample is within 1e-4 of ΔE.
#[tokio::test]
async fn wittenbauers_tangents_touch_the_energy_inertia_curve() {
    let app = TestApp::new().await;
    let r = app.post("/v1/flywheel", &request("p103_slider")).await.json()["result"].clone();
    let (i, t0) = (r["inertia_exact"].as_f64().unwrap(), r["kinetic_energy_at_start"].as_f64().unwrap());
    let de = r["energy_fluctuation"].as_f64().unwrap();
    for (omega, side) in [(r["omega_max"].as_f64().unwrap(), 1.0), (r["omega_min"].as_f64().unwrap(), -1.0)] {
        let gaps: Vec<f64> = r["samples"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| {
                let line = omega * omega / 2.0 * (s["reduced_inertia"].as_f64().unwrap() + i) - t0;
                side * (line - s["work"].as_f64().unwrap())
            })
            .collect();
        let nearest = gaps.iter().copied().fold(f64::INFINITY, f64::min);
        assert!(nearest > -1e-9 * de, "the curve crosses the tangent of ω = {omega}: {nearest}");
        assert!(nearest < 1e-4 * de, "the tangent of ω = {omega} misses the curve by {nearest} J");
    }
}

#[tokio::test]
async fn kinetostatics_plots_draw_the_mechanism_at_any_step_and_refuse_a_step_beyond() {
    let app = TestApp::new().await;
    let (id, plots) = plots_of(&app, "/v1/kinetostatics", &request("k1_offset_slider_crank")).await;
    let names: Vec<&str> = plots.iter().map(|p| p.0.as_str()).collect();
    for expected in
        ["driving", "reactions", "reaction-O", "reaction-guide", "reduced-inertia", "reduced-torque", "mechanism"]
    {
        assert!(names.contains(&expected), "{expected} in {names:?}");
    }
    every_plot_draws(&app, &plots).await;
    let title = &plots.iter().find(|p| p.0 == "mechanism").unwrap().1;
    let texts = svg_texts(&app, &format!("/v1/jobs/{id}/plots/mechanism.svg?step=3"), title).await;
    // K1 has 12 steps over 360°: step 3 is at 90°.
    assert!(texts.iter().any(|t| t.contains("step 3 of 0 to 11: input 90°")), "{texts:?}");
    for body in ["crank", "rod", "piston"] {
        assert!(texts.iter().any(|t| t == body), "{body} in the legend");
    }
    // The plots against the input show the drawn step as their cursor; the page asks them so.
    let title = &plots.iter().find(|p| p.0 == "driving").unwrap().1;
    let texts = svg_texts(&app, &format!("/v1/jobs/{id}/plots/driving.svg?step=3"), title).await;
    assert!(texts.iter().any(|t| t == "step 3"), "the cursor at step 3: {texts:?}");
    let page = app.get(&format!("/jobs/{id}?step=3")).await.text;
    assert!(page.contains("plots/driving.svg?step=3"), "the page's plots share the step");
    let r = app.get(&format!("/v1/jobs/{id}/plots/mechanism.svg?step=12")).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    assert_eq!(r.json()["errors"][0]["parameter"], "step");
    assert!(r.json()["errors"][0]["message"].as_str().unwrap().contains("0 to 11"), "{}", r.text);
    let r = app.get(&format!("/v1/jobs/{id}/plots/nothing.svg")).await;
    assert_eq!(r.status, StatusCode::NOT_FOUND);
    assert_eq!(r.json()["type"], "/problems/no-such-plot");
    assert!(r.json()["detail"].as_str().unwrap().contains("reaction-guide"), "the plots are listed: {}", r.text);
    let r = app.get(&format!("/v1/jobs/{id}/plots/driving")).await;
    assert_eq!(r.status, StatusCode::NOT_FOUND);
    assert!(r.json()["detail"].as_str().unwrap().contains("driving.svg"), "the addresses it has: {}", r.text);
}

/// The two-link arm's bodies as stored at every sample: the upper arm's
/// centre of mass stays 0.25 m from the shoulder O and the elbow 0.5 m
/// (the drawn lengths, P.68), to the integration's constraint tolerance.
#[tokio::test]
async fn a_mechanism_in_dynamics_stores_its_bodies_positions_and_draws_their_paths() {
    let app = TestApp::new().await;
    let (id, plots) = plots_of(&app, "/v1/dynamics", &request("p68_two_link_arm")).await;
    let names: Vec<&str> = plots.iter().map(|p| p.0.as_str()).collect();
    assert_eq!(names, ["angle", "speed", "phase", "energy", "reactions", "mechanism", "motion", "path-elbow"]);
    every_plot_draws(&app, &plots).await;
    let job = app.get(&format!("/v1/jobs/{id}")).await.json();
    for s in job["result"]["machine"]["samples"].as_array().unwrap() {
        let upper = &s["bodies"][0];
        assert_eq!(upper["body"], "upper arm");
        let (x, y, th) = (upper["x"].as_f64().unwrap(), upper["y"].as_f64().unwrap(), upper["theta"].as_f64().unwrap());
        assert!((x.hypot(y) - 0.25).abs() < 1e-8, "|OG| = {}", x.hypot(y));
        // The elbow, 0.25 m beyond G along the arm (drawn along +y): 0.5 m from O.
        let elbow = (x - 0.25 * th.sin(), y + 0.25 * th.cos());
        assert!((elbow.0.hypot(elbow.1) - 0.5).abs() < 1e-8);
    }
}

#[tokio::test]
async fn rotors_and_gears_have_their_plots_and_kinds_without_curves_have_none() {
    let app = TestApp::new().await;
    let angles: Vec<String> = (0..=24).map(|k| format!("{} deg", 15 * k)).collect();
    let mut rotor = crate::helpers::example("RotorRequest");
    rotor["angles"] = json!(angles);
    let (_, plots) = plots_of(&app, "/v1/rotor", &rotor).await;
    assert_eq!(plots.iter().map(|p| p.0.as_str()).collect::<Vec<_>>(), ["bearings"]);
    every_plot_draws(&app, &plots).await;
    let (_, plots) = plots_of(&app, "/v1/gears/geometry", &json!({"module": "4 mm", "teeth": 18})).await;
    assert_eq!(plots.iter().map(|p| p.0.as_str()).collect::<Vec<_>>(), ["tooth"]);
    every_plot_draws(&app, &plots).await;
    let (_, plots) = plots_of(&app, "/v1/gears/train", &crate::helpers::example("TrainRequest")).await;
    assert!(plots.is_empty());
    // P.107's I* is constant: Wittenbauer's diagram would be a vertical segment, so it is not offered.
    let (_, plots) = plots_of(&app, "/v1/flywheel", &request("p107_two_stroke")).await;
    assert_eq!(plots.iter().map(|p| p.0.as_str()).collect::<Vec<_>>(), ["torque", "work", "speed"]);
    let mut flywheel = request("p103_slider");
    flywheel["samples"] = json!(0);
    let (_, plots) = plots_of(&app, "/v1/flywheel", &flywheel).await;
    assert!(plots.is_empty(), "no samples, no curve: {plots:?}");
}

/// A name with markup stays text in the SVG (XML-escaped; a control
/// character, which XML cannot hold at all, replaced).
#[tokio::test]
async fn names_with_markup_stay_text_in_a_plot() {
    let app = TestApp::new().await;
    let mut k1 = request("k1_offset_slider_crank");
    let evil = "<script>alert(1)</script>&\u{1}";
    k1["mechanism"]["bodies"][1]["name"] = json!(evil);
    for j in k1["mechanism"]["joints"].as_array_mut().unwrap() {
        for b in j["bodies"].as_array_mut().unwrap() {
            if b == "rod" {
                *b = json!(evil);
            }
        }
    }
    let (_, plots) = plots_of(&app, "/v1/kinetostatics", &k1).await;
    let mechanism = plots.iter().find(|p| p.0 == "mechanism").unwrap();
    let texts = svg_texts(&app, &mechanism.2, &mechanism.1).await;
    assert!(texts.iter().any(|t| t == "<script>alert(1)</script>&\u{FFFD}"), "{texts:?}");
}

/// The energy residual at each sample: at the last one it is the result's
/// own for a mechanism (the same integrated power W and kinetic energy, so
/// the same double); for the reduced form with torques of φ only the result
/// takes W by quadrature over the angle instead, so the two agree to the
/// integration's tolerance (1e-9 here, the default tolerance's order).
#[tokio::test]
async fn the_energy_residual_is_stored_at_every_sample_and_agrees_with_the_results() {
    let app = TestApp::new().await;
    let arm = app.post("/v1/dynamics", &request("p68_two_link_arm")).await.json()["result"].clone();
    let last = arm["samples"].as_array().unwrap().last().unwrap()["energy_residual"].as_f64().unwrap();
    assert_eq!(last, arm["energy_residual"].as_f64().unwrap());
    let reduced = app.post("/v1/dynamics", &crate::helpers::example("DynamicsRequest")).await.json()["result"].clone();
    let samples = reduced["samples"].as_array().unwrap();
    assert_eq!(samples[0]["energy_residual"].as_f64().unwrap(), 0.0, "nothing drifted at the start");
    let last = samples.last().unwrap()["energy_residual"].as_f64().unwrap();
    let by_quadrature = reduced["energy_residual"].as_f64().unwrap();
    assert!((last - by_quadrature).abs() < 1e-9, "{last} against {by_quadrature}");
    // Along the way the balance holds to the same order: 1e-8, ten times the agreement above.
    assert!(samples.iter().all(|s| s["energy_residual"].as_f64().unwrap().abs() < 1e-8));
}

/// The frames of a motion SVG: (step, when it shows, a fraction of the
/// loop) in order, and the loop's duration in seconds; each frame's
/// `<animate>` turns it visible at its time and hidden at the next's.
fn frames(svg: &str) -> (Vec<(usize, f64)>, f64) {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let mut out = Vec::new();
    let mut seconds = 0.0;
    for g in doc.descendants().filter(|n| n.has_tag_name("g") && n.attribute("data-step").is_some()) {
        let step = g.attribute("data-step").unwrap().parse().unwrap();
        let a = g.children().find(|n| n.has_tag_name("animate")).expect("each frame animated");
        assert_eq!((a.attribute("attributeName"), a.attribute("calcMode")), (Some("visibility"), Some("discrete")));
        seconds = a.attribute("dur").unwrap().trim_end_matches('s').parse().unwrap();
        let values: Vec<&str> = a.attribute("values").unwrap().split(';').collect();
        let times: Vec<f64> = a.attribute("keyTimes").unwrap().split(';').map(|t| t.parse().unwrap()).collect();
        let on = values.iter().position(|v| *v == "visible").unwrap();
        out.push((step, times[on]));
    }
    (out, seconds)
}

/// A sweep of 360 steps plays in 120 frames (every third step) at equal
/// shares of its 4 s loop; a dynamics run shows each sample at its own
/// time (t − t₀ over the run), the run played in 2 to 20 s.
#[tokio::test]
async fn a_motion_shows_its_steps_in_turn_at_their_times() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["input"]["steps"] = json!(360);
    let (id, _) = plots_of(&app, "/v1/kinetostatics", &body).await;
    let svg = app.get(&format!("/v1/jobs/{id}/plots/motion.svg")).await.text;
    let (shown, seconds) = frames(&svg);
    assert_eq!(seconds, 4.0);
    assert_eq!(shown.len(), 120);
    for (i, (step, at)) in shown.iter().enumerate() {
        assert_eq!((*step, *at), (3 * i, i as f64 / 120.0), "frame {i}");
    }
    let (id, _) = plots_of(&app, "/v1/dynamics", &request("p68_two_link_arm")).await;
    let job = app.get(&format!("/v1/jobs/{id}")).await.json();
    let samples = job["result"]["machine"]["samples"].as_array().unwrap();
    let t = |k: usize| samples[k]["t"].as_f64().unwrap();
    let run = t(samples.len() - 1) - t(0);
    let (shown, seconds) = frames(&app.get(&format!("/v1/jobs/{id}/plots/motion.svg")).await.text);
    assert_eq!(seconds, run.clamp(2.0, 20.0));
    assert_eq!(shown.len(), samples.len().min(120));
    for (step, at) in shown {
        assert!((at - (t(step) - t(0)) / run).abs() < 1e-12, "sample {step} shows at its time: {at}");
    }
}

/// A flywheel's machine moves too: its 72 poses are where a kinetostatics
/// sweep of the same mechanism puts its bodies (a second solver: a sweep
/// from the drawing against the machine's anchors and Newton, 1e-9 m and
/// rad), and each is shown at the time the flywheel's speed takes to reach
/// it: within ε of an even share of the loop, not all of them even.
#[tokio::test]
async fn a_flywheels_machine_moves_at_its_speed() {
    let app = TestApp::new().await;
    let body = request("p103_slider_machine");
    let (id, plots) = plots_of(&app, "/v1/flywheel", &body).await;
    assert!(plots.iter().any(|p| p.0 == "motion"), "{plots:?}");
    let result = app.get(&format!("/v1/jobs/{id}")).await.json()["result"].clone();
    let poses = result["machine_poses"].as_array().unwrap();
    assert_eq!(poses.len(), 72);
    let sweep = json!({
        "mechanism": body["machine"]["mechanism"],
        "input": {"joint": "O", "speed": "60 rpm", "start": 0, "end": "360 deg", "steps": 72},
        "outputs": ["kinematics"],
    });
    let swept = app.result("/v1/kinetostatics", &sweep).await;
    for (k, (pose, step)) in poses.iter().zip(swept["steps"].as_array().unwrap()).enumerate() {
        assert!((pose["angle"].as_f64().unwrap() - step["input"].as_f64().unwrap()).abs() < 1e-12);
        for (b, swept_body) in step["kinematics"].as_array().unwrap().iter().enumerate() {
            for key in ["x", "y", "theta"] {
                let Some(expected) = swept_body[key].as_f64() else { continue }; // the massless crank's G
                let got = pose["bodies"][b][key].as_f64().unwrap();
                assert!((got - expected).abs() < 1e-9, "pose {k}, body {b}, {key}: {got} against {expected}");
            }
        }
    }
    let (shown, seconds) = frames(&app.get(&format!("/v1/jobs/{id}/plots/motion.svg")).await.text);
    assert_eq!((shown.len(), seconds), (72, 4.0));
    let eps = 0.04;
    for (step, at) in &shown {
        assert!((at - *step as f64 / 72.0).abs() <= eps, "frame {step} at {at}");
    }
    assert!(shown.iter().any(|(step, at)| (at - *step as f64 / 72.0).abs() > 1e-4), "the speed varies");
}
