//! A sparse Cholesky factor of the Gram matrix of a jam's active contacts, for the dual method
//! on large clusters (`dynamics/impact.rs`, [`solve_on_gram`](super::impact)).
//!
//! ## The matrix
//!
//! Contact `k` is a row `c_k` over the balls' velocities (`-n_k` at `a` and `n_k` at `b` for two
//! balls, `n_k` at `a` for a surface). The dual method's linear algebra is that of the active
//! rows' Gram matrix in the metric of the inverse masses,
//!
//! ```text
//! G_ij = c_i . M^-1 c_j = sum over the balls x that both reach of  s_i(x) s_j(x) (n_i . n_j) / m_x,
//! ```
//!
//! `s_k(x)` the sign of `n_k` at `x`. Two contacts that share no ball have `G_ij = 0`, so in a
//! pile, where a ball touches at most six others, a row of `G` has four to seven entries
//! (BENCHMARKS.md, stop 54: 72.7 rows of a big jam's projection, 288 entries).
//!
//! ## The factor, a row at a time
//!
//! `G = L L^T`, `L` lower triangular with a positive diagonal, is built one row at a time in
//! the active set's order: the row of a contact `k` joining rows `0..n` is `l = L^-1 g`, `g` its
//! column of `G` against them (forward substitution), and its diagonal is `d = sqrt(G_kk -
//! l . l)`, the length of the part of `c_k` independent of the others (`d^2` is, in exact
//! arithmetic, the `c_p . z` of the dual method's step). A row starts at the first of the
//! earlier contacts its column meets, and its later entries are the fill: each row is stored
//! where it is not zero.
//! Dropping row `s` keeps rows `0..s` (a Cholesky factor's leading rows are those rows' own
//! factor) and the rows after it join again in turn.
//!
//! ## Accuracy, refinement, and where the factor is not used
//!
//! The normal equations square the condition of the rows: `d^2` is computed to about `eps
//! G_kk`, so a contact nearly a combination of the active ones (a thin wedge: a sine of `1e-6`
//! between two resting contacts, `d^2 = 1e-12 G_kk`) keeps only some four good digits of it,
//! where the Gram-Schmidt basis of `dynamics/impact.rs` keeps its part orthogonal to them to
//! the rounding of `c_k` itself. Such a contact, and every solve of a factor that holds one
//! (a *thin* row, its pivot squared within [`NEAR_DEPENDENT`] of its length), is refined once
//! against the rows themselves: with `r` from the factor and `z = M^-1 (c_p - J_A^T r)`, the
//! residual `J_A z` (zero in exact arithmetic) is solved on the factor again, `G dr = J_A z`,
//! and `r + dr` gives `z` anew and `c_p . z` as the pivot. These are Bjorck's corrected
//! semi-normal equations (1987): each such step shrinks the error by about `eps kappa(G)`,
//! `kappa(G) <= 1 / TOO_NEAR` here, so one step takes it from some `1e-4` of the thin part
//! to the rounding the rows themselves carry. Below [`TOO_NEAR`] (exact dependences, the
//! exact fits of the hunts) the programme goes back to Gram-Schmidt.

use glam::DVec2;

use super::impact::ContactRow;
use super::shelf::{self, REALS};

/// The pivot below which the factor's solves are refined ([`ActiveRows::refine`]), as a
/// fraction of the contact's own squared length: `d^2 <= 1e-6 G_kk`, an angle of `1e-3`
/// between the contact and the span of the rows before it. Above it `d^2` keeps ten good
/// digits (its rounding is some `eps G_kk`), and the step `z = M^-1 (c_k - sum_j r_j c_j)`
/// loses at most six to cancellation. Measured on the 400-ball pile's projections of 40 balls
/// and more (stop 54, a scratch solve on such factors beside the engine's): above it every
/// answer agreed with Gram-Schmidt's to 1e-9 of the fastest speed (at most 8.5e-11) unrefined;
/// taken as they came below it, 1,336 did not (exact and near dependences). A start's row this
/// near stays out of the start (the steps take it, refined, if it is violated).
pub(crate) const NEAR_DEPENDENT: f64 = 1e-6;

