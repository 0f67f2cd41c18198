//! Golden values: the first samples of every sampler in `SamplerKind::ALL`,
//! and the public primitives, pinned bit for bit.
//!
//! Sample values are part of wellspread's contract: a renderer that stores
//! seeds, or compares images across versions, relies on them. **Changing any
//! value below is a breaking change**: record it in CHANGELOG.md, saying which
//! samplers changed and why.
//!
//! Every kind is pinned at the same cases ([`CASES`]: n = 1, a square, a
//! non-square and a prime; patterns 0, `u32::MAX` and one in between), as
//! `f32::to_bits` of (x, y) for the first 8 indices (fewer when n < 8); the
//! decimal value in each comment is for reading only. A kind without its
//! entries fails `every_kind_is_pinned_at_every_case`, so a new sampler
//! cannot ship unpinned.
//!
//! # Blessing new values
//!
//! When a change of values is intended, regenerate both tables from the
//! implementation (after the property tests in `tests/samplers.rs` pass):
//!
//! ```text
//! WELLSPREAD_BLESS=1 cargo test --test golden -- --nocapture --test-threads 1
//! ```
//!
//! prints the Rust source of `GOLDEN` and `PRIMITIVES` (with the tests
//! passing, not comparing); paste each over the constant of the same name
//! below, run `cargo fmt`, and check the diff touches only what you meant to
//! change.

use wellspread::glam::Vec2;
use wellspread::primitives::{
    hash_combine, hash_u32, pattern_seed, permute, rand_u32, stratum_to_unit_f32, u32_to_unit_f32,
};
use wellspread::{Sampler2D, SamplerKind};

/// The (n, pattern) pairs every sampler is pinned at: n = 1 at both pattern
/// extremes, a 4 x 4 square, a 4 x 6 non-square and the prime 97.
const CASES: [(u32, u32); 6] = [
    (1, 0),
    (1, u32::MAX),
    (16, 0),
    (16, u32::MAX),
    (24, 0xdead_beef),
    (97, 0),
];

/// How many leading samples each case pins.
const PINNED: u32 = 8;

/// True when the tests should print new tables instead of comparing.
fn blessing() -> bool {
    std::env::var_os("WELLSPREAD_BLESS").is_some_and(|v| !v.is_empty() && v != "0")
}

fn bits(p: Vec2) -> [u32; 2] {
    [p.x.to_bits(), p.y.to_bits()]
}

/// The first samples of `kind` at (n, pattern), through `sample`.
fn first_samples(kind: SamplerKind, n: u32, pattern: u32) -> Vec<[u32; 2]> {
    let sampler = kind
        .build(n)
        .unwrap_or_else(|e| panic!("{kind} n = {n}: {e}"));
    (0..n.min(PINNED))
        .map(|i| bits(sampler.sample(i, pattern)))
        .collect()
}

fn pattern_literal(pattern: u32) -> String {
    if pattern == u32::MAX {
        "u32::MAX".to_owned()
    } else {
        format!("{pattern:#x}")
    }
}

/// The Rust source of `GOLDEN` as the implementation computes it now.
fn blessed_golden() -> String {
    let mut s =
        String::from("#[rustfmt::skip]\nconst GOLDEN: &[(&str, u32, u32, &[[u32; 2]])] = &[\n");
    for &kind in SamplerKind::ALL {
        for (n, pattern) in CASES {
            s += &format!(
                "    (\"{}\", {n}, {}, &[\n",
                kind.name(),
                pattern_literal(pattern)
            );
            for [x, y] in first_samples(kind, n, pattern) {
                s += &format!(
                    "        [{x:#010x}, {y:#010x}], // ({:?}, {:?})\n",
                    f32::from_bits(x),
                    f32::from_bits(y)
                );
            }
            s += "    ]),\n";
        }
    }
    s + "];\n"
}

/// Every pinned primitive call, labelled by its source text, with its value
/// as the implementation computes it now (f32 results as bits).
fn primitive_calls() -> Vec<(String, u32)> {
    let mut calls = Vec::new();
    for x in [0, 1, 2, 0xdead_beef, u32::MAX] {
        calls.push((format!("hash_u32({x:#x})"), hash_u32(x)));
    }
    for (a, b) in [(0, 0), (1, 2), (0xdead_beef, 7)] {
        calls.push((format!("hash_combine({a:#x}, {b})"), hash_combine(a, b)));
    }
    for (i, p) in [(0, 0), (1, 2), (5, 0xdead_beef)] {
        calls.push((format!("rand_u32({i}, {p:#x})"), rand_u32(i, p)));
    }
    // Short lengths (each of 1 to 8, where the exact shuffles live), a
    // prime, powers of two, and the extremes.
    for (i, len, p) in [
        (0, 1, 0x0),
        (1, 2, 0x0),
        (2, 3, 0x2a),
        (1, 4, 0x0),
        (4, 5, u32::MAX),
        (2, 6, 0xdead_beef),
        (6, 7, 0x1),
        (7, 8, 0x0),
        (3, 10, 0x2a),
        (0, 16, 0xdead_beef),
        (5, 20, 0x3),
        (96, 97, u32::MAX),
        (99, 100, 0x7),
        (12345, 1 << 24, 0x1234_5678),
        (0, u32::MAX, 0x1),
        (u32::MAX - 1, u32::MAX, 0xdead_beef),
    ] {
        calls.push((format!("permute({i}, {len}, {p:#x})"), permute(i, len, p)));
    }
    for x in [0, 1 << 8, 0x8000_0000, u32::MAX] {
        calls.push((
            format!("u32_to_unit_f32({x:#x}).to_bits()"),
            u32_to_unit_f32(x).to_bits(),
        ));
    }
    for (stratum, strata, bits) in [(2, 3, 0), (0, 1, 1 << 31), (4092, 4093, u32::MAX)] {
        calls.push((
            format!("stratum_to_unit_f32({stratum}, {strata}, {bits:#x}).to_bits()"),
            stratum_to_unit_f32(stratum, strata, bits).to_bits(),
        ));
    }
    // Renderers store and derive patterns from `pattern_seed(x, y, frame,
    // dimension)`, so its values are pinned like the samples.
    for (x, y, frame, dimension) in [
        (0, 0, 0, 0),
        (1, 0, 0, 0),
        (0, 1, 0, 0),
        (0, 0, 1, 0),
        (0, 0, 0, 1),
        (120, 45, 0, 0),
        (120, 45, 7, 3),
        (1919, 1079, 59, 12),
        (u32::MAX, u32::MAX, u32::MAX, u32::MAX),
    ] {
        calls.push((
            format!("pattern_seed({x}, {y}, {frame}, {dimension})"),
            pattern_seed(x, y, frame, dimension),
        ));
    }
    calls
}

