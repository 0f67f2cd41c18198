//! Samples addressed the way a renderer asks for them: by pixel, sample
//! index and draw, through a small per-sample state, [`Domain`], that
//! hands out draws of one to four dimensions and derives keyed child
//! domains; [`PixelSampler::sample_pixel`] is a domain's `d`-th 2D draw in
//! O(1).

pub(crate) mod blue_noise;
mod camera;
mod domain;
mod kind;
mod padded;
mod padded_nd;
#[cfg(feature = "rand")]
mod rng;
mod zsobol;

use glam::{Vec2, Vec3, Vec4};

pub use blue_noise::BlueNoise;
pub use camera::CameraSample;
pub use domain::Domain;
pub use kind::{AnyPixelSampler, PixelSamplerKind, PixelSamplerVisitor};
pub use padded::Padded;
pub use padded_nd::PaddedNd;
pub use zsobol::ZSobol;

use crate::error::Error;
use crate::primitives::{mix64, salt};
use crate::traits::second_stream;

/// The check every pixel sampler with a film shares: a width and a height
/// of at least one pixel.
pub(crate) fn check_resolution(resolution: [u32; 2]) -> Result<(), Error> {
    if resolution.contains(&0) {
        Err(Error::ZeroResolution { resolution })
    } else {
        Ok(())
    }
}

/// [`check_resolution`], and at least one sample per pixel.
pub(crate) fn check_film(samples_per_pixel: u32, resolution: [u32; 2]) -> Result<(), Error> {
    if samples_per_pixel == 0 {
        return Err(Error::ZeroSamples);
    }
    check_resolution(resolution)
}

/// Sample positions for a whole image: sample `index` of pixel `pixel` as
/// a [`Domain`] ([`start`](Self::start)) that draws 1D to 4D values.
///
/// # Properties
///
/// - Every draw is a pure function of the sampler, the pixel, the index,
///   the domain's key and its draw counter: the same arguments give the
///   same values on every thread, machine and run, so any tile order
///   renders the same image. Implementors are `Send + Sync`.
/// - Every coordinate is in `[0, 1)`.
/// - One value per (pixel, index, draw):
///   [`sample_pixel(pixel, index, pair)`](Self::sample_pixel) is the
///   `pair`-th [`next_2d`](Domain::next_2d) of `start(pixel, index)`, by
///   definition (a provided method, not a second formula).
///
/// # Edges, the same for every pixel sampler, debug and release
///
/// - **Index at or beyond the count.** With `samples_per_pixel() =
///   Some(n)`, indices `p n .. (p + 1) n` are pass `p`. Fixed-size
///   samplers (the grid family, [`ZSobol`], the orthogonal array) key each
///   pass's sets by `p`: each pass is a complete set with the sampler's
///   guarantees, independent of the others. The progressive sequences
///   ([`Sobol`](crate::Sobol), [`Pmj02`](crate::Pmj02),
///   [`Halton`](crate::Halton), [`BlueNoise`],
///   [`Faure4D`](crate::Faure4D)) go on along their
///   sequence: every prefix `0 .. 2^k` stays a net, and so do passes 0
///   and 1 and the first `2^a` passes together, but a single pass `p >= 2`
///   is not a net (for passes that are nets each, draw pass `p` from
///   `start(pixel, i).branch(p)`, `i < n`: see
///   [`DomainSampler`](crate::implement::DomainSampler)). Nothing panics, nothing
///   repeats.
/// - **Progressive samplers have no count.** `samples_per_pixel()` is
///   `None` for an unbounded sequence (`Padded::new(Sobol::unbounded(), _)`):
///   ask for indices, any `u32`.
/// - **Pixels outside a resolution.** [`Padded`] and [`BlueNoise`] have no
///   resolution: every `[u32; 2]` is a distinct pixel. [`ZSobol`] maps a
///   pixel outside its film onto the film (coordinates modulo the width
///   and height) with the scrambles keyed by the tile it fell in, so it
///   gets a full, unrelated set.
///
/// # Implementing
///
/// A renderer calls the three methods here; a new sampler also
/// implements the hooks these call, [`PixelSamplerHooks`]
/// ([`implement`](crate::implement) lists the steps): `samples_per_pixel`
/// here, and `root` and `draw_2d` there are required.
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
pub trait PixelSampler: PixelSamplerHooks + Send + Sync {
    /// Samples per pixel of one pass (see the edges above), or `None` for a
    /// progressive sampler, which takes any index.
    fn samples_per_pixel(&self) -> Option<u32>;

