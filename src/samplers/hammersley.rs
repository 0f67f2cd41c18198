use glam::Vec2;

use crate::error::Error;
use crate::primitives::{
    InvariantDivisor, MAX_STRATA, hash_u32, owen_scramble_reversed, permute, rand_u32, salt,
    u32_to_unit_f32,
};
use crate::samplers::SamplerKind;
use crate::simd::{self, PointKernel, Pointwise};
use crate::traits::DomainSampler;
use crate::traits::{Sampler2D, check_fill_len, debug_check_index};

/// The Hammersley set `(i / n, phi_2(i))`, randomised: scrambled.
///
/// Point `index` lies in column `index` of `n` (x jittered uniformly inside
/// it, in fixed point by [`stratum_to_unit_f32`](crate::primitives::stratum_to_unit_f32)), and its y is the base-2
/// radical inverse of `index`, Owen-scrambled with Burley's hash
/// ([`owen_scramble_reversed`]). The randomisation keeps the structure
/// (columns and y's elementary intervals) and makes each pattern an
/// independent, unbiased set. The unscrambled textbook set is the case of
/// no jitter and no scramble; it is not offered because its points sit on
/// the lower-left corners of their boxes and repeat in every pixel.
///
/// # Properties
///
/// - Latin in x: one point per column of `n`, for every `n`.
/// - For `n = 2^m` (`m <= 24`) a (0,m,2)-net: each of the `2^m` boxes
///   `2^-a x 2^-(m-a)` of every shape holds exactly one point (the top `a`
///   bits of the index pick the column band, its low `m - a` bits the row
///   band, and the scramble permutes bands as whole blocks). So it is also
///   stratified on `2^k x 2^k` for `n = 4^k`, and Latin in y.
/// - For other `n`, the y values of the first `2^j <= n` points are one per
///   row of `2^j`; the set is not progressive (a prefix of it is not a good
///   set: its x values crowd the left of the square).
///
/// # Cost
///
/// One pattern hash (once per [`fill`](Sampler2D::fill)), one [`rand_u32`]
/// and one Owen-scramble hash, one bit reversal and one fixed-point stratum
/// conversion per sample.
///
/// # Limits
///
/// `n` at most 2^24 ([`Hammersley::MAX_SAMPLES`]): the columns must be
/// distinct f32 strata. In release builds an index at or above `len()`
/// returns a point in the last column.
///
/// # Examples
///
/// ```
/// use wellspread::{Hammersley, Sampler2D};
/// let hammersley = Hammersley::new(64)?;
/// // n = 64 = 8 x 8: stratified on the 8 x 8 grid, Latin on 64 x 64.
/// let mut cells = [0; 64];
/// let mut rows = [0; 64];
/// for i in 0..64 {
///     let p = hammersley.sample(i, 3);
///     cells[(p.y * 8.0) as usize * 8 + (p.x * 8.0) as usize] += 1;
///     rows[(p.y * 64.0) as usize] += 1;
/// }
/// assert_eq!(cells, [1; 64]);
/// assert_eq!(rows, [1; 64]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Hammersley 1960, "Monte Carlo methods for solving multivariable
///   problems", Ann. N.Y. Acad. Sci. 86.
/// - Owen 1997, "Monte Carlo variance of scrambled net quadrature", SIAM J.
///   Numer. Anal. 34(5).
/// - Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Hammersley {
    // Carries its reciprocal, so no sample needs a division.
    n: InvariantDivisor,
}

impl Hammersley {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

    /// A scrambled Hammersley set of `n` points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`Hammersley::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        if n > Self::MAX_SAMPLES {
            return Err(Error::TooManySamples {
                sampler: SamplerKind::Hammersley.name(),
                requested: n as u64,
                max: Self::MAX_SAMPLES as u64,
                reason: "one point per column of n needs n distinct f32 columns in [0, 1), and f32 has 2^24 at equal spacing",
            });
        }
        Ok(Self {
            n: InvariantDivisor::new(n),
        })
    }
}

impl Hammersley {
    /// Sample `index < n` given `pattern_hash`, the hash of the pattern:
    /// the one formula `sample` and `fill` share.
    #[inline(always)]
    fn point(&self, pattern_hash: u32, index: u32) -> Vec2 {
        Vec2::new(
            self.n
                .stratum_to_unit_f32(index, rand_u32(index, pattern_hash ^ salt::JITTER_X)),
            // In reversed bit order the radical inverse of `index` is `index`.
            u32_to_unit_f32(
                owen_scramble_reversed(index, pattern_hash ^ salt::JITTER_Y).reverse_bits(),
            ),
        )
    }
}

/// One pattern of [`Hammersley`]: its hash.
struct HammersleyKernel<'a> {
    sampler: &'a Hammersley,
    pattern_hash: u32,
}

impl PointKernel for HammersleyKernel<'_> {
    #[inline(always)]
    fn point(&self, index: u32) -> Vec2 {
        self.sampler.point(self.pattern_hash, index)
    }
}

impl Sampler2D for Hammersley {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        // Clamp so a release build with a bad index stays in the last column.
        let column = if index < self.len() {
            index
        } else {
            self.len() - 1
        };
        let pattern_hash = hash_u32(pattern);
        let p = self.point(pattern_hash, column);
        // The y coordinate keeps the unclamped index, as a sequence would.
        Vec2::new(
            p.x,
            u32_to_unit_f32(
                owen_scramble_reversed(index, pattern_hash ^ salt::JITTER_Y).reverse_bits(),
            ),
        )
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        let pattern_hash = hash_u32(pattern);
        let kernel = HammersleyKernel {
            sampler: self,
            pattern_hash,
        };
        simd::fill(&Pointwise(kernel), 0, out);
    }
}

/// A domain's 2D draws read the index through a keyed permutation of the
/// set first: Hammersley visits its points in the same order for every
/// pattern, so unshuffled draws would pair their samples. 1D draws are
/// the default stratified ones, 3D and 4D padded.
impl DomainSampler for Hammersley {
    #[inline]
    fn domain_2d(&self, index: u32, stream: u64) -> Vec2 {
        let n = self.len();
        let index = if index < n { index } else { index % n };
        self.sample(permute(index, n, (stream >> 32) as u32), stream as u32)
    }
}
