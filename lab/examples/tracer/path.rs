//! The path-traced scene fed by the library's [`Domain`]: the tracer's
//! side of `cornell/` (the scene and its path loop).
//!
//! Every pixel sample starts one domain (`PixelSampler::start`), the path
//! draws its film offset and lens point from it, and each bounce draws from
//! `root.branch(BOUNCE).branch(b)`, one branch per purpose, or, with
//! `--draws call-order`, from the root in call order (the layout is in
//! `cornell/mod.rs`). Film and
//! lens are one `next_4d` draw ([`FilmLens::Joint`]: for the sequences one
//! point of a 4D Owen-scrambled Sobol' set, so depth of field keeps the
//! coupled stratification) or two `next_2d` draws ([`FilmLens::Pairs`],
//! the control that `sobol-pairs` renders).
//!
//! The reference renders [`REFERENCE_SPP`] samples of `sobol` per pixel,
//! every root moved to the branch [`REFERENCE_KEY`], so it shares no pattern
//! with a compared frame, whatever its frame number, and samples the light
//! by area ([`REFERENCE_LIGHT`]) whichever `--light` the frames use, with
//! keyed draws, at the frames' `--max-depth`. It is
//! cached under `out/` in a file named after a fingerprint of the scene and
//! of the path tracer as the reference runs it, so a change to either
//! recomputes it.
//!
//! The baseline `pcg32` is not the crate: [`Pcg32Source`] starts one
//! `rand_pcg::Pcg32` per pixel sample and frame, and the same path code
//! draws every number from it in call order. [`render`] picks the source
//! once per frame ([`FrameSampler`]); `render_cornell` is generic over it,
//! so neither side pays for the other in its draws, and a library sampler's
//! frame runs through [`AnyPixelSampler::visit`], compiled for the concrete
//! sampler, as a renderer that picks its sampler at run time would: its
//! draws cost what the concrete type's do, not the enum's dispatch per
//! draw (`lab/frame_cost.sh` counts a frame's instructions).

use rand::{Rng as _, SeedableRng as _};
use rand_pcg::Pcg32;
use wellspread::glam::{Vec2, Vec4};
use wellspread::{
    AnyPixelSampler, Domain, PixelSampler, PixelSamplerKind, PixelSamplerVisitor, SamplerKind,
};

use crate::cornell::{Light, PathSamples, SampleSource, Tracing, render_cornell};
use crate::joint_sobol::JointSobol;
use crate::render::{FilmLens, Image, TracerSampler};
use crate::scenes::Rgb;

/// A [`SampleSource`] over a pixel sampler's domains.
#[derive(Clone, Copy, Debug)]
pub struct Domains<P> {
    pub sampler: P,
    pub film_lens: FilmLens,
    /// `Some(key)`: every sample's root is `start(pixel, index).branch(key)`
    /// rather than the start domain itself.
    pub root_branch: Option<u32>,
}

impl<P> Domains<P> {
    /// A frame's source: every sample's root is its start domain.
    pub fn frame(sampler: P, film_lens: FilmLens) -> Self {
        Self {
            sampler,
            film_lens,
            root_branch: None,
        }
    }
}

/// One path's samples: a domain and how its film and lens are drawn.
#[derive(Clone, Copy, Debug)]
pub struct DomainSamples<P> {
    domain: Domain<P>,
    film_lens: FilmLens,
}

impl<P: PixelSampler + Copy> SampleSource for Domains<P> {
    type Samples = DomainSamples<P>;

    #[inline]
    fn start(&self, pixel: [u32; 2], index: u32) -> DomainSamples<P> {
        let start = Domain::start(self.sampler, pixel, index);
        DomainSamples {
            domain: self.root_branch.map_or(start, |key| start.branch(key)),
            film_lens: self.film_lens,
        }
    }
}

impl<P: PixelSampler + Copy> PathSamples for DomainSamples<P> {
    #[inline]
    fn next_1d(&mut self) -> f32 {
        self.domain.next_1d()
    }

    #[inline]
    fn next_2d(&mut self) -> wellspread::glam::Vec2 {
        self.domain.next_2d()
    }

