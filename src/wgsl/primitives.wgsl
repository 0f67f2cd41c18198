// wellspread WGSL primitives: the integer hashes, Owen scrambles,
// permutations and unit conversions of `wellspread::primitives`, bit for
// bit. 64-bit values are `vec2<u32>(low, high)`. Every name starts with
// `ws_`. No floating point except `ws_unit` and `ws_stratum_unit`, whose only
// float operation is `f32(t) * 2^-24` with `t < 2^24` (exact everywhere).

// --- Salts (`primitives::salt`), 64-bit ones as (low, high) -------------
const WS_SALT_ORDER: u32 = 0x51633e2du;
const WS_SALT_JITTER_X: u32 = 0xa399d265u;
const WS_SALT_JITTER_Y: u32 = 0x711ad6a5u;
const WS_SALT_JITTER_1D: u32 = 0x68e31da4u;
const WS_SALT_SOBOL_Z: u32 = 0x6f4f2a35u;
const WS_SALT_SOBOL_W: u32 = 0x8f1bbcddu;
const WS_SALT_DRAW_ORDER: u32 = 0x2c1b3c6du;
const WS_SALT_DRAW_WEYL: vec2<u32> = vec2<u32>(0x7f4a7c15u, 0x9e3779b9u);
const WS_SALT_BRANCH_WEYL: vec2<u32> = vec2<u32>(0xf3bcc909u, 0x6a09e667u);
const WS_SALT_BRANCH: vec2<u32> = vec2<u32>(0x84caa73bu, 0xbb67ae85u);
const WS_SALT_SPLIT: vec2<u32> = vec2<u32>(0xfe94f82bu, 0x3c6ef372u);
const WS_SALT_PASS: vec2<u32> = vec2<u32>(0x5c26c926u, 0x2e1b2138u);
const WS_SALT_SECOND: vec2<u32> = vec2<u32>(0x5f1d36f1u, 0xa54ff53au);
const WS_SALT_PADDED_FRAME: vec2<u32> = vec2<u32>(0xade682d1u, 0x510e527fu);
const WS_SALT_ZSOBOL_FRAME: vec2<u32> = vec2<u32>(0x2b3e6c1fu, 0x9b05688cu);
const WS_SALT_BLUE_NOISE_FRAME: vec2<u32> = vec2<u32>(0xfb41bd6bu, 0x1f83d9abu);
const WS_SALT_BLUE_NOISE_PIXEL: vec2<u32> = vec2<u32>(0x137e2179u, 0x5be0cd19u);
const WS_SALT_RANDOM_INDEX: vec2<u32> = vec2<u32>(0xc1059ed9u, 0xcbbb9d5du);

// --- 32-bit helpers ------------------------------------------------------

fn ws_rotr(x: u32, r: u32) -> u32 {
    // `& 31u`: WGSL takes shift amounts mod 32, and r = 0 must give x.
    return (x >> (r & 31u)) | (x << ((32u - r) & 31u));
}

fn ws_rotl(x: u32, r: u32) -> u32 {
    return ws_rotr(x, (32u - r) & 31u);
}

// The full 64-bit product of two u32s, from four 16-bit partial products.
fn ws_mul_wide(a: u32, b: u32) -> vec2<u32> {
    let a0 = a & 0xffffu;
    let a1 = a >> 16u;
    let b0 = b & 0xffffu;
    let b1 = b >> 16u;
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let p11 = a1 * b1;
    let mid = (p00 >> 16u) + (p01 & 0xffffu) + (p10 & 0xffffu);
    return vec2<u32>((p00 & 0xffffu) | (mid << 16u), p11 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u));
}

// The high word of a u32 product (`(a as u64 * b as u64) >> 32`).
fn ws_mul_hi(a: u32, b: u32) -> u32 {
    return ws_mul_wide(a, b).y;
}

// --- 64-bit arithmetic on (low, high) pairs ------------------------------

fn ws_add64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let lo = a.x + b.x;
    return vec2<u32>(lo, a.y + b.y + select(0u, 1u, lo < a.x));
}

// The low 64 bits of a 64-bit product.
fn ws_mul64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let p = ws_mul_wide(a.x, b.x);
    return vec2<u32>(p.x, p.y + a.x * b.y + a.y * b.x);
}

// `z >> s` for 0 < s < 32.
fn ws_shr64(z: vec2<u32>, s: u32) -> vec2<u32> {
    return vec2<u32>((z.x >> s) | (z.y << (32u - s)), z.y >> s);
}

