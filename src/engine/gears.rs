//! Involute spur gear geometry (standard full-depth teeth).
//!
//! Symbols: module m, teeth z, pressure angle φ_A at the pitch circle;
//! pitch radius R_A = m·z/2, base radius R_b = R_A cos φ_A; addendum and
//! dedendum as multiples of m. The involute function is inv φ = tan φ − φ, and
//! the tooth thickness on the circle of radius R_T is
//!
//! ```text
//! e_T = R_T·[e_A/R_A + 2(inv φ_A − inv φ_T)],   R_A cos φ_A = R_T cos φ_T,
//! ```
//!
//! with e_A = πm/2 at the pitch circle. An internal gear's (a ring's) tooth
//! is the space of the external gear of the same z and m, so on that circle
//! it is the circular pitch less e_T:
//!
//! ```text
//! e_T,ring = 2π·R_T/z − e_T = 2R_T·(π/(2z) − inv φ_A + inv φ_T).
//! ```

use std::f64::consts::PI;

/// A standard gear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gear {
    pub module: f64,
    pub teeth: f64,
    pub pressure_angle: f64,
    /// Addendum and dedendum in modules (1 and 1.25 for full-depth teeth).
    pub addendum: f64,
    pub dedendum: f64,
    /// An internal gear (ring): its tip circle is inside the pitch circle.
    pub internal: bool,
}

/// Radii of a gear, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Radii {
    pub pitch: f64,
    pub base: f64,
    pub tip: f64,
    pub root: f64,
}

/// The tooth on one circle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Thickness {
    pub radius: f64,
    /// φ_T, rad.
    pub pressure_angle: f64,
    /// e_T, m (arc length on that circle).
    pub thickness: f64,
}

/// inv φ = tan φ − φ.
pub fn involute(phi: f64) -> f64 {
    phi.tan() - phi
}

impl Gear {
    pub fn radii(&self) -> Radii {
        let pitch = self.module * self.teeth / 2.0;
        let (a, d) = (self.addendum * self.module, self.dedendum * self.module);
        let (tip, root) = if self.internal { (pitch - a, pitch + d) } else { (pitch + a, pitch - d) };
        Radii { pitch, base: pitch * self.pressure_angle.cos(), tip, root }
    }

    /// The tooth thickness on the circle of radius `radius`, or None below the
    /// base circle (no involute there).
    pub fn thickness_at(&self, radius: f64) -> Option<Thickness> {
        let r = self.radii();
        let cos_t = r.base / radius;
        if !(0.0..=1.0).contains(&cos_t) {
            return None;
        }
        let phi_t = cos_t.acos();
        let e_a = PI * self.module / 2.0;
        let external = radius * (e_a / r.pitch + 2.0 * (involute(self.pressure_angle) - involute(phi_t)));
        let thickness = if self.internal { 2.0 * PI * radius / self.teeth - external } else { external };
        Some(Thickness { radius, pressure_angle: phi_t, thickness })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At the pitch circle the formula gives back e_A = πm/2 (identity).
    #[test]
    fn the_thickness_at_the_pitch_circle_is_half_the_circular_pitch() {
        let g = Gear {
            module: 0.004,
            teeth: 30.0,
            pressure_angle: 20f64.to_radians(),
            addendum: 1.0,
            dedendum: 1.25,
            internal: false,
        };
        let t = g.thickness_at(g.radii().pitch).unwrap();
        assert!((t.thickness - PI * 0.002).abs() < 1e-15);
        assert!(g.thickness_at(0.9 * g.radii().base).is_none());
        let ring = Gear { internal: true, ..g };
        assert!((ring.thickness_at(g.radii().pitch).unwrap().thickness - PI * 0.002).abs() < 1e-15);
    }

    /// A ring's tooth is thinnest at its tip (inside the pitch circle) and
    /// thickens toward its root, where an external tooth does the reverse;
    /// the two add up to the circular pitch on every circle (identity).
    #[test]
    fn a_rings_tooth_is_the_external_gears_space() {
        let g = Gear {
            module: 0.002,
            teeth: 72.0,
            pressure_angle: 20f64.to_radians(),
            addendum: 1.0,
            dedendum: 1.25,
            internal: false,
        };
        let ring = Gear { internal: true, ..g };
        let (tip, root) = (ring.radii().tip, ring.radii().root);
        let at = |gear: &Gear, r: f64| gear.thickness_at(r).unwrap().thickness;
        assert!(
            at(&ring, tip) < at(&ring, root),
            "ring: {} at the tip, {} at the root",
            at(&ring, tip),
            at(&ring, root)
        );
        for r in [tip, 0.072, root] {
            assert!((at(&ring, r) + at(&g, r) - 2.0 * PI * r / 72.0).abs() < 1e-15);
        }
    }
}