    #[inline]
    fn film_lens(&mut self) -> Vec4 {
        match self.film_lens {
            FilmLens::Joint => self.domain.next_4d(),
            FilmLens::Pairs => {
                let film = self.domain.next_2d();
                let lens = self.domain.next_2d();
                Vec4::new(film.x, film.y, lens.x, lens.y)
            }
        }
    }

    #[inline]
    fn branch(&self, key: u32) -> Self {
        Self {
            domain: self.domain.branch(key),
            film_lens: self.film_lens,
        }
    }
}

/// What one frame of the path-traced scene draws from: a library pixel
/// sampler, through its [`Domain`]s, or the `pcg32` baseline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrameSampler {
    Pixel(AnyPixelSampler),
    Pcg32(Pcg32Source),
    JointSobol(JointSobol),
}

impl FrameSampler {
    /// What frame `frame` of `sampler` renders with at `spp` samples per
    /// pixel on a `width x height` film: the library pixel sampler, or
    /// `pcg32`'s generators for that frame (any count).
    pub fn new(
        sampler: TracerSampler,
        spp: u32,
        (width, height): (u32, u32),
        frame: u32,
    ) -> Result<Self, wellspread::Error> {
        if let TracerSampler::Joint(candidate) = sampler {
            return Ok(FrameSampler::JointSobol(JointSobol::candidate(
                candidate, frame,
            )));
        }
        match sampler.pixel_kind() {
            Some(kind) => kind
                .build(spp, [width, height], frame)
                .map(FrameSampler::Pixel),
            None => Ok(FrameSampler::Pcg32(Pcg32Source { frame })),
        }
    }
}

/// The baseline that is not the crate, as a renderer's own random-number
/// path does it: sample `index` of `pixel` in frame `frame` gets a fresh
/// `rand_pcg::Pcg32` seeded by hashing the three ([`Pcg32Source::seed`]),
/// and the path draws every number from it in call order (film, lens, then
/// per bounce light choice, light sample, BSDF, roulette).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pcg32Source {
    pub frame: u32,
}

impl Pcg32Source {
    /// The `seed_from_u64` seed of sample `index` of `pixel`: the pixel,
    /// then the index and frame, as two 64-bit words folded through
    /// SplitMix64's finaliser (a bijection, so nearby samples get
    /// unrelated seeds).
    pub fn seed(&self, [x, y]: [u32; 2], index: u32) -> u64 {
        let mix = |mut z: u64| {
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        let pixel = (u64::from(x) << 32) | u64::from(y);
        let sample = (u64::from(index) << 32) | u64::from(self.frame);
        mix(mix(pixel) ^ sample)
    }
}

impl SampleSource for Pcg32Source {
    type Samples = Pcg32Samples;

    #[inline]
    fn start(&self, pixel: [u32; 2], index: u32) -> Pcg32Samples {
        Pcg32Samples(Pcg32::seed_from_u64(self.seed(pixel, index)))
    }
}

/// One path's generator: every draw advances it, a branch is the stream
/// where it is and hands it back through `rejoin`, so the path's numbers
/// are the generator's in call order.
#[derive(Clone, Debug)]
pub struct Pcg32Samples(Pcg32);

impl PathSamples for Pcg32Samples {
    #[inline]
    fn next_1d(&mut self) -> f32 {
        self.0.random()
    }

    #[inline]
    fn next_2d(&mut self) -> Vec2 {
        let x = self.0.random();
        Vec2::new(x, self.0.random())
    }

    #[inline]
    fn film_lens(&mut self) -> Vec4 {
        let film = self.next_2d();
        let lens = self.next_2d();
        Vec4::new(film.x, film.y, lens.x, lens.y)
    }

    #[inline]
    fn branch(&self, _key: u32) -> Self {
        self.clone()
    }

