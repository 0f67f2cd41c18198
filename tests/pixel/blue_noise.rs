//! `BlueNoise`: every power-of-two prefix of every pixel is a net in every
//! dimension pair, the per-pixel error is that of `Padded<Sobol>`, the
//! error is blue across the screen at every prefix, frames are
//! decorrelated, and nothing repeats at 256 (or 65536) pixels.
//!
//! The statistical tests use fixed frames, so they are deterministic; the
//! margins below say how far each figure sits from its bound.

use proptest::prelude::*;
use wellspread::blue_noise::{ExplicitColumns, PixelColumns, SearchedColumns};
use wellspread::glam::Vec2;
use wellspread::metrics::is_net_base2;
use wellspread::primitives::hash_u32;
use wellspread::{BlueNoise, Error, Padded, PixelSampler, Sobol};

use crate::{branch_pass, other_aligned_blocks_that_are_nets};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn every_power_of_two_prefix_and_dyadic_block_is_a_net(
        x in any::<u32>(),
        y in any::<u32>(),
        frame in any::<u32>(),
        dimension in prop_oneof![0u32..8, any::<u32>()],
        m in 0u32..=12,
        block in 0u32..2,
    ) {
        let sampler = BlueNoise::unbounded([u32::MAX, u32::MAX], frame).unwrap();
        let pixel = [x % u32::MAX, y % u32::MAX];
        let n = 1u32 << m;
        // The prefix 0..2^m and the dyadic block [2^m, 2^(m+1)), the ranges
        // the docs say are nets (the indices between two powers of two are
        // shuffled among themselves only).
        let points: Vec<Vec2> = (block * n..(block + 1) * n)
            .map(|i| sampler.sample_pixel(pixel, i, dimension))
            .collect();
        prop_assert!(is_net_base2(&points).unwrap(), "pixel {pixel:?} frame {frame} pair {dimension} n {n}");
        // The 1D draws (first coordinates) are stratified in 1D.
        let mut strata: Vec<u32> = points.iter().map(|p| (p.x * n as f32) as u32).collect();
        strata.sort_unstable();
        prop_assert!(strata.iter().zip(0..).all(|(&s, i)| s == i));
    }

    #[test]
    fn four_d_draws_film_half_is_the_2d_draw(
        x in any::<u32>(),
        y in any::<u32>(),
        frame in any::<u32>(),
        index in any::<u32>(),
    ) {
        // The lens half joins the film's sequence point (the net check of
        // the whole 4D draw is in tests/pixel/domain.rs); the film half is
        // what the domain's 2D draw gives.
        let sampler = BlueNoise::unbounded([u32::MAX, u32::MAX], frame).unwrap();
        let v = sampler.start([x, y], index).next_4d();
        let film = sampler.start([x, y], index).next_2d();
        prop_assert_eq!((v.x, v.y), (film.x, film.y));
    }

    #[test]
    fn explicit_columns_draw_what_the_default_draws(
        x in any::<u32>(),
        y in any::<u32>(),
        frame in any::<u32>(),
        index in any::<u32>(),
        key in any::<u32>(),
        spp in prop_oneof![Just(None), (1u32..=64).prop_map(Some)],
    ) {
        let shipped = match spp {
            Some(n) => BlueNoise::new(n, [4096, 4096], frame),
            None => BlueNoise::unbounded([4096, 4096], frame),
        }
        .unwrap();
        let explicit =
            shipped.with_columns(ExplicitColumns::new(SearchedColumns.columns()).unwrap());
        prop_assert_eq!(explicit.samples_per_pixel(), shipped.samples_per_pixel());
        for pair in [0, 1, 7, key] {
            prop_assert_eq!(
                explicit.sample_pixel([x, y], index, pair),
                shipped.sample_pixel([x, y], index, pair)
            );
        }
        // Every draw width, in and under a branch and a split.
        let (a, b) = (shipped.start([x, y], index), explicit.start([x, y], index));
        for (mut a, mut b) in [
            (a, b),
            (a.branch(key), b.branch(key)),
            (a.split(key, 12, 5), b.split(key, 12, 5)),
        ] {
            for _ in 0..2 {
                prop_assert_eq!(a.next_1d(), b.next_1d());
                prop_assert_eq!(a.next_2d(), b.next_2d());
                prop_assert_eq!(a.next_3d(), b.next_3d());
                prop_assert_eq!(a.next_4d(), b.next_4d());
            }
        }
    }

    #[test]
    fn any_count_is_a_prefix_of_the_progressive_sampler(
        spp in 1u32..=1 << 16,
        frame in any::<u32>(),
        x in 0u32..4096,
        y in 0u32..4096,
        index in any::<u32>(),
    ) {
        let counted = BlueNoise::new(spp, [4096, 4096], frame).unwrap();
        let progressive = BlueNoise::unbounded([4096, 4096], frame).unwrap();
        let index = index % spp;
        for dimension in 0..3 {
            let p = counted.sample_pixel([x, y], index, dimension);
            prop_assert_eq!(p, progressive.sample_pixel([x, y], index, dimension));
            prop_assert!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0);
        }
    }
}

