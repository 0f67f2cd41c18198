//! Quality report: discrepancy, minimum distance and integration error per
//! sampler. `cargo bench -p wellspread-lab --bench quality [-- --quick | --docs]`.
//!
//! For every sampler in `SamplerKind::ALL` and n in {4, 16, ..., 4096}
//! (powers of four, so also powers of two), averaged over many patterns:
//!
//! - the metrics of `wellspread::metrics` (star and L2-star discrepancy,
//!   normalised toroidal minimum distance);
//! - the RMSE of estimating the integrals of the test integrands of
//!   Christensen, Kensler & Kilpatrick 2018 (disk, triangle, step, Gaussian,
//!   bilinear), and the least-squares slope of log RMSE against log n;
//! - the radially averaged power spectrum at one n;
//! - a coupled 4D integrand through `Domain::next_4d` and through two
//!   padded pairs, per pixel of a 64 x 64 film at n = 16 to 1024
//!   (`quality_4d.rs`).
//!
//! Markdown tables go to stdout and `target/quality/report.md`; SVG plots
//! (convergence per integrand, each sampler's points, the spectra) next to
//! it. The full run also rewrites the generated block of `docs/quality.md`
//! (between its `quality-report` markers) and copies the spectrum plot to
//! `docs/images/` when asked with `--docs`: a plain `cargo bench` writes
//! nothing into the source tree. `--quick` (for CI) runs
//! a small version into `target/quality/quick/` in seconds and never
//! touches `docs/`. Unknown flags, such as the `--bench` cargo passes, are
//! ignored.

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use wellspread::glam::Vec2;
use wellspread::metrics;
use wellspread::primitives::pattern_seed;
use wellspread::{AnySampler, Sampler2D, SamplerKind};

#[path = "../../examples/shared/machine.rs"]
mod machine;
mod quality_4d;

/// How big a run is.
struct Config {
    quick: bool,
    sizes: &'static [u32],
    /// Patterns per (sampler, n) for the integrands: RMSE needs many.
    integrand_patterns: u32,
    /// Patterns per (sampler, n) for the metrics (star discrepancy is
    /// quadratic in n).
    metric_patterns: u32,
    /// The n, frequency radius and pattern count of the power spectra.
    spectrum_n: u32,
    spectrum_radius: u32,
    spectrum_patterns: u32,
    /// The n of the point plots.
    points_n: u32,
}

const FULL: Config = Config {
    quick: false,
    sizes: &[4, 16, 64, 256, 1024, 4096],
    integrand_patterns: 256,
    metric_patterns: 64,
    spectrum_n: 256,
    spectrum_radius: 64,
    spectrum_patterns: 64,
    points_n: 256,
};

const QUICK: Config = Config {
    quick: true,
    sizes: &[4, 16, 64, 256],
    integrand_patterns: 32,
    metric_patterns: 8,
    spectrum_n: 64,
    spectrum_radius: 24,
    spectrum_patterns: 8,
    points_n: 256,
};

/// A test integrand over `[0, 1)^2` with its exact integral.
struct Integrand {
    name: &'static str,
    f: fn(Vec2) -> f64,
    exact: f64,
    smooth: bool,
}

/// The test integrands of Christensen, Kensler & Kilpatrick 2018, with the
/// exact integrals listed in REFERENCES.md.
const INTEGRANDS: [Integrand; 5] = [
    Integrand {
        name: "disk",
        // Quarter disk of area 1/2: x^2 + y^2 < 2 / pi.
        f: |p| f64::from(u8::from(sq(p.x) + sq(p.y) < 2.0 / PI)),
        exact: 0.5,
        smooth: false,
    },
    Integrand {
        name: "triangle",
        f: |p| f64::from(u8::from(p.y < p.x)),
        exact: 0.5,
        smooth: false,
    },
    Integrand {
        name: "step",
        f: |p| f64::from(u8::from(f64::from(p.x) < 1.0 / PI)),
        exact: 1.0 / PI,
        smooth: false,
    },
    Integrand {
        name: "gaussian",
        f: |p| (-sq(p.x) - sq(p.y)).exp(),
        // (sqrt(pi) / 2 * erf(1))^2
        exact: 0.557_746_285_351_033,
        smooth: true,
    },
    Integrand {
        name: "bilinear",
        f: |p| f64::from(p.x) * f64::from(p.y),
        exact: 0.25,
        smooth: true,
    },
];

