//! A higher pair against its closed form: the eccentric circular cam under
//! a flat-faced follower (`samples::eccentric_cam`: disk R = 0.05 m, its
//! centre e = 0.02 m from the pivot O, the follower 2 kg on a vertical
//! guide, gravity 9.81 m/s²) is a Scotch yoke: the lift is e(1 − cos θ),
//! the contact lies e·sin θ along the face, and at constant ω the normal
//! force is N = m(g + eω² cos θ), the driving torque N·e·sin θ (the cam's
//! centre of mass on its pivot does not load it), the contact's reaction on
//! the follower (0, N) with no couple about the contact point.

use mechdyn::engine::Deadline;
use mechdyn::engine::kinetostatics::{Outputs, contact_state, solve};
use mechdyn::engine::samples::eccentric_cam;

#[test]
fn an_eccentric_cam_under_a_flat_follower_is_a_scotch_yoke() {
    let (e, m, g, w) = (0.02, 2.0, 9.81, 10.0);
    let mechanism = eccentric_cam();
    let angles: Vec<f64> = (0..12).map(|k| 0.1 + 0.5 * f64::from(k)).collect();
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, w, 0.0]]).collect();
    let outputs = Outputs { driving: true, reactions: true, reduced: true, kinematics: true, condition: false };
    let solution = solve(&mechanism, &[], &positions, outputs, &Deadline::none()).unwrap();
    assert_eq!(solution.totals.mobility.dof, 1);
    for (theta, step) in angles.iter().zip(&solution.steps) {
        let k = step.kinematics.as_ref().unwrap();
        let (s, c) = theta.sin_cos();
        let n = m * (g + e * w * w * c);
        let close = |got: f64, want: f64, scale: f64, what: &str| {
            assert!((got - want).abs() < 1e-9 * scale, "θ = {theta}: {what} {got} vs {want}");
        };
        close(k.q[4] - 0.1, e * (1.0 - c), e, "lift");
        close(k.qd[4], e * w * s, e * w, "follower speed");
        close(k.qdd[4], e * w * w * c, e * w * w, "follower acceleration");
        close(k.q[7], e * s, e, "the contact along the face");
        close(step.driving[0], n * e * s, m * g * e, "driving torque");
        close(step.driving_virtual_power[0], n * e * s, m * g * e, "driving torque by virtual power");
        let contact = &step.reactions[2];
        close(contact.fx, 0.0, m * g, "tangential reaction");
        close(contact.fy, n, m * g, "normal reaction");
        close(contact.moment, 0.0, m * g * e, "couple about the contact point");
    }
}

/// With friction μ = 0.1 at the contact (the guide and the pin without):
/// the follower slides on the cam at ω(R − e cos θ) along the face, so the
/// friction μN acts on it against that (−x), on the cam at the contact
/// (R − e cos θ above O): the torque is N(e sin θ + μ(R − e cos θ)), the
/// normal force unchanged (the guide takes the friction), 1e-9. The
/// contact's state says the same: at (e sin θ, R − e cos θ), normal N,
/// tangential −μN, sliding ω(R − e cos θ), radii [R, straight], pressure
/// angle 0 (a flat-faced follower).
#[test]
fn contact_friction_adds_mu_n_at_the_contact_to_the_torque() {
    let (r, e, m, g, w, mu) = (0.05, 0.02, 2.0, 9.81, 10.0, 0.1);
    let mut mechanism = eccentric_cam();
    mechanism.joints[2].friction = Some(mechdyn::engine::model::Friction { mu, radius: 0.0 });
    let angles: Vec<f64> = (0..12).map(|k| 0.1 + 0.5 * f64::from(k)).collect();
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, w, 0.0]]).collect();
    let outputs = Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false };
    let solution = solve(&mechanism, &[], &positions, outputs, &Deadline::none()).unwrap();
    for (theta, step) in angles.iter().zip(&solution.steps) {
        let (s, c) = theta.sin_cos();
        let n = m * (g + e * w * w * c);
        let torque = n * (e * s + mu * (r - e * c));
        let k = step.kinematics.as_ref().unwrap();
        let state = contact_state(&mechanism, (&k.q, &k.qd), None, &step.reactions[2]).unwrap();
        // The bodies' (sin θ, cos θ) given (as a sweep has them) or found: the same state, bit for bit.
        let mut trig = Vec::new();
        mechanism.turns_into(&k.q, &mut trig);
        assert_eq!(contact_state(&mechanism, (&k.q, &k.qd), Some(&trig), &step.reactions[2]), Some(state));
        let near = |a: f64, b: f64, scale: f64| (a - b).abs() < 1e-9 * scale;
        assert!(near(state.point[0], e * s, e) && near(state.point[1], r - e * c, e), "{state:?}");
        assert!(near(state.normal, n, m * g) && near(state.tangential, -mu * n, m * g), "{state:?}");
        assert!(near(state.sliding_velocity, w * (r - e * c), w * r), "{state:?}");
        assert!(near(state.curvature_radius[0].unwrap(), r, r) && state.curvature_radius[1].is_none(), "{state:?}");
        assert!(state.pressure_angle.unwrap() < 1e-9, "a flat follower's pressure angle is 0: {state:?}");
        assert!((step.driving[0] - torque).abs() < 1e-9 * m * g * r, "θ = {theta}: {} vs {torque}", step.driving[0]);
        let contact = &step.reactions[2];
        assert!((contact.fx + mu * n).abs() < 1e-9 * m * g && (contact.fy - n).abs() < 1e-9 * m * g, "{contact:?}");
    }
}

