//! `PaddedNd`: a domain's successive draws take consecutive dimensions of
//! one set per pixel, so an orthogonal array stratifies them jointly and a
//! Latin hypercube keeps each of them Latin; pages, padding, branches and
//! passes.

use wellspread::{
    Domain, Error, Faure4D, LatinHypercube, OrthogonalArray, PaddedNd, PixelSampler,
    PixelSamplerKind, Sobol4D,
};

/// The values of `draws` (widths) of sample `index` of `pixel`, flattened.
fn values<S: PixelSampler + Copy>(
    sampler: S,
    pixel: [u32; 2],
    index: u32,
    widths: &[u32],
) -> Vec<f32> {
    let mut d: Domain<S> = Domain::start(sampler, pixel, index);
    draws(&mut d, widths)
}

fn draws<S: PixelSampler + Copy>(d: &mut Domain<S>, widths: &[u32]) -> Vec<f32> {
    widths
        .iter()
        .flat_map(|w| match w {
            1 => vec![d.next_1d()],
            2 => d.next_2d().to_array().to_vec(),
            3 => d.next_3d().to_array().to_vec(),
            _ => d.next_4d().to_array().to_vec(),
        })
        .collect()
}

/// Whether the pixel's `n = q^2` points, in the dimensions `a` and `b` of
/// `points` (one row per sample), fill every cell of a `q x q` grid once.
fn pair_stratified(points: &[Vec<f32>], q: usize, a: usize, b: usize) -> bool {
    let mut cells = vec![0; q * q];
    for p in points {
        cells[(p[a] * q as f32) as usize * q + (p[b] * q as f32) as usize] += 1;
    }
    cells.iter().all(|&c| c == points.len() / (q * q))
}

/// Whether dimension `a` of `points` has one point in each of `n` strata.
fn latin(points: &[Vec<f32>], a: usize) -> bool {
    let n = points.len();
    let mut seen = vec![false; n];
    for p in points {
        let s = (f64::from(p[a]) * n as f64) as usize;
        if std::mem::replace(&mut seen[s], true) {
            return false;
        }
    }
    true
}

