use glam::Vec2;

use super::jittered::JitteredPattern;
use super::{Centre, Grid, GridPattern, fill_grid};
use crate::primitives::{Permutation, derived_key, hash_u32, salt};
use crate::simd::Isa;
use crate::traits::{FillOn, Sampler2D};
use crate::{Error, SamplerKind};

/// Cell centres of a `columns x rows` grid: the deterministic baseline that
/// aliases.
///
/// # Properties
///
/// - Stratified: exactly one point in each cell of the `columns x rows` grid,
///   at its centre (to within `2^-24`, the f32 grid step below 1.0).
/// - Every pattern gives the same set; the pattern only shuffles the order in
///   which indices visit the cells, so that further dimension pairs padded
///   with other patterns are not correlated with this one.
///
/// [`Regular::new`] picks the most square grid with `columns <= rows` and
/// `columns * rows = n`: `4 x 4` for 16, `4 x 8` for 32, and `1 x n` strips
/// for a prime `n`. [`Regular::with_grid`] takes any shape.
///
/// # Cost
///
/// Per sample: one permutation lookup (a nibble of the pattern's shuffle for
/// n <= 8, else four or five rounds of about eight integer operations) and two
/// fixed-point stratum conversions; no division (the grid stores the
/// reciprocals of its sides). `sample` adds one hash of the pattern and one
/// 5-operation key derivation.
///
/// # Limits
///
/// `columns` and `rows` at most 2^24 (f32 cannot separate more strata) and
/// `columns * rows` at most `u32::MAX`. In release builds an index at or above
/// `len()` returns one of the set's points.
///
/// # Examples
///
/// ```
/// use wellspread::{Regular, Sampler2D};
/// let regular = Regular::new(4)?; // 2 x 2
/// let mut xs: Vec<f32> = (0..4).map(|i| regular.sample(i, 9).x).collect();
/// xs.sort_by(f32::total_cmp);
/// assert_eq!(xs, [0.25, 0.25, 0.75, 0.75]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Mitchell 1987, "Generating antialiased images at low sampling densities"
/// (why regular grids alias); Shirley 1991 uses it as the baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Regular {
    grid: Grid,
}

impl Regular {
    /// `n` cell centres on the most square grid that has `n` cells.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::GridTooFine`] when the
    /// grid would have more than 2^24 rows (a prime above 2^24, or twice one).
    pub fn new(n: u32) -> Result<Self, Error> {
        Grid::most_square(SamplerKind::Regular, n).map(|grid| Self { grid })
    }

    /// Cell centres of a `columns x rows` grid.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroGridSide`] if either side is 0; [`Error::GridTooFine`]
    /// if a side exceeds 2^24; [`Error::TooManySamples`] if `columns * rows`
    /// exceeds `u32::MAX`.
    pub fn with_grid(columns: u32, rows: u32) -> Result<Self, Error> {
        Grid::with_sides(SamplerKind::Regular, columns, rows).map(|grid| Self { grid })
    }

    /// Number of grid columns.
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.grid.columns()
    }

    /// Number of grid rows.
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.grid.rows()
    }

    /// A jittered pattern whose offset is the cell's centre: only the order
    /// in which indices visit the cells depends on `pattern`.
    #[inline(always)]
    fn pattern(&self, pattern: u32) -> JitteredPattern<'_, Centre> {
        JitteredPattern {
            grid: &self.grid,
            order: Permutation::new(self.len(), derived_key(hash_u32(pattern), salt::ORDER)),
            offset: Centre,
        }
    }
}

impl Sampler2D for Regular {
    #[inline]
    fn len(&self) -> u32 {
        self.grid.len()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        self.pattern(pattern).point(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        self.fill_on(Isa::best(), pattern, out);
    }
}

impl FillOn for Regular {
    fn fill_on(&self, isa: Isa, pattern: u32, out: &mut [Vec2]) {
        fill_grid(&self.pattern(pattern), isa, out);
    }
}
