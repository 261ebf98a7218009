//! Sparse symmetric LDLᵀ factorisation, S = P L D Lᵀ Pᵀ, L unit lower
//! triangular, for matrices whose pattern is fixed while their values
//! change (the range-space matrix Φ_q M⁻¹ Φ_qᵀ of a mechanism at every
//! evaluation of its equations of motion).
//!
//! [`Pattern::new`] orders the rows once by minimum degree (greedy, on the
//! elimination graph, ties broken by the lower index) and works out L's
//! pattern, fill included; [`Ldl::factor`] then costs Σᵢ Σ_{j∈Pᵢ} |P_j|
//! (Pᵢ the pattern of row i of L), linear in the rows for the chains and
//! trees that mechanisms are. No pivoting: the caller reads the pivots D
//! (each the squared distance of a row to the span of the rows eliminated
//! before it, in S's metric) to tell whether S is near singular.
//!
//! Written here rather than taken from a crate: nalgebra-sparse's Cholesky
//! has no fill-reducing ordering and stops with an error at a small pivot
//! instead of reporting it, and faer would be the largest dependency of
//! the service for ~120 lines.

use std::collections::BTreeSet;

/// Elimination order and the pattern of L (in elimination order).
#[derive(Clone, Debug)]
pub struct Pattern {
    /// `order[k]`: the original row eliminated k-th; `rank[i]` its inverse.
    pub order: Vec<usize>,
    pub rank: Vec<usize>,
    /// Row k of L: `cols[start[k]..start[k + 1]]`, ascending, all < k.
    start: Vec<usize>,
    cols: Vec<usize>,
}

impl Pattern {
    /// From the graph of S's off-diagonal entries (`neighbours[i]`: the rows
    /// j ≠ i with S_ij ≠ 0, original numbering); the rows `last` are
    /// eliminated after all the others (by minimum degree among themselves).
    pub fn new(neighbours: &[Vec<usize>], last: &[usize]) -> Self {
        let n = neighbours.len();
        let mut adj: Vec<BTreeSet<usize>> =
            neighbours.iter().enumerate().map(|(i, ns)| ns.iter().copied().filter(|&j| j != i).collect()).collect();
        for i in 0..n {
            for j in adj[i].clone() {
                adj[j].insert(i);
            }
        }
        let mut late = vec![false; n];
        last.iter().for_each(|&i| late[i] = true);
        let mut queue: BTreeSet<(usize, usize)> = (0..n).filter(|&i| !late[i]).map(|i| (adj[i].len(), i)).collect();
        let (mut order, mut rank) = (Vec::with_capacity(n), vec![usize::MAX; n]);
        // Column k of L: the neighbours of the k-th row still to eliminate.
        let mut below: Vec<Vec<usize>> = Vec::with_capacity(n);
        loop {
            let Some((_, v)) = queue.pop_first() else {
                if !late.contains(&true) {
                    break;
                }
                // The late rows' turn.
                queue.extend((0..n).filter(|&i| late[i]).map(|i| (adj[i].len(), i)));
                late.fill(false);
                continue;
            };
            rank[v] = order.len();
            order.push(v);
            let clique: Vec<usize> = std::mem::take(&mut adj[v]).into_iter().collect();
            for &a in &clique {
                let queued = queue.remove(&(adj[a].len(), a));
                adj[a].remove(&v);
                adj[a].extend(clique.iter().copied().filter(|&b| b != a));
                if queued {
                    queue.insert((adj[a].len(), a));
                }
            }
            below.push(clique);
        }
        let mut rows: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (k, col) in below.iter().enumerate() {
            for &i in col {
                rows[rank[i]].push(k);
            }
        }
        let (mut start, mut cols) = (vec![0], Vec::new());
        for row in rows {
            cols.extend(row);
            start.push(cols.len());
        }
        Self { order, rank, start, cols }
    }

    pub fn len(&self) -> usize {
        self.order.len()
    }

    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// Entries of L below the diagonal (fill included).
    pub fn entries(&self) -> usize {
        self.cols.len()
    }

    /// Position of S_ij (original rows, i ≠ j) in the strictly lower values
    /// [`Ldl::factor`] takes, or None when L has no entry there.
    pub fn position(&self, i: usize, j: usize) -> Option<usize> {
        let (a, b) = (self.rank[i].max(self.rank[j]), self.rank[i].min(self.rank[j]));
        let row = &self.cols[self.start[a]..self.start[a + 1]];
        row.binary_search(&b).ok().map(|k| self.start[a] + k)
    }

    fn row(&self, k: usize) -> std::ops::Range<usize> {
        self.start[k]..self.start[k + 1]
    }
}

/// The numeric factors; workspaces kept from one factorisation to the next.
#[derive(Clone, Debug)]
pub struct Ldl {
    pub pattern: Pattern,
    l: Vec<f64>,
    /// Pivots in elimination order.
    pub d: Vec<f64>,
    work: Vec<f64>,
}

impl Ldl {
    pub fn new(pattern: Pattern) -> Self {
        let (n, e) = (pattern.len(), pattern.entries());
        Self { pattern, l: vec![0.0; e], d: vec![0.0; n], work: vec![0.0; n] }
    }

