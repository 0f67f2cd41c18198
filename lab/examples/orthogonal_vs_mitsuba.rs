//! wellspread's N-dimensional sets against Mitsuba 3's `orthogonal`
//! sampler: per-pixel RMSE over 1024 patterns on three integrands of 4, 6
//! and 8 dimensions, printed as the Markdown table of `docs/quality.md`.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example orthogonal_vs_mitsuba -- lab/examples/orthogonal_vs_mitsuba.csv
//! ```
//!
//! The CSV holds Mitsuba 3.9.1's figures (`scalar_rgb` variant), written by
//! `lab/examples/orthogonal_vs_mitsuba.py`:
//!
//! ```sh
//! python3 -m venv venv && venv/bin/pip install mitsuba numpy
//! venv/bin/python lab/examples/orthogonal_vs_mitsuba.py > lab/examples/orthogonal_vs_mitsuba.csv
//! ```
//!
//! Without the CSV argument the Mitsuba columns are left out. With
//! `--svg FILE` it also draws the 2D projections of dimension pairs 0-1,
//! 0-6 and 3-5 of one pattern of `orthogonal`, `latin-hypercube` and
//! padded Sobol' pairs at n = 25 and 64 (`docs/images/orthogonal-projections.svg`):
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example orthogonal_vs_mitsuba -- lab/examples/orthogonal_vs_mitsuba.csv \
//!     --svg docs/images/orthogonal-projections.svg
//! ```
//!
//! Integrands (exact values in closed form):
//! - `coupled-4d`: `exp(-((x0 - x2)^2 + (x1 - x3)^2))`, dimensions coupled
//!   across pairs;
//! - `product-6d`, `product-8d`: `prod_k exp(-4 (x_k - 1/2)^2)`.
//!
//! Each pattern is one pixel's set; every sampler fills dimensions 0 to 7
//! of each sample. `orthogonal` sets with fewer than 8 dimensions (`q + 1
//! < 8`) are padded: dimensions from `q + 1` on come from a second array
//! of another pattern, as a renderer pads. `sobol` and `random` are the 2D
//! samplers padded pair by pair (a new pattern per pair of dimensions).

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Parser;
use wellspread::primitives::hash_combine;
use wellspread::{
    LatinHypercube, OrthogonalArray, OrthogonalArrayOffset, Random, Sampler2D, SamplerNd, Sobol,
};

#[path = "shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// The N-dimensional sets against Mitsuba 3's `orthogonal` sampler (the
/// table of docs/quality.md on standard output; about a minute).
#[derive(Parser, Debug)]
pub struct Args {
    /// Mitsuba's figures, as written by orthogonal_vs_mitsuba.py; without
    /// it the Mitsuba columns are left out
    #[arg(value_name = "CSV")]
    pub csv: Option<PathBuf>,
    /// Also draw the 2D projections of three dimension pairs into this SVG
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
}

/// Parses the arguments (without the program name): `Ok(None)` when the
/// help was written to `out`.
pub fn parse(
    args: impl IntoIterator<Item = OsString>,
    out: &mut dyn std::io::Write,
) -> Result<Option<Args>, Failure> {
    shared::parse::<Args>("orthogonal_vs_mitsuba", shared::EXIT_CODES, args, out)
}

/// Patterns (pixels) per RMSE: a relative standard error of about
/// `1 / sqrt(2 * 1024)`, 2.2%.
const PATTERNS: u32 = 1024;

/// The sample counts: squares of primes (Mitsuba's only counts), the
/// powers of two that are squares of prime powers (16 = 4^2, 64 = 8^2,
/// 256 = 16^2, 1024 = 32^2), and 961 = 31^2.
const COUNTS: [u32; 11] = [9, 16, 25, 49, 64, 121, 169, 256, 289, 961, 1024];

const DIMENSIONS: usize = 8;

/// An integrand of the 8 coordinates, with its exact integral.
struct Integrand {
    name: &'static str,
    f: fn(&[f64; DIMENSIONS]) -> f64,
    exact: f64,
}

