//! Choosing a pixel sampler by name: [`PixelSamplerKind`] and its
//! statically dispatched product, [`AnyPixelSampler`].

use core::fmt;
use core::str::FromStr;

use glam::{Vec2, Vec3, Vec4};

use super::{BlueNoise, Draw, Padded, PaddedNd, PixelSampler, PixelSamplerHooks, Root, ZSobol};
use crate::error::{Error, UnknownName, same_name};
use crate::samplers::ALIAS_NAMES as SAMPLER_ALIAS_NAMES;
use crate::samplers::{
    AnySampler, Faure4D, LatinHypercube, OrthogonalArray, SamplerKind, SamplerVisitor,
};
use crate::traits::DomainSampler;

/// The pixel samplers that are not a padded [`SamplerKind`], in
/// [`PixelSamplerKind::ALL`]'s order.
const PIXEL_ONLY: [PixelSamplerKind; 5] = [
    PixelSamplerKind::ZSobol,
    PixelSamplerKind::BlueNoise,
    PixelSamplerKind::Orthogonal,
    PixelSamplerKind::LatinHypercube,
    PixelSamplerKind::Faure,
];

/// The pixel-only kinds' short names.
const PIXEL_ALIASES: [(&str, PixelSamplerKind); 1] = [("lhs", PixelSamplerKind::LatinHypercube)];

/// Every name the parser takes, for error messages: the padded kinds'
/// names, then the pixel-only kinds'.
const PIXEL_NAMES: [&str; SamplerKind::ALL.len() + PIXEL_ONLY.len()] = {
    let mut names = [""; SamplerKind::ALL.len() + PIXEL_ONLY.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = PixelSamplerKind::ALL[i].name();
        i += 1;
    }
    names
};

/// Every alias the parser takes: [`SamplerKind`]'s, then the pixel-only
/// kinds'.
const PIXEL_ALIAS_NAMES: [&str; SAMPLER_ALIAS_NAMES.len() + PIXEL_ALIASES.len()] = {
    let mut names = [""; SAMPLER_ALIAS_NAMES.len() + PIXEL_ALIASES.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = if i < SAMPLER_ALIAS_NAMES.len() {
            SAMPLER_ALIAS_NAMES[i]
        } else {
            PIXEL_ALIASES[i - SAMPLER_ALIAS_NAMES.len()].0
        };
        i += 1;
    }
    names
};

/// Every pixel sampler wellspread offers: [`Padded`] over each
/// [`SamplerKind`], [`ZSobol`], [`BlueNoise`], and [`PaddedNd`] over an
/// [`OrthogonalArray`], a [`LatinHypercube`] and [`Faure4D`].
///
/// Names are the README's: a [`SamplerKind`] name (`"sobol"`,
/// `"correlated-multi-jittered"`, ...) for its padded form, `"zsobol"`,
/// `"blue-noise"`, `"orthogonal"`, `"latin-hypercube"` and `"faure"`.
/// Parsing ignores case, `-`, `_` and spaces, and accepts the short
/// aliases `cmj`, `mj`, `pmj`, `rooks` (padded n-rooks, the 2D Latin
/// hypercube), `stratified`, `white` and `lhs` (`latin-hypercube`, the
/// N-dimensional one).
///
/// ```
/// use wellspread::{PixelSampler, PixelSamplerKind, SamplerKind};
/// let kind: PixelSamplerKind = "CMJ".parse()?;
/// assert_eq!(kind, PixelSamplerKind::Padded(SamplerKind::CorrelatedMultiJittered));
/// let sampler = kind.build(16, [640, 480], 0)?;
/// let mut d = sampler.start([10, 20], 3);
/// let film = d.next_2d();
/// assert!(film.x < 1.0 && film.y < 1.0);
/// assert_eq!("zsobol".parse::<PixelSamplerKind>()?.name(), "zsobol");
/// assert!(PixelSamplerKind::all().count() > SamplerKind::ALL.len());
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// Not `#[non_exhaustive]`, like [`SamplerKind`]: a `match` over the kinds
/// fails to compile until a new pixel sampler has its line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelSamplerKind {
    /// [`Padded`] over a sampler of this kind.
    Padded(SamplerKind),
    /// [`ZSobol`].
    ZSobol,
    /// [`BlueNoise`].
    BlueNoise,
    /// [`PaddedNd`] over an [`OrthogonalArray`] of strength 2 with its
    /// most dimensions, for any count `n = lambda q^2` with `q` a prime
    /// power (8, 12, 18, 32, 50, 128, ... besides the squares): `q` is the
    /// largest that fits, and the pixel's `n` samples are `lambda` passes
    /// of the `q^2` array (indices `p q^2 .. (p + 1) q^2` are pass `p`,
    /// keyed independently). Each pass is a full array: every page of
    /// `q + 1` dimensions has every pair of them fill the `q x q` grid,
    /// every dimension Latin over the pass's `q^2` samples; over all `n`
    /// samples each dimension has `lambda` samples in each of those `q^2`
    /// strata. So 8 spp is two 4-sample arrays (`q = 2`, 3 dimensions a
    /// page), 32 spp two of 16 (`q = 4`), 128 two of 64 (`q = 8`). Counts
    /// with no such form (1, 2, 3, 5, 6, 7, 10, ...) are an error naming
    /// the nearest valid ones: one sample has no pairs to stratify, and
    /// `q = 1` would be a random point per dimension.
    Orthogonal,
    /// [`PaddedNd`] over a [`LatinHypercube`] of
    /// [`MAX_DIMENSIONS`](LatinHypercube::MAX_DIMENSIONS).
    LatinHypercube,
    /// [`PaddedNd`] over [`Faure4D`], the (0,4)-sequence in base 4: a
    /// progressive kind (any count, every power-of-two prefix the same
    /// set) whose domains read their draws in call order as pages of four
    /// dimensions, so at 16 spp every pair of a page's dimensions fills the
    /// `4 x 4` grid (a film and lens `next_4d`, or a light choice and the
    /// light sample's pair), at 64 spp every triple `4 x 4 x 4`, and each
    /// dimension is stratified at every power-of-two prefix. What
    /// `orthogonal` gives at `q = 4`, for four dimensions a page instead of
    /// five, at every count and at a sequence draw's cost.
    Faure,
}

