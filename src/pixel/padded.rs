//! Any [`Sampler2D`] as a pixel sampler, and the per-family draws that
//! [`Domain`](crate::Domain) makes through it.

use glam::{Vec2, Vec3, Vec4};

use super::{Draw, PixelSampler, Root};
use crate::primitives::{
    hash_combine, hash_u32, owen_scramble, owen_scramble_reversed, pattern_seed, permute, rand_u32,
    stratum_to_unit_f32, u32_to_unit_f32,
};
use crate::samplers::sequence::digital::OwenSeeds;
use crate::samplers::sequence::pmj02::{stirling_x, stirling_y};
use crate::samplers::sequence::sobol::pascal_reversed;
use crate::samplers::sequence::sobol_4d::dimensions_2_3_reversed;
use crate::{
    AnySampler, CorrelatedMultiJittered, Halton, Hammersley, Jittered, MultiJittered, NRooks,
    Pmj02, Random, Regular, Sampler2D, Sobol,
};

/// Any [`Sampler2D`] as a [`PixelSampler`]: pixel `[x, y]`, dimension pair
/// `d` uses pattern `pattern_seed(x, y, frame, d)` ([`pattern_seed`]), so
/// every pixel and every dimension pair gets an independent randomisation
/// ("padding").
///
/// # Properties
///
/// - Each pixel's `len()` samples in each dimension pair are one set of the
///   wrapped sampler, with all its guarantees (stratification, nets).
/// - Different pixels, dimension pairs and frames get unrelated patterns, so
///   the error is white noise across pixels. Pair this with a sampler that
///   shuffles its index ([`Sobol`], [`Pmj02`], the grid family):
///   [`Halton`] and [`Hammersley`] visit points in the same order for
///   every pattern, which correlates dimension pairs (see their docs).
/// - Through a [`Domain`](crate::Domain), each draw is one set of the
///   sampler too, for a pattern picked by the draw's `stream` instead of
///   `pattern_seed`: the draws have the same guarantees as `sample_pixel`,
///   with other values. What each width gives is [`DomainSampler`]'s table.
///
/// `Padded<S>` is a pixel sampler for every `S:` [`DomainSampler`]; the
/// crate's samplers all are, and a [`Sampler2D`] of your own becomes one
/// with `impl DomainSampler for MySampler {}`.
///
/// # Cost
///
/// `sample_pixel`: one [`pattern_seed`] (seven [`hash_u32`]) plus the
/// wrapped sampler's `sample`. `start`: one 64-bit mix of the pixel; each
/// draw then one hash plus the family kernel of [`DomainSampler`].
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
/// use wellspread::{Padded, PixelSampler, Sampler2D, Sobol, pattern_seed};
/// let pixels = Padded::new(Sobol::new(16)?, 7);
/// assert_eq!(pixels.samples_per_pixel(), Some(16));
/// let lens = pixels.sample_pixel([3, 4], 5, 1);
/// assert_eq!(lens, Sobol::new(16)?.sample(5, pattern_seed(3, 4, 7, 1)));
/// // Progressive: no count, any index.
/// assert_eq!(Padded::new(Sobol::unbounded(), 7).samples_per_pixel(), None);
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Padded<S> {
    sampler: S,
    frame: u32,
    /// The frame's part of every [`root`](PixelSampler::root) key, hashed
    /// once here.
    frame_key: u32,
}

impl<S: Sampler2D> Padded<S> {
    /// `sampler` for every pixel and dimension pair; `frame` (a frame
    /// number, say) picks one of 2^32 unrelated sets of patterns.
    #[inline]
    pub const fn new(sampler: S, frame: u32) -> Self {
        Self {
            sampler,
            frame,
            frame_key: hash_u32(frame ^ 0x2545_f491),
        }
    }

    /// The wrapped sampler.
    #[inline]
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The frame, the `frame` argument of [`pattern_seed`].
    #[inline]
    pub const fn frame(&self) -> u32 {
        self.frame
    }
}

