// wellspread WGSL pixel samplers: `PixelSampler::start` and the draws of a
// `Domain` (`next_1d` ... `next_4d`, `branch`, `split`), bit for bit, for
// `Padded<Random>`, `Padded<Sobol>`, `Padded<Pmj02>`, `Padded<Jittered>`,
// `ZSobol` and `BlueNoise`. Needs primitives.wgsl before it.

const WS_RANDOM: u32 = 0u;
const WS_SOBOL: u32 = 1u;
const WS_PMJ02: u32 = 2u;
const WS_JITTERED: u32 = 3u;
const WS_ZSOBOL: u32 = 4u;
const WS_BLUE_NOISE: u32 = 5u;

// A pixel sampler's settings (what the CPU type holds), 8 u32s: fill one
// on the host with the `ws_*` constructors' arithmetic or call them here.
struct WsSampler {
    // WS_RANDOM ... WS_BLUE_NOISE.
    kind: u32,
    // Samples per pixel (`Random::new(n)`, `Jittered`: columns * rows,
    // `ZSobol`: a power of two). Sobol, Pmj02 and BlueNoise ignore it:
    // their draws continue the sequence past any count.
    n: u32,
    // Jittered's grid (`Jittered::columns()`, `rows()`).
    columns: u32,
    rows: u32,
    // The frame (`Padded::new(_, frame)`, `ZSobol::new(_, _, frame)`, ...).
    frame: u32,
    // ZSobol's film (`resolution`); BlueNoise has none.
    width: u32,
    height: u32,
    // ZSobol: log2 of the samples per pixel.
    log2_spp: u32,
}

fn ws_padded(kind: u32, n: u32, frame: u32) -> WsSampler {
    return WsSampler(kind, n, 1u, n, frame, 0u, 0u, 0u);
}

// `Padded::new(Jittered::with_grid(columns, rows)?, frame)`.
fn ws_jittered(columns: u32, rows: u32, frame: u32) -> WsSampler {
    return WsSampler(WS_JITTERED, columns * rows, columns, rows, frame, 0u, 0u, 0u);
}

// `ZSobol::new(spp, [width, height], frame)` (spp a power of two).
fn ws_zsobol(spp: u32, width: u32, height: u32, frame: u32) -> WsSampler {
    return WsSampler(WS_ZSOBOL, spp, 0u, 0u, frame, width, height, countTrailingZeros(spp));
}

// `BlueNoise::new(_, _, frame)`.
fn ws_blue_noise(frame: u32) -> WsSampler {
    return WsSampler(WS_BLUE_NOISE, 0u, 0u, 0u, frame, 0u, 0u, 0u);
}

// One pixel sample's state (`Domain`): 5 u32s, passed by value or pointer.
struct WsDomain {
    key: vec2<u32>,
    index: u32,
    draws: u32,
    pixel_state: u32,
}

// What one draw hands its sampler (`Draw`).
struct WsDraw {
    index: u32,
    pixel_state: u32,
    stream: vec2<u32>,
}

// `Draw::new(key, draw, dimension, index, pixel_state)` without the
// `dimension` and `key` fields, which only `PaddedNd` reads and WGSL has no
// twin of: the same `index`, `pixel_state` and `stream`.
fn ws_draw(key: vec2<u32>, draw: u32, index: u32, pixel_state: u32) -> WsDraw {
    return WsDraw(index, pixel_state, ws_mix64(ws_add64(key, ws_mul64(vec2<u32>(draw, 0u), WS_SALT_DRAW_WEYL))));
}

fn ws_second_stream(stream: vec2<u32>) -> vec2<u32> {
    return ws_mix64(stream ^ WS_SALT_SECOND);
}

// --- Owen-scrambled Sobol' (the `digital` module) --------------------------

// `OwenSeeds::from_stream`: (index, x, y).
fn ws_seeds(stream: vec2<u32>) -> vec3<u32> {
    return vec3<u32>(ws_rotr(stream.x ^ stream.y, 16u) ^ WS_SALT_DRAW_ORDER, stream.y, stream.x);
}

