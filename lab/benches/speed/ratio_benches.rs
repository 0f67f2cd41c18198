//! The speed targets as ratios, each measured side by side with its baseline
//! in one criterion group of one run, and the table of them printed last:
//! `cargo bench -p wellspread-lab --bench speed -- ratio` runs only these groups.
//!
//! Groups (one 2D sample per element, `Throughput::Elements`):
//!
//! - `ratio-fill/<n>`: `baseline/pcg32` (a fixed-seed `rand_pcg::Pcg32`
//!   writing `n` `Vec2` of two uniform f32) and `fill` of jittered, n-rooks,
//!   correlated-multi-jittered, multi-jittered, sobol and pmj02, each as its
//!   own type;
//! - `ratio-scattered/<n>`: `sample(index, pattern)` over the same `n`
//!   (index, pattern) pairs from a fixed-seed `Pcg32`, for
//!   `baseline/kensler` (Kensler's 2013 `cmj` listing, [`crate::kensler`], on
//!   the same `columns x rows` grid), `baseline/sobol_burley` (two
//!   `sobol_burley::sample` calls, dimensions 0 and 1, per point),
//!   correlated-multi-jittered and sobol.
//!
//! Each baseline runs first and last in its group (`<name>` and
//! `<name>-again`); the ratio divides the sampler's median by the faster of
//! the two baseline medians, and marks the cell `~` when they differ by more
//! than 20% (the shared machine was busy). The table uses only estimates
//! written during this run (criterion's `estimates.json`, by modification
//! time), so a filtered run shows `-` rather than an older number. It goes
//! to stdout and, as markdown headed by the rustc version, `RUSTFLAGS`, the
//! target features compiled in and the CPU model, to `<target>/speed-ratios.md` (`speed-ratios-native.md` when
//! `RUSTFLAGS` asks for `target-cpu=native`, `speed-ratios-custom.md` for
//! other flags), so that both builds can be kept side by side. A separate
//! target directory keeps both builds' caches:
//! `CARGO_TARGET_DIR=$PWD/target/native RUSTFLAGS="-C target-cpu=native" cargo
//! bench -p wellspread-lab --bench speed -- ratio` writes `target/native/speed-ratios-native.md`.
//!
//! Time: the ratio groups alone take about 2 minutes after the build; the
//! whole `cargo bench -p wellspread-lab --bench speed` about 16 (10 for the sampler groups, 4
//! for the metrics), measured on the shared 2-vCPU machine.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::SystemTime;

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_group};
use wellspread::glam::Vec2;
use wellspread::{
    CorrelatedMultiJittered, Jittered, MultiJittered, NRooks, Pmj02, Sampler2D, Sobol,
};

use crate::kensler;
use crate::sampler_benches::{
    SIZES, configure, estimate_ns, pcg, pcg32_vec2, scattered, sobol_vec2, target_dir,
};

/// Two runs of one baseline in one group further apart than this factor
/// mark the cell `~`: the machine was busy, the ratio is not to be trusted.
const NOISY: f64 = 1.2;

/// One row of the table: `numerator / denominator` in `group`, and its limit.
struct Row {
    what: &'static str,
    group: &'static str,
    numerator: &'static str,
    denominator: &'static str,
    limit: f64,
    baseline: &'static str,
}

const ROWS: &[Row] = &[
    fill_row("`fill` jittered", "jittered", 1.0),
    fill_row("`fill` n-rooks", "n-rooks", 1.0),
    fill_row(
        "`fill` correlated-multi-jittered",
        "correlated-multi-jittered",
        1.0,
    ),
    fill_row("`fill` multi-jittered", "multi-jittered", 2.0),
    fill_row("`fill` sobol", "sobol", 0.5),
    fill_row("`fill` pmj02", "pmj02", 0.5),
    Row {
        what: "CMJ scattered `sample`",
        group: "ratio-scattered",
        numerator: "correlated-multi-jittered",
        denominator: "baseline/kensler",
        limit: 1.0,
        baseline: "Kensler's listing",
    },
    Row {
        what: "sobol scattered `sample`",
        group: "ratio-scattered",
        numerator: "sobol",
        denominator: "baseline/sobol_burley",
        limit: 0.33,
        baseline: "sobol_burley",
    },
];

const fn fill_row(what: &'static str, numerator: &'static str, limit: f64) -> Row {
    Row {
        what,
        group: "ratio-fill",
        numerator,
        denominator: "baseline/pcg32",
        limit,
        baseline: "Pcg32 fill",
    }
}