/// The Rust source of `PRIMITIVES` as the implementation computes it now.
fn blessed_primitives() -> String {
    let mut s = String::from("#[rustfmt::skip]\nconst PRIMITIVES: &[(&str, u32)] = &[\n");
    for (call, value) in primitive_calls() {
        s += &format!("    ({call:?}, {value:#010x}),\n");
    }
    s + "];\n"
}

#[test]
fn every_kind_is_pinned_at_every_case() {
    if blessing() {
        return; // the printed table covers every kind
    }
    for &(name, n, pattern, _) in GOLDEN {
        assert!(
            name.parse::<SamplerKind>().is_ok(),
            "GOLDEN pins {name:?}, which is no sampler's name"
        );
        assert!(
            CASES.contains(&(n, pattern)),
            "{name} n = {n} pattern {pattern:#x} is not in CASES"
        );
    }
    for &kind in SamplerKind::ALL {
        for (n, pattern) in CASES {
            let entries = GOLDEN
                .iter()
                .filter(|g| (g.0, g.1, g.2) == (kind.name(), n, pattern))
                .count();
            assert_eq!(
                entries, 1,
                "{kind} n = {n} pattern {pattern:#x}: pinned {entries} times, expected once \
                 (bless: see the top of tests/golden.rs)"
            );
        }
    }
}

#[test]
fn first_samples_are_pinned() {
    if blessing() {
        println!("\n{}", blessed_golden());
        return;
    }
    for &(name, n, pattern, expected) in GOLDEN {
        let kind: SamplerKind = name.parse().unwrap();
        let sampler = kind.build(n).unwrap();
        assert_eq!(expected.len() as u32, n.min(PINNED), "{name} n = {n}");
        for (index, &want) in (0..).zip(expected) {
            let p = sampler.sample(index, pattern);
            assert_eq!(
                bits(p),
                want,
                "{name} n = {n} pattern {pattern:#x} index {index}: got ({}, {}), pinned ({}, {})",
                p.x,
                p.y,
                f32::from_bits(want[0]),
                f32::from_bits(want[1]),
            );
        }
        // fill must agree with the pinned values too.
        let mut filled = vec![Vec2::NAN; expected.len()];
        sampler.fill(pattern, &mut filled);
        for (index, (p, &want)) in filled.iter().zip(expected).enumerate() {
            assert_eq!(
                bits(*p),
                want,
                "{name} n = {n} pattern {pattern:#x} fill index {index}"
            );
        }
    }
}

#[test]
fn primitives_are_pinned() {
    if blessing() {
        println!("\n{}", blessed_primitives());
        return;
    }
    let computed = primitive_calls();
    let labels: Vec<&str> = computed.iter().map(|(call, _)| call.as_str()).collect();
    let pinned: Vec<&str> = PRIMITIVES.iter().map(|&(call, _)| call).collect();
    assert_eq!(
        labels, pinned,
        "the pinned calls changed: bless (see the top of tests/golden.rs)"
    );
    for ((call, value), &(_, want)) in computed.iter().zip(PRIMITIVES) {
        assert_eq!(*value, want, "{call} = {value:#010x}, pinned {want:#010x}");
    }
}

/// Pasting the bless output reproduces this file: its tables are
/// byte for byte what `WELLSPREAD_BLESS=1` prints (so the mechanism the top
/// of this file describes keeps working, and nobody hand-edits a value).
#[test]
fn tables_are_what_bless_prints() {
    if blessing() {
        return;
    }
    let source = include_str!("golden.rs");
    assert!(
        source.contains(&blessed_golden()),
        "GOLDEN differs from what bless prints (see the top of tests/golden.rs)"
    );
    assert!(
        source.contains(&blessed_primitives()),
        "PRIMITIVES differs from what bless prints (see the top of tests/golden.rs)"
    );
}

// ---- The tables (generated by the bless mode; do not edit by hand) ----