fn ws_pascal_reversed(index: u32) -> u32 {
    var y = index;
    y ^= (y >> 1u) & 0x55555555u;
    y ^= (y >> 2u) & 0x33333333u;
    y ^= (y >> 4u) & 0x0f0f0f0fu;
    y ^= (y >> 8u) & 0x00ff00ffu;
    y ^= y >> 16u;
    return y;
}

fn ws_stirling_x(index: u32) -> u32 {
    var w = index;
    w ^= (w & 0xccccccccu) >> 1u;
    w ^= (w & 0xf0f0f0f0u) >> 2u;
    w ^= (w & 0xff00ff00u) >> 4u;
    w ^= (w & 0xffff0000u) >> 8u;
    return w;
}

fn ws_stirling_y(index: u32) -> u32 {
    return (ws_stirling_x(index << 1u) >> 1u) ^ ((0u - (index >> 31u)) & 0x80008000u);
}

// Sobol' dimensions 2 and 3, bit-reversed: column j of each generator
// matrix (index bit j), as (dimension 2, dimension 3). Generated from the
// CPU tables; a library test checks them.
const WS_SOBOL_COLUMNS_2_3 = array<vec2<u32>, 32>(
// ws-sobol-columns-begin
    vec2<u32>(0x00000001u, 0x00000001u),
    vec2<u32>(0x00000003u, 0x00000003u),
    vec2<u32>(0x00000006u, 0x00000004u),
    vec2<u32>(0x00000009u, 0x0000000au),
    vec2<u32>(0x00000017u, 0x0000001fu),
    vec2<u32>(0x0000003au, 0x0000002eu),
    vec2<u32>(0x00000071u, 0x00000045u),
    vec2<u32>(0x000000a3u, 0x000000c9u),
    vec2<u32>(0x00000116u, 0x0000011bu),
    vec2<u32>(0x00000339u, 0x000002a4u),
    vec2<u32>(0x00000677u, 0x0000079au),
    vec2<u32>(0x000009aau, 0x00000b67u),
    vec2<u32>(0x00001601u, 0x0000101eu),
    vec2<u32>(0x00003903u, 0x0000302du),
    vec2<u32>(0x00007706u, 0x00004041u),
    vec2<u32>(0x0000aa09u, 0x0000a0c3u),
    vec2<u32>(0x00010117u, 0x0001f104u),
    vec2<u32>(0x0003033au, 0x0002e28au),
    vec2<u32>(0x00060671u, 0x000457dfu),
    vec2<u32>(0x000909a3u, 0x000c9baeu),
    vec2<u32>(0x00171616u, 0x0011a105u),
    vec2<u32>(0x003a3939u, 0x002a7289u),
    vec2<u32>(0x00717777u, 0x0079e7dbu),
    vec2<u32>(0x00a3aaaau, 0x00b6dba4u),
    vec2<u32>(0x01170001u, 0x0100011au),
    vec2<u32>(0x033a0003u, 0x030002a7u),
    vec2<u32>(0x06710006u, 0x0400079eu),
    vec2<u32>(0x09a30009u, 0x0a000b6du),
    vec2<u32>(0x16160017u, 0x1f001001u),
    vec2<u32>(0x3939003au, 0x2e003003u),
    vec2<u32>(0x77770071u, 0x45004004u),
    vec2<u32>(0xaaaa00a3u, 0xc900a00au),
// ws-sobol-columns-end
);

// The xor of the columns whose bits are set in `bits`: a 32 x 64 matrix
// over GF(2) times a vector.
fn ws_xor_columns(columns: array<vec2<u32>, 32>, bits: u32) -> vec2<u32> {
    var v = vec2<u32>(0u, 0u);
    for (var j = 0u; j < 32u; j++) {
        v ^= columns[j] & vec2<u32>(0u - ((bits >> j) & 1u));
    }
    return v;
}

fn ws_sobol_2_3_reversed(index: u32) -> vec2<u32> {
    return ws_xor_columns(WS_SOBOL_COLUMNS_2_3, index);
}

fn ws_scrambled_unit(reversed: u32, seed: u32) -> f32 {
    return ws_unit(reverseBits(ws_owen_scramble_reversed(reversed, seed)));
}