fn fill_one<S: Sampler2D>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    sampler: &S,
    out: &mut [Vec2],
) {
    group.bench_function(name, |b| {
        let sampler = black_box(sampler);
        b.iter(|| {
            sampler.fill(black_box(7), out);
            black_box(&mut *out);
        })
    });
}

fn scattered_one<S: Sampler2D>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    sampler: &S,
    pairs: &[(u32, u32)],
) {
    group.bench_function(name, |b| {
        let sampler = black_box(sampler);
        b.iter(|| {
            for &(i, p) in pairs {
                black_box(sampler.sample(i, p));
            }
        })
    });
}

fn fill_group(c: &mut Criterion, n: u32) {
    let mut group = c.benchmark_group(format!("ratio-fill/{n}"));
    configure(&mut group, n);
    let mut out = vec![Vec2::ZERO; n as usize];
    let mut rng = pcg();
    let mut pcg32_fill = |group: &mut BenchmarkGroup<'_, WallTime>, out: &mut [Vec2], id| {
        group.bench_function(BenchmarkId::new("baseline", id), |b| {
            b.iter(|| {
                for p in out.iter_mut() {
                    *p = pcg32_vec2(&mut rng);
                }
                black_box(&mut *out);
            })
        });
    };
    pcg32_fill(&mut group, &mut out, "pcg32");
    fill_one(&mut group, "jittered", &Jittered::new(n).unwrap(), &mut out);
    fill_one(&mut group, "n-rooks", &NRooks::new(n).unwrap(), &mut out);
    fill_one(
        &mut group,
        "correlated-multi-jittered",
        &CorrelatedMultiJittered::new(n).unwrap(),
        &mut out,
    );
    fill_one(
        &mut group,
        "multi-jittered",
        &MultiJittered::new(n).unwrap(),
        &mut out,
    );
    fill_one(&mut group, "sobol", &Sobol::new(n).unwrap(), &mut out);
    fill_one(&mut group, "pmj02", &Pmj02::new(n).unwrap(), &mut out);
    pcg32_fill(&mut group, &mut out, "pcg32-again");
    group.finish();
}

fn scattered_group(c: &mut Criterion, n: u32) {
    let mut group = c.benchmark_group(format!("ratio-scattered/{n}"));
    configure(&mut group, n);
    let pairs = scattered(n);
    let cmj = CorrelatedMultiJittered::new(n).unwrap();
    // Kensler's m is the number of columns (`s % m` picks the column).
    let (m, k) = (cmj.columns(), cmj.rows());
    if n <= 256 {
        kensler::check(m, k);
    }
    let baselines = |group: &mut BenchmarkGroup<'_, WallTime>, suffix: &str| {
        group.bench_function(
            BenchmarkId::new("baseline", format!("kensler{suffix}")),
            |b| {
                let (m, k) = black_box((m, k));
                b.iter(|| {
                    for &(i, p) in &pairs {
                        black_box(kensler::cmj(i, m, k, p));
                    }
                })
            },
        );
        group.bench_function(
            BenchmarkId::new("baseline", format!("sobol_burley{suffix}")),
            |b| {
                b.iter(|| {
                    for &(i, p) in &pairs {
                        black_box(sobol_vec2(i, p));
                    }
                })
            },
        );
    };
    baselines(&mut group, "");
    scattered_one(&mut group, "correlated-multi-jittered", &cmj, &pairs);
    scattered_one(&mut group, "sobol", &Sobol::new(n).unwrap(), &pairs);
    baselines(&mut group, "-again");
    group.finish();
}

fn ratios(c: &mut Criterion) {
    let start = SystemTime::now();
    for n in SIZES {
        fill_group(c, n);
        scattered_group(c, n);
    }
    report(start);
}

/// The table: one row per target, one column per n.
fn table(since: SystemTime) -> String {
    let mut t = String::new();
    let _ = write!(t, "| what | target |");
    for n in SIZES {
        let _ = write!(t, " n = {n} |");
    }
    let _ = writeln!(t);
    let _ = writeln!(t, "|---|---|{}", "---|".repeat(SIZES.len()));
    for row in ROWS {
        let _ = write!(
            t,
            "| {} | <= {:.2}x {} |",
            row.what, row.limit, row.baseline
        );
        for n in SIZES {
            let group = format!("{}/{n}", row.group);
            let median = |id: &str| estimate_ns(&group, id, since, "median");
            let again = format!("{}-again", row.denominator);
            let cell = match (
                median(row.numerator),
                median(row.denominator),
                median(&again),
            ) {
                (Some(a), Some(b1), b2) => {
                    // The baseline ran first and last in its group; the
                    // faster run is the one the machine disturbed less.
                    let b = b2.map_or(b1, |b2| b1.min(b2));
                    let ratio = a / b;
                    let mark = if ratio <= row.limit { "pass" } else { "MISS" };
                    let noisy = match b2 {
                        Some(b2) if b1.max(b2) > NOISY * b1.min(b2) => " ~",
                        _ => "",
                    };
                    format!("{ratio:.2}x {mark}{noisy}")
                }
                _ => "-".to_owned(),
            };
            let _ = write!(t, " {cell} |");
        }
        let _ = writeln!(t);
    }
    t
}

