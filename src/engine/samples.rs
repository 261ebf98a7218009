//! Canonical mechanisms shared by tests, docs and examples.

use super::model::{Body, Driver, Joint, JointKind, Mechanism};

fn body(name: &str, mass: f64, inertia: f64, cg: [f64; 2]) -> Body {
    Body { name: name.into(), mass, inertia, cg }
}

fn joint(name: &str, kind: JointKind, bodies: [usize; 2], at: [f64; 2]) -> Joint {
    Joint { name: name.into(), kind, bodies, at }
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
        drivers: vec![Driver { joint: 0, reference: 0.0 }],
        gravity: [0.0, -9.81],
    }
}
