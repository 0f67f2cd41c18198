use glam::Vec2;

use super::{CellOffset, Grid, GridPattern, Jitter, fill_grid};
use crate::error::Error;
use crate::primitives::{MAX_STRATA, Permutation, derived_key, hash_u32, salt};
use crate::samplers::SamplerKind;
use crate::traits::{DomainSampler, Sampler2D};

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
/// Per sample: two permutations of `n` (one for columns, one for rows), two
/// [`rand_u32`](crate::primitives::rand_u32), two fixed-point stratum
/// conversions; no division. `sample` adds one hash of the pattern and two
/// 5-operation key derivations.
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

    #[inline(always)]
    fn prepare(&self, pattern: u32) -> NRooksPattern<'_> {
        let pattern_hash = hash_u32(pattern);
        NRooksPattern {
            grid: &self.grid,
            columns: Permutation::new(self.len(), derived_key(pattern_hash, salt::SHUFFLE_X)),
            rows: Permutation::new(self.len(), derived_key(pattern_hash, salt::SHUFFLE_Y)),
            jitter: Jitter::new(pattern_hash),
        }
    }
}

impl Sampler2D for NRooks {
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
impl DomainSampler for NRooks {}

/// One pattern of [`NRooks`]: its column and row permutations and jitter.
struct NRooksPattern<'a> {
    grid: &'a Grid,
    columns: Permutation,
    rows: Permutation,
    jitter: Jitter,
}

impl GridPattern for NRooksPattern<'_> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        // Column and row are two independent permutations of the index, so
        // index order says nothing about position and padded dimension pairs
        // that share an index stay decorrelated.
        let columns = self.columns.apply_lanes(index);
        let rows = self.rows.apply_lanes(index);
        let n = self.grid.n;
        let mut out = [Vec2::ZERO; N];
        for (lane, point) in out.iter_mut().enumerate() {
            let (x_bits, y_bits) = self.jitter.bits(index[lane]);
            *point = Vec2::new(
                n.stratum_to_unit_f32_in::<POW2>(columns[lane], x_bits),
                n.stratum_to_unit_f32_in::<POW2>(rows[lane], y_bits),
            );
        }
        out
    }
}