fn sq(v: f32) -> f64 {
    f64::from(v) * f64::from(v)
}

/// A metric from `wellspread::metrics`.
type Metric = fn(&[Vec2]) -> Result<f64, wellspread::Error>;

const METRICS: [(&str, Metric); 3] = [
    ("star discrepancy", metrics::star_discrepancy),
    ("L2-star discrepancy", metrics::l2_star_discrepancy),
    (
        "normalised toroidal minimum distance",
        metrics::normalized_toroidal_min_distance,
    ),
];

/// The pattern for repetition `r` of a set of `n`: distinct across n too.
fn pattern(r: u32, n: u32) -> u32 {
    pattern_seed(r, n, 0, 0)
}

fn points(sampler: &AnySampler, pattern: u32) -> Vec<Vec2> {
    let mut out = vec![Vec2::ZERO; sampler.len() as usize];
    sampler.fill(pattern, &mut out);
    out
}

/// Samplers that can build a set of `n` (a sampler may reject some n).
fn samplers(n: u32) -> impl Iterator<Item = (SamplerKind, AnySampler)> {
    SamplerKind::ALL
        .iter()
        .filter_map(move |&kind| Some((kind, kind.build(n).ok()?)))
}

/// `rmse[kind][integrand][size]`, `None` where the sampler rejects that n.
type Rmse = Vec<Vec<Vec<Option<f64>>>>;

fn integrand_rmse(config: &Config) -> Rmse {
    let kinds = SamplerKind::ALL;
    let mut rmse = vec![vec![vec![None; config.sizes.len()]; INTEGRANDS.len()]; kinds.len()];
    for (s, &n) in config.sizes.iter().enumerate() {
        for (kind, sampler) in samplers(n) {
            let k = kinds.iter().position(|&x| x == kind).unwrap_or(0);
            let mut sum_sq = [0.0f64; INTEGRANDS.len()];
            for r in 0..config.integrand_patterns {
                let pts = points(&sampler, pattern(r, n));
                for (integrand, acc) in INTEGRANDS.iter().zip(&mut sum_sq) {
                    let estimate =
                        pts.iter().map(|&p| (integrand.f)(p)).sum::<f64>() / f64::from(n);
                    *acc += (estimate - integrand.exact).powi(2);
                }
            }
            for (i, acc) in sum_sq.iter().enumerate() {
                rmse[k][i][s] = Some((acc / f64::from(config.integrand_patterns)).sqrt());
            }
        }
    }
    rmse
}

/// Least-squares slope of log `y` against log `x` over the points present
/// (and with `y > 0`); `None` with fewer than two.
fn log_log_slope(xs: &[u32], ys: &[Option<f64>]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = xs
        .iter()
        .zip(ys)
        .filter_map(|(&x, &y)| y.filter(|&y| y > 0.0).map(|y| (f64::from(x).ln(), y.ln())))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let m = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / m, b + y / m));
    let sxy: f64 = pts.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = pts.iter().map(|&(x, _)| (x - mx).powi(2)).sum();
    Some(sxy / sxx)
}

