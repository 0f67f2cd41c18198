//! Every metric of a point set, as one JSON object.
//!
//! ```sh
//! cargo run --release --example metrics -- points.csv
//! cargo run --release --example metrics -- --stratified 8x8 - < points.csv
//! ```
//!
//! Run with `--help` for the input and output formats and the exit codes.

use std::ffi::OsString;
use std::io::{self, Read, Write};
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
    /// CSV file to read; standard input when absent or `-`
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,
}

/// What `--help` prints after the options.
pub const AFTER_HELP: &str = "\
Input: CSV with one `x,y` point per line, each coordinate in [0, 1) and
read as f32. Blank lines are ignored, and so are a UTF-8 byte-order mark
and a first line with no numeric field (a header such as `x,y`); any
other line that is not two numbers is an error naming its line.

Output: one JSON object on one line with the fields `n`,
`star_discrepancy`, `l2_star_discrepancy`, `centered_l2_discrepancy`,
`wraparound_l2_discrepancy`, `min_distance`, `toroidal_min_distance`,
`normalized_toroidal_min_distance`, `is_latin`, `is_net_base2`, `t_value`
(the smallest t for which the set is a (t, m, 2)-net in base 2) and, with
--stratified, `is_stratified`. A metric that is not defined for the set
is `null`: the distances need two points, `is_net_base2` and `t_value`
need n = 2^m.
Numbers are f64 in shortest round-trip form.
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
    let mut bytes = Vec::new();
    match &args.file {
        Some(path) if path.as_os_str() != "-" => {
            bytes = std::fs::read(path)
                .map_err(|e| Failure::Io(format!("cannot read {}: {e}", path.display())))?;
        }
        _ => {
            stdin
                .read_to_end(&mut bytes)
                .map_err(|e| Failure::Io(format!("cannot read standard input: {e}")))?;
        }
    }
    let points = parse_points(&bytes).map_err(Failure::Input)?;
    let json = report(&points, args.stratified).map_err(Failure::Input)?;
    writeln!(stdout, "{json}").map_err(|e| Failure::Io(format!("cannot write the report: {e}")))
}

/// Parses `M x K` as in `8x8`.
pub fn parse_grid(text: &str) -> Result<(u32, u32), String> {
    let side = |s: &str| s.trim().parse::<u32>().ok().filter(|&v| v > 0);
    text.split_once(['x', 'X'])
        .and_then(|(m, k)| Some((side(m)?, side(k)?)))
        .ok_or_else(|| format!("{text:?} is not a grid MxK of two whole numbers from 1, e.g. 8x8"))
}

/// The points of a CSV text, or a one-line error naming the 1-based line.
pub fn parse_points(bytes: &[u8]) -> Result<Vec<Vec2>, String> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let line = 1 + bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        format!("line {line}: not UTF-8 text")
    })?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut points = Vec::new();
    let mut first = true;
    for (number, line) in (1..).zip(text.lines()) {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let header = fields.iter().all(|f| f.parse::<f64>().is_err());
        if std::mem::replace(&mut first, false) && header {
            continue;
        }
        let [x, y] = fields[..] else {
            return Err(format!(
                "line {number}: expected `x,y` (two numbers), got {} fields in `{line}`",
                fields.len()
            ));
        };
        points.push(Vec2::new(
            coordinate(number, "x", x)?,
            coordinate(number, "y", y)?,
        ));
    }
    if points.is_empty() {
        return Err("no points in the input (expected `x,y` lines)".to_owned());
    }
    Ok(points)
}

/// One coordinate read as f32 and checked to be in [0, 1).
fn coordinate(line: usize, axis: &str, text: &str) -> Result<f32, String> {
    let value: f32 = text
        .parse()
        .map_err(|_| format!("line {line}: {axis} = `{text}` is not a number"))?;
    // `-0.0` is taken as 0, as the metrics do.
    if !value.is_finite() {
        Err(format!("line {line}: {axis} = {text} is not finite"))
    } else if (0.0..1.0).contains(&value) {
        Ok(value)
    } else if value == 1.0 && text.parse::<f64>().is_ok_and(|v| v < 1.0) {
        Err(format!(
            "line {line}: {axis} = {text} rounds to 1 in f32, outside [0, 1)"
        ))
    } else {
        Err(format!("line {line}: {axis} = {text} is outside [0, 1)"))
    }
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
