//! The gap between a point moving on a parabola and a fixed circle: a quartic in time.
//!
//! A ball under uniform gravity `g` has centre `q + v t + g t^2 / 2` relative to a fixed point
//! (a segment's end point or a static circle's centre). It touches when the distance equals `R`
//! (the ball radius, plus the static circle's radius), so the squared gap
//!
//! ```text
//! f(t)   = |w|^2 - R^2,            w  = q + v t + g t^2 / 2,   w' = v + g t
//! f'(t)  = 2 w . w'
//! f''(t) = 2 (|w'|^2 + w . g)      = 2 (|v|^2 + q.g) + 6 (v.g) t + 3 |g|^2 t^2
//! ```
//!
//! is a quartic with a positive leading coefficient `|g|^2 / 4`. There is no useful closed
//! form, so we isolate its roots instead: `f''` is a quadratic (closed form), so `f'` is
//! monotone between the roots of `f''` and each of its roots can be bracketed and refined;
//! those roots split time into intervals on which `f` itself is monotone, and a contact is an
//! interval whose start has `f > 0` and whose end has `f <= 0`. Refinement then finds the first
//! float of contact (see `refine`). The turning points are refined as the search reads them,
//! none past its horizon, and a minimum that a bound shows to lie clear of contact is not
//! refined at all (see `ParabolicGap::clear_minimum`): the search goes the same way, to the
//! bit. `f`, `f'`, `f''` are always evaluated from the geometry (`w` and `w'`), never from
//! expanded polynomial coefficients, so the value near contact is accurate to a few ulps of
//! `R^2`, which is as good as the inputs allow. The expanded coefficients are used only for a
//! root bound.
//!
//! The beyond-the-last-critical-point interval always rises to `+inf`, so a contact is always
//! found on a bounded interval; only an *exit* (a ball leaving a sensor) can lie on the last
//! interval, and then Cauchy's bound on the roots closes the bracket.

use glam::DVec2;

use super::{first_contact, refine_descent};

/// A dip of the squared gap to within this many ulps of `|w|^2 + R^2` below zero, at a turning
/// point, is a graze (a double root blurred by rounding), not a contact.
///
/// At a true tangency `f` touches zero without crossing it, but its computed value carries a
/// rounding error of a few ulps of `|w|^2 + R^2`, so the computed minimum can be a hair below
/// zero. The straight-line kernels call a double root tangential (no contact); this makes the
/// quartic agree. A real crossing this shallow would overlap by at most `8 eps R`, far below any
/// tolerance.
const GRAZE_ULPS: f64 = 8.0;

/// A minimum of the squared gap shown to lie above this many ulps of `|w|^2 + R^2` is not
/// refined (see `ParabolicGap::clear_minimum`): twice [`GRAZE_ULPS`], room for the rounding
/// of `f` where it is shown and where the search would have evaluated it.
const CLEAR_ULPS: f64 = 2.0 * GRAZE_ULPS;

/// How many steps `ParabolicGap::clear_minimum` takes before the minimum is refined instead.
const CLEAR_STEPS: u32 = 16;

/// The squared-distance gap between a ballistic point and a fixed circle of radius `R`
/// centred at the origin. Times are relative to the moment the motion is given for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParabolicGap {
    /// Position relative to the circle centre at `t = 0`.
    pub q: DVec2,
    /// Velocity at `t = 0`.
    pub v: DVec2,
    /// Constant acceleration. Zero is allowed: [`first_contact`](Self::first_contact) and
    /// [`first_exit`](Self::first_exit) then solve the quadratic of straight motion, as
    /// [`time_of_impact_ball_point`](crate::toi::time_of_impact_ball_point) does.
    pub g: DVec2,
    /// The contact distance `R`.
    pub radius: f64,
}

impl ParabolicGap {
    /// `w(t) = q + v t + g t^2 / 2`: the position relative to the circle's centre.
    #[inline]
    fn w(&self, t: f64) -> DVec2 {
        self.q + self.v * t + self.g * (0.5 * t * t)
    }

    /// `f(t) = |w(t)|^2 - R^2`.
    #[must_use]
    #[inline]
    pub fn value(&self, t: f64) -> f64 {
        let w = self.w(t);
        w.dot(w) - self.radius * self.radius
    }

    /// `f'(t) = 2 w . w'`.
    #[must_use]
    #[inline]
    pub fn derivative(&self, t: f64) -> f64 {
        2.0 * self.w(t).dot(self.v + self.g * t)
    }

