//! Vectors of the plane: the dot product, the z-component of the cross
//! product, and the normal of a direction.

/// The unit normal (−u_y, u_x) of a direction u (u turned +90°).
pub fn perp(u: [f64; 2]) -> [f64; 2] {
    [-u[1], u[0]]
}

pub fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// z-component of a × b.
pub fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
