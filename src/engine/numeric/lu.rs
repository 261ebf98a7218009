//! Dense LU with partial pivoting, P A = L U, over storage kept from one
//! factorisation to the next: a sweep over thousands of positions factors
//! a Φ_q of the same size at each and allocates nothing after the first.
//! One factorisation serves A x = b and the transposed Aᵀ y = c
//! (Aᵀ = Uᵀ Lᵀ P: the multipliers from the factors the velocities used).
//!
//! nalgebra's LU takes its matrix by value and allocates its permutation
//! and, for the transposed solve, copies of L and U at every call; this is
//! the same algorithm (LAPACK's xGETRF with xGETRS, unblocked) in place.

use nalgebra::DMatrix;

/// The factors of a square matrix: L (unit diagonal, not stored) below the
/// diagonal and U on and above it, column-major; `swaps[k]` is the row
/// exchanged with row k at step k.
#[derive(Clone, Debug, Default)]
pub struct Lu {
    n: usize,
    lu: Vec<f64>,
    swaps: Vec<usize>,
    /// 1/u_kk: the solves multiply where they would divide (a division's
    /// latency, in the chain of a triangular solve, was half its time).
    inverse_pivots: Vec<f64>,
    /// No pivot is zero or subnormal (the solves are defined).
    regular: bool,
}

impl Lu {
    /// Factors `a` into this storage; false if a pivot is zero (or subnormal) or `a` is
    /// not square (the solves then refuse).
    pub fn factor(&mut self, a: &DMatrix<f64>) -> bool {
        self.regular = false;
        if !a.is_square() {
            return false;
        }
        let n = a.nrows();
        self.n = n;
        self.lu.clear();
        self.lu.extend_from_slice(a.as_slice());
        self.swaps.clear();
        self.swaps.resize(n, 0);
        self.inverse_pivots.clear();
        self.inverse_pivots.resize(n, 0.0);
        self.regular = by_size!(n, factor_in(&mut self.lu, &mut self.swaps, &mut self.inverse_pivots));
        self.regular
    }

    /// Whether the last factorisation had no zero (or subnormal) pivot.
    pub fn is_regular(&self) -> bool {
        self.regular
    }

    /// x with A x = b, in place of b; false (b then undefined) if A is
    /// singular or x is not finite.
    pub fn solve(&self, b: &mut [f64]) -> bool {
        let n = self.n;
        self.regular && b.len() == n && by_size!(n, solve_in(&self.lu, &self.swaps, &self.inverse_pivots, b))
    }

    /// y with Aᵀ y = c, in place of c: Uᵀ w = c, Lᵀ z = w, y = Pᵀ z.
    pub fn solve_transposed(&self, c: &mut [f64]) -> bool {
        let n = self.n;
        self.regular && c.len() == n && by_size!(n, solve_transposed_in(&self.lu, &self.swaps, &self.inverse_pivots, c))
    }

    /// ‖A⁻¹‖₁: exact up to [`EXACT_UP_TO`] rows ([`Lu::inverse_norms1`]),
    /// else by Hager's estimator (Higham, *Accuracy and Stability of
    /// Numerical Algorithms*, Alg. 15.1, as LAPACK's xGECON): ‖A⁻¹x‖₁ over
    /// unit vectors x, ascending until x is a local maximiser; a lower
    /// bound, in practice within a factor 3. `y` is scratch; `x` is the
    /// estimator's start and ends as the maximiser found: a sweep hands it
    /// to the next position, where it is usually a maximiser again (one
    /// solve each way instead of two), else n⁻¹·(1, …, 1) starts.
    pub fn inverse_norm1(&self, x: &mut Vec<f64>, y: &mut Vec<f64>) -> f64 {
        self.scaled_inverse_norm1(x, y, [&[], &[]])
    }

    /// ‖(R A C)⁻¹‖₁ = ‖C⁻¹ A⁻¹ R⁻¹‖₁ for diagonal scalings R = diag(`rows`)
    /// and C = diag(`cols`) (an empty slice: the identity), as
    /// [`Lu::inverse_norm1`] finds ‖A⁻¹‖₁.
    pub fn scaled_inverse_norm1(&self, x: &mut Vec<f64>, y: &mut Vec<f64>, scales: [&[f64]; 2]) -> f64 {
        if self.n <= EXACT_UP_TO {
            return self.exact_norms1(scales)[1];
        }
        self.estimated_norm1(x, y, scales)
    }

