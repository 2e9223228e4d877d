//! A simultaneous impact: several contacts among several balls resolved at once.
//!
//! Balls `i` of mass `m_i` with velocities `v_i` touch each other and static surfaces at
//! contacts `k`, each with a unit normal `n_k` and a relative normal velocity `u_k(v)`: for a
//! ball `a` against a surface, `n_k . v_a` (`n_k` from the surface to the ball); for balls `a`
//! and `b`, `n_k . (v_b - v_a)` (`n_k` from `a` to `b`). Every contact `k` asks for
//! `u_k >= w_k`, its *target* (its restitution times the speed at which it approached, or
//! zero), less a slack `s_k` of rounding. The impact is the change of velocities that meets
//! every target with the least change of kinetic energy in the balls' own frame,
//!
//! ```text
//! minimise  sum_i m_i |v'_i - v_i|^2 / 2   subject to   u_k(v') >= w_k - s_k  for all k,
//! ```
//!
//! a strictly convex quadratic programme (the masses make its Hessian positive definite).
//! Its multipliers are the contacts' impulses: non-negative (a contact pushes, never pulls),
//! and zero at a contact that separates faster than asked, so the answer is the impulse law
//! of rigid bodies in unilateral contact (Moreau 1988; with every target zero, the perfectly
//! plastic impact, whose result is the projection of the velocities onto the cone of
//! velocities that penetrate nothing, in the kinetic-energy metric). Such a projection never
//! adds kinetic energy when every target is zero: the velocities all zero are feasible, and a
//! projection onto a convex set holding them is no longer than what it projects.
//!
//! It is solved exactly, in a finite number of steps, by the dual active-set method of
//! Goldfarb and Idnani ("A numerically stable dual method for solving strictly convex
//! quadratic programs", Math. Programming 27, 1983): start from the unconstrained minimum
//! `v' = v`, and add violated constraints one at a time, each with the step along the
//! directions the active constraints leave free that satisfies it, dropping an active
//! constraint whose impulse would turn negative on the way. Each full step raises the dual
//! objective strictly, so no active set repeats. A constraint that depends linearly on the
//! active ones (within `DEPENDENT` of its own length: two opposite walls of an exact-fit
//! channel) is met by the partial steps alone, or is infeasible.
//!
//! The method may also start from any set of independent contacts met exactly whose impulses
//! all push (an S-pair, in Goldfarb and Idnani's words), factorised: a jam's hold solves its
//! accelerations over the contacts its projection of the velocities has just factorised, and
//! starts there ([`resolve_impact_from`]). With equalities (contacts met exactly, see
//! [`resolve_with_equalities_factored`]) it starts from the least change that meets them all,
//! their impulses free in sign ([`Problem::equalities_met`]).
//!
//! Two factorisations of the active contacts carry the method's linear algebra. Below
//! [`GRAM_FROM`] balls, and wherever a contact comes within `TOO_NEAR` of the span of the
//! active ones, their Gram-Schmidt basis ([`Basis`]): accurate to the rounding of each contact
//! itself, down to the thin wedges [`DEPENDENT`] tells from dependences. From [`GRAM_FROM`]
//! balls on, a sparse Cholesky factor of their Gram matrix `J_A M^-1 J_A^T`
//! (`dynamics/gram.rs`, [`solve_on_gram`]): a pile's contact meets the few others at its two
//! balls, so the factor's rows are short, where a basis vector reaches half its cluster. It
//! squares the rows' condition, so its solves are refined once where a contact is within
//! `NEAR_DEPENDENT` of the active ones, and a contact within `TOO_NEAR` hands the programme
//! back to the basis, which solves it from the start.

use std::cell::{Cell, RefCell};

use glam::DVec2;

use super::gram::{ActiveRows, GramFactor};
use super::shelf::{self, REALS, Shelf, VECTORS};

/// A contact of a simultaneous impact: see the module documentation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ContactRow {
    /// The ball (index into the impact's balls).
    pub a: usize,
    /// The other ball, or `None` for a static surface.
    pub b: Option<usize>,
    /// Unit normal: from the surface to `a`, or from `a` to `b`.
    pub normal: DVec2,
    /// The relative normal velocity asked for.
    pub target: f64,
    /// How far below the target rounding may leave it.
    pub slack: f64,
}

impl ContactRow {
    /// The relative velocity (or acceleration) of `x` along the row's normal: `n . x_a` for a
    /// surface, `n . (x_b - x_a)` for two balls.
    pub(crate) fn relative(&self, x: &[DVec2]) -> f64 {
        match self.b {
            None => self.normal.dot(x[self.a]),
            Some(b) => self.normal.dot(x[b] - x[self.a]),
        }
    }

    /// The same contact along its tangent, the normal turned a quarter counter-clockwise.
    pub(crate) fn tangent(self) -> ContactRow {
        ContactRow {
            normal: self.normal.perp(),
            ..self
        }
    }
}

/// Why an impact has no solution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ImpactError {
    /// The targets cannot all be met (a ball between two opposite walls asked to leave one
    /// of them).
    Infeasible,
}

/// A constraint whose part independent of the active ones is below this fraction of its own
/// length (in the metric of the inverse masses) depends on them: `1e-28`, the square of the
/// sine of an angle of `1e-14`, some fifty ulps. That part is computed to about `eps` of the
/// constraint's length, so at this angle it still has two good digits: a point `5e-7` off the
/// line of a floor `5e5` away (an angle of `1e-12`: an exact-fit gap between a floor and a
/// ceiling's end at a scale of `1e6`) is a thin wedge that pins a ball and can be met; two
/// walls of an exact-fit channel opposite to a rounding error depend on each other (and the
/// slack keeps the second from being violated). (It was `1e-24`: that wedge of `1e-12` was
/// taken for dependent, and its ball's acceleration declared infeasible.)
const DEPENDENT: f64 = 1e-28;

/// How independent of the equalities before it an equality must be to join the point the
/// dual method starts from ([`Problem::equalities_met`]): its part orthogonal to them at least
/// `1e-6` of its squared length (in the metric of the inverse masses), an angle of `1e-3`.
/// One nearer dependence is left to the dual steps, which add it only where it is violated,
/// as they always did. Joined at once, a thin wedge's pair of resting contacts (a sine of
/// `1e-12`) asked for opposite impulses of `1e12` times the velocities, whose rounding the
/// solve then refused: 16 of the 6,140 projections of the 400-ball pile from t = 2.0 to 2.02
/// (seed 1, e = 0.5) had no answer where the steps found one. At this bound every one has an
/// answer, within `1e-9` of the fastest speed of the steps' (with friction, 11 of 7,995 differ
/// by up to `2e-6` of it: both meet every contact to the solve's tolerance, at two points of a
/// thin wedge of stuck tangents).
const WELL_APART: f64 = 1e-6;

/// The velocities after the simultaneous impact of balls of `masses` with `velocities` at
/// `contacts` (see the module documentation).
///
/// # Errors
/// [`ImpactError::Infeasible`] if no velocities meet every target.
pub(crate) fn resolve_impact(
    masses: &[f64],
    velocities: &[DVec2],
    contacts: &[ContactRow],
) -> Result<Vec<DVec2>, ImpactError> {
    solve(masses, velocities, contacts, 0, None).map(|(x, _, _)| x)
}

/// As [`resolve_impact`], with each contact's impulse: its multiplier, the magnitude of the
/// impulse along its normal (on `a` for a surface; on `b`, and its opposite on `a`, for two
/// balls), zero for a contact not in the active set. The velocities are those of
/// [`resolve_impact`], to the bit; `x = v + M^-1 sum_k l_k c_k` to the rounding of the solve.
///
/// # Errors
/// [`ImpactError::Infeasible`] if no velocities meet every target.
pub(crate) fn resolve_impact_with_impulses(
    masses: &[f64],
    velocities: &[DVec2],
    contacts: &[ContactRow],
) -> Result<(Vec<DVec2>, Vec<f64>), ImpactError> {
    let (x, start, impulses) = solve(masses, velocities, contacts, 0, None)?;
    let mut each = vec![0.0; contacts.len()];
    for (&k, &l) in start.active.iter().zip(&impulses) {
        each[k] += l;
    }
    Ok((x, each))
}

/// As [`resolve_impact_with_impulses`], the dual method started from `start` if any (see
/// [`resolve_impact_from`]), with its own end as a start for the next solve of the same
/// contacts: a group's friction solves one programme again and again with other forces
/// (`dynamics/contact_friction.rs`), and its active set seldom changes from one to the next.
///
/// # Errors
/// [`ImpactError::Infeasible`] if no velocities meet every target.
pub(crate) fn resolve_impact_with_impulses_from(
    masses: &[f64],
    velocities: &[DVec2],
    contacts: &[ContactRow],
    start: Option<Start>,
) -> Result<(Vec<DVec2>, Vec<f64>, Start), ImpactError> {
    let (x, end, impulses) = solve(masses, velocities, contacts, 0, start)?;
    let mut each = vec![0.0; contacts.len()];
    for (&k, &l) in end.active.iter().zip(&impulses) {
        each[k] += l;
    }
    Ok((x, each, end))
}

/// As [`resolve_impact_with_impulses`], the dual method started from a guess of its active
/// set: the contacts `guess` (indices into `contacts`, none factorised), those the optimum is
/// likely to push at. A pile's cluster is solved for its accelerations microseconds after the
/// last solve of nearly the same contacts, and the contacts that pushed then mostly push
/// now: a start from them ends in a few steps, where the projection's active set (every
/// contact resting, its impulses an equality's, which pull at a quarter of them) first drops
/// those that pull and then adds most of them back, one step each (`WARM_FROM` in
/// `pipeline/jam.rs`).
///
/// Any guess will do: as for [`resolve_impact_from`], the start is first made a set of
/// independent contacts met exactly whose impulses all push (a contact nearly dependent on
/// those before it stays out; while an impulse pulls, the contacts from the first that pulls
/// join again without those that pull), and the dual method goes on from there to the
/// programme's only optimum. The guess is only taken on the Gram matrix's factor (from
/// [`GRAM_FROM`] balls): where that hands the programme back (a thin wedge), or below it, the
/// answer is `None`, and the caller solves the programme from a start of its own (the
/// Gram-Schmidt basis, whose start must be independent contacts, solved the handed-back ones
/// from nothing in 12 to 18 ms each, five times a solve from the projection's factor).
pub(crate) fn resolve_impact_guessed(
    masses: &[f64],
    velocities: &[DVec2],
    contacts: &[ContactRow],
    guess: &[usize],
) -> Option<(Vec<DVec2>, Vec<f64>)> {
    if masses.len() < GRAM_FROM {
        return None;
    }
    let speed = velocities.iter().fold(0.0_f64, |s, v| s.max(v.length()));
    let problem = Problem::new(masses, contacts, speed);
    let (x, end, impulses) =
        solve_on_gram(&problem, velocities, 0, Some((guess, GramFactor::new())))?;
    let mut each = vec![0.0; contacts.len()];
    for (&k, &l) in end.active.iter().zip(&impulses) {
        each[k] += l;
    }
    Some((x, each))
}

/// As [`resolve_impact_with_impulses`], the dual method started from `start`: contacts of
/// another programme over the same balls and normals, already factorised
/// ([`Factored::restate`]).
///
/// Any set of independent contacts met exactly whose impulses are all non-negative is a
/// point the dual method may start from (Goldfarb and Idnani 1983 call it an S-pair: the
/// least change that meets those contacts exactly, pushing at each): its steps go on from
/// there as from the empty set, and end at the same optimum, the programme's only one (it is
/// strictly convex). So the start is first made such a set: its least change is computed
/// from the basis (`x = v + M^-1 sum_i y_i q_i`, `R^T y` the contacts' shortfalls, the
/// impulses `R^-1 y`), and while an impulse comes out negative those contacts leave the set
/// (each round drops one at least, so the rounds end).
///
/// The hold's accelerations are a projection over the contacts its projection of the
/// velocities has just factorised: started from there, a pile's cluster of a hundred balls
/// joins its 170 contacts at once instead of one at a time, each step projecting a contact
/// against all those before it.
///
/// # Errors
/// [`ImpactError::Infeasible`] if no velocities meet every target.
pub(crate) fn resolve_impact_from(
    masses: &[f64],
    velocities: &[DVec2],
    contacts: &[ContactRow],
    start: Start,
) -> Result<(Vec<DVec2>, Vec<f64>), ImpactError> {
    resolve_impact_with_impulses_from(masses, velocities, contacts, Some(start))
        .map(|(x, impulses, _)| (x, impulses))
}

/// The contacts a solve ended with met exactly (its active set), factorised: each an index
/// into the contacts it was given, `equalities` then `inequalities` (see
/// [`resolve_with_equalities_factored`]), and whether the factorisation holds its reverse, in
/// its order. The factorisation is the Gram-Schmidt basis, or, where the Gram matrix's factor
/// solved the programme, that factor up to its first thin or refined row
/// (`ActiveRows::into_factor`, `dynamics/gram.rs`).
pub(crate) struct Factored {
    contacts: Vec<(usize, bool)>,
    basis: Basis,
    factor: GramFactor,
}

/// A start for [`resolve_impact_from`]: contacts (indices into its programme's), and a
/// basis, or a Gram matrix's factor, that factorises the first of them, in their order (the
/// rest join it in turn).
pub(crate) struct Start {
    active: Vec<usize>,
    basis: Basis,
    factor: GramFactor,
}

impl Factored {
    /// The same factorisation with each contact's index `k` renamed `name(k)`.
    pub(crate) fn restated(mut self, name: impl Fn(usize) -> usize) -> Self {
        for (k, _) in &mut self.contacts {
            *k = name(*k);
        }
        self
    }

    /// The same factorisation as a start for a programme whose contacts are `index` of these
    /// (`None`: not one of its contacts), each taken the way round these are given. The basis
    /// is kept up to the first contact the programme lacks (a QR factorisation's first
    /// columns are those columns' own); the contacts after it join it again when the
    /// programme starts, in turn (rotating each missing one out instead mixes the supports of
    /// every vector after it, and every later projection reads them). One the kept basis
    /// holds reversed (an equality met from its other side) is turned round (its column, its
    /// row of `R` and its vector change sign, so that the diagonal stays positive and every
    /// product holds). A Gram matrix's factor is kept and turned round likewise
    /// ([`GramFactor::turn`]).
    pub(crate) fn restate(self, index: impl Fn(usize) -> Option<usize>) -> Start {
        let Factored {
            contacts,
            mut basis,
            mut factor,
        } = self;
        let mut active = Vec::with_capacity(contacts.len());
        let mut turned = Vec::with_capacity(contacts.len());
        let mut kept = None;
        for (slot, (k, reversed)) in contacts.into_iter().enumerate() {
            let Some(at) = index(k) else {
                kept.get_or_insert(active.len());
                continue;
            };
            // A basis shorter than the contacts (none, from the Gram matrix's solve) is
            // extended when the programme starts.
            if reversed && kept.is_none() && slot < basis.q.len() {
                basis.turn(slot);
            }
            active.push(at);
            turned.push(reversed);
        }
        if let Some(columns) = kept {
            basis.truncate(columns);
            factor.truncate(columns);
        }
        turned.truncate(factor.rows());
        factor.turn(&turned);
        Start {
            active,
            basis,
            factor,
        }
    }
}