fn ws_scrambled_point(x_reversed: u32, y_reversed: u32, seeds: vec3<u32>) -> vec2<f32> {
    return vec2<f32>(
        ws_scrambled_unit(x_reversed, seeds.y),
        ws_scrambled_unit(y_reversed, seeds.z),
    );
}

// `sobol_4d_point(s, stream, shift)`.
fn ws_sobol_4d_point(s: u32, stream: vec2<u32>, shift: vec4<u32>) -> vec4<f32> {
    let seeds = ws_seeds(stream);
    let z = ws_rotr(stream.x, 11u) ^ ws_rotr(stream.y, 5u) ^ WS_SALT_SOBOL_Z;
    let w = ws_rotr(stream.y, 21u) ^ ws_rotr(stream.x, 27u) ^ WS_SALT_SOBOL_W;
    let c23 = ws_sobol_2_3_reversed(s);
    return vec4<f32>(
        ws_scrambled_unit(s ^ shift.x, seeds.y),
        ws_scrambled_unit(ws_pascal_reversed(s) ^ shift.y, seeds.z),
        ws_scrambled_unit(c23.x ^ shift.z, z),
        ws_scrambled_unit(c23.y ^ shift.w, w),
    );
}

// --- The progressive sequences (Sobol, Pmj02) ------------------------------

fn ws_sobol_1d(index: u32, stream: vec2<u32>) -> f32 {
    let seeds = ws_seeds(stream);
    return ws_scrambled_unit(ws_prefix_shuffle(index, seeds.x), seeds.y);
}

fn ws_sobol_2d(index: u32, stream: vec2<u32>) -> vec2<f32> {
    let seeds = ws_seeds(stream);
    let s = ws_prefix_shuffle(index, seeds.x);
    return ws_scrambled_point(s, ws_pascal_reversed(s), seeds);
}

fn ws_pmj02_2d(index: u32, stream: vec2<u32>) -> vec2<f32> {
    let seeds = ws_seeds(stream);
    let s = ws_prefix_shuffle(index, seeds.x);
    return ws_scrambled_point(ws_stirling_x(s), ws_stirling_y(s), seeds);
}

fn ws_sobol_4d(index: u32, stream: vec2<u32>) -> vec4<f32> {
    let s = ws_prefix_shuffle(index, ws_seeds(stream).x);
    return ws_sobol_4d_point(s, stream, vec4<u32>(0u));
}

// --- Random ------------------------------------------------------------------

fn ws_random_2d(stream: vec2<u32>) -> vec2<f32> {
    return vec2<f32>(ws_unit(stream.y), ws_unit(stream.x));
}

// --- Jittered (the grid family's defaults) -----------------------------------

// `stratified_1d(index, n, stream, true)`: the default 1D draw.
fn ws_stratified_1d(index0: u32, n0: u32, stream: vec2<u32>) -> f32 {
    let n = clamp(n0, 1u, 0x1000000u);
    let index = index0 % n;
    let stratum = ws_permute(index, n, stream.x);
    let bits = ws_rand_u32(index, stream.y ^ WS_SALT_JITTER_1D);
    return ws_stratum_unit(stratum, n, bits);
}

// `Jittered::sample(index, pattern)` for index < columns * rows.
fn ws_jittered_sample(s: WsSampler, index: u32, pattern: u32) -> vec2<f32> {
    let pattern_hash = ws_hash_u32(pattern);
    let cell = ws_permutation(index, s.n, ws_derived_key(pattern_hash, WS_SALT_ORDER));
    let row = cell / s.columns;
    let column = cell - row * s.columns;
    return vec2<f32>(
        ws_stratum_unit(column, s.columns, ws_rand_u32(cell, pattern_hash ^ WS_SALT_JITTER_X)),
        ws_stratum_unit(row, s.rows, ws_rand_u32(cell, pattern_hash ^ WS_SALT_JITTER_Y)),
    );
}

// --- ZSobol --------------------------------------------------------------------

fn ws_zsobol_index(s: WsSampler, d: WsDraw) -> u32 {
    let seeds = ws_seeds(d.stream);
    let low = (1u << s.log2_spp) - 1u;
    let place = ws_prefix_shuffle(d.index & low, ws_hash_u32(seeds.x ^ d.pixel_state));
    return ws_owen_scramble(d.pixel_state | place, ws_rotr(seeds.y, 8u) ^ ws_rotr(seeds.z, 24u));
}