    /// [‖A⁻¹‖₁, ‖(R A C)⁻¹‖₁] as [`Lu::inverse_norm1`] and
    /// [`Lu::scaled_inverse_norm1`] find each (`x`, `xs` their
    /// estimators' maximisers), from one A⁻¹ where it is formed.
    pub fn inverse_norms1(&self, [x, xs, y]: [&mut Vec<f64>; 3], scales: [&[f64]; 2]) -> [f64; 2] {
        if self.n <= EXACT_UP_TO {
            return self.exact_norms1(scales);
        }
        [self.estimated_norm1(x, y, [&[], &[]]), self.estimated_norm1(xs, y, scales)]
    }

    /// The two norms of [`Lu::inverse_norms1`] from A⁻¹ formed from the
    /// factors; infinite where A is singular or A⁻¹ not finite.
    fn exact_norms1(&self, scales: [&[f64]; 2]) -> [f64; 2] {
        let n = self.n;
        let norms =
            self.regular.then(|| by_size!(n, inverse_norms_in(&self.lu, &self.swaps, &self.inverse_pivots, scales)));
        norms.flatten().unwrap_or([f64::INFINITY; 2])
    }

    /// Hager's estimate of ‖(R A C)⁻¹‖₁ (see [`Lu::inverse_norm1`]).
    fn estimated_norm1(&self, x: &mut Vec<f64>, y: &mut Vec<f64>, [rows, cols]: [&[f64]; 2]) -> f64 {
        let n = self.n;
        if x.len() != n {
            x.clear();
            x.resize(n, 1.0 / n as f64);
        }
        let divide = |v: &mut [f64], d: &[f64]| v.iter_mut().zip(d).for_each(|(v, d)| *v /= d);
        let mut estimate = f64::INFINITY;
        for _ in 0..5 {
            y.clear();
            y.extend_from_slice(x);
            divide(y, rows);
            if !self.solve(y) {
                return f64::INFINITY;
            }
            divide(y, cols);
            estimate = y.iter().map(|v| v.abs()).sum();
            // z = (RAC)⁻ᵀ sign(y) = R⁻¹ A⁻ᵀ C⁻¹ sign(y), in y's place; x·z before x changes.
            y.iter_mut().for_each(|v| *v = if *v >= 0.0 { 1.0 } else { -1.0 });
            divide(y, cols);
            if !self.solve_transposed(y) {
                return f64::INFINITY;
            }
            divide(y, rows);
            let j = (0..n).fold(0, |j, i| if y[i].abs() > y[j].abs() { i } else { j });
            let zx: f64 = y.iter().zip(x.iter()).map(|(a, b)| a * b).sum();
            if y[j].abs() <= zx {
                break;
            }
            x.iter_mut().enumerate().for_each(|(i, v)| *v = if i == j { 1.0 } else { 0.0 });
        }
        estimate
    }
}

/// The largest matrix whose inverse's norms are found exactly: A⁻¹ costs
/// n³ multiply-adds, each step over a whole row of it (independent sums),
/// where the estimator's four or more triangular solves of n²/2 each wait
/// on their last step; at n = 8 and 9 (a cam, a slider-crank) forming A⁻¹
/// took less than the estimate (docs/BENCHMARKS.md).
pub const EXACT_UP_TO: usize = 12;

/// `f::<N>(args)` with N = n for the sizes of planar mechanisms of up to
/// six moving bodies (three coordinates each) and the augmented matrices
/// [M Φ_qᵀ; Φ_q 0] of up to three (3 to 11: a point mass on a link is 5),
/// where the compiler unrolls the loops below (a 9×9 solve: 125 → 75 ns;
/// 39 ns once the solves multiply by the pivots' reciprocals); `f::<0>`
/// (n read at run time) for other sizes.
macro_rules! by_size {
    ($n:expr, $f:ident($($arg:expr),*)) => {
        match $n {
            3 => $f::<3>($n, $($arg),*),
            4 => $f::<4>($n, $($arg),*),
            5 => $f::<5>($n, $($arg),*),
            6 => $f::<6>($n, $($arg),*),
            7 => $f::<7>($n, $($arg),*),
            8 => $f::<8>($n, $($arg),*),
            9 => $f::<9>($n, $($arg),*),
            10 => $f::<10>($n, $($arg),*),
            11 => $f::<11>($n, $($arg),*),
            12 => $f::<12>($n, $($arg),*),
            15 => $f::<15>($n, $($arg),*),
            18 => $f::<18>($n, $($arg),*),
            _ => $f::<0>($n, $($arg),*),
        }
    };
}
use by_size;

