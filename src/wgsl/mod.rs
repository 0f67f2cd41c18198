//! The samplers and warps as WGSL source, for a wgpu or Bevy renderer that
//! wants the same samples on the GPU as on the CPU.
//!
//! [`SOURCE`] is plain WGSL (no entry point, no bindings, every name
//! prefixed `ws_`) to concatenate in front of a shader. It holds:
//!
//! - [`PRIMITIVES`]: the hashes, Owen scrambles, permutations, Morton codes
//!   and unit conversions of [`primitives`](crate::primitives), with 64-bit
//!   values emulated as `vec2<u32>(low, high)` (WGSL has no 64-bit
//!   integers);
//! - [`SAMPLERS`]: `WsSampler` (the settings of [`Padded`](crate::Padded)
//!   `<`[`Random`](crate::Random)`>`, `Padded<`[`Sobol`](crate::Sobol)`>`,
//!   `Padded<`[`Pmj02`](crate::Pmj02)`>`, `Padded<`[`Jittered`](crate::Jittered)`>`,
//!   [`ZSobol`](crate::ZSobol) and [`BlueNoise`](crate::BlueNoise)) and
//!   `WsDomain` (a [`Domain`](crate::Domain) in five u32s) with `ws_start`,
//!   `ws_next_1d` ... `ws_next_4d`, `ws_branch`, `ws_split` and
//!   `ws_sample_pixel`;
//! - [`WARPS`]: the warps of [`warp`](crate::warp) (disk, cosine and
//!   uniform hemisphere, sphere, triangle, discrete) with their pdfs.
//!
//! # Properties
//!
//! - Every integer and every `[0, 1)` value of the samplers is bit-identical
//!   to the CPU's, for every pixel, index, key and draw: the only float
//!   operation on that path is `f32(t) * 2^-24` with `t < 2^24`, exact on
//!   any IEEE-754 GPU. The `wellspread-gpu` test crate (`gpu/` in the
//!   repository) checks it on Mesa's lavapipe over 2^20 inputs per sampler.
//! - The triangle and discrete warps are bit-exact too; the warps that call
//!   `sin`, `cos`, `sqrt` or divide are within the bounds `docs/gpu.md`
//!   states.
//!
//! # Examples
//!
//! ```
//! let shader = format!(
//!     "{}\n@group(0) @binding(0) var<storage, read_write> out: array<vec2<f32>>;\n\
//!      @compute @workgroup_size(64)\n\
//!      fn main(@builtin(global_invocation_id) id: vec3<u32>) {{\n\
//!          if (id.x >= arrayLength(&out)) {{ return; }}\n\
//!          let sampler = ws_padded(WS_SOBOL, 16u, 0u);\n\
//!          var d = ws_start(sampler, vec2<u32>(id.x % 64u, id.x / 64u), 0u);\n\
//!          out[id.x] = ws_next_2d(sampler, &d);\n\
//!      }}\n",
//!     wellspread::wgsl::SOURCE
//! );
//! assert!(shader.contains("fn ws_next_2d"));
//! ```

/// The primitives: hashes, scrambles, permutations, 64-bit emulation, unit
/// conversions (`src/wgsl/primitives.wgsl`).
pub const PRIMITIVES: &str = include_str!("primitives.wgsl");

/// The pixel samplers and the domain (`src/wgsl/samplers.wgsl`); needs
/// [`PRIMITIVES`] before it.
pub const SAMPLERS: &str = include_str!("samplers.wgsl");

/// The warps with their pdfs (`src/wgsl/warps.wgsl`); needs
/// [`PRIMITIVES`] before it (the discrete warp's 64-bit product).
pub const WARPS: &str = include_str!("warps.wgsl");

/// [`PRIMITIVES`], [`SAMPLERS`] and [`WARPS`] in order: everything, ready to
/// put in front of a shader.
pub const SOURCE: &str = concat!(
    include_str!("primitives.wgsl"),
    "\n",
    include_str!("samplers.wgsl"),
    "\n",
    include_str!("warps.wgsl")
);

