//! Choosing a pixel sampler by name: [`PixelSamplerKind`] and its
//! statically dispatched product, [`AnyPixelSampler`].

use core::fmt;
use core::str::FromStr;

use glam::{Vec2, Vec3, Vec4};

use super::{BlueNoise, Draw, Padded, PixelSampler, Root, ZSobol};
use crate::error::InputText;
use crate::{AnySampler, Error, SamplerKind};

/// Short names accepted besides the full ones, each with its kind. Names
/// are compared ignoring case, `-`, `_` and spaces.
const ALIASES: &[(&str, SamplerKind)] = &[
    ("cmj", SamplerKind::CorrelatedMultiJittered),
    ("mj", SamplerKind::MultiJittered),
    ("pmj", SamplerKind::Pmj02),
    ("rooks", SamplerKind::NRooks),
    ("latin-hypercube", SamplerKind::NRooks),
    ("lhs", SamplerKind::NRooks),
    ("stratified", SamplerKind::Jittered),
    ("white", SamplerKind::Random),
];

/// The aliases as the error message lists them.
pub(crate) const ALIASES_TEXT: &str =
    "cmj, mj, pmj, rooks, latin-hypercube, lhs, stratified, white";

/// Every pixel sampler wellspread offers: [`Padded`] over each
/// [`SamplerKind`], [`ZSobol`] and [`BlueNoise`].
///
/// Names are the README's: a [`SamplerKind`] name (`"sobol"`,
/// `"correlated-multi-jittered"`, ...) for its padded form, `"zsobol"` and
/// `"blue-noise"`.
/// Parsing ignores case, `-`, `_` and spaces, and accepts the short
/// aliases `cmj`, `mj`, `pmj`, `rooks`, `latin-hypercube`, `lhs`,
/// `stratified` and `white`.
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
}

impl PixelSamplerKind {
    /// Every pixel sampler kind: the padded form of each of
    /// [`SamplerKind::ALL`], in its order, then `ZSobol`.
    pub fn all() -> impl Iterator<Item = PixelSamplerKind> + Clone {
        SamplerKind::ALL
            .iter()
            .map(|&kind| PixelSamplerKind::Padded(kind))
            .chain([PixelSamplerKind::ZSobol, PixelSamplerKind::BlueNoise])
    }

    /// The name tools use: the [`SamplerKind`] name, `"zsobol"` or
    /// `"blue-noise"`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            PixelSamplerKind::Padded(kind) => kind.name(),
            PixelSamplerKind::ZSobol => "zsobol",
            PixelSamplerKind::BlueNoise => "blue-noise",
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
    /// index space for ZSobol (see [`ZSobol::new`]).
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
        })
    }
}

impl fmt::Display for PixelSamplerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// `a` and `b` equal ignoring ASCII case and the separators `-`, `_`, ` `.
fn same_name(a: &str, b: &str) -> bool {
    let key = |s: &str| {
        s.bytes()
            .filter(|c| !matches!(c, b'-' | b'_' | b' '))
            .map(|c| c.to_ascii_lowercase())
            .collect::<heapless_bytes::Bytes>()
    };
    key(a) == key(b)
}

/// A fixed-capacity byte string for [`same_name`], so parsing needs no
/// allocation (no_std).
mod heapless_bytes {
    /// Up to 64 bytes; longer inputs keep a marker so they never compare
    /// equal to a (short) sampler name.
    #[derive(PartialEq, Eq)]
    pub(super) struct Bytes {
        bytes: [u8; 64],
        len: usize,
        overflow: bool,
    }

    impl FromIterator<u8> for Bytes {
        fn from_iter<I: IntoIterator<Item = u8>>(iter: I) -> Self {
            let mut out = Bytes {
                bytes: [0; 64],
                len: 0,
                overflow: false,
            };
            for b in iter {
                if out.len == out.bytes.len() {
                    out.overflow = true;
                    break;
                }
                out.bytes[out.len] = b;
                out.len += 1;
            }
            out
        }
    }
}

impl FromStr for PixelSamplerKind {
    type Err = Error;

    /// The kind named `name`, ignoring case and separators, or an alias.
    ///
    /// # Errors
    ///
    /// [`Error::UnknownPixelSampler`], which names the input and lists
    /// the valid names.
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        if let Some(kind) = PixelSamplerKind::all().find(|kind| same_name(kind.name(), name)) {
            return Ok(kind);
        }
        ALIASES
            .iter()
            .find(|(alias, _)| same_name(alias, name))
            .map(|&(_, kind)| PixelSamplerKind::Padded(kind))
            .ok_or(Error::UnknownPixelSampler {
                name: InputText::new(name),
            })
    }
}

/// Any pixel sampler, chosen at run time: the owned dynamic form (`Copy`,
/// `'static`, enum dispatch with no allocation), so `Domain<AnyPixelSampler>`
/// can live in a thread-local or be passed by value. Made by
/// [`PixelSamplerKind::build`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AnyPixelSampler {
    /// A padded [`AnySampler`].
    Padded(Padded<AnySampler>),
    /// A [`ZSobol`].
    ZSobol(ZSobol),
    /// A [`BlueNoise`].
    BlueNoise(BlueNoise),
}

impl AnyPixelSampler {
    /// Which kind it is.
    #[must_use]
    pub const fn kind(&self) -> PixelSamplerKind {
        match self {
            AnyPixelSampler::Padded(p) => PixelSamplerKind::Padded(p.sampler().kind()),
            AnyPixelSampler::ZSobol(_) => PixelSamplerKind::ZSobol,
            AnyPixelSampler::BlueNoise(_) => PixelSamplerKind::BlueNoise,
        }
    }
}

impl PixelSampler for AnyPixelSampler {
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        match self {
            AnyPixelSampler::Padded(s) => s.samples_per_pixel(),
            AnyPixelSampler::ZSobol(s) => s.samples_per_pixel(),
            AnyPixelSampler::BlueNoise(s) => s.samples_per_pixel(),
        }
    }
    #[inline]
    fn root(&self, pixel: [u32; 2]) -> Root {
        match self {
            AnyPixelSampler::Padded(s) => s.root(pixel),
            AnyPixelSampler::ZSobol(s) => s.root(pixel),
            AnyPixelSampler::BlueNoise(s) => s.root(pixel),
        }
    }
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        match self {
            AnyPixelSampler::Padded(s) => s.locate(index, key),
            AnyPixelSampler::ZSobol(s) => s.locate(index, key),
            AnyPixelSampler::BlueNoise(s) => s.locate(index, key),
        }
    }
    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_1d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_1d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_1d(draw),
        }
    }
    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_2d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_2d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_2d(draw),
        }
    }
    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_3d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_3d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_3d(draw),
        }
    }
    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_4d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_4d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_4d(draw),
        }
    }
}
