//! The render core: where each pixel's samples go (the library's
//! [`PixelSampler`]), what they see (the scene), and how they become pixels
//! (the reconstruction filter).
//!
//! Every pixel value is a fixed sequence of f64 additions in a fixed order,
//! whichever thread computes it, so the image is bit-identical for any
//! thread count (the test at the bottom checks 1 against 2 threads).

use std::fmt;
use std::str::FromStr;

use rayon::prelude::*;
use wellspread::filter::{AnyFilter, Filter, FilterKind, LanczosFilter, TentFilter};
use wellspread::{PixelSampler, PixelSamplerKind, SamplerKind};

use crate::joint_sobol::Candidate;
use crate::scenes::{Built, Rgb, Scene, SceneKind};

/// A linear-RGB image, row-major, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<Rgb>,
}

impl Image {
    /// Root-mean-square difference over every pixel and channel, in f64.
    pub fn rmse(&self, other: &Image) -> f64 {
        self.rmse_where(other, |_| true)
    }

    /// The RMSE over the pixels whose row-major index `keep` accepts; 0
    /// where it accepts none.
    pub fn rmse_where(&self, other: &Image, keep: impl Fn(usize) -> bool) -> f64 {
        assert_eq!((self.width, self.height), (other.width, other.height));
        let (mut sum, mut count) = (0.0, 0usize);
        for (i, (a, b)) in self.pixels.iter().zip(&other.pixels).enumerate() {
            if keep(i) {
                count += 1;
                sum += (0..3)
                    .map(|c| (f64::from(a[c]) - f64::from(b[c])).powi(2))
                    .sum::<f64>();
            }
        }
        (sum / (3 * count.max(1)) as f64).sqrt()
    }
}

/// The reconstruction filter the tracer renders with under `kind`: how
/// samples are weighted into pixels (Smith 1995, "A Pixel Is Not A Little
/// Square"). Every filter is the library's ([`wellspread::filter`]),
/// separable, `w(dx, dy) = f(dx) f(dy)`, with `d` measured in pixels from
/// the pixel centre; its values and its samples both come from the
/// library. The parameters are the library's defaults
/// ([`FilterKind::build`]: pbrt-v4's; box radius 1/2, the little square;
/// Gaussian sigma 1/2 truncated at 1.5; Mitchell & Netravali's B = C = 1/3
/// at radius 2; Blackman-Harris radius 2) but for two narrower ones: the
/// tent of radius 1, linear interpolation's filter, and Lanczos-3,
/// `sinc(x) sinc(x / 3)` at radius 3.
pub fn tracer_filter(kind: FilterKind) -> AnyFilter {
    let valid = "the tracer's filter parameters are valid";
    match kind {
        FilterKind::Tent => TentFilter::new(1.0).expect(valid).into(),
        FilterKind::Lanczos => LanczosFilter::new(3.0, 3.0).expect(valid).into(),
        _ => kind.build(),
    }
}

/// Offsets from the pixel centre where [`tracer_filter`]'s 1D profile is
/// not smooth (its ends, the tent's peak, the joins of Mitchell's cubic
/// pieces) or, for the smooth windows, where its lobes meet, in
/// increasing order: the quadrature reference integrates piece by piece.
pub fn breaks(kind: FilterKind) -> &'static [f64] {
    match kind {
        FilterKind::Box => &[-0.5, 0.5],
        FilterKind::Tent => &[-1.0, 0.0, 1.0],
        FilterKind::Gaussian => &[-1.5, 1.5],
        FilterKind::Mitchell | FilterKind::BlackmanHarris => &[-2.0, -1.0, 0.0, 1.0, 2.0],
        FilterKind::Lanczos => &[-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0],
    }
}

/// Whether [`tracer_filter`]'s profile goes negative somewhere (ringing
/// at edges).
pub fn has_negative_lobes(kind: FilterKind) -> bool {
    tracer_filter(kind).weight_magnitude() > 1.0 + 1e-6
}

/// How samples become a filtered pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FilterMode {
    /// Box samples (uniform in their pixel) splatted into every pixel
    /// whose filter reaches them, weighted by the filter's value:
    /// `sum(f L) / sum(f)`.
    Weighted,
    /// Filter-importance sampling: each pixel's own samples are mapped
    /// through the library's `Filter::sample` to `centre + offset`, and
    /// the pixel is pbrt-v4's `sum(w L) / sum(w)` with `w = f / pdf`.
    Importance,
    /// The same samples, the unbiased mean instead of the ratio:
    /// `sum(w L) / (n m)`, `m` the filter's mass inside the film (1 away
    /// from the border). No division by a sum of signed weights.
    ImportanceMean,
}