    #[inline]
    fn rejoin(&mut self, child: Self) {
        *self = child;
    }
}

/// One frame of the Cornell box: samples `0..spp` of every pixel of
/// `sampler`, film and lens drawn as `film_lens` says (a library
/// sampler's), paths traced as `tracing` says (light sampling, draw
/// layout, depth), box filter.
pub fn render(
    width: u32,
    height: u32,
    spp: u32,
    sampler: FrameSampler,
    film_lens: FilmLens,
    tracing: Tracing,
) -> Image {
    let frame = CornellFrame {
        width,
        height,
        spp,
        film_lens,
        tracing,
    };
    let pixels = match sampler {
        // One dispatch per frame: the frame's loop is compiled for the
        // concrete sampler, each path's domain borrows it (32 bytes).
        FrameSampler::Pixel(sampler) => sampler.visit(frame),
        FrameSampler::Pcg32(source) => render_cornell(width, height, spp, &source, tracing),
        FrameSampler::JointSobol(sampler) => frame.visit(&sampler),
    };
    Image {
        width,
        height,
        pixels,
    }
}

/// A frame of the Cornell box on a concrete pixel sampler, as
/// [`AnyPixelSampler::visit`] runs it (or [`render`] directly, for a
/// sampler that is already concrete): the draws cost what the concrete
/// type's do, with the same values as through the enum.
struct CornellFrame {
    width: u32,
    height: u32,
    spp: u32,
    film_lens: FilmLens,
    tracing: Tracing,
}

impl PixelSamplerVisitor for CornellFrame {
    type Output = Vec<Rgb>;

