//! The film of every pixel sampler equals the CPU's; and the comparison
//! catches one WGSL constant that differs from the CPU's.

use wellspread::SamplerKind;
use wellspread::wgsl::SOURCE;
use wellspread_gpu::Gpu;
use wellspread_gpu::film::{cases, cpu_film, gpu_film};
use wellspread_gpu::samplers::{Case, compare};

#[test]
fn films_equal_the_cpu_films() {
    let Some(gpu) = Gpu::get() else { return };
    let (width, height) = (160, 120);
    for case in cases(width, height) {
        assert!(
            gpu_film(&gpu, &case, width, height) == cpu_film(&case, width, height),
            "{}: the GPU film differs from the CPU's",
            case.name
        );
    }
}

/// One constant changed in the WGSL (a salt, an Owen multiplier, a hash
/// multiplier, a 64-bit salt's high half, an entry of the blue-noise and
/// of the Sobol' table, Kensler's constant): the comparison
/// must report mismatches for a sampler that uses it.
#[test]
fn a_changed_constant_fails_the_comparison() {
    let Some(gpu) = Gpu::get() else { return };
    let mutations = [
        (
            "const WS_SALT_DRAW_ORDER: u32 = 0x2c1b3c6du;",
            "const WS_SALT_DRAW_ORDER: u32 = 0x2c1b3c6cu;",
            Case::padded("sobol", SamplerKind::Sobol, 16, 0),
        ),
        (
            "const WS_SALT_JITTER_1D: u32 = 0x68e31da4u;",
            "const WS_SALT_JITTER_1D: u32 = 0x68e31da5u;",
            Case::jittered("jittered", 12, 0),
        ),
        (
            "x ^= x * 0x6c50b47cu;",
            "x ^= x * 0x6c50b47eu;",
            Case::padded("pmj02", SamplerKind::Pmj02, 16, 0),
        ),
        (
            "x *= 0x846ca68bu;",
            "x *= 0x846ca689u;",
            Case::zsobol("zsobol", 16, [64, 48], 0),
        ),
        (
            "vec2<u32>(0x5c26c926u, 0x2e1b2138u)",
            "vec2<u32>(0x5c26c926u, 0x2e1b2139u)",
            Case::jittered("jittered", 16, 0),
        ),
        (
            "vec2<u32>(0x007c92bau, 0x006d233bu)",
            "vec2<u32>(0x007c92bau, 0x006d233au)",
            Case::blue_noise("blue-noise", 16, 0),
        ),
        (
            "vec2<u32>(0x00000006u, 0x00000004u)",
            "vec2<u32>(0x00000006u, 0x00000005u)",
            Case::padded("sobol", SamplerKind::Sobol, 16, 0),
        ),
        (
            "0xdf6e307fu",
            "0xdf6e307eu",
            Case::jittered("jittered", 7, 0),
        ),
    ];
    for (from, to, case) in mutations {
        assert_eq!(
            SOURCE.matches(from).count(),
            1,
            "`{from}` is not in the source once"
        );
        let mutated = SOURCE.replacen(from, to, 1);
        let (failures, _) = compare(&gpu, &mutated, &case, 1 << 12, 9);
        eprintln!(
            "`{to}`: {}",
            failures.last().map_or("no mismatch", |s| s.as_str())
        );
        assert!(
            !failures.is_empty(),
            "changing `{from}` to `{to}` went unnoticed"
        );
    }
    // And the unchanged source passes the same comparison.
    let (failures, _) = compare(
        &gpu,
        SOURCE,
        &Case::padded("sobol", SamplerKind::Sobol, 16, 0),
        1 << 12,
        9,
    );
    assert!(failures.is_empty(), "{failures:?}");
}