/// The smallest pivot the factor takes at all, as a fraction of the contact's own squared
/// length: `d^2 > 1e-12 G_kk`, an angle of `1e-6`. Its rounding, some `eps G_kk`, is then at
/// most `1e-4` of it, and one step of refinement converges by that factor ([`NEAR_DEPENDENT`],
/// the module documentation). Below it lie the exact dependences, which a partial step of the
/// dual method must tell from thin wedges by `DEPENDENT` (`1e-28`, `dynamics/impact.rs`), far
/// past what the normal equations resolve: those programmes go back to Gram-Schmidt. Measured
/// on the frictionless 400-ball pile to t = 1.9 (stop 56): of the 116,126 programmes of 40
/// balls and more, 227 reach a pivot below it, and 37 refined answers fail the final checks
/// (both then solved on the basis); with the hand-back at [`NEAR_DEPENDENT`] instead, 4,144
/// went back.
pub(crate) const TOO_NEAR: f64 = 1e-12;

/// `c_i . M^-1 c_j` for two contacts, `inverse` the balls' inverse masses.
pub(crate) fn gram(ci: &ContactRow, cj: &ContactRow, inverse: &[f64]) -> f64 {
    // The row's value at a ball: `-n` at `a` and `n` at `b` for two balls, `n` at a
    // surface's `a`.
    let at = |c: &ContactRow, ball: usize| {
        if c.b == Some(ball) {
            Some(c.normal)
        } else if c.a == ball {
            Some(if c.b.is_some() { -c.normal } else { c.normal })
        } else {
            None
        }
    };
    let mut sum = 0.0;
    for ball in [Some(ci.a), ci.b].into_iter().flatten() {
        if let (Some(x), Some(y)) = (at(ci, ball), at(cj, ball)) {
            sum += x.dot(y) * inverse[ball];
        }
    }
    sum
}

/// `L`, lower triangular: row `i`'s entries left of the diagonal where they are not zero, and
/// its diagonal.
#[derive(Clone, Debug, Default)]
pub(crate) struct GramFactor {
    /// Where each row's entries start in `columns` and `values` (one more than the rows).
    starts: Vec<usize>,
    columns: Vec<u32>,
    values: Vec<f64>,
    diagonal: Vec<f64>,
}

impl GramFactor {
    /// An empty factor (of no rows).
    pub(crate) fn new() -> Self {
        GramFactor {
            starts: vec![0],
            ..GramFactor::default()
        }
    }

    /// How many rows it has.
    pub(crate) fn rows(&self) -> usize {
        self.diagonal.len()
    }

    /// `g <- L^-1 g`, in place, `g` as long as the factor has rows: forward substitution from
    /// the first entry of `g` that is not zero (the rows before it give zeros). (Solving only
    /// the rows the entries of `g` reach, found by following each column's later rows, as
    /// Gilbert and Peierls 1988 do, cost the 400-ball pile's solves more than it saved: a
    /// big jam's rows fill in, and most of them are reached.)
    pub(crate) fn forward(&self, g: &mut [f64]) {
        debug_assert_eq!(g.len(), self.rows());
        let Some(first) = g.iter().position(|&x| x != 0.0) else {
            return;
        };
        for i in first..self.rows() {
            let mut sum = g[i];
            let (from, to) = (self.starts[i], self.starts[i + 1]);
            for (&j, &l) in self.columns[from..to].iter().zip(&self.values[from..to]) {
                sum -= l * g[j as usize];
            }
            g[i] = sum / self.diagonal[i];
        }
    }

