//! The GPU cost of one draw per pixel sampler and width, in SPIR-V
//! instructions (naga's Vulkan output), checked against the table in
//! docs/gpu.md; `WELLSPREAD_BLESS=1` rewrites the table. Needs no GPU.

use std::collections::HashMap;
use std::fmt::Write as _;

use wellspread::wgsl::SOURCE;
use wellspread_gpu::HARNESS;

/// The sampler-specific draw expressions, as `ws_draw_1d`, `ws_draw_2d`
/// and `ws_draw_4d` dispatch them, on `d: WsDraw` and `s: WsSampler`.
const DRAWS: [(&str, [&str; 3]); 6] = [
    (
        "random",
        [
            "vec4<f32>(ws_unit(d.stream.y), 0.0, 0.0, 0.0)",
            "vec4<f32>(ws_random_2d(d.stream), 0.0, 0.0)",
            "vec4<f32>(ws_random_2d(d.stream), ws_random_2d(ws_second_stream(d.stream)))",
        ],
    ),
    (
        "sobol",
        [
            "vec4<f32>(ws_sobol_1d(d.index, d.stream), 0.0, 0.0, 0.0)",
            "vec4<f32>(ws_sobol_2d(d.index, d.stream), 0.0, 0.0)",
            "ws_sobol_4d(d.index, d.stream)",
        ],
    ),
    (
        "pmj02",
        [
            "vec4<f32>(ws_sobol_1d(d.index, d.stream), 0.0, 0.0, 0.0)",
            "vec4<f32>(ws_pmj02_2d(d.index, d.stream), 0.0, 0.0)",
            "ws_sobol_4d(d.index, d.stream)",
        ],
    ),
    (
        "jittered",
        [
            "vec4<f32>(ws_stratified_1d(d.index, s.n, d.stream), 0.0, 0.0, 0.0)",
            "vec4<f32>(ws_jittered_sample(s, d.index, d.stream.x), 0.0, 0.0)",
            "vec4<f32>(ws_jittered_sample(s, d.index, d.stream.x), \
             ws_jittered_sample(s, d.index, ws_second_stream(d.stream).x))",
        ],
    ),
    (
        "zsobol",
        [
            "vec4<f32>(ws_zsobol_1d(s, d), 0.0, 0.0, 0.0)",
            "vec4<f32>(ws_zsobol_2d(s, d), 0.0, 0.0)",
            "ws_zsobol_4d(s, d)",
        ],
    ),
    (
        "blue-noise",
        [
            "vec4<f32>(ws_blue_noise_2d(d).x, 0.0, 0.0, 0.0)",
            "vec4<f32>(ws_blue_noise_2d(d), 0.0, 0.0)",
            "ws_blue_noise_4d(d)",
        ],
    ),
];

/// A kernel that reads a sampler, a key, an index, a draw number and a
/// pixel state, makes the draw `d` (`ws_draw`, the stream's `mix64`),
/// evaluates `expression` (a `vec4<f32>`) and writes its sum.
fn kernel(expression: &str) -> String {
    format!(
        "{SOURCE}\n{HARNESS}\n
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {{
    let i = invocation(id);
    let s = WsSampler(params[0].x, params[0].y, params[0].z, params[0].w,
                      params[1].x, params[1].y, params[1].z, params[1].w);
    let d = ws_draw(vec2<u32>(input[i], input[i + 1u]), input[i + 3u], input[i + 2u], input[i + 4u]);
    let v: vec4<f32> = {expression};
    output[i] = bitcast<u32>(v.x + v.y + v.z + v.w);
}}
"
    )
}

/// Instructions of the entry point of the SPIR-V naga writes for `source`,
/// each function call counted as its callee's body (as after inlining);
/// labels, parameters and variable declarations not counted, and a loop
/// body once however often it runs.
fn spirv_instructions(source: &str) -> usize {
    let mut module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(source)));
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{}", e.emit_to_string(source)));
    let words = naga::back::spv::write_vec(
        &module,
        &info,
        &naga::back::spv::Options::default(),
        Some(&naga::back::spv::PipelineOptions {
            shader_stage: naga::ShaderStage::Compute,
            entry_point: "main".into(),
        }),
    )
    .expect("SPIR-V");
    const FUNCTION: u32 = 54;
    const FUNCTION_PARAMETER: u32 = 55;
    const FUNCTION_END: u32 = 56;
    const FUNCTION_CALL: u32 = 57;
    const VARIABLE: u32 = 59;
    const LINE: u32 = 8;
    const NO_LINE: u32 = 317;
    const LABEL: u32 = 248;
    // Per function (by result id): its own instructions and its calls.
    let mut functions: HashMap<u32, (usize, Vec<u32>)> = HashMap::new();
    let (mut at, mut current, mut last) = (5, None, 0);
    while at < words.len() {
        let (length, opcode) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        match opcode {
            FUNCTION => {
                current = Some(words[at + 2]);
                last = words[at + 2];
                functions.insert(last, (0, Vec::new()));
            }
            FUNCTION_END => current = None,
            FUNCTION_PARAMETER | VARIABLE | LINE | NO_LINE | LABEL => {}
            _ => {
                if let Some(f) = current {
                    let entry = functions.get_mut(&f).unwrap();
                    entry.0 += 1;
                    if opcode == FUNCTION_CALL {
                        entry.1.push(words[at + 3]);
                    }
                }
            }
        }
        at += length.max(1);
    }
    // The entry point is written last; count every call as its callee's
    // whole body, as a driver that inlines would.
    fn inlined(f: u32, functions: &HashMap<u32, (usize, Vec<u32>)>) -> usize {
        let (own, calls) = &functions[&f];
        own + calls.iter().map(|&c| inlined(c, functions)).sum::<usize>()
    }
    inlined(last, &functions)
}

