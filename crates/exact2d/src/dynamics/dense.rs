//! A small dense linear solve for the tests' brute-force references (enumerations of active
//! sets): Gauss-Jordan elimination with partial pivoting.

/// The solution `x` of `A x = b`, given `[A | b]` (`n` rows of `n + 1`), or `None` if a pivot
/// falls below `singular` (the set is skipped as dependent).
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