/// `values[metric][kind][size]`: the mean over patterns.
fn metric_means(config: &Config) -> Vec<Vec<Vec<Option<f64>>>> {
    let kinds = SamplerKind::ALL;
    let mut values = vec![vec![vec![None; config.sizes.len()]; kinds.len()]; METRICS.len()];
    for (s, &n) in config.sizes.iter().enumerate() {
        for (kind, sampler) in samplers(n) {
            let k = kinds.iter().position(|&x| x == kind).unwrap_or(0);
            let mut sums = [0.0f64; METRICS.len()];
            let mut ok = [true; METRICS.len()];
            for r in 0..config.metric_patterns {
                let pts = points(&sampler, pattern(r, n));
                for (m, (_, metric)) in METRICS.iter().enumerate() {
                    match metric(&pts) {
                        Ok(v) => sums[m] += v,
                        Err(_) => ok[m] = false,
                    }
                }
            }
            for m in 0..METRICS.len() {
                if ok[m] {
                    values[m][k][s] = Some(sums[m] / f64::from(config.metric_patterns));
                }
            }
        }
    }
    values
}

/// `metrics::radial_power_spectrum` up to `spectrum_radius`, averaged over
/// patterns: entry `r - 1` is the mean periodogram over the integer
/// frequencies whose rounded length is `r`. Uniform random points give 1.
fn radial_spectrum(sampler: &AnySampler, config: &Config) -> Vec<f64> {
    let n = sampler.len();
    let mut power = vec![0.0f64; config.spectrum_radius as usize];
    for p in 0..config.spectrum_patterns {
        let spectrum =
            metrics::radial_power_spectrum(&points(sampler, pattern(p, n)), config.spectrum_radius)
                .expect("sampler points are in [0, 1)");
        for (sum, v) in power.iter_mut().zip(spectrum) {
            *sum += v / f64::from(config.spectrum_patterns);
        }
    }
    power
}

// ---------------------------------------------------------------- output

fn out_dir(config: &Config) -> PathBuf {
    // Benches run in the lab's folder: the workspace's target is one up.
    let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || {
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .parent()
                .unwrap()
                .join("target")
        },
        PathBuf::from,
    );
    let dir = target.join("quality");
    if config.quick { dir.join("quick") } else { dir }
}

/// Distinct colours for up to a dozen samplers (then they repeat).
const COLOURS: [&str; 12] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
    "#7f7f7f", "#bcbd22", "#000000", "#aec7e8",
];

fn colour(k: usize) -> &'static str {
    COLOURS[k % COLOURS.len()]
}

fn fmt_opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "-".to_owned(), |v| format!("{v:.digits$}"))
}

fn fmt_sci(v: Option<f64>) -> String {
    v.map_or_else(|| "-".to_owned(), |v| format!("{v:.2e}"))
}

