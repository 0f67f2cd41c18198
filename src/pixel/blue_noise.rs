//! Screen-space blue noise that survives progressive rendering: one digital
//! point set over (pixel, sample) whose sample columns are Sobol's and whose
//! pixel columns were searched so that neighbouring pixels complement each
//! other at every prefix, Owen-scrambled per frame and dimension pair.

use glam::Vec2;

use crate::primitives::{hash_combine, hash_u32, owen_scramble, owen_scramble_reversed};
use crate::{Error, PixelSampler};

/// Salts that split a dimension pair's seed into the index shuffle's and
/// the two coordinates' scramble seeds (fixed odd words with about half
/// their bits set).
const SALT_INDEX: u32 = 0x2c1b_3c6d;
const SALT_X: u32 = 0x297a_2d39;
const SALT_Y: u32 = 0x9e48_5565;
const SALT_PIXEL: u32 = 0x6a09_e667;

/// Bits of `x` and `y` the pixel columns cover: a `65536 x 65536` square.
const TILE_BITS: u32 = 16;

/// Fixed-point digits of a coordinate: the f32 resolution of `[0, 1)`.
const DIGITS: u32 = 24;

/// The pixel columns of the generator matrix: entry `2 j` is the
/// contribution (x digits, y digits, 24-bit natural order: bit 23 is the
/// digit of weight 1/2) of bit `j` of the pixel's `x`, entry `2 j + 1`
/// that of bit `j` of `y`. Entries 0..8 (the 2 x 2 to 16 x 16 levels of
/// the pixel hierarchy) are the result of
/// `cargo run --release --example blue_noise_search`, a deterministic
/// hill-climb on the blurred error; the rest are its fixed pseudo-random
/// start. `the_columns_are_independent` tests that together with the
/// first 16 Sobol columns they span all 48 digits.
const PIXEL_COLUMNS: [[u32; 2]; 32] = [
    [0x5ed9e5, 0x7ba552],
    [0x69f8d4, 0xbc9f6b],
    [0x6842b8, 0x6bbd15],
    [0x1b27b0, 0x59d62b],
    [0x3dcc48, 0x6a751e],
    [0x21ae75, 0x750b34],
    [0x60298f, 0x05666a],
    [0x212e2b, 0x721e50],
    [0x277021, 0x2f62c0],
    [0x14d14e, 0x75d837],
    [0x377070, 0x62b04a],
    [0x1bfe8e, 0x5f2075],
    [0x6158ab, 0x1f2d89],
    [0x632471, 0x674253],
    [0x56355f, 0x01b3c5],
    [0x76ba7e, 0x53df9e],
    [0x32524a, 0x32010a],
    [0x1429af, 0x7a80d2],
    [0x5c6c29, 0x473349],
    [0x3561ed, 0x2be8a2],
    [0x2e7ee5, 0x5f71ca],
    [0x57132a, 0x0e3de8],
    [0x39823e, 0x1ffa96],
    [0x11e22a, 0x14299a],
    [0x018360, 0x0a35e1],
    [0x3cfd76, 0x0df7b7],
    [0x2e8138, 0x6e1b84],
    [0x158577, 0x3a0e48],
    [0x737f7c, 0x348199],
    [0x2067f4, 0x10ee15],
    [0x2ea49f, 0x6e625b],
    [0x0782f2, 0x4b706d],
];

/// [`PIXEL_COLUMNS`] combined per byte of the Morton code: entry
/// `[b][v]` is the xor of the columns of the set bits of `v << 8 b`.
const PIXEL_TABLE: [[[u32; 2]; 256]; 4] = {
    let mut table = [[[0u32; 2]; 256]; 4];
    let mut b = 0;
    while b < 4 {
        let mut v = 0;
        while v < 256 {
            let mut bit = 0;
            while bit < 8 {
                if v >> bit & 1 == 1 {
                    let column = PIXEL_COLUMNS[8 * b + bit];
                    table[b][v][0] ^= column[0];
                    table[b][v][1] ^= column[1];
                }
                bit += 1;
            }
            v += 1;
        }
        b += 1;
    }
    table
};

