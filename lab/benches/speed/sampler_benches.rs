//! Sampler speed: `sample` and `fill` against constant, Pcg32 and sobol_burley baselines.
//!
//! Every group times one 2D sample per element (`Throughput::Elements`), so
//! criterion's per-element figures compare directly:
//!
//! - `baseline/constant`: writing a constant `Vec2` (the memory limit);
//! - `baseline/pcg32`: a `rand_pcg::Pcg32` drawing two uniform f32 (the RNG limit);
//! - `baseline/sobol_burley`: `sobol_burley::sample(i, d, seed)` for d = 0, 1
//!   (a peer with O(1) random access);
//! - `any/<sampler>`: every kind in `SamplerKind::ALL` through `AnySampler`;
//! - `concrete/<sampler>`: the same sampler as its own type (generic code, no
//!   match), for every kind, to show what the match costs.
//!
//! Groups: `fill/<n>` (one whole set), `sample-sequential/<n>` (`sample(i, p)`
//! for i in 0..n, one pattern) and `sample-scattered/<n>` (indices and
//! patterns drawn from a fixed-seed Pcg32, as a renderer asks for them).
//!
//! After the groups ran, a table of ns/sample and ratios against the
//! baselines is printed from criterion's saved estimates (those of this run
//! only) and saved as `target/criterion/wellspread-summary.md`. The speed
//! targets, with Kensler's listing as a further baseline, are in
//! `ratio_benches.rs`, which runs last and prints its table at the end.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::{Duration, SystemTime};

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use wellspread::glam::Vec2;
use wellspread::{AnySampler, Sampler2D, SamplerKind};

/// Set sizes: a pixel's worth up to a whole tile's.
pub(crate) const SIZES: [u32; 4] = [16, 256, 4096, 65536];

/// Short runs: the benchmark machine is shared, and ratios within one run are
/// what the targets are about.
pub(crate) fn configure(group: &mut BenchmarkGroup<'_, WallTime>, n: u32) {
    group
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_millis(1500))
        .sample_size(30)
        .throughput(Throughput::Elements(u64::from(n)));
}

/// Something done with one concrete sampler type (generic code, no match).
trait Visit {
    fn visit<S: Sampler2D>(&mut self, name: &str, sampler: &S);
}

/// Calls `visit` with the concrete sampler inside `any`. The match has one
/// arm per kind and no wildcard, so a new kind does not compile until it
/// gets its `concrete` groups here.
fn visit_concrete(any: &AnySampler, v: &mut impl Visit) {
    let name = any.kind().name();
    match any {
        AnySampler::Regular(s) => v.visit(name, s),
        AnySampler::Random(s) => v.visit(name, s),
        AnySampler::Jittered(s) => v.visit(name, s),
        AnySampler::NRooks(s) => v.visit(name, s),
        AnySampler::MultiJittered(s) => v.visit(name, s),
        AnySampler::CorrelatedMultiJittered(s) => v.visit(name, s),
        AnySampler::BlueMultiJittered(s) => v.visit(name, s),
        AnySampler::Hammersley(s) => v.visit(name, s),
        AnySampler::Halton(s) => v.visit(name, s),
        AnySampler::Sobol(s) => v.visit(name, s),
        AnySampler::Pmj02(s) => v.visit(name, s),
    }
}

pub(crate) fn pcg() -> Pcg32 {
    Pcg32::seed_from_u64(0x5eed_2026)
}

/// (index, pattern) pairs in random order, as a renderer scattered over
/// pixels asks for them.
pub(crate) fn scattered(n: u32) -> Vec<(u32, u32)> {
    let mut rng = pcg();
    (0..n)
        .map(|_| (rng.random_range(0..n), rng.random::<u32>()))
        .collect()
}

pub(crate) fn pcg32_vec2(rng: &mut Pcg32) -> Vec2 {
    Vec2::new(rng.random::<f32>(), rng.random::<f32>())
}

pub(crate) fn sobol_vec2(index: u32, seed: u32) -> Vec2 {
    Vec2::new(
        sobol_burley::sample(index, 0, seed),
        sobol_burley::sample(index, 1, seed),
    )
}