impl PixelSamplerKind {
    /// Every pixel sampler kind: the padded form of each of
    /// [`SamplerKind::ALL`], in its order, then `ZSobol`, `BlueNoise`,
    /// `Orthogonal`, `LatinHypercube` and `Faure`.
    pub const ALL: &'static [PixelSamplerKind] = &{
        let padded = SamplerKind::ALL.len();
        let mut all = [PixelSamplerKind::ZSobol; SamplerKind::ALL.len() + PIXEL_ONLY.len()];
        let mut i = 0;
        while i < all.len() {
            all[i] = if i < padded {
                PixelSamplerKind::Padded(SamplerKind::ALL[i])
            } else {
                PIXEL_ONLY[i - padded]
            };
            i += 1;
        }
        all
    };

    /// [`ALL`](Self::ALL) as an iterator.
    pub fn all() -> impl Iterator<Item = PixelSamplerKind> + Clone {
        Self::ALL.iter().copied()
    }

    /// The name tools use: the [`SamplerKind`] name, `"zsobol"`,
    /// `"blue-noise"`, `"orthogonal"`, `"latin-hypercube"` or `"faure"`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            PixelSamplerKind::Padded(kind) => kind.name(),
            PixelSamplerKind::ZSobol => "zsobol",
            PixelSamplerKind::BlueNoise => "blue-noise",
            PixelSamplerKind::Orthogonal => "orthogonal",
            PixelSamplerKind::LatinHypercube => "latin-hypercube",
            PixelSamplerKind::Faure => "faure",
        }
    }

    /// The pixel sampler for `samples_per_pixel` samples on a
    /// `resolution = [width, height]` film, `frame` picking its
    /// randomisation. Padded samplers ignore the resolution (any pixel is
    /// valid); ZSobol and BlueNoise key their pixel order by it.
    ///
    /// # Errors
    ///
    /// What the sampler's constructor rejects: `samples_per_pixel = 0` for
    /// all, a count that is not a power of two, a zero side or too large an
    /// index space for ZSobol (see [`ZSobol::new`]), a count that is not
    /// `lambda q^2` for a prime power `q` for `Orthogonal`
    /// ([`Error::NotOrthogonalPixelCount`], which names the nearest valid
    /// counts).
    pub fn build(
        self,
        samples_per_pixel: u32,
        resolution: [u32; 2],
        frame: u32,
    ) -> Result<AnyPixelSampler, Error> {
        Ok(match self {
            PixelSamplerKind::Padded(kind) => {
                AnyPixelSampler::Padded(Padded::new(kind.build(samples_per_pixel)?, frame))
            }
            PixelSamplerKind::ZSobol => {
                AnyPixelSampler::ZSobol(ZSobol::new(samples_per_pixel, resolution, frame)?)
            }
            PixelSamplerKind::BlueNoise => {
                AnyPixelSampler::BlueNoise(BlueNoise::new(samples_per_pixel, resolution, frame)?)
            }
            PixelSamplerKind::Orthogonal => {
                if samples_per_pixel == 0 {
                    return Err(Error::ZeroSamples);
                }
                let q = OrthogonalArray::pass_levels(samples_per_pixel).ok_or_else(|| {
                    let (below, above) = OrthogonalArray::nearest_pass_counts(samples_per_pixel);
                    Error::NotOrthogonalPixelCount {
                        samples_per_pixel,
                        below,
                        above,
                    }
                })?;
                // Every column strength 2 has: q + 1.
                let array = OrthogonalArray::new(q * q, q + 1, 2)?;
                let passes = samples_per_pixel / (q * q);
                AnyPixelSampler::Orthogonal(PaddedNd::new(array, frame).with_passes(passes))
            }
            PixelSamplerKind::LatinHypercube => {
                let cube = LatinHypercube::new(samples_per_pixel, LatinHypercube::MAX_DIMENSIONS)?;
                AnyPixelSampler::LatinHypercube(PaddedNd::new(cube, frame))
            }
            PixelSamplerKind::Faure => {
                AnyPixelSampler::Faure(PaddedNd::new(Faure4D::new(samples_per_pixel)?, frame))
            }
        })
    }
}