/// A log-log plot of error against n: one line per sampler.
fn convergence_svg(title: &str, sizes: &[u32], series: &[(&str, Vec<Option<f64>>)]) -> String {
    let (w, h, left, right, top, bottom) = (640.0, 420.0, 70.0, 210.0, 40.0, 50.0);
    let values = series.iter().flat_map(|(_, v)| v.iter().flatten().copied());
    let (lo, hi) = values
        .filter(|&v| v > 0.0)
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    let (lo, hi) = if lo <= hi {
        (
            lo.log10().floor(),
            hi.log10().ceil().max(lo.log10().floor() + 1.0),
        )
    } else {
        (-1.0, 0.0)
    };
    let (x0, x1) = (
        f64::from(sizes[0]).log2(),
        f64::from(*sizes.last().unwrap_or(&sizes[0]))
            .log2()
            .max(f64::from(sizes[0]).log2() + 1.0),
    );
    let px = |n: f64| left + (n.log2() - x0) / (x1 - x0) * (w - left - right);
    let py = |v: f64| top + (hi - v.log10()) / (hi - lo) * (h - top - bottom);
    let mut s = svg_open(w, h);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="24" font-size="16" text-anchor="middle">{title}</text>"#,
        (left + w - right) / 2.0
    );
    for d in (lo as i32)..=(hi as i32) {
        let y = py(10f64.powi(d));
        let _ = writeln!(
            s,
            r##"<line x1="{left}" x2="{}" y1="{y:.1}" y2="{y:.1}" stroke="#ddd"/><text x="{}" y="{:.1}" font-size="11" text-anchor="end">1e{d}</text>"##,
            w - right,
            left - 6.0,
            y + 4.0
        );
    }
    for &n in sizes {
        let x = px(f64::from(n));
        let _ = writeln!(
            s,
            r##"<line x1="{x:.1}" x2="{x:.1}" y1="{top}" y2="{}" stroke="#ddd"/><text x="{x:.1}" y="{}" font-size="11" text-anchor="middle">{n}</text>"##,
            h - bottom,
            h - bottom + 16.0
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" font-size="12" text-anchor="middle">n (log scale)</text><text x="16" y="{}" font-size="12" transform="rotate(-90 16 {})" text-anchor="middle">RMSE (log scale)</text>"#,
        (left + w - right) / 2.0,
        h - 12.0,
        h / 2.0,
        h / 2.0
    );
    for (k, (name, values)) in series.iter().enumerate() {
        let pts: Vec<String> = sizes
            .iter()
            .zip(values)
            .filter_map(|(&n, v)| {
                v.filter(|&v| v > 0.0)
                    .map(|v| format!("{:.1},{:.1}", px(f64::from(n)), py(v)))
            })
            .collect();
        let c = colour(k);
        let _ = writeln!(
            s,
            r#"<polyline fill="none" stroke="{c}" stroke-width="1.5" points="{}"/>"#,
            pts.join(" ")
        );
        for p in &pts {
            let (x, y) = p.split_once(',').unwrap_or(("0", "0"));
            let _ = writeln!(s, r#"<circle cx="{x}" cy="{y}" r="2.5" fill="{c}"/>"#);
        }
        let ly = top + 10.0 + 18.0 * k as f64;
        // A log axis cannot show an exact (zero) error.
        let name = if pts.is_empty() {
            format!("{name} (0: not drawn)")
        } else {
            (*name).to_owned()
        };
        let _ = writeln!(
            s,
            r#"<line x1="{}" x2="{}" y1="{ly}" y2="{ly}" stroke="{c}" stroke-width="2"/><text x="{}" y="{}" font-size="12">{name}</text>"#,
            w - right + 10.0,
            w - right + 30.0,
            w - right + 36.0,
            ly + 4.0
        );
    }
    s.push_str("</svg>\n");
    s
}

/// Small multiples: one square panel per sampler, drawn by `panel` into a
/// `size x size` box at the origin.
fn panels_svg(
    title: &str,
    names: &[&str],
    size: f64,
    mut panel: impl FnMut(usize, &mut String),
) -> String {
    let columns = 4usize;
    let rows = names.len().div_ceil(columns).max(1);
    let (pad, head) = (30.0, 24.0 + 16.0 * title.lines().count() as f64);
    let w = columns as f64 * (size + pad) + pad;
    let h = rows as f64 * (size + pad + 16.0) + head;
    let mut s = svg_open(w, h);
    // A title line, then any further lines smaller.
    for (line, text) in title.lines().enumerate() {
        let (y, size) = if line == 0 {
            (22, 16)
        } else {
            (22 + 16 * line, 11)
        };
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{y}" font-size="{size}" text-anchor="middle">{text}</text>"#,
            w / 2.0
        );
    }
    for (i, name) in names.iter().enumerate() {
        let x = pad + (i % columns) as f64 * (size + pad);
        let y = head + (i / columns) as f64 * (size + pad + 16.0) + 16.0;
        let _ = writeln!(
            s,
            r#"<g transform="translate({x},{y})"><text x="{}" y="-5" font-size="12" text-anchor="middle">{name}</text>"#,
            size / 2.0
        );
        panel(i, &mut s);
        s.push_str("</g>\n");
    }
    s.push_str("</svg>\n");
    s
}

fn svg_open(w: f64, h: f64) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">
<rect width="100%" height="100%" fill="white"/>
"#
    )
}