/// The same cam left free: the follower's weight turns it from 0.5 rad at
/// rest, through the contact alone. Only gravity works, so every sample's
/// T + V is the first's (1e-8 of m g e: tolerance 1e-10, the energy not
/// held by projection), while T grows past a tenth of that scale; the
/// follower stays on the cam (its lift is e(1 − cos θ) of the cam's angle).
#[test]
fn a_free_cam_turned_by_its_follower_keeps_its_energy() {
    use mechdyn::engine::dynamics::mechanism::{MechanismProblem, solve as integrate};
    use mechdyn::engine::dynamics::{End, KEPT_BYTES};
    let (e, m, g) = (0.02, 2.0, 9.81);
    let problem = MechanismProblem {
        mechanism: eccentric_cam(),
        loads: Vec::new(),
        period: std::f64::consts::TAU,
        initial: vec![[0.5, 0.0]],
        end: End::Duration(0.5),
        tolerance: 1e-10,
        integrator: None,
        conserve_energy: Some(false),
        samples: 11,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
        reactions: true,
        motion: true,
    };
    let run = integrate(&problem).unwrap();
    let energy = |k: usize| {
        let d = &run.details[k].energy;
        d.kinetic + d.gravity + d.springs
    };
    let scale = m * g * e;
    let mut moved = 0.0f64;
    for k in 0..run.details.len() {
        assert!((energy(k) - energy(0)).abs() < 1e-8 * scale, "sample {k}: {} vs {}", energy(k), energy(0));
        moved = moved.max(run.details[k].energy.kinetic);
        let q = &run.details[k].motion.as_ref().unwrap().q;
        assert!((q[4] - 0.1 - e * (1.0 - q[2].cos())).abs() < 1e-9 * e, "sample {k}: off the cam");
    }
    assert!(moved > 0.1 * scale, "it turns: T reached {moved} J");
}

/// A coin rolling round an equal fixed coin (radius R = 0.05 m), kept on
/// it by the rolling contact alone, driven by its own rotation θ: it turns
/// twice per orbit, so its centre is at 2R(cos θ/2, sin θ/2) with velocity
/// Rθ̇(−sin θ/2, cos θ/2) (1e-9 of R; the classic coin paradox).
#[test]
fn a_coin_rolling_round_an_equal_coin_turns_twice_per_orbit() {
    use mechdyn::engine::curves::Curve;
    use mechdyn::engine::model::{Body, Contact, Coordinate, Driver, Joint, JointKind, Mechanism};
    let r = 0.05;
    let curves = [
        Curve::Circle { centre: [0.0, 0.0], radius: r, inside: false },
        Curve::Circle { centre: [2.0 * r, 0.0], radius: r, inside: false },
    ];
    let coin = Joint {
        name: "rim".into(),
        kind: JointKind::Contact(Box::new(Contact::new(curves, true, [r, 0.0]))),
        bodies: [0, 1],
        at: [r, 0.0],
        friction: None,
        length: None,
    };
    let body = |name: &str, mass: f64, cg: [f64; 2]| Body { name: name.into(), mass, inertia: 0.5 * mass * r * r, cg };
    let m = Mechanism {
        bodies: vec![body("ground", 0.0, [0.0, 0.0]), body("coin", 0.01, [2.0 * r, 0.0])],
        joints: vec![coin],
        drivers: vec![Driver { coordinate: Coordinate::Body(1), reference: 0.0, actuator: None }],
        gravity: [0.0, 0.0],
    };
    let w = 3.0;
    let positions: Vec<Vec<[f64; 3]>> = (0..12).map(|k| vec![[0.25 * f64::from(k), w, 0.0]]).collect();
    let outputs = Outputs { driving: true, reactions: false, reduced: false, kinematics: true, condition: false };
    let solution = solve(&m, &[], &positions, outputs, &Deadline::none()).unwrap();
    assert_eq!(solution.totals.mobility.dof, 1);
    for (p, step) in positions.iter().zip(&solution.steps) {
        let (theta, k) = (p[0][0], step.kinematics.as_ref().unwrap());
        let (s, c) = (theta / 2.0).sin_cos();
        let want = [2.0 * r * c, 2.0 * r * s, -r * w * s, r * w * c];
        let got = [k.q[0], k.q[1], k.qd[0], k.qd[1]];
        for (g, e) in got.iter().zip(want) {
            assert!((g - e).abs() < 1e-9 * r * w, "θ = {theta}: {got:?} vs {want:?}");
        }
    }
}