impl FilterMode {
    pub const ALL: [FilterMode; 3] = [
        FilterMode::Weighted,
        FilterMode::Importance,
        FilterMode::ImportanceMean,
    ];

    pub fn name(self) -> &'static str {
        match self {
            FilterMode::Weighted => "weighted",
            FilterMode::Importance => "importance",
            FilterMode::ImportanceMean => "importance-mean",
        }
    }
}

impl fmt::Display for FilterMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for FilterMode {
    type Err = String;

    fn from_str(name: &str) -> Result<Self, Self::Err> {
        crate::shared::by_name(&FilterMode::ALL, name, FilterMode::name, "filter mode")
    }
}

/// How a path's film offset and lens point are drawn from its root domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FilmLens {
    /// One `next_4d`: film `xy`, lens `zw`.
    Joint,
    /// Two `next_2d`: the film, then the lens.
    Pairs,
}

/// A sampler as the command line names it: one of the library's pixel
/// samplers ([`PixelSamplerKind::all`], so a new one appears here by
/// itself), `sobol-pairs`, the control of the path-traced scene's
/// 4D-versus-pairs comparison, or `pcg32`, the baseline that is not the
/// crate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TracerSampler {
    /// `kind.build(spp, [width, height], frame)`. In the path-traced scene
    /// its film offset and lens point are one `next_4d` draw.
    Pixel(PixelSamplerKind),
    /// `sobol` with the path-traced scene's film offset and lens point
    /// drawn as two `next_2d` pairs. The 2D scenes draw no lens, where it
    /// would be `sobol` again, so it renders only the path-traced one.
    SobolPairs,
    /// Not the crate: what a renderer's own random-number path does, one
    /// `rand_pcg::Pcg32` per pixel sample and frame, seeded by hashing
    /// them, every number of the path drawn from it in call order
    /// (`path::Pcg32Source`). The yardstick of the ratio table; the
    /// path-traced scene only (the 2D scenes take their film positions
    /// from a [`PixelSampler`]).
    Pcg32,
    /// A candidate of the progressive joint-stratification study
    /// (`docs/joint_study.md`, `shared/joint_sobol.rs`): successive
    /// dimensions of one Owen-scrambled digital sequence, a new copy
    /// every few. Not the crate; the path-traced scene only.
    Joint(Candidate),
}

/// `sobol`, the pixel sampler both sides of the 4D-versus-pairs rows use.
pub const SOBOL: TracerSampler = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Sobol));

impl TracerSampler {
    /// Every sampler, in the order tables list them.
    pub fn all() -> Vec<TracerSampler> {
        PixelSamplerKind::all()
            .map(TracerSampler::Pixel)
            .chain([TracerSampler::SobolPairs, TracerSampler::Pcg32])
            .collect()
    }

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            TracerSampler::Pixel(kind) => kind.name(),
            TracerSampler::SobolPairs => "sobol-pairs",
            TracerSampler::Pcg32 => "pcg32",
            TracerSampler::Joint(candidate) => candidate.name(),
        }
    }

    /// The study's candidates: rendered only when asked for by name.
    pub fn study() -> [TracerSampler; 2] {
        Candidate::ALL.map(TracerSampler::Joint)
    }

    /// How the path-traced scene draws its film offset and lens point
    /// (`pcg32` draws four numbers in a row either way).
    pub fn film_lens(self) -> FilmLens {
        match self {
            TracerSampler::Pixel(_) | TracerSampler::Pcg32 | TracerSampler::Joint(_) => {
                FilmLens::Joint
            }
            TracerSampler::SobolPairs => FilmLens::Pairs,
        }
    }

    /// Whether `scene` renders with this sampler: the library's samplers
    /// every scene; `sobol-pairs`, which differs from `sobol` only in the
    /// lens, and `pcg32`, which is no pixel sampler, the path-traced one.
    pub fn renders(self, scene: SceneKind) -> bool {
        match self {
            TracerSampler::Pixel(_) => true,
            TracerSampler::SobolPairs => scene.has_lens(),
            TracerSampler::Pcg32 | TracerSampler::Joint(_) => {
                matches!(scene.build(1, 1), Built::PathTraced)
            }
        }
    }

    /// The library pixel sampler this one builds; `None` for `pcg32` and
    /// the study's candidates.
    pub fn pixel_kind(self) -> Option<PixelSamplerKind> {
        match self {
            TracerSampler::Pixel(kind) => Some(kind),
            TracerSampler::SobolPairs => Some(PixelSamplerKind::Padded(SamplerKind::Sobol)),
            TracerSampler::Pcg32 | TracerSampler::Joint(_) => None,
        }
    }

    /// The library pixel sampler of [`FrameSampler::new`](crate::path::FrameSampler::new), for the tests
    /// that render a library sampler only. Panics for `pcg32`.
    #[cfg(test)]
    pub fn build(
        self,
        spp: u32,
        width: u32,
        height: u32,
        frame: u32,
    ) -> Result<wellspread::AnyPixelSampler, wellspread::Error> {
        let kind = self.pixel_kind().expect("pcg32 builds no library sampler");
        kind.build(spp, [width, height], frame)
    }
}

