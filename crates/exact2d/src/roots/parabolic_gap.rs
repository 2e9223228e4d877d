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
//! float of contact (see `refine`). `f`, `f'`, `f''` are always evaluated from the geometry
//! (`w` and `w'`), never from expanded polynomial coefficients, so the value near contact is
//! accurate to a few ulps of `R^2`, which is as good as the inputs allow. The expanded
//! coefficients are used only for a root bound.
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
        self.crossing_in_range(sign, horizon, touching_policy, accept)
            .filter(|t| t.is_finite())
    }

    /// [`first_crossing`](Self::first_crossing) for a horizon `>= 0`.
    fn crossing_in_range<A: Fn(f64) -> bool>(
        &self,
        sign: f64,
        horizon: f64,
        touching_policy: bool,
        accept: A,
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
            let Some(c) = critical.next() else {
                break;
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

    /// The root of `f'` on the `i`-th interval between roots of `f''` (the last one open
    /// above), if `f'` changes sign there.
    fn critical_point_in(&self, breaks: &[f64], i: usize) -> Option<f64> {
        let d1 = |t: f64| (self.derivative(t), self.second_derivative(t));
        let lo = breaks[i];
        let f_lo = d1(lo).0;
        let (hi, f_hi) = if i + 1 < breaks.len() {
            (breaks[i + 1], d1(breaks[i + 1]).0)
        } else if f_lo < 0.0 {
            self.derivative_bracket(lo)?
        } else {
            return None;
        };
        if hi <= lo {
            return None;
        }
        sign_change_root(d1, lo, hi, f_lo, f_hi)
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

/// The critical points of a gap, ascending, each refined as it is read (at most three: `f'`
/// is a cubic). A root no later than the one before it (rounding, at a double root of
/// `f''`) is skipped.
struct CriticalPoints<'a> {
    gap: &'a ParabolicGap,
    /// 0 and the positive roots of `f''`, ascending: `f'` is monotone between them.
    breaks: [f64; 3],
    len: usize,
    /// The interval to search next.
    next: usize,
    /// The last critical point given.
    last: Option<f64>,
}

impl Iterator for CriticalPoints<'_> {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        while self.next < self.len {
            let i = self.next;
            self.next += 1;
            let Some(t) = self.gap.critical_point_in(&self.breaks[..self.len], i) else {
                continue;
            };
            if self.last.is_none_or(|last| t > last) {
                self.last = Some(t);
                return Some(t);
            }
        }
        None
    }
}