#[test]
fn constructors_check_their_input() {
    assert_eq!(BlueNoise::new(0, [4, 4], 0), Err(Error::ZeroSamples));
    assert!(matches!(
        BlueNoise::new(4, [0, 4], 0),
        Err(Error::ZeroResolution { resolution: [0, 4] })
    ));
    assert!(matches!(
        BlueNoise::unbounded([4, 0], 0),
        Err(Error::ZeroResolution { resolution: [4, 0] })
    ));
    for spp in [1, 2, 3, 5, 12, 100, 1 << 16, (1 << 16) + 1, u32::MAX] {
        let sampler = BlueNoise::new(spp, [3840, 2160], 1).unwrap();
        assert_eq!(sampler.samples_per_pixel(), Some(spp));
        assert_eq!(sampler.samples_per_pixel(), Some(spp));
    }
    let progressive = BlueNoise::unbounded([u32::MAX, u32::MAX], 0).unwrap();
    assert_eq!(progressive.samples_per_pixel(), None);
    assert_eq!(progressive.samples_per_pixel(), None);
    assert_eq!(progressive.resolution(), [u32::MAX, u32::MAX]);
    assert_eq!(BlueNoise::new(3, [5, 6], 9).unwrap().frame(), 9);
}

#[test]
fn edges_stay_in_the_unit_square() {
    let sampler = BlueNoise::unbounded([u32::MAX, u32::MAX], u32::MAX).unwrap();
    let edge = u32::MAX - 1;
    for pixel in [[0, 0], [edge, 0], [0, edge], [edge, edge], [65535, 65536]] {
        for index in [0, 1, (1 << 24) - 1, 1 << 24, u32::MAX] {
            for dimension in [0, 1, u32::MAX] {
                let p = sampler.sample_pixel(pixel, index, dimension);
                assert!(p.cmpge(Vec2::ZERO).all() && p.cmplt(Vec2::ONE).all(), "{p}");
            }
        }
    }
}

/// The first `n` samples of a pixel, sorted (as a set).
fn sample_set(sampler: &BlueNoise, pixel: [u32; 2], n: u32, dimension: u32) -> Vec<[u32; 2]> {
    let mut set: Vec<[u32; 2]> = (0..n)
        .map(|i| {
            let p = sampler.sample_pixel(pixel, i, dimension);
            [p.x.to_bits(), p.y.to_bits()]
        })
        .collect();
    set.sort_unstable();
    set
}

#[test]
fn no_repetition_at_256_or_65536_pixels() {
    // OpenQMC's tables repeat every 256 pixels; here pixels 256 apart (and
    // a 65536-pixel tile apart) get different shifts, so their first
    // sample and their whole 16-sample sets differ.
    let sampler = BlueNoise::unbounded([1 << 20, 1 << 20], 3).unwrap();
    for (x, y) in [(0, 0), (17, 200), (255, 255), (1000, 3), (65535, 65535)] {
        for (dx, dy) in [
            (256, 0),
            (0, 256),
            (256, 256),
            (512, 0),
            (65536, 0),
            (0, 65536),
        ] {
            let (p, q) = ([x, y], [x + dx, y + dy]);
            for dimension in [0, 2] {
                assert_ne!(
                    sampler.sample_pixel(p, 0, dimension),
                    sampler.sample_pixel(q, 0, dimension),
                    "{p:?} {q:?} pair {dimension}"
                );
                assert_ne!(
                    sample_set(&sampler, p, 16, dimension),
                    sample_set(&sampler, q, 16, dimension),
                    "{p:?} {q:?} pair {dimension}"
                );
            }
        }
    }
    // Within a 64 x 64 block no two pixels share their first sample.
    let mut firsts: Vec<[u32; 2]> = (0..64 * 64)
        .map(|i| sample_set(&sampler, [i % 64, i / 64], 1, 0)[0])
        .collect();
    firsts.sort_unstable();
    firsts.dedup();
    assert_eq!(firsts.len(), 64 * 64);
}

