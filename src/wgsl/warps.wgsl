// wellspread WGSL warps: `wellspread::warp`'s maps of the unit square with
// their pdfs. `ws_uniform_triangle`, `ws_discrete` and the constant pdfs
// are bit-exact; the maps that call sin, cos or sqrt or divide are within
// the bounds of docs/gpu.md. Needs nothing before it.

const WS_FRAC_1_PI: f32 = 0x1.45f306p-2f;
const WS_FRAC_PI_2: f32 = 0x1.921fb6p+0f;
const WS_FRAC_PI_4: f32 = 0x1.921fb6p-1f;
const WS_TAU: f32 = 0x1.921fb6p+2f;
// The largest f32 below 1.
const WS_ONE_MINUS_EPSILON: f32 = 0x1.fffffep-1f;
// `concentric_disk_pdf`'s slack in squared length: 4 f32::EPSILON.
const WS_DISK_SLACK: f32 = 0x1p-21f;

// A coordinate clamped to [0, 1).
fn ws_warp_unit(x: f32) -> f32 {
    return min(max(x, 0.0), WS_ONE_MINUS_EPSILON);
}

fn ws_warp_unit2(u: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(ws_warp_unit(u.x), ws_warp_unit(u.y));
}

// Shirley and Chiu's concentric map onto the unit disk (`warp::concentric_disk`).
fn ws_concentric_disk(u: vec2<f32>) -> vec2<f32> {
    let o = 2.0 * ws_warp_unit2(u) - vec2<f32>(1.0);
    if (o.x == 0.0 && o.y == 0.0) {
        return vec2<f32>(0.0);
    }
    var r: f32;
    var theta: f32;
    if (abs(o.x) > abs(o.y)) {
        r = o.x;
        theta = WS_FRAC_PI_4 * (o.y / o.x);
    } else {
        r = o.y;
        theta = WS_FRAC_PI_2 - WS_FRAC_PI_4 * (o.x / o.y);
    }
    return vec2<f32>(r * cos(theta), r * sin(theta));
}

// 1/pi inside the disk (with the map's rounding slack), else 0.
fn ws_concentric_disk_pdf(p: vec2<f32>) -> f32 {
    return select(0.0, WS_FRAC_1_PI, p.x * p.x + p.y * p.y <= 1.0 + WS_DISK_SLACK);
}

// Cosine-weighted directions about +z (`warp::cosine_hemisphere`).
fn ws_cosine_hemisphere(u: vec2<f32>) -> vec3<f32> {
    let d = ws_concentric_disk(u);
    let z = sqrt(max(1.0 - (d.x * d.x + d.y * d.y), 0x1p-24f));
    return vec3<f32>(d, z);
}

fn ws_cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    return max(cos_theta, 0.0) * WS_FRAC_1_PI;
}

// Uniform directions on the hemisphere about +z (`warp::uniform_hemisphere`).
fn ws_uniform_hemisphere(u0: vec2<f32>) -> vec3<f32> {
    let u = ws_warp_unit2(u0);
    let z = u.x;
    let r = sqrt(max((1.0 - z) * (1.0 + z), 0.0));
    let phi = WS_TAU * u.y;
    return vec3<f32>(r * cos(phi), r * sin(phi), z);
}

fn ws_uniform_hemisphere_pdf(v: vec3<f32>) -> f32 {
    return select(0.0, 0.5 * WS_FRAC_1_PI, v.z >= 0.0);
}

// Uniform directions on the unit sphere (`warp::uniform_sphere`).
fn ws_uniform_sphere(u0: vec2<f32>) -> vec3<f32> {
    let u = ws_warp_unit2(u0);
    let z = 1.0 - 2.0 * u.x;
    let r = 2.0 * sqrt(max(u.x * (1.0 - u.x), 0.0));
    let phi = WS_TAU * u.y;
    return vec3<f32>(r * cos(phi), r * sin(phi), z);
}

fn ws_uniform_sphere_pdf(v: vec3<f32>) -> f32 {
    return 0.25 * WS_FRAC_1_PI;
}

// Uniform barycentrics on a triangle (`warp::uniform_triangle`, Heitz's
// low-distortion map): bit-exact.
fn ws_uniform_triangle(u0: vec2<f32>) -> vec3<f32> {
    let u = ws_warp_unit2(u0);
    if (u.x < u.y) {
        let b0 = 0.5 * u.x;
        return vec3<f32>(b0, u.y - b0, 1.0 - u.y);
    }
    let b1 = 0.5 * u.y;
    return vec3<f32>(u.x - b1, b1, 1.0 - u.x);
}

