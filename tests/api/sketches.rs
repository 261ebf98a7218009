//! Dimensions from any rough sketch (contract, part four: "Dimensions,
//! precisely"): five mechanisms stated by their dimensions, each sketched
//! with every point moved at random by up to 20 % of its shortest
//! dimension, many times. Each request is accepted, its assembled points
//! are the figure's own, placed by hand in closed form on the sketch's
//! branch (1e-9 of the figure's size), and every dimension holds on them
//! to 1e-12 of the size, as the contract says.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};
use std::collections::BTreeMap;

/// A figure: its points placed by hand, its request with those points as
/// the sketch, and its shortest dimension (m).
struct Figure {
    name: &'static str,
    exact: BTreeMap<&'static str, [f64; 2]>,
    request: Value,
    shortest: f64,
}

fn revolute(name: &str, a: &str, b: &str) -> Value {
    json!({"name": name, "type": "revolute", "bodies": [a, b], "at": name})
}

fn kinetostatics(mechanism: Value, input: Value) -> Value {
    json!({"mechanism": mechanism, "input": input, "outputs": ["driving"]})
}

fn crank_input(joint: &str) -> Value {
    json!({"joint": joint, "speed": 1, "start": 0, "end": 0.01, "steps": 1})
}

/// The slider-crank: O (0, 0), crank O-A 100 mm at 50°, rod A-B 350 mm, B on y = 0.
fn slider_crank() -> Figure {
    let a = [0.1 * 50f64.to_radians().cos(), 0.1 * 50f64.to_radians().sin()];
    let b = [a[0] + (0.35f64.powi(2) - a[1] * a[1]).sqrt(), 0.0];
    let mechanism = json!({
        "bodies": [{"name": "crank"}, {"name": "rod"}, {"name": "slider"}],
        "joints": [revolute("O", "ground", "crank"), revolute("A", "crank", "rod"), revolute("B", "rod", "slider"),
            {"name": "guide", "type": "prismatic", "bodies": ["ground", "slider"], "at": "B", "axis": [1, 0]}],
        "dimensions": [{"x": "O", "value": 0}, {"y": "O", "value": 0}, {"distance": ["O", "A"], "value": "100 mm"},
            {"angle": ["O", "A"], "value": "50°"}, {"distance": ["A", "B"], "value": "350 mm"}, {"y": "B", "value": 0}]
    });
    let exact = BTreeMap::from([("O", [0.0, 0.0]), ("A", a), ("B", b)]);
    Figure { name: "slider-crank", exact, request: kinetostatics(mechanism, crank_input("O")), shortest: 0.1 }
}

/// "Crank 0.1 m at 60°, coupler 0.3 m, rocker 0.25 m, frame 0.3 m", B
/// above the line A-O4: the intersection of the circles (A, 0.3) and (O4, 0.25).
fn four_bar() -> Figure {
    let a = [0.05, 3f64.sqrt() / 20.0];
    let b = circles(a, 0.3, [0.3, 0.0], 0.25, true);
    let mechanism = json!({
        "bodies": [{"name": "crank"}, {"name": "coupler"}, {"name": "rocker"}],
        "joints": [revolute("O2", "ground", "crank"), revolute("A", "crank", "coupler"),
            revolute("B", "coupler", "rocker"), revolute("O4", "rocker", "ground")],
        "dimensions": [{"distance": ["O2", "A"], "value": "100 mm"}, {"angle": ["O2", "A"], "value": "60 deg"},
            {"distance": ["A", "B"], "value": 0.3}, {"distance": ["O4", "B"], "value": "250 mm"},
            {"distance": ["O2", "O4"], "value": 0.3}, {"x": "O2", "value": 0}, {"y": "O2", "value": 0}, {"y": "O4", "value": 0}]
    });
    let exact = BTreeMap::from([("O2", [0.0, 0.0]), ("O4", [0.3, 0.0]), ("A", a), ("B", b)]);
    Figure { name: "four-bar", exact, request: kinetostatics(mechanism, crank_input("O2")), shortest: 0.1 }
}