fn points_svg(config: &Config) -> String {
    let n = config.points_n;
    let sets: Vec<(&str, Vec<Vec2>)> = samplers(n)
        .map(|(kind, s)| (kind.name(), points(&s, pattern(0, n))))
        .collect();
    let names: Vec<&str> = sets.iter().map(|(name, _)| *name).collect();
    let size = 200.0;
    panels_svg(&format!("{n} points, pattern 0"), &names, size, |i, s| {
        let _ = writeln!(
            s,
            r##"<rect width="{size}" height="{size}" fill="none" stroke="#888"/>"##
        );
        for p in &sets[i].1 {
            // y up, as in the papers' plots.
            let _ = writeln!(
                s,
                r#"<circle cx="{:.2}" cy="{:.2}" r="1.6"/>"#,
                f64::from(p.x) * size,
                (1.0 - f64::from(p.y)) * size
            );
        }
    })
}

fn spectrum_svg(config: &Config, spectra: &[(&str, Vec<f64>)]) -> String {
    let names: Vec<&str> = spectra.iter().map(|(name, _)| *name).collect();
    let size = 200.0;
    let y_max = 3.0;
    let r = f64::from(config.spectrum_radius);
    let nyquist = f64::from(config.spectrum_n).sqrt();
    let title = format!(
        "radially averaged power spectrum, n = {}, mean of {} patterns\nx: |k| from 0 to {r}, dashed at sqrt(n); y: 0 to {y_max} (clipped), grey line at 1 (white noise)",
        config.spectrum_n, config.spectrum_patterns
    );
    panels_svg(&title, &names, size, |i, s| {
        let py = |v: f64| size - v.min(y_max) / y_max * size;
        let _ = writeln!(
            s,
            r##"<rect width="{size}" height="{size}" fill="none" stroke="#888"/><line x1="0" x2="{size}" y1="{y:.1}" y2="{y:.1}" stroke="#bbb"/><line x1="{xn:.1}" x2="{xn:.1}" y1="0" y2="{size}" stroke="#bbb" stroke-dasharray="4 3"/>"##,
            y = py(1.0),
            xn = nyquist / r * size
        );
        let pts: Vec<String> = spectra[i]
            .1
            .iter()
            .enumerate()
            .map(|(i, &v)| format!("{:.1},{:.1}", (i + 1) as f64 / r * size, py(v)))
            .collect();
        let _ = writeln!(
            s,
            r##"<polyline fill="none" stroke="#1f77b4" stroke-width="1.2" points="{}"/>"##,
            pts.join(" ")
        );
    })
}

