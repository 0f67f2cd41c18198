//! Every metric of a point set, as one JSON object.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example metrics -- points.csv
//! cargo run --release -p wellspread-lab --example metrics -- --stratified 8x8 - < points.csv
//! cargo run --release -p wellspread-lab --example points -- --sampler orthogonal --n 64 --dimensions 5 --strength 3 \
//!     | cargo run --release -p wellspread-lab --example metrics -- --dimensions 5 --levels 4 --strength 3
//! ```
//!
//! Run with `--help` for the input and output formats and the exit codes.

use std::ffi::OsString;
use std::io::{self, BufRead, Read, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use wellspread::glam::Vec2;
use wellspread::metrics;

#[path = "shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// Every metric of a 2D point set in [0, 1)^2, as one JSON object.
#[derive(Parser, Debug)]
pub struct Args {
    /// Also report `is_stratified` on a grid of M columns and K rows
    #[arg(long, value_name = "MxK", value_parser = parse_grid)]
    pub stratified: Option<(u32, u32)>,
    /// Values per line: 2 for the 2D metrics (default); 1, or 3 to 65536,
    /// for an N-dimensional set, checked projection by projection
    #[arg(long, value_name = "D", default_value = "2", value_parser = parse_dimensions)]
    pub dimensions: usize,
    /// With --dimensions other than 2: check every projection onto 1 to
    /// --strength dimensions for equal counts in the Q^k cells
    #[arg(long, value_name = "Q", value_parser = parse_levels)]
    pub levels: Option<u32>,
    /// The largest projection --levels checks, 1 to 4
    #[arg(long, value_name = "T", default_value = "2", value_parser = parse_strength)]
    pub strength: usize,
    /// CSV file to read; standard input when absent or `-`
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,
}

/// What `--help` prints after the options.
pub const AFTER_HELP: &str = "\
Input: CSV with one `x,y` point per line, each coordinate in [0, 1) and
read as f32. Blank lines are ignored, and so are a UTF-8 byte-order mark
and a first line with no digit and no number in it (a header such as
`x,y`); any other line that is not two numbers is an error naming its
line, so a typo such as `O.5,O.5` is never skipped as a header. A line
may hold up to 1024 bytes, or 128 bytes per number with --dimensions D
(so any line `points --dimensions D` writes); a longer line is an error.

Output: one JSON object on one line with the fields `n`,
`star_discrepancy`, `l2_star_discrepancy`, `centered_l2_discrepancy`,
`wraparound_l2_discrepancy`, `min_distance`, `toroidal_min_distance`,
`normalized_toroidal_min_distance`, `is_latin`, `is_net_base2`, `t_value`
(the smallest t for which the set is a (t, m, 2)-net in base 2) and, with
--stratified, `is_stratified`. A metric that is not defined for the set
is `null`: the distances need two points, `is_net_base2` and `t_value`
need n = 2^m.
Numbers are f64 in shortest round-trip form.

With --dimensions D other than 2, each line holds D numbers and the
object has `n`, `dimensions`, `is_latin` (every 1D projection has one
point in each of its n strata) and `non_latin_dimension` (the first that
is not, or null); with --levels Q, for k = 1 to --strength,
`stratified_<k>d` (every projection onto k dimensions has the same count
in each of its Q^k cells; null if Q^k does not divide n) and
`unstratified_<k>d` (the first projection that is not, as an array of
dimensions, or null).
";

fn main() -> ExitCode {
    let result = main_with(
        std::env::args_os().skip(1),
        &mut io::stdin().lock(),
        &mut io::stdout().lock(),
    );
    shared::exit("metrics", result)
}

/// The whole tool: parses `args`, reads the points from the file or
/// `stdin`, and writes the JSON line (or the help) to `stdout`.
pub fn main_with(
    args: impl IntoIterator<Item = OsString>,
    stdin: &mut dyn Read,
    stdout: &mut dyn Write,
) -> Result<(), Failure> {
    let after_help = format!("{AFTER_HELP}\n{}", shared::EXIT_CODES);
    let Some(args) = shared::parse::<Args>("metrics", &after_help, args, stdout)? else {
        return Ok(());
    };
    if args.dimensions != 2 {
        let read = |reader: &mut dyn BufRead, size: u64, source: &str| {
            let mut rows = Rows {
                dimensions: args.dimensions,
                values: Vec::new(),
            };
            read_records(reader, size, args.dimensions, &mut rows)
                .map(|()| rows)
                .map_err(|e| match e {
                    ReadError::Input(message) => Failure::Input(message),
                    ReadError::Io(e) => Failure::Io(format!("cannot read {source}: {e}")),
                })
        };
        let rows = match &args.file {
            Some(path) if path.as_os_str() != "-" => {
                let file = std::fs::File::open(path)
                    .map_err(|e| Failure::Io(format!("cannot read {}: {e}", path.display())))?;
                let size = file.metadata().map_or(0, |m| m.len());
                read(
                    &mut io::BufReader::new(file),
                    size,
                    &path.display().to_string(),
                )?
            }
            _ => read(&mut io::BufReader::new(stdin), 0, "standard input")?,
        };
        let json = report_nd(&rows, args.levels, args.strength).map_err(Failure::Input)?;
        return writeln!(stdout, "{json}")
            .map_err(|e| Failure::Io(format!("cannot write the report: {e}")));
    }
    if args.levels.is_some() {
        return Err(Failure::Input(
            "--levels checks N-dimensional sets: give --dimensions (1, or more than 2); \
             for 2D sets use --stratified MxK"
                .to_owned(),
        ));
    }
    let points = match &args.file {
        Some(path) if path.as_os_str() != "-" => {
            let file = std::fs::File::open(path)
                .map_err(|e| Failure::Io(format!("cannot read {}: {e}", path.display())))?;
            let size = file.metadata().map_or(0, |m| m.len());
            read_points(&mut io::BufReader::new(file), size).map_err(|e| match e {
                ReadError::Input(message) => Failure::Input(message),
                ReadError::Io(e) => Failure::Io(format!("cannot read {}: {e}", path.display())),
            })?
        }
        _ => read_points(&mut io::BufReader::new(stdin), 0).map_err(|e| match e {
            ReadError::Input(message) => Failure::Input(message),
            ReadError::Io(e) => Failure::Io(format!("cannot read standard input: {e}")),
        })?,
    };
    let json = report(&points, args.stratified).map_err(Failure::Input)?;
    writeln!(stdout, "{json}").map_err(|e| Failure::Io(format!("cannot write the report: {e}")))
}

/// Parses `M x K` as in `8x8`.
pub fn parse_grid(text: &str) -> Result<(u32, u32), String> {
    shared::non_negative(text)?;
    let side = |s: &str| s.trim().parse::<u32>().ok().filter(|&v| v > 0);
    text.split_once(['x', 'X'])
        .and_then(|(m, k)| Some((side(m)?, side(k)?)))
        .ok_or_else(|| {
            format!(
                "{} is not a grid MxK of two whole numbers from 1, e.g. 8x8",
                shared::quoted(text)
            )
        })
}

/// `--dimensions`: a whole number from 1 to [`MAX_DIMENSIONS`].
pub fn parse_dimensions(text: &str) -> Result<usize, String> {
    match shared::whole_number(text)? as usize {
        0 => Err("a point has at least 1 dimension, got 0".to_owned()),
        d if d > MAX_DIMENSIONS => Err(format!(
            "at most {MAX_DIMENSIONS} dimensions (the most points writes), got {d}"
        )),
        d => Ok(d),
    }
}

/// `--levels`: a whole number from 1.
pub fn parse_levels(text: &str) -> Result<u32, String> {
    match shared::whole_number(text)? {
        0 => Err("a projection has at least 1 level per dimension, got 0".to_owned()),
        q => Ok(q),
    }
}

/// `--strength`: 1 to 4.
pub fn parse_strength(text: &str) -> Result<usize, String> {
    match shared::whole_number(text)? {
        t @ 1..=4 => Ok(t as usize),
        t => Err(format!(
            "projections of 1 to 4 dimensions are checked, got {t}"
        )),
    }
}

/// Where [`read_records`] puts each line's numbers.
pub trait Records {
    /// Room for `additional` more lines.
    fn reserve(&mut self, additional: usize);
    /// One line's numbers, as many as the reader was asked for.
    fn push(&mut self, values: &[f32]);
    /// Whether no line was pushed.
    fn is_empty(&self) -> bool;
}

impl Records for Vec<Vec2> {
    fn reserve(&mut self, additional: usize) {
        self.reserve_exact(additional);
    }
    fn push(&mut self, values: &[f32]) {
        Vec::push(self, Vec2::new(values[0], values[1]));
    }
    fn is_empty(&self) -> bool {
        Vec::is_empty(self)
    }
}

/// The points of an N-dimensional set, `dimensions` values each, flat.
#[derive(Debug)]
pub struct Rows {
    pub dimensions: usize,
    pub values: Vec<f32>,
}

impl Records for Rows {
    fn reserve(&mut self, additional: usize) {
        self.values.reserve_exact(additional * self.dimensions);
    }
    fn push(&mut self, values: &[f32]) {
        self.values.extend_from_slice(values);
    }
    fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
}

/// Why [`read_points`] stopped.
#[derive(Debug)]
pub enum ReadError {
    /// Bad input: a one-line message naming the line and column.
    Input(String),
    /// Reading failed.
    Io(io::Error),
}

/// Bytes of a line kept for parsing at the fewest dimensions: far more
/// than any two f32 numbers need. A longer line is an error, reported
/// without reading the rest (an endless line, as from `/dev/zero`, stops
/// here too).
pub const MAX_LINE: usize = 1024;

/// Bytes a line may spend per number, its comma and spaces included:
/// twice the longest value `points` writes (the f64 decimal of the smallest
/// f32 subnormal, 62 characters).
pub const MAX_FIELD: usize = 128;

/// The most numbers per line: the most dimensions `points` writes
/// (`LatinHypercube::MAX_DIMENSIONS`), so that the line limit stays at
/// most 8 MiB.
pub const MAX_DIMENSIONS: usize = wellspread::LatinHypercube::MAX_DIMENSIONS as usize;

/// The longest line read for `dimensions` numbers: [`MAX_FIELD`] bytes per
/// number, and never less than [`MAX_LINE`].
pub fn line_limit(dimensions: usize) -> usize {
    MAX_LINE.max(MAX_FIELD.saturating_mul(dimensions))
}

/// Characters of the input an error message quotes at most.
pub const QUOTE: usize = 80;

/// The points of a CSV text (`x,y` per line; a byte-order mark, blank lines
/// and a header line are skipped), or a one-line error naming the 1-based
/// line and column and quoting at most [`QUOTE`] characters of the input.
///
/// The input is streamed: memory is the points plus one line of at most
/// [`MAX_LINE`] bytes ([`line_limit`] for N-dimensional lines), whatever
/// the input holds. `size_hint` (the input's
/// size in bytes, 0 if unknown) sizes the point buffer once the first lines
/// show the typical line length.
pub fn read_points(reader: &mut dyn BufRead, size_hint: u64) -> Result<Vec<Vec2>, ReadError> {
    let mut points = Vec::new();
    read_records(reader, size_hint, 2, &mut points)?;
    Ok(points)
}

/// [`read_points`] for lines of `dimensions` numbers each, into `points`.
pub fn read_records(
    reader: &mut dyn BufRead,
    size_hint: u64,
    dimensions: usize,
    points: &mut dyn Records,
) -> Result<(), ReadError> {
    const SAMPLE_LINES: usize = 1024;
    let limit = line_limit(dimensions);
    let mut line = Vec::with_capacity(MAX_LINE);
    let mut header_allowed = true;
    let mut bytes_read = 0u64;
    for number in 1usize.. {
        let Some(length) = read_line(reader, &mut line, limit).map_err(ReadError::Io)? else {
            break;
        };
        bytes_read += length as u64 + 1;
        if number == SAMPLE_LINES && size_hint > bytes_read {
            // Room for the rest at the mean line length so far, plus 1%.
            let mean = (bytes_read / SAMPLE_LINES as u64).max(1);
            let rest = (size_hint - bytes_read) / mean;
            points.reserve((rest + rest / 100) as usize);
        }
        let mut bytes = &line[..];
        if number == 1 {
            bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
        }
        let (text, bad_utf8) = match std::str::from_utf8(bytes) {
            Ok(text) => (text, false),
            Err(e) => (
                std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or(""),
                // A character cut by the line limit is not an error.
                e.error_len().is_some() || length == line.len(),
            ),
        };
        let column = |text: &str| text.chars().count() + 1;
        if bad_utf8 {
            return Err(ReadError::Input(format!(
                "line {number}, column {}: not UTF-8 text",
                column(text)
            )));
        }
        if length > line.len() {
            return Err(ReadError::Input(format!(
                "line {number}, column {}: a line of more than the {limit} bytes \
                 allowed; expected {}, got `{}`",
                column(text),
                numbers(dimensions),
                quote(text.trim_start())
            )));
        }
        if text.trim().is_empty() {
            continue;
        }
        let header = std::mem::replace(&mut header_allowed, false);
        if let Some(point) = parse_line(number, text, header, dimensions)? {
            points.push(&point);
        }
    }
    if points.is_empty() {
        return Err(ReadError::Input(format!(
            "no points in the input (expected {} lines)",
            expected(dimensions)
        )));
    }
    Ok(())
}

/// What a line should hold, for messages: `` `x,y` `` or `` `d` numbers ``.
fn expected(dimensions: usize) -> String {
    if dimensions == 2 {
        "`x,y`".to_owned()
    } else {
        format!("{dimensions}-number")
    }
}

/// What a line of `dimensions` numbers holds, for messages: `` `x,y` (two
/// numbers) `` or `80 numbers`.
fn numbers(dimensions: usize) -> String {
    if dimensions == 2 {
        "`x,y` (two numbers)".to_owned()
    } else {
        format!("{dimensions} numbers")
    }
}

/// Reads one line without its `\n` into `line`, keeping at most `limit`
/// bytes of it; returns the line's length, or `None` at the end of the
/// input. A line longer than `limit` stops the reading there: its length
/// is reported as `limit + 1` and the rest is left unread (the caller
/// reports the error and stops).
fn read_line(
    reader: &mut dyn BufRead,
    line: &mut Vec<u8>,
    limit: usize,
) -> io::Result<Option<usize>> {
    line.clear();
    let (mut length, mut any) = (0usize, false);
    loop {
        let chunk = match reader.fill_buf() {
            Ok(chunk) => chunk,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if chunk.is_empty() {
            return Ok(any.then_some(length));
        }
        any = true;
        let end = chunk.iter().position(|&b| b == b'\n');
        let part = &chunk[..end.unwrap_or(chunk.len())];
        let room = limit - line.len();
        if part.len() > room {
            line.extend_from_slice(&part[..room]);
            return Ok(Some(limit + 1));
        }
        line.extend_from_slice(part);
        length += part.len();
        let used = part.len() + usize::from(end.is_some());
        reader.consume(used);
        if end.is_some() {
            return Ok(Some(length));
        }
    }
}

/// At most [`QUOTE`] characters of `text`, with `...` if cut, and every
/// control character escaped (`\u{0}`, `\u{1b}`, `\t`), so that input
/// bytes such as NUL or an ANSI escape never reach the terminal raw.
fn quote(text: &str) -> String {
    let (kept, cut) = match text.char_indices().nth(QUOTE) {
        Some((cut, _)) => (&text[..cut], "..."),
        None => (text, ""),
    };
    let mut quoted = String::with_capacity(kept.len() + cut.len());
    for c in kept.chars() {
        if c.is_control() {
            quoted.extend(c.escape_default());
        } else {
            quoted.push(c);
        }
    }
    quoted + cut
}

/// One non-blank line: `Ok(None)` for the header (a first line with no
/// digit and no numeric field, when `header_allowed`), else its point or a
/// one-line error.
fn parse_line(
    number: usize,
    line: &str,
    header_allowed: bool,
    dimensions: usize,
) -> Result<Option<Vec<f32>>, ReadError> {
    // Each field trimmed, with the 1-based column where it starts, counted
    // field by field (a line of 65,536 numbers is read in linear time).
    let mut fields = Vec::new();
    let mut start_column = 1;
    for raw in line.split(',') {
        let trimmed = raw.trim_start();
        let lead = raw[..raw.len() - trimmed.len()].chars().count();
        fields.push((start_column + lead, raw.trim()));
        start_column += raw.chars().count() + 1;
    }
    if header_allowed
        && !line.bytes().any(|b| b.is_ascii_digit())
        && fields.iter().all(|(_, f)| f.parse::<f64>().is_err())
    {
        return Ok(None);
    }
    if fields.len() != dimensions {
        let column = match fields.get(dimensions) {
            Some(&(column, _)) => column,
            None => line.trim_end().chars().count() + 1,
        };
        return Err(ReadError::Input(format!(
            "line {number}, column {column}: expected {}, got {} fields in `{}`",
            numbers(dimensions),
            fields.len(),
            quote(line.trim())
        )));
    }
    let mut values = Vec::with_capacity(dimensions);
    for (k, &(column, text)) in fields.iter().enumerate() {
        let axis = match (dimensions, k) {
            (2, 0) => "x".to_owned(),
            (2, _) => "y".to_owned(),
            _ => format!("dimension {k}"),
        };
        values.push(coordinate(number, column, &axis, text).map_err(ReadError::Input)?);
    }
    Ok(Some(values))
}

/// One coordinate read as f32 and checked to be in [0, 1).
fn coordinate(line: usize, column: usize, axis: &str, text: &str) -> Result<f32, String> {
    let at = format!("line {line}, column {column}: {axis} = ");
    let shown = quote(text);
    let value: f32 = text
        .parse()
        .map_err(|_| format!("{at}`{shown}` is not a number"))?;
    // `-0.0` is taken as 0, as the metrics do.
    if !value.is_finite() {
        Err(format!("{at}{shown} is not finite"))
    } else if (0.0..1.0).contains(&value) {
        Ok(value)
    } else if value == 1.0 && decimal_below_one(text) {
        Err(format!("{at}{shown} rounds to 1 in f32, outside [0, 1)"))
    } else {
        Err(format!("{at}{shown} is outside [0, 1)"))
    }
}

/// Whether a decimal number (as f32 parsing reads it: a sign, digits with an
/// optional point, an optional exponent) is below 1, decided on its digits,
/// so that a value that rounds to 1 in f32 and in f64 still counts as below.
fn decimal_below_one(text: &str) -> bool {
    let text = text.strip_prefix('+').unwrap_or(text);
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(at) => (&text[..at], text[at + 1..].parse::<i64>()),
        None => (text, Ok(0)),
    };
    let Ok(exponent) = exponent else {
        return false;
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = || whole.bytes().chain(fraction.bytes());
    if !digits().all(|b| b.is_ascii_digit()) {
        return false;
    }
    let leading_zeros = digits().take_while(|&b| b == b'0').count();
    if leading_zeros == whole.len() + fraction.len() {
        return false;
    }
    // The value is 0.D x 10^power with D starting with a nonzero digit.
    let power = whole.len() as i64 - leading_zeros as i64 + exponent;
    power <= 0
}

/// The JSON object, one `"name": value` field per metric. Values are f64
/// in shortest round-trip form, booleans, or `null` where the metric is
/// not defined for this set.
pub fn report(points: &[Vec2], grid: Option<(u32, u32)>) -> Result<String, String> {
    // The points are checked (non-empty, finite, in [0, 1)), so a metric
    // that still fails is one that this n does not define.
    fn number(value: Result<f64, wellspread::Error>) -> String {
        value.map_or_else(|_| "null".to_owned(), |v| format!("{v:?}"))
    }
    fn boolean(value: Result<bool, wellspread::Error>) -> String {
        value.map_or_else(|_| "null".to_owned(), |v| v.to_string())
    }
    let mut fields: Vec<(&str, String)> = vec![
        ("n", points.len().to_string()),
        (
            "star_discrepancy",
            number(metrics::star_discrepancy(points)),
        ),
        (
            "l2_star_discrepancy",
            number(metrics::l2_star_discrepancy(points)),
        ),
        (
            "centered_l2_discrepancy",
            number(metrics::centered_l2_discrepancy(points)),
        ),
        (
            "wraparound_l2_discrepancy",
            number(metrics::wraparound_l2_discrepancy(points)),
        ),
        ("min_distance", number(metrics::min_distance(points))),
        (
            "toroidal_min_distance",
            number(metrics::toroidal_min_distance(points)),
        ),
        (
            "normalized_toroidal_min_distance",
            number(metrics::normalized_toroidal_min_distance(points)),
        ),
        ("is_latin", boolean(metrics::is_latin(points))),
        ("is_net_base2", boolean(metrics::is_net_base2(points))),
        (
            "t_value",
            metrics::net_t_value(points).map_or_else(|_| "null".to_owned(), |t| t.to_string()),
        ),
    ];
    if let Some((columns, rows)) = grid {
        let cells = u64::from(columns) * u64::from(rows);
        if !(points.len() as u64).is_multiple_of(cells) {
            return Err(format!(
                "--stratified {columns}x{rows}: its {cells} cells do not divide n = {}",
                points.len()
            ));
        }
        fields.push((
            "is_stratified",
            boolean(metrics::is_stratified(points, columns, rows)),
        ));
    }
    let body: Vec<String> = fields
        .iter()
        .map(|(k, v)| format!("\"{k}\": {v}"))
        .collect();
    Ok(format!("{{{}}}", body.join(", ")))
}

/// The JSON object of an N-dimensional set (see the help): Latin in every
/// dimension, and with `levels`, stratification of every projection onto
/// 1 to `strength` dimensions, each check exact on the f32 values.
pub fn report_nd(rows: &Rows, levels: Option<u32>, strength: usize) -> Result<String, String> {
    let d = rows.dimensions;
    let n = rows.values.len() / d;
    let point = |i: usize| &rows.values[i * d..(i + 1) * d];
    // `x` has at most 24 significant bits and the counts are below 2^29,
    // so the f64 product is exact.
    let stratum = |x: f32, parts: u64| (f64::from(x) * parts as f64).floor() as u64;
    let mut fields: Vec<(String, String)> = vec![
        ("n".to_owned(), n.to_string()),
        ("dimensions".to_owned(), d.to_string()),
    ];
    let non_latin = (0..d).find(|&k| {
        let mut seen = vec![false; n];
        (0..n).any(|i| std::mem::replace(&mut seen[stratum(point(i)[k], n as u64) as usize], true))
    });
    fields.push(("is_latin".to_owned(), non_latin.is_none().to_string()));
    fields.push((
        "non_latin_dimension".to_owned(),
        non_latin.map_or_else(|| "null".to_owned(), |k| k.to_string()),
    ));
    if let Some(q) = levels {
        for k in 1..=strength {
            let cells = u64::from(q)
                .checked_pow(k as u32)
                .filter(|&c| c <= n as u64);
            let (stratified, first) = match cells {
                Some(cells) if (n as u64).is_multiple_of(cells) => {
                    let each = n as u64 / cells;
                    let first = subsets(d, k).find(|dims| {
                        let mut counts = vec![0u64; cells as usize];
                        for i in 0..n {
                            let cell = dims.iter().fold(0, |cell, &j| {
                                cell * u64::from(q) + stratum(point(i)[j], u64::from(q))
                            });
                            counts[cell as usize] += 1;
                        }
                        counts.iter().any(|&c| c != each)
                    });
                    let shown = first.as_ref().map_or_else(
                        || "null".to_owned(),
                        |dims| {
                            let list: Vec<String> = dims.iter().map(usize::to_string).collect();
                            format!("[{}]", list.join(","))
                        },
                    );
                    (
                        if k <= d {
                            first.is_none().to_string()
                        } else {
                            "null".to_owned()
                        },
                        shown,
                    )
                }
                _ => ("null".to_owned(), "null".to_owned()),
            };
            fields.push((format!("stratified_{k}d"), stratified));
            fields.push((format!("unstratified_{k}d"), first));
        }
    }
    let body: Vec<String> = fields
        .iter()
        .map(|(k, v)| format!("\"{k}\": {v}"))
        .collect();
    Ok(format!("{{{}}}", body.join(", ")))
}

/// Every set of `k` distinct dimensions below `d`, as increasing lists.
fn subsets(d: usize, k: usize) -> impl Iterator<Item = Vec<usize>> {
    let mut next = (k <= d).then(|| (0..k).collect::<Vec<usize>>());
    std::iter::from_fn(move || {
        let current = next.take()?;
        let mut pick = current.clone();
        if let Some(i) = (0..k).rev().find(|&i| pick[i] < d - k + i) {
            pick[i] += 1;
            for j in i + 1..k {
                pick[j] = pick[j - 1] + 1;
            }
            next = Some(pick);
        }
        Some(current)
    })
}