fn fill_group(c: &mut Criterion, n: u32) {
    let mut group = c.benchmark_group(format!("fill/{n}"));
    configure(&mut group, n);
    let mut out = vec![Vec2::ZERO; n as usize];
    group.bench_function(BenchmarkId::new("baseline", "constant"), |b| {
        b.iter(|| {
            out.fill(black_box(Vec2::new(0.25, 0.75)));
            black_box(&mut out);
        })
    });
    let mut rng = pcg();
    group.bench_function(BenchmarkId::new("baseline", "pcg32"), |b| {
        b.iter(|| {
            for p in out.iter_mut() {
                *p = pcg32_vec2(&mut rng);
            }
            black_box(&mut out);
        })
    });
    group.bench_function(BenchmarkId::new("baseline", "sobol_burley"), |b| {
        b.iter(|| {
            let seed = black_box(7);
            for (i, p) in (0..).zip(out.iter_mut()) {
                *p = sobol_vec2(i, seed);
            }
            black_box(&mut out);
        })
    });
    struct Concrete<'a, 'b> {
        group: &'a mut BenchmarkGroup<'b, WallTime>,
        out: &'a mut Vec<Vec2>,
    }
    impl Visit for Concrete<'_, '_> {
        fn visit<S: Sampler2D>(&mut self, name: &str, sampler: &S) {
            let out = &mut *self.out;
            self.group
                .bench_function(BenchmarkId::new("concrete", name), |b| {
                    b.iter(|| {
                        sampler.fill(black_box(7), out);
                        black_box(&mut *out);
                    })
                });
        }
    }
    for &kind in SamplerKind::ALL {
        let Ok(sampler) = kind.build(n) else { continue };
        group.bench_function(BenchmarkId::new("any", kind.name()), |b| {
            b.iter(|| {
                black_box(&sampler).fill(black_box(7), &mut out);
                black_box(&mut out);
            })
        });
        visit_concrete(
            &sampler,
            &mut Concrete {
                group: &mut group,
                out: &mut out,
            },
        );
    }
    group.finish();
}

fn sample_group(c: &mut Criterion, n: u32, access: &str, pairs: &[(u32, u32)]) {
    let mut group = c.benchmark_group(format!("sample-{access}/{n}"));
    configure(&mut group, n);
    group.bench_function(BenchmarkId::new("baseline", "constant"), |b| {
        b.iter(|| {
            for &(i, p) in pairs {
                black_box(Vec2::new(i as f32, p as f32));
            }
        })
    });
    let mut rng = pcg();
    group.bench_function(BenchmarkId::new("baseline", "pcg32"), |b| {
        b.iter(|| {
            for _ in pairs {
                black_box(pcg32_vec2(&mut rng));
            }
        })
    });
    group.bench_function(BenchmarkId::new("baseline", "sobol_burley"), |b| {
        b.iter(|| {
            for &(i, p) in pairs {
                black_box(sobol_vec2(i, p));
            }
        })
    });
    struct Concrete<'a, 'b, 'c> {
        group: &'a mut BenchmarkGroup<'b, WallTime>,
        pairs: &'c [(u32, u32)],
    }
    impl Visit for Concrete<'_, '_, '_> {
        fn visit<S: Sampler2D>(&mut self, name: &str, sampler: &S) {
            let pairs = self.pairs;
            self.group
                .bench_function(BenchmarkId::new("concrete", name), |b| {
                    b.iter(|| {
                        for &(i, p) in pairs {
                            black_box(sampler.sample(i, p));
                        }
                    })
                });
        }
    }
    for &kind in SamplerKind::ALL {
        let Ok(sampler) = kind.build(n) else { continue };
        group.bench_function(BenchmarkId::new("any", kind.name()), |b| {
            let sampler = black_box(&sampler);
            b.iter(|| {
                for &(i, p) in pairs {
                    black_box(sampler.sample(i, p));
                }
            })
        });
        visit_concrete(
            &sampler,
            &mut Concrete {
                group: &mut group,
                pairs,
            },
        );
    }
    group.finish();
}

