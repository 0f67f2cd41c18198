//! `rand_core::RngCore` for [`Domain`] (feature `rand`): a renderer written
//! against `rand::Rng` draws from a pixel sample's domain by changing where
//! its generator comes from.

use rand_core::RngCore;

use super::{Domain, PixelSampler};

/// `2^24`: a draw in `[0, 1)` times this is its 24 bits.
const SCALE: f32 = 16_777_216.0;

/// The top 24 bits of a draw `v` in `[0, 1)`: `floor(v 2^24)`, exact for
/// every multiple of 2^-24 (the scaling by a power of two is exact, the
/// conversion truncates).
#[inline]
fn bits_24(v: f32) -> u32 {
    (v * SCALE) as u32
}

/// Each call is one 1D draw of the domain ([`Domain::next_1d`]), so that
/// `rng.random::<f32>()` (rand 0.9) returns exactly `next_1d()`.
///
/// - `next_u32` is the draw's 24 bits in the top of the word, the low 8
///   bits 0: `floor(v 2^24) << 8`. rand 0.9 makes an `f32` from the top 24
///   bits of a `u32`, `(u >> 8) as f32 * 2^-24`, which gives `v` back.
/// - `next_u64` is one draw too, its 24 bits in the top of the word
///   (`floor(v 2^24) << 40`): rand's `f64` (the top 53 bits times 2^-53) is
///   `v` exactly.
/// - `fill_bytes` writes 3 bytes per draw (its 24 bits, most significant
///   first).
///
/// Every pixel sampler of the crate returns multiples of 2^-24 (its one
/// conversion to f32 truncates to 24 bits), so the values are exact; a
/// sampler of one's own with finer values gets them truncated to 24 bits.
///
/// # What it gives, and what it cannot
///
/// Each call is the next dimension of the domain, stratified in 1D over
/// the pixel's samples where the sampler allows (see each sampler's
/// `draw_1d`): a renderer that draws its lens, light and BSDF numbers one
/// `random::<f32>()` at a time gets every number stratified on its own.
/// Two calls are two separate dimensions, so a pair of them is not
/// stratified in 2D (the film position, a point on a light): for those,
/// call [`Domain::next_2d`] (or `next_3d`, `next_4d`) on the same domain,
/// which keeps the pair's joint strata. Integer draws (`random_range(0..n)`
/// with rand's widening multiply) use the top bits, so they are stratified
/// choices too; anything that reads the low 8 bits of a word sees zeros.
///
/// # Examples
///
/// ```
/// use rand::Rng;
/// use wellspread::{Padded, PixelSampler, Sobol};
///
/// let pixels = Padded::new(Sobol::new(16)?, 0);
/// let (mut rng, mut d) = (pixels.start([3, 4], 5), pixels.start([3, 4], 5));
/// for _ in 0..8 {
///     assert_eq!(rng.random::<f32>(), d.next_1d());
/// }
/// // Over a pixel's 16 samples, one dimension is one value per 1/16.
/// let mut seen = [false; 16];
/// for index in 0..16 {
///     let mut rng = pixels.start([3, 4], index);
///     seen[(rng.random::<f32>() * 16.0) as usize] = true;
/// }
/// assert!(seen.iter().all(|&s| s));
/// # Ok::<(), wellspread::Error>(())
/// ```
#[cfg_attr(docsrs, doc(cfg(feature = "rand")))]
impl<S: PixelSampler> RngCore for Domain<S> {
    #[inline]
    fn next_u32(&mut self) -> u32 {
        bits_24(self.next_1d()) << 8
    }

    #[inline]
    fn next_u64(&mut self) -> u64 {
        u64::from(bits_24(self.next_1d())) << 40
    }

    fn fill_bytes(&mut self, dst: &mut [u8]) {
        for chunk in dst.chunks_mut(3) {
            let bytes = bits_24(self.next_1d()).to_be_bytes();
            chunk.copy_from_slice(&bytes[1..1 + chunk.len()]);
        }
    }
}
