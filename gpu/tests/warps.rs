//! The warps' WGSL twins against the CPU crate over 2^20 inputs: the
//! exact ones bit for bit, the ones that call sin, cos or sqrt or divide
//! within the bounds docs/gpu.md states.

use wellspread::wgsl::SOURCE;
use wellspread_gpu::Gpu;
use wellspread_gpu::warps::{OUTPUT_NAMES, compare};

#[test]
fn warps_match_the_cpu() {
    let Some(gpu) = Gpu::get() else { return };
    let t = std::time::Instant::now();
    let (errors, lines) = compare(&gpu, SOURCE, 1 << 20, 42);
    eprintln!("warps: 2^20 inputs in {:.2?}", t.elapsed());
    for ((name, exact), e) in OUTPUT_NAMES.iter().zip(&errors) {
        eprintln!(
            "{name:48} {} mismatches {:7} max ulps {:5} max abs {:.3e}",
            if *exact { "exact " } else { "approx" },
            e.mismatches,
            e.max_ulps,
            e.max_abs
        );
    }
    assert!(
        lines.is_empty(),
        "bit-exact warps differ:\n{}",
        lines.join("\n")
    );
}
