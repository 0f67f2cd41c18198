//! Samples addressed the way a renderer asks for them: by pixel, sample
//! index and dimension, either by pure O(1) access
//! ([`PixelSampler::sample_pixel`]) or through an owned per-sample state,
//! [`Domain`], that hands out draws of one to four dimensions and derives
//! keyed child domains.

mod blue_noise;
mod domain;
mod kind;
mod padded;
#[cfg(feature = "rand")]
mod rng;
mod zsobol;

use glam::{Vec2, Vec3, Vec4};

pub use blue_noise::BlueNoise;
pub use domain::Domain;
pub(crate) use kind::ALIASES_TEXT;
pub use kind::{AnyPixelSampler, PixelSamplerKind};
pub use padded::{DomainSampler, Padded};
pub use zsobol::ZSobol;

use crate::primitives::hash_u32;

/// Sample positions for a whole image: sample `index` of pixel `pixel`,
/// either one dimension pair at a time ([`sample_pixel`](Self::sample_pixel))
/// or as a [`Domain`] ([`start`](Self::start)) that draws 1D to 4D values.
///
/// # Properties
///
/// - `sample_pixel` and every draw are pure functions of the sampler, the
///   pixel, the index and the domain's keys: the same arguments give the
///   same values on every thread, machine and run, so any tile order
///   renders the same image. Implementors are `Send + Sync`.
/// - Every coordinate is in `[0, 1)`.
///
/// # Edges, the same for every pixel sampler, debug and release
///
/// - **Index at or beyond the count.** With `samples_per_pixel() =
///   Some(n)`, indices `p n .. (p + 1) n` are pass `p`: a complete set with
///   the sampler's guarantees. Fixed-size samplers (the grid family,
///   [`ZSobol`]) key each pass's sets by `p` (independent sets); the
///   progressive sequences ([`Sobol`](crate::Sobol), [`Pmj02`](crate::Pmj02),
///   [`Halton`](crate::Halton)) go on along their sequence, so every
///   prefix `0 .. 2^k` stays a net. Nothing panics, nothing repeats.
/// - **Progressive samplers have no count.** `samples_per_pixel()` is
///   `None` for an unbounded sequence (`Padded::new(Sobol::unbounded(), _)`):
///   ask for indices, any `u32`.
/// - **Pixels outside a resolution.** [`Padded`] has no resolution: every
///   `[u32; 2]` is a distinct pixel. [`ZSobol`] maps a pixel outside its
///   film onto the film (coordinates modulo the width and height) with the
///   scramble keyed by the tile it fell in, so it gets a full, unrelated
///   set.
///
/// # Implementing
///
/// Only [`samples_per_pixel`](Self::samples_per_pixel) and
/// [`sample_pixel`](Self::sample_pixel) are required: the provided draw
/// methods then call `sample_pixel(pixel, index, stream)` with a
/// per-draw hash `stream` as the dimension, so a new pixel sampler works
/// with [`Domain`], branches and splits at once. Override
/// [`root`](Self::root) and the `draw_*` methods to make draws cheaper
/// (the pixel hashed once per sample instead of per draw) or better
/// (stratified 1D draws, true 4D sets), as [`Padded`] and [`ZSobol`] do.
///
/// # Examples
///
/// A path tracer's sample loop: the film and the lens as one 4D draw,
/// per-bounce branches so each bounce's dimensions never depend on how
/// many the bounces before it drew, and a split for light samples. The
/// sampler comes from a command-line flag.
///
/// ```
/// use wellspread::{PixelSampler, PixelSamplerKind};
///
/// // Keys: any u32, fixed per purpose.
/// const BOUNCE: u32 = 1;
/// const LIGHT: u32 = 2;
///
/// let kind: PixelSamplerKind = "Sobol".parse()?; // also "cmj", "zsobol", ...
/// let (width, height, spp) = (32, 24, 16);
/// let sampler = kind.build(spp, [width, height], 0)?;
/// let mut image = vec![0.0f32; (width * height) as usize];
/// for py in 0..height {
///     for px in 0..width {
///         let mut sum = 0.0;
///         for index in 0..spp {
///             let mut d = sampler.start([px, py], index);
///             let film_lens = d.next_4d(); // film (x, y), lens (z, w): one 4D set
///             let time = d.next_1d();
///             let mut throughput = 1.0;
///             for b in 0..8 {
///                 // Bounce b's own domain: the same whatever was drawn before.
///                 let mut bounce = d.branch(BOUNCE).branch(b);
///                 let light_pick = bounce.next_1d();
///                 for j in 0..4 {
///                     // Four light samples; for the sequences the 4 spp of
///                     // them in a pixel form one (0, m, 2)-net.
///                     let on_light = bounce.split(LIGHT, 4, j).next_2d();
///                     sum += throughput * on_light.x * light_pick * 0.25;
///                 }
///                 let direction = bounce.next_2d();
///                 let roulette = bounce.next_1d();
///                 if roulette > 0.7 {
///                     break;
///                 }
///                 throughput *= 0.5 * (direction.x + film_lens.z * time);
///             }
///         }
///         image[(py * width + px) as usize] = sum / spp as f32;
///     }
/// }
/// assert!(image.iter().all(|v| v.is_finite()));
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait PixelSampler: Send + Sync {
    /// Samples per pixel of one pass (see the edges above), or `None` for a
    /// progressive sampler, which takes any index.
    fn samples_per_pixel(&self) -> Option<u32>;

    /// Sample `index` of pixel `pixel` (`[x, y]`) in dimension pair
    /// `dimension`, in O(1). Out-of-range arguments follow the edge rules
    /// above.
    fn sample_pixel(&self, pixel: [u32; 2], index: u32, dimension: u32) -> Vec2;

    /// What [`start`](Self::start) computes once per pixel sample: the
    /// root key of the domain tree and the sampler's own pixel state.
    ///
    /// The default keys every pixel alike (key 0, state 0), for samplers
    /// whose `sample_pixel` mixes the pixel in itself.
    #[inline]
    fn root(&self, pixel: [u32; 2]) -> Root {
        let _ = pixel;
        Root { key: 0, pixel: 0 }
    }

    /// Where sample `index` of a domain keyed `key` lives, after the
    /// index-beyond-the-count rule: `(index in the set, key of the set)`.
    ///
    /// The default is the fixed-size rule: pass `index / n` keys an
    /// independent set. Progressive samplers return `(index, key)`.
    #[inline]
    fn locate(&self, index: u32, key: u32) -> (u32, u32) {
        match self.samples_per_pixel() {
            Some(n) if index >= n && n > 0 => {
                (index % n, crate::primitives::hash_combine(key, index / n))
            }
            _ => (index, key),
        }
    }

    /// One value in `[0, 1)` for `draw`. The default is the first
    /// coordinate of [`draw_2d`](Self::draw_2d).
    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        self.draw_2d(draw).x
    }

    /// One point in `[0, 1)^2` for `draw`. The default is
    /// `sample_pixel(draw.pixel, draw.index, draw.stream)`.
    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        self.sample_pixel(draw.pixel, draw.index, draw.stream)
    }

    /// One point in `[0, 1)^3`. The default pads a pair and a 1D draw.
    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        let a = self.draw_2d(draw);
        a.extend(self.draw_1d(draw.second()))
    }

    /// One point in `[0, 1)^4`. The default pads two pairs.
    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        let a = self.draw_2d(draw);
        let b = self.draw_2d(draw.second());
        Vec4::new(a.x, a.y, b.x, b.y)
    }

    /// A [`PixelCursor`] at sample `index` of `pixel`: `sample_pixel`'s
    /// dimension pairs 0, 1, 2, ... in order.
    #[inline]
    fn cursor(&self, pixel: [u32; 2], index: u32) -> PixelCursor<'_, Self>
    where
        Self: Sized,
    {
        PixelCursor::new(self, pixel, index)
    }

    /// The domain of sample `index` of `pixel`: the pixel is hashed here,
    /// once; every draw after costs one hash and the sampler's kernel.
    #[inline(always)]
    fn start(&self, pixel: [u32; 2], index: u32) -> Domain<Self>
    where
        Self: Sized + Copy,
    {
        Domain::start(*self, pixel, index)
    }
}