    /// `y <- L^-T y`, in place, by back substitution a row at a time: once `x_i` is known, row
    /// `i`'s entries are taken from the unknowns left of it.
    pub(crate) fn backward(&self, y: &mut [f64]) {
        debug_assert_eq!(y.len(), self.rows());
        for i in (0..self.rows()).rev() {
            let xi = y[i] / self.diagonal[i];
            y[i] = xi;
            if xi == 0.0 {
                continue;
            }
            let (from, to) = (self.starts[i], self.starts[i + 1]);
            for (&j, &l) in self.columns[from..to].iter().zip(&self.values[from..to]) {
                y[j as usize] -= l * xi;
            }
        }
    }

    /// Appends a row: `l`, the new contact's column forward-substituted ([`Self::forward`]),
    /// stored where it is not zero, and its diagonal `d > 0`.
    pub(crate) fn push(&mut self, l: &[f64], d: f64) {
        debug_assert_eq!(l.len(), self.rows());
        debug_assert!(d > 0.0);
        for (j, &x) in l.iter().enumerate() {
            if x != 0.0 {
                self.columns.push(j as u32);
                self.values.push(x);
            }
        }
        self.starts.push(self.columns.len());
        self.diagonal.push(d);
    }

    /// Row `i`'s entries left of the diagonal times `y`, summed in the order of their
    /// columns: the `l . y` of [`ActiveRows::row`]'s dense `l`, to the bit (its zeros add
    /// nothing).
    pub(crate) fn dot_row(&self, i: usize, y: &[f64]) -> f64 {
        let (from, to) = (self.starts[i], self.starts[i + 1]);
        self.columns[from..to]
            .iter()
            .zip(&self.values[from..to])
            .map(|(&j, &l)| l * y[j as usize])
            .sum::<f64>()
    }

    /// The factor of the same contacts with those `reversed` turned round (`c_k` as `-c_k`):
    /// `G` becomes `S G S`, `S` the diagonal of signs, whose factor is `S L S`, an entry's sign
    /// changed where one of its row and its column is turned; the diagonal stays.
    pub(crate) fn turn(&mut self, reversed: &[bool]) {
        for i in 0..self.rows() {
            for at in self.starts[i]..self.starts[i + 1] {
                if reversed[i] != reversed[self.columns[at] as usize] {
                    self.values[at] = -self.values[at];
                }
            }
        }
    }

    /// Keeps the first `rows` rows: the factor of their contacts alone.
    pub(crate) fn truncate(&mut self, rows: usize) {
        if rows >= self.rows() {
            return;
        }
        let end = self.starts[rows];
        self.columns.truncate(end);
        self.values.truncate(end);
        self.starts.truncate(rows + 1);
        self.diagonal.truncate(rows);
    }

    /// The entries stored, the diagonal's included.
    #[cfg(test)]
    pub(crate) fn entries(&self) -> usize {
        self.columns.len() + self.rows()
    }

    /// `L` written out.
    #[cfg(test)]
    fn dense(&self) -> Vec<Vec<f64>> {
        let n = self.rows();
        let mut l = vec![vec![0.0; n]; n];
        for (i, row) in l.iter_mut().enumerate() {
            for at in self.starts[i]..self.starts[i + 1] {
                row[self.columns[at] as usize] = self.values[at];
            }
            row[i] = self.diagonal[i];
        }
        l
    }
}

/// A programme's active contacts in order, with their [`GramFactor`]: what the dual method
/// keeps on the Gram matrix (`dynamics/impact.rs`), and what it takes to grow it: each ball's
/// contacts, so that a contact's column of `G` (the active contacts at its two balls) is found
/// without a pass over the active set, and each contact's place in it.
pub(crate) struct ActiveRows<'a> {
    contacts: &'a [ContactRow],
    inverse: &'a [f64],
    /// Ball `b`'s contacts are `at_ball[starts[b]..starts[b + 1]]`.
    starts: Vec<usize>,
    at_ball: Vec<usize>,
    /// Each contact's slot in `active`, or `usize::MAX`.
    slot_of: Vec<usize>,
    active: Vec<usize>,
    /// Whether each active row is thin: its pivot within [`NEAR_DEPENDENT`] of its length.
    thin_rows: Vec<bool>,
    /// Whether each active row joined with a refined pivot.
    refined_rows: Vec<bool>,
    factor: GramFactor,
}

