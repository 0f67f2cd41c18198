//! The one conversion from random bits to a float in `[0, 1)`, in 24-bit
//! fixed point, so that no coordinate is ever 1.0 or in the wrong stratum.

use super::division::InvariantDivisor;

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

/// Maps 32 random bits to a float in `[0, 1)` that can never be 1.0.
///
/// Keeps the top 24 bits, which f32 represents exactly below 1.0; the
/// largest result is [`ONE_MINUS_EPSILON`]. (Multiplying all 32 bits by
/// `2^-32` would round values above `1 - 2^-25` up to 1.0.)
///
/// ```
/// use wellspread::primitives::u32_to_unit_f32;
/// assert_eq!(u32_to_unit_f32(0), 0.0);
/// assert!(u32_to_unit_f32(u32::MAX) < 1.0);
/// ```
#[inline(always)]
#[must_use]
pub const fn u32_to_unit_f32(bits: u32) -> f32 {
    to_unit_f32(bits >> (32 - UNIT_BITS))
}

/// `t * 2^-24` for `t < 2^24`, exactly. (`t` goes through i32, which it
/// fits: SIMD units convert signed integers to floats in one instruction
/// and unsigned ones in several.)
#[inline(always)]
const fn to_unit_f32(t: u32) -> f32 {
    debug_assert!(t < MAX_STRATA);
    t as i32 as f32 * (1.0 / MAX_STRATA as f32)
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
/// use wellspread::primitives::stratum_to_unit_f32;
/// let n = 3_000_017; // prime, and 2^24 / n is not an integer
/// let x = stratum_to_unit_f32(n - 1, n, u32::MAX);
/// assert!(x < 1.0);
/// assert_eq!((x as f64 * n as f64).floor() as u32, n - 1);
/// ```
#[inline(always)]
#[must_use]
#[track_caller]
pub const fn stratum_to_unit_f32(stratum: u32, strata: u32, bits: u32) -> f32 {
    debug_assert!(strata >= 1 && strata <= MAX_STRATA && stratum < strata);
    let strata = strata as u64;
    let start = ((stratum as u64) << UNIT_BITS).div_ceil(strata);
    let end = ((stratum as u64 + 1) << UNIT_BITS).div_ceil(strata);
    within_stratum(start, end, bits)
}

/// The grid point at fraction `bits / 2^32` of the way from `start` to
/// `end` (the first grid points of a stratum and of the next one), as a
/// float. `end > start` whenever the strata number at most 2^24;
/// `saturating_sub` and the clamp keep a release build handed bad
/// arguments inside `[0, 1)`.
#[inline(always)]
const fn within_stratum(start: u64, end: u64, bits: u32) -> f32 {
    let t = start + ((end.saturating_sub(start) * bits as u64) >> 32);
    let t = if t < MAX_STRATA as u64 {
        t
    } else {
        MAX_STRATA as u64 - 1
    };
    to_unit_f32(t as u32)
}

/// The stratum conversion with the strata count's reciprocal prepared once
/// per sampler, so that the per-sample paths need no division. Results are
/// bit-identical to [`stratum_to_unit_f32`] (tested below).
impl InvariantDivisor {
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
            let k = match self.log2() {
                Some(k) => k,
                None => 0,
            };
            power_of_two_stratum_to_unit_f32(stratum, k, bits)
        } else {
            self.stratum_to_unit_f32(stratum, bits)
        }
    }

    /// [`stratum_to_unit_f32`]`(stratum, len, bits)` for `stratum < len <=
    /// 2^24`, without its two 64-bit divisions.
    #[inline(always)]
    pub(crate) const fn stratum_to_unit_f32(self, stratum: u32, bits: u32) -> f32 {
        debug_assert!(self.get() <= MAX_STRATA && stratum < self.get());
        if let Some(k) = self.log2()
            && k <= UNIT_BITS
        {
            return power_of_two_stratum_to_unit_f32(stratum, k, bits);
        }
        let start = self.div_ceil((stratum as u64) << UNIT_BITS);
        let end = self.div_ceil((stratum as u64 + 1) << UNIT_BITS);
        within_stratum(start, end, bits)
    }
}

/// [`stratum_to_unit_f32`]`(stratum, 2^k, bits)` for `k <= 24`, by shifts:
/// with `2^k` strata of width `2^(24 - k)`, `start` and `end` are exact
/// shifts and `(width * bits) >> 32` is `bits >> (8 + k)`; the sum stays below
/// 2^24, so there is no clamp either.
#[inline(always)]
const fn power_of_two_stratum_to_unit_f32(stratum: u32, k: u32, bits: u32) -> f32 {
    // (Two shifts: at k = 24 one shift would be by 32.)
    let t = (stratum << (UNIT_BITS - k)) + ((bits >> (32 - UNIT_BITS)) >> k);
    to_unit_f32(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_f32_edges() {
        assert_eq!(u32_to_unit_f32(u32::MAX), ONE_MINUS_EPSILON);
        assert_eq!(u32_to_unit_f32(1 << 8), 1.0 / 16_777_216.0);
    }

    #[test]
    fn prepared_strata_match_the_free_function() {
        // The divisions by a prepared `InvariantDivisor` (and the
        // power-of-two shifts) against the plain u64 divisions.
        let mut x = 0x9e37_79b9_u32;
        for strata in (1..=300).chain([4095, 4096, 4097, 65_536, 65_537, 3_000_017, MAX_STRATA]) {
            let prepared = InvariantDivisor::new(strata);
            for _ in 0..64 {
                x = x.wrapping_mul(0x2c1b_3c6d).wrapping_add(0x2976_2fb1);
                let stratum = x % strata;
                for bits in [0, 1, 1 << 31, u32::MAX, x.rotate_left(7)] {
                    let want = stratum_to_unit_f32(stratum, strata, bits).to_bits();
                    let got = prepared.stratum_to_unit_f32(stratum, bits).to_bits();
                    assert_eq!(got, want, "{stratum} of {strata}, bits {bits:#x}");
                    if strata.is_power_of_two() {
                        let shifted = prepared.stratum_to_unit_f32_in::<true>(stratum, bits);
                        assert_eq!(shifted.to_bits(), want, "{stratum} of {strata} (POW2)");
                    }
                }
            }
        }
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
}
