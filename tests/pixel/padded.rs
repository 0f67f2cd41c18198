//! `Padded`: dimension pairs decorrelated, and what the check catches
//! when one pattern is reused for every pair; the index ranges of the
//! padded sequences that are nets, and the ones that are not.

use wellspread::glam::Vec2;
use wellspread::implement::{Draw, PixelSamplerHooks, Root};
use wellspread::primitives::{hash_u32, owen_scramble, u32_to_unit_f32};
use wellspread::{Domain, Padded, PixelSampler, Pmj02, Sampler2D, Sobol};

use crate::{
    branch_pass, dependence, first_documented_range_not_a_net, other_aligned_blocks_that_are_nets,
};

/// The padded sequences, unbounded, at a few frames.
fn sequences() -> Vec<(&'static str, Box<dyn PixelSampler>)> {
    let mut out: Vec<(&'static str, Box<dyn PixelSampler>)> = Vec::new();
    for frame in [0, 9, 0xdead_beef] {
        out.push(("sobol", Box::new(Padded::new(Sobol::unbounded(), frame))));
        out.push(("pmj02", Box::new(Padded::new(Pmj02::unbounded(), frame))));
    }
    out
}

#[test]
fn sequences_prefixes_and_dyadic_blocks_are_nets() {
    // What `DomainSampler`'s docs promise: every prefix 0..2^m and every
    // block [2^m, 2^(m+1)), in every pixel and dimension pair, and for the
    // draws of a domain and of a branch.
    for (name, sampler) in sequences() {
        for pixel in [[0, 0], [17, 301], [u32::MAX, 5]] {
            for pair in [0, 3] {
                let bad =
                    first_documented_range_not_a_net(|i| sampler.sample_pixel(pixel, i, pair), 8);
                assert_eq!(bad, None, "{name} pixel {pixel:?} pair {pair}");
            }
            let bad = first_documented_range_not_a_net(
                |i| Domain::start(&*sampler, pixel, i).branch(4).next_2d(),
                8,
            );
            assert_eq!(bad, None, "{name} pixel {pixel:?} branch");
        }
    }
}

#[test]
fn sequences_other_aligned_blocks_are_not_all_nets() {
    // The negative the docs state: aligned blocks [j 2^k, (j+1) 2^k) with
    // j >= 2 are shuffled subsets of their dyadic block. Below 4096, of
    // the 2046 blocks of 2, 254 of 16 and 14 of 256, at most the share
    // below is nets (measured: 24% to 26% of the blocks of 2, a random pair
    // of a net's points being a (0,1,2)-net about a quarter of the time;
    // none of the others); the unshuffled sequence has every one a net.
    for (name, sampler) in sequences() {
        for (k, most) in [(1, 0.35), (4, 0.05), (8, 0.5)] {
            let (nets, blocks) =
                other_aligned_blocks_that_are_nets(|i| sampler.sample_pixel([3, 4], i, 1), k, 4096);
            assert!(
                (nets as f64) < most * blocks as f64,
                "{name} blocks of {}: {nets} of {blocks} nets",
                1 << k
            );
        }
    }
}

#[test]
fn sequences_passes_of_a_power_of_two_are_nets_through_a_branch_per_pass() {
    // Progressive passes of 16 samples: pass p drawn from
    // `start(pixel, i).branch(p)`, i < 16, is a net each; the pass rule
    // (samples_per_pixel 16, pass p the indices 16 p..16 (p + 1)) continues
    // the sequence, so passes 0 and 1 are nets and the first 2^a passes
    // together are, but single passes p >= 2 are not (measured: none of
    // the 28 per sampler).
    let net = |points: &[Vec2]| wellspread::metrics::is_net_base2(points).unwrap();
    for (name, sampler) in [
        (
            "sobol",
            Box::new(Padded::new(Sobol::new(16).unwrap(), 2)) as Box<dyn PixelSampler>,
        ),
        ("pmj02", Box::new(Padded::new(Pmj02::new(16).unwrap(), 2))),
    ] {
        let mut rule_nets = 0;
        for pixel in [[0, 0], [40, 7]] {
            let rule = |p: u32| -> Vec<Vec2> {
                (16 * p..16 * (p + 1))
                    .map(|i| Domain::start(&*sampler, pixel, i).next_2d())
                    .collect()
            };
            for p in 0..16 {
                assert!(
                    net(&branch_pass(&*sampler, pixel, p, 16)),
                    "{name} {pixel:?} pass {p}"
                );
                if p >= 2 {
                    rule_nets += usize::from(net(&rule(p)));
                }
            }
            assert!(net(&rule(0)) && net(&rule(1)), "{name} {pixel:?}");
            let first_four: Vec<Vec2> = (0..4).flat_map(rule).collect();
            assert!(net(&first_four), "{name} {pixel:?}");
        }
        assert!(
            rule_nets < 7,
            "{name}: {rule_nets} of 28 passes p >= 2 nets"
        );
    }
}

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

    fn sample_pixel(&self, pixel: [u32; 2], index: u32, _pair: u32) -> Vec2 {
        self.0.sample_pixel(pixel, index, 0)
    }
}

