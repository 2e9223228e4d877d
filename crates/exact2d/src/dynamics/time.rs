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
        Self { hi: seconds, lo: 0.0 }
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
    fn cmp(&self, other: &Self) -> Ordering {
        // With `hi` the rounded sum, comparing `hi` first and then `lo` is comparing values.
        self.hi.total_cmp(&other.hi).then_with(|| self.lo.total_cmp(&other.lo))
    }
}

impl PartialOrd for Time {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Knuth's two-sum: `a + b = s + e` exactly, `s = fl(a + b)`.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_durations_added_to_a_large_time_are_not_lost() {
        let mut t = Time::new(1.0e6);
        for _ in 0..1000 {
            t = t.after(1.0e-12);
        }
        // 1e6 + 1e-9 is not representable; the residual keeps it.
        assert!((t.since(Time::new(1.0e6)) - 1.0e-9).abs() < 1e-21);
        assert_eq!(t.seconds(), 1.0e6);
    }

    #[test]
    fn ordering_follows_the_exact_value() {
        let a = Time::new(1.0).after(1e-20);
        let b = Time::new(1.0);
        assert!(a > b && b < a);
        assert_eq!(a.seconds(), b.seconds());
    }
}
