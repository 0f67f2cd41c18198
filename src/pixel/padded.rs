//! Any [`Sampler2D`] with its draws ([`DomainSampler`]) as a pixel
//! sampler.

use glam::{Vec2, Vec3, Vec4};

use super::{Draw, PixelSampler, PixelSamplerHooks, Root};
use crate::primitives::salt;
use crate::traits::{DomainSampler, Sampler2D};

/// Any [`DomainSampler`] as a [`PixelSampler`]: every pixel, every draw
/// and every frame gets its own pattern of the wrapped sampler (hashed
/// from the pixel, the frame, the domain's key and the draw counter), so
/// each gets an independent randomisation ("padding").
///
/// # Properties
///
/// - Each pixel's `len()` samples in each draw are one set of the wrapped
///   sampler, with all its guarantees (stratification, nets).
/// - Different pixels, draws and frames get unrelated patterns, so the
///   error is white noise across pixels, and two draws of a pixel pair
///   their samples like independent sets (the sequences, and
///   [`Halton`](crate::Halton) and [`Hammersley`](crate::Hammersley),
///   whose order is the same for every pattern, shuffle their index per
///   draw: see [`DomainSampler`]).
/// - Each draw of a [`Domain`](crate::Domain) is one set of the sampler for
///   a pattern picked by the draw's `stream`; what each width gives is
///   [`DomainSampler`]'s table.
///
/// `Padded<S>` is a pixel sampler for every `S:` [`DomainSampler`]; the
/// crate's samplers all are, and a [`Sampler2D`] of your own becomes one
/// with `impl DomainSampler for MySampler {}`.
///
/// # Cost
///
/// `start`: the pixel packed into a 64-bit key and xored with a multiple
/// of the frame (no hash); each draw one
/// [`mix64`](crate::primitives::mix64) plus the sampler's
/// [`DomainSampler`] kernel.
///
/// # Limits
///
/// Every `[u32; 2]` is a pixel (there is no resolution). An index at or
/// beyond `len()` follows [`PixelSampler`]'s edge rule, in `sample_pixel`
/// too: for the fixed-size samplers pass `index / len` keys an
/// independent set; the sequences continue.
///
/// # Examples
///
/// ```
/// use wellspread::{Padded, PixelSampler, Sobol, metrics::is_net_base2};
/// let pixels = Padded::new(Sobol::new(16)?, 7);
/// assert_eq!(pixels.samples_per_pixel(), Some(16));
/// // Each draw of a pixel's 16 samples is a (0,4,2)-net.
/// let lens: Vec<_> = (0..16).map(|i| pixels.sample_pixel([3, 4], i, 1)).collect();
/// assert!(is_net_base2(&lens)?);
/// // Progressive: no count, any index.
/// assert_eq!(Padded::new(Sobol::unbounded(), 7).samples_per_pixel(), None);
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Padded<S> {
    sampler: S,
    frame: u32,
}

impl<S: Sampler2D> Padded<S> {
    /// `sampler` for every pixel and dimension pair; `frame` (a frame
    /// number, say) picks one of 2^32 unrelated sets of patterns.
    #[inline]
    pub const fn new(sampler: S, frame: u32) -> Self {
        Self { sampler, frame }
    }

    /// The wrapped sampler.
    #[inline]
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The frame it was built with.
    #[inline]
    pub const fn frame(&self) -> u32 {
        self.frame
    }
}

impl<S: DomainSampler + Send + Sync> PixelSampler for Padded<S> {
    /// `None` when the wrapped sampler is a progressive sequence
    /// ([`DomainSampler::is_progressive`]) built with no set size
    /// (`unbounded()`, `len() == u32::MAX`); otherwise its `len()`. A
    /// fixed-size set of `u32::MAX` points has a count: its indices start
    /// a new pass past it like any other set's.
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        let n = self.sampler.len();
        if self.sampler.is_progressive() && n == u32::MAX {
            None
        } else {
            Some(n)
        }
    }
}

impl<S: DomainSampler + Send + Sync> PixelSamplerHooks for Padded<S> {
    /// The key: `(y, x)` packed into 64 bits, xored with the frame times
    /// an odd 64-bit constant (no hash: every draw mixes the key). Distinct
    /// pixels of one frame get distinct keys, and a frame's keys differ
    /// from another's in their high bits too, so no pixel of one frame
    /// shares its key with a nearby pixel of another.
    #[inline(always)]
    fn root(&self, pixel: [u32; 2]) -> Root {
        packed_root(pixel, self.frame)
    }

    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        self.sampler.locate(index, key)
    }

    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        self.sampler.domain_1d(draw.index, draw.stream)
    }

    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        self.sampler.domain_2d(draw.index, draw.stream)
    }

    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        self.sampler.domain_3d(draw.index, draw.stream)
    }

    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        self.sampler.domain_4d(draw.index, draw.stream)
    }
}

/// The root of a padded domain: `(y, x)` packed into 64 bits, xored with
/// the frame times an odd 64-bit constant (no hash: every draw mixes the
/// key).
#[inline(always)]
pub(super) fn packed_root([x, y]: [u32; 2], frame: u32) -> Root {
    Root {
        key: (u64::from(y) << 32 | u64::from(x))
            ^ u64::from(frame).wrapping_mul(salt::PADDED_FRAME),
        pixel_state: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::SamplerKind;

    #[test]
    fn only_an_unbounded_sequence_has_no_count() {
        for &kind in SamplerKind::ALL {
            // Fixed-size sets of u32::MAX points (where the kind accepts
            // that many) have a count, and their indices wrap into passes.
            let Ok(sampler) = kind.build(u32::MAX) else {
                continue;
            };
            let expected = if sampler.as_sequence().is_some() {
                None
            } else {
                Some(u32::MAX)
            };
            assert_eq!(
                Padded::new(sampler, 0).samples_per_pixel(),
                expected,
                "{kind}"
            );
        }
        for kind in [
            SamplerKind::Regular,
            SamplerKind::Jittered,
            SamplerKind::Random,
        ] {
            assert!(kind.build(u32::MAX).is_ok(), "{kind}");
        }
    }
}