/// `rustc -V` of the toolchain cargo ran (rustup passes it down through the
/// environment), if it can be asked.
fn rustc_version() -> String {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".to_owned());
    std::process::Command::new(rustc)
        .arg("-V")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map_or_else(|| "unknown".to_owned(), |v| v.trim().to_owned())
}

/// The x86 vector features this binary was compiled for (what
/// `target-cpu=native` changes), not what the CPU has.
fn compiled_features() -> String {
    let features = [
        ("sse4.1", cfg!(target_feature = "sse4.1")),
        ("avx", cfg!(target_feature = "avx")),
        ("avx2", cfg!(target_feature = "avx2")),
        ("fma", cfg!(target_feature = "fma")),
        ("bmi2", cfg!(target_feature = "bmi2")),
        ("avx512f", cfg!(target_feature = "avx512f")),
    ];
    let on: Vec<&str> = features
        .iter()
        .filter(|(_, on)| *on)
        .map(|(name, _)| *name)
        .collect();
    if on.is_empty() {
        "baseline (none of sse4.1, avx, avx2, fma, bmi2, avx512f)".to_owned()
    } else {
        on.join(", ")
    }
}

fn report(since: SystemTime) {
    let table = table(since);
    if !table.contains(" pass") && !table.contains(" MISS") {
        // A filter left out every ratio group: keep the last table's file.
        println!(
            "\nno ratio group ran; `cargo bench -p wellspread-lab --bench speed -- ratio` runs them"
        );
        return;
    }
    let rustflags = std::env::var("RUSTFLAGS").unwrap_or_default();
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let target_env = std::env::var("CARGO_TARGET_DIR").unwrap_or_default();
    let command = format!(
        "{}{}cargo bench -p wellspread-lab --bench speed{}",
        if target_env.is_empty() {
            String::new()
        } else {
            format!("CARGO_TARGET_DIR={target_env} ")
        },
        if rustflags.is_empty() {
            String::new()
        } else {
            format!("RUSTFLAGS=\"{rustflags}\" ")
        },
        if args.is_empty() {
            String::new()
        } else {
            format!(" -- {}", args.join(" "))
        }
    );
    let mut md = String::new();
    let _ = writeln!(md, "# Speed ratios\n");
    let _ = writeln!(md, "Regenerate with `{command}`.\n");
    let _ = writeln!(md, "- rustc: {}", rustc_version());
    let _ = writeln!(
        md,
        "- RUSTFLAGS: {}",
        if rustflags.is_empty() {
            "(none: the default build)".to_owned()
        } else {
            format!("`{rustflags}`")
        }
    );
    let _ = writeln!(md, "- target features compiled in: {}", compiled_features());
    let _ = writeln!(
        md,
        "- CPU: {}",
        crate::machine::cpu_model().unwrap_or_else(|| "unknown".to_owned())
    );
    let _ = writeln!(
        md,
        "\nEach ratio is (time of the sampler) / (time of its baseline): \
         criterion medians from the same group of this run. Each baseline \
         runs first and last in its group and the faster of the two counts; \
         `~` marks a cell whose two baseline runs differ by more than {:.0}% \
         (a busy machine: re-run before quoting it), and `-` a pair that did \
         not run.\n",
        (NOISY - 1.0) * 100.0
    );
    md.push_str(&table);
    println!("\n{md}");
    let name = if rustflags.is_empty() {
        "speed-ratios.md"
    } else if rustflags.contains("target-cpu=native") {
        "speed-ratios-native.md"
    } else {
        "speed-ratios-custom.md"
    };
    let path: PathBuf = target_dir().join(name);
    match std::fs::write(&path, &md) {
        Ok(()) => println!("written to {}", path.display()),
        Err(e) => eprintln!("could not write {}: {e}", path.display()),
    }
}

criterion_group!(benches, ratios);
