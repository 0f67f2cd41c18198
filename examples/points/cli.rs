//! Argument parsing and output for the `points` example, apart from `main`
//! so that `tests/points_cli.rs` can test them without spawning a process.

use std::ffi::OsString;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::PathBuf;

use clap::{Parser, ValueEnum};
use wellspread::{AnySampler, Sampler2D, SamplerKind};

#[path = "../shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// Writes the N points of one wellspread sample pattern.
#[derive(Parser, Debug)]
pub struct Args {
    /// Sampler name, one of those listed below
    #[arg(long, value_name = "NAME", value_parser = shared::sampler_kind)]
    pub sampler: SamplerKind,
    /// Number of points, from 1 to the sampler's limit
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = shared::whole_number)]
    pub n: u32,
    /// Which randomisation, decimal or 0x hex
    #[arg(long, value_name = "P", default_value = "0", value_parser = shared::u32_dec_or_hex)]
    pub pattern: u32,
    /// Output format (see below)
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub format: Format,
    /// Write to FILE instead of standard output
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// What `--help` prints after the options.
pub fn after_help() -> String {
    format!(
        "\
Samplers: {}

Output: csv (default) is one `x,y` line per point, no header. Each value is
the shortest decimal of the f32 widened to f64, so f32 and f64 parsers
(Rust, numpy, pandas) both read back the exact f32 the sampler returned.
svg is the unit square with the sampler's strata and the points, y up.

{}",
        shared::sampler_names(),
        shared::EXIT_CODES
    )
}

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One `x,y` line per point
    Csv,
    /// A picture of the unit square, its strata and the points
    Svg,
}

/// A checked command line.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    pub sampler: AnySampler,
    pub pattern: u32,
    pub format: Format,
    pub out: Option<PathBuf>,
}

/// Parses the arguments after the program name. `Ok(None)`: the help was
/// written to `help_out`.
pub fn parse<I: IntoIterator<Item = OsString>>(
    args: I,
    help_out: &mut dyn Write,
) -> Result<Option<Options>, Failure> {
    let Some(args) = shared::parse::<Args>("points", &after_help(), args, help_out)? else {
        return Ok(None);
    };
    let sampler = args
        .sampler
        .build(args.n)
        .map_err(|e| Failure::Input(format!("--n {}: {e}", args.n)))?;
    Ok(Some(Options {
        sampler,
        pattern: args.pattern,
        format: args.format,
        out: args.out,
    }))
}

/// The whole tool: parses `args`, writes the points to `--out` or
/// `stdout` (the help too), and returns the outcome for
/// [`shared::finish`].
pub fn main_with<I: IntoIterator<Item = OsString>>(
    args: I,
    stdout: &mut dyn Write,
) -> Result<(), Failure> {
    match parse(args, stdout)? {
        None => Ok(()),
        Some(options) => run(&options, stdout),
    }
}

/// Writes the points to `--out` or `stdout`. A closed pipe (`| head`) is
/// not an error.
pub fn run(options: &Options, stdout: &mut dyn Write) -> Result<(), Failure> {
    let result = match &options.out {
        Some(path) => {
            let file = File::create(path)
                .map_err(|e| Failure::Io(format!("cannot create {}: {e}", path.display())))?;
            let mut file = BufWriter::new(file);
            write_points(options, &mut file).and_then(|()| file.flush())
        }
        None => {
            let mut stdout = BufWriter::new(stdout);
            write_points(options, &mut stdout).and_then(|()| stdout.flush())
        }
    };
    match result {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(Failure::Io(format!("cannot write the points: {e}"))),
        Ok(()) => Ok(()),
    }
}

/// Writes the set in the chosen format.
pub fn write_points(options: &Options, out: &mut dyn Write) -> io::Result<()> {
    match options.format {
        Format::Csv => write_csv(&options.sampler, options.pattern, out),
        Format::Svg => write_svg(&options.sampler, options.pattern, out),
    }
}

fn write_csv(sampler: &AnySampler, pattern: u32, out: &mut dyn Write) -> io::Result<()> {
    for index in 0..sampler.len() {
        let p = sampler.sample(index, pattern);
        writeln!(out, "{},{}", csv_value(p.x), csv_value(p.y))?;
    }
    Ok(())
}

/// One CSV value: the shortest decimal that parses back to the f32
/// widened to f64. Parsed as f64 it is that f64 exactly, and parsed as f32
/// it is the f32, because the decimal is within half an f64 ulp of it,
/// far inside the f32 rounding interval. (The shortest f32 decimal can be
/// up to half an f32 ulp away, which an f64 reader keeps.)
pub fn csv_value(v: f32) -> String {
    format!("{}", f64::from(v))
}

/// What a sampler's picture should show: its coarse grid, if it has one,
/// and whether it is Latin on the fine `n x n` grid.
pub struct Strata {
    pub coarse: Option<(u32, u32)>,
    pub rooks: bool,
}

