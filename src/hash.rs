//! Hash and permutation primitives: the only source of randomness in wellspread.
//!
//! Every sampler draws its randomness from these functions, so a sample is a
//! pure function of `(index, pattern)`: the same on every thread, machine and
//! run, with no tables and no state. Each function names where it comes from,
//! and each magic constant says why it is there.
//!
//! Floats are made in one place, [`stratum_to_unit_f32`] (and its special
//! case [`u32_to_unit_f32`]), which works in 24-bit fixed point and truncates,
//! so a coordinate is never `1.0` and never lands in the neighbouring stratum.
//! Samplers call its division-free twin (a crate-private `Length` that
//! stores the reciprocal of the stratum count), which
//! `tests/bench_equivalence.rs` checks bit for bit against a frozen copy.

/// Number of fraction bits in every coordinate wellspread produces.
///
/// Coordinates are multiples of `2^-24`: the spacing of f32 just below 1.0,
/// so every value in `[0, 1)` on that grid is exactly representable.
pub const UNIT_BITS: u32 = 24;

/// The most strata one axis can be cut into while every stratum still holds a
/// representable coordinate: `2^24`, since coordinates are multiples of `2^-24`.
pub const MAX_STRATA: u32 = 1 << UNIT_BITS;

/// The largest f32 below 1.0 (`0x1.fffffep-1`), the top of every range.
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// A 32-bit integer hash with good avalanche: `lowbias32` from Chris Wellons'
/// hash-prospector (2018), a search over xorshift-multiply hashes.
///
/// It is a bijection on `u32`, so distinct inputs never collide.
#[inline]
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
#[inline]
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
/// use wellspread::hash::pattern_seed;
/// let pixel = pattern_seed(10, 20, 0, 0);
/// let lens = pattern_seed(10, 20, 0, 1);
/// assert_ne!(pixel, lens);
/// assert_eq!(pixel, pattern_seed(10, 20, 0, 0));
/// ```
#[inline]
#[must_use]
pub const fn pattern_seed(x: u32, y: u32, frame: u32, dimension: u32) -> u32 {
    hash_combine(hash_combine(hash_combine(hash_u32(x), y), frame), dimension)
}

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

/// Exact division by a fixed `d` in `[1, 2^32)` as a shift (powers of two)
/// or one 64 x 64 -> 128-bit multiply and a shift, for numerators below 2^49.
///
/// Samplers divide by the same few numbers (`n`, columns, rows) for every
/// sample; a hardware 64-bit divide costs tens of cycles, the multiply a few.
/// For `d` not a power of two, with `l = ceil(log2 d)`, `s = max(64, 49 + l)`
/// and `m = ceil(2^s / d)`, `floor(x / d) = floor(x * m / 2^s)` for all
/// `x < 2^(s - l)`, which includes all `x < 2^49` (Granlund & Montgomery
/// 1994, "Division by invariant integers using multiplication", Theorem 4.2:
/// `m * d - 2^s < d <= 2^l`, so the error term stays below `1 / d`). Taking
/// `s >= 64` makes the first shift the free "high word" of the product;
/// `m < 2^63` fits in u64 (`d >= 3` when `s = 64`, else `m <= 2^50 + 1`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Divisor {
    d: u32,
    /// `log2 d` for a power of two, else `s - 64`.
    shift: u32,
    /// `m`, or 0 for a power of two.
    magic: u64,
}

impl Divisor {
    /// Numerators must be below `2^NUMERATOR_BITS`: `2^48` (a stratum
    /// boundary `(stratum + 1) << 24` with `stratum < 2^24`) plus a
    /// rounding term below `2^32`.
    const NUMERATOR_BITS: u32 = 49;

    /// The divisor `d`; `d` must be at least 1 (checked in debug builds; a
    /// zero is treated as 1 in release builds).
    pub(crate) const fn new(d: u32) -> Self {
        debug_assert!(d >= 1);
        let d = if d == 0 { 1 } else { d };
        if d.is_power_of_two() {
            return Self {
                d,
                shift: d.trailing_zeros(),
                magic: 0,
            };
        }
        let l = u32::BITS - (d - 1).leading_zeros();
        let s = if Self::NUMERATOR_BITS + l > 64 {
            Self::NUMERATOR_BITS + l
        } else {
            64
        };
        let magic = (1u128 << s).div_ceil(d as u128);
        Self {
            d,
            shift: s - 64,
            magic: magic as u64,
        }
    }