/// The dimension pairs of [`PixelSampler::sample_pixel`] in order, for
/// code written against pbrt-v4's `StartPixelSample` / `Get2D`. A renderer
/// should prefer [`Domain`]: it owns its sampler, hashes the pixel once,
/// draws 1D to 4D values and branches by key.
///
/// A cursor is a thin view of `sample_pixel`: the `k`-th
/// call to [`next_2d`](Self::next_2d) returns
/// `sample_pixel(pixel, index, k)`, so a renderer that asks for its
/// dimension pairs in a fixed order needs no bookkeeping. It borrows the
/// sampler and is cheap to make: one per pixel sample and thread.
///
/// ```
/// use wellspread::{Padded, PixelSampler, Sobol};
/// let pixels = Padded::new(Sobol::new(4)?, 0);
/// let mut cursor = pixels.cursor([10, 20], 3);
/// let film = cursor.next_2d();
/// let lens = cursor.next_2d();
/// assert_eq!(film, pixels.sample_pixel([10, 20], 3, 0));
/// assert_eq!(lens, pixels.sample_pixel([10, 20], 3, 1));
/// assert_eq!(cursor.dimension(), 2);
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct PixelCursor<'a, P: ?Sized> {
    sampler: &'a P,
    pixel: [u32; 2],
    index: u32,
    dimension: u32,
}

impl<'a, P: PixelSampler + ?Sized> PixelCursor<'a, P> {
    /// A cursor at sample `index` of `pixel`, dimension pair 0.
    #[inline]
    pub fn new(sampler: &'a P, pixel: [u32; 2], index: u32) -> Self {
        Self {
            sampler,
            pixel,
            index,
            dimension: 0,
        }
    }

    /// Moves to sample `index` of `pixel` and back to dimension pair 0.
    #[inline]
    pub fn start_pixel_sample(&mut self, pixel: [u32; 2], index: u32) {
        self.pixel = pixel;
        self.index = index;
        self.dimension = 0;
    }