/// As [`resolve_impact`], with the contacts `equalities` asked to meet their targets exactly
/// (`u_k = w_k`, to within their slack on either side) and the contacts `inequalities` as an
/// impact asks (`u_k >= w_k`); with the answer, the active set it ended with, factorised: a
/// start for a programme over the same contacts ([`Factored::restate`]); and each contact's
/// impulse (as [`resolve_impact_with_impulses`]; `equalities` then `inequalities`, an
/// equality's negative where it pulls).
///
/// An equality is a contact and its reverse (`-u_k >= -w_k`), met together. Given to
/// [`resolve_impact`] as two contacts, the pair depends on itself, and the dual method turned
/// each such pair over by partial steps, adding one, then the other, which dropped the first,
/// again and again (the hold's projection of a pile's cluster, every contact resting, took
/// 278 steps for 157 contacts so, and four times the time of the same problem solved here).
/// Here either of the two is added as any violated contact is, but once added an equality is
/// never dropped: its impulse may take either sign, so it takes no part in the partial steps,
/// and its reverse, met with it, is never added (Goldfarb and Idnani 1983 keep equality
/// constraints active in the same way).
///
/// # Errors
/// [`ImpactError::Infeasible`] if no velocities meet every target.
pub(crate) fn resolve_with_equalities_factored(
    masses: &[f64],
    velocities: &[DVec2],
    equalities: &[ContactRow],
    inequalities: &[ContactRow],
) -> Result<(Vec<DVec2>, Factored, Vec<f64>), ImpactError> {
    let contacts = with_reverses(equalities, inequalities);
    let (
        x,
        Start {
            active,
            basis,
            factor,
        },
        impulses,
    ) = solve(masses, velocities, &contacts, equalities.len(), None)?;
    // An equality's reverse is named by the equality, turned round.
    let given = equalities.len() + inequalities.len();
    let mut each = vec![0.0; given];
    for (&k, &l) in active.iter().zip(&impulses) {
        if k < given {
            each[k] += l;
        } else {
            each[k - given] -= l;
        }
    }
    let contacts = active
        .into_iter()
        .map(|k| {
            if k < given {
                (k, false)
            } else {
                (k - given, true)
            }
        })
        .collect();
    Ok((
        x,
        Factored {
            contacts,
            basis,
            factor,
        },
        each,
    ))
}

/// The programme [`resolve_with_equalities_factored`] solves: `equalities`, then
/// `inequalities`, then each equality's reverse (`-u_k >= -w_k`), in the equalities' order.
fn with_reverses(equalities: &[ContactRow], inequalities: &[ContactRow]) -> Vec<ContactRow> {
    let reversed = equalities.iter().map(|row| ContactRow {
        normal: -row.normal,
        target: -row.target,
        ..*row
    });
    equalities
        .iter()
        .chain(inequalities)
        .copied()
        .chain(reversed)
        .collect()
}

/// [`resolve_with_equalities_factored`]'s answer alone.
#[cfg(test)]
pub(crate) fn resolve_with_equalities(
    masses: &[f64],
    velocities: &[DVec2],
    equalities: &[ContactRow],
    inequalities: &[ContactRow],
) -> Result<Vec<DVec2>, ImpactError> {
    resolve_with_equalities_factored(masses, velocities, equalities, inequalities)
        .map(|(x, _, _)| x)
}

/// The dual active-set method (see the module documentation) on `contacts`: the first
/// `equalities` of them and the last as many are the equalities and their reverses, in the
/// same order (see [`resolve_with_equalities_factored`]); the rest are inequalities; from
/// `start` if given (see [`resolve_impact_from`]). With the answer, its active set (indices
/// into `contacts`) and their basis, as a start for a later programme, and their impulses
/// (the multipliers, in the active set's order). Programmes of [`GRAM_FROM`] balls and more
/// are solved on the Gram matrix's factor ([`solve_on_gram`]) unless it hands them back; their
/// start then has no basis (the Gram-Schmidt solve extends it from none, should it be given
/// that start).
fn solve(
    masses: &[f64],
    velocities: &[DVec2],
    contacts: &[ContactRow],
    equalities: usize,
    mut start: Option<Start>,
) -> Result<(Vec<DVec2>, Start, Vec<f64>), ImpactError> {
    let speed = velocities.iter().fold(0.0_f64, |s, v| s.max(v.length()));
    let problem = Problem::new(masses, contacts, speed);
    // A start factorised on the basis (the projection it comes from was handed back: a
    // contact came near the span of the others) goes on there: on the factor, two in three
    // such accelerations were handed back too, after the work of a solve (100-ball piles),
    // and the basis reuses its columns.
    let on_basis = start.as_ref().is_some_and(|s| !s.basis.q.is_empty());
    if masses.len() >= GRAM_FROM && !on_basis {
        let from = start.as_mut().map(|s| {
            let factor = std::mem::replace(&mut s.factor, GramFactor::new());
            (s.active.as_slice(), factor)
        });
        if let Some(answer) = solve_on_gram(&problem, velocities, equalities, from) {
            return Ok(answer);
        }
    }
    solve_on_basis(&problem, velocities, equalities, start)
}

/// [`solve`] on the Gram-Schmidt basis of the active contacts: every programme below
/// [`GRAM_FROM`] balls, and those [`solve_on_gram`] hands back.
fn solve_on_basis(
    problem: &Problem,
    velocities: &[DVec2],
    equalities: usize,
    start: Option<Start>,
) -> Result<(Vec<DVec2>, Start, Vec<f64>), ImpactError> {
    let (masses, contacts) = (problem.masses, problem.contacts);
    let count = contacts.len();
    let twin = |k: usize| twin_of(k, count, equalities);
    let mut x: Vec<DVec2> = velocities.to_vec();
    // Only a constraint independent of the active ones joins them (a dependent one is met
    // by partial steps), so they are at most twice the balls (the velocities' dimension):
    // room for them from the start, so that growing the set copies nothing.
    let room = count.min(2 * masses.len() + 2);
    let mut active: Vec<usize> = Vec::with_capacity(room);
    // Active, or (an equality) met by its active twin.
    let mut is_active = vec![false; count];
    let mut impulses: Vec<f64> = Vec::with_capacity(room);
    let mut basis = Basis {
        q: Vec::with_capacity(room),
        r: Vec::with_capacity(room),
    };
    if let Some(start) = start {
        debug_assert_eq!(equalities, 0, "a start is for inequalities alone");
        (x, active, impulses, basis) = problem.pushing(velocities, start);
        for &k in &active {
            is_active[k] = true;
        }
    } else if equalities > 0 {
        (x, active, impulses, basis) = problem.equalities_met(velocities, equalities);
        for &k in &active {
            is_active[k] = true;
            is_active[twin(k).expect("an equality has a reverse")] = true;
        }
    }
    let mut state = State {
        x,
        active,
        is_active,
        impulses,
    };
    let mut on_basis = OnBasis(basis);
    dual_steps(problem, velocities, equalities, &mut on_basis, &mut state)
        .ok_or(ImpactError::Infeasible)?;
    let State {
        x,
        active,
        impulses,
        ..
    } = state;
    let OnBasis(mut basis) = on_basis;
    // The last contact added joins the basis only at the next step: here, so that the
    // basis factorises the whole active set.
    problem.extend(&mut basis, &active);
    let factor = GramFactor::new();
    Ok((
        x,
        Start {
            active,
            basis,
            factor,
        },
        impulses,
    ))
}

/// The other half of an equality, if `k` is one, among `count` contacts whose first and last
/// `equalities` are the equalities and their reverses, in the same order.
fn twin_of(k: usize, count: usize, equalities: usize) -> Option<usize> {
    if k < equalities {
        Some(k + count - equalities)
    } else if k >= count - equalities {
        Some(k + equalities - count)
    } else {
        None
    }
}

/// Where the dual method stands: the velocities, the active contacts (in their
/// factorisation's order), which contacts are active (or, an equality, met by its active
/// twin), and the active contacts' impulses.
struct State {
    x: Vec<DVec2>,
    active: Vec<usize>,
    is_active: Vec<bool>,
    impulses: Vec<f64>,
}

/// What the dual method's steps ask of a factorisation of the active contacts: the Gram-Schmidt
/// basis ([`OnBasis`]) or the Gram matrix's sparse Cholesky factor ([`OnGram`]).
trait Factorisation {
    /// For a violated contact `p`: the active impulses' rates `r` (how fast each must fall
    /// per unit of `p`'s impulse to keep its contact met) and the velocity change `z = M^-1
    /// (c_p - sum_j r_j c_j)` per unit of it (give it back with [`Problem::recycle`]); `None`
    /// where this factorisation cannot tell it accurately.
    fn direction(
        &mut self,
        problem: &Problem,
        active: &[usize],
        p: usize,
    ) -> Option<(Vec<f64>, Vec<DVec2>)>;

    /// `p`, whose direction was the last asked for, joins as the last active contact.
    fn join(&mut self, p: usize);

    /// The active contact at `slot` leaves; `false` where the factorisation cannot take the
    /// rest.
    fn remove(&mut self, problem: &Problem, slot: usize) -> bool;
}

/// The dual method's steps (see the module documentation) from `state`, a point it may start
/// from, to the answer, which is checked: every contact met to its tolerance, and no more
/// kinetic energy than `velocities` where every target is zero or below. `None` where there
/// is no answer: no step meets a violated contact (it depends on the active ones and none of
/// them can give way), the steps went round (rounding), the factorisation cannot take a step,
/// or the answer failed the checks.
fn dual_steps(
    problem: &Problem,
    velocities: &[DVec2],
    equalities: usize,
    factorisation: &mut impl Factorisation,
    state: &mut State,
) -> Option<()> {
    let count = problem.contacts.len();
    let twin = |k: usize| twin_of(k, count, equalities);
    let State {
        x,
        active,
        is_active,
        impulses,
    } = state;
    // Each full step adds a constraint and each partial step drops one, so in exact
    // arithmetic the work is bounded by the number of active sets visited, none twice. This
    // bound only guards against rounding making a step repeat.
    let mut budget = 64 * (count + 2 * problem.masses.len()) + 64;
    while let Some(p) = problem.most_violated(x, is_active) {
        let mut added = 0.0;
        loop {
            budget = budget.checked_sub(1)?;
            let (r, z) = factorisation.direction(problem, active, p)?;
            let zz = problem.dot(p, &z);
            let dependent = zz <= DEPENDENT * problem.norm_squared(p);
            // The largest step that keeps every active inequality's impulse non-negative.
            let mut partial: Option<(f64, usize)> = None;
            for (slot, (&rj, &uj)) in r.iter().zip(impulses.iter()).enumerate() {
                if rj > 0.0 && twin(active[slot]).is_none() {
                    let t = uj / rj;
                    if partial.is_none_or(|(best, _)| t < best) {
                        partial = Some((t, slot));
                    }
                }
            }
            let short = problem.shortfall(p, x);
            let full = (!dependent).then(|| short / zz);
            let t = match (full, partial) {
                (Some(f), Some((q, _))) => f.min(q),
                (Some(f), None) => f,
                (None, Some((q, _))) => q,
                (None, None) => return None,
            };
            if !dependent {
                for (xi, zi) in x.iter_mut().zip(&z) {
                    *xi += *zi * t;
                }
            }
            problem.recycle(z);
            for (uj, &rj) in impulses.iter_mut().zip(&r) {
                *uj -= t * rj;
            }
            shelf::give(&REALS, r);
            added += t;
            if full.is_some_and(|f| t >= f) {
                factorisation.join(p);
                active.push(p);
                is_active[p] = true;
                if let Some(other) = twin(p) {
                    is_active[other] = true;
                }
                impulses.push(added);
                break;
            }
            let (_, slot) = partial.expect("a partial step has a constraint to drop");
            is_active[active.remove(slot)] = false;
            impulses.remove(slot);
            if !factorisation.remove(problem, slot) {
                return None;
            }
        }
    }
    // Rounding in a badly conditioned set (constraints nearly dependent, far from the
    // velocities) could leave an active one unmet: such an answer is refused.
    let speed = problem.fastest(x);
    let met = (0..count).all(|k| problem.shortfall(k, x) <= 2.0 * problem.tolerance_at(k, speed));
    (met && problem.no_longer(velocities, x)).then_some(())
}

/// The Gram-Schmidt basis as the dual method's factorisation.
struct OnBasis(Basis);

impl Factorisation for OnBasis {
    fn direction(
        &mut self,
        problem: &Problem,
        active: &[usize],
        p: usize,
    ) -> Option<(Vec<f64>, Vec<DVec2>)> {
        Some(problem.step_direction(&mut self.0, active, p))
    }

    /// Nothing yet: the basis takes the contact at the next step ([`Problem::extend`]), from
    /// the residual this step kept.
    fn join(&mut self, _: usize) {}

    fn remove(&mut self, problem: &Problem, slot: usize) -> bool {
        self.0.remove(slot);
        problem.last_residual.set(None);
        true
    }
}

/// The balls from which a programme is first solved on its active contacts' Gram matrix
/// ([`solve_on_gram`]), Gram-Schmidt taking it over only where that hands it back: a pile's
/// jams of forty balls and more, whose basis vectors reach half their cluster (BENCHMARKS.md,
/// stops 54 and 55). Below it the basis is about as fast (20 to 39 balls: 15 to 20 % slower
/// than the factor before the hand-backs are paid for; under 20, faster), and the bits of
/// every scene whose clusters stay smaller stand.
const GRAM_FROM: usize = 40;

