//! Argument parsing and output for the `points` example, apart from `main`
//! so that `tests/points_cli.rs` can test them without spawning a process.

use std::ffi::OsString;
use std::fs::File;
use std::io::{self, BufWriter, Write};

use wellspread::{AnySampler, Sampler2D, SamplerKind};

/// What `--help` prints: [`USAGE`] and the sampler names.
pub fn usage() -> String {
    let mut text = String::from(USAGE);
    text += "\nSamplers:";
    for kind in SamplerKind::ALL {
        text += &format!(" {kind}");
    }
    text + "\n"
}

/// The fixed part of the help text.
pub const USAGE: &str = "\
usage: points --sampler NAME --n N [--pattern P] [--format csv|svg] [--out FILE]

Writes the N points of one wellspread sample pattern.

  --sampler NAME   one of the samplers listed below
  --n N            number of points, from 1 to the sampler's limit
  --pattern P      which randomisation, decimal or 0x hex (default 0)
  --format F       csv: one `x,y` line per point, shortest round-trip
                   floats, no header (default); svg: the unit square with
                   the sampler's strata and the points, y pointing up
  --out FILE       write to FILE instead of standard output
  --help           print this and exit

Exit status: 0 on success, 2 for bad arguments, 1 if writing fails.
";

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// One `x,y` line per point.
    Csv,
    /// A picture of the unit square, its strata and the points.
    Svg,
}

/// A parsed command line.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    pub sampler: AnySampler,
    pub pattern: u32,
    pub format: Format,
    pub out: Option<OsString>,
}

/// What the command line asks for.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    Help,
    Run(Options),
}

/// Parses the arguments after the program name. An `Err` is a one-line
/// message for standard error.
pub fn parse<I: IntoIterator<Item = OsString>>(args: I) -> Result<Command, String> {
    let mut sampler = None;
    let mut n = None;
    let mut pattern = None;
    let mut format = None;
    let mut out = None;
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let flag = arg
            .to_str()
            .ok_or_else(|| format!("argument {arg:?} is not valid UTF-8"))?
            .to_owned();
        if flag == "--help" || flag == "-h" {
            return Ok(Command::Help);
        }
        let slot: &mut Option<OsString> = match flag.as_str() {
            "--sampler" => &mut sampler,
            "--n" => &mut n,
            "--pattern" => &mut pattern,
            "--format" => &mut format,
            "--out" => &mut out,
            _ => return Err(format!("unknown argument {flag:?} (try --help)")),
        };
        let value = args
            .next()
            .ok_or_else(|| format!("{flag} needs a value (try --help)"))?;
        if slot.replace(value).is_some() {
            return Err(format!("{flag} given twice"));
        }
    }

    let text = |flag: &str, value: OsString| {
        value
            .into_string()
            .map_err(|v| format!("{flag} {v:?} is not valid UTF-8"))
    };
    let name = text(
        "--sampler",
        sampler.ok_or("--sampler NAME is required (try --help)")?,
    )?;
    let kind: SamplerKind = name
        .parse()
        .map_err(|e| format!("--sampler {name:?}: {e}"))?;
    let n = text("--n", n.ok_or("--n N is required (try --help)")?)?;
    let count: u32 = n
        .parse()
        .map_err(|_| format!("--n {n:?} is not a whole number from 1 to {}", u32::MAX))?;
    let sampler = kind.build(count).map_err(|e| format!("--n {count}: {e}"))?;
    let pattern = match pattern {
        None => 0,
        Some(p) => {
            let p = text("--pattern", p)?;
            parse_u32(&p).ok_or_else(|| {
                format!(
                    "--pattern {p:?} is not a number from 0 to {} (decimal or 0x hex)",
                    u32::MAX
                )
            })?
        }
    };
    let format = match format.map(|f| text("--format", f)).transpose()?.as_deref() {
        None | Some("csv") => Format::Csv,
        Some("svg") => Format::Svg,
        Some(other) => return Err(format!("--format {other:?}: expected csv or svg")),
    };
    Ok(Command::Run(Options {
        sampler,
        pattern,
        format,
        out,
    }))
}

fn parse_u32(text: &str) -> Option<u32> {
    match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => u32::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    }
}

/// Writes the points to `--out` or standard output. A closed pipe (`| head`)
/// is not an error.
pub fn run(options: &Options) -> io::Result<()> {
    let result = match &options.out {
        Some(path) => {
            let mut file = BufWriter::new(File::create(path)?);
            write_points(options, &mut file).and_then(|()| file.flush())
        }
        None => {
            let mut stdout = BufWriter::new(io::stdout().lock());
            write_points(options, &mut stdout).and_then(|()| stdout.flush())
        }
    };
    match result {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
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
        // `{}` on f32 is the shortest text that parses back to the same f32.
        writeln!(out, "{},{}", p.x, p.y)?;
    }
    Ok(())
}

/// What a sampler's picture should show: its coarse grid, if it has one,
/// and whether it is Latin on the fine `n x n` grid.
pub struct Strata {
    pub coarse: Option<(u32, u32)>,
    pub rooks: bool,
}

/// The strata of each sampler; a sampler without a line here is drawn as
/// bare points.
pub fn strata(sampler: &AnySampler) -> Strata {
    let (coarse, rooks) = match sampler {
        AnySampler::Regular(s) => (Some((s.columns(), s.rows())), false),
        AnySampler::Jittered(s) => (Some((s.columns(), s.rows())), false),
        AnySampler::NRooks(_) => (None, true),
        AnySampler::MultiJittered(s) => (Some((s.columns(), s.rows())), true),
        AnySampler::CorrelatedMultiJittered(s) => (Some((s.columns(), s.rows())), true),
        _ => (None, false),
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