    /// Draw `pair` of sample `index` of `pixel` as a point in `[0, 1)^2`,
    /// in O(1): exactly the `pair`-th [`Domain::next_2d`] of
    /// `start(pixel, index)` after `pair` calls of `next_2d`, for code
    /// written against pbrt-v4's `Get2D` or a per-pair pattern. (Only
    /// [`PaddedNd`] reads how many dimensions the draws before took; for
    /// every other sampler the draws before may have any width.)
    ///
    /// ```
    /// use wellspread::{Padded, PixelSampler, Sobol};
    /// let pixels = Padded::new(Sobol::new(16)?, 0);
    /// let mut d = pixels.start([3, 4], 5);
    /// let film = d.next_2d();
    /// let lens = d.next_2d();
    /// assert_eq!(film, pixels.sample_pixel([3, 4], 5, 0));
    /// assert_eq!(lens, pixels.sample_pixel([3, 4], 5, 1));
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    fn sample_pixel(&self, pixel: [u32; 2], index: u32, pair: u32) -> Vec2 {
        let root = self.root(pixel);
        let (index, key) = self.locate(index, root.key);
        self.draw_2d(Draw::new(
            key,
            pair,
            pair.wrapping_mul(2),
            index,
            root.pixel_state,
        ))
    }

    /// The domain of sample `index` of `pixel`, borrowing the sampler:
    /// [`root`](PixelSamplerHooks::root) and [`locate`](PixelSamplerHooks::locate) run here, once;
    /// each draw after costs one [`mix64`] and the sampler's kernel.
    ///
    /// The domain is 32 bytes for every sampler (a key, four counters and
    /// the reference), `Copy`, and lives as long as the borrow: what a
    /// renderer passes down its call tree, by `&mut` to each routine that
    /// draws. A domain that must outlive the borrow (a thread-local, a
    /// `'static` boundary) owns its sampler: [`Domain::start`] by value,
    /// with the same values (its size is the sampler's plus 24 bytes).
    ///
    /// ```
    /// use wellspread::{AnyPixelSampler, Domain, PixelSampler, PixelSamplerKind};
    /// // A renderer's routine draws from the domain it is handed.
    /// fn light_sample(d: &mut Domain<&AnyPixelSampler>) -> f32 {
    ///     let on_light = d.next_2d();
    ///     on_light.x * on_light.y
    /// }
    /// let sampler = "sobol".parse::<PixelSamplerKind>()?.build(16, [64, 64], 0)?;
    /// let d = sampler.start([3, 4], 5); // Domain<&AnyPixelSampler>
    /// assert_eq!(core::mem::size_of_val(&d), 32);
    /// let light = light_sample(&mut d.branch(7));
    /// // The owned, 'static form gives the same values.
    /// let mut owned = Domain::start(sampler, [3, 4], 5).branch(7);
    /// let p = owned.next_2d();
    /// assert_eq!(light, p.x * p.y);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline(always)]
    fn start(&self, pixel: [u32; 2], index: u32) -> Domain<&Self>
    where
        Self: Sized,
    {
        Domain::start(self, pixel, index)
    }
}

/// The hooks [`PixelSampler`]'s methods and [`Domain`]'s draws call: what
/// a new pixel sampler implements besides
/// [`samples_per_pixel`](PixelSampler::samples_per_pixel). A renderer
/// never calls these; [`implement`](crate::implement) lists the steps.
///
/// [`root`](Self::root) and [`draw_2d`](Self::draw_2d) are required. The
/// other draws have padded defaults; override them to make draws better
/// (stratified 1D draws, true 4D sets), as [`Padded`], [`ZSobol`] and
/// [`BlueNoise`] do.
pub trait PixelSamplerHooks {
    /// What [`PixelSampler::start`] computes once per pixel sample: the
    /// root key of the domain tree and the sampler's own pixel state.
    fn root(&self, pixel: [u32; 2]) -> Root;