impl<S: DomainSampler + Send + Sync> PixelSampler for Padded<S> {
    /// `None` when the wrapped sampler is unbounded (`len() == u32::MAX`).
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        match self.sampler.len() {
            u32::MAX => None,
            n => Some(n),
        }
    }

    #[inline]
    fn sample_pixel(&self, [x, y]: [u32; 2], index: u32, dimension: u32) -> Vec2 {
        let pattern = pattern_seed(x, y, self.frame, dimension);
        let (index, pattern) = self.locate(index, pattern);
        self.sampler.sample(index, pattern)
    }

    /// The key: a 64-bit mix of `(x, y)` and the frame, so distinct pixels
    /// of one frame never share a key before the final truncation to 32
    /// bits.
    #[inline(always)]
    fn root(&self, [x, y]: [u32; 2]) -> Root {
        let packed = (u64::from(y) << 32 | u64::from(x)) ^ u64::from(self.frame_key) << 32;
        Root {
            key: mix64(packed),
            pixel: 0,
        }
    }

    #[inline]
    fn locate(&self, index: u32, key: u32) -> (u32, u32) {
        let n = self.sampler.len();
        if index < n || self.sampler.is_progressive() {
            (index, key)
        } else {
            (index % n, hash_combine(key, index / n))
        }
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

/// The 64-bit finaliser of SplitMix64 (Steele, Lea & Flood 2014, "Fast
/// splittable pseudorandom number generators"), a bijection on u64; the
/// top 32 bits.
#[inline(always)]
const fn mix64(mut z: u64) -> u32 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    ((z ^ (z >> 31)) >> 32) as u32
}

/// A [`Sampler2D`] that [`Padded`] can draw [`Domain`](crate::Domain)
/// dimensions from: one set per draw, picked by the draw's `stream` (a
/// well-mixed u32), in 1 to 4 dimensions.
///
/// Every method has a default, so a new sampler needs only
/// `impl DomainSampler for MySampler {}` (2D draws through `sample`, 1D
/// from the first coordinate, 3D/4D padded). The crate's samplers
/// override them:
///
/// | family | `domain_1d` | `domain_2d` | `domain_3d` / `domain_4d` |
/// | --- | --- | --- | --- |
/// | grid ([`Regular`], [`Jittered`], [`NRooks`], [`MultiJittered`], [`CorrelatedMultiJittered`]) and [`Hammersley`] | the `n` samples in `n` distinct strata of `[0, 1)` (a keyed permutation of the index, jittered inside the stratum; centred for `Regular`) | `sample(index, stream)`: the sampler's own set | padded: a pair and a 1D draw, or two pairs, from unrelated streams |
/// | [`Sobol`], [`Pmj02`] | Owen-scrambled Sobol' dimension 0 of the shuffled index: a (0,m,1)-net on every power-of-two prefix | the sampler's own (0,2)-sequence, seeds taken from `stream` without further hashing | one Owen-scrambled 4D Sobol' set: (3,m,4)-nets on every power-of-two prefix (`m >= 3`), dimensions (0, 1) a (0,2)-sequence; 3D is its first three coordinates |
/// | [`Halton`] | as Sobol's 1D | `sample(index, stream)` | padded |
/// | [`Random`] | one independent uniform value (no stratification: the baseline) | independent uniform points (one hash per coordinate; not `sample`'s values) | padded |
///
/// The draws of [`Pmj02`] in 3D and 4D are the Sobol' set's (pmj02 has no
/// 4D construction); its 2D draws stay pmj02.
pub trait DomainSampler: Sampler2D {
    /// Whether indices at or beyond [`len`](Sampler2D::len) continue the
    /// same sequence (the progressive sequences) rather than repeat a
    /// fixed set. Default `false`.
    #[inline]
    fn is_progressive(&self) -> bool {
        false
    }

