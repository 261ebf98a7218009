//! Closed-form positions of a mechanism made of a crank and dyads (Assur
//! groups of class II), as a linkage is drawn by compass and ruler.
//!
//! A dyad is two bodies b₁, b₂ sharing a revolute joint C, each joined to
//! a body already placed: b₁ by a revolute joint at A; b₂ by a revolute
//! joint at B (RRR: C is where the circles of radius l₁ = |C − A| about A
//! and l₂ = |C − B| about B meet) or by a prismatic joint to the ground (RRP:
//! b₂ a slider, C where the circle about A meets the slide's line). Of the
//! two intersections the one on the side the mechanism is on is taken, so
//! the assembly branch is kept as Newton's continuation keeps it. The crank
//! is placed by the input φ, then each dyad in turn; a mechanism with any
//! other joint (a gear, a pin in a slot, a joint left over) has no such
//! decomposition and is solved by Newton alone.

use crate::engine::model::{BodyId, Coordinate, Driver, JointKind, Mechanism, cross, dot, perp};
use std::f64::consts::TAU;

/// A joint of a dyad's body to a body placed before it.
#[derive(Clone, Copy, Debug)]
struct Pin {
    on: BodyId,
    /// The joint's point in the reference configuration, and from `on`'s G to it.
    at: [f64; 2],
    local: [f64; 2],
}

/// A dyad's body, placed by its pin and by C: from the pin to C (length
/// l), and the pin and C from the body's G, in the reference configuration.
#[derive(Clone, Copy, Debug)]
struct Link {
    body: BodyId,
    pin: Pin,
    to_c: [f64; 2],
    l: f64,
    pin_from_g: [f64; 2],
    c_from_g: [f64; 2],
}

#[derive(Clone, Copy, Debug)]
enum Group {
    /// Two links sharing C.
    Rrr([Link; 2]),
    /// A link and a slider sharing C (`c`, reference), the slider (G at
    /// `g`) sliding on the ground along the unit `axis`.
    Rrp { link: Link, slider: BodyId, c: [f64; 2], g: [f64; 2], axis: [f64; 2] },
}

/// The crank (θ = sign·(φ − reference), about `pivot` on the ground) and
/// the dyads in the order they are placed.
#[derive(Clone, Debug)]
pub struct Dyads {
    crank: BodyId,
    pivot: [f64; 2],
    sign: f64,
    reference: f64,
    groups: Vec<Group>,
}

impl Dyads {
    /// The decomposition of a mechanism with one input, a revolute joint
    /// to the ground, into dyads; None where it has none.
    pub fn new(m: &Mechanism) -> Option<Self> {
        let [Driver { coordinate: Coordinate::Joint(driven), reference, .. }] = m.drivers[..] else { return None };
        let joint = &m.joints[driven];
        let (crank, sign) = match (&joint.kind, joint.bodies) {
            (JointKind::Revolute, [0, b]) if b != 0 => (b, 1.0),
            (JointKind::Revolute, [b, 0]) if b != 0 => (b, -1.0),
            _ => return None,
        };
        let mut placed = vec![false; m.bodies.len()];
        let mut used = vec![false; m.joints.len()];
        (placed[0], placed[crank], used[driven]) = (true, true, true);
        let mut groups = Vec::new();
        while let Some((group, joints)) = next_group(m, &placed, &used) {
            joints.into_iter().for_each(|j| used[j] = true);
            match group {
                Group::Rrr([l1, l2]) => (placed[l1.body], placed[l2.body]) = (true, true),
                Group::Rrp { link, slider, .. } => (placed[link.body], placed[slider]) = (true, true),
            }
            groups.push(group);
        }
        let whole = placed.iter().all(|&p| p) && used.iter().all(|&u| u);
        whole.then_some(Self { crank, pivot: joint.at, sign, reference, groups })
    }

