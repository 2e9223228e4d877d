//! Sine and cosine, correctly rounded (to nearest) in plain `+ - * /`, so that a scene built
//! from angles has the same starting bits on every platform.
//!
//! `f64::sin` and `f64::cos` come from the platform's maths library, and those differ: glibc
//! rounds them correctly, the `libm` port that Rust's wasm32 standard library uses is only
//! within one unit in the last place. The engine's golden run once drew its balls'
//! directions with them, and in wasm32 8 of its first 160 sines and cosines came out one
//! unit off, so every hash after the first event differed. Correct rounding gives glibc's
//! bits wherever glibc is correct, which keeps the golden values as they were.
//!
//! The method: the argument reduced by the nearest multiple `k` of pi/2 given as three
//! doubles (Cody and Waite), the remainder `r` kept as a double-double, the Taylor series of
//! `sin r` and `cos r` (`|r| <= pi/4`) summed in double-double arithmetic (Dekker, "A
//! floating-point technique for extending the available precision", 1971; Knuth's two-sum),
//! then rounded once. Each step errs by about 2^-104 relative, so the rounding is wrong only
//! if the true value lies within about 2^-100 of a midpoint between two doubles.

/// pi/2 as three doubles whose sum is pi/2 to about 2^-160 (computed at 300 bits).
const HALF_PI: [f64; 3] = [
    f64::from_bits(0x3ff9_21fb_5444_2d18),
    f64::from_bits(0x3c91_a626_3314_5c07),
    f64::from_bits(0xb91f_1976_b7ed_8fbc),
];

/// The largest argument accepted: `k` stays an exact integer and `k * HALF_PI[2]` stays
/// below 2^-140 relative error.
pub const MAX_ARGUMENT: f64 = 1_048_576.0;

/// A double-double: the unevaluated sum `hi + lo`, `|lo| <= ulp(hi) / 2`.
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
}

/// `a + b` as a rounded sum and its exact error (Knuth's two-sum: no condition).
fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    Dd {
        hi: s,
        lo: (a - (s - bb)) + (b - bb),
    }
}

/// `a + b` as a rounded sum and its exact error, when `|a| >= |b|` (or `a` is 0).
fn fast_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

/// `a * b` as a rounded product and its exact error (Dekker's product: each factor split
/// into two halves of 26 bits by `2^27 + 1`, so the partial products are exact).
fn two_product(a: f64, b: f64) -> Dd {
    let split = |x: f64| {
        let t = 134_217_729.0 * x;
        let hi = t - (t - x);
        (hi, x - hi)
    };
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    Dd {
        hi: p,
        lo: ((ah * bh - p) + ah * bl + al * bh) + al * bl,
    }
}

impl Dd {
    fn from(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    fn add(self, other: Dd) -> Dd {
        let s = two_sum(self.hi, other.hi);
        let t = two_sum(self.lo, other.lo);
        let u = fast_two_sum(s.hi, s.lo + t.hi);
        fast_two_sum(u.hi, u.lo + t.lo)
    }

    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    fn mul(self, other: Dd) -> Dd {
        let p = two_product(self.hi, other.hi);
        fast_two_sum(p.hi, p.lo + (self.hi * other.lo + self.lo * other.hi))
    }

    /// Divided by a double `d` (here a small exact integer).
    fn div(self, d: f64) -> Dd {
        let q = self.hi / d;
        let p = two_product(q, d);
        let rest = ((self.hi - p.hi) - p.lo + self.lo) / d;
        fast_two_sum(q, rest)
    }

    /// The nearest double.
    fn round(self) -> f64 {
        self.hi + self.lo
    }
}

/// `sin x` and `cos x`, each correctly rounded to nearest (but for values within about
/// 2^-100 of a midpoint, see the module's docs).
///
/// # Panics
/// If `x` is not finite or `|x| > MAX_ARGUMENT`: the scenes use angles of a few radians.
#[must_use]
pub fn sin_cos(x: f64) -> (f64, f64) {
    assert!(
        x.abs() <= MAX_ARGUMENT,
        "sin_cos({x}): only finite arguments up to {MAX_ARGUMENT} in magnitude"
    );
    let k = (x / HALF_PI[0]).round();
    // r = x - k pi/2: `k HALF_PI[0]` and `k HALF_PI[1]` exactly as double-doubles, the last
    // third rounded (its error is far below 2^-104 of any remainder a double can leave).
    let r = two_sum(x, 0.0)
        .add(two_product(k, HALF_PI[0]).neg())
        .add(two_product(k, HALF_PI[1]).neg())
        .add(Dd::from(-k * HALF_PI[2]));
    let (s, c) = (sin_series(r), cos_series(r));
    let (s, c) = match (k as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, s.neg()),
        2 => (s.neg(), c.neg()),
        _ => (c.neg(), s),
    };
    (s.round(), c.round())
}

