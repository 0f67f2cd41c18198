//! Hashed permutations of `[0, len)`: element `index` of permutation
//! `pattern` in O(1), with no table.

use super::division::InvariantDivisor;
use super::hash::hash_u32;

/// A pseudo-random bijection of `[0, len)`: element `index` of permutation
/// `pattern`, after Kensler 2013 ("Correlated Multi-Jittered Sampling",
/// Pixar Technical Memo 13-01, listing 3), with a keyed hash whose rounds
/// scale with the domain so that short lengths are shuffled well.
///
/// A reversible hash scrambles `index` within the smallest power-of-two
/// domain that holds `len`; results at or above `len` are hashed again
/// ("cycle walking", Black & Rogaway 2002) until they fall inside, and the
/// result is rotated by `pattern % len` (as in Kensler's listing). Each walk
/// step lands inside with probability above 1/2. A step is 4 rounds of about
/// ten integer operations for lengths above 32, 5 rounds from 9 to 32 and
/// 13 from 2 to 8 (short domains draw fewer key bits per round).
///
/// Patterns reach the permutations of short lengths evenly. Over
/// `20,000 * len!` hashed patterns every permutation of lengths 2 to 6
/// appears, and the counts are chi-square-uniform: 10, 103 and 654 on 23,
/// 119 and 719 degrees of freedom at lengths 4, 5 and 6 (Kensler's hash,
/// used before, reached 8 of the 24 permutations of length 4, chi-square
/// 960,012). At lengths 8, 16, 64 and 1000 each index lands uniformly, and
/// 10,000 patterns give 10,000 distinct permutations (at length 8, 8,896 of
/// the 40,320; a uniform family gives 8,858 +- 29; Kensler's gave 1,023).
/// `tests/permute.rs` checks all of this.
///
/// `len` must be at least 1 and `index < len`; an `index` at or above `len`
/// (checked in debug builds) is reduced modulo `len` first, so it still
/// returns a value in `[0, len)`. (Walking from outside the range could
/// loop forever: the hash's cycle through such an index may never enter it.)
///
/// # Panics
///
/// If `len` is 0.
///
/// ```
/// use wellspread::hash::permute;
/// let mut seen = [false; 10];
/// for i in 0..10 {
///     seen[permute(i, 10, 7) as usize] = true;
/// }
/// assert!(seen.iter().all(|&s| s));
/// ```
#[inline]
#[must_use]
pub fn permute(index: u32, len: u32, pattern: u32) -> u32 {
    debug_assert!(len >= 1, "permute needs len >= 1");
    debug_assert!(index < len, "permute index {index} out of range 0..{len}");
    // Only reached with a bad index; panics (division by zero) for len = 0.
    let index = if index < len { index } else { index % len };
    let i = permute_hash(index, len, permute_mask(len), permute_key(pattern));
    // The final rotation by `p` makes permutations of the same `len` differ
    // even where the hash above agrees (Kensler's listing does the same). The
    // sum is taken in u64 so that `len` near 2^32 cannot wrap.
    ((i as u64 + pattern as u64) % len as u64) as u32
}

/// The smallest all-ones mask covering `[0, len)`: the power-of-two domain
/// [`permute`] hashes in.
#[inline]
const fn permute_mask(len: u32) -> u32 {
    let mut w = len.wrapping_sub(1);
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    w
}

/// The key of [`permute_hash`] for `pattern`: its hash, so that nearby
/// patterns get unrelated keys. The xor moves the one pattern whose key is 0
/// (every multiplier 1, every gate shut) away from pattern 0, the one callers
/// use most; the constant is the golden ratio's fraction bits, as in
/// [`hash_combine`].
#[inline(always)]
const fn permute_key(pattern: u32) -> u32 {
    hash_u32(pattern ^ 0x9e37_79b9)
}