/// `erf(1)` to 17 digits, for the exact integrals.
const ERF_1: f64 = 0.842_700_792_949_714_9;

/// `prod_k exp(-4 (x_k - 1/2)^2)` over the first `k` coordinates.
fn product(x: &[f64], k: usize) -> f64 {
    x[..k]
        .iter()
        .map(|x| (-4.0 * (x - 0.5) * (x - 0.5)).exp())
        .product()
}

fn integrands() -> [Integrand; 3] {
    let sqrt_pi = std::f64::consts::PI.sqrt();
    // Integral of exp(-4 (x - 1/2)^2) over [0, 1), and of exp(-(a - b)^2)
    // over [0, 1)^2.
    let one_d = sqrt_pi * ERF_1 / 2.0;
    let pair = sqrt_pi * ERF_1 - (1.0 - (-1.0f64).exp());
    [
        Integrand {
            name: "coupled-4d",
            f: |x| (-((x[0] - x[2]).powi(2) + (x[1] - x[3]).powi(2))).exp(),
            exact: pair * pair,
        },
        Integrand {
            name: "product-6d",
            f: |x| product(x, 6),
            exact: one_d.powi(6),
        },
        Integrand {
            name: "product-8d",
            f: |x| product(x, 8),
            exact: one_d.powi(8),
        },
    ]
}

/// A way to fill the 8 coordinates of sample `index` of pattern `pattern`.
trait Fill {
    fn fill(&self, index: u32, pattern: u32, out: &mut [f64; DIMENSIONS]);
}

/// An N-dimensional set, padded with further patterns past its
/// dimensions.
struct Padded<S>(S);

impl<S: SamplerNd> Fill for Padded<S> {
    fn fill(&self, index: u32, pattern: u32, out: &mut [f64; DIMENSIONS]) {
        let d = self.0.dimensions() as usize;
        let mut point = vec![0.0f32; d];
        for (block, chunk) in out.chunks_mut(d).enumerate() {
            let pattern = if block == 0 {
                pattern
            } else {
                hash_combine(pattern, block as u32)
            };
            self.0.sample(index, pattern, &mut point);
            for (o, &x) in chunk.iter_mut().zip(&point) {
                *o = f64::from(x);
            }
        }
    }
}

/// A 2D sampler, a new pattern per pair of dimensions.
struct Pairs<S>(S);

impl<S: Sampler2D> Fill for Pairs<S> {
    fn fill(&self, index: u32, pattern: u32, out: &mut [f64; DIMENSIONS]) {
        for (pair, chunk) in out.chunks_mut(2).enumerate() {
            let p = self.0.sample(index, hash_combine(pattern, pair as u32));
            chunk[0] = f64::from(p.x);
            chunk[1] = f64::from(p.y);
        }
    }
}

/// RMSE of each integrand's estimate over [`PATTERNS`] patterns of `n`
/// samples.
fn rmse(sampler: &dyn Fill, n: u32, integrands: &[Integrand]) -> Vec<f64> {
    let mut squared = vec![0.0; integrands.len()];
    let mut x = [0.0; DIMENSIONS];
    for pattern in 0..PATTERNS {
        let mut sums = vec![0.0; integrands.len()];
        for index in 0..n {
            sampler.fill(index, pattern, &mut x);
            for (sum, integrand) in sums.iter_mut().zip(integrands) {
                *sum += (integrand.f)(&x);
            }
        }
        for ((squared, sum), integrand) in squared.iter_mut().zip(&sums).zip(integrands) {
            let error = sum / f64::from(n) - integrand.exact;
            *squared += error * error;
        }
    }
    squared
        .iter()
        .map(|s| (s / f64::from(PATTERNS)).sqrt())
        .collect()
}

