//! Small dense linear solves: Gaussian elimination with partial pivoting, for a principal
//! subsystem of a complementarity problem (`dynamics/principal.rs`), and Gauss-Jordan for the
//! tests' brute-force references (enumerations of active sets).

/// Solves `A x = b` in place (`a`: `n` by `n`, by rows; `b` becomes `x`) by Gaussian
/// elimination with partial pivoting and back substitution. Returns `false` (with `a` and `b`
/// overwritten) if a pivot is at most `singular` times the largest entry of `A`: the system
/// is taken for singular.
pub(crate) fn solve_in_place(a: &mut [f64], b: &mut [f64], singular: f64) -> bool {
    let n = b.len();
    debug_assert_eq!(a.len(), n * n);
    let scale = a.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
    let small = singular * scale;
    for col in 0..n {
        let Some(pivot) =
            (col..n).max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
        else {
            return false;
        };
        let p = a[pivot * n + col];
        if !(p.abs() > small) {
            return false;
        }
        if pivot != col {
            for k in 0..n {
                a.swap(col * n + k, pivot * n + k);
            }
            b.swap(col, pivot);
        }
        let (upper, lower) = a.split_at_mut((col + 1) * n);
        let pivot_row = &upper[col * n..];
        for (i, row) in lower.chunks_exact_mut(n).enumerate() {
            let f = row[col] / p;
            if f != 0.0 {
                for (x, y) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                    *x -= f * y;
                }
                b[col + 1 + i] -= f * b[col];
            }
        }
    }
    for i in (0..n).rev() {
        let row = &a[i * n..(i + 1) * n];
        let mut x = b[i];
        for (rij, bj) in row[i + 1..].iter().zip(&b[i + 1..]) {
            x -= rij * bj;
        }
        b[i] = x / row[i];
    }
    b.iter().all(|x| x.is_finite())
}

/// The solution `x` of `A x = b`, given `[A | b]` (`n` rows of `n + 1`), or `None` if a pivot
/// falls below `singular` (the set is skipped as dependent).
#[cfg(test)]
pub(crate) fn solve_dense(mut a: Vec<Vec<f64>>, singular: f64) -> Option<Vec<f64>> {
    let n = a.len();
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() < singular {
            return None;
        }
        a.swap(col, pivot);
        let pivot_row = a[col].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != col {
                let f = row[col] / pivot_row[col];
                for (x, p) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                    *x -= f * p;
                }
            }
        }
    }
    Some((0..n).map(|i| a[i][n] / a[i][i]).collect())
}

/// Every solution of a small linear complementarity problem (`z >= 0`, `w = q + M z >= 0`,
/// `z . w = 0`; `m` by rows), to 1e-9, by enumerating which of each pair `(z_i, w_i)` may be
/// non-zero: the tests' reference for `dynamics/lemke.rs` and `dynamics/principal.rs`.
#[cfg(test)]
pub(crate) fn lcp_by_enumeration(m: &[Vec<f64>], q: &[f64]) -> Vec<Vec<f64>> {
    let n = q.len();
    let mut found = Vec::new();
    for set in 0..(1_u32 << n) {
        let active: Vec<usize> = (0..n).filter(|&i| set >> i & 1 == 1).collect();
        // Rows of `active`: `(M z)_i = -q_i` over `z` on `active`.
        let a: Vec<Vec<f64>> = active
            .iter()
            .map(|&i| {
                let mut row: Vec<f64> = active.iter().map(|&j| m[i][j]).collect();
                row.push(-q[i]);
                row
            })
            .collect();
        let Some(solved) = solve_dense(a, 1e-12) else {
            continue;
        };
        let mut z = vec![0.0; n];
        for (&i, x) in active.iter().zip(solved) {
            z[i] = x;
        }
        let w = (0..n).map(|i| q[i] + (0..n).map(|j| m[i][j] * z[j]).sum::<f64>());
        if z.iter().all(|&x| x >= -1e-9) && w.into_iter().all(|x| x >= -1e-9) {
            found.push(z);
        }
    }
    found
}

/// The tests' numbers: `state` advanced by xorshift, as a number in `[-1, 1)`.
#[cfg(test)]
pub(crate) fn uniform(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1_u64 << 53) as f64 * 2.0 - 1.0
}

/// A random `n` by `n` P-matrix (every principal minor positive, so that each complementarity
/// problem of it has exactly one solution), from numbers `next` draws in `[-1, 1)`:
/// `B B^T + 0.1 I + (S - S^T)`, positive definite in its symmetric part.
#[cfg(test)]
pub(crate) fn random_p_matrix(n: usize, next: &mut impl FnMut() -> f64) -> Vec<Vec<f64>> {
    let b: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| next()).collect()).collect();
    let s: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| next()).collect()).collect();
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let bb: f64 = (0..n).map(|k| b[i][k] * b[j][k]).sum();
                    bb + if i == j { 0.1 } else { 0.0 } + s[i][j] - s[j][i]
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gaussian elimination agrees with Gauss-Jordan on random systems, and refuses a singular
    /// one.
    #[test]
    fn elimination_agrees_with_gauss_jordan() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || uniform(&mut state);
        for _ in 0..500 {
            let n = 1 + ((next() + 1.0) * 4.0) as usize;
            let a: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| next()).collect()).collect();
            let b: Vec<f64> = (0..n).map(|_| next()).collect();
            let augmented = a
                .iter()
                .zip(&b)
                .map(|(row, &bi)| row.iter().copied().chain([bi]).collect())
                .collect();
            let Some(expected) = solve_dense(augmented, 1e-9) else {
                continue;
            };
            let mut flat: Vec<f64> = a.concat();
            let mut x = b.clone();
            assert!(solve_in_place(&mut flat, &mut x, 1e-14));
            for (got, want) in x.iter().zip(&expected) {
                assert!(
                    (got - want).abs() <= 1e-8 * (1.0 + want.abs()),
                    "{x:?} {expected:?}"
                );
            }
        }
        let mut singular = vec![1.0, 2.0, 2.0, 4.0];
        assert!(!solve_in_place(&mut singular, &mut [1.0, 1.0], 1e-12));
    }
}
