use glam::Vec2;

use crate::primitives::{MAX_STRATA, Permutation, hash_u32, rand_u32, salt};
use crate::sampler::{Sampler2D, debug_check_index};
use crate::samplers::grid::{Grid, GridPattern, fill_grid};
use crate::{Error, SamplerKind};

/// N-rooks (Latin hypercube) sampling: one point in every row and every
/// column of the `n x n` grid, like `n` rooks that cannot take each other.
///
/// # Properties
///
/// - Latin (the rook condition): for every `j < n` exactly one point has
///   `floor(x * n) = j` and exactly one has `floor(y * n) = j`, checked
///   exactly on the f32 values. Both 1D projections are perfectly stratified.
/// - No 2D stratification: the points may cluster along a diagonal. Error on
///   general integrands falls as `n^-1/2` (as random), but as `n^-1` on
///   integrands that vary along one axis only.
/// - Any `n`; the pattern picks both column and row orders.
///
/// # Cost
///
/// One hash, two [`permute`](crate::primitives::permute) (expected under two
/// rounds each) and two [`rand_u32`] per sample, plus two fixed-point stratum
/// conversions; no division (the sampler stores the reciprocal of `n`).
/// `fill` hashes the pattern once.
///
/// # Limits
///
/// `n` at most 2^24 ([`NRooks::MAX_SAMPLES`]): beyond that f32 cannot hold a
/// point in each of `n` columns. In release builds an index at or above
/// `len()` returns a point in the fine column and row of sample `index % n`.
///
/// # Examples
///
/// ```
/// use wellspread::{NRooks, Sampler2D};
/// let rooks = NRooks::new(7)?;
/// let mut columns = [0; 7];
/// for i in 0..7 {
///     columns[(rooks.sample(i, 1).x * 7.0) as usize] += 1;
/// }
/// assert_eq!(columns, [1; 7]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Shirley 1991, "Discrepancy as a quality measure for sample
/// distributions", Eurographics; McKay, Beckman & Conover 1979 (Latin
/// hypercube sampling). Random access through Kensler's (2013) hashed
/// permutations instead of a shuffled table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NRooks {
    // Only `n` matters: the rook condition is on the n x n fine grid.
    grid: Grid,
}

/// The statisticians' name for the same set.
pub type LatinHypercube = NRooks;

impl NRooks {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

    /// An n-rooks set of `n` points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`NRooks::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        Grid::latin(SamplerKind::NRooks, n).map(|grid| Self { grid })
    }

    fn pattern(&self, pattern: u32) -> NRooksPattern<'_> {
        let seed = hash_u32(pattern);
        NRooksPattern {
            grid: &self.grid,
            seed,
            columns: self.grid.n.permutation(seed ^ salt::SHUFFLE_X),
            rows: self.grid.n.permutation(seed ^ salt::SHUFFLE_Y),
        }
    }
}

/// One pattern of [`NRooks`]: its hash and its column and row permutations.
struct NRooksPattern<'a> {
    grid: &'a Grid,
    seed: u32,
    columns: Permutation,
    rows: Permutation,
}

impl GridPattern for NRooksPattern<'_> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn point<const POW2: bool>(&self, index: u32) -> Vec2 {
        // Column and row are two independent permutations of the index, so
        // index order says nothing about position and padded dimension pairs
        // that share an index stay decorrelated.
        let column = self.columns.apply(index);
        let row = self.rows.apply(index);
        let n = self.grid.n;
        Vec2::new(
            n.stratum_to_unit_f32_in::<POW2>(column, rand_u32(index, self.seed ^ salt::JITTER_X)),
            n.stratum_to_unit_f32_in::<POW2>(row, rand_u32(index, self.seed ^ salt::JITTER_Y)),
        )
    }
}

impl Sampler2D for NRooks {
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
