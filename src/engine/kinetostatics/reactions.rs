//! A joint's reaction from the multipliers λ of Φ_qᵀλ = Q − M q̈: the
//! forces its rows of Φ_q put on its second body, the moment about the
//! joint's point (a contact's where it touches now), a guide's two ends and
//! a gear mesh's tooth force.

use super::Reaction;
use super::loads::point_motion;
use crate::engine::model::{
    BodyId, Coordinate, Driver, Guide, JointKind, Mechanism, Pitch, cross, dot, perp, rotate_by,
};
use nalgebra::DMatrix;

/// Every joint's reaction from the multipliers λ of Φ_qᵀλ = Q − M q̈ (the
/// joints' rows first in Φ_q, joint k's from `offsets[k]`), flagged where
/// `indeterminate` lists the joint.
pub fn reactions(
    m: &Mechanism,
    q: &[f64],
    jac: &DMatrix<f64>,
    lambda: &[f64],
    offsets: &[usize],
    indeterminate: &[usize],
) -> Vec<Reaction> {
    let mut trig = Vec::new();
    m.turns_into(q, &mut trig);
    let mut out = Vec::with_capacity(m.joints.len());
    reactions_into(m, (q, &trig), (jac, lambda, &[]), (offsets, indeterminate), &mut out);
    out
}

/// [`reactions`] appended to `out`, with (sin θ, cos θ) of every body at q
/// (ground first) in `trig`, flagged where `indeterminate` lists the joint.
pub(super) fn reactions_into(
    m: &Mechanism,
    at: (&[f64], &[(f64, f64)]),
    efforts: (&DMatrix<f64>, &[f64], &[f64]),
    (offsets, indeterminate): (&[usize], &[usize]),
    out: &mut Vec<Reaction>,
) {
    out.extend(
        (0..m.joints.len())
            .map(|k| Reaction { determinate: !indeterminate.contains(&k), ..reaction_of(m, at, efforts, offsets, k) }),
    );
}

/// Joint k's reaction from λ (its rows of Φ_q from `offsets[k]`), flagged
/// determinate. A contact that carries an input's `driving` effort (its own
/// coordinate driven, or it the actuator) passes it through its equations
/// to the bodies; its reaction is what is left, the effort being the
/// actuator's, not the contact's (a frictionless contact's tangential part
/// is then 0).
pub(super) fn reaction_of(
    m: &Mechanism,
    (q, trig): (&[f64], &[(f64, f64)]),
    (jac, lambda, driving): (&DMatrix<f64>, &[f64], &[f64]),
    offsets: &[usize],
    k: usize,
) -> Reaction {
    let joint = &m.joints[k];
    let rows = offsets[k]..offsets[k] + Mechanism::joint_rows(&joint.kind);
    let force_on = |b: BodyId| -> [f64; 3] {
        let Some(col) = m.column(b) else { return [0.0; 3] };
        let f = |d: usize| -rows.clone().map(|r| jac[(r, col + d)] * lambda[r]).sum::<f64>();
        [f(0), f(1), f(2)]
    };
    let [i, j] = joint.bodies;
    // On the second body, or minus the action on the first when the second is the ground.
    let (b, sign) = if j != 0 { (j, 1.0) } else { (i, -1.0) };
    let [fx, fy, mg] = force_on(b);
    // About the joint's point, carried by the body; a contact's where it touches now.
    let at = m.contact_point(k, b, q).unwrap_or(joint.at);
    let arm = rotate_by(trig[b], m.local(b, at));
    let moment = mg - cross(arm, [fx, fy]);
    if let JointKind::Gear { pitch: Some(pitch), .. } = &joint.kind {
        let [tx, ty] = tooth_force(m, q, [i, j], pitch, sign * moment);
        return Reaction { joint: k, on: j, by: i, fx: tx, fy: ty, moment: 0.0, ends: None, determinate: true };
    }
    let [fx, fy, moment] = [sign * fx, sign * fy, sign * moment];
    // The actuator's force at the contact point: no moment about it.
    let [ax, ay] = contact_effort(m, q, k, driving);
    let [fx, fy] = [fx - ax, fy - ay];
    let ends = match (&joint.kind, joint.length) {
        (JointKind::Prismatic { axis }, Some(guide)) => {
            // The moment about the guide's centre, on the body that carries it.
            let carrier = if matches!(guide, Guide::Fixed(_)) { i } else { j };
            let (centre, here) = (placed(m, (q, trig), carrier, joint.at), placed(m, (q, trig), b, joint.at));
            let moment = moment + cross([here[0] - centre[0], here[1] - centre[1]], [fx, fy]);
            let (normal, length) = (dot(perp(rotate_by(trig[i], *axis)), [fx, fy]), guide.length());
            Some([normal / 2.0 - moment / length, normal / 2.0 + moment / length])
        }
        _ => None,
    };
    Reaction { joint: k, on: j, by: i, fx, fy, moment, ends, determinate: true }
}