impl fmt::Display for TracerSampler {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for TracerSampler {
    type Err = String;

    /// A name from [`TracerSampler::all`], or any name or alias the
    /// library's [`PixelSamplerKind`] parses (any case, `cmj`, ...).
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        if let Some(candidate) = Candidate::from_name(name) {
            return Ok(TracerSampler::Joint(candidate));
        }
        for lab in [TracerSampler::SobolPairs, TracerSampler::Pcg32] {
            if name == lab.name() {
                return Ok(lab);
            }
        }
        name.parse::<PixelSamplerKind>()
            .map(TracerSampler::Pixel)
            .map_err(|_| {
                let names: Vec<&str> = TracerSampler::all()
                    .iter()
                    .chain(&TracerSampler::study())
                    .map(|s| s.name())
                    .collect();
                format!(
                    "unknown sampler {name:?}; expected one of: {} (any case; aliases such as cmj)",
                    names.join(" ")
                )
            })
    }
}

/// Samples per pixel of a frame: the tracer builds every sampler with a
/// count, so none is progressive.
fn spp<P: PixelSampler>(sampler: &P) -> u32 {
    sampler
        .samples_per_pixel()
        .expect("the tracer builds every sampler with a sample count")
}

/// The dimension pair images use for the film position. Monte Carlo
/// references use [`REFERENCE_DIMENSION`], a pair no compared image uses,
/// so a reference is never correlated with what it measures.
pub const FILM_DIMENSION: u32 = 0;
/// See [`FILM_DIMENSION`].
pub const REFERENCE_DIMENSION: u32 = 1;

/// Renders `scene` on its `width x height` film: pixel `(px, py)` takes
/// samples `0..samples_per_pixel()` of dimension pair `dimension` of
/// `sampler`, and `filter` turns them into pixel values: as offsets
/// inside the pixel weighted by the filter, or mapped through the
/// filter's sampling (`mode`).
///
/// Runs on the current rayon pool (`ThreadPool::install` picks another).
pub fn render<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
    filter: FilterKind,
    mode: FilterMode,
) -> Image {
    let pixels = match (filter, mode) {
        (_, FilterMode::Importance | FilterMode::ImportanceMean) => {
            let filter = &tracer_filter(filter);
            render_importance(scene, width, height, sampler, dimension, filter, mode)
        }
        (FilterKind::Box, FilterMode::Weighted) => {
            render_box(scene, width, height, sampler, dimension)
        }
        (_, FilterMode::Weighted) => render_filtered(
            scene,
            width,
            height,
            sampler,
            dimension,
            &tracer_filter(filter),
        ),
    };
    Image {
        width,
        height,
        pixels,
    }
}

/// The samples of pixel `(px, py)`, one at a time: each one's film
/// position (in pixels) and the radiance the scene sends there. The
/// library's O(1) random access means no per-pixel buffer.
#[inline]
fn pixel_samples<'a, P: PixelSampler>(
    scene: &'a Scene,
    sampler: &'a P,
    dimension: u32,
    px: u32,
    py: u32,
) -> impl Iterator<Item = (f64, f64, Rgb)> + 'a {
    (0..spp(sampler)).map(move |index| {
        let offset = sampler.sample_pixel([px, py], index, dimension);
        let x = f64::from(px) + f64::from(offset.x);
        let y = f64::from(py) + f64::from(offset.y);
        (x, y, scene.radiance(x, y))
    })
}

/// Box filter: every pixel is the plain mean of its own samples, so rows
/// are independent and each is one rayon task.
fn render_box<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
) -> Vec<Rgb> {
    let mut pixels = vec![[0.0; 3]; width as usize * height as usize];
    pixels
        .par_chunks_mut(width as usize)
        .enumerate()
        .for_each(|(py, row)| {
            for (pixel, px) in row.iter_mut().zip(0..width) {
                *pixel = box_pixel(scene, sampler, dimension, px, py as u32);
            }
        });
    pixels
}