impl fmt::Display for PixelSamplerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for PixelSamplerKind {
    type Err = Error;

    /// The kind named `name`: `"zsobol"`, `"blue-noise"`, `"orthogonal"`,
    /// `"latin-hypercube"`, or a [`SamplerKind`] name or alias for its
    /// padded form, by [`SamplerKind`]'s rule (any case, with or without
    /// `-`, `_` or spaces).
    ///
    /// # Errors
    ///
    /// [`Error::UnknownPixelSampler`], which names the input and lists
    /// the valid names.
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        let pixel_only = PIXEL_ONLY.iter().map(|&kind| (kind.name(), kind));
        if let Some((_, kind)) = pixel_only
            .chain(PIXEL_ALIASES)
            .find(|&(known, _)| same_name(name, known))
        {
            return Ok(kind);
        }
        name.parse::<SamplerKind>()
            .map(PixelSamplerKind::Padded)
            .map_err(|_| {
                Error::UnknownPixelSampler(UnknownName::new(name, &PIXEL_NAMES, &PIXEL_ALIAS_NAMES))
            })
    }
}

/// `PixelSamplerKind` in settings files (feature `serde`): serialized as
/// its [`name`](PixelSamplerKind::name), deserialized from it with the
/// same error as [`FromStr`].
#[cfg(feature = "serde")]
mod serde_impls {
    use serde::de::{Deserialize, Deserializer};
    use serde::ser::{Serialize, Serializer};

    use super::PixelSamplerKind;

    #[cfg_attr(docsrs, doc(cfg(feature = "serde")))]
    impl Serialize for PixelSamplerKind {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            serializer.serialize_str(self.name())
        }
    }

    #[cfg_attr(docsrs, doc(cfg(feature = "serde")))]
    impl<'de> Deserialize<'de> for PixelSamplerKind {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            crate::error::deserialize_name(
                deserializer,
                "a pixel sampler name such as \"sobol\" or \"blue-noise\"",
            )
        }
    }
}

/// Any pixel sampler, chosen at run time (`Copy`, `'static`, enum
/// dispatch with no allocation). Made by [`PixelSamplerKind::build`].
///
/// Three ways to draw from it, with the same values:
///
/// - `sampler.start(pixel, index)`: a 32-byte `Domain<&AnyPixelSampler>`
///   that borrows it, the default. Each draw matches on the kind and calls
///   that kind's kernel.
/// - `Domain::start(sampler, pixel, index)`: the owned
///   `Domain<AnyPixelSampler>` (120 bytes, `'static`), for a thread-local
///   or a boundary without lifetimes; the same draws.
/// - [`visit`](Self::visit): code generic over the sampler, run on the
///   concrete type, with no dispatch per draw (a tile's or a frame's loop).
///
/// `docs/performance.md` lists the draws' cost each way.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum AnyPixelSampler {
    /// A padded [`AnySampler`].
    Padded(Padded<AnySampler>),
    /// A [`ZSobol`].
    ZSobol(ZSobol),
    /// A [`BlueNoise`].
    BlueNoise(BlueNoise),
    /// An orthogonal array through [`PaddedNd`].
    Orthogonal(PaddedNd<OrthogonalArray>),
    /// A Latin hypercube through [`PaddedNd`].
    LatinHypercube(PaddedNd<LatinHypercube>),
    /// The base-4 (0,4)-sequence through [`PaddedNd`].
    Faure(PaddedNd<Faure4D>),
}

