use glam::{Vec2, Vec3, Vec4};

use super::{Draw, PixelSampler, PixelSamplerHooks, Root};
use crate::error::Error;
use crate::primitives::morton::morton;
use crate::primitives::{
    child_key, hash_combine, hash_u32, mix64, owen_scramble, prefix_shuffle, salt,
};
use crate::samplers::sequence::digital::{
    OwenSeeds, bits_to_point, scrambled_unit, sobol_4d_point, sobol_point_bits,
};

/// Index bits the Sobol sequence here accepts: the generator matrices are
/// applied to 32-bit indices.
const INDEX_BITS: u32 = 32;

/// Blue-noise error across the screen: the pixels in Morton (Z) order, each
/// owning a block of the Owen-scrambled Sobol (0,2)-sequence, with the
/// blocks shuffled hierarchically (Ahmed & Wonka 2020, pbrt-v4's
/// `ZSobolSampler`).
///
/// # Construction
///
/// For pixel `(x, y)`, sample `index` and a draw whose stream (from the
/// frame, the domain's key and the draw counter) seeds everything below:
///
/// 1. The Morton index of the pixel (bits of `x` and `y` interleaved, `x`
///    in the even bits) shifted up by `m = log2(spp)` is the pixel's block
///    of `spp` sequence indices: consecutive pixels of the Z curve get
///    consecutive blocks, so the four pixels of every 2 x 2 quad together
///    hold `4 spp` consecutive indices, the sixteen of every 4 x 4 quad
///    `16 spp`, and so on.
/// 2. The sample's place inside the block is `index` read through a
///    [`prefix_shuffle`] keyed by the draw and the pixel (so every
///    power-of-two prefix of the pixel is an aligned sub-block, and two
///    draws pair their samples freely, differently in every pixel).
/// 3. That index is moved by a base-2 nested scramble ([`owen_scramble`]:
///    every bit flipped by a hash of the bits above it), which visits the
///    quads of every level of the hierarchy in a random order, different
///    for every draw, and moves each pixel's prefixes to other aligned
///    sub-blocks of its block, differently in every pixel.
/// 4. The result indexes Sobol dimensions 0 and 1 (the same generator
///    matrices as [`Sobol`](crate::Sobol)), Owen-scrambled
///    ([`owen_scramble_reversed`](crate::primitives::owen_scramble_reversed)),
///    and truncated to 24 bits; 1D draws take dimension 0, 3D and 4D draws
///    the 4D Owen-scrambled Sobol' set.
///
/// Neighbouring pixels thus take neighbouring blocks of one (0,2)-sequence,
/// whose union is again a net: their sub-pixel offsets complement each
/// other, so on a smooth image the per-pixel errors of a quad tend to
/// cancel and the error left over is high-frequency (blue) noise.
///
/// # Properties
///
/// - Each pixel's `spp` samples in every 2D draw form a
///   (0,m,2)-net: one point in each `2^-a x 2^-(m-a)` box, `a = 0..=m`,
///   checked exactly on the f32 values (`m <= 24`); 1D draws a (0,m,1)-net,
///   4D draws a (3,m,4)-net for `spp >= 8`.
/// - Inside a pass, every power-of-two prefix `0..2^a` and every dyadic
///   block `[2^a, 2^(a+1))` of the indices is a (0,a,2)-net too; other
///   aligned blocks `[j 2^k, (j + 1) 2^k)` (`j >= 2`) are shuffled subsets
///   of their dyadic block (many are not nets), and a prefix between two
///   powers of two `2^a < n < 2^(a+1)` is the net `0..2^a` plus a uniformly
///   random subset of the next block. Each pass of the pass rule (indices
///   `p spp .. (p + 1) spp`, see Limits) is a complete net, keyed by `p`:
///   a renderer's progressive passes of `spp` samples are nets each
///   ([`DomainSampler`](crate::implement::DomainSampler)'s section on which ranges
///   are nets).
/// - More: for `k` levels of the Morton hierarchy, the `4^k` pixels of an
///   aligned `2^k x 2^k` square together hold a (0, m + 2k, 2)-net.
/// - Different draws use unrelated block scrambles, index shuffles and
///   Owen scrambles, so they are decorrelated (tested for every pixel
///   sampler); each point is uniform over `[0, 1)^2`, so estimates are
///   unbiased.
/// - Error across pixels is blue noise where neighbouring pixels integrate
///   nearly the same function of the sub-pixel offset (a smooth, resolved
///   image); where the image changes completely inside a pixel there is
///   nothing to cancel and the error is as white as per-pixel patterns'.
///   One scramble serves the whole image, so whole-frame RMSE varies more
///   from frame to frame than with per-pixel patterns: compare frames by
///   their average. See `docs/zsobol.md` for measurements.
///
/// # Cost
///
/// `start`: the Morton code of the pixel. Each draw: one
/// [`mix64`], the block's nested scramble, a
/// [`prefix_shuffle`] and a [`Sobol`](crate::Sobol) point.
///
/// # Limits
///
/// The index space is the Morton square: the resolution's longer side
/// rounded up to a power of two, `side`, gives `side^2 x spp` indices,
/// which must fit in the sequence's `2^32`: `2 log2(side) + m <= 32`.
/// 1920 x 1080 (side 2048) allows up to 1024 spp, 3840 x 2160 (side 4096)
/// up to 256, 512 x 512 up to 16384. [`ZSobol::new`] returns
/// [`Error::IndexSpaceTooLarge`] beyond that; render more spp as several
/// passes with different frames and average them. Nets are exact for
/// `spp <= 2^24`, the f32 resolution of `[0, 1)`.
///
/// A pixel outside the resolution is mapped onto the film (`x mod width`,
/// `y mod height`) with every scramble keyed by the tile it fell in, and
/// an `index >= spp` is sample `index mod spp` of pass `index / spp`, with
/// every scramble keyed by the pass: both get complete, unrelated sets,
/// in debug and release builds alike ([`PixelSampler`]'s edge rules).
///
/// # Examples
///
/// ```
/// use wellspread::{PixelSampler, ZSobol, metrics::is_net_base2};
/// let zsobol = ZSobol::new(16, [320, 240], 7)?;
/// for pair in 0..3 {
///     let points: Vec<_> = (0..16)
///         .map(|i| zsobol.sample_pixel([100, 50], i, pair))
///         .collect();
///     assert!(is_net_base2(&points)?);
/// }
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Ahmed & Wonka 2020, "Screen-Space Blue-Noise Diffusion of Monte Carlo
///   Sampling Error via Hierarchical Ordering of Pixels", ACM TOG 39(6).
/// - Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed.
///   (2023), section 8.7.7, `ZSobolSampler`.
/// - Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ZSobol {
    resolution: [u32; 2],
    log2_spp: u32,
    frame: u32,
    /// The root key of its domains, hashed from the frame once here.
    frame_key: u64,
}

