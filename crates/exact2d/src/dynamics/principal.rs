//! A linear complementarity problem solved from a guess of its active set, by block principal
//! pivoting: `z >= 0`, `w = q + M z >= 0`, `z . w = 0`.
//!
//! A guess `F` of the rows whose `z` is positive fixes the rest: `z_i = 0` off `F`, and
//! `w_i = 0` on it, so `M_FF z_F = -q_F`, one dense solve of `F`'s rows (`dynamics/dense.rs`).
//! If every `z_F` and every `w` off `F` is non-negative, that is a solution. Otherwise every
//! row that is wrong changes sides at once (a *block* exchange), and the solve is repeated;
//! while the exchanges do not lessen the number of wrong rows, after three tries only the
//! wrong row of the highest index changes sides (Murty's rule, which ends for a P-matrix).
//! J. J. Judice and F. M. Pires, "A block principal pivoting algorithm for large-scale
//! strictly monotone linear complementarity problems", Computers and Operations Research 21,
//! 1994; the safeguard as in J. Kim and H. Park, SIAM J. Sci. Comput. 33, 2011.
//!
//! Started from a good guess (the active set the last of a group's friction rounds ended
//! with, `dynamics/contact_friction.rs`), it ends in a solve or two, where Lemke's method
//! (`dynamics/lemke.rs`) pivots once for each row it makes active, every pivot updating a
//! tableau of twice the rows' square: on the rough 200-ball pile's holds of a hundred rows
//! and more, Lemke's method was a fifth of the wall. It gives up (`None`) after
//! [`EXCHANGES`] exchanges or at a singular subsystem, for Lemke's method to take over.

use super::dense::solve_in_place;

/// The most exchanges before giving up: `16`.
const EXCHANGES: usize = 16;

/// A `z` below this share of the largest `|z|`, or a `w` below it of the largest `|q|` (the
/// same units as `w`), is wrong; above it, rounding: `1e-12`. (The caller checks the answer
/// against its own problem: a rounding taken for right here costs an answer, not a wrong
/// one.)
const WRONG: f64 = 1e-12;

/// A pivot of the subsystem at most this share of its largest entry makes it singular:
/// `1e-13`.
const SINGULAR: f64 = 1e-13;

/// Tries the block exchanges from the rows `guess` marks (a `true` row's `z` guessed
/// positive) of the problem `(q, m)` (`m` by rows): a solution, each `z` at least zero, or
/// `None`.
pub(crate) fn from_guess(m: &[Vec<f64>], q: &[f64], guess: &[bool]) -> Option<Vec<f64>> {
    let n = q.len();
    debug_assert!(m.len() == n && guess.len() == n);
    let q_scale = q.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
    let mut in_f = guess.to_vec();
    let (mut fewest, mut tries) = (n + 1, 3);
    let mut z = vec![0.0; n];
    let mut a = Vec::new();
    for _ in 0..=EXCHANGES {
        let f: Vec<usize> = (0..n).filter(|&i| in_f[i]).collect();
        a.clear();
        for &i in &f {
            a.extend(f.iter().map(|&j| m[i][j]));
        }
        let mut x: Vec<f64> = f.iter().map(|&i| -q[i]).collect();
        if !solve_in_place(&mut a, &mut x, SINGULAR) {
            return None;
        }
        z.iter_mut().for_each(|zi| *zi = 0.0);
        for (&i, &xi) in f.iter().zip(&x) {
            z[i] = xi;
        }
        let z_scale = x.iter().fold(0.0_f64, |s, v| s.max(v.abs()));
        let wrong: Vec<usize> = (0..n)
            .filter(|&i| {
                if in_f[i] {
                    z[i] < -WRONG * z_scale
                } else {
                    let w = q[i] + f.iter().map(|&j| m[i][j] * z[j]).sum::<f64>();
                    w < -WRONG * q_scale
                }
            })
            .collect();
        if wrong.is_empty() {
            for zi in &mut z {
                *zi = zi.max(0.0);
            }
            return Some(z);
        }
        if wrong.len() < fewest {
            (fewest, tries) = (wrong.len(), 3);
            wrong.iter().for_each(|&i| in_f[i] = !in_f[i]);
        } else if tries > 0 {
            tries -= 1;
            wrong.iter().for_each(|&i| in_f[i] = !in_f[i]);
        } else {
            let last = *wrong.last().expect("not empty");
            in_f[last] = !in_f[last];
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::dense::{lcp_by_enumeration, random_p_matrix, uniform};

    /// On 2,000 random problems whose matrix is a P-matrix (positive definite in its
    /// symmetric part, plus a skew part: each has exactly one solution) of one to eight rows,
    /// from the solution's own active set and from a random guess, the exchanges find the
    /// solution enumeration finds, to 1e-9 (Murty's rule ends for a P-matrix, and within
    /// [`EXCHANGES`] at these sizes).
    #[test]
    fn the_exchanges_find_the_solution_enumeration_finds() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || uniform(&mut state);
        let (mut found, problems) = (0, 2000);
        for _ in 0..problems {
            let n = 1 + ((next() + 1.0) * 4.0) as usize;
            let m = random_p_matrix(n, &mut next);
            let q: Vec<f64> = (0..n).map(|_| next()).collect();
            let all = lcp_by_enumeration(&m, &q);
            assert_eq!(all.len(), 1, "{m:?} {q:?}: {all:?}");
            let solution = &all[0];
            let close = |z: &[f64]| {
                z.iter()
                    .zip(solution)
                    .all(|(a, b)| (a - b).abs() <= 1e-9 * (1.0 + b.abs()))
            };
            let own: Vec<bool> = solution.iter().map(|&x| x > 1e-9).collect();
            let z = from_guess(&m, &q, &own).expect("the solution's own active set");
            assert!(close(&z), "{z:?} {solution:?}");
            let guess: Vec<bool> = (0..n).map(|_| next() > 0.0).collect();
            if let Some(z) = from_guess(&m, &q, &guess) {
                assert!(close(&z), "{z:?} {solution:?}");
                found += 1;
            }
        }
        assert_eq!(found, problems);
    }
}