    /// Places every body at input φ, each dyad on the side its bodies are
    /// on in `q` (the last position or a prediction of this one); false
    /// where a dyad cannot be assembled (q is then partly placed). `trig`
    /// keeps the bodies' rotations from one placement to the next.
    pub fn place(&self, m: &Mechanism, phi: f64, q: &mut [f64], trig: &mut Trig) -> bool {
        let theta = self.sign * (phi - self.reference);
        let (sin, cos) = theta.sin_cos();
        trig.0.resize(m.bodies.len(), [f64::NAN; 3]);
        let mut p = Placer { m, q, trig };
        p.set(self.crank, m.local(self.crank, self.pivot), self.pivot, [theta, cos, sin]);
        self.groups.iter().all(|group| match group {
            Group::Rrr(links) => p.rrr(links),
            Group::Rrp { link, slider, c, g, axis } => p.rrp(link, *slider, *c, *g, *axis),
        })
    }
}

/// (θ, cos θ, sin θ) of every body as last placed: a body's rotation is
/// known from its vectors when it is placed, and read back while its θ in
/// q is the same (a sweep leaves it so where Newton has nothing to mend).
#[derive(Clone, Debug, Default)]
pub struct Trig(Vec<[f64; 3]>);

/// The next dyad whose outer joints reach placed bodies, with its joints.
fn next_group(m: &Mechanism, placed: &[bool], used: &[bool]) -> Option<(Group, [usize; 3])> {
    let free = |j: usize| !used[j];
    let revolute = |j: usize| matches!(m.joints[j].kind, JointKind::Revolute);
    // A revolute joint of body b, other than `not`, to a placed body.
    let pin = |b: BodyId, not: usize| {
        (0..m.joints.len()).filter(|&j| j != not && free(j) && revolute(j)).find_map(|j| {
            let [i, k] = m.joints[j].bodies;
            let other = if i == b {
                k
            } else if k == b {
                i
            } else {
                return None;
            };
            let at = m.joints[j].at;
            placed[other].then_some((j, Pin { on: other, at, local: m.local(other, at) }))
        })
    };
    // Body b on `pin`, reaching C: None where C is on the pin (no length).
    let link = |body: BodyId, pin: Pin, c: [f64; 2]| {
        let to_c = difference(c, pin.at);
        let l = dot(to_c, to_c).sqrt();
        let (pin_from_g, c_from_g) = (m.local(body, pin.at), m.local(body, c));
        (l > 0.0).then_some(Link { body, pin, to_c, l, pin_from_g, c_from_g })
    };
    for (jc, joint) in m.joints.iter().enumerate().filter(|(j, _)| free(*j) && revolute(*j)) {
        let [x, y] = joint.bodies;
        if placed[x] || placed[y] {
            continue;
        }
        let c = joint.at;
        for (b1, b2) in [(x, y), (y, x)] {
            let Some((ja, first)) = pin(b1, jc).and_then(|(ja, a)| Some((ja, link(b1, a, c)?))) else { continue };
            if let Some((jb, second)) = pin(b2, jc).and_then(|(jb, b)| Some((jb, link(b2, b, c)?))) {
                return Some((Group::Rrr([first, second]), [jc, ja, jb]));
            }
            if let Some((js, axis)) = slide(m, b2, used) {
                let g = m.bodies[b2].cg;
                return Some((Group::Rrp { link: first, slider: b2, c, g, axis }, [jc, ja, js]));
            }
        }
    }
    None
}

/// A prismatic joint of body b to the ground, not yet used: it and its axis.
fn slide(m: &Mechanism, b: BodyId, used: &[bool]) -> Option<(usize, [f64; 2])> {
    m.joints.iter().enumerate().find_map(|(j, joint)| match (&joint.kind, joint.bodies) {
        (JointKind::Prismatic { axis }, [0, k] | [k, 0]) if k == b && !used[j] => Some((j, *axis)),
        _ => None,
    })
}

/// The angle in (−π, π] with this sine and cosine (of a vector of length
/// 1): atan2, or for a short turn (tangent t within ±0.1) atan's series
/// t − t³/3 + t⁵/5 − … to t¹⁷/17, whose next term is below 1e-19·|t|.
fn turn(sin: f64, cos: f64) -> f64 {
    let t = sin / cos;
    if !(cos > 0.0 && t.abs() <= 0.1) {
        return sin.atan2(cos);
    }
    const TERMS: [f64; 9] =
        [1.0, -1.0 / 3.0, 1.0 / 5.0, -1.0 / 7.0, 1.0 / 9.0, -1.0 / 11.0, 1.0 / 13.0, -1.0 / 15.0, 1.0 / 17.0];
    let x = t * t;
    t * TERMS.iter().rev().fold(0.0, |sum, c| c + x * sum)
}

