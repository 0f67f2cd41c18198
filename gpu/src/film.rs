//! A film with one sample per pixel, on the GPU and on the CPU: pixel
//! `(x, y)` holds `next_2d()` and `next_1d()` of sample 0 as red, green and
//! blue.

use wellspread::PixelSampler;
use wellspread::wgsl::SOURCE;

use crate::samplers::Case;
use crate::{Gpu, HARNESS};

/// The film kernel: [`HARNESS`], then this, after `wgsl::SOURCE`.
pub const KERNEL: &str = "
// The sampler's kind, a pipeline constant: the compiler keeps one sampler.
override KIND: u32;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = invocation(id);
    let width = params[2].x;
    let height = params[2].y;
    // (`input` is unused here, but the harness binds it.)
    if (i >= width * height || arrayLength(&input) == 0u) {
        return;
    }
    let s = WsSampler(KIND, params[0].y, params[0].z, params[0].w,
                      params[1].x, params[1].y, params[1].z, params[1].w);
    var d = ws_start(s, vec2<u32>(i % width, i / width), 0u);
    let film = ws_next_2d(s, &d);
    let blue = ws_next_1d(s, &d);
    output[3u * i] = bitcast<u32>(film.x);
    output[3u * i + 1u] = bitcast<u32>(film.y);
    output[3u * i + 2u] = bitcast<u32>(blue);
}
";

/// The film of `case` at `width` x `height` as f32 bits, three per pixel,
/// from the GPU.
pub fn gpu_film(gpu: &Gpu, case: &Case, width: u32, height: u32) -> Vec<u32> {
    let mut params = [0u32; 16];
    params[..8].copy_from_slice(&case.gpu);
    params[8] = width;
    params[9] = height;
    let pixels = (width * height) as usize;
    gpu.kernel_with(
        &format!("{SOURCE}\n{HARNESS}\n{KERNEL}"),
        &[("KIND", f64::from(case.gpu[0]))],
    )
    .run(&params, &[], pixels as u32, 3 * pixels)
}

/// The same film from the CPU crate.
pub fn cpu_film(case: &Case, width: u32, height: u32) -> Vec<u32> {
    let mut film = Vec::with_capacity((3 * width * height) as usize);
    for y in 0..height {
        for x in 0..width {
            let mut d = case.cpu.start([x, y], 0);
            let p = d.next_2d();
            let blue = d.next_1d();
            film.extend([p.x.to_bits(), p.y.to_bits(), blue.to_bits()]);
        }
    }
    film
}

/// The film as a binary PPM (8 bits a channel, `floor(256 v)`).
pub fn ppm(film: &[u32], width: u32, height: u32) -> Vec<u8> {
    let mut out = format!("P6\n{width} {height}\n255\n").into_bytes();
    out.extend(
        film.iter()
            .map(|&bits| (f32::from_bits(bits) * 256.0) as u8),
    );
    out
}

/// The six pixel samplers with a WGSL twin, as the film shows them.
pub fn cases(width: u32, height: u32) -> Vec<Case> {
    use wellspread::SamplerKind;
    vec![
        Case::padded("random", SamplerKind::Random, 1, 0),
        Case::padded("sobol", SamplerKind::Sobol, 1, 0),
        Case::padded("pmj02", SamplerKind::Pmj02, 1, 0),
        Case::jittered("jittered", 1, 0),
        Case::zsobol("zsobol", 1, [width, height], 0),
        Case::blue_noise("blue-noise", 1, 0),
    ]
}
