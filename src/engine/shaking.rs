//! The shaking of the frame by a linkage's moving links, and the
//! counterweights that remove its force.
//!
//! Symbols (complex numbers stand for plane vectors, i a quarter turn CCW):
//! - F = −Σ m·a_G, the resultant of the moving links' inertia forces, and
//!   M = −Σ (r_G × m·a_G + I_G·α) its moment about the origin: with no
//!   gravity and no load, what the links put on the frame;
//! - S = Σ m·r_G, the moving links' mass moment (F = −S̈): a stationary
//!   centre of mass is a constant S;
//! - a link pivoted to the frame at O, its other joint at distance r along
//!   the unit e (its line as drawn, β = arg e); p = (G − O)/e its centre of
//!   mass in its own frame (x along its line), and c the counterweight's
//!   mass moment m·r there;
//! - a four-bar O₂ A B O₄: crank r₂ = |O₂A|, coupler l₃ = |AB| with p₃ from
//!   A along AB, rocker r₄ = |O₄B|. Eliminating the coupler's direction from
//!   the loop (the method of linearly independent vectors, Berkof–Lowen)
//!   leaves S = const + e^{iθ₂}(m₂p₂ + m₃r₂(1 − p₃/l₃)) + e^{iθ₄}(m₄p₄ + m₃r₄p₃/l₃),
//!   so c₂ = −m₂p₂ − m₃r₂(1 − p₃/l₃) and c₄ = −m₄p₄ − m₃r₄·p₃/l₃ make S constant;
//! - a slider-crank O₂ A B: the rod's share at the crank pin,
//!   m₃(1 − p₃/l₃), rotates with the crank; m_rec = m₄ + m₃·Re(p₃)/l₃
//!   reciprocates with B. c₂ = −m₂p₂ − m₃r₂(1 − p₃/l₃) − f·m_rec·r₂ balances
//!   the rotating masses and the fraction f of the reciprocating one (its
//!   primary force along the guide, at the cost of f of it across). A rod's
//!   centre of mass off its line leaves its share across the line,
//!   i·m₃·Im(p₃)/l₃ moving with B, unbalanced.

use super::balancing::{Planar, polar};
use super::kinetostatics::Motion;
use super::model::{BodyId, JointKind, Mechanism};
use nalgebra::Complex;

type C = Complex<f64>;

/// The resultant of the moving links' inertia forces and its moment about the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shaking {
    pub force: [f64; 2],
    pub moment: f64,
}

/// F = −Σ m·a_G and M = −Σ (r_G × m·a_G + I_G·α) at the motion `m`.
pub fn shaking(mechanism: &Mechanism, m: &Motion) -> Shaking {
    let mut out = Shaking { force: [0.0; 2], moment: 0.0 };
    for (b, body) in mechanism.bodies.iter().enumerate().skip(1) {
        let c = 3 * (b - 1);
        let (fx, fy) = (-body.mass * m.qdd[c], -body.mass * m.qdd[c + 1]);
        out.force[0] += fx;
        out.force[1] += fy;
        out.moment += m.q[c] * fy - m.q[c + 1] * fx - body.inertia * m.qdd[c + 2];
    }
    out
}

/// A counterweight on a link pivoted to the frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Counterweight {
    pub body: BodyId,
    /// m·r from the pivot, kg·m.
    pub mass_radius: f64,
    /// In the link's frame, from its line (pivot to its other joint), CCW, 0 to 2π rad.
    pub angle: f64,
    /// The link's line as drawn, β (rad from the x axis).
    pub line: f64,
}

impl Counterweight {
    fn new(body: BodyId, c: C, line: f64) -> Self {
        let (mass_radius, angle) = polar(Planar::new(c.re, c.im));
        Self { body, mass_radius, angle, line }
    }

    /// Its inertia force at the motion `m`: −d²/dt²(c·e^{i(β+θ)}) = (ω² − iα)·c·e^{i(β+θ)}.
    pub fn force(&self, m: &Motion) -> [f64; 2] {
        let k = 3 * (self.body - 1) + 2;
        let c = C::from_polar(self.mass_radius, self.angle + self.line + m.q[k]);
        let f = C::new(m.qd[k] * m.qd[k], -m.qdd[k]) * c;
        [f.re, f.im]
    }
}

/// What the counterweights balance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Linkage {
    /// Full force balance: the moving links' centre of mass stationary.
    FourBar,
    /// The rotating masses and a fraction of the reciprocating one.
    SliderCrank,
}

