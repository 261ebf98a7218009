//! A matrix measured free of its rows' and columns' units.
//!
//! Symbols: C = diag(c_j), a length scale per column (a mechanism's
//! coordinates: its size L for a length, 1 for an angle,
//! `model::scale`); R = diag(r_i), r_i = 1 / max_j |a_ij c_j|, each row
//! of A C divided by its largest entry. Where A is a constraint Jacobian
//! drawn s times larger, a length row of A C grows by s and an angle row
//! not at all, so R A C is the same matrix at every scale: its condition
//! number decides singular positions and its rank the mobility, against
//! cut-offs that hold from micrometres to kilometres, and R Φ is the
//! residual Newton drives to zero.

use super::lu::Lu;
use nalgebra::DMatrix;

/// r_i of every row of `a` (1 for a row of zeros) into `rows`; `cols` holds
/// the c_j (empty: all 1).
pub fn row_scales(a: &DMatrix<f64>, cols: &[f64], rows: &mut Vec<f64>) {
    rows.clear();
    rows.resize(a.nrows(), 0.0);
    // Over the column-major storage: nalgebra's column iterator and f64::max
    // (NaN-aware) took more than the sweep's Newton solve.
    let columns = a.as_slice().chunks_exact(a.nrows().max(1));
    for (column, c) in columns.zip(cols.iter().chain(std::iter::repeat(&1.0))) {
        rows.iter_mut().zip(column).for_each(|(r, v)| {
            let v = (v * c).abs();
            *r = if v > *r || v.is_nan() { v } else { *r };
        });
    }
    rows.iter_mut().for_each(|r| *r = if *r > 0.0 && r.is_finite() { 1.0 / *r } else { 1.0 });
}

/// R A C.
pub fn scaled(a: &DMatrix<f64>, [rows, cols]: [&[f64]; 2]) -> DMatrix<f64> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| {
        a[(i, j)] * rows.get(i).copied().unwrap_or(1.0) * cols.get(j).copied().unwrap_or(1.0)
    })
}

/// κ₁(R A C) = ‖R A C‖₁ ‖(R A C)⁻¹‖₁ from A's LU ([`Lu::scaled_inverse_norm1`]:
/// exact up to 12 rows, else Hager's estimator, a lower bound, in practice
/// within a factor 3; empty scales: κ₁(A)); `x` starts the estimator and
/// keeps its maximiser for the next position, `y` is scratch.
pub fn estimated_condition(a: &DMatrix<f64>, lu: &Lu, scales: [&[f64]; 2], [x, y]: [&mut Vec<f64>; 2]) -> f64 {
    let [_, norm] = norms1(a, scales);
    times(norm, lu.scaled_inverse_norm1(x, y, scales))
}

/// κ₁(A) and κ₁(R A C) from A's LU, as [`estimated_condition`] finds each
/// (`x` and `xs` their maximisers), the two norms in one pass over A and
/// the two of the inverse from one A⁻¹ where it is formed.
pub fn estimated_conditions(
    a: &DMatrix<f64>,
    lu: &Lu,
    scales: [&[f64]; 2],
    [x, xs, y]: [&mut Vec<f64>; 3],
) -> [f64; 2] {
    let [plain, scaled] = norms1(a, scales);
    let [inverse, of_scaled] = lu.inverse_norms1([x, xs, y], scales);
    [times(plain, inverse), times(scaled, of_scaled)]
}

fn times(norm: f64, inverse_norm: f64) -> f64 {
    if inverse_norm.is_finite() { norm * inverse_norm } else { f64::INFINITY }
}

