//! Base-2 digit scrambling for the progressive sequences (Sobol, pmj02,
//! Halton, Hammersley): Owen scrambling.
//!
//! The base-2 radical inverse (van der Corput) of `index` in 0.32 fixed
//! point is `index.reverse_bits()`: the bits mirrored about the binary
//! point. That is also the "reversed-bit" form the scrambles below work
//! in: bit `k` of a reversed value is the digit of weight `2^-(k+1)`. The
//! crate writes `reverse_bits()` for both meanings, with a comment where
//! it is a radical inverse.

/// Owen scrambling (a nested uniform scramble) of a value given in reversed
/// bit order: the hash-based Laine-Karras permutation of Burley 2020,
/// "Practical Hash-based Owen Scrambling", JCGT 9(4) (building on Laine &
/// Karras 2011, "Stratified Sampling for Stochastic Transparency").
///
/// In reversed order bit 0 is the most significant fraction digit. Every step
/// below changes bit `k` only as a function of bits `0..=k` and the seed
/// (adding the seed carries upwards; `x * c` with an even `c` has bit `k`
/// made of bits `< k`), so each digit is flipped by a hash of the digits
/// above it: the defining property of Owen's nested scramble. It is a
/// bijection of `u32` for every seed, and every base-2 elementary interval
/// maps onto one of the same size, so (t, m, 2)-nets stay nets.
///
/// ```
/// use wellspread::primitives::owen_scramble_reversed;
/// // The most significant digit (bit 0 here) flips or not by the seed alone.
/// let flip = owen_scramble_reversed(0, 7) & 1;
/// assert!((0..64).all(|x| (owen_scramble_reversed(x, 7) ^ x) & 1 == flip));
/// ```
#[inline(always)]
#[must_use]
pub const fn owen_scramble_reversed(mut x: u32, seed: u32) -> u32 {
    // Burley's seed add and four even multipliers (his improvement on
    // Laine & Karras's hash): evenness is what keeps each step upward-only.
    x = x.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6c50_b47c);
    x ^= x.wrapping_mul(0xb82f_1e52);
    x ^= x.wrapping_mul(0xc7af_e638);
    x ^= x.wrapping_mul(0x8d22_f6e6);
    x
}

/// Owen scrambling of a 0.32 fixed-point value in natural bit order (bit 31
/// is the digit of weight 1/2): [`owen_scramble_reversed`] between two
/// bit reversals, Burley 2020's `nested_uniform_scramble`.
///
/// Applied to a sample *index* it is Burley's shuffle: bit `k` of the result
/// depends only on bits `k..32` of `index`, so for every `m` the aligned
/// blocks of `2^m` consecutive indices are permuted among themselves, and the
/// first `2^m` shuffled indices form one aligned block. A (0,2)-sequence is a
/// (0,m,2)-net on every aligned block, so the shuffle keeps every
/// power-of-two prefix a net while making prefixes of different seeds
/// independent.
///
/// ```
/// use wellspread::primitives::owen_scramble;
/// let mut block: Vec<u32> = (0..16).map(|i| owen_scramble(i, 99) / 16).collect();
/// block.dedup();
/// assert_eq!(block.len(), 1); // the first 16 land in one aligned block of 16
/// ```
#[inline(always)]
#[must_use]
pub const fn owen_scramble(x: u32, seed: u32) -> u32 {
    owen_scramble_reversed(x.reverse_bits(), seed).reverse_bits()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn owen_scramble_is_nested_and_bijective() {
        for seed in [0, 1, 0xdead_beef, u32::MAX] {
            // Values sharing their top k digits keep sharing them (and no
            // more), so elementary intervals map onto elementary intervals.
            for (x, y) in [
                (0x1234_5678u32, 0x1234_9999u32),
                (0, 1),
                (u32::MAX, 0x8000_0000),
            ] {
                let shared = (x ^ y).leading_zeros();
                let (sx, sy) = (owen_scramble(x, seed), owen_scramble(y, seed));
                assert_eq!(
                    (sx ^ sy).leading_zeros(),
                    shared,
                    "{x:#x} {y:#x} seed {seed:#x}"
                );
            }
            // A bijection: the 2^16 values with fixed low bits map to
            // distinct values.
            let mut seen = std::vec![false; 1 << 16];
            for i in 0..1u32 << 16 {
                let r = owen_scramble_reversed(i, seed) & 0xffff;
                assert!(!seen[r as usize]);
                seen[r as usize] = true;
            }
        }
    }

    #[test]
    fn owen_scrambles_are_pinned() {
        // Part of every Sobol, Pmj02, Halton and Hammersley sample; values
        // cross-checked against an independent Python transcription.
        assert_eq!(owen_scramble_reversed(0, 0), 0);
        assert_eq!(owen_scramble_reversed(1, 0), 0x3707_b665);
        assert_eq!(
            owen_scramble_reversed(0x1234_5678, 0xdead_beef),
            0x023f_ba03
        );
        assert_eq!(owen_scramble(0x8000_0000, 0), 0xa66d_e0ec);
    }
}