impl AnyPixelSampler {
    /// Which kind it is.
    #[must_use]
    pub const fn kind(&self) -> PixelSamplerKind {
        match self {
            AnyPixelSampler::Padded(p) => PixelSamplerKind::Padded(p.sampler().kind()),
            AnyPixelSampler::ZSobol(_) => PixelSamplerKind::ZSobol,
            AnyPixelSampler::BlueNoise(_) => PixelSamplerKind::BlueNoise,
            AnyPixelSampler::Orthogonal(_) => PixelSamplerKind::Orthogonal,
            AnyPixelSampler::LatinHypercube(_) => PixelSamplerKind::LatinHypercube,
            AnyPixelSampler::Faure(_) => PixelSamplerKind::Faure,
        }
    }

    /// Runs `visitor` on the concrete pixel sampler inside (a padded kind
    /// as `Padded<Sobol>`, `Padded<Jittered>`, ...): one dispatch, then
    /// every draw compiled for that type, at its cost. Draws through
    /// `Domain<&AnyPixelSampler>` dispatch on the kind at each draw instead
    /// (see [`PixelSamplerVisitor`] for the trade). Same values either way.
    #[inline]
    pub fn visit<V: PixelSamplerVisitor>(&self, visitor: V) -> V::Output {
        match self {
            AnyPixelSampler::Padded(p) => p.sampler().visit(Padding {
                frame: p.frame(),
                visitor,
            }),
            AnyPixelSampler::ZSobol(s) => visitor.visit(s),
            AnyPixelSampler::BlueNoise(s) => visitor.visit(s),
            AnyPixelSampler::Orthogonal(s) => visitor.visit(s),
            AnyPixelSampler::LatinHypercube(s) => visitor.visit(s),
            AnyPixelSampler::Faure(s) => visitor.visit(s),
        }
    }
}

/// Code generic over the pixel sampler, run by [`AnyPixelSampler::visit`]
/// on the concrete sampler: the renderer's sampler comes from a flag, and
/// its loop over a tile or a frame is still compiled for that one type.
///
/// # Cost
///
/// One `match` per `visit`; inside, each draw costs what the concrete
/// type's does. A `Domain<&AnyPixelSampler>` instead matches on the kind
/// at every draw and calls the kind's kernel out of line, which adds about
/// two PCG-hash units per draw (`docs/performance.md` lists both); the
/// price of the visitor is code size (the loop is compiled once per kind)
/// and a generic method where a plain function would do.
///
/// ```
/// use wellspread::{PixelSampler, PixelSamplerKind, PixelSamplerVisitor};
/// struct Tile<'a> {
///     out: &'a mut [f32],
///     spp: u32,
/// }
/// impl PixelSamplerVisitor for Tile<'_> {
///     type Output = ();
///     fn visit<S: PixelSampler + Copy>(self, sampler: &S) {
///         for (x, v) in self.out.iter_mut().enumerate() {
///             for i in 0..self.spp {
///                 let mut d = sampler.start([x as u32, 0], i); // Domain<&S>
///                 *v += d.next_2d().x / self.spp as f32;
///             }
///         }
///     }
/// }
/// let sampler = "pmj02".parse::<PixelSamplerKind>()?.build(16, [8, 1], 0)?;
/// let mut row = [0.0f32; 8];
/// sampler.visit(Tile { out: &mut row, spp: 16 });
/// // The same values as the dynamic domain's draws.
/// let x3: f32 = (0..16).map(|i| sampler.start([3, 0], i).next_2d().x / 16.0).sum();
/// assert_eq!(row[3], x3);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait PixelSamplerVisitor {
    /// What [`visit`](Self::visit) returns.
    type Output;
    /// Runs on the concrete pixel sampler.
    fn visit<S: PixelSampler + Copy>(self, sampler: &S) -> Self::Output;
}

/// A padded kind's visitor: the concrete sampler, padded with the frame.
struct Padding<V> {
    frame: u32,
    visitor: V,
}

impl<V: PixelSamplerVisitor> SamplerVisitor for Padding<V> {
    type Output = V::Output;
    #[inline]
    fn visit<S: DomainSampler + Copy + Send + Sync>(self, sampler: &S) -> V::Output {
        self.visitor.visit(&Padded::new(*sampler, self.frame))
    }
}