impl<P: PixelSampler> PixelSamplerHooks for Reused<P> {
    fn root(&self, pixel: [u32; 2]) -> Root {
        self.0.root(pixel)
    }

    fn draw_2d(&self, draw: Draw) -> Vec2 {
        self.0.draw_2d(draw)
    }
}

/// Sobol' dimensions 0 and 1 at `index` in natural order (no index
/// shuffle), each Owen-scrambled by its own seed.
fn unshuffled_sobol(index: u32, seeds: [u32; 2]) -> Vec2 {
    let mut y = 0u32;
    let mut v = 1u32 << 31;
    let mut bits = index;
    while bits != 0 {
        if bits & 1 == 1 {
            y ^= v;
        }
        v ^= v >> 1;
        bits >>= 1;
    }
    Vec2::new(
        u32_to_unit_f32(owen_scramble(index.reverse_bits(), seeds[0])),
        u32_to_unit_f32(owen_scramble(y, seeds[1])),
    )
}

#[test]
fn sobol_prefixes_between_powers_of_two_pay_for_the_prefix_shuffle() {
    // Per-pixel RMSE of exp(-x^2 - y^2) over the first n samples of 4096
    // pixels: Padded<Sobol> (index through `prefix_shuffle`), the bare
    // Sobol (Burley's nested index scramble, which keeps every aligned
    // block a net) and Owen-scrambled Sobol' in natural order. At powers
    // of two the three agree; between them the prefix shuffle's last
    // samples are a random subset of their block and its error is
    // several times the natural order's, while the nested scramble keeps
    // it (`docs/quality.md`, Prefixes between powers of two, quotes the
    // rows printed with `--nocapture`).
    let exact = 0.557_746_285_351_033_f64;
    let padded = Padded::new(Sobol::unbounded(), 0);
    let bare = Sobol::unbounded();
    let f = |p: Vec2| f64::from(-(p.x * p.x + p.y * p.y)).exp();
    let rmse = |n: u32, point: &dyn Fn(u32, u32) -> Vec2| -> f64 {
        let pixels = 4096;
        let sum: f64 = (0..pixels)
            .map(|pixel| {
                let mean = (0..n).map(|i| f(point(pixel, i))).sum::<f64>() / f64::from(n);
                (mean - exact).powi(2)
            })
            .sum();
        (sum / f64::from(pixels)).sqrt()
    };
    for n in [8, 12, 16, 24, 32, 48, 64, 100] {
        let shuffled = rmse(n, &|pixel, i| {
            padded.sample_pixel([pixel % 64, pixel / 64], i, 0)
        });
        let nested = rmse(n, &|pixel, i| bare.sample(i, pixel));
        let natural = rmse(n, &|pixel, i| {
            unshuffled_sobol(i, [hash_u32(pixel), hash_u32(pixel ^ 0x9e37_79b9)])
        });
        println!(
            "n {n}: natural {natural:.2e}, prefix shuffle {shuffled:.2e} ({:.2}x), \
             nested index scramble {nested:.2e} ({:.2}x)",
            shuffled / natural,
            nested / natural
        );
        let power_of_two = n.is_power_of_two();
        assert!(
            (0.85..1.15).contains(&(nested / natural)),
            "n {n}: nested {nested} natural {natural}"
        );
        if power_of_two {
            assert!(
                (0.85..1.15).contains(&(shuffled / natural)),
                "n {n}: {shuffled} {natural}"
            );
        } else {
            assert!(shuffled > 1.3 * natural, "n {n}: {shuffled} {natural}");
        }
    }
}