    /// Factors S given its diagonal (elimination order) and its strictly
    /// lower entries at [`Pattern::position`] (zero at fill positions).
    pub fn factor(&mut self, diag: &[f64], lower: &[f64]) {
        let (p, l, d, work) = (&self.pattern, &mut self.l, &mut self.d, &mut self.work);
        // Over slices of each row (L's finished rows, row i's own), which
        // spare the bounds checks of indexing L and P by position: A02's
        // factor at N = 40 took a fifth of an evaluation so.
        for (i, s) in diag.iter().enumerate() {
            let row = p.row(i);
            let (done, rest) = l.split_at_mut(row.start);
            let mut di = *s;
            for ((l_ij, &j), &s_ij) in rest[..row.len()].iter_mut().zip(&p.cols[row.clone()]).zip(&lower[row.clone()]) {
                // w_j = L_ij·D_j = S_ij − Σ_{k∈P_j} L_jk·w_k.
                let of_j = p.row(j);
                let w = done[of_j.clone()].iter().zip(&p.cols[of_j]).fold(s_ij, |w, (l_jk, &k)| w - l_jk * work[k]);
                work[j] = w;
                *l_ij = w / d[j];
                di -= *l_ij * w;
            }
            p.cols[row].iter().for_each(|&k| work[k] = 0.0);
            d[i] = di;
        }
    }

    /// z = L⁻¹·b in place (elimination order).
    pub fn forward(&self, z: &mut [f64]) {
        let p = &self.pattern;
        for i in 0..p.len() {
            let row = p.row(i);
            let s: f64 = self.l[row.clone()].iter().zip(&p.cols[row]).map(|(l, &k)| l * z[k]).sum();
            z[i] -= s;
        }
    }

    /// x = L⁻ᵀ·z in place (elimination order).
    pub fn backward(&self, x: &mut [f64]) {
        let p = &self.pattern;
        for i in (0..p.len()).rev() {
            let (xi, row) = (x[i], p.row(i));
            for (l, &k) in self.l[row.clone()].iter().zip(&p.cols[row]) {
                x[k] -= l * xi;
            }
        }
    }

    /// x = S⁻¹·b (elimination order), every pivot used as it is.
    pub fn solve(&self, x: &mut [f64]) {
        self.forward(x);
        x.iter_mut().zip(&self.d).for_each(|(v, d)| *v /= d);
        self.backward(x);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;

    /// A ladder of 2×2 blocks coupled to their neighbours plus one long-range
    /// entry (fill), against nalgebra's dense Cholesky: S·x = b to 1e-12, and
    /// the pivots' product equals det S (LDLᵀ with L unit: det = Π D); in
    /// the minimum-degree order and with two rows put last.
    #[test]
    fn factors_and_solves_like_the_dense_cholesky() {
        for last in [&[][..], &[3, 5]] {
            factors_and_solves_in_order(last);
        }
    }

    fn factors_and_solves_in_order(last: &[usize]) {
        let n = 12;
        let mut s = DMatrix::<f64>::zeros(n, n);
        for i in 0..n {
            s[(i, i)] = 4.0 + i as f64 * 0.1;
        }
        let mut neighbours = vec![Vec::new(); n];
        let mut link = |s: &mut DMatrix<f64>, i: usize, j: usize, v: f64| {
            s[(i, j)] = v;
            s[(j, i)] = v;
            neighbours[i].push(j);
        };
        for i in 0..n - 1 {
            link(&mut s, i, i + 1, -1.0 + 0.05 * i as f64);
        }
        link(&mut s, 0, n - 1, 0.7);
        link(&mut s, 3, 8, -0.4);
        let pattern = Pattern::new(&neighbours, last);
        let mut tail = pattern.order[n - last.len()..].to_vec();
        tail.sort_unstable();
        assert_eq!(tail, last, "the rows put last");
        let mut lower = vec![0.0; pattern.entries()];
        for i in 0..n {
            for j in 0..i {
                if s[(i, j)] != 0.0 {
                    lower[pattern.position(i, j).expect("an entry of S is in L's pattern")] = s[(i, j)];
                }
            }
        }
        let diag: Vec<f64> = pattern.order.iter().map(|&i| s[(i, i)]).collect();
        let mut ldl = Ldl::new(pattern);
        ldl.factor(&diag, &lower);
        let b: Vec<f64> = (0..n).map(|i| (i as f64).sin()).collect();
        let mut x: Vec<f64> = ldl.pattern.order.iter().map(|&i| b[i]).collect();
        ldl.solve(&mut x);
        let dense = s.clone().cholesky().expect("positive definite").solve(&nalgebra::DVector::from_vec(b));
        for (k, &i) in ldl.pattern.order.iter().enumerate() {
            assert!((x[k] - dense[i]).abs() < 1e-12, "x[{i}] {} vs {}", x[k], dense[i]);
        }
        let det: f64 = ldl.d.iter().product();
        assert!((det / s.determinant() - 1.0).abs() < 1e-12);
    }
}