/// P A = L U in place of A (n×n, column-major), the exchanges in `swaps`
/// and 1/u_kk in `inverse` (length n); false if a pivot is zero or
/// subnormal (its reciprocal overflows: κ beyond 1e308).
fn factor_in<const N: usize>(n: usize, a: &mut [f64], swaps: &mut [usize], inverse: &mut [f64]) -> bool {
    let n = if N > 0 { N } else { n };
    let (a, swaps, inverse) = (&mut a[..n * n], &mut swaps[..n], &mut inverse[..n]);
    let mut regular = true;
    for k in 0..n {
        let column = &a[k * n..(k + 1) * n];
        let p = (k + 1..n).fold(k, |p, i| if column[i].abs() > column[p].abs() { i } else { p });
        swaps[k] = p;
        if p != k {
            (0..n).for_each(|j| a.swap(j * n + k, j * n + p));
        }
        let pivot = a[k * n + k];
        if pivot.abs() < f64::MIN_POSITIVE {
            regular = false;
            continue;
        }
        let (left, right) = a.split_at_mut((k + 1) * n);
        let l = &mut left[k * n + k + 1..];
        inverse[k] = 1.0 / pivot;
        l.iter_mut().for_each(|v| *v *= inverse[k]);
        for column in right.chunks_exact_mut(n) {
            let u = column[k];
            if u != 0.0 {
                column[k + 1..].iter_mut().zip(l.iter()).for_each(|(a, l)| *a -= l * u);
            }
        }
    }
    regular
}

/// x with A x = b in place of b, from `factor_in`'s factors.
fn solve_in<const N: usize>(n: usize, a: &[f64], swaps: &[usize], inverse: &[f64], b: &mut [f64]) -> bool {
    let n = if N > 0 { N } else { n };
    let (a, swaps, inverse, b) = (&a[..n * n], &swaps[..n], &inverse[..n], &mut b[..n]);
    for (k, &p) in swaps.iter().enumerate() {
        b.swap(k, p);
    }
    for (j, column) in a.chunks_exact(n).enumerate() {
        let (done, rest) = b.split_at_mut(j + 1);
        let x = done[j];
        rest.iter_mut().zip(&column[j + 1..]).for_each(|(v, l)| *v -= l * x);
    }
    for (j, column) in a.chunks_exact(n).enumerate().rev() {
        let (rest, done) = b.split_at_mut(j);
        done[0] *= inverse[j];
        let x = done[0];
        rest.iter_mut().zip(&column[..j]).for_each(|(v, u)| *v -= u * x);
    }
    b.iter().all(|v| v.is_finite())
}

/// y with Aᵀ y = c in place of c, from `factor_in`'s factors.
fn solve_transposed_in<const N: usize>(n: usize, a: &[f64], swaps: &[usize], inverse: &[f64], c: &mut [f64]) -> bool {
    let n = if N > 0 { N } else { n };
    let (a, swaps, inverse, c) = (&a[..n * n], &swaps[..n], &inverse[..n], &mut c[..n]);
    // Along the rows of U and L (stride n), so that no sum waits on the last.
    for j in 0..n {
        c[j] *= inverse[j];
        let w = c[j];
        (j + 1..n).for_each(|k| c[k] -= a[k * n + j] * w);
    }
    for j in (0..n).rev() {
        let z = c[j];
        (0..j).for_each(|k| c[k] -= a[k * n + j] * z);
    }
    for (k, &p) in swaps.iter().enumerate().rev() {
        c.swap(k, p);
    }
    c.iter().all(|v| v.is_finite())
}

/// A row of A⁻¹ as [`inverse_norms_in`] forms it (the first n entries used).
type Row = [f64; EXACT_UP_TO];