#[test]
fn each_sample_splits_the_film_in_halves() {
    // At one sample index, a pixel's coordinate falls below 1/2 for about
    // half the pixels of a film, as with independent pixels: a renderer's
    // first draw (a light choice, say) must not pick the same half in
    // every pixel. (A table whose columns never touched the top digit put
    // every pixel of a sample in the same half.) Over 64 x 64 pixels,
    // frames 0 to 3, pairs 0 to 2 and samples 0 to 3.
    for frame in 0..4 {
        let sampler = BlueNoise::new(16, [64, 64], frame).unwrap();
        for dimension in 0..3 {
            for index in 0..4 {
                let mut below = [0u32; 2];
                for p in 0..64 * 64 {
                    let q = sampler.sample_pixel([p % 64, p / 64], index, dimension);
                    below[0] += u32::from(q.x < 0.5);
                    below[1] += u32::from(q.y < 0.5);
                }
                for (axis, count) in below.into_iter().enumerate() {
                    let fraction = f64::from(count) / 4096.0;
                    assert!(
                        (0.4..=0.6).contains(&fraction),
                        "frame {frame} pair {dimension} index {index} axis {axis}: {fraction:.3} below 1/2"
                    );
                }
            }
        }
    }
}

/// Chi-square over 16 x 16 cells of the first coordinates of two
/// dimension pairs at the same pixel and index, over a 64 x 64 film at 16
/// samples per pixel (65,536 points, 255 degrees of freedom).
fn pair_chi_square(sampler: &dyn PixelSampler, a: u32, b: u32) -> f64 {
    let mut counts = vec![0u32; 256];
    for p in 0..64 * 64 {
        for i in 0..16 {
            let pixel = [p % 64, p / 64];
            let u = sampler.sample_pixel(pixel, i, a).x;
            let v = sampler.sample_pixel(pixel, i, b).x;
            counts[(u * 16.0) as usize * 16 + (v * 16.0) as usize] += 1;
        }
    }
    counts
        .iter()
        .map(|&c| (f64::from(c) - 256.0).powi(2) / 256.0)
        .sum()
}

#[test]
fn unrelated_pairs_are_independent_at_each_pixel() {
    // A Domain's consecutive draws are dimension pairs picked by unrelated
    // hashes; here 32 frames, each with its own two hashed pairs. Every
    // pair's shifts are blue across pixels, but the two pairs' shifts at
    // one pixel must look independent across the film: the chi-square of
    // their first coordinates stays near its 255 degrees of freedom
    // (Padded<Sobol> measures a median of 240 and at most 320 over such
    // choices).
    let mut chis: Vec<f64> = (0..32u32)
        .map(|k| {
            let sampler = BlueNoise::new(16, [64, 64], k).unwrap();
            let (a, b) = (hash_u32(2 * k + 1000), hash_u32(2 * k + 1001));
            pair_chi_square(&sampler, a, b)
        })
        .collect();
    chis.sort_by(f64::total_cmp);
    let (median, max) = (chis[16], chis[31]);
    // Measured: median 251, largest 1,067 (the one outlier; the next is
    // 456); the previous table, 4,234 and 67,818 over 48 such frames.
    assert!(median < 300.0, "median chi-square {median:.0}: {chis:?}");
    assert!(max < 1500.0, "largest chi-square {max:.0}: {chis:?}");
}