/// Terms `r^n / n!` beyond which the series stops: `(pi/4)^28 / 28! < 2^-120`.
const LAST_POWER: u32 = 28;

/// `sin r = r - r^3/3! + r^5/5! - ...` for `|r| <= pi/4`, the terms in decreasing size.
fn sin_series(r: Dd) -> Dd {
    series(r, r, 1)
}

/// `cos r = 1 - r^2/2! + r^4/4! - ...` for `|r| <= pi/4`.
fn cos_series(r: Dd) -> Dd {
    series(r, Dd::from(1.0), 0)
}

/// The alternating series from `first = r^n / n!`, each term `-r^2 / ((n+1)(n+2))` times the
/// one before.
fn series(r: Dd, first: Dd, n: u32) -> Dd {
    let minus_r2 = r.mul(r).neg();
    let (mut term, mut sum, mut n) = (first, first, n);
    while n + 2 <= LAST_POWER {
        term = term.mul(minus_r2).div(f64::from((n + 1) * (n + 2)));
        sum = sum.add(term);
        n += 2;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sines and cosines rounded from 300-bit values (mpmath), as bits.
    const REFERENCE: [(f64, u64, u64); 11] = [
        (0.0, 0x0000_0000_0000_0000, 0x3ff0_0000_0000_0000),
        (1e-300, 0x01a5_6e1f_c2f8_f359, 0x3ff0_0000_0000_0000),
        (0.5, 0x3fde_aee8_744b_05f0, 0x3fec_1528_065b_7d50),
        (1.0, 0x3fea_ed54_8f09_0cee, 0x3fe1_4a28_0fb5_068c),
        (
            std::f64::consts::FRAC_PI_2,
            0x3ff0_0000_0000_0000,
            0x3c91_a626_3314_5c07,
        ),
        (
            std::f64::consts::PI,
            0x3ca1_a626_3314_5c07,
            0xbff0_0000_0000_0000,
        ),
        (
            4.712_388_980_384_69,
            0xbff0_0000_0000_0000,
            0xbcaa_7939_4c9e_8a0a,
        ),
        (
            std::f64::consts::TAU,
            0xbcb1_a626_3314_5c07,
            0x3ff0_0000_0000_0000,
        ),
        (0.3, 0x3fd2_e9cd_95ba_ba33, 0x3fee_921d_d42f_09ba),
        (6.2, 0xbfb5_4558_dbbe_cd1d, 0x3fef_e3ac_4079_a9ce),
        (100.0, 0xbfe0_3425_b78c_4db8, 0x3feb_981d_bf66_5fdf),
    ];

    #[test]
    fn sines_and_cosines_are_the_correctly_rounded_ones() {
        for (x, sin, cos) in REFERENCE {
            let (s, c) = sin_cos(x);
            assert_eq!((s.to_bits(), c.to_bits()), (sin, cos), "x = {x}");
            let (s, c) = sin_cos(-x);
            assert_eq!(-s, f64::from_bits(sin), "x = -{x}");
            assert_eq!(c.to_bits(), cos, "x = -{x}");
        }
    }

    /// Within one unit in the last place of the platform's (which is itself within one).
    #[test]
    fn sines_and_cosines_are_within_one_unit_of_the_platforms() {
        let mut rng = crate::engine::SplitMix(3);
        let ulp = |a: f64, b: f64| (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs();
        for _ in 0..100_000 {
            let x = rng.range(-20.0, 20.0);
            let (s, c) = sin_cos(x);
            assert!(ulp(s, x.sin()) <= 1 && ulp(c, x.cos()) <= 1, "x = {x}");
        }
    }

    #[test]
    #[should_panic(expected = "only finite arguments")]
    fn an_argument_out_of_range_is_refused() {
        let _ = sin_cos(f64::NAN);
    }
}
