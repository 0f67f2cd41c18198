//! Argument parsing and output for the `points` example, apart from `main`
//! so that `tests/points_cli.rs` can test them without spawning a process.

use std::ffi::OsString;
use std::io::{self, BufWriter, Write};
use std::path::PathBuf;

use clap::{Parser, ValueEnum};
use wellspread::{
    AnySampler, Faure4D, LatinHypercube, OrthogonalArray, OrthogonalArrayOffset, Sampler2D,
    SamplerKind, SamplerNd, Sobol4D,
};

#[path = "../shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// Writes the N points of one wellspread sample pattern.
#[derive(Parser, Debug)]
pub struct Args {
    /// Sampler name, one of those listed below
    #[arg(long, value_name = "NAME", value_parser = sampler_name)]
    pub sampler: SamplerName,
    /// Number of points, from 1 to the sampler's limit
    #[arg(long, value_name = "N", value_parser = shared::whole_number)]
    pub n: u32,
    /// Which randomisation, decimal or 0x hex
    #[arg(long, value_name = "P", default_value = "0", value_parser = shared::u32_dec_or_hex)]
    pub pattern: u32,
    /// Coordinates per point: 2 for the 2D samplers; 1 to the set's limit
    /// for latin-hypercube and orthogonal, 4 for sobol-4d and faure-4d
    #[arg(long, value_name = "D", default_value = "2", value_parser = shared::whole_number)]
    pub dimensions: u32,
    /// Strength of an orthogonal array: 2, 3 or 4
    #[arg(long, value_name = "T", default_value = "2", value_parser = shared::whole_number)]
    pub strength: u32,
    /// Offsets of an orthogonal array
    #[arg(long, value_enum, default_value_t = Offset::CorrelatedMultiJittered)]
    pub offset: Offset,
    /// The two dimensions an svg of latin-hypercube or orthogonal shows
    #[arg(long, value_name = "I,J", default_value = "0,1", value_parser = projection)]
    pub projection: Projection,
    /// Output format (see below)
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub format: Format,
    /// Write to FILE instead of standard output (missing folders are
    /// created)
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// What `--help` prints after the options.
pub fn after_help() -> String {
    format!(
        "\
Samplers: {}
N-dimensional sets (with --dimensions): {}

Output: csv (default) is one `x,y` line per point (one value per dimension
for latin-hypercube and orthogonal), no header. Each value is the shortest
decimal of the f32 widened to f64, so f32 and f64 parsers (Rust, numpy,
pandas) both read back the exact f32 the sampler returned. svg is the unit
square with the sampler's strata and the points, y up (for an
N-dimensional set, the --projection pair of dimensions).

{}",
        shared::sampler_names(),
        ND_NAMES.join(" "),
        shared::EXIT_CODES
    )
}

/// The N-dimensional sets the tool writes besides the [`SamplerKind`]s.
pub const ND_NAMES: [&str; 4] = ["latin-hypercube", "orthogonal", "sobol-4d", "faure-4d"];

/// What `--sampler` names: a 2D sampler or an N-dimensional set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SamplerName {
    /// A [`SamplerKind`].
    Plane(SamplerKind),
    /// [`LatinHypercube`].
    LatinHypercube,
    /// [`OrthogonalArray`].
    Orthogonal,
    /// [`Sobol4D`].
    Sobol4D,
    /// [`Faure4D`].
    Faure4D,
}

/// `--sampler`'s parser: a [`SamplerKind`] name or one of [`ND_NAMES`].
pub fn sampler_name(name: &str) -> Result<SamplerName, String> {
    match name {
        "latin-hypercube" => Ok(SamplerName::LatinHypercube),
        "orthogonal" => Ok(SamplerName::Orthogonal),
        "sobol-4d" => Ok(SamplerName::Sobol4D),
        "faure-4d" => Ok(SamplerName::Faure4D),
        _ => shared::sampler_kind(name)
            .map(SamplerName::Plane)
            .map_err(|e| format!("{e}, or N-dimensional: {}", ND_NAMES.join(" "))),
    }
}

/// `--offset`: [`OrthogonalArrayOffset`] by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Offset {
    /// Jittered inside each level's stratum
    Jittered,
    /// Latin in every dimension, a sub-stratum order per level
    MultiJittered,
    /// Latin in every dimension, one sub-stratum order per dimension
    CorrelatedMultiJittered,
}

impl From<Offset> for OrthogonalArrayOffset {
    fn from(offset: Offset) -> Self {
        match offset {
            Offset::Jittered => Self::Jittered,
            Offset::MultiJittered => Self::MultiJittered,
            Offset::CorrelatedMultiJittered => Self::CorrelatedMultiJittered,
        }
    }
}

/// `--projection`: two dimension indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Projection(pub [u32; 2]);

