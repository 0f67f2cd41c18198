//! Morton (Z-order) codes: the bits of a pixel's `x` and `y` interleaved,
//! so that aligned `2^k x 2^k` squares of pixels are aligned blocks of
//! `4^k` codes. [`ZSobol`](crate::ZSobol) and
//! [`BlueNoise`](crate::BlueNoise) order pixels by them.

/// Even bits of a 32-bit Morton code (the `x` bits).
pub(crate) const EVEN_BITS: u32 = 0x5555_5555;

/// The bits of `v` moved to the even positions of a u64 (bit `k` to bit
/// `2 k`).
#[inline(always)]
#[must_use]
const fn spread_32(v: u32) -> u64 {
    let mut v = v as u64;
    v = (v | v << 16) & 0x0000_ffff_0000_ffff;
    v = (v | v << 8) & 0x00ff_00ff_00ff_00ff;
    v = (v | v << 4) & 0x0f0f_0f0f_0f0f_0f0f;
    v = (v | v << 2) & 0x3333_3333_3333_3333;
    v = (v | v << 1) & 0x5555_5555_5555_5555;
    v
}

/// The Morton code of the low 16 bits of `x` and `y`: `x` in the even
/// bits, `y` in the odd ones.
#[inline(always)]
#[must_use]
pub(crate) const fn morton(x: u32, y: u32) -> u32 {
    morton_64(x & 0xffff, y & 0xffff) as u32
}

/// The Morton code of all 32 bits of `x` and `y` (the metrics' z-order).
#[inline(always)]
#[must_use]
pub(crate) const fn morton_64(x: u32, y: u32) -> u64 {
    spread_32(x) | spread_32(y) << 1
}

/// The Morton code of the pixel `(x + dx, y + dy)` (modulo 2^16 on each
/// axis) from the code of `(x, y)` and that of `(dx, dy)`: addition of
/// dilated integers (the odd bits are set to 1 so that carries ripple
/// through them, then masked off), two adds instead of a new interleave.
#[inline(always)]
#[must_use]
pub(crate) const fn morton_add(code: u32, offset: u32) -> u32 {
    let x = ((code | !EVEN_BITS).wrapping_add(offset & EVEN_BITS)) & EVEN_BITS;
    let y = ((code | EVEN_BITS).wrapping_add(offset & !EVEN_BITS)) & !EVEN_BITS;
    x | y
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn morton_interleaves_x_in_the_even_bits() {
        assert_eq!(morton(1, 0), 1);
        assert_eq!(morton(0, 1), 2);
        assert_eq!(morton(3, 3), 15);
        assert_eq!(morton(0b101, 0b010), 0b01_10_01);
        assert_eq!(morton(0xffff, 0), EVEN_BITS);
        assert_eq!(morton(0xffff, 0xffff), u32::MAX);
        // Only the low 16 bits count.
        assert_eq!(morton(0x1_0003, 0x2_0000), 5);
        // The 64-bit code keeps them all, and agrees below.
        assert_eq!(morton_64(u32::MAX, 0), 0x5555_5555_5555_5555);
        assert_eq!(morton_64(0, 1 << 31), 1 << 63);
        assert_eq!(morton_64(0x1_0003, 0x2_0000), 1 << 32 | 1 << 35 | 5);
    }

    #[test]
    fn dilated_addition_is_addition_of_pixels() {
        let mut s = 0x1234_5678_u32;
        for _ in 0..10_000 {
            s = crate::primitives::hash_u32(s);
            let (x, y, dx, dy) = (
                s & 0xffff,
                s >> 16,
                s.rotate_left(7) & 0xffff,
                s.rotate_left(19) >> 16,
            );
            assert_eq!(
                morton_add(morton(x, y), morton(dx, dy)),
                morton(x.wrapping_add(dx), y.wrapping_add(dy)),
                "({x}, {y}) + ({dx}, {dy})"
            );
        }
    }
}
