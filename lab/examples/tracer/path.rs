//! The path-traced scene fed by the library's [`Domain`]: the tracer's
//! side of `cornell/` (the scene and its path loop).
//!
//! Every pixel sample starts one domain (`PixelSampler::start`), the path
//! draws its film offset and lens point from it, and each bounce draws from
//! `root.branch(BOUNCE).branch(b)` (the layout is in `cornell/mod.rs`). Film and
//! lens are one `next_4d` draw ([`FilmLens::Joint`]: for the sequences one
//! point of a 4D Owen-scrambled Sobol' set, so depth of field keeps the
//! coupled stratification) or two `next_2d` draws ([`FilmLens::Pairs`],
//! the control that `sobol-pairs` renders).
//!
//! The reference renders [`REFERENCE_SPP`] samples of `sobol` per pixel,
//! every root moved to the branch [`REFERENCE_KEY`], so it shares no pattern
//! with a compared frame, whatever its frame number, and samples the light
//! by area ([`REFERENCE_LIGHT`]) whichever `--light` the frames use. It is
//! cached under `out/` in a file named after a fingerprint of the scene and
//! of the path tracer as the reference runs it, so a change to either
//! recomputes it.

use wellspread::glam::Vec4;
use wellspread::{AnyPixelSampler, Domain, PixelSampler, PixelSamplerKind, SamplerKind};

use crate::cornell::{Light, PathSamples, SampleSource, render_cornell};
use crate::render::{FilmLens, Image};

/// A [`SampleSource`] over a pixel sampler's domains.
#[derive(Clone, Copy, Debug)]
pub struct Domains<P> {
    pub sampler: P,
    pub film_lens: FilmLens,
    /// `Some(key)`: every sample's root is `start(pixel, index).branch(key)`
    /// rather than the start domain itself.
    pub root_branch: Option<u32>,
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

/// One frame of the Cornell box: samples `0..spp` of every pixel of
/// `sampler`, film and lens drawn as `film_lens` says, the light sampled
/// as `light` says, box filter.
pub fn render(
    width: u32,
    height: u32,
    spp: u32,
    sampler: AnyPixelSampler,
    film_lens: FilmLens,
    light: Light,
) -> Image {
    // Borrowed: each path's domain is 32 bytes (owned, 112).
    let source = Domains {
        sampler: &sampler,
        film_lens,
        root_branch: None,
    };
    Image {
        width,
        height,
        pixels: render_cornell(width, height, spp, &source, light),
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

/// The reference image at `width x height`: [`REFERENCE_SPP`] samples per
/// pixel, see the module docs.
pub fn reference(width: u32, height: u32) -> Image {
    let source = reference_source(REFERENCE_SPP, width, height);
    Image {
        width,
        height,
        pixels: render_cornell(width, height, REFERENCE_SPP, &source, REFERENCE_LIGHT),
    }
}

/// A fingerprint of the reference: [`REFERENCE_SPP`] and the bits of a
/// tiny render of the scene (8 x 8 pixels, 4 samples each, about 400 rays),
/// folded by FNV-1a. Any change to the geometry, materials, camera, layout,
/// estimator or reference count changes it, so a cached reference keyed by
/// it is never stale.
pub fn fingerprint() -> u32 {
    let source = reference_source(4, 8, 8);
    let image = render_cornell(8, 8, 4, &source, REFERENCE_LIGHT);
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
    use crate::render::{SOBOL, TracerSampler, one_and_two_threads, pixel_bits};

    #[test]
    fn cornell_frames_are_bit_identical_for_one_and_two_threads() {
        let (one, two) = one_and_two_threads();
        let (width, height) = (24, 20);
        for sampler in TracerSampler::all() {
            let frame = sampler.build(4, width, height, 3).unwrap();
            let draw = || {
                render(
                    width,
                    height,
                    4,
                    frame,
                    sampler.film_lens(),
                    Light::SolidAngle,
                )
            };
            let (a, b) = (one.install(draw), two.install(draw));
            assert_eq!(pixel_bits(&a.pixels), pixel_bits(&b.pixels), "{sampler}");
        }
        let a = one.install(fingerprint);
        assert_eq!(a, two.install(fingerprint));
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
