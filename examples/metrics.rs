//! Every metric of a point set, as one JSON object.
//!
//! ```sh
//! cargo run --release --example metrics -- points.csv
//! cargo run --example points -- --sampler jittered --n 64 | cargo run --example metrics
//! cargo run --example metrics -- --stratified 8x8 - < points.csv
//! ```
//!
//! Input: CSV with one `x,y` point per line, an optional header line, blank
//! lines ignored; a file argument, or stdin when there is none or it is `-`.
//! Output: `n`, the four discrepancies, the three minimum distances,
//! `is_latin`, `is_net_base2` and `t_value` (the smallest t of a (t, m, 2)-net;
//! both null unless n is a power of two) and, with
//! `--stratified MxK`, `is_stratified`. Exit code 2 on a malformed line (with
//! its line number) or a metric error.

use std::io::{self, Read};
use std::process::ExitCode;

use wellspread::glam::Vec2;
use wellspread::metrics;

const USAGE: &str = "usage: metrics [--stratified MxK] [FILE | -]";

fn fail(message: &str) -> ExitCode {
    eprintln!("metrics: {message}");
    ExitCode::from(2)
}

/// Parses `M x K` as in `8x8`.
fn parse_grid(text: &str) -> Option<(u32, u32)> {
    let (m, k) = text.split_once(['x', 'X'])?;
    Some((m.trim().parse().ok()?, k.trim().parse().ok()?))
}

/// One `x,y` line, or None if it is not two f32 values.
fn parse_point(line: &str) -> Option<Vec2> {
    let mut fields = line.split(',');
    let x = fields.next()?.trim().parse().ok()?;
    let y = fields.next()?.trim().parse().ok()?;
    fields.next().is_none().then_some(Vec2::new(x, y))
}

fn parse_points(text: &str) -> Result<Vec<Vec2>, String> {
    let mut points = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        match parse_point(line) {
            Some(p) => points.push(p),
            // The first line may be a header such as `x,y`.
            None if number == 0 => {}
            None => {
                return Err(format!(
                    "line {}: expected `x,y` (two numbers), got `{line}`",
                    number + 1
                ));
            }
        }
    }
    Ok(points)
}

fn main() -> ExitCode {
    let mut grid = None;
    let mut path = None;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--stratified" => {
                let Some(value) = args.next() else {
                    return fail(&format!("--stratified needs MxK, e.g. 8x8\n{USAGE}"));
                };
                match parse_grid(&value) {
                    Some(g) => grid = Some(g),
                    None => return fail(&format!("--stratified: expected MxK, got `{value}`")),
                }
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            _ if path.is_none() && (arg == "-" || !arg.starts_with('-')) => path = Some(arg),
            _ => return fail(&format!("unexpected argument `{arg}`\n{USAGE}")),
        }
    }

    let mut text = String::new();
    let read = match path.as_deref() {
        None | Some("-") => io::stdin().read_to_string(&mut text).map(|_| ()),
        Some(file) => std::fs::read_to_string(file).map(|t| text = t),
    };
    if let Err(e) = read {
        return fail(&format!("cannot read input: {e}"));
    }
    let points = match parse_points(&text) {
        Ok(p) => p,
        Err(e) => return fail(&e),
    };
    match report(&points, grid) {
        Ok(json) => {
            println!("{json}");
            ExitCode::SUCCESS
        }
        Err(e) => fail(&e.to_string()),
    }
}

/// The JSON object; f64 values use Rust's shortest round-trip formatting.
fn report(points: &[Vec2], grid: Option<(u32, u32)>) -> Result<String, wellspread::Error> {
    let mut fields: Vec<(&str, String)> = vec![
        ("n", points.len().to_string()),
        (
            "star_discrepancy",
            format!("{:?}", metrics::star_discrepancy(points)?),
        ),
        (
            "l2_star_discrepancy",
            format!("{:?}", metrics::l2_star_discrepancy(points)?),
        ),
        (
            "centered_l2_discrepancy",
            format!("{:?}", metrics::centered_l2_discrepancy(points)?),
        ),
        (
            "wraparound_l2_discrepancy",
            format!("{:?}", metrics::wraparound_l2_discrepancy(points)?),
        ),
        (
            "min_distance",
            format!("{:?}", metrics::min_distance(points)?),
        ),
        (
            "toroidal_min_distance",
            format!("{:?}", metrics::toroidal_min_distance(points)?),
        ),
        (
            "normalized_toroidal_min_distance",
            format!("{:?}", metrics::normalized_toroidal_min_distance(points)?),
        ),
        ("is_latin", metrics::is_latin(points)?.to_string()),
        (
            "is_net_base2",
            if points.len().is_power_of_two() {
                metrics::is_net_base2(points)?.to_string()
            } else {
                "null".to_string()
            },
        ),
        (
            "t_value",
            if points.len().is_power_of_two() {
                metrics::net_t_value(points)?.to_string()
            } else {
                "null".to_string()
            },
        ),
    ];
    if let Some((columns, rows)) = grid {
        fields.push((
            "is_stratified",
            metrics::is_stratified(points, columns, rows)?.to_string(),
        ));
    }
    let body: Vec<String> = fields
        .iter()
        .map(|(k, v)| format!("\"{k}\": {v}"))
        .collect();
    Ok(format!("{{{}}}", body.join(", ")))
}
