//! `Domain::camera_sample`: the film, lens, time and weight a camera needs,
//! from one 4D and one 1D draw.

use wellspread::filter::{BoxFilter, Filter, GaussianFilter, MitchellFilter};
use wellspread::glam::Vec2;
use wellspread::metrics::is_net_base2;
use wellspread::warp::concentric_disk;
use wellspread::{PixelSampler, PixelSamplerKind};

/// For every pixel sampler the camera sample is exactly the composition it
/// documents: `next_4d` through the filter's and the disk's maps, then
/// `next_1d`; the domain's next draw is its third.
#[test]
fn camera_sample_is_one_4d_and_one_1d_draw_for_every_kind() {
    let mitchell = MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0).unwrap();
    for kind in PixelSamplerKind::all() {
        let sampler = kind.build(16, [64, 64], 7).unwrap();
        for (pixel, index) in [([0, 0], 0), ([63, 5], 3), ([17, 40], 15), ([3, 9], 16)] {
            let mut d = sampler.start(pixel, index);
            let camera = d.camera_sample(pixel, &mitchell);
            let after = d.next_2d();
            let mut e = sampler.start(pixel, index);
            let p = e.next_4d();
            let time = e.next_1d();
            let filtered = mitchell.sample(Vec2::new(p.x, p.y));
            let centre = Vec2::new(pixel[0] as f32 + 0.5, pixel[1] as f32 + 0.5);
            assert_eq!(camera.film, centre + filtered.offset, "{kind}");
            assert_eq!(camera.filter_weight, filtered.weight, "{kind}");
            assert_eq!(camera.lens, concentric_disk(Vec2::new(p.z, p.w)), "{kind}");
            assert_eq!(camera.time.to_bits(), time.to_bits(), "{kind}");
            assert_eq!(after, e.next_2d(), "{kind}");
        }
    }
}

/// Under a box filter of radius 1/2 the film positions of a pixel's 16
/// sobol samples are a (0,4,2)-net of the pixel's square, and the lens
/// points lie in the unit disk with 4 in each quadrant (film and lens come
/// from one 4D Sobol' point, each pair of dimensions a net).
#[test]
fn box_filtered_film_is_a_net_of_the_pixel_and_lens_fills_the_disk() {
    let sampler = "sobol"
        .parse::<PixelSamplerKind>()
        .unwrap()
        .build(16, [32, 32], 0)
        .unwrap();
    let filter = BoxFilter::new(0.5).unwrap();
    for pixel in [[0, 0], [5, 9], [31, 31]] {
        let samples: Vec<_> = (0..16)
            .map(|index| sampler.start(pixel, index).camera_sample(pixel, &filter))
            .collect();
        let film: Vec<Vec2> = samples
            .iter()
            .map(|s| s.film - Vec2::new(pixel[0] as f32, pixel[1] as f32))
            .collect();
        assert!(
            film.iter()
                .all(|p| p.min_element() >= 0.0 && p.max_element() < 1.0)
        );
        assert!(is_net_base2(&film).unwrap(), "pixel {pixel:?}: {film:?}");
        let mut quadrants = [0; 4];
        for s in &samples {
            assert!(s.lens.length() <= 1.0, "{:?}", s.lens);
            assert_eq!(s.filter_weight, 1.0);
            quadrants[usize::from(s.lens.x >= 0.0) + 2 * usize::from(s.lens.y >= 0.0)] += 1;
        }
        assert_eq!(quadrants, [4; 4], "pixel {pixel:?}");
        let mut times: Vec<u32> = samples.iter().map(|s| (s.time * 16.0) as u32).collect();
        times.sort_unstable();
        assert_eq!(
            times,
            (0..16).collect::<Vec<_>>(),
            "time strata, pixel {pixel:?}"
        );
    }
}

/// The edges: pixel coordinates up to `u32::MAX` give finite film
/// positions within the filter's radius of the centre (to f32's spacing
/// there), and index `u32::MAX` of a fixed-size sampler is a sample.
#[test]
fn camera_sample_edges() {
    let filter = GaussianFilter::new(1.5, 0.5).unwrap();
    for kind in PixelSamplerKind::all() {
        let sampler = kind.build(4, [8, 8], u32::MAX).unwrap();
        for pixel in [[0, 0], [u32::MAX, 0], [1 << 24, (1 << 16) + 1]] {
            let camera = sampler.start(pixel, u32::MAX).camera_sample(pixel, &filter);
            let centre = Vec2::new(pixel[0] as f32, pixel[1] as f32) + 0.5;
            let spacing = centre.max_element() * f32::EPSILON;
            assert!(camera.film.is_finite(), "{kind} {pixel:?}");
            assert!(
                (camera.film - centre).abs().max_element() <= filter.radius() + spacing,
                "{kind} {pixel:?}: {:?}",
                camera.film
            );
            assert!(camera.lens.length() <= 1.0 && (0.0..1.0).contains(&camera.time));
        }
    }
}