/// [‖A⁻¹‖₁, ‖C⁻¹ A⁻¹ R⁻¹‖₁] (R = diag(r_j), C = diag(c_i); missing
/// entries 1) from `factor_in`'s factors: A⁻¹ = U⁻¹ L⁻¹ P formed from P's
/// rows with L and U solved for every column at once, a whole row at a
/// time (n³ multiply-adds: on L's triangle alone, 2n³/3 as LAPACK's
/// xGETRI, the rows' lengths known only at run time made it no faster at
/// n = 8 and 9), then its column sums; None if an entry is not finite.
fn inverse_norms_in<const N: usize>(
    n: usize,
    a: &[f64],
    swaps: &[usize],
    inverse: &[f64],
    [rows, cols]: [&[f64]; 2],
) -> Option<[f64; 2]> {
    let n = if N > 0 { N } else { n };
    // `by_size!` makes this for 15 and 18 rows too, which the callers never ask: nothing then.
    if n > EXACT_UP_TO {
        return None;
    }
    let (a, swaps, inverse) = (&a[..n * n], &swaps[..n], &inverse[..n]);
    let mut x = [[0.0; EXACT_UP_TO]; EXACT_UP_TO];
    let x = &mut x[..n];
    let mut order: [usize; EXACT_UP_TO] = std::array::from_fn(|i| i);
    for (k, &p) in swaps.iter().enumerate() {
        order.swap(k, p);
    }
    x.iter_mut().zip(&order).for_each(|(row, &j)| row[j] = 1.0);
    // x_i −= m·x_j over a whole row; Φ_q's factors are mostly zeros (a
    // joint's rows touch two bodies), their pattern the same at every position.
    let update = |target: &mut Row, m: f64, source: &Row| {
        if m != 0.0 {
            target[..n].iter_mut().zip(&source[..n]).for_each(|(t, s)| *t -= m * s);
        }
    };
    for j in 0..n {
        let source = x[j];
        for (i, target) in x.iter_mut().enumerate().skip(j + 1) {
            update(target, a[j * n + i], &source);
        }
    }
    for j in (0..n).rev() {
        x[j][..n].iter_mut().for_each(|v| *v *= inverse[j]);
        let source = x[j];
        for (i, target) in x[..j].iter_mut().enumerate() {
            update(target, a[j * n + i], &source);
        }
    }
    // (C⁻¹ A⁻¹ R⁻¹)_ij = x_ij / (c_i r_j): column j's sums, plain and over c_i.
    let (mut plain, mut scaled) = ([0.0f64; EXACT_UP_TO], [0.0f64; EXACT_UP_TO]);
    for (i, row) in x.iter().enumerate() {
        let over_c = 1.0 / cols.get(i).copied().unwrap_or(1.0);
        for ((p, s), v) in plain[..n].iter_mut().zip(&mut scaled[..n]).zip(&row[..n]) {
            *p += v.abs();
            *s += v.abs() * over_c;
        }
    }
    let r = |j: usize| rows.get(j).copied().unwrap_or(1.0);
    let (mut largest, mut largest_scaled) = (0.0f64, 0.0f64);
    for j in 0..n {
        // NaN or ∞ in x makes its column's sum so.
        if !(plain[j].is_finite() && scaled[j].is_finite()) {
            return None;
        }
        (largest, largest_scaled) = (largest.max(plain[j]), largest_scaled.max(scaled[j] / r(j)));
    }
    Some([largest, largest_scaled])
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// Matrices with zeros on the diagonal (every step exchanges rows) of
    /// sizes compiled with n known (6, 9, 18) and not (7), and a 1×1: both
    /// solves against nalgebra's LU of A and of Aᵀ, to 1e-13 of the
    /// solution's size (rounding of well-conditioned matrices).
    #[test]
    fn both_solves_match_nalgebras_lu() {
        let zero_diagonal = |n: usize| {
            DMatrix::from_fn(n, n, |i, j| if i == j { 0.0 } else { ((3 * i + 5 * j) as f64).sin() + 0.1 * i as f64 })
        };
        let sizes = [6, 7, 9, 18].map(zero_diagonal);
        for a in sizes.into_iter().chain([DMatrix::from_element(1, 1, -2.5)]) {
            let n = a.nrows();
            let b = DVector::from_fn(n, |k, _| (k as f64).cos());
            let mut lu = Lu::default();
            assert!(lu.factor(&a));
            let (mut x, mut y) = (b.as_slice().to_vec(), b.as_slice().to_vec());
            assert!(lu.solve(&mut x) && lu.solve_transposed(&mut y));
            let want_x = a.clone().lu().solve(&b).unwrap();
            let want_y = a.transpose().lu().solve(&b).unwrap();
            for (got, want) in [(x, want_x), (y, want_y)] {
                let gap = got.iter().zip(want.iter()).map(|(g, w)| (g - w).abs()).fold(0.0, f64::max);
                assert!(gap <= 1e-13 * want.amax(), "{got:?} vs {want}");
            }
        }
    }

    /// Up to [`EXACT_UP_TO`] rows both norms of the inverse are its own, to
    /// 1e-13 of nalgebra's inverse (sizes with n known, 3 to 12, and not,
    /// 1, 2: every step exchanging rows); beyond, the estimate is a lower
    /// bound within a factor 3. A singular matrix has infinite norms.
    #[test]
    fn the_inverse_s_norms_are_exact_up_to_twelve_rows() {
        let zero_diagonal = |n: usize| {
            DMatrix::from_fn(n, n, |i, j| if i == j { 0.0 } else { ((3 * i + 5 * j) as f64).sin() + 0.1 * i as f64 })
        };
        for n in 1..=EXACT_UP_TO + 2 {
            let a = if n == 1 { DMatrix::from_element(1, 1, -2.5) } else { zero_diagonal(n) };
            let rows: Vec<f64> = (0..n).map(|i| 1.0 + 0.5 * i as f64).collect();
            let cols: Vec<f64> = (0..n).map(|j| if j % 3 == 2 { 1.0 } else { 0.02 }).collect();
            let inverse = a.clone().try_inverse().expect("regular");
            let scaled = DMatrix::from_fn(n, n, |i, j| inverse[(i, j)] / (cols[i] * rows[j]));
            let norm1 = |m: &DMatrix<f64>| m.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
            let want = [norm1(&inverse), norm1(&scaled)];
            let mut lu = Lu::default();
            assert!(lu.factor(&a));
            let [mut x, mut xs, mut y] = [Vec::new(), Vec::new(), Vec::new()];
            let got = lu.inverse_norms1([&mut x, &mut xs, &mut y], [&rows, &cols]);
            for (got, want) in got.into_iter().zip(want) {
                if n <= EXACT_UP_TO {
                    assert!((got - want).abs() <= 1e-13 * want, "n = {n}: {got} vs {want}");
                } else {
                    assert!(got <= want * (1.0 + 1e-13) && got >= want / 3.0, "n = {n}: {got} vs {want}");
                }
            }
            let alone = lu.scaled_inverse_norm1(&mut Vec::new(), &mut y, [&rows, &cols]);
            assert_eq!(alone.to_bits(), got[1].to_bits(), "n = {n}: alone as together");
        }
        let mut lu = Lu::default();
        lu.factor(&DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 0.0, 1.0, 1.0]));
        assert_eq!(
            lu.inverse_norms1([&mut Vec::new(), &mut Vec::new(), &mut Vec::new()], [&[], &[]]),
            [f64::INFINITY; 2]
        );
    }

    /// A zero pivot (a repeated row) makes the factors singular and the
    /// solves refuse; the same storage then factors a regular matrix again.
    #[test]
    fn a_singular_matrix_is_refused_and_the_storage_reused() {
        let mut lu = Lu::default();
        let singular = DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 0.0, 1.0, 1.0]);
        assert!(!lu.factor(&singular));
        assert!(!lu.solve(&mut [1.0, 1.0, 1.0]) && !lu.solve_transposed(&mut [1.0, 1.0, 1.0]));
        assert!(lu.factor(&DMatrix::from_row_slice(2, 2, &[0.0, 2.0, 4.0, 0.0])));
        let mut x = [2.0, 8.0];
        assert!(lu.solve(&mut x));
        assert_eq!(x, [2.0, 1.0], "x₀ = 8/4, x₁ = 2/2: exact in binary");
        // A subnormal pivot (κ ~ 1e310): its reciprocal would overflow, so it counts as zero.
        assert!(!lu.factor(&DMatrix::from_row_slice(2, 2, &[1e-310, 0.0, 1e-311, 1.0])));
        assert!(!lu.solve(&mut [0.0, 1.0]) && !lu.solve_transposed(&mut [1.0, 0.0]));
    }
}
