use glam::Vec2;

use crate::primitives::{Permutation, hash_combine, hash_u32, salt};
use crate::sampler::{SMALL_TABLE, Sampler2D, debug_check_index, small_table};
use crate::samplers::grid::{Grid, GridPattern, fill_grid};
use crate::{Error, SamplerKind};

/// Multi-jittered sampling: jittered on a coarse `columns x rows` grid and
/// n-rooks on the fine `n x n` grid at the same time.
///
/// # Properties
///
/// - Stratified: exactly one point in each cell of the `columns x rows` grid
///   (`columns * rows = n`, the most square factorisation, `columns <= rows`).
/// - Latin: exactly one point in each of the `n` columns and `n` rows of the
///   fine grid, checked exactly on the f32 values.
/// - As in Chiu, Shirley & Wang, each coarse column shuffles its fine
///   sub-columns independently (and each coarse row its sub-rows); compare
///   [`CorrelatedMultiJittered`](crate::CorrelatedMultiJittered), which
///   shares one shuffle and spreads points more evenly.
/// - For a prime `n` the coarse grid is `1 x n`, so the set is n-rooks with
///   the y strata of jittered: no extra 2D stratification.
///
/// # Cost
///
/// One hash of the pattern, two [`hash_combine`] for the per-column and
/// per-row shuffles, three [`permute`](crate::primitives::permute) (expected under
/// two rounds each) and two [`rand_u32`](crate::primitives::rand_u32) per sample; no division (the sampler
/// stores reciprocals of its lengths). `fill` hashes the pattern once and
/// tabulates the per-column and per-row shuffle seeds (for grids up to 256 x
/// 256); the three permutes per sample remain.
///
/// # Limits
///
/// `n` at most 2^24 ([`MultiJittered::MAX_SAMPLES`]), the number of f32
/// strata in `[0, 1)`. The fine grid is never formed as `n * n`, so nothing
/// overflows. In release builds an index at or above `len()` returns one of
/// the set's points.
///
/// # Examples
///
/// ```
/// use wellspread::{MultiJittered, Sampler2D};
/// let mj = MultiJittered::new(16)?; // 4 x 4 coarse, 16 x 16 fine
/// let mut fine_columns = [0; 16];
/// let mut coarse_cells = [0; 16];
/// for i in 0..16 {
///     let p = mj.sample(i, 2);
///     fine_columns[(p.x * 16.0) as usize] += 1;
///     coarse_cells[(p.y * 4.0) as usize * 4 + (p.x * 4.0) as usize] += 1;
/// }
/// assert_eq!(fine_columns, [1; 16]);
/// assert_eq!(coarse_cells, [1; 16]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Chiu, Shirley & Wang 1994, "Multi-jittered sampling", Graphics Gems IV.
/// Random access replaces their table shuffles with Kensler's (2013) hashed
/// permutations: column `c`'s shuffle is `permute(_, rows, hash(seed, c))`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MultiJittered {
    grid: Grid,
}

impl MultiJittered {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = crate::primitives::MAX_STRATA;

    /// A multi-jittered set of `n` points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`MultiJittered::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        Grid::latin(SamplerKind::MultiJittered, n).map(|grid| Self { grid })
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

/// One pattern of [`MultiJittered`]: its hash, the order of the cells, and
/// each coarse column's and row's shuffle pattern (`column_pattern(column)`
/// shuffles that column's sub-columns, `row_pattern(row)` that row's
/// sub-rows), computed or looked up.
struct MultiJitteredPattern<'a, C, R> {
    grid: &'a Grid,
    seed: u32,
    order: Permutation,
    column_pattern: C,
    row_pattern: R,
}

impl<C: Fn(u32) -> u32, R: Fn(u32) -> u32> GridPattern for MultiJitteredPattern<'_, C, R> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn point<const POW2: bool>(&self, index: u32) -> Vec2 {
        let grid = self.grid;
        let cell = self.order.apply(index);
        let (row, column) = grid.cell::<POW2>(cell);
        // Coarse column `column` holds one point per coarse row: the column's
        // own shuffle of its rows picks which fine column each point takes.
        // Likewise for rows. Distinct shuffles per column make it Chiu et al.'s
        // (uncorrelated) multi-jitter.
        let sub_column = grid
            .rows
            .permutation_in::<POW2>((self.column_pattern)(column))
            .apply(row);
        let sub_row = grid
            .columns
            .permutation_in::<POW2>((self.row_pattern)(row))
            .apply(column);
        grid.latin_point::<POW2>(cell, (row, column), (sub_column, sub_row), self.seed)
    }
}

impl MultiJittered {
    fn pattern(
        &self,
        pattern: u32,
    ) -> MultiJitteredPattern<'_, impl Fn(u32) -> u32, impl Fn(u32) -> u32> {
        let seed = hash_u32(pattern);
        MultiJitteredPattern {
            grid: &self.grid,
            seed,
            order: self.grid.n.permutation(seed ^ salt::ORDER),
            column_pattern: move |column| hash_combine(seed ^ salt::SHUFFLE_X, column),
            row_pattern: move |row| hash_combine(seed ^ salt::SHUFFLE_Y, row),
        }
    }
}

impl Sampler2D for MultiJittered {
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
            // Each column's and each row's shuffle pattern costs two hashes;
            // there are only `columns + rows` of them, so tabulate them once.
            let column_patterns = small_table(columns, &computed.column_pattern);
            let row_patterns = small_table(rows, &computed.row_pattern);
            let tabled = MultiJitteredPattern {
                column_pattern: |column: u32| column_patterns[column as usize],
                row_pattern: |row: u32| row_patterns[row as usize],
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