    #[inline]
    fn second_derivative(&self, t: f64) -> f64 {
        let dw = self.v + self.g * t;
        2.0 * (dw.dot(dw) + self.w(t).dot(self.g))
    }

    /// The first time of contact, `t` in `[0, horizon]`, following the touching-contact
    /// policy: touching (`f(0) <= 0`) and approaching (`f'(0) < 0`, or with `f'(0) = 0` the
    /// first derivative after it that is not zero negative: `f''(0)`, then `f'''(0) = 6 v . g`)
    /// is contact now; touching and separating or tangential is no contact now. `None` if there is no contact by
    /// `horizon` (which may be infinite; a negative or NaN horizon gives `None`).
    ///
    /// A `Some(t)` is always finite with `0 <= t <= horizon`. NaN or an infinity anywhere in
    /// the gap gives `None`. Magnitudes whose squares overflow (`|q|`, `|v| t`, `|g| t^2` or
    /// `R` beyond about `1e150`) leave the gap unevaluable there, and a contact can be missed.
    #[must_use]
    pub fn first_contact(&self, horizon: f64) -> Option<f64> {
        self.first_crossing_of_any_motion(1.0, horizon)
    }

    /// The first time the point *leaves* the circle (`f` rises through zero), with the mirrored
    /// policy: `f(0) >= 0` and `f'(0) > 0` is an exit now. Used for sensors. The same domain
    /// as [`first_contact`](Self::first_contact).
    #[must_use]
    pub fn first_exit(&self, horizon: f64) -> Option<f64> {
        self.first_crossing_of_any_motion(-1.0, horizon)
    }

    /// [`first_crossing`](Self::first_crossing), or the quadratic of straight motion if `g` is
    /// zero (the quartic's analysis needs a positive leading coefficient).
    fn first_crossing_of_any_motion(&self, sign: f64, horizon: f64) -> Option<f64> {
        if self.g != DVec2::ZERO {
            return self.first_crossing(sign, horizon, true, |_| true);
        }
        let (q, v) = (self.q, self.v);
        let t = first_contact(
            sign * v.dot(v),
            sign * q.dot(v),
            sign * (q.dot(q) - self.radius * self.radius),
        )?;
        (t <= horizon).then_some(t)
    }

    /// The first descent through zero of `sign * f` in `[0, horizon]` whose time `accept`s.
    ///
    /// With `touching_policy`, `sign * f <= 0` and falling at `t = 0` counts as a crossing now;
    /// without it only a descent from a positive value counts (used for features whose region
    /// the ball is not in, where "touching now" is meaningless). A crossing that `accept`
    /// refuses (a segment's end point crossed where the ball projects onto the interior) does
    /// not end the search: under gravity a later crossing of the same circle may be the one.
    pub(crate) fn first_crossing<A: Fn(f64) -> bool>(
        &self,
        sign: f64,
        horizon: f64,
        touching_policy: bool,
        accept: A,
    ) -> Option<f64> {
        // Nothing lies in an empty or NaN range (the policy's contact now included), and a time
        // that overflowed is no time.
        if !(horizon >= 0.0) || !self.is_finite() {
            return None;
        }
        self.crossing_in_range(sign, horizon, touching_policy, accept, true)
            .filter(|t| t.is_finite())
    }

