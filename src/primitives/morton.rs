//! Morton (Z-order) codes: the bits of a pixel's `x` and `y` interleaved,
//! so that aligned `2^k x 2^k` squares of pixels are aligned blocks of
//! `4^k` codes. [`ZSobol`](crate::ZSobol) and
//! [`BlueNoise`](crate::BlueNoise) order pixels by them.

/// Even bits of a 32-bit Morton code (the `x` bits).
pub(crate) const EVEN_BITS: u32 = 0x5555_5555;

/// The low 16 bits of `v` moved to the even positions of a u32.
#[inline(always)]
#[must_use]
pub(crate) const fn spread_16(v: u32) -> u32 {
    let mut v = v & 0xffff;
    v = (v | v << 8) & 0x00ff_00ff;
    v = (v | v << 4) & 0x0f0f_0f0f;
    v = (v | v << 2) & 0x3333_3333;
    v = (v | v << 1) & EVEN_BITS;
    v
}

/// The Morton code of the low 16 bits of `x` and `y`: `x` in the even
/// bits, `y` in the odd ones.
#[inline(always)]
#[must_use]
pub(crate) const fn morton(x: u32, y: u32) -> u32 {
    spread_16(x) | spread_16(y) << 1
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
