//! What the shuffled, Owen-scrambled digital (0,2)-sequences ([`Sobol`],
//! [`Pmj02`]) share: their seeds, the scramble of a point's digits and the
//! conversion to a point, and the lane-parallel `fill`.
//!
//! [`Sobol`]: crate::Sobol
//! [`Pmj02`]: crate::Pmj02

use glam::Vec2;

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

/// Finishes a point of a shuffled digital (0,2)-sequence: Owen-scrambles
/// the two coordinates, given as digits in reversed bit order, and returns
/// them in natural order (0.32 fixed point).
#[inline(always)]
pub(crate) const fn scrambled_bits(
    x_reversed: u32,
    y_reversed: u32,
    seeds: OwenSeeds,
) -> (u32, u32) {
    (
        owen_scramble_reversed(x_reversed, seeds.x).reverse_bits(),
        owen_scramble_reversed(y_reversed, seeds.y).reverse_bits(),
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