/// Per-pixel and blurred errors of a `size x size` render, per prefix.
struct Errors {
    /// Mean squared error per prefix `n = 1..=spp`, summed over frames.
    pixel: Vec<f64>,
    /// The same after a Gaussian blur of sigma = 2 pixels (wrapping).
    blurred: Vec<f64>,
    /// The error images of the first two frames at every prefix.
    images: Vec<Vec<Vec<f64>>>,
}

/// The same Gaussian bump in every pixel, or a smooth image whose footprint
/// changes from pixel to pixel; the integrand and the exact pixel value.
fn integrand(footprint: bool, [x, y]: [u32; 2], p: Vec2) -> (f64, f64) {
    let (u, v) = (f64::from(p.x), f64::from(p.y));
    let (x, y) = (f64::from(x), f64::from(y));
    if footprint {
        let ix = ((0.9 * x).cos() - (0.9 * (x + 1.0)).cos()) / 0.9;
        let iy = ((0.7 * y).cos() - (0.7 * (y + 1.0)).cos()) / 0.7;
        (
            0.5 + 0.5 * (0.9 * (x + u)).sin() * (0.7 * (y + v)).sin(),
            0.5 + 0.5 * ix * iy,
        )
    } else {
        // sqrt(pi) erf(1/2), the integral of exp(-t^2) over [-1/2, 1/2].
        let g = 0.922_562_427_258_656_3_f64;
        ((-((u - 0.5).powi(2) + (v - 0.5).powi(2))).exp(), g * g)
    }
}

fn blur(image: &[f64], size: usize) -> Vec<f64> {
    let kernel: Vec<f64> = (-8i32..=8)
        .map(|t| (-f64::from(t * t) / 8.0).exp())
        .collect();
    let total: f64 = kernel.iter().sum();
    let wrap = |i: usize, t: usize| (i + size + t - 8) % size;
    let mut rows = vec![0.0; size * size];
    let mut out = vec![0.0; size * size];
    for y in 0..size {
        for x in 0..size {
            rows[y * size + x] = (0..17)
                .map(|t| kernel[t] * image[y * size + wrap(x, t)])
                .sum::<f64>()
                / total;
        }
    }
    for y in 0..size {
        for x in 0..size {
            out[y * size + x] = (0..17)
                .map(|t| kernel[t] * rows[wrap(y, t) * size + x])
                .sum::<f64>()
                / total;
        }
    }
    out
}

fn errors(
    make: impl Fn(u32) -> Box<dyn PixelSampler>,
    size: u32,
    spp: u32,
    frames: std::ops::Range<u32>,
    footprint: bool,
    dimension: u32,
    blurred: bool,
) -> Errors {
    let mut out = Errors {
        pixel: vec![0.0; spp as usize],
        blurred: vec![0.0; spp as usize],
        images: Vec::new(),
    };
    for frame in frames {
        let sampler = make(frame);
        let mut images = vec![vec![0.0; (size * size) as usize]; spp as usize];
        for y in 0..size {
            for x in 0..size {
                let mut sum = 0.0;
                for i in 0..spp {
                    let (f, exact) = integrand(
                        footprint,
                        [x, y],
                        sampler.sample_pixel([x, y], i, dimension),
                    );
                    sum += f;
                    images[i as usize][(y * size + x) as usize] = sum / f64::from(i + 1) - exact;
                }
            }
        }
        for (n, image) in images.iter().enumerate() {
            let mean_square = |v: &[f64]| v.iter().map(|e| e * e).sum::<f64>() / v.len() as f64;
            out.pixel[n] += mean_square(image);
            if blurred {
                out.blurred[n] += mean_square(&blur(image, size as usize));
            }
        }
        if out.images.len() < 2 {
            out.images.push(images);
        }
    }
    out
}

fn padded(frame: u32) -> Box<dyn PixelSampler> {
    Box::new(Padded::new(Sobol::new(16).unwrap(), frame))
}

fn blue_noise(size: u32) -> impl Fn(u32) -> Box<dyn PixelSampler> {
    move |frame| Box::new(BlueNoise::new(16, [size, size], frame).unwrap())
}