/// The configurations measured at `n`, by column name (those `n` allows).
fn samplers(n: u32) -> Vec<(String, Box<dyn Fill>)> {
    let mut list: Vec<(String, Box<dyn Fill>)> = Vec::new();
    for (name, offset) in [
        ("oa2-cmj", OrthogonalArrayOffset::CorrelatedMultiJittered),
        ("oa2-mj", OrthogonalArrayOffset::MultiJittered),
        ("oa2-j", OrthogonalArrayOffset::Jittered),
    ] {
        if let Ok(probe) = OrthogonalArray::new(n, 1, 2) {
            let d = probe.max_dimensions().min(DIMENSIONS as u32);
            let array = OrthogonalArray::new(n, d, 2).unwrap().with_offset(offset);
            list.push((name.into(), Box::new(Padded(array))));
        }
    }
    for t in [3, 4] {
        if let Ok(probe) = OrthogonalArray::new(n, 1, t) {
            let d = probe.max_dimensions().min(DIMENSIONS as u32);
            let array = OrthogonalArray::new(n, d, t).unwrap();
            list.push((format!("oa{t}-cmj"), Box::new(Padded(array))));
        }
    }
    let cube = LatinHypercube::new(n, DIMENSIONS as u32).unwrap();
    list.push(("latin-hypercube".into(), Box::new(Padded(cube))));
    list.push((
        "sobol-pairs".into(),
        Box::new(Pairs(Sobol::new(n).unwrap())),
    ));
    list.push(("random".into(), Box::new(Pairs(Random::new(n).unwrap()))));
    list
}

/// Mitsuba's figures: `(requested n, integrand) -> (n it rendered, RMSE)`.
pub type MitsubaTable = BTreeMap<(u32, String), (u32, f64)>;

/// Reads the Python script's CSV; a line that is not four fields with a
/// finite RMSE is an input error naming the line.
pub fn read_mitsuba(path: &Path) -> Result<MitsubaTable, Failure> {
    let text = shared::read_text(path, "Mitsuba CSV")?;
    let mut table = BTreeMap::new();
    for (number, line) in text.lines().enumerate().skip(1) {
        let fields: Vec<&str> = line.split(',').collect();
        let parsed = match fields[..] {
            [requested, used, integrand, rmse] => {
                match (requested.parse(), used.parse(), rmse.parse::<f64>()) {
                    (Ok(requested), Ok(used), Ok(rmse)) if rmse.is_finite() => {
                        Some(((requested, integrand.to_owned()), (used, rmse)))
                    }
                    _ => None,
                }
            }
            _ => None,
        };
        let Some((key, value)) = parsed else {
            return Err(Failure::Input(format!(
                "{} line {}: {} is not `requested,used,integrand,rmse`",
                path.display(),
                number + 1,
                shared::quoted(line)
            )));
        };
        table.insert(key, value);
    }
    Ok(table)
}

/// The least-squares slope of `ln rmse` against `ln n`.
fn slope(points: &[(f64, f64)]) -> f64 {
    let logs: Vec<(f64, f64)> = points.iter().map(|&(n, r)| (n.ln(), r.ln())).collect();
    let count = logs.len() as f64;
    let (mx, my) = logs
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / count, b + y / count));
    let (sxy, sxx) = logs.iter().fold((0.0, 0.0), |(sxy, sxx), &(x, y)| {
        (sxy + (x - mx) * (y - my), sxx + (x - mx) * (x - mx))
    });
    sxy / sxx
}