fn main() {
    let start = Instant::now();
    let config = if std::env::args().any(|a| a == "--quick") {
        QUICK
    } else {
        FULL
    };
    let dir = out_dir(&config);
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("cannot create {}: {e}", dir.display());
        std::process::exit(1);
    }
    let kinds = SamplerKind::ALL;
    let names: Vec<&str> = kinds.iter().map(|k| k.name()).collect();
    let mut report = String::new();
    let _ = writeln!(
        report,
        "# wellspread quality report{}\n\nn in {:?}; integrand RMSE over {} patterns, metrics averaged over {} patterns; \
         patterns are `pattern_seed(r, n, 0, 0)` for r = 0, 1, ...\n",
        if config.quick { " (quick)" } else { "" },
        config.sizes,
        config.integrand_patterns,
        config.metric_patterns
    );
    let tables_start = report.len();

    // Integrands: RMSE tables, slopes, convergence plots.
    let rmse = integrand_rmse(&config);
    let header = |report: &mut String, first: &str| {
        let _ = write!(report, "| {first} |");
        for n in config.sizes {
            let _ = write!(report, " {n} |");
        }
        let _ = write!(report, "\n|---|");
        for _ in config.sizes {
            let _ = write!(report, "---|");
        }
        report.push('\n');
    };
    for (i, integrand) in INTEGRANDS.iter().enumerate() {
        let _ = writeln!(
            report,
            "## RMSE: {} (exact integral {:.15})\n",
            integrand.name, integrand.exact
        );
        header(&mut report, "sampler \\ n");
        for (k, name) in names.iter().enumerate() {
            let _ = write!(report, "| {name} |");
            for v in &rmse[k][i] {
                let _ = write!(report, " {} |", fmt_sci(*v));
            }
            report.push('\n');
        }
        report.push('\n');
        let series: Vec<(&str, Vec<Option<f64>>)> = names
            .iter()
            .enumerate()
            .map(|(k, &name)| (name, rmse[k][i].clone()))
            .collect();
        let svg = convergence_svg(
            &format!("RMSE, {} integrand", integrand.name),
            config.sizes,
            &series,
        );
        let _ = std::fs::write(dir.join(format!("convergence-{}.svg", integrand.name)), svg);
    }
    // Slopes over all n, and over n >= 64 only: the smallest sets are
    // pre-asymptotic (and tiny power-of-two permutations are structured).
    for (heading, from) in [("all n", 0), ("n >= 64", 64)] {
        let first = config.sizes.iter().position(|&n| n >= from).unwrap_or(0);
        let _ = writeln!(
            report,
            "## Convergence: least-squares slope of log RMSE against log n ({heading})\n"
        );
        let _ = write!(report, "| sampler |");
        for integrand in &INTEGRANDS {
            let kind = if integrand.smooth {
                "smooth"
            } else {
                "discontinuous"
            };
            let _ = write!(report, " {} ({kind}) |", integrand.name);
        }
        let _ = writeln!(report, "\n|---|{}", "---|".repeat(INTEGRANDS.len()));
        for (k, name) in names.iter().enumerate() {
            let _ = write!(report, "| {name} |");
            for errors in &rmse[k] {
                let _ = write!(
                    report,
                    " {} |",
                    fmt_opt(log_log_slope(&config.sizes[first..], &errors[first..]), 2)
                );
            }
            report.push('\n');
        }
        report.push('\n');
    }

    // Metrics.
    let means = metric_means(&config);
    for (m, (metric, _)) in METRICS.iter().enumerate() {
        let _ = writeln!(
            report,
            "## {metric} (mean over {} patterns)\n",
            config.metric_patterns
        );
        header(&mut report, "sampler \\ n");
        for (k, name) in names.iter().enumerate() {
            let _ = write!(report, "| {name} |");
            for v in &means[m][k] {
                let _ = write!(report, " {} |", fmt_opt(*v, 4));
            }
            report.push('\n');
        }
        report.push('\n');
    }

    // The 4D section: one 4D draw against padded pairs.
    report.push_str(&quality_4d::section(config.quick, log_log_slope));

    let tables_end = report.len();

    // Pictures.
    let _ = std::fs::write(dir.join("points.svg"), points_svg(&config));
    let spectra: Vec<(&str, Vec<f64>)> = samplers(config.spectrum_n)
        .map(|(kind, s)| (kind.name(), radial_spectrum(&s, &config)))
        .collect();
    let _ = std::fs::write(dir.join("spectrum.svg"), spectrum_svg(&config, &spectra));
    let _ = writeln!(
        report,
        "Plots: `convergence-<integrand>.svg`, `points.svg`, `spectrum.svg` in `{}`.\n\nRun time {:.2} s.",
        dir.display(),
        start.elapsed().as_secs_f64()
    );
    print!("{report}");
    if let Err(e) = std::fs::write(dir.join("report.md"), &report) {
        eprintln!("cannot write the report: {e}");
        std::process::exit(1);
    }
    let docs_asked = std::env::args().any(|a| a == "--docs");
    if docs_asked && config.quick {
        eprintln!("--docs needs the full run: a --quick run never writes docs/");
    }
    if docs_asked && !config.quick {
        let docs = Path::new(env!("CARGO_MANIFEST_DIR"))
            .parent()
            .unwrap()
            .join("docs");
        let block = docs_block(
            &config,
            &report[tables_start..tables_end],
            start.elapsed().as_secs_f64(),
        );
        match write_docs(&docs, &dir, &block) {
            Ok(()) => eprintln!(
                "rewrote the generated block of {}",
                docs.join(DOCS_PAGE).display()
            ),
            Err(e) => {
                eprintln!("cannot update {}: {e}", docs.join(DOCS_PAGE).display());
                std::process::exit(1);
            }
        }
    }
}

