//! Vectors of the plane: the dot product, the z-component of the cross
//! product, the normal of a direction, and the size of a set of points.

/// The unit normal (−u_y, u_x) of a direction u (u turned +90°).
pub fn perp(u: [f64; 2]) -> [f64; 2] {
    [-u[1], u[0]]
}

pub fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// The diagonal of the box round `points` (0 for one point, NaN for none).
pub fn diagonal(points: impl IntoIterator<Item = [f64; 2]>) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// z-component of a × b.
pub fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
