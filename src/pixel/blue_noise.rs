//! Screen-space blue noise that survives progressive rendering: one digital
//! point set over (pixel, sample) whose sample columns are Sobol's and whose
//! pixel columns were searched so that neighbouring pixels complement each
//! other at every prefix, Owen-scrambled per frame and dimension pair.

use glam::{Vec2, Vec3, Vec4};

use super::{Draw, PixelSampler, PixelSamplerHooks, Root};
use crate::error::Error;
use crate::primitives::morton::{morton, morton_add};
use crate::primitives::{hash_u32, mix64, owen_scramble_reversed, prefix_shuffle, salt};
use crate::samplers::sequence::digital::{
    OwenSeeds, bits_to_point, scrambled_bits, sobol_4d_point, sobol_reversed,
};
use crate::traits::second_stream;

/// Bits of `x` and `y` the pixel columns cover: a `65536 x 65536` square.
const TILE_BITS: u32 = 16;

/// Bits of the (translated) Morton code below the squares that share one
/// sample order: `16 x 16` pixels.
const ORDER_SQUARE_BITS: u32 = 8;

/// Fixed-point digits of a pixel column: the f32 resolution of `[0, 1)`.
const DIGITS: u32 = 24;

/// The pixel columns of the generator matrix: entry `2 j` is the
/// contribution (x digits, y digits, 24-bit natural order: bit 23 is the
/// digit of weight 1/2) of bit `j` of the pixel's `x`, entry `2 j + 1`
/// that of bit `j` of `y`. The output of `cargo run --release -p
/// wellspread-lab --example blue_noise_search` (deterministic), a
/// hill-climb on the blurred error that scores each candidate by running
/// `BlueNoise::with_columns` with it, so under exactly this sampler's
/// randomisation. It climbed entries 0..8 (the 2 x 2 to 16 x 16 levels of
/// the pixel hierarchy) for its default three sweeps, starting from the
/// table of a first search (`docs/blue_noise.md`, The search, measures
/// the two tables against each other); the rest are that first search's
/// pseudo-random start, 24 random digits each (so the coarse
/// levels flip the top digits too, which keeps the dimension pairs of a
/// pixel independent). `ExplicitColumns::new` accepts them
/// (`the_columns_are_independent`): together with the first 16 Sobol
/// columns they span all 48 digits.
const PIXEL_COLUMNS: [[u32; 2]; 32] = [
    [0xdc59e5, 0xe7e552],
    [0x6838d4, 0xbe5f6b],
    [0x1ac2b8, 0x6ffd15],
    [0x9127b0, 0x4a162b],
    [0x350c48, 0x70f51e],
    [0x6dee75, 0x6acb34],
    [0x72698f, 0x01a66a],
    [0x636e2b, 0x74de50],
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

/// The shift `G code` of a pixel whose Morton code is `code`: the xor of
/// the `columns` of the code's set bits, in the columns' 24-digit natural
/// order. The one place a shift is made from columns: the table below is
/// built with it, and [`ExplicitColumns`] calls it per draw.
const fn xor_columns(columns: &[[u32; 2]; 32], code: u32) -> [u32; 2] {
    let mut shift = [0, 0];
    let mut j = 0;
    while j < 32 {
        if code >> j & 1 == 1 {
            shift[0] ^= columns[j][0];
            shift[1] ^= columns[j][1];
        }
        j += 1;
    }
    shift
}

/// A shift in natural order (bit 23 the digit of weight 1/2) in the
/// reversed-digit form the scrambles work in (bit `k` the digit of weight
/// `2^-(k+1)`).
const fn reversed([x, y]: [u32; 2]) -> [u32; 2] {
    [
        (x << (32 - DIGITS)).reverse_bits(),
        (y << (32 - DIGITS)).reverse_bits(),
    ]
}

/// [`PIXEL_COLUMNS`] in reversed-digit form, combined per byte of the
/// bit-reversed Morton code: entry `[b][v]` is the shift of the code whose
/// bit-reversal is `v << 8 b`.
const PIXEL_TABLE: [[[u32; 2]; 256]; 4] = {
    let mut table = [[[0u32; 2]; 256]; 4];
    let mut b = 0;
    while b < 4 {
        let mut v = 0;
        while v < 256 {
            let code = ((v as u32) << (8 * b)).reverse_bits();
            table[b][v] = reversed(xor_columns(&PIXEL_COLUMNS, code));
            v += 1;
        }
        b += 1;
    }
    table
};

/// Rank over GF(2) of 48-digit vectors.
fn rank(vectors: impl Iterator<Item = u64>) -> u32 {
    let mut basis = [0u64; 64];
    let mut rank = 0;
    for mut v in vectors {
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

/// How many of the 48 digits of a `(x, y)` pair of 24-digit shifts the 16
/// Sobol' columns of the first `2^16` samples and the 32 pixel `columns`
/// span together: 48 when no two pixels of a `65536 x 65536` tile share a
/// shift, nor a set of `2^16` or fewer samples.
fn span(columns: &[[u32; 2]; 32]) -> u32 {
    let sobol = (0..16).map(|k| {
        let (x, y) = sobol_reversed(1 << k);
        [
            x.reverse_bits() >> (32 - DIGITS),
            y.reverse_bits() >> (32 - DIGITS),
        ]
    });
    rank(
        sobol
            .chain(columns.iter().copied())
            .map(|[x, y]| u64::from(x) << DIGITS | u64::from(y)),
    )
}

pub(crate) mod sealed {
    /// What [`PixelColumns`](super::PixelColumns) needs from a column
    /// list, kept inside the crate so that every implementation is one
    /// [`BlueNoise`](super::BlueNoise) checks.
    pub trait Shift {
        /// The shift of a pixel whose (translated, scrambled) Morton code,
        /// bit-reversed, is `code_reversed`, in reversed-digit form, x
        /// then y.
        fn shift_reversed(&self, code_reversed: u32) -> [u32; 2];
    }
}

/// The pixel columns a [`BlueNoise`] shifts its pixels by: the searched
/// table ([`SearchedColumns`], the default) or a checked list of your own
/// ([`ExplicitColumns`]). Sealed: these two are all the implementations,
/// so every `BlueNoise` keeps the properties its docs state.
pub trait PixelColumns:
    sealed::Shift + Copy + core::fmt::Debug + PartialEq + Eq + core::hash::Hash + Send + Sync
{
    /// The 32 columns, as [`ExplicitColumns::new`] takes them: entry `2 j`
    /// is the shift (x digits, y digits, 24 digits each, bit 23 the digit
    /// of weight 1/2) that bit `j` of a pixel's `x` contributes, entry
    /// `2 j + 1` that of bit `j` of `y`.
    fn columns(&self) -> [[u32; 2]; 32];
}

/// The pixel columns [`BlueNoise`] ships and uses by default: a zero-sized
/// name for a table built at compile time.
///
/// # Properties
///
/// Its draws equal those of `ExplicitColumns::new(SearchedColumns.columns())`
/// bit for bit, and its columns pass that constructor's check.
///
/// # Cost
///
/// Zero bytes in the sampler; a draw looks its shift up in an 8 KiB table
/// (four lookups).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SearchedColumns;

impl sealed::Shift for SearchedColumns {
    #[inline(always)]
    fn shift_reversed(&self, code_reversed: u32) -> [u32; 2] {
        let mut shift = [0, 0];
        for (b, table) in PIXEL_TABLE.iter().enumerate() {
            let entry = table[(code_reversed >> (8 * b)) as usize & 0xff];
            shift[0] ^= entry[0];
            shift[1] ^= entry[1];
        }
        shift
    }
}

impl PixelColumns for SearchedColumns {
    fn columns(&self) -> [[u32; 2]; 32] {
        PIXEL_COLUMNS
    }
}

/// Pixel columns of your choice for a [`BlueNoise`]
/// ([`with_columns`](BlueNoise::with_columns)): for searching or
/// comparing column tables by running the sampler itself.
///
/// # Properties
///
/// A `BlueNoise` with these columns draws exactly as the default one does
/// with [`SearchedColumns`]'s columns replaced by them: the same
/// translation, code scramble, index shuffle and Owen scrambles. Whatever
/// the columns, each pixel keeps [`BlueNoise`]'s per-pixel properties
/// (every power-of-two prefix a net, each point uniform, the 4D draw's
/// nets), and the check of [`new`](Self::new) keeps the pixels of a
/// `65536 x 65536` tile on distinct shifts. What holds across pixels is
/// the columns' own: the blue-noise ratios, the independence of a pixel's
/// pairs across the film, and each index splitting the film in halves
/// (columns that leave a top digit alone break the last two) are measured
/// and tested for [`SearchedColumns`] only.
///
/// # Cost
///
/// 256 bytes in the sampler. A draw xors up to 32 columns per shift
/// instead of four table lookups: slower than [`SearchedColumns`], fine
/// for a search.
///
/// # Examples
///
/// ```
/// use wellspread::blue_noise::{ExplicitColumns, PixelColumns, SearchedColumns};
/// use wellspread::{BlueNoise, PixelSampler};
/// let columns = ExplicitColumns::new(SearchedColumns.columns())?;
/// let shipped = BlueNoise::new(16, [64, 64], 3)?;
/// let explicit = shipped.with_columns(columns);
/// assert_eq!(
///     explicit.sample_pixel([10, 20], 5, 2),
///     shipped.sample_pixel([10, 20], 5, 2)
/// );
/// // Columns that leave digits out are refused.
/// assert!(ExplicitColumns::new([[0, 0]; 32]).is_err());
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ExplicitColumns {
    columns: [[u32; 2]; 32],
}

impl ExplicitColumns {
    /// Checks `columns` (laid out as [`PixelColumns::columns`] returns
    /// them) and keeps them.
    ///
    /// # Errors
    ///
    /// [`Error::PixelColumnTooWide`] for a coordinate at or above `2^24`
    /// (a column has 24 digits), and [`Error::DependentPixelColumns`] when
    /// the columns and the 16 Sobol' columns of the first `2^16` samples
    /// do not span all 48 digits (two pixels of a tile would share a
    /// shift).
    ///
    /// # Cost
    ///
    /// A rank over GF(2) of 48 vectors: about a microsecond.
    pub fn new(columns: [[u32; 2]; 32]) -> Result<Self, Error> {
        for (index, column) in (0u32..).zip(columns) {
            if column.iter().any(|&digits| digits >> DIGITS != 0) {
                return Err(Error::PixelColumnTooWide { index, column });
            }
        }
        match span(&columns) {
            48 => Ok(Self { columns }),
            rank => Err(Error::DependentPixelColumns { rank }),
        }
    }
}

impl sealed::Shift for ExplicitColumns {
    #[inline]
    fn shift_reversed(&self, code_reversed: u32) -> [u32; 2] {
        reversed(xor_columns(&self.columns, code_reversed.reverse_bits()))
    }
}

impl PixelColumns for ExplicitColumns {
    fn columns(&self) -> [[u32; 2]; 32] {
        self.columns
    }
}

/// Blue-noise error across the screen at every prefix of every pixel: one
/// digital point set over all pixels and samples, whose sample columns are
/// those of the Sobol (0,2)-sequence and whose pixel columns make
/// neighbouring pixels complement each other, Owen-scrambled per frame and
/// dimension pair.
///
/// How it is built (the prefix shuffle, the translated and scrambled
/// Morton code, the pixel columns, the Owen scramble) and why every
/// prefix keeps its nets: `docs/blue_noise.md`, section Construction.
///
/// The pixel columns are the type parameter `C`: [`SearchedColumns`], the
/// shipped table, unless [`with_columns`](Self::with_columns) put others
/// in ([`ExplicitColumns`], to search or compare tables with the sampler
/// itself). The properties below are those of [`SearchedColumns`]; with
/// other columns the per-pixel ones still hold, the ones across pixels
/// are the columns' own ([`ExplicitColumns`] says which).
///
/// # Properties
///
/// - Every power-of-two prefix `0..2^m`, and every dyadic block
///   `[2^m, 2^(m+1))`, of every pixel's indices in every dimension pair is a
///   (0,m,2)-net, checked exactly on the f32 values (`m <= 24`); in
///   particular every such range is Latin. No other range is: an aligned
///   block `[j 2^k, (j + 1) 2^k)` with `j >= 2` is a shuffled subset of its
///   dyadic block (many are not nets), and a prefix between two powers of
///   two `2^m < n < 2^(m+1)` is the net `0..2^m` plus a uniformly random
///   subset of the next block. Progressive passes of `2^k` samples that
///   are nets each: [`DomainSampler`](crate::implement::DomainSampler)'s section on
///   which ranges are nets.
/// - Each point is uniform over `[0, 1)^2`; estimates are unbiased, with
///   the per-pixel variance of `Padded<Sobol>`.
/// - Blue-noise error across pixels at every prefix on integrands that are
///   smooth inside a pixel: `docs/blue_noise.md` measures the blurred RMSE
///   at 0.27 to 0.52 times `Padded<Sobol>`'s on a per-pixel Gaussian and
///   0.52 to 0.78 times on an image footprint (n = 1 to 16, pairs 0 and 2,
///   1D draws and the lens half of the 4D draw).
/// - A domain's `next_4d` is one point of a 4D Owen-scrambled Sobol set per
///   pixel, each half shifted as a pair is: every power-of-two prefix is a
///   (3,m,4)-net, film and lens stratified together as in `Padded<Sobol>`.
/// - Draws and frames use unrelated translations, shuffles and
///   scrambles, so they are decorrelated: two draws of one pixel look
///   independent across the film (chi-square of their first coordinates
///   near its degrees of freedom) and over the pixel's samples (tested for
///   every pixel sampler), at each index half the pixels fall in each half
///   of `[0, 1)`, and averaging frames converges.
/// - **One frame of a small film pairs draws less freely.** The pixels of
///   a `16 x 16` square share each draw's sample order, so a frame holds
///   one order per square, and two draws' pairing averages over few of
///   them: at 16 spp the worst of 28 key pairs correlates 1.32x to 1.66x
///   as much as independent sets on a `32 x 32` film and 1.30x to 1.39x on
///   `64 x 64`, the median pair 1.08x to 1.19x (four frames each,
///   `tests/pixel/independence.rs`, which bounds them at 1.75x and 1.45x,
///   median 1.25x and 1.18x). Over 16 frames of `32 x 32`, or a larger
///   film, the figures fall to the other sequences' (at most 1.15x).
/// - No tile: the 2^32 pixels of a `65536 x 65536` square get distinct
///   shifts, and no two of them the same set of 2^16 or fewer samples;
///   beyond that square, its position is hashed into the scramble seeds.
///   One scramble serves the whole frame, so a single frame's overall
///   error varies more from frame to frame than with per-pixel patterns.
///
/// # Cost
///
/// `start`: the pixel's Morton code, once. Per draw: a
/// [`Sobol`](crate::Sobol) draw plus one more [`mix64`] (the translation
/// and the code's scramble seed), two adds of dilated integers (the
/// translated code), one bit reversal and one Owen scramble of the code,
/// and four lookups in an 8 KiB table computed at compile time from the
/// 256-byte column list ([`ExplicitColumns`] xor up to 32 columns
/// instead). `docs/performance.md` has the ratio to `Padded<Sobol>`'s
/// draw. The default's columns take no space in the sampler.
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
/// for pair in 0..3 {
///     // Every power-of-two prefix of a 12-sample pixel is a net.
///     for n in [1, 2, 4, 8] {
///         let points: Vec<_> = (0..n)
///             .map(|i| sampler.sample_pixel([100, 50], i, pair))
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
pub struct BlueNoise<C = SearchedColumns> {
    /// Samples per pixel; 0 for a progressive (unbounded) sampler (a
    /// plain u32 keeps the domain small).
    samples_per_pixel: u32,
    resolution: [u32; 2],
    frame: u32,
    /// The frame's part of every root key, hashed once here.
    frame_key: u64,
    /// The pixel columns: zero-sized for the default.
    columns: C,
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
    /// [`Error::ZeroResolution`] for a zero width or height.
    pub fn new(samples_per_pixel: u32, resolution: [u32; 2], frame: u32) -> Result<Self, Error> {
        super::check_film(samples_per_pixel, resolution)?;
        Self::unbounded(resolution, frame).map(|s| Self {
            samples_per_pixel,
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
    /// [`Error::ZeroResolution`] for a zero width or height.
    pub fn unbounded(resolution: [u32; 2], frame: u32) -> Result<Self, Error> {
        super::check_resolution(resolution)?;
        Ok(Self {
            samples_per_pixel: 0,
            resolution,
            frame,
            frame_key: mix64(frame as u64 ^ salt::BLUE_NOISE_FRAME),
            columns: SearchedColumns,
        })
    }
}

impl<C: PixelColumns> BlueNoise<C> {
    /// The same sampler (count, resolution, frame) with its pixel columns
    /// replaced by `columns`, typically [`ExplicitColumns`]: every draw is
    /// made as before, with `columns` in place of the old ones.
    ///
    /// ```
    /// use wellspread::blue_noise::{ExplicitColumns, PixelColumns, SearchedColumns};
    /// use wellspread::{BlueNoise, PixelSampler};
    /// let mut columns = SearchedColumns.columns();
    /// columns[0][0] ^= 1 << 23;
    /// let sampler = BlueNoise::unbounded([64, 64], 0)?.with_columns(ExplicitColumns::new(columns)?);
    /// let mut domain = sampler.start([5, 6], 7);
    /// let point = domain.next_4d();
    /// assert!(point.min_element() >= 0.0 && point.max_element() < 1.0);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[must_use]
    pub fn with_columns<D: PixelColumns>(self, columns: D) -> BlueNoise<D> {
        BlueNoise {
            samples_per_pixel: self.samples_per_pixel,
            resolution: self.resolution,
            frame: self.frame,
            frame_key: self.frame_key,
            columns,
        }
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

    /// The sequence index of a draw's sample and the pixel's shift.
    ///
    /// The pixel's Morton code is translated and scrambled by a second mix
    /// of the stream, then looked up for the shift. The index is read
    /// through a [`prefix_shuffle`] keyed by the draw and by the pixel's
    /// `16 x 16` square of the translated grid: inside a square (the levels
    /// the columns were searched for) every pixel visits its samples in the
    /// same order, so squares complement each other at every prefix, not
    /// only at powers of two; from square to square two draws pair their
    /// samples differently. Every power-of-two prefix, and every dyadic
    /// block `[2^m, 2^(m+1))`, stays the same aligned block of the
    /// sequence; other aligned blocks of indices do not.
    #[inline(always)]
    fn index_and_shift(&self, draw: Draw, seeds: OwenSeeds) -> (u32, [u32; 2]) {
        let (code, seed) = Self::translated(draw.pixel_state, draw.stream);
        let order = hash_u32(seeds.index ^ code >> ORDER_SQUARE_BITS);
        (prefix_shuffle(draw.index, order), self.shift_of(code, seed))
    }

    /// The Morton code `code` of a pixel translated for a draw with
    /// `stream`, and the seed of its scramble: a second mix of the stream,
    /// whose low half is a random offset already in Morton form (its even
    /// bits move x, its odd bits y).
    #[inline(always)]
    fn translated(code: u32, stream: u64) -> (u32, u32) {
        let extra = mix64(stream ^ salt::BLUE_NOISE_PIXEL);
        (morton_add(code, extra as u32), (extra >> 32) as u32)
    }

    /// The shift of a translated code: the code's nested scramble
    /// (`owen_scramble`, left bit-reversed for the table), looked up.
    #[inline(always)]
    fn shift_of(&self, code: u32, seed: u32) -> [u32; 2] {
        self.columns
            .shift_reversed(owen_scramble_reversed(code.reverse_bits(), seed))
    }
}

impl<C: PixelColumns> PixelSampler for BlueNoise<C> {
    /// The count it was built with, or `None` for
    /// [`unbounded`](BlueNoise::unbounded).
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        match self.samples_per_pixel {
            0 => None,
            n => Some(n),
        }
    }
}

impl<C: PixelColumns> PixelSamplerHooks for BlueNoise<C> {
    /// The key from the frame and the pixel's `65536 x 65536` tile; the
    /// pixel state its Morton code inside the tile.
    #[inline(always)]
    fn root(&self, [x, y]: [u32; 2]) -> Root {
        let tile = x >> TILE_BITS | (y >> TILE_BITS) << TILE_BITS;
        Root {
            key: self.frame_key ^ u64::from(tile) << 32,
            pixel_state: morton(x, y),
        }
    }

    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        let seeds = OwenSeeds::from_stream(draw.stream);
        let (s, [gx, gy]) = self.index_and_shift(draw, seeds);
        let (x, y) = sobol_reversed(s);
        bits_to_point(scrambled_bits(x ^ gx, y ^ gy, seeds))
    }

    /// Dimensions 0 to 2 of [`draw_4d`](Self::draw_4d)'s point.
    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        self.draw_4d(draw).truncate()
    }

    /// One point of a 4D Owen-scrambled Sobol set per pixel, as
    /// `Padded<Sobol>` draws it (a (3,m,4)-net at every power-of-two
    /// prefix, film and lens stratified together), each pair shifted as
    /// [`draw_2d`](Self::draw_2d) shifts it: the first two coordinates are
    /// `draw_2d(draw)`, the last two Sobol' dimensions 2 and 3 under the
    /// shift of an unrelated stream.
    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        let (s, [gx, gy]) = self.index_and_shift(draw, OwenSeeds::from_stream(draw.stream));
        let (lens, seed) = Self::translated(draw.pixel_state, second_stream(draw.stream));
        let [hx, hy] = self.shift_of(lens, seed);
        sobol_4d_point(s, draw.stream, [gx, gy, hx, hy])
    }
}

#[cfg(test)]
mod tests {
    use super::sealed::Shift;
    use super::*;
    use std::string::ToString;

    #[test]
    fn the_columns_are_independent() {
        // The 16 Sobol columns of the first 2^16 samples and the 32 pixel
        // columns span all 48 digits: two pixels of a tile never share a
        // shift, nor a set of up to 2^16 samples.
        assert_eq!(span(&PIXEL_COLUMNS), 48);
        assert_eq!(
            ExplicitColumns::new(PIXEL_COLUMNS).map(|c| c.columns()),
            Ok(PIXEL_COLUMNS)
        );
    }

    #[test]
    fn dependent_or_wide_columns_are_refused() {
        let mut twice = PIXEL_COLUMNS;
        twice[31] = twice[30];
        let error = ExplicitColumns::new(twice).unwrap_err();
        assert_eq!(error, Error::DependentPixelColumns { rank: 47 });
        assert!(error.to_string().contains("47 of the 48"), "{error}");
        // A column equal to a Sobol' column (sample 1: x = 1/2, y = 1/2).
        let mut sobol = PIXEL_COLUMNS;
        sobol[31] = [1 << 23, 1 << 23];
        assert!(matches!(
            ExplicitColumns::new(sobol),
            Err(Error::DependentPixelColumns { rank: 47 })
        ));
        assert_eq!(
            ExplicitColumns::new([[0, 0]; 32]),
            Err(Error::DependentPixelColumns { rank: 16 })
        );
        let mut wide = PIXEL_COLUMNS;
        wide[5][1] |= 1 << 24;
        let error = ExplicitColumns::new(wide).unwrap_err();
        assert_eq!(
            error,
            Error::PixelColumnTooWide {
                index: 5,
                column: wide[5]
            }
        );
        assert!(error.to_string().contains("0xffffff"), "{error}");
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
        let explicit = ExplicitColumns::new(PIXEL_COLUMNS).unwrap();
        let mut code = 0x1234_5678u32;
        for _ in 0..4096 {
            code = hash_u32(code);
            for c in [code, code & 0xff, code & 0xffff_0000, 1 << (code % 32)] {
                assert_eq!(
                    SearchedColumns.shift_reversed(c),
                    explicit.shift_reversed(c),
                    "{c:#x}"
                );
            }
        }
        // Linear in the code, and bit `j` of the code gives column `j`.
        let natural = |[x, y]: [u32; 2]| [x.reverse_bits() >> 8, y.reverse_bits() >> 8];
        for (j, column) in PIXEL_COLUMNS.iter().enumerate() {
            let code = 1u32 << j;
            assert_eq!(
                natural(SearchedColumns.shift_reversed(code.reverse_bits())),
                *column
            );
        }
        let (a, b) = (
            morton(4660, 300).reverse_bits(),
            morton(65535, 17).reverse_bits(),
        );
        let [ax, ay] = SearchedColumns.shift_reversed(a);
        let [bx, by] = SearchedColumns.shift_reversed(b);
        assert_eq!(SearchedColumns.shift_reversed(a ^ b), [ax ^ bx, ay ^ by]);
    }
}