impl<'a> ActiveRows<'a> {
    /// None of `contacts` active yet; `inverse` the balls' inverse masses.
    fn new(contacts: &'a [ContactRow], inverse: &'a [f64]) -> Self {
        let balls = inverse.len();
        let mut starts = vec![0_usize; balls + 1];
        for c in contacts {
            starts[c.a + 1] += 1;
            if let Some(b) = c.b {
                starts[b + 1] += 1;
            }
        }
        for i in 0..balls {
            starts[i + 1] += starts[i];
        }
        let mut at_ball = vec![0_usize; starts[balls]];
        let mut next = starts.clone();
        for (k, c) in contacts.iter().enumerate() {
            for ball in [Some(c.a), c.b].into_iter().flatten() {
                at_ball[next[ball]] = k;
                next[ball] += 1;
            }
        }
        ActiveRows {
            contacts,
            inverse,
            starts,
            at_ball,
            slot_of: vec![usize::MAX; contacts.len()],
            active: Vec::new(),
            thin_rows: Vec::new(),
            refined_rows: Vec::new(),
            factor: GramFactor::new(),
        }
    }

    /// The first of `active`, a start's contacts, joined with `factor`, their factor from an
    /// earlier programme over the same rows ([`Self::into_factor`], turned round where the
    /// programme takes a contact the other way round): as many as the factor has rows, none
    /// of them thin (none for an empty factor).
    pub(crate) fn with_factor(
        contacts: &'a [ContactRow],
        inverse: &'a [f64],
        factor: GramFactor,
        active: &[usize],
    ) -> Self {
        let mut rows = ActiveRows::new(contacts, inverse);
        let kept = factor.rows();
        debug_assert!(kept <= active.len());
        for (slot, &k) in active[..kept].iter().enumerate() {
            rows.slot_of[k] = slot;
        }
        rows.active = active[..kept].to_vec();
        rows.thin_rows = vec![false; kept];
        rows.refined_rows = vec![false; kept];
        rows.factor = factor;
        rows
    }

    /// The factor, up to its first thin row or row joined with a refined pivot: the rows a
    /// later programme over the same contacts in the same order factorises to the same bits
    /// (a start leaves a thin row out, and a refined pivot is not the one [`Self::row`]
    /// gives).
    pub(crate) fn into_factor(self) -> GramFactor {
        let mut factor = self.factor;
        let plain = |(t, r): (&bool, &bool)| *t || *r;
        if let Some(first) = self
            .thin_rows
            .iter()
            .zip(&self.refined_rows)
            .position(plain)
        {
            factor.truncate(first);
        }
        factor
    }

    /// The pivot of the active contact at `slot`.
    pub(crate) fn pivot(&self, slot: usize) -> f64 {
        self.factor.diagonal[slot]
    }

    /// `l . y` for the active contact at `slot`, from the factor's row (as [`Self::row`]'s
    /// `l` would give it, to the bit).
    pub(crate) fn dot_row(&self, slot: usize, y: &[f64]) -> f64 {
        self.factor.dot_row(slot, y)
    }

    /// The active contacts, in the factor's order.
    pub(crate) fn active(&self) -> &[usize] {
        &self.active
    }

    /// `G_kk`, contact `k`'s squared length in the metric of the inverse masses.
    pub(crate) fn own(&self, k: usize) -> f64 {
        gram(&self.contacts[k], &self.contacts[k], self.inverse)
    }

