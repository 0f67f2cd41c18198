//! The warps on both sides: inputs on the samplers' 2^-24 grid (and some
//! arbitrary floats), the test shader and the CPU twin of what it writes.

use wellspread::glam::{Vec2, Vec3};
use wellspread::warp;

use crate::{Gpu, HARNESS};

/// Words per input: u.x and u.y as f32 bits, a count n for `discrete`.
pub const INPUT_WORDS: usize = 3;

/// Words per output (see [`OUTPUT_NAMES`]).
pub const OUTPUT_WORDS: usize = 24;

/// What each output word is, and whether it must be bit-exact.
pub const OUTPUT_NAMES: [(&str, bool); OUTPUT_WORDS] = [
    ("uniform_triangle.x", true),
    ("uniform_triangle.y", true),
    ("uniform_triangle.z", true),
    ("discrete.index", true),
    ("discrete.remapped", true),
    ("cosine_hemisphere_pdf(u.x - 0.25)", true),
    ("uniform_hemisphere_pdf((0, 0, u.x - 0.5))", true),
    ("uniform_sphere_pdf", true),
    ("concentric_disk_pdf(2 u - 1)", true),
    ("discrete_pdf(n)", false),
    ("uniform_triangle_pdf(u.x + 2^-24)", false),
    ("concentric_disk.x", false),
    ("concentric_disk.y", false),
    ("cosine_hemisphere.x", false),
    ("cosine_hemisphere.y", false),
    ("cosine_hemisphere.z", false),
    ("uniform_hemisphere.x", false),
    ("uniform_hemisphere.y", false),
    ("uniform_hemisphere.z", false),
    ("uniform_sphere.x", false),
    ("uniform_sphere.y", false),
    ("uniform_sphere.z", false),
    ("concentric_disk_pdf(concentric_disk(u))", true),
    ("cosine_hemisphere_pdf(cosine_hemisphere(u).z)", false),
];

/// The test kernel: [`HARNESS`], then this, after `wgsl::SOURCE`.
pub const KERNEL: &str = "
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = invocation(id);
    if (i >= params[0].x) {
        return;
    }
    let a = i * 3u;
    let u = vec2<f32>(bitcast<f32>(input[a]), bitcast<f32>(input[a + 1u]));
    let n = input[a + 2u];
    let o = i * 24u;
    let t = bitcast<vec3<u32>>(ws_uniform_triangle(u));
    output[o] = t.x;
    output[o + 1u] = t.y;
    output[o + 2u] = t.z;
    let choice = ws_discrete(u.x, n);
    output[o + 3u] = choice.index;
    output[o + 4u] = bitcast<u32>(choice.remapped);
    output[o + 5u] = bitcast<u32>(ws_cosine_hemisphere_pdf(u.x - 0.25));
    output[o + 6u] = bitcast<u32>(ws_uniform_hemisphere_pdf(vec3<f32>(0.0, 0.0, u.x - 0.5)));
    output[o + 7u] = bitcast<u32>(ws_uniform_sphere_pdf(vec3<f32>(u, 0.0)));
    output[o + 8u] = bitcast<u32>(ws_concentric_disk_pdf(2.0 * u - vec2<f32>(1.0)));
    output[o + 9u] = bitcast<u32>(ws_discrete_pdf(n));
    output[o + 10u] = bitcast<u32>(ws_uniform_triangle_pdf(u.x + 0x1p-24f));
    let disk = ws_concentric_disk(u);
    output[o + 11u] = bitcast<u32>(disk.x);
    output[o + 12u] = bitcast<u32>(disk.y);
    let cosine = bitcast<vec3<u32>>(ws_cosine_hemisphere(u));
    output[o + 13u] = cosine.x;
    output[o + 14u] = cosine.y;
    output[o + 15u] = cosine.z;
    let hemisphere = bitcast<vec3<u32>>(ws_uniform_hemisphere(u));
    output[o + 16u] = hemisphere.x;
    output[o + 17u] = hemisphere.y;
    output[o + 18u] = hemisphere.z;
    let sphere = bitcast<vec3<u32>>(ws_uniform_sphere(u));
    output[o + 19u] = sphere.x;
    output[o + 20u] = sphere.y;
    output[o + 21u] = sphere.z;
    output[o + 22u] = bitcast<u32>(ws_concentric_disk_pdf(disk));
    output[o + 23u] = bitcast<u32>(ws_cosine_hemisphere_pdf(bitcast<f32>(cosine.z)));
}
";