/// The dual method of [`solve`] on a sparse Cholesky factor of the active contacts' Gram
/// matrix `G = J_A M^-1 J_A^T` (`dynamics/gram.rs`) instead of their Gram-Schmidt basis: the
/// same steps, the same active sets, the same answer to rounding, where every contact that
/// joins is independent of those before it by [`TOO_NEAR`](super::gram::TOO_NEAR), the
/// solves refined once below [`NEAR_DEPENDENT`](super::gram::NEAR_DEPENDENT), from `start`'s
/// contacts and the factor of the first of them if given. The velocities, the active set with
/// its factor (as a [`Start`], for a later programme) and its impulses; `None` hands the
/// programme back to Gram-Schmidt (a pivot below `TOO_NEAR`: an exact-fit channel's opposite
/// walls, an exact dependence, the thinnest wedges; or an answer the final checks refuse). The
/// steps are [`dual_steps`], the basis's own: only the start and the linear algebra differ.
///
/// In the factor's terms, with `g` a contact's column of `G` against the active rows and
/// `l = L^-1 g`: a violated contact `p`'s step has the rates `r = L^-T l` (`G r = J_A M^-1
/// c_p`), the direction `z = M^-1 (c_p - J_A^T r)`, and `c_p . z = G_pp - l . l`, the square of
/// the pivot `p` would join with. From a start or from the equalities, the least change that
/// meets the rows joined so far is `x = v + M^-1 J_A^T L^-T y`, `y = L^-1 b` and `b` their
/// shortfalls at `v`: a contact's shortfall at that `x` is `b_k - l . y`, and joining it
/// appends `(b_k - l . y) / d` to `y` (forward substitution), so the equalities are checked
/// and joined in turn without forming `x`.
fn solve_on_gram(
    problem: &Problem,
    velocities: &[DVec2],
    equalities: usize,
    start: Option<(&[usize], GramFactor)>,
) -> Option<(Vec<DVec2>, Start, Vec<f64>)> {
    let contacts = problem.contacts;
    let count = contacts.len();
    let twin = |k: usize| twin_of(k, count, equalities);
    let inverse = &problem.inverse_masses;
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let (start, factor) = match start {
        Some((start, factor)) => (Some(start), factor),
        None => (None, GramFactor::new()),
    };
    let mut rows = ActiveRows::with_factor(contacts, inverse, factor, start.unwrap_or(&[]));
    let mut is_active = vec![false; count];
    let x;
    let impulses;
    if let Some(start) = start {
        // As `Problem::pushing`: the start's rows joined in turn, and while an impulse pulls,
        // the rows from the first that pulls joined again without those that pull. A row
        // nearly dependent on those before it stays out (a start need only be independent
        // rows that push): the steps add it again where it is violated. The first rows come
        // factorised (the projection's factor, where the accelerations start from its
        // contacts), as they would join, to the bit.
        let kept = rows.active().len();
        let mut y: Vec<f64> = Vec::with_capacity(start.len());
        for (slot, &k) in start[..kept].iter().enumerate() {
            y.push((problem.shortfall(k, velocities) - rows.dot_row(slot, &y)) / rows.pivot(slot));
        }
        let mut joining = start[kept..].to_vec();
        loop {
            for k in joining.drain(..) {
                let (l, d2) = rows.row(k);
                if !rows.near(k, d2) {
                    let d = d2.sqrt();
                    y.push((problem.shortfall(k, velocities) - dot(&l, &y)) / d);
                    rows.join(k, &l, d, false);
                }
                shelf::give(&REALS, l);
            }
            let mut lambda = y.clone();
            rows.backward(&mut lambda);
            let Some(first) = lambda.iter().position(|&l| l < 0.0) else {
                x = rows.changed(velocities, &lambda);
                impulses = lambda;
                break;
            };
            let active = rows.active();
            joining.extend(
                (first..active.len())
                    .filter(|&j| lambda[j] >= 0.0)
                    .map(|j| active[j]),
            );
            rows.truncate(first);
            y.truncate(first);
        }
        for &k in rows.active() {
            is_active[k] = true;
        }
    } else {
        // As `Problem::equalities_met`: each equality not met already joins, unless it is
        // nearly dependent on those before it (within `WELL_APART`, as the basis tells them):
        // that one is left to the steps, which take it (refined) if it is violated.
        let speed = problem.fastest(velocities);
        let mut y: Vec<f64> = Vec::new();
        for k in 0..equalities {
            let (l, d2) = rows.row(k);
            let short = problem.shortfall(k, velocities) - dot(&l, &y);
            if short.abs() > problem.tolerance_at(k, speed) && d2 > WELL_APART * rows.own(k) {
                let d = d2.sqrt();
                y.push(short / d);
                rows.join(k, &l, d, false);
                is_active[k] = true;
                is_active[twin(k).expect("an equality has a reverse")] = true;
            }
            shelf::give(&REALS, l);
        }
        rows.backward(&mut y);
        x = rows.changed(velocities, &y);
        impulses = y;
    }
    let active = rows.active().to_vec();
    let mut state = State {
        x,
        active,
        is_active,
        impulses,
    };
    let mut on_gram = OnGram { rows, last: None };
    dual_steps(problem, velocities, equalities, &mut on_gram, &mut state)?;
    let start = Start {
        active: state.active,
        basis: Basis::default(),
        factor: on_gram.rows.into_factor(),
    };
    Some((state.x, start, state.impulses))
}

/// The Gram matrix's sparse Cholesky factor as the dual method's factorisation, with the row
/// the last direction computed (the contact, `L^-1 g`, its pivot squared, and whether that
/// pivot is a refined solve's), which it appends should that contact join.
struct OnGram<'a> {
    rows: ActiveRows<'a>,
    last: Option<(usize, Vec<f64>, f64, bool)>,
}

impl Factorisation for OnGram<'_> {
    /// `r = L^-T l` and `z = M^-1 (c_p - J_A^T r)`, refined once where `p` or a row of the
    /// factor is thin (with `c_p . z` then `p`'s pivot squared); none where `p`'s pivot is
    /// within `TOO_NEAR` of its length.
    fn direction(
        &mut self,
        problem: &Problem,
        _: &[usize],
        p: usize,
    ) -> Option<(Vec<f64>, Vec<DVec2>)> {
        let (l, mut d2) = self.rows.row(p);
        if self.rows.too_near(p, d2) {
            shelf::give(&REALS, l);
            return None;
        }
        let mut r = shelf::take(&REALS);
        r.extend_from_slice(&l);
        let refined = self.rows.refines(p, d2);
        let (r, z) = step_on_factor(problem, &self.rows, p, r, refined);
        if refined {
            d2 = problem.dot(p, &z);
            if self.rows.too_near(p, d2) {
                problem.recycle(z);
                return None;
            }
        }
        self.last = Some((p, l, d2, refined));
        Some((r, z))
    }

    fn join(&mut self, p: usize) {
        let (k, l, d2, refined) = self
            .last
            .take()
            .expect("a contact joins after its direction");
        debug_assert_eq!(k, p);
        self.rows.join(p, &l, d2.sqrt(), refined);
        shelf::give(&REALS, l);
    }

    fn remove(&mut self, _: &Problem, slot: usize) -> bool {
        self.last = None;
        self.rows.remove(slot)
    }
}

/// A set of contacts kept exactly, factorised once: a group's (`pipeline/rigid.rs`), which
/// takes a hit on one of its balls as one body while every contact it keeps pushes.
///
/// A hit asks for one contact more, with its target, on top of the kept ones met exactly
/// (their relative normal velocities stay what they are). That is one step of the dual method
/// from the kept set, all of it active with no impulse yet: the change is `M^-1 d t`, `d` the
/// new contact's gradient less its parts along the kept ones (projected against the stored
/// basis) and `t` the impulse that meets its target; each kept contact's impulse is `-t r_j`.
/// If none of those is negative, the kept contacts all push, and the answer is the optimum of
/// the impact with the kept contacts as inequalities (touching, not approaching: target zero)
/// too: it meets every constraint with non-negative impulses, zero on none it does not meet
/// exactly, which are the conditions of that optimum.
///
/// Should one pull, the hit would part the set: the answer found is then the least change that
/// meets the new contact's target with the kept contacts held as they are (some pulling), and
/// the impact itself is solved too, every kept contact an inequality. [`Hit::Parting`] gives
/// both, and the caller decides whether the parting is slow enough for the set to hold
/// (`pipeline/rigid.rs`).
#[derive(Clone)]
pub(crate) struct Rigid {
    masses: Vec<f64>,
    /// The kept contacts the basis factorises (indices into the rows it was made of, which
    /// each hit is given again), in its order: each independent of those before it. The
    /// others depend on them, and are met with them.
    independent: Vec<usize>,
    basis: Basis,
    /// From [`GRAM_FROM`] balls, where no kept contact comes within
    /// [`NEAR_DEPENDENT`](super::gram::NEAR_DEPENDENT) of the span of those before it: their
    /// Gram matrix's sparse Cholesky factor, in the basis's place (then empty). A group of a
    /// hundred balls is factorised in a fraction of the basis's time (`dynamics/gram.rs`),
    /// and groups live for microseconds in a settling pile, most of them hit once or twice.
    factor: Option<GramFactor>,
}

impl Rigid {
    /// The contacts `rows` among balls of `masses` factorised: each row independent of those
    /// kept before it (by [`DEPENDENT`]) joins the basis; one that depends on them is met with
    /// them, and left out of the basis (the impact of a parting hit takes it too). From
    /// [`GRAM_FROM`] balls they are factorised on their Gram matrix instead, where none is
    /// thin ([`NEAR_DEPENDENT`](super::gram::NEAR_DEPENDENT)): the basis tells a dependence
    /// from a thin wedge, the normal equations do not.
    pub(crate) fn new(masses: Vec<f64>, rows: &[ContactRow]) -> Self {
        let on_gram = masses.len() >= GRAM_FROM;
        Self::factorised(masses, rows, on_gram)
    }

    /// [`Self::new`], on the Gram matrix's factor if `on_gram` (and no kept contact is thin),
    /// on the basis otherwise.
    fn factorised(masses: Vec<f64>, rows: &[ContactRow], on_gram: bool) -> Self {
        if on_gram {
            if let Some(factor) = factor_kept(&masses, rows) {
                return Rigid {
                    masses,
                    independent: (0..rows.len()).collect(),
                    basis: Basis::default(),
                    factor: Some(factor),
                };
            }
        }
        let mut independent = Vec::with_capacity(rows.len());
        let mut basis = Basis::default();
        {
            let problem = Problem::new(&masses, rows, 0.0);
            for k in 0..rows.len() {
                if problem.join_unless_dependent(&mut basis, k, DEPENDENT) {
                    independent.push(k);
                }
            }
        }
        Rigid {
            masses,
            independent,
            basis,
            factor: None,
        }
    }

    /// The velocities after contact `row` meets its target from velocities `v`, the kept
    /// contacts `rows` (those the set was made of) met as they are: `v` holds the set's balls
    /// and then, if `outsider` gives its
    /// mass, one ball more (index `masses.len()`, `row.b`). [`Hit::Whole`] if every kept
    /// contact pushes; [`Hit::Parting`] if one would have to pull; `None` if the row depends
    /// on the kept ones, it does not fall short of its target, or rounding would leave more
    /// kinetic energy than before.
    pub(crate) fn hit(
        &mut self,
        rows: &[ContactRow],
        outsider: Option<f64>,
        v: &[DVec2],
        row: ContactRow,
    ) -> Option<Hit> {
        let mut masses = self.masses.clone();
        masses.extend(outsider);
        debug_assert_eq!(masses.len(), v.len());
        let mut contacts = rows.to_vec();
        contacts.push(row);
        let speed = v.iter().fold(0.0_f64, |s, x| s.max(x.length()));
        let problem = Problem::new(&masses, &contacts, speed);
        let p = rows.len();
        let on_factor = (self.factor.as_mut())
            .and_then(|factor| direction_on_factor(&problem, factor, &self.independent, p));
        let (r, z) = match on_factor {
            Some(direction) => direction,
            None => {
                // A struck contact too near the kept ones' span for the factor (a thin wedge)
                // is the basis's, which tells a thin wedge from a dependence: the set is
                // factorised on it from then on.
                if self.factor.is_some() {
                    *self = Rigid::factorised(self.masses.clone(), rows, false);
                }
                problem.step_direction(&mut self.basis, &self.independent, p)
            }
        };
        let active = &self.independent;
        let zz = problem.dot(p, &z);
        let short = problem.shortfall(p, v);
        if zz <= DEPENDENT * problem.norm_squared(p) || !(short > 0.0) {
            return None;
        }
        let t = short / zz;
        let x: Vec<DVec2> = v.iter().zip(&z).map(|(a, b)| *a + *b * t).collect();
        let kinetic = |u: &[DVec2]| -> f64 {
            u.iter()
                .zip(&masses)
                .map(|(u, m)| m * u.length_squared())
                .sum()
        };
        if kinetic(&x) > kinetic(v) {
            return None;
        }
        // A kept contact whose impulse, `-t r_j`, would be negative beyond the rounding of the
        // rates would pull.
        // The impulses: `t` on the struck contact, `-t r_j` on each kept one the basis
        // factorises (those that depend on them carry none).
        let mut impulses = vec![0.0; contacts.len()];
        impulses[p] = t;
        for (&k, &rj) in active.iter().zip(&r) {
            impulses[k] = -t * rj;
        }
        let scale = r.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
        if r.iter().all(|&rj| rj <= 64.0 * f64::EPSILON * scale) {
            return Some(Hit::Whole(x, impulses));
        }
        // The impact itself, by the dual method from nothing over every kept contact and
        // the struck one: it adds only the contacts that end pushing. (Continued from the
        // kept basis instead, every kept contact active, its partial steps dropped the
        // contacts that would pull one at a time, each a rotation of every later column: 2.7
        // ms a hit in the 400-ball pile at e = 0.8 to t = 2.05, where this takes 65 us.)
        let impact = resolve_impact(&masses, v, &contacts).ok();
        Some(Hit::Parting {
            held: x,
            held_impulses: impulses,
            impact,
        })
    }
}

/// The Gram matrix's factor of the kept contacts `rows` (every one, in order) among balls of
/// `masses`, for [`Rigid`]; `None` if one comes within
/// [`NEAR_DEPENDENT`](super::gram::NEAR_DEPENDENT) of the span of those before it (its
/// solves would need refining, and below [`TOO_NEAR`](super::gram::TOO_NEAR) the factor
/// cannot tell a dependence: the basis takes such a set).
fn factor_kept(masses: &[f64], rows: &[ContactRow]) -> Option<GramFactor> {
    let inverse: Vec<f64> = masses.iter().map(|m| 1.0 / m).collect();
    let mut active = ActiveRows::with_factor(rows, &inverse, GramFactor::new(), &[]);
    for k in 0..rows.len() {
        let (l, d2) = active.row(k);
        if active.near(k, d2) {
            shelf::give(&REALS, l);
            return None;
        }
        active.join(k, &l, d2.sqrt(), false);
        shelf::give(&REALS, l);
    }
    Some(active.into_factor())
}

/// A hit's step on the kept contacts' Gram factor `factor` (their slots `active`, every row
/// factorised, none thin) for the struck contact `p`, as the dual method's step on the factor
/// (`OnGram::direction`): the rates `r` and `z = M^-1 (c_p - J_A^T r)`, refined once where `p`
/// is thin; `None` where `p` is within [`TOO_NEAR`](super::gram::TOO_NEAR) of the kept
/// contacts' span (the basis then takes the hit). The factor is left as it was.
fn direction_on_factor(
    problem: &Problem,
    factor: &mut GramFactor,
    active: &[usize],
    p: usize,
) -> Option<(Vec<f64>, Vec<DVec2>)> {
    let kept = std::mem::take(factor);
    let rows = ActiveRows::with_factor(problem.contacts, &problem.inverse_masses, kept, active);
    let (l, d2) = rows.row(p);
    if rows.too_near(p, d2) {
        shelf::give(&REALS, l);
        *factor = rows.into_factor();
        return None;
    }
    let refined = rows.refines(p, d2);
    let direction = step_on_factor(problem, &rows, p, l, refined);
    *factor = rows.into_factor();
    Some(direction)
}