/// A disk (m = 2 kg, R = 0.1 m, I = ½mR²) rolling from rest down a 30°
/// incline, free: a = ⅔ g sin α along it, so after t it has gone ½at² and
/// turned −½at²/R, and the friction that makes it roll is ⅓ m g sin α up
/// the slope, the normal force m g cos α (1e-7 of the scales: tolerance 1e-10).
#[test]
fn a_disk_rolls_down_an_incline_at_two_thirds_g_sin_alpha() {
    use mechdyn::engine::curves::Curve;
    use mechdyn::engine::dynamics::mechanism::{MechanismProblem, solve as integrate};
    use mechdyn::engine::dynamics::{End, KEPT_BYTES};
    use mechdyn::engine::model::{Body, Contact, Coordinate, Driver, Joint, JointKind, Mechanism};
    let (m, r, g, alpha) = (2.0, 0.1, 9.81, 30f64.to_radians());
    let (sa, ca) = alpha.sin_cos();
    let (d, n) = ([ca, -sa], [sa, ca]);
    let centre = [r * n[0], r * n[1]];
    let curves = [Curve::Line { at: [0.0, 0.0], direction: d }, Curve::Circle { centre, radius: r, inside: false }];
    let contact = Joint {
        name: "slope".into(),
        kind: JointKind::Contact(Box::new(Contact::new(curves, true, [0.0, 0.0]))),
        bodies: [0, 1],
        at: [0.0, 0.0],
        friction: None,
        length: None,
    };
    let mechanism = Mechanism {
        bodies: vec![
            Body { name: "ground".into(), mass: 0.0, inertia: 0.0, cg: [0.0, 0.0] },
            Body { name: "disk".into(), mass: m, inertia: 0.5 * m * r * r, cg: centre },
        ],
        joints: vec![contact],
        drivers: vec![Driver { coordinate: Coordinate::Body(1), reference: 0.0, actuator: None }],
        gravity: [0.0, -g],
    };
    let problem = MechanismProblem {
        mechanism,
        loads: Vec::new(),
        period: std::f64::consts::TAU,
        initial: vec![[0.0, 0.0]],
        end: End::Duration(1.0),
        tolerance: 1e-10,
        integrator: None,
        conserve_energy: Some(false),
        samples: 5,
        kept_bytes: KEPT_BYTES,
        deadline: Deadline::none(),
        reactions: true,
        motion: true,
    };
    let run = integrate(&problem).unwrap();
    let a = 2.0 / 3.0 * g * sa;
    for (sample, detail) in run.solution.samples.iter().zip(&run.details) {
        let t = sample.t;
        let q = &detail.motion.as_ref().unwrap().q;
        let along = (q[0] - centre[0]) * d[0] + (q[1] - centre[1]) * d[1];
        assert!((along - 0.5 * a * t * t).abs() < 1e-7 * a, "t = {t}: {along} vs {}", 0.5 * a * t * t);
        assert!(
            (detail.inputs[0][0] + 0.5 * a * t * t / r).abs() < 1e-7 * a / r,
            "t = {t}: turned {}",
            detail.inputs[0][0]
        );
        let f = &detail.reactions[0];
        let (tangential, normal) = (f.fx * d[0] + f.fy * d[1], f.fx * n[0] + f.fy * n[1]);
        assert!((tangential + m * g * sa / 3.0).abs() < 1e-7 * m * g, "t = {t}: friction {tangential}");
        assert!((normal - m * g * ca).abs() < 1e-7 * m * g, "t = {t}: normal {normal}");
        let motion = detail.motion.as_ref().unwrap();
        let state = contact_state(&problem.mechanism, (&motion.q, &motion.qd), None, f).unwrap();
        assert!((state.normal - m * g * ca).abs() < 1e-7 * m * g, "pressing: {state:?}");
        assert!((state.tangential + m * g * sa / 3.0).abs() < 1e-7 * m * g, "{state:?}");
        assert!(state.sliding_velocity.abs() < 1e-7 * a, "rolling, not sliding: {state:?}");
    }
}