// SplitMix64's finaliser (`primitives::mix64`).
fn ws_mix64(z0: vec2<u32>) -> vec2<u32> {
    var z = z0;
    z = ws_mul64(z ^ ws_shr64(z, 30u), vec2<u32>(0x1ce4e5b9u, 0xbf58476du));
    z = ws_mul64(z ^ ws_shr64(z, 27u), vec2<u32>(0x133111ebu, 0x94d049bbu));
    return z ^ ws_shr64(z, 31u);
}

// `child_key`: a child's key from its parent's key, a salt and a u32.
fn ws_child_key(key: vec2<u32>, salt: vec2<u32>, child: u32) -> vec2<u32> {
    return ws_add64(ws_mix64(key ^ salt), ws_mul64(vec2<u32>(child, 0u), WS_SALT_BRANCH_WEYL));
}

// --- Hashes (`primitives::hash_u32`, `hash_combine`, `rand_u32`) ---------

fn ws_hash_u32(x0: u32) -> u32 {
    var x = x0;
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

fn ws_hash_combine(seed: u32, value: u32) -> u32 {
    return ws_hash_u32(seed ^ (ws_hash_u32(value) + 0x9e3779b9u));
}

fn ws_rand_u32(index: u32, pattern: u32) -> u32 {
    var i = index ^ pattern;
    i ^= i >> 17u;
    i ^= i >> 10u;
    i *= 0xb36534e5u;
    i ^= i >> 12u;
    i ^= i >> 21u;
    i *= 0x93fc4795u;
    i ^= 0xdf6e307fu;
    i ^= i >> 17u;
    i *= 1u | (pattern >> 18u);
    return i;
}

// --- Owen scrambling (`primitives::owen_scramble_reversed`) --------------

fn ws_owen_scramble_reversed(x0: u32, seed: u32) -> u32 {
    var x = x0 + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

fn ws_owen_scramble(x: u32, seed: u32) -> u32 {
    return reverseBits(ws_owen_scramble_reversed(reverseBits(x), seed));
}

// --- Permutations (`primitives::permute`, `prefix_shuffle`) --------------

fn ws_shuffle_round(x0: u32, k: u32, mask: u32, half: u32) -> u32 {
    var x = (x0 + k) & mask;
    x = (x * (ws_rotr(k, 11u) | 1u)) & mask;
    x ^= x >> half;
    return x ^ ((x >> 1u) & ws_rotr(k, 22u));
}

// One round of `prefix_shuffle` on the top bits of y: add r, multiply by
// the odd 2 r + 1, xorshift down by half.
fn ws_prefix_round(y0: u32, r: u32, half: u32) -> u32 {
    let y = (y0 + r) * (2u * r + 1u);
    return y ^ (y >> half);
}

// A keyed shuffle inside each dyadic block [2^j, 2^(j+1)), on the bits
// below the leading one moved to the top of the word. WGSL takes shift
// amounts mod 32, so each shift by 1 to 32 is two shifts.
fn ws_prefix_shuffle(index: u32, key: u32) -> u32 {
    let below = countLeadingZeros(index | 1u);
    let half = (32u - below) >> 1u;
    let bits = (index << below) << 1u;
    let domain = (0xffffffffu << below) << 1u;
    var y = ws_prefix_round(bits, key, half);
    y = ws_prefix_round(y & domain, ws_rotr(key, 16u), half);
    y = ws_prefix_round(y & domain, ws_rotr(key, 24u), half);
    y ^= (y >> 1u) & ws_rotr(key, 8u);
    return index ^ (((bits ^ y) >> below) >> 1u);
}

// `derived_key`: a permutation key from a pattern hash and a salt.
fn ws_derived_key(pattern_hash: u32, salt: u32) -> u32 {
    let k = ws_rotl(pattern_hash ^ salt, salt >> 27u) * 0x7feb352du;
    return k ^ (k >> 15u);
}

fn ws_permutation_hash(i0: u32, key: u32, mask: u32, half: u32, rounds: u32) -> u32 {
    var i = i0;
    for (var r = 0u; r < rounds; r++) {
        let k = ws_rotr(key, 7u * r);
        i = ws_shuffle_round(i, k, mask, half);
    }
    return i;
}

// Element `index` (< len) of the permutation of [0, len) keyed `key`
// (`Permutation::new(len, key).apply(index)`): a Fisher-Yates shuffle of
// nibbles up to 8 elements, else a cycle-walking hash and a rotation.
fn ws_permutation(index: u32, len: u32, key: u32) -> u32 {
    if (len <= 8u) {
        var packed = 0x76543210u;
        var u = key;
        var k = len;
        while (k > 1u) {
            k -= 1u;
            let product = ws_mul_wide(u, k + 1u);
            let j = product.y;
            u = product.x;
            let diff = ((packed >> (4u * k)) ^ (packed >> (4u * j))) & 0xfu;
            packed ^= (diff << (4u * k)) | (diff << (4u * j));
        }
        return (packed >> ((index & 7u) * 4u)) & 0xfu;
    }
    let rotation = ws_mul_hi(ws_rotr(key, 16u), len);
    let mask = 0xffffffffu >> countLeadingZeros(len - 1u);
    let bits = 32u - countLeadingZeros(mask);
    let half = (bits + 1u) >> 1u;
    let rounds = select(4u, 5u, bits <= 5u);
    var i = ws_permutation_hash(index, key, mask, half, rounds);
    while (i >= len) {
        i = ws_permutation_hash(i, key, mask, half, rounds);
    }
    let wrap = len - rotation;
    return select(i + rotation, i - wrap, i >= wrap);
}

// `primitives::permute(index, len, pattern)`.
fn ws_permute(index: u32, len: u32, pattern: u32) -> u32 {
    return ws_permutation(index % len, len, ws_hash_u32(pattern ^ 0x9e3779b9u));
}

// --- Unit conversions (`primitives::u32_to_unit_f32`, `stratum_to_unit_f32`) --

// 24-bit fixed point to f32: t < 2^24, so both operations are exact.
fn ws_fixed_to_unit(t: u32) -> f32 {
    return f32(t) * (1.0 / 16777216.0);
}

// The top 24 bits of `bits` as a float in [0, 1). The one conversion of
// random bits to floats: exact on every GPU.
fn ws_unit(bits: u32) -> f32 {
    return ws_fixed_to_unit(bits >> 8u);
}

// ceil((stratum 2^24) / strata) for stratum < strata <= 2^24, by long
// division in 8-bit digits (every remainder times 256 fits a u32).
fn ws_stratum_start(stratum: u32, strata: u32) -> u32 {
    // The 64-bit numerator stratum 2^24 + strata - 1 (below 2^49).
    let lo0 = stratum << 24u;
    let lo = lo0 + (strata - 1u);
    let hi = (stratum >> 8u) + select(0u, 1u, lo < lo0);
    var r = 0u;
    var q = 0u;
    for (var c = 0u; c < 7u; c++) {
        let at = 48u - 8u * c;
        var digit: u32;
        if (at >= 32u) {
            digit = (hi >> (at - 32u)) & 0xffu;
        } else {
            digit = (lo >> at) & 0xffu;
        }
        r = (r << 8u) | digit;
        q = (q << 8u) | (r / strata);
        r = r % strata;
    }
    return q;
}

// A value in stratum `stratum` of `strata` equal strata of [0, 1), placed
// by `bits` (`primitives::stratum_to_unit_f32`).
fn ws_stratum_unit(stratum: u32, strata: u32, bits: u32) -> f32 {
    if ((strata & (strata - 1u)) == 0u) {
        let k = countTrailingZeros(strata);
        return ws_fixed_to_unit((stratum << (24u - k)) + ((bits >> 8u) >> k));
    }
    let start = ws_stratum_start(stratum, strata);
    let end = ws_stratum_start(stratum + 1u, strata);
    let t = start + ws_mul_hi(end - start, bits);
    return ws_fixed_to_unit(min(t, 0xffffffu));
}

// --- Morton codes ---------------------------------------------------------

fn ws_spread_16(v0: u32) -> u32 {
    var v = v0 & 0xffffu;
    v = (v | (v << 8u)) & 0x00ff00ffu;
    v = (v | (v << 4u)) & 0x0f0f0f0fu;
    v = (v | (v << 2u)) & 0x33333333u;
    v = (v | (v << 1u)) & 0x55555555u;
    return v;
}

fn ws_morton(x: u32, y: u32) -> u32 {
    return ws_spread_16(x) | (ws_spread_16(y) << 1u);
}

fn ws_morton_add(code: u32, offset: u32) -> u32 {
    let x = ((code | 0xaaaaaaaau) + (offset & 0x55555555u)) & 0x55555555u;
    let y = ((code | 0x55555555u) + (offset & 0xaaaaaaaau)) & 0xaaaaaaaau;
    return x | y;
}
