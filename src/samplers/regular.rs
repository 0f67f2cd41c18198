use glam::Vec2;

use crate::primitives::{Permutation, derived_key, hash_u32, salt};
use crate::sampler::Sampler2D;
use crate::samplers::grid::{Grid, GridPattern};
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
/// reciprocals of its sides). `sample` adds one hash of the pattern and a
/// 3-operation key derivation. `fill` runs the same formula on 8 or 16 lanes at once (AVX2 or AVX-512,
/// detected at run time), bit for bit equal to `sample`; measured ratios to a
/// `rand_pcg::Pcg32` fill are in `docs/performance.md`.
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

grid_constructors!(cells Regular, Regular, "cell centres");

grid_sampler!(Regular, fill_on);

impl Regular {
    #[inline(always)]
    fn pattern(&self, pattern: u32) -> RegularPattern<'_> {
        RegularPattern {
            grid: &self.grid,
            order: Permutation::new(self.len(), derived_key(hash_u32(pattern), salt::ORDER)),
        }
    }
}

/// One pattern of [`Regular`]: only the order in which indices visit cells.
struct RegularPattern<'a> {
    grid: &'a Grid,
    order: Permutation,
}

impl GridPattern for RegularPattern<'_> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let mut out = [Vec2::ZERO; N];
        for (point, cell) in out.iter_mut().zip(self.order.apply_lanes(index)) {
            // Half-way bits put the point at the cell's centre, to within 2^-24.
            *point = self.grid.cell_point::<POW2>(cell, (1 << 31, 1 << 31));
        }
        out
    }
}
