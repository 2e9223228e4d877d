//! Error-free products and the compensated discriminant.
//!
//! The discriminant `b*b - a*c` cancels catastrophically exactly where it matters: near a
//! grazing contact, where the two roots of a gap quadratic merge. Kahan ("On the cost of
//! floating-point computation without extra-precise arithmetic", 2004) shows that evaluating
//! both products exactly, as an unevaluated sum of two doubles, and subtracting the parts
//! separately gives the discriminant to within a couple of ulps of its own size. We compute the
//! exact products with Dekker's splitting (1971) rather than a fused multiply-add, because
//! `f64::mul_add` falls back to a slow software routine on x86-64 targets without FMA.

/// Veltkamp's splitter for f64: 2^27 + 1.
const SPLITTER: f64 = 134_217_729.0;

/// Splits `a` into a high and a low half of 26 significant bits each, `a = hi + lo` exactly.
#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// The exact product of two doubles as a rounded product and its rounding error:
/// `a * b = p + e` exactly, with `p = fl(a * b)`.
///
/// Exact unless `a * b` overflows or `|a|` or `|b|` exceeds about 1e300 (the splitting then
/// overflows); no input of a physics scene comes near that.
#[must_use]
#[inline]
pub fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    (p, e)
}

/// `b*b - a*c`, accurate to a few ulps of the result even when the two products almost cancel.
#[must_use]
#[inline]
pub fn discriminant(a: f64, b: f64, c: f64) -> f64 {
    let (p, dp) = two_product(b, b);
    let (q, dq) = two_product(a, c);
    (p - q) + (dp - dq)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_product_is_exact_for_values_whose_product_needs_more_than_53_bits() {
        // (2^27 + 1)^2 = 2^54 + 2^28 + 1 needs 55 bits: the rounded product drops the final 1.
        let a = 134_217_729.0;
        let (p, e) = two_product(a, a);
        assert_eq!(p, 18_014_398_777_917_440.0);
        assert_eq!(e, 1.0);
    }

    #[test]
    fn discriminant_survives_cancellation_that_destroys_the_naive_formula() {
        // b^2 - a*c with b = 1 + 2^-30, a = 1, c = 1 + 2^-29: exact value 2^-60.
        let b = 1.0 + 2f64.powi(-30);
        let c = 1.0 + 2f64.powi(-29);
        assert_eq!(discriminant(1.0, b, c), 2f64.powi(-60));
        assert_eq!(b * b - c, 0.0, "the naive formula loses every digit here");
    }
}