/// The dual method's step for contact `p` on the factor of the active contacts `rows`, from
/// `l = L^-1 g`, its row against them: the rates `r = L^-T l` and `z = M^-1 (c_p - J_A^T r)`,
/// refined once if `refine` (Bjorck's corrected semi-normal equations, `dynamics/gram.rs`).
fn step_on_factor(
    problem: &Problem,
    rows: &ActiveRows,
    p: usize,
    mut r: Vec<f64>,
    refine: bool,
) -> (Vec<f64>, Vec<DVec2>) {
    rows.backward(&mut r);
    let step = |r: &[f64]| {
        let mut z = problem.gradient(p);
        rows.subtract(&mut z, r);
        for (x, m) in z.iter_mut().zip(problem.masses) {
            *x /= *m;
        }
        z
    };
    let mut z = step(&r);
    if refine {
        rows.refine(&mut r, &z);
        problem.recycle(z);
        z = step(&r);
    }
    (r, z)
}

/// What a hit on a set of kept contacts comes to ([`Rigid::hit`]).
#[derive(Debug)]
pub(crate) enum Hit {
    /// Every kept contact pushes: the velocities after the impact, which keeps them all, and
    /// each contact's impulse (the kept ones, then the struck one: as
    /// [`resolve_impact_with_impulses`]).
    Whole(Vec<DVec2>, Vec<f64>),
    /// Some kept contact would have to pull to stay met.
    Parting {
        /// The velocities with every kept contact held as it is (touching: pulling where it
        /// must), the new contact at its target: the least change of kinetic energy that
        /// does so.
        held: Vec<DVec2>,
        /// Each contact's impulse for `held` (negative where a kept contact pulls).
        held_impulses: Vec<f64>,
        /// The velocities after the impact itself (every kept contact an inequality, those
        /// that would pull parting), if the dual method found it.
        impact: Option<Vec<DVec2>>,
    },
}

/// How much longer (as a share of its kinetic energy) than the velocities it projects an
/// answer of targets all zero may come out before it is taken for rounding's and refused:
/// `1e-9`. In exact arithmetic it is never longer; its rounding, some ulps of each velocity,
/// is more than a million times smaller.
const LONGER: f64 = 1e-9;

impl Problem<'_> {
    /// Whether the answer `x` is no longer than the velocities `v` it came from, in the
    /// kinetic-energy metric, to within [`LONGER`], where every target is zero or below.
    ///
    /// Then the velocities all zero meet every constraint, and the answer, the projection of
    /// `v` onto a convex set holding zero, is no farther from zero than `v` (a projection
    /// onto a convex set is non-expansive, and zero is its own image). A thin wedge of two
    /// constraints nearly parallel (a ball on a floor just past the end point of a second
    /// segment on it, both resting: a wedge of 1.6e-11 radians) asks for impulses of 1e11
    /// times the velocities, and the rounding of those can leave another ball of the cluster
    /// a thousand times faster while every constraint is still met to its tolerance (which
    /// grows with the fastest speed): such an answer is refused, and the jam keeps its
    /// velocities (hunt seed 8061178).
    fn no_longer(&self, v: &[DVec2], x: &[DVec2]) -> bool {
        if self.contacts.iter().any(|c| c.target > 0.0) {
            return true;
        }
        let kinetic = |u: &[DVec2]| -> f64 {
            u.iter()
                .zip(self.masses)
                .map(|(u, m)| m * u.length_squared())
                .sum()
        };
        kinetic(x) <= kinetic(v) * (1.0 + LONGER)
    }
}

/// The programme's data, with the inner products it needs.
struct Problem<'a> {
    masses: &'a [f64],
    /// Each ball's inverse mass, for the inner product's inner loop.
    inverse_masses: Vec<f64>,
    contacts: &'a [ContactRow],
    /// The fastest speed before the impact.
    speed: f64,
    /// The residual of the constraint the last [`Self::step_direction`] was asked for, and
    /// its column of `R`, against the basis as it was then ([`Residual`]): should that
    /// constraint join the active set, [`Self::extend`] appends it as it is. The dual method
    /// projected each constraint it added twice, once to step and once to join the basis, the
    /// same arithmetic on the same basis: half of a pile's solve.
    last_residual: Cell<Option<Residual>>,
}

/// A constraint's residual against the first `len` vectors of a basis, with its column of
/// `R` (room for the diagonal last): what [`Problem::residual`] gives, kept.
struct Residual {
    k: usize,
    len: usize,
    v: Vec<DVec2>,
    column: Vec<f64>,
}

impl Drop for Residual {
    fn drop(&mut self) {
        shelf::give(&VECTORS, std::mem::take(&mut self.v));
        shelf::give(&REALS, std::mem::take(&mut self.column));
    }
}

impl Drop for Problem<'_> {
    fn drop(&mut self) {
        shelf::give(&REALS, std::mem::take(&mut self.inverse_masses));
    }
}

impl<'a> Problem<'a> {
    fn new(masses: &'a [f64], contacts: &'a [ContactRow], speed: f64) -> Self {
        Problem {
            masses,
            inverse_masses: {
                let mut inverse = shelf::take(&REALS);
                inverse.extend(masses.iter().map(|m| 1.0 / m));
                inverse
            },
            contacts,
            speed,
            last_residual: Cell::new(None),
        }
    }

    /// Gives `v`, a vector this problem handed out, back to its shelf for the next
    /// [`Self::gradient`]: a pile's solve takes some hundred steps, and allocating, zeroing
    /// and freeing two such vectors and a mask at each was a fifth of its instructions.
    fn recycle(&self, v: Vec<DVec2>) {
        shelf::give(&VECTORS, v);
    }

    /// Gives `mask`, from [`Self::reach`], back likewise.
    fn recycle_mask(&self, mask: Mask) {
        shelf::give(&WORDS, mask.0);
    }

    /// `u_k(x) - (w_k - s_k)`: negative where constraint `k` is violated beyond its slack.
    #[cfg(test)]
    fn slack(&self, k: usize, x: &[DVec2]) -> f64 {
        let c = &self.contacts[k];
        let u = match c.b {
            None => c.normal.dot(x[c.a]),
            Some(b) => c.normal.dot(x[b] - x[c.a]),
        };
        u - (c.target - c.slack)
    }

    /// How far constraint `k` falls short of its target: `w_k - u_k(x)`. A full step closes
    /// it exactly (the slack only decides what counts as violated).
    fn shortfall(&self, k: usize, x: &[DVec2]) -> f64 {
        self.contacts[k].target - self.dot(k, x)
    }

    /// The fastest speed before the impact or in `x`.
    fn fastest(&self, x: &[DVec2]) -> f64 {
        x.iter().fold(self.speed, |s, v| s.max(v.length()))
    }

    /// How far short of its target constraint `k` may fall: its slack, plus `1e-9` of the
    /// target (a restitution met to nine digits), plus the rounding of the velocities, which
    /// unequal masses amplify by their ratio (64 ulps of `speed`, the fastest before or now,
    /// [`Self::fastest`]).
    fn tolerance_at(&self, k: usize, speed: f64) -> f64 {
        let c = &self.contacts[k];
        c.slack + 1e-9 * c.target.abs() + 64.0 * f64::EPSILON * speed
    }

    /// The inactive constraint violated most (beyond its tolerance, so that the rounding of a
    /// step never brings one back), the lowest index on a tie.
    fn most_violated(&self, x: &[DVec2], is_active: &[bool]) -> Option<usize> {
        let mut worst: Option<(f64, usize)> = None;
        let speed = self.fastest(x);
        for (k, &active) in is_active.iter().enumerate() {
            if active {
                continue;
            }
            let s = self.shortfall(k, x) - self.tolerance_at(k, speed);
            if s > 0.0 && worst.is_none_or(|(w, _)| s > w) {
                worst = Some((s, k));
            }
        }
        worst.map(|(_, k)| k)
    }

    /// Constraint `k`'s gradient scaled by the inverse masses, as a velocity change per
    /// unit impulse: `M^-1 c_k`.
    #[cfg(test)]
    fn push(&self, k: usize, out: &mut [DVec2]) {
        let c = &self.contacts[k];
        match c.b {
            None => out[c.a] += c.normal / self.masses[c.a],
            Some(b) => {
                out[c.a] -= c.normal / self.masses[c.a];
                out[b] += c.normal / self.masses[b];
            }
        }
    }

    /// `c_k . y`.
    fn dot(&self, k: usize, y: &[DVec2]) -> f64 {
        let c = &self.contacts[k];
        match c.b {
            None => c.normal.dot(y[c.a]),
            Some(b) => c.normal.dot(y[b] - y[c.a]),
        }
    }

    /// `c_k . M^-1 c_k`: what `push` into zeros and then [`Self::dot`] give, operation for
    /// operation (so the same bits), without the vector.
    fn norm_squared(&self, k: usize) -> f64 {
        let c = &self.contacts[k];
        match c.b {
            None => c.normal.dot(DVec2::ZERO + c.normal / self.masses[c.a]),
            Some(b) => {
                let ya = DVec2::ZERO - c.normal / self.masses[c.a];
                let yb = DVec2::ZERO + c.normal / self.masses[b];
                c.normal.dot(yb - ya)
            }
        }
    }

    /// Constraint `k` as a vector over the balls' velocities: `c_k`.
    fn gradient(&self, k: usize) -> Vec<DVec2> {
        let c = &self.contacts[k];
        let mut y = shelf::take(&VECTORS);
        y.resize(self.masses.len(), DVec2::ZERO);
        match c.b {
            None => y[c.a] = c.normal,
            Some(b) => {
                y[c.a] = -c.normal;
                y[b] = c.normal;
            }
        }
        y
    }

    /// `x . M^-1 y`, the inner product in which constraints are orthogonalised.
    fn inner(&self, x: &[DVec2], y: &[DVec2]) -> f64 {
        x.iter()
            .zip(y)
            .zip(&self.inverse_masses)
            .map(|((a, b), w)| a.dot(*b) * w)
            .sum()
    }

    /// `v` less its parts along the orthonormal vectors of `basis`, the parts added into
    /// `coefficients`: modified Gram-Schmidt, taken a second time where the first pass left
    /// less than `1 / sqrt 2` of `v`'s length (the criterion of Daniel, Gragg, Kaufman and
    /// Stewart 1976: only then has cancellation cost digits, and twice is then enough: Giraud,
    /// Langou and Rozloznik 2005). A thin wedge, a constraint nearly a combination of the
    /// active ones, is such a case.
    ///
    /// Each vector is visited only where it is not zero (its support, [`Sparse`]), and not at
    /// all where `v` is zero on the whole of it: `reach` holds the lowest and highest ball at
    /// which `v` may not be zero, and a vector whose support lies outside that range adds a
    /// zero to its coefficient and takes nothing from `v`, so skipping it leaves every
    /// non-zero number as it was (a zero's sign aside). In a cluster of a hundred balls the
    /// first constraints met lie all over it, and most of them are skipped.
    fn project(&self, v: &mut [DVec2], reach: &mut Mask, basis: &Basis, coefficients: &mut [f64]) {
        let mut length = self.inner(v, v);
        for _ in 0..2 {
            for (i, q) in basis.q.iter().enumerate() {
                if !reach.meets(&q.mask) {
                    continue;
                }
                let mut a = -0.0;
                for e in &q.entries {
                    a += e.value.dot(v[e.ball]) * e.weight;
                }
                coefficients[i] += a;
                for e in &q.entries {
                    v[e.ball] -= e.value * a;
                }
                reach.join(&q.mask);
            }
            let left = self.inner(v, v);
            if left >= 0.5 * length {
                break;
            }
            length = left;
        }
    }

    /// From `start`, a set of contacts whose every impulse pushes, with the least change of
    /// `v` that meets them exactly: the velocities, the contacts, their impulses and their
    /// basis (see [`resolve_impact_from`]).
    fn pushing(&self, v: &[DVec2], start: Start) -> (Vec<DVec2>, Vec<usize>, Vec<f64>, Basis) {
        let Start {
            mut active,
            mut basis,
            ..
        } = start;
        loop {
            self.extend(&mut basis, &active);
            let n = active.len();
            // `R^T y = b`, `b` the shortfalls, by forward substitution (`R`'s column `j` is
            // `basis.r[j]`); then the impulses `R l = y`.
            let mut y: Vec<f64> = active.iter().map(|&k| self.shortfall(k, v)).collect();
            for j in 0..n {
                let column = &basis.r[j];
                let mut yj = y[j];
                for (rij, yi) in column[..j].iter().zip(&y[..j]) {
                    yj -= rij * yi;
                }
                let diagonal = column[j];
                y[j] = if diagonal > 0.0 { yj / diagonal } else { 0.0 };
            }
            let mut impulses = y.clone();
            basis.solve_upper(&mut impulses);
            let pulling: Vec<usize> = (0..n).filter(|&j| impulses[j] < 0.0).collect();
            if pulling.is_empty() {
                // `x = v + M^-1 sum_i y_i q_i`.
                let mut x = v.to_vec();
                for (q, &yi) in basis.q.iter().zip(&y) {
                    for e in &q.entries {
                        x[e.ball] += e.value * (yi * e.weight);
                    }
                }
                return (x, active, impulses, basis);
            }
            // The columns before the first that pulls keep their factorisation (a QR
            // factorisation's prefix is its columns' own); those after it, less the ones
            // that pull, are factorised again in turn. Rotating each out instead (as a
            // partial step does) mixed the supports of every later vector, and the steps
            // that followed projected onto vectors reaching most of the cluster.
            let first = pulling[0];
            let mut pulls = vec![false; n];
            for &j in &pulling {
                pulls[j] = true;
            }
            let after: Vec<usize> = (first..n)
                .filter(|&j| !pulls[j])
                .map(|j| active[j])
                .collect();
            active.truncate(first);
            basis.truncate(first);
            active.extend(after);
        }
    }

    /// The least change of `v` that meets the first `equalities` contacts (equalities, see
    /// [`resolve_with_equalities_factored`]) exactly, the point the dual method starts from
    /// when there are equalities: the velocities, the equalities met, their impulses (of
    /// either sign) and their basis.
    ///
    /// An equality's impulse may take either sign, so the least change that meets them all
    /// is a point the dual method may start from (its active set holds no inequality whose
    /// impulse could pull; Goldfarb and Idnani 1983 start with the equalities so). Each joins
    /// the basis in the order given, which is the cluster's (each ball's contacts, the balls
    /// in the order they were reached from the jam's): added one at a time as the most
    /// violated, the hold's projection of a pile's cluster joined contacts from all over it,
    /// each vector of the basis spread over more of the balls, and every step paid for the
    /// search and the update of the whole set: from the same states, the 400-ball pile's
    /// projections took 1.7 to 1.9 times as long a ball of their clusters. One nearly dependent on those before it
    /// (within [`WELL_APART`]) stays out, for the steps to add where violated, as before.
    fn equalities_met(
        &self,
        v: &[DVec2],
        equalities: usize,
    ) -> (Vec<DVec2>, Vec<usize>, Vec<f64>, Basis) {
        let room = equalities.min(2 * self.masses.len() + 2);
        let mut basis = Basis {
            q: Vec::with_capacity(room),
            r: Vec::with_capacity(room),
        };
        let mut active = Vec::with_capacity(room);
        // The least change meeting those joined so far, `x = v + M^-1 sum_i y_i q_i`, kept
        // as they join: `y_j` is the newest one's shortfall at the `x` before it over `R_jj`
        // (its row of `R^T y = b`, the shortfalls at `v`, by forward substitution).
        let mut x = v.to_vec();
        let mut y = Vec::with_capacity(room);
        let mut speed = self.fastest(v);
        for k in 0..equalities {
            // One met already (to the tolerance the steps ask) joins only if a later step
            // finds it violated, as the steps would have it.
            let short = self.shortfall(k, &x);
            if short.abs() <= self.tolerance_at(k, speed) {
                continue;
            }
            if !self.join_unless_dependent(&mut basis, k, WELL_APART) {
                continue;
            }
            active.push(k);
            let j = basis.q.len() - 1;
            let yj = short / basis.r[j][j];
            for e in &basis.q[j].entries {
                x[e.ball] += e.value * (yj * e.weight);
                speed = speed.max(x[e.ball].length());
            }
            y.push(yj);
        }
        let mut impulses = y;
        basis.solve_upper(&mut impulses);
        (x, active, impulses, basis)
    }

