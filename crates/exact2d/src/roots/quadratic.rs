//! The first descending root of a quadratic gap function, in closed form.
//!
//! A gap quadratic is written in half-b form, `p(t) = a t^2 + 2 b t + c`, because every
//! geometric coefficient comes out that way (`b` is a dot product, not twice one). Its roots are
//! `(-b ± sqrt(d)) / a` with `d = b^2 - a c`, and `p'(t) = 2 (a t + b)` equals `∓ 2 sqrt(d)` at
//! them, so the root at which `p` *descends* through zero is always `t = (-b - sqrt(d)) / a`,
//! whatever the sign of `a`. Written like that it cancels when `b < 0`; multiplying by the
//! conjugate gives the equivalent `t = c / (sqrt(d) - b)`, whose denominator is then a sum of two
//! non-negative numbers. Choosing the form by the sign of `b` never subtracts nearly equal
//! numbers (Press et al., *Numerical Recipes*, section 5.6; Higham, *Accuracy and Stability of
//! Numerical Algorithms*, section 1.8).

use super::discriminant;

/// The first time `t > 0` at which `p(t) = a t^2 + 2 b t + c` crosses zero going down
/// (`p(t) = 0` and `p'(t) < 0`), or `None` if it never does.
///
/// A double root (`d = 0`) is a tangency, not a descent, and gives `None`. The sign of `c` may
/// be anything: with `c < 0` this finds the moment a function that is negative now comes back
/// down through zero after first rising above it.
///
/// A `Some` is always finite and `>= 0`. A coefficient that is NaN gives `None` (or, for an
/// infinite one, whatever the IEEE arithmetic of the formulas decides, never a panic); a root
/// too large for an `f64` (`c / (-2 b)` overflowing, say) gives `None`: it lies beyond every
/// finite horizon.
#[must_use]
pub fn first_descent(a: f64, b: f64, c: f64) -> Option<f64> {
    let t = if a == 0.0 {
        // Linear: 2 b t + c descends through zero only if b < 0, at t = c / (-2b) > 0.
        (b < 0.0 && c > 0.0).then(|| c / (-2.0 * b))
    } else {
        // Two cheap exits that decide exactly as the formulas below would: a convex gap not
        // falling now never descends, and a discriminant negative by more than the naive
        // formula's rounding (at most about 2 eps (b^2 + |a c|)) is negative.
        if a > 0.0 && b >= 0.0 {
            return None;
        }
        let (bb, ac) = (b * b, a * c);
        if bb - ac < -4.0 * f64::EPSILON * (bb + ac.abs()) {
            return None;
        }
        let d = discriminant(a, b, c);
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        let sd = d.sqrt();
        if b > 0.0 {
            // t = -(b + sd) / a is positive only for a < 0 (a concave gap that comes back down).
            (a < 0.0).then(|| -(b + sd) / a)
        } else {
            // t = c / (sd - b) with sd - b > 0: positive only if the gap is positive now.
            (c > 0.0).then(|| c / (sd - b))
        }
    };
    t.filter(|t| t.is_finite())
}

/// The time of first contact for a gap quadratic `p(t) = a t^2 + 2 b t + c` whose value now
/// is `c`, following the engine's touching-contact policy:
///
/// - `c <= 0` (touching, or overlapping by rounding) and approaching, at first or second
///   order (`b < 0`, or `b = 0` with `a < 0`: at rest against a surface that pulls it in):
///   contact now, `Some(0.0)`;
/// - `c <= 0` and separating too slowly to get clear (`b > 0`, `a < 0` and the gap's maximum
///   `c - b^2 / a` not above zero): contact at that maximum, `-b / a`, where it stops
///   separating and starts to approach without ever having come apart;
/// - `c <= 0` otherwise (separating for good, or tangential with no pull): no event now; the
///   next descent, if the gap later comes back, is found as usual;
/// - `c > 0`: the first descending root.
///
/// So a ball touching or overlapping a surface is never left approaching it without a
/// contact. NaN coefficients give `None`, except that touching and approaching is decided
/// from `b` and `c` alone (`a` does not matter for a contact now). See [`first_descent`] for
/// infinite coefficients and roots too large for an `f64`.
#[must_use]
#[inline]
pub fn first_contact(a: f64, b: f64, c: f64) -> Option<f64> {
    if c <= 0.0 {
        return touching_contact(a, b, c);
    }
    first_descent(a, b, c)
}