/// The table: per sampler, the instructions of a 1D, 2D and 4D draw
/// (the stream included) beyond the kernel's own (reading the inputs,
/// writing the sum).
fn table() -> String {
    // The same kernel with the inputs read into a draw but no stream made.
    let touch = "vec4<f32>(f32(d.stream.x ^ d.stream.y), 0.0, 0.0, 0.0)";
    let baseline = spirv_instructions(&kernel(touch).replace(
        "let d = ws_draw(vec2<u32>(input[i], input[i + 1u]), input[i + 3u], ",
        "let d = WsDraw(input[i + 2u] ^ input[i + 3u], input[i + 4u], vec2<u32>(input[i], input[i + 1u])); //",
    ));
    let stream = spirv_instructions(&kernel(touch)) - baseline;
    let mut out = String::from(
        "| pixel sampler | `next_1d` | `next_2d` | `next_4d` |\n| --- | --- | --- | --- |\n",
    );
    for (name, draws) in DRAWS {
        let [one, two, four] = draws.map(|e| spirv_instructions(&kernel(e)) - baseline);
        writeln!(out, "| `{name}` | {one} | {two} | {four} |").unwrap();
    }
    writeln!(
        out,
        "\nOf each, {stream} make the draw's stream (`ws_draw`: a 64-bit multiply-add \
         and `mix64` on u32 pairs)."
    )
    .unwrap();
    // The warps, on a point made of the stream's bits.
    let u = "vec2<f32>(bitcast<f32>(d.stream.x), bitcast<f32>(d.stream.y))";
    let warp_baseline = spirv_instructions(&kernel(&format!("vec4<f32>({u}, 0.0, 0.0)")));
    out.push_str("\n| warp | instructions |\n| --- | --- |\n");
    for (name, expression) in [
        (
            "concentric_disk",
            "vec4<f32>(ws_concentric_disk(U), 0.0, 0.0)",
        ),
        (
            "concentric_disk_pdf",
            "vec4<f32>(ws_concentric_disk_pdf(U), U, 0.0)",
        ),
        (
            "cosine_hemisphere",
            "vec4<f32>(ws_cosine_hemisphere(U), 0.0)",
        ),
        (
            "uniform_hemisphere",
            "vec4<f32>(ws_uniform_hemisphere(U), 0.0)",
        ),
        ("uniform_sphere", "vec4<f32>(ws_uniform_sphere(U), 0.0)"),
        ("uniform_triangle", "vec4<f32>(ws_uniform_triangle(U), 0.0)"),
        (
            "discrete",
            "vec4<f32>(U, ws_discrete(U.x, d.index).remapped, 0.0)",
        ),
    ] {
        let cost = spirv_instructions(&kernel(&expression.replace('U', u))) - warp_baseline;
        writeln!(out, "| `{name}` | {cost} |").unwrap();
    }
    out
}

#[test]
fn docs_list_the_spirv_instruction_counts() {
    let table = table();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/gpu.md");
    let page = std::fs::read_to_string(path).expect("docs/gpu.md");
    let (begin, end) = ("<!-- spirv-counts-begin -->\n", "<!-- spirv-counts-end -->");
    let start = page.find(begin).expect("begin marker") + begin.len();
    let stop = page.find(end).expect("end marker");
    if std::env::var("WELLSPREAD_BLESS").is_ok_and(|v| v == "1") {
        let page = format!("{}{table}{}", &page[..start], &page[stop..]);
        std::fs::write(path, page).unwrap();
        return;
    }
    assert_eq!(
        page[start..stop],
        table,
        "docs/gpu.md's instruction table is stale: rerun with WELLSPREAD_BLESS=1"
    );
}
