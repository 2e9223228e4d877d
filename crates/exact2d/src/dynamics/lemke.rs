//! Lemke's method for a linear complementarity problem: `z >= 0`, `w = q + M z >= 0`,
//! `z . w = 0`, for a square `M` of any symmetry.
//!
//! C. E. Lemke, "Bimatrix equilibrium points and mathematical programming", Management
//! Science 11, 1965; R. W. Cottle, J.-S. Pang and R. E. Stone, *The Linear Complementarity
//! Problem*, 1992, section 4.4. One artificial variable `z0` with the covering vector of ones
//! makes `w = q + M z + z0 1` feasible at once (`z0 = -min q`); the method then pivots along
//! the path of *almost complementary* bases, each entering variable the complement of the one
//! that last left, until `z0` leaves (a solution) or no basic variable blocks the entering one
//! (a ray: the method gives up, which for a matrix that is not copositive-plus may happen
//! though a solution exists). Each basis is a Gauss-Jordan tableau of the `n` equations.
//!
//! Used where a fixed-point iteration does not agree and block principal pivoting from its
//! last active set (`dynamics/principal.rs`) gives up: a group's forces with kinetic friction
//! (`dynamics/contact_friction.rs`), whose matrix is not symmetric (a sliding contact's force
//! leans against its slip, off its normal). Its answers are checked there against the
//! problem itself, so a rounding that leads it astray costs an answer, not a wrong one.

/// The most pivots, as a multiple of the problem's size: `64`. Without degeneracy each
/// almost complementary basis is visited once; this bounds the work where rounding or ties
/// would make the path turn back on itself.
const PIVOTS_PER_ROW: usize = 64;

/// A tableau entry at most this share of the largest in its column (or of the right-hand
/// side's scale) is taken for zero in the ratio test: `1e-12`.
const PIVOT_ZERO: f64 = 1e-12;

/// A solution `z` of the problem `(q, m)` (`m` by rows), if the method finds one.
pub(crate) fn lemke(m: &[Vec<f64>], q: &[f64]) -> Option<Vec<f64>> {
    let n = q.len();
    debug_assert!(m.len() == n && m.iter().all(|row| row.len() == n));
    if q.iter().all(|&qi| qi >= 0.0) {
        return Some(vec![0.0; n]);
    }
    // Columns: w (0..n), z (n..2n), z0 (2n); the right-hand side apart. The equations
    // `w - M z - z0 1 = q`.
    let width = 2 * n + 1;
    let mut tableau: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            let mut row = vec![0.0; width];
            row[i] = 1.0;
            for j in 0..n {
                row[n + j] = -m[i][j];
            }
            row[2 * n] = -1.0;
            row
        })
        .collect();
    let mut rhs = q.to_vec();
    let mut basic: Vec<usize> = (0..n).collect();
    // z0 enters where q is most negative.
    let first = (0..n).min_by(|&a, &b| q[a].total_cmp(&q[b]))?;
    pivot(&mut tableau, &mut rhs, first, 2 * n);
    let mut leaving = basic[first];
    basic[first] = 2 * n;
    for _ in 0..PIVOTS_PER_ROW * n + 8 {
        // The complement of the variable that left enters.
        let entering = if leaving < n {
            leaving + n
        } else {
            leaving - n
        };
        let column_scale = tableau
            .iter()
            .fold(0.0_f64, |s, row| s.max(row[entering].abs()));
        // The ratio test: the basic variable that reaches zero first as `entering` grows
        // (`x_b = rhs - t x_e`), ties to z0 (it ends the path), then to the largest entry.
        let mut best: Option<(f64, usize)> = None;
        for (i, row) in tableau.iter().enumerate() {
            let a = row[entering];
            if a <= PIVOT_ZERO * column_scale {
                continue;
            }
            let ratio = rhs[i].max(0.0) / a;
            let better = match best {
                None => true,
                Some((r, at)) => {
                    ratio < r - PIVOT_ZERO * (1.0 + r)
                        || (ratio <= r + PIVOT_ZERO * (1.0 + r)
                            && (basic[i] == 2 * n
                                || (basic[at] != 2 * n && a > tableau[at][entering])))
                }
            };
            if better {
                best = Some((ratio, i));
            }
        }
        let (_, r) = best?;
        pivot(&mut tableau, &mut rhs, r, entering);
        leaving = basic[r];
        basic[r] = entering;
        if leaving == 2 * n {
            let mut z = vec![0.0; n];
            for (i, &b) in basic.iter().enumerate() {
                if (n..2 * n).contains(&b) {
                    z[b - n] = rhs[i].max(0.0);
                }
            }
            return z.iter().all(|x| x.is_finite()).then_some(z);
        }
    }
    None
}

/// A Gauss-Jordan pivot of the tableau on row `r` and column `c`.
fn pivot(tableau: &mut [Vec<f64>], rhs: &mut [f64], r: usize, c: usize) {
    let p = tableau[r][c];
    for x in tableau[r].iter_mut() {
        *x /= p;
    }
    rhs[r] /= p;
    let pivot_row = tableau[r].clone();
    let pivot_rhs = rhs[r];
    for (i, row) in tableau.iter_mut().enumerate() {
        if i == r {
            continue;
        }
        let f = row[c];
        if f != 0.0 {
            for (x, &y) in row.iter_mut().zip(&pivot_row) {
                *x -= f * y;
            }
            rhs[i] -= f * pivot_rhs;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::dense::{lcp_by_enumeration, random_p_matrix, uniform};

    /// On 2,000 random problems whose matrix is a positive definite one plus a skew part (a
    /// P-matrix: each has exactly one solution), Lemke's method finds that solution, as
    /// enumeration finds it, to 1e-9.
    #[test]
    fn lemke_finds_the_solution_enumeration_finds() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || uniform(&mut state);
        for _ in 0..2000 {
            let n = 1 + ((next() + 1.0) * 3.0) as usize;
            let m = random_p_matrix(n, &mut next);
            let q: Vec<f64> = (0..n).map(|_| next()).collect();
            let z = lemke(&m, &q).expect("a P-matrix problem has a solution");
            let all = lcp_by_enumeration(&m, &q);
            assert_eq!(all.len(), 1, "{m:?} {q:?}: {all:?}");
            for (a, b) in z.iter().zip(&all[0]) {
                assert!((a - b).abs() <= 1e-9 * (1.0 + b.abs()), "{z:?} {all:?}");
            }
        }
    }
}