/// Seed 002's scissor lift (bars DE and BC of 2L = 1 m crossed at their
/// midpoints F, DE at 30°, B on the floor driven by the piston, C and E
/// under the platform): D (0, 0), E = (cos 30°, sin 30°), F their
/// midpoint, B = (cos 30°, 0) and C = (0, sin 30°) (the seed's figure).
fn scissor_lift() -> Figure {
    let (c, s) = (30f64.to_radians().cos(), 0.5);
    let mechanism = json!({
        "bodies": [{"name": "DE"}, {"name": "BC"}, {"name": "platform"}, {"name": "block"}],
        "joints": [revolute("D", "ground", "DE"), revolute("F", "DE", "BC"), revolute("C", "BC", "platform"),
            {"name": "E", "type": "pin_slot", "bodies": ["platform", "DE"], "at": "E", "axis": [1, 0]},
            revolute("B", "block", "BC"),
            {"name": "piston", "type": "prismatic", "bodies": ["ground", "block"], "at": "B", "axis": [1, 0]}],
        "dimensions": [{"x": "D", "value": 0}, {"y": "D", "value": 0}, {"distance": ["D", "E"], "value": "1 m"},
            {"angle": ["D", "E"], "value": "30°"}, {"on": "F", "between": ["D", "E"], "ratio": 0.5},
            {"on": "F", "between": ["B", "C"], "ratio": 0.5}, {"y": "B", "value": 0}, {"distance": ["B", "C"], "value": 1}]
    });
    let exact =
        BTreeMap::from([("D", [0.0, 0.0]), ("E", [c, s]), ("F", [c / 2.0, s / 2.0]), ("B", [c, 0.0]), ("C", [0.0, s])]);
    let input = json!({"point": "C", "body": "platform", "direction": [0, -1], "speed": 0.3, "start": 0, "end": 0.01, "steps": 1});
    let mut request = kinetostatics(mechanism, input);
    request["actuators"] = json!(["piston"]);
    Figure { name: "scissor lift", exact, request, shortest: 0.5 }
}

/// A six-bar of seed 000's kind (P.53: a linkage driving a slider): the
/// four-bar above, and a rod from the coupler's point C (midway along A-B)
/// of 0.35 m to a slider D on the line y = −0.05 m, ahead of C.
fn six_bar() -> Figure {
    let mut f = four_bar();
    let (a, b) = (f.exact["A"], f.exact["B"]);
    let c = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
    let d = [c[0] + (0.35f64.powi(2) - (c[1] + 0.05).powi(2)).sqrt(), -0.05];
    let m = &mut f.request["mechanism"];
    m["bodies"].as_array_mut().unwrap().extend([json!({"name": "rod"}), json!({"name": "slider"})]);
    m["joints"].as_array_mut().unwrap().extend([
        revolute("C", "coupler", "rod"),
        revolute("D", "rod", "slider"),
        json!({"name": "guide", "type": "prismatic", "bodies": ["ground", "slider"], "at": "D", "axis": [1, 0]}),
    ]);
    m["dimensions"].as_array_mut().unwrap().extend([
        json!({"on": "C", "between": ["A", "B"], "ratio": 0.5}),
        json!({"distance": ["C", "D"], "value": "350 mm"}),
        json!({"y": "D", "value": "-50 mm"}),
    ]);
    f.exact.extend([("C", c), ("D", d)]);
    Figure { name: "six-bar", ..f }
}

/// IFToMM's N-four-bar (A02) with N = 4: pivots P0…P4 at (k, 0), bars of
/// 1 m up to T0…T4 at (k, 1), couplers of 1 m between the Tk; the first bar at 90°.
fn n_four_bar() -> Figure {
    const P: [&str; 5] = ["P0", "P1", "P2", "P3", "P4"];
    const T: [&str; 5] = ["T0", "T1", "T2", "T3", "T4"];
    let mut bodies = Vec::new();
    let mut joints = Vec::new();
    let mut dimensions = vec![json!({"angle": ["P0", "T0"], "value": "90°"})];
    let mut exact = BTreeMap::new();
    for k in 0..5 {
        let bar = format!("bar{k}");
        bodies.push(json!({"name": bar}));
        joints.push(revolute(P[k], "ground", &bar));
        dimensions.extend([
            json!({"x": P[k], "value": k as f64}),
            json!({"y": P[k], "value": 0}),
            json!({"distance": [P[k], T[k]], "value": 1}),
        ]);
        exact.extend([(P[k], [k as f64, 0.0]), (T[k], [k as f64, 1.0])]);
        if k > 0 {
            let coupler = format!("coupler{k}");
            bodies.push(json!({"name": coupler}));
            joints.push(json!({"name": format!("{}a", T[k - 1]), "type": "revolute", "bodies": [format!("bar{}", k - 1), coupler], "at": T[k - 1]}));
            joints
                .push(json!({"name": format!("{}b", T[k]), "type": "revolute", "bodies": [coupler, bar], "at": T[k]}));
            dimensions.push(json!({"distance": [T[k - 1], T[k]], "value": 1}));
        }
    }
    let mechanism = json!({"bodies": bodies, "joints": joints, "dimensions": dimensions});
    Figure { name: "N-four-bar", exact, request: kinetostatics(mechanism, crank_input("P0")), shortest: 1.0 }
}

