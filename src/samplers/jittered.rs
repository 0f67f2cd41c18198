use glam::Vec2;

use crate::primitives::{Permutation, hash_u32, rand_u32, salt};
use crate::sampler::{Sampler2D, debug_check_index};
use crate::samplers::grid::{Grid, GridPattern, fill_grid};
use crate::{Error, SamplerKind};

/// One uniformly random point in each cell of a `columns x rows` grid
/// (stratified or "jittered" sampling).
///
/// # Properties
///
/// - Stratified: exactly one point in each cell `[c / columns, (c + 1) /
///   columns) x [r / rows, (r + 1) / rows)`, checked exactly on the f32
///   values.
/// - The x and y projections are not Latin: up to `rows` points can share a
///   column of width `1 / n` (use [`MultiJittered`](crate::MultiJittered) for
///   both guarantees).
/// - Error falls as about `n^-3/4` on discontinuous integrands and `n^-1` on
///   smooth ones, against `n^-1/2` for [`Random`](crate::Random).
///
/// [`Jittered::new`] picks the most square grid with `columns <= rows` and
/// `columns * rows = n`; for a prime `n` that is `1 x n` strips, stratified in
/// y only. [`Jittered::with_grid`] takes any shape.
///
/// # Cost
///
/// One hash, one [`permute`](crate::primitives::permute) (expected under two
/// rounds) and two [`rand_u32`] per sample, plus two fixed-point stratum
/// conversions; no division (the sampler stores reciprocals of its lengths).
/// `fill` hashes the pattern once.
///
/// # Limits
///
/// `columns` and `rows` at most 2^24 and `columns * rows` at most `u32::MAX`.
/// Inside a cell the offset is quantised to the `2^-24` grid. In release
/// builds an index at or above `len()` returns a point of the set's grid.
///
/// # Examples
///
/// ```
/// use wellspread::{Jittered, Sampler2D};
/// let jittered = Jittered::new(16)?; // 4 x 4
/// let mut cells = [false; 16];
/// for i in 0..16 {
///     let p = jittered.sample(i, 5);
///     cells[(p.y * 4.0) as usize * 4 + (p.x * 4.0) as usize] = true;
/// }
/// assert!(cells.iter().all(|&hit| hit));
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Cook, Porter & Carpenter 1984, "Distributed ray tracing"; Cook 1986,
/// "Stochastic sampling in computer graphics", ACM TOG 5(1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Jittered {
    grid: Grid,
}

impl Jittered {
    /// `n` jittered points on the most square grid that has `n` cells.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::GridTooFine`] when the
    /// grid would have more than 2^24 rows (a prime above 2^24, or twice one).
    pub fn new(n: u32) -> Result<Self, Error> {
        Grid::most_square(SamplerKind::Jittered, n).map(|grid| Self { grid })
    }

    /// Jittered points on a `columns x rows` grid.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroGridSide`] if either side is 0; [`Error::GridTooFine`]
    /// if a side exceeds 2^24; [`Error::TooManySamples`] if `columns * rows`
    /// exceeds `u32::MAX`.
    pub fn with_grid(columns: u32, rows: u32) -> Result<Self, Error> {
        Grid::with_sides(SamplerKind::Jittered, columns, rows).map(|grid| Self { grid })
    }

    /// Number of grid columns (strata along x).
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.grid.columns()
    }

    /// Number of grid rows (strata along y).
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.grid.rows()
    }

    fn pattern(&self, pattern: u32) -> JitteredPattern<'_> {
        let seed = hash_u32(pattern);
        JitteredPattern {
            grid: &self.grid,
            seed,
            order: self.grid.n.permutation(seed ^ salt::ORDER),
        }
    }
}

/// One pattern of [`Jittered`]: its hash and the order of the cells.
struct JitteredPattern<'a> {
    grid: &'a Grid,
    seed: u32,
    order: Permutation,
}

impl GridPattern for JitteredPattern<'_> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn point<const POW2: bool>(&self, index: u32) -> Vec2 {
        let cell = self.order.apply(index);
        let (row, column) = self.grid.cell::<POW2>(cell);
        Vec2::new(
            self.grid
                .columns
                .stratum_to_unit_f32_in::<POW2>(column, rand_u32(cell, self.seed ^ salt::JITTER_X)),
            self.grid
                .rows
                .stratum_to_unit_f32_in::<POW2>(row, rand_u32(cell, self.seed ^ salt::JITTER_Y)),
        )
    }
}

impl Sampler2D for Jittered {
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
        fill_grid(&self.pattern(pattern), out);
    }
}