/// `--projection`'s parser: `I,J`, two whole numbers.
pub fn projection(text: &str) -> Result<Projection, String> {
    let (i, j) = text
        .split_once(',')
        .ok_or_else(|| format!("{} is not two dimensions I,J", shared::quoted(text)))?;
    Ok(Projection([
        shared::whole_number(i)?,
        shared::whole_number(j)?,
    ]))
}

/// An N-dimensional set the tool writes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NdSet {
    LatinHypercube(LatinHypercube),
    Orthogonal(OrthogonalArray),
    Sobol4D(Sobol4D),
    Faure4D(Faure4D),
}

impl SamplerNd for NdSet {
    fn len(&self) -> u32 {
        match self {
            NdSet::LatinHypercube(s) => s.len(),
            NdSet::Orthogonal(s) => s.len(),
            NdSet::Sobol4D(s) => s.len(),
            NdSet::Faure4D(s) => s.len(),
        }
    }

    fn dimensions(&self) -> u32 {
        match self {
            NdSet::LatinHypercube(s) => s.dimensions(),
            NdSet::Orthogonal(s) => s.dimensions(),
            NdSet::Sobol4D(s) => s.dimensions(),
            NdSet::Faure4D(s) => s.dimensions(),
        }
    }

    fn coordinate(&self, index: u32, pattern: u32, dimension: u32) -> f32 {
        match self {
            NdSet::LatinHypercube(s) => s.coordinate(index, pattern, dimension),
            NdSet::Orthogonal(s) => s.coordinate(index, pattern, dimension),
            NdSet::Sobol4D(s) => s.coordinate(index, pattern, dimension),
            NdSet::Faure4D(s) => s.coordinate(index, pattern, dimension),
        }
    }

    fn sample(&self, index: u32, pattern: u32, out: &mut [f32]) {
        match self {
            NdSet::LatinHypercube(s) => s.sample(index, pattern, out),
            NdSet::Orthogonal(s) => s.sample(index, pattern, out),
            NdSet::Sobol4D(s) => s.sample(index, pattern, out),
            NdSet::Faure4D(s) => s.sample(index, pattern, out),
        }
    }
}

/// The set the tool writes: a 2D sampler or an N-dimensional set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PointSet {
    Plane(AnySampler),
    Nd(NdSet),
}

// Read by tests/points_cli.rs, not by the tool itself.
#[allow(dead_code)]
impl PointSet {
    /// Number of points.
    pub fn len(&self) -> u32 {
        match self {
            PointSet::Plane(s) => s.len(),
            PointSet::Nd(s) => s.len(),
        }
    }

