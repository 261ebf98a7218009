//! Seed 002 question 4, the ring P threaded on the rim of a disk pinned off
//! its centre (`samples::ring_on_rim`: R = 0.1 m, the centre C drawn 0.05 m
//! right of the pin O), driven by the disk's rotation θ (ω, α) and the arc
//! length s the ring runs along the rim (v, a). Its motion is the textbook
//! composition (seed 000, "composición de movimientos"): with ρ = OP,
//! e_t the rim's tangent and e_n = (C − P)/R its inward normal at P,
//! v_P = ω × ρ + v e_t,
//! a_P = α × ρ − ω² ρ + a e_t + (v²/R) e_n + 2 ω × v e_t (Coriolis).
//! The ring has mass and no inertia: a particle, its rotation not a
//! coordinate (held as drawn) and left out of Grübler's count.

use mechdyn::engine::Deadline;
use mechdyn::engine::kinetostatics::{Outputs, solve};
use mechdyn::engine::model::rotate;
use mechdyn::engine::samples::ring_on_rim;

#[test]
fn a_ring_on_a_turning_rim_moves_as_the_composition_of_motions_says() {
    let (r, d, m) = (0.1, 0.05, 0.5);
    let mechanism = ring_on_rim();
    assert_eq!(mechanism.grubler().mobility, 2, "3·2 − 1 (the particle) − 2 (pin) − 1 (point on a curve)");
    let outputs = Outputs { driving: true, reactions: true, reduced: false, kinematics: true, condition: false };
    let cases = [[0.4, 3.0, -2.0, 0.05, 0.7, 1.5], [2.1, -1.5, 4.0, -0.2, -0.3, 0.0], [5.0, 10.0, 0.0, 0.3, 2.0, -3.0]];
    let positions: Vec<Vec<[f64; 3]>> = cases.iter().map(|c| vec![[c[0], c[1], c[2]], [c[3], c[4], c[5]]]).collect();
    let solution = solve(&mechanism, &[], &positions, outputs, &Deadline::none()).unwrap();
    assert_eq!(solution.totals.mobility.dof, 2);
    for (c, step) in cases.iter().zip(&solution.steps) {
        let [theta, w, alpha, s, v, a] = *c;
        // The ring's angle on the rim from C, and the rim's frame at P (ground frame).
        let u = std::f64::consts::FRAC_PI_2 + s / r;
        let rho = rotate(theta, [d + r * u.cos(), r * u.sin()]);
        let e_t = rotate(theta, [-u.sin(), u.cos()]);
        let e_n = rotate(theta, [-u.cos(), -u.sin()]);
        let cross_w = |k: f64, p: [f64; 2]| [-k * p[1], k * p[0]];
        let (wr, ar, cor) = (cross_w(w, rho), cross_w(alpha, rho), cross_w(2.0 * w * v, e_t));
        let vp = [wr[0] + v * e_t[0], wr[1] + v * e_t[1]];
        let ap: Vec<f64> = (0..2).map(|k| ar[k] - w * w * rho[k] + a * e_t[k] + v * v / r * e_n[k] + cor[k]).collect();
        let k = step.kinematics.as_ref().unwrap();
        let close = |got: f64, want: f64, scale: f64, what: &str| {
            assert!((got - want).abs() < 1e-9 * scale, "{c:?}: {what} {got} vs {want}");
        };
        for i in 0..2 {
            close(k.q[3 + i], rho[i], r, "P");
            close(k.qd[3 + i], vp[i], 1.0, "v_P");
            close(k.qdd[3 + i], ap[i], 10.0, "a_P");
        }
        close(k.q[5], 0.0, 1.0, "the particle's rotation, held");
        // The ring moves by m a_P (no gravity): the arc-length input's
        // actuator pushes it along the rim with m a_P · e_t, and the
        // frictionless rim's reaction is the rest, m (a_P · e_n) e_n.
        let (along, across) = (ap[0] * e_t[0] + ap[1] * e_t[1], ap[0] * e_n[0] + ap[1] * e_n[1]);
        let force = &step.reactions[1];
        close(step.driving[1], m * along, 10.0 * m, "force along the rim");
        close(force.fx, m * across * e_n[0], 10.0 * m, "rim on ring, x");
        close(force.fy, m * across * e_n[1], 10.0 * m, "rim on ring, y");
    }
}
