//! The mechanism's size, and its coordinates measured in it.
//!
//! Symbols: L is the mechanism's size (m); c_j the length scale of
//! coordinate j — L for a length (x_G, y_G, a line's parameter, its arc
//! length), 1 for an angle (θ) or a closed curve's or spline's own
//! parameter. In the coordinates q_j / c_j and with each constraint row
//! divided by its own size, Φ_q is the same matrix for the mechanism
//! drawn at any scale (`numeric::scaled`).

use super::{Coordinate, Domain, JointKind, Mechanism};
use crate::engine::numeric::plane::diagonal;

impl Mechanism {
    /// L: the diagonal of the box round the bodies' centres of mass and the
    /// joints' points as drawn (1 m where these all coincide: a single point
    /// has no size of its own).
    pub fn size(&self) -> f64 {
        let points = self.bodies.iter().map(|b| b.cg).chain(self.joints.iter().map(|j| j.at));
        let l = diagonal(points);
        if l.is_finite() && l > 0.0 { l } else { 1.0 }
    }

    /// c_j of every coordinate, in column order.
    pub fn column_lengths(&self) -> Vec<f64> {
        let l = self.size();
        let bodies = (0..self.n_body_coordinates()).map(|k| if k % 3 == 2 { 1.0 } else { l });
        let curves = self
            .joints
            .iter()
            .filter_map(|j| match &j.kind {
                JointKind::Contact(c) => Some(c.curves.iter()),
                _ => None,
            })
            .flatten()
            .filter_map(|c| match c.domain() {
                Domain::None => None,
                Domain::Unbounded => Some(l),
                _ => Some(1.0),
            });
        bodies.chain(curves).collect()
    }

    /// Each input's length scale: L where φ is a length (a prismatic joint's
    /// or a contact's travel, a point's displacement), 1 where it is an angle.
    pub fn input_lengths(&self) -> impl Iterator<Item = f64> + '_ {
        let l = self.size();
        self.drivers.iter().map(move |d| match d.coordinate {
            Coordinate::Joint(k) => match self.joints[k].kind {
                JointKind::Prismatic { .. } | JointKind::Contact(_) => l,
                _ => 1.0,
            },
            Coordinate::Point { .. } => l,
            Coordinate::Body(_) => 1.0,
        })
    }
}