    /// Sample `index` of the 1D set picked by `stream`.
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        self.domain_2d(index, stream).x
    }

    /// Sample `index` of the 2D set picked by `stream`.
    #[inline]
    fn domain_2d(&self, index: u32, stream: u32) -> Vec2 {
        self.sample(index, stream)
    }

    /// Sample `index` of the 3D set picked by `stream`.
    #[inline]
    fn domain_3d(&self, index: u32, stream: u32) -> Vec3 {
        let a = self.domain_2d(index, stream);
        a.extend(self.domain_1d(index, second(stream)))
    }

    /// Sample `index` of the 4D set picked by `stream`.
    #[inline]
    fn domain_4d(&self, index: u32, stream: u32) -> Vec4 {
        let a = self.domain_2d(index, stream);
        let b = self.domain_2d(index, second(stream));
        Vec4::new(a.x, a.y, b.x, b.y)
    }
}

/// The second pattern of a padded 3D or 4D draw.
#[inline(always)]
const fn second(stream: u32) -> u32 {
    Draw {
        pixel: [0, 0],
        pixel_state: 0,
        index: 0,
        stream,
    }
    .second()
    .stream
}

/// Sample `index` of `n` in 1D: stratum `permute(index, n, stream)`, at a
/// hashed position inside it (`jitter`) or at its centre.
#[inline]
fn stratified_1d(index: u32, n: u32, stream: u32, jitter: bool) -> f32 {
    let n = n.clamp(1, crate::primitives::MAX_STRATA);
    let index = if index < n { index } else { index % n };
    let stratum = permute(index, n, stream);
    let bits = if jitter {
        rand_u32(index, stream ^ 0x68e3_1da4)
    } else {
        1 << 31
    };
    stratum_to_unit_f32(stratum, n, bits)
}

/// The three seeds of a shuffled, scrambled 2D draw from one well-mixed
/// `stream`, without hashing again: the index shuffle takes `stream`, each
/// coordinate a rotation of it (xored with a constant, so that stream 0
/// gives three different seeds). The low bits of a seed pick the
/// scramble's top digits, and each seed's come from a different part of
/// `stream`.
#[inline(always)]
pub(super) const fn seeds_2d(stream: u32) -> OwenSeeds {
    OwenSeeds {
        index: stream,
        x: stream.rotate_right(11) ^ 0x2c1b_3c6d,
        y: stream.rotate_right(22) ^ 0x297a_2d39,
    }
}

/// `(reverse_bits(a), reverse_bits(b))` in one 64-bit reversal: x86 has
/// no bit-reverse instruction, and a 64-bit reversal costs what a 32-bit
/// one does.
#[inline(always)]
const fn reverse_pair(a: u32, b: u32) -> (u32, u32) {
    let r = ((b as u64) << 32 | a as u64).reverse_bits();
    ((r >> 32) as u32, r as u32)
}

/// The point with reversed-digit coordinates `(x, y)`, Owen-scrambled by
/// `seeds`, truncated to 24 bits.
#[inline(always)]
const fn scrambled_point(x: u32, y: u32, seeds: OwenSeeds) -> Vec2 {
    let (x, y) = reverse_pair(
        owen_scramble_reversed(x, seeds.x),
        owen_scramble_reversed(y, seeds.y),
    );
    Vec2::new(u32_to_unit_f32(x), u32_to_unit_f32(y))
}

/// Point `s` (an already shuffled sequence index) of Sobol' dimensions
/// (0, 1), scrambled by `seeds`.
#[inline(always)]
pub(super) const fn sobol_2d_at(s: u32, seeds: OwenSeeds) -> Vec2 {
    // Dimension 0's generator is the identity: its reversed digits are `s`.
    scrambled_point(s, pascal_reversed(s), seeds)
}

/// Point `s` of Sobol' dimension 0, scrambled by `seed`.
#[inline(always)]
pub(super) const fn sobol_1d_at(s: u32, seed: u32) -> f32 {
    u32_to_unit_f32(owen_scramble_reversed(s, seed).reverse_bits())
}

/// The Owen-scrambled van der Corput value (Sobol' dimension 0) of
/// `index`, shuffled by `stream`.
#[inline(always)]
const fn sobol_1d(index: u32, stream: u32) -> f32 {
    let seeds = seeds_2d(stream);
    sobol_1d_at(owen_scramble(index, seeds.index), seeds.x)
}

