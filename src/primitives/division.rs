//! Division by an integer fixed for a sampler's lifetime, as a multiply and
//! a shift.

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
pub(crate) struct InvariantDivisor {
    d: u32,
    /// `log2 d` for a power of two, else `s - 64`.
    shift: u32,
    /// `m`, or 0 for a power of two, as its low and high halves: two u32
    /// keep the struct 4-byte aligned, so a sampler holding several packs
    /// them with its other u32 fields.
    magic: [u32; 2],
}

impl InvariantDivisor {
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
                magic: [0; 2],
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
            magic: [magic as u32, (magic >> 32) as u32],
        }
    }

    /// `m`.
    #[inline(always)]
    const fn magic(self) -> u64 {
        (self.magic[1] as u64) << 32 | self.magic[0] as u64
    }

    /// The divisor itself.
    #[inline(always)]
    pub(crate) const fn get(self) -> u32 {
        self.d
    }

    /// `log2 d` if `d` is a power of two.
    #[inline(always)]
    pub(crate) const fn log2(self) -> Option<u32> {
        if self.magic() == 0 {
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
        if self.magic() == 0 {
            x >> self.shift
        } else {
            (((x as u128 * self.magic() as u128) >> 64) as u64) >> self.shift
        }
    }

    /// `(x / d, x % d)` for a u32 `x`.
    #[inline(always)]
    pub(crate) const fn div_rem(self, x: u32) -> (u32, u32) {
        let q = self.div(x as u64) as u32;
        (q, x - q * self.d)
    }

    /// Whether `d` is a power of two: then the `POW2 = true` instances of
    /// the `_in` methods below (and of the samplers' loops) apply.
    #[inline(always)]
    pub(crate) const fn is_power_of_two(self) -> bool {
        self.magic() == 0
    }

    /// [`div_rem`](Self::div_rem), specialised at compile time: with `POW2`
    /// the caller guarantees a power of two (checked in debug builds), so
    /// the loop that calls it holds a shift and a mask and no branch.
    #[inline(always)]
    pub(crate) const fn div_rem_in<const POW2: bool>(self, x: u32) -> (u32, u32) {
        if POW2 {
            debug_assert!(self.is_power_of_two());
            (x >> self.shift, x & (self.d - 1))
        } else {
            self.div_rem(x)
        }
    }

    /// `ceil(x / d)` for `x <= 2^48`.
    #[inline(always)]
    pub(crate) const fn div_ceil(self, x: u64) -> u64 {
        self.div(x + self.d as u64 - 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
            let div = InvariantDivisor::new(d);
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
}