impl ZSobol {
    /// A ZSobol sampler for a `resolution = [width, height]` film at
    /// `samples_per_pixel` samples per pixel; `frame` (a frame number, say)
    /// picks one of 2^32 unrelated scrambles.
    ///
    /// # Errors
    ///
    /// - [`Error::ZeroSamples`] for `samples_per_pixel = 0`, and
    ///   [`Error::SamplesNotPowerOfTwo`] for any other count that is not a
    ///   power of two.
    /// - [`Error::ZeroResolution`] for a zero width or height.
    /// - [`Error::IndexSpaceTooLarge`] when `side^2 x spp` exceeds `2^32`
    ///   (see Limits above).
    pub fn new(samples_per_pixel: u32, resolution: [u32; 2], frame: u32) -> Result<Self, Error> {
        super::check_film(samples_per_pixel, resolution)?;
        if !samples_per_pixel.is_power_of_two() {
            return Err(Error::SamplesNotPowerOfTwo { samples_per_pixel });
        }
        let [width, height] = resolution;
        let log2_spp = samples_per_pixel.trailing_zeros();
        let log2_side = u64::from(width.max(height))
            .next_power_of_two()
            .trailing_zeros();
        let bits = 2 * log2_side + log2_spp;
        if bits > INDEX_BITS {
            return Err(Error::IndexSpaceTooLarge {
                resolution,
                samples_per_pixel,
                index_bits: bits,
            });
        }
        Ok(Self {
            resolution,
            log2_spp,
            frame,
            frame_key: mix64(frame as u64 ^ salt::ZSOBOL_FRAME),
        })
    }

