//! What the shuffled, Owen-scrambled digital (0,2)-sequences ([`Sobol`],
//! [`Pmj02`]) share: their seeds, the scramble of a point's digits and the
//! conversion to a point, and the lane-parallel `fill`.
//!
//! [`Sobol`]: crate::Sobol
//! [`Pmj02`]: crate::Pmj02

use glam::Vec2;

use crate::primitives::{hash_u32, owen_scramble_reversed, salt, u32_to_unit_f32};

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
        // Hashing each salted seed again (rather than only xoring salts in)
        // keeps the three scrambles unrelated: Owen scrambles add the seed,
        // and seeds that differ by a fixed xor would differ predictably.
        let seed = hash_u32(pattern);
        Self {
            index: hash_u32(seed ^ salt::ORDER),
            x: hash_u32(seed ^ salt::JITTER_X),
            y: hash_u32(seed ^ salt::JITTER_Y),
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

/// Points per batch in [`fill_in_lanes`].
const LANES: usize = 8;

/// `fill` (and `fill_from`) for sequences whose point is
/// `bits_to_point(point_bits(index, seeds))`: writes indices
/// `start..start + out.len()` in batches of [`LANES`] independent indices.
/// Every step of a point is a 32-bit integer operation on its own lane
/// (multiplies, shifts, masks, bit reversals), so the compiler can run a
/// batch in SIMD registers. The values are exactly those of `sample`,
/// which calls the same `point_bits`.
#[inline(always)]
pub(crate) fn fill_in_lanes(
    out: &mut [Vec2],
    start: u32,
    seeds: OwenSeeds,
    point_bits: impl Fn(u32, OwenSeeds) -> (u32, u32),
) {
    // Callers check `start + out.len() <= 2^32`, so every index fits in
    // u32; only the base after the last full batch may reach 2^32, and it
    // is then not used.
    debug_assert!(u64::from(start) + out.len() as u64 <= 1 << 32);
    let mut chunks = out.chunks_exact_mut(LANES);
    let mut base = start;
    for chunk in &mut chunks {
        let mut x = [0u32; LANES];
        let mut y = [0u32; LANES];
        for (lane, (x, y)) in (0..).zip(x.iter_mut().zip(y.iter_mut())) {
            (*x, *y) = point_bits(base + lane, seeds);
        }
        for ((point, &x), &y) in chunk.iter_mut().zip(&x).zip(&y) {
            *point = bits_to_point((x, y));
        }
        base = base.wrapping_add(LANES as u32);
    }
    for (offset, point) in (0..).zip(chunks.into_remainder()) {
        *point = bits_to_point(point_bits(base + offset, seeds));
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