    /// Whether contact `k`'s pivot squared `d2` is within [`NEAR_DEPENDENT`] of its own
    /// squared length: a thin row, whose solves are refined.
    pub(crate) fn near(&self, k: usize, d2: f64) -> bool {
        d2 <= NEAR_DEPENDENT * self.own(k)
    }

    /// Whether contact `k`'s pivot squared `d2` is within [`TOO_NEAR`] of its own squared
    /// length: too near the span of the rows before it for the factor at all.
    pub(crate) fn too_near(&self, k: usize, d2: f64) -> bool {
        d2 <= TOO_NEAR * self.own(k)
    }

    /// Whether a solve with contact `k` (pivot squared `d2`) is refined: it is thin, or the
    /// factor holds a thin row.
    pub(crate) fn refines(&self, k: usize, d2: f64) -> bool {
        self.near(k, d2) || self.thin_rows.contains(&true)
    }

    /// One step of refinement of `r`, a step's rates (`G r = J_A M^-1 c_p`), from `z = M^-1
    /// (c_p - J_A^T r)`: the residual `J_A z` of the normal equations, solved on the factor,
    /// added to `r` (Bjorck's corrected semi-normal equations; the module documentation).
    pub(crate) fn refine(&self, r: &mut [f64], z: &[DVec2]) {
        let mut h: Vec<f64> = self
            .active
            .iter()
            .map(|&k| self.contacts[k].relative(z))
            .collect();
        self.factor.forward(&mut h);
        self.factor.backward(&mut h);
        for (ri, hi) in r.iter_mut().zip(&h) {
            *ri += hi;
        }
    }

    /// Contact `k`'s row against the factor's rows, `l = L^-1 g`, and its pivot squared
    /// `G_kk - l . l`.
    pub(crate) fn row(&self, k: usize) -> (Vec<f64>, f64) {
        let rows = self.factor.rows();
        let mut l = shelf::take(&REALS);
        l.resize(rows, 0.0);
        let c = &self.contacts[k];
        for ball in [Some(c.a), c.b].into_iter().flatten() {
            for &j in &self.at_ball[self.starts[ball]..self.starts[ball + 1]] {
                let slot = self.slot_of[j];
                if slot < rows {
                    l[slot] = gram(&self.contacts[j], c, self.inverse);
                }
            }
        }
        self.factor.forward(&mut l);
        let d2 = self.own(k) - l.iter().map(|x| x * x).sum::<f64>();
        (l, d2)
    }

    /// Contact `k` joins as the last row, with its [`Self::row`] `l` and diagonal `d`,
    /// `refined` if `d` is a refined solve's.
    pub(crate) fn join(&mut self, k: usize, l: &[f64], d: f64, refined: bool) {
        self.push_row(k, l, d, refined);
        self.slot_of[k] = self.active.len();
        self.active.push(k);
    }

    /// Keeps the first `rows` contacts.
    pub(crate) fn truncate(&mut self, rows: usize) {
        for &k in &self.active[rows.min(self.active.len())..] {
            self.slot_of[k] = usize::MAX;
        }
        self.active.truncate(rows);
        self.cut_factor(rows);
    }

    /// Contact `k`'s row `l` and diagonal `d` appended to the factor, marked thin or not and
    /// `refined` or not.
    fn push_row(&mut self, k: usize, l: &[f64], d: f64, refined: bool) {
        self.thin_rows.push(self.near(k, d * d));
        self.refined_rows.push(refined);
        self.factor.push(l, d);
    }

    /// Keeps the factor's first `rows` rows, with their marks.
    fn cut_factor(&mut self, rows: usize) {
        self.thin_rows.truncate(rows);
        self.refined_rows.truncate(rows);
        self.factor.truncate(rows);
    }