fn samplers(c: &mut Criterion) {
    let start = SystemTime::now();
    for n in SIZES {
        fill_group(c, n);
        let sequential: Vec<(u32, u32)> = (0..n).map(|i| (i, 7)).collect();
        sample_group(c, n, "sequential", &sequential);
        sample_group(c, n, "scattered", &scattered(n));
    }
    print_summary(start);
}

/// Cargo's target directory as the bench sees it (`CARGO_TARGET_DIR`, else
/// the workspace's `target`, one up from the lab, where cargo runs benches).
pub(crate) fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || {
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .parent()
                .unwrap()
                .join("target")
        },
        PathBuf::from,
    )
}

/// Where criterion saved its estimates (it honours `CRITERION_HOME`, then
/// the target directory).
fn criterion_dir() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return home.into();
    }
    target_dir().join("criterion")
}

/// Mean time per iteration in ns from `<group>/<id>/new/estimates.json`, if
/// that benchmark ran since `since` (criterion replaces `/` in group names
/// with `_`; a `BenchmarkId`'s function and parameter become nested
/// directories). Older files, from runs that a filter left out this time,
/// count as not run.
pub(crate) fn mean_ns(group: &str, id: &str, since: SystemTime) -> Option<f64> {
    estimate_ns(group, id, since, "mean")
}

/// Like [`mean_ns`], for any statistic criterion estimates (`"mean"`,
/// `"median"`, ...).
pub(crate) fn estimate_ns(
    group: &str,
    id: &str,
    since: SystemTime,
    statistic: &str,
) -> Option<f64> {
    let path = criterion_dir()
        .join(group.replace('/', "_"))
        .join(id)
        .join("new/estimates.json");
    if std::fs::metadata(&path).ok()?.modified().ok()? < since {
        return None;
    }
    let json = std::fs::read_to_string(path).ok()?;
    let estimate = &json[json.find(&format!("\"{statistic}\""))?..];
    let value = &estimate[estimate.find("\"point_estimate\":")? + "\"point_estimate\":".len()..];
    let end = value.find([',', '}'])?;
    value[..end].trim().parse().ok()
}

fn print_summary(since: SystemTime) {
    let mut table = String::new();
    let _ = writeln!(
        table,
        "\nns per 2D sample (criterion means of this run) and ratios to the baselines\n"
    );
    let _ = writeln!(
        table,
        "| access | n | sampler | any ns | concrete ns | / pcg32 | / constant | / sobol_burley |"
    );
    let _ = writeln!(table, "|---|---|---|---|---|---|---|---|");
    let mut groups = 0;
    for access in ["fill", "sample-sequential", "sample-scattered"] {
        for n in SIZES {
            let group = format!("{access}/{n}");
            let per = |id: &str| mean_ns(&group, id, since).map(|t| t / f64::from(n));
            let (Some(pcg), Some(constant), Some(sobol)) = (
                per("baseline/pcg32"),
                per("baseline/constant"),
                per("baseline/sobol_burley"),
            ) else {
                continue;
            };
            groups += 1;
            let _ = writeln!(
                table,
                "| {access} | {n} | *baselines* | pcg32 {pcg:.2} | constant {constant:.2} | | | sobol_burley {sobol:.2} |"
            );
            for kind in SamplerKind::ALL {
                let name = kind.name();
                let Some(any) = per(&format!("any/{name}")) else {
                    continue;
                };
                let concrete = per(&format!("concrete/{name}"))
                    .map_or_else(|| "-".to_owned(), |t| format!("{t:.2}"));
                let _ = writeln!(
                    table,
                    "| {access} | {n} | {name} | {any:.2} | {concrete} | {:.2} | {:.2} | {:.2} |",
                    any / pcg,
                    any / constant,
                    any / sobol
                );
            }
        }
    }
    if groups == 0 {
        return; // a filter left out every sampler group: keep the last file
    }
    println!("{table}");
    let dir = criterion_dir();
    if std::fs::create_dir_all(&dir).is_ok() {
        let _ = std::fs::write(dir.join("wellspread-summary.md"), &table);
    }
}

criterion_group!(benches, samplers);