/// The eccentric cam under a radial roller follower (roller ρ = 0.015 m):
/// the contact normal is the line of centres, so the pressure angle is
/// asin(e sin θ/(R + ρ)) — the disk's centre e sin θ off the follower's
/// line, R + ρ from the roller's centre (1e-9).
#[test]
fn a_roller_follower_s_pressure_angle_is_that_of_the_line_of_centres() {
    use mechdyn::engine::curves::Curve;
    use mechdyn::engine::model::{Contact, JointKind};
    let (r, e, rho, w) = (0.05, 0.02, 0.015, 10.0);
    let mut mechanism = eccentric_cam();
    let curves = [
        Curve::Circle { centre: [0.0, -e], radius: r, inside: false },
        Curve::Circle { centre: [0.0, r - e + rho], radius: rho, inside: false },
    ];
    mechanism.joints[2].kind = JointKind::Contact(Box::new(Contact::new(curves, false, [0.0, r - e])));
    let angles: Vec<f64> = (0..12).map(|k| 0.1 + 0.5 * f64::from(k)).collect();
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, w, 0.0]]).collect();
    let outputs = Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false };
    let solution = solve(&mechanism, &[], &positions, outputs, &Deadline::none()).unwrap();
    for (theta, step) in angles.iter().zip(&solution.steps) {
        let k = step.kinematics.as_ref().unwrap();
        let state = contact_state(&mechanism, (&k.q, &k.qd), None, &step.reactions[2]).unwrap();
        let want = (e * theta.sin() / (r + rho)).asin().abs();
        let got = state.pressure_angle.unwrap();
        assert!((got - want).abs() < 1e-9, "θ = {theta}: {got} vs {want}");
        assert!(state.normal > 0.0, "the follower presses on the cam: {state:?}");
    }
}

/// A cam designed from its program (dwell 90°, cycloidal rise of 10 mm over
/// 90°, dwell, cycloidal return; base radius 40 mm) under the flat-faced
/// follower it was designed for: turned by φ, the cam lifts the follower by
/// s(φ) exactly, and its radius of curvature at the contact is
/// R_b + s + s″ (the flat follower's closed form), the pressure angle 0
/// (1e-9 of the lift).
#[test]
fn a_cam_made_from_its_program_lifts_its_flat_follower_by_the_program() {
    use mechdyn::engine::cam::{Law, Program, Segment};
    use mechdyn::engine::curves::{Curve, Face};
    use mechdyn::engine::model::{Contact, JointKind};
    use std::f64::consts::FRAC_PI_2 as Q;
    let (base, h) = (0.04, 0.01);
    let seg = |law, start: f64, from, to| Segment { law, start, span: Q, from, to };
    let program = Program::new(vec![
        seg(Law::Dwell, 0.0, 0.0, 0.0),
        seg(Law::Cycloidal, Q, 0.0, h),
        seg(Law::Dwell, 2.0 * Q, h, h),
        seg(Law::Cycloidal, 3.0 * Q, h, 0.0),
    ])
    .unwrap();
    let mut mechanism = eccentric_cam();
    let cam = Curve::Cam { centre: [0.0, 0.0], zero: Q, base, face: Face::Flat, program: Box::new(program.clone()) };
    let face = Curve::Line { at: [0.0, base], direction: [1.0, 0.0] };
    mechanism.joints[2].kind = JointKind::Contact(Box::new(Contact::new([cam, face], false, [0.0, base])));
    let angles: Vec<f64> = (0..72).map(|k| 0.087 * f64::from(k)).collect();
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, 10.0, 0.0]]).collect();
    let outputs = Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false };
    let solution = solve(&mechanism, &[], &positions, outputs, &Deadline::none()).unwrap();
    for (phi, step) in angles.iter().zip(&solution.steps) {
        let [s, _, s2, ..] = program.eval(*phi);
        let k = step.kinematics.as_ref().unwrap();
        assert!((k.q[4] - 0.1 - s).abs() < 1e-9 * h, "φ = {phi}: lift {} vs {s}", k.q[4] - 0.1);
        let state = contact_state(&mechanism, (&k.q, &k.qd), None, &step.reactions[2]).unwrap();
        let rho = state.curvature_radius[0].unwrap();
        assert!((rho - (base + s + s2)).abs() < 1e-9 * base, "φ = {phi}: ρ {rho} vs {}", base + s + s2);
    }
}