/// The point on the `above` side of the line P→Q (left of it) where the
/// circles (P, r) and (Q, s) cross.
fn circles(p: [f64; 2], r: f64, q: [f64; 2], s: f64, above: bool) -> [f64; 2] {
    let d = (q[0] - p[0]).hypot(q[1] - p[1]);
    let along = (d * d + r * r - s * s) / (2.0 * d);
    let h = (r * r - along * along).sqrt() * if above { 1.0 } else { -1.0 };
    let u = [(q[0] - p[0]) / d, (q[1] - p[1]) / d];
    [p[0] + along * u[0] - h * u[1], p[1] + along * u[1] + h * u[0]]
}

/// xorshift64*: the sketches' random moves, the same on every run.
struct Random(u64);

impl Random {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Every dimension's misfit on `points` (m; an angle's as the offset across its line).
fn misfits(dimensions: &[Value], points: &Value) -> Vec<f64> {
    let at = |name: &Value| {
        [points[name.as_str().unwrap()][0].as_f64().unwrap(), points[name.as_str().unwrap()][1].as_f64().unwrap()]
    };
    let si = |v: &Value| match v {
        Value::Number(n) => n.as_f64().unwrap(),
        Value::String(s) if s.ends_with("mm") => s.trim_end_matches("mm").trim().parse::<f64>().unwrap() / 1e3,
        Value::String(s) if s.ends_with(" m") => s.trim_end_matches(" m").parse().unwrap(),
        Value::String(s) => s.trim_end_matches(['°', ' ', 'd', 'e', 'g']).parse::<f64>().unwrap().to_radians(),
        _ => panic!("{v}"),
    };
    let mut out = Vec::new();
    for d in dimensions {
        if let Some([p, q]) = d["distance"].as_array().map(|l| [at(&l[0]), at(&l[1])]) {
            out.push(((q[0] - p[0]).hypot(q[1] - p[1]) - si(&d["value"])).abs());
        } else if let Some([p, q]) = d["angle"].as_array().map(|l| [at(&l[0]), at(&l[1])]) {
            let v = si(&d["value"]);
            out.push((-v.sin() * (q[0] - p[0]) + v.cos() * (q[1] - p[1])).abs());
        } else if d["x"].is_string() {
            out.push((at(&d["x"])[0] - si(&d["value"])).abs());
        } else if d["y"].is_string() {
            out.push((at(&d["y"])[1] - si(&d["value"])).abs());
        } else {
            let (m, l) = (at(&d["on"]), d["between"].as_array().unwrap());
            let (a, b, r) = (at(&l[0]), at(&l[1]), d["ratio"].as_f64().unwrap());
            out.extend((0..2).map(|k| (m[k] - a[k] - r * (b[k] - a[k])).abs()));
        }
    }
    out
}

/// The property: 40 sketches of each figure, every point moved by up to
/// 20 % of the shortest dimension; the figure as drawn by hand is the
/// exact sketch's answer too.
#[tokio::test]
async fn consistent_dimensions_are_met_from_any_rough_sketch_on_its_branch() {
    let app = TestApp::new().await;
    let mut random = Random(0x9E37_79B9_7F4A_7C15);
    for figure in [slider_crank(), four_bar(), scissor_lift(), six_bar(), n_four_bar()] {
        let size = figure.exact.values().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        for trial in 0..41 {
            let reach = if trial == 0 { 0.0 } else { 0.2 * figure.shortest };
            let sketch: BTreeMap<&str, [f64; 2]> = figure
                .exact
                .iter()
                .map(|(n, p)| {
                    let (r, turn) = (reach * random.unit(), std::f64::consts::TAU * random.unit());
                    (*n, [p[0] + r * turn.cos(), p[1] + r * turn.sin()])
                })
                .collect();
            let mut request = figure.request.clone();
            request["mechanism"]["points"] = json!(sketch);
            let r = app.post("/v1/kinetostatics", &request).await;
            let name = figure.name;
            assert_eq!(r.status, StatusCode::CREATED, "{name}, sketch {trial} {sketch:?}: {}", r.text);
            let points = r.json()["result"]["assembled_points"].clone();
            for (n, p) in &figure.exact {
                for k in 0..2 {
                    let got = points[n][k].as_f64().unwrap();
                    assert!(
                        (got - p[k]).abs() <= 1e-9 * size,
                        "{name}, sketch {trial}: {n}[{k}] {got} against {}",
                        p[k]
                    );
                }
            }
            let dimensions = request["mechanism"]["dimensions"].as_array().unwrap();
            let worst = misfits(dimensions, &points).into_iter().fold(0.0, f64::max);
            assert!(worst <= 1e-12 * size, "{name}, sketch {trial}: a dimension is off by {worst} m");
        }
    }
}

