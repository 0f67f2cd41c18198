//! Every pixel sampler's WGSL twin against the CPU crate, bit for bit:
//! 2^20 inputs (pixel, index, key, draw, split, branch chain) per sampler,
//! 24 u32 or f32 bit patterns each, edges included.

use wellspread::SamplerKind;
use wellspread::wgsl::SOURCE;
use wellspread_gpu::Gpu;
use wellspread_gpu::samplers::{Case, compare};

const INPUTS: usize = 1 << 20;

fn check(cases: &[(Case, usize)], seed: u64) {
    let Some(gpu) = Gpu::get() else { return };
    eprintln!("adapter: {}", gpu.adapter);
    let mut failures = Vec::new();
    for (i, (case, count)) in cases.iter().enumerate() {
        let (f, time) = compare(&gpu, SOURCE, case, *count, seed + i as u64);
        eprintln!(
            "{}: {count} inputs, GPU {time:.2?}, {} mismatches",
            case.name,
            f.len()
        );
        failures.extend(f);
    }
    assert!(
        failures.is_empty(),
        "GPU and CPU differ:\n{}",
        failures.join("\n")
    );
}

#[test]
fn random_is_bit_exact() {
    check(
        &[(Case::padded("random", SamplerKind::Random, 16, 7), INPUTS)],
        1,
    );
}

#[test]
fn sobol_is_bit_exact() {
    check(
        &[(Case::padded("sobol", SamplerKind::Sobol, 16, 7), INPUTS)],
        2,
    );
}

#[test]
fn pmj02_is_bit_exact() {
    check(
        &[(
            Case::padded("pmj02", SamplerKind::Pmj02, 64, u32::MAX),
            INPUTS,
        )],
        3,
    );
}

/// Powers of two (shifts), other counts (the long division), short
/// permutations (at most 8 cells) and a 1 x n grid.
#[test]
fn jittered_is_bit_exact() {
    check(
        &[
            (Case::jittered("jittered 16", 16, 0), INPUTS / 4),
            (Case::jittered("jittered 12", 12, 5), INPUTS / 4),
            (Case::jittered("jittered 1000", 1000, 9), INPUTS / 8),
            (Case::jittered("jittered 7", 7, 1), INPUTS / 8),
            (Case::jittered("jittered 1", 1, 2), INPUTS / 8),
            (Case::jittered("jittered 65537", 65_537, 3), INPUTS / 8),
        ],
        4,
    );
}

#[test]
fn zsobol_is_bit_exact() {
    check(
        &[
            (
                Case::zsobol("zsobol 16spp 64x48", 16, [64, 48], 3),
                INPUTS / 2,
            ),
            (
                Case::zsobol("zsobol 1spp 1000x1", 1, [1000, 1], 0),
                INPUTS / 4,
            ),
            (
                Case::zsobol("zsobol 256spp 16x16", 256, [16, 16], u32::MAX),
                INPUTS / 4,
            ),
        ],
        5,
    );
}

#[test]
fn blue_noise_is_bit_exact() {
    check(&[(Case::blue_noise("blue-noise", 16, 11), INPUTS)], 6);
}