    /// The divisor itself.
    #[inline(always)]
    pub(crate) const fn get(self) -> u32 {
        self.d
    }

    /// `log2 d` if `d` is a power of two.
    #[inline(always)]
    const fn log2(self) -> Option<u32> {
        if self.magic == 0 {
            Some(self.shift)
        } else {
            None
        }
    }

    /// `x / d` for `x < 2^49`.
    #[inline(always)]
    pub(crate) const fn div(self, x: u64) -> u64 {
        debug_assert!(x < 1 << Self::NUMERATOR_BITS);
        // The branch goes the same way for every call on one divisor.
        if self.magic == 0 {
            x >> self.shift
        } else {
            (((x as u128 * self.magic as u128) >> 64) as u64) >> self.shift
        }
    }

    /// `(x / d, x % d)` for a u32 `x`.
    #[inline(always)]
    pub(crate) const fn div_rem(self, x: u32) -> (u32, u32) {
        let q = self.div(x as u64) as u32;
        (q, x - q * self.d)
    }

    /// `ceil(x / d)` for `x <= 2^48`.
    #[inline(always)]
    const fn div_ceil(self, x: u64) -> u64 {
        self.div(x + self.d as u64 - 1)
    }
}

/// A length prepared for [`permute`] and [`stratum_to_unit_f32`]: its
/// hashing mask and its reciprocal, computed once per sampler so that the
/// per-sample paths need no division. Results are bit-identical to the free
/// functions (`tests/bench_equivalence.rs` checks it against a frozen copy).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Length {
    divisor: Divisor,
    mask: u32,
}

impl Length {
    /// Prepares `len >= 1`.
    pub(crate) const fn new(len: u32) -> Self {
        Self {
            divisor: Divisor::new(len),
            mask: permute_mask(len),
        }
    }

    /// The length itself.
    #[inline(always)]
    pub(crate) const fn get(self) -> u32 {
        self.divisor.get()
    }

    /// `(x / len, x % len)`.
    #[inline(always)]
    pub(crate) const fn div_rem(self, x: u32) -> (u32, u32) {
        self.divisor.div_rem(x)
    }

    /// Whether the length is a power of two: then every grid length of a
    /// sampler of `n = len` is one too, and `fill` runs the `POW2 = true`
    /// instances of the methods below.
    #[inline(always)]
    pub(crate) const fn is_power_of_two(self) -> bool {
        self.divisor.log2().is_some()
    }

    /// [`div_rem`](Self::div_rem), specialised at compile time: with `POW2`
    /// the caller guarantees a power of two (checked in debug builds), so
    /// the loop that calls it holds a shift and a mask and no branch.
    #[inline(always)]
    pub(crate) const fn div_rem_in<const POW2: bool>(self, x: u32) -> (u32, u32) {
        if POW2 {
            debug_assert!(self.is_power_of_two());
            (x >> self.divisor.shift, x & (self.get() - 1))
        } else {
            self.div_rem(x)
        }
    }

    /// [`stratum_to_unit_f32`](Self::stratum_to_unit_f32), specialised at
    /// compile time like [`div_rem_in`](Self::div_rem_in).
    #[inline(always)]
    pub(crate) const fn stratum_to_unit_f32_in<const POW2: bool>(
        self,
        stratum: u32,
        bits: u32,
    ) -> f32 {
        if POW2 {
            debug_assert!(self.is_power_of_two() && self.get() <= MAX_STRATA);
            power_of_two_stratum_to_unit_f32(stratum, self.divisor.shift, bits)
        } else {
            self.stratum_to_unit_f32(stratum, bits)
        }
    }

    /// Permutation `pattern` of `[0, len)`: [`permute`]`(_, len, pattern)`
    /// with the per-pattern work (the rotation `pattern % len`) done here,
    /// once.
    #[inline(always)]
    pub(crate) const fn permutation(self, pattern: u32) -> Permutation {
        Permutation {
            len: self,
            key: permute_key(pattern),
            rotation: self.divisor.div_rem(pattern).1,
        }
    }