/// The strata of each sampler. The sequences and `random` have no grid to
/// draw: their points are drawn bare. Every kind has its line, so a new
/// kind is a compile error here until it says what to draw.
pub fn strata(sampler: &AnySampler) -> Strata {
    let (coarse, rooks) = match sampler {
        AnySampler::Regular(s) => (Some((s.columns(), s.rows())), false),
        AnySampler::Jittered(s) => (Some((s.columns(), s.rows())), false),
        AnySampler::NRooks(_) => (None, true),
        AnySampler::MultiJittered(s) => (Some((s.columns(), s.rows())), true),
        AnySampler::CorrelatedMultiJittered(s) => (Some((s.columns(), s.rows())), true),
        AnySampler::BlueMultiJittered(s) => (Some((s.columns(), s.rows())), true),
        AnySampler::Random(_)
        | AnySampler::Hammersley(_)
        | AnySampler::Halton(_)
        | AnySampler::Sobol(_)
        | AnySampler::Pmj02(_) => (None, false),
    };
    Strata { coarse, rooks }
}

/// Fine grid lines are drawn up to this n, coarse ones up to this many
/// per axis: denser lines would only grey the square out.
pub const MAX_FINE_LINES: u32 = 64;
pub const MAX_COARSE_LINES: u32 = 256;

/// Side of the unit square in SVG user units, and the margin around it.
const SIDE: f64 = 512.0;
const MARGIN: f64 = 16.0;

fn write_svg(sampler: &AnySampler, pattern: u32, out: &mut dyn Write) -> io::Result<()> {
    let n = sampler.len();
    let kind = sampler.kind();
    let strata = strata(sampler);
    // Unit coordinates to SVG: x right, y up (SVG's y points down).
    let sx = |x: f64| MARGIN + x * SIDE;
    let sy = |y: f64| MARGIN + (1.0 - y) * SIDE;
    let (width, height) = (SIDE + 2.0 * MARGIN, SIDE + 2.0 * MARGIN + 40.0);

    let title = format!("{kind}, n = {n}, pattern {pattern:#x}");
    let guarantee = match (strata.coarse, strata.rooks) {
        (Some((columns, rows)), false) => format!("one point per cell of {columns} x {rows}"),
        (Some((columns, rows)), true) => {
            format!("one point per cell of {columns} x {rows} and per row and column of {n} x {n}")
        }
        (None, true) => format!("one point per row and column of {n} x {n}"),
        (None, false) => String::new(),
    };
    let caption = if guarantee.is_empty() {
        title.clone()
    } else {
        format!("{title}: {guarantee}")
    };

    writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    )?;
    writeln!(out, "<title>{caption}</title>")?;
    writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#)?;

    let line = |out: &mut dyn Write, t: f64, vertical: bool, style: &str| {
        if vertical {
            writeln!(
                out,
                r#"<line x1="{0:.3}" y1="{1:.3}" x2="{0:.3}" y2="{2:.3}" {style}/>"#,
                sx(t),
                sy(0.0),
                sy(1.0)
            )
        } else {
            writeln!(
                out,
                r#"<line x1="{1:.3}" y1="{0:.3}" x2="{2:.3}" y2="{0:.3}" {style}/>"#,
                sy(t),
                sx(0.0),
                sx(1.0)
            )
        }
    };
    if strata.rooks && n <= MAX_FINE_LINES {
        writeln!(out, r#"<g id="fine-grid">"#)?;
        for k in 1..n {
            let t = k as f64 / n as f64;
            line(out, t, true, r##"stroke="#d8d8d8" stroke-width="0.5""##)?;
            line(out, t, false, r##"stroke="#d8d8d8" stroke-width="0.5""##)?;
        }
        writeln!(out, "</g>")?;
    }
    if let Some((columns, rows)) = strata.coarse {
        writeln!(out, r#"<g id="coarse-grid">"#)?;
        let style = r##"stroke="#7a7a7a" stroke-width="1""##;
        if columns <= MAX_COARSE_LINES {
            for c in 1..columns {
                line(out, c as f64 / columns as f64, true, style)?;
            }
        }
        if rows <= MAX_COARSE_LINES {
            for r in 1..rows {
                line(out, r as f64 / rows as f64, false, style)?;
            }
        }
        writeln!(out, "</g>")?;
    }
    writeln!(
        out,
        r#"<rect x="{MARGIN}" y="{MARGIN}" width="{SIDE}" height="{SIDE}" fill="none" stroke="black" stroke-width="1.5"/>"#
    )?;

    // Dots shrink as n grows so that neighbours stay apart.
    let radius = (SIDE / (n as f64).sqrt() / 5.0).clamp(0.75, 4.0);
    writeln!(out, r##"<g id="points" fill="#c0392b">"##)?;
    for index in 0..n {
        let p = sampler.sample(index, pattern);
        writeln!(
            out,
            r#"<circle cx="{:.3}" cy="{:.3}" r="{radius:.2}"/>"#,
            sx(p.x as f64),
            sy(p.y as f64)
        )?;
    }
    writeln!(out, "</g>")?;
    for (line_number, text) in [title, guarantee].iter().enumerate() {
        writeln!(
            out,
            r#"<text x="{MARGIN}" y="{:.1}" font-family="sans-serif" font-size="13">{text}</text>"#,
            SIDE + MARGIN + 20.0 + 17.0 * line_number as f64
        )?;
    }
    writeln!(out, "</svg>")
}
