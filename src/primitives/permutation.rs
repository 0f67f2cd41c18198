//! Hashed permutations of `[0, len)`: element `index` of permutation
//! `pattern` in O(1), with no table.
//!
//! Two constructions, chosen by length:
//!
//! - **Lengths 1 to 8** ([`SHORT_LEN`]): an exact Fisher-Yates shuffle
//!   (Durstenfeld 1964) of `0..len` packed into the nibbles of a u32, with
//!   its swap indices drawn from one 32-bit key by multiply-high (Lemire
//!   2019). Each step `j = (u * (k + 1)) >> 32`, `u = (u * (k + 1)) mod 2^32`
//!   peels one mixed-radix digit off the fraction `u / 2^32` exactly, so the
//!   `len - 1` indices are the digits of `floor(u * len! / 2^32)`: as `u`
//!   runs over all of u32, every one of the `len!` permutations is reached
//!   `floor(2^32 / len!)` or `ceil(2^32 / len!)` times (at most 1 part in
//!   106,000 apart at `len = 8`). Keys are bijective hashes of the pattern,
//!   so this holds over patterns too.
//! - **Longer lengths**: a keyed bijective hash of the smallest power-of-two
//!   domain that holds `len` (add-multiply-xorshift rounds shaped like an
//!   ARX cipher shrunk to the domain), walked back into `[0, len)` by
//!   re-hashing ("cycle walking", Black & Rogaway 2002), then rotated.
//!   Kensler 2013 (listing 3) has the same shape with fixed shifts, which at
//!   short domains reach few permutations; here the shifts scale with the
//!   domain. Each walk step lands inside with probability above 1/2; a
//!   power-of-two length never walks. Lane-parallel callers re-hash only
//!   the lanes still outside, so a batch stays branch-free per lane.

use super::hash::{hash_u32, salt};

/// The longest permutation built as an exact Fisher-Yates shuffle: eight
/// nibbles fill a u32, and `8! = 40,320` leaves the key's 2^32 values
/// spread over the permutations to within one part in 10^5.
pub(crate) const SHORT_LEN: u32 = 8;

/// A pseudo-random bijection of `[0, len)`: element `index` of permutation
/// `pattern`.
///
/// For `len <= 8` it is an exact uniform shuffle: over the 2^32 patterns
/// every permutation appears `floor(2^32 / len!)` or `ceil(2^32 / len!)`
/// times. Longer lengths use a keyed bijective hash of the next power of two
/// with cycle walking, after Kensler 2013,
/// whose uniformity `tests/primitives.rs` measures (pair frequencies, distinct
/// permutations).
///
/// Cost: one hash of `pattern`, then for `len <= 8` up to seven swap steps
/// of about ten integer operations, and for longer lengths four rounds of
/// about eight (five below 33 elements) times the expected walk length
/// (under 2; exactly 1 for powers of two). Samplers hoist the per-pattern
/// part, so a sample pays only the lookup or the rounds.
///
/// `index < len` is checked in debug builds; in release builds a larger
/// `index` is reduced modulo `len` first, so it still returns a value in
/// `[0, len)`. (Walking from outside the range could loop forever: the
/// hash's cycle through such an index may never enter it.)
///
/// # Panics
///
/// If `len` is 0.
///
/// ```
/// use wellspread::primitives::permute;
/// let mut seen = [false; 10];
/// for i in 0..10 {
///     seen[permute(i, 10, 7) as usize] = true;
/// }
/// assert!(seen.iter().all(|&s| s));
/// ```
#[inline]
#[must_use]
#[track_caller]
pub fn permute(index: u32, len: u32, pattern: u32) -> u32 {
    assert!(len >= 1, "permute needs len >= 1");
    debug_assert!(index < len, "permute index {index} out of range 0..{len}");
    // Only reached with a bad index; panics (division by zero) for len = 0.
    let index = if index < len { index } else { index % len };
    Permutation::new(len, permute_key(pattern)).apply(index)
}