impl PixelSampler for AnyPixelSampler {
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        match self {
            AnyPixelSampler::Padded(s) => s.samples_per_pixel(),
            AnyPixelSampler::ZSobol(s) => s.samples_per_pixel(),
            AnyPixelSampler::BlueNoise(s) => s.samples_per_pixel(),
            AnyPixelSampler::Orthogonal(s) => s.samples_per_pixel(),
            AnyPixelSampler::LatinHypercube(s) => s.samples_per_pixel(),
            AnyPixelSampler::Faure(s) => s.samples_per_pixel(),
        }
    }
}

impl PixelSamplerHooks for AnyPixelSampler {
    #[inline(always)]
    fn root(&self, pixel: [u32; 2]) -> Root {
        match self {
            AnyPixelSampler::Padded(s) => s.root(pixel),
            AnyPixelSampler::ZSobol(s) => s.root(pixel),
            AnyPixelSampler::BlueNoise(s) => s.root(pixel),
            AnyPixelSampler::Orthogonal(s) => s.root(pixel),
            AnyPixelSampler::LatinHypercube(s) => s.root(pixel),
            AnyPixelSampler::Faure(s) => s.root(pixel),
        }
    }

    #[inline(always)]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        match self {
            AnyPixelSampler::Padded(s) => s.locate(index, key),
            AnyPixelSampler::ZSobol(s) => s.locate(index, key),
            AnyPixelSampler::BlueNoise(s) => s.locate(index, key),
            AnyPixelSampler::Orthogonal(s) => s.locate(index, key),
            AnyPixelSampler::LatinHypercube(s) => s.locate(index, key),
            AnyPixelSampler::Faure(s) => s.locate(index, key),
        }
    }

    #[inline(always)]
    fn draw_1d(&self, draw: Draw) -> f32 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_1d(draw),
            AnyPixelSampler::ZSobol(s) => kernel_1d(s, draw),
            AnyPixelSampler::BlueNoise(s) => kernel_1d(s, draw),
            AnyPixelSampler::Orthogonal(s) => kernel_1d(s, draw),
            AnyPixelSampler::LatinHypercube(s) => kernel_1d(s, draw),
            AnyPixelSampler::Faure(s) => kernel_1d(s, draw),
        }
    }

    #[inline(always)]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_2d(draw),
            AnyPixelSampler::ZSobol(s) => kernel_2d(s, draw),
            AnyPixelSampler::BlueNoise(s) => kernel_2d(s, draw),
            AnyPixelSampler::Orthogonal(s) => kernel_2d(s, draw),
            AnyPixelSampler::LatinHypercube(s) => kernel_2d(s, draw),
            AnyPixelSampler::Faure(s) => kernel_2d(s, draw),
        }
    }

    #[inline(always)]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_3d(draw),
            AnyPixelSampler::ZSobol(s) => kernel_3d(s, draw),
            AnyPixelSampler::BlueNoise(s) => kernel_3d(s, draw),
            AnyPixelSampler::Orthogonal(s) => kernel_3d(s, draw),
            AnyPixelSampler::LatinHypercube(s) => kernel_3d(s, draw),
            AnyPixelSampler::Faure(s) => kernel_3d(s, draw),
        }
    }

    #[inline(always)]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_4d(draw),
            AnyPixelSampler::ZSobol(s) => kernel_4d(s, draw),
            AnyPixelSampler::BlueNoise(s) => kernel_4d(s, draw),
            AnyPixelSampler::Orthogonal(s) => kernel_4d(s, draw),
            AnyPixelSampler::LatinHypercube(s) => kernel_4d(s, draw),
            AnyPixelSampler::Faure(s) => kernel_4d(s, draw),
        }
    }
}

// The pixel-only kinds' draws, out of line (see `AnySampler`'s kernels).
#[inline(never)]
fn kernel_1d<S: PixelSampler>(s: &S, draw: Draw) -> f32 {
    s.draw_1d(draw)
}
#[inline(never)]
fn kernel_2d<S: PixelSampler>(s: &S, draw: Draw) -> Vec2 {
    s.draw_2d(draw)
}
#[inline(never)]
fn kernel_3d<S: PixelSampler>(s: &S, draw: Draw) -> Vec3 {
    s.draw_3d(draw)
}
#[inline(never)]
fn kernel_4d<S: PixelSampler>(s: &S, draw: Draw) -> Vec4 {
    s.draw_4d(draw)
}
