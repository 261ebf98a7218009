//! The `contact` joint over HTTP: curves in the drawing, where they touch,
//! the contact's state in every step and its forces in the reaction, the
//! errors at their fields.

use crate::helpers::{TestApp, template_request};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// |actual − expected| ≤ 1e-9·scale.
#[track_caller]
fn near(actual: &Value, expected: f64, scale: f64, what: &str) {
    let a = actual.as_f64().unwrap_or_else(|| panic!("{what}: {actual} is not a number"));
    assert!((a - expected).abs() <= 1e-9 * scale, "{what}: {a} vs {expected}");
}

async fn kinetostatics(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()["result"].clone()
}

/// Template `cam-flat-follower` (seed 002 q2) with its eccentric disk: a
/// Scotch yoke (R = 0.05, e = 0.02, m = 2 kg, g = 9.81, ω = 10 rad/s, μ =
/// 0.1). At θ the follower is lifted e(1 − cos θ), the contact lies at
/// (e sin θ, R − e cos θ), N = m(g + eω² cos θ), the friction on the
/// follower −μN (it slides at ω(R − e cos θ) along +x on the cam), the
/// cam's torque N(e sin θ + μ(R − e cos θ)); the contact point moves on
/// the cam at ω × OK and on the follower at (0, eω sin θ); the radii are
/// [R, straight] and a flat follower's pressure angle 0 (1e-9).
#[tokio::test]
async fn the_eccentric_cam_under_a_flat_follower_is_a_scotch_yoke() {
    let app = TestApp::new().await;
    let (r, e, m, g, w, mu) = (0.05, 0.02, 2.0, 9.81, 10.0, 0.1);
    let result = kinetostatics(&app, &template_request("cam-flat-follower")).await;
    assert_eq!((result["dof"].as_i64(), result["grubler"]["mobility"].as_i64()), (Some(1), Some(1)), "{result}");
    let steps = result["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 36);
    for step in steps {
        let theta = step["input"].as_f64().unwrap();
        let (s, c) = theta.sin_cos();
        let n = m * (g + e * w * w * c);
        let what = |x: &str| format!("θ = {theta}: {x}");
        near(&step["driving"], n * (e * s + mu * (r - e * c)), m * g * r, &what("cam torque"));
        let contact = &step["contacts"][0];
        assert_eq!(contact["joint"], "K");
        near(&contact["point"][0], e * s, r, &what("contact x"));
        near(&contact["point"][1], r - e * c, r, &what("contact y"));
        near(&contact["normal"], n, m * g, &what("N"));
        near(&contact["tangential"], -mu * n, m * g, &what("friction on the follower"));
        near(&contact["sliding_velocity"], w * (r - e * c), w * r, &what("sliding"));
        near(&contact["velocities"][0][0], -w * (r - e * c), w * r, &what("v on the cam, x"));
        near(&contact["velocities"][0][1], w * e * s, w * r, &what("v on the cam, y"));
        near(&contact["velocities"][1][0], 0.0, w * r, &what("v on the follower, x"));
        near(&contact["velocities"][1][1], e * w * s, w * r, &what("v on the follower, y"));
        near(&contact["curvature_radius"][0], r, r, &what("the disk's radius"));
        assert!(contact["curvature_radius"][1].is_null(), "a flat face is straight");
        // (Null where the follower stands still: at θ = 0 exactly.)
        if theta == 0.0 {
            assert!(contact["pressure_angle"].is_null(), "a follower at rest has no pressure angle: {contact}");
        } else {
            near(&contact["pressure_angle"], 0.0, 1.0, &what("pressure angle"));
        }
        let reaction = step["reactions"].as_array().unwrap().iter().find(|x| x["joint"] == "K").unwrap();
        assert_eq!((reaction["on"].as_str(), reaction["by"].as_str()), (Some("follower"), Some("cam")));
        near(&reaction["fx"], -mu * n, m * g, &what("reaction fx"));
        near(&reaction["fy"], n, m * g, &what("reaction fy"));
        near(&reaction["normal"], n, m * g, &what("reaction's normal"));
        near(&reaction["tangential"], -mu * n, m * g, &what("reaction's tangential"));
        assert!(reaction.get("mu_required").is_none(), "a sliding contact needs no μ: {reaction}");
    }
    assert!(result["warnings"].as_array().unwrap().is_empty(), "{}", result["warnings"]);
}

/// Turned fast enough (eω² > g: ω > √(9.81/0.02) = 22.1 rad/s) the
/// follower would leave the cam near the top of the lift, where
/// N = m(g + eω² cos θ) < 0: a warning names the range, the numbers stay.
#[tokio::test]
async fn a_follower_that_would_jump_is_a_warning_with_its_range() {
    let app = TestApp::new().await;
    let mut body = template_request("cam-flat-follower");
    body["input"]["speed"] = json!(30);
    let result = kinetostatics(&app, &body).await;
    let warnings = result["warnings"].to_string();
    // cos θ < −g/(eω²) = −0.545: θ in (123°, 237°), the sampled 130° to 230°.
    assert!(warnings.contains("contact K: the normal force is negative at 130 deg to 230 deg"), "{warnings}");
    let negative =
        result["steps"].as_array().unwrap().iter().filter(|s| s["contacts"][0]["normal"].as_f64().unwrap() < 0.0);
    assert_eq!(negative.count(), 11);
}

/// Curves that do not touch as drawn, or cross, are a 422 at the joint's
/// `curves` saying so; a contact without curves, curves on another joint,
/// a point that rolls and a bad radius point where they are.
#[tokio::test]
async fn contacts_that_are_not_drawn_touching_are_refused_at_their_curves() {
    let app = TestApp::new().await;
    let curves = "/mechanism/joints/2/curves";
    let mut gap = template_request("cam-flat-follower");
    gap["mechanism"]["points"]["F"] = json!([0, 0.031]);
    let r = app.post("/v1/kinetostatics", &gap).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let error = &r.json()["errors"][0];
    assert_eq!(error["pointer"], curves);
    assert!(
        error["message"].as_str().unwrap().contains("do not touch as drawn: 1.000e-3 m apart near (0, 0.0305)"),
        "{error}"
    );
    let mut cross = template_request("cam-flat-follower");
    cross["mechanism"]["points"]["F"] = json!([0, 0.02]);
    let r = app.post("/v1/kinetostatics", &cross).await;
    assert!(r.json()["errors"][0]["message"].as_str().unwrap().contains("cross at"), "{}", r.text);
    let mut bad = template_request("cam-flat-follower");
    bad["mechanism"]["joints"][2]["curves"][0]["circle"]["radius"] = json!("-5 mm");
    bad["mechanism"]["joints"][1]["rolling"] = json!(true);
    assert_eq!(
        app.pointers("/v1/kinetostatics", &bad).await,
        ["/mechanism/joints/1/rolling", "/mechanism/joints/2/curves/0/circle/radius"]
    );
    let mut none = template_request("cam-flat-follower");
    none["mechanism"]["joints"][2].as_object_mut().unwrap().remove("curves");
    assert_eq!(app.pointers("/v1/kinetostatics", &none).await, ["/mechanism/joints/2"]);
    let mut point = template_request("cam-flat-follower");
    point["mechanism"]["joints"][2]["curves"][1] = json!({"point": [0, 0.03]});
    point["mechanism"]["joints"][2]["rolling"] = json!(true);
    assert_eq!(app.pointers("/v1/kinetostatics", &point).await, ["/mechanism/joints/2/rolling"]);
}

/// Template `ring-on-rim` (seed 002 q4: R = 0.1 m, the pin O R/2 left of
/// the centre C, the ring P at the rim's top, ω = 2 rad/s, v = 0.5 m/s to
/// the right as the seed draws it (clockwise along the rim), both
/// constant): v_P = ω × OP + v = (−0.2 + 0.5, 0.1) and a_P = −ω² OP −
/// (v²/R) e_r + 2ω × v = (−0.2, −0.4 − 2.5 + 2.0) m/s² (hand-worked, 1e-12). The ring is a particle: two inputs move the
/// whole (Grübler: 3·2 − 1 − 2 − 1 = 2), its rotation stays 0, and its
/// contact, which holds both ways, warns of nothing.
#[tokio::test]
async fn a_ring_on_a_rim_moves_as_the_composition_of_motions_says() {
    let app = TestApp::new().await;
    let result = kinetostatics(&app, &template_request("ring-on-rim")).await;
    assert_eq!((result["dof"].as_i64(), result["grubler"]["mobility"].as_i64()), (Some(2), Some(2)), "{result}");
    assert_eq!(result["inputs"][1]["coordinate_unit"], "m");
    let p = &result["steps"][0]["points"][0];
    for (field, want) in [("vx", 0.3), ("vy", 0.1), ("ax", -0.2), ("ay", -0.9)] {
        near(&p[field], want, 1e-3, field);
    }
    let ring = &result["steps"][0]["kinematics"][1];
    assert_eq!((ring["theta"].as_f64(), ring["omega"].as_f64()), (Some(0.0), Some(0.0)), "{ring}");
    near(&result["steps"][0]["contacts"][0]["sliding_velocity"], -0.5, 1e-3, "the ring along the rim, clockwise");
    assert!(result["warnings"].as_array().unwrap().is_empty(), "{}", result["warnings"]);
}

async fn dynamics(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/dynamics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()["result"].clone()
}

/// Template `rolling-disk`: a uniform disk rolling from rest down an
/// incline (drawn level, gravity g(sin α, −cos α) tilted by α = 30°).
/// The closed forms: s = ½at² with a = g sin α/(1 + I/(mR²)) = ⅔ g sin α,
/// the incline's friction on it ⅓ m g sin α up the slope, normal m g cos α,
/// so mu_required = tan α/3 (1e-9); made a hoop (I = mR²), a = ½ g sin α.
/// Energy is conserved (rolling does no work) to the integrator's 1e-10.
#[tokio::test]
async fn a_disk_rolls_down_an_incline_at_two_thirds_g_sin_alpha() {
    let app = TestApp::new().await;
    let mut body = template_request("rolling-disk");
    let (m, r) = (2.0, 0.1);
    let gravity = &body["machine"]["mechanism"]["gravity"];
    let (g_sin, g_cos) = (gravity[0].as_f64().unwrap(), -gravity[1].as_f64().unwrap());
    for (inertia, share) in [(0.5 * m * r * r, 2.0 / 3.0), (m * r * r, 0.5)] {
        body["machine"]["mechanism"]["bodies"][0]["inertia"] = json!(inertia);
        let result = dynamics(&app, &body).await;
        assert!(result["energy_residual"].as_f64().unwrap().abs() < 1e-9, "{}", result["energy_residual"]);
        let a = share * g_sin;
        for sample in result["machine"]["samples"].as_array().unwrap() {
            let t = sample["t"].as_f64().unwrap();
            let input = &sample["inputs"][0];
            near(&input["angle"], 0.5 * a * t * t, a, &format!("s at t = {t}"));
            near(&input["acceleration"], a, a, &format!("a at t = {t}"));
            let reaction = &sample["reactions"][0];
            near(&reaction["normal"], m * g_cos, m * g_cos, "N = m g cos α");
            near(
                &json!(reaction["tangential"].as_f64().unwrap().abs()),
                m * g_sin * (1.0 - share),
                m * g_sin,
                "friction",
            );
            near(&reaction["mu_required"], (1.0 - share) * g_sin / g_cos, 1.0, "μ_min");
            near(&sample["contacts"][0]["sliding_velocity"], 0.0, 1.0, "rolling does not slide");
        }
    }
}

/// A disk (r = 0.1 m, I = ½mr²) rolling inside a circular track (R = 0.5
/// m, `inside`), released from rest 0.01 rad from the bottom, swings with
/// ω² = 2g/(3(R − r)) (the rolling pendulum; amplitude 0.01 lengthens the
/// period by 6e-6): half a period later the contact has run −2Rθ₀ along the
/// track (1e-5 relative), and T + V stays E₀ to the integrator's tolerance.
#[tokio::test]
async fn a_disk_rolling_in_a_circular_track_swings_as_its_pendulum() {
    let app = TestApp::new().await;
    let (big, small, g, theta) = (0.5, 0.1, 9.81, 0.01f64);
    let centre = [(big - small) * theta.sin(), big - (big - small) * theta.cos()];
    let period = std::f64::consts::TAU * (3.0 * (big - small) / (2.0 * g)).sqrt();
    let body = json!({
        "machine": {
            "mechanism": {
                "points": {"O": [0, big], "C": centre},
                "bodies": [{"name": "disk", "mass": 1, "inertia": 0.5 * small * small, "cg": "C"}],
                "joints": [{"name": "K", "type": "contact", "bodies": ["ground", "disk"], "rolling": true,
                    "curves": [{"circle": {"center": "O", "radius": big, "inside": true}},
                               {"circle": {"center": "C", "radius": small}}]}],
                "gravity": [0, -g]
            },
            "input": {"joint": "K"}
        },
        "initial": {"angle": 0, "speed": 0},
        "duration": period / 2.0,
        "tolerance": 1e-11,
        "samples": 3
    });
    let result = dynamics(&app, &body).await;
    let last = result["machine"]["samples"].as_array().unwrap().last().unwrap().clone();
    let s = last["inputs"][0]["angle"].as_f64().unwrap();
    assert!((s.abs() - 2.0 * big * theta).abs() < 1e-5 * 2.0 * big * theta, "s(T/2) = {s}");
    assert!(result["energy_residual"].as_f64().unwrap().abs() < 1e-9, "{}", result["energy_residual"]);
    assert!(result["warnings"].as_array().unwrap().is_empty(), "{}", result["warnings"]);
    // A disk of the track's own radius fills it: refused at the curves, not a run in which nothing moves.
    let mut full = body.clone();
    full["machine"]["mechanism"]["joints"][0]["curves"][1]["circle"]["radius"] = json!(big);
    full["machine"]["mechanism"]["points"]["C"] = json!([0, big]);
    let r = app.post("/v1/dynamics", &full).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/machine/mechanism/joints/0/curves", "{}", r.text);
    assert!(r.text.contains("touches it all round"), "{}", r.text);
}

/// A flywheel's `machine` may hold a contact: the eccentric cam of
/// `cam-flat-follower` (no friction) at 300 rpm, δ = 0.02, needs the same
/// flywheel as its reduced functions written by hand — I*(φ) = I_cam +
/// m(e sin φ)² (the follower moves at eω sin φ) and the weight's M*(φ) =
/// −m g e sin φ — to 1e-9 (two paths: the mechanism solver's I*, M* at
/// every angle against the expressions).
#[tokio::test]
async fn a_flywheel_machine_with_a_cam_equals_its_reduced_functions() {
    let app = TestApp::new().await;
    let mut mechanism = template_request("cam-flat-follower")["mechanism"].clone();
    mechanism["joints"][2].as_object_mut().unwrap().remove("friction");
    let machine = json!({"mean_speed": "300 rpm", "irregularity": 0.02, "torques": [{"name": "motor", "balance": true}],
        "machine": {"mechanism": mechanism, "input": {"joint": "O"}}});
    let written = json!({"mean_speed": "300 rpm", "irregularity": 0.02,
        "torques": [{"name": "gravity", "value": {"expr": "-2*9.81*0.02*sin(phi)"}}, {"name": "motor", "balance": true}],
        "reduced_inertia": {"expr": "0.002 + 2*(0.02*sin(phi))^2"}});
    let (a, b) = (app.flywheel(&machine).await, app.flywheel(&written).await);
    let (a, b) = (a["result"]["inertia_exact"].as_f64().unwrap(), b["result"]["inertia_exact"].as_f64().unwrap());
    assert!((a - b).abs() < 1e-9 * b, "{a} vs {b}");
}

/// Mobility with contacts: a sliding contact is a class-II pair and rolling
/// a class-I one in Grübler's count, a particle counts two coordinates, and
/// the Jacobian's rank agrees — the cam 3·2 − 2·2 − 1 = 1, the rolling disk
/// 3·1 − 2 = 1, the ring on its rim 3·2 − 1 − 2 − 1 = 2.
#[tokio::test]
async fn contacts_count_as_their_class_and_the_rank_agrees() {
    let app = TestApp::new().await;
    for (template, machine, dof) in
        [("cam-flat-follower", false, 1), ("rolling-disk", true, 1), ("ring-on-rim", false, 2)]
    {
        let request = template_request(template);
        let mechanism = if machine { request["machine"]["mechanism"].clone() } else { request["mechanism"].clone() };
        let r = app.post("/v1/mobility", &json!({"mechanism": mechanism})).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let result = &r.json()["result"];
        assert_eq!(
            (result["dof"].as_i64(), result["grubler"]["mobility"].as_i64()),
            (Some(dof), Some(dof)),
            "{template}: {result}"
        );
    }
}

/// A ring driven along an open spline track (ground) beyond the track's
/// end: the steps past it are warned of, never passed off as a contact.
#[tokio::test]
async fn a_contact_that_runs_off_an_open_curve_is_a_warning() {
    let app = TestApp::new().await;
    let body = json!({
        "mechanism": {
            "points": {"P": [0.1, 0.02]},
            "bodies": [{"name": "ring", "mass": 0.1, "cg": "P"}],
            "joints": [{"name": "track", "type": "contact", "bodies": ["ground", "ring"],
                "curves": [{"spline": {"points": [[0, 0], [0.1, 0.02], [0.2, 0], [0.3, 0.02]]}}, {"point": "P"}]}]
        },
        "input": {"joint": "track", "start": 0, "end": 0.4, "steps": 9, "speed": 1},
        "outputs": ["driving", "reactions", "kinematics"]
    });
    let result = kinetostatics(&app, &body).await;
    let warnings = result["warnings"].to_string();
    assert!(warnings.contains("contact track: the contact runs off the end of an open curve at"), "{warnings}");
    let steps = result["steps"].as_array().unwrap();
    assert!(steps[0]["contacts"][0].get("off_end").is_none(), "on the track at the start");
    assert_eq!(steps.last().unwrap()["contacts"][0]["off_end"], true);
}

/// Direct dynamics of the eccentric cam left to turn at 20 rad/s against
/// its follower pressed by a spring (2000 N/m, 0.05 m of preload) and its
/// weight: only conservative forces work, so T + V stays at its start
/// (1e-9 of E₀ at the integrator's 1e-10), and the spring keeps the
/// follower on the cam (the normal force positive throughout, no warning).
#[tokio::test]
async fn a_spring_loaded_cam_follower_keeps_its_energy_in_dynamics() {
    let app = TestApp::new().await;
    let mut mechanism = template_request("cam-flat-follower")["mechanism"].clone();
    mechanism["joints"][2].as_object_mut().unwrap().remove("friction");
    mechanism["points"]["S"] = json!([0, 0.2]);
    let body = json!({
        "machine": {"mechanism": mechanism, "input": {"joint": "O"},
            "loads": [{"type": "spring", "a": ["ground", "S"], "b": ["follower", "G"], "stiffness": "2000 N/m",
                "free_length": "0.15 m"}]},
        "initial": {"angle": 0, "speed": 20}, "duration": 2, "tolerance": 1e-10, "samples": 41
    });
    let result = dynamics(&app, &body).await;
    let samples = result["machine"]["samples"].as_array().unwrap();
    let energy = |s: &Value| {
        let e = &s["energy"];
        ["gravity", "springs"].iter().map(|k| e["potential"][k].as_f64().unwrap()).sum::<f64>()
            + e["kinetic"]["total"].as_f64().unwrap()
    };
    let e0 = energy(&samples[0]);
    for s in samples {
        assert!((energy(s) - e0).abs() < 1e-9 * e0.abs(), "t = {}: {} vs {e0}", s["t"], energy(s));
        assert!(s["contacts"][0]["normal"].as_f64().unwrap() > 0.0, "{}", s["contacts"][0]);
    }
    assert!(result["warnings"].as_array().unwrap().is_empty(), "{}", result["warnings"]);
}

/// A flat-faced follower on a peanut-shaped cam r(ψ) = 50 + 20 cos 2ψ mm:
/// its profile turns concave at ψᵢ where r² + 2r′² − r r″ = 0 (72.37°),
/// so the contact followed from the top of a lobe could go on until the
/// cam has turned by the tangent's turn from ψ = 0 to ψᵢ (the fold, θ_f =
/// 106.8°, both found here from the polar curve's formulas). But the face
/// leaves that lobe earlier: it rests on the cam's highest points, and by
/// the cam's half-turn symmetry both lobes are level at θ = 90° (and
/// 270°), where the face touches both. The sweep (5° steps) reports the
/// jump at the first position past 90° and before the fold, and again
/// half a turn later, in the contacts and in a warning, never silently.
#[tokio::test]
async fn a_contact_that_jumps_to_another_lobe_is_a_warning() {
    let app = TestApp::new().await;
    let (a, b) = (0.05, 0.02);
    let r = |p: f64| [a + b * (2.0 * p).cos(), -2.0 * b * (2.0 * p).sin(), -4.0 * b * (2.0 * p).cos()];
    let convex = |p: f64| {
        let [r0, r1, r2] = r(p);
        r0 * r0 + 2.0 * r1 * r1 - r0 * r2
    };
    let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if convex(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    // The tangent's direction of r e(ψ + 90°): its turn from ψ = 0 to ψᵢ.
    let tangent = |p: f64| {
        let ([r0, r1, _], (s, c)) = (r(p), (p + std::f64::consts::FRAC_PI_2).sin_cos());
        (r1 * s + r0 * c).atan2(r1 * c - r0 * s)
    };
    let fold = (tangent(lo) - tangent(0.0)).rem_euclid(std::f64::consts::TAU).to_degrees();
    assert!((fold - 106.8).abs() < 0.1, "θ_f = {fold}°");
    let mut body = template_request("cam-flat-follower");
    let mechanism = &mut body["mechanism"];
    mechanism["points"]["F"] = json!([0, 0.07]);
    mechanism["joints"][2]["curves"][0] =
        json!({"polar": {"center": "O", "zero": [0, 1], "radius": {"expr": "0.05 + 0.02*cos(2*psi)"}}});
    body["input"]["steps"] = json!(72);
    let result = kinetostatics(&app, &body).await;
    let jumped: Vec<f64> = result["steps"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["contacts"][0]["jumped"] == true)
        .map(|s| s["input"].as_f64().unwrap().to_degrees())
        .collect();
    assert_eq!(jumped.len(), 2, "{jumped:?}");
    for (at, level) in jumped.iter().zip([90.0, 270.0]) {
        assert!(
            *at > level && *at <= level + 5.0 + 1e-9 && *at < level + fold - 90.0,
            "the jump at {at}° (level at {level}°)"
        );
    }
    let warnings = result["warnings"].to_string();
    assert!(warnings.contains("contact K: the contact jumped at"), "{warnings}");
}

/// The driving actions two independent ways — the multipliers, and virtual
/// power (Σ Q·q̇ per unit input speed, no multipliers) — agree to 1e-10
/// with contacts: the eccentric cam with friction at its contact (one
/// input), and the ring on the rim under gravity with both of its inputs
/// (the disk's turn and the ring's run along the rim) swept together.
#[tokio::test]
async fn virtual_power_agrees_with_the_multipliers_with_contacts() {
    let app = TestApp::new().await;
    let cam = kinetostatics(&app, &template_request("cam-flat-follower")).await;
    let mut ring = template_request("ring-on-rim");
    ring["mechanism"]["gravity"] = json!([0, -9.81]);
    ring["input"][0]["end"] = json!("90 deg");
    ring["input"][1]["end"] = json!("60 mm");
    for input in ring["input"].as_array_mut().unwrap() {
        input["steps"] = json!(10);
    }
    let ring = kinetostatics(&app, &ring).await;
    for (what, result) in [("cam", cam), ("ring", ring)] {
        let residual = result["summary"]["virtual_power_residual"].as_f64();
        assert!(residual.is_some_and(|r| r <= 1e-10), "{what}: {:?} ({})", residual, result["summary"]);
    }
}
