//! Choosing a pixel sampler by name: [`PixelSamplerKind`] and its
//! statically dispatched product, [`AnyPixelSampler`].

use core::fmt;
use core::str::FromStr;

use glam::{Vec2, Vec3, Vec4};

use super::{BlueNoise, Draw, Padded, PixelSampler, Root, ZSobol};
use crate::error::InputText;
use crate::samplers::same_name;
use crate::{AnySampler, Error, SamplerKind};

/// The names of the pixel samplers that are not a padded [`SamplerKind`],
/// in [`PixelSamplerKind::ALL`]'s order.
pub(crate) const PIXEL_ONLY_NAMES: &[&str] = &["zsobol", "blue-noise"];

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
    /// [`SamplerKind::ALL`], in its order, then `ZSobol` and `BlueNoise`.
    pub const ALL: &'static [PixelSamplerKind] = &{
        let mut all = [PixelSamplerKind::ZSobol; SamplerKind::ALL.len() + 2];
        let mut i = 0;
        while i < SamplerKind::ALL.len() {
            all[i] = PixelSamplerKind::Padded(SamplerKind::ALL[i]);
            i += 1;
        }
        all[i + 1] = PixelSamplerKind::BlueNoise;
        all
    };

    /// [`ALL`](Self::ALL) as an iterator.
    pub fn all() -> impl Iterator<Item = PixelSamplerKind> + Clone {
        Self::ALL.iter().copied()
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

impl FromStr for PixelSamplerKind {
    type Err = Error;

    /// The kind named `name`: `"zsobol"`, `"blue-noise"`, or a
    /// [`SamplerKind`] name or alias for its padded form, by
    /// [`SamplerKind`]'s rule (any case, with or without `-`, `_` or
    /// spaces).
    ///
    /// # Errors
    ///
    /// [`Error::UnknownPixelSampler`], which names the input and lists
    /// the valid names.
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        if same_name(name, PixelSamplerKind::ZSobol.name()) {
            return Ok(PixelSamplerKind::ZSobol);
        }
        if same_name(name, PixelSamplerKind::BlueNoise.name()) {
            return Ok(PixelSamplerKind::BlueNoise);
        }
        name.parse::<SamplerKind>()
            .map(PixelSamplerKind::Padded)
            .map_err(|_| Error::UnknownPixelSampler {
                name: InputText::new(name),
                pixel_only: PIXEL_ONLY_NAMES,
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
