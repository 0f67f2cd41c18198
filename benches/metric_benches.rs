//! Metric speed at n = 2^10 to 2^20: `cargo bench --bench speed -- metric`.
//!
//! Distances and discrepancies run on uniform random points from a fixed-seed
//! `Pcg32`; the stratification checks run on a Hammersley set, which passes
//! them all, so they never stop early. The quadratic wrap-around L2
//! discrepancy stops at 2^16. Large sizes take 10 single-iteration samples.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use wellspread::glam::Vec2;
use wellspread::metrics;

const SIZES: [u32; 4] = [10, 14, 16, 20];

fn random_points(n: usize) -> Vec<Vec2> {
    let mut rng = Pcg32::seed_from_u64(0x5eed_0003);
    (0..n)
        .map(|_| Vec2::new(rng.random::<f32>(), rng.random::<f32>()))
        .collect()
}

fn hammersley(m: u32) -> Vec<Vec2> {
    let n = 1u32 << m;
    (0..n)
        .map(|i| {
            Vec2::new(
                i as f32 / n as f32,
                (i.reverse_bits() >> (32 - m)) as f32 / n as f32,
            )
        })
        .collect()
}

type Metric = fn(&[Vec2]) -> f64;
/// A check, given the set and log2 of its size.
type Check = fn(&[Vec2], u32) -> bool;

fn metrics(c: &mut Criterion) {
    let f64_metrics: [(&str, Metric, u32); 7] = [
        (
            "star_discrepancy",
            |p| metrics::star_discrepancy(p).unwrap(),
            20,
        ),
        (
            "l2_star_discrepancy",
            |p| metrics::l2_star_discrepancy(p).unwrap(),
            20,
        ),
        (
            "centered_l2_discrepancy",
            |p| metrics::centered_l2_discrepancy(p).unwrap(),
            20,
        ),
        (
            "wraparound_l2_discrepancy",
            |p| metrics::wraparound_l2_discrepancy(p).unwrap(),
            16,
        ),
        ("min_distance", |p| metrics::min_distance(p).unwrap(), 20),
        (
            "toroidal_min_distance",
            |p| metrics::toroidal_min_distance(p).unwrap(),
            20,
        ),
        (
            "normalized_toroidal_min_distance",
            |p| metrics::normalized_toroidal_min_distance(p).unwrap(),
            20,
        ),
    ];
    let random: Vec<(u32, Vec<Vec2>)> = SIZES.iter().map(|&k| (k, random_points(1 << k))).collect();
    for (name, metric, max_log2) in f64_metrics {
        let mut group = c.benchmark_group(format!("metric/{name}"));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for (k, points) in random.iter().filter(|(k, _)| *k <= max_log2) {
            if *k >= 16 {
                group.sampling_mode(SamplingMode::Flat);
            }
            group.throughput(Throughput::Elements(points.len() as u64));
            group.bench_with_input(BenchmarkId::from_parameter(1u32 << k), points, |b, p| {
                b.iter(|| metric(black_box(p)))
            });
        }
        group.finish();
    }

    let nets: Vec<(u32, Vec<Vec2>)> = SIZES.iter().map(|&k| (k, hammersley(k))).collect();
    let checks: [(&str, Check); 3] = [
        ("is_latin", |p, _| metrics::is_latin(p).unwrap()),
        ("is_stratified", |p, k| {
            metrics::is_stratified(p, 1 << (k / 2), 1 << (k - k / 2)).unwrap()
        }),
        ("is_net_base2", |p, _| metrics::is_net_base2(p).unwrap()),
    ];
    for (name, check) in checks {
        let mut group = c.benchmark_group(format!("metric/{name}"));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for (k, points) in &nets {
            group.throughput(Throughput::Elements(points.len() as u64));
            group.bench_with_input(BenchmarkId::from_parameter(1u32 << k), points, |b, p| {
                b.iter(|| assert!(check(black_box(p), *k)))
            });
        }
        group.finish();
    }
}

criterion_group!(benches, metrics);
