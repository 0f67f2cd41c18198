//! The cost of [`Domain`](wellspread::Domain) draws as ratios to a unit: an
//! inline PCG hash (O'Neill's RXS-M-XS output of one LCG step) of the pixel,
//! index and dimension, hashed once more, making two floats. That is what a
//! renderer pays for two `thread_rng`-style floats, and the baseline the
//! OpenQMC comparison used.
//!
//! Group `domain-ratio` (one pixel sample per element, 4096 elements with
//! scattered pixels and indices from a fixed-seed `Pcg32`), side by side
//! in one run:
//!
//! - `unit/2d`: one unit; `unit/path`: one unit per pair a path draws;
//! - `<back end>/start+2d`: `start` and one `next_2d`;
//! - `<back end>/start+4d`: `start` and one `next_4d`;
//! - `<back end>/path`: `start`, `next_4d` (film and lens), `next_1d`
//!   (time), then per bounce `branch(BOUNCE).branch(b)`, `next_2d` and
//!   `next_1d`: 4 to 9 draws per sample, the count scattered too.
//!
//! Back ends: sobol, pmj02, random, cmj (padded) and zsobol, as concrete
//! types. The unit runs first and last (`unit/2d-again`); ratios divide
//! by the faster. The table goes to stdout and `<target>/domain-ratios.md`.
//! `cargo bench --bench speed -- domain` runs only this group.

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::SystemTime;

use criterion::{BenchmarkId, Criterion, criterion_group};
use rand::Rng;
use wellspread::glam::Vec2;
use wellspread::{CorrelatedMultiJittered, Padded, PixelSampler, Pmj02, Random, Sobol, ZSobol};

use crate::sampler_benches::{configure, estimate_ns, pcg, target_dir};

/// Pixel samples per iteration.
const N: u32 = 4096;
/// The film the scattered pixels fall on.
const RESOLUTION: [u32; 2] = [1920, 1080];
/// Samples per pixel.
const SPP: u32 = 16;
/// The bounce key of the path workload.
const BOUNCE: u32 = 1;

/// One LCG step and PCG's RXS-M-XS output permutation (O'Neill 2014,
/// "PCG: A Family of Simple Fast Space-Efficient Statistically Good
/// Algorithms for Random Number Generation", `pcg_output_rxs_m_xs_32_32`).
#[inline(always)]
fn pcg_hash(x: u32) -> u32 {
    let state = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

/// The unit: two floats from a PCG hash of the pixel, index and dimension
/// (mixed in by odd multipliers) and a second hash of the first.
#[inline(always)]
fn unit([x, y]: [u32; 2], index: u32, dimension: u32) -> Vec2 {
    let seed = x
        ^ y.wrapping_mul(0x9e37_79b9)
        ^ index.wrapping_mul(0x85eb_ca6b)
        ^ dimension.wrapping_mul(0xc2b2_ae35);
    let a = pcg_hash(seed);
    let b = pcg_hash(a);
    let f = |v: u32| (v >> 8) as f32 * (1.0 / (1u32 << 24) as f32);
    Vec2::new(f(a), f(b))
}

/// A scattered pixel sample: pixel, index, and how many draws its path
/// makes (4 to 9).
#[derive(Clone, Copy)]
struct Input {
    pixel: [u32; 2],
    index: u32,
    draws: u32,
}

fn inputs() -> Vec<Input> {
    let mut rng = pcg();
    (0..N)
        .map(|_| Input {
            pixel: [
                rng.random_range(0..RESOLUTION[0]),
                rng.random_range(0..RESOLUTION[1]),
            ],
            index: rng.random_range(0..SPP),
            draws: rng.random_range(4..=9),
        })
        .collect()
}

/// The path workload: film and lens, time, then bounces until `draws`
/// draws are made. Returns a value that depends on every draw.
#[inline(always)]
fn path<P: PixelSampler + Copy>(sampler: &P, input: Input) -> f32 {
    let mut d = sampler.start(input.pixel, input.index);
    let film_lens = d.next_4d();
    let mut acc = film_lens.x + film_lens.w + d.next_1d();
    let mut made = 2;
    let mut b = 0;
    while made < input.draws {
        let mut bounce = d.branch(BOUNCE).branch(b);
        acc += bounce.next_2d().y;
        made += 1;
        if made < input.draws {
            acc += bounce.next_1d();
            made += 1;
        }
        b += 1;
    }
    acc
}

/// Pairs the unit makes for the same path: the 4D draw is two.
#[inline(always)]
fn unit_path(input: Input) -> f32 {
    let mut acc = 0.0;
    for dimension in 0..=input.draws {
        acc += unit(input.pixel, input.index, dimension).x;
    }
    acc
}

fn back_end<P: PixelSampler + Copy>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    sampler: P,
    inputs: &[Input],
) {
    group.bench_function(BenchmarkId::new(name, "start+2d"), |b| {
        b.iter(|| {
            for input in inputs {
                black_box(sampler.start(input.pixel, input.index).next_2d());
            }
        })
    });
    group.bench_function(BenchmarkId::new(name, "start+4d"), |b| {
        b.iter(|| {
            for input in inputs {
                black_box(sampler.start(input.pixel, input.index).next_4d());
            }
        })
    });
    group.bench_function(BenchmarkId::new(name, "path"), |b| {
        b.iter(|| {
            for input in inputs {
                black_box(path(&sampler, *input));
            }
        })
    });
}