/// One box-filtered pixel: the mean radiance of its samples, summed in f64.
pub fn box_pixel<P: PixelSampler>(
    scene: &Scene,
    sampler: &P,
    dimension: u32,
    px: u32,
    py: u32,
) -> Rgb {
    let mut sum = [0.0f64; 3];
    for (_, _, radiance) in pixel_samples(scene, sampler, dimension, px, py) {
        for c in 0..3 {
            sum[c] += f64::from(radiance[c]);
        }
    }
    let inverse_count = 1.0 / f64::from(spp(sampler));
    sum.map(|s| (s * inverse_count) as f32)
}

/// Filter-importance sampling: pixel `(px, py)`'s sample `u` goes to
/// `centre + offset` for the library's `filter.sample(u)`, with weight
/// `w = f / pdf` (1 for box, tent and Gaussian; `+-c` for the filters with
/// negative lobes). The pixel is `sum(w L) / sum(w)`, the estimator
/// pbrt-v4's `RGBFilm` uses (`AddSample` accumulates `w L` and `w`,
/// `GetPixelRGB` divides). Samples that land off the film are dropped, so
/// border pixels normalise over the film like the weighted mode and the
/// references do. Each pixel reads only its own samples: rows are
/// independent rayon tasks. [`FilterMode::ImportanceMean`] divides by
/// `n` times the filter's mass on the film instead.
fn render_importance<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
    filter: &AnyFilter,
    mode: FilterMode,
) -> Vec<Rgb> {
    let mut pixels = vec![[0.0; 3]; width as usize * height as usize];
    pixels
        .par_chunks_mut(width as usize)
        .enumerate()
        .for_each(|(py, row)| {
            for (pixel, px) in row.iter_mut().zip(0..width) {
                let estimate = match mode {
                    FilterMode::ImportanceMean => importance_mean_pixel,
                    _ => importance_pixel,
                };
                *pixel = estimate(
                    scene, width, height, sampler, dimension, filter, px, py as u32,
                );
            }
        });
    pixels
}

/// The sums both importance-sampled estimators share, in f64: `sum(w L)`
/// per channel and `sum(w)`, over the pixel's samples placed at the
/// pixel centre plus the filter's offset; samples off the film add
/// nothing.
#[allow(clippy::too_many_arguments)]
fn importance_sums<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
    filter: &AnyFilter,
    px: u32,
    py: u32,
) -> [f64; 4] {
    let mut sum = [0.0f64; 4];
    for index in 0..spp(sampler) {
        let u = sampler.sample_pixel([px, py], index, dimension);
        let s = filter.sample(u);
        let x = f64::from(px) + 0.5 + f64::from(s.offset.x);
        let y = f64::from(py) + 0.5 + f64::from(s.offset.y);
        if !(0.0..f64::from(width)).contains(&x) || !(0.0..f64::from(height)).contains(&y) {
            continue;
        }
        let w = f64::from(s.weight);
        let radiance = scene.radiance(x, y);
        for c in 0..3 {
            sum[c] += w * f64::from(radiance[c]);
        }
        sum[3] += w;
    }
    sum
}

/// One pixel of [`render_importance`]: `sum(w L) / sum(w)`, black when no
/// weight is left (every sample off the film, or negative lobes
/// cancelling at very low counts).
#[allow(clippy::too_many_arguments)]
pub fn importance_pixel<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
    filter: &AnyFilter,
    px: u32,
    py: u32,
) -> Rgb {
    let sum = importance_sums(scene, width, height, sampler, dimension, filter, px, py);
    if sum[3].abs() > 1e-12 {
        [sum[0], sum[1], sum[2]].map(|s| (s / sum[3]) as f32)
    } else {
        [0.0; 3]
    }
}

/// One pixel of [`FilterMode::ImportanceMean`]: `sum(w L) / (n m)`, with
/// `m` the mass of the (normalised) filter inside the film, `m_x m_y`,
/// each the 1D profile's integral over the part of the support on the
/// film (8-point Gauss-Legendre per piece between the breaks). Off-film
/// samples add nothing, and `E[w 1(on film)] = m`, so the estimate is
/// unbiased for the clipped, renormalised filter the references use.
#[allow(clippy::too_many_arguments)]
pub fn importance_mean_pixel<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
    filter: &AnyFilter,
    px: u32,
    py: u32,
) -> Rgb {
    let sum = importance_sums(scene, width, height, sampler, dimension, filter, px, py);
    let mass = film_mass(filter, f64::from(px) + 0.5, f64::from(width))
        * film_mass(filter, f64::from(py) + 0.5, f64::from(height));
    let scale = 1.0 / (f64::from(spp(sampler)) * mass);
    [sum[0], sum[1], sum[2]].map(|s| (s * scale) as f32)
}

