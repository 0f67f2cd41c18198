//! Screen-space blue noise that survives progressive rendering: one digital
//! point set over (pixel, sample) whose sample columns are Sobol's and whose
//! pixel columns were searched so that neighbouring pixels complement each
//! other at every prefix, Owen-scrambled per frame and dimension pair.

use glam::{Vec2, Vec3, Vec4};

use crate::primitives::{hash_combine, hash_u32, owen_scramble, owen_scramble_reversed};
// Sobol dimension 1 in reversed bit order (the Pascal matrix mod 2).
use crate::pixel::Draw;
use crate::samplers::sequence::sobol::pascal_reversed;
use crate::samplers::sequence::sobol_4d::dimensions_2_3_reversed;
use crate::{Error, PixelSampler};

/// Salts that split a dimension pair's seed into the index shuffle's and
/// the two coordinates' scramble seeds (fixed odd words with about half
/// their bits set).
const SALT_INDEX: u32 = 0x2c1b_3c6d;
const SALT_X: u32 = 0x297a_2d39;
const SALT_Y: u32 = 0x9e48_5565;
const SALT_PIXEL: u32 = 0x6a09_e667;
const SALT_TRANSLATE: u32 = 0x3c6e_f372;

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
/// hill-climb on the blurred error under exactly this sampler's
/// randomisation; the rest are its fixed pseudo-random start, 24 random
/// digits each (so the coarse levels flip the top digits too, which keeps
/// the dimension pairs of a pixel independent). `the_columns_are_independent`
/// tests that together with the first 16 Sobol columns they span all 48
/// digits.
const PIXEL_COLUMNS: [[u32; 2]; 32] = [
    [0xd459e5, 0xe7e552],
    [0x7878d4, 0xbe5f6b],
    [0x0a02b8, 0x6ffd15],
    [0x9ba7b0, 0x4a162b],
    [0x350c48, 0x66b51e],
    [0x65ae75, 0x6bcb34],
    [0x6ae98f, 0x14e66a],
    [0x632e2b, 0x74de50],
    [0x4ee042, 0x5ec581],
    [0x29a29d, 0xebb06f],
    [0x6ee0e0, 0xc56094],
    [0x37fd1c, 0xbe40ea],
    [0xc2b157, 0x3e5b13],
    [0xc648e2, 0xce84a7],
    [0xac6abf, 0x03678b],
    [0xed74fc, 0xa7bf3d],
    [0x64a494, 0x640215],
    [0x28535e, 0xf501a5],
    [0xb8d852, 0x8e6692],
    [0x6ac3db, 0x57d145],
    [0x5cfdcb, 0xbee394],
    [0xae2655, 0x1c7bd1],
    [0x73047d, 0x3ff52c],
    [0x23c455, 0x285334],
    [0x0306c1, 0x146bc3],
    [0x79faed, 0x1bef6f],
    [0x5d0270, 0xdc3709],
    [0x2b0aee, 0x741c90],
    [0xe6fef9, 0x690333],
    [0x40cfe8, 0x21dc2b],
    [0x5d493e, 0xdcc4b6],
    [0xacaef8, 0xbe91d9],
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
/// 2. `c`: the Morton code (bits of `x` and `y` interleaved) of the pixel
///    translated by a hashed offset (per frame, pair and tile, modulo the
///    tile), then shuffled the same way as the index (per frame, pair and
///    tile). Aligned squares of the translated grid keep aligned blocks of
///    codes, so each square's shifts are one coset of its columns, while
///    which pixel gets which shift, and where the squares' edges lie,
///    change with every frame and pair: two pairs of one pixel have
///    unrelated shifts. (A fixed arrangement per 16 x 16 block, the same
///    for every pair, lowers the blurred error on image-space integrands
///    but ties a pixel's draws together across the film; see
///    `docs/blue_noise.md`.)
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
///   at 0.30 to 0.53 times `Padded<Sobol>`'s on a per-pixel Gaussian and
///   0.64 to 0.87 times on an image footprint (n = 1 to 16, pairs 0 and 2,
///   1D draws and the lens half of the 4D draw).
/// - A domain's `next_4d` is one point of a 4D Owen-scrambled Sobol set per
///   pixel, each half shifted as a pair is: every power-of-two prefix is a
///   (3,m,4)-net, film and lens stratified together as in `Padded<Sobol>`.
/// - Dimension pairs and frames use unrelated translations, shuffles and
///   scrambles, so they are decorrelated: two pairs of one pixel look
///   independent across the film (chi-square of their first coordinates
///   near its degrees of freedom), at each index half the pixels fall in
///   each half of `[0, 1)`, and averaging frames converges.
/// - No tile: the 2^32 pixels of a `65536 x 65536` square get distinct
///   shifts, and no two of them the same set of 2^16 or fewer samples;
///   beyond that square, its position is hashed into the scramble seeds.
///   One scramble serves the whole frame, so a single frame's overall
///   error varies more from frame to frame than with per-pixel patterns.
///
/// # Cost
///
/// Per sample: the pair's seeds and the translation (seven hashes), the
/// index shuffle, the code shuffle and two coordinate scrambles (four Owen scrambles, one more
/// than a [`Sobol`](crate::Sobol) point), the Morton code and four
/// lookups in an 8 KiB table computed at compile time from the 256-byte
/// column list. Callgrind counts about 410 x86-64 instructions per
/// `sample_pixel` through `&dyn PixelSampler` at scattered pixels (release
/// build; the translation adds 4%): 1.6 times `Padded<Sobol>`'s 264 and
/// 0.6 times `ZSobol`'s 662.
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

/// `2^-24 t` for `t < 2^24`, exactly.
#[inline(always)]
fn unit(t: u32) -> f32 {
    t as f32 * (1.0 / (1u32 << DIGITS) as f32)
}

impl BlueNoise {
    /// The seed of dimension pair `dimension` in this frame, and the seed
    /// of its `65536 x 65536` tile at `pixel`.
    #[inline(always)]
    fn seeds(&self, [x, y]: [u32; 2], dimension: u32) -> (u32, u32) {
        let pair = hash_combine(hash_u32(self.frame), dimension);
        (
            pair,
            hash_combine(pair, hash_combine(x >> TILE_BITS, y >> TILE_BITS)),
        )
    }

    /// Sample `index` of `pixel` in dimension pair `dimension`, and the
    /// shuffled sequence index it is the point of.
    #[inline(always)]
    fn point_and_index(&self, pixel: [u32; 2], index: u32, dimension: u32) -> (Vec2, u32) {
        let (pair, tile) = self.seeds(pixel, dimension);
        let s = owen_scramble(index, hash_u32(pair ^ SALT_INDEX));
        let point = shifted_point(
            tile,
            pixel,
            s.reverse_bits(),
            pascal_reversed(s).reverse_bits(),
        );
        (point, s)
    }
}

/// A point of a digital net (its two coordinates `u` and `v` as 0.32 fixed
/// point, natural order) shifted by the pixel columns of `pixel`'s code and
/// Owen-scrambled, both seeded by `tile`.
#[inline(always)]
fn shifted_point(tile: u32, [x, y]: [u32; 2], u: u32, v: u32) -> Vec2 {
    // The pixel's Morton code shuffled as Burley shuffles an index:
    // aligned blocks of codes (aligned squares of pixels) map onto
    // aligned blocks, so each square's shifts stay one coset of its
    // columns, while which pixel gets which shift changes with every
    // frame, pair and tile (so two pairs of one pixel are unrelated).
    // Before that, the pixel grid is translated by a hashed offset (per
    // frame, pair and tile, modulo the tile), so the aligned squares of
    // two pairs do not line up: their shifts at one pixel share no
    // block structure.
    let t = hash_u32(tile ^ SALT_TRANSLATE);
    let code = owen_scramble(
        morton(x.wrapping_add(t), y.wrapping_add(t >> 16)),
        hash_u32(tile ^ SALT_PIXEL),
    );
    let [gx, gy] = BlueNoise::pixel_shift(code);
    // Natural-order 24-digit coordinates of the shifted point.
    let qx = (u >> (32 - DIGITS)) ^ gx;
    let qy = (v >> (32 - DIGITS)) ^ gy;
    // The scramble works in reversed order on 32 bits: the 24 digits
    // sit in bits 0..24, and the 8 below the f32 resolution are dropped.
    let scramble = |q: u32, salt: u32| {
        owen_scramble_reversed((q << (32 - DIGITS)).reverse_bits(), hash_u32(tile ^ salt))
            .reverse_bits()
            >> (32 - DIGITS)
    };
    Vec2::new(unit(scramble(qx, SALT_X)), unit(scramble(qy, SALT_Y)))
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
    fn sample_pixel(&self, pixel: [u32; 2], index: u32, dimension: u32) -> Vec2 {
        self.point_and_index(pixel, index, dimension).0
    }

    /// Dimensions 0 to 2 of [`draw_4d`](Self::draw_4d)'s point.
    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        self.draw_4d(draw).truncate()
    }

    /// One point of a 4D Owen-scrambled Sobol set per pixel, as
    /// `Padded<Sobol>` draws it (a (3,m,4)-net at every power-of-two
    /// prefix, film and lens stratified together), with each pair shifted
    /// as [`sample_pixel`](Self::sample_pixel) shifts it: the first two
    /// coordinates are `draw_2d(draw)`, the last two are Sobol dimensions
    /// 2 and 3 of the same shuffled index under the pixel shift and
    /// scrambles of `draw.second()`'s stream.
    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        let (film, s) = self.point_and_index(draw.pixel, draw.index, draw.stream);
        let (_, lens_tile) = self.seeds(draw.pixel, draw.second().stream);
        let (c2, c3) = dimensions_2_3_reversed(s);
        let lens = shifted_point(lens_tile, draw.pixel, c2.reverse_bits(), c3.reverse_bits());
        Vec4::new(film.x, film.y, lens.x, lens.y)
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
    fn the_coarse_columns_flip_the_top_digits() {
        // With no coarse column touching the top digit of x (or y), that
        // digit of every shift would follow the pixel's place in its
        // 16 x 16 block alone, much the same for every dimension pair.
        for coordinate in 0..2 {
            let flips = PIXEL_COLUMNS[8..]
                .iter()
                .filter(|c| c[coordinate] >> (DIGITS - 1) & 1 == 1)
                .count();
            assert!(
                (6..=18).contains(&flips),
                "coordinate {coordinate}: {flips} of 24"
            );
        }
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