fn ws_zsobol_1d(s: WsSampler, d: WsDraw) -> f32 {
    return ws_scrambled_unit(ws_zsobol_index(s, d), ws_seeds(d.stream).y);
}

fn ws_zsobol_2d(s: WsSampler, d: WsDraw) -> vec2<f32> {
    let i = ws_zsobol_index(s, d);
    return ws_scrambled_point(i, ws_pascal_reversed(i), ws_seeds(d.stream));
}

fn ws_zsobol_4d(s: WsSampler, d: WsDraw) -> vec4<f32> {
    return ws_sobol_4d_point(ws_zsobol_index(s, d), d.stream, vec4<u32>(0u));
}

// --- BlueNoise -------------------------------------------------------------------

// `BlueNoise::pixel_shift(1 << p)` for bit p of the reversed, scrambled
// Morton code, as (x, y). Generated from the CPU tables; a library test
// checks them.
const WS_BLUE_NOISE_COLUMNS = array<vec2<u32>, 32>(
// ws-blue-noise-columns-begin
    vec2<u32>(0x001f7535u, 0x009b897du),
    vec2<u32>(0x007c92bau, 0x006d233bu),
    vec2<u32>(0x0017f302u, 0x00d43b84u),
    vec2<u32>(0x009f7f67u, 0x00ccc096u),
    vec2<u32>(0x007750d4u, 0x0009382eu),
    vec2<u32>(0x000e40bau, 0x0090ec3bu),
    vec2<u32>(0x00b75f9eu, 0x00f6f7d8u),
    vec2<u32>(0x008360c0u, 0x00c3d628u),
    vec2<u32>(0x00aa23c4u, 0x002cca14u),
    vec2<u32>(0x00be20ceu, 0x0034affcu),
    vec2<u32>(0x00aa6475u, 0x008bde38u),
    vec2<u32>(0x00d3bf3au, 0x0029c77du),
    vec2<u32>(0x00dbc356u, 0x00a28beau),
    vec2<u32>(0x004a1b1du, 0x00496671u),
    vec2<u32>(0x007aca14u, 0x00a580afu),
    vec2<u32>(0x00292526u, 0x00a84026u),
    vec2<u32>(0x003f2eb7u, 0x00bcfde5u),
    vec2<u32>(0x00fd5635u, 0x00d1e6c0u),
    vec2<u32>(0x00471263u, 0x00e52173u),
    vec2<u32>(0x00ea8d43u, 0x00c8da7cu),
    vec2<u32>(0x0038bfecu, 0x0057027du),
    vec2<u32>(0x00070776u, 0x002906a3u),
    vec2<u32>(0x00b94594u, 0x00f60dd7u),
    vec2<u32>(0x00420772u, 0x0081a37au),
    vec2<u32>(0x00d476c6u, 0x000a7b2eu),
    vec2<u32>(0x00f1964eu, 0x00566580u),
    vec2<u32>(0x00ae77b6u, 0x002cd356u),
    vec2<u32>(0x001230acu, 0x0078af0eu),
    vec2<u32>(0x000de489u, 0x00d46852u),
    vec2<u32>(0x001d4358u, 0x00a8bff6u),
    vec2<u32>(0x002b1c16u, 0x00d6fa7du),
    vec2<u32>(0x00a79a3bu, 0x004aa7e7u),
// ws-blue-noise-columns-end
);

fn ws_blue_noise_pixel_shift(code_reversed: u32) -> vec2<u32> {
    return ws_xor_columns(WS_BLUE_NOISE_COLUMNS, code_reversed);
}

// `BlueNoise::translated`: (code, seed).
fn ws_blue_noise_translated(code: u32, stream: vec2<u32>) -> vec2<u32> {
    let extra = ws_mix64(stream ^ WS_SALT_BLUE_NOISE_PIXEL);
    return vec2<u32>(ws_morton_add(code, extra.x), extra.y);
}

fn ws_blue_noise_shift(translated: vec2<u32>) -> vec2<u32> {
    return ws_blue_noise_pixel_shift(ws_owen_scramble_reversed(reverseBits(translated.x), translated.y));
}

