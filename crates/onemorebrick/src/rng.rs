//! The game's random numbers: PCG-32 (`rand_pcg`), seeded, serialisable, never global.

use rand_core::{RngCore, SeedableRng};
use rand_pcg::Pcg32;
use serde::{Deserialize, Serialize};

/// A seeded generator whose whole state is saved with the game, so a loaded game draws the
/// same numbers it would have drawn.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct GameRng(Pcg32);

impl GameRng {
    /// A generator from a seed (`rand_core`'s `seed_from_u64`, fixed across versions).
    #[must_use]
    pub fn from_seed(seed: u64) -> Self {
        Self(Pcg32::seed_from_u64(seed))
    }

    /// A uniform integer in `0..n` (Lemire's multiply-shift with rejection, so unbiased).
    ///
    /// # Panics
    /// If `n` is zero (a caller's bug: every range in the rules is non-empty).
    pub fn below(&mut self, n: u32) -> u32 {
        assert!(n > 0, "empty range");
        // Reject the low products that would make some results more likely.
        let threshold = n.wrapping_neg() % n;
        loop {
            let m = u64::from(self.0.next_u32()) * u64::from(n);
            if (m as u32) >= threshold {
                return (m >> 32) as u32;
            }
        }
    }

    /// A uniform integer in `lo..=hi`.
    pub fn between(&mut self, lo: u32, hi: u32) -> u32 {
        lo + self.below(hi - lo + 1)
    }

    /// A uniform double in `[0, 1)`, a multiple of `2^-53`.
    pub fn unit(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Whether a draw with probability `numerator / denominator` succeeds.
    pub fn chance(&mut self, numerator: u32, denominator: u32) -> bool {
        self.below(denominator) < numerator
    }

    /// A deterministic text form of the state, for hashing.
    #[must_use]
    pub fn fingerprint(&self) -> String {
        serde_json::to_string(&self.0).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn below_covers_its_range_evenly() {
        let mut rng = GameRng::from_seed(1);
        let mut counts = [0u32; 7];
        for _ in 0..70_000 {
            counts[rng.below(7) as usize] += 1;
        }
        // Each count is binomial(70000, 1/7): mean 10000, sd 93; 6 sd either way.
        assert!(
            counts.iter().all(|&c| (9_440..=10_560).contains(&c)),
            "{counts:?}"
        );
    }

    #[test]
    fn unit_is_in_range_and_seeds_differ() {
        let (mut a, mut b) = (GameRng::from_seed(1), GameRng::from_seed(2));
        let xs: Vec<f64> = (0..1000).map(|_| a.unit()).collect();
        assert!(xs.iter().all(|&x| (0.0..1.0).contains(&x)));
        assert_ne!(a.unit(), b.unit());
    }
}