/// Back ends and their targets for start+2d (and next_4d for sobol).
const BACK_ENDS: &[(&str, f64, Option<f64>)] = &[
    ("sobol", 2.5, Some(3.0)),
    ("pmj02", 2.5, None),
    ("random", 1.5, None),
    ("cmj", 3.5, None),
    ("zsobol", 3.5, None),
];

fn domain(c: &mut Criterion) {
    let since = SystemTime::now();
    let inputs = inputs();
    let mut group = c.benchmark_group("domain-ratio");
    configure(&mut group, N);
    let unit_2d = |b: &mut criterion::Bencher<'_>| {
        b.iter(|| {
            for input in &inputs {
                black_box(unit(input.pixel, input.index, 0));
            }
        })
    };
    group.bench_function(BenchmarkId::new("unit", "2d"), unit_2d);
    group.bench_function(BenchmarkId::new("unit", "path"), |b| {
        b.iter(|| {
            for input in &inputs {
                black_box(unit_path(*input));
            }
        })
    });
    back_end(
        &mut group,
        "sobol",
        Padded::new(Sobol::new(SPP).unwrap(), 0),
        &inputs,
    );
    back_end(
        &mut group,
        "pmj02",
        Padded::new(Pmj02::new(SPP).unwrap(), 0),
        &inputs,
    );
    back_end(
        &mut group,
        "random",
        Padded::new(Random::new(SPP).unwrap(), 0),
        &inputs,
    );
    back_end(
        &mut group,
        "cmj",
        Padded::new(CorrelatedMultiJittered::new(SPP).unwrap(), 0),
        &inputs,
    );
    back_end(
        &mut group,
        "zsobol",
        ZSobol::new(SPP, RESOLUTION, 0).unwrap(),
        &inputs,
    );
    group.bench_function(BenchmarkId::new("unit", "2d-again"), unit_2d);
    group.finish();
    report(since);
}

/// The table of ratios of this run.
fn report(since: SystemTime) {
    let median = |id: &str| estimate_ns("domain-ratio", id, since, "median");
    let unit = match (median("unit/2d"), median("unit/2d-again")) {
        (Some(a), Some(b)) => a.min(b),
        (Some(a), None) | (None, Some(a)) => a,
        _ => return,
    };
    let unit_path = median("unit/path");
    let mut t = String::new();
    let _ = writeln!(
        t,
        "| back end | start+next_2d / unit | target | start+next_4d / unit | target | path / unit path |"
    );
    let _ = writeln!(t, "|---|---|---|---|---|---|");
    for &(name, target_2d, target_4d) in BACK_ENDS {
        let cell = |id: &str, base: Option<f64>| match (median(&format!("{name}/{id}")), base) {
            (Some(a), Some(b)) => format!("{:.2}x", a / b),
            _ => "-".to_string(),
        };
        let _ = writeln!(
            t,
            "| {name} | {} | <= {target_2d:.1}x | {} | {} | {} |",
            cell("start+2d", Some(unit)),
            cell("start+4d", Some(unit)),
            target_4d.map_or("-".to_string(), |v| format!("<= {v:.1}x")),
            cell("path", unit_path),
        );
    }
    println!("\nDomain cost, ratios to the unit (median ns per pixel sample / unit's)\n\n{t}");
    let _ = std::fs::write(target_dir().join("domain-ratios.md"), t);
}

criterion_group!(benches, domain);