    /// The balls constraint `k` reaches.
    fn reach(&self, k: usize) -> Mask {
        let c = &self.contacts[k];
        let mut mask = Mask(shelf::take(&WORDS));
        mask.clear(self.masses.len());
        mask.set(c.a);
        if let Some(b) = c.b {
            mask.set(b);
        }
        mask
    }

    /// Extends `basis` to every constraint of `active` (the last added joins it only at the
    /// next step, or here).
    fn extend(&self, basis: &mut Basis, active: &[usize]) {
        for &k in &active[basis.q.len()..] {
            let kept = self
                .last_residual
                .take()
                .filter(|r| r.k == k && r.len == basis.q.len());
            let (v, column) = match kept {
                Some(mut r) => (std::mem::take(&mut r.v), std::mem::take(&mut r.column)),
                None => self.residual(k, basis),
            };
            let left = self.inner(&v, &v).max(0.0);
            self.append(basis, v, column, left);
        }
    }

    /// Constraint `k`'s gradient less its parts along `basis`, and `R`'s next column: those
    /// parts, with room for the rest's length last.
    fn residual(&self, k: usize, basis: &Basis) -> (Vec<DVec2>, Vec<f64>) {
        let j = basis.q.len();
        let mut v = self.gradient(k);
        let mut column = shelf::take(&REALS);
        column.resize(j + 1, 0.0);
        let mut reach = self.reach(k);
        self.project(&mut v, &mut reach, basis, &mut column[..j]);
        self.recycle_mask(reach);
        (v, column)
    }

    /// Adds constraint `k` to `basis` as its next vector, unless the part of it independent of
    /// the vectors there is at most `bound` of its squared length (in the metric of the inverse
    /// masses): whether it joined.
    fn join_unless_dependent(&self, basis: &mut Basis, k: usize, bound: f64) -> bool {
        let (v, column) = self.residual(k, basis);
        let left = self.inner(&v, &v).max(0.0);
        if left <= bound * self.norm_squared(k) {
            self.recycle(v);
            return false;
        }
        self.append(basis, v, column, left);
        true
    }

    /// Adds a [`Self::residual`] `v`, of squared length `left`, to `basis` as its next
    /// vector, normalised, with its `column` of `R`.
    fn append(&self, basis: &mut Basis, mut v: Vec<DVec2>, mut column: Vec<f64>, left: f64) {
        let length = left.sqrt();
        column[basis.q.len()] = length;
        if length > 0.0 {
            for x in &mut v {
                *x /= length;
            }
        }
        basis.q.push(Sparse::of(&v, &self.inverse_masses));
        self.recycle(v);
        basis.r.push(column);
    }

    /// For a violated constraint `p` and the active set: the active impulses' rates `r` (how
    /// fast each active impulse must fall per unit of `p`'s impulse to keep its constraint
    /// exactly met) and the velocity change `z = M^-1 (c_p - sum_j r_j c_j)` per unit of it,
    /// which changes no active constraint.
    ///
    /// The active constraints are orthonormalised in the inner product `x . M^-1 y`
    /// ([`Basis`], extended here to the whole active set) and `c_p`'s part orthogonal to them
    /// is taken directly, so that `z` is accurate to the rounding of `c_p` itself even when
    /// `c_p` is nearly a combination of active constraints (a thin wedge), where the normal
    /// equations would lose it.
    fn step_direction(
        &self,
        basis: &mut Basis,
        active: &[usize],
        p: usize,
    ) -> (Vec<f64>, Vec<DVec2>) {
        let n = active.len();
        self.extend(basis, active);
        let mut d = self.gradient(p);
        let mut a = shelf::take(&REALS);
        a.resize(n, 0.0);
        let mut reach = self.reach(p);
        self.project(&mut d, &mut reach, basis, &mut a);
        self.recycle_mask(reach);
        // Kept for `extend`, should `p` join the active set before the basis changes.
        let mut column = shelf::take(&REALS);
        column.extend_from_slice(&a);
        column.push(0.0);
        let mut v = shelf::take(&VECTORS);
        v.extend_from_slice(&d);
        self.last_residual.set(Some(Residual {
            k: p,
            len: n,
            v,
            column,
        }));
        let mut r = a;
        basis.solve_upper(&mut r);
        // `z = M^-1 d`, in place (hand it back with [`Self::recycle`]).
        for (x, m) in d.iter_mut().zip(self.masses) {
            *x /= *m;
        }
        (r, d)
    }
}

/// The active constraints orthonormalised in order, `c_j = sum_i R_ij q_i` with `R` upper
/// triangular: the vectors `q` and `R`'s columns. Adding a constraint adds one column; dropping
/// one deletes its column and restores the triangle with plane rotations ([`Basis::remove`]).
/// (Computed afresh at every step, the basis cost a cluster of a hundred balls
/// `O(active^3 x balls)` per impact; recomputing only the columns after a dropped one still
/// cost a hundred drops of a pile's solve half a second.)
///
/// A vector is zero outside the balls its constraint and those it was orthogonalised against
/// reach (its *support*): in a pile's cluster a third of the entries on average. Each is
/// stored on its support alone ([`Sparse`]), so that products read no zeros and a basis of
/// three hundred vectors over four hundred balls fits the cache a dense one overflowed.
#[derive(Clone, Default)]
struct Basis {
    q: Vec<Sparse>,
    r: Vec<Vec<f64>>,
}

/// A vector over the cluster's balls, stored where it is not zero: the balls in increasing
/// order and the vector's value at each, in one allocation.
#[derive(Clone, Debug, Default, PartialEq)]
struct Sparse {
    entries: Vec<Entry>,
    /// The support as a set.
    mask: Mask,
}

thread_local! {
    /// Basis vectors' entries and masks, kept between solves (`dynamics/shelf.rs`).
    static ENTRIES: Shelf<Entry> = const { RefCell::new(Vec::new()) };
    static WORDS: Shelf<u64> = const { RefCell::new(Vec::new()) };
}

impl Drop for Sparse {
    fn drop(&mut self) {
        shelf::give(&ENTRIES, std::mem::take(&mut self.entries));
        shelf::give(&WORDS, std::mem::take(&mut self.mask.0));
    }
}

/// One ball of a [`Sparse`] vector's support.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Entry {
    ball: usize,
    value: DVec2,
    /// The ball's inverse mass (the inner product's weight there).
    weight: f64,
}

/// A set of balls, a bit each.
#[derive(Clone, Debug, Default, PartialEq)]
struct Mask(Vec<u64>);

impl Mask {
    /// Empties the set and sizes it for `balls` balls.
    fn clear(&mut self, balls: usize) {
        self.0.clear();
        self.0.resize(balls.div_ceil(64), 0);
    }
    fn set(&mut self, b: usize) {
        self.0[b / 64] |= 1 << (b % 64);
    }
    fn meets(&self, other: &Mask) -> bool {
        self.0.iter().zip(&other.0).any(|(a, b)| a & b != 0)
    }
    fn join(&mut self, other: &Mask) {
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a |= b;
        }
    }
}

impl Sparse {
    /// The entries of `v` that are not zero, with the `weights` of their balls.
    fn of(v: &[DVec2], weights: &[f64]) -> Self {
        let size = v.iter().filter(|x| **x != DVec2::ZERO).count();
        let mut sparse = Sparse::empty(size, v.len());
        for (b, &x) in v.iter().enumerate() {
            if x != DVec2::ZERO {
                sparse.entries.push(Entry {
                    ball: b,
                    value: x,
                    weight: weights[b],
                });
                sparse.mask.set(b);
            }
        }
        sparse
    }

    /// A vector with no entries, room for `size` and an empty mask over `balls` balls, in
    /// what dropped vectors left (`dynamics/shelf.rs`).
    fn empty(size: usize, balls: usize) -> Self {
        let mut entries = shelf::take(&ENTRIES);
        entries.reserve(size);
        let mut words = shelf::take(&WORDS);
        words.resize(balls.div_ceil(64), 0);
        Sparse {
            entries,
            mask: Mask(words),
        }
    }

    /// The vector written out over `balls` balls.
    #[cfg(test)]
    fn dense(&self, balls: usize) -> Vec<DVec2> {
        let mut v = vec![DVec2::ZERO; balls];
        for e in &self.entries {
            v[e.ball] = e.value;
        }
        v
    }
}

impl Drop for Basis {
    fn drop(&mut self) {
        for column in self.r.drain(..) {
            shelf::give(&REALS, column);
        }
    }
}

impl Basis {
    /// Drops the column at `slot` (its active constraint left the set), keeping `c_j = sum_i
    /// R_ij q_i` for the columns that stay, `R` upper triangular and the `q` orthonormal.
    ///
    /// Without the column, `R` is upper Hessenberg from `slot` on: column `j >= slot` (once
    /// `j + 1`) has an entry below its diagonal, at row `j + 1`. A plane rotation `G` of rows
    /// `k` and `k + 1` (`k = slot, slot + 1, ...`) zeroes it in column `k`, and `Q R = (Q G^T)
    /// (G R)`: the same rotation of `q_k` and `q_{k+1}` keeps every product, and rotations keep
    /// the vectors orthonormal (Golub and Van Loan, "Matrix Computations", 12.5, the QR
    /// downdate after a deleted column). The last vector then spans no column and goes. Each
    /// rotation costs the supports of two vectors, where recomputing the columns after `slot`
    /// cost each of them a projection onto all before it. But a rotation leaves both vectors
    /// on the union of their supports: many columns dropped at once (a start's contacts
    /// that would pull, [`Problem::pushing`]) are cheaper recomputed ([`Basis::truncate`]);
    /// one dropped by a partial step is not (recomputing was 20 % dearer there, the 400-ball
    /// pile's accelerations' solves compared on the same inputs).
    fn remove(&mut self, slot: usize) {
        shelf::give(&REALS, self.r.remove(slot));
        let columns = self.r.len();
        for k in slot..columns {
            let (a, b) = (self.r[k][k], self.r[k][k + 1]);
            if b != 0.0 {
                let h = portable_hypot(a, b);
                let (c, s) = (a / h, b / h);
                for column in &mut self.r[k..] {
                    let (x, y) = (column[k], column[k + 1]);
                    column[k] = c * x + s * y;
                    column[k + 1] = c * y - s * x;
                }
                self.rotate(k, c, s);
                self.r[k][k] = h;
            }
            self.r[k].truncate(k + 1);
        }
        self.q.truncate(columns);
    }

    /// `R x = b` for the first `b.len()` columns, in place, by back substitution a column at
    /// a time (`R`'s column `j` is `r[j]`, stored contiguously): once `x_j` is known, column
    /// `j` is taken from the rows above. A column with no diagonal (a constraint that
    /// depended on those before it) gets zero.
    fn solve_upper(&self, b: &mut [f64]) {
        for j in (0..b.len()).rev() {
            let column = &self.r[j];
            let diagonal = column[j];
            b[j] = if diagonal > 0.0 { b[j] / diagonal } else { 0.0 };
            let xj = b[j];
            // A zero takes nothing from the rows above (a zero's sign aside).
            if xj == 0.0 {
                continue;
            }
            for (bi, rij) in b[..j].iter_mut().zip(&column[..j]) {
                *bi -= rij * xj;
            }
        }
    }

    /// Keeps the first `columns` columns (a factorisation of their constraints alone).
    fn truncate(&mut self, columns: usize) {
        self.q.truncate(columns);
        for column in self.r.drain(columns.min(self.r.len())..) {
            shelf::give(&REALS, column);
        }
    }

    /// Turns the constraint of column `slot` round (`c_slot <- -c_slot`): its column of `R`,
    /// then its row and its vector, change sign, so that the diagonal stays positive and
    /// every other column's product is kept.
    fn turn(&mut self, slot: usize) {
        for x in &mut self.r[slot] {
            *x = -*x;
        }
        for column in &mut self.r[slot..] {
            column[slot] = -column[slot];
        }
        for e in &mut self.q[slot].entries {
            e.value = -e.value;
        }
    }

    /// `q_k, q_{k+1} <- c q_k + s q_{k+1}, c q_{k+1} - s q_k`, on the union of their supports.
    fn rotate(&mut self, k: usize, c: f64, s: f64) {
        // On one support (the common case once a cluster's vectors have filled in), in
        // place: the same products, no new vectors.
        if self.q[k].mask == self.q[k + 1].mask {
            let (head, tail) = self.q.split_at_mut(k + 1);
            for (a, b) in head[k].entries.iter_mut().zip(&mut tail[0].entries) {
                let (p, q) = (a.value, b.value);
                a.value = p * c + q * s;
                b.value = q * c - p * s;
            }
            return;
        }
        let (x, y) = (&self.q[k].entries, &self.q[k + 1].entries);
        let size = x.len() + y.len();
        let balls = self.q[k].mask.0.len() * 64;
        let (mut first, mut second) = (Sparse::empty(size, balls), Sparse::empty(size, balls));
        for mask in [&mut first.mask, &mut second.mask] {
            mask.join(&self.q[k].mask);
            mask.join(&self.q[k + 1].mask);
        }
        let (mut i, mut j) = (0, 0);
        while i < x.len() || j < y.len() {
            let (b, p, q, w) = match (x.get(i), y.get(j)) {
                (Some(a), Some(b)) if a.ball == b.ball => {
                    i += 1;
                    j += 1;
                    (a.ball, a.value, b.value, a.weight)
                }
                (Some(a), Some(b)) if a.ball < b.ball => {
                    i += 1;
                    (a.ball, a.value, DVec2::ZERO, a.weight)
                }
                (Some(a), None) => {
                    i += 1;
                    (a.ball, a.value, DVec2::ZERO, a.weight)
                }
                (_, Some(b)) => {
                    j += 1;
                    (b.ball, DVec2::ZERO, b.value, b.weight)
                }
                (None, None) => unreachable!("the loop runs while one has entries"),
            };
            first.entries.push(Entry {
                ball: b,
                value: p * c + q * s,
                weight: w,
            });
            second.entries.push(Entry {
                ball: b,
                value: q * c - p * s,
                weight: w,
            });
        }
        self.q[k] = first;
        self.q[k + 1] = second;
    }
}

