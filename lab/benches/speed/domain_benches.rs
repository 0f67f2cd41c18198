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
//! - `unit/2d`: one unit; `unit/path`: nine units (one per draw of the
//!   path below);
//! - `<back end>/start+2d` and `<back end>/any+2d`: `start` and one
//!   `next_2d`, through the concrete type and through `AnyPixelSampler`
//!   (what `PixelSamplerKind::build` returns);
//! - `<back end>/start+4d`: `start` and one `next_4d`;
//! - `<back end>/path` and `<back end>/any-path`: `start`, then three
//!   bounces of `branch(BOUNCE).branch(b)`, `next_1d`, `next_1d`,
//!   `next_2d`: nine keyed draws, what a path tracer with light sampling
//!   draws per sample.
//!
//! Back ends: sobol, pmj02, random, jittered, cmj, blue-multi-jittered
//! (padded), zsobol, blue-noise, orthogonal, latin-hypercube and faure. The unit runs first and last
//! (`unit/2d-again`); ratios divide by the faster. The table goes to
//! stdout and `<target>/domain-ratios.md`.
//! `cargo bench -p wellspread-lab --bench speed -- domain` runs only this group.

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::SystemTime;

use criterion::{BenchmarkId, Criterion, criterion_group};
use rand::Rng;
use wellspread::glam::Vec2;
use wellspread::{
    AnyPixelSampler, BlueMultiJittered, BlueNoise, CorrelatedMultiJittered, Faure4D, Jittered,
    LatinHypercube, OrthogonalArray, Padded, PaddedNd, PixelSampler, PixelSamplerKind, Pmj02,
    Random, Sobol, ZSobol,
};

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

/// A scattered pixel sample: pixel and index.
#[derive(Clone, Copy)]
struct Input {
    pixel: [u32; 2],
    index: u32,
}

/// Bounces of the path workload: three keyed draws each.
const BOUNCES: u32 = 3;

fn inputs() -> Vec<Input> {
    let mut rng = pcg();
    (0..N)
        .map(|_| Input {
            pixel: [
                rng.random_range(0..RESOLUTION[0]),
                rng.random_range(0..RESOLUTION[1]),
            ],
            index: rng.random_range(0..SPP),
        })
        .collect()
}

/// The path workload: three bounces of a bounce branch, two 1D draws and
/// a 2D draw. Returns a value that depends on every value drawn (a
/// coordinate left unused would let the compiler skip its work).
#[inline(always)]
fn path<P: PixelSampler + Copy>(sampler: &P, input: Input) -> f32 {
    let d = sampler.start(input.pixel, input.index);
    let mut acc = 0.0;
    for b in 0..BOUNCES {
        let mut bounce = d.branch(BOUNCE).branch(b);
        acc += bounce.next_1d();
        acc += bounce.next_1d();
        acc += bounce.next_2d().element_sum();
    }
    acc
}

/// The unit's cost of the same path: one unit per draw, both its floats
/// used.
#[inline(always)]
fn unit_path(input: Input) -> f32 {
    let mut acc = 0.0;
    for dimension in 0..3 * BOUNCES {
        acc += unit(input.pixel, input.index, dimension).element_sum();
    }
    acc
}

