//! The grid family ([`Regular`], [`Jittered`], [`NRooks`],
//! [`MultiJittered`], [`CorrelatedMultiJittered`], [`BlueMultiJittered`])
//! and its core: the
//! `columns x rows` shape, its input checks, the lengths with their
//! reciprocals, the cell mapping, and the loop that runs a prepared pattern
//! over a slice with the power-of-two case chosen once per call. Each
//! sampler's file holds its constructors, its point formula and its trait
//! impls, calling these helpers.
//!
//! [`Regular`]: crate::Regular
//! [`Jittered`]: crate::Jittered
//! [`NRooks`]: crate::NRooks
//! [`MultiJittered`]: crate::MultiJittered
//! [`CorrelatedMultiJittered`]: crate::CorrelatedMultiJittered
//! [`BlueMultiJittered`]: crate::BlueMultiJittered

use glam::Vec2;

mod blue_multi_jittered;
mod correlated_multi_jittered;
mod jittered;
mod multi_jittered;
mod n_rooks;
mod regular;

pub use blue_multi_jittered::BlueMultiJittered;
pub use correlated_multi_jittered::CorrelatedMultiJittered;
pub use jittered::Jittered;
pub use multi_jittered::MultiJittered;
pub use n_rooks::NRooks;
pub use regular::Regular;

use crate::error::Error;
use crate::primitives::{InvariantDivisor, MAX_STRATA, Permutation, derived_key, rand_u32, salt};
use crate::samplers::SamplerKind;
use crate::simd::{self, Kernel};
use crate::traits::{check_fill_len, debug_check_index};

/// Entries of the stack tables some `fill` overrides build for per-row or
/// per-column work (1 KiB of u32 each): enough for the coarse grid of every
/// n up to 65536, small enough for any stack.
pub(crate) const SMALL_TABLE: usize = 256;

