//! Writes one wellspread sample pattern as CSV or as an SVG picture.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example points -- --sampler correlated-multi-jittered --n 16
//! mkdir -p out && cargo run --release -p wellspread-lab --example points -- --sampler multi-jittered --n 100 --format svg --out out/mj.svg
//! cargo run --release -p wellspread-lab --example points -- --sampler orthogonal --n 64 --dimensions 5 --strength 3
//! cargo run --release -p wellspread-lab --example points -- --sampler latin-hypercube --n 25 --dimensions 8 --format svg --projection 3,5
//! ```
//!
//! Run with `--help` for every option, the output format and the exit codes.

mod cli;

use std::process::ExitCode;

fn main() -> ExitCode {
    let result = cli::main_with(std::env::args_os().skip(1), &mut std::io::stdout().lock());
    cli::shared::exit("points", result)
}