    /// The film size this sampler was built for, `[width, height]`.
    #[inline]
    pub const fn resolution(&self) -> [u32; 2] {
        self.resolution
    }

    /// The frame it was built with.
    #[inline]
    pub const fn frame(&self) -> u32 {
        self.frame
    }

    /// `pixel` on the film, and 0 if it was there or else a nonzero key of
    /// the tile of the film's repetition it fell in.
    #[inline(always)]
    fn on_film(&self, [x, y]: [u32; 2]) -> ([u32; 2], u32) {
        let [width, height] = self.resolution;
        if x < width && y < height {
            ([x, y], 0)
        } else {
            self.wrap_onto_film([x, y])
        }
    }

    /// [`on_film`](Self::on_film) for a pixel off the film, out of line.
    #[cold]
    #[inline(never)]
    fn wrap_onto_film(&self, [x, y]: [u32; 2]) -> ([u32; 2], u32) {
        let [width, height] = self.resolution;
        (
            [x % width, y % height],
            hash_combine(x / width, y / height) | 1,
        )
    }

    /// `spp - 1`: the mask of a sample's place in its pixel's block.
    #[inline(always)]
    const fn low_mask(&self) -> u32 {
        (1 << self.log2_spp) - 1
    }

    /// The pixel's Morton index shifted up by `m`: the first sequence index
    /// of its block, before the scramble. `new` checked
    /// `2 log2(side) + m <= 32`, so it fits for pixels on the film.
    #[inline]
    fn block_start(&self, [x, y]: [u32; 2]) -> u32 {
        morton(x, y) << self.log2_spp
    }

    /// The Sobol index of sample `index` (below spp) of the pixel whose
    /// block starts at `block`, for a draw with `stream`: the sample's place
    /// in the block under a [`prefix_shuffle`], then the whole index under
    /// a nested scramble of its bits ([`owen_scramble`]), which moves the
    /// block among the blocks of every level of the Morton hierarchy and
    /// the sample's prefixes among the aligned sub-blocks of the block,
    /// differently in every pixel.
    #[inline(always)]
    fn draw_index(&self, block: u32, index: u32, stream: u64) -> u32 {
        let seeds = OwenSeeds::from_stream(stream);
        let low = self.low_mask();
        // Keyed by the pixel too, so two draws pair their samples
        // differently in every pixel.
        let place = prefix_shuffle(index & low, hash_u32(seeds.index ^ block));
        owen_scramble(
            block | place,
            seeds.x.rotate_right(8) ^ seeds.y.rotate_right(24),
        )
    }
}

impl PixelSampler for ZSobol {
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        Some(1 << self.log2_spp)
    }
}

impl PixelSamplerHooks for ZSobol {
    /// The key from the frame (and the tile, off the film), the pixel
    /// state the Morton block start.
    #[inline(always)]
    fn root(&self, pixel: [u32; 2]) -> Root {
        let (pixel, tile) = self.on_film(pixel);
        Root {
            key: self.frame_key ^ u64::from(tile) << 32,
            pixel_state: self.block_start(pixel),
        }
    }