    /// Where sample `index` of a domain keyed `key` lives, after the
    /// index-beyond-the-count rule: `(index in the set, key of the set)`.
    ///
    /// The default is the progressive rule: `(index, key)`.
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        (index, key)
    }

    /// One value in `[0, 1)` for `draw`. The default is the first
    /// coordinate of [`draw_2d`](Self::draw_2d).
    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        self.draw_2d(draw).x
    }

    /// One point in `[0, 1)^2` for `draw`.
    fn draw_2d(&self, draw: Draw) -> Vec2;

    /// One point in `[0, 1)^3`. The default pads a pair and a 1D draw of
    /// [`Draw::second`].
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
}

/// A pixel sampler behind a reference is one too: the borrowed domain
/// [`PixelSampler::start`] returns is a `Domain<&S>`, and a renderer that
/// holds `&dyn PixelSampler` gets a `Domain<&dyn PixelSampler>` (40 bytes)
/// from `Domain::start(sampler, pixel, index)`.
impl<T: PixelSampler + ?Sized> PixelSampler for &T {
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        (**self).samples_per_pixel()
    }
}

impl<T: PixelSampler + ?Sized> PixelSamplerHooks for &T {
    #[inline]
    fn root(&self, pixel: [u32; 2]) -> Root {
        (**self).root(pixel)
    }

    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
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

/// The start of a domain tree, from [`PixelSamplerHooks::root`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Root {
    /// The root key: [`Domain::branch`] and every draw's `stream` derive
    /// from it. [`Padded`] packs the pixel and the frame's key into it
    /// (no hash: each draw mixes the key).
    pub key: u64,
    /// Whatever else the sampler needs per pixel (for [`ZSobol`], the
    /// pixel's Morton block; for [`BlueNoise`], its Morton code), handed
    /// back in every [`Draw`].
    pub pixel_state: u32,
}

/// What one draw of a [`Domain`] hands its sampler.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Draw {
    /// The sample index within its set, after [`PixelSamplerHooks::locate`].
    pub index: u32,
    /// The sampler's pixel state, [`Root::pixel_state`].
    pub pixel_state: u32,
    /// A well-mixed 64-bit value that picks this draw's pattern: [`mix64`]
    /// of the domain's key plus the draw counter times an odd Weyl
    /// increment, so it is the same for every sample index of a pixel (as
    /// a pattern must be) and unrelated between draws, keys and branches.
    pub stream: u64,
    /// The domain's key, for samplers whose draws share one pattern
    /// across a domain ([`PaddedNd`]).
    pub key: u64,
    /// The draw's first scalar dimension within its domain: how many
    /// values the domain's draws before it returned (1 per `next_1d`, 2
    /// per `next_2d`, ...; [`Domain::dimensions`]).
    pub dimension: u32,
}

impl Draw {
    /// Draw number `draw` of a domain keyed `key`, starting at its scalar
    /// dimension `dimension`, at sample `index`: the one formula
    /// [`Domain`] and [`PixelSampler::sample_pixel`] share.
    #[inline(always)]
    #[must_use]
    pub const fn new(key: u64, draw: u32, dimension: u32, index: u32, pixel_state: u32) -> Self {
        Self {
            index,
            pixel_state,
            stream: mix64(key.wrapping_add((draw as u64).wrapping_mul(salt::DRAW_WEYL))),
            key,
            dimension,
        }
    }

    /// The draw with an unrelated `stream` (one [`mix64`]), for samplers
    /// that pad a 3D or 4D draw from two patterns.
    #[inline]
    #[must_use]
    pub const fn second(self) -> Self {
        Self {
            stream: second_stream(self.stream),
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::{Pmj02, Sobol};

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
        assert!(core::mem::size_of::<Domain<Padded<Sobol>>>() <= 48);
    }
}