fn ws_uniform_triangle_pdf(area: f32) -> f32 {
    return 1.0 / area;
}

// A choice among n equal ones and the remapped rest of u.
struct WsChoice {
    index: u32,
    remapped: f32,
}

// 1 << k as a (low, high) pair, k < 64.
fn ws_bit64(k: u32) -> vec2<u32> {
    if (k >= 32u) {
        return vec2<u32>(0u, 1u << (k - 32u));
    }
    return vec2<u32>(1u << k, 0u);
}

// z >> k for k < 64.
fn ws_shr64_any(z: vec2<u32>, k: u32) -> vec2<u32> {
    if (k == 0u) {
        return z;
    }
    if (k >= 32u) {
        return vec2<u32>(z.y >> (k - 32u), 0u);
    }
    return vec2<u32>((z.x >> k) | (z.y << (32u - k)), z.y >> k);
}

// z & (2^k - 1) for k < 64.
fn ws_low_bits64(z: vec2<u32>, k: u32) -> vec2<u32> {
    if (k >= 32u) {
        return vec2<u32>(z.x, z.y & ((1u << (k - 32u)) - 1u));
    }
    return vec2<u32>(z.x & ((1u << k) - 1u), 0u);
}

fn ws_gt64(a: vec2<u32>, b: vec2<u32>) -> bool {
    return a.y > b.y || (a.y == b.y && a.x > b.x);
}

// The f32 bits of rest 2^-shift (rest < 2^shift, shift < 64), rounded once
// to nearest, ties to even, as Rust's `rest as f32` then the exact scaling.
fn ws_scaled_f32_bits(rest: vec2<u32>, shift: u32) -> u32 {
    if (rest.x == 0u && rest.y == 0u) {
        return 0u;
    }
    var top: u32;
    if (rest.y != 0u) {
        top = 63u - countLeadingZeros(rest.y);
    } else {
        top = 31u - countLeadingZeros(rest.x);
    }
    var mantissa: u32;
    if (top <= 23u) {
        mantissa = rest.x << (23u - top);
    } else {
        let drop = top - 23u;
        mantissa = ws_shr64_any(rest, drop).x;
        let below = ws_low_bits64(rest, drop);
        let half = ws_bit64(drop - 1u);
        let tie = below.x == half.x && below.y == half.y;
        if (ws_gt64(below, half) || (tie && (mantissa & 1u) == 1u)) {
            mantissa += 1u;
            if (mantissa == 0x1000000u) {
                mantissa = 0x800000u;
                top += 1u;
            }
        }
    }
    // top - shift + 127 >= 64: always a normal number.
    return ((top + 127u - shift) << 23u) | (mantissa & 0x7fffffu);
}

// `warp::discrete(u, n)`: the choice floor(u n) and the rest u n - index,
// rounded once; bit-exact for every u from a sampler (u >= 2^-40 or 0).
fn ws_discrete(u0: f32, n0: u32) -> WsChoice {
    let n = max(n0, 1u);
    let u = ws_warp_unit(u0);
    let bits = bitcast<u32>(u);
    let exponent = (bits >> 23u) & 0xffu;
    if (exponent == 0u && (bits & 0x7fffffu) == 0u) {
        return WsChoice(0u, 0.0);
    }
    var m: u32;
    var shift: u32;
    if (exponent == 0u) {
        m = bits & 0x7fffffu;
        shift = 149u;
    } else {
        m = (bits & 0x7fffffu) | 0x800000u;
        shift = 150u - exponent;
    }
    if (shift >= 64u) {
        // u n < 2^-8: choice 0, the f32 product (not bit-exact on a GPU).
        return WsChoice(0u, ws_warp_unit(u * f32(n)));
    }
    let scaled = ws_mul_wide(m, n);
    let index = ws_shr64_any(scaled, shift).x;
    let rest = ws_low_bits64(scaled, shift);
    let remapped = min(ws_scaled_f32_bits(rest, shift), 0x3f7fffffu);
    return WsChoice(index, bitcast<f32>(remapped));
}

fn ws_discrete_pdf(n: u32) -> f32 {
    return select(1.0 / f32(n), 0.0, n == 0u);
}