/// The projections picture: rows are (sampler, n), columns dimension
/// pairs; each panel the unit square with the `sqrt(n) x sqrt(n)` grid and
/// the points of pattern 0.
fn projections_svg() -> String {
    const PANEL: f64 = 170.0;
    const GAP: f64 = 24.0;
    const LEFT: f64 = 190.0;
    const TOP: f64 = 40.0;
    let pairs = [(0, 1), (0, 6), (3, 5)];
    let mut rows: Vec<(String, u32, Box<dyn Fill>)> = Vec::new();
    for n in [25, 64] {
        let q = OrthogonalArray::new(n, 1, 2).unwrap().levels();
        let d = (q + 1).min(DIMENSIONS as u32);
        let array = OrthogonalArray::new(n, d, 2).unwrap();
        let what = if q + 1 < 7 {
            format!("orthogonal (dims {}+ padded)", q + 1)
        } else {
            "orthogonal".to_owned()
        };
        rows.push((what, n, Box::new(Padded(array))));
        let cube = LatinHypercube::new(n, DIMENSIONS as u32).unwrap();
        rows.push(("latin-hypercube".to_owned(), n, Box::new(Padded(cube))));
        rows.push((
            "sobol, padded pairs".to_owned(),
            n,
            Box::new(Pairs(Sobol::new(n).unwrap())),
        ));
    }
    let width = LEFT + pairs.len() as f64 * (PANEL + GAP);
    let height = TOP + rows.len() as f64 * (PANEL + GAP);
    let mut svg = String::new();
    writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="13">"#
    )
    .unwrap();
    writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#).unwrap();
    for (c, (a, b)) in pairs.iter().enumerate() {
        let x = LEFT + c as f64 * (PANEL + GAP);
        writeln!(
            svg,
            r#"<text x="{x}" y="{}">dimensions {a} (across) and {b} (up)</text>"#,
            TOP - 14.0
        )
        .unwrap();
    }
    let mut point = [0.0; DIMENSIONS];
    for (r, (name, n, sampler)) in rows.iter().enumerate() {
        let y0 = TOP + r as f64 * (PANEL + GAP);
        writeln!(
            svg,
            r#"<text x="10" y="{}">{name}</text>"#,
            y0 + PANEL / 2.0 - 8.0
        )
        .unwrap();
        writeln!(
            svg,
            r#"<text x="10" y="{}">n = {n}</text>"#,
            y0 + PANEL / 2.0 + 10.0
        )
        .unwrap();
        let points: Vec<[f64; DIMENSIONS]> = (0..*n)
            .map(|index| {
                sampler.fill(index, 0, &mut point);
                point
            })
            .collect();
        let q = (*n as f64).sqrt();
        for (c, &(a, b)) in pairs.iter().enumerate() {
            let x0 = LEFT + c as f64 * (PANEL + GAP);
            for k in 1..q as u32 {
                let t = f64::from(k) / q * PANEL;
                writeln!(
                    svg,
                    r##"<path d="M{:.2} {y0:.2}v{PANEL}M{x0:.2} {:.2}h{PANEL}" stroke="#bbb" stroke-width="0.7"/>"##,
                    x0 + t,
                    y0 + t
                )
                .unwrap();
            }
            writeln!(
                svg,
                r#"<rect x="{x0}" y="{y0}" width="{PANEL}" height="{PANEL}" fill="none" stroke="black"/>"#
            )
            .unwrap();
            for p in &points {
                writeln!(
                    svg,
                    r##"<circle cx="{:.2}" cy="{:.2}" r="2.2" fill="#c0392b"/>"##,
                    x0 + p[a] * PANEL,
                    y0 + (1.0 - p[b]) * PANEL
                )
                .unwrap();
            }
        }
    }
    svg += "</svg>\n";
    svg
}

fn main() -> ExitCode {
    let result = match parse(std::env::args_os().skip(1), &mut std::io::stdout().lock()) {
        Ok(Some(args)) => run(&args),
        Ok(None) => Ok(()),
        Err(failure) => Err(failure),
    };
    shared::exit("orthogonal_vs_mitsuba", result)
}

