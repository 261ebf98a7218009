//! Equivalent point-mass systems of a rigid link (course notes ch. 1 §5).
//!
//! Point masses m_i at points r_i (relative to the centre of mass G) are
//! *statically* equivalent to the link (mass m, inertia I_G about G) when
//! Σm_i = m and Σm_i r_i = 0, and *completely* equivalent when also
//! Σm_i |r_i|² = I_G. For a bar with masses at its ends A, B and at G:
//! m_A = I_G/(l·r_A), m_B = I_G/(l·r_B), m_G = m − I_G/(r_A r_B).

use super::numeric::svd::svd;
use nalgebra::{DMatrix, DVector};

/// The masses found, and how well and how uniquely they satisfy the conditions.
#[derive(Clone, Debug, PartialEq)]
pub struct Equivalent {
    pub masses: Vec<f64>,
    /// Largest residual of the four conditions, relative to m (and I_G).
    pub residual: f64,
    /// False when the points leave the masses undetermined (a minimum-norm set is given).
    pub unique: bool,
}

/// Masses at `points` (coordinates relative to G) completely equivalent to a
/// link of mass `mass` and inertia `inertia` about G.
pub fn equivalent_masses(mass: f64, inertia: f64, points: &[[f64; 2]]) -> Equivalent {
    let n = points.len();
    // Rows: mass, first moments in x and y, second moment (inertia about
    // G), each over its size in L (the farthest point from G): every row
    // of order 1, so that the rank is that of the drawing.
    let length = points.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let a = DMatrix::from_fn(4, n, |r, c| {
        let [x, y] = points[c].map(|v| v / length);
        [1.0, x, y, x * x + y * y][r]
    });
    let b = DVector::from_column_slice(&[mass, 0.0, 0.0, inertia / (length * length)]);
    // The API passes finite values only; a decomposition that fails leaves no masses.
    let Some(svd) = svd(a.clone(), true, true) else {
        return Equivalent { masses: vec![0.0; n], residual: f64::INFINITY, unique: false };
    };
    let tol = DRAWN * svd.singular_values.max().max(f64::MIN_POSITIVE);
    let rank = svd.singular_values.iter().filter(|s| **s > tol).count();
    let x = svd.solve(&b, tol).unwrap_or_else(|_| DVector::zeros(n));
    let r = &a * &x - &b;
    // Each condition against its own natural size: m, m·L and max(I_G, m·L²)
    // (over L², as the rows are; a link with I_G = 0 is measured by m·L²,
    // not by I_G).
    let m = mass.abs();
    let scale = [m, m, m, (inertia.abs() / (length * length)).max(m)];
    let relative = |k: usize| if r[k] == 0.0 { 0.0 } else { r[k].abs() / scale[k] };
    let residual = (0..4).map(relative).fold(0.0, f64::max);
    Equivalent { masses: x.iter().copied().collect(), residual, unique: rank == n }
}

/// Points within this fraction of the link's size of a line (or of each
/// other) are on it: the drawing's precision, not the masses' (1 nm off a
/// bar's line once made its three masses "no set matches").
const DRAWN: f64 = 1e-8;

#[cfg(test)]
mod tests {
    use super::*;

    /// Bar, m = 3 kg, I_G = 0.09 kg·m², A 0.2 m and B 0.4 m from G (l = 0.6):
    /// m_A = 0.09/(0.6·0.2) = 0.75, m_B = 0.09/(0.6·0.4) = 0.375,
    /// m_G = 3 − 0.09/(0.2·0.4) = 1.875 (closed form of the notes).
    #[test]
    fn a_bar_with_masses_at_its_ends_and_centre() {
        let e = equivalent_masses(3.0, 0.09, &[[-0.2, 0.0], [0.4, 0.0], [0.0, 0.0]]);
        for (m, want) in e.masses.iter().zip([0.75, 0.375, 1.875]) {
            assert!((m - want).abs() < 1e-12, "{:?}", e.masses);
        }
        assert!(e.unique && e.residual < 1e-12);
    }

    /// A 3 kg link with I_G = 0 (a point mass) and points at A, 0.2 m from
    /// G, and at G: all the mass at G matches exactly (m_G = 3, m_A = 0; by
    /// hand), so the residual is at rounding level, not divided by I_G = 0.
    #[test]
    fn a_point_mass_link_is_matched_by_its_mass_at_g() {
        let e = equivalent_masses(3.0, 0.0, &[[-0.2, 0.0], [0.0, 0.0]]);
        assert!(e.masses[0].abs() < 1e-12 && (e.masses[1] - 3.0).abs() < 1e-12, "{:?}", e.masses);
        assert!(e.residual < 1e-12, "{e:?}");
    }

    /// Two points cannot match mass, centre and inertia of any bar: the best
    /// fit leaves a residual, reported.
    #[test]
    fn two_arbitrary_points_are_not_completely_equivalent() {
        let e = equivalent_masses(3.0, 0.09, &[[-0.2, 0.0], [0.4, 0.0]]);
        assert!(e.residual > 1e-3, "{e:?}");
    }
}