    /// The 2D sampler's kind, if it is one.
    pub fn kind(&self) -> Option<SamplerKind> {
        match self {
            PointSet::Plane(s) => Some(s.kind()),
            PointSet::Nd(_) => None,
        }
    }
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
    pub sampler: PointSet,
    pub projection: [u32; 2],
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
    let n = args.n;
    let d = args.dimensions;
    let four_dimensions = |name: &str| {
        if d == 4 {
            Ok(())
        } else {
            Err(Failure::Input(format!(
                "--dimensions {d}: {name} has 4 dimensions"
            )))
        }
    };
    let n_checked = |e: wellspread::Error| Failure::Input(format!("--n {n}: {e}"));
    let sampler = match args.sampler {
        SamplerName::Plane(kind) => {
            if d != 2 {
                return Err(Failure::Input(format!(
                    "--dimensions {d}: {kind} is a 2D sampler; N-dimensional: {}",
                    ND_NAMES.join(" ")
                )));
            }
            PointSet::Plane(kind.build(n).map_err(n_checked)?)
        }
        SamplerName::LatinHypercube => PointSet::Nd(NdSet::LatinHypercube(
            LatinHypercube::new(n, d)
                .map_err(|e| Failure::Input(format!("--n {n} --dimensions {d}: {e}")))?,
        )),
        SamplerName::Orthogonal => PointSet::Nd(NdSet::Orthogonal(
            OrthogonalArray::new(n, d, args.strength)
                .map_err(|e| {
                    Failure::Input(format!(
                        "--n {n} --dimensions {d} --strength {}: {e}",
                        args.strength
                    ))
                })?
                .with_offset(args.offset.into()),
        )),
        SamplerName::Sobol4D => {
            four_dimensions("sobol-4d")?;
            PointSet::Nd(NdSet::Sobol4D(Sobol4D::new(n).map_err(n_checked)?))
        }
        SamplerName::Faure4D => {
            four_dimensions("faure-4d")?;
            PointSet::Nd(NdSet::Faure4D(Faure4D::new(n).map_err(n_checked)?))
        }
    };
    let projection = args.projection.0;
    if let PointSet::Nd(set) = sampler
        && args.format == Format::Svg
        && (projection[0] >= d || projection[1] >= d || projection[0] == projection[1])
    {
        return Err(Failure::Input(format!(
            "--projection {},{}: two different dimensions below {}",
            projection[0],
            projection[1],
            set.dimensions()
        )));
    }
    Ok(Some(Options {
        sampler,
        projection,
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
/// not an error: [`Failure::OutputClosed`], exit status 0, no message.
pub fn run(options: &Options, stdout: &mut dyn Write) -> Result<(), Failure> {
    let result = match &options.out {
        Some(path) => {
            let mut file = BufWriter::new(shared::create_file(path)?);
            write_points(options, &mut file).and_then(|()| file.flush())
        }
        None => {
            let mut stdout = BufWriter::new(stdout);
            write_points(options, &mut stdout).and_then(|()| stdout.flush())
        }
    };
    shared::written(result, "the points")
}

/// Writes the set in the chosen format.
pub fn write_points(options: &Options, out: &mut dyn Write) -> io::Result<()> {
    let pattern = options.pattern;
    match (options.format, &options.sampler) {
        (Format::Csv, PointSet::Plane(sampler)) => write_csv(sampler, pattern, out),
        (Format::Csv, PointSet::Nd(set)) => write_csv_nd(set, pattern, out),
        (Format::Svg, PointSet::Plane(sampler)) => {
            let picture = Picture {
                title: format!(
                    "{}, n = {}, pattern {pattern:#x}",
                    sampler.kind(),
                    sampler.len()
                ),
                n: sampler.len(),
                strata: strata(sampler),
            };
            write_svg(&picture, |index| sampler.sample(index, pattern).into(), out)
        }
        (Format::Svg, PointSet::Nd(set)) => {
            let [i, j] = options.projection;
            let (name, strata) = match set {
                NdSet::LatinHypercube(_) => (
                    "latin-hypercube".to_owned(),
                    Strata {
                        coarse: None,
                        rooks: true,
                    },
                ),
                NdSet::Sobol4D(_) => (
                    "sobol-4d".to_owned(),
                    Strata {
                        coarse: None,
                        rooks: false,
                    },
                ),
                // Every power-of-two prefix is stratified in each dimension;
                // from 16 points every pair fills 4 x 4.
                NdSet::Faure4D(faure) => (
                    "faure-4d".to_owned(),
                    Strata {
                        coarse: (faure.len().is_power_of_two() && faure.len() >= 16)
                            .then_some((4, 4)),
                        rooks: faure.len().is_power_of_two(),
                    },
                ),
                NdSet::Orthogonal(array) => (
                    format!(
                        "orthogonal (strength {}, {:?})",
                        array.strength(),
                        array.offset()
                    ),
                    Strata {
                        coarse: Some((array.levels(), array.levels())),
                        rooks: array.offset() != OrthogonalArrayOffset::Jittered,
                    },
                ),
            };
            let picture = Picture {
                title: format!(
                    "{name}, n = {}, {} dimensions, {i} across and {j} up, pattern {pattern:#x}",
                    set.len(),
                    set.dimensions()
                ),
                n: set.len(),
                strata,
            };
            let mut point = vec![0.0; set.dimensions() as usize];
            write_svg(
                &picture,
                |index| {
                    set.sample(index, pattern, &mut point);
                    [point[i as usize], point[j as usize]]
                },
                out,
            )
        }
    }
}

fn write_csv(sampler: &AnySampler, pattern: u32, out: &mut dyn Write) -> io::Result<()> {
    for index in 0..sampler.len() {
        let p = sampler.sample(index, pattern);
        writeln!(out, "{},{}", csv_value(p.x), csv_value(p.y))?;
    }
    Ok(())
}

/// One line per point, one value per dimension.
fn write_csv_nd(set: &NdSet, pattern: u32, out: &mut dyn Write) -> io::Result<()> {
    let mut point = vec![0.0; set.dimensions() as usize];
    let mut line = String::new();
    for index in 0..set.len() {
        set.sample(index, pattern, &mut point);
        line.clear();
        for (k, &x) in point.iter().enumerate() {
            if k > 0 {
                line.push(',');
            }
            line += &csv_value(x);
        }
        writeln!(out, "{line}")?;
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

/// What a picture shows besides its points.
struct Picture {
    title: String,
    n: u32,
    strata: Strata,
}

fn write_svg(
    picture: &Picture,
    mut point: impl FnMut(u32) -> [f32; 2],
    out: &mut dyn Write,
) -> io::Result<()> {
    let n = picture.n;
    let strata = &picture.strata;
    // Unit coordinates to SVG: x right, y up (SVG's y points down).
    let sx = |x: f64| MARGIN + x * SIDE;
    let sy = |y: f64| MARGIN + (1.0 - y) * SIDE;
    let (width, height) = (SIDE + 2.0 * MARGIN, SIDE + 2.0 * MARGIN + 40.0);

    let title = picture.title.clone();
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
        let [x, y] = point(index);
        writeln!(
            out,
            r#"<circle cx="{:.3}" cy="{:.3}" r="{radius:.2}"/>"#,
            sx(x as f64),
            sy(y as f64)
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