// ---------------------------------------------------------------- docs page

/// The page under `docs/` that the full run refreshes, and the markers
/// around the part it writes; the prose outside them is kept.
const DOCS_PAGE: &str = "quality.md";
const BEGIN: &str = "<!-- quality-report:begin: written by `cargo bench -p wellspread-lab --bench quality -- --docs`; edits inside are lost -->";
const END: &str = "<!-- quality-report:end -->";
/// Plots copied from the run's directory to `docs/images/`, as
/// (file in the run, file in `docs/images/`, alt text).
/// (The point plot, about 100 kB, stays in `target/quality/`.)
const DOCS_PLOTS: [(&str, &str, &str); 1] = [(
    "spectrum.svg",
    "quality-spectrum.svg",
    "radially averaged power spectra",
)];

/// The generated block: the machine and run time, the tables (headings one
/// level down, under the page's own), and the copied plots.
fn docs_block(config: &Config, tables: &str, seconds: f64) -> String {
    let cpu = machine::cpu_model().unwrap_or_else(|| "unknown CPU".to_owned());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut block = String::new();
    let _ = writeln!(
        block,
        "Last run: {cpu}, {threads} threads, {seconds:.1} s. n in {:?}; integrand RMSE over {} \
         patterns, metrics averaged over {} patterns; pattern r is `pattern_seed(r, n, 0, 0)`. \
         The values are seeded, so any machine gives the same tables.\n",
        config.sizes, config.integrand_patterns, config.metric_patterns
    );
    for line in tables.lines() {
        match line.strip_prefix("## ") {
            Some(heading) => {
                let _ = writeln!(block, "### {heading}");
            }
            None => {
                let _ = writeln!(block, "{line}");
            }
        }
    }
    let _ = writeln!(
        block,
        "### Spectra\n\nAt n = {}, mean of {} patterns, |k| up to {}; the run also writes \
         `target/quality/points.svg` (every sampler at n = {}) and the convergence plots.\n",
        config.spectrum_n, config.spectrum_patterns, config.spectrum_radius, config.points_n
    );
    for (_, file, alt) in DOCS_PLOTS {
        let _ = writeln!(block, "![{alt}](images/{file})");
    }
    block
}

/// Replaces the block between [`BEGIN`] and [`END`] in `docs/quality.md`
/// and copies the plots; the page must already have both markers.
fn write_docs(docs: &Path, run_dir: &Path, block: &str) -> Result<(), String> {
    let page_path = docs.join(DOCS_PAGE);
    let page = std::fs::read_to_string(&page_path).map_err(|e| e.to_string())?;
    let (Some(begin), Some(end)) = (page.find(BEGIN), page.find(END)) else {
        return Err(format!("the page lacks the markers {BEGIN:?} and {END:?}"));
    };
    if end < begin {
        return Err("the end marker comes before the begin marker".to_owned());
    }
    let page = format!("{}{BEGIN}\n\n{block}\n{}", &page[..begin], &page[end..]);
    std::fs::write(&page_path, page).map_err(|e| e.to_string())?;
    std::fs::create_dir_all(docs.join("images")).map_err(|e| e.to_string())?;
    for (from, to, _) in DOCS_PLOTS {
        std::fs::copy(run_dir.join(from), docs.join("images").join(to))
            .map_err(|e| format!("copying {from}: {e}"))?;
    }
    Ok(())
}