/// Point `s` (an already shuffled sequence index) of the 4D Owen-scrambled
/// Sobol' set whose scrambles are seeded by `stream`.
#[inline(always)]
pub(super) const fn sobol_4d_at(s: u32, stream: u32) -> Vec4 {
    // The seeds of `seeds_2d` and two more rotations.
    let OwenSeeds { x, y, .. } = seeds_2d(stream);
    let z = stream.rotate_right(6) ^ 0x6f4f_2a35;
    let w = stream.rotate_right(27) ^ 0x8f1b_bcdd;
    let (c2, c3) = dimensions_2_3_reversed(s);
    let (a, b) = reverse_pair(
        owen_scramble_reversed(s, x),
        owen_scramble_reversed(pascal_reversed(s), y),
    );
    let (c, d) = reverse_pair(owen_scramble_reversed(c2, z), owen_scramble_reversed(c3, w));
    Vec4::new(
        u32_to_unit_f32(a),
        u32_to_unit_f32(b),
        u32_to_unit_f32(c),
        u32_to_unit_f32(d),
    )
}

/// Sample `index` of the shuffled 4D Sobol' set of `stream`.
#[inline(always)]
const fn sobol_4d(index: u32, stream: u32) -> Vec4 {
    sobol_4d_at(owen_scramble(index, stream), stream)
}

impl DomainSampler for Sobol {
    #[inline]
    fn is_progressive(&self) -> bool {
        true
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        sobol_1d(index, stream)
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u32) -> Vec2 {
        let seeds = seeds_2d(stream);
        sobol_2d_at(owen_scramble(index, seeds.index), seeds)
    }
    #[inline]
    fn domain_3d(&self, index: u32, stream: u32) -> Vec3 {
        sobol_4d(index, stream).truncate()
    }
    #[inline]
    fn domain_4d(&self, index: u32, stream: u32) -> Vec4 {
        sobol_4d(index, stream)
    }
}

impl DomainSampler for Pmj02 {
    #[inline]
    fn is_progressive(&self) -> bool {
        true
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        sobol_1d(index, stream)
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u32) -> Vec2 {
        let seeds = seeds_2d(stream);
        let s = owen_scramble(index, seeds.index);
        scrambled_point(stirling_x(s), stirling_y(s), seeds)
    }
    #[inline]
    fn domain_3d(&self, index: u32, stream: u32) -> Vec3 {
        sobol_4d(index, stream).truncate()
    }
    #[inline]
    fn domain_4d(&self, index: u32, stream: u32) -> Vec4 {
        sobol_4d(index, stream)
    }
}

impl DomainSampler for Halton {
    #[inline]
    fn is_progressive(&self) -> bool {
        true
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        sobol_1d(index, stream)
    }
}

/// Random's draws hash the index into the already mixed `stream` (a
/// Weyl step and one hash per coordinate) instead of hashing a pattern
/// first: independent uniform values, other than `sample`'s.
#[inline(always)]
const fn random_bits(index: u32, stream: u32) -> u32 {
    hash_u32(stream.wrapping_add(index.wrapping_mul(0x9e37_79b9)))
}

impl DomainSampler for Random {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        u32_to_unit_f32(random_bits(index, stream))
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u32) -> Vec2 {
        let x = random_bits(index, stream);
        let y = hash_u32(x ^ 0x711a_d6a5);
        Vec2::new(u32_to_unit_f32(x), u32_to_unit_f32(y))
    }
}

impl DomainSampler for Regular {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        stratified_1d(index, self.len(), stream, false)
    }
}

impl DomainSampler for Jittered {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        stratified_1d(index, self.len(), stream, true)
    }
}

impl DomainSampler for NRooks {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        stratified_1d(index, self.len(), stream, true)
    }
}

impl DomainSampler for MultiJittered {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        stratified_1d(index, self.len(), stream, true)
    }
}

impl DomainSampler for CorrelatedMultiJittered {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        stratified_1d(index, self.len(), stream, true)
    }
}

impl DomainSampler for Hammersley {
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        stratified_1d(index, self.len(), stream, true)
    }
}