#[test]
fn per_pixel_error_is_that_of_padded_sobol_at_every_prefix() {
    // One scramble serves a whole frame, so a frame's mean squared error
    // varies from frame to frame; 384 frames of 32 x 32 pixels bring the
    // ratio's sampling error to about 2% (measured ratios 0.97 to 1.04).
    for footprint in [false, true] {
        let base = errors(padded, 32, 16, 0..384, footprint, 0, false);
        let ours = errors(blue_noise(32), 32, 16, 0..384, footprint, 0, false);
        for n in 0..16 {
            let ratio = (ours.pixel[n] / base.pixel[n]).sqrt();
            assert!(
                ratio < 1.1,
                "footprint {footprint} n {}: per-pixel RMSE ratio {ratio:.3}",
                n + 1
            );
        }
    }
}

#[test]
fn error_is_blue_at_every_prefix() {
    // 128 x 128 pixels, 8 frames, pairs 0 and 2: the blurred RMSE against
    // Padded<Sobol>'s on the same prefixes (measured: Gaussian 0.23 to
    // 0.49, footprint 0.65 to 0.78). docs/blue_noise.md measures 256 x 256
    // over 16 frames; this smaller film is noisier, so the footprint bound
    // is looser than the 0.9 (and its 0.6 at powers of two, which
    // the footprint misses: see the docs).
    for dimension in [0, 2] {
        for footprint in [false, true] {
            let base = errors(padded, 128, 16, 0..8, footprint, dimension, true);
            let ours = errors(blue_noise(128), 128, 16, 0..8, footprint, dimension, true);
            for n in 0..16 {
                let ratio = (ours.blurred[n] / base.blurred[n]).sqrt();
                let bound = if footprint { 0.86 } else { 0.6 };
                assert!(
                    ratio < bound,
                    "pair {dimension} footprint {footprint} n {}: blurred RMSE ratio {ratio:.3}",
                    n + 1
                );
            }
        }
    }
}

#[test]
fn frames_are_decorrelated_and_their_average_converges() {
    // One scramble serves a frame, so two frames' error images can be
    // correlated by chance, but not on average: over 63 consecutive pairs
    // of 32 x 32 frames the mean correlation is near 0 (measured -0.06 to
    // 0.04 at prefixes 1, 2 and 4), and the average of 64 frames has at
    // most about 1/64 of one frame's mean squared error, as independent
    // frames would (measured 0.35 to 1.00 times that: a frame's whole-film
    // error varies widely, so the estimate is loose and the bound
    // one-sided).
    for footprint in [false, true] {
        let size = 32u32;
        let mut images = Vec::new();
        for frame in 0..64 {
            let sampler = BlueNoise::new(4, [size, size], frame).unwrap();
            let image: Vec<[f64; 3]> = (0..size * size)
                .map(|p| {
                    let pixel = [p % size, p / size];
                    let mut sum = 0.0;
                    let mut out = [0.0; 3];
                    for i in 0..4 {
                        let (f, exact) =
                            integrand(footprint, pixel, sampler.sample_pixel(pixel, i, 0));
                        sum += f;
                        let slot = [0, 1, 3].iter().position(|&k| k == i);
                        if let Some(slot) = slot {
                            out[slot] = sum / f64::from(i + 1) - exact;
                        }
                    }
                    out
                })
                .collect();
            images.push(image);
        }
        for k in 0..3 {
            let mut mean_rho = 0.0;
            for pair in images.windows(2) {
                let ab: f64 = pair[0].iter().zip(&pair[1]).map(|(a, b)| a[k] * b[k]).sum();
                let aa: f64 = pair[0].iter().map(|a| a[k] * a[k]).sum();
                let bb: f64 = pair[1].iter().map(|b| b[k] * b[k]).sum();
                mean_rho += ab / (aa * bb).sqrt() / 63.0;
            }
            assert!(
                mean_rho.abs() < 0.08,
                "footprint {footprint} prefix {k}: mean correlation {mean_rho:.3}"
            );
            let single: f64 =
                images.iter().flatten().map(|e| e[k] * e[k]).sum::<f64>() / images.len() as f64;
            let average: f64 = (0..(size * size) as usize)
                .map(|p| {
                    let mean = images.iter().map(|im| im[p][k]).sum::<f64>() / images.len() as f64;
                    mean * mean
                })
                .sum();
            let ratio = average * images.len() as f64 / single;
            assert!(
                ratio < 1.6,
                "footprint {footprint} prefix {k}: 64-frame average at {ratio:.2} of 1/64 of one frame's"
            );
        }
    }
}