/// The force on the second body of joint k from the inputs' efforts that
/// act at it, where it is a sliding contact: each effort along the
/// direction in which it works on the contact's arc length.
fn contact_effort(m: &Mechanism, q: &[f64], k: usize, driving: &[f64]) -> [f64; 2] {
    let JointKind::Contact(c) = &m.joints[k].kind else { return [0.0; 2] };
    let acting = |d: &Driver| d.actuator.or(if let Coordinate::Joint(j) = d.coordinate { Some(j) } else { None });
    let effort: f64 = m.drivers.iter().zip(driving).filter(|(d, _)| acting(d) == Some(k)).map(|(_, f)| f).sum();
    if effort == 0.0 || c.rolling {
        return [0.0; 2];
    }
    m.contact_arc_direction(k, q).map_or([0.0; 2], |t| [effort * t[0], effort * t[1]])
}

/// Where body `b`'s point `p` (reference coordinates) is at q.
fn placed(m: &Mechanism, (q, trig): (&[f64], &[(f64, f64)]), b: BodyId, p: [f64; 2]) -> [f64; 2] {
    let Some(c) = m.column(b) else { return p };
    let s = rotate_by(trig[b], m.local(b, p));
    [q[c] + s[0], q[c + 1] + s[1]]
}

/// The tooth force on the second gear at the pitch point, from the mesh's
/// couple on it: tangential M₂/r₂, radial |M₂/r₂|·tan α pushing the teeth apart
/// (towards the gear's centre; outwards for the ring of an internal mesh).
fn tooth_force(m: &Mechanism, q: &[f64], [i, j]: [BodyId; 2], pitch: &Pitch, couple: f64) -> [f64; 2] {
    let Some((_, w)) = mesh_line(m, q, [i, j], pitch) else { return [0.0; 2] };
    let t = perp(w);
    let tangential = couple / pitch.radius;
    let radial = tangential.abs() * pitch.pressure_angle.tan() * if pitch.second_is_ring { 1.0 } else { -1.0 };
    [tangential * t[0] + radial * w[0], tangential * t[1] + radial * w[1]]
}

/// The pitch point of a mesh at q, where its tooth force acts: the second
/// gear's pitch radius from its centre along w.
pub(super) fn pitch_point(m: &Mechanism, q: &[f64], bodies: [BodyId; 2], pitch: &Pitch) -> [f64; 2] {
    mesh_line(m, q, bodies, pitch)
        .map_or(pitch.centers[1], |(c2, w)| [c2[0] + pitch.radius * w[0], c2[1] + pitch.radius * w[1]])
}

/// The second gear's centre at q and w, the unit vector from it to the
/// pitch point (towards the first gear's centre, or away from the ring's);
/// None where the centres coincide.
fn mesh_line(m: &Mechanism, q: &[f64], [i, j]: [BodyId; 2], pitch: &Pitch) -> Option<([f64; 2], [f64; 2])> {
    let (c1, _) = point_motion(m, q, &vec![0.0; q.len()], (i, pitch.centers[0]));
    let (c2, _) = point_motion(m, q, &vec![0.0; q.len()], (j, pitch.centers[1]));
    let d = [c1[0] - c2[0], c1[1] - c2[1]];
    let length = d[0].hypot(d[1]);
    if length == 0.0 {
        return None;
    }
    let away = pitch.internal && !pitch.second_is_ring;
    Some((c2, if away { [-d[0] / length, -d[1] / length] } else { [d[0] / length, d[1] / length] }))
}