impl DomainSampler for AnySampler {
    #[inline]
    fn is_progressive(&self) -> bool {
        match self {
            AnySampler::Regular(s) => s.is_progressive(),
            AnySampler::Random(s) => s.is_progressive(),
            AnySampler::Jittered(s) => s.is_progressive(),
            AnySampler::NRooks(s) => s.is_progressive(),
            AnySampler::MultiJittered(s) => s.is_progressive(),
            AnySampler::CorrelatedMultiJittered(s) => s.is_progressive(),
            AnySampler::Hammersley(s) => s.is_progressive(),
            AnySampler::Halton(s) => s.is_progressive(),
            AnySampler::Sobol(s) => s.is_progressive(),
            AnySampler::Pmj02(s) => s.is_progressive(),
        }
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u32) -> f32 {
        match self {
            AnySampler::Regular(s) => s.domain_1d(index, stream),
            AnySampler::Random(s) => s.domain_1d(index, stream),
            AnySampler::Jittered(s) => s.domain_1d(index, stream),
            AnySampler::NRooks(s) => s.domain_1d(index, stream),
            AnySampler::MultiJittered(s) => s.domain_1d(index, stream),
            AnySampler::CorrelatedMultiJittered(s) => s.domain_1d(index, stream),
            AnySampler::Hammersley(s) => s.domain_1d(index, stream),
            AnySampler::Halton(s) => s.domain_1d(index, stream),
            AnySampler::Sobol(s) => s.domain_1d(index, stream),
            AnySampler::Pmj02(s) => s.domain_1d(index, stream),
        }
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u32) -> Vec2 {
        match self {
            AnySampler::Regular(s) => s.domain_2d(index, stream),
            AnySampler::Random(s) => s.domain_2d(index, stream),
            AnySampler::Jittered(s) => s.domain_2d(index, stream),
            AnySampler::NRooks(s) => s.domain_2d(index, stream),
            AnySampler::MultiJittered(s) => s.domain_2d(index, stream),
            AnySampler::CorrelatedMultiJittered(s) => s.domain_2d(index, stream),
            AnySampler::Hammersley(s) => s.domain_2d(index, stream),
            AnySampler::Halton(s) => s.domain_2d(index, stream),
            AnySampler::Sobol(s) => s.domain_2d(index, stream),
            AnySampler::Pmj02(s) => s.domain_2d(index, stream),
        }
    }
    #[inline]
    fn domain_3d(&self, index: u32, stream: u32) -> Vec3 {
        match self {
            AnySampler::Regular(s) => s.domain_3d(index, stream),
            AnySampler::Random(s) => s.domain_3d(index, stream),
            AnySampler::Jittered(s) => s.domain_3d(index, stream),
            AnySampler::NRooks(s) => s.domain_3d(index, stream),
            AnySampler::MultiJittered(s) => s.domain_3d(index, stream),
            AnySampler::CorrelatedMultiJittered(s) => s.domain_3d(index, stream),
            AnySampler::Hammersley(s) => s.domain_3d(index, stream),
            AnySampler::Halton(s) => s.domain_3d(index, stream),
            AnySampler::Sobol(s) => s.domain_3d(index, stream),
            AnySampler::Pmj02(s) => s.domain_3d(index, stream),
        }
    }
    #[inline]
    fn domain_4d(&self, index: u32, stream: u32) -> Vec4 {
        match self {
            AnySampler::Regular(s) => s.domain_4d(index, stream),
            AnySampler::Random(s) => s.domain_4d(index, stream),
            AnySampler::Jittered(s) => s.domain_4d(index, stream),
            AnySampler::NRooks(s) => s.domain_4d(index, stream),
            AnySampler::MultiJittered(s) => s.domain_4d(index, stream),
            AnySampler::CorrelatedMultiJittered(s) => s.domain_4d(index, stream),
            AnySampler::Hammersley(s) => s.domain_4d(index, stream),
            AnySampler::Halton(s) => s.domain_4d(index, stream),
            AnySampler::Sobol(s) => s.domain_4d(index, stream),
            AnySampler::Pmj02(s) => s.domain_4d(index, stream),
        }
    }
}