fn back_end<P: PixelSampler + Copy>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    sampler: P,
    any: AnyPixelSampler,
    inputs: &[Input],
) {
    group.bench_function(BenchmarkId::new(name, "start+2d"), |b| {
        b.iter(|| {
            for input in inputs {
                black_box(sampler.start(input.pixel, input.index).next_2d());
            }
        })
    });
    group.bench_function(BenchmarkId::new(name, "any+2d"), |b| {
        b.iter(|| {
            for input in inputs {
                black_box(any.start(input.pixel, input.index).next_2d());
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
    group.bench_function(BenchmarkId::new(name, "any-path"), |b| {
        b.iter(|| {
            for input in inputs {
                black_box(path(&any, *input));
            }
        })
    });
}

/// Back ends and their targets for start + next_2d over the unit (for
/// blue-noise: over padded sobol's start + next_2d), and for sobol's
/// next_4d.
/// Back ends with their targets for start+next_2d and start+next_4d,
/// where one is set.
const BACK_ENDS: &[(&str, Option<f64>, Option<f64>)] = &[
    ("sobol", Some(3.0), Some(4.5)),
    ("pmj02", Some(3.0), None),
    ("random", Some(1.0), None),
    ("jittered", Some(5.0), None),
    ("cmj", Some(5.0), None),
    ("blue-multi-jittered", Some(5.0), None),
    ("zsobol", Some(3.5), None),
    ("blue-noise", Some(1.3), None),
    ("orthogonal", None, None),
    ("latin-hypercube", None, None),
    ("faure", None, None),
];

/// The `AnyPixelSampler` of a back end's name.
fn any(name: &str) -> AnyPixelSampler {
    name.parse::<PixelSamplerKind>()
        .unwrap()
        .build(SPP, RESOLUTION, 0)
        .unwrap()
}

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
        any("sobol"),
        &inputs,
    );
    back_end(
        &mut group,
        "pmj02",
        Padded::new(Pmj02::new(SPP).unwrap(), 0),
        any("pmj02"),
        &inputs,
    );
    back_end(
        &mut group,
        "random",
        Padded::new(Random::new(SPP).unwrap(), 0),
        any("random"),
        &inputs,
    );
    back_end(
        &mut group,
        "jittered",
        Padded::new(Jittered::new(SPP).unwrap(), 0),
        any("jittered"),
        &inputs,
    );
    back_end(
        &mut group,
        "cmj",
        Padded::new(CorrelatedMultiJittered::new(SPP).unwrap(), 0),
        any("cmj"),
        &inputs,
    );
    back_end(
        &mut group,
        "blue-multi-jittered",
        Padded::new(BlueMultiJittered::new(SPP).unwrap(), 0),
        any("blue-multi-jittered"),
        &inputs,
    );
    back_end(
        &mut group,
        "zsobol",
        ZSobol::new(SPP, RESOLUTION, 0).unwrap(),
        any("zsobol"),
        &inputs,
    );
    back_end(
        &mut group,
        "blue-noise",
        BlueNoise::new(SPP, RESOLUTION, 0).unwrap(),
        any("blue-noise"),
        &inputs,
    );
    back_end(
        &mut group,
        "orthogonal",
        PaddedNd::new(OrthogonalArray::new(SPP, 5, 2).unwrap(), 0),
        any("orthogonal"),
        &inputs,
    );
    back_end(
        &mut group,
        "latin-hypercube",
        PaddedNd::new(
            LatinHypercube::new(SPP, LatinHypercube::MAX_DIMENSIONS).unwrap(),
            0,
        ),
        any("latin-hypercube"),
        &inputs,
    );
    back_end(
        &mut group,
        "faure",
        PaddedNd::new(Faure4D::new(SPP).unwrap(), 0),
        any("faure"),
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
    let sobol_2d = median("sobol/start+2d");
    let ratio = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}x", a / b),
        _ => "-".to_string(),
    };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "| back end | start+next_2d / unit | through AnyPixelSampler | target | any / static | start+next_4d / unit | 9-draw path / unit path | any path / static path |"
    );
    let _ = writeln!(t, "|---|---|---|---|---|---|---|---|");
    for &(name, target_2d, target_4d) in BACK_ENDS {
        let m = |id: &str| median(&format!("{name}/{id}"));
        let base = if name == "blue-noise" {
            sobol_2d
        } else {
            Some(unit)
        };
        let target = match target_2d {
            Some(v) if name == "blue-noise" => format!("<= {v:.1}x sobol's"),
            Some(v) => format!("<= {v:.1}x"),
            None => "-".to_string(),
        };
        let four = match target_4d {
            Some(v) => format!("{} (<= {v:.1}x)", ratio(m("start+4d"), Some(unit))),
            None => ratio(m("start+4d"), Some(unit)),
        };
        let _ = writeln!(
            t,
            "| {name} | {} | {} | {target} | {} | {four} | {} | {} |",
            ratio(m("start+2d"), base),
            ratio(m("any+2d"), base),
            ratio(m("any+2d"), m("start+2d")),
            ratio(m("path"), unit_path),
            ratio(m("any-path"), m("path")),
        );
    }
    let _ = writeln!(
        t,
        "\nBlue-noise's first two columns are over padded sobol's start+next_2d; the others over the unit. Targets on AnyPixelSampler: <= 1.15x the static type."
    );
    println!("\nDomain cost, ratios to the unit (median ns per pixel sample / unit's)\n\n{t}");
    let _ = std::fs::write(target_dir().join("domain-ratios.md"), t);
}

criterion_group!(benches, domain);