/// Blue-noise error across the screen at every prefix of every pixel: one
/// digital point set over all pixels and samples, whose sample columns are
/// those of the Sobol (0,2)-sequence and whose pixel columns make
/// neighbouring pixels complement each other, Owen-scrambled per frame and
/// dimension pair.
///
/// # Construction
///
/// For frame `f`, dimension pair `d`, pixel `p = (x, y)` and sample
/// `index`, in 24-digit fixed point:
///
/// 1. `s = owen_scramble(index, seed_i)`: Burley's index shuffle, the same
///    for every pixel, so each power-of-two prefix is an aligned block of
///    the sequence, and different pairs visit it in unrelated orders.
/// 2. `c`: the pixel's Morton code (bits of `x` and `y` interleaved),
///    shuffled the same way (per frame, pair and tile), so aligned squares
///    of pixels keep aligned blocks of codes, while which pixel of a
///    square gets which shift changes with every frame and pair. (Keeping
///    the low bits fixed, one tuned arrangement per 16 x 16 block, lowers
///    the blurred error on image-space integrands by about a fifth but
///    gives every pair of a pixel the same shift, which correlates a
///    sample's draws across pixels.)
/// 3. `q = C s xor G c`: `C s` is Sobol point `s` (dimensions 0 and 1, the
///    [`Sobol`](crate::Sobol) generator matrices), and `G c` the xor of the
///    pixel columns `G` of the set bits of `c`: a digital shift per pixel.
/// 4. The point is `q` with both coordinates Owen-scrambled
///    ([`owen_scramble_reversed`]), seeds hashed from `f`, `d` and the
///    `65536 x 65536` tile of the pixel.
///
/// A digital shift maps elementary intervals onto elementary intervals,
/// and so does an Owen scramble: each pixel's power-of-two prefixes keep
/// the nets of the Sobol sequence, and each pixel's samples have the
/// distribution of an Owen-scrambled Sobol set ([`Padded`](crate::Padded)
/// `<Sobol>`'s). Over a block of neighbouring pixels, the prefix of `2^m`
/// samples is the union of `2^m`-point nets shifted by the block's
/// columns; a Walsh coefficient of the integrand that the block's shifts
/// do not all leave alone cancels in the block's sum, so it leaves only
/// high-frequency error on the screen. Which coefficients matter depends on
/// `m`; `G` was searched so that the low ones cancel within small blocks
/// for every prefix at once (unlike ZSobol, whose block structure is made
/// for one count). Neither the count nor the resolution enters the formula,
/// so every prefix of every count gets the same treatment.
///
/// # Properties
///
/// - Every power-of-two prefix `0..2^m` (and every aligned block) of every
///   pixel in every dimension pair is a (0,m,2)-net, checked exactly on the
///   f32 values (`m <= 24`); in particular every such prefix is Latin.
/// - Each point is uniform over `[0, 1)^2`; estimates are unbiased, with
///   the per-pixel variance of `Padded<Sobol>`.
/// - Blue-noise error across pixels at every prefix on integrands that are
///   smooth inside a pixel: `docs/blue_noise.md` measures the blurred RMSE
///   at 0.3 to 0.6 times `Padded<Sobol>`'s.
/// - Dimension pairs and frames use unrelated shuffles and scrambles, so
///   they are decorrelated, and averaging frames converges.
/// - No tile: the 2^32 pixels of a `65536 x 65536` square get distinct
///   shifts, and no two of them the same set of 2^16 or fewer samples;
///   beyond that square, its position is hashed into the scramble seeds.
///   One scramble serves the whole frame, so a single frame's overall
///   error varies more from frame to frame than with per-pixel patterns.
///
/// # Cost
///
/// Per sample: the pair's seeds (six hashes), the index shuffle, the code
/// shuffle and two coordinate scrambles (four Owen scrambles, one more
/// than a [`Sobol`](crate::Sobol) point), the Morton code and four
/// lookups in an 8 KiB table computed at compile time from the 256-byte
/// column list. Callgrind counts about 395 x86-64 instructions per
/// `sample_pixel` through `&dyn PixelSampler` at scattered pixels (release
/// build): 1.5 times `Padded<Sobol>`'s 264 and 0.6 times `ZSobol`'s 662.
///
/// # Limits
///
/// Any count from 1 to `2^32 - 1` ([`new`](Self::new)) or none
/// ([`unbounded`](Self::unbounded)), any resolution. Nets are exact up to
/// `2^24` samples, the f32 resolution of `[0, 1)`. Edges follow the
/// crate's rule for progressive sequences, in debug and release alike: an
/// index at or past the count is the next sample of the same sequence
/// (`new(n, ..)` is a prefix of [`unbounded`](Self::unbounded)), and every
/// `[u32; 2]` is a pixel of its own, inside the resolution or not (the
/// resolution is only recorded).
///
/// # Examples
///
/// ```
/// use wellspread::{BlueNoise, PixelSampler, metrics::is_net_base2};
/// let sampler = BlueNoise::new(12, [320, 240], 7)?;
/// for dimension in 0..3 {
///     // Every power-of-two prefix of a 12-sample pixel is a net.
///     for n in [1, 2, 4, 8] {
///         let points: Vec<_> = (0..n)
///             .map(|i| sampler.sample_pixel([100, 50], i, dimension))
///             .collect();
///         assert!(is_net_base2(&points)?);
///     }
/// }
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Heitz, Belcour, Ostromoukhov, Coeurjolly & Iehl 2019, "A Low-Discrepancy
///   Sampler that Distributes Monte Carlo Errors as a Blue Noise in Screen
///   Space", SIGGRAPH Talks: per-pixel randomisations of one shared
///   sequence, chosen offline.
/// - Ahmed & Wonka 2020, "Screen-Space Blue-Noise Diffusion of Monte Carlo
///   Sampling Error via Hierarchical Ordering of Pixels", ACM TOG 39(6):
///   the Morton hierarchy of pixels.
/// - Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4).
/// - Owen 1997, "Monte Carlo variance of scrambled net quadrature", SIAM J.
///   Numer. Anal. 34(5): why scrambled nets cancel Walsh coefficients.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BlueNoise {
    /// Samples per pixel; `None` for a progressive (unbounded) sampler.
    samples_per_pixel: Option<u32>,
    resolution: [u32; 2],
    frame: u32,
}

