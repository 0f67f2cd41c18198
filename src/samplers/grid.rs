//! The grid core the stratified family shares ([`Regular`], [`Jittered`],
//! [`NRooks`], [`MultiJittered`], [`CorrelatedMultiJittered`]): the
//! `columns x rows` shape, its input checks, the lengths with their
//! reciprocals, the cell mapping, and the loop that runs a prepared pattern
//! over a slice. Each sampler keeps its own point formula in its own file.
//!
//! [`Regular`]: crate::Regular
//! [`Jittered`]: crate::Jittered
//! [`NRooks`]: crate::NRooks
//! [`MultiJittered`]: crate::MultiJittered
//! [`CorrelatedMultiJittered`]: crate::CorrelatedMultiJittered

use glam::Vec2;

use crate::primitives::{InvariantDivisor, MAX_STRATA, rand_u32, salt};
use crate::sampler::check_fill_len;
use crate::{Error, SamplerKind};

/// A `columns x rows` grid of `n = columns * rows` cells, each length
/// stored with its reciprocal so that no sample divides.
///
/// Cell `c` is column `c % columns` of row `c / columns`. The samplers that
/// are also Latin cut each axis into `n` fine strata as well: coarse column
/// `j` spans fine columns `j * rows .. (j + 1) * rows`, and coarse row `i`
/// spans fine rows `i * columns .. (i + 1) * columns`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Grid {
    pub(crate) columns: InvariantDivisor,
    pub(crate) rows: InvariantDivisor,
    pub(crate) n: InvariantDivisor,
}

impl Grid {
    /// The most square grid of `n` cells: `columns` the largest divisor of
    /// `n` not above `sqrt(n)`, so `columns <= rows`. Squares give
    /// `sqrt(n) x sqrt(n)`, `2^(2k+1)` gives `2^k x 2^(k+1)`, and a prime
    /// gives `1 x n`. O(sqrt(n)) time, paid once per constructor.
    ///
    /// For samplers that stratify cells only (regular, jittered): each side
    /// must be at most 2^24.
    pub(crate) fn most_square(sampler: SamplerKind, n: u32) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        let (columns, rows) = most_square_sides(n);
        Self::with_sides(sampler, columns, rows)
    }

    /// A `columns x rows` grid for the samplers that stratify cells only:
    /// each side at most 2^24, and at most `u32::MAX` cells.
    pub(crate) fn with_sides(sampler: SamplerKind, columns: u32, rows: u32) -> Result<Self, Error> {
        if columns == 0 || rows == 0 {
            return Err(Error::ZeroGridSide { columns, rows });
        }
        if columns > MAX_STRATA || rows > MAX_STRATA {
            return Err(Error::GridTooFine {
                sampler,
                columns,
                rows,
            });
        }
        let cells = columns as u64 * rows as u64;
        if cells > u32::MAX as u64 {
            return Err(Error::TooManySamples {
                sampler,
                requested: cells,
                max: u32::MAX as u64,
                reason: "sample indices are u32",
            });
        }
        Ok(Self::new(columns, rows))
    }

    /// The most square grid of `n` cells for the samplers that also cut
    /// each axis into `n` fine strata (n-rooks, multi-jittered): `n` at most
    /// 2^24.
    pub(crate) fn latin(sampler: SamplerKind, n: u32) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        if n > MAX_STRATA {
            return Err(Error::TooManySamples {
                sampler,
                requested: n as u64,
                max: MAX_STRATA as u64,
                reason: "the rook condition needs n distinct f32 columns in [0, 1), \
                         and f32 has 2^24 at equal spacing",
            });
        }
        let (columns, rows) = most_square_sides(n);
        Ok(Self::new(columns, rows))
    }

    const fn new(columns: u32, rows: u32) -> Self {
        Self {
            columns: InvariantDivisor::new(columns),
            rows: InvariantDivisor::new(rows),
            n: InvariantDivisor::new(columns * rows),
        }
    }

    /// Number of columns.
    #[inline(always)]
    pub(crate) const fn columns(&self) -> u32 {
        self.columns.get()
    }

    /// Number of rows.
    #[inline(always)]
    pub(crate) const fn rows(&self) -> u32 {
        self.rows.get()
    }

    /// Number of cells, `columns * rows`.
    #[inline(always)]
    pub(crate) const fn len(&self) -> u32 {
        self.n.get()
    }

    /// `(row, column)` of cell `cell`. `POW2` promises a power-of-two `n`
    /// (so both sides are powers of two too): a shift and a mask.
    #[inline(always)]
    pub(crate) const fn cell<const POW2: bool>(&self, cell: u32) -> (u32, u32) {
        self.columns.div_rem_in::<POW2>(cell)
    }

    /// The point of a Latin grid sampler (multi-jittered, correlated
    /// multi-jittered) in cell `cell` at `(row, column)`, in the fine column
    /// `column * rows + sub_column` and fine row `row * columns + sub_row`
    /// that the sampler's shuffles picked, jittered uniformly inside that
    /// fine cell by `seed`.
    #[inline(always)]
    pub(crate) fn latin_point<const POW2: bool>(
        &self,
        cell: u32,
        (row, column): (u32, u32),
        (sub_column, sub_row): (u32, u32),
        seed: u32,
    ) -> Vec2 {
        Vec2::new(
            self.n.stratum_to_unit_f32_in::<POW2>(
                column * self.rows() + sub_column,
                rand_u32(cell, seed ^ salt::JITTER_X),
            ),
            self.n.stratum_to_unit_f32_in::<POW2>(
                row * self.columns() + sub_row,
                rand_u32(cell, seed ^ salt::JITTER_Y),
            ),
        )
    }
}