/// A body's `cg` given as coordinates rides with its body (contract, part
/// four): the slider-crank above with masses, each centre of mass sketched
/// at the middle of its body's sketched points, answers the driving torque
/// of the figure drawn by hand with the centres at the true middles
/// (1e-9 relative); a contradiction (the rod shorter than the crank's
/// height above the guide) says its misfit in the statement's millimetres.
#[tokio::test]
async fn a_centre_of_mass_given_as_coordinates_moves_with_its_body() {
    let app = TestApp::new().await;
    let figure = slider_crank();
    let mid = |p: [f64; 2], q: [f64; 2]| json!([(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0]);
    let with_masses = |points: &BTreeMap<&str, [f64; 2]>| {
        let mut r = figure.request.clone();
        r["mechanism"]["points"] = json!(points);
        r["mechanism"]["bodies"] = json!([
            {"name": "crank", "mass": 2, "inertia": 0.002, "cg": mid(points["O"], points["A"])},
            {"name": "rod", "mass": 3, "inertia": 0.03, "cg": mid(points["A"], points["B"])},
            {"name": "slider", "mass": 1.5, "cg": points["B"]}
        ]);
        r["mechanism"]["gravity"] = json!([0, -9.81]);
        r["input"] = json!({"joint": "O", "speed": "300 rpm", "start": 0, "end": 0.01, "steps": 1});
        r
    };
    let sketch = BTreeMap::from([("O", [0.0, 0.0]), ("A", [0.06, 0.08]), ("B", [0.41, 0.0])]);
    let r = app.post("/v1/kinetostatics", &with_masses(&sketch)).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let mut drawn = with_masses(&figure.exact);
    drawn["mechanism"].as_object_mut().unwrap().remove("dimensions");
    let by_hand = app.post("/v1/kinetostatics", &drawn).await;
    assert_eq!(by_hand.status, StatusCode::CREATED, "{}", by_hand.text);
    let expected = by_hand.json()["result"]["steps"][0]["driving"].as_f64().unwrap();
    crate::helpers::close(&r.json()["result"]["steps"][0]["driving"], expected, 1e-9, "the driving torque");
    let mut short = with_masses(&sketch);
    short["mechanism"]["dimensions"][4]["value"] = json!("70 mm");
    let r = app.post("/v1/kinetostatics", &short).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert!(r.text.contains(" mm at the least change"), "the misfit in the statement's unit: {}", r.text);
}

/// Only points that cannot move weigh more (contract, part four): the
/// slider-crank without its rod's length, its slider's pin B placed instead
/// by a mark M on the frame (a point of no moving body, sketched at (0.5,
/// 0.05)) 100 mm from it. M stays where it is drawn (to 1e-7 m: the share
/// of the change its 10⁶ weight leaves it) and B, a pin on a guide, moves
/// like any other point, 33 mm: to M − (√(0.1² − M_y²), M_y) (closed form, 1e-12 m).
#[tokio::test]
async fn a_slider_pin_moves_like_any_other_point_and_a_frame_mark_stays() {
    let app = TestApp::new().await;
    let mut request = slider_crank().request;
    let dimensions = request["mechanism"]["dimensions"].as_array_mut().unwrap();
    dimensions[4] = json!({"distance": ["M", "B"], "value": "100 mm"});
    request["mechanism"]["points"] = json!({"O": [0, 0], "A": [0.06, 0.08], "B": [0.38, 0.0], "M": [0.5, 0.05]});
    let r = app.post("/v1/kinetostatics", &request).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let points = r.json()["result"]["assembled_points"].clone();
    let got = |n: &str, k: usize| points[n][k].as_f64().unwrap();
    assert!((got("M", 0) - 0.5).abs() < 1e-7 && (got("M", 1) - 0.05).abs() < 1e-7, "M moved: {points}");
    let b = got("M", 0) - (0.01 - got("M", 1).powi(2)).sqrt();
    assert!((got("B", 0) - b).abs() < 1e-12 && got("B", 1).abs() < 1e-12, "B {points} against ({b}, 0)");
}

/// A student's slips on the scissor lift, each answered so it can be put
/// right: a bare 30 for the angle (read in radians, 278.9° on the sketch's
/// other side) is refused with the reason beside it — the number read in
/// radians and "30°" the way to write degrees; `"ratio": "0,5"` (a decimal
/// comma in a text where a number is asked) is read as 0.5; a point's
/// coordinates with decimal commas ([0,45, 0,6], four numbers to JSON) are
/// said in Spanish with the comma named; an input of one position needs no
/// `end`; the answer is the same as the figure's without the slips.
#[tokio::test]
async fn a_students_slips_are_answered_so_they_can_be_put_right() {
    let app = TestApp::new().await;
    let mut figure = scissor_lift();
    figure.request["mechanism"]["points"] = json!(figure.exact);
    let mut bare = figure.request.clone();
    bare["mechanism"]["dimensions"][3]["value"] = json!(30);
    let r = app.post("/v1/kinetostatics?lang=es", &bare).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let beside = r.json()["errors"].as_array().unwrap().iter().any(|e| {
        e["pointer"] == "/mechanism/dimensions/3/value"
            && e["message"] == "el número sin unidad 30 se lee en radianes (1719°); para grados escriba \"30°\""
    });
    assert!(beside, "{}", r.text);

    let mut slips = figure.request.clone();
    slips["mechanism"]["dimensions"][4]["ratio"] = json!("0,5");
    slips["input"].as_object_mut().unwrap().remove("end");
    let r = app.post("/v1/kinetostatics", &slips).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let clean = app.post("/v1/kinetostatics", &figure.request).await.json();
    assert_eq!(r.json()["result"]["steps"][0]["driving"], clean["result"]["steps"][0]["driving"]);

    let mut commas = figure.request.clone();
    commas["mechanism"]["points"] =
        json!({"D": [0, 0], "E": [0.87, 0.5], "F": [0,45, 0,25], "B": [0.87, 0], "C": [0, 0.5]});
    let r = app.post("/v1/kinetostatics?lang=es", &commas).await;
    let message = r.json()["errors"][0]["message"].as_str().unwrap_or_default().to_string();
    assert!(message.contains("menos elementos") && message.contains("coma decimal"), "{}", r.text);
    let raw = figure.request.to_string().replace("\"ratio\":0.5", "\"ratio\":0,5");
    assert!(raw.contains("\"ratio\":0,5"), "{raw}");
    let r = app.post_raw("/v1/kinetostatics?lang=es", "application/json", raw).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST, "{}", r.text);
    assert!(r.json()["detail"].as_str().unwrap().contains("una coma decimal parte un número de JSON"), "{}", r.text);
}