    /// The next dimension pair of the current pixel sample.
    ///
    /// A release build wraps the dimension counter after 2^32 calls (a
    /// debug build panics on the overflow); no renderer asks for that many.
    #[inline]
    pub fn next_2d(&mut self) -> Vec2 {
        let point = self
            .sampler
            .sample_pixel(self.pixel, self.index, self.dimension);
        self.dimension += 1;
        point
    }

    /// The next dimension pair's first coordinate; the pair's second
    /// coordinate goes unused ([`Domain::next_1d`] wastes nothing and is
    /// stratified in 1D).
    #[inline]
    pub fn next_1d(&mut self) -> f32 {
        self.next_2d().x
    }

    /// The dimension pair the next call to [`next_2d`](Self::next_2d)
    /// returns.
    #[inline]
    pub fn dimension(&self) -> u32 {
        self.dimension
    }

    /// The current pixel.
    #[inline]
    pub fn pixel(&self) -> [u32; 2] {
        self.pixel
    }

    /// The current sample index.
    #[inline]
    pub fn index(&self) -> u32 {
        self.index
    }
}

/// A pixel sampler behind a reference is one too, so a renderer that holds
/// `&dyn PixelSampler` gets a `Domain<&dyn PixelSampler>` from
/// `Domain::start(sampler, pixel, index)` (`Copy`, `Send`
/// and `Sync`, borrowing the sampler). [`AnyPixelSampler`] is the owned,
/// `'static` dynamic form.
impl<T: PixelSampler + ?Sized> PixelSampler for &T {
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        (**self).samples_per_pixel()
    }
    #[inline]
    fn sample_pixel(&self, pixel: [u32; 2], index: u32, dimension: u32) -> Vec2 {
        (**self).sample_pixel(pixel, index, dimension)
    }
    #[inline]
    fn root(&self, pixel: [u32; 2]) -> Root {
        (**self).root(pixel)
    }
    #[inline]
    fn locate(&self, index: u32, key: u32) -> (u32, u32) {
        (**self).locate(index, key)
    }
    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        (**self).draw_1d(draw)
    }
    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        (**self).draw_2d(draw)
    }
    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        (**self).draw_3d(draw)
    }
    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        (**self).draw_4d(draw)
    }
}

/// The start of a domain tree, from [`PixelSampler::root`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Root {
    /// The root key: [`Domain::branch`] and every draw's `stream` derive
    /// from it. A sampler whose draws depend on the pixel through the key
    /// (as [`Padded`]) hashes the pixel and frame into it.
    pub key: u32,
    /// Whatever else the sampler needs per pixel (for [`ZSobol`], the
    /// pixel's Morton index shifted by `log2(spp)`), handed back in every
    /// [`Draw`].
    pub pixel: u32,
}

/// What one draw of a [`Domain`] hands its sampler.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Draw {
    /// The pixel, `[x, y]`, as passed to [`PixelSampler::start`].
    pub pixel: [u32; 2],
    /// The sampler's pixel state, [`Root::pixel`].
    pub pixel_state: u32,
    /// The sample index within its set, after [`PixelSampler::locate`].
    pub index: u32,
    /// A well-mixed 32-bit value that picks this draw's pattern: a hash of
    /// the domain's key and its dimension counter, so it is the same for
    /// every sample index of a pixel (as a pattern must be) and unrelated
    /// between dimensions, keys and branches.
    pub stream: u32,
}

impl Draw {
    /// The draw with an unrelated `stream` (one hash), for samplers that
    /// pad a 3D or 4D draw from two patterns.
    #[inline]
    #[must_use]
    pub const fn second(self) -> Self {
        Self {
            stream: hash_u32(self.stream ^ 0x5bd1_e995),
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Pmj02, Sobol};

    #[test]
    fn padded_pairs_differ_and_repeat() {
        let pixels = Padded::new(Pmj02::new(8).unwrap(), 3);
        let a = pixels.sample_pixel([1, 2], 0, 0);
        assert_eq!(a, pixels.sample_pixel([1, 2], 0, 0));
        assert_ne!(a, pixels.sample_pixel([1, 2], 0, 1));
        assert_ne!(a, pixels.sample_pixel([2, 1], 0, 0));
        assert_ne!(
            a,
            Padded::new(Pmj02::new(8).unwrap(), 4).sample_pixel([1, 2], 0, 0)
        );
    }

    fn assert_send_sync<T: Send + Sync + Copy + 'static>() {}

    #[test]
    fn domains_are_send_sync_copy_static_and_small() {
        assert_send_sync::<Padded<Sobol>>();
        assert_send_sync::<ZSobol>();
        assert_send_sync::<Domain<Padded<Sobol>>>();
        assert_send_sync::<Domain<AnyPixelSampler>>();
        assert_send_sync::<Domain<&'static dyn PixelSampler>>();
        assert!(core::mem::size_of::<Domain<Padded<Sobol>>>() <= 40);
    }
}
