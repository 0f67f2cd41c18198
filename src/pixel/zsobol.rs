use glam::{Vec2, Vec3, Vec4};

use super::padded::{seeds_2d, sobol_1d_at, sobol_2d_at, sobol_4d_at};
use super::{Draw, PixelSampler, Root};
use crate::Error;
use crate::primitives::{hash_combine, hash_u32, owen_scramble};
use crate::samplers::sequence::digital::{OwenSeeds, bits_to_point, scrambled_bits};
use crate::samplers::sequence::sobol::pascal_reversed;

/// The 24 permutations of `{0, 1, 2, 3}` in lexicographic order, each packed
/// two bits per entry: entry `d` is `(PERMUTATIONS_4[p] >> 2 d) & 3`.
const PERMUTATIONS_4: [u8; 24] = {
    let mut table = [0u8; 24];
    let mut count = 0;
    let mut code = 0u32;
    // Every 4-digit base-4 number whose digits are distinct, in order.
    while code < 256 {
        let d = [code >> 6 & 3, code >> 4 & 3, code >> 2 & 3, code & 3];
        let seen = (1u32 << d[0]) | (1 << d[1]) | (1 << d[2]) | (1 << d[3]);
        if seen == 0b1111 {
            table[count] = (d[0] | d[1] << 2 | d[2] << 4 | d[3] << 6) as u8;
            count += 1;
        }
        code += 1;
    }
    table
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
/// For pixel `(x, y)`, sample `index` and dimension pair `d`:
///
/// 1. The Morton index of the pixel (bits of `x` and `y` interleaved, `x`
///    in the even bits) is shifted up by `m = log2(spp)` and `index` fills
///    the low bits: consecutive pixels of the Z curve get consecutive
///    blocks of `spp` sequence indices, so the four pixels of every 2 x 2
///    quad together hold `4 spp` consecutive indices, the sixteen of every
///    4 x 4 quad `16 spp`, and so on.
/// 2. That index is read as base-4 digits (for odd `m` the lowest digit is
///    a single bit), and each digit is mapped by one of the 24 permutations
///    of `{0, 1, 2, 3}` (one bit flip or not for the single bit), chosen by
///    a hash of the digits above it, the frame and `d`: a nested scramble
///    that visits the quads of every level in a random order, different for
///    every dimension pair.
/// 3. The result indexes Sobol dimensions 0 and 1 (the same generator
///    matrices as [`Sobol`](crate::Sobol)), Owen-scrambled with seeds hashed
///    from the frame and `d` ([`owen_scramble_reversed`](crate::primitives::owen_scramble_reversed)),
///    and truncated to 24 bits.
///
/// Neighbouring pixels thus take neighbouring blocks of one (0,2)-sequence,
/// whose union is again a net: their sub-pixel offsets complement each
/// other, so on a smooth image the per-pixel errors of a quad tend to
/// cancel and the error left over is high-frequency (blue) noise.
///
/// # Properties
///
/// - Each pixel's `spp` samples in every dimension pair form a
///   (0,m,2)-net: one point in each `2^-a x 2^-(m-a)` box, `a = 0..=m`,
///   checked exactly on the f32 values (`m <= 24`).
/// - More: for `k` levels of the Morton hierarchy, the `4^k` pixels of an
///   aligned `2^k x 2^k` square together hold a (0, m + 2k, 2)-net.
/// - Different dimension pairs use unrelated digit permutations and
///   scrambles, so they are decorrelated; each point is uniform over
///   `[0, 1)^2`, so estimates are unbiased.
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
/// One [`hash_combine`] and the four hashes of the per-pair seeds, one
/// [`hash_u32`] per base-4 digit of the index (`log2(side) + ceil(m / 2)`
/// digits, at most 16), then a [`Sobol`](crate::Sobol) point without its
/// index shuffle.
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
/// # Domains
///
/// Through a [`Domain`](crate::Domain) each draw uses the same Morton
/// ordering as `sample_pixel`, keyed by the draw's stream instead of
/// `(frame, dimension)`, with the blocks of each level shuffled by one
/// base-2 nested scramble instead of a hashed base-4 permutation per digit
/// (so the values differ from `sample_pixel`'s), and every draw keeps the
/// properties above: 2D draws are Sobol' dimensions (0, 1) of the pixel's
/// permuted block; 1D draws its dimension 0 (a (0,m,1)-net per pixel); 3D
/// and 4D draws the 4D Sobol' set of [`DomainSampler`](crate::DomainSampler)'s
/// table on that block ((3,m,4)-nets per pixel for `spp >= 8`, and the
/// quads of the Morton hierarchy together finer nets). The pixel's Morton
/// index is computed once, in `start`; the permutations are per draw. The
/// scrambles do not depend on the pixel, so no pattern repeats across the
/// film (no 256-pixel tile: tested).
///
/// # Examples
///
/// ```
/// use wellspread::{PixelSampler, ZSobol, metrics::is_net_base2};
/// let zsobol = ZSobol::new(16, [320, 240], 7)?;
/// for dimension in 0..3 {
///     let points: Vec<_> = (0..16)
///         .map(|i| zsobol.sample_pixel([100, 50], i, dimension))
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
    samples_per_pixel: u32,
    resolution: [u32; 2],
    log2_spp: u32,
    /// Base-4 digits of the index, the single low bit of an odd `m`
    /// counted as one.
    base4_digits: u32,
    frame: u32,
    /// The root key of its domains, hashed from the frame once here.
    frame_key: u32,
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
    /// - [`Error::ZeroGridSide`] for a zero width or height.
    /// - [`Error::IndexSpaceTooLarge`] when `side^2 x spp` exceeds `2^32`
    ///   (see Limits above).
    pub fn new(samples_per_pixel: u32, resolution: [u32; 2], frame: u32) -> Result<Self, Error> {
        if samples_per_pixel == 0 {
            return Err(Error::ZeroSamples);
        }
        if !samples_per_pixel.is_power_of_two() {
            return Err(Error::SamplesNotPowerOfTwo { samples_per_pixel });
        }
        let [width, height] = resolution;
        if width == 0 || height == 0 {
            return Err(Error::ZeroGridSide {
                columns: width,
                rows: height,
            });
        }
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
            samples_per_pixel,
            resolution,
            log2_spp,
            base4_digits: log2_side + log2_spp.div_ceil(2),
            frame,
            frame_key: hash_u32(frame ^ 0x7a3c_9e15),
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

    /// The pixel's Morton index shifted up by `m`: the first sequence index
    /// of its block, before the permutations. `new` checked
    /// `2 log2(side) + m <= 32`, so it fits for pixels on the film.
    #[inline]
    fn block_start(&self, [x, y]: [u32; 2]) -> u32 {
        // On the film both coordinates are below 2^16 (`new` checked the
        // index space), so the 32-bit interleave is exact; it also keeps
        // the low 16 bits of larger ones, as the 64-bit form did.
        (morton_32(x, y) << self.log2_spp) as u32
    }

    /// The Sobol index of sample `index` of the pixel whose block starts
    /// at `block`, for a [`Domain`](crate::Domain) draw keyed `stream`: the
    /// Morton-ordered index under a base-2 nested scramble
    /// ([`owen_scramble`]: every bit flipped by a hash of the bits above
    /// it), which permutes the blocks of every level of the Morton
    /// hierarchy among themselves as the base-4 digit permutations of
    /// `sample_pixel` do, from the 8 of the 24 orders of each quad that
    /// nested bit flips reach, at the cost of one scramble instead of one
    /// hash per digit.
    #[inline(always)]
    fn draw_index(&self, block: u32, index: u32, stream: u32) -> u32 {
        owen_scramble(block | (index & (self.samples_per_pixel - 1)), stream)
    }

    /// The Sobol index of sample `index` (below spp) of the pixel whose
    /// block starts at `block`, after the Morton ordering and the digit
    /// permutations (`permutation_key` picks the dimension's permutations).
    #[inline]
    fn sequence_index(&self, block: u32, index: u32, permutation_key: u32) -> u32 {
        let morton_index = block | (index & (self.samples_per_pixel - 1));
        let odd = self.log2_spp & 1;
        let mut permuted = 0u32;
        // Digit i covers bits `2 i - odd` and the one above; for odd m the
        // lowest digit (i = 0) is the single bit 0, handled below.
        for i in (odd..self.base4_digits).rev() {
            let shift = 2 * i - odd;
            let digit = (morton_index >> shift) & 3;
            let permutation =
                PERMUTATIONS_4[pick(node(morton_index, shift + 2), permutation_key, 24)];
            permuted |= u32::from(permutation >> (2 * digit) & 3) << shift;
        }
        if odd == 1 {
            let flip = hash_u32(node(morton_index, 1) ^ permutation_key) >> 31;
            permuted |= (morton_index & 1) ^ flip;
        }
        permuted
    }
}

/// The low 16 bits of `x` and `y` interleaved, `x` in the even bits.
#[inline]
const fn morton_32(x: u32, y: u32) -> u64 {
    (spread_16(x) | spread_16(y) << 1) as u64
}

/// The low 16 bits of `v` moved to the even positions of a u32.
#[inline]
const fn spread_16(v: u32) -> u32 {
    let mut v = v & 0xffff;
    v = (v | v << 8) & 0x00ff_00ff;
    v = (v | v << 4) & 0x0f0f_0f0f;
    v = (v | v << 2) & 0x3333_3333;
    v = (v | v << 1) & 0x5555_5555;
    v
}

/// The node of the digit tree above bit `from`: the digits of `index` from
/// bit `from` up, with a marker bit above them so that equal digit values
/// at different depths name different nodes.
#[inline]
const fn node(index: u32, from: u32) -> u32 {
    if from >= 32 {
        1
    } else {
        // The marker sits at bit 32 - from <= 31.
        (index >> from) | 1 << (32 - from)
    }
}

/// A value in `0..count` from a hash of `node` and `key` (Lemire's
/// multiply-shift reduction; bias below `count / 2^32`).
#[inline]
const fn pick(node: u32, key: u32, count: u32) -> usize {
    ((hash_u32(node ^ key) as u64 * count as u64) >> 32) as usize
}

impl PixelSampler for ZSobol {
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        Some(self.samples_per_pixel)
    }

    /// Sample `index` of `pixel` in dimension pair `dimension`; see the
    /// type's Limits for out-of-range arguments.
    #[inline]
    fn sample_pixel(&self, pixel: [u32; 2], index: u32, dimension: u32) -> Vec2 {
        let (pixel, tile) = self.on_film(pixel);
        let pass = index >> self.log2_spp;
        // `index` seeds the permutations, `x` and `y` the Owen scrambles:
        // three independent hashes of (frame, dimension).
        let mut pattern = hash_combine(self.frame, dimension);
        if tile != 0 || pass != 0 {
            pattern = hash_combine(pattern, tile ^ hash_u32(pass));
        }
        let seeds = OwenSeeds::new(pattern);
        let s = self.sequence_index(self.block_start(pixel), index, seeds.index);
        // Dimension 0's generator is the identity: its reversed digits are `s`.
        bits_to_point(scrambled_bits(s, pascal_reversed(s), seeds))
    }

    /// The key from the frame (and the tile, off the film), the pixel
    /// state the Morton block start.
    #[inline(always)]
    fn root(&self, pixel: [u32; 2]) -> Root {
        let (pixel, tile) = self.on_film(pixel);
        let key = self.frame_key;
        Root {
            key: if tile == 0 {
                key
            } else {
                hash_combine(key, tile)
            },
            pixel: self.block_start(pixel),
        }
    }

    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        let seeds = seeds_2d(draw.stream);
        let s = self.draw_index(draw.pixel_state, draw.index, seeds.index);
        sobol_1d_at(s, seeds.x)
    }

    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        let seeds = seeds_2d(draw.stream);
        let s = self.draw_index(draw.pixel_state, draw.index, seeds.index);
        sobol_2d_at(s, seeds)
    }

    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        self.draw_4d(draw).truncate()
    }

    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        let s = self.draw_index(draw.pixel_state, draw.index, draw.stream);
        sobol_4d_at(s, draw.stream)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_permutation_table_holds_each_permutation_once() {
        let mut seen = std::vec::Vec::new();
        for &p in &PERMUTATIONS_4 {
            let entries: std::vec::Vec<u8> = (0..4).map(|d| p >> (2 * d) & 3).collect();
            let mut sorted = entries.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, [0, 1, 2, 3], "{p:#010b}");
            assert!(!seen.contains(&p));
            seen.push(p);
        }
        assert_eq!(seen.len(), 24);
    }

    #[test]
    fn morton_interleaves_x_in_the_even_bits() {
        assert_eq!(morton_32(1, 0), 1);
        assert_eq!(morton_32(0, 1), 2);
        assert_eq!(morton_32(3, 3), 15);
        assert_eq!(morton_32(0b101, 0b010), 0b01_10_01);
        assert_eq!(morton_32(0xffff, 0), 0x5555_5555);
        assert_eq!(morton_32(0xffff, 0xffff), 0xffff_ffff);
    }

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
                        .map(|i| z.sequence_index(z.block_start([x, y]), i, 99))
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
            .flat_map(|&p| (0..4).map(move |i| z.sequence_index(z.block_start(p), i, 5) / 16))
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
            Err(Error::ZeroGridSide { .. })
        ));
    }

    #[test]
    fn the_largest_film_keeps_its_corner_pixels_apart() {
        let z = ZSobol::new(1, [65536, 65536], 1).unwrap();
        let a = z.sequence_index(z.block_start([65535, 65535]), 0, 7);
        let b = z.sequence_index(z.block_start([65535, 65534]), 0, 7);
        let c = z.sequence_index(z.block_start([0, 0]), 0, 7);
        assert!(a != b && a != c && b != c);
    }
}