    /// The fixed-size rule: indices `p spp .. (p + 1) spp` are pass `p`,
    /// a complete set keyed by `p`.
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        let pass = index >> self.log2_spp;
        if pass == 0 {
            (index, key)
        } else {
            (index & self.low_mask(), child_key(key, salt::PASS, pass))
        }
    }

    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        let s = self.draw_index(draw.pixel_state, draw.index, draw.stream);
        scrambled_unit(s, OwenSeeds::from_stream(draw.stream).x)
    }

    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        let s = self.draw_index(draw.pixel_state, draw.index, draw.stream);
        bits_to_point(sobol_point_bits(s, OwenSeeds::from_stream(draw.stream)))
    }

    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        self.draw_4d(draw).truncate()
    }

    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        let s = self.draw_index(draw.pixel_state, draw.index, draw.stream);
        sobol_4d_point(s, draw.stream, [0; 4])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_pixel_owns_one_aligned_block_of_indices() {
        // Sequence indices of one pixel are a bijection of an aligned block
        // of spp, and the pixels of the film share none.
        for spp in [1, 2, 4, 8, 32] {
            let z = ZSobol::new(spp, [8, 8], 3).unwrap();
            let mut seen = std::collections::HashSet::new();
            for y in 0..8 {
                for x in 0..8 {
                    let block: std::vec::Vec<u32> = (0..spp)
                        .map(|i| z.draw_index(z.block_start([x, y]), i, 99))
                        .collect();
                    let base = block[0] / spp;
                    assert!(block.iter().all(|&s| s / spp == base), "spp {spp}");
                    for s in block {
                        assert!(seen.insert(s), "spp {spp}: index {s} twice");
                    }
                }
            }
            assert_eq!(seen.len(), 64 * spp as usize);
        }
    }

    #[test]
    fn quads_share_a_block_of_four_pixels() {
        // The 2 x 2 quad at (2, 6) holds one aligned block of 4 spp indices.
        let z = ZSobol::new(4, [16, 16], 0).unwrap();
        let blocks: std::vec::Vec<u32> = [[2, 6], [3, 6], [2, 7], [3, 7]]
            .iter()
            .flat_map(|&p| (0..4).map(move |i| z.draw_index(z.block_start(p), i, 5) / 16))
            .collect();
        assert!(blocks.iter().all(|&b| b == blocks[0]));
    }

    #[test]
    fn index_space_limits() {
        assert!(ZSobol::new(1024, [1920, 1080], 0).is_ok());
        assert!(ZSobol::new(256, [3840, 2160], 0).is_ok());
        assert_eq!(
            ZSobol::new(512, [3840, 2160], 0),
            Err(Error::IndexSpaceTooLarge {
                resolution: [3840, 2160],
                samples_per_pixel: 512,
                index_bits: 33,
            })
        );
        assert!(ZSobol::new(1, [65536, 65536], 0).is_ok());
        assert!(ZSobol::new(1, [65537, 1], 0).is_err());
        assert!(ZSobol::new(1, [u32::MAX, u32::MAX], 0).is_err());
        assert_eq!(ZSobol::new(0, [4, 4], 0), Err(Error::ZeroSamples));
        assert!(matches!(
            ZSobol::new(12, [4, 4], 0),
            Err(Error::SamplesNotPowerOfTwo {
                samples_per_pixel: 12
            })
        ));
        assert!(matches!(
            ZSobol::new(4, [0, 4], 0),
            Err(Error::ZeroResolution { .. })
        ));
    }

    #[test]
    fn the_largest_film_keeps_its_corner_pixels_apart() {
        let z = ZSobol::new(1, [65536, 65536], 1).unwrap();
        let a = z.draw_index(z.block_start([65535, 65535]), 0, 7);
        let b = z.draw_index(z.block_start([65535, 65534]), 0, 7);
        let c = z.draw_index(z.block_start([0, 0]), 0, 7);
        assert!(a != b && a != c && b != c);
    }
}
