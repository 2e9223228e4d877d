//! Where a generator's choices come from: a seeded generator, or a fuzzer's bytes.

/// A stream of choices. Every choice is made from [`Source::next_u64`], so the same stream
/// gives the same scene.
pub trait Source {
    /// The next 64 bits.
    fn next_u64(&mut self) -> u64;

    /// A number in `0..n` (`n > 0`).
    fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }

    /// One of `items` (not empty).
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }

    /// A double in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// `true` with probability `p`.
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
}

/// SplitMix64 (Steele, Lea and Flood 2014): a seed names a scene, on every machine.
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl Source for SplitMix64 {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
}

/// A fuzzer's bytes, eight to a choice (zeros once they run out): the fuzzer steers the
/// generator through them.
#[derive(Clone, Debug)]
pub struct Bytes<'a> {
    data: &'a [u8],
    at: usize,
}

impl<'a> Bytes<'a> {
    /// Choices from `data`.
    #[must_use]
    pub fn new(data: &'a [u8]) -> Self {
        Self { data, at: 0 }
    }
}

impl Source for Bytes<'_> {
    fn next_u64(&mut self) -> u64 {
        let mut word = [0u8; 8];
        let end = (self.at + 8).min(self.data.len());
        if self.at < end {
            word[..end - self.at].copy_from_slice(&self.data[self.at..end]);
        }
        self.at = end.max(self.at);
        u64::from_le_bytes(word)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_mix_is_the_published_sequence() {
        // The first outputs for seed 0 (Vigna's reference implementation).
        let mut s = SplitMix64(0);
        assert_eq!(s.next_u64(), 0xe220_a839_7b1d_cdaf);
        assert_eq!(s.next_u64(), 0x6e78_9e6a_a1b9_65f4);
    }

    #[test]
    fn bytes_run_out_into_zeros() {
        let mut b = Bytes::new(&[1, 0, 0, 0, 0, 0, 0, 0, 2]);
        assert_eq!(b.next_u64(), 1);
        assert_eq!(b.next_u64(), 2);
        assert_eq!(b.next_u64(), 0);
        assert_eq!(b.below(0), 0);
    }
}