/// `f(0), f(1), ..., f(len - 1)` in a stack table of [`SMALL_TABLE`]
/// entries (`len <= SMALL_TABLE`), for the per-row and per-column work a
/// `fill` hoists out of its loop.
#[inline(always)]
pub(crate) fn small_table(len: u32, f: impl Fn(u32) -> u32) -> [u32; SMALL_TABLE] {
    debug_assert!(len as usize <= SMALL_TABLE);
    let mut table = [0; SMALL_TABLE];
    for (i, entry) in (0..len).zip(table.iter_mut()) {
        *entry = f(i);
    }
    table
}

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
                sampler: sampler.name(),
                columns,
                rows,
            });
        }
        let cells = columns as u64 * rows as u64;
        if cells > u32::MAX as u64 {
            return Err(Error::TooManySamples {
                sampler: sampler.name(),
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
                sampler: sampler.name(),
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

    /// The order in which pattern `pattern_hash`'s indices visit the
    /// cells: a permutation of `0..n` keyed by
    /// `derived_key(pattern_hash, salt::ORDER)`. Every grid sampler but
    /// [`NRooks`] (which has no cells to order) shuffles its
    /// indices with it, so that padded dimension pairs sharing an index are
    /// not correlated.
    #[inline(always)]
    pub(crate) fn cell_order(&self, pattern_hash: u32) -> Permutation {
        Permutation::new(self.len(), derived_key(pattern_hash, salt::ORDER))
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

    /// [`cell`](Self::cell) of every lane: `(rows, columns)`.
    #[inline(always)]
    pub(crate) fn cells<const POW2: bool, const N: usize>(
        &self,
        cell: [u32; N],
    ) -> ([u32; N], [u32; N]) {
        let (mut row, mut column) = ([0; N], [0; N]);
        for lane in 0..N {
            (row[lane], column[lane]) = self.cell::<POW2>(cell[lane]);
        }
        (row, column)
    }

    /// The point of coarse cell `cell` at fraction `bits / 2^32` of the way
    /// across it in x and y (regular, jittered).
    #[inline(always)]
    pub(crate) fn cell_point<const POW2: bool>(
        &self,
        cell: u32,
        (x_bits, y_bits): (u32, u32),
    ) -> Vec2 {
        let (row, column) = self.cell::<POW2>(cell);
        Vec2::new(
            self.columns.stratum_to_unit_f32_in::<POW2>(column, x_bits),
            self.rows.stratum_to_unit_f32_in::<POW2>(row, y_bits),
        )
    }

    /// The points of a Latin grid sampler (multi-jittered, correlated
    /// multi-jittered), one lane each: the point of cell `cell` at `(row,
    /// column)` lies in the fine column `column * rows + sub_column` and
    /// the fine row `row * columns + sub_row` that the sampler's shuffles
    /// picked, jittered uniformly inside that fine cell.
    #[inline(always)]
    pub(crate) fn latin_points<const POW2: bool, const N: usize>(
        &self,
        cell: [u32; N],
        (row, column): ([u32; N], [u32; N]),
        (sub_column, sub_row): ([u32; N], [u32; N]),
        jitter: &impl CellOffset,
    ) -> [Vec2; N] {
        let mut out = [Vec2::ZERO; N];
        for (lane, point) in out.iter_mut().enumerate() {
            let (x_bits, y_bits) = jitter.bits(cell[lane]);
            *point = Vec2::new(
                self.n.stratum_to_unit_f32_in::<POW2>(
                    column[lane] * self.rows() + sub_column[lane],
                    x_bits,
                ),
                self.n.stratum_to_unit_f32_in::<POW2>(
                    row[lane] * self.columns() + sub_row[lane],
                    y_bits,
                ),
            );
        }
        out
    }
}

/// Where inside its cell or stratum a point lands: the fraction
/// `bits / 2^32` of the way across, per coordinate, for the point keyed
/// `key`.
pub(crate) trait CellOffset {
    /// The x and y fractions of the point keyed `key`, in 0.32 fixed point.
    fn bits(&self, key: u32) -> (u32, u32);
}

/// The two jitter seeds of one pattern: where inside its stratum each
/// coordinate of a point lands, as 32 random bits per coordinate from
/// [`rand_u32`] (Kensler 2013's `randfloat` hash).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Jitter {
    x: u32,
    y: u32,
}

impl Jitter {
    /// The jitter seeds of the pattern whose hash is `pattern_hash`.
    #[inline(always)]
    pub(crate) const fn new(pattern_hash: u32) -> Self {
        Self {
            x: pattern_hash ^ salt::JITTER_X,
            y: pattern_hash ^ salt::JITTER_Y,
        }
    }
}

impl CellOffset for Jitter {
    #[inline(always)]
    fn bits(&self, key: u32) -> (u32, u32) {
        (rand_u32(key, self.x), rand_u32(key, self.y))
    }
}

/// The offset of [`Regular`]: half-way bits put every point at its cell's
/// centre, to within `2^-24`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Centre;

impl CellOffset for Centre {
    #[inline(always)]
    fn bits(&self, _key: u32) -> (u32, u32) {
        (1 << 31, 1 << 31)
    }
}

/// `(columns, rows)` of the most square grid of `n >= 1` cells (see
/// [`Grid::most_square`]).
pub(crate) fn most_square_sides(n: u32) -> (u32, u32) {
    debug_assert!(n >= 1);
    let mut columns = n.isqrt();
    while !n.is_multiple_of(columns) {
        columns -= 1;
    }
    (columns, n / columns)
}

/// One pattern of a grid sampler with its per-pattern work done (the
/// `pattern_hash`, its permutations, tables): what `sample` and `fill` share,
/// so that the two cannot differ.
pub(crate) trait GridPattern {
    /// The sampler's grid.
    fn grid(&self) -> &Grid;

    /// Points `index[0..N]`, one lane each (see [`Kernel`]). `POW2`
    /// promises a power-of-two `n` (so both sides too), for shifts in place
    /// of the multiply-high divisions.
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N];

    /// Sample `index` alone, reduced modulo `n` first (release builds only
    /// see a bad index; debug builds reject it).
    #[inline(always)]
    fn point(&self, index: u32) -> Vec2 {
        let n = self.grid().len();
        debug_check_index(index, n);
        let index = if index < n {
            index
        } else {
            self.grid().n.div_rem(index).1
        };
        self.points::<false, 1>([index])[0]
    }
}

/// A [`GridPattern`] as a [`Kernel`], with `POW2` fixed.
struct GridKernel<'a, P, const POW2: bool>(&'a P);

impl<P: GridPattern, const POW2: bool> Kernel for GridKernel<'_, P, POW2> {
    #[inline(always)]
    fn points<const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        self.0.points::<POW2, N>(index)
    }
}

/// `fill` for every grid sampler: the prepared pattern's points
/// `0..out.len()`, with the power-of-two case chosen once per call.
#[inline]
#[track_caller]
pub(crate) fn fill_grid<P: GridPattern>(pattern: &P, out: &mut [Vec2]) {
    check_fill_len(out.len(), pattern.grid().len());
    if pattern.grid().n.is_power_of_two() {
        simd::fill(&GridKernel::<P, true>(pattern), 0, out);
    } else {
        simd::fill(&GridKernel::<P, false>(pattern), 0, out);
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
                sampler: "jittered",
                columns: 1,
                rows: 16_777_259
            }
        );
        let message = std::format!("{err}");
        assert!(message.contains("1 x 16777259"), "{message}");
        assert!(message.contains("2^24"), "{message}");
    }
}
