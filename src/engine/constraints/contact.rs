//! The rows of a higher pair (a sliding contact between two curves).
//!
//! Symbols: body i carries curve 1 with parameter u₁, body j curve 2 with
//! u₂ (a point has none); s_k(u) = c_k(u) − G_k its point relative to the
//! body's centre of mass as drawn, P_k = r_k + A(θ_k)s_k its place, and
//! T_k = A(θ_k)c_k′(u_k) its tangent. The rows are the coincidence
//! P₂ − P₁ = 0 and, where both curves have a parameter, the common tangent
//! T₁ × T₂ = 0. With B = dA/dθ (dB/dθ = −A), a moving point A s(u) has
//! the velocity-squared terms h = −A s θ̇² + 2B s′ θ̇ u̇ + A s″ u̇² in its
//! second derivative, and γ gathers them with the opposite sign.

use super::{Builder, Jacobian};
use crate::engine::curves::{Curve, Domain, Local};
use crate::engine::model::{BodyId, Contact, cross};

/// One curve of a contact at the current state: its local point and
/// derivatives (relative to the body's centre of mass), the body's angle
/// rate and the parameter's column, value and rate.
struct Side {
    body: BodyId,
    l: Local,
    column: Option<usize>,
    w: f64,
    ud: f64,
}

impl<J: Jacobian> Builder<'_, '_, J> {
    fn side(&self, body: BodyId, curve: &Curve, column: Option<usize>) -> Side {
        let u = column.map_or(0.0, |c| self.s.q[c]);
        let mut l = curve.at(u);
        let g = self.m.bodies[body].cg;
        l.r = [l.r[0] - g[0], l.r[1] - g[1]];
        let ud = match (column, self.s.qd) {
            (Some(c), Some(qd)) => qd[c],
            _ => 0.0,
        };
        Side { body, l, column, w: self.rates(body).1, ud }
    }

    /// h(v) = −A v θ̇² + 2B v′ θ̇ u̇ + A v″ u̇², the velocity-squared terms of
    /// d²/dt²(A v(u)) for v = s (with v′ = s′, v″ = s″) or v = c′.
    fn quadratic(&self, side: &Side, [v, v1, v2]: [[f64; 2]; 3]) -> [f64; 2] {
        let (a, b1, a2) = (self.rot(side.body, v), self.rot_d(side.body, v1), self.rot(side.body, v2));
        let (w, ud) = (side.w, side.ud);
        [-a[0] * w * w + 2.0 * b1[0] * w * ud + a2[0] * ud * ud, -a[1] * w * w + 2.0 * b1[1] * w * ud + a2[1] * ud * ud]
    }

    /// The rows of `contact` between `bodies` from `row`, its parameters'
    /// columns from `column`.
    pub(super) fn contact(&mut self, row: usize, [i, j]: [BodyId; 2], contact: &Contact, column: usize) {
        let mut next = column;
        let mut parameter = |c: &Curve| {
            (c.domain() != Domain::None).then(|| {
                next += 1;
                next - 1
            })
        };
        let (c1, c2) = (parameter(&contact.curves[0]), parameter(&contact.curves[1]));
        let (one, two) = (self.side(i, &contact.curves[0], c1), self.side(j, &contact.curves[1], c2));
        self.coincidence(row, &one, &two);
        if c1.is_some() && c2.is_some() {
            self.tangency(row + 2, &one, &two);
        }
        let mut next_row = row + 2 + usize::from(c1.is_some() && c2.is_some());
        if contact.rolling {
            self.rolling(next_row, contact, [&one, &two]);
            next_row += 1;
        }
        if contact.particle {
            // The particle's rotation held as drawn: θ = 0.
            let particle = if c1.is_none() { i } else { j };
            self.angles(next_row, &[(particle, 1.0)], 0.0);
        }
    }

    /// Row a(u) − a(u as drawn) − target: the arc length the contact point
    /// has run along contact joint k's first curve with a parameter. With
    /// d|c′|/du = c′·c″/|c′|, its second derivative's quadratic part is
    /// (c′·c″/|c′|) u̇².
    pub(super) fn contact_arc(&mut self, row: usize, k: usize, contact: &Contact, target: f64) {
        let Some(side) = contact.measured_side() else { return };
        let Some(column) = self.m.contact_column(k, side) else { return };
        let curve = &contact.curves[side];
        let (u, ud) = (self.s.q[column], self.s.qd.map_or(0.0, |qd| qd[column]));
        let l = curve.at(u);
        let speed = l.d1[0].hypot(l.d1[1]);
        self.phi[row] = curve.arc(u) - curve.arc(contact.drawn[side]) - target;
        self.jacobian.add_one(row, column, speed);
        self.gamma[row] = -(l.d1[0] * l.d2[0] + l.d1[1] * l.d2[1]) / speed * ud * ud;
    }