/// A keyed permutation of the sequence indices `0..2^32` that maps every
/// dyadic block `[2^k, 2^(k+1))` onto itself (0 and 1 stay put), so every
/// power-of-two prefix `0..2^m` keeps its set of indices while the order
/// inside each block is shuffled: a progressive sequence read through it
/// keeps every prefix a net, and two streams read through independently
/// keyed shuffles pair their samples as freely as prefixes allow.
///
/// The sets kept are those of every prefix `0..2^m` and every block
/// `[2^m, 2^(m+1))`, nothing finer: an aligned block `[j 2^k, (j + 1) 2^k)`
/// with `j >= 2` goes to a shuffled subset of its dyadic block, and the
/// `n - 2^m` indices of a prefix `2^m < n < 2^(m+1)` past its last power of
/// two to a uniformly random subset of the next block. A sequence whose
/// aligned blocks were nets keeps nets on the kept ranges only
/// ([`DomainSampler`](crate::implement::DomainSampler) says what a progressive
/// renderer should use; `docs/quality.md`, Prefixes between powers of two,
/// measures what the prefixes in between lose).
///
/// Why not an Owen (nested) scramble of the index, as Burley 2020 shuffles
/// one sequence (each index bit flipped by a hash of the bits above it,
/// which maps every aligned block onto an aligned block): simulated on two
/// Owen-scrambled van der Corput streams, it pairs them at 1.13x, 1.22x
/// and 1.24x the mean absolute correlation of two independently shuffled
/// stratified sets at 4, 16 and 64 samples. The top digits are not tied
/// (in 49% of pixels at 4 samples, against 33% for independent sets; none
/// from 16). The nested scramble in the other direction, each bit flipped
/// by the bits below it, is an Owen scramble of the index's radical
/// inverse, so two streams are both Owen scrambles of the same radical
/// inverse and their top digits are tied (equal or opposite) in every
/// pixel: 1.55x, 3.6x and 7.4x. Shuffling inside the dyadic blocks is the
/// most a prefix-keeping pairing can do: with uniform permutations per
/// block the simulation gives 1.14x, 1.10x and 1.05x (20,000 pairs per
/// figure, `lab/examples/prefix_pairing.py`); the crate's draws through
/// this shuffle measure 1.14x to 1.17x, 1.11x to 1.13x and 1.04x to 1.06x
/// (`docs/quality.md`).
///
/// The block's `k` bits below the leading one are moved to the top of the
/// word, where three rounds of a keyed bijection shuffle them (add the
/// round key `r`, multiply by the odd `2 r + 1`, xorshift down by half the
/// width, rounded up) and a key-gated neighbour step `y ^= (y >> 1) & g`
/// ends. The round keys are `key` rotated right by 0, 16 and 24 bits, the
/// gate `key` rotated right by 8. With the bits below the block zero, the
/// add and the multiply take the block's value `t` to
/// `(t + r') (2 r + 1) + c` modulo `2^k`, where `r'` is the top `k` bits of
/// `r` and `c` comes from its bits below (so one key serves the add and,
/// through its low bits, the multiplier); the xorshifts and the gate move
/// bits only downwards, and a mask clears what reaches below the block
/// before each further add. Each step is a bijection of the block for
/// every key and every width up to 31 bits.
///
/// Cost: a leading-zero count and about thirty-five integer operations,
/// three of them multiplies; no table, no loop.
///
/// ```
/// use wellspread::primitives::prefix_shuffle;
/// let mut block: Vec<u32> = (8..16).map(|i| prefix_shuffle(i, 99)).collect();
/// assert_ne!(block, (8..16).collect::<Vec<_>>()); // shuffled
/// block.sort_unstable();
/// assert_eq!(block, (8..16).collect::<Vec<_>>()); // inside its block
/// assert_eq!(prefix_shuffle(0, 99), 0);
/// ```
#[inline(always)]
#[must_use]
pub const fn prefix_shuffle(index: u32, key: u32) -> u32 {
    // The `k` bits below the leading one (none for indices 0 and 1), moved
    // to the top of the word: in u64, a shift by 32 leaves nothing.
    let below = (index | 1).leading_zeros();
    let shift = below + 1;
    let half = (32 - below) >> 1;
    let bits = ((index as u64) << shift) as u32;
    let domain = (u64::MAX << shift) as u32;
    let mut r = key;
    let mut y = prefix_round(bits, r, half);
    r = r.rotate_right(16);
    y = prefix_round(y & domain, r, half);
    r = r.rotate_right(8);
    y = prefix_round(y & domain, r, half);
    r = r.rotate_right(16);
    y ^= (y >> 1) & r;
    // The bits below the domain shift out; the leading one stays.
    index ^ (((bits ^ y) as u64 >> shift) as u32)
}