/// `(columns, rows)` of the most square grid of `n >= 1` cells (see
/// [`Grid::most_square`]).
pub(crate) fn most_square_sides(n: u32) -> (u32, u32) {
    debug_assert!(n >= 1);
    let mut columns = n.isqrt();
    while n % columns != 0 {
        columns -= 1;
    }
    (columns, n / columns)
}

/// One pattern of a grid sampler with its per-pattern work done (the
/// pattern hash, its permutations, tables): what `sample` and `fill` share,
/// so that the two cannot differ.
pub(crate) trait GridPattern {
    /// The sampler's grid.
    fn grid(&self) -> &Grid;

    /// Sample `index`. `POW2` promises a power-of-two `n`, for a
    /// branch-free `fill` loop.
    fn point<const POW2: bool>(&self, index: u32) -> Vec2;
}

/// `fill` for every grid sampler: the prepared pattern's points `0..out.len()`,
/// with the power-of-two case chosen once per call.
#[inline(always)]
pub(crate) fn fill_grid<P: GridPattern>(pattern: &P, out: &mut [Vec2]) {
    check_fill_len(out.len(), pattern.grid().len());
    if pattern.grid().n.is_power_of_two() {
        for (index, point) in (0..).zip(out.iter_mut()) {
            *point = pattern.point::<true>(index);
        }
    } else {
        for (index, point) in (0..).zip(out.iter_mut()) {
            *point = pattern.point::<false>(index);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn most_square_sides_picks_the_closest_divisors() {
        assert_eq!(most_square_sides(1), (1, 1));
        assert_eq!(most_square_sides(16), (4, 4));
        assert_eq!(most_square_sides(32), (4, 8));
        assert_eq!(most_square_sides(100), (10, 10));
        assert_eq!(most_square_sides(12), (3, 4));
        assert_eq!(most_square_sides(13), (1, 13));
        assert_eq!(most_square_sides(u32::MAX), (65_535, 65_537));
    }

    #[test]
    fn a_prime_above_2_pow_24_says_why_it_has_no_grid() {
        let err = Grid::most_square(SamplerKind::Jittered, 16_777_259).unwrap_err();
        assert_eq!(
            err,
            Error::GridTooFine {
                sampler: SamplerKind::Jittered,
                columns: 1,
                rows: 16_777_259
            }
        );
        let message = std::format!("{err}");
        assert!(message.contains("1 x 16777259"), "{message}");
        assert!(message.contains("2^24"), "{message}");
    }
}