/// Nodes and weights of `N`-point Gauss-Legendre quadrature on `[-1, 1]`,
/// by Newton's method on the Legendre polynomial (three-term recurrence)
/// from the Chebyshev-like first guess `cos(pi (i + 3/4) / (N + 1/2))`.
pub fn gauss_legendre<const N: usize>() -> ([f64; N], [f64; N]) {
    let mut nodes = [0.0; N];
    let mut weights = [0.0; N];
    let n = N as f64;
    for i in 0..N {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n + 0.5)).cos();
        let mut derivative = 0.0;
        for _ in 0..100 {
            // P_N(x) and P_{N-1}(x) by (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}.
            let (mut p, mut p_previous) = (1.0, 0.0);
            for k in 0..N {
                let k = k as f64;
                let next = ((2.0 * k + 1.0) * x * p - k * p_previous) / (k + 1.0);
                p_previous = p;
                p = next;
            }
            derivative = n * (x * p - p_previous) / (x * x - 1.0);
            let step = p / derivative;
            x -= step;
            if step.abs() < 1e-15 {
                break;
            }
        }
        nodes[i] = x;
        weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    (nodes, weights)
}

/// The integral of `filter`'s normalised 1D profile centred at `centre`
/// over `[0, limit]`: 1 when the support is inside.
fn film_mass(filter: &AnyFilter, centre: f64, limit: f64) -> f64 {
    let r = f64::from(filter.radius());
    if centre - r >= 0.0 && centre + r <= limit {
        return 1.0;
    }
    let (nodes, weights) = gauss_legendre::<8>();
    breaks(filter.kind())
        .windows(2)
        .map(|pair| ((centre + pair[0]).max(0.0), (centre + pair[1]).min(limit)))
        .filter(|(a, b)| b > a)
        .map(|(a, b)| {
            let half = 0.5 * (b - a);
            nodes
                .iter()
                .zip(&weights)
                .map(|(t, w)| w * half * filter.evaluate_1d(a + (t + 1.0) * half - centre))
                .sum::<f64>()
        })
        .sum()
}

/// Output rows per rayon task for the wide filters. Each band also shades
/// the `margin` rows above and below it that its filter reaches, so taller
/// bands waste less; 16 rows still give 16 tasks at 256 pixels high.
const BAND_ROWS: u32 = 16;

/// Wide filters: a pixel is `sum(w L) / sum(w)` over every sample within
/// the filter radius of its centre, from any pixel. The film is cut into
/// horizontal bands; a band shades the sample rows its pixels can see
/// (its own and `margin` more on each side) and splats each sample into
/// the band's pixels in a fixed order. Rows near a band edge are shaded
/// twice, by both bands, which is the price of bands never sharing
/// writable state.
fn render_filtered<P: PixelSampler>(
    scene: &Scene,
    width: u32,
    height: u32,
    sampler: &P,
    dimension: u32,
    filter: &AnyFilter,
) -> Vec<Rgb> {
    let radius = f64::from(filter.radius());
    // A sample at y in [sy, sy + 1) reaches pixel rows whose centre
    // py + 1/2 is within `radius`, which is at most `margin` rows away.
    let margin = (radius - 0.5).ceil() as i64;
    let mut pixels = vec![[0.0; 3]; width as usize * height as usize];
    pixels
        .par_chunks_mut((BAND_ROWS * width) as usize)
        .enumerate()
        .for_each(|(band_index, band)| {
            let band_rows = (band.len() / width as usize) as i64;
            let band_y0 = band_index as i64 * i64::from(BAND_ROWS);
            // Running sums of w * L (three channels) and of w, per pixel.
            let mut sums = vec![[0.0f64; 4]; band.len()];
            let first_row = (band_y0 - margin).max(0);
            let last_row = (band_y0 + band_rows - 1 + margin).min(i64::from(height) - 1);
            for sy in first_row..=last_row {
                for sx in 0..width {
                    for (x, y, radiance) in pixel_samples(scene, sampler, dimension, sx, sy as u32)
                    {
                        let radiance = radiance.map(f64::from);
                        // Pixels whose centre (p + 1/2) is within the radius.
                        let x_lo = ((x - 0.5 - radius).floor() as i64 + 1).max(0);
                        let x_hi = ((x - 0.5 + radius).ceil() as i64 - 1).min(i64::from(width) - 1);
                        let y_lo = ((y - 0.5 - radius).floor() as i64 + 1).max(band_y0);
                        let y_hi =
                            ((y - 0.5 + radius).ceil() as i64 - 1).min(band_y0 + band_rows - 1);
                        for py in y_lo..=y_hi {
                            let wy = filter.evaluate_1d(y - (py as f64 + 0.5));
                            if wy == 0.0 {
                                continue;
                            }
                            let row = ((py - band_y0) * i64::from(width)) as usize;
                            for px in x_lo..=x_hi {
                                let w = wy * filter.evaluate_1d(x - (px as f64 + 0.5));
                                let sum = &mut sums[row + px as usize];
                                sum[0] += w * radiance[0];
                                sum[1] += w * radiance[1];
                                sum[2] += w * radiance[2];
                                sum[3] += w;
                            }
                        }
                    }
                }
            }
            for (pixel, sum) in band.iter_mut().zip(&sums) {
                // Mitchell's negative lobes can, at very low counts, leave a
                // pixel with no net weight; black is the honest answer.
                *pixel = if sum[3].abs() > 1e-12 {
                    [sum[0], sum[1], sum[2]].map(|s| (s / sum[3]) as f32)
                } else {
                    [0.0; 3]
                };
            }
        });
    pixels
}