/// One round of [`prefix_shuffle`]'s bijection of the top bits of `y`
/// (those below them zero on entry), keyed by `r`: add `r`, multiply by
/// the odd `2 r + 1`, then xorshift the top bits down by `half`.
#[inline(always)]
const fn prefix_round(y: u32, r: u32, half: u32) -> u32 {
    let odd = r.wrapping_mul(2).wrapping_add(1);
    let y = y.wrapping_add(r).wrapping_mul(odd);
    y ^ (y >> half)
}

/// The key of the permutation for a bare `pattern`: its hash, so that nearby
/// patterns get unrelated keys. The xor moves the one pattern whose key is 0
/// away from pattern 0, the one callers use most; the constant is the golden
/// ratio's fraction bits, as in [`hash_combine`](super::hash_combine).
#[inline(always)]
const fn permute_key(pattern: u32) -> u32 {
    hash_u32(pattern ^ salt::GOLDEN_32)
}

/// The key of one of several permutations drawn from one `pattern_hash`,
/// told apart by `salt`: `pattern_hash` xored with `salt` and rotated by
/// `salt`'s top five bits, then one multiply and a fold of the high half
/// onto the low half (5 operations instead of a 7-operation hash per
/// permutation).
///
/// The rotation is what keeps the keys of one pattern apart: the
/// Fisher-Yates shuffles read a key from its top bits down, and the
/// product's top bits come mostly from the top bits of what is multiplied,
/// so each key's top bits come from a different part of `pattern_hash`.
/// The multiplier is [`hash_u32`]'s first. A bijection of `pattern_hash`
/// for each salt, so each permutation alone keeps the exact uniformity of
/// [`permute`]; `tests/primitives.rs` measures the joint uniformity.
#[inline(always)]
pub(crate) const fn derived_key(pattern_hash: u32, salt: u32) -> u32 {
    let k = (pattern_hash ^ salt)
        .rotate_left(salt >> 27)
        .wrapping_mul(0x7feb_352d);
    k ^ (k >> 15)
}

/// The smallest all-ones mask covering `[0, len)`: the power-of-two domain
/// the long permutations hash in.
#[inline(always)]
const fn permute_mask(len: u32) -> u32 {
    if len <= 1 {
        0
    } else {
        u32::MAX >> (len - 1).leading_zeros()
    }
}

/// Rounds of [`round_lanes`] for a domain of `bits` bits (`bits >= 4`).
/// Four rounds make every output bit depend on every input bit (each
/// `>> half` moves the top half down, each multiply moves low bits up), and
/// pass the pair-frequency measurements from 64 elements up (chi-square of
/// `(p(0), p(1))` over 3 x 10^6 patterns); 9 to 32 elements draw fewer key
/// bits per round and need a fifth (with four, the pair frequencies at
/// lengths 12 and 16 sat at z = 2.8).
#[inline(always)]
const fn permute_rounds(bits: u32) -> u32 {
    if bits <= 5 { 5 } else { 4 }
}

/// One round of the keyed bijection of the `b`-bit domain under mask
/// `w = 2^b - 1` that long permutations walk in, on every lane, lane `l`
/// with round key `k[l]`. The permutation's key rotated by `7 r` bits is
/// round `r`'s key.
///
/// Each round is an add-multiply-xorshift step keyed by 32 bits of `key`,
/// with every step reaching the whole domain:
///
/// - `i + k`: an addition modulo `2^b` (low bits carry upwards only, so it
///   is a bijection of the low `b` bits); mixed with the xors below it makes
///   the rounds nonlinear over GF(2).
/// - `i * (k' | 1) & w`: an odd, key-chosen multiplier, a bijection modulo
///   `2^b` that moves low bits up.
/// - `i ^= i >> half`, `half = ceil(b / 2)`, and `i ^= (i >> 1) & k''`: the
///   high half down onto the low half (the xorshift of murmur-style
///   finalisers, scaled to `b`), then a key-gated neighbour step (with
///   `i < 2^b` both are invertible: the top bits pass unchanged).
///
/// `k`, `k'` and `k''` are the round key rotated by 0, 11 and 22 bits, and
/// round `r` uses `key` rotated by `7 r` bits (coprime to 32, so successive
/// rounds read different bits).
#[inline(always)]
fn round_lanes<const N: usize>(i: &mut [u32; N], k: &RoundKeys<N>, w: u32, half: u32) {
    // One operation at a time across the lanes: the shape the compiler's
    // SIMD vectoriser handles (a long chain per lane defeats it).
    for (i, add) in i.iter_mut().zip(&k.add) {
        *i = i.wrapping_add(*add);
    }
    for (i, multiplier) in i.iter_mut().zip(&k.multiplier) {
        *i = i.wrapping_mul(*multiplier) & w;
    }
    for i in i.iter_mut() {
        *i ^= *i >> half;
    }
    for (i, gate) in i.iter_mut().zip(&k.gate) {
        *i ^= (*i >> 1) & gate;
    }
}

