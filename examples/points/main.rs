//! Writes one wellspread sample pattern as CSV or as an SVG picture.
//!
//! ```sh
//! cargo run --release --example points -- --sampler correlated-multi-jittered --n 16
//! cargo run --release --example points -- --sampler multi-jittered --n 100 --format svg --out mj.svg
//! ```
//!
//! Run with `--help` for every option. Bad arguments print one line on
//! standard error and exit with status 2.

mod cli;

use std::process::ExitCode;

fn main() -> ExitCode {
    match cli::parse(std::env::args_os().skip(1)) {
        Ok(cli::Command::Help) => {
            print!("{}", cli::usage());
            ExitCode::SUCCESS
        }
        Ok(cli::Command::Run(options)) => match cli::run(&options) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("points: cannot write the points: {e}");
                ExitCode::FAILURE
            }
        },
        Err(message) => {
            eprintln!("points: {message}");
            ExitCode::from(2)
        }
    }
}