#[test]
fn orthogonal_draws_are_stratified_jointly_across_draws() {
    for (spp, q) in [(4, 2), (9, 3), (16, 4), (25, 5), (64, 8)] {
        let page = q + 1;
        for frame in [0, 7, u32::MAX] {
            let sampler = PixelSamplerKind::Orthogonal
                .build(spp, [64, 64], frame)
                .unwrap();
            for pixel in [[0, 0], [5, 9], [u32::MAX, 3]] {
                // Film, lens, then 1D draws to the end of the page.
                let widths = if page < 4 {
                    vec![2, 1]
                } else {
                    let mut widths = vec![2, 2];
                    widths.resize(page - 2, 1);
                    widths
                };
                let points: Vec<Vec<f32>> = (0..spp)
                    .map(|i| values(sampler, pixel, i, &widths))
                    .collect();
                for a in 0..page {
                    assert!(latin(&points, a), "{spp} spp dimension {a}");
                    for b in a + 1..page {
                        assert!(
                            pair_stratified(&points, q, a, b),
                            "{spp} spp frame {frame} pixel {pixel:?}: dimensions {a} and {b}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_draw_past_the_page_is_padded_and_the_next_page_is_an_array() {
    // 16 samples: q = 4, pages of 5 dimensions. Draws 2, 2 fill 0..4; the
    // third 2D draw would cross into page 1, so it takes a fresh pattern
    // (dimensions 4 and 5 are skipped); then a 1D and a 2D draw read
    // dimensions 6, 7 and 8 of page 1.
    let array = OrthogonalArray::new(16, 5, 2).unwrap();
    let sampler = PaddedNd::new(array, 3);
    let points: Vec<Vec<f32>> = (0..16)
        .map(|i| values(sampler, [2, 3], i, &[2, 2, 2, 1, 2]))
        .collect();
    // The padded draw is a set of its own: stratified in its pair.
    assert!(pair_stratified(&points, 4, 4, 5));
    // Page 1's three dimensions are stratified jointly.
    for (a, b) in [(6, 7), (6, 8), (7, 8)] {
        assert!(pair_stratified(&points, 4, a, b), "{a} {b}");
    }
    // And page 1 is not page 0 again: the values differ.
    assert!(points.iter().all(|p| p[6] != p[1]));
    let mut d = sampler.start([2, 3], 0);
    draws(&mut d, &[2, 2, 2, 1, 2]);
    assert_eq!((d.draws(), d.dimensions()), (5, 9));
}

#[test]
fn a_set_with_fewer_dimensions_than_a_draw_pads_within_the_draw() {
    // One-dimensional Latin hypercube: every coordinate of a 4D draw comes
    // from its own pattern, each Latin.
    let sampler = PaddedNd::new(LatinHypercube::new(10, 1).unwrap(), 0);
    let points: Vec<Vec<f32>> = (0..10)
        .map(|i| values(sampler, [1, 1], i, &[4, 3]))
        .collect();
    for a in 0..7 {
        assert!(latin(&points, a), "dimension {a}");
    }
    assert!(points.iter().all(|p| p[0] != p[1] && p[4] != p[0]));
}

#[test]
fn latin_hypercube_draws_are_latin_in_every_dimension() {
    for spp in [1, 2, 7, 16, 100] {
        let sampler = PixelSamplerKind::LatinHypercube
            .build(spp, [64, 64], 5)
            .unwrap();
        let widths = [1, 2, 3, 4, 2, 1];
        let points: Vec<Vec<f32>> = (0..spp)
            .map(|i| values(sampler, [4, 4], i, &widths))
            .collect();
        for a in 0..13 {
            assert!(latin(&points, a), "{spp} spp dimension {a}");
        }
    }
}

#[test]
fn branches_and_passes_get_fresh_arrays() {
    let sampler = PixelSamplerKind::Orthogonal.build(16, [64, 64], 0).unwrap();
    let parent: Vec<Vec<f32>> = (0..16)
        .map(|i| values(sampler, [7, 7], i, &[2, 2]))
        .collect();
    let child: Vec<Vec<f32>> = (0..16)
        .map(|i| draws(&mut sampler.start([7, 7], i).branch(1), &[2, 2]))
        .collect();
    // Pass 1 (indices 16..32) is a complete array of its own.
    let pass: Vec<Vec<f32>> = (16..32)
        .map(|i| values(sampler, [7, 7], i, &[2, 2]))
        .collect();
    for other in [&child, &pass] {
        for (a, b) in [(0, 1), (0, 3), (1, 2)] {
            assert!(pair_stratified(other, 4, a, b));
        }
        let shared = other
            .iter()
            .flatten()
            .filter(|v| parent.iter().flatten().any(|p| p == *v))
            .count();
        assert_eq!(shared, 0, "a fresh array shares no value");
    }
}

/// Any count `lambda q^2` (q a prime power) builds: `lambda` passes of the
/// `q^2` array with the largest such `q`, each pass a full array (every
/// pair of a page's dimensions fills the `q x q` grid, every dimension
/// Latin over the pass), passes unrelated, and `samples_per_pixel` the
/// count asked for.
#[test]
fn orthogonal_takes_every_count_lambda_q_squared_as_passes() {
    for (spp, q) in [
        (4, 2),
        (8, 2),
        (9, 3),
        (12, 2),
        (16, 4),
        (18, 3),
        (32, 4),
        (64, 8),
        (72, 3),
        (128, 8),
        (256, 16),
    ] {
        let sampler = PixelSamplerKind::Orthogonal
            .build(spp, [64, 64], 5)
            .unwrap();
        assert_eq!(sampler.samples_per_pixel(), Some(spp), "{spp}");
        let (n, page) = (q * q, q as usize + 1);
        let widths = vec![1; page];
        for pixel in [[0, 0], [7, 3]] {
            let mut passes = Vec::new();
            for pass in 0..spp / n {
                let points: Vec<Vec<f32>> = (pass * n..(pass + 1) * n)
                    .map(|i| values(sampler, pixel, i, &widths))
                    .collect();
                for a in 0..page {
                    assert!(latin(&points, a), "{spp} spp pass {pass} dimension {a}");
                    for b in a + 1..page {
                        assert!(
                            pair_stratified(&points, q as usize, a, b),
                            "{spp} spp pass {pass}: dimensions {a} and {b}"
                        );
                    }
                }
                passes.push(points);
            }
            // Passes are keyed apart: no value repeats between two.
            for pair in passes.windows(2) {
                let shared = pair[0]
                    .iter()
                    .flatten()
                    .filter(|v| pair[1].iter().flatten().any(|w| w == *v))
                    .count();
                assert_eq!(shared, 0, "{spp} spp: two passes share values");
            }
        }
    }
}

/// Counts with no square factor of a prime power are errors that name the
/// nearest valid counts.
#[test]
fn orthogonal_counts_without_a_prime_power_square_factor_are_errors() {
    for (spp, below, above) in [
        (1, None, Some(4)),
        (2, None, Some(4)),
        (3, None, Some(4)),
        (5, Some(4), Some(8)),
        (7, Some(4), Some(8)),
        (10, Some(9), Some(12)),
        (u32::MAX, Some(u32::MAX - 3), None),
    ] {
        let result = PixelSamplerKind::Orthogonal.build(spp, [64, 64], 0);
        assert_eq!(
            result,
            Err(Error::NotOrthogonalPixelCount {
                samples_per_pixel: spp,
                below,
                above
            }),
            "{spp}"
        );
        let message = result.unwrap_err().to_string();
        assert!(message.contains("lambda q^2"), "{message}");
        assert!(!message.contains('\n'), "{message}");
    }
    assert_eq!(
        PixelSamplerKind::LatinHypercube.build(0, [64, 64], 0),
        Err(Error::ZeroSamples)
    );
}

#[test]
fn faure_draws_are_stratified_jointly_at_any_count() {
    // Call order: film (2D), lens (2D), light choice (1D), light sample
    // (2D), BSDF (2D): pages of four dimensions, the BSDF pair crossing
    // into the third page is padded.
    let widths = [2, 2, 1, 2, 2];
    for frame in [0, 9, u32::MAX] {
        for pixel in [[0, 0], [31, 7], [u32::MAX, u32::MAX]] {
            // Built for any count; the draws do not depend on it.
            let sampler = PixelSamplerKind::Faure.build(16, [64, 64], frame).unwrap();
            let other = PixelSamplerKind::Faure.build(37, [64, 64], frame).unwrap();
            assert_eq!(sampler.samples_per_pixel(), Some(16));
            assert_eq!(other.samples_per_pixel(), Some(37));
            let points = |n: u32| -> Vec<Vec<f32>> {
                (0..n).map(|i| values(sampler, pixel, i, &widths)).collect()
            };
            assert_eq!(
                values(other, pixel, 5, &widths),
                values(sampler, pixel, 5, &widths)
            );
            // 16 samples: every pair inside each page fills 4 x 4.
            let p = points(16);
            for page in [0..4, 4..7] {
                for a in page.clone() {
                    for b in a + 1..page.end {
                        assert!(pair_stratified(&p, 4, a, b), "frame {frame}, ({a}, {b})");
                    }
                }
            }
            // Across a page's end the draws are independent sets.
            assert!(!pair_stratified(&p, 4, 0, 4) || !pair_stratified(&p, 4, 1, 5));
            // The padded BSDF pair is still a 2D stratified pair, each
            // dimension Latin.
            assert!(pair_stratified(&p, 4, 7, 8) && latin(&p, 7) && latin(&p, 8));
            // 64 samples: film and lens x (dimensions 0, 1, 2) fill 4 x 4 x 4.
            let p = points(64);
            let mut cells = [0; 64];
            for q in &p {
                let c = |d: usize| (q[d] * 4.0) as usize;
                cells[c(0) * 16 + c(1) * 4 + c(2)] += 1;
            }
            assert_eq!(cells, [1; 64], "frame {frame}");
            // Progressive: 48 samples are 64's prefix, every dimension of the
            // power-of-two prefix Latin.
            assert_eq!(points(48)[..], p[..48]);
            assert!((0..9).all(|d| latin(&p, d)));
        }
    }
    assert_eq!(
        PixelSamplerKind::Faure.build(0, [64, 64], 0),
        Err(Error::ZeroSamples)
    );
    // A progressive set built with no size has no count, and an index past
    // a sized one's count goes on along the sequence (no pass key).
    assert_eq!(
        PaddedNd::new(Faure4D::unbounded(), 0).samples_per_pixel(),
        None
    );
    assert_eq!(
        PaddedNd::new(Sobol4D::unbounded(), 0).samples_per_pixel(),
        None
    );
    let (sized, unbounded) = (
        PaddedNd::new(Faure4D::new(4).unwrap(), 3),
        PaddedNd::new(Faure4D::unbounded(), 3),
    );
    for index in [3, 4, 17, u32::MAX] {
        assert_eq!(
            values(sized, [1, 2], index, &[2, 2]),
            values(unbounded, [1, 2], index, &[2, 2])
        );
    }
    let array = PaddedNd::new(OrthogonalArray::new(16, 5, 2).unwrap(), 3);
    assert_eq!(array.samples_per_pixel(), Some(16));
}
