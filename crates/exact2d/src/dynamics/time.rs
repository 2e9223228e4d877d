//! Simulation time kept exactly: an unevaluated sum of two doubles.
//!
//! Event times are sums: the origin of a trajectory plus a time of impact `tau` that the kernels
//! compute to full *relative* precision. Rounding that sum to one double would throw away
//! everything of `tau` below one ulp of the absolute time: at `t = 64` an ulp is 1.4e-14 s, and a
//! ball at 10^4 units/s would land up to 7e-11 units off the contact point at every bounce,
//! with the same sign bounce after bounce (the roundings repeat with the same pattern), a drift
//! that grows linearly with the number of events and with the clock. Keeping the rounding error
//! of each sum (Knuth's two-sum, exact) as a second double makes every origin exact to about
//! 1e-32 relative, so the precision of a run no longer depends on how long it has been running.

use std::cmp::Ordering;

/// The shortest duration a time `t` can be told apart from, as a fraction of `|t|`: `2^-100`.
///
/// A `Time` resolves about `2^-106 |t|`; durations within a few dozen of those ulps of each
/// other cannot be ordered or stated reliably. An event predicted closer than this to its
/// trajectory's origin is *unresolvable*: handling it would restate the ball at (nearly) the
/// same instant and predict the same event again, without end. This is how an inelastic ball
/// bouncing on a floor under gravity, whose bounces shrink geometrically, ends: its bounces
/// past this resolution are treated as tangential, like a graze. (In a world, resting contact
/// ends such a sequence long before: see `SETTLE_HEIGHT`.)
pub const RESOLUTION: f64 = 7.888_609_052_210_118e-31;

/// A time as `hi + lo` exactly, with `hi` the nearest double to the sum (so `|lo|` is at most
/// half an ulp of `hi`). Ordered by value.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Time {
    hi: f64,
    lo: f64,
}

impl Time {
    /// Time zero.
    pub const ZERO: Time = Time { hi: 0.0, lo: 0.0 };

    /// A time given as one double.
    #[must_use]
    #[inline]
    pub const fn new(seconds: f64) -> Self {
        Self {
            hi: seconds,
            lo: 0.0,
        }
    }

    /// The nearest double.
    #[must_use]
    #[inline]
    pub fn seconds(self) -> f64 {
        self.hi
    }

    /// The rounding error of [`seconds`](Self::seconds): the exact time is `seconds() + residual()`.
    #[must_use]
    #[inline]
    pub fn residual(self) -> f64 {
        self.lo
    }

    /// This time plus a duration, with the sum's rounding error kept.
    #[must_use]
    #[inline]
    pub fn after(self, duration: f64) -> Self {
        let (hi, lo) = two_sum(self.hi, self.lo + duration);
        Self { hi, lo }
    }

    /// Whether a positive `duration` after this time is long enough to be resolved: at least
    /// [`RESOLUTION`] times the time's magnitude.
    #[must_use]
    #[inline]
    pub fn resolves(self, duration: f64) -> bool {
        duration >= RESOLUTION * self.hi.abs()
    }

    /// The shortest positive duration this time resolves: [`RESOLUTION`] times its magnitude.
    #[must_use]
    #[inline]
    pub fn shortest(self) -> f64 {
        RESOLUTION * self.hi.abs()
    }

    /// This time plus `duration`, or `None` if a positive `duration` is too short to resolve
    /// (see [`RESOLUTION`]) or the sum is past the largest finite time; a zero duration is
    /// always kept.
    #[must_use]
    #[inline]
    pub fn resolved_after(self, duration: f64) -> Option<Self> {
        (duration == 0.0 || self.resolves(duration))
            .then(|| self.after(duration))
            .filter(|t| t.hi.is_finite())
    }

    /// The duration from `earlier` to `self` (negative if `earlier` is later), to about one
    /// rounding of the difference.
    #[must_use]
    #[inline]
    pub fn since(self, earlier: Time) -> f64 {
        (self.hi - earlier.hi) + (self.lo - earlier.lo)
    }
}

impl Eq for Time {}

impl Ord for Time {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        // With `hi` the rounded sum, comparing `hi` first and then `lo` is comparing values.
        // Leading doubles that differ as numbers differ the same way in the total order (two
        // comparisons, where the total order's integer keys cost a dozen instructions); only
        // equal ones (+0 and -0 among them) and NaN reach the total order.
        if self.hi < other.hi {
            Ordering::Less
        } else if self.hi > other.hi {
            Ordering::Greater
        } else {
            self.hi
                .total_cmp(&other.hi)
                .then_with(|| self.lo.total_cmp(&other.lo))
        }
    }
}

impl PartialOrd for Time {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Knuth's two-sum: `a + b = s + e` exactly, `s = fl(a + b)` (six operations, no condition
/// on the magnitudes; a non-finite sum gives a non-finite error).
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// The sooner of two durations that may never come (`None`): the one that comes, or the
/// shorter of the two.
#[must_use]
pub(crate) fn sooner(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_order_is_the_total_order_of_hi_then_lo() {
        // The reference: the total order of the leading doubles, then of the trailing ones.
        let values = [
            f64::NEG_INFINITY,
            -1.0,
            -f64::MIN_POSITIVE / 2.0,
            -0.0,
            0.0,
            f64::MIN_POSITIVE / 2.0,
            1.0,
            1.0 + f64::EPSILON,
            f64::INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        let times: Vec<Time> = values
            .iter()
            .flat_map(|&hi| values.iter().map(move |&lo| Time { hi, lo }))
            .collect();
        for a in &times {
            for b in &times {
                let reference = a.hi.total_cmp(&b.hi).then(a.lo.total_cmp(&b.lo));
                assert_eq!(a.cmp(b), reference, "{a:?} against {b:?}");
                let max = if reference.is_gt() { a } else { b };
                let bits = |t: &Time| (t.hi.to_bits(), t.lo.to_bits());
                assert_eq!(bits(&(*a).max(*b)), bits(max));
            }
        }
    }

    #[test]
    fn small_durations_added_to_a_large_time_are_not_lost() {
        // An ulp of 1e6 is 1.16e-10: adding 1e-14 a thousand times never moves the double,
        // but the residual keeps all of it.
        let mut t = Time::new(1.0e6);
        for _ in 0..1000 {
            t = t.after(1.0e-14);
        }
        assert_eq!(t.seconds(), 1.0e6);
        assert!((t.since(Time::new(1.0e6)) - 1.0e-11).abs() < 1e-24);
        // Past half an ulp the double moves, and the sum is still exact.
        for _ in 0..99_000 {
            t = t.after(1.0e-14);
        }
        assert_eq!(t.seconds(), 1.0e6 + 1.0e-9);
        assert!((t.since(Time::new(1.0e6)) - 1.0e-9).abs() < 1e-22);
    }

    #[test]
    fn resolution_is_two_to_the_minus_100() {
        assert_eq!(RESOLUTION, 2f64.powi(-100));
        assert!(Time::new(1.0).resolves(RESOLUTION) && !Time::new(2.0).resolves(RESOLUTION));
    }

    #[test]
    fn ordering_follows_the_exact_value() {
        let a = Time::new(1.0).after(1e-20);
        let b = Time::new(1.0);
        assert!(a > b);
        assert_eq!(a.cmp(&b), std::cmp::Ordering::Greater);
        assert_eq!(a.seconds(), b.seconds());
    }
}