#[test]
fn out_of_range_arguments_continue_the_sequence() {
    // Debug and release alike: an index past the count is the next sample
    // of the progressive sampler, a pixel off the film its own.
    let counted = BlueNoise::new(4, [8, 8], 0).unwrap();
    let progressive = BlueNoise::unbounded([1 << 16, 1 << 16], 0).unwrap();
    for (pixel, index) in [([1, 1], 4), ([9, 300], 0), ([7, 7], u32::MAX)] {
        assert_eq!(
            counted.sample_pixel(pixel, index, 1),
            progressive.sample_pixel(pixel, index, 1)
        );
    }
}

#[test]
fn domain_draws_keep_the_nets() {
    // Through `start`: each draw's stream is the same for every pixel and
    // index, so a pixel's 2D draws are prefix nets and its 1D draws
    // stratified, at every power-of-two prefix, for the first draws and a
    // branch's.
    let sampler = BlueNoise::unbounded([640, 480], 5).unwrap();
    for pixel in [[0, 0], [17, 301], [639, 479]] {
        for m in 0..=6 {
            let n = 1u32 << m;
            let mut film = Vec::new();
            let mut time = Vec::new();
            let mut light = Vec::new();
            for i in 0..n {
                let mut d = sampler.start(pixel, i);
                film.push(d.next_2d());
                time.push(d.next_1d());
                light.push(d.branch(7).next_2d());
            }
            assert!(is_net_base2(&film).unwrap(), "{pixel:?} n {n}");
            assert!(is_net_base2(&light).unwrap(), "{pixel:?} n {n}");
            let mut strata: Vec<u32> = time.iter().map(|t| (t * n as f32) as u32).collect();
            strata.sort_unstable();
            assert!(
                strata.iter().zip(0..).all(|(&s, i)| s == i),
                "{pixel:?} n {n}"
            );
        }
    }
}

#[test]
fn other_aligned_blocks_are_not_all_nets() {
    // The negative the docs state: aligned blocks [j 2^k, (j+1) 2^k) with
    // j >= 2 are shuffled subsets of their dyadic block. Below 4096, of
    // the 2046 blocks of 2, 254 of 16 and 14 of 256, at most the share
    // below is nets (measured: 24% and 29% of the blocks of 2, none of the
    // others).
    let sampler = BlueNoise::unbounded([640, 480], 2).unwrap();
    for pixel in [[0, 0], [300, 17]] {
        for (k, most) in [(1, 0.4), (4, 0.05), (8, 0.5)] {
            let (nets, blocks) =
                other_aligned_blocks_that_are_nets(|i| sampler.sample_pixel(pixel, i, 1), k, 4096);
            assert!(
                (nets as f64) < most * blocks as f64,
                "{pixel:?} blocks of {}: {nets} of {blocks} nets",
                1 << k
            );
        }
    }
}

#[test]
fn passes_through_a_branch_per_pass_are_nets() {
    // Progressive passes of 16 samples drawn as the docs recommend, pass p
    // from `start(pixel, i).branch(p)` with i < 16: a net each. The pass
    // rule (indices 16 p .. 16 (p + 1)) continues the sequence instead, so
    // its passes p >= 2 are not nets (measured: none of the 14 per pixel).
    let sampler = BlueNoise::new(16, [640, 480], 8).unwrap();
    for pixel in [[0, 0], [300, 17]] {
        let mut rule_nets = 0;
        for p in 0..16 {
            let pass = branch_pass(&sampler, pixel, p, 16);
            assert!(is_net_base2(&pass).unwrap(), "{pixel:?} pass {p}");
            let rule: Vec<Vec2> = (16 * p..16 * (p + 1))
                .map(|i| sampler.sample_pixel(pixel, i, 0))
                .collect();
            if p >= 2 {
                rule_nets += usize::from(is_net_base2(&rule).unwrap());
            }
        }
        assert!(
            rule_nets < 4,
            "{pixel:?}: {rule_nets} of 14 pass-rule passes nets"
        );
    }
}
