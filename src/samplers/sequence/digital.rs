//! The one Owen-scrambled Sobol' module: what the shuffled, scrambled
//! digital sequences ([`Sobol`], [`Pmj02`]) share (their seeds, the
//! scramble of a point's digits and the conversion to a point, the
//! lane-parallel `fill`), Sobol' dimensions 0 and 1 (the identity and the
//! Pascal matrix), and the draws of a [`Domain`](crate::Domain) built from
//! them: 1D, 2D and the 4D set (with dimensions 2 and 3 from
//! [`sobol_4d`](super::sobol_4d)). [`Sobol`], [`Pmj02`],
//! [`Padded`](crate::Padded), [`ZSobol`](crate::ZSobol) and
//! [`BlueNoise`](crate::BlueNoise) all call these.
//!
//! [`Sobol`]: crate::Sobol
//! [`Pmj02`]: crate::Pmj02

use glam::{Vec2, Vec4};

use super::sobol_4d::dimensions_2_3_reversed;
use crate::primitives::{hash_u32, owen_scramble_reversed, salt, u32_to_unit_f32};
use crate::simd::{PointKernel, Pointwise};

/// Three independent seeds for a shuffled, Owen-scrambled 2D sequence: one
/// for the index shuffle and one per coordinate.
#[derive(Clone, Copy, Debug)]
pub(crate) struct OwenSeeds {
    pub(crate) index: u32,
    pub(crate) x: u32,
    pub(crate) y: u32,
}

impl OwenSeeds {
    #[inline]
    pub(crate) const fn new(pattern: u32) -> Self {
        // Hashing each salted pattern_hash again (rather than only xoring
        // salts in) keeps the three scrambles unrelated: Owen scrambles add the seed,
        // and seeds that differ by a fixed xor would differ predictably.
        let pattern_hash = hash_u32(pattern);
        Self {
            index: hash_u32(pattern_hash ^ salt::ORDER),
            x: hash_u32(pattern_hash ^ salt::JITTER_X),
            y: hash_u32(pattern_hash ^ salt::JITTER_Y),
        }
    }
}

impl OwenSeeds {
    /// The seeds of a [`Domain`](crate::Domain) draw from its well-mixed
    /// 64-bit `stream`, without hashing again: `x` and `y` are its two
    /// halves, the index shuffle's key a rotation of their xor. The low
    /// bits of a seed pick a scramble's top digits, and each seed's come
    /// from a different part of `stream`.
    #[inline(always)]
    pub(crate) const fn from_stream(stream: u64) -> Self {
        let (low, high) = (stream as u32, (stream >> 32) as u32);
        Self {
            index: (low ^ high).rotate_right(16) ^ salt::DRAW_ORDER,
            x: high,
            y: low,
        }
    }
}

/// Sobol' dimension 1 of `index`, in reversed bit order (bit `k` is the digit
/// of weight `2^-(k+1)`).
///
/// Its generator matrix is the Pascal matrix mod 2: digit `k` is the xor of
/// the index bits `j` with `binomial(j, k)` odd, which by Lucas' theorem are
/// the `j` whose set bits include those of `k`. That xor over supersets is
/// computed for all 32 digits at once in five butterfly steps, one per bit of
/// `k`: step `b` folds bit `k + 2^b` into bit `k` wherever bit `b` of `k` is
/// clear, which is what each mask selects (`0x5555_5555`: positions with bit
/// 0 clear; `0x3333_3333`: bit 1 clear; and so on). Equivalently, its
/// direction numbers are those of the primitive polynomial `x + 1`,
/// `v_0 = 2^31` and `v_j = v_(j-1) ^ (v_(j-1) >> 1)` (Joe & Kuo's dimension
/// 2), tested in `sobol.rs`.
#[inline(always)]
pub(crate) const fn pascal_reversed(index: u32) -> u32 {
    let mut y = index;
    y ^= (y >> 1) & 0x5555_5555;
    y ^= (y >> 2) & 0x3333_3333;
    y ^= (y >> 4) & 0x0f0f_0f0f;
    y ^= (y >> 8) & 0x00ff_00ff;
    y ^= y >> 16;
    y
}

/// Sobol' dimensions 0 and 1 of sequence index `s`, in reversed-digit
/// form: dimension 0's generator is the identity, so its reversed digits
/// are `s` itself.
#[inline(always)]
pub(crate) const fn sobol_reversed(s: u32) -> (u32, u32) {
    (s, pascal_reversed(s))
}

/// The one Sobol' point formula: point `s` (an already shuffled sequence
/// index) of dimensions (0, 1), Owen-scrambled by `seeds`, in
/// natural-order 0.32 fixed point.
#[inline(always)]
pub(crate) const fn sobol_point_bits(s: u32, seeds: OwenSeeds) -> (u32, u32) {
    let (x, y) = sobol_reversed(s);
    scrambled_bits(x, y, seeds)
}

/// One coordinate given as reversed digits, Owen-scrambled by `seed`, as
/// a value in `[0, 1)`: a 1D draw.
#[inline(always)]
pub(crate) const fn scrambled_unit(reversed: u32, seed: u32) -> f32 {
    u32_to_unit_f32(owen_scramble_reversed(reversed, seed).reverse_bits())
}

/// `(reverse_bits(a), reverse_bits(b))` in one 64-bit reversal: x86 has
/// no bit-reverse instruction, and a 64-bit reversal costs what a 32-bit
/// one does.
#[inline(always)]
const fn reverse_pair(a: u32, b: u32) -> (u32, u32) {
    let r = ((b as u64) << 32 | a as u64).reverse_bits();
    ((r >> 32) as u32, r as u32)
}