/// One round's `k`, `k' | 1` and `k''` (see [`round_lanes`]) for each lane.
struct RoundKeys<const N: usize> {
    add: [u32; N],
    multiplier: [u32; N],
    gate: [u32; N],
}

impl<const N: usize> RoundKeys<N> {
    /// The round keys of round key `k`, the same in every lane.
    #[inline(always)]
    const fn splat(k: u32) -> Self {
        Self {
            add: [k; N],
            multiplier: [k.rotate_right(11) | 1; N],
            gate: [k.rotate_right(22); N],
        }
    }

    /// The round keys of round key `k[lane]` in each lane.
    #[inline(always)]
    fn each(k: &[u32; N]) -> Self {
        let mut keys = Self::splat(0);
        for (l, &k) in k.iter().enumerate() {
            keys.add[l] = k;
            keys.multiplier[l] = k.rotate_right(11) | 1;
            keys.gate[l] = k.rotate_right(22);
        }
        keys
    }
}

/// The identity permutation of `0..8`, one element per nibble.
const IDENTITY_NIBBLES: u32 = 0x7654_3210;

/// The Fisher-Yates shuffle of `0..len` (`len <= 8`) drawn from `key`, one
/// element per nibble (element `i` in bits `4 i .. 4 i + 4`). Swap `k`
/// (from `len - 1` down to 1) exchanges nibbles `k` and `j`, with `j` the
/// next mixed-radix digit of `key / 2^32` in base `k + 1` (see the module
/// docs for why this is exactly uniform).
#[inline(always)]
const fn shuffled_nibbles(len: u32, key: u32) -> u32 {
    let mut packed = IDENTITY_NIBBLES;
    let mut u = key;
    let mut k = len;
    while k > 1 {
        k -= 1;
        let product = u as u64 * (k as u64 + 1);
        let j = (product >> 32) as u32;
        u = product as u32;
        // Swap nibbles k and j (j <= k) with one xor of their difference.
        let diff = ((packed >> (4 * k)) ^ (packed >> (4 * j))) & 0xf;
        packed ^= (diff << (4 * k)) | (diff << (4 * j));
    }
    packed
}

/// One permutation of `[0, len)`, ready to apply: the per-pattern work
/// (the shuffle of a short length; the rotation of a long one) done once,
/// for `fill` loops and random access alike.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub(crate) struct Permutation {
    len: u32,
    /// `permute_mask(len)`, the long hash's domain; 0 for short lengths.
    mask: u32,
    /// The key: the long hash's round keys.
    key: u32,
    /// Short lengths: the shuffled nibbles. Long lengths: the final
    /// rotation, in `[0, len)`.
    packed_or_rotation: u32,
}

impl Permutation {
    /// The permutation of `[0, len)` (`len >= 1`) with key `key`.
    #[inline(always)]
    pub(crate) const fn new(len: u32, key: u32) -> Self {
        debug_assert!(len >= 1);
        if len <= SHORT_LEN {
            Self {
                len,
                mask: 0,
                key,
                packed_or_rotation: shuffled_nibbles(len, key),
            }
        } else {
            // The rotation reads the key's bits afresh (rotated by 16) and
            // maps them onto [0, len) by multiply-high: no division.
            let rotation = ((key.rotate_right(16) as u64 * len as u64) >> 32) as u32;
            Self {
                len,
                mask: permute_mask(len),
                key,
                packed_or_rotation: rotation,
            }
        }
    }

    /// Element `index` (`< len`, checked in debug builds) of the
    /// permutation.
    #[inline(always)]
    pub(crate) fn apply(&self, index: u32) -> u32 {
        self.apply_lanes([index])[0]
    }

    /// Elements `index[lane]` (each `< len`) of the permutation, one lane
    /// each: branch-free per lane, so a batch of lanes runs in SIMD
    /// registers. The walk re-hashes only the lanes still outside `[0,
    /// len)`, so every lane gets exactly what [`apply`](Self::apply) gives.
    #[inline(always)]
    pub(crate) fn apply_lanes<const N: usize>(&self, index: [u32; N]) -> [u32; N] {
        apply_with(self.len, self.mask, self, index)
    }