    /// The contact at `slot` leaves; those after it join the factor again in turn. Whether
    /// they all did: one within [`TOO_NEAR`] leaves the factor short of the set.
    pub(crate) fn remove(&mut self, slot: usize) -> bool {
        let gone = self.active.remove(slot);
        self.slot_of[gone] = usize::MAX;
        for (at, &k) in self.active.iter().enumerate().skip(slot) {
            self.slot_of[k] = at;
        }
        self.cut_factor(slot);
        for at in slot..self.active.len() {
            let k = self.active[at];
            let (l, d2) = self.row(k);
            if self.too_near(k, d2) {
                shelf::give(&REALS, l);
                return false;
            }
            self.push_row(k, &l, d2.sqrt(), false);
            shelf::give(&REALS, l);
        }
        true
    }

    /// `y <- L^-T y` ([`GramFactor::backward`]).
    pub(crate) fn backward(&self, y: &mut [f64]) {
        self.factor.backward(y);
    }

    /// `v + M^-1 J_A^T impulses`: the velocities the active contacts' impulses give.
    pub(crate) fn changed(&self, v: &[DVec2], impulses: &[f64]) -> Vec<DVec2> {
        let mut x = v.to_vec();
        for (&k, &l) in self.active.iter().zip(impulses) {
            let c = &self.contacts[k];
            match c.b {
                None => x[c.a] += c.normal * (l * self.inverse[c.a]),
                Some(b) => {
                    x[c.a] -= c.normal * (l * self.inverse[c.a]);
                    x[b] += c.normal * (l * self.inverse[b]);
                }
            }
        }
        x
    }