/// ‖A‖₁ and ‖R A C‖₁: the largest column sums of |a_ij| and of |a_ij r_i| c_j
/// (empty scales: all 1). Each column is summed down in order, four
/// columns side by side over the column-major storage, so that no sum waits
/// on another's last addition (summed one column after the other, the two
/// norms took a quarter of the estimates).
fn norms1(a: &DMatrix<f64>, [rows, cols]: [&[f64]; 2]) -> [f64; 2] {
    let n = a.nrows().max(1);
    let r = |i: usize| rows.get(i).copied().unwrap_or(1.0);
    let mut norms = [0.0f64; 2];
    for (group, quad) in a.as_slice().chunks(4 * n).enumerate() {
        let mut sums = [[0.0f64; 2]; 4];
        for i in 0..n {
            let ri = r(i);
            for (k, sum) in sums.iter_mut().enumerate().take(quad.len() / n) {
                let v = quad[k * n + i];
                sum[0] += v.abs();
                sum[1] += (v * ri).abs();
            }
        }
        for (k, [plain, scaled]) in sums.into_iter().enumerate().take(quad.len() / n) {
            let c = cols.get(4 * group + k).copied().unwrap_or(1.0);
            norms = [norms[0].max(plain), norms[1].max(c * scaled)];
        }
    }
    norms
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scaled matrix of A and of S_r A S_c⁻¹ (A drawn s times larger:
    /// its length rows and translation columns) are the same; the estimate
    /// from the drawn matrix's factors is the same at every scale, a lower
    /// bound of κ₁ of the scaled matrix (its inverse formed outright) within
    /// a factor 3.
    #[test]
    fn the_scaled_matrix_does_not_depend_on_the_drawing_s_scale() {
        // Two length rows and an angle row; columns x, y, θ.
        let a = DMatrix::from_row_slice(3, 3, &[1.0, 0.0, -0.3, 0.0, 1.0, 0.7, 0.0, 0.0, 1.0]);
        let at = |s: f64| {
            let (row, col) = ([s, s, 1.0], [s, s, 1.0]);
            DMatrix::from_fn(3, 3, |i, j| a[(i, j)] * row[i] / col[j])
        };
        let of = |s: f64| {
            let (a, cols) = (at(s), [s, s, 1.0]);
            let mut rows = Vec::new();
            row_scales(&a, &cols, &mut rows);
            let mut lu = Lu::default();
            lu.factor(&a);
            let estimate = estimated_condition(&a, &lu, [&rows, &cols], [&mut Vec::new(), &mut Vec::new()]);
            (scaled(&a, [&rows, &cols]), estimate)
        };
        let (reference, first) = of(1.0);
        let norm1 = |m: &DMatrix<f64>| m.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
        let kappa1 = norm1(&reference) * norm1(&reference.clone().try_inverse().unwrap());
        assert!(first <= kappa1 * (1.0 + 1e-12) && first >= kappa1 / 3.0, "{first} vs κ₁ {kappa1}");
        for s in [1e-9, 1e-3, 1e4, 1e9] {
            let (b, estimate) = of(s);
            assert!((&b - &reference).amax() <= 1e-15, "at {s}: {b} vs {reference}");
            assert!((estimate - first).abs() <= 1e-12 * first, "at {s}: {estimate} vs {first}");
            let s = b.clone().singular_values();
            assert!(s.max() / s.min() < 10.0, "κ₂ {}", s.max() / s.min());
        }
    }

    /// r_i = 1 / max_j |a_ij c_j| to the bit (the maximum is exact), 1 for
    /// a row of zeros and for a row with a NaN; a column past the scales
    /// given is taken with c_j = 1.
    #[test]
    fn each_row_is_scaled_by_its_largest_entry() {
        let a = DMatrix::from_row_slice(4, 3, &[3.0, -8.0, 0.5, 0.0, 0.0, 0.0, 1.0, f64::NAN, 2.0, -0.25, 1e-3, 4.0]);
        let cols = [2.0, 0.5];
        let mut rows = Vec::new();
        row_scales(&a, &cols, &mut rows);
        let largest = |i: usize| (0..3).map(|j| (a[(i, j)] * cols.get(j).unwrap_or(&1.0)).abs()).fold(0.0, f64::max);
        assert_eq!(rows, [1.0 / largest(0), 1.0, 1.0, 1.0 / largest(3)]);
        assert_eq!((largest(0), largest(3)), (6.0, 4.0), "|−8 × 0.5| < |3 × 2|; the last column unscaled");
        let regular = a.select_rows([0, 3].iter());
        row_scales(&regular, &cols, &mut rows);
        assert_eq!(rows, [1.0 / 6.0, 0.25]);
    }

    /// Both estimates from one pass over A are, bit for bit, those of two
    /// estimates each with its own pass (sizes with 1, 2, 3 and 4
    /// columns past the last group of four), and ‖A‖₁ and ‖R A C‖₁ their definitions.
    #[test]
    fn the_two_estimates_together_are_each_alone() {
        for n in [5, 6, 7, 8, 9] {
            let a = DMatrix::from_fn(n, n, |i, j| ((3 * i + 7 * j) as f64).sin() + if i == j { 2.0 } else { 0.0 });
            let cols: Vec<f64> = (0..n).map(|j| if j % 3 == 2 { 1.0 } else { 0.3 }).collect();
            let mut rows = Vec::new();
            row_scales(&a, &cols, &mut rows);
            let mut lu = Lu::default();
            assert!(lu.factor(&a));
            let scratch = || [Vec::new(), Vec::new(), Vec::new()];
            let [mut x, mut xs, mut y] = scratch();
            let both = estimated_conditions(&a, &lu, [&rows, &cols], [&mut x, &mut xs, &mut y]);
            let [mut x, mut xs, mut y] = scratch();
            let plain = estimated_condition(&a, &lu, [&[], &[]], [&mut x, &mut y]);
            let scaled_alone = estimated_condition(&a, &lu, [&rows, &cols], [&mut xs, &mut y]);
            assert_eq!(both.map(f64::to_bits), [plain, scaled_alone].map(f64::to_bits), "n = {n}");
            let norm1 = |m: &DMatrix<f64>| m.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
            let [p, q] = norms1(&a, [&rows, &cols]);
            assert!((p - norm1(&a)).abs() <= 1e-15 * p, "‖A‖₁ at n = {n}");
            let s = norm1(&scaled(&a, [&rows, &cols]));
            assert!((q - s).abs() <= 1e-15 * s, "‖R A C‖₁ at n = {n}");
        }
    }
}
