use glam::Vec2;

use crate::error::Error;
use crate::primitives::{hash_combine, hash_u32, salt, u32_to_unit_f32};
use crate::simd::{self, PointKernel, Pointwise};
use crate::traits::DomainSampler;
use crate::traits::{Sampler2D, check_fill_len, debug_check_index};

/// Independent uniform points: the baseline every other sampler must beat.
///
/// # Properties
///
/// None beyond uniformity: points clump and leave gaps, and the error of an
/// estimate falls only as `n^-1/2`. Different patterns give independent sets.
///
/// # Cost
///
/// Three 32-bit integer hashes per sample after one hash of the pattern
/// (once per `fill`); no division, no loop.
///
/// # Limits
///
/// Any `n` from 1 to `u32::MAX`. Coordinates are multiples of `2^-24`. In
/// release builds an index at or above `len()` returns a further random point.
///
/// # Examples
///
/// ```
/// use wellspread::{Random, Sampler2D};
/// let random = Random::new(1000)?;
/// let mean_x = (0..1000).map(|i| random.sample(i, 3).x).sum::<f32>() / 1000.0;
/// assert!((mean_x - 0.5).abs() < 0.05);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Cook 1986, "Stochastic sampling in computer graphics", ACM TOG 5(1).
/// The hash is `lowbias32` (Wellons 2018); see [`hash_u32`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Random {
    n: u32,
}

impl Random {
    /// A set of `n` independent uniform points.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`.
    pub fn new(n: u32) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        Ok(Self { n })
    }
}

impl Random {
    /// Sample `index` given `pattern_hash`, the hash of the pattern: the one
    /// formula `sample` and `fill` share.
    #[inline(always)]
    fn point(pattern_hash: u32, index: u32) -> Vec2 {
        // Hashing the index before mixing in the pattern_hash matters: with
        // `index ^ pattern_hash`, two patterns whose hashes differ only in
        // bits below n would feed the same inputs in another order and so
        // give the same set. The index must not be hashed like the pattern
        // either: with `hash(index) ^ hash(pattern)`, sample i of pattern p
        // is sample p of pattern i, so patterns 0 and 1 of a 2-point set
        // would be the same set. `hash_combine` adds a constant to the index's hash first.
        // Both are bijections of the index, so one pattern's x bits are all
        // distinct; y hashes x's full 32 bits again with another salt.
        let bits_x = hash_combine(pattern_hash ^ salt::JITTER_X, index);
        let bits_y = hash_u32(bits_x ^ salt::JITTER_Y);
        Vec2::new(u32_to_unit_f32(bits_x), u32_to_unit_f32(bits_y))
    }
}

/// One pattern of [`Random`]: its hash.
struct RandomKernel {
    pattern_hash: u32,
}

impl PointKernel for RandomKernel {
    #[inline(always)]
    fn point(&self, index: u32) -> Vec2 {
        Random::point(self.pattern_hash, index)
    }
}

impl Sampler2D for Random {
    #[inline]
    fn len(&self) -> u32 {
        self.n
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.n);
        Self::point(hash_u32(pattern), index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.n);
        // The pattern hash once per set: three hashes per sample, not four.
        let pattern_hash = hash_u32(pattern);
        simd::fill(&Pointwise(RandomKernel { pattern_hash }), 0, out);
    }
}

/// A domain's draws are independent uniform values, cheaper than
/// `sample`'s (and other values): [`locate`](DomainSampler::locate) folds
/// the sample index into the key once per domain, so each draw's
/// well-mixed stream is already unique to the sample and its two halves
/// are the two coordinates. 3D and 4D draws pad.
impl DomainSampler for Random {
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        (
            index,
            key ^ u64::from(index).wrapping_mul(salt::RANDOM_INDEX),
        )
    }
    #[inline]
    fn domain_1d(&self, _index: u32, stream: u64) -> f32 {
        u32_to_unit_f32((stream >> 32) as u32)
    }
    #[inline]
    fn domain_2d(&self, _index: u32, stream: u64) -> Vec2 {
        Vec2::new(
            u32_to_unit_f32((stream >> 32) as u32),
            u32_to_unit_f32(stream as u32),
        )
    }
}