/// The four scramble seeds of a 4D draw from its well-mixed `stream`:
/// dimensions 0 and 1 take [`OwenSeeds::from_stream`]'s (so a 4D draw's
/// first two coordinates are the 2D draw's), dimensions 2 and 3 two more
/// rotations of its halves.
#[inline(always)]
pub(crate) const fn seeds_4d(stream: u64) -> [u32; 4] {
    let seeds = OwenSeeds::from_stream(stream);
    let (low, high) = (stream as u32, (stream >> 32) as u32);
    [
        seeds.x,
        seeds.y,
        low.rotate_right(11) ^ high.rotate_right(5) ^ salt::SOBOL_Z,
        high.rotate_right(21) ^ low.rotate_right(27) ^ salt::SOBOL_W,
    ]
}

/// Point `s` (an already shuffled index) of the 4D Owen-scrambled Sobol'
/// set whose scrambles are seeded by `stream` ([`seeds_4d`]), each
/// coordinate's reversed digits first xored with `shift` (a digital shift:
/// zeros for the plain set, a pixel's shift for
/// [`BlueNoise`](crate::BlueNoise)).
#[inline(always)]
pub(crate) const fn sobol_4d_point(s: u32, stream: u64, shift: [u32; 4]) -> Vec4 {
    let [x, y, z, w] = seeds_4d(stream);
    let (c0, c1) = sobol_reversed(s);
    let (c2, c3) = dimensions_2_3_reversed(s);
    let (a, b) = reverse_pair(
        owen_scramble_reversed(c0 ^ shift[0], x),
        owen_scramble_reversed(c1 ^ shift[1], y),
    );
    let (c, d) = reverse_pair(
        owen_scramble_reversed(c2 ^ shift[2], z),
        owen_scramble_reversed(c3 ^ shift[3], w),
    );
    Vec4::new(
        u32_to_unit_f32(a),
        u32_to_unit_f32(b),
        u32_to_unit_f32(c),
        u32_to_unit_f32(d),
    )
}

/// Finishes a point of a shuffled digital (0,2)-sequence: Owen-scrambles
/// the two coordinates, given as digits in reversed bit order, and returns
/// them in natural order (0.32 fixed point).
#[inline(always)]
pub(crate) const fn scrambled_bits(
    x_reversed: u32,
    y_reversed: u32,
    seeds: OwenSeeds,
) -> (u32, u32) {
    reverse_pair(
        owen_scramble_reversed(x_reversed, seeds.x),
        owen_scramble_reversed(y_reversed, seeds.y),
    )
}

/// The point with coordinates `bits / 2^32`, truncated to 24 bits.
#[inline(always)]
pub(crate) const fn bits_to_point((x, y): (u32, u32)) -> Vec2 {
    Vec2::new(u32_to_unit_f32(x), u32_to_unit_f32(y))
}

/// A shuffled, Owen-scrambled digital (0,2)-sequence: its point formula,
/// and the kernel built from it that `sample`, `fill` and `fill_from` run.
pub(crate) trait DigitalSequence: Sized {
    /// Point `index` in natural-order 0.32 fixed point, for the pattern
    /// whose seeds are `seeds`.
    fn point_bits(index: u32, seeds: OwenSeeds) -> (u32, u32);

    /// The points of pattern `pattern`, as a lane kernel: the one
    /// `sample`, `fill` and `fill_from` run. Every step of a point is a
    /// 32-bit integer operation on its own lane (multiplies, shifts, masks,
    /// bit reversals), so batches run in SIMD registers.
    #[inline(always)]
    fn kernel(pattern: u32) -> Pointwise<impl PointKernel> {
        Pointwise(SequenceKernel::<Self> {
            seeds: OwenSeeds::new(pattern),
            sequence: core::marker::PhantomData,
        })
    }
}

/// One pattern of a digital sequence, as a [`PointKernel`].
struct SequenceKernel<D> {
    seeds: OwenSeeds,
    sequence: core::marker::PhantomData<D>,
}

impl<D: DigitalSequence> PointKernel for SequenceKernel<D> {
    #[inline(always)]
    fn point(&self, index: u32) -> Vec2 {
        bits_to_point(D::point_bits(index, self.seeds))
    }
}

#[cfg(test)]
pub(crate) mod tests {
    /// `true` if the digital sequence whose generator matrices have columns
    /// `x_column(j)` and `y_column(j)` (reversed bit order: bit `k` is digit
    /// `k`) is a (0,2)-sequence in base 2 for every `m <= 32`: for each
    /// shape `d0 + d1 = m`, the first `d0` rows of one matrix and the first
    /// `d1` of the other, cut to `m` columns, are linearly independent
    /// (Niederreiter 1992, "Random Number Generation and Quasi-Monte Carlo
    /// Methods", ch. 4). Owen scrambling keeps the property.
    pub(crate) fn is_02_sequence(
        x_column: impl Fn(u32) -> u32,
        y_column: impl Fn(u32) -> u32,
    ) -> bool {
        let row = |column: &dyn Fn(u32) -> u32, k: u32, m: u32| -> u64 {
            (0..m).fold(0, |r, j| r | ((column(j) >> k & 1) as u64) << j)
        };
        for m in 1..=32 {
            for d0 in 0..=m {
                let mut basis: std::vec::Vec<u64> = std::vec::Vec::new();
                let rows = (0..d0)
                    .map(|k| row(&x_column, k, m))
                    .chain((0..m - d0).map(|k| row(&y_column, k, m)));
                for mut v in rows {
                    for &b in &basis {
                        v = v.min(v ^ b);
                    }
                    if v == 0 {
                        return false;
                    }
                    basis.push(v);
                    basis.sort_unstable_by(|a, b| b.cmp(a));
                }
            }
        }
        true
    }
}
