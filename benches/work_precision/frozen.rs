//! A fixed workload that measures the host's speed and nothing of this
//! crate: at each of 3600 positions of a turn, a 9 × 9 matrix built from
//! the sines and cosines of three angles (a three-body Φ_q's shape and
//! size), its LU with partial pivoting, three solves with the factors, and
//! a record of the position kept in a growing list with a small allocation
//! of its own (about 1 MB a pass, read back and freed at its end) — the
//! kinds of work one kinetostatic position does, its memory's included,
//! so that a host whose caches and memory are contended slows it too.
//!
//! Do not edit: its time at the speed of 2026-11-27 was calibrated on
//! 2026-11-30 against that day's code (`bench/calibrate-gauge.sh`) and is
//! `gauge.rs`'s REFERENCE; a change needs the calibration run again. It
//! depends on nothing of the crate, so that the engine's changes, faster
//! or slower, do not move it.

use std::hint::black_box;

/// Coordinates (rows and columns) of the matrix.
const N: usize = 9;
/// Positions of a pass.
pub const POSITIONS: usize = 3600;

/// One pass over a turn; returns a sum of the solutions, so that nothing
/// can be left out.
pub fn pass() -> f64 {
    let step = black_box(std::f64::consts::TAU / POSITIONS as f64);
    let mut kept: Vec<([f64; 3 * N], Vec<f64>)> = Vec::new();
    for k in 0..POSITIONS {
        let mut a = matrix(k as f64 * step);
        let pivots = factor(&mut a);
        let mut x = [1.0; N];
        for _ in 0..3 {
            solve(&a, &pivots, &mut x);
        }
        let mut record = [0.0; 3 * N];
        record[..N].copy_from_slice(&x);
        record[N..2 * N].copy_from_slice(&a[N - 1]);
        record[2 * N..].copy_from_slice(&a[0]);
        kept.push((record, x.to_vec()));
    }
    kept.iter().map(|(record, x)| record[0] + record[2 * N] + x[N - 1]).sum()
}

/// A diagonally dominant matrix whose entries turn with φ.
fn matrix(phi: f64) -> [[f64; N]; N] {
    let trig = [phi.sin_cos(), (0.7 * phi + 0.2).sin_cos(), (1.3 * phi - 0.4).sin_cos()];
    let mut a = [[0.0; N]; N];
    for (i, row) in a.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            let (s, c) = trig[(i + j) % 3];
            *v = if i == j { 6.0 + c } else { 0.3 * s * (j as f64 - i as f64).signum() };
        }
    }
    a
}

/// LU in place (L's multipliers below the diagonal), row pivots returned.
#[allow(clippy::needless_range_loop)] // written as LAPACK's loops, and never to change (above)
fn factor(a: &mut [[f64; N]; N]) -> [usize; N] {
    let mut pivots = [0; N];
    for k in 0..N {
        let p = (k..N).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs())).unwrap_or(k);
        a.swap(k, p);
        pivots[k] = p;
        let inverse = 1.0 / a[k][k];
        for i in k + 1..N {
            let l = a[i][k] * inverse;
            a[i][k] = l;
            for j in k + 1..N {
                a[i][j] -= l * a[k][j];
            }
        }
    }
    pivots
}

/// x ← A⁻¹ x by the factors.
fn solve(a: &[[f64; N]; N], pivots: &[usize; N], x: &mut [f64; N]) {
    for (k, &p) in pivots.iter().enumerate() {
        x.swap(k, p);
    }
    for i in 0..N {
        x[i] -= (0..i).map(|j| a[i][j] * x[j]).sum::<f64>();
    }
    for i in (0..N).rev() {
        x[i] = (x[i] - (i + 1..N).map(|j| a[i][j] * x[j]).sum::<f64>()) / a[i][i];
    }
}
