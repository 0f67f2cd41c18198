//! Choosing a pixel sampler by name: [`PixelSamplerKind`] and its
//! statically dispatched product, [`AnyPixelSampler`].

use core::fmt;
use core::str::FromStr;

use glam::{Vec2, Vec3, Vec4};

use super::{BlueNoise, Draw, Padded, PaddedNd, PixelSampler, Root, ZSobol};
use crate::error::Error;
use crate::error::InputText;
use crate::samplers::same_name;
use crate::samplers::{AnySampler, LatinHypercube, OrthogonalArray, SamplerKind};

/// The pixel samplers that are not a padded [`SamplerKind`], in
/// [`PixelSamplerKind::ALL`]'s order.
const PIXEL_ONLY: [PixelSamplerKind; 4] = [
    PixelSamplerKind::ZSobol,
    PixelSamplerKind::BlueNoise,
    PixelSamplerKind::Orthogonal,
    PixelSamplerKind::LatinHypercube,
];

/// Their names, for error messages.
pub(crate) const PIXEL_ONLY_NAMES: &[&str] = &{
    let mut names = [""; PIXEL_ONLY.len()];
    let mut i = 0;
    while i < PIXEL_ONLY.len() {
        names[i] = PIXEL_ONLY[i].name();
        i += 1;
    }
    names
};

/// Every pixel sampler wellspread offers: [`Padded`] over each
/// [`SamplerKind`], [`ZSobol`], [`BlueNoise`], and [`PaddedNd`] over an
/// [`OrthogonalArray`] and a [`LatinHypercube`].
///
/// Names are the README's: a [`SamplerKind`] name (`"sobol"`,
/// `"correlated-multi-jittered"`, ...) for its padded form, `"zsobol"`,
/// `"blue-noise"`, `"orthogonal"` and `"latin-hypercube"`.
/// Parsing ignores case, `-`, `_` and spaces, and accepts the short
/// aliases `cmj`, `mj`, `pmj`, `rooks`, `lhs` (padded n-rooks, the 2D
/// Latin hypercube), `stratified` and `white`.
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
    /// most dimensions (`q + 1` for `q^2` samples per pixel).
    Orthogonal,
    /// [`PaddedNd`] over a [`LatinHypercube`] of
    /// [`MAX_DIMENSIONS`](LatinHypercube::MAX_DIMENSIONS).
    LatinHypercube,
}

impl PixelSamplerKind {
    /// Every pixel sampler kind: the padded form of each of
    /// [`SamplerKind::ALL`], in its order, then `ZSobol`, `BlueNoise`,
    /// `Orthogonal` and `LatinHypercube`.
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
    /// `"blue-noise"`, `"orthogonal"` or `"latin-hypercube"`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            PixelSamplerKind::Padded(kind) => kind.name(),
            PixelSamplerKind::ZSobol => "zsobol",
            PixelSamplerKind::BlueNoise => "blue-noise",
            PixelSamplerKind::Orthogonal => "orthogonal",
            PixelSamplerKind::LatinHypercube => "latin-hypercube",
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
    /// the square of a prime power for `Orthogonal` (the error names the
    /// nearest valid counts; see [`OrthogonalArray::new`]).
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
                // Every column strength 2 has: ask for 3 (any q has them),
                // then for all of them.
                let most = OrthogonalArray::new(samples_per_pixel, 3, 2)?.max_dimensions();
                let array = OrthogonalArray::new(samples_per_pixel, most, 2)?;
                AnyPixelSampler::Orthogonal(PaddedNd::new(array, frame))
            }
            PixelSamplerKind::LatinHypercube => {
                let cube = LatinHypercube::new(samples_per_pixel, LatinHypercube::MAX_DIMENSIONS)?;
                AnyPixelSampler::LatinHypercube(PaddedNd::new(cube, frame))
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
        if let Some(&kind) = PIXEL_ONLY.iter().find(|kind| same_name(name, kind.name())) {
            return Ok(kind);
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
    /// An orthogonal array through [`PaddedNd`].
    Orthogonal(PaddedNd<OrthogonalArray>),
    /// A Latin hypercube through [`PaddedNd`].
    LatinHypercube(PaddedNd<LatinHypercube>),
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
            AnyPixelSampler::Orthogonal(s) => s.samples_per_pixel(),
            AnyPixelSampler::LatinHypercube(s) => s.samples_per_pixel(),
        }
    }
    #[inline]
    fn root(&self, pixel: [u32; 2]) -> Root {
        match self {
            AnyPixelSampler::Padded(s) => s.root(pixel),
            AnyPixelSampler::ZSobol(s) => s.root(pixel),
            AnyPixelSampler::BlueNoise(s) => s.root(pixel),
            AnyPixelSampler::Orthogonal(s) => s.root(pixel),
            AnyPixelSampler::LatinHypercube(s) => s.root(pixel),
        }
    }
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        match self {
            AnyPixelSampler::Padded(s) => s.locate(index, key),
            AnyPixelSampler::ZSobol(s) => s.locate(index, key),
            AnyPixelSampler::BlueNoise(s) => s.locate(index, key),
            AnyPixelSampler::Orthogonal(s) => s.locate(index, key),
            AnyPixelSampler::LatinHypercube(s) => s.locate(index, key),
        }
    }
    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_1d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_1d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_1d(draw),
            AnyPixelSampler::Orthogonal(s) => s.draw_1d(draw),
            AnyPixelSampler::LatinHypercube(s) => s.draw_1d(draw),
        }
    }
    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_2d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_2d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_2d(draw),
            AnyPixelSampler::Orthogonal(s) => s.draw_2d(draw),
            AnyPixelSampler::LatinHypercube(s) => s.draw_2d(draw),
        }
    }
    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_3d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_3d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_3d(draw),
            AnyPixelSampler::Orthogonal(s) => s.draw_3d(draw),
            AnyPixelSampler::LatinHypercube(s) => s.draw_3d(draw),
        }
    }
    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        match self {
            AnyPixelSampler::Padded(s) => s.draw_4d(draw),
            AnyPixelSampler::ZSobol(s) => s.draw_4d(draw),
            AnyPixelSampler::BlueNoise(s) => s.draw_4d(draw),
            AnyPixelSampler::Orthogonal(s) => s.draw_4d(draw),
            AnyPixelSampler::LatinHypercube(s) => s.draw_4d(draw),
        }
    }
}
