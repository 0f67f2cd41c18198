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
use wellspread::hash::{
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
        [0x3f600000, 0x3f600000], // (0.875, 0.875)
        [0x3e000000, 0x3e000000], // (0.125, 0.125)
        [0x3e000000, 0x3ec00000], // (0.125, 0.375)
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
        [0x3f200000, 0x3f600000], // (0.625, 0.875)
        [0x3ec00000, 0x3f600000], // (0.375, 0.875)
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3f600000, 0x3ec00000], // (0.875, 0.375)
    ]),
    ("regular", 16, u32::MAX, &[
        [0x3f200000, 0x3f200000], // (0.625, 0.625)
        [0x3f200000, 0x3f600000], // (0.625, 0.875)
        [0x3e000000, 0x3f200000], // (0.125, 0.625)
        [0x3f600000, 0x3e000000], // (0.875, 0.125)
        [0x3ec00000, 0x3ec00000], // (0.375, 0.375)
        [0x3e000000, 0x3e000000], // (0.125, 0.125)
        [0x3f600000, 0x3f200000], // (0.875, 0.625)
        [0x3ec00000, 0x3f600000], // (0.375, 0.875)
    ]),
    ("regular", 24, 0xdeadbeef, &[
        [0x3f600000, 0x3f400000], // (0.875, 0.75)
        [0x3ec00000, 0x3ed55556], // (0.375, 0.4166667)
        [0x3f200000, 0x3daaaaa8], // (0.625, 0.08333331)
        [0x3f200000, 0x3ed55556], // (0.625, 0.4166667)
        [0x3ec00000, 0x3f6aaaab], // (0.375, 0.9166667)
        [0x3ec00000, 0x3e800000], // (0.375, 0.25)
        [0x3e000000, 0x3daaaaa8], // (0.125, 0.08333331)
        [0x3f600000, 0x3f6aaaab], // (0.875, 0.9166667)
    ]),
    ("regular", 97, 0x0, &[
        [0x3f000000, 0x3f054742], // (0.5, 0.52061856)
        [0x3f000000, 0x3e38be04], // (0.5, 0.18041235)
        [0x3f000000, 0x3f6ed86a], // (0.5, 0.9329897)
        [0x3f000000, 0x3e23a0fc], // (0.5, 0.1597938)
        [0x3f000000, 0x3f2cddb1], // (0.5, 0.67525774)
        [0x3f000000, 0x3ed07eae], // (0.5, 0.4072165)
        [0x3f000000, 0x3f3cb377], // (0.5, 0.7371134)
        [0x3f000000, 0x3f5f02a4], // (0.5, 0.87113404)
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
        [0x3f453189, 0x3f640d7f], // (0.7702871, 0.89083093)
        [0x3d516600, 0x3e253128], // (0.051122665, 0.16132033)
        [0x3e532888, 0x3edd866e], // (0.2062093, 0.43266624)
        [0x3f26d01d, 0x3f27df77], // (0.65161306, 0.65575355)
        [0x3f22aec3, 0x3f46b4b8], // (0.63547915, 0.77619505)
        [0x3ed76ee4, 0x3f40a452], // (0.4207679, 0.7525073)
        [0x3ebbdf8a, 0x3eee3764], // (0.36693984, 0.46526635)
        [0x3f7c3210, 0x3ea3ef8a], // (0.9851389, 0.3201869)
    ]),
    ("jittered", 16, u32::MAX, &[
        [0x3f079c55, 0x3f0b7b27], // (0.5297292, 0.5448479)
        [0x3f068184, 0x3f79f7b2], // (0.52541375, 0.9764358)
        [0x3cb874e0, 0x3f345b4d], // (0.022516668, 0.70451814)
        [0x3f79e594, 0x3d8f9798], // (0.97615933, 0.07011336)
        [0x3ebed990, 0x3ea8744c], // (0.37275362, 0.32901227)
        [0x3dff0b28, 0x3e635b04], // (0.124533, 0.22202688)
        [0x3f409c30, 0x3f1b8279], // (0.75238323, 0.6074596)
        [0x3e989b34, 0x3f59806b], // (0.2980591, 0.84961575)
    ]),
    ("jittered", 24, 0xdeadbeef, &[
        [0x3f6de5f2, 0x3f52b85c], // (0.92928994, 0.8231256)
        [0x3eda5e46, 0x3ef81432], // (0.4265005, 0.48452908)
        [0x3f02cfd0, 0x3d2201d0], // (0.51098347, 0.03955251)
        [0x3f08e25f, 0x3eed1384], // (0.53470415, 0.46303952)
        [0x3e92ee4c, 0x3f761c1f], // (0.2869743, 0.9613666)
        [0x3ea993d0, 0x3e8a3b48], // (0.33120584, 0.26998353)
        [0x3d1361a0, 0x3d96c7c8], // (0.035981774, 0.07362324)
        [0x3f6af10c, 0x3f71cb7a], // (0.9177406, 0.94451106)
    ]),
    ("jittered", 97, 0x0, &[
        [0x3f2de2c3, 0x3f0629f8], // (0.67924136, 0.5240779)
        [0x3ea33314, 0x3e37f11c], // (0.31874907, 0.1796307)
        [0x3ddc86d8, 0x3f6fcd1f], // (0.10767907, 0.93672365)
        [0x3da63128, 0x3e244c20], // (0.081148446, 0.16044664)
        [0x3f11dc71, 0x3f2e2a3c], // (0.5697699, 0.68033195)
        [0x3e0f1510, 0x3ecfd2c4], // (0.13972878, 0.4059049)
        [0x3f761e26, 0x3f3c9a55], // (0.9613975, 0.7367299)
        [0x3f37963e, 0x3f5fe572], // (0.71713626, 0.8745948)
    ]),
    ("n-rooks", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("n-rooks", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("n-rooks", 16, 0x0, &[
        [0x3f434598, 0x3f1a5312], // (0.76278067, 0.60283005)
        [0x3f0f3aec, 0x3f7cdf46], // (0.5594928, 0.9877819)
        [0x3e8dfa18, 0x3f622833], // (0.2772987, 0.8834259)
        [0x3db7ee48, 0x3f38c600], // (0.089809954, 0.72177124)
        [0x3efa6510, 0x3eb7619a], // (0.4890523, 0.35816652)
        [0x3e5defc4, 0x3f2dc6ec], // (0.21673495, 0.67881656)
        [0x3f24eb91, 0x3ed18ed4], // (0.64421946, 0.40929282)
        [0x3ede1908, 0x3e11f7c4], // (0.43378472, 0.14254671)
    ]),
    ("n-rooks", 16, u32::MAX, &[
        [0x3f37f859, 0x3f5e35b0], // (0.71863323, 0.8680067)
        [0x3f4b6b52, 0x3ed2962c], // (0.7946063, 0.41130197)
        [0x3ea5c878, 0x3f42e21e], // (0.32379508, 0.7612628)
        [0x3d679650, 0x3f047cbc], // (0.056539834, 0.5175283)
        [0x3defa118, 0x3ee26c94], // (0.11700648, 0.44223464)
        [0x3e1f6cc8, 0x3f250e89], // (0.1556884, 0.64475304)
        [0x3f7d8f2d, 0x3f3ebd4c], // (0.99046594, 0.74507594)
        [0x3f11449c, 0x3dde6b30], // (0.56745315, 0.10860288)
    ]),
    ("n-rooks", 24, 0xdeadbeef, &[
        [0x3e062410, 0x3dd05c98], // (0.13099694, 0.10173911)
        [0x3ec37852, 0x3f2a1941], // (0.38177735, 0.66444784)
        [0x3e964546, 0x3f77dd5d], // (0.29349726, 0.9682215)
        [0x3e7cd748, 0x3f4ed98a], // (0.24691498, 0.8080069)
        [0x3f4d8d48, 0x3e377e48], // (0.80293703, 0.17919266)
        [0x3f4376fc, 0x3e6fc84c], // (0.7635343, 0.23416251)
        [0x3e4f82d4, 0x3ec755ba], // (0.2026475, 0.38932592)
        [0x3f57a878, 0x3eb9b570], // (0.8424144, 0.36271238)
    ]),
    ("n-rooks", 97, 0x0, &[
        [0x3f467a53, 0x3f79c916], // (0.775304, 0.9757246)
        [0x3f091c32, 0x3f28642c], // (0.5355865, 0.6577785)
        [0x3ea5ef30, 0x3e9f0fe6], // (0.32409048, 0.31066817)
        [0x3f2cb31a, 0x3d400fd0], // (0.6746079, 0.04689008)
        [0x3f500856, 0x3f38080d], // (0.8126272, 0.71887285)
        [0x3f0fbffe, 0x3f3b03c8], // (0.5615233, 0.73052645)
        [0x3b4fc300, 0x3d8a43d8], // (0.0031701922, 0.067512214)
        [0x3d7ad9c0, 0x3f2c498f], // (0.06124282, 0.6729974)
    ]),
    ("multi-jittered", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("multi-jittered", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("multi-jittered", 16, 0x0, &[
        [0x3f714c62, 0x3f49035f], // (0.94257176, 0.7852077)
        [0x3e4d1660, 0x3d253120], // (0.20028067, 0.040330052)
        [0x3de99440, 0x3ef7619a], // (0.114052296, 0.48316652)
        [0x3f29b407, 0x3f19f7dd], // (0.66290325, 0.60143834)
        [0x3f18abb0, 0x3f61ad2e], // (0.59636974, 0.88154876)
        [0x3ed5dbb8, 0x3f502914], // (0.41769195, 0.8131268)
        [0x3e8ef7e2, 0x3ebb8dd8], // (0.27923495, 0.36631656)
        [0x3f4f0c84, 0x3e88fbe2], // (0.8087847, 0.2675467)
    ]),
    ("multi-jittered", 16, u32::MAX, &[
        [0x3f01e715, 0x3f32dec9], // (0.5074323, 0.69871193)
        [0x3f21a061, 0x3f5e7dec], // (0.63135344, 0.8691089)
        [0x3d8b8748, 0x3f1d16d3], // (0.06812912, 0.6136295)
        [0x3f4e7965, 0x3e11f2f0], // (0.80653983, 0.1425283)
        [0x3ecfb664, 0x3eea1d12], // (0.4056884, 0.45725304)
        [0x3e1fe164, 0x3e78d6c0], // (0.15613323, 0.2430067)
        [0x3f70270c, 0x3f26e09e], // (0.9380958, 0.6518649)
        [0x3ee626cc, 0x3f46601a], // (0.44951475, 0.7749039)
    ]),
    ("multi-jittered", 24, 0xdeadbeef, &[
        [0x3f7250fe, 0x3f34ae17], // (0.94654834, 0.7057814)
        [0x3eb9ba60, 0x3ebe050c], // (0.36275005, 0.37113225)
        [0x3f2b22a3, 0x3d532b20], // (0.66849726, 0.0515548)
        [0x3f217b0f, 0x3ed09a36], // (0.630784, 0.40742654)
        [0x3ec327b6, 0x3f7d8708], // (0.38116235, 0.99034166)
        [0x3edc434e, 0x3ea28ed2], // (0.430201, 0.31749588)
        [0x3bc48200, 0x3dd05c98], // (0.0059969425, 0.10173911)
        [0x3f7c7d82, 0x3f71c834], // (0.9862901, 0.9444611)
    ]),
    ("multi-jittered", 97, 0x0, &[
        [0x3eac7e14, 0x3f0629f8], // (0.3368994, 0.5240779)
        [0x3f29bf9b, 0x3e37f11c], // (0.6630799, 0.1796307)
        [0x3ec3de0a, 0x3f6fcd1f], // (0.3825534, 0.93672365)
        [0x3e345210, 0x3e244c20], // (0.1760943, 0.16044664)
        [0x3f2d0cd4, 0x3f2e2a3c], // (0.675977, 0.68033195)
        [0x3eb43392, 0x3ecfd2c4], // (0.35195595, 0.4059049)
        [0x3f38a3f1, 0x3f3c9a55], // (0.72125155, 0.7367299)
        [0x3ecc5cd4, 0x3f5fe572], // (0.39914572, 0.8745948)
    ]),
    ("correlated-multi-jittered", 1, 0x0, &[
        [0x3e516608, 0x3f25312b], // (0.20449078, 0.6452815)
    ]),
    ("correlated-multi-jittered", 1, u32::MAX, &[
        [0x3eff0b28, 0x3f635b06], // (0.498132, 0.88810766)
    ]),
    ("correlated-multi-jittered", 16, 0x0, &[
        [0x3f414c62, 0x3f69035f], // (0.75507176, 0.9102077)
        [0x3e4d1660, 0x3d253120], // (0.20028067, 0.040330052)
        [0x3de99440, 0x3e97619a], // (0.114052296, 0.29566652)
        [0x3f29b407, 0x3f39f7dd], // (0.66290325, 0.72643834)
        [0x3f08abb0, 0x3f71ad2e], // (0.53386974, 0.94404876)
        [0x3e95dbb8, 0x3f502914], // (0.29269195, 0.8131268)
        [0x3eaef7e2, 0x3ebb8dd8], // (0.34173495, 0.36631656)
        [0x3f5f0c84, 0x3ec8fbe2], // (0.8712847, 0.3925467)
    ]),
    ("correlated-multi-jittered", 16, u32::MAX, &[
        [0x3f21e715, 0x3f32dec9], // (0.6324323, 0.69871193)
        [0x3f31a061, 0x3f7e7dec], // (0.69385344, 0.9941089)
        [0x3e05c3a4, 0x3f2d16d3], // (0.13062912, 0.6761295)
        [0x3f4e7965, 0x3da3e5e0], // (0.80653983, 0.080028296)
        [0x3eafb664, 0x3e8a1d12], // (0.3431884, 0.26975304)
        [0x3cff0b20, 0x3e38d6c0], // (0.031133235, 0.1805067)
        [0x3f60270c, 0x3f16e09e], // (0.8755958, 0.5893649)
        [0x3ee626cc, 0x3f46601a], // (0.44951475, 0.7749039)
    ]),
    ("correlated-multi-jittered", 24, 0xdeadbeef, &[
        [0x3f67a653, 0x3f4a036c], // (0.90488166, 0.7891147)
        [0x3ee4650c, 0x3ed35a62], // (0.44608343, 0.41279894)
        [0x3f0b22a3, 0x3e0a201c], // (0.54349726, 0.13488811)
        [0x3f2c25ba, 0x3efb44e0], // (0.67245066, 0.49075985)
        [0x3eadd262, 0x3f6831b2], // (0.33949572, 0.9070083)
        [0x3ef198a2, 0x3e6fc84c], // (0.47186762, 0.23416251)
        [0x3d433af0, 0x3c96c7c0], // (0.04766363, 0.018405795)
        [0x3f5c7d82, 0x3f71c834], // (0.8612901, 0.9444611)
    ]),
    ("correlated-multi-jittered", 97, 0x0, &[
        [0x3d1b5cd0, 0x3f0629f8], // (0.03793031, 0.5240779)
        [0x3f04cccd, 0x3e37f11c], // (0.51875, 0.1796307)
        [0x3e0a5fb4, 0x3f6fcd1f], // (0.1351307, 0.93672365)
        [0x3e496f18, 0x3e244c20], // (0.19671285, 0.16044664)
        [0x3d9fd2d0, 0x3f2e2a3c], // (0.07803881, 0.68033195)
        [0x3f2946a7, 0x3ecfd2c4], // (0.6612343, 0.4059049)
        [0x3f6ac8e4, 0x3f3c9a55], // (0.91712785, 0.7367299)
        [0x3ebc870e, 0x3f5fe572], // (0.3682179, 0.8745948)
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
    ("permute(2, 3, 0x2a)", 0x00000000),
    ("permute(1, 4, 0x0)", 0x00000000),
    ("permute(4, 5, 0xffffffff)", 0x00000001),
    ("permute(2, 6, 0xdeadbeef)", 0x00000003),
    ("permute(6, 7, 0x1)", 0x00000005),
    ("permute(7, 8, 0x0)", 0x00000002),
    ("permute(3, 10, 0x2a)", 0x00000003),
    ("permute(0, 16, 0xdeadbeef)", 0x00000007),
    ("permute(5, 20, 0x3)", 0x00000007),
    ("permute(96, 97, 0xffffffff)", 0x00000051),
    ("permute(99, 100, 0x7)", 0x00000016),
    ("permute(12345, 16777216, 0x12345678)", 0x00c1fb56),
    ("permute(0, 4294967295, 0x1)", 0xa760a37f),
    ("permute(4294967294, 4294967295, 0xdeadbeef)", 0x7a92a0ba),
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
