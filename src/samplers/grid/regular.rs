use glam::Vec2;

use super::jittered::JitteredPattern;
use super::{Centre, Grid, GridPattern, fill_grid};
use crate::error::Error;
use crate::primitives::hash_u32;
use crate::samplers::SamplerKind;
use crate::traits::{DomainSampler, Sampler2D, stratified_1d};

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
/// The grids are [`Jittered`](crate::Jittered)'s: [`Regular::new`] picks
/// the most square one (`4 x 4` for 16, `4 x 8` for 32, `1 x n` strips for
/// a prime `n`), [`Regular::with_grid`] takes any shape.
///
/// # Cost
///
/// [`Jittered`](crate::Jittered)'s without the jitter: per sample one
/// permutation lookup and two fixed-point stratum conversions.
///
/// # Limits
///
/// [`Jittered`](crate::Jittered)'s grid limits. In release builds an index
/// at or above `len()` returns one of the set's points.
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
    /// Those of [`Jittered::new`](crate::Jittered::new).
    pub fn new(n: u32) -> Result<Self, Error> {
        Grid::most_square(SamplerKind::Regular, n).map(|grid| Self { grid })
    }

    /// Cell centres of a `columns x rows` grid.
    ///
    /// # Errors
    ///
    /// Those of [`Jittered::with_grid`](crate::Jittered::with_grid).
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
    fn prepare(&self, pattern: u32) -> JitteredPattern<'_, Centre> {
        JitteredPattern {
            grid: &self.grid,
            order: self.grid.cell_order(hash_u32(pattern)),
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
        self.prepare(pattern).point(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        fill_grid(&self.prepare(pattern), out);
    }
}

/// A domain's draws: 2D the sampler's own grid, 1D the cell centres of
/// `n` strata in a keyed order (no jitter), 3D and 4D padded.
impl DomainSampler for Regular {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u64) -> f32 {
        stratified_1d(index, self.len(), stream, false)
    }
}