/// `sqrt(a^2 + b^2)` without overflow or underflow, from `+ - * /` and `sqrt` alone, which IEEE
/// 754 rounds the same on every platform. `f64::hypot` calls the platform's C library, whose
/// results differ in the last bit between implementations (glibc on x86_64, the Rust port of
/// musl's in wasm32): a jam that drops a contact would not give the same bits in a browser.
fn portable_hypot(a: f64, b: f64) -> f64 {
    let (x, y) = (a.abs(), b.abs());
    let (big, small) = if x >= y { (x, y) } else { (y, x) };
    if big == 0.0 || big.is_infinite() {
        return big;
    }
    let ratio = small / big;
    big * (1.0 + ratio * ratio).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use determinism_check::engine::SplitMix;

    fn wall(a: usize, normal: DVec2, target: f64) -> ContactRow {
        ContactRow {
            a,
            b: None,
            normal,
            target,
            slack: 1e-15,
        }
    }

    /// A contact of a random ball, against another random ball (if it draws one) or a wall,
    /// along a random direction, asking for `target`.
    fn random_row(next: &mut dyn FnMut() -> f64, balls: usize, target: f64) -> ContactRow {
        let angle = next() * std::f64::consts::TAU;
        let a = (next() * balls as f64) as usize;
        let b = (next() * balls as f64) as usize;
        ContactRow {
            a,
            b: (b != a && next() < 0.6).then_some(b),
            normal: DVec2::new(angle.cos(), angle.sin()),
            target,
            slack: 1e-12,
        }
    }

    fn pair(a: usize, b: usize, normal: DVec2, target: f64) -> ContactRow {
        ContactRow {
            a,
            b: Some(b),
            normal,
            target,
            slack: 1e-15,
        }
    }

    #[test]
    fn the_portable_hypot_is_within_two_ulps_of_the_exact_length_at_every_scale() {
        assert_eq!(portable_hypot(3.0, -4.0), 5.0);
        assert_eq!(portable_hypot(0.0, -0.0), 0.0);
        assert_eq!(portable_hypot(f64::INFINITY, 1.0), f64::INFINITY);
        let big = portable_hypot(1e300, 1e300);
        assert!((big / 1e300 - std::f64::consts::SQRT_2).abs() <= 2.0 * f64::EPSILON);
        let tiny = portable_hypot(3e-310, 4e-310);
        assert!((tiny / 5e-310 - 1.0).abs() <= 1e-9, "{tiny:e}");
        // Against the platform's hypot (native only: glibc's is within an ulp).
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for _ in 0..10_000 {
            let (x, y) = (next(), next() * 1e-3);
            let h = portable_hypot(x, y);
            assert!(
                (h - x.hypot(y)).abs() <= 2.0 * f64::EPSILON * h,
                "{x} {y}: {h}"
            );
        }
    }

    #[test]
    fn one_wall_reflects_with_the_target() {
        let v = resolve_impact(&[1.0], &[DVec2::new(1.0, -2.0)], &[wall(0, DVec2::Y, 1.0)]);
        let v = v.unwrap()[0];
        assert!(v.x == 1.0 && (v.y - 1.0).abs() < 4.0 * f64::EPSILON, "{v}");
    }

    #[test]
    fn a_ball_between_opposite_walls_loses_its_speed_across_them_and_keeps_the_rest() {
        let walls = [wall(0, DVec2::X, 0.0), wall(0, -DVec2::X, 0.0)];
        let v = resolve_impact(&[1.0], &[DVec2::new(-3.0, 2.0)], &walls).unwrap();
        assert!(v[0].x.abs() < 1e-14 && v[0].y == 2.0, "{v:?}");
        // Asked to bounce off one, it would have to enter the other.
        let bounce = [wall(0, DVec2::X, 1.5), wall(0, -DVec2::X, 0.0)];
        assert_eq!(
            resolve_impact(&[1.0], &[DVec2::new(-3.0, 2.0)], &bounce),
            Err(ImpactError::Infeasible)
        );
    }

    #[test]
    fn a_wedge_stops_a_ball_driven_into_it() {
        let a = 5f64.to_radians();
        let walls = [
            wall(0, DVec2::new(a.cos(), a.sin()), 0.0),
            wall(0, DVec2::new(-a.cos(), a.sin()), 0.0),
        ];
        let v = resolve_impact(&[1.0], &[DVec2::new(0.3, -2.0)], &walls).unwrap();
        assert!(v[0].length() < 1e-14, "{v:?}");
    }

    #[test]
    fn a_heavy_ball_pressing_a_light_one_into_a_wall_meets_the_backed_answer() {
        // Light ball 0 touches a wall above it; heavy ball 1 hits it from below at 1.
        let (masses, e) = ([0.001, 1.0], 0.5);
        let contacts = [wall(0, -DVec2::Y, 0.0), pair(1, 0, DVec2::Y, e * 1.0)];
        let v = resolve_impact(&masses, &[DVec2::ZERO, DVec2::Y], &contacts).unwrap();
        let backed =
            crate::collide_balls_backed(DVec2::ZERO, 0.001, DVec2::Y, 1.0, -DVec2::Y, e, -DVec2::Y);
        assert!((v[0] - backed.0).length() < 1e-12, "{v:?} {backed:?}");
        assert!((v[1] - backed.1).length() < 1e-12, "{v:?} {backed:?}");
    }

    #[test]
    fn a_row_jammed_between_two_walls_stops_dead() {
        // Three balls touching in a row between walls, all driven into it.
        let masses = [1.0, 2.0, 3.0];
        let velocities = [
            DVec2::new(1.0, 0.5),
            DVec2::new(-2.0, 0.0),
            DVec2::new(3.0, -1.0),
        ];
        let contacts = [
            wall(0, DVec2::X, 0.0),
            pair(0, 1, DVec2::X, 0.0),
            pair(1, 2, DVec2::X, 0.0),
            wall(2, -DVec2::X, 0.0),
        ];
        let v = resolve_impact(&masses, &velocities, &contacts).unwrap();
        for (vi, v0) in v.iter().zip(&velocities) {
            assert!(vi.x.abs() < 1e-14 && vi.y == v0.y, "{v:?}");
        }
    }

    /// The objective `sum m |x - v|^2 / 2`.
    /// Asserts that `impulses` on `contacts` take balls of `masses` from `v` to `x`:
    /// `x = v + M^-1 sum_k l_k c_k`, to 1e-9 of the speeds and velocity changes involved (the
    /// solve's rounding spreads over the cluster through its basis).
    fn assert_impulses_give(
        masses: &[f64],
        v: &[DVec2],
        contacts: &[ContactRow],
        impulses: &[f64],
        x: &[DVec2],
    ) {
        assert_eq!(impulses.len(), contacts.len());
        let mut y = v.to_vec();
        let mut scale = 0.0_f64;
        for (c, &l) in contacts.iter().zip(impulses) {
            let on_a = if c.b.is_some() { -l } else { l };
            y[c.a] += c.normal * (on_a / masses[c.a]);
            scale += (l / masses[c.a]).abs();
            if let Some(b) = c.b {
                y[b] += c.normal * (l / masses[b]);
                scale += (l / masses[b]).abs();
            }
        }
        for (a, b) in v.iter().zip(x) {
            scale = scale.max(a.length()).max(b.length());
        }
        for i in 0..v.len() {
            let tolerance = 1e-9 * scale;
            assert!(
                (y[i] - x[i]).length() <= tolerance,
                "ball {i}: {:?} from the impulses, {:?} solved ({contacts:?}, {impulses:?})",
                y[i],
                x[i]
            );
        }
    }

    fn objective(masses: &[f64], x: &[DVec2], v: &[DVec2]) -> f64 {
        masses
            .iter()
            .zip(x.iter().zip(v))
            .map(|(m, (a, b))| 0.5 * m * (*a - *b).length_squared())
            .sum()
    }

    /// The brute-force optimum: for every subset of the constraints, the minimum with exactly
    /// those met with equality (Gaussian elimination); the best feasible one. The optimum of a
    /// strictly convex programme is the equality-constrained minimum of its active set, so it
    /// is among them, and every feasible candidate is no better.
    fn brute_force(masses: &[f64], v: &[DVec2], contacts: &[ContactRow]) -> Option<f64> {
        brute_force_with(masses, v, &[], contacts)
    }

    /// As [`brute_force`], the first `equalities.len()` rows met with equality in every
    /// candidate (and checked so on both sides).
    fn brute_force_with(
        masses: &[f64],
        v: &[DVec2],
        equalities: &[ContactRow],
        inequalities: &[ContactRow],
    ) -> Option<f64> {
        let contacts: Vec<ContactRow> = equalities.iter().chain(inequalities).copied().collect();
        let contacts = contacts.as_slice();
        let fixed = equalities.len();
        let problem = Problem::new(masses, contacts, 0.0);
        let mut best: Option<f64> = None;
        for subset in 0u32..1 << inequalities.len() {
            let rows: Vec<usize> = (0..contacts.len())
                .filter(|&k| k < fixed || subset >> (k - fixed) & 1 == 1)
                .collect();
            let n = rows.len();
            let pushes: Vec<Vec<DVec2>> = rows
                .iter()
                .map(|&j| {
                    let mut y = vec![DVec2::ZERO; masses.len()];
                    problem.push(j, &mut y);
                    y
                })
                .collect();
            // [S | w - c.v] with S_ij = c_i . M^-1 c_j.
            let mut a = vec![vec![0.0; n + 1]; n];
            for i in 0..n {
                for j in 0..n {
                    a[i][j] = problem.dot(rows[i], &pushes[j]);
                }
                a[i][n] = contacts[rows[i]].target - problem.dot(rows[i], v);
            }
            let Some(impulses) = crate::dynamics::dense::solve_dense(a, 1e-9) else {
                continue;
            };
            let mut x = v.to_vec();
            for (push, &l) in pushes.iter().zip(&impulses) {
                for (xi, pi) in x.iter_mut().zip(push) {
                    *xi += *pi * l;
                }
            }
            let feasible = (0..contacts.len()).all(|k| {
                let slack = problem.slack(k, &x) - contacts[k].slack;
                slack > -1e-9 && (k >= fixed || slack < 1e-9)
            });
            if feasible {
                let f = objective(masses, &x, v);
                if best.is_none_or(|b| f < b) {
                    best = Some(f);
                }
            }
        }
        best
    }

    /// Dropping a column by rotations leaves a basis that still reproduces every remaining
    /// constraint (`c_j = sum_i R_ij q_i`), orthonormal in the inner product, `R` upper
    /// triangular: checked for every slot of random bases of a cluster of touching balls.
    #[test]
    fn a_dropped_column_leaves_an_orthonormal_factorisation_of_the_rest() {
        let mut state = 0x9e37_u64;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..40 {
            let balls = 6;
            let masses: Vec<f64> = (0..balls).map(|_| 0.5 + next()).collect();
            let contacts: Vec<ContactRow> = (0..9)
                .map(|k| {
                    let angle = next() * std::f64::consts::TAU;
                    let a = k % balls;
                    let b = (a + 1 + (next() * (balls - 1) as f64) as usize) % balls;
                    ContactRow {
                        a,
                        b: (next() < 0.7).then_some(b),
                        normal: DVec2::new(angle.cos(), angle.sin()),
                        target: 0.0,
                        slack: 0.0,
                    }
                })
                .collect();
            let problem = Problem::new(&masses, &contacts, 1.0);
            // The active set as the method builds it: no constraint that depends on those
            // before it (it would be met by partial steps, never added).
            let mut active: Vec<usize> = Vec::new();
            for k in 0..contacts.len() - 1 {
                let mut basis = Basis::default();
                active.push(k);
                problem.step_direction(&mut basis, &active, contacts.len() - 1);
                if basis.r[active.len() - 1][active.len() - 1] < 1e-3 {
                    active.pop();
                }
            }
            for slot in 0..active.len() {
                let mut basis = Basis::default();
                problem.step_direction(&mut basis, &active, contacts.len() - 1);
                basis.remove(slot);
                let mut kept = active.clone();
                kept.remove(slot);
                assert_eq!(basis.q.len(), kept.len());
                for (j, &k) in kept.iter().enumerate() {
                    assert_eq!(basis.r[j].len(), j + 1, "R stays triangular");
                    let mut c = vec![DVec2::ZERO; balls];
                    for (i, rij) in basis.r[j].iter().enumerate() {
                        for (cb, qb) in c.iter_mut().zip(&basis.q[i].dense(balls)) {
                            *cb += *qb * *rij;
                        }
                    }
                    let g = problem.gradient(k);
                    let error: f64 = c.iter().zip(&g).map(|(x, y)| (*x - *y).length()).sum();
                    assert!(error < 1e-12, "column {j} of slot {slot}: {error}");
                    for i in 0..kept.len() {
                        let dot = problem.inner(&basis.q[i].dense(balls), &basis.q[j].dense(balls));
                        let expected = if i == j { 1.0 } else { 0.0 };
                        assert!((dot - expected).abs() < 1e-12, "q{i} . q{j} = {dot}");
                    }
                    let q = &basis.q[j];
                    assert!(
                        q.entries.windows(2).all(|w| w[0].ball < w[1].ball),
                        "support in order"
                    );
                }
            }
        }
    }

    /// A cluster of `balls` balls, a pile's: rows of a hexagonal packing on a floor against a
    /// wall (on its left: a cluster some of whose contacts ask to part can), each ball moved
    /// off its site by up to `jitter` radii (so no two contacts are parallel), every pair
    /// nearer than `reach` radii in contact along the line of their centres.
    fn pile_cluster(
        next: &mut dyn FnMut() -> f64,
        balls: usize,
        (jitter, reach): (f64, f64),
    ) -> Vec<ContactRow> {
        let width = 7;
        let sites: Vec<DVec2> = (0..balls)
            .map(|i| {
                let (row, at) = (i / width, i % width);
                let x = 2.0 * at as f64 + if row % 2 == 1 { 1.0 } else { 0.0 };
                let y = 3.0_f64.sqrt() * row as f64;
                DVec2::new(
                    x + jitter * (2.0 * next() - 1.0),
                    y + jitter * (2.0 * next() - 1.0),
                )
            })
            .collect();
        let mut rows = Vec::new();
        for (a, pa) in sites.iter().enumerate() {
            if a < width {
                rows.push(wall(a, DVec2::Y, 0.0));
            }
            if a % width == 0 {
                rows.push(wall(a, DVec2::X, 0.0));
            }
            for (b, pb) in sites.iter().enumerate().skip(a + 1) {
                if pa.distance(*pb) < reach {
                    rows.push(pair(a, b, (*pb - *pa).normalize(), 0.0));
                }
            }
        }
        rows
    }

    /// `start` without its Gram matrix's factor: its contacts alone.
    fn bare(start: &Start) -> Start {
        Start {
            active: start.active.clone(),
            basis: start.basis.clone(),
            factor: GramFactor::new(),
        }
    }

    /// Large clusters, as a pile's jams solve them, on the Gram matrix's factor: the impact,
    /// the projection with resting contacts as equalities, and the accelerations started from
    /// the projection's end. Each answer meets the programme's optimality conditions (every
    /// target met, every impulse pushing, the velocities those impulses give) and is the
    /// Gram-Schmidt basis's answer to `1e-9` of the fastest speed. In loose clusters nearly
    /// all of them are found on the factor; in tight ones (three contacts a ball, more than
    /// the two velocities each has: dependences, and near ones its refined solves take) three
    /// in four and more, and those with an exact dependence are handed back: the answers
    /// stand either way.
    #[test]
    fn large_clusters_solved_on_the_gram_matrix_meet_the_optimality_conditions() {
        let mut rng = SplitMix(0x6a4d_0b17_u64);
        let mut next = || rng.next_f64();
        let (mut programmes, mut on_gram) = (0, 0);
        let (mut tight, mut tight_on_gram) = (0, 0);
        for round in 0..60 {
            let balls = GRAM_FROM + (next() * 40.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.5 + next()).collect();
            let loose = round % 3 != 0;
            let shape = if loose { (0.1, 2.05) } else { (0.01, 2.1) };
            let mut rows = pile_cluster(&mut next, balls, shape);
            let velocities: Vec<DVec2> = (0..balls)
                .map(|_| DVec2::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0))
                .collect();
            for row in &mut rows {
                row.slack = 1e-12;
                if round % 2 == 1 && next() < 0.3 {
                    row.target = next();
                }
            }
            // The impact.
            let check = |contacts: &[ContactRow],
                         equalities: usize,
                         v: &[DVec2],
                         start: Option<Start>,
                         on_gram: &mut usize| {
                let problem = Problem::new(&masses, contacts, 0.0);
                let from = start
                    .as_ref()
                    .map(|s| (s.active.as_slice(), s.factor.clone()));
                if solve_on_gram(&problem, v, equalities, from).is_some() {
                    *on_gram += 1;
                }
                // A start's factor gives the bits its contacts alone give.
                let bare = start.as_ref().map(bare);
                let (x, end, impulses) =
                    solve(&masses, v, contacts, equalities, start).expect("feasible");
                if bare.is_some() {
                    let (again, _, _) =
                        solve(&masses, v, contacts, equalities, bare).expect("feasible");
                    assert_eq!(x, again);
                }
                let (reference, _, _) =
                    solve_on_basis(&problem, v, equalities, None).expect("feasible");
                let fastest = x.iter().chain(v).fold(0.0_f64, |s, u| s.max(u.length()));
                for (a, b) in x.iter().zip(&reference) {
                    assert!((*a - *b).length() <= 1e-9 * fastest, "{a} {b}");
                }
                let mut each = vec![0.0; contacts.len()];
                for (&k, &l) in end.active.iter().zip(&impulses) {
                    each[k] += l;
                    if k >= equalities && k < contacts.len() - equalities {
                        assert!(l >= 0.0, "contact {k} pulls: {l}");
                    }
                }
                assert_impulses_give(&masses, v, contacts, &each, &x);
                for k in 0..contacts.len() {
                    assert!(problem.slack(k, &x) > -1e-9 * fastest, "{k} violated");
                }
                (x, end)
            };
            let (count, found) = if loose {
                (&mut programmes, &mut on_gram)
            } else {
                (&mut tight, &mut tight_on_gram)
            };
            *count += 3;
            check(&rows, 0, &velocities, None, found);
            // The projection: a third of the contacts resting (equalities, reversed last),
            // every target zero.
            let resting: Vec<ContactRow> = rows
                .iter()
                .filter(|_| next() < 0.3)
                .map(|r| ContactRow { target: 0.0, ..*r })
                .collect();
            let others: Vec<ContactRow> = rows
                .iter()
                .map(|r| ContactRow { target: 0.0, ..*r })
                .collect();
            let contacts = with_reverses(&resting, &others);
            let (projected, _) = check(&contacts, resting.len(), &velocities, None, found);
            // The accelerations, from the projection's active set among the inequalities.
            let (_, end, _) = solve(&masses, &projected, &others, 0, None).expect("feasible");
            let gravity = vec![DVec2::new(0.0, -9.81); balls];
            check(&others, 0, &gravity, Some(end), found);
        }
        assert!(
            on_gram * 10 >= programmes * 9,
            "{on_gram} of {programmes} on the factor"
        );
        assert!(
            tight_on_gram * 4 >= tight * 3 && tight_on_gram < tight,
            "{tight_on_gram} of {tight} tight ones on it"
        );
    }

    /// Accelerations of large clusters, as a pile's holds solve them, started from guesses of
    /// their active set (`resolve_impact_guessed`): the contacts that push at the optimum,
    /// those that pushed at a nearby programme's (the same cluster a little moved), half the
    /// contacts at random and every contact (pulling ones, and in tight clusters dependent
    /// ones, among them). Each ends at the optimum the solve from nothing finds, to `1e-9` of
    /// gravity, with every impulse pushing and the accelerations those impulses give.
    #[test]
    fn accelerations_started_from_any_guess_end_at_the_optimum() {
        let mut rng = SplitMix(0x9e55_ed01_u64);
        let mut next = || rng.next_f64();
        let g = DVec2::new(0.0, -9.81);
        let (mut solved, mut handed_back) = (0, 0);
        for round in 0..40 {
            let balls = GRAM_FROM + (next() * 40.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.5 + next()).collect();
            let shape = if round % 3 == 0 {
                (0.01, 2.1)
            } else {
                (0.1, 2.05)
            };
            let mut rows = pile_cluster(&mut next, balls, shape);
            for row in &mut rows {
                row.slack = 1e-12;
            }
            let gravity = vec![g; balls];
            let (cold, cold_impulses) =
                resolve_impact_with_impulses(&masses, &gravity, &rows).expect("feasible");
            // The same contacts a little moved: their normals turned by up to 1e-3.
            let moved: Vec<ContactRow> = rows
                .iter()
                .map(|row| ContactRow {
                    normal: DVec2::from_angle(1e-3 * (2.0 * next() - 1.0)).rotate(row.normal),
                    ..*row
                })
                .collect();
            let (_, moved_impulses) =
                resolve_impact_with_impulses(&masses, &gravity, &moved).expect("feasible");
            let pushing = |impulses: &[f64]| -> Vec<usize> {
                (0..rows.len()).filter(|&k| impulses[k] > 0.0).collect()
            };
            let guesses = [
                pushing(&cold_impulses),
                pushing(&moved_impulses),
                (0..rows.len()).filter(|_| next() < 0.5).collect(),
                (0..rows.len()).collect(),
            ];
            for guess in &guesses {
                let Some((x, impulses)) = resolve_impact_guessed(&masses, &gravity, &rows, guess)
                else {
                    // Handed back: the basis solves it from the caller's start.
                    handed_back += 1;
                    continue;
                };
                solved += 1;
                for (a, b) in x.iter().zip(&cold) {
                    assert!((*a - *b).length() <= 1e-9 * g.length(), "{a} {b}");
                }
                assert!(impulses.iter().all(|&l| l >= 0.0), "an impulse pulls");
                assert_impulses_give(&masses, &gravity, &rows, &impulses, &x);
                let problem = Problem::new(&masses, &rows, 0.0);
                for k in 0..rows.len() {
                    assert!(problem.slack(k, &x) > -1e-9 * g.length(), "{k} violated");
                }
            }
        }
        assert!(
            solved >= 9 * handed_back,
            "{solved} solved, {handed_back} handed back"
        );
    }

    /// The accelerations started from a big projection's factor, kept by
    /// [`Factored::restate`], give the bits the same start's contacts give joined afresh.
    /// (An equality the projection meets from its other side, rare here, turns the kept
    /// factor round: `dynamics/gram.rs` tests that to the bit.)
    #[test]
    fn a_start_from_the_projections_factor_gives_the_bits_of_its_contacts_alone() {
        let mut rng = SplitMix(0x5eed_fac7_u64);
        let mut next = || rng.next_f64();
        let mut kept = 0;
        for _ in 0..20 {
            let balls = GRAM_FROM + (next() * 30.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.5 + next()).collect();
            let rows = pile_cluster(&mut next, balls, (0.1, 2.05));
            let velocities: Vec<DVec2> = (0..balls)
                .map(|_| DVec2::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0))
                .collect();
            let (resting, others): (Vec<ContactRow>, Vec<ContactRow>) =
                rows.iter().partition(|_| next() < 0.5);
            let (_, factored, _) =
                resolve_with_equalities_factored(&masses, &velocities, &resting, &others)
                    .expect("feasible");
            let all: Vec<ContactRow> = resting.iter().chain(&others).copied().collect();
            let start = factored.restate(Some);
            kept += start.factor.rows();
            let bare = bare(&start);
            let gravity = vec![DVec2::new(0.0, -9.81); balls];
            let x = resolve_impact_from(&masses, &gravity, &all, start)
                .expect("feasible")
                .0;
            let again = resolve_impact_from(&masses, &gravity, &all, bare)
                .expect("feasible")
                .0;
            assert_eq!(x, again);
        }
        assert!(kept > 20 * GRAM_FROM, "{kept} rows kept");
    }

    /// A thin wedge in a large cluster: a ball driven into a shallow valley (two surfaces
    /// sloping at `theta` either way, a pivot squared of `sin^2 2 theta` against the other),
    /// beside a row of balls on a floor, spreading away from it. At `theta = 2e-5` (a pivot
    /// squared of `1.6e-9` of the contact's length, between `TOO_NEAR` and `NEAR_DEPENDENT`)
    /// the factor takes the programme, refined, and at `2e-7` (`1.6e-13`, the second side
    /// still violated beyond the tolerance, by `2 theta^2` of the speed) hands it back; both
    /// ways the answer is the basis's to `1e-9` of the fastest speed, with both sides of the
    /// valley active and the ball stopped in it.
    #[test]
    fn a_thin_wedge_in_a_large_cluster_is_taken_on_the_factor_refined_or_handed_back() {
        let mut rng = SplitMix(0x7e1d_9e55_u64);
        let mut next = || rng.next_f64();
        for (theta, taken) in [(2e-5_f64, true), (2e-7, false)] {
            for _ in 0..20 {
                let balls = GRAM_FROM + 5;
                let masses: Vec<f64> = (0..balls).map(|_| 0.5 + next()).collect();
                let (s, c) = theta.sin_cos();
                let mut rows = vec![
                    wall(0, DVec2::new(s, c), 0.0),
                    pair(0, 1, DVec2::X, 0.0),
                    wall(0, DVec2::new(-s, c), 0.0),
                ];
                for i in 1..balls {
                    rows.push(wall(i, DVec2::Y, 0.0));
                    if i + 1 < balls {
                        rows.push(pair(i, i + 1, DVec2::X, 0.0));
                    }
                }
                // Down into the valley, the row spreading away from it.
                let velocities: Vec<DVec2> = (0..balls)
                    .map(|i| {
                        DVec2::new(
                            0.1 * i as f64 + 0.05 * next() * i.min(1) as f64,
                            -1.0 - next(),
                        )
                    })
                    .collect();
                let problem = Problem::new(&masses, &rows, 0.0);
                let on_gram = solve_on_gram(&problem, &velocities, 0, None);
                assert_eq!(on_gram.is_some(), taken, "theta {theta}");
                let (x, end, _) = solve(&masses, &velocities, &rows, 0, None).expect("feasible");
                let (reference, _, _) =
                    solve_on_basis(&problem, &velocities, 0, None).expect("feasible");
                let fastest = velocities.iter().fold(0.0_f64, |m, u| m.max(u.length()));
                for (a, b) in x.iter().zip(&reference) {
                    assert!((*a - *b).length() <= 1e-9 * fastest, "{a} {b}");
                }
                assert!(end.active.contains(&0) && end.active.contains(&2));
                assert!(x[0].length() <= 1e-9 * fastest, "{}", x[0]);
            }
        }
    }

    /// Random small impacts against the brute-force optimum: the method's answer is feasible
    /// and as good, or both find none.
    #[test]
    fn random_impacts_meet_the_brute_force_optimum() {
        let mut rng = SplitMix(0x1234_5678_u64);
        let mut next = || rng.next_f64();
        let (mut solved, mut infeasible) = (0, 0);
        let mut refused = Vec::new();
        for _ in 0..3000 {
            let balls = 1 + (next() * 3.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.1 + 3.0 * next()).collect();
            let velocities: Vec<DVec2> = (0..balls)
                .map(|_| DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0))
                .collect();
            let mut contacts = Vec::new();
            for _ in 0..1 + (next() * 6.0) as usize {
                let angle = next() * std::f64::consts::TAU;
                let a = (next() * balls as f64) as usize;
                let b = (next() * balls as f64) as usize;
                contacts.push(ContactRow {
                    a,
                    b: (b != a && next() < 0.6).then_some(b),
                    normal: DVec2::new(angle.cos(), angle.sin()),
                    target: if next() < 0.5 { 0.0 } else { next() },
                    slack: 1e-12,
                });
            }
            let expected = brute_force(&masses, &velocities, &contacts);
            match resolve_impact(&masses, &velocities, &contacts) {
                Ok(v) => {
                    solved += 1;
                    // The same answer, with the impulses that give it, none pulling.
                    let (same, impulses) =
                        resolve_impact_with_impulses(&masses, &velocities, &contacts)
                            .expect("the same programme");
                    assert_eq!(same, v);
                    assert_impulses_give(&masses, &velocities, &contacts, &impulses, &v);
                    assert!(impulses.iter().all(|&l| l >= 0.0), "{impulses:?}");
                    let problem = Problem::new(&masses, &contacts, 0.0);
                    for k in 0..contacts.len() {
                        assert!(problem.slack(k, &v) > -1e-9, "{k} violated: {contacts:?}");
                    }
                    let f = objective(&masses, &v, &velocities);
                    let best = expected.expect("the brute force finds a feasible point too");
                    assert!(
                        f <= best * (1.0 + 1e-9) + 1e-12,
                        "{f} > {best}: {contacts:?}"
                    );
                }
                Err(ImpactError::Infeasible) => {
                    infeasible += 1;
                    if let Some(best) = expected {
                        refused.push(
                            best / objective(&masses, &vec![DVec2::ZERO; balls], &velocities)
                                .max(1e-300),
                        );
                    }
                }
            }
        }
        // Refused with a feasible answer: only programmes nearly infeasible, whose answer
        // would multiply the balls' kinetic energy by a hundred or more.
        assert!(refused.iter().all(|&r| r > 100.0), "{refused:?}");
        assert!(
            solved > 1500 && infeasible > 10,
            "{solved} solved, {infeasible} infeasible"
        );
    }

    /// Random small programmes with equalities against the brute-force optimum (every
    /// equality met in each candidate) and against the same programme given to
    /// [`resolve_impact`] as each equality and its reverse: feasible, as good, the same answer.
    #[test]
    fn random_equalities_meet_the_brute_force_optimum_and_the_reversed_pairs() {
        let mut rng = SplitMix(0x5eed_u64);
        let mut next = || rng.next_f64();
        let (mut solved, mut infeasible, mut dependent) = (0, 0, 0);
        let mut refused = Vec::new();
        for _ in 0..3000 {
            let balls = 1 + (next() * 3.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.1 + 3.0 * next()).collect();
            let velocities: Vec<DVec2> = (0..balls)
                .map(|_| DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0))
                .collect();
            let (e, i) = ((next() * 3.0) as usize, (next() * 5.0) as usize);
            let mut row = |sign: f64| {
                let target = if next() < 0.5 { 0.0 } else { sign * next() };
                random_row(&mut next, balls, target)
            };
            // Equalities ask for either sign; inequalities, as impacts, for separation.
            let equalities: Vec<ContactRow> = (0..e)
                .map(|k| row(if k % 2 == 0 { 1.0 } else { -1.0 }))
                .collect();
            let inequalities: Vec<ContactRow> = (0..i).map(|_| row(1.0)).collect();
            let expected = brute_force_with(&masses, &velocities, &equalities, &inequalities);
            let paired = with_reverses(&equalities, &inequalities);
            let pairs = resolve_impact(&masses, &velocities, &paired);
            match resolve_with_equalities(&masses, &velocities, &equalities, &inequalities) {
                Ok(v) => {
                    solved += 1;
                    let problem = Problem::new(&masses, &paired, 0.0);
                    for k in 0..paired.len() {
                        assert!(problem.slack(k, &v) > -1e-9, "{k} violated: {paired:?}");
                    }
                    let f = objective(&masses, &v, &velocities);
                    // The brute force takes every equality in each candidate: equalities that
                    // depend on each other leave it none to compare with.
                    match expected {
                        Some(best) => assert!(f <= best * (1.0 + 1e-9) + 1e-12, "{f} > {best}"),
                        None => dependent += 1,
                    }
                    let scale = velocities.iter().fold(1.0_f64, |s, x| s.max(x.length()));
                    if let Ok(w) = pairs {
                        for (a, b) in v.iter().zip(&w) {
                            assert!((*a - *b).length() <= 1e-9 * scale, "{v:?} against {w:?}");
                        }
                    }
                }
                Err(ImpactError::Infeasible) => {
                    infeasible += 1;
                    assert!(pairs.is_err(), "the reversed pairs solve what this refuses");
                    if let Some(best) = expected {
                        let none = objective(&masses, &vec![DVec2::ZERO; balls], &velocities);
                        refused.push(best / none.max(1e-300));
                    }
                }
            }
        }
        // As for impacts: refused with a feasible answer only where that answer would
        // multiply the balls' kinetic energy a hundredfold or more.
        assert!(refused.iter().all(|&r| r > 100.0), "{refused:?}");
        assert!(
            solved > 1500 && infeasible > 10 && dependent < solved / 20,
            "{solved} solved ({dependent} with dependent equalities), {infeasible} infeasible"
        );
    }

    /// The hold's two programmes on random clusters: a projection with equalities, then a
    /// second projection (another vector: gravity's) over a random part of its contacts,
    /// every target zero. Started from the first's factorisation, the second ends where it
    /// ends started from nothing, and at the brute force's optimum.
    #[test]
    fn a_programme_started_from_another_factorisation_ends_at_the_same_optimum() {
        let mut rng = SplitMix(0x0a11_5eed_u64);
        let mut next = || rng.next_f64();
        let (mut compared, mut turned, mut removed, mut checked) = (0, 0, 0, 0);
        for _ in 0..4500 {
            let balls = 1 + (next() * 4.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.1 + 3.0 * next()).collect();
            let random_vectors = |next: &mut dyn FnMut() -> f64| -> Vec<DVec2> {
                (0..balls)
                    .map(|_| DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0))
                    .collect()
            };
            let velocities = random_vectors(&mut next);
            let gravity = random_vectors(&mut next);
            let row = |next: &mut dyn FnMut() -> f64| random_row(next, balls, 0.0);
            let (e, i) = ((next() * 4.0) as usize, (next() * 5.0) as usize);
            // Some equalities nearly parallel to the one before (3e-4 to 9e-4 radians from
            // it), so nearly dependent that the start leaves them to the steps (`WELL_APART`),
            // which add them from whichever side they are violated on: turned round in the
            // basis.
            let mut equalities: Vec<ContactRow> = Vec::with_capacity(e);
            let mut thin = false;
            for _ in 0..e {
                let near = equalities.last().copied().filter(|_| next() < 0.5);
                thin |= near.is_some();
                equalities.push(match near {
                    Some(r) => ContactRow {
                        normal: DVec2::from_angle((3e-4 + 6e-4 * next()) * (next() - 0.5).signum())
                            .rotate(r.normal),
                        ..r
                    },
                    None => row(&mut next),
                });
            }
            let inequalities: Vec<ContactRow> = (0..i).map(|_| row(&mut next)).collect();
            let Ok((x, factored, impulses)) =
                resolve_with_equalities_factored(&masses, &velocities, &equalities, &inequalities)
            else {
                continue;
            };
            let all: Vec<ContactRow> = equalities.iter().chain(&inequalities).copied().collect();
            assert_impulses_give(&masses, &velocities, &all, &impulses, &x);
            for (k, &l) in impulses.iter().enumerate().skip(e) {
                assert!(l >= 0.0, "an inequality pulls: {k} {l}");
            }
            turned += factored.contacts.iter().filter(|c| c.1).count();
            // The second programme: each contact of the first kept or not.
            let kept: Vec<usize> = (0..all.len()).filter(|_| next() < 0.8).collect();
            let mut position = vec![None; all.len()];
            for (at, &k) in kept.iter().enumerate() {
                position[k] = Some(at);
            }
            removed += factored
                .contacts
                .iter()
                .filter(|c| position[c.0].is_none())
                .count();
            let rows: Vec<ContactRow> = kept.iter().map(|&k| all[k]).collect();
            let cold = resolve_impact(&masses, &gravity, &rows);
            let start = factored.restate(|k| position[k]);
            let warm = resolve_impact_from(&masses, &gravity, &rows, start).map(|(x, _)| x);
            let (Ok(cold), Ok(warm)) = (cold, warm) else {
                panic!("every target zero: both are feasible ({rows:?})");
            };
            let scale = gravity.iter().fold(1.0_f64, |s, x| s.max(x.length()));
            for (a, b) in cold.iter().zip(&warm) {
                assert!(
                    (*a - *b).length() <= 1e-9 * scale,
                    "{cold:?} against {warm:?}"
                );
            }
            let problem = Problem::new(&masses, &rows, 0.0);
            for k in 0..rows.len() {
                assert!(problem.slack(k, &warm) > -1e-9, "{k} violated: {rows:?}");
            }
            if let Some(best) = brute_force(&masses, &gravity, &rows) {
                // A thin wedge's optimum is as far from the brute force's as its rounding
                // carries along the wedge, the cold solve's too: there the two solves agree
                // (above), and the brute force is asked only of the others.
                let f = objective(&masses, &warm, &gravity);
                if !thin {
                    assert!(f <= best * (1.0 + 1e-9) + 1e-12, "{f} > {best}");
                    checked += 1;
                }
            }
            compared += 1;
        }
        assert!(
            compared > 3800 && turned > 300 && removed > 300 && checked > 2500,
            "{compared} compared, {turned} turned round, {removed} removed, {checked} checked"
        );
    }

    #[test]
    fn a_hit_on_a_big_groups_factor_is_the_hit_on_its_basis() {
        // Groups of 40 to 60 balls in columns on a floor: each ball rests on the one before
        // it or on the floor (so the kept contacts are independent), its normal within a
        // radian of the vertical, and in half the groups a few contacts more between random
        // balls; their velocities meet every kept contact, and a ball from above, or a
        // surface, strikes a member downwards: the top of a column (every kept contact
        // pushes, unless the contacts more pull) or any member. The hit on the Gram matrix's
        // factor is the hit on the basis, whole or parting alike.
        let mut rng = SplitMix(0x61a4_u64);
        let mut next = || rng.next_f64();
        let (mut on_factor, mut whole, mut parting) = (0, 0, 0);
        for _ in 0..60 {
            let members = 40 + (next() * 21.0) as usize;
            let masses: Vec<f64> = (0..members).map(|_| 0.5 + 1.5 * next()).collect();
            let unit = |next: &mut dyn FnMut() -> f64| {
                let angle = std::f64::consts::FRAC_PI_2 + 2.0 * next() - 1.0;
                DVec2::new(angle.cos(), angle.sin())
            };
            // Columns: each ball rests on the one before it, or starts a column on the floor.
            let mut kept = vec![wall(0, unit(&mut next), 0.0)];
            let mut tops = Vec::new();
            for b in 1..members {
                if next() < 0.15 {
                    tops.push(b - 1);
                    kept.push(wall(b, unit(&mut next), 0.0));
                } else {
                    kept.push(pair(b - 1, b, unit(&mut next), 0.0));
                }
            }
            tops.push(members - 1);
            let extra = if next() < 0.5 {
                0
            } else {
                1 + (next() * 12.0) as usize
            };
            for _ in 0..extra {
                let (a, b) = (
                    (next() * members as f64) as usize,
                    (next() * members as f64) as usize,
                );
                if a != b {
                    kept.push(pair(a.min(b), a.max(b), unit(&mut next), 0.0));
                }
            }
            let free: Vec<DVec2> = (0..members)
                .map(|_| DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0))
                .collect();
            let Ok(mut v) = resolve_with_equalities(&masses, &free, &kept, &[]) else {
                continue;
            };
            let outsider = (next() < 0.5).then(|| 0.5 + 1.5 * next());
            // The top of a column (a hit every kept contact takes pushing), or any member.
            let a = if next() < 0.5 {
                tops[(next() * tops.len() as f64) as usize]
            } else {
                (next() * members as f64) as usize
            };
            let row = match outsider {
                Some(_) => {
                    v.push(DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0));
                    pair(a, members, unit(&mut next), 2.0 * next())
                }
                None => wall(a, -unit(&mut next), 2.0 * next()),
            };
            let mut gram = Rigid::factorised(masses.clone(), &kept, true);
            if gram.factor.is_none() {
                continue;
            }
            on_factor += 1;
            let mut basis = Rigid::factorised(masses.clone(), &kept, false);
            let (Some(a), Some(b)) = (
                gram.hit(&kept, outsider, &v, row),
                basis.hit(&kept, outsider, &v, row),
            ) else {
                continue;
            };
            let speed = v.iter().fold(0.0_f64, |s, x| s.max(x.length()));
            let close = |x: &[DVec2], y: &[DVec2]| {
                x.iter()
                    .zip(y)
                    .all(|(x, y)| (*x - *y).length() <= 1e-9 * speed)
            };
            match (a, b) {
                (Hit::Whole(x, _), Hit::Whole(y, _)) => {
                    assert!(close(&x, &y), "{x:?} against {y:?}");
                    whole += 1;
                }
                (Hit::Parting { held: x, .. }, Hit::Parting { held: y, .. }) => {
                    assert!(close(&x, &y), "{x:?} against {y:?}");
                    parting += 1;
                }
                (a, b) => panic!("{a:?} against {b:?}"),
            }
        }
        assert!(
            on_factor >= 50 && whole >= 5 && parting >= 5,
            "{on_factor} {whole} {parting}"
        );
    }

    /// A hit on kept contacts, on random sets (a wall or an outside ball striking): every
    /// kept contact pushing, the answer is the impact's optimum (the brute force over the kept
    /// contacts as inequalities and the struck one); one pulling, `held` is the optimum with
    /// the kept contacts as equalities and `impact` the impact's, each against its brute force.
    #[test]
    fn a_hit_on_kept_contacts_meets_the_brute_force_held_and_parting() {
        let mut rng = SplitMix(0x0b1d_u64);
        let mut next = || rng.next_f64();
        let (mut whole, mut parting, mut held_checked) = (0, 0, 0);
        for _ in 0..4000 {
            let members = 1 + (next() * 4.0) as usize;
            let outsider = (next() < 0.5).then(|| 0.1 + 3.0 * next());
            let balls = members + usize::from(outsider.is_some());
            let masses: Vec<f64> = (0..members).map(|_| 0.1 + 3.0 * next()).collect();
            let kept: Vec<ContactRow> = (0..1 + (next() * 4.0) as usize)
                .map(|_| random_row(&mut next, members, 0.0))
                .collect();
            let free: Vec<DVec2> = (0..members)
                .map(|_| DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0))
                .collect();
            // The members' velocities meet every kept contact exactly.
            let Ok(mut v) = resolve_with_equalities(&masses, &free, &kept, &[]) else {
                continue;
            };
            let mut all_masses = masses.clone();
            let row = match outsider {
                Some(m) => {
                    all_masses.push(m);
                    v.push(DVec2::new(next() * 4.0 - 2.0, next() * 4.0 - 2.0));
                    let angle = next() * std::f64::consts::TAU;
                    ContactRow {
                        a: (next() * members as f64) as usize,
                        b: Some(members),
                        normal: DVec2::new(angle.cos(), angle.sin()),
                        target: 2.0 * next(),
                        slack: 1e-12,
                    }
                }
                None => {
                    let target = 2.0 * next();
                    random_row(&mut next, members, target)
                }
            };
            debug_assert_eq!(v.len(), balls);
            let mut rigid = Rigid::new(masses.clone(), &kept);
            let Some(hit) = rigid.hit(&kept, outsider, &v, row) else {
                continue;
            };
            let mut every = kept.clone();
            every.push(row);
            let problem = Problem::new(&all_masses, &every, 0.0);
            let meets = |x: &[DVec2], equal: bool| {
                (0..every.len()).all(|k| {
                    let slack = problem.slack(k, x) - every[k].slack;
                    slack > -1e-9 && (!equal || k == kept.len() || slack < 1e-9)
                })
            };
            let near = |x: &[DVec2], best: f64| {
                let f = objective(&all_masses, x, &v);
                (f - best).abs() <= 1e-9 * best.max(1.0)
            };
            match hit {
                Hit::Whole(x, impulses) => {
                    assert!(meets(&x, false), "{every:?}: {x:?}");
                    assert_impulses_give(&all_masses, &v, &every, &impulses, &x);
                    // Every kept contact pushes, to the rounding of the rates.
                    let most = impulses.iter().fold(0.0_f64, |s, l| s.max(l.abs()));
                    assert!(impulses.iter().all(|&l| l >= -1e-12 * most), "{impulses:?}");
                    let best = brute_force(&all_masses, &v, &every).expect("feasible");
                    assert!(near(&x, best), "{every:?}: {x:?} against {best}");
                    whole += 1;
                }
                Hit::Parting {
                    held,
                    held_impulses,
                    impact,
                } => {
                    assert!(meets(&held, true), "{every:?}: {held:?}");
                    assert_impulses_give(&all_masses, &v, &every, &held_impulses, &held);
                    // Dependent kept contacts leave every candidate singular.
                    if let Some(best) = brute_force_with(&all_masses, &v, &kept, &[row]) {
                        assert!(near(&held, best), "{every:?}: {held:?} against {best}");
                        held_checked += 1;
                    }
                    let impact = impact.expect("feasible: the kept contacts may all part");
                    assert!(meets(&impact, false), "{every:?}: {impact:?}");
                    let best = brute_force(&all_masses, &v, &every).expect("feasible");
                    assert!(near(&impact, best), "{every:?}: {impact:?} against {best}");
                    let f = objective(&all_masses, &held, &v);
                    assert!(
                        f >= best * (1.0 - 1e-9),
                        "held {f} below the impact's {best}"
                    );
                    parting += 1;
                }
            }
        }
        assert!(
            whole > 300 && parting > 300 && held_checked > 200,
            "{whole} whole, {parting} parting, {held_checked} held compared"
        );
    }
}
