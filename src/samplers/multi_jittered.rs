use glam::Vec2;

use crate::Error;
use crate::hash::{Length, Permutation, hash_combine, hash_u32, rand_u32, salt};
use crate::sampler::{
    SMALL_TABLE, Sampler2D, check_fill_len, debug_check_index, most_square_grid, small_table,
};
use crate::samplers::n_rooks::check_rook_count;

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
/// per-row shuffles, three [`permute`](crate::hash::permute) (expected under
/// two rounds each) and two [`rand_u32`] per sample; no division (the sampler
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
    // Lengths carry their reciprocals, so no sample needs a division.
    columns: Length,
    rows: Length,
    n: Length,
}

impl MultiJittered {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = crate::hash::MAX_STRATA;

    /// A multi-jittered set of `n` points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`MultiJittered::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        check_rook_count("multi-jittered", n)?;
        let (columns, rows) = most_square_grid(n);
        Ok(Self {
            columns: Length::new(columns),
            rows: Length::new(rows),
            n: Length::new(n),
        })
    }

    /// Number of coarse grid columns.
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns.get()
    }

    /// Number of coarse grid rows.
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows.get()
    }
}

impl MultiJittered {
    /// Sample `index` given the pattern's hash `seed`, its order permutation
    /// and the per-column and per-row shuffle patterns (`column_pattern(column)`
    /// shuffles that column's sub-columns, `row_pattern(row)` that row's
    /// sub-rows): the one formula `sample` and `fill` share. `POW2` promises
    /// a power-of-two `n` (so grid sides too), for a branch-free `fill` loop.
    #[inline(always)]
    fn point<const POW2: bool>(
        &self,
        seed: u32,
        order: &Permutation,
        column_pattern: impl Fn(u32) -> u32,
        row_pattern: impl Fn(u32) -> u32,
        index: u32,
    ) -> Vec2 {
        let cell = order.apply(index);
        let (row, column) = self.columns.div_rem_in::<POW2>(cell);
        // Coarse column `column` spans fine columns [column * rows, (column +
        // 1) * rows) and holds one point per coarse row: the column's own
        // shuffle of its rows picks which fine column each point takes.
        // Likewise for rows. Distinct shuffles per column make it Chiu et al.'s
        // (uncorrelated) multi-jitter.
        let sub_column = self
            .rows
            .permutation_in::<POW2>(column_pattern(column))
            .apply(row);
        let sub_row = self
            .columns
            .permutation_in::<POW2>(row_pattern(row))
            .apply(column);
        let (columns, rows) = (self.columns.get(), self.rows.get());
        Vec2::new(
            self.n.stratum_to_unit_f32_in::<POW2>(
                column * rows + sub_column,
                rand_u32(cell, seed ^ salt::JITTER_X),
            ),
            self.n.stratum_to_unit_f32_in::<POW2>(
                row * columns + sub_row,
                rand_u32(cell, seed ^ salt::JITTER_Y),
            ),
        )
    }
}

impl Sampler2D for MultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        let seed = hash_u32(pattern);
        self.point::<false>(
            seed,
            &self.n.permutation(seed ^ salt::ORDER),
            |column| hash_combine(seed ^ salt::SHUFFLE_X, column),
            |row| hash_combine(seed ^ salt::SHUFFLE_Y, row),
            index,
        )
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        let seed = hash_u32(pattern);
        let order = self.n.permutation(seed ^ salt::ORDER);
        let (columns, rows) = (self.columns.get(), self.rows.get());
        if columns as usize <= SMALL_TABLE && rows as usize <= SMALL_TABLE {
            // Each column's and each row's shuffle pattern costs two hashes;
            // there are only `columns + rows` of them, so tabulate them once.
            let column_patterns = small_table(columns, |column| {
                hash_combine(seed ^ salt::SHUFFLE_X, column)
            });
            let row_patterns = small_table(rows, |row| hash_combine(seed ^ salt::SHUFFLE_Y, row));
            let (column_pattern, row_pattern) = (
                |column: u32| column_patterns[column as usize],
                |row: u32| row_patterns[row as usize],
            );
            if self.n.is_power_of_two() {
                for (index, point) in (0..).zip(out.iter_mut()) {
                    *point = self.point::<true>(seed, &order, column_pattern, row_pattern, index);
                }
            } else {
                for (index, point) in (0..).zip(out.iter_mut()) {
                    *point = self.point::<false>(seed, &order, column_pattern, row_pattern, index);
                }
            }
        } else {
            for (index, point) in (0..).zip(out.iter_mut()) {
                *point = self.point::<false>(
                    seed,
                    &order,
                    |column| hash_combine(seed ^ salt::SHUFFLE_X, column),
                    |row| hash_combine(seed ^ salt::SHUFFLE_Y, row),
                    index,
                );
            }
        }
    }
}