    /// [`first_crossing`](Self::first_crossing) for a horizon `>= 0`; without `clear`, every
    /// minimum is refined to its last float (for the tests: the answer is the same).
    fn crossing_in_range<A: Fn(f64) -> bool>(
        &self,
        sign: f64,
        horizon: f64,
        touching_policy: bool,
        accept: A,
        clear: bool,
    ) -> Option<f64> {
        let phi = |t: f64| (sign * self.value(t), sign * self.derivative(t));
        let (phi0, dphi0) = phi(0.0);
        // Touching or overlapping and approaching, at first, second or third order: contact
        // now. (`f''' = 6 w' . g`, and `f'''' = 6 |g|^2 > 0`: with `f'` and `f''` both zero,
        // `f` falls from 0 exactly when `v . g < 0`. A ball driven along a channel into one
        // that slides past it at `v^2 = a_n d` is such a pair.)
        let pulled_in = || {
            dphi0 == 0.0 && {
                let ddphi0 = sign * self.second_derivative(0.0);
                ddphi0 < 0.0 || (ddphi0 == 0.0 && sign * self.v.dot(self.g) < 0.0)
            }
        };
        if touching_policy && phi0 <= 0.0 && (dphi0 < 0.0 || pulled_in()) && accept(0.0) {
            return Some(0.0);
        }
        if sign > 0.0 && self.cannot_reach(horizon) {
            return None;
        }
        // The critical points are where `f'` changes sign: between them `phi` is monotone,
        // falling and rising in turn, from the way it goes at 0.
        let mut falling = dphi0 < 0.0 || pulled_in();
        let mut start = (0.0, phi0);
        let mut critical = self.critical_points();
        loop {
            // Past the horizon nothing more counts: the next turning point is not sought.
            if start.0 > horizon {
                return None;
            }
            // A contact search asks of a minimum only whether `f` reaches zero there.
            let Some(turn) = critical.next_turn(clear && sign > 0.0 && falling) else {
                break;
            };
            let c = match turn {
                Turn::At(c) => c,
                Turn::ClearMinimum(lower) => {
                    // No contact on this falling stretch; what follows rises to a turning
                    // point found exactly, and `lower` serves the horizon test alone.
                    falling = false;
                    start = (lower, phi(lower).0);
                    continue;
                }
            };
            let end = (c, phi(c).0);
            // `start.0 < c` always holds for finite inputs; checked so that values overflowing
            // to infinities can never hand the refinement a reversed bracket.
            if falling && end.1 <= 0.0 && start.0 < c {
                if start.1 > 0.0 {
                    if !self.is_graze(c, end.1) {
                        let t = refine_descent(phi, start.0, end.0, start.1, end.1);
                        if t > horizon {
                            return None;
                        }
                        if accept(t) {
                            return Some(t);
                        }
                    }
                } else if start.0 > 0.0 && !self.is_graze(c, end.1) {
                    // It turned back at `start` touching, or overlapping by rounding, without
                    // getting clear (a contact that rounding would otherwise call a graze, or
                    // a ball that never came out of an overlap): it approaches from there.
                    if accept(start.0) {
                        return Some(start.0);
                    }
                }
            }
            falling = !falling;
            start = end;
        }
        // Beyond the last critical point f rises to +inf: only an exit can happen there.
        if sign > 0.0 || start.0 > horizon || start.1 <= 0.0 {
            return None;
        }
        let (end, phi_end) = self.exit_bracket(start.0)?;
        if !(start.0 < end) {
            return None;
        }
        let t = refine_descent(phi, start.0, end, start.1, phi_end);
        (t <= horizon && accept(t)).then_some(t)
    }

    /// Whether every number of the gap is finite.
    fn is_finite(&self) -> bool {
        self.q.is_finite() && self.v.is_finite() && self.g.is_finite() && self.radius.is_finite()
    }

    /// Whether `phi`, non-positive at the turning point `t`, dips below zero by no more than
    /// the rounding error of `f` there (see [`GRAZE_ULPS`]).
    fn is_graze(&self, t: f64, phi: f64) -> bool {
        let w = self.w(t);
        let noise = GRAZE_ULPS * f64::EPSILON * (w.dot(w) + self.radius * self.radius);
        phi > -noise
    }

    /// Whether the point certainly cannot come within `R` before `horizon`: it moves at most
    /// `|v| h + |g| h^2 / 2` in time `h`. The 1e-12 margin covers the rounding of this test,
    /// so it never rejects a contact the full solver would find.
    fn cannot_reach(&self, horizon: f64) -> bool {
        if !horizon.is_finite() {
            return false;
        }
        let reach = self.v.length() * horizon + 0.5 * self.g.length() * horizon * horizon;
        self.q.length() - self.radius > reach * (1.0 + 1e-12) + 1e-300
    }

