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
    hash_u32(seed ^ hash_u32(value).wrapping_add(0x9e37_79b9))
}

/// The pattern for one pixel, frame (or seed) and dimension pair.
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
pub(crate) mod salt {
    pub(crate) const ORDER: u32 = 0x51633e2d;
    pub(crate) const SHUFFLE_X: u32 = 0xa511e9b3;
    pub(crate) const SHUFFLE_Y: u32 = 0x63d83595;
    pub(crate) const JITTER_X: u32 = 0xa399d265;
    pub(crate) const JITTER_Y: u32 = 0x711ad6a5;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives::permute;

    #[test]
    fn hashes_are_pinned() {
        // Golden values (the hashes cross-checked against an independent
        // Python transcription): a change here changes every sample
        // wellspread makes.
        assert_eq!(hash_u32(0), 0);
        assert_eq!(hash_u32(1), 0x6889_90c0);
        assert_eq!(rand_u32(0, 0), 0xdf6e_5fc8);
        // A long (hashed) and a short (Fisher-Yates) permutation.
        assert_eq!(permute(3, 10, 42), 3);
        assert_eq!(permute(2, 6, 0xdead_beef), 1);
    }
}
