use glam::Vec2;

use super::{Grid, GridPattern, Jitter, SMALL_TABLE, fill_grid, small_table};
use crate::error::Error;
use crate::primitives::{MAX_STRATA, Permutation, derived_key, hash_u32, salt};
use crate::samplers::SamplerKind;
use crate::traits::{DomainSampler, Sampler2D};

/// Correlated multi-jittered sampling (Kensler 2013): multi-jitter in which
/// every coarse column uses the same shuffle of its fine sub-columns (and every
/// coarse row the same shuffle of its sub-rows).
///
/// # Properties
///
/// - Stratified on the coarse grid and Latin on the fine grid, as
///   [`MultiJittered`](crate::MultiJittered).
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
/// `sample`: one hash of the pattern and three 5-operation key derivations,
/// then three permutations (the cells, and the two shared shuffles: a
/// Fisher-Yates shuffle for sides up to 8), two
/// [`rand_u32`](crate::primitives::rand_u32) and two fixed-point stratum
/// conversions; no division, no table. `fill` builds the two shared
/// shuffles once per pattern (as tables for sides 9 to 256), so a sample
/// pays one permutation and two lookups.
///
/// # Limits
///
/// `n` at most [`CorrelatedMultiJittered::MAX_SAMPLES`]. In release builds
/// an index at or above `len()` returns one of the set's points.
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
/// 13-01 (`cmj`, listing 4, including the shuffle of sample order). The
/// permutation keys here are derived from a hash of the pattern rather than
/// Kensler's `p * constant`, which is 0 for every key at pattern 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CorrelatedMultiJittered {
    grid: Grid,
}

impl CorrelatedMultiJittered {
    /// The largest `n` accepted: 2^24, as for
    /// [`NRooks`](crate::NRooks::MAX_SAMPLES).
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

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

impl Sampler2D for CorrelatedMultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.grid.len()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        self.prepare(pattern).point(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        let computed = self.prepare(pattern);
        let (columns, rows) = (self.grid.columns(), self.grid.rows());
        // Short shuffles are already one nibble lookup; longer ones up to
        // SMALL_TABLE elements are hashed once per element here instead of
        // once per sample.
        let short = rows <= crate::primitives::SHORT_LEN;
        if !short && columns as usize <= SMALL_TABLE && rows as usize <= SMALL_TABLE {
            let tabled = CorrelatedMultiJitteredPattern {
                grid: computed.grid,
                order: computed.order,
                sub_columns: ShuffleTable(small_table(rows, |row| computed.sub_columns.apply(row))),
                sub_rows: ShuffleTable(small_table(columns, |column| {
                    computed.sub_rows.apply(column)
                })),
                jitter: computed.jitter,
            };
            fill_grid(&tabled, out);
        } else {
            fill_grid(&computed, out);
        }
    }
}

/// One pattern of [`CorrelatedMultiJittered`]: the order of the cells, the
/// two shared shuffles (`sub_columns`: of the rows, shared by every column;
/// `sub_rows`: of the columns, shared by every row), permutations or
/// tables of them, and the jitter.
struct CorrelatedMultiJitteredPattern<'a, S> {
    grid: &'a Grid,
    order: Permutation,
    sub_columns: S,
    sub_rows: S,
    jitter: Jitter,
}

/// A shared shuffle, applied lane by lane.
trait Shuffle {
    fn shuffle<const N: usize>(&self, index: [u32; N]) -> [u32; N];
}

impl Shuffle for Permutation {
    #[inline(always)]
    fn shuffle<const N: usize>(&self, index: [u32; N]) -> [u32; N] {
        self.apply_lanes(index)
    }
}

/// A shuffle of at most [`SMALL_TABLE`] elements, written out.
struct ShuffleTable([u32; SMALL_TABLE]);

impl Shuffle for ShuffleTable {
    #[inline(always)]
    fn shuffle<const N: usize>(&self, index: [u32; N]) -> [u32; N] {
        let mut out = index;
        for i in &mut out {
            *i = self.0[*i as usize % SMALL_TABLE];
        }
        out
    }
}

impl<S: Shuffle> GridPattern for CorrelatedMultiJitteredPattern<'_, S> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let cell = self.order.apply_lanes(index);
        let (row, column) = self.grid.cells::<POW2, N>(cell);
        // One shuffle for all columns, one for all rows: Kensler's
        // correlation.
        let sub = (self.sub_columns.shuffle(row), self.sub_rows.shuffle(column));
        self.grid
            .latin_points::<POW2, N>(cell, (row, column), sub, &self.jitter)
    }
}

impl CorrelatedMultiJittered {
    /// The pattern with its three permutations; keys from one hash of the
    /// pattern by three cheap derivations.
    #[inline(always)]
    fn prepare(&self, pattern: u32) -> CorrelatedMultiJitteredPattern<'_, Permutation> {
        let pattern_hash = hash_u32(pattern);
        let grid = &self.grid;
        CorrelatedMultiJitteredPattern {
            grid,
            order: grid.cell_order(pattern_hash),
            sub_columns: Permutation::new(grid.rows(), derived_key(pattern_hash, salt::SHUFFLE_X)),
            sub_rows: Permutation::new(grid.columns(), derived_key(pattern_hash, salt::SHUFFLE_Y)),
            jitter: Jitter::new(pattern_hash),
        }
    }
}

/// A domain's draws: 2D the sampler's own set, 1D stratified, 3D and 4D
/// padded ([`DomainSampler`]'s defaults).
impl DomainSampler for CorrelatedMultiJittered {}
