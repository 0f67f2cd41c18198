use glam::Vec2;

use super::{Grid, GridPattern, Jitter, SMALL_TABLE, fill_grid};
use crate::error::Error;
use crate::primitives::{MAX_STRATA, Permutation, hash_u32, salt};
use crate::samplers::SamplerKind;
use crate::traits::{DomainSampler, Sampler2D};

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
/// Per sample: one permutation of the cells, the shuffle of the point's coarse
/// column and of its coarse row (each its own permutation, keyed by a hash of
/// the line: a Fisher-Yates shuffle for sides up to 8), two
/// [`rand_u32`](crate::primitives::rand_u32), two fixed-point stratum
/// conversions; no division. `fill` builds the `columns + rows` line shuffles
/// once per pattern (for sides up to 256), so a sample pays three
/// permutation lookups.
///
/// # Limits
///
/// `n` at most [`MultiJittered::MAX_SAMPLES`]. The fine grid is never
/// formed as `n * n`, so nothing overflows. In release builds an index at
/// or above `len()` returns one of the set's points.
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
/// permutations: column `c`'s shuffle is `permute(_, rows, hash(pattern_hash, c))`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MultiJittered {
    grid: Grid,
}

impl MultiJittered {
    /// The largest `n` accepted: 2^24, as for
    /// [`NRooks`](crate::NRooks::MAX_SAMPLES).
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

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

impl Sampler2D for MultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.grid.len()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        self.prepare(pattern).point(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        // There are only `columns + rows` shuffles, each built from a hash
        // (and a Fisher-Yates shuffle for short sides): build them once and
        // look them up.
        fn tabled<'a, const S: usize>(
            computed: &MultiJitteredPattern<'a, HashedLines>,
        ) -> MultiJitteredPattern<'a, TabledLines<S>> {
            MultiJitteredPattern {
                grid: computed.grid,
                order: computed.order,
                shuffles: TabledLines::new(&computed.shuffles),
                jitter: computed.jitter,
            }
        }
        let computed = self.prepare(pattern);
        // `rows >= columns`: the longer side decides the table.
        let rows = self.grid.rows() as usize;
        if rows <= 16 {
            fill_grid(&tabled::<16>(&computed), out);
        } else if rows <= SMALL_TABLE {
            fill_grid(&tabled::<SMALL_TABLE>(&computed), out);
        } else {
            fill_grid(&computed, out);
        }
    }
}

/// One pattern of [`MultiJittered`]: the order of the cells, each coarse
/// column's shuffle of its sub-columns and each coarse row's shuffle of its
/// sub-rows (hashed or looked up), and the jitter.
struct MultiJitteredPattern<'a, S> {
    grid: &'a Grid,
    order: Permutation,
    shuffles: S,
    jitter: Jitter,
}

/// Where each coarse line's own shuffle comes from. (A trait rather than
/// closures: its methods can be forced inline into the SIMD batch.)
trait LineShuffles {
    /// Coarse column `column`'s shuffle of its `rows` sub-columns.
    fn column(&self, column: u32) -> Permutation;
    /// Coarse row `row`'s shuffle of its `columns` sub-rows.
    fn row(&self, row: u32) -> Permutation;
}

/// Each line's shuffle built from a hash of the line: random access.
#[derive(Clone, Copy)]
struct HashedLines {
    columns: u32,
    rows: u32,
    seed_x: u32,
    seed_y: u32,
}

impl LineShuffles for HashedLines {
    #[inline(always)]
    fn column(&self, column: u32) -> Permutation {
        Permutation::new(self.rows, line_key(self.seed_x, column))
    }

    #[inline(always)]
    fn row(&self, row: u32) -> Permutation {
        Permutation::new(self.columns, line_key(self.seed_y, row))
    }
}

/// Every line's shuffle built once, for `fill` on sides up to `S` (a
/// power of two: 16 for the sample counts renderers use, else
/// [`SMALL_TABLE`]), so that a short set does not pay for a long table.
struct TabledLines<const S: usize> {
    columns: [Permutation; S],
    rows: [Permutation; S],
}

impl<const S: usize> TabledLines<S> {
    fn new(hashed: &HashedLines) -> Self {
        let mut tables = Self {
            columns: [Permutation::default(); S],
            rows: [Permutation::default(); S],
        };
        for (column, shuffle) in (0..hashed.columns).zip(&mut tables.columns) {
            *shuffle = hashed.column(column);
        }
        for (row, shuffle) in (0..hashed.rows).zip(&mut tables.rows) {
            *shuffle = hashed.row(row);
        }
        tables
    }
}

impl<const S: usize> LineShuffles for TabledLines<S> {
    #[inline(always)]
    fn column(&self, column: u32) -> Permutation {
        self.columns[column as usize % S]
    }

    #[inline(always)]
    fn row(&self, row: u32) -> Permutation {
        self.rows[row as usize % S]
    }
}

impl<S: LineShuffles> GridPattern for MultiJitteredPattern<'_, S> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let cell = self.order.apply_lanes(index);
        let (row, column) = self.grid.cells::<POW2, N>(cell);
        // Coarse column `column` holds one point per coarse row: the
        // column's own shuffle of its rows picks which fine column each
        // point takes. Likewise for rows. Distinct shuffles per column make
        // it Chiu et al.'s (uncorrelated) multi-jitter.
        let mut column_shuffles = [Permutation::default(); N];
        let mut row_shuffles = [Permutation::default(); N];
        for lane in 0..N {
            column_shuffles[lane] = self.shuffles.column(column[lane]);
            row_shuffles[lane] = self.shuffles.row(row[lane]);
        }
        let sub = (
            Permutation::apply_each(&column_shuffles, row),
            Permutation::apply_each(&row_shuffles, column),
        );
        self.grid
            .latin_points::<POW2, N>(cell, (row, column), sub, &self.jitter)
    }
}

/// The key of coarse line `line`'s own shuffle, from the pattern's shuffle
/// seed for that axis: a full hash, since every line's shuffle must look
/// independent of its neighbours' (the golden-ratio multiplier spreads
/// consecutive lines over all 32 bits first).
#[inline(always)]
const fn line_key(seed: u32, line: u32) -> u32 {
    hash_u32(seed ^ line.wrapping_mul(salt::GOLDEN_32))
}

impl MultiJittered {
    #[inline(always)]
    fn prepare(&self, pattern: u32) -> MultiJitteredPattern<'_, HashedLines> {
        let pattern_hash = hash_u32(pattern);
        MultiJitteredPattern {
            grid: &self.grid,
            order: self.grid.cell_order(pattern_hash),
            shuffles: HashedLines {
                columns: self.grid.columns(),
                rows: self.grid.rows(),
                seed_x: pattern_hash ^ salt::SHUFFLE_X,
                seed_y: pattern_hash ^ salt::SHUFFLE_Y,
            },
            jitter: Jitter::new(pattern_hash),
        }
    }
}

/// A domain's draws: 2D the sampler's own set, 1D stratified, 3D and 4D
/// padded ([`DomainSampler`]'s defaults).
impl DomainSampler for MultiJittered {}