    /// Row a₁(u₁) − σ a₂(u₂) − (a₁ − σ a₂ as drawn) = 0: a the arc length
    /// along each curve, σ = ±1 as the tangents run the same way or not
    /// (the contact point advances as far along both curves).
    fn rolling(&mut self, row: usize, contact: &Contact, [one, two]: [&Side; 2]) {
        let [k1, k2] = &contact.curves;
        let (t1, t2) = (self.rot(one.body, one.l.d1), self.rot(two.body, two.l.d1));
        let sigma = if t1[0] * t2[0] + t1[1] * t2[1] >= 0.0 { 1.0 } else { -1.0 };
        let (u1, u2) = (one.column.map_or(0.0, |c| self.s.q[c]), two.column.map_or(0.0, |c| self.s.q[c]));
        let drawn = k1.arc(contact.drawn[0]) - sigma * k2.arc(contact.drawn[1]);
        self.phi[row] = k1.arc(u1) - sigma * k2.arc(u2) - drawn;
        let speed = |l: &Local| l.d1[0].hypot(l.d1[1]);
        // d|c′|/du = c′·c″/|c′|.
        let bend = |l: &Local| (l.d1[0] * l.d2[0] + l.d1[1] * l.d2[1]) / speed(l);
        if let Some(c) = one.column {
            self.jacobian.add_one(row, c, speed(&one.l));
        }
        if let Some(c) = two.column {
            self.jacobian.add_one(row, c, -sigma * speed(&two.l));
        }
        self.gamma[row] = -(bend(&one.l) * one.ud * one.ud - sigma * bend(&two.l) * two.ud * two.ud);
    }

    /// Rows 2: P₂ − P₁ = 0.
    fn coincidence(&mut self, row: usize, one: &Side, two: &Side) {
        let (p1, p2) = (self.point(one.body, one.l.r).0, self.point(two.body, two.l.r).0);
        let (b1, b2) = (self.rot_d(one.body, one.l.r), self.rot_d(two.body, two.l.r));
        let (t1, t2) = (self.rot(one.body, one.l.d1), self.rot(two.body, two.l.d1));
        let (h1, h2) =
            (self.quadratic(one, [one.l.r, one.l.d1, one.l.d2]), self.quadratic(two, [two.l.r, two.l.d1, two.l.d2]));
        for k in 0..2 {
            self.phi[row + k] = p2[k] - p1[k];
            let e = if k == 0 { [1.0, 0.0] } else { [0.0, 1.0] };
            self.add(row + k, two.body, e, b2[k]);
            self.add(row + k, one.body, [-e[0], -e[1]], -b1[k]);
            if let Some(c) = two.column {
                self.jacobian.add_one(row + k, c, t2[k]);
            }
            if let Some(c) = one.column {
                self.jacobian.add_one(row + k, c, -t1[k]);
            }
            self.gamma[row + k] = h1[k] - h2[k];
        }
    }

    /// Row T₁ × T₂ = 0.
    fn tangency(&mut self, row: usize, one: &Side, two: &Side) {
        let (t1, t2) = (self.rot(one.body, one.l.d1), self.rot(two.body, two.l.d1));
        self.phi[row] = cross(t1, t2);
        let (bt1, bt2) = (self.rot_d(one.body, one.l.d1), self.rot_d(two.body, two.l.d1));
        let (n1, n2) = (self.rot(one.body, one.l.d2), self.rot(two.body, two.l.d2));
        self.add(row, one.body, [0.0, 0.0], cross(bt1, t2));
        self.add(row, two.body, [0.0, 0.0], cross(t1, bt2));
        if let Some(c) = one.column {
            self.jacobian.add_one(row, c, cross(n1, t2));
        }
        if let Some(c) = two.column {
            self.jacobian.add_one(row, c, cross(t1, n2));
        }
        // Ṫ = B c′ θ̇ + A c″ u̇; the quadratic part of T̈ is h with v = c′.
        let rate = |s: &Side, bt: [f64; 2], n: [f64; 2]| [bt[0] * s.w + n[0] * s.ud, bt[1] * s.w + n[1] * s.ud];
        let (d1, d2) = (rate(one, bt1, n1), rate(two, bt2, n2));
        let (h1, h2) =
            (self.quadratic(one, [one.l.d1, one.l.d2, one.l.d3]), self.quadratic(two, [two.l.d1, two.l.d2, two.l.d3]));
        self.gamma[row] = -(cross(h1, t2) + 2.0 * cross(d1, d2) + cross(t1, h2));
    }
}