/// [`first_contact`] for a gap that is zero or negative now (`c <= 0`): out of the hot path
/// of predictions between bodies apart.
#[cold]
#[inline(never)]
fn touching_contact(a: f64, b: f64, c: f64) -> Option<f64> {
    if b < 0.0 || (b == 0.0 && a < 0.0) {
        return Some(0.0);
    }
    if b > 0.0 && a < 0.0 {
        // Rising to `c - b^2 / a = -d / a` at `-b / a`: clear of the surface only if the
        // discriminant `d = b^2 - a c` is positive.
        let d = discriminant(a, b, c);
        if !(d > 0.0) {
            return Some(-b / a).filter(|t| t.is_finite());
        }
    }
    first_descent(a, b, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn convex_gap_descends_at_its_smaller_root() {
        // (t - 1)(t - 3) = t^2 - 4t + 3: half-b = -2.
        assert_eq!(first_descent(1.0, -2.0, 3.0), Some(1.0));
    }

    #[test]
    fn concave_gap_descends_at_its_positive_root() {
        // -(t + 1)(t - 2) = -t^2 + t + 2: half-b = 0.5.
        assert_eq!(first_descent(-1.0, 0.5, 2.0), Some(2.0));
    }

    #[test]
    fn negative_now_but_rising_then_falling_descends_at_the_larger_root() {
        // -(t - 1)(t - 3) = -t^2 + 4t - 3: negative at 0, up through 1, down through 3.
        assert_eq!(first_descent(-1.0, 2.0, -3.0), Some(3.0));
    }

    #[test]
    fn separating_convex_gap_never_descends() {
        assert_eq!(first_descent(1.0, 2.0, 3.0), None);
    }

    #[test]
    fn double_root_is_a_tangency_not_a_contact() {
        // (t - 2)^2: touches zero at t = 2 without crossing.
        assert_eq!(first_descent(1.0, -2.0, 4.0), None);
    }

    #[test]
    fn a_root_too_large_for_an_f64_is_no_root() {
        assert_eq!(first_descent(0.0, -1e-300, 1e300), None);
        assert_eq!(first_descent(1e-320, -1e-10, 1e299), None);
    }

    #[test]
    fn linear_gap() {
        assert_eq!(first_descent(0.0, -1.0, 4.0), Some(2.0));
        assert_eq!(first_descent(0.0, 1.0, 4.0), None);
    }

    #[test]
    fn touching_and_approaching_is_contact_now() {
        assert_eq!(first_contact(1.0, -1.0, 0.0), Some(0.0));
        assert_eq!(first_contact(1.0, -1.0, -1e-18), Some(0.0));
    }

    #[test]
    fn touching_and_separating_or_tangential_is_no_contact() {
        assert_eq!(first_contact(1.0, 1.0, 0.0), None);
        assert_eq!(first_contact(1.0, 0.0, 0.0), None);
        assert_eq!(first_contact(1.0, 1.0, -1e-18), None);
        assert_eq!(first_contact(0.0, 0.0, 0.0), None);
        assert_eq!(first_contact(0.0, 0.0, -1e-18), None);
    }

    #[test]
    fn overlapping_at_rest_and_pulled_in_is_contact_now() {
        // A ball placed a hair into a floor under gravity: its gap only falls.
        assert_eq!(first_contact(-1.0, 0.0, -1e-12), Some(0.0));
        assert_eq!(first_contact(-1.0, 0.0, 0.0), Some(0.0));
    }

    #[test]
    fn overlapping_and_separating_too_slowly_to_get_clear_meets_at_the_turning_point() {
        // -t^2 + 2 t - 2: rises from -2 to -1 at t = 1, then falls: it never surfaces.
        assert_eq!(first_contact(-1.0, 1.0, -2.0), Some(1.0));
        // -t^2 + 2 t - 0.75: surfaces at 0.5 and comes back down through zero at 1.5.
        assert_eq!(first_contact(-1.0, 1.0, -0.75), Some(1.5));
    }

    #[test]
    fn tiny_root_far_from_cancellation_keeps_full_relative_precision() {
        // t^2 - 2e8 t + 1 = 0: the small root is 5e-9 (to 1e-25); the textbook formula
        // (2e8 - sqrt(4e16 - 4)) / 2 returns 0 or a value with no correct digit.
        let t = first_descent(1.0, -1e8, 1.0).unwrap();
        assert!((t - 5e-9).abs() <= 5e-9 * 1e-15, "{t}");
    }
}
