//! Samples addressed the way a renderer asks for them: by pixel, sample
//! index and dimension pair.

use glam::Vec2;

use crate::{Sampler2D, pattern_seed};

/// Sample positions for a whole image: sample `index` of pixel `pixel` in
/// dimension pair `dimension`.
///
/// `dimension` counts 2D pairs: 0 is usually the offset inside the pixel,
/// then the lens, time, the light, and so on, each pair a fresh well-spread
/// pattern that is decorrelated from the others. `index` runs over
/// `0..samples_per_pixel()`.
///
/// # Properties
///
/// - `sample_pixel` is O(1) and pure: the same arguments give the same
///   point on every thread, machine and run, so any tile order renders the
///   same image. Implementors are `Send + Sync`.
/// - Both coordinates are in `[0, 1)`.
///
/// Implementations: [`Padded`] turns any [`Sampler2D`] into a pixel
/// sampler (white-noise error across pixels), and
/// [`ZSobol`](crate::ZSobol) spreads the error across pixels as blue noise.
/// [`PixelCursor`] hands out the dimension pairs one after another.
///
/// # Examples
///
/// A box-filtered pixel loop with three dimension pairs (film position,
/// lens, light):
///
/// ```
/// use wellspread::{PixelSampler, ZSobol};
///
/// let (width, height) = (64, 48);
/// let sampler = ZSobol::new(16, [width, height], 0)?;
/// let mut image = vec![0.0f32; (width * height) as usize];
/// for py in 0..height {
///     for px in 0..width {
///         let mut sum = 0.0;
///         for index in 0..sampler.samples_per_pixel() {
///             let mut cursor = sampler.cursor([px, py], index);
///             let film = cursor.next_2d(); // dimension pair 0
///             let lens = cursor.next_2d(); // 1
///             let light = cursor.next_2d(); // 2
///             let (x, y) = (px as f32 + film.x, py as f32 + film.y);
///             sum += (x * 0.1).sin() * (y * 0.1).cos() * lens.x * light.y;
///         }
///         image[(py * width + px) as usize] = sum / sampler.samples_per_pixel() as f32;
///     }
/// }
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait PixelSampler: Send + Sync {
    /// Samples per pixel: `index` runs over `0..samples_per_pixel()`.
    fn samples_per_pixel(&self) -> u32;

    /// Sample `index` of pixel `pixel` (`[x, y]`) in dimension pair
    /// `dimension`, in O(1).
    ///
    /// `index` must be below [`samples_per_pixel`](Self::samples_per_pixel)
    /// and the pixel inside the resolution the sampler was built for
    /// (checked in debug builds); each implementation documents what a
    /// release build returns otherwise, always a point in `[0, 1)^2`.
    fn sample_pixel(&self, pixel: [u32; 2], index: u32, dimension: u32) -> Vec2;

    /// A cursor at sample `index` of `pixel`, handing out dimension pairs
    /// 0, 1, 2, ... one per [`next_2d`](PixelCursor::next_2d).
    #[inline]
    fn cursor(&self, pixel: [u32; 2], index: u32) -> PixelCursor<'_, Self>
    where
        Self: Sized,
    {
        PixelCursor::new(self, pixel, index)
    }
}

/// Any [`Sampler2D`] as a [`PixelSampler`]: pixel `[x, y]`, dimension pair
/// `d` uses pattern `pattern_seed(x, y, seed, d)` ([`pattern_seed`]), so
/// every pixel and every dimension pair gets an independent randomisation
/// ("padding").
///
/// # Properties
///
/// - Each pixel's `len()` samples in each dimension pair are one set of the
///   wrapped sampler, with all its guarantees (stratification, nets).
/// - Different pixels, dimension pairs and seeds get unrelated patterns, so
///   the error is white noise across pixels. Pair this with a sampler that
///   shuffles its index ([`Sobol`](crate::Sobol), [`Pmj02`](crate::Pmj02),
///   the grid family): [`Halton`](crate::Halton) and
///   [`Hammersley`](crate::Hammersley) visit points in the same order for
///   every pattern, which correlates dimension pairs (see their docs).
///
/// # Cost
///
/// One [`pattern_seed`] (four hashes) plus the wrapped sampler's `sample`.
///
/// # Examples
///
/// ```
/// use wellspread::{Padded, PixelSampler, Sampler2D, Sobol, pattern_seed};
/// let pixels = Padded::new(Sobol::new(16)?, 7);
/// assert_eq!(pixels.samples_per_pixel(), 16);
/// let lens = pixels.sample_pixel([3, 4], 5, 1);
/// assert_eq!(lens, Sobol::new(16)?.sample(5, pattern_seed(3, 4, 7, 1)));
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Padded<S> {
    sampler: S,
    seed: u32,
}

impl<S: Sampler2D> Padded<S> {
    /// `sampler` for every pixel and dimension pair; `seed` (a frame
    /// number, say) picks one of 2^32 unrelated sets of patterns.
    #[inline]
    pub const fn new(sampler: S, seed: u32) -> Self {
        Self { sampler, seed }
    }

    /// The wrapped sampler.
    #[inline]
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The seed, the `frame` argument of [`pattern_seed`].
    #[inline]
    pub const fn seed(&self) -> u32 {
        self.seed
    }
}

impl<S: Sampler2D + Send + Sync> PixelSampler for Padded<S> {
    #[inline]
    fn samples_per_pixel(&self) -> u32 {
        self.sampler.len()
    }

    #[inline]
    fn sample_pixel(&self, [x, y]: [u32; 2], index: u32, dimension: u32) -> Vec2 {
        self.sampler
            .sample(index, pattern_seed(x, y, self.seed, dimension))
    }
}

/// A renderer's inner-loop state for one sample of one pixel: which pixel,
/// which sample, and the next dimension pair to hand out (pbrt-v4's
/// `StartPixelSample` / `Get2D`).
///
/// It is a thin adapter over [`PixelSampler::sample_pixel`]: the `k`-th
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

    /// The next dimension pair's first coordinate, for a 1D need (time,
    /// a light choice); the pair's second coordinate goes unused.
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

    #[test]
    fn cursor_restarts_at_dimension_zero() {
        let pixels = Padded::new(Sobol::new(4).unwrap(), 0);
        let mut cursor = pixels.cursor([0, 0], 0);
        cursor.next_2d();
        cursor.next_1d();
        assert_eq!(cursor.dimension(), 2);
        cursor.start_pixel_sample([5, 6], 2);
        assert_eq!(
            (cursor.pixel(), cursor.index(), cursor.dimension()),
            ([5, 6], 2, 0)
        );
        assert_eq!(cursor.next_2d(), pixels.sample_pixel([5, 6], 2, 0));
    }

    fn assert_send_sync<T: Send + Sync>() {}

    #[test]
    fn pixel_samplers_are_send_and_sync() {
        assert_send_sync::<Padded<Sobol>>();
        assert_send_sync::<crate::ZSobol>();
        assert_send_sync::<PixelCursor<'_, Padded<Sobol>>>();
    }
}