#[cfg(test)]
mod tests {
    use std::format;
    use std::string::String;

    use super::*;
    use crate::pixel::blue_noise::SearchedColumns;
    use crate::pixel::blue_noise::sealed::Shift;
    use crate::primitives::salt;
    use crate::samplers::sequence::sobol_4d::dimensions_2_3_reversed;

    /// The lines between `// <name>-begin` and `// <name>-end`.
    fn block(name: &str) -> &'static str {
        let begin = format!("// {name}-begin\n");
        let end = format!("// {name}-end");
        let start = SOURCE.find(&begin).expect("begin marker") + begin.len();
        let stop = SOURCE.find(&end).expect("end marker");
        &SOURCE[start..stop]
    }

    fn table(entries: impl Iterator<Item = (u32, u32)>) -> String {
        entries
            .map(|(a, b)| format!("    vec2<u32>({a:#010x}u, {b:#010x}u),\n"))
            .collect()
    }

    #[test]
    fn sobol_columns_are_the_cpu_tables() {
        let want = table((0..32).map(|j| dimensions_2_3_reversed(1 << j)));
        assert_eq!(block("ws-sobol-columns"), want, "paste this block:\n{want}");
    }

    #[test]
    fn blue_noise_columns_are_the_cpu_tables() {
        let want = table((0..32).map(|p| {
            let [x, y] = SearchedColumns.shift_reversed(1 << p);
            (x, y)
        }));
        assert_eq!(
            block("ws-blue-noise-columns"),
            want,
            "paste this block:\n{want}"
        );
    }

    #[test]
    fn salts_are_the_cpu_salts() {
        let u32s = [
            ("ORDER", salt::ORDER),
            ("JITTER_X", salt::JITTER_X),
            ("JITTER_Y", salt::JITTER_Y),
            ("JITTER_1D", salt::JITTER_1D),
            ("SOBOL_Z", salt::SOBOL_Z),
            ("SOBOL_W", salt::SOBOL_W),
            ("DRAW_ORDER", salt::DRAW_ORDER),
        ];
        for (name, value) in u32s {
            let line = format!("const WS_SALT_{name}: u32 = {value:#010x}u;");
            assert!(SOURCE.contains(&line), "missing `{line}`");
        }
        let u64s = [
            ("DRAW_WEYL", salt::DRAW_WEYL),
            ("BRANCH_WEYL", salt::BRANCH_WEYL),
            ("BRANCH", salt::BRANCH),
            ("SPLIT", salt::SPLIT),
            ("PASS", salt::PASS),
            ("SECOND", salt::SECOND),
            ("PADDED_FRAME", salt::PADDED_FRAME),
            ("ZSOBOL_FRAME", salt::ZSOBOL_FRAME),
            ("BLUE_NOISE_FRAME", salt::BLUE_NOISE_FRAME),
            ("BLUE_NOISE_PIXEL", salt::BLUE_NOISE_PIXEL),
            ("RANDOM_INDEX", salt::RANDOM_INDEX),
        ];
        for (name, value) in u64s {
            let line = format!(
                "const WS_SALT_{name}: vec2<u32> = vec2<u32>({:#010x}u, {:#010x}u);",
                value as u32,
                (value >> 32) as u32
            );
            assert!(SOURCE.contains(&line), "missing `{line}`");
        }
    }

    /// naga parses and validates each part and the whole, as wgpu would.
    #[test]
    fn naga_validates_the_source() {
        for (name, source) in [
            ("PRIMITIVES", PRIMITIVES.into()),
            ("PRIMITIVES + SAMPLERS", format!("{PRIMITIVES}\n{SAMPLERS}")),
            ("PRIMITIVES + WARPS", format!("{PRIMITIVES}\n{WARPS}")),
            ("SOURCE", SOURCE.into()),
        ] {
            let module = naga::front::wgsl::parse_str(&source)
                .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(&source)));
            naga::valid::Validator::new(
                naga::valid::ValidationFlags::all(),
                naga::valid::Capabilities::empty(),
            )
            .validate(&module)
            .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(&source)));
        }
    }
}