/// A sketch drawn in millimetres as bare numbers (read in metres) beside
/// dimensions in mm: the figure is met as always, and a warning says the
/// sketch is about 1000 times the dimensions' size, how bare numbers are
/// read, and what that does to a centre of mass sketched so (a trial's
/// came out 10 m from its body, with reactions of 78 MN and no word of
/// why). Dimensions in metres where millimetres were meant are said the
/// other way; a sketch a few times off its dimensions is not remarked on.
#[tokio::test]
async fn a_sketch_a_thousand_times_its_dimensions_is_said_to_be() {
    let app = TestApp::new().await;
    let figure = slider_crank();
    let warnings = |scale: f64, [crank, rod]: [&str; 2]| {
        let mut r = figure.request.clone();
        let sketch: BTreeMap<&str, [f64; 2]> =
            figure.exact.iter().map(|(n, p)| (*n, [p[0] * scale, p[1] * scale])).collect();
        r["mechanism"]["points"] = json!(sketch);
        r["mechanism"]["dimensions"][2]["value"] = json!(crank);
        r["mechanism"]["dimensions"][4]["value"] = json!(rod);
        let app = &app;
        async move {
            let r = app.post("/v1/kinetostatics", &r).await;
            assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
            r.json()["result"]["warnings"].to_string()
        }
    };
    let millimetres = warnings(1000.0, ["100 mm", "350 mm"]).await;
    assert!(millimetres.contains("about 1000 times as far apart as the dimensions place them"), "{millimetres}");
    assert!(millimetres.contains("for millimetres write \\\"40 mm\\\""), "{millimetres}");
    assert!(
        !warnings(3.0, ["100 mm", "350 mm"]).await.contains("times as far apart"),
        "a rough sketch 3 times too large"
    );
    // Every length in m where mm were meant: the sketch is the smaller.
    let metres = warnings(1.0, ["100 m", "350 m"]).await;
    assert!(metres.contains("times closer together than the dimensions place them"), "{metres}");
}