    fn visit<S: PixelSampler + Copy>(self, sampler: &S) -> Vec<Rgb> {
        let source = Domains::frame(sampler, self.film_lens);
        render_cornell(self.width, self.height, self.spp, &source, self.tracing)
    }
}

/// Samples per pixel of the reference: 256 times the largest default count
/// (16), as many as the other scenes' Monte Carlo references. Its own
/// error, at Monte Carlo's rate, is then a sixteenth of a 16-spp frame's,
/// so it inflates that frame's RMSE by about 0.2%.
pub const REFERENCE_SPP: u32 = 4096;

/// How the reference samples the light: by area, whatever the frames use.
/// Both estimators converge to the same image, so the reference serves
/// frames of either, and a reference made apart from the estimator a frame
/// is measured with shares none of its sampling code.
pub const REFERENCE_LIGHT: Light = Light::Area;

/// The branch every reference sample's root moves to ("Refr").
pub const REFERENCE_KEY: u32 = 0x5265_6672;

/// The sampler of the reference: `sobol`, frame 0, 4D film and lens.
fn reference_source(spp: u32, width: u32, height: u32) -> Domains<AnyPixelSampler> {
    let sampler = PixelSamplerKind::Padded(SamplerKind::Sobol)
        .build(spp, [width, height], 0)
        .expect("a power of two is a valid Sobol count");
    Domains {
        sampler,
        film_lens: FilmLens::Joint,
        root_branch: Some(REFERENCE_KEY),
    }
}

/// How the reference traces paths of at most `max_depth` bounces:
/// [`REFERENCE_LIGHT`], keyed draws.
fn reference_tracing(max_depth: u32) -> Tracing {
    Tracing {
        max_depth,
        ..Tracing::from(REFERENCE_LIGHT)
    }
}

/// The reference image at `width x height` for paths of at most
/// `max_depth` bounces: [`REFERENCE_SPP`] samples per pixel, see the
/// module docs.
pub fn reference(width: u32, height: u32, max_depth: u32) -> Image {
    let source = reference_source(REFERENCE_SPP, width, height);
    let tracing = reference_tracing(max_depth);
    Image {
        width,
        height,
        pixels: render_cornell(width, height, REFERENCE_SPP, &source, tracing),
    }
}

/// A fingerprint of the reference: [`REFERENCE_SPP`] and the bits of a
/// tiny render of the scene (8 x 8 pixels, 4 samples each, about 400 rays),
/// folded by FNV-1a. Any change to the geometry, materials, camera, layout,
/// estimator, depth (`max_depth`, as [`reference`] takes it) or reference
/// count changes it, so a cached reference keyed by it is never stale.
pub fn fingerprint(max_depth: u32) -> u32 {
    let source = reference_source(4, 8, 8);
    let image = render_cornell(8, 8, 4, &source, reference_tracing(max_depth));
    REFERENCE_SPP
        .to_le_bytes()
        .into_iter()
        .chain(
            image
                .iter()
                .flatten()
                .flat_map(|v| v.to_bits().to_le_bytes()),
        )
        .fold(0x811c_9dc5, |hash: u32, byte| {
            (hash ^ u32::from(byte)).wrapping_mul(0x0100_0193)
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cornell::{Draws, MAX_BOUNCES};
    use crate::render::{SOBOL, TracerSampler, one_and_two_threads, pixel_bits};

    /// Keyed and call-order draws give different images (but pcg32's,
    /// call order either way), each bit-identical for 1 and 2 threads.
    #[test]
    fn cornell_frames_are_bit_identical_for_one_and_two_threads() {
        let (one, two) = one_and_two_threads();
        let (width, height) = (24, 20);
        // Every sampler, pcg32 included, under both layouts, at full depth
        // and direct light only.
        for sampler in TracerSampler::all() {
            let frame = FrameSampler::new(sampler, 4, (width, height), 3).unwrap();
            for max_depth in [MAX_BOUNCES, 1] {
                let images = Draws::ALL.map(|draws| {
                    let tracing = Tracing {
                        light: Light::SolidAngle,
                        draws,
                        max_depth,
                    };
                    let draw = || render(width, height, 4, frame, sampler.film_lens(), tracing);
                    let (a, b) = (one.install(draw), two.install(draw));
                    let what = format!("{sampler} {draws} depth {max_depth}");
                    assert_eq!(pixel_bits(&a.pixels), pixel_bits(&b.pixels), "{what}");
                    a
                });
                let [keyed, call_order] = images;
                if sampler == TracerSampler::Pcg32 {
                    assert_eq!(keyed, call_order, "pcg32 depth {max_depth}");
                } else {
                    assert_ne!(keyed, call_order, "{sampler} depth {max_depth}");
                }
            }
        }
        for max_depth in [MAX_BOUNCES, 1] {
            let a = one.install(|| fingerprint(max_depth));
            assert_eq!(a, two.install(|| fingerprint(max_depth)));
        }
        // The depth-1 reference is cached under a name of its own.
        assert_ne!(fingerprint(1), fingerprint(MAX_BOUNCES));
    }

    /// `render` runs a library sampler's frame through `visit`, on the
    /// concrete type; its pixels are bit for bit those of the frame drawn
    /// through the enum's domains, for every pixel sampler and both layouts.
    #[test]
    fn a_visited_frame_is_the_frame_through_the_enum() {
        let (width, height, spp) = (12, 10, 4);
        let mut compared = 0;
        for sampler in TracerSampler::all() {
            let Ok(FrameSampler::Pixel(any)) = FrameSampler::new(sampler, spp, (width, height), 3)
            else {
                continue;
            };
            for draws in Draws::ALL {
                let tracing = Tracing {
                    light: Light::SolidAngle,
                    draws,
                    max_depth: MAX_BOUNCES,
                };
                let film_lens = sampler.film_lens();
                let visited = render(
                    width,
                    height,
                    spp,
                    FrameSampler::Pixel(any),
                    film_lens,
                    tracing,
                );
                let source = Domains::frame(&any, film_lens);
                let through_enum = render_cornell(width, height, spp, &source, tracing);
                let what = format!("{sampler} {draws}");
                assert_eq!(
                    pixel_bits(&visited.pixels),
                    pixel_bits(&through_enum),
                    "{what}"
                );
            }
            compared += 1;
        }
        // Every pixel kind, and sobol-pairs.
        assert_eq!(compared, PixelSamplerKind::all().count() + 1);
    }

    /// A pcg32 path is one generator in call order: film and lens, then
    /// each bounce's six numbers, continuing through every branch.
    #[test]
    fn pcg32_draws_every_number_of_a_path_from_one_stream_in_call_order() {
        use crate::cornell::BOUNCE;
        let source = Pcg32Source { frame: 7 };
        let mut rng = Pcg32::seed_from_u64(source.seed([3, 4], 5));
        let mut expected = |n: usize| -> Vec<f32> { (0..n).map(|_| rng.random()).collect() };
        let mut root = source.start([3, 4], 5);
        assert_eq!(root.film_lens().to_array().to_vec(), expected(4));
        let mut bounces = root.branch(BOUNCE);
        for bounce in 0..3 {
            let mut domain = bounces.branch(bounce);
            let (choice, light) = (domain.next_1d(), domain.next_2d());
            let (bsdf, roulette) = (domain.next_2d(), domain.next_1d());
            bounces.rejoin(domain);
            let drawn = [choice, light.x, light.y, bsdf.x, bsdf.y, roulette];
            assert_eq!(drawn.to_vec(), expected(6), "bounce {bounce}");
        }
    }

    #[test]
    fn pcg32_seeds_differ_for_every_pixel_sample_and_frame() {
        let mut seeds = std::collections::HashSet::new();
        for frame in 0..4 {
            let source = Pcg32Source { frame };
            for (x, y, index) in
                (0..16).flat_map(|x| (0..16).flat_map(move |y| (0..16).map(move |i| (x, y, i))))
            {
                seeds.insert(source.seed([x, y], index));
            }
        }
        assert_eq!(seeds.len(), 4 * 16 * 16 * 16);
        // A frame of pcg32 is not the next frame's.
        let frame = |frame| {
            render(
                8,
                8,
                4,
                FrameSampler::Pcg32(Pcg32Source { frame }),
                FilmLens::Joint,
                Light::SolidAngle.into(),
            )
        };
        assert_ne!(frame(0), frame(1));
    }

    #[test]
    fn joint_and_paired_film_lens_differ_only_in_the_lens_draws() {
        let sampler = SOBOL.build(16, 8, 8, 0).unwrap();
        let joint = Domains {
            sampler,
            film_lens: FilmLens::Joint,
            root_branch: None,
        };
        let pairs = Domains {
            film_lens: FilmLens::Pairs,
            ..joint
        };
        let (mut a, mut b) = (joint.start([3, 4], 5), pairs.start([3, 4], 5));
        let mut d = sampler.start([3, 4], 5);
        assert_eq!(a.film_lens(), d.next_4d());
        let mut d = sampler.start([3, 4], 5);
        let (film, lens) = (d.next_2d(), d.next_2d());
        assert_eq!(b.film_lens(), Vec4::new(film.x, film.y, lens.x, lens.y));
        // The bounces' branches do not depend on how the root drew.
        assert_eq!(a.branch(9).next_2d(), b.branch(9).next_2d());
    }

    #[test]
    fn the_reference_shares_no_domain_with_a_frame() {
        let frame = Domains {
            sampler: SOBOL.build(1024, 8, 8, 0).unwrap(),
            film_lens: FilmLens::Joint,
            root_branch: None,
        };
        let reference = reference_source(1024, 8, 8);
        for index in [0, 1, 1023] {
            let (mut f, mut r) = (frame.start([2, 2], index), reference.start([2, 2], index));
            assert_ne!(f.film_lens(), r.film_lens(), "{index}");
        }
    }

    /// The 4D draw keeps the coupled stratification: over the 16 samples
    /// of a pixel, the film offsets and lens points of `sobol` through
    /// `next_4d` put one sample in each of the 16 cells of the 2 x 2 x 2 x 2
    /// grid of [0, 1)^4; padded pairs need not.
    #[test]
    fn joint_film_lens_fills_every_four_dimensional_cell() {
        let sampler = SOBOL.build(16, 8, 8, 0).unwrap();
        let source = Domains {
            sampler,
            film_lens: FilmLens::Joint,
            root_branch: None,
        };
        for pixel in [[0, 0], [5, 3], [7, 7]] {
            let mut cells = [0u32; 16];
            for index in 0..16 {
                let v = source.start(pixel, index).film_lens().to_array();
                let cell = v.iter().fold(0, |c, &x| 2 * c + usize::from(x >= 0.5));
                cells[cell] += 1;
            }
            assert_eq!(cells, [1; 16], "{pixel:?}");
        }
    }
}