    /// Element `index[lane]` of permutation `permutations[lane]`, all of one
    /// length, one lane each: [`apply`](Self::apply) lane by lane, for
    /// samplers whose every column has its own permutation.
    #[inline(always)]
    pub(crate) fn apply_each<const N: usize>(
        permutations: &[Permutation; N],
        index: [u32; N],
    ) -> [u32; N] {
        let Some(first) = permutations.first() else {
            return index;
        };
        debug_assert!(permutations.iter().all(|p| p.len == first.len));
        apply_with(first.len, first.mask, permutations, index)
    }
}

/// The permutation each lane uses: one for all lanes, or one per lane.
/// (A trait rather than a closure: trait methods can be forced inline, so
/// the batch stays in the function compiled for the detected SIMD set.)
trait LanePermutations<const N: usize> {
    fn lane(&self, lane: usize) -> &Permutation;

    /// The rounds of [`round_lanes`] on every lane under its permutation's
    /// key.
    fn hash<const ROUNDS: u32>(&self, i: &mut [u32; N], w: u32, half: u32);
}

impl<const N: usize> LanePermutations<N> for Permutation {
    #[inline(always)]
    fn lane(&self, _: usize) -> &Permutation {
        self
    }

    #[inline(always)]
    fn hash<const ROUNDS: u32>(&self, i: &mut [u32; N], w: u32, half: u32) {
        // One key for all lanes: its round keys are scalars, broadcast.
        let round = |i: &mut [u32; N], r: u32| {
            let k = self.key.rotate_right(7 * r);
            let keys = RoundKeys::<N>::splat(k);
            round_lanes(i, &keys, w, half);
        };
        round(i, 0);
        round(i, 1);
        round(i, 2);
        round(i, 3);
        if ROUNDS > 4 {
            round(i, 4);
        }
    }
}

impl<const N: usize> LanePermutations<N> for [Permutation; N] {
    #[inline(always)]
    fn lane(&self, lane: usize) -> &Permutation {
        &self[lane]
    }

    #[inline(always)]
    fn hash<const ROUNDS: u32>(&self, i: &mut [u32; N], w: u32, half: u32) {
        let mut key = [0; N];
        for (l, key) in key.iter_mut().enumerate() {
            *key = self[l].key;
        }
        for _ in 0..ROUNDS {
            round_lanes(i, &RoundKeys::each(&key), w, half);
            for key in &mut key {
                *key = key.rotate_right(7);
            }
        }
    }
}

/// The long permutations' hash of every lane, walked into `[0, len)`.
#[inline(always)]
fn hash_and_walk<const ROUNDS: u32, const N: usize>(
    len: u32,
    mask: u32,
    permutations: &impl LanePermutations<N>,
    i: &mut [u32; N],
) {
    let half = (u32::BITS - mask.leading_zeros()).div_ceil(2);
    permutations.hash::<ROUNDS>(i, mask, half);
    if mask != len - 1 {
        while i.iter().any(|&i| i >= len) {
            let mut next = *i;
            permutations.hash::<ROUNDS>(&mut next, mask, half);
            for (i, next) in i.iter_mut().zip(next) {
                *i = if *i >= len { next } else { *i };
            }
        }
    }
}

/// [`Permutation::apply_lanes`] with lane `l` under permutation
/// `permutations.lane(l)`, all of length `len` and mask `mask`.
#[inline(always)]
fn apply_with<const N: usize>(
    len: u32,
    mask: u32,
    permutations: &impl LanePermutations<N>,
    index: [u32; N],
) -> [u32; N] {
    debug_assert!(
        index.iter().all(|&i| i < len),
        "permute index out of range 0..{len}"
    );
    let mut i = index;
    if len <= SHORT_LEN {
        for (l, i) in i.iter_mut().enumerate() {
            // (`& 7` keeps the shift in range for a bad index in release builds.)
            *i = (permutations.lane(l).packed_or_rotation >> ((*i & 7) * 4)) & 0xf;
        }
        return i;
    }
    // The round count is the same for every lane: chosen outside the lane
    // loops, which must stay free of branches to run as SIMD.
    let bits = u32::BITS - mask.leading_zeros();
    if permute_rounds(bits) > 4 {
        hash_and_walk::<5, N>(len, mask, permutations, &mut i);
    } else {
        hash_and_walk::<4, N>(len, mask, permutations, &mut i);
    }
    // Rotate by `rotation < len` without overflowing u32.
    for (l, i) in i.iter_mut().enumerate() {
        let rotation = permutations.lane(l).packed_or_rotation;
        let wrap = len - rotation;
        *i = if *i >= wrap { *i - wrap } else { *i + rotation };
    }
    i
}

