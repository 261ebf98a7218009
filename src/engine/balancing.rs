//! Balancing of a rigid rotor (equilibrado) in one or two correction planes.
//!
//! Symbols: the rotor turns about z; a mass mᵢ at radius rᵢ, angle θᵢ (CCW
//! from the rotor's x axis) and axial position zᵢ is the vector
//! mᵢrᵢ(cos θᵢ, sin θᵢ) in its plane.
//! - U = Σ mᵢrᵢ e^{iθᵢ}, the static unbalance (kg·m): the centrifugal
//!   force of the rotor at speed ω is ω²U.
//! - D(z₀) = Σ mᵢrᵢ(zᵢ − z₀) e^{iθᵢ}, the dynamic unbalance about the plane
//!   z₀ (kg·m²): the moment of the centrifugal forces about the axis' point
//!   at z₀ is ω²·k × D(z₀). D(z₀) = D(0) − z₀U, so a rotor is kept as U and D(0).
//! - Correction planes k at z_k with radius R_k: corrections C_k = m_k R_k e^{iα_k}.
//!   One plane (static balancing): C₁ = −U. Two planes z₁ < z₂ (dynamic
//!   balancing): U + C₁ + C₂ = 0 and D(z₁) + (z₂ − z₁)C₂ = 0, so
//!   C₂ = −D(z₁)/(z₂ − z₁), C₁ = −U − C₂.
//! - Bearings A, B at z_A ≠ z_B: the forces they put on the rotor, turning
//!   at ω with no other load, R_A + R_B = −ω²U and (z_B − z_A)R_B = −ω²D(z_A)
//!   (the rotor's own frame, at angle 0).

use nalgebra::Vector2;

/// A vector in a plane normal to the axis, (x, y); as a complex number x + iy.
pub type Planar = Vector2<f64>;

/// A point mass: m (kg), r (m), θ (rad), z (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mass {
    pub m: f64,
    pub r: f64,
    pub theta: f64,
    pub z: f64,
}

/// A correction plane: its axial position z and the radius R where its mass goes (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub z: f64,
    pub radius: f64,
}

/// A rotor's unbalance: U (kg·m) and D(0) (kg·m², about z = 0).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Unbalance {
    pub u: Planar,
    pub d0: Planar,
}

impl Unbalance {
    /// Of point masses.
    pub fn of(masses: &[Mass]) -> Self {
        masses.iter().fold(Self::default(), |acc, p| {
            let (s, c) = p.theta.sin_cos();
            acc.with(p.m * p.r * Vector2::new(c, s), p.z)
        })
    }

    /// D(z₀) = D(0) − z₀U.
    pub fn about(&self, z0: f64) -> Planar {
        self.d0 - z0 * self.u
    }

    /// With a vector C added in the plane z.
    fn with(self, c: Planar, z: f64) -> Self {
        Self { u: self.u + c, d0: self.d0 + z * c }
    }
}

/// A correction: its plane, the mass at the plane's radius, its angle (rad) and m·R (kg·m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Correction {
    pub plane: Plane,
    pub mass: f64,
    pub angle: f64,
    pub mass_radius: f64,
}

/// The corrections in the given planes (one or two, ordered by z, distinct
/// z and positive radii: validated by the caller) and the unbalance left.
pub fn balance(before: Unbalance, planes: &[Plane]) -> (Vec<Correction>, Unbalance) {
    let vectors: Vec<Planar> = match planes {
        [_] => vec![-before.u],
        [p1, p2, ..] => {
            let c2 = -before.about(p1.z) / (p2.z - p1.z);
            vec![-before.u - c2, c2]
        }
        [] => Vec::new(),
    };
    let after = planes.iter().zip(&vectors).fold(before, |u, (p, c)| u.with(*c, p.z));
    let corrections = planes
        .iter()
        .zip(&vectors)
        .map(|(plane, c)| {
            let (mass_radius, angle) = polar(*c);
            Correction { plane: *plane, mass: mass_radius / plane.radius, angle, mass_radius }
        })
        .collect();
    (corrections, after)
}

/// The forces the bearings at `[z_A, z_B]` put on the rotor turning at ω,
/// in its own frame at angle 0: [R_A, R_B].
pub fn bearing_forces(u: &Unbalance, omega: f64, [za, zb]: [f64; 2]) -> [Planar; 2] {
    let w2 = omega * omega;
    let rb = -w2 / (zb - za) * u.about(za);
    [-w2 * u.u - rb, rb]
}

/// The magnitude of a planar vector and its angle in [0, 2π) (0 for the zero vector).
pub fn polar(v: Planar) -> (f64, f64) {
    let value = v.norm();
    (value, if value > 0.0 { v.y.atan2(v.x).rem_euclid(std::f64::consts::TAU) } else { 0.0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A single mass balanced in two planes: the corrections split it by
    /// the lever rule (closed form: m₁ = m·(z₂ − z)/(z₂ − z₁) opposite it).
    #[test]
    fn one_mass_splits_by_the_lever_rule() {
        let mass = Mass { m: 0.2, r: 0.1, theta: 0.5, z: 0.3 };
        let planes = [Plane { z: 0.0, radius: 0.05 }, Plane { z: 0.4, radius: 0.1 }];
        let (c, after) = balance(Unbalance::of(&[mass]), &planes);
        // m·r = 0.02 kg·m; lever: 0.02·0.1/0.4 in plane 1, 0.02·0.3/0.4 in plane 2.
        assert!((c[0].mass_radius - 0.005).abs() < 1e-15 && (c[1].mass_radius - 0.015).abs() < 1e-15);
        assert!((c[0].mass - 0.1).abs() < 1e-14 && (c[1].mass - 0.15).abs() < 1e-14);
        let opposite = 0.5 + std::f64::consts::PI;
        assert!((c[0].angle - opposite).abs() < 1e-12 && (c[1].angle - opposite).abs() < 1e-12);
        assert!(polar(after.u).0 < 1e-17 && polar(after.d0).0 < 1e-17);
    }

    /// Bearing forces by the lever rule: a mass midway loads both bearings
    /// equally with half of m·r·ω², towards the mass's opposite.
    #[test]
    fn a_mass_midway_loads_both_bearings_alike() {
        let u = Unbalance::of(&[Mass { m: 1.0, r: 0.01, theta: 0.0, z: 0.5 }]);
        let [ra, rb] = bearing_forces(&u, 100.0, [0.0, 1.0]);
        // m·r·ω² = 100 N, half on each, pulling the rotor back towards the axis (−x).
        assert!((ra.x + 50.0).abs() < 1e-12 && (rb.x + 50.0).abs() < 1e-12);
        assert!(ra.y.abs() < 1e-15 && rb.y.abs() < 1e-15);
    }
}
