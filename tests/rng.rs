//! Feature `rand`: `Domain` as a `rand::RngCore` (rand 0.9) gives exactly
//! the domain's 1D draws. Run with `cargo test --features rand --test rng`.
#![cfg(feature = "rand")]

use rand::{Rng, RngCore};
use wellspread::{PixelSampler, PixelSamplerKind};

/// For every pixel sampler kind, `random::<f32>()` and `random::<f64>()`
/// are `next_1d()` exactly, call for call, interleaved with 2D draws (each
/// call advances the domain by one dimension), on several pixels and
/// indices, including indices past the count.
#[test]
fn random_f32_is_next_1d_exactly() {
    let mut checked = 0;
    for kind in PixelSamplerKind::all() {
        let sampler = kind.build(16, [64, 64], 7).unwrap();
        for pixel in [[0, 0], [5, 9], [63, 63], [1000, 3]] {
            for index in [0, 1, 7, 15, 16, 40] {
                let (mut rng, mut d) = (sampler.start(pixel, index), sampler.start(pixel, index));
                for k in 0..12 {
                    let v = d.next_1d();
                    // Every sampler's draw is a multiple of 2^-24.
                    assert_eq!(v, (v * 16_777_216.0).floor() / 16_777_216.0, "{kind}: {v}");
                    match k % 3 {
                        0 => assert_eq!(rng.random::<f32>(), v, "{kind} {pixel:?} {index}"),
                        1 => assert_eq!(rng.random::<f64>(), f64::from(v), "{kind}"),
                        _ => assert_eq!(rng.next_u32(), ((v * 16_777_216.0) as u32) << 8, "{kind}"),
                    }
                    checked += 1;
                    // A 2D draw between keeps both in step.
                    assert_eq!(rng.next_2d(), d.next_2d());
                }
            }
        }
    }
    println!("{checked} draws equal");
    assert!(checked > 1000);
}

/// 1D stratification carries through: over a pixel's 16 samples, one
/// `random::<f32>()` call is one value per 1/16 (for the sequences and
/// the grids, whose 1D draws are stratified), and `random_range(0..4)` is
/// each choice 4 times.
#[test]
fn rand_draws_keep_one_dimensional_strata() {
    for name in [
        "sobol",
        "pmj02",
        "zsobol",
        "blue-noise",
        "correlated-multi-jittered",
    ] {
        let sampler = name
            .parse::<PixelSamplerKind>()
            .unwrap()
            .build(16, [8, 8], 1)
            .unwrap();
        for pixel in [[0, 0], [3, 5]] {
            let mut seen = [0; 16];
            let mut choices = [0; 4];
            for index in 0..16 {
                let mut rng = sampler.start(pixel, index);
                seen[(rng.random::<f32>() * 16.0) as usize] += 1;
                choices[rng.random_range(0..4usize)] += 1;
            }
            assert_eq!(seen, [1; 16], "{name}");
            assert_eq!(choices, [4; 4], "{name}");
        }
    }
}

/// `fill_bytes` writes each draw's 24 bits, most significant byte first.
#[test]
fn fill_bytes_is_three_bytes_per_draw() {
    let sampler = "sobol"
        .parse::<PixelSamplerKind>()
        .unwrap()
        .build(16, [8, 8], 1)
        .unwrap();
    let (mut rng, mut d) = (sampler.start([1, 2], 3), sampler.start([1, 2], 3));
    let mut bytes = [0u8; 8];
    rng.fill_bytes(&mut bytes);
    let mut expected = Vec::new();
    for _ in 0..3 {
        let bits = (d.next_1d() * 16_777_216.0) as u32;
        expected.extend_from_slice(&bits.to_be_bytes()[1..]);
    }
    assert_eq!(&bytes[..], &expected[..8]);
}