    /// [`permutation`](Self::permutation), specialised at compile time like
    /// [`div_rem_in`](Self::div_rem_in).
    #[inline(always)]
    pub(crate) const fn permutation_in<const POW2: bool>(self, pattern: u32) -> Permutation {
        Permutation {
            len: self,
            key: permute_key(pattern),
            rotation: self.div_rem_in::<POW2>(pattern).1,
        }
    }

    /// [`stratum_to_unit_f32`]`(stratum, len, bits)` for `stratum < len <=
    /// 2^24`, without its two 64-bit divisions.
    #[inline(always)]
    pub(crate) const fn stratum_to_unit_f32(self, stratum: u32, bits: u32) -> f32 {
        debug_assert!(self.get() <= MAX_STRATA && stratum < self.get());
        if let Some(k) = self.divisor.log2() {
            if k <= UNIT_BITS {
                return power_of_two_stratum_to_unit_f32(stratum, k, bits);
            }
        }
        let start = self.divisor.div_ceil((stratum as u64) << UNIT_BITS);
        let end = self.divisor.div_ceil((stratum as u64 + 1) << UNIT_BITS);
        // Same arithmetic as `stratum_to_unit_f32` from here on; with valid
        // arguments `end > start` and `t < 2^24`, and the clamps stay for
        // release builds handed bad ones.
        let t = start + ((end.saturating_sub(start) * bits as u64) >> 32);
        let t = if t < MAX_STRATA as u64 {
            t
        } else {
            MAX_STRATA as u64 - 1
        };
        t as f32 * (1.0 / MAX_STRATA as f32)
    }
}

/// [`stratum_to_unit_f32`]`(stratum, 2^k, bits)` for `k <= 24`, by shifts:
/// with `2^k` strata of width `2^(24 - k)`, `start` and `end` are exact
/// shifts and `(width * bits) >> 32` is `bits >> (8 + k)`; the sum stays below
/// 2^24, so there is no clamp either.
#[inline(always)]
const fn power_of_two_stratum_to_unit_f32(stratum: u32, k: u32, bits: u32) -> f32 {
    // (Shifted as u64: at k = 24 the shift is 32.)
    let t = (stratum << (UNIT_BITS - k)) + ((bits as u64) >> (32 - UNIT_BITS + k)) as u32;
    t as f32 * (1.0 / MAX_STRATA as f32)
}

/// One permutation of `[0, len)`, ready to apply: [`permute`] with its
/// per-pattern work hoisted, for `fill` loops and random access alike.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Permutation {
    len: Length,
    /// `permute_key(pattern)`, the key of [`permute_hash`].
    key: u32,
    /// `pattern % len`: `(i + pattern) % len == (i + rotation) % len`, and
    /// with `i, rotation < len` that is one conditional subtraction.
    rotation: u32,
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
        let i = permute_hash(index, len, self.len.mask, self.key);
        // i + rotation < 2 len <= 2^33: summed in u64 so that it cannot wrap.
        let sum = i as u64 + self.rotation as u64;
        if sum >= len as u64 {
            (sum - len as u64) as u32
        } else {
            sum as u32
        }
    }
}

/// 32 random bits for `(index, pattern)`: Kensler 2013's `randfloat` hash
/// (listing 2) without its final conversion to float.
#[inline]
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

/// Maps 32 random bits to a float in `[0, 1)` that can never be 1.0.
///
/// Keeps the top 24 bits, which f32 represents exactly below 1.0; the
/// largest result is [`ONE_MINUS_EPSILON`]. (Multiplying all 32 bits by
/// `2^-32` would round values above `1 - 2^-25` up to 1.0.)
///
/// ```
/// use wellspread::hash::u32_to_unit_f32;
/// assert_eq!(u32_to_unit_f32(0), 0.0);
/// assert!(u32_to_unit_f32(u32::MAX) < 1.0);
/// ```
#[inline]
#[must_use]
pub const fn u32_to_unit_f32(bits: u32) -> f32 {
    (bits >> (32 - UNIT_BITS)) as f32 * (1.0 / MAX_STRATA as f32)
}