    /// `z <- z - J_A^T r`, `r` a coefficient for each active contact.
    pub(crate) fn subtract(&self, z: &mut [DVec2], r: &[f64]) {
        for (&j, &rj) in self.active.iter().zip(r) {
            let c = &self.contacts[j];
            match c.b {
                None => z[c.a] -= c.normal * rj,
                Some(b) => {
                    z[c.a] += c.normal * rj;
                    z[b] -= c.normal * rj;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    /// A chain of balls along a line, each touching the next, the first on a floor, with
    /// slanted normals and unequal masses: a sparse Gram matrix with fill.
    fn chain(balls: usize) -> (Vec<ContactRow>, Vec<f64>) {
        let mut rows = vec![ContactRow {
            a: 0,
            b: None,
            normal: DVec2::Y,
            target: 0.0,
            slack: 0.0,
        }];
        for i in 1..balls {
            let angle = 0.3 + 0.7 * (i as f64 * 1.7).sin();
            rows.push(ContactRow {
                a: i - 1,
                b: Some(i),
                normal: DVec2::new(angle.cos(), angle.sin()),
                target: 0.0,
                slack: 0.0,
            });
            // A second contact of every third ball with its neighbour but one.
            if i >= 2 && i % 3 == 0 {
                let normal = DVec2::new(1.0, -0.4).normalize();
                rows.push(ContactRow {
                    a: i - 2,
                    b: Some(i),
                    normal,
                    target: 0.0,
                    slack: 0.0,
                });
            }
        }
        let inverse = (0..balls).map(|i| 1.0 / (1.0 + (i % 4) as f64)).collect();
        (rows, inverse)
    }

    fn factor(rows: &[ContactRow], inverse: &[f64]) -> GramFactor {
        let mut factor = GramFactor::new();
        for (k, row) in rows.iter().enumerate() {
            let mut g: Vec<f64> = rows[..k].iter().map(|r| gram(r, row, inverse)).collect();
            factor.forward(&mut g);
            let d2 = gram(row, row, inverse) - g.iter().map(|x| x * x).sum::<f64>();
            assert!(d2 > NEAR_DEPENDENT * gram(row, row, inverse));
            factor.push(&g, d2.sqrt());
        }
        factor
    }

    /// The Gram matrix written out from the rows as dense vectors over the balls, without
    /// [`gram`]: an independent reference.
    fn dense_gram(rows: &[ContactRow], inverse: &[f64]) -> Vec<Vec<f64>> {
        let vector = |row: &ContactRow| {
            let mut v = vec![DVec2::ZERO; inverse.len()];
            match row.b {
                None => v[row.a] = row.normal,
                Some(b) => {
                    v[row.a] = -row.normal;
                    v[b] = row.normal;
                }
            }
            v
        };
        let vectors: Vec<_> = rows.iter().map(vector).collect();
        vectors
            .iter()
            .map(|x| {
                vectors
                    .iter()
                    .map(|y| {
                        (0..inverse.len())
                            .map(|i| x[i].dot(y[i]) * inverse[i])
                            .sum()
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn the_factor_times_its_transpose_is_the_gram_matrix() {
        let (rows, inverse) = chain(40);
        let factor = factor(&rows, &inverse);
        let l = factor.dense();
        let g = dense_gram(&rows, &inverse);
        let n = rows.len();
        for i in 0..n {
            for j in 0..n {
                let product: f64 = (0..n).map(|k| l[i][k] * l[j][k]).sum();
                assert!((product - g[i][j]).abs() < 1e-13, "{i} {j}");
            }
        }
        // Stored where not zero: far fewer entries than the lower triangle.
        assert!(factor.entries() < n * (n + 1) / 4, "{}", factor.entries());
    }

    #[test]
    fn forward_and_backward_solve_the_gram_system() {
        let (rows, inverse) = chain(30);
        let factor = factor(&rows, &inverse);
        let g = dense_gram(&rows, &inverse);
        let n = rows.len();
        let b: Vec<f64> = (0..n).map(|i| ((i * 7 % 11) as f64) - 5.0).collect();
        let mut x = b.clone();
        factor.forward(&mut x);
        factor.backward(&mut x);
        for i in 0..n {
            let gx: f64 = (0..n).map(|j| g[i][j] * x[j]).sum();
            assert!((gx - b[i]).abs() < 1e-10, "{i}: {gx} {}", b[i]);
        }
    }

    #[test]
    fn a_truncated_factor_is_the_factor_of_the_leading_rows() {
        let (rows, inverse) = chain(30);
        let mut whole = factor(&rows, &inverse);
        let part = factor(&rows[..17], &inverse);
        whole.truncate(17);
        assert_eq!(whole.dense(), part.dense());
        // And it grows again to the same bits.
        let again = factor(&rows, &inverse);
        for (k, row) in rows.iter().enumerate().skip(17) {
            let mut g: Vec<f64> = rows[..k].iter().map(|r| gram(r, row, &inverse)).collect();
            whole.forward(&mut g);
            let d2 = gram(row, row, &inverse) - g.iter().map(|x| x * x).sum::<f64>();
            whole.push(&g, d2.sqrt());
        }
        assert_eq!(whole.dense(), again.dense());
    }

    /// A factor turned round where some rows are reversed is, to the bit, the factor of the
    /// reversed rows, and its rows' products with a vector are the dense row's.
    #[test]
    fn a_turned_factor_is_the_factor_of_the_reversed_rows() {
        let (rows, inverse) = chain(30);
        let reversed: Vec<bool> = (0..rows.len()).map(|k| k % 3 == 1 || k == 0).collect();
        let turned_rows: Vec<ContactRow> = rows
            .iter()
            .zip(&reversed)
            .map(|(row, &r)| ContactRow {
                normal: if r { -row.normal } else { row.normal },
                ..*row
            })
            .collect();
        let mut turned = factor(&rows, &inverse);
        turned.turn(&reversed);
        let fresh = factor(&turned_rows, &inverse);
        assert_eq!(turned.dense(), fresh.dense());
        let l = fresh.dense();
        let y: Vec<f64> = (0..rows.len()).map(|i| (i as f64 * 0.37).sin()).collect();
        for (i, row) in l.iter().enumerate() {
            let dense = row[..i].iter().zip(&y).map(|(a, b)| a * b).sum::<f64>();
            assert_eq!(fresh.dot_row(i, &y[..i]), dense);
        }
    }
}
