//! Tridiagonal systems in O(n): Thomas's algorithm, and a cyclic system
//! (the corner terms of a periodic spline) by Sherman–Morrison on it. The
//! splines' systems are strictly diagonally dominant, so neither pivots.

/// Solves the cyclic tridiagonal system (corner terms lower[0], upper[n−1]).
pub fn cyclic(a: &[f64], b: &[f64], c: &[f64], r: &[f64]) -> Vec<f64> {
    let n = b.len();
    let gamma = -b[0];
    let mut bb = b.to_vec();
    bb[0] -= gamma;
    bb[n - 1] -= a[0] * c[n - 1] / gamma;
    let x = solve(a, &bb, c, r);
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = c[n - 1];
    let z = solve(a, &bb, c, &u);
    let fact = (x[0] + a[0] * x[n - 1] / gamma) / (1.0 + z[0] + a[0] * z[n - 1] / gamma);
    x.iter().zip(&z).map(|(xi, zi)| xi - fact * zi).collect()
}

/// Thomas algorithm; a[0] and c[n−1] are ignored.
pub fn solve(a: &[f64], b: &[f64], c: &[f64], r: &[f64]) -> Vec<f64> {
    let n = b.len();
    let mut cp = vec![0.0; n];
    let mut x = vec![0.0; n];
    let mut beta = b[0];
    x[0] = r[0] / beta;
    for i in 1..n {
        cp[i] = c[i - 1] / beta;
        beta = b[i] - a[i] * cp[i];
        x[i] = (r[i] - a[i] * x[i - 1]) / beta;
    }
    for i in (0..n - 1).rev() {
        x[i] -= cp[i + 1] * x[i + 1];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both solvers against the dense system they stand for, multiplied
    /// back: residual at rounding (1e-12 of the right side).
    #[test]
    fn the_solutions_satisfy_their_systems() {
        let n = 7;
        let a: Vec<f64> = (0..n).map(|i| 1.0 + 0.1 * i as f64).collect();
        let b: Vec<f64> = (0..n).map(|i| 4.0 + 0.3 * i as f64).collect();
        let c: Vec<f64> = (0..n).map(|i| 0.9 - 0.05 * i as f64).collect();
        let r: Vec<f64> = (0..n).map(|i| (i as f64).sin() + 2.0).collect();
        for cyclic_system in [false, true] {
            let x = if cyclic_system { cyclic(&a, &b, &c, &r) } else { solve(&a, &b, &c, &r) };
            for i in 0..n {
                let mut lhs = b[i] * x[i];
                if i > 0 || cyclic_system {
                    lhs += a[i] * x[(i + n - 1) % n];
                }
                if i + 1 < n || cyclic_system {
                    lhs += c[i] * x[(i + 1) % n];
                }
                assert!((lhs - r[i]).abs() < 1e-12 * r[i].abs(), "row {i} ({cyclic_system}): {lhs} vs {}", r[i]);
            }
        }
    }
}
