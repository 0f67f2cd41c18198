//! A fixed workload of `Domain` draws for instruction counting:
//!
//! ```sh
//! cargo build --release -p wellspread-lab --example draw_cost
//! valgrind --tool=callgrind target/release/examples/draw_cost sobol 2d
//! ```
//!
//! runs `start` and one draw (`1d`, `2d`, `4d`, every value it returns
//! summed, so that no coordinate's work is optimised away), `start` alone (`none`) or
//! the bench's nine-draw path (`path`) for 2^16 scattered pixel samples of
//! a back end (any `PixelSamplerKind` name, or `unit` for the bench's PCG
//! unit: one unit, or nine for `path`; `joint-sobol` and `joint-sobol-4d`
//! are the candidates of `docs/joint_study.md`, static only). `path-call`
//! makes the same nine draws in call order from the start domain. The domain borrows the sampler
//! (`PixelSampler::start`, 32 bytes): the concrete type (through
//! `AnyPixelSampler::visit`), or `AnyPixelSampler` itself when the
//! workload ends in `-any`; `-any-owned` runs the owned
//! `Domain<AnyPixelSampler>` (`Domain::start` by value).
//! Subtract a run of `sobol loop` (the inputs alone) and divide by 2^16
//! for the count per pixel sample; `docs/performance.md` lists them.

use std::ffi::OsString;
use std::hint::black_box;
use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use wellspread::{AnyPixelSampler, Domain, PixelSampler, PixelSamplerKind, PixelSamplerVisitor};

#[path = "shared/cli.rs"]
pub mod shared;

#[path = "shared/joint_sobol.rs"]
mod joint_sobol;

use joint_sobol::{Candidate, JointSobol};

use shared::Failure;

/// A fixed workload of `Domain` draws, for `valgrind --tool=callgrind`.
#[derive(Parser, Debug)]
pub struct Args {
    /// A pixel sampler's name (sobol, blue-noise, cmj, ...), or `unit`
    /// for the bench's PCG unit
    #[arg(value_name = "SAMPLER", value_parser = back_end)]
    pub back_end: BackEnd,
    /// What each pixel sample does: 1d, 2d, 4d, path, none or loop, with
    /// `-any` to go through AnyPixelSampler (2d-any), `-any-owned` for the
    /// owned Domain<AnyPixelSampler>
    #[arg(value_name = "WORKLOAD", value_parser = workload)]
    pub workload: (Workload, Through),
}

/// Which sampler type the domain holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Through {
    /// A reference to the concrete type.
    Static,
    /// `&AnyPixelSampler`, what `start` gives.
    Any,
    /// `AnyPixelSampler` by value.
    AnyOwned,
}

/// What is measured: a pixel sampler, or the unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BackEnd {
    Unit,
    Sampler(PixelSamplerKind),
    /// A study candidate (`docs/joint_study.md`).
    Joint(Candidate),
}

/// The work per pixel sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Workload {
    /// `start` and one `next_1d`.
    OneD,
    /// `start` and one `next_2d`.
    TwoD,
    /// `start` and one `next_4d`.
    FourD,
    /// `start` and the bench's nine keyed draws.
    Path,
    /// `start` and the same nine draws in call order.
    PathCall,
    /// `start` alone.
    None,
    /// The inputs alone, the count to subtract.
    Loop,
}

fn back_end(text: &str) -> Result<BackEnd, String> {
    if text == "unit" {
        return Ok(BackEnd::Unit);
    }
    if let Some(candidate) = Candidate::from_name(text) {
        return Ok(BackEnd::Joint(candidate));
    }
    text.parse()
        .map(BackEnd::Sampler)
        .map_err(|e| format!("{e}"))
}

fn workload(text: &str) -> Result<(Workload, Through), String> {
    let (name, through) = if let Some(name) = text.strip_suffix("-any-owned") {
        (name, Through::AnyOwned)
    } else if let Some(name) = text.strip_suffix("-any") {
        (name, Through::Any)
    } else {
        (text, Through::Static)
    };
    let workload = match name {
        "1d" => Workload::OneD,
        "2d" => Workload::TwoD,
        "4d" => Workload::FourD,
        "path" => Workload::Path,
        "path-call" => Workload::PathCall,
        "none" => Workload::None,
        "loop" => Workload::Loop,
        _ => {
            return Err(format!(
                "{} is not one of 1d, 2d, 4d, path, path-call, none, loop (each may end in -any or -any-owned)",
                shared::quoted(text)
            ));
        }
    };
    Ok((workload, through))
}

