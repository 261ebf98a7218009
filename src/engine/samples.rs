//! Canonical mechanisms shared by tests, docs and examples.

use super::curves::Curve;
use super::model::{Body, Contact, Driver, Joint, JointKind, Mechanism};

fn body(name: &str, mass: f64, inertia: f64, cg: [f64; 2]) -> Body {
    Body { name: name.into(), mass, inertia, cg }
}

fn joint(name: &str, kind: JointKind, bodies: [usize; 2], at: [f64; 2]) -> Joint {
    Joint { name: name.into(), kind, bodies, at, friction: None, length: None }
}

/// The offset slider-crank of reference case K1, drawn at φ = 0: crank
/// OA = 0.08 m (2 kg, 0.004 kg·m², G 0.02 m from O), rod AB = 0.3 m (1.2 kg,
/// 0.012 kg·m², G 0.09 m from A), piston 0.9 kg (0.001 kg·m², G at B) on the
/// line y = e = 0.02 m; gravity −9.81 m/s² along y; the crank is driven.
pub fn offset_slider_crank() -> Mechanism {
    let (r, l, e): (f64, f64, f64) = (0.08, 0.3, 0.02);
    let a = [r, 0.0];
    let b = [r + (l * l - e * e).sqrt(), e];
    let along = |t: f64| [a[0] + t / l * (b[0] - a[0]), a[1] + t / l * (b[1] - a[1])];
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("crank", 2.0, 0.004, [0.02, 0.0]),
            body("rod", 1.2, 0.012, along(0.09)),
            body("piston", 0.9, 0.001, b),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("A", JointKind::Revolute, [1, 2], a),
            joint("B", JointKind::Revolute, [2, 3], b),
            joint("guide", JointKind::Prismatic { axis: [1.0, 0.0] }, [0, 3], b),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// A scotch yoke: crank R = 0.1 m (2 kg at its pin, I_G = 0.05 kg·m²) drives
/// a 5 kg yoke on a horizontal guide through a pin in its vertical slot.
pub fn scotch_yoke() -> Mechanism {
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("crank", 2.0, 0.05, [0.1, 0.0]),
            body("yoke", 5.0, 0.3, [0.3, 0.0]),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("slide", JointKind::Prismatic { axis: [1.0, 0.0] }, [0, 2], [0.3, 0.0]),
            joint("pin", JointKind::PinSlot { axis: [0.0, 1.0] }, [2, 1], [0.1, 0.0]),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// A Grashof crank-rocker four-bar: ground O2 (0, 0)–O4 (0.4, 0), crank
/// 0.1 m, coupler 0.35 m, rocker 0.3 m, drawn with the crank along +x.
pub fn four_bar() -> Mechanism {
    let (a, o4) = ([0.1, 0.0], [0.4, 0.0]);
    // B: |B − A| = 0.35, |B − O4| = 0.3; A and O4 lie on the x axis, 0.3 apart.
    let bx = 0.1 + (0.35f64 * 0.35 - 0.3 * 0.3 + 0.3 * 0.3) / (2.0 * 0.3);
    let b = [bx, (0.35f64 * 0.35 - (bx - 0.1) * (bx - 0.1)).sqrt()];
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("crank", 0.5, 0.001, [0.05, 0.0]),
            body("coupler", 1.0, 0.01, [(a[0] + b[0]) / 2.0, b[1] / 2.0]),
            body("rocker", 0.8, 0.006, [(o4[0] + b[0]) / 2.0, b[1] / 2.0]),
        ],
        joints: vec![
            joint("O2", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("A", JointKind::Revolute, [1, 2], a),
            joint("B", JointKind::Revolute, [2, 3], b),
            joint("O4", JointKind::Revolute, [3, 0], o4),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// A Watt six-bar: the four-bar O2-A-B-O4 whose coupler is ternary (A, B,
/// D), and a second dyad D-F-O6 hung on it; points chosen freely (a joint's
/// one point is both bodies', so the drawing is assembled).
pub fn watt_six_bar() -> Mechanism {
    let (o2, a, b, o4, d, f, o6) =
        ([0.0, 0.0], [0.1, 0.02], [0.35, 0.25], [0.4, 0.0], [0.3, 0.4], [0.6, 0.45], [0.7, 0.1]);
    let revolute = |name: &str, bodies: [usize; 2], at: [f64; 2]| joint(name, JointKind::Revolute, bodies, at);
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("crank", 1.0, 0.01, [0.05, 0.01]),
            body("coupler", 1.0, 0.01, [0.25, 0.22]),
            body("rocker", 1.0, 0.01, [0.37, 0.12]),
            body("link", 1.0, 0.01, [0.45, 0.42]),
            body("rocker 2", 1.0, 0.01, [0.65, 0.27]),
        ],
        joints: vec![
            revolute("O2", [0, 1], o2),
            revolute("A", [1, 2], a),
            revolute("B", [2, 3], b),
            revolute("O4", [3, 0], o4),
            revolute("D", [2, 4], d),
            revolute("F", [4, 5], f),
            revolute("O6", [5, 0], o6),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// The differential train of reference case K5: sun (z = 60), planet (30),
/// internal ring (120) on a carrier, all about O; planet pin at 0.09 m.
/// Driven by the carrier and the ring.
pub fn planetary_train() -> Mechanism {
    let gear = |ratio: f64| JointKind::Gear { ratio, carrier: 2, pitch: None };
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("sun", 1.0, 0.002, [0.0, 0.0]),
            body("carrier", 1.5, 0.01, [0.0, 0.0]),
            body("planet", 0.3, 0.0002, [0.09, 0.0]),
            body("ring", 2.0, 0.03, [0.0, 0.0]),
        ],
        joints: vec![
            joint("sun bearing", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("carrier bearing", JointKind::Revolute, [0, 2], [0.0, 0.0]),
            joint("planet pin", JointKind::Revolute, [2, 3], [0.09, 0.0]),
            joint("ring bearing", JointKind::Revolute, [0, 4], [0.0, 0.0]),
            joint("sun-planet", gear(-2.0), [1, 3], [0.0, 0.0]),
            joint("planet-ring", gear(0.25), [3, 4], [0.0, 0.0]),
        ],
        drivers: vec![Driver::joint(1, 0.0), Driver::joint(3, 0.0)],
        gravity: [0.0, 0.0],
    }
}

/// A hydraulic cylinder (pivoted on the ground at C) lifting an arm pivoted at
/// O; the cylinder's rod slides in it (prismatic) and is pinned to the arm at
/// P. Driven by the prismatic joint (a linear actuator).
pub fn actuated_arm() -> Mechanism {
    let (o, c, p) = ([0.0, 0.0], [0.5, -0.3], [0.4, 0.0]);
    let axis = [(p[0] - c[0]) / 0.316_227_766_016_837_94, (p[1] - c[1]) / 0.316_227_766_016_837_94];
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("arm", 10.0, 0.6, [0.5, 0.0]),
            body("cylinder", 3.0, 0.02, [0.47, -0.21]),
            body("rod", 1.0, 0.005, [0.43, -0.09]),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], o),
            joint("C", JointKind::Revolute, [0, 2], c),
            joint("stroke", JointKind::Prismatic { axis }, [2, 3], p),
            joint("P", JointKind::Revolute, [3, 1], p),
        ],
        drivers: vec![Driver::joint(2, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// A centred slider-crank: crank r, rod l, piston of 3 kg on the x axis,
/// massless crank and rod, drawn at φ = 0.
pub fn slider_crank(r: f64, l: f64) -> Mechanism {
    let b = [r + l, 0.0];
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("crank", 0.0, 0.0, [0.0, 0.0]),
            body("rod", 0.0, 0.0, [r, 0.0]),
            body("piston", 3.0, 0.0, b),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("A", JointKind::Revolute, [1, 2], [r, 0.0]),
            joint("B", JointKind::Revolute, [2, 3], b),
            joint("guide", JointKind::Prismatic { axis: [1.0, 0.0] }, [0, 3], b),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, 0.0],
    }
}

/// The crank / slotted lever / slider six-bar of the course notes (P.77):
/// crank O1B = 0.1 m about O1 = (0.3, 0); block 3 at B slides along the lever
/// O2A (O2 at the origin, 0.5 m); block 5 at A slides in a horizontal slot of
/// body 6, which slides vertically.
pub fn slotted_lever() -> Mechanism {
    let (d, r, a) = (0.3, 0.1, 0.5);
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("crank", 1.0, 0.02, [d, 0.0]),
            body("block3", 0.5, 0.001, [d + r, 0.0]),
            body("lever", 2.0, 2.0 * a * a / 12.0, [a / 2.0, 0.0]),
            body("block5", 0.3, 0.0, [a, 0.0]),
            body("slider6", 4.0, 0.1, [a, 0.2]),
        ],
        joints: vec![
            joint("O1", JointKind::Revolute, [0, 1], [d, 0.0]),
            joint("B", JointKind::Revolute, [1, 2], [d + r, 0.0]),
            joint("slot4", JointKind::Prismatic { axis: [1.0, 0.0] }, [3, 2], [d + r, 0.0]),
            joint("O2", JointKind::Revolute, [0, 3], [0.0, 0.0]),
            joint("A", JointKind::Revolute, [3, 4], [a, 0.0]),
            joint("slot6", JointKind::Prismatic { axis: [1.0, 0.0] }, [5, 4], [a, 0.0]),
            joint("guide6", JointKind::Prismatic { axis: [0.0, 1.0] }, [0, 5], [a, 0.2]),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, 0.0],
    }
}