/// Rayon pools of one and two threads, for the tests that render a frame
/// on each and compare the bits.
#[cfg(test)]
pub(crate) fn one_and_two_threads() -> (rayon::ThreadPool, rayon::ThreadPool) {
    let pool = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
    };
    (pool(1), pool(2))
}

/// Every channel of `pixels` as f32 bits, for bit-for-bit comparisons.
#[cfg(test)]
pub(crate) fn pixel_bits(pixels: &[Rgb]) -> Vec<u32> {
    pixels.iter().flatten().map(|v| v.to_bits()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenes::SceneKind;

    #[test]
    fn gauss_legendre_integrates_degree_fifteen_exactly() {
        let (nodes, weights) = gauss_legendre::<8>();
        // The integral of x^14 over [-1, 1] is 2/15; odd powers vanish.
        let even: f64 = nodes
            .iter()
            .zip(&weights)
            .map(|(x, w)| w * x.powi(14))
            .sum();
        let odd: f64 = nodes
            .iter()
            .zip(&weights)
            .map(|(x, w)| w * x.powi(15))
            .sum();
        assert!((even - 2.0 / 15.0).abs() < 1e-13, "{even}");
        assert!(odd.abs() < 1e-13, "{odd}");
    }

    #[test]
    fn images_are_bit_identical_for_one_and_two_threads() {
        let (one, two) = crate::render::one_and_two_threads();
        // 40 rows make three bands, so the wide filters' band seams are
        // exercised too.
        let (width, height) = (24, 40);
        // The path-traced scene has its own test, in path.rs.
        for scene_kind in SceneKind::ALL {
            let Some(scene) = scene_kind.film(width, height) else {
                continue;
            };
            for &filter in FilterKind::ALL {
                for mode in FilterMode::ALL {
                    for kind in [
                        TracerSampler::Pixel(PixelSamplerKind::Padded(
                            SamplerKind::CorrelatedMultiJittered,
                        )),
                        TracerSampler::Pixel(PixelSamplerKind::ZSobol),
                    ] {
                        let sampler = kind.build(16, width, height, 7).unwrap();
                        let draw = || render(&scene, width, height, &sampler, 0, filter, mode);
                        let (a, b) = (one.install(draw), two.install(draw));
                        assert_eq!(
                            pixel_bits(&a.pixels),
                            pixel_bits(&b.pixels),
                            "{scene_kind} {filter} {mode} {kind}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn filters_are_normalised_and_vanish_at_their_radius() {
        for &kind in FilterKind::ALL {
            let filter = tracer_filter(kind);
            let r = f64::from(filter.radius());
            assert_eq!(filter.evaluate_1d(r * (1.0 + 1e-9)), 0.0, "{kind}");
            assert_eq!(filter.evaluate_1d(-r * (1.0 + 1e-9)), 0.0, "{kind}");
            // Midpoint rule over the support, piece by piece between the
            // breaks: the library's profiles integrate to 1.
            let n = 100_000;
            let integral: f64 = breaks(kind)
                .windows(2)
                .map(|pair| {
                    let h = (pair[1] - pair[0]) / f64::from(n);
                    (0..n)
                        .map(|i| filter.evaluate_1d(pair[0] + (f64::from(i) + 0.5) * h) * h)
                        .sum::<f64>()
                })
                .sum();
            assert!((integral - 1.0).abs() < 1e-6, "{kind}: {integral}");
            assert_eq!((breaks(kind)[0], breaks(kind).last()), (-r, Some(&r)));
        }
        // Ringing needs negative lobes: Mitchell and Lanczos have them.
        let ringing: Vec<FilterKind> = FilterKind::ALL
            .iter()
            .copied()
            .filter(|&kind| has_negative_lobes(kind))
            .collect();
        assert_eq!(ringing, [FilterKind::Mitchell, FilterKind::Lanczos]);
    }

    #[test]
    fn box_render_of_a_constant_region_is_exact() {
        // Inside the 64 x 64 polygon, every sample sees yellow.
        let scene = SceneKind::Polygon.film(64, 64).unwrap();
        let sampler = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Random))
            .build(4, 64, 64, 0)
            .unwrap();
        let image = render(
            &scene,
            64,
            64,
            &sampler,
            FILM_DIMENSION,
            FilterKind::Box,
            FilterMode::Weighted,
        );
        assert_eq!(image.pixels[32 * 64 + 20], crate::scenes::Polygon::YELLOW);
    }

    #[test]
    fn importance_sampled_render_of_a_constant_region_is_exact() {
        // Pixel (20, 32) of the 64 x 64 polygon is more than 3 pixels (the
        // widest radius, Lanczos) from every edge: every sample sees
        // yellow, and sum(w L) / sum(w) returns it for any weights, the
        // negative ones of Mitchell and Lanczos included.
        let scene = SceneKind::Polygon.film(64, 64).unwrap();
        for kind in [
            PixelSamplerKind::Padded(SamplerKind::Random),
            PixelSamplerKind::Padded(SamplerKind::Sobol),
            PixelSamplerKind::ZSobol,
        ] {
            let sampler = TracerSampler::Pixel(kind).build(16, 64, 64, 3).unwrap();
            for &filter in FilterKind::ALL {
                let library = &tracer_filter(filter);
                let pixel =
                    importance_pixel(&scene, 64, 64, &sampler, FILM_DIMENSION, library, 20, 32);
                assert_eq!(pixel, crate::scenes::Polygon::YELLOW, "{filter} {kind}");
            }
        }
    }

    #[test]
    fn importance_mean_is_exact_where_weights_are_one_and_unbiased_elsewhere() {
        // Box, tent and Gaussian have weight exactly 1: sum(L) / n is
        // exact on a constant region. Mitchell and Lanczos carry signed
        // weights, so the mean fluctuates about the value, and over many
        // frames it averages to it.
        let scene = SceneKind::Polygon.film(64, 64).unwrap();
        let yellow = crate::scenes::Polygon::YELLOW;
        let kind = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Random));
        for filter in [FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian] {
            let sampler = kind.build(16, 64, 64, 3).unwrap();
            let library = &tracer_filter(filter);
            let pixel =
                importance_mean_pixel(&scene, 64, 64, &sampler, FILM_DIMENSION, library, 20, 32);
            assert_eq!(pixel, yellow, "{filter}");
        }
        for filter in [FilterKind::Mitchell, FilterKind::Lanczos] {
            let library = &tracer_filter(filter);
            let frames = 400;
            let mean: f64 = (0..frames)
                .map(|frame| {
                    let sampler = kind.build(16, 64, 64, frame).unwrap();
                    let pixel = importance_mean_pixel(
                        &scene,
                        64,
                        64,
                        &sampler,
                        FILM_DIMENSION,
                        library,
                        20,
                        32,
                    );
                    f64::from(pixel[0])
                })
                .sum::<f64>()
                / f64::from(frames);
            // 6400 samples of weight +-c (c < 1.4): a standard error
            // under 0.02; 0.1 is five of them.
            assert!(
                (mean - f64::from(yellow[0])).abs() < 0.1,
                "{filter}: {mean}"
            );
        }
        // The clipped mass: half a tent at the film's edge, all inside.
        let (tent, lanczos) = (FilterKind::Tent, FilterKind::Lanczos);
        assert!((film_mass(&tracer_filter(tent), 0.0, 64.0) - 0.5).abs() < 1e-12);
        assert_eq!(film_mass(&tracer_filter(lanczos), 32.0, 64.0), 1.0);
    }

    #[test]
    fn importance_sampling_places_samples_by_the_library_filter() {
        // A one-sample pixel at the film's centre: the pixel is the
        // radiance at centre + the library's offset for the sampler's u.
        let scene = SceneKind::Polygon.film(64, 64).unwrap();
        let sampler = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Random))
            .build(1, 64, 64, 0)
            .unwrap();
        for &filter in FilterKind::ALL {
            let library = &tracer_filter(filter);
            for (px, py) in [(7, 11), (40, 30), (60, 5)] {
                let u = sampler.sample_pixel([px, py], 0, FILM_DIMENSION);
                let s = library.sample(u);
                let x = f64::from(px) + 0.5 + f64::from(s.offset.x);
                let y = f64::from(py) + 0.5 + f64::from(s.offset.y);
                let pixel =
                    importance_pixel(&scene, 64, 64, &sampler, FILM_DIMENSION, library, px, py);
                assert_eq!(pixel, scene.radiance(x, y), "{filter} ({px}, {py})");
            }
        }
    }

    #[test]
    fn importance_sampled_box_matches_the_box_render() {
        // The box filter's map is `u - 1/2` about the centre: the same
        // film positions as the plain box render, up to f32 rounding of
        // the offset, so the images agree to a tiny fraction.
        let scene = SceneKind::Moire.film(32, 32).unwrap();
        let sampler = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Sobol))
            .build(16, 32, 32, 1)
            .unwrap();
        let plain = render(
            &scene,
            32,
            32,
            &sampler,
            0,
            FilterKind::Box,
            FilterMode::Weighted,
        );
        let sampled = render(
            &scene,
            32,
            32,
            &sampler,
            0,
            FilterKind::Box,
            FilterMode::Importance,
        );
        assert!(plain.rmse(&sampled) < 1e-3, "{}", plain.rmse(&sampled));
    }
}