/// Rounds of [`permute_hash`] beyond the first four, for a `bits`-bit
/// domain. Four rounds make every output bit depend on every input bit
/// (each `>> half` moves the top half down, each multiply moves low bits
/// up), and pass the pair-frequency measurements from 64 elements up
/// (chi-square of `(p(0), p(1))` over 3 x 10^6 patterns). Short domains
/// draw only a few key bits per round and need more: 13 in all for 2 to 8
/// elements (with 11, the 720 permutations of length 6 were measurably
/// uneven over 3.6 x 10^7 patterns, z = 3.5; 12 was the fewest that
/// passed; one more for margin) and 5 for 9 to 32 elements (with 4, the
/// pair frequencies at lengths 12 and 16 sat at z = 2.8). A 0-bit domain
/// (length 1) has one permutation and needs no more.
#[inline(always)]
const fn permute_extra_rounds(bits: u32) -> u32 {
    match bits {
        1..=3 => 9,
        4..=5 => 1,
        _ => 0,
    }
}

/// One round of [`permute_hash`] with round key `k` (see there).
#[inline(always)]
const fn permute_round(i: u32, k: u32, w: u32, half: u32) -> u32 {
    let i = i.wrapping_add(k);
    let i = i.wrapping_mul(k.rotate_right(11) | 1) & w;
    let i = i ^ (i >> half);
    i ^ ((i >> 1) & k.rotate_right(22))
}

/// [`permute`] before its final rotation: a keyed bijection of the `b`-bit
/// domain under mask `w = 2^b - 1`, cycle-walked into `[0, len)`. `key` is
/// the hashed pattern. Shared by [`permute`] and [`Permutation`] so that the
/// two cannot drift apart.
///
/// Each round is an add-multiply-xorshift step keyed by 32 bits of `key`:
/// the shape of Kensler's hash, but with every step reaching the whole
/// domain whatever its size. Kensler's right shifts are fixed (4, 1, 11, 2,
/// 2, 5 bits), so for a domain of a few bits most steps do nothing and the
/// pattern enters through one multiplier and xors alone: a length of 4 met
/// only 8 of its 24 permutations. Here the shift scales with `b` and the
/// key enters every round in three ways:
///
/// - `i + k`: an addition modulo `2^b` (low bits carry upwards only, so it
///   is a bijection of the low `b` bits); mixed with the xors below it makes
///   the rounds nonlinear over GF(2).
/// - `i * (k' | 1) & w`: an odd, key-chosen multiplier, a bijection modulo
///   `2^b` that moves low bits up.
/// - `i ^= i >> half`, `half = ceil(b / 2)`, and `i ^= (i >> 1) & k''`: the
///   high half down onto the low half (the xorshift of murmur-style
///   finalisers, scaled to `b`), then a key-gated neighbour step, so that
///   even a 2-bit domain gets a key-chosen linear map each round (with
///   `i < 2^b` both are invertible: the top bits pass unchanged).
///
/// `k`, `k'` and `k''` are `key` rotated by 0, 11 and 22 bits (disjoint
/// windows for domains of up to 10 bits), and the key rotates by 7 bits
/// after each round (coprime to 32, so successive rounds read different
/// bits; beyond four rounds a short domain rereads bits in new roles).
/// This is the round structure of an ARX block cipher shrunk to `b` bits,
/// as in format-preserving encryption (Black & Rogaway 2002); the design
/// was chosen by measuring how uniformly it reaches the permutations of
/// short lengths (see [`permute`]).
#[inline(always)]
fn permute_hash(index: u32, len: u32, w: u32, key: u32) -> u32 {
    let bits = u32::BITS - w.leading_zeros();
    let half = bits.div_ceil(2);
    let extra = permute_extra_rounds(bits);
    let mut i = index;
    loop {
        // Round r uses the key rotated by 7 r bits; the first four are
        // written out so that their rotations are constants.
        i = permute_round(i, key, w, half);
        i = permute_round(i, key.rotate_right(7), w, half);
        i = permute_round(i, key.rotate_right(14), w, half);
        i = permute_round(i, key.rotate_right(21), w, half);
        let mut k = key.rotate_right(28);
        for _ in 0..extra {
            i = permute_round(i, k, w, half);
            k = k.rotate_right(7);
        }
        if i < len {
            return i;
        }
    }
}

