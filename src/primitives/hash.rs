//! Integer hashes and pattern seeds: where every sampler's randomness comes
//! from.

/// A 32-bit integer hash with good avalanche: `lowbias32` from Chris Wellons'
/// hash-prospector (2018), a search over xorshift-multiply hashes.
///
/// It is a bijection on `u32`, so distinct inputs never collide.
#[inline(always)]
#[must_use]
pub const fn hash_u32(mut x: u32) -> u32 {
    // Constants and shifts are the search's best two-round result (bias ~0.17).
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

/// Mixes `value` into `seed`: the hash of a pair, used to derive independent
/// patterns from one seed.
#[inline(always)]
#[must_use]
pub const fn hash_combine(seed: u32, value: u32) -> u32 {
    // The golden-ratio constant 0x9e3779b9 keeps (seed, 0) from hashing like
    // a bare seed; hashing `value` first spreads small consecutive values.
    hash_u32(seed ^ hash_u32(value).wrapping_add(salt::GOLDEN_32))
}

/// The 64-bit finaliser of SplitMix64 (Steele, Lea & Flood 2014, "Fast
/// splittable pseudorandom number generators", OOPSLA): two multiplies and
/// three xor-shifts, a bijection of `u64` with full avalanche. What a
/// [`Domain`](crate::Domain) spends per draw to turn its key and draw
/// counter into the draw's 64-bit stream.
///
/// ```
/// use wellspread::primitives::mix64;
/// assert_eq!(mix64(0), 0);
/// assert_ne!(mix64(1) >> 32, mix64(2) >> 32);
/// ```
#[inline(always)]
#[must_use]
pub const fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The key of child `child` of a domain keyed `key`, for the kind of child
/// `salt` names (a branch, a split, a pass): one [`mix64`] of the salted
/// parent key, plus the child number times an odd Weyl increment, so
/// children of one parent differ and a child's key is never one of its
/// parent's draw streams.
#[inline(always)]
#[must_use]
pub(crate) const fn child_key(key: u64, salt: u64, child: u32) -> u64 {
    mix64(key ^ salt).wrapping_add((child as u64).wrapping_mul(salt::BRANCH_WEYL))
}

/// The fixed-size rule for sample `index` of a set of `n` keyed `key`:
/// indices `p n .. (p + 1) n` are pass `p`, a complete set keyed by the
/// pass's child key. Returns `(index in the set, key of the set)`.
#[inline(always)]
#[must_use]
pub(crate) fn locate_pass(index: u32, n: u32, key: u64) -> (u32, u64) {
    if index < n || n == 0 {
        (index, key)
    } else {
        (index % n, child_key(key, salt::PASS, index / n))
    }
}

/// The pattern for one pixel, frame and dimension pair.
///
/// Renderers call this once per pixel and dimension pair (pixel position,
/// lens, time, ...) and pass the result as `pattern` to
/// [`Sampler2D::sample`](crate::Sampler2D::sample). Different dimension pairs
/// get unrelated patterns ("padding"), which is how wellspread decorrelates
/// dimensions: never by reusing one pattern.
///
/// ```
/// use wellspread::primitives::pattern_seed;
/// let pixel = pattern_seed(10, 20, 0, 0);
/// let lens = pattern_seed(10, 20, 0, 1);
/// assert_ne!(pixel, lens);
/// assert_eq!(pixel, pattern_seed(10, 20, 0, 0));
/// ```
#[inline(always)]
#[must_use]
pub const fn pattern_seed(x: u32, y: u32, frame: u32, dimension: u32) -> u32 {
    hash_combine(hash_combine(hash_combine(hash_u32(x), y), frame), dimension)
}

/// 32 random bits for `(index, pattern)`: Kensler 2013's `randfloat` hash
/// (listing 2) without its final conversion to float.
#[inline(always)]
#[must_use]
pub const fn rand_u32(index: u32, pattern: u32) -> u32 {
    let mut i = index ^ pattern;
    i ^= i >> 17;
    i ^= i >> 10;
    i = i.wrapping_mul(0xb365_34e5);
    i ^= i >> 12;
    i ^= i >> 21;
    i = i.wrapping_mul(0x93fc_4795);
    // Kensler's constant: breaks the fixed point at i = 0.
    i ^= 0xdf6e_307f;
    i ^= i >> 17;
    i = i.wrapping_mul(1 | pattern >> 18);
    i
}

/// Salts that split one `pattern_hash = hash_u32(pattern)` into independent
/// inputs, one per random choice a sampler makes (sample order, x shuffle,
/// y shuffle, x jitter, y jitter), at one hash per pattern instead of one
/// per choice. Permutation keys are `derived_key(pattern_hash, SALT)` (a
/// rotation and a multiply on top of the xor: keys that differ by a bare
/// xor correlate the Fisher-Yates shuffles); the jitter and the sequences'
/// Owen seeds feed `pattern_hash ^ SALT` to a further hash. The constants
/// are Kensler's (2013) pattern multipliers, odd with about half their bits
/// set, so that pattern 0 still yields five unrelated inputs.
///
/// The salts of the pixel layer follow: each keeps two derivations from one
/// key apart, and `tests` below checks that the ones used together differ.
pub(crate) mod salt {
    pub(crate) const ORDER: u32 = 0x51633e2d;
    pub(crate) const SHUFFLE_X: u32 = 0xa511e9b3;
    pub(crate) const SHUFFLE_Y: u32 = 0x63d83595;
    pub(crate) const JITTER_X: u32 = 0xa399d265;
    pub(crate) const JITTER_Y: u32 = 0x711ad6a5;

    /// Weyl increment between the streams of a domain's successive draws:
    /// the fraction bits of the golden ratio, odd, so `key + k W` visits
    /// every u64 before repeating.
    pub(crate) const DRAW_WEYL: u64 = 0x9e37_79b9_7f4a_7c15;
    /// Weyl increment between the keys of a domain's children
    /// ([`Domain::branch`](crate::Domain::branch)): the fraction bits of
    /// sqrt(2), odd.
    pub(crate) const BRANCH_WEYL: u64 = 0x6a09_e667_f3bc_c909;
    /// Xored into the parent key before a branch's mix (fraction bits of
    /// sqrt(3)), so a child's key is never the parent's draw stream.
    pub(crate) const BRANCH: u64 = 0xbb67_ae85_84ca_a73b;
    /// Xored into the parent key before a split's mix (fraction bits of
    /// sqrt(5)), so `split(k, ..)` and `branch(k)` are unrelated.
    pub(crate) const SPLIT: u64 = 0x3c6e_f372_fe94_f82b;
    /// Xored into the parent key for the set of pass `p` of a fixed-size
    /// sampler (indices `p n .. (p + 1) n`; fraction bits of sqrt(29)).
    pub(crate) const PASS: u64 = 0x2e1b_2138_5c26_c926;
    /// Xored into a stream for the second pattern of a padded 3D or 4D
    /// draw (fraction bits of sqrt(7)).
    pub(crate) const SECOND: u64 = 0xa54f_f53a_5f1d_36f1;
    /// The multiplier of the frame in a [`Padded`](crate::Padded) root key
    /// (fraction bits of sqrt(11), odd, so distinct frames differ).
    pub(crate) const PADDED_FRAME: u64 = 0x510e_527f_ade6_82d1;
    /// The frame's key in a [`ZSobol`](crate::ZSobol) domain (fraction
    /// bits of sqrt(13)).
    pub(crate) const ZSOBOL_FRAME: u64 = 0x9b05_688c_2b3e_6c1f;
    /// The frame's key in a [`BlueNoise`](crate::BlueNoise) domain
    /// (fraction bits of sqrt(17)).
    pub(crate) const BLUE_NOISE_FRAME: u64 = 0x1f83_d9ab_fb41_bd6b;
    /// The second 64 bits a [`BlueNoise`](crate::BlueNoise) draw needs
    /// (its pixel translation and code shuffle), mixed from its stream
    /// xored with this (fraction bits of sqrt(19)).
    pub(crate) const BLUE_NOISE_PIXEL: u64 = 0x5be0_cd19_137e_2179;
    /// The jitter inside a stratum of a 1D draw of a fixed-size sampler.
    pub(crate) const JITTER_1D: u32 = 0x68e3_1da4;
    /// The multiplier that folds a sample index into a
    /// [`Random`](crate::Random) domain's key (the fraction bits of
    /// sqrt(23), odd).
    pub(crate) const RANDOM_INDEX: u64 = 0xcbbb_9d5d_c105_9ed9;
    /// Seeds of the 4D Sobol' draw's last two coordinates, xored into
    /// rotations of its stream.
    pub(crate) const SOBOL_Z: u32 = 0x6f4f_2a35;
    pub(crate) const SOBOL_W: u32 = 0x8f1b_bcdd;
    /// The index shuffle's key, xored into a rotation of a stream.
    pub(crate) const DRAW_ORDER: u32 = 0x2c1b_3c6d;
    /// Xored into a domain's key for the pattern of page `p` of a
    /// [`PaddedNd`](crate::PaddedNd) (its dimensions `p D .. (p + 1) D`;
    /// fraction bits of sqrt(31)).
    pub(crate) const PAGE: u64 = 0x9159_015a_3070_dd17;
    /// Xored into a pattern before the mix that makes a
    /// [`Sobol4D`](crate::Sobol4D) pattern's stream (fraction bits of
    /// sqrt(37)).
    pub(crate) const SOBOL_SET: u64 = 0x152f_ecd8_f70e_5939;
    /// Xored into a pattern before the mix that makes a
    /// [`Faure4D`](crate::Faure4D) pattern's stream (fraction bits of
    /// sqrt(41)).
    pub(crate) const FAURE_SET: u64 = 0x6733_2667_ffc0_0b31;

    /// The golden ratio's fraction bits in 32 bits (odd, about half its
    /// bits set): the step between Halton's per-level seeds, the
    /// multiplier that spreads multi-jitter's line numbers over all 32
    /// bits, and the offset of [`hash_combine`](super::hash_combine) and of
    /// a bare pattern's permutation key.
    pub(crate) const GOLDEN_32: u32 = 0x9e37_79b9;

    /// The orthogonal array's sub-stratum permutation per level
    /// (multi-jittered offsets).
    pub(crate) const ND_SUB_STRATA: u32 = 0x7a2f_c639;
    /// Xored into an orthogonal array's pattern before the mix that
    /// makes its hash, row order and choice of columns (fraction bits of
    /// sqrt(43)).
    pub(crate) const ND_PATTERN: u64 = 0x8eb4_4a87_6858_1511;

    /// Blue multi-jitter's per-pattern placement of its lattice: the
    /// offsets and shifts of the cells, and the mirror and transpose flags
    /// (the top bits of the flags' key).
    pub(crate) const LATTICE_OFFSET_X: u32 = 0x2f6b_4a93;
    pub(crate) const LATTICE_OFFSET_Y: u32 = 0x4c1d_e357;
    pub(crate) const LATTICE_SHIFT_X: u32 = 0x6a3c_95e1;
    pub(crate) const LATTICE_SHIFT_Y: u32 = 0x8e57_1ab3;
    pub(crate) const LATTICE_FLAGS: u32 = 0xb4d2_6c8f;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives::permute;

    #[test]
    fn salts_used_together_differ() {
        let u64s = [
            salt::DRAW_WEYL,
            salt::BRANCH_WEYL,
            salt::BRANCH,
            salt::SPLIT,
            salt::SECOND,
            salt::PASS,
            salt::PADDED_FRAME,
            salt::ZSOBOL_FRAME,
            salt::BLUE_NOISE_FRAME,
            salt::BLUE_NOISE_PIXEL,
            salt::RANDOM_INDEX,
            salt::PAGE,
            salt::SOBOL_SET,
            salt::FAURE_SET,
            salt::ND_PATTERN,
        ];
        let u32s = [
            salt::ORDER,
            salt::SHUFFLE_X,
            salt::SHUFFLE_Y,
            salt::JITTER_X,
            salt::JITTER_Y,
            salt::JITTER_1D,
            salt::SOBOL_Z,
            salt::SOBOL_W,
            salt::DRAW_ORDER,
            salt::GOLDEN_32,
            salt::ND_SUB_STRATA,
            salt::LATTICE_OFFSET_X,
            salt::LATTICE_OFFSET_Y,
            salt::LATTICE_SHIFT_X,
            salt::LATTICE_SHIFT_Y,
            salt::LATTICE_FLAGS,
        ];
        for (i, a) in u64s.iter().enumerate() {
            assert!(u64s[i + 1..].iter().all(|b| a != b), "{a:#x} twice");
            // Halves too: streams are split into 32-bit seeds.
            assert_ne!(*a as u32, (*a >> 32) as u32);
        }
        for (i, a) in u32s.iter().enumerate() {
            assert!(u32s[i + 1..].iter().all(|b| a != b), "{a:#x} twice");
        }
        // The Weyl increments and multipliers are odd, so their multiples
        // are distinct (checked when the test compiles).
        const {
            assert!(
                salt::DRAW_WEYL & salt::BRANCH_WEYL & salt::RANDOM_INDEX & salt::PADDED_FRAME & 1
                    == 1
            )
        };
    }

    /// `derived_key` rotates by a salt's top five bits: salts that key
    /// permutations of one hash must differ there, or two of their keys
    /// would differ by a bare xor.
    #[test]
    fn derived_key_salts_differ_in_their_top_five_bits() {
        let groups: [&[u32]; 2] = [
            &[salt::ORDER, salt::SHUFFLE_X, salt::SHUFFLE_Y],
            &[
                salt::LATTICE_OFFSET_X,
                salt::LATTICE_OFFSET_Y,
                salt::LATTICE_SHIFT_X,
                salt::LATTICE_SHIFT_Y,
                salt::LATTICE_FLAGS,
            ],
        ];
        for group in groups {
            for (i, a) in group.iter().enumerate() {
                for b in &group[i + 1..] {
                    assert_ne!(a >> 27, b >> 27, "{a:#x} and {b:#x}");
                }
            }
        }
    }

    #[test]
    fn hashes_are_pinned() {
        // Golden values (the hashes cross-checked against an independent
        // Python transcription): a change here changes every sample
        // wellspread makes.
        assert_eq!(hash_u32(0), 0);
        assert_eq!(hash_u32(1), 0x6889_90c0);
        assert_eq!(rand_u32(0, 0), 0xdf6e_5fc8);
        assert_eq!(mix64(1), 0x5692_161d_100b_05e5);
        // A long (hashed) and a short (Fisher-Yates) permutation.
        assert_eq!(permute(3, 10, 42), 3);
        assert_eq!(permute(2, 6, 0xdead_beef), 1);
    }
}