fn difference(p: [f64; 2], q: [f64; 2]) -> [f64; 2] {
    [p[0] - q[0], p[1] - q[1]]
}

/// One placement: the mechanism, its coordinates and the rotations known.
struct Placer<'a> {
    m: &'a Mechanism,
    q: &'a mut [f64],
    trig: &'a mut Trig,
}

impl Placer<'_> {
    /// (cos θ, sin θ) of body b at q.
    #[inline(always)]
    fn turn(&mut self, b: BodyId) -> [f64; 2] {
        let Some(col) = self.m.column(b) else { return [1.0, 0.0] };
        let (theta, known) = (self.q[col + 2], &mut self.trig.0[b]);
        if known[0] != theta {
            let (sin, cos) = theta.sin_cos();
            *known = [theta, cos, sin];
        }
        [known[1], known[2]]
    }

    /// The point `s` from body b's G (reference) at q.
    #[inline(always)]
    fn point(&mut self, b: BodyId, s: [f64; 2]) -> [f64; 2] {
        let Some(col) = self.m.column(b) else { return s };
        let [cos, sin] = self.turn(b);
        [self.q[col] + cos * s[0] - sin * s[1], self.q[col + 1] + sin * s[0] + cos * s[1]]
    }

    /// Where a pin is now.
    #[inline(always)]
    fn pin(&mut self, pin: &Pin) -> [f64; 2] {
        if pin.on == 0 { pin.at } else { self.point(pin.on, pin.local) }
    }

    /// Body b rotated by θ (with its cos and sin), its point `s` from G
    /// (reference) at `now`.
    #[inline(always)]
    fn set(&mut self, b: BodyId, s: [f64; 2], now: [f64; 2], [theta, cos, sin]: [f64; 3]) {
        let Some(col) = self.m.column(b) else { return };
        (self.q[col], self.q[col + 1], self.q[col + 2]) =
            (now[0] - cos * s[0] + sin * s[1], now[1] - sin * s[0] - cos * s[1], theta);
        self.trig.0[b] = [theta, cos, sin];
    }

    /// A link with its pin `at` and C at `now`: cos θ and sin θ from the
    /// two vectors pin → C (both of length l), θ the value nearest the
    /// body's last one.
    #[inline(always)]
    fn swing(&mut self, link: &Link, at: [f64; 2], now: [f64; 2]) {
        let near = self.m.column(link.body).map_or(0.0, |col| self.q[col + 2]);
        let (to, scale) = (difference(now, at), 1.0 / (link.l * link.l));
        let (cos, sin) = (dot(link.to_c, to) * scale, cross(link.to_c, to) * scale);
        let [_, was_cos, was_sin] = self.trig.0[link.body];
        let theta = if self.trig.0[link.body][0] == near {
            // The turn from the body's last rotation: short along a sweep.
            near + turn(sin * was_cos - cos * was_sin, cos * was_cos + sin * was_sin)
        } else {
            let step = sin.atan2(cos) - near;
            near + step - TAU * (step / TAU).round()
        };
        self.set(link.body, link.pin_from_g, at, [theta, cos, sin]);
    }

    /// RRR: C at l₁ from A and l₂ from B, on the side of AB it is on.
    fn rrr(&mut self, [first, second]: &[Link; 2]) -> bool {
        let (pa, pb) = (self.pin(&first.pin), self.pin(&second.pin));
        let before = self.point(first.body, first.c_from_g);
        let (d, [l1, l2]) = (difference(pb, pa), [first.l, second.l]);
        let distance = dot(d, d).sqrt();
        let inverse = 1.0 / distance;
        let x = 0.5 * (l1 * l1 - l2 * l2 + distance * distance) * inverse;
        let h2 = l1 * l1 - x * x;
        if !(h2 >= 0.0 && distance > 0.0) {
            return false;
        }
        let e = [d[0] * inverse, d[1] * inverse];
        let side = if cross(e, difference(before, pa)) < 0.0 { -1.0 } else { 1.0 };
        let (h, n) = (side * h2.sqrt(), perp(e));
        let now = [pa[0] + x * e[0] + h * n[0], pa[1] + x * e[1] + h * n[1]];
        self.swing(first, pa, now);
        self.swing(second, pb, now);
        true
    }

    /// RRP: the slider moved by s along the axis u so that C is l₁ from A,
    /// the root of |C_ref + s·u − A| = l₁ nearest the slider's s in q.
    fn rrp(&mut self, link: &Link, slider: BodyId, c: [f64; 2], g: [f64; 2], u: [f64; 2]) -> bool {
        let pa = self.pin(&link.pin);
        let Some(col) = self.m.column(slider) else { return false };
        let before = dot(difference([self.q[col], self.q[col + 1]], g), u);
        let w = difference(c, pa);
        let p = dot(w, u);
        let disc = p * p - (dot(w, w) - link.l * link.l);
        if disc.is_nan() || disc < 0.0 {
            return false;
        }
        let root = disc.sqrt();
        let s = if (-p + root - before).abs() <= (-p - root - before).abs() { -p + root } else { -p - root };
        (self.q[col], self.q[col + 1], self.q[col + 2]) = (g[0] + s * u[0], g[1] + s * u[1], 0.0);
        self.trig.0[slider] = [0.0, 1.0, 0.0];
        self.swing(link, pa, [c[0] + s * u[0], c[1] + s * u[1]]);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::constraints::{State, evaluate};
    use crate::engine::kinematics::Workspace;
    use crate::engine::samples::{four_bar, offset_slider_crank, planetary_train, slotted_lever, watt_six_bar};

    /// Each position placed in closed form from the last equals Newton's
    /// from the same start (a second method: Φ = 0 solved iteratively) to
    /// 1e-12, and leaves |Φ| ≤ 1e-14: the four-bar and the offset
    /// slider-crank (RRR, RRP) over a whole turn and back, the six-bar
    /// (two dyads, one on a ternary link) over ±0.4 rad.
    #[test]
    fn closed_form_positions_match_newtons() {
        let turn: Vec<f64> = (0..=200).map(|k| 4.0 * std::f64::consts::PI * k as f64 / 200.0).collect();
        let swing: Vec<f64> = (0..=80).map(|k| 0.4 * (k as f64 * 0.157).sin()).collect();
        for (name, m, inputs) in [
            ("four-bar", four_bar(), &turn),
            ("slider-crank", offset_slider_crank(), &turn),
            ("six-bar", watt_six_bar(), &swing),
        ] {
            let dyads = Dyads::new(&m).unwrap_or_else(|| panic!("{name}: a crank and dyads"));
            let (mut placed, mut ws, mut trig) = (m.reference_q(), Workspace::default(), Trig::default());
            for &phi in inputs.iter() {
                let mut newton = placed.clone();
                assert!(dyads.place(&m, phi, &mut placed, &mut trig), "{name} at {phi}");
                ws.assemble(&m, &mut newton, &[[phi, 0.0, 0.0]], 0).expect("assembled");
                let gap = placed.iter().zip(&newton).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
                assert!(gap <= 1e-12, "{name} at φ = {phi}: {gap:e} from Newton's");
                let residual = evaluate(&m, &State { q: &placed, qd: None, inputs: &[[phi, 0.0, 0.0]] }).phi.amax();
                assert!(residual <= 1e-14, "{name} at φ = {phi}: |Φ| = {residual:e}");
            }
        }
    }

    /// A pin in a slot, gears, or a driven slider leave no such decomposition.
    #[test]
    fn other_mechanisms_have_no_dyads() {
        assert!(Dyads::new(&slotted_lever()).is_none());
        assert!(Dyads::new(&planetary_train()).is_none());
        assert!(Dyads::new(&crate::engine::samples::actuated_arm()).is_none());
    }

    /// A dyad that cannot close (its circles apart) is said, not placed:
    /// the four-bar's coupler shortened until it no longer reaches.
    #[test]
    fn a_dyad_out_of_reach_is_refused() {
        let mut m = four_bar();
        m.joints[2].at = [0.15, 0.0];
        let dyads = Dyads::new(&m).expect("still a crank and a dyad");
        let mut q = m.reference_q();
        assert!(
            !dyads.place(&m, std::f64::consts::PI, &mut q, &mut Trig::default()),
            "|A − O4| = 0.5 > 0.05 + |B − O4|"
        );
    }
}