    /// The roots of `f'` in `(0, inf)`, ascending: the times at which `f` turns. Each is
    /// refined when the search asks for it, so a search that ends early (a contact found,
    /// the horizon passed) refines no more of them than it reads.
    fn critical_points(&self) -> CriticalPoints<'_> {
        // f''/2 = (|v|^2 + q.g) + 3 (v.g) t + (3/2)|g|^2 t^2, in half-b form.
        let a = 1.5 * self.g.dot(self.g);
        let b = 1.5 * self.v.dot(self.g);
        let c = self.v.dot(self.v) + self.q.dot(self.g);
        let mut breaks = [0.0; 3];
        let mut n = 1;
        for s in quadratic_roots(a, b, c) {
            if s > 0.0 {
                breaks[n] = s;
                n += 1;
            }
        }
        CriticalPoints {
            gap: self,
            breaks,
            len: n,
            next: 0,
            last: None,
        }
    }

    /// The turning point on the `i`-th interval between roots of `f''` (the last one open
    /// above), if `f'` changes sign there: its root, or, with `clear_minimum` and a minimum
    /// of `f` there that [`clear_minimum`](Self::clear_minimum) shows to lie above the graze
    /// noise, a time no later than it.
    fn turn_in(&self, breaks: &[f64], i: usize, clear_minimum: bool) -> Option<Turn> {
        let d1 = |t: f64| (self.derivative(t), self.second_derivative(t));
        let lo = breaks[i];
        let f_lo = self.derivative(lo);
        let (hi, f_hi) = if i + 1 < breaks.len() {
            (breaks[i + 1], self.derivative(breaks[i + 1]))
        } else if f_lo < 0.0 {
            self.derivative_bracket(lo)?
        } else {
            return None;
        };
        if hi <= lo {
            return None;
        }
        if clear_minimum && f_lo < 0.0 && f_hi >= 0.0 {
            if let Some(lower) = self.clear_minimum(lo, hi, f_lo, f_hi) {
                return Some(Turn::ClearMinimum(lower));
            }
        }
        sign_change_root(d1, lo, hi, f_lo, f_hi).map(Turn::At)
    }

    /// A time no later than the minimum `c` of `f` on `[lo, hi]` (where `f'` rises through
    /// zero from `f'(lo) = d_lo < 0` to `f'(hi) = d_hi >= 0`), if `f(c)` is shown to exceed
    /// [`CLEAR_ULPS`] ulps of `|w|^2 + R^2`: then the search, which refines `c` to its last
    /// float only to ask whether `f(c) <= 0`, would find `f(c) > 0` and no contact there, and
    /// `c` need not be refined. `None` (refine `c`) if that is not shown within
    /// [`CLEAR_STEPS`] steps, or if `f` comes near zero.
    ///
    /// The bound: `f'` is monotone on `[lo, hi]` (it lies between roots of `f''`), so `f''`
    /// keeps its sign there, and `f''` is a convex quadratic, so on a bracket `[a, b]` of `c`
    /// `|f''| <= M = max(|f''(a)|, |f''(b)|)`. With `f'(c) = 0`, `|f'(s)| <= M |s - c|`,
    /// so `f(c) >= f(a) - M (b - a)^2 / 2`. Newton's method on `f'` comes near `c`; once its
    /// step is within half the width `W` that `f` there allows, a probe half of `W` beyond
    /// its target brackets `c` with the iterate. The ends' values are computed: `M` is
    /// given the rounding of `f''` as slack, and the floor (twice
    /// [`GRAZE_ULPS`]) covers the rounding of `f` at the ends and at `c`, so that the
    /// search's own `f(c)`, had it refined `c`, would be positive: the search goes the same
    /// way, to the bit.
    fn clear_minimum(&self, lo: f64, hi: f64, d_lo: f64, d_hi: f64) -> Option<f64> {
        let r2 = self.radius * self.radius;
        let g_len = self.g.length();
        // f', f'' (its bound, with its rounding), f, and the floor at t.
        let at = |t: f64| {
            let (w, dw) = (self.w(t), self.v + self.g * t);
            let ww = w.dot(w);
            let f1 = 2.0 * w.dot(dw);
            let f2 = 2.0 * (dw.dot(dw) + w.dot(self.g));
            let f2_bound = f2.abs() + 32.0 * f64::EPSILON * (dw.dot(dw) + ww.sqrt() * g_len);
            let floor = CLEAR_ULPS * f64::EPSILON * (ww + r2);
            (f1, f2, f2_bound, ww - r2, floor)
        };
        let (mut a, mut b) = (lo, hi);
        let mut x = lo + (hi - lo) * (-d_lo / (d_hi - d_lo));
        for _ in 0..CLEAR_STEPS {
            if !(x > a && x < b) {
                x = 0.5 * (a + b);
            }
            let (d, f2, m_x, f, floor) = at(x);
            if !(f > floor) {
                return None;
            }
            if d < 0.0 {
                a = x;
            } else {
                b = x;
            }
            let next = x - d / f2;
            // The widest bracket whose bound keeps `f(c)` above the floor, with room for a
            // bound at the probe up to twice this one.
            let allowed = ((f - floor) / m_x).sqrt();
            if !((next - x).abs() < 0.5 * allowed) {
                x = next;
                continue;
            }
            let probe = if d < 0.0 {
                (next + 0.5 * allowed).min(b)
            } else {
                (next - 0.5 * allowed).max(a)
            };
            let (d_p, _, m_p, f_p, floor_p) = at(probe);
            if (d_p < 0.0) == (d < 0.0) {
                if d_p < 0.0 {
                    a = probe;
                } else {
                    b = probe;
                }
                x = probe;
                continue;
            }
            let width = (probe - x).abs();
            let m = m_x.max(m_p);
            let best = f.max(f_p);
            if best - 0.5 * m * width * width > floor.max(floor_p) {
                return Some(x.min(probe));
            }
            return None;
        }
        None
    }

    /// A time beyond `from` at which `f' > 0`, from Cauchy's bound on the roots of the cubic
    /// `f'/2 = (|g|^2/2) t^3 + (3/2)(v.g) t^2 + (|v|^2 + q.g) t + q.v`.
    fn derivative_bracket(&self, from: f64) -> Option<(f64, f64)> {
        let lead = 0.5 * self.g.dot(self.g);
        let others = [
            1.5 * self.v.dot(self.g),
            self.v.dot(self.v) + self.q.dot(self.g),
            self.q.dot(self.v),
        ];
        upper_bracket(|t| self.derivative(t), from, lead, &others, 1.0)
    }

    /// A time beyond `from` at which `-f < 0`, from Cauchy's bound on the quartic `f`.
    fn exit_bracket(&self, from: f64) -> Option<(f64, f64)> {
        let lead = 0.25 * self.g.dot(self.g);
        let others = [
            self.v.dot(self.g),
            self.v.dot(self.v) + self.q.dot(self.g),
            2.0 * self.q.dot(self.v),
            self.q.dot(self.q) - self.radius * self.radius,
        ];
        upper_bracket(|t| self.value(t), from, lead, &others, -1.0)
    }
}

