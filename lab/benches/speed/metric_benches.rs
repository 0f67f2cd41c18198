//! Metric speed at n = 2^10 to 2^20: `cargo bench -p wellspread-lab --bench speed -- metric`.
//!
//! Distances and discrepancies run on uniform random points from a fixed-seed
//! `Pcg32`; the stratification checks and the t-value run on a Hammersley
//! set, which passes them all, so they never stop early. Large sizes take 10
//! single-iteration samples.
//!
//! `metric/min_distance_crowded` runs the minimum distances on the sets that
//! crowd a bounding-box grid (the diagonal at 2^20 and 2^22, two lattice blobs
//! of 724² points with spacing 2^-17) next to uniform points of the same
//! size. `metric/discrepancy_vs_scipy` prints the ratio of
//! `scipy.stats.qmc.discrepancy(method=..., workers=1)`'s time to ours at
//! 2^14 points for L2-star, centred and wrap-around L2, when `python3` can
//! import scipy, and says it skipped otherwise.

use std::hint::black_box;
use std::process::Command;
use std::sync::Once;
use std::time::{Duration, Instant};

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
            20,
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
    let checks: [(&str, Check); 4] = [
        ("is_latin", |p, _| metrics::is_latin(p).unwrap()),
        ("is_stratified", |p, k| {
            metrics::is_stratified(p, 1 << (k / 2), 1 << (k - k / 2)).unwrap()
        }),
        ("is_net_base2", |p, _| metrics::is_net_base2(p).unwrap()),
        ("net_t_value", |p, _| metrics::net_t_value(p).unwrap() == 0),
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

/// The sets of the issue's adversarial families, by name, with a uniform set
/// of the same size for each.
fn crowded_sets() -> Vec<(String, Vec<Vec2>)> {
    let mut sets = Vec::new();
    for k in [20u32, 22] {
        let n = 1usize << k;
        sets.push((format!("uniform/2^{k}"), random_points(n)));
        let diagonal = (0..n).map(|i| Vec2::splat(i as f32 / n as f32)).collect();
        sets.push((format!("diagonal/2^{k}"), diagonal));
    }
    let side = 724;
    let spacing = 1.0 / (1u32 << 17) as f32;
    let mut blobs = Vec::with_capacity(2 * side * side);
    for origin in [0.25f32, 0.75] {
        for i in 0..side * side {
            blobs.push(Vec2::new(
                origin + (i % side) as f32 * spacing,
                origin + (i / side) as f32 * spacing,
            ));
        }
    }
    sets.push(("uniform/2x724^2".to_string(), random_points(blobs.len())));
    sets.push(("blobs/2x724^2".to_string(), blobs));
    sets
}

fn crowded(c: &mut Criterion) {
    let sets = crowded_sets();
    let mut group = c.benchmark_group("metric/min_distance_crowded");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2))
        .sampling_mode(SamplingMode::Flat);
    for (name, points) in &sets {
        group.throughput(Throughput::Elements(points.len() as u64));
        group.bench_with_input(BenchmarkId::new("min_distance", name), points, |b, p| {
            b.iter(|| metrics::min_distance(black_box(p)).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("toroidal", name), points, |b, p| {
            b.iter(|| metrics::toroidal_min_distance(black_box(p)).unwrap())
        });
    }
    group.finish();
}

fn spectrum(c: &mut Criterion) {
    let mut group = c.benchmark_group("metric/radial_power_spectrum");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    let points = random_points(1024);
    for max_frequency in [16u32, 64] {
        group.bench_with_input(
            BenchmarkId::new("n=1024", max_frequency),
            &max_frequency,
            |b, &f| b.iter(|| metrics::radial_power_spectrum(black_box(&points), f).unwrap()),
        );
    }
    group.finish();
}

/// Times `scipy.stats.qmc.discrepancy(method=method)` (best of 5, one
/// worker) on the same points: `(seconds, value)`, or the reason it could
/// not run (no python3 or scipy).
fn scipy_seconds(points: &[Vec2], method: &str) -> Result<(f64, f64), String> {
    let probe = Command::new("python3")
        .args(["-c", "import scipy"])
        .output();
    match probe {
        Ok(out) if out.status.success() => {}
        _ => return Err("python3 with scipy not found (pip install scipy)".to_string()),
    }
    let path = std::env::temp_dir().join(format!("wellspread-{method}-{}.csv", std::process::id()));
    // f64 text of the f32 values reads back exactly.
    let text: String = points
        .iter()
        .map(|p| format!("{:?},{:?}\n", f64::from(p.x), f64::from(p.y)))
        .collect();
    std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    let script = r#"
import sys, time, numpy as np
from scipy.stats import qmc
p = np.loadtxt(sys.argv[1], delimiter=',')
best = float('inf')
for _ in range(5):
    t = time.perf_counter()
    v = qmc.discrepancy(p, method=sys.argv[2], workers=1)
    best = min(best, time.perf_counter() - t)
print(best, repr(float(v)))
"#;
    let out = Command::new("python3")
        .args(["-c", script])
        .arg(&path)
        .arg(method)
        .output();
    let _ = std::fs::remove_file(&path);
    let out = out.map_err(|e| format!("cannot run python3: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "scipy failed: {}",
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    let mut fields = stdout.split_whitespace().map(str::parse::<f64>);
    match (fields.next(), fields.next()) {
        (Some(Ok(seconds)), Some(Ok(value))) => Ok((seconds, value)),
        _ => Err(format!("unexpected scipy output `{}`", stdout.trim())),
    }
}

fn versus_scipy(c: &mut Criterion) {
    let points = random_points(1 << 14);
    let mut group = c.benchmark_group("metric/discrepancy_vs_scipy");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    // scipy's method name, ours, and whether scipy returns the square.
    let methods: [(&str, Metric, bool); 3] = [
        (
            "L2-star",
            |p| metrics::l2_star_discrepancy(p).unwrap(),
            false,
        ),
        ("CD", |p| metrics::centered_l2_discrepancy(p).unwrap(), true),
        (
            "WD",
            |p| metrics::wraparound_l2_discrepancy(p).unwrap(),
            true,
        ),
    ];
    for (method, metric, squared) in methods {
        let report = Once::new();
        group.bench_function(format!("{method}/16384"), |b| {
            report.call_once(|| {
                let ours = (0..5)
                    .map(|_| {
                        let start = Instant::now();
                        black_box(metric(black_box(&points)));
                        start.elapsed().as_secs_f64()
                    })
                    .fold(f64::INFINITY, f64::min);
                let value = metric(&points);
                match scipy_seconds(&points, method) {
                    Ok((theirs, v)) => {
                        let v = if squared { v.sqrt() } else { v };
                        println!(
                            "{method} at 2^14, best of 5: wellspread {:.2} ms, scipy {:.1} ms, \
                             ratio {:.1}; values {value:e} and {v:e} (rel. diff {:.1e})",
                            ours * 1e3,
                            theirs * 1e3,
                            theirs / ours,
                            (value - v).abs() / value
                        )
                    }
                    Err(why) => println!("{method} versus scipy: skipped, {why}"),
                }
            });
            b.iter(|| metric(black_box(&points)))
        });
    }
    group.finish();
}

criterion_group!(benches, metrics, crowded, spectrum, versus_scipy);
