//! The isometric view of the spatial drawings (a mechanism, a free body):
//! seen from (1, 1, 1) with one axis upright — the one against gravity, y
//! without gravity — and the other two 30° below the horizontal, so that
//! the axes stay right-handed on the page.

use std::ops::Index;

/// Which axis is up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct View {
    pub up: usize,
}

impl View {
    /// The axis along which gravity `g` acts (its largest component) up; y without gravity.
    pub fn against(g: &impl Index<usize, Output = f64>) -> Self {
        let size = [g[0].abs(), g[1].abs(), g[2].abs()];
        let largest = (0..3).max_by(|&a, &b| size[a].total_cmp(&size[b])).unwrap_or(1);
        Self { up: if size[largest] > 0.0 { largest } else { 1 } }
    }

    /// "x", "y" or "z".
    pub fn up_name(self) -> &'static str {
        ["x", "y", "z"][self.up]
    }

    /// (u, v) on the page of a point in space: of the two axes after `up`
    /// in turn, the first drawn 30° below the horizontal to the left, the
    /// second to the right.
    pub fn project(self, p: &impl Index<usize, Output = f64>) -> (f64, f64) {
        let (a, b) = (p[(self.up + 1) % 3], p[(self.up + 2) % 3]);
        let (s, c) = std::f64::consts::FRAC_PI_6.sin_cos();
        ((b - a) * c, p[self.up] - (a + b) * s)
    }
}

#[cfg(test)]
mod tests {
    use super::View;

    /// An isometric view looks along (1, 1, 1): that direction falls on the
    /// page's origin, each axis is drawn the same length, and x, y, z go
    /// round counter-clockwise 120° apart (a right-handed frame seen from
    /// outside), whichever axis is up.
    #[test]
    fn the_view_is_isometric_and_right_handed() {
        for up in 0..3 {
            let view = View { up };
            let (u, v) = view.project(&[1.0, 1.0, 1.0]);
            assert!(u.abs() < 1e-15 && v.abs() < 1e-15, "up {up}: ({u}, {v})");
            let axis = |k: usize| std::array::from_fn::<f64, 3, _>(|i| f64::from(u8::from(i == k)));
            let angle = |k: usize| {
                let (u, v) = view.project(&axis(k));
                assert!((u.hypot(v) - 1.0).abs() < 1e-15);
                v.atan2(u)
            };
            for k in 0..3 {
                let turn = (angle((k + 1) % 3) - angle(k)).rem_euclid(std::f64::consts::TAU);
                assert!((turn - 2.0 * std::f64::consts::FRAC_PI_3).abs() < 1e-12, "up {up}, axis {k}: {turn}");
            }
            let (u, v) = view.project(&axis(up));
            assert!(u.abs() < 1e-15 && (v - 1.0).abs() < 1e-15);
        }
    }

    /// Gravity along −z puts z up; none puts y up.
    #[test]
    fn up_is_against_gravity() {
        assert_eq!(View::against(&[0.0, 0.0, -9.81]).up_name(), "z");
        assert_eq!(View::against(&[0.0, 0.0, 0.0]).up_name(), "y");
    }
}
