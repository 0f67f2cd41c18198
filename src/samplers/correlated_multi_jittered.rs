use glam::Vec2;

use crate::primitives::{Permutation, hash_u32, salt};
use crate::sampler::{SMALL_TABLE, Sampler2D, debug_check_index, small_table};
use crate::samplers::grid::{Grid, GridPattern, fill_grid};
use crate::{Error, SamplerKind};

/// Correlated multi-jittered sampling (Kensler 2013): multi-jitter in which
/// every coarse column uses the same shuffle of its fine sub-columns (and every
/// coarse row the same shuffle of its sub-rows).
///
/// # Properties
///
/// - Stratified: exactly one point in each cell of the `columns x rows` grid
///   (`columns * rows = n`, the most square factorisation, `columns <= rows`).
/// - Latin: exactly one point in each of the `n` columns and `n` rows of the
///   fine grid, checked exactly on the f32 values.
/// - The shared shuffle keeps neighbouring points apart: the mean minimum
///   distance is about twice [`MultiJittered`](crate::MultiJittered)'s (at
///   n = 64 to 256), at about the same L2-star discrepancy. It also makes
///   sample `index` computable in O(1) from two permutations.
/// - For a prime `n` the coarse grid is `1 x n`: the set is n-rooks with no
///   extra 2D stratification. Kensler instead pads to a larger grid and drops
///   samples, which loses the rook property; wellspread keeps it.
///
/// # Cost
///
/// One hash of the pattern, three [`permute`](crate::primitives::permute)
/// (expected under two rounds each) and two [`rand_u32`](crate::primitives::rand_u32) per sample, plus two
/// fixed-point stratum conversions; no division (the sampler stores
/// reciprocals of its lengths). `fill` hashes the pattern once and tabulates
/// the two shared shuffles (for grids up to 256 x 256), leaving one permute
/// per sample.
///
/// # Limits
///
/// `n` at most 2^24 ([`CorrelatedMultiJittered::MAX_SAMPLES`]), the number
/// of f32 strata in `[0, 1)`. In release builds an index at or above `len()`
/// returns one of the set's points.
///
/// # Examples
///
/// ```
/// use wellspread::{CorrelatedMultiJittered, Sampler2D};
/// let cmj = CorrelatedMultiJittered::new(12)?; // 3 x 4 coarse
/// let mut fine_rows = [0; 12];
/// for i in 0..12 {
///     fine_rows[(cmj.sample(i, 0).y * 12.0) as usize] += 1;
/// }
/// assert_eq!(fine_rows, [1; 12]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Kensler 2013, "Correlated Multi-Jittered Sampling", Pixar Technical Memo
/// 13-01 (`cmj`, listing 4, including the shuffle of sample order). Pattern
/// seeds here are salted hashes rather than Kensler's `p * constant`, which
/// collapses every seed to 0 for pattern 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CorrelatedMultiJittered {
    grid: Grid,
}

impl CorrelatedMultiJittered {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = crate::primitives::MAX_STRATA;

    /// A correlated multi-jittered set of `n` points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`CorrelatedMultiJittered::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        Grid::latin(SamplerKind::CorrelatedMultiJittered, n).map(|grid| Self { grid })
    }

    /// Number of coarse grid columns.
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.grid.columns()
    }

    /// Number of coarse grid rows.
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.grid.rows()
    }
}

/// One pattern of [`CorrelatedMultiJittered`]: its hash, the order of the
/// cells, and the two shared shuffles (`sub_column(row)`,
/// `sub_row(column)`), computed or looked up.
struct CorrelatedMultiJitteredPattern<'a, C, R> {
    grid: &'a Grid,
    seed: u32,
    order: Permutation,
    sub_column: C,
    sub_row: R,
}

impl<C: Fn(u32) -> u32, R: Fn(u32) -> u32> GridPattern
    for CorrelatedMultiJitteredPattern<'_, C, R>
{
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn point<const POW2: bool>(&self, index: u32) -> Vec2 {
        let cell = self.order.apply(index);
        let (row, column) = self.grid.cell::<POW2>(cell);
        // One shuffle for all columns, one for all rows: Kensler's
        // correlation.
        let sub = ((self.sub_column)(row), (self.sub_row)(column));
        self.grid
            .latin_point::<POW2>(cell, (row, column), sub, self.seed)
    }
}

impl CorrelatedMultiJittered {
    fn pattern(
        &self,
        pattern: u32,
    ) -> CorrelatedMultiJitteredPattern<'_, impl Fn(u32) -> u32, impl Fn(u32) -> u32> {
        let seed = hash_u32(pattern);
        let shuffle_x = self.grid.rows.permutation(seed ^ salt::SHUFFLE_X);
        let shuffle_y = self.grid.columns.permutation(seed ^ salt::SHUFFLE_Y);
        CorrelatedMultiJitteredPattern {
            grid: &self.grid,
            seed,
            order: self.grid.n.permutation(seed ^ salt::ORDER),
            sub_column: move |row| shuffle_x.apply(row),
            sub_row: move |column| shuffle_y.apply(column),
        }
    }
}

impl Sampler2D for CorrelatedMultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.grid.len()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        self.pattern(pattern).point::<false>(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        let computed = self.pattern(pattern);
        let (columns, rows) = (self.grid.columns(), self.grid.rows());
        if columns as usize <= SMALL_TABLE && rows as usize <= SMALL_TABLE {
            // The two shared shuffles have only `rows` and `columns` entries
            // (16 each at n = 256): tabulated once, they replace two of the
            // three permutes per sample with loads.
            let sub_columns = small_table(rows, &computed.sub_column);
            let sub_rows = small_table(columns, &computed.sub_row);
            let tabled = CorrelatedMultiJitteredPattern {
                sub_column: |row: u32| sub_columns[row as usize],
                sub_row: |column: u32| sub_rows[column as usize],
                grid: computed.grid,
                seed: computed.seed,
                order: computed.order,
            };
            fill_grid(&tabled, out);
        } else {
            fill_grid(&computed, out);
        }
    }
}
