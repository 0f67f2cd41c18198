use glam::Vec2;

use crate::Error;
use crate::hash::{Length, MAX_STRATA, Permutation, hash_u32, rand_u32, salt};
use crate::sampler::{Sampler2D, check_fill_len, debug_check_index};

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
/// One hash, two [`permute`](crate::hash::permute) (expected under two
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
    // Carries its reciprocal, so no sample needs a division.
    n: Length,
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
        Ok(Self { n: Length::new(n) })
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

impl NRooks {
    /// Sample `index` given the pattern's hash `seed` and its column and row
    /// permutations: the one formula `sample` and `fill` share. `POW2`
    /// promises a power-of-two `n`, for a branch-free `fill` loop.
    #[inline(always)]
    fn point<const POW2: bool>(
        &self,
        seed: u32,
        columns: &Permutation,
        rows: &Permutation,
        index: u32,
    ) -> Vec2 {
        // Column and row are two independent permutations of the index, so
        // index order says nothing about position and padded dimension pairs
        // that share an index stay decorrelated.
        let column = columns.apply(index);
        let row = rows.apply(index);
        Vec2::new(
            self.n
                .stratum_to_unit_f32_in::<POW2>(column, rand_u32(index, seed ^ salt::JITTER_X)),
            self.n
                .stratum_to_unit_f32_in::<POW2>(row, rand_u32(index, seed ^ salt::JITTER_Y)),
        )
    }

    fn permutations(&self, seed: u32) -> (Permutation, Permutation) {
        (
            self.n.permutation(seed ^ salt::SHUFFLE_X),
            self.n.permutation(seed ^ salt::SHUFFLE_Y),
        )
    }
}

impl Sampler2D for NRooks {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        let seed = hash_u32(pattern);
        let (columns, rows) = self.permutations(seed);
        self.point::<false>(seed, &columns, &rows, index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        // The pattern hash and both rotations once per set.
        let seed = hash_u32(pattern);
        let (columns, rows) = self.permutations(seed);
        if self.n.is_power_of_two() {
            for (index, point) in (0..).zip(out.iter_mut()) {
                *point = self.point::<true>(seed, &columns, &rows, index);
            }
        } else {
            for (index, point) in (0..).zip(out.iter_mut()) {
                *point = self.point::<false>(seed, &columns, &rows, index);
            }
        }
    }
}
