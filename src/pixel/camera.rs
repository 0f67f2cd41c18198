//! The camera sample: where a pixel sample lands on the film and on the
//! lens, its filter weight and its time, from one domain.

use glam::Vec2;

use super::{Domain, PixelSampler};
use crate::filter::Filter;
use crate::warp::concentric_disk;

/// What a camera needs of one pixel sample, from
/// [`Domain::camera_sample`]: the counterpart of pbrt-v4's
/// `CameraSample`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    /// The film position in raster coordinates: the pixel's centre
    /// (`pixel + 0.5`) plus the filter's offset, so inside the pixel's
    /// square grown by the filter's radius. An f32 holds the position to
    /// 2^-24 of its magnitude: a pixel coordinate above 2^16 keeps the
    /// offset to 2^-8 of a pixel or coarser, and above 2^24 the pixel
    /// itself is rounded.
    pub film: Vec2,
    /// The point on the unit lens disk (concentric map); scale it by the
    /// lens radius. Jointly stratified with `film` (one 4D draw).
    pub lens: Vec2,
    /// The time in `[0, 1)`, for motion blur: map it onto the shutter
    /// interval. Drawn whether or not the camera uses it.
    pub time: f32,
    /// The filter weight the sample's radiance gets
    /// ([`FilterSample::weight`](crate::filter::FilterSample::weight)):
    /// 1 for the positive filters, `sign(f) c` for those with negative
    /// lobes.
    pub filter_weight: f32,
}

impl<S: PixelSampler> Domain<S> {
    /// The camera sample of `pixel` (the pixel this domain was started
    /// for) under `filter`, from the domain's next two draws: one
    /// [`next_4d`](Self::next_4d), the film offset (through the filter's
    /// sampling map) and the lens point (through the concentric disk map)
    /// from one 4D point, so film and lens are stratified jointly; then one
    /// [`next_1d`](Self::next_1d) for the time.
    ///
    /// Cost: the two draws, the filter's sampling map and one concentric
    /// map. Call it first on a fresh domain, so that the film always takes
    /// the same draws (the filter's map keeps the 4D set's stratification:
    /// each axis goes through its own monotone inverse CDF).
    ///
    /// ```
    /// use wellspread::filter::{Filter, GaussianFilter};
    /// use wellspread::{PixelSampler, PixelSamplerKind};
    ///
    /// let sampler = "sobol".parse::<PixelSamplerKind>()?.build(16, [64, 48], 0)?;
    /// let filter = GaussianFilter::new(1.5, 0.5)?;
    /// let pixel = [10, 20];
    /// for index in 0..16 {
    ///     let mut d = sampler.start(pixel, index);
    ///     let camera = d.camera_sample(pixel, &filter);
    ///     // Within the filter's radius of the pixel's centre.
    ///     let centre = wellspread::glam::Vec2::new(10.5, 20.5);
    ///     assert!((camera.film - centre).abs().max_element() <= filter.radius());
    ///     assert!(camera.lens.length() <= 1.0);
    ///     assert!((0.0..1.0).contains(&camera.time));
    ///     assert_eq!(camera.filter_weight, 1.0);
    ///     // ... then the path's draws: d.branch(BOUNCE) ...
    /// }
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    pub fn camera_sample<F: Filter + ?Sized>(
        &mut self,
        pixel: [u32; 2],
        filter: &F,
    ) -> CameraSample {
        let film_lens = self.next_4d();
        let time = self.next_1d();
        let filtered = filter.sample(Vec2::new(film_lens.x, film_lens.y));
        let centre = Vec2::new(pixel[0] as f32, pixel[1] as f32) + 0.5;
        CameraSample {
            film: centre + filtered.offset,
            lens: concentric_disk(Vec2::new(film_lens.z, film_lens.w)),
            time,
            filter_weight: filtered.weight,
        }
    }
}
