use glam::Vec2;

use crate::Error;
use crate::hash::{hash_u32, permute, rand_u32, salt, stratum_to_unit_f32};
use crate::sampler::{Sampler2D, most_square_grid};
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
/// One hash of the pattern, three [`permute`] (expected under two rounds
/// each) and two [`rand_u32`] per sample, plus two fixed-point stratum
/// conversions.
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
    columns: u32,
    rows: u32,
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
        Ok(Self { columns, rows })
    }

    /// Number of coarse grid columns.
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns
    }

    /// Number of coarse grid rows.
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows
    }
}

impl Sampler2D for CorrelatedMultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.columns * self.rows
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        let n = self.len();
        debug_assert!(index < n, "index {index} out of range 0..{n}");
        let seed = hash_u32(pattern);
        let cell = permute(index, n, seed ^ salt::ORDER);
        let (column, row) = (cell % self.columns, cell / self.columns);
        // One shuffle for all columns, one for all rows: Kensler's
        // correlation. Fine column = column * rows + shuffled row.
        let sub_column = permute(row, self.rows, seed ^ salt::SHUFFLE_X);
        let sub_row = permute(column, self.columns, seed ^ salt::SHUFFLE_Y);
        Vec2::new(
            stratum_to_unit_f32(
                column * self.rows + sub_column,
                n,
                rand_u32(cell, seed ^ salt::JITTER_X),
            ),
            stratum_to_unit_f32(
                row * self.columns + sub_row,
                n,
                rand_u32(cell, seed ^ salt::JITTER_Y),
            ),
        )
    }
}