/// Finds `t > from` with `h(t) > 0` using Cauchy's bound `1 + max |a_i / a_n|` on the roots
/// of a polynomial with leading coefficient `lead > 0`, doubling it if rounding leaves `h`
/// non-positive there. Returns `(t, sign * h(t))`.
///
/// With a leading coefficient tiny against the others (an acceleration of `1e-79` of the
/// velocities' scale: the rounding of a solved acceleration that should be zero), the bound
/// is so far out (`1e158`) that `h` overflows there and the bracket was lost, and with it a
/// head-on contact a tenth of a second away (rough hunt seed 236585). Then the bracket is
/// sought the other way, doubling up from `from`: `h` rises beyond `from` (the caller's
/// last turning point), so the first time it is positive closes the bracket as well.
fn upper_bracket<H: Fn(f64) -> f64>(
    h: H,
    from: f64,
    lead: f64,
    others: &[f64],
    sign: f64,
) -> Option<(f64, f64)> {
    let max_ratio = others.iter().fold(0.0_f64, |m, a| m.max((a / lead).abs()));
    // Doubling up from `t` (at most `steps` times) to the first positive `h`; none if `t`
    // overflows or `h` is not a number first.
    let climb = |mut t: f64, steps: usize| {
        for _ in 0..steps {
            if !t.is_finite() {
                return None;
            }
            let value = h(t);
            if value > 0.0 {
                return Some((t, sign * value));
            }
            if value.is_nan() {
                return None;
            }
            t *= 2.0;
        }
        None
    };
    // Else up from `from`: each step doubles `t`, so at most some two thousand of them pass
    // the largest double.
    climb((1.0 + max_ratio).max(from * 2.0 + 1.0), 64)
        .or_else(|| climb(from * 2.0 + 1.0, usize::MAX))
}

/// A root of the monotone function `h` on `[lo, hi]` if it changes sign there.
fn sign_change_root<H>(h: H, lo: f64, hi: f64, h_lo: f64, h_hi: f64) -> Option<f64>
where
    H: Fn(f64) -> (f64, f64),
{
    if h_lo > 0.0 && h_hi <= 0.0 {
        Some(refine_descent(h, lo, hi, h_lo, h_hi))
    } else if h_lo < 0.0 && h_hi >= 0.0 {
        let neg = |t: f64| {
            let (v, d) = h(t);
            (-v, -d)
        };
        Some(refine_descent(neg, lo, hi, -h_lo, -h_hi))
    } else {
        None
    }
}