/// One permutation of `[0, len)`, ready to apply: [`permute`] with its
/// per-pattern work hoisted, for `fill` loops and random access alike.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Permutation {
    len: InvariantDivisor,
    /// The hashing domain's mask, `permute_mask(len)`.
    mask: u32,
    /// `permute_key(pattern)`, the key of [`permute_hash`].
    key: u32,
    /// `pattern % len`: `(i + pattern) % len == (i + rotation) % len`, and
    /// with `i, rotation < len` that is one conditional subtraction.
    rotation: u32,
}

impl InvariantDivisor {
    /// Permutation `pattern` of `[0, len)` for `len = self`:
    /// [`permute`]`(_, len, pattern)` with the per-pattern work (the key and
    /// the rotation `pattern % len`) done here, once.
    #[inline(always)]
    pub(crate) const fn permutation(self, pattern: u32) -> Permutation {
        self.permutation_in::<false>(pattern)
    }

    /// [`permutation`](Self::permutation), specialised at compile time like
    /// [`div_rem_in`](Self::div_rem_in).
    #[inline(always)]
    pub(crate) const fn permutation_in<const POW2: bool>(self, pattern: u32) -> Permutation {
        Permutation {
            len: self,
            mask: permute_mask(self.get()),
            key: permute_key(pattern),
            rotation: self.div_rem_in::<POW2>(pattern).1,
        }
    }
}

impl Permutation {
    /// Element `index` (`< len`) of the permutation.
    #[inline(always)]
    pub(crate) fn apply(&self, index: u32) -> u32 {
        let len = self.len.get();
        debug_assert!(index < len, "permute index {index} out of range 0..{len}");
        // As in `permute`: a bad index is reduced first, or the walk could
        // loop forever.
        let index = if index < len {
            index
        } else {
            self.len.div_rem(index).1
        };
        let i = permute_hash(index, len, self.mask, self.key);
        // i + rotation < 2 len <= 2^33: summed in u64 so that it cannot wrap.
        let sum = i as u64 + self.rotation as u64;
        if sum >= len as u64 {
            (sum - len as u64) as u32
        } else {
            sum as u32
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permute_is_a_bijection_for_many_lengths_and_patterns() {
        for len in (1..=70).chain([127, 128, 129, 1000, 4097]) {
            for pattern in [0, 1, 0xdead_beef, u32::MAX] {
                let mut seen = std::vec![false; len as usize];
                for i in 0..len {
                    let j = permute(i, len, pattern);
                    assert!(j < len);
                    assert!(!seen[j as usize], "len {len} pattern {pattern}: {j} twice");
                    seen[j as usize] = true;
                }
            }
        }
    }

    #[test]
    fn permute_differs_between_patterns() {
        let a: std::vec::Vec<u32> = (0..64).map(|i| permute(i, 64, 1)).collect();
        let b: std::vec::Vec<u32> = (0..64).map(|i| permute(i, 64, 2)).collect();
        assert_ne!(a, b);
    }

    #[test]
    fn permute_handles_lengths_near_u32_max() {
        for i in [0, 1, u32::MAX - 2] {
            assert!(permute(i, u32::MAX - 1, 12345) < u32::MAX - 1);
        }
    }

    #[test]
    #[should_panic]
    fn permute_of_an_empty_range_panics() {
        let _ = permute(0, 0, 1);
    }

    // Release builds only (debug builds reject the index). Before the index
    // was reduced, (3, 3, 0) and many others cycle-walked forever.
    #[cfg(not(debug_assertions))]
    #[test]
    fn permute_out_of_range_index_terminates_in_range() {
        for len in [1, 3, 5, 100, 4097] {
            for pattern in 0..200 {
                for index in (len..3 * len).chain([u32::MAX]) {
                    let j = permute(index, len, pattern);
                    assert_eq!(j, permute(index % len, len, pattern));
                }
            }
        }
    }
}