impl BlueNoise {
    /// A sampler for a `resolution = [width, height]` film at
    /// `samples_per_pixel` samples per pixel (any count: the first `n`
    /// samples of a pixel are those of every larger count); `frame` picks
    /// one of 2^32 unrelated scrambles.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `samples_per_pixel = 0`, and
    /// [`Error::ZeroGridSide`] for a zero width or height.
    pub fn new(samples_per_pixel: u32, resolution: [u32; 2], frame: u32) -> Result<Self, Error> {
        if samples_per_pixel == 0 {
            return Err(Error::ZeroSamples);
        }
        Self::unbounded(resolution, frame).map(|s| Self {
            samples_per_pixel: Some(samples_per_pixel),
            ..s
        })
    }

    /// A progressive sampler: no sample count, every index in `0..2^32` is
    /// valid, and the first `n` samples of a pixel are those of
    /// `BlueNoise::new(n, ..)`.
    /// [`samples_per_pixel`](PixelSampler::samples_per_pixel) is `None`;
    /// ask for the indices you want.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroGridSide`] for a zero width or height.
    pub fn unbounded(resolution: [u32; 2], frame: u32) -> Result<Self, Error> {
        let [width, height] = resolution;
        if width == 0 || height == 0 {
            return Err(Error::ZeroGridSide {
                columns: width,
                rows: height,
            });
        }
        Ok(Self {
            samples_per_pixel: None,
            resolution,
            frame,
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

    /// The sample count, `None` for a progressive sampler.
    #[inline]
    pub const fn count(&self) -> Option<u32> {
        self.samples_per_pixel
    }

    /// The digital shift `G code` of a pixel whose (shuffled) Morton code
    /// is `code`, in 24-digit natural order, x then y.
    #[inline]
    pub(crate) fn pixel_shift(code: u32) -> [u32; 2] {
        let mut shift = [0, 0];
        for (b, table) in PIXEL_TABLE.iter().enumerate() {
            let entry = table[(code >> (8 * b)) as usize & 0xff];
            shift[0] ^= entry[0];
            shift[1] ^= entry[1];
        }
        shift
    }
}

/// `x` and `y` (their low 16 bits) interleaved, `x` in the even bits.
#[inline(always)]
const fn morton(x: u32, y: u32) -> u32 {
    spread_bits(x) | spread_bits(y) << 1
}

/// The low 16 bits of `v` moved to the even positions.
#[inline(always)]
const fn spread_bits(v: u32) -> u32 {
    let mut v = v & ((1 << TILE_BITS) - 1);
    v = (v | v << 8) & 0x00ff_00ff;
    v = (v | v << 4) & 0x0f0f_0f0f;
    v = (v | v << 2) & 0x3333_3333;
    v = (v | v << 1) & 0x5555_5555;
    v
}

/// Sobol dimension 1 in reversed bit order (the Pascal matrix mod 2); the
/// same five steps as [`Sobol`](crate::Sobol)'s.
#[inline(always)]
const fn pascal_reversed(index: u32) -> u32 {
    let mut y = index;
    y ^= (y >> 1) & 0x5555_5555;
    y ^= (y >> 2) & 0x3333_3333;
    y ^= (y >> 4) & 0x0f0f_0f0f;
    y ^= (y >> 8) & 0x00ff_00ff;
    y ^= y >> 16;
    y
}

/// `2^-24 t` for `t < 2^24`, exactly.
#[inline(always)]
fn unit(t: u32) -> f32 {
    t as f32 * (1.0 / (1u32 << DIGITS) as f32)
}

impl PixelSampler for BlueNoise {
    /// The count it was built with, or `None` for
    /// [`unbounded`](BlueNoise::unbounded).
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        self.samples_per_pixel
    }

    /// Sample `index` of `pixel` in dimension pair `dimension`; any index
    /// and any pixel (see the type's Limits).
    #[inline]
    fn sample_pixel(&self, [x, y]: [u32; 2], index: u32, dimension: u32) -> Vec2 {
        let pair = hash_combine(hash_u32(self.frame), dimension);
        let tile = hash_combine(pair, hash_combine(x >> TILE_BITS, y >> TILE_BITS));
        let s = owen_scramble(index, hash_u32(pair ^ SALT_INDEX));
        // The pixel's Morton code shuffled as Burley shuffles an index:
        // aligned blocks of codes (aligned squares of pixels) map onto
        // aligned blocks, so each square's shifts stay one coset of its
        // columns, while which pixel gets which shift changes with every
        // frame, pair and tile (so two pairs of one pixel are unrelated).
        let code = owen_scramble(morton(x, y), hash_u32(tile ^ SALT_PIXEL));
        let [gx, gy] = Self::pixel_shift(code);
        // Natural-order 24-digit coordinates of the shifted Sobol point.
        let qx = (s.reverse_bits() >> (32 - DIGITS)) ^ gx;
        let qy = (pascal_reversed(s).reverse_bits() >> (32 - DIGITS)) ^ gy;
        // The scramble works in reversed order on 32 bits: the 24 digits
        // sit in bits 0..24, and the 8 below the f32 resolution are dropped.
        let scramble = |q: u32, salt: u32| {
            owen_scramble_reversed((q << (32 - DIGITS)).reverse_bits(), hash_u32(tile ^ salt))
                .reverse_bits()
                >> (32 - DIGITS)
        };
        Vec2::new(unit(scramble(qx, SALT_X)), unit(scramble(qy, SALT_Y)))
    }

    /// A progressive sequence: an index past the count continues it, so
    /// every prefix stays a net (the crate's edge rule for sequences).
    #[inline]
    fn locate(&self, index: u32, key: u32) -> (u32, u32) {
        (index, key)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn morton_interleaves_x_in_the_even_bits() {
        assert_eq!(morton(1, 0), 1);
        assert_eq!(morton(0, 1), 2);
        assert_eq!(morton(3, 3), 15);
        assert_eq!(morton(0b101, 0b010), 0b01_10_01);
        assert_eq!(morton(0xffff, 0), 0x5555_5555);
        assert_eq!(morton(0xffff, 0xffff), u32::MAX);
    }

    /// Rank over GF(2) of 48-bit vectors.
    fn rank(vectors: &[u64]) -> usize {
        let mut basis = [0u64; 64];
        let mut rank = 0;
        for &v in vectors {
            let mut v = v;
            while v != 0 {
                let top = 63 - v.leading_zeros() as usize;
                if basis[top] == 0 {
                    basis[top] = v;
                    rank += 1;
                    break;
                }
                v ^= basis[top];
            }
        }
        rank
    }

    #[test]
    fn the_columns_are_independent() {
        // The 16 Sobol columns of the first 2^16 samples and the 32 pixel
        // columns span all 48 digits: two pixels of a tile never share a
        // shift, nor a set of up to 2^16 samples.
        let mut vectors: std::vec::Vec<u64> = (0..16)
            .map(|k| {
                let s = 1u32 << k;
                let x = s.reverse_bits() >> 8;
                let y = pascal_reversed(s).reverse_bits() >> 8;
                u64::from(x) << 24 | u64::from(y)
            })
            .collect();
        vectors.extend(
            PIXEL_COLUMNS
                .iter()
                .map(|&[x, y]| u64::from(x) << 24 | u64::from(y)),
        );
        assert!(
            PIXEL_COLUMNS
                .iter()
                .all(|c| c[0] < 1 << 24 && c[1] < 1 << 24)
        );
        assert_eq!(rank(&vectors), 48);
    }

    #[test]
    fn the_table_is_the_xor_of_the_columns() {
        for (x, y) in [
            (0, 0),
            (1, 0),
            (0, 1),
            (255, 17),
            (65535, 65535),
            (4660, 300),
        ] {
            let code = morton(x, y);
            let mut expect = [0, 0];
            for (j, column) in PIXEL_COLUMNS.iter().enumerate() {
                if code >> j & 1 == 1 {
                    expect[0] ^= column[0];
                    expect[1] ^= column[1];
                }
            }
            assert_eq!(BlueNoise::pixel_shift(code), expect, "({x}, {y})");
        }
    }
}
