//! Refining a bracketed root to the last representable time.
//!
//! The caller gives an interval `[lo, hi]` of non-negative times on which a function `f`
//! goes from positive (`f(lo) > 0`) to non-positive (`f(hi) <= 0`). We return the *first
//! float* `t` in the interval at which the computed `f(t) <= 0`: the earliest representable
//! time of contact. The interval shrinks by safeguarded Newton steps (fast, about six steps
//! from a good bracket) and, whenever a Newton step would leave the bracket or stalls, by
//! bisection of the *bit patterns* of the end points. For non-negative doubles the bit pattern
//! is monotone in the value, so bit bisection halves the number of floats in the bracket and
//! ends after at most 64 steps, however close to zero the root lies.

/// How many Newton steps we allow before falling back to pure bisection. Newton converges
/// quadratically from a bracket given by critical points, so this is never reached in
/// practice; it bounds the work if `f` is badly behaved.
const MAX_NEWTON_STEPS: u32 = 40;

/// A Newton step shorter than this many ulps of `x` means Newton has converged: the root is
/// within a few floats of `x`, and we finish by galloping across it and bisecting.
const CONVERGED_ULPS: f64 = 4.0;

/// The first float `t` in `[lo, hi]` with `f(t).0 <= 0`, given `f(lo) > 0 >= f(hi)`.
///
/// `f` returns the value and the derivative. `f_lo` and `f_hi` are the values at the ends
/// (already known to the caller). Requires `0 <= lo < hi`, both finite.
pub(crate) fn refine_descent<F>(f: F, mut lo: f64, mut hi: f64, f_lo: f64, f_hi: f64) -> f64
where
    F: Fn(f64) -> (f64, f64),
{
    debug_assert!(lo >= 0.0 && lo < hi && f_lo > 0.0 && f_hi <= 0.0);
    // Start from the secant (regula falsi) point: the end points are often critical points
    // of `f`, where a Newton step from the end would be useless.
    let mut x = lo + (hi - lo) * (f_lo / (f_lo - f_hi));
    if !(x > lo && x < hi) {
        x = bit_midpoint(lo, hi);
    }
    for _ in 0..MAX_NEWTON_STEPS {
        if are_adjacent(lo, hi) {
            return hi;
        }
        let (fx, dfx) = f(x);
        if fx > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        if are_adjacent(lo, hi) {
            return hi;
        }
        let next = x - fx / dfx;
        if !(next > lo && next < hi) {
            x = bit_midpoint(lo, hi);
        } else if (next - x).abs() <= CONVERGED_ULPS * ulp(x) {
            return close_bracket(&f, lo, hi, x, fx > 0.0);
        } else {
            x = next;
        }
    }
    bisect(&f, lo, hi)
}

/// Newton has converged to `x`, one end of the bracket; the root is a few floats away on
/// the other side. Step across it with doubling strides, then bisect what is left.
fn close_bracket<F>(f: &F, mut lo: f64, mut hi: f64, x: f64, x_is_lo: bool) -> f64
where
    F: Fn(f64) -> (f64, f64),
{
    let mut stride: u64 = 1;
    loop {
        let probe = if x_is_lo {
            f64::from_bits(x.to_bits().saturating_add(stride))
        } else {
            f64::from_bits(x.to_bits().saturating_sub(stride))
        };
        if !(probe > lo && probe < hi) {
            break;
        }
        if f(probe).0 > 0.0 {
            lo = probe;
            if !x_is_lo {
                break;
            }
        } else {
            hi = probe;
            if x_is_lo {
                break;
            }
        }
        stride *= 2;
    }
    bisect(f, lo, hi)
}

/// Bit bisection until `lo` and `hi` are adjacent floats; returns `hi`.
fn bisect<F>(f: &F, mut lo: f64, mut hi: f64) -> f64
where
    F: Fn(f64) -> (f64, f64),
{
    while !are_adjacent(lo, hi) {
        let mid = bit_midpoint(lo, hi);
        if f(mid).0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}

/// Whether no float lies strictly between `lo` and `hi` (`0 <= lo < hi`).
#[inline]
fn are_adjacent(lo: f64, hi: f64) -> bool {
    hi.to_bits() - lo.to_bits() <= 1
}

/// The float halfway between `lo` and `hi` in bit-pattern order (`0 <= lo < hi`).
#[inline]
fn bit_midpoint(lo: f64, hi: f64) -> f64 {
    let (a, b) = (lo.to_bits(), hi.to_bits());
    f64::from_bits(a + (b - a) / 2)
}

/// The distance from `x` to the next larger float.
#[inline]
fn ulp(x: f64) -> f64 {
    let x = x.abs();
    f64::from_bits(x.to_bits() + 1) - x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic(t: f64) -> (f64, f64) {
        // (2 - t)(t^2 + 1): a single real root at t = 2, negative beyond it.
        (
            (2.0 - t) * (t * t + 1.0),
            -(t * t + 1.0) + (2.0 - t) * 2.0 * t,
        )
    }

    #[test]
    fn finds_the_exact_root_when_it_is_representable() {
        let (f0, f3) = (cubic(0.0).0, cubic(3.0).0);
        assert_eq!(refine_descent(cubic, 0.0, 3.0, f0, f3), 2.0);
    }

    #[test]
    fn returns_the_first_float_at_which_the_function_is_not_positive() {
        // f(t) = 2 - t^2: root sqrt(2), not representable.
        let f = |t: f64| (2.0 - t * t, -2.0 * t);
        let t = refine_descent(f, 0.0, 2.0, 2.0, -2.0);
        assert!(f(t).0 <= 0.0);
        let before = f64::from_bits(t.to_bits() - 1);
        assert!(f(before).0 > 0.0);
    }

    #[test]
    fn roots_near_zero_keep_their_relative_precision() {
        let r = 3e-200;
        let f = |t: f64| (r - t, -1.0);
        assert_eq!(refine_descent(f, 0.0, 1.0, r, r - 1.0), r);
    }

    #[test]
    fn a_useless_derivative_still_converges_by_bisection() {
        let f = |t: f64| (1.0 - t, 1e300);
        assert_eq!(refine_descent(f, 0.0, 4.0, 1.0, -3.0), 1.0);
    }
}