/// A float inside stratum `stratum` of `strata` equal strata of `[0, 1)`,
/// at fraction `bits / 2^32` of the way across it.
///
/// The result is `t * 2^-24` for an integer `t` chosen in fixed point among
/// the 24-bit grid points of `[stratum / strata, (stratum + 1) / strata)`,
/// so it is exactly representable and provably inside the stratum: the
/// textbook `(stratum + u) / strata` in f32 rounds to the next stratum's
/// left edge (or to 1.0) once `strata` reaches about 2^12.
///
/// Every stratum holds at least one grid point while `strata <= MAX_STRATA`
/// (`2^24`), which is why samplers that cut an axis into `n` strata accept
/// at most 2^24 samples. With fewer than `2^24 / strata` grid points per
/// stratum the offset is quantised to them. An out-of-range `stratum`, or
/// `strata` above 2^24 (checked in debug builds), still yields a value in
/// `[0, 1)`.
///
/// # Panics
///
/// If `strata` is 0.
///
/// ```
/// use wellspread::hash::stratum_to_unit_f32;
/// let n = 3_000_017; // prime, and 2^24 / n is not an integer
/// let x = stratum_to_unit_f32(n - 1, n, u32::MAX);
/// assert!(x < 1.0);
/// assert_eq!((x as f64 * n as f64).floor() as u32, n - 1);
/// ```
#[inline]
#[must_use]
pub const fn stratum_to_unit_f32(stratum: u32, strata: u32, bits: u32) -> f32 {
    debug_assert!(strata >= 1 && strata <= MAX_STRATA && stratum < strata);
    let strata = strata as u64;
    let start = ((stratum as u64) << UNIT_BITS).div_ceil(strata);
    let end = ((stratum as u64 + 1) << UNIT_BITS).div_ceil(strata);
    // end > start whenever strata <= 2^24; `saturating_sub` and the `min`
    // keep a release build with bad arguments inside [0, 1).
    let t = start + ((end.saturating_sub(start) * bits as u64) >> 32);
    let t = if t < MAX_STRATA as u64 {
        t
    } else {
        MAX_STRATA as u64 - 1
    };
    t as f32 * (1.0 / MAX_STRATA as f32)
}

/// Salts that split one hashed pattern into independent seeds, one per
/// random choice a sampler makes (sample order, x shuffle, y shuffle, x
/// jitter, y jitter). Samplers compute `hash_u32(pattern) ^ SALT`, which
/// costs one hash per sample instead of one per choice; the constants are
/// Kensler's (2013) pattern multipliers, odd with about half their bits
/// set, reused here as xor salts so that pattern 0 still
/// yields five unrelated seeds.
pub(crate) mod salt {
    pub(crate) const ORDER: u32 = 0x51633e2d;
    pub(crate) const SHUFFLE_X: u32 = 0xa511e9b3;
    pub(crate) const SHUFFLE_Y: u32 = 0x63d83595;
    pub(crate) const JITTER_X: u32 = 0xa399d265;
    pub(crate) const JITTER_Y: u32 = 0x711ad6a5;
}

// ---------------------------------------------------------------------------
// Base-2 digit scrambling for progressive sequences (Sobol, pmj02, Halton,
// Hammersley). Added for issue #6; nothing above this line changed.
// ---------------------------------------------------------------------------