#[cfg(test)]
mod sampler_tests {
    use super::*;

    #[test]
    fn names_round_trip_and_bad_names_are_named() {
        let all = TracerSampler::all();
        for kind in &all {
            assert_eq!(kind.name().parse::<TracerSampler>(), Ok(*kind));
        }
        // Every pixel sampler of the library, each once, then sobol-pairs
        // and pcg32.
        let pixel: Vec<TracerSampler> = PixelSamplerKind::all().map(TracerSampler::Pixel).collect();
        assert_eq!(all[..pixel.len()], pixel[..]);
        assert_eq!(
            all[pixel.len()..],
            [TracerSampler::SobolPairs, TracerSampler::Pcg32]
        );
        // The library's aliases and case.
        assert_eq!(
            "CMJ".parse(),
            Ok(TracerSampler::Pixel(PixelSamplerKind::Padded(
                SamplerKind::CorrelatedMultiJittered
            )))
        );
        let message = "jitterd".parse::<TracerSampler>().unwrap_err();
        assert!(message.contains("\"jitterd\""), "{message}");
        let names: Vec<&str> = all.iter().map(|s| s.name()).collect();
        assert!(message.contains(&names.join(" ")), "{message}");
    }

    #[test]
    fn sobol_pairs_renders_only_where_there_is_a_lens() {
        for scene in SceneKind::ALL {
            assert_eq!(TracerSampler::SobolPairs.renders(scene), scene.has_lens());
            assert_eq!(
                TracerSampler::Pcg32.renders(scene),
                scene == SceneKind::Cornell
            );
            assert!(SOBOL.renders(scene));
            for study in TracerSampler::study() {
                assert_eq!(study.renders(scene), scene == SceneKind::Cornell);
            }
        }
        // The study's candidates parse by name, are no library kind, and
        // stay out of the default list.
        for study in TracerSampler::study() {
            assert_eq!(study.name().parse::<TracerSampler>(), Ok(study));
            assert_eq!(study.pixel_kind(), None);
            assert!(!TracerSampler::all().contains(&study));
        }
        assert_eq!(TracerSampler::SobolPairs.film_lens(), FilmLens::Pairs);
        assert_eq!(SOBOL.film_lens(), FilmLens::Joint);
        // Both build the same pixel sampler.
        assert_eq!(
            TracerSampler::SobolPairs.build(16, 4, 4, 2),
            SOBOL.build(16, 4, 4, 2)
        );
    }

    #[test]
    fn padded_kinds_use_the_library_adapter() {
        let sampler = SOBOL.build(4, 8, 8, 3).unwrap();
        let expected = wellspread::Padded::new(SamplerKind::Sobol.build(4).unwrap(), 3);
        assert_eq!(
            sampler.sample_pixel([2, 5], 1, 0),
            expected.sample_pixel([2, 5], 1, 0)
        );
    }
}