/// An eccentric circular cam under a flat-faced follower (a higher pair):
/// the cam pinned at O (0, 0), its disk of radius R = 0.05 m centred e =
/// 0.02 m below O as drawn (the follower at its lowest); the follower (2 kg)
/// slides vertically, its face the line y = R − e touching the disk's top.
/// The cam's rotation from the drawing is the input; the lift is e(1 − cos θ)
/// and the contact is e·sin θ along the face (a Scotch yoke's motion).
pub fn eccentric_cam() -> Mechanism {
    let (r, e) = (0.05, 0.02);
    let curves = [
        Curve::Circle { centre: [0.0, -e], radius: r, inside: false },
        Curve::Line { at: [0.0, r - e], direction: [1.0, 0.0] },
    ];
    let contact = Contact::new(curves, false, [0.0, r - e]);
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("cam", 1.0, 0.002, [0.0, 0.0]),
            body("follower", 2.0, 0.01, [0.0, 0.1]),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("guide", JointKind::Prismatic { axis: [0.0, 1.0] }, [0, 2], [0.0, 0.1]),
            joint("contact", JointKind::Contact(Box::new(contact)), [1, 2], [0.0, r - e]),
        ],
        drivers: vec![Driver::joint(0, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// The scissor lift of seed 002 at α = 30°: bars DE and BC (10 kg, 1 m)
/// crossed at their midpoints F, platform 90 kg pinned at C and sliding on E,
/// a block at B on the ground driven by the horizontal piston.
pub fn scissor_lift() -> Mechanism {
    let (l, c30) = (0.5, 3f64.sqrt() / 2.0);
    let f = [l * c30, l / 2.0];
    let (e, b, c) = ([2.0 * l * c30, l], [2.0 * l * c30, 0.0], [0.0, l]);
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("DE", 10.0, 10.0 * l * l / 3.0, f),
            body("BC", 10.0, 10.0 * l * l / 3.0, f),
            body("platform", 90.0, 1.0, [l * c30, l]),
            body("block", 0.0, 0.0, b),
        ],
        joints: vec![
            joint("D", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("F", JointKind::Revolute, [1, 2], f),
            joint("C", JointKind::Revolute, [2, 3], c),
            joint("E", JointKind::PinSlot { axis: [1.0, 0.0] }, [3, 1], e),
            joint("B", JointKind::Revolute, [4, 2], b),
            joint("piston", JointKind::Prismatic { axis: [1.0, 0.0] }, [0, 4], b),
        ],
        drivers: vec![Driver::joint(5, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// IFToMM A02's N-four-bar: N + 1 cranks hinged on the ground 1 m apart at
/// (i, 0), drawn upright, and N couplers across their tips, every bar 1 m,
/// 1 kg, I_G = 1/12 kg·m² (uniform rods), under gravity. The input is the
/// first crank's angle from +x (π/2 as drawn). 3(2N + 1) coordinates.
pub fn parallelogram_chain(n: usize) -> Mechanism {
    let rod = |name: String, cg: [f64; 2]| Body { name, mass: 1.0, inertia: 1.0 / 12.0, cg };
    let pin = |name: String, bodies: [usize; 2], at: [f64; 2]| joint(&name, JointKind::Revolute, bodies, at);
    let mut bodies = vec![body("ground", 0.0, 0.0, [0.0, 0.0])];
    bodies.extend((0..=n).map(|i| rod(format!("crank {i}"), [i as f64, 0.5])));
    bodies.extend((0..n).map(|i| rod(format!("coupler {i}"), [i as f64 + 0.5, 1.0])));
    let mut joints: Vec<Joint> = (0..=n).map(|i| pin(format!("O{i}"), [0, i + 1], [i as f64, 0.0])).collect();
    for i in 0..n {
        joints.push(pin(format!("A{i}"), [i + 1, n + 2 + i], [i as f64, 1.0]));
        joints.push(pin(format!("B{i}"), [i + 2, n + 2 + i], [i as f64 + 1.0, 1.0]));
    }
    Mechanism { bodies, joints, drivers: vec![Driver::joint(0, std::f64::consts::FRAC_PI_2)], gravity: [0.0, -9.81] }
}

/// IFToMM A01's pendulum made elastic: a massless arm pinned at O, the
/// 1 kg bob sliding along it (a prismatic joint at 1 m); both joints are
/// inputs (2 DOF). A spring of free length 1 m from the arm's (0, 0) to
/// the bob's (1, 0) holds the bob: its radial mode √(k/m) is the stiff
/// one, and the swing from the horizontal stretches it by at most 3mg/k.
pub fn elastic_pendulum() -> Mechanism {
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("arm", 0.0, 0.0, [0.5, 0.0]),
            body("bob", 1.0, 0.0, [1.0, 0.0]),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("slide", JointKind::Prismatic { axis: [1.0, 0.0] }, [1, 2], [1.0, 0.0]),
        ],
        drivers: vec![Driver::joint(0, 0.0), Driver::joint(1, 0.0)],
        gravity: [0.0, -9.81],
    }
}

/// Seed 002 question 4: a disk of radius R = 0.1 m pinned at O, its centre
/// C drawn d = 0.05 m to the right of O, and a ring P (0.5 kg, a particle)
/// threaded on its rim, drawn at the rim's top (0.05, 0.1). Two inputs:
/// the disk's rotation and the arc length the ring has run along the rim.
pub fn ring_on_rim() -> Mechanism {
    let (r, d) = (0.1, 0.05);
    let rim = Curve::Circle { centre: [d, 0.0], radius: r, inside: false };
    let mut contact = Contact::new([rim, Curve::Point([d, r])], false, [d, r]);
    contact.particle = true;
    Mechanism {
        bodies: vec![
            body("ground", 0.0, 0.0, [0.0, 0.0]),
            body("disk", 2.0, 0.01, [d, 0.0]),
            body("ring", 0.5, 0.0, [d, r]),
        ],
        joints: vec![
            joint("O", JointKind::Revolute, [0, 1], [0.0, 0.0]),
            joint("rim", JointKind::Contact(Box::new(contact)), [1, 2], [d, r]),
        ],
        drivers: vec![Driver::joint(0, 0.0), Driver::joint(1, 0.0)],
        gravity: [0.0, 0.0],
    }
}