/// Both real roots of `a t^2 + 2 b t + c` (`a > 0`), ascending; empty if complex.
fn quadratic_roots(a: f64, b: f64, c: f64) -> impl Iterator<Item = f64> {
    let d = super::discriminant(a, b, c);
    let roots = if a > 0.0 && d >= 0.0 {
        // Cancellation-free: the root of larger magnitude is q / a with q = -(b + sign(b) sqrt d),
        // and the other follows from the product of the roots, c / a.
        let sd = d.sqrt();
        let q = -(b + sd.copysign(b));
        let (r1, r2) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
        Some((r1.min(r2), r1.max(r2)))
    } else {
        None
    };
    roots.into_iter().flat_map(|(r1, r2)| [r1, r2])
}

/// A turning point of the gap, as the search is given it.
enum Turn {
    /// The root of `f'`, to its last float.
    At(f64),
    /// A minimum of `f` shown to lie above the graze noise, with a time no later than it.
    ClearMinimum(f64),
}

/// The turning points of a gap, ascending, each refined as it is read (at most three: `f'`
/// is a cubic). A root no later than the one before it (rounding, at a double root of
/// `f''`) is skipped.
struct CriticalPoints<'a> {
    gap: &'a ParabolicGap,
    /// 0 and the positive roots of `f''`, ascending: `f'` is monotone between them.
    breaks: [f64; 3],
    len: usize,
    /// The interval to search next.
    next: usize,
    /// The last turning point given (for a clear minimum, its interval's start: the next
    /// root lies beyond that interval's end).
    last: Option<f64>,
}

impl CriticalPoints<'_> {
    /// The next turning point; a minimum of `f` may come as [`Turn::ClearMinimum`] if
    /// `clear_minimum`.
    fn next_turn(&mut self, clear_minimum: bool) -> Option<Turn> {
        while self.next < self.len {
            let i = self.next;
            self.next += 1;
            let Some(turn) = self.gap.turn_in(&self.breaks[..self.len], i, clear_minimum) else {
                continue;
            };
            self.last = Some(match turn {
                Turn::At(t) if self.last.is_some_and(|last| t <= last) => continue,
                Turn::At(t) => t,
                Turn::ClearMinimum(_) => self.breaks[i],
            });
            return Some(turn);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn gap(q: (f64, f64), v: (f64, f64), g: (f64, f64), radius: f64) -> ParabolicGap {
        ParabolicGap {
            q: DVec2::new(q.0, q.1),
            v: DVec2::new(v.0, v.1),
            g: DVec2::new(g.0, g.1),
            radius,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        /// A minimum left unrefined because it is shown clear of contact changes no answer:
        /// the search with every minimum refined to its last float gives the same bits, on
        /// passes near and far, grazes and contacts (`q` within a few radii, `v` and `g` of
        /// every direction; a summed radius of a few scales).
        #[test]
        fn a_clear_minimum_gives_the_answer_of_a_refined_one(
            q in (-3.0f64..3.0, -3.0f64..3.0),
            v in (-4.0f64..4.0, -4.0f64..4.0),
            g in (-10.0f64..10.0, -10.0f64..10.0),
            radius in prop_oneof![Just(0.4), Just(1.0), 0.01f64..2.0],
            horizon in prop_oneof![Just(f64::INFINITY), 0.0f64..3.0],
        ) {
            let gap = gap(q, v, g, radius);
            prop_assume!(gap.g != DVec2::ZERO);
            let fast = gap.crossing_in_range(1.0, horizon, true, |_| true, true);
            let slow = gap.crossing_in_range(1.0, horizon, true, |_| true, false);
            prop_assert_eq!(fast.map(f64::to_bits), slow.map(f64::to_bits));
        }
    }

    /// A pass whose closest approach is a hair outside or inside the circle (a graze within
    /// or beyond the rounding noise, or a shallow contact) is not taken for clear by the
    /// bound, and its minimum is refined: the answers agree.
    #[test]
    fn near_grazes_are_refined_and_agree() {
        for k in -1_000_i32..1_000 {
            // A ball falling past a point at the side, its closest approach `miss` outside.
            let miss = 1e-16 * f64::from(k * k.abs());
            let gap = gap((-(1.0 + miss), 2.0), (0.0, 0.0), (0.0, -9.81), 1.0);
            let fast = gap.crossing_in_range(1.0, f64::INFINITY, true, |_| true, true);
            let slow = gap.crossing_in_range(1.0, f64::INFINITY, true, |_| true, false);
            assert_eq!(
                fast.map(f64::to_bits),
                slow.map(f64::to_bits),
                "miss {miss:e}"
            );
        }
    }
}
