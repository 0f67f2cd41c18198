use glam::Vec2;

use crate::Error;
use crate::hash::{MAX_STRATA, hash_u32, permute, rand_u32, salt, stratum_to_unit_f32};
use crate::sampler::Sampler2D;

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
/// One hash, two [`permute`] (expected under two rounds each) and two
/// [`rand_u32`] per sample, plus two fixed-point stratum conversions.
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
    n: u32,
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
        check_rook_count("n-rooks", n)?;
        Ok(Self { n })
    }
}

/// Validation shared by the samplers that cut each axis into `n` strata.
pub(crate) fn check_rook_count(sampler: &'static str, n: u32) -> Result<(), Error> {
    if n == 0 {
        return Err(Error::ZeroSamples);
    }
    if n > MAX_STRATA {
        return Err(Error::TooManySamples {
            sampler,
            requested: n as u64,
            max: MAX_STRATA as u64,
            reason: "the rook condition needs n distinct f32 columns in [0, 1), and f32 has 2^24 at equal spacing",
        });
    }
    Ok(())
}

impl Sampler2D for NRooks {
    #[inline]
    fn len(&self) -> u32 {
        self.n
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_assert!(index < self.n, "index {index} out of range 0..{}", self.n);
        let seed = hash_u32(pattern);
        // Column and row are two independent permutations of the index, so
        // index order says nothing about position and padded dimension pairs
        // that share an index stay decorrelated.
        let column = permute(index, self.n, seed ^ salt::SHUFFLE_X);
        let row = permute(index, self.n, seed ^ salt::SHUFFLE_Y);
        Vec2::new(
            stratum_to_unit_f32(column, self.n, rand_u32(index, seed ^ salt::JITTER_X)),
            stratum_to_unit_f32(row, self.n, rand_u32(index, seed ^ salt::JITTER_Y)),
        )
    }
}
