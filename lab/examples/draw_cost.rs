//! A fixed workload of `Domain` draws for instruction counting:
//!
//! ```sh
//! cargo build --release -p wellspread-lab --example draw_cost
//! valgrind --tool=callgrind target/release/examples/draw_cost sobol 2d
//! ```
//!
//! runs `start` and one draw (`1d`, `2d`, `4d`), `start` alone (`none`) or
//! the bench's nine-draw path (`path`) for 2^16 scattered pixel samples of
//! a back end (any `PixelSamplerKind` name, or `unit` for the bench's PCG
//! unit: one unit, or nine for `path`), through `AnyPixelSampler` when the
//! workload ends in `-any`. Subtract a run of `sobol loop` (the inputs
//! alone) and divide by 2^16 for the count per pixel sample;
//! `docs/performance.md` lists them.

use std::hint::black_box;
use std::process::ExitCode;

use wellspread::{AnyPixelSampler, AnySampler, Padded, PixelSampler, PixelSamplerKind};

const SAMPLES: u32 = 1 << 16;

fn unit(x: u32) -> u32 {
    let state = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

fn run<P: PixelSampler + Copy>(sampler: P, workload: &str, inputs: &[([u32; 2], u32)]) -> f32 {
    let mut acc = 0.0;
    if workload == "loop" {
        return inputs
            .iter()
            .map(|&(p, i)| black_box(p[0] ^ p[1] ^ i) as f32)
            .sum();
    }
    for &(pixel, index) in inputs {
        let mut d = sampler.start(pixel, index);
        acc += match workload {
            "1d" => d.next_1d(),
            "2d" => d.next_2d().x,
            "4d" => d.next_4d().w,
            "path" => {
                let mut s = 0.0;
                for b in 0..3 {
                    let mut bounce = d.branch(1).branch(b);
                    s += bounce.next_1d() + bounce.next_1d() + bounce.next_2d().y;
                }
                s
            }
            _ => 0.0,
        };
        black_box(&d);
    }
    acc
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [name, workload] = args.as_slice() else {
        eprintln!(
            "usage: draw_cost <pixel sampler | unit> <1d | 2d | 4d | path | none | loop>[-any]"
        );
        return ExitCode::from(2);
    };
    let mut x = 0x5eed_u32;
    let inputs: Vec<([u32; 2], u32)> = (0..SAMPLES)
        .map(|_| {
            x = unit(x);
            ([x % 1920, (x >> 11) % 1080], x >> 28)
        })
        .collect();
    let (workload, through_any) = match workload.strip_suffix("-any") {
        Some(w) => (w, true),
        None => (workload.as_str(), false),
    };
    let total = if name == "unit" {
        let draws = if workload == "path" { 9 } else { 1 };
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
    } else {
        let kind: PixelSamplerKind = match name.parse() {
            Ok(kind) => kind,
            Err(e) => {
                eprintln!("draw_cost: {e}");
                return ExitCode::from(2);
            }
        };
        let any: AnyPixelSampler = kind.build(16, [1920, 1080], 0).expect("16 spp builds");
        if through_any {
            run(any, workload, &inputs)
        } else {
            // The concrete type of every kind: no wildcard, so a new kind
            // does not compile until it has its line.
            match any {
                AnyPixelSampler::Padded(p) => match *p.sampler() {
                    AnySampler::Regular(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::Random(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::Jittered(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::NRooks(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::MultiJittered(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::CorrelatedMultiJittered(s) => {
                        run(Padded::new(s, 0), workload, &inputs)
                    }
                    AnySampler::BlueMultiJittered(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::Hammersley(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::Halton(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::Sobol(s) => run(Padded::new(s, 0), workload, &inputs),
                    AnySampler::Pmj02(s) => run(Padded::new(s, 0), workload, &inputs),
                },
                AnyPixelSampler::ZSobol(s) => run(s, workload, &inputs),
                AnyPixelSampler::BlueNoise(s) => run(s, workload, &inputs),
                AnyPixelSampler::Orthogonal(s) => run(s, workload, &inputs),
                AnyPixelSampler::LatinHypercube(s) => run(s, workload, &inputs),
            }
        }
    };
    println!("{total}");
    ExitCode::SUCCESS
}