/// Measures every set, writes the SVG if asked, and prints the tables.
fn run(args: &Args) -> Result<(), Failure> {
    // Inputs and outputs are checked before the minute of measuring.
    let mitsuba = args.csv.as_deref().map(read_mitsuba).transpose()?;
    if let Some(path) = &args.svg {
        let mut file = shared::create_file(path)?;
        file.write_all(projections_svg().as_bytes())
            .map_err(|e| Failure::Io(format!("cannot write {}: {e}", path.display())))?;
    }
    let integrands = integrands();
    // (n, column) -> RMSE per integrand.
    let mut results: BTreeMap<(u32, String), Vec<f64>> = BTreeMap::new();
    let mut columns: Vec<String> = Vec::new();
    for n in COUNTS {
        for (name, sampler) in samplers(n) {
            let r = rmse(sampler.as_ref(), n, &integrands);
            eprintln!(
                "n {n} {name}: {:?}",
                r.iter().map(|x| format!("{x:.3e}")).collect::<Vec<_>>()
            );
            if !columns.contains(&name) {
                columns.push(name.clone());
            }
            results.insert((n, name), r);
        }
    }
    let mut out = String::new();
    for (k, integrand) in integrands.iter().enumerate() {
        writeln!(
            out,
            "\n#### {} (RMSE x 1e4; ratio to Mitsuba in brackets)\n",
            integrand.name
        )
        .unwrap();
        let mut header = String::from("| n |");
        let mut rule = String::from("| ---: |");
        if mitsuba.is_some() {
            header += " mitsuba orthogonal (n used) |";
            rule += " ---: |";
        }
        for column in &columns {
            write!(header, " {column} |").unwrap();
            rule += " ---: |";
        }
        writeln!(out, "{header}\n{rule}").unwrap();
        for n in COUNTS {
            let reference = mitsuba
                .as_ref()
                .and_then(|m| m.get(&(n, integrand.name.to_owned())).copied());
            let mut row = format!("| {n} |");
            if mitsuba.is_some() {
                match reference {
                    Some((used, r)) => write!(row, " {:.2} ({used}) |", r * 1e4).unwrap(),
                    None => row += " |",
                }
            }
            for column in &columns {
                match results.get(&(n, column.clone())) {
                    Some(r) => {
                        write!(row, " {:.2}", r[k] * 1e4).unwrap();
                        if let Some((_, m)) = reference {
                            write!(row, " ({:.2})", r[k] / m).unwrap();
                        }
                        row += " |";
                    }
                    None => row += " - |",
                }
            }
            writeln!(out, "{row}").unwrap();
        }
        // Convergence: the least-squares slope of log RMSE against log n.
        let mut row = String::from("| slope |");
        if let Some(m) = &mitsuba {
            let mut used: Vec<(f64, f64)> = m
                .iter()
                .filter(|((_, name), _)| name == integrand.name)
                .map(|(_, &(used, r))| (f64::from(used), r))
                .collect();
            used.dedup_by(|a, b| a.0 == b.0);
            write!(row, " {:.2} |", slope(&used)).unwrap();
        }
        for column in &columns {
            let points: Vec<(f64, f64)> = COUNTS
                .iter()
                .filter_map(|&n| {
                    results
                        .get(&(n, column.clone()))
                        .map(|r| (f64::from(n), r[k]))
                })
                .collect();
            if points.len() >= 3 {
                write!(row, " {:.2} |", slope(&points)).unwrap();
            } else {
                row += " - |";
            }
        }
        writeln!(out, "{row}").unwrap();
    }
    // Variance per sample at the prime-power counts against Mitsuba's at
    // the count it rounds them up to.
    if let Some(m) = &mitsuba {
        writeln!(
            out,
            "\n#### Variance per sample (RMSE^2 x n) of oa2-cmj at prime-power counts, \
             over Mitsuba's at the count it renders instead\n"
        )
        .unwrap();
        writeln!(
            out,
            "| n | Mitsuba renders | coupled-4d | product-6d | product-8d |"
        )
        .unwrap();
        writeln!(out, "| ---: | ---: | ---: | ---: | ---: |").unwrap();
        for n in [16, 64, 256, 1024] {
            let Some(ours) = results.get(&(n, "oa2-cmj".to_owned())) else {
                continue;
            };
            let mut row = String::new();
            let mut used_by_mitsuba = 0;
            for (k, integrand) in integrands.iter().enumerate() {
                let Some(&(used, r)) = m.get(&(n, integrand.name.to_owned())) else {
                    continue;
                };
                used_by_mitsuba = used;
                let ratio = ours[k].powi(2) * f64::from(n) / (r * r * f64::from(used));
                write!(row, " {ratio:.2} |").unwrap();
            }
            writeln!(out, "| {n} | {used_by_mitsuba} |{row}").unwrap();
        }
    }
    std::io::stdout()
        .write_all(out.as_bytes())
        .map_err(|e| Failure::Io(format!("cannot write the table: {e}")))
}