// `BlueNoise::index_and_shift`'s index.
fn ws_blue_noise_index(d: WsDraw, seeds: vec3<u32>, code: u32) -> u32 {
    return ws_prefix_shuffle(d.index, ws_hash_u32(seeds.x ^ (code >> 8u)));
}

fn ws_blue_noise_2d(d: WsDraw) -> vec2<f32> {
    let seeds = ws_seeds(d.stream);
    let t = ws_blue_noise_translated(d.pixel_state, d.stream);
    let s = ws_blue_noise_index(d, seeds, t.x);
    let g = ws_blue_noise_shift(t);
    return ws_scrambled_point(s ^ g.x, ws_pascal_reversed(s) ^ g.y, seeds);
}

fn ws_blue_noise_4d(d: WsDraw) -> vec4<f32> {
    let seeds = ws_seeds(d.stream);
    let t = ws_blue_noise_translated(d.pixel_state, d.stream);
    let s = ws_blue_noise_index(d, seeds, t.x);
    let g = ws_blue_noise_shift(t);
    let h = ws_blue_noise_shift(ws_blue_noise_translated(d.pixel_state, ws_second_stream(d.stream)));
    return ws_sobol_4d_point(s, d.stream, vec4<u32>(g, h));
}

// --- PixelSampler: root, locate and the draws ---------------------------------

// `PixelSampler::root`: (key low, key high, pixel state).
fn ws_root(s: WsSampler, pixel: vec2<u32>) -> vec3<u32> {
    switch s.kind {
        case 4u: {
            // ZSobol: a pixel off the film wraps onto it, keyed by its tile.
            var p = pixel;
            var tile = 0u;
            if (p.x >= s.width || p.y >= s.height) {
                tile = ws_hash_combine(p.x / s.width, p.y / s.height) | 1u;
                p = vec2<u32>(p.x % s.width, p.y % s.height);
            }
            let frame_key = ws_mix64(vec2<u32>(s.frame, 0u) ^ WS_SALT_ZSOBOL_FRAME);
            return vec3<u32>(frame_key.x, frame_key.y ^ tile, ws_morton(p.x, p.y) << s.log2_spp);
        }
        case 5u: {
            let tile = (pixel.x >> 16u) | ((pixel.y >> 16u) << 16u);
            let frame_key = ws_mix64(vec2<u32>(s.frame, 0u) ^ WS_SALT_BLUE_NOISE_FRAME);
            return vec3<u32>(frame_key.x, frame_key.y ^ tile, ws_morton(pixel.x, pixel.y));
        }
        default: {
            let key = vec2<u32>(pixel.x, pixel.y) ^ ws_mul64(vec2<u32>(s.frame, 0u), WS_SALT_PADDED_FRAME);
            return vec3<u32>(key, 0u);
        }
    }
}

// `PixelSampler::locate`: where sample `index` of a domain keyed `key`
// lives, as (index, key low, key high).
fn ws_locate(s: WsSampler, index: u32, key: vec2<u32>) -> vec3<u32> {
    switch s.kind {
        case 0u: {
            return vec3<u32>(index, key ^ ws_mul64(vec2<u32>(index, 0u), WS_SALT_RANDOM_INDEX));
        }
        case 3u: {
            if (index < s.n) {
                return vec3<u32>(index, key);
            }
            return vec3<u32>(index % s.n, ws_child_key(key, WS_SALT_PASS, index / s.n));
        }
        case 4u: {
            let pass_index = index >> s.log2_spp;
            if (pass_index == 0u) {
                return vec3<u32>(index, key);
            }
            return vec3<u32>(index & ((1u << s.log2_spp) - 1u), ws_child_key(key, WS_SALT_PASS, pass_index));
        }
        default: {
            return vec3<u32>(index, key);
        }
    }
}

fn ws_draw_2d(s: WsSampler, d: WsDraw) -> vec2<f32> {
    switch s.kind {
        case 0u: {
            return ws_random_2d(d.stream);
        }
        case 1u: {
            return ws_sobol_2d(d.index, d.stream);
        }
        case 2u: {
            return ws_pmj02_2d(d.index, d.stream);
        }
        case 3u: {
            return ws_jittered_sample(s, d.index, d.stream.x);
        }
        case 4u: {
            return ws_zsobol_2d(s, d);
        }
        default: {
            return ws_blue_noise_2d(d);
        }
    }
}

