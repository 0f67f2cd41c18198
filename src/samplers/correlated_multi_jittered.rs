use glam::Vec2;

use crate::Error;
use crate::hash::{Length, Permutation, hash_u32, rand_u32, salt};
use crate::sampler::{
    SMALL_TABLE, Sampler2D, check_fill_len, debug_check_index, most_square_grid, small_table,
};
use crate::samplers::n_rooks::check_rook_count;

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
/// One hash of the pattern, three [`permute`](crate::hash::permute)
/// (expected under two rounds each) and two [`rand_u32`] per sample, plus two
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
    // Lengths carry their reciprocals, so no sample needs a division.
    columns: Length,
    rows: Length,
    n: Length,
}

impl CorrelatedMultiJittered {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = crate::hash::MAX_STRATA;

    /// A correlated multi-jittered set of `n` points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`CorrelatedMultiJittered::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        check_rook_count("correlated-multi-jittered", n)?;
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

impl CorrelatedMultiJittered {
    /// Sample `index` given the pattern's hash `seed`, its order permutation
    /// and the shared shuffles (`sub_column(row)`, `sub_row(column)`): the
    /// one formula `sample` and `fill` share. `POW2` promises a power-of-two
    /// `n` (so grid sides too), for a branch-free `fill` loop.
    #[inline(always)]
    fn point<const POW2: bool>(
        &self,
        seed: u32,
        order: &Permutation,
        sub_column: impl Fn(u32) -> u32,
        sub_row: impl Fn(u32) -> u32,
        index: u32,
    ) -> Vec2 {
        let cell = order.apply(index);
        let (row, column) = self.columns.div_rem_in::<POW2>(cell);
        // One shuffle for all columns, one for all rows: Kensler's
        // correlation. Fine column = column * rows + shuffled row.
        let (columns, rows) = (self.columns.get(), self.rows.get());
        Vec2::new(
            self.n.stratum_to_unit_f32_in::<POW2>(
                column * rows + sub_column(row),
                rand_u32(cell, seed ^ salt::JITTER_X),
            ),
            self.n.stratum_to_unit_f32_in::<POW2>(
                row * columns + sub_row(column),
                rand_u32(cell, seed ^ salt::JITTER_Y),
            ),
        )
    }
}

impl Sampler2D for CorrelatedMultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        let seed = hash_u32(pattern);
        let shuffle_x = self.rows.permutation(seed ^ salt::SHUFFLE_X);
        let shuffle_y = self.columns.permutation(seed ^ salt::SHUFFLE_Y);
        self.point::<false>(
            seed,
            &self.n.permutation(seed ^ salt::ORDER),
            |row| shuffle_x.apply(row),
            |column| shuffle_y.apply(column),
            index,
        )
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        let seed = hash_u32(pattern);
        let order = self.n.permutation(seed ^ salt::ORDER);
        let shuffle_x = self.rows.permutation(seed ^ salt::SHUFFLE_X);
        let shuffle_y = self.columns.permutation(seed ^ salt::SHUFFLE_Y);
        let (columns, rows) = (self.columns.get(), self.rows.get());
        if columns as usize <= SMALL_TABLE && rows as usize <= SMALL_TABLE {
            // The two shared shuffles have only `rows` and `columns` entries
            // (16 each at n = 256): tabulated once, they replace two of the
            // three permutes per sample with loads.
            let sub_columns = small_table(rows, |row| shuffle_x.apply(row));
            let sub_rows = small_table(columns, |column| shuffle_y.apply(column));
            let (sub_column, sub_row) = (
                |row: u32| sub_columns[row as usize],
                |column: u32| sub_rows[column as usize],
            );
            if self.n.is_power_of_two() {
                for (index, point) in (0..).zip(out.iter_mut()) {
                    *point = self.point::<true>(seed, &order, sub_column, sub_row, index);
                }
            } else {
                for (index, point) in (0..).zip(out.iter_mut()) {
                    *point = self.point::<false>(seed, &order, sub_column, sub_row, index);
                }
            }
        } else {
            for (index, point) in (0..).zip(out.iter_mut()) {
                *point = self.point::<false>(
                    seed,
                    &order,
                    |row| shuffle_x.apply(row),
                    |column| shuffle_y.apply(column),
                    index,
                );
            }
        }
    }
}