/// The base-2 radical inverse (van der Corput) of `index` in 0.32 fixed
/// point: the bits of `index` mirrored about the binary point, so the result
/// is `radical_inverse_2(index) / 2^32`.
///
/// This is also the "reversed-bit" form the scrambles below work in: bit `k`
/// of a reversed value is the digit of weight `2^-(k+1)`.
///
/// ```
/// use wellspread::hash::radical_inverse_2;
/// assert_eq!(radical_inverse_2(1), 1 << 31); // 1/2
/// assert_eq!(radical_inverse_2(6), 3 << 29); // 0.011 in binary = 3/8
/// ```
#[inline]
#[must_use]
pub const fn radical_inverse_2(index: u32) -> u32 {
    index.reverse_bits()
}

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
/// use wellspread::hash::owen_scramble_reversed;
/// // The most significant digit (bit 0 here) flips or not by the seed alone.
/// let flip = owen_scramble_reversed(0, 7) & 1;
/// assert!((0..64).all(|x| (owen_scramble_reversed(x, 7) ^ x) & 1 == flip));
/// ```
#[inline]
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
/// use wellspread::hash::owen_scramble;
/// let mut block: Vec<u32> = (0..16).map(|i| owen_scramble(i, 99) / 16).collect();
/// block.dedup();
/// assert_eq!(block.len(), 1); // the first 16 land in one aligned block of 16
/// ```
#[inline]
#[must_use]
pub const fn owen_scramble(x: u32, seed: u32) -> u32 {
    owen_scramble_reversed(x.reverse_bits(), seed).reverse_bits()
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

    #[test]
    fn unit_f32_edges() {
        assert_eq!(u32_to_unit_f32(u32::MAX), ONE_MINUS_EPSILON);
        assert_eq!(u32_to_unit_f32(1 << 8), 1.0 / 16_777_216.0);
    }

    #[test]
    fn stratum_values_stay_in_their_stratum() {
        for strata in [
            1u32,
            2,
            3,
            7,
            4095,
            4096,
            4097,
            65_537,
            1 << 20,
            16_777_213,
            MAX_STRATA,
        ] {
            for stratum in [0, 1 % strata, strata / 2, strata - 1] {
                for bits in [0, 1, 1 << 31, u32::MAX - 1, u32::MAX] {
                    let x = stratum_to_unit_f32(stratum, strata, bits);
                    assert!((0.0..1.0).contains(&x));
                    let s = (x as f64 * strata as f64).floor() as u32;
                    assert_eq!(s, stratum, "strata {strata} bits {bits}: {x}");
                }
            }
        }
    }

    #[test]
    fn divisor_is_exact_below_2_pow_49() {
        let mut divisors: std::vec::Vec<u32> = (1..=1000).collect();
        for k in 10..32 {
            divisors.extend([(1 << k) - 1, 1 << k, (1 << k) + 1]);
        }
        divisors.extend([16_777_213, 65_521, 3_000_000_019, u32::MAX - 1, u32::MAX]);
        let top = (1u64 << 49) - 1;
        let mut x = 0x1234_5678_9abc_u64;
        for d in divisors {
            let div = Divisor::new(d);
            let d64 = d as u64;
            let q_top = top / d64;
            let mut xs = std::vec![0, 1, d64 - 1, d64, d64 + 1, top, top - 1];
            xs.extend([q_top * d64, q_top * d64 - 1, (q_top - 1) * d64 + d64 - 1]);
            for _ in 0..200 {
                x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                xs.push(x >> 15);
                xs.push((x >> 40) * d64 + d64 - 1);
            }
            for x in xs.into_iter().filter(|&x| x <= top) {
                assert_eq!(div.div(x), x / d64, "{x} / {d}");
            }
            for x in [0, 1, d - 1, d, u32::MAX - 1, u32::MAX] {
                assert_eq!(div.div_rem(x), (x / d, x % d), "{x} divrem {d}");
            }
        }
    }

    #[test]
    fn hashes_are_pinned() {
        // Golden values, cross-checked against an independent Python
        // transcription: a change here changes every sample wellspread makes.
        assert_eq!(hash_u32(0), 0);
        assert_eq!(hash_u32(1), 0x6889_90c0);
        assert_eq!(rand_u32(0, 0), 0xdf6e_5fc8);
        assert_eq!(permute(3, 10, 42), 3);
        assert_eq!(permute(2, 6, 0xdead_beef), 3);
    }
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
        assert_eq!(radical_inverse_2(1), 0x8000_0000);
        assert_eq!(owen_scramble_reversed(0, 0), 0);
        assert_eq!(owen_scramble_reversed(1, 0), 0x3707_b665);
        assert_eq!(
            owen_scramble_reversed(0x1234_5678, 0xdead_beef),
            0x023f_ba03
        );
        assert_eq!(owen_scramble(0x8000_0000, 0), 0xa66d_e0ec);
    }
}