/// The CPU's outputs for one input, in the kernel's order.
pub fn cpu_outputs(input: &[u32]) -> [u32; OUTPUT_WORDS] {
    let u = Vec2::new(f32::from_bits(input[0]), f32::from_bits(input[1]));
    let n = input[2];
    let t = warp::uniform_triangle(u);
    let (index, remapped) = warp::discrete(u.x, n);
    let disk = warp::concentric_disk(u);
    let cosine = warp::cosine_hemisphere(u);
    let hemisphere = warp::uniform_hemisphere(u);
    let sphere = warp::uniform_sphere(u);
    let b = f32::to_bits;
    [
        b(t.x),
        b(t.y),
        b(t.z),
        index,
        b(remapped),
        b(warp::cosine_hemisphere_pdf(u.x - 0.25)),
        b(warp::uniform_hemisphere_pdf(Vec3::new(0.0, 0.0, u.x - 0.5))),
        b(warp::uniform_sphere_pdf(u.extend(0.0))),
        b(warp::concentric_disk_pdf(2.0 * u - Vec2::ONE)),
        b(warp::discrete_pdf(n)),
        b(warp::uniform_triangle_pdf(u.x + 1.0 / 16_777_216.0)),
        b(disk.x),
        b(disk.y),
        b(cosine.x),
        b(cosine.y),
        b(cosine.z),
        b(hemisphere.x),
        b(hemisphere.y),
        b(hemisphere.z),
        b(sphere.x),
        b(sphere.y),
        b(sphere.z),
        b(warp::concentric_disk_pdf(disk)),
        b(warp::cosine_hemisphere_pdf(cosine.z)),
    ]
}

/// `count` inputs: coordinates on the 2^-24 grid every sampler draws from
/// (edges 0, 2^-24, 1/2 and 1 - 2^-24 included), one in eight an
/// arbitrary float in `[2^-40, 1)`; counts 1 to `u32::MAX`.
pub fn inputs(count: usize, seed: u64) -> Vec<u32> {
    let mut state = seed;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 16) as u32
    };
    let edges = [0u32, 1, 1 << 23, (1 << 24) - 1, 1 << 22, 3 << 22, 1 << 21];
    let coordinate = |r: u32, s: u32| -> u32 {
        match r & 7 {
            0 => (edges[(s % edges.len() as u32) as usize] as f32 / 16_777_216.0).to_bits(),
            1 => {
                // An arbitrary float in [2^-40, 1): exponent 87 ..= 126.
                let exponent = 87 + s % 40;
                exponent << 23 | (s >> 9 & 0x7f_ffff)
            }
            _ => ((s >> 8) as f32 / 16_777_216.0).to_bits(),
        }
    };
    let mut words = Vec::with_capacity(count * INPUT_WORDS);
    for _ in 0..count {
        let (r, s, t, v) = (next(), next(), next(), next());
        let x = coordinate(r, s);
        let y = coordinate(r >> 3, t);
        let n = match v & 7 {
            0 => [1, 2, 3, u32::MAX, 1 << 24, (1 << 24) + 1, 5, 7][(v >> 3) as usize % 8],
            1..=3 => 1 + (v >> 3) % 16,
            _ => next().max(1),
        };
        words.extend_from_slice(&[x, y, n]);
    }
    words
}

/// The distance between two f32s in units in the last place (0 for equal
/// bits; both must have the same sign or be zero for a small result).
pub fn ulps(a: u32, b: u32) -> u64 {
    let key = |x: u32| -> i64 {
        if x >> 31 == 1 {
            -((x & 0x7fff_ffff) as i64)
        } else {
            x as i64
        }
    };
    key(a).abs_diff(key(b))
}

/// Per output word: mismatches, the largest difference in ulps and the
/// largest absolute difference.
#[derive(Clone, Copy, Debug, Default)]
pub struct Error {
    /// Words that differ.
    pub mismatches: usize,
    /// The largest ulp distance.
    pub max_ulps: u64,
    /// The largest absolute difference (as f64).
    pub max_abs: f64,
}

/// Runs the warps over `count` inputs on both sides; per output word its
/// [`Error`], and lines describing the first mismatches of the words that
/// must be bit-exact.
pub fn compare(
    gpu: &Gpu,
    source: &str,
    count: usize,
    seed: u64,
) -> ([Error; OUTPUT_WORDS], Vec<String>) {
    let shader = format!("{source}\n{HARNESS}\n{KERNEL}");
    let input = inputs(count, seed);
    let mut params = [0u32; 16];
    params[0] = count as u32;
    let got = gpu.run(&shader, &params, &input, count as u32, count * OUTPUT_WORDS);
    let mut errors = [Error::default(); OUTPUT_WORDS];
    let mut lines = Vec::new();
    for (input, got) in input
        .chunks_exact(INPUT_WORDS)
        .zip(got.chunks_exact(OUTPUT_WORDS))
    {
        let want = cpu_outputs(input);
        for (w, (&g, &c)) in got.iter().zip(&want).enumerate() {
            if g == c {
                continue;
            }
            let e = &mut errors[w];
            e.mismatches += 1;
            let is_index = w == 3;
            if !is_index {
                e.max_ulps = e.max_ulps.max(ulps(g, c));
                let d = (f64::from(f32::from_bits(g)) - f64::from(f32::from_bits(c))).abs();
                e.max_abs = e.max_abs.max(d);
            }
            if OUTPUT_NAMES[w].1 && lines.len() < 12 {
                lines.push(format!(
                    "u = ({}, {}), n = {}: {} GPU {g:#010x} CPU {c:#010x}",
                    f32::from_bits(input[0]),
                    f32::from_bits(input[1]),
                    input[2],
                    OUTPUT_NAMES[w].0
                ));
            }
        }
    }
    (errors, lines)
}