/// Parses the arguments (without the program name): `Ok(None)` when the
/// help was written to `out`.
pub fn parse(
    args: impl IntoIterator<Item = OsString>,
    out: &mut dyn std::io::Write,
) -> Result<Option<Args>, Failure> {
    shared::parse::<Args>("draw_cost", shared::EXIT_CODES, args, out)
}

const SAMPLES: u32 = 1 << 16;

fn unit(x: u32) -> u32 {
    let state = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

fn run<P: PixelSampler + Copy>(sampler: P, workload: Workload, inputs: &[([u32; 2], u32)]) -> f32 {
    let mut acc = 0.0;
    if workload == Workload::Loop {
        return inputs
            .iter()
            .map(|&(p, i)| black_box(p[0] ^ p[1] ^ i) as f32)
            .sum();
    }
    for &(pixel, index) in inputs {
        let mut d = Domain::start(sampler, pixel, index);
        acc += match workload {
            Workload::OneD => d.next_1d(),
            Workload::TwoD => d.next_2d().element_sum(),
            Workload::FourD => d.next_4d().element_sum(),
            Workload::Path => {
                let mut s = 0.0;
                for b in 0..3 {
                    let mut bounce = d.branch(1).branch(b);
                    s += bounce.next_1d() + bounce.next_1d() + bounce.next_2d().element_sum();
                }
                s
            }
            Workload::PathCall => {
                let mut s = 0.0;
                for _ in 0..3 {
                    s += d.next_1d() + d.next_1d() + d.next_2d().element_sum();
                }
                s
            }
            Workload::None | Workload::Loop => 0.0,
        };
        black_box(&d);
    }
    acc
}

/// `run` on the concrete sampler behind an `AnyPixelSampler`.
struct Concrete<'a> {
    workload: Workload,
    inputs: &'a [([u32; 2], u32)],
}

impl PixelSamplerVisitor for Concrete<'_> {
    type Output = f32;
    fn visit<S: PixelSampler + Copy>(self, sampler: &S) -> f32 {
        run(sampler, self.workload, self.inputs)
    }
}

fn main() -> ExitCode {
    let args = match parse(std::env::args_os().skip(1), &mut std::io::stdout().lock()) {
        Ok(Some(args)) => args,
        Ok(None) => return ExitCode::SUCCESS,
        Err(failure) => return shared::exit("draw_cost", Err(failure)),
    };
    let ((workload, through), back_end) = (args.workload, args.back_end);
    let mut x = 0x5eed_u32;
    let inputs: Vec<([u32; 2], u32)> = (0..SAMPLES)
        .map(|_| {
            x = unit(x);
            ([x % 1920, (x >> 11) % 1080], x >> 28)
        })
        .collect();
    let total = match back_end {
        BackEnd::Unit => {
            let draws = if matches!(workload, Workload::Path | Workload::PathCall) {
                9
            } else {
                1
            };
            inputs
                .iter()
                .map(|&([px, py], i)| {
                    (0..draws)
                        .map(|d| {
                            let seed = px
                                ^ py.wrapping_mul(0x9e37_79b9)
                                ^ i.wrapping_mul(0x85eb_ca6b)
                                ^ (d as u32).wrapping_mul(0xc2b2_ae35);
                            let a = unit(seed);
                            black_box((a >> 8) as f32 + (unit(a) >> 8) as f32)
                        })
                        .sum::<f32>()
                })
                .sum::<f32>()
        }
        BackEnd::Joint(candidate) => {
            if through != Through::Static {
                return shared::exit(
                    "draw_cost",
                    Err(Failure::Input(
                        "the study's candidates are not AnyPixelSampler kinds: static workloads only"
                            .to_owned(),
                    )),
                );
            }
            let joint = JointSobol::candidate(candidate, 0);
            run::<&JointSobol>(&joint, workload, &inputs)
        }
        BackEnd::Sampler(kind) => {
            let any = match kind.build(16, [1920, 1080], 0) {
                Ok(any) => any,
                Err(e) => {
                    return shared::exit(
                        "draw_cost",
                        Err(Failure::Input(format!("{kind} at 16 spp: {e}"))),
                    );
                }
            };
            if through == Through::AnyOwned {
                run(any, workload, &inputs)
            } else if through == Through::Any {
                run::<&AnyPixelSampler>(&any, workload, &inputs)
            } else {
                any.visit(Concrete {
                    workload,
                    inputs: &inputs,
                })
            }
        }
    };
    shared::exit(
        "draw_cost",
        shared::to_stdout(writeln!(std::io::stdout(), "{total}")),
    )
}