fn ws_draw_1d(s: WsSampler, d: WsDraw) -> f32 {
    switch s.kind {
        case 0u: {
            return ws_unit(d.stream.y);
        }
        case 1u, 2u: {
            return ws_sobol_1d(d.index, d.stream);
        }
        case 3u: {
            return ws_stratified_1d(d.index, s.n, d.stream);
        }
        case 4u: {
            return ws_zsobol_1d(s, d);
        }
        default: {
            return ws_blue_noise_2d(d).x;
        }
    }
}

fn ws_draw_4d(s: WsSampler, d: WsDraw) -> vec4<f32> {
    switch s.kind {
        case 1u, 2u: {
            return ws_sobol_4d(d.index, d.stream);
        }
        case 4u: {
            return ws_zsobol_4d(s, d);
        }
        case 5u: {
            return ws_blue_noise_4d(d);
        }
        default: {
            // Two padded pairs: the draw and its second stream.
            let second = WsDraw(d.index, d.pixel_state, ws_second_stream(d.stream));
            return vec4<f32>(ws_draw_2d(s, d), ws_draw_2d(s, second));
        }
    }
}

fn ws_draw_3d(s: WsSampler, d: WsDraw) -> vec3<f32> {
    switch s.kind {
        case 0u, 3u: {
            // A pair and a 1D draw of the second stream.
            let second = WsDraw(d.index, d.pixel_state, ws_second_stream(d.stream));
            return vec3<f32>(ws_draw_2d(s, d), ws_draw_1d(s, second));
        }
        default: {
            return ws_draw_4d(s, d).xyz;
        }
    }
}

// --- Domain -----------------------------------------------------------------------

// `PixelSampler::start(pixel, index)`.
fn ws_start(s: WsSampler, pixel: vec2<u32>, index: u32) -> WsDomain {
    let root = ws_root(s, pixel);
    let at = ws_locate(s, index, root.xy);
    return WsDomain(at.yz, at.x, 0u, root.z);
}

// The next draw's inputs; advances the draw counter.
fn ws_advance(d: ptr<function, WsDomain>) -> WsDraw {
    let draw = ws_draw((*d).key, (*d).draws, (*d).index, (*d).pixel_state);
    (*d).draws += 1u;
    return draw;
}

fn ws_next_1d(s: WsSampler, d: ptr<function, WsDomain>) -> f32 {
    return ws_draw_1d(s, ws_advance(d));
}

fn ws_next_2d(s: WsSampler, d: ptr<function, WsDomain>) -> vec2<f32> {
    return ws_draw_2d(s, ws_advance(d));
}

fn ws_next_3d(s: WsSampler, d: ptr<function, WsDomain>) -> vec3<f32> {
    return ws_draw_3d(s, ws_advance(d));
}

fn ws_next_4d(s: WsSampler, d: ptr<function, WsDomain>) -> vec4<f32> {
    return ws_draw_4d(s, ws_advance(d));
}

// `Domain::branch(key)`: the child keyed `key`, at draw 0.
fn ws_branch(d: WsDomain, key: u32) -> WsDomain {
    return WsDomain(ws_child_key(d.key, WS_SALT_BRANCH, key), d.index, 0u, d.pixel_state);
}

// `Domain::split(key, count, j)`: sample `index * count + j` of the child
// keyed `key` (count 0 is taken as 1, as a release build does).
fn ws_split(s: WsSampler, d: WsDomain, key: u32, count: u32, j: u32) -> WsDomain {
    let child = d.index * max(count, 1u) + j;
    let at = ws_locate(s, child, ws_child_key(d.key, WS_SALT_SPLIT, key));
    return WsDomain(at.yz, at.x, 0u, d.pixel_state);
}

// `PixelSampler::sample_pixel(pixel, index, pair)`.
fn ws_sample_pixel(s: WsSampler, pixel: vec2<u32>, index: u32, pair: u32) -> vec2<f32> {
    var d = ws_start(s, pixel, index);
    d.draws = pair;
    return ws_next_2d(s, &d);
}
