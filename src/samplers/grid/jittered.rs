use glam::Vec2;

use super::{CellOffset, Grid, GridPattern, Jitter, fill_grid};
use crate::error::Error;
use crate::primitives::{Permutation, hash_u32};
use crate::samplers::SamplerKind;
use crate::traits::{DomainSampler, Sampler2D};

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
/// `columns * rows = n`: `4 x 4` for 16, `4 x 8` for 32, and for a prime `n`
/// `1 x n` strips, stratified in y only. [`Jittered::with_grid`] takes any
/// shape.
///
/// # Cost
///
/// Per sample: one permutation of the cells (a nibble lookup for n <= 8, else
/// four or five rounds of about eight integer operations), two
/// [`rand_u32`](crate::primitives::rand_u32) for the jitter, two fixed-point
/// stratum conversions; no division. `sample` adds one hash of the pattern and
/// one 5-operation key derivation.
///
/// # Limits
///
/// `columns` and `rows` at most 2^24 (f32 cannot separate more strata) and
/// `columns * rows` at most `u32::MAX`.
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

    /// Jittered points of a `columns x rows` grid.
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

    #[inline(always)]
    fn prepare(&self, pattern: u32) -> JitteredPattern<'_, Jitter> {
        let pattern_hash = hash_u32(pattern);
        JitteredPattern {
            grid: &self.grid,
            order: self.grid.cell_order(pattern_hash),
            offset: Jitter::new(pattern_hash),
        }
    }
}

impl Sampler2D for Jittered {
    #[inline]
    fn len(&self) -> u32 {
        self.grid.len()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        self.prepare(pattern).point(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        fill_grid(&self.prepare(pattern), out);
    }
}

/// A domain's draws: 2D the sampler's own set, 1D stratified, 3D and 4D
/// padded ([`DomainSampler`]'s defaults).
impl DomainSampler for Jittered {}

/// One pattern of [`Jittered`] (offset [`Jitter`]) or of
/// [`Regular`](crate::Regular) (offset [`Centre`](super::Centre)): the
/// order in which indices visit the cells, and where in its cell each
/// point lands.
pub(super) struct JitteredPattern<'a, O> {
    pub(super) grid: &'a Grid,
    pub(super) order: Permutation,
    pub(super) offset: O,
}

impl<O: CellOffset> GridPattern for JitteredPattern<'_, O> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let mut out = [Vec2::ZERO; N];
        for (point, cell) in out.iter_mut().zip(self.order.apply_lanes(index)) {
            *point = self.grid.cell_point::<POW2>(cell, self.offset.bits(cell));
        }
        out
    }
}