/// A roller sitting in the waist of a peanut-shaped cam r(ψ) = 50 + 20
/// cos 2ψ mm, whose hollow there has a radius of curvature of 18 mm
/// (ρ = r³/(r² − r r″) with r = 30 mm, r″ = 80 mm: the polar formula): a
/// roller of 15 mm fits it, one of 25 mm overlaps the cam on both sides of
/// the contact — it would rest on the two shoulders instead — and the
/// contact's state says so; a flat face there overlaps too.
#[test]
fn a_roller_larger_than_the_hollow_it_sits_in_overlaps_the_cam() {
    use mechdyn::engine::curves::Curve;
    use mechdyn::engine::expr::Expr;
    use mechdyn::engine::function::Function;
    use mechdyn::engine::kinetostatics::Reaction;
    use mechdyn::engine::model::{Body, Contact, Joint, JointKind, Mechanism};
    let (r, r2) = (0.03f64, 0.08);
    let hollow = r.powi(3) / (r * r - r * r2);
    assert!((hollow + 0.018).abs() < 1e-15, "ρ = {hollow}");
    let peanut =
        || Curve::polar([0.0, 0.0], 0.0, Function::Expr(Expr::compile("0.05 + 0.02*cos(2*psi)", &["psi"]).unwrap()));
    for (radius, overlaps) in [(Some(0.015), false), (Some(0.025), true), (None, true)] {
        let follower = match radius {
            Some(rr) => Curve::Circle { centre: [0.0, r + rr], radius: rr, inside: false },
            None => Curve::Line { at: [0.0, r], direction: [1.0, 0.0] },
        };
        let contact = Contact::new([peanut(), follower], false, [0.0, r]);
        let joint = Joint {
            name: "K".into(),
            kind: JointKind::Contact(Box::new(contact)),
            bodies: [0, 1],
            at: [0.0, r],
            friction: None,
            length: None,
        };
        let body = |name: &str, cg: [f64; 2]| Body { name: name.into(), mass: 1.0, inertia: 1e-3, cg };
        let m = Mechanism {
            bodies: vec![body("ground", [0.0, 0.0]), body("follower", [0.0, 0.06])],
            joints: vec![joint],
            drivers: Vec::new(),
            gravity: [0.0, 0.0],
        };
        let q = m.reference_q();
        let qd = vec![0.0; q.len()];
        let reaction =
            Reaction { joint: 0, on: 1, by: 0, fx: 0.0, fy: 1.0, moment: 0.0, ends: None, determinate: true };
        let state = contact_state(&m, (&q, &qd), None, &reaction).unwrap();
        assert_eq!(state.overlap, overlaps, "{radius:?}: {state:?}");
    }
}

/// A fine sweep of the eccentric cam (no dyads: Newton places it) starts
/// each position within Newton's tolerance once two positions are behind
/// it (the predictor's third-order term, `kinematics/sweep.rs`): no
/// Newton step after the second, where a quadratic predictor needs one at
/// every position (its error e·Δφ³/6 ≈ 2e-11 m at Δφ = 0.1°). The lift
/// stays the closed form e(1 − cos φ) within Newton's tolerance (1e-13 of
/// the coordinates' size; 2.3e-14 m measured).
#[test]
fn a_fine_cam_sweep_is_predicted_within_newtons_tolerance() {
    let (e, mechanism) = (0.02, eccentric_cam());
    let angles: Vec<f64> = (0..=3600).map(|k| 0.1 + std::f64::consts::TAU * f64::from(k) / 3600.0).collect();
    let positions: Vec<Vec<[f64; 3]>> = angles.iter().map(|&a| vec![[a, 10.0, 0.0]]).collect();
    let configurations = mechdyn::engine::kinematics::sweep(
        &mechanism,
        &positions,
        &Deadline::none(),
        mechdyn::engine::kinematics::Conditions::Estimated,
    )
    .unwrap();
    let newton: Vec<usize> =
        (configurations.iter().enumerate()).filter(|(_, c)| c.iterations > 0).map(|(k, _)| k).collect();
    assert!(newton.iter().all(|&k| k < 2), "positions that took a Newton step: {newton:?}");
    let off = configurations.iter().zip(&angles).map(|(c, phi)| (c.q[4] - 0.1 - e * (1.0 - phi.cos())).abs());
    let off = off.fold(0.0, f64::max);
    assert!(off < 1e-13, "the lift is off the closed form by {off:e} m");
}