#[cfg(test)]
mod tests {
    use super::prefix_shuffle;

    #[test]
    fn prefix_shuffle_permutes_each_dyadic_block() {
        for key in [0, 1, 0x1234_5678, u32::MAX] {
            assert_eq!(prefix_shuffle(0, key), 0);
            assert_eq!(prefix_shuffle(1, key), 1);
            for k in 1..=12 {
                let mut seen = std::vec![false; 1 << k];
                for i in 1u32 << k..2 << k {
                    let s = prefix_shuffle(i, key);
                    assert_eq!(s >> k, 1, "{i} left its block");
                    assert!(!seen[(s - (1 << k)) as usize], "key {key:#x}: {s} twice");
                    seen[(s - (1 << k)) as usize] = true;
                }
            }
            // The last block's ends stay in it.
            assert!(prefix_shuffle(u32::MAX, key) >= 1 << 31);
            assert!(prefix_shuffle(1 << 31, key) >= 1 << 31);
        }
    }

    #[test]
    fn prefix_shuffle_reaches_every_order_of_small_blocks() {
        // Blocks of 2 and 4 (indices 2..4 and 4..8): over many keys every
        // order appears, about equally often.
        let mut twos = [0u32; 2];
        let mut fours = std::collections::HashMap::new();
        let keys = 24_000u32;
        for key in 0..keys {
            let key = crate::primitives::hash_u32(key);
            twos[(prefix_shuffle(2, key) - 2) as usize] += 1;
            let order: [u32; 4] = core::array::from_fn(|i| prefix_shuffle(4 + i as u32, key));
            *fours.entry(order).or_insert(0u32) += 1;
        }
        assert!(
            twos.iter().all(|&c| c.abs_diff(keys / 2) < keys / 20),
            "{twos:?}"
        );
        assert_eq!(fours.len(), 24);
        assert!(
            fours
                .values()
                .all(|&c| c.abs_diff(keys / 24) < keys / 24 / 2),
            "{fours:?}"
        );
    }

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
    fn short_shuffles_reach_every_permutation_exactly_evenly() {
        // Key `u` gives the permutation whose Fisher-Yates digits are those
        // of `r = floor(u * len! / 2^32)`: each `r` owns the block of keys
        // `ceil(r 2^32 / len!) ..= ceil((r + 1) 2^32 / len!) - 1`. Both ends
        // of every block give the same permutation, distinct blocks give
        // distinct permutations, and blocks hold floor or ceil of
        // `2^32 / len!` keys: so every permutation has that many keys.
        for len in 1..=SHORT_LEN {
            let total: u64 = (1..=len as u64).product();
            let first_key = |r: u64| (r << 32).div_ceil(total);
            let mut seen = std::collections::BTreeSet::new();
            for r in 0..total {
                let (first, last) = (first_key(r), first_key(r + 1) - 1);
                let packed = shuffled_nibbles(len, first as u32);
                assert_eq!(
                    shuffled_nibbles(len, last as u32),
                    packed,
                    "len {len} r {r}"
                );
                assert!(
                    seen.insert(packed),
                    "len {len}: rank {r} repeats {packed:#x}"
                );
                let keys = last - first + 1;
                assert!(keys == (1 << 32) / total || keys == (1 << 32) / total + 1);
                // And it is a permutation of 0..len.
                let mut elements: std::vec::Vec<u32> =
                    (0..len).map(|i| (packed >> (4 * i)) & 0xf).collect();
                elements.sort_unstable();
                assert!(
                    elements.iter().copied().eq(0..len),
                    "len {len}: {packed:#x}"
                );
            }
            assert_eq!(seen.len() as u64, total);
        }
    }

    #[test]
    fn lanes_walk_exactly_like_single_lanes() {
        // Lengths just above a power of two make most lanes walk.
        for len in [9, 17, 33, 100, 257, 4097, 65_537] {
            for key in [0, 1, 0x1234_5678, u32::MAX] {
                let p = Permutation::new(len, key);
                let index: [u32; 16] = core::array::from_fn(|l| (l as u32 * 7919) % len);
                let lanes = p.apply_lanes(index);
                for (l, &i) in index.iter().enumerate() {
                    assert_eq!(lanes[l], p.apply(i), "len {len} key {key:#x} index {i}");
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
    #[should_panic(expected = "permute needs len >= 1")]
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