/// Why no counterweights can be found.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Unbalanceable {
    #[error("counterweights are found for a four-bar or a slider-crank")]
    NotALinkage,
    /// A body asked for that is not the crank or the rocker (its index in the list).
    #[error("counterweight {at} is on a link not pivoted to the frame")]
    NotPivoted { at: usize },
    /// A link that needs one left out of the list (a four-bar's crank or
    /// rocker, a slider-crank's crank).
    #[error("the {linkage:?}'s balance needs a counterweight on body {body}")]
    Missing { linkage: Linkage, body: BodyId },
}

/// A link pivoted at O, its other joint at `to`: (r, e, p).
struct Link {
    body: BodyId,
    r: f64,
    e: C,
    p: C,
    mass: f64,
}

impl Link {
    /// None for a link of no length.
    fn new(m: &Mechanism, body: BodyId, from: [f64; 2], to: [f64; 2]) -> Option<Self> {
        let (o, to, g) = (c(from), c(to), c(m.bodies[body].cg));
        let r = (to - o).norm();
        let e = (r > 0.0).then(|| (to - o).unscale(r))?;
        Some(Self { body, r, e, p: (g - o) / e, mass: m.bodies[body].mass })
    }

    /// A slider: only its mass counts.
    fn slider(m: &Mechanism, body: BodyId) -> Self {
        Self { body, r: 0.0, e: C::new(1.0, 0.0), p: C::default(), mass: m.bodies[body].mass }
    }

    fn weight(&self, c: C) -> Counterweight {
        Counterweight::new(self.body, c, self.e.arg())
    }
}

fn c(p: [f64; 2]) -> C {
    C::new(p[0], p[1])
}

/// The counterweights on `on` (the crank and, of a four-bar, the rocker)
/// with the fraction `f` of a slider-crank's reciprocating mass, in `on`'s order.
pub fn counterweights(m: &Mechanism, on: &[BodyId], f: f64) -> Result<(Linkage, Vec<Counterweight>), Unbalanceable> {
    let (linkage, crank, coupler, other) = recognise(m).ok_or(Unbalanceable::NotALinkage)?;
    let rotating = -crank.p * crank.mass - crank.r * coupler.mass * (C::new(1.0, 0.0) - coupler.p / coupler.r);
    let mut weights = vec![crank.weight(match linkage {
        Linkage::FourBar => rotating,
        Linkage::SliderCrank => rotating - f * (other.mass + coupler.mass * coupler.p.re / coupler.r) * crank.r,
    })];
    if linkage == Linkage::FourBar {
        weights.push(other.weight(-other.p * other.mass - other.r * coupler.mass * coupler.p / coupler.r));
    }
    let on_link = |b: &BodyId| weights.iter().find(|w| w.body == *b).copied();
    if let Some(at) = on.iter().position(|b| on_link(b).is_none()) {
        return Err(Unbalanceable::NotPivoted { at });
    }
    if let Some(w) = weights.iter().find(|w| !on.contains(&w.body)) {
        return Err(Unbalanceable::Missing { linkage, body: w.body });
    }
    Ok((linkage, on.iter().filter_map(on_link).collect()))
}

/// The linkage `m` is, with its crank, coupler (origin at the crank pin A,
/// x along AB) and rocker or slider (a four-bar's rocker from O₄ to B).
fn recognise(m: &Mechanism) -> Option<(Linkage, Link, Link, Link)> {
    if m.bodies.len() != 4 || m.joints.len() != 4 {
        return None;
    }
    let revolute = |a: BodyId, b: BodyId| {
        m.joints.iter().find(|j| j.kind == JointKind::Revolute && (j.bodies == [a, b] || j.bodies == [b, a]))
    };
    let slides = |b: BodyId| {
        m.joints
            .iter()
            .any(|j| matches!(j.kind, JointKind::Prismatic { .. }) && (j.bodies == [0, b] || j.bodies == [b, 0]))
    };
    let pivoted: Vec<BodyId> = (1..4).filter(|&b| revolute(0, b).is_some()).collect();
    let [crank, coupler, other] = match pivoted[..] {
        [a, b] => [a, 6 - a - b, b],
        [a] => {
            let slider = (1..4).find(|&b| b != a && slides(b))?;
            [a, 6 - a - slider, slider]
        }
        _ => return None,
    };
    let (o2, a) = (revolute(0, crank)?.at, revolute(crank, coupler)?.at);
    let b = revolute(coupler, other)?.at;
    let (crank_link, coupler_link) = (Link::new(m, crank, o2, a)?, Link::new(m, coupler, a, b)?);
    Some(match pivoted.len() {
        2 => (Linkage::FourBar, crank_link, coupler_link, Link::new(m, other, revolute(0, other)?.at, b)?),
        _ => (Linkage::SliderCrank, crank_link, coupler_link, Link::slider(m, other)),
    })
}
