//! `Padded`: dimension pairs decorrelated, and what the check catches
//! when one pattern is reused for every pair.

use wellspread::glam::Vec2;
use wellspread::{Draw, Padded, PixelSampler, Root, Sobol};

use crate::dependence;

/// Padded Sobol's dimension pairs are independent by the measure and bounds
/// of `zsobol_dimension_pairs_are_decorrelated` (per-pixel shuffles), and
/// the measure has teeth: a sampler that reuses one pattern for every
/// dimension pair (the mistake padding prevents) fails it by far.
#[test]
fn padded_dimension_pairs_are_decorrelated() {
    let limit_r = 5.0 / (16384f64).sqrt();
    let padded = Padded::new(Sobol::new(16).unwrap(), 0);
    let (chi, r) = dependence(&padded, 0, 1);
    assert!(chi < 400.0 && r < limit_r, "padded sobol: {chi} {r}");
    let (chi, r) = dependence(&Reused(padded), 0, 1);
    assert!(chi > 10_000.0 && r > 0.9, "reused pattern: {chi} {r}");
}

/// The mistake: dimension pair 0's pattern for every pair.
struct Reused<P>(P);

impl<P: PixelSampler> PixelSampler for Reused<P> {
    fn samples_per_pixel(&self) -> Option<u32> {
        self.0.samples_per_pixel()
    }

    fn root(&self, pixel: [u32; 2]) -> Root {
        self.0.root(pixel)
    }

    fn draw_2d(&self, draw: Draw) -> Vec2 {
        self.0.draw_2d(draw)
    }

    fn sample_pixel(&self, pixel: [u32; 2], index: u32, _pair: u32) -> Vec2 {
        self.0.sample_pixel(pixel, index, 0)
    }
}