#[rustfmt::skip]
const GOLDEN: &[(&str, u32, u32, &[[u32; 2]])] = &[
    ("regular", 1, 0x0, &[
        [0x3f000000, 0x3f000000], // (0.5, 0.5)
    ]),
    ("regular", 1, u32::MAX, &[
        [0x3f000000, 0x3f000000], // (0.5, 0.5)
    ]),
    ("regular", 16, 0x0, &[
        [0x3ec00000, 0x3e000000], // (0.375, 0.125)
        [0x3e000000, 0x3e000000], // (0.125, 0.125)
        [0x3e000000, 0x3f200000], // (0.125, 0.625)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
        [0x3e000000, 0x3f600000], // (0.125, 0.875)
        [0x3f200000, 0x3f600000], // (0.625, 0.875)
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
        [0x3f200000, 0x3e000000], // (0.625, 0.125)
    ]),
    ("regular", 16, u32::MAX, &[
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
        [0x3e000000, 0x3f200000], // (0.125, 0.625)
        [0x3f600000, 0x3f200000], // (0.875, 0.625)
        [0x3f200000, 0x3ec00000], // (0.625, 0.375)
        [0x3f200000, 0x3e000000], // (0.625, 0.125)
        [0x3e000000, 0x3f600000], // (0.125, 0.875)
    ]),
    ("regular", 24, 0xdeadbeef, &[
        [0x3e000000, 0x3e800000], // (0.125, 0.25)
        [0x3f200000, 0x3ed55556], // (0.625, 0.4166667)
        [0x3f600000, 0x3f6aaaab], // (0.875, 0.9166667)
        [0x3e000000, 0x3f6aaaab], // (0.125, 0.9166667)
        [0x3e000000, 0x3ed55556], // (0.125, 0.4166667)
        [0x3e000000, 0x3daaaaa8], // (0.125, 0.08333331)
        [0x3ec00000, 0x3f400000], // (0.375, 0.75)
        [0x3f200000, 0x3f6aaaab], // (0.625, 0.9166667)
    ]),
    ("regular", 97, 0x0, &[
        [0x3f000000, 0x3f7c0a8f], // (0.5, 0.9845361)
        [0x3f000000, 0x3e4ddb0c], // (0.5, 0.20103091)
        [0x3f000000, 0x3f34c894], // (0.5, 0.7061856)
        [0x3f000000, 0x3f5f02a4], // (0.5, 0.87113404)
        [0x3f000000, 0x3f2f8152], // (0.5, 0.685567)
        [0x3f000000, 0x3db376c0], // (0.5, 0.08762884)
        [0x3f000000, 0x3ed5c5f0], // (0.5, 0.41752577)
        [0x3f000000, 0x3eab8be0], // (0.5, 0.33505154)
    ]),
    ("random", 1, 0x0, &[
        [0x3f4d1ebc, 0x3f128a72], // (0.8012502, 0.572425)
    ]),
    ("random", 1, u32::MAX, &[
        [0x3f57c392, 0x3ee91524], // (0.8428279, 0.45523942)
    ]),
    ("random", 16, 0x0, &[
        [0x3f4d1ebc, 0x3f128a72], // (0.8012502, 0.572425)
        [0x3f5837e5, 0x3f3dfe06], // (0.8446029, 0.74215734)
        [0x3eb0f1a0, 0x3e1a79e4], // (0.34559345, 0.1508556)
        [0x3d6de3e0, 0x3df6bb60], // (0.058078647, 0.12047458)
        [0x3f150389, 0x3e9b0958], // (0.5820852, 0.30280566)
        [0x3f0f73cb, 0x3e7deebc], // (0.5603606, 0.24798101)
        [0x3f533fc1, 0x3f57e236], // (0.82519156, 0.84329545)
        [0x3f03036e, 0x3e29b3c4], // (0.5117711, 0.16572481)
    ]),
    ("random", 16, u32::MAX, &[
        [0x3f57c392, 0x3ee91524], // (0.8428279, 0.45523942)
        [0x3d369c40, 0x3f6e0abd], // (0.044582605, 0.92985135)
        [0x3f0313ab, 0x3f78ba82], // (0.51201886, 0.9715959)
        [0x3f1e85e7, 0x3e7bd3ac], // (0.6192307, 0.24592465)
        [0x3f01a7f6, 0x3f2c4978], // (0.50646913, 0.67299604)
        [0x3f7b4cf7, 0x3d8d6a30], // (0.98164314, 0.06905019)
        [0x3dea6398, 0x3dc168e0], // (0.11444777, 0.094438314)
        [0x3d1bd150, 0x3efd926e], // (0.038041413, 0.4952578)
    ]),
    ("random", 24, 0xdeadbeef, &[
        [0x3f126bde, 0x3d6f4290], // (0.5719584, 0.05841309)
        [0x3f7465fa, 0x3e8615b0], // (0.95468104, 0.2618842)
        [0x3f3dee00, 0x3f4e75b8], // (0.74191284, 0.80648375)
        [0x3f0731f6, 0x3f32a2ea], // (0.5281061, 0.6977984)
        [0x3f097879, 0x3f22d7f0], // (0.5369945, 0.63610744)
        [0x3f4ce0a4, 0x3e10e7b4], // (0.80030274, 0.14150888)
        [0x3ec665b8, 0x3ea15172], // (0.3874948, 0.3150745)
        [0x3e2e30f4, 0x3f4e7a22], // (0.17010862, 0.8065511)
    ]),
    ("random", 97, 0x0, &[
        [0x3f4d1ebc, 0x3f128a72], // (0.8012502, 0.572425)
        [0x3f5837e5, 0x3f3dfe06], // (0.8446029, 0.74215734)
        [0x3eb0f1a0, 0x3e1a79e4], // (0.34559345, 0.1508556)
        [0x3d6de3e0, 0x3df6bb60], // (0.058078647, 0.12047458)
        [0x3f150389, 0x3e9b0958], // (0.5820852, 0.30280566)
        [0x3f0f73cb, 0x3e7deebc], // (0.5603606, 0.24798101)
        [0x3f533fc1, 0x3f57e236], // (0.82519156, 0.84329545)
        [0x3f03036e, 0x3e29b3c4], // (0.5117711, 0.16572481)
    ]),
    ("jittered", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("jittered", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("jittered", 16, 0x0, &[
        [0x3ef9d760, 0x3e4df46c], // (0.4879713, 0.20112771)
        [0x3d516600, 0x3e253128], // (0.051122665, 0.16132033)
        [0x3d33ab40, 0x3f03a286], // (0.04386449, 0.51419866)
        [0x3f13ae46, 0x3ec63b50], // (0.57687795, 0.38717127)
        [0x3d92a3b0, 0x3f54b0be], // (0.07160127, 0.8308219)
        [0x3f22aec3, 0x3f46b4b8], // (0.63547915, 0.77619505)
        [0x3f26d01d, 0x3f27df77], // (0.65161306, 0.65575355)
        [0x3f1bf433, 0x3d0a0cc0], // (0.60919493, 0.033703566)
    ]),
    ("jittered", 16, u32::MAX, &[
        [0x3ebed990, 0x3ea8744c], // (0.37275362, 0.32901227)
        [0x3f451270, 0x3ede6b32], // (0.7698126, 0.4344116)
        [0x3f079c55, 0x3f0b7b27], // (0.5297292, 0.5448479)
        [0x3cb874e0, 0x3f345b4d], // (0.022516668, 0.70451814)
        [0x3f409c30, 0x3f1b8279], // (0.75238323, 0.6074596)
        [0x3f363cb6, 0x3ef5ea64], // (0.7118639, 0.48030388)
        [0x3f0b90f2, 0x3d3887b0], // (0.54518044, 0.045051277)
        [0x3e728014, 0x3f61e529], // (0.2368167, 0.88240296)
    ]),
    ("jittered", 24, 0xdeadbeef, &[
        [0x3d8a7d80, 0x3e5df924], // (0.067622185, 0.21677071)
        [0x3f08e25f, 0x3eed1384], // (0.53470415, 0.46303952)
        [0x3f6af10c, 0x3f71cb7a], // (0.9177406, 0.94451106)
        [0x3e0d925c, 0x3f6669a9], // (0.13825363, 0.90004975)
        [0x3d248270, 0x3eeb52f4], // (0.040163457, 0.45961726)
        [0x3d1361a0, 0x3d96c7c8], // (0.035981774, 0.07362324)
        [0x3ea0e68a, 0x3f4d9012], // (0.31425887, 0.8029796)
        [0x3f2cda7b, 0x3f69915b], // (0.67520875, 0.9123742)
    ]),
    ("jittered", 97, 0x0, &[
        [0x3de39b38, 0x3f7d19de], // (0.1111359, 0.98867595)
        [0x3f3eb651, 0x3e48db14], // (0.7449694, 0.19614822)
        [0x3f78b5c6, 0x3f350ca6], // (0.97152364, 0.70722425)
        [0x3f37963e, 0x3f5fe572], // (0.71713626, 0.8745948)
        [0x3f22dc83, 0x3f2f9534], // (0.63617724, 0.6858704)
        [0x3e33ab40, 0x3daa1b38], // (0.17545795, 0.08305973)
        [0x3f6b2860, 0x3ed5babe], // (0.9185848, 0.41744035)
        [0x3e753e34, 0x3eac97e8], // (0.2394951, 0.33709645)
    ]),
    ("n-rooks", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("n-rooks", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("n-rooks", 16, 0x0, &[
        [0x3f434598, 0x3ef4a624], // (0.76278067, 0.47783005)
        [0x3f3f3aec, 0x3e99be8c], // (0.7469928, 0.30028188)
        [0x3ecdfa18, 0x3f622833], // (0.4022987, 0.8834259)
        [0x3f26fdc9, 0x3e631800], // (0.65230995, 0.22177124)
        [0x3f6d3288, 0x3d3b0cd0], // (0.9265523, 0.045666516)
        [0x3e1defc4, 0x3f2dc6ec], // (0.15423495, 0.67881656)
        [0x3e53ae44, 0x3eb18ed4], // (0.20671946, 0.34679282)
        [0x3ebe1908, 0x3ec8fbe2], // (0.37128472, 0.3925467)
    ]),
    ("n-rooks", 16, u32::MAX, &[
        [0x3f07f859, 0x3efc6b60], // (0.53113323, 0.4930067)
        [0x3ed6d6a4, 0x3dca58b0], // (0.41960633, 0.09880197)
        [0x3ea5c878, 0x3ea5c43c], // (0.32379508, 0.32376277)
        [0x3f6e7965, 0x3f547cbc], // (0.93153983, 0.8300283)
        [0x3f1df423, 0x3f71364a], // (0.6170065, 0.94223464)
        [0x3eefb664, 0x3ca1d120], // (0.4681884, 0.019753039)
        [0x3e363cb4, 0x3f6ebd4c], // (0.17796594, 0.93257594)
        [0x3f21449c, 0x3f0bcd66], // (0.62995315, 0.5461029)
    ]),
    ("n-rooks", 24, 0xdeadbeef, &[
        [0x3f56de5a, 0x3f24b63e], // (0.8393303, 0.6434058)
        [0x3d466d40, 0x3f34c3ec], // (0.048444033, 0.70611453)
        [0x3e80eff0, 0x3f37dd5d], // (0.25183058, 0.7182215)
        [0x3d1e07d0, 0x3f442edf], // (0.03858167, 0.7663402)
        [0x3f1837f3, 0x3f788a3d], // (0.5946037, 0.97085935)
        [0x3eb198a2, 0x3f669cbe], // (0.34686762, 0.9008292)
        [0x3df45af8, 0x3e8755ba], // (0.119314134, 0.26432592)
        [0x3f425322, 0x3f12300e], // (0.759081, 0.57104576)
    ]),
    ("n-rooks", 97, 0x0, &[
        [0x3eb48b14, 0x3f22b155], // (0.35262358, 0.6355184)
        [0x3c20c7c0, 0x3f304f0f], // (0.009813249, 0.68870634)
        [0x3f24c817, 0x3e0aa908], // (0.6436781, 0.13541043)
        [0x3f2cb31a, 0x3ea13eae], // (0.6746079, 0.31493133)
        [0x3f00db78, 0x3f7217e3], // (0.5033488, 0.945677)
        [0x3eeab768, 0x3f08ded5], // (0.45843053, 0.53465015)
        [0x3ecf7a94, 0x3f6ef94f], // (0.40523207, 0.93349165)
        [0x3f65738d, 0x3daed5b0], // (0.8962944, 0.085368514)
    ]),
    ("multi-jittered", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("multi-jittered", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("multi-jittered", 16, 0x0, &[
        [0x3e9e75d8, 0x3e737d18], // (0.30949283, 0.23778188)
        [0x3d9a2cc0, 0x3d253120], // (0.07528067, 0.040330052)
        [0x3c33ab40, 0x3f30e8a1], // (0.010966122, 0.69104964)
        [0x3f24eb91, 0x3ef18ed4], // (0.64421946, 0.47179282)
        [0x3e125474, 0x3f552c2f], // (0.14290029, 0.83270544)
        [0x3f08abb0, 0x3f71ad2e], // (0.53386974, 0.94404876)
        [0x3f19b407, 0x3f19f7dd], // (0.60040325, 0.60143834)
        [0x3f36fd0c, 0x3e08a0cc], // (0.7147987, 0.13342589)
    ]),
    ("multi-jittered", 16, u32::MAX, &[
        [0x3e8fb664, 0x3eaa1d12], // (0.2806884, 0.33225304)
        [0x3f71449c, 0x3ed79acc], // (0.94245315, 0.42110288)
        [0x3f01e715, 0x3f22dec9], // (0.5074323, 0.63621193)
        [0x3d8b8748, 0x3f1d16d3], // (0.06812912, 0.6136295)
        [0x3f50270c, 0x3f06e09e], // (0.8130958, 0.5268649)
        [0x3f2d8f2d, 0x3e9d7a98], // (0.67796594, 0.30757594)
        [0x3f32e43c, 0x3c388780], // (0.6987951, 0.0112627745)
        [0x3e7ca004, 0x3f58794a], // (0.24670416, 0.8456007)
    ]),
    ("multi-jittered", 24, 0xdeadbeef, &[
        [0x3dc1bf98, 0x3e9bbf24], // (0.09460372, 0.30419266)
        [0x3f2c25ba, 0x3ed09a36], // (0.67245066, 0.40742654)
        [0x3f51d2d8, 0x3f7c72de], // (0.8196235, 0.98612773)
        [0x3e179864, 0x3f599a6a], // (0.14804226, 0.8500124)
        [0x3e318570, 0x3ee57f68], // (0.17336059, 0.44823766)
        [0x3e5b7968, 0x3dd05c98], // (0.21433032, 0.10173911)
        [0x3e9ad118, 0x3f48b959], // (0.3023765, 0.7840782)
        [0x3f1ccf14, 0x3f6fb9ac], // (0.61253476, 0.9364269)
    ]),
    ("multi-jittered", 97, 0x0, &[
        [0x3f561107, 0x3f7d19de], // (0.8361973, 0.98867595)
        [0x3f7a0c70, 0x3e48db14], // (0.9767523, 0.19614822)
        [0x3f6d735c, 0x3f350ca6], // (0.9275415, 0.70722425)
        [0x3de24670, 0x3f5fe572], // (0.11048591, 0.8745948)
        [0x3e59d994, 0x3f2f9534], // (0.21274406, 0.6858704)
        [0x3f7b2f4a, 0x3daa1b38], // (0.9811903, 0.08305973)
        [0x3f558eef, 0x3ed5babe], // (0.83421224, 0.41744035)
        [0x3d5d3f40, 0x3eac97e8], // (0.054015398, 0.33709645)
    ]),
    ("correlated-multi-jittered", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("correlated-multi-jittered", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("correlated-multi-jittered", 16, 0x0, &[
        [0x3ebe75d8, 0x3e337d18], // (0.37199283, 0.17528188)
        [0x3d9a2cc0, 0x3dd29890], // (0.07528067, 0.10283005)
        [0x3e4b3ab4, 0x3f10e8a1], // (0.19846612, 0.56604964)
        [0x3f04eb91, 0x3ef18ed4], // (0.51921946, 0.47179282)
        [0x3e125474, 0x3f552c2f], // (0.14290029, 0.83270544)
        [0x3f28abb0, 0x3f71ad2e], // (0.65886974, 0.94404876)
        [0x3f39b407, 0x3f39f7dd], // (0.72540325, 0.72643834)
        [0x3f16fd0c, 0x3e48a0cc], // (0.5897987, 0.19592589)
    ]),
    ("correlated-multi-jittered", 16, u32::MAX, &[
        [0x3ecfb664, 0x3eca1d12], // (0.4056884, 0.39475304)
        [0x3f61449c, 0x3ef79acc], // (0.87995315, 0.48360288)
        [0x3f01e715, 0x3f12dec9], // (0.5074323, 0.57371193)
        [0x3bb87480, 0x3f0d16d3], // (0.0056291223, 0.5511295)
        [0x3f40270c, 0x3f36e09e], // (0.7505958, 0.7143649)
        [0x3f2d8f2d, 0x3ebd7a98], // (0.67796594, 0.37007594)
        [0x3f12e43c, 0x3d9710f0], // (0.5737951, 0.073762774)
        [0x3e7ca004, 0x3f48794a], // (0.24670416, 0.7831007)
    ]),
    ("correlated-multi-jittered", 24, 0xdeadbeef, &[
        [0x3d58d480, 0x3e8669ce], // (0.05293703, 0.26252598)
        [0x3f217b0f, 0x3ed09a36], // (0.630784, 0.40742654)
        [0x3f5c7d82, 0x3f7c72de], // (0.8612901, 0.98612773)
        [0x3dd9db70, 0x3f6eefc0], // (0.106375575, 0.9333458)
        [0x3e06dac4, 0x3ee57f68], // (0.1316939, 0.44823766)
        [0x3e30cebc, 0x3dd05c98], // (0.17266363, 0.10173911)
        [0x3e857bc2, 0x3f336404], // (0.26070982, 0.70074487)
        [0x3f1ccf14, 0x3f650f01], // (0.61253476, 0.8947602)
    ]),
    ("correlated-multi-jittered", 97, 0x0, &[
        [0x3f7b03d5, 0x3f7d19de], // (0.9805272, 0.98867595)
        [0x3f32ca75, 0x3e48db14], // (0.69840175, 0.19614822)
        [0x3f13b7fa, 0x3f350ca6], // (0.577026, 0.70722425)
        [0x3e979440, 0x3f5fe572], // (0.29605293, 0.8745948)
        [0x3cdea260, 0x3f2f9534], // (0.027177036, 0.6858704)
        [0x3e0b16e0, 0x3daa1b38], // (0.13582945, 0.08305973)
        [0x3f601d73, 0x3ed5babe], // (0.87544936, 0.41744035)
        [0x3ef4117a, 0x3eac97e8], // (0.47669584, 0.33709645)
    ]),
    ("hammersley", 1, 0x0, &[
        [0x3e516608, 0x3f0eb7f7], // (0.20449078, 0.5574946)
    ]),
    ("hammersley", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f550eda], // (0.498132, 0.83225787)
    ]),
    ("hammersley", 16, 0x0, &[
        [0x3c516600, 0x3f0eb7f7], // (0.012780666, 0.5574946)
        [0x3df9d760, 0x3ee33b28], // (0.12199283, 0.4438107)
        [0x3e1bf430, 0x3f439c5a], // (0.15229869, 0.7641045)
        [0x3e5bf724, 0x3d82eea0], // (0.21480995, 0.0639317)
        [0x3e9a6510, 0x3f312a8d], // (0.3015523, 0.6920555)
        [0x3eaef7e2, 0x3e832490], // (0.34173495, 0.25613832)
        [0x3ec9d722, 0x3f7cca46], // (0.39421946, 0.98746145)
        [0x3efe1908, 0x3e7c06dc], // (0.49628472, 0.24611992)
    ]),
    ("hammersley", 16, u32::MAX, &[
        [0x3cff0b20, 0x3f550eda], // (0.031133235, 0.83225787)
        [0x3ddb5a90, 0x3d506930], // (0.10710633, 0.050881565)
        [0x3e0b90f0, 0x3f2be1ae], // (0.13629508, 0.67141235)
        [0x3e79e594, 0x3eb92e5a], // (0.24403983, 0.36168176)
        [0x3e9be846, 0x3f66188c], // (0.30450648, 0.89881206)
        [0x3eafb664, 0x3e10f098], // (0.3431884, 0.14154279)
        [0x3edb1e5a, 0x3f07373a], // (0.42796594, 0.52818644)
        [0x3ee28938, 0x3ef5eb00], // (0.44245315, 0.48030853)
    ]),
    ("hammersley", 24, 0xdeadbeef, &[
        [0x3bc48200, 0x3ee1f014], // (0.0059969425, 0.44128478)
        [0x3d466d40, 0x3f42f635], // (0.048444033, 0.7615693)
        [0x3dae6a68, 0x3d8bf310], // (0.08516389, 0.0683347)
        [0x3e2781f4, 0x3f300617], // (0.16358167, 0.6875929)
        [0x3e363520, 0x3e81353a], // (0.17793703, 0.2523592)
        [0x3e633144, 0x3f7dcc30], // (0.22186762, 0.9913969)
        [0x3e926c14, 0x3e79380c], // (0.28598082, 0.24337786)
        [0x3e99fb9a, 0x3f182db3], // (0.3007477, 0.5944473)
    ]),
    ("hammersley", 97, 0x0, &[
        [0x3b0a2800, 0x3f0eb7f7], // (0.002108097, 0.5574946)
        [0x3ca4d800, 0x3ee33b28], // (0.020122528, 0.4438107)
        [0x3ccdcb60, 0x3f439c5a], // (0.02512139, 0.7641045)
        [0x3d1121c0, 0x3d82eea0], // (0.035432577, 0.0639317)
        [0x3d4bbcc0, 0x3f312a8d], // (0.049740553, 0.6920555)
        [0x3d66e2d0, 0x3e832490], // (0.05636865, 0.25613832)
        [0x3d852c48, 0x3f7cca46], // (0.065025866, 0.98746145)
        [0x3da7a6f0, 0x3e7c06dc], // (0.08186138, 0.24611992)
    ]),
    ("halton", 1, 0x0, &[
        [0x3f4a2137, 0x3f706541], // (0.7895693, 0.939045)
    ]),
    ("halton", 1, u32::MAX, &[
        [0x3f6a542e, 0x3ebee2ca], // (0.915347, 0.372824)
    ]),
    ("halton", 16, 0x0, &[
        [0x3f4a2137, 0x3f706541], // (0.7895693, 0.939045)
        [0x3dda3a20, 0x3e8e165e], // (0.10655618, 0.2775144)
        [0x3f381890, 0x3f0845d6], // (0.7191248, 0.5323156)
        [0x3e92fb1c, 0x3f5de932], // (0.28707206, 0.8668395)
        [0x3f74c47e, 0x3e13cec0], // (0.95612323, 0.14434338)
        [0x3e5efeac, 0x3edfb510], // (0.21776837, 0.43692827)
        [0x3f13b8d7, 0x3f3f8ee9], // (0.5770392, 0.7482744)
        [0x3edcb56c, 0x3d2145d0], // (0.43107164, 0.03937322)
    ]),
    ("halton", 16, u32::MAX, &[
        [0x3f6a542e, 0x3ebee2ca], // (0.915347, 0.372824)
        [0x3e20475c, 0x3f37b7d6], // (0.15652221, 0.71764886)
        [0x3f0a1122, 0x3ea0c99c], // (0.5393239, 0.31403816)
        [0x3ee87d26, 0x3f1c4766], // (0.4540798, 0.61046445)
        [0x3f476a87, 0x3f6bf0a9], // (0.7789692, 0.92164093)
        [0x3dab2490, 0x3e55de14], // (0.08356583, 0.20885497)
        [0x3f35b46f, 0x3f04a9e0], // (0.70978445, 0.5182171)
        [0x3e889b54, 0x3f5b3d33], // (0.26681006, 0.8564026)
    ]),
    ("halton", 24, 0xdeadbeef, &[
        [0x3f6f6c5d, 0x3f531a6e], // (0.93524724, 0.82462204)
        [0x3e32bec8, 0x3eade11e], // (0.1745559, 0.33960813)
        [0x3f0e6b1f, 0x3d98a8f8], // (0.55632204, 0.07454103)
        [0x3ee28cfa, 0x3f63d4b7], // (0.44248182, 0.8899645)
        [0x3f43453b, 0x3ee401e6], // (0.7627751, 0.44532698)
        [0x3d85ce50, 0x3e98bc94], // (0.065334916, 0.29831374)
        [0x3f31f428, 0x3f459b0e], // (0.6951318, 0.7718972)
        [0x3e82c7fa, 0x3f151376], // (0.25543195, 0.5823282)
    ]),
    ("halton", 97, 0x0, &[
        [0x3f4a2137, 0x3f706541], // (0.7895693, 0.939045)
        [0x3dda3a20, 0x3e8e165e], // (0.10655618, 0.2775144)
        [0x3f381890, 0x3f0845d6], // (0.7191248, 0.5323156)
        [0x3e92fb1c, 0x3f5de932], // (0.28707206, 0.8668395)
        [0x3f74c47e, 0x3e13cec0], // (0.95612323, 0.14434338)
        [0x3e5efeac, 0x3edfb510], // (0.21776837, 0.43692827)
        [0x3f13b8d7, 0x3f3f8ee9], // (0.5770392, 0.7482744)
        [0x3edcb56c, 0x3d2145d0], // (0.43107164, 0.03937322)
    ]),
    ("sobol", 1, 0x0, &[
        [0x3f476d62, 0x3f7c112b], // (0.7790128, 0.98463696)
    ]),
    ("sobol", 1, u32::MAX, &[
        [0x3f78d317, 0x3f077660], // (0.971971, 0.52915)
    ]),
    ("sobol", 16, 0x0, &[
        [0x3f476d62, 0x3f7c112b], // (0.7790128, 0.98463696)
        [0x3dab1a70, 0x3e82cb24], // (0.08354652, 0.2554561)
        [0x3f35b39d, 0x3e7f062c], // (0.70977193, 0.24904698)
        [0x3e88948a, 0x3f19f012], // (0.26675826, 0.60131943)
        [0x3ec546ca, 0x3d71b500], // (0.3853057, 0.059010506)
        [0x3f1cdec6, 0x3f29efef], // (0.61277425, 0.66381735)
        [0x3f78bad8, 0x3ecf9cb6], // (0.971601, 0.40549248)
        [0x3e6dd4ac, 0x3f575d1d], // (0.23225659, 0.84126455)
    ]),
    ("sobol", 16, u32::MAX, &[
        [0x3f78d317, 0x3f077660], // (0.971971, 0.52915)
        [0x3e6c4ab8, 0x3e11d07c], // (0.23075378, 0.14239687)
        [0x3ec599e0, 0x3f4a483c], // (0.3859396, 0.7901647)
        [0x3f1caba8, 0x3ef5792a], // (0.61199427, 0.47944003)
        [0x3f53db35, 0x3dd9b4b0], // (0.8275636, 0.106301665)
        [0x3d3f2e90, 0x3f3879e4], // (0.046675265, 0.7206099)
        [0x3eb7146e, 0x3e9233c0], // (0.35757774, 0.28555107)
        [0x3f2de443, 0x3f74aa19], // (0.67926425, 0.9557205)
    ]),
    ("sobol", 24, 0xdeadbeef, &[
        [0x3bc62200, 0x3f211f52], // (0.0060465336, 0.62938416)
        [0x3f5c686b, 0x3cf06d20], // (0.8609683, 0.02934891)
        [0x3f27c9cf, 0x3f580ff5], // (0.6554231, 0.8439935)
        [0x3ea54a02, 0x3ed74616], // (0.32283026, 0.4204566)
        [0x3e59b3d8, 0x3e3d318c], // (0.21260011, 0.18475932)
        [0x3f7578f4, 0x3f0def3b], // (0.95887685, 0.5544316)
        [0x3f123242, 0x3ea9f186], // (0.5710794, 0.3319208)
        [0x3edf6f94, 0x3f6cccb9], // (0.43639815, 0.9249988)
    ]),
    ("sobol", 97, 0x0, &[
        [0x3f476d62, 0x3f7c112b], // (0.7790128, 0.98463696)
        [0x3dab1a70, 0x3e82cb24], // (0.08354652, 0.2554561)
        [0x3f35b39d, 0x3e7f062c], // (0.70977193, 0.24904698)
        [0x3e88948a, 0x3f19f012], // (0.26675826, 0.60131943)
        [0x3ec546ca, 0x3d71b500], // (0.3853057, 0.059010506)
        [0x3f1cdec6, 0x3f29efef], // (0.61277425, 0.66381735)
        [0x3f78bad8, 0x3ecf9cb6], // (0.971601, 0.40549248)
        [0x3e6dd4ac, 0x3f575d1d], // (0.23225659, 0.84126455)
    ]),
    ("pmj02", 1, 0x0, &[
        [0x3f735ead, 0x3ec1a474], // (0.9506634, 0.3782078)
    ]),
    ("pmj02", 1, u32::MAX, &[
        [0x3f57c817, 0x3ef56dd4], // (0.8428969, 0.47935355)
    ]),
    ("pmj02", 16, 0x0, &[
        [0x3f735ead, 0x3ec1a474], // (0.9506634, 0.3782078)
        [0x3e438898, 0x3f515432], // (0.19095075, 0.81769097)
        [0x3f14511d, 0x3f2f2497], // (0.5793627, 0.68415207)
        [0x3ed072e0, 0x3d175750], // (0.40712643, 0.036948502)
        [0x3de31870, 0x3e8c12d2], // (0.110886455, 0.2735811)
        [0x3f4dc2b9, 0x3f7ae47a], // (0.8037525, 0.9800488)
        [0x3f3fe178, 0x3e67db98], // (0.74953413, 0.22642362)
        [0x3e9f7e68, 0x3f1e3d4c], // (0.31151128, 0.6181228)
    ]),
    ("pmj02", 16, u32::MAX, &[
        [0x3f57c817, 0x3ef56dd4], // (0.8428969, 0.47935355)
        [0x3d7b9600, 0x3f4a4062], // (0.061422348, 0.7900449)
        [0x3ebc48de, 0x3e11fea0], // (0.36774343, 0.14257288)
        [0x3f295313, 0x3f077cd5], // (0.66142386, 0.52924854)
        [0x3f197433, 0x3dd9fb38], // (0.5994293, 0.10643619)
        [0x3eceed94, 0x3f387369], // (0.40415633, 0.720511)
        [0x3e7d45d8, 0x3e922736], // (0.24733675, 0.2854554)
        [0x3f7c9086, 0x3f74a117], // (0.98658025, 0.95558304)
    ]),
    ("pmj02", 24, 0xdeadbeef, &[
        [0x3e8923b2, 0x3f4f1fcc], // (0.26785046, 0.80907893)
        [0x3f3575e5, 0x3efe7912], // (0.7088302, 0.49701744)
        [0x3f4784a6, 0x3f3d8118], // (0.7793678, 0.74025106)
        [0x3dad5118, 0x3df429d8], // (0.08462733, 0.119220436)
        [0x3e2346e0, 0x3f168f4a], // (0.15945005, 0.5881239)
        [0x3f6ab860, 0x3e4aff5c], // (0.91687584, 0.19823974)
        [0x3f0ae6d8, 0x3f71cc72], // (0.5425849, 0.94452584)
        [0x3ee9d400, 0x3e9beaf8], // (0.45669556, 0.30452704)
    ]),
    ("pmj02", 97, 0x0, &[
        [0x3f735ead, 0x3ec1a474], // (0.9506634, 0.3782078)
        [0x3e438898, 0x3f515432], // (0.19095075, 0.81769097)
        [0x3f14511d, 0x3f2f2497], // (0.5793627, 0.68415207)
        [0x3ed072e0, 0x3d175750], // (0.40712643, 0.036948502)
        [0x3de31870, 0x3e8c12d2], // (0.110886455, 0.2735811)
        [0x3f4dc2b9, 0x3f7ae47a], // (0.8037525, 0.9800488)
        [0x3f3fe178, 0x3e67db98], // (0.74953413, 0.22642362)
        [0x3e9f7e68, 0x3f1e3d4c], // (0.31151128, 0.6181228)
    ]),
];

#[rustfmt::skip]
const PRIMITIVES: &[(&str, u32)] = &[
    ("hash_u32(0x0)", 0x00000000),
    ("hash_u32(0x1)", 0x688990c0),
    ("hash_u32(0x2)", 0xd1132181),
    ("hash_u32(0xdeadbeef)", 0xe628c683),
    ("hash_u32(0xffffffff)", 0x6768824a),
    ("hash_combine(0x0, 0)", 0x01fce552),
    ("hash_combine(0x1, 2)", 0x6287eb6e),
    ("hash_combine(0xdeadbeef, 7)", 0x88cc31ae),
    ("rand_u32(0, 0x0)", 0xdf6e5fc8),
    ("rand_u32(1, 0x2)", 0xf6f8e090),
    ("rand_u32(5, 0xdeadbeef)", 0xe7f686d1),
    ("permute(0, 1, 0x0)", 0x00000000),
    ("permute(1, 2, 0x0)", 0x00000000),
    ("permute(2, 3, 0x2a)", 0x00000001),
    ("permute(1, 4, 0x0)", 0x00000002),
    ("permute(4, 5, 0xffffffff)", 0x00000001),
    ("permute(2, 6, 0xdeadbeef)", 0x00000001),
    ("permute(6, 7, 0x1)", 0x00000004),
    ("permute(7, 8, 0x0)", 0x00000000),
    ("permute(3, 10, 0x2a)", 0x00000003),
    ("permute(0, 16, 0xdeadbeef)", 0x0000000e),
    ("permute(5, 20, 0x3)", 0x0000000a),
    ("permute(96, 97, 0xffffffff)", 0x00000024),
    ("permute(99, 100, 0x7)", 0x00000054),
    ("permute(12345, 16777216, 0x12345678)", 0x0030436d),
    ("permute(0, 4294967295, 0x1)", 0x30cd4875),
    ("permute(4294967294, 4294967295, 0xdeadbeef)", 0xfefe8980),
    ("u32_to_unit_f32(0x0).to_bits()", 0x00000000),
    ("u32_to_unit_f32(0x100).to_bits()", 0x33800000),
    ("u32_to_unit_f32(0x80000000).to_bits()", 0x3f000000),
    ("u32_to_unit_f32(0xffffffff).to_bits()", 0x3f7fffff),
    ("stratum_to_unit_f32(2, 3, 0x0).to_bits()", 0x3f2aaaab),
    ("stratum_to_unit_f32(0, 1, 0x80000000).to_bits()", 0x3f000000),
    ("stratum_to_unit_f32(4092, 4093, 0xffffffff).to_bits()", 0x3f7fffff),
    ("pattern_seed(0, 0, 0, 0)", 0x1a5905f6),
    ("pattern_seed(1, 0, 0, 0)", 0x87e58df0),
    ("pattern_seed(0, 1, 0, 0)", 0xded7d127),
    ("pattern_seed(0, 0, 1, 0)", 0x3244c546),
    ("pattern_seed(0, 0, 0, 1)", 0x47cc53fb),
    ("pattern_seed(120, 45, 0, 0)", 0x136c10a7),
    ("pattern_seed(120, 45, 7, 3)", 0x66d0781e),
    ("pattern_seed(1919, 1079, 59, 12)", 0x9a107ad1),
    ("pattern_seed(4294967295, 4294967295, 4294967295, 4294967295)", 0x0c2bc6ba),
];

/// `ZSobol` (a `PixelSampler`, so not in the table above): samples 0..8 of
/// one pixel and dimension pair, as `[x bits, y bits]`, at an even and an
/// odd log2(spp). Cross-checked against an independent Python
/// transcription of the algorithm in `ZSobol`'s docs.
/// (spp, resolution, seed, pixel, dimension, samples as `[x bits, y bits]`).
type ZSobolCase = (u32, [u32; 2], u32, [u32; 2], u32, [[u32; 2]; 8]);

#[rustfmt::skip]
const ZSOBOL_GOLDEN: &[ZSobolCase] = &[
    (16, [64, 48], 0x0, [5, 9], 0, [
        [0x3c316000, 0x3f3a2ed1], // (0.010826111, 0.72727686)
        [0x3f24b54e, 0x3e97ef0e], // (0.6433915, 0.29674572)
        [0x3f69c6be, 0x3f48e7c0], // (0.9131888, 0.7847862)
        [0x3ea36270, 0x3dcf78f8], // (0.3191104, 0.10130495)
        [0x3e6099a0, 0x3f5fbb0a], // (0.21933603, 0.87394774)
        [0x3ec25c7e, 0x3ea1237a], // (0.3796119, 0.3147238)
        [0x3f509874, 0x3f258cb6], // (0.81482625, 0.6466783)
        [0x3f1f8865, 0x3c778d40], // (0.62317497, 0.01510936)
    ]),
    (8, [1920, 1080], 0xdeadbeef, [1000, 700], 3, [
        [0x3e95dca4, 0x3f2a46e8], // (0.29269898, 0.66514444)
        [0x3f3b49b3, 0x3d4f8470], // (0.7315933, 0.05066341)
        [0x3ef2e2c0, 0x3e708704], // (0.47438622, 0.23489004)
        [0x3f047a29, 0x3f1ac279], // (0.517489, 0.6045299)
        [0x3f770d77, 0x3f54d498], // (0.9650492, 0.8313689)
        [0x3e533ad8, 0x3ec8fa7a], // (0.20627916, 0.39253598)
        [0x3f4997aa, 0x3e8546ec], // (0.78747046, 0.26030672)
        [0x3dc433d0, 0x3f7f5320], // (0.09580195, 0.99736214)
    ]),
];

#[test]
fn zsobol_samples_are_pinned() {
    use wellspread::{PixelSampler, ZSobol};
    for &(spp, resolution, seed, pixel, dimension, expected) in ZSOBOL_GOLDEN {
        let zsobol = ZSobol::new(spp, resolution, seed).unwrap();
        for (index, &[x, y]) in (0..).zip(&expected) {
            let p = zsobol.sample_pixel(pixel, index, dimension);
            assert_eq!(
                [p.x.to_bits(), p.y.to_bits()],
                [x, y],
                "zsobol spp {spp} seed {seed:#x} pixel {pixel:?} dimension {dimension} index {index}"
            );
        }
    }
}
