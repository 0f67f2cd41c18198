//! Golden values: the first samples of every sampler in `SamplerKind::ALL`,
//! of the pixel samplers, and of the public primitives, pinned bit for bit.
//!
//! Sample values are part of wellspread's contract: a renderer that stores
//! patterns, or compares images across versions, relies on them. **Changing
//! any value is a breaking change**: record it in CHANGELOG.md, saying which
//! samplers changed and why.
//!
//! The values are data, in `tests/golden/`, read at compile time:
//! - `samplers.txt`: every kind at the same cases ([`CASES`]: n = 1, a
//!   square, a non-square and a prime; patterns 0, `u32::MAX` and one in
//!   between), samples `0..min(n, 8)`;
//! - `pixel_samplers.txt`: the pixel samplers that are not `Padded`
//!   ([`ZSobol`], `BlueNoise`) at two sample counts, frames, pixels and
//!   dimension pairs, samples `0..8`;
//! - `domains.txt`: every `PixelSamplerKind`'s draws through a `Domain`
//!   (1D, 2D, 4D, a branch and a split) for samples `0..4`;
//! - `primitives.txt`: hashes, permutations, unit conversions, pattern seeds.
//! - `nd_samplers.txt`: the [`SamplerNd`] point sets (`LatinHypercube`, `Sobol4D`, `Faure4D`,
//!   `OrthogonalArray` at every strength and offset) at a few sizes,
//!   dimension counts and patterns, samples `0..min(n, 8)`, every
//!   coordinate.
//!
//! Each line holds the bits of a value (`f32::to_bits`, hex) and, for
//! reading only, its decimal value. A kind without its lines fails
//! `every_kind_is_pinned_at_every_case`, so a new sampler cannot ship
//! unpinned.
//!
//! # Blessing new values
//!
//! When a change of values is intended, rewrite the files from the
//! implementation (after the property tests in `tests/samplers/` pass):
//!
//! ```text
//! WELLSPREAD_BLESS=1 cargo test --test golden
//! ```
//!
//! then check that `git diff tests/golden` touches only what you meant to
//! change. On unchanged code the files come out byte for byte the same.

use std::fmt::Write as _;

use wellspread::glam::Vec2;
use wellspread::primitives::{
    hash_combine, hash_u32, pattern_seed, permute, prefix_shuffle, rand_u32, stratum_to_unit_f32,
    u32_to_unit_f32,
};
use wellspread::{
    Faure4D, LatinHypercube, OrthogonalArray, OrthogonalArrayOffset, PixelSampler,
    PixelSamplerKind, Sampler2D, SamplerKind, SamplerNd, Sobol4D, ZSobol,
};

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

/// A pixel sampler case: (spp, resolution, frame, pixel, dimension pair).
type PixelCase = (u32, [u32; 2], u32, [u32; 2], u32);

/// The pixel sampler cases, at an even and an odd log2(spp).
const PIXEL_CASES: [PixelCase; 2] = [
    (16, [64, 48], 0, [5, 9], 0),
    (8, [1920, 1080], 0xdead_beef, [1000, 700], 3),
];

const SAMPLERS: &str = include_str!("golden/samplers.txt");
const PIXEL_SAMPLERS: &str = include_str!("golden/pixel_samplers.txt");
const PRIMITIVES: &str = include_str!("golden/primitives.txt");
const DOMAINS: &str = include_str!("golden/domains.txt");
const ND_SAMPLERS: &str = include_str!("golden/nd_samplers.txt");

/// True when the tests should rewrite the files instead of comparing.
fn blessing() -> bool {
    std::env::var_os("WELLSPREAD_BLESS").is_some_and(|v| !v.is_empty() && v != "0")
}

/// Writes `text` over `tests/golden/<name>`.
fn bless(name: &str, text: &str) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name);
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

/// One pinned point as a line's value fields: the bits, then the decimals.
fn point_fields(p: Vec2) -> String {
    format!(
        "{:08x} {:08x}  {:?} {:?}",
        p.x.to_bits(),
        p.y.to_bits(),
        p.x,
        p.y
    )
}

const HEADER: &str = "# Golden values of wellspread, written by `WELLSPREAD_BLESS=1 cargo test --test golden`:\n\
                      # do not edit. Changing a value is a breaking change (see tests/golden.rs).\n";

/// `samplers.txt` as the implementation computes it now: one line per
/// sample, `kind n pattern index x-bits y-bits  x y`, through `sample`.
fn samplers_text() -> String {
    let mut text = String::from(HEADER);
    text += "# kind n pattern index: x and y as f32 bits, then as decimals\n";
    for &kind in SamplerKind::ALL {
        for (n, pattern) in CASES {
            let sampler = kind
                .build(n)
                .unwrap_or_else(|e| panic!("{kind} n = {n}: {e}"));
            for index in 0..n.min(PINNED) {
                let p = sampler.sample(index, pattern);
                writeln!(text, "{kind} {n} {pattern:08x} {index} {}", point_fields(p)).unwrap();
            }
        }
    }
    text
}

/// `pixel_samplers.txt` as the implementation computes it now: one line per
/// sample, `name spp width height frame x y dimension index x-bits y-bits  x y`.
fn pixel_samplers_text() -> String {
    let mut text = String::from(HEADER);
    text += "# sampler spp width height frame pixel-x pixel-y dimension index: x and y as f32 bits, then as decimals\n";
    for kind in [PixelSamplerKind::ZSobol, PixelSamplerKind::BlueNoise] {
        for (spp, [width, height], frame, [x, y], dimension) in PIXEL_CASES {
            let sampler = kind.build(spp, [width, height], frame).unwrap();
            for index in 0..PINNED {
                let p = sampler.sample_pixel([x, y], index, dimension);
                writeln!(
                    text,
                    "{kind} {spp} {width} {height} {frame:08x} {x} {y} {dimension} {index} {}",
                    point_fields(p)
                )
                .unwrap();
            }
        }
    }
    text
}

/// `domains.txt` as the implementation computes it now: for every pixel
/// sampler kind and case, the draws of samples `0..4` through a `Domain`
/// (`next_1d`, `next_2d`, `next_4d`, then `branch(7).next_2d()` and
/// `split(3, 4, 1).next_2d()`), each value's bits in hex.
fn domains_text() -> String {
    let mut text = String::from(HEADER);
    text += "# sampler spp width height frame pixel-x pixel-y index: next_1d | next_2d | next_4d | branch(7).next_2d | split(3, 4, 1).next_2d\n";
    for kind in PixelSamplerKind::all() {
        for (spp, [width, height], frame, [x, y], _) in PIXEL_CASES {
            let sampler = match kind.build(spp, [width, height], frame) {
                Ok(sampler) => sampler,
                // 8 is not the square of a prime power.
                Err(_) if kind == PixelSamplerKind::Orthogonal && spp == 8 => continue,
                Err(e) => panic!("{kind} at {spp} spp: {e}"),
            };
            for index in 0..4 {
                let mut d = sampler.start([x, y], index);
                let one = d.next_1d();
                let two = d.next_2d();
                let four = d.next_4d();
                let branch = d.branch(7).next_2d();
                let split = d.split(3, 4, 1).next_2d();
                let hex = |values: &[f32]| {
                    values
                        .iter()
                        .map(|v| format!("{:08x}", v.to_bits()))
                        .collect::<Vec<_>>()
                        .join(" ")
                };
                writeln!(
                    text,
                    "{kind} {spp} {width} {height} {frame:08x} {x} {y} {index}: {} | {} | {} | {} | {}",
                    hex(&[one]),
                    hex(&two.to_array()),
                    hex(&four.to_array()),
                    hex(&branch.to_array()),
                    hex(&split.to_array()),
                )
                .unwrap();
            }
        }
    }
    text
}

/// The N-dimensional cases: `(n, dimensions, pattern)` for the Latin
/// hypercube (n = 1, a power of two, a prime, a count above 4096) and
/// `(n, dimensions, strength)` for the arrays (a prime q, q = 4 over
/// GF(2^2), q = 3 at strength 3, q = 4 at strength 3 and 4, with every
/// dimension an array of that size has).
const LATIN_CASES: [(u32, u32, u32); 6] = [
    (1, 3, 0),
    (1, 3, u32::MAX),
    (16, 4, 0),
    (16, 4, u32::MAX),
    (97, 5, 0xdead_beef),
    (4097, 2, 0),
];
const ARRAY_CASES: [(u32, u32, u32); 6] = [
    (4, 3, 2),
    (16, 5, 2),
    (25, 6, 2),
    (27, 4, 3),
    (64, 5, 3),
    (256, 5, 4),
];

/// `nd_samplers.txt` as the implementation computes it now: one line per
/// sample, `name n dimensions [strength offset] pattern index: bits...`,
/// through `SamplerNd::sample`.
fn nd_samplers_text() -> String {
    let mut text = String::from(HEADER);
    text +=
        "# sampler n dimensions [strength offset] pattern index: every coordinate as f32 bits\n";
    let mut write = |label: String, sampler: &dyn SamplerNd, pattern: u32| {
        let mut point = vec![f32::NAN; sampler.dimensions() as usize];
        for index in 0..sampler.len().min(PINNED) {
            sampler.sample(index, pattern, &mut point);
            let bits: Vec<String> = point
                .iter()
                .map(|x| format!("{:08x}", x.to_bits()))
                .collect();
            writeln!(text, "{label} {pattern:08x} {index}: {}", bits.join(" ")).unwrap();
        }
    };
    for (n, d, pattern) in LATIN_CASES {
        let cube = LatinHypercube::new(n, d).unwrap();
        write(format!("latin-hypercube {n} {d}"), &cube, pattern);
    }
    for offset in [
        OrthogonalArrayOffset::Jittered,
        OrthogonalArrayOffset::MultiJittered,
        OrthogonalArrayOffset::CorrelatedMultiJittered,
    ] {
        for (n, d, t) in ARRAY_CASES {
            let array = OrthogonalArray::new(n, d, t).unwrap().with_offset(offset);
            for pattern in [0, u32::MAX] {
                write(
                    format!("orthogonal-array {n} {d} {t} {offset:?}"),
                    &array,
                    pattern,
                );
            }
        }
    }
    for pattern in [0, u32::MAX] {
        write(
            "sobol-4d 16".to_string(),
            &Sobol4D::new(16).unwrap(),
            pattern,
        );
        write(
            "faure-4d 16".to_string(),
            &Faure4D::new(16).unwrap(),
            pattern,
        );
    }
    text
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

/// `primitives.txt` as the implementation computes it now: `call = bits`.
fn primitives_text() -> String {
    let mut text = String::from(HEADER);
    for (call, value) in primitive_calls() {
        writeln!(text, "{call} = {value:08x}").unwrap();
    }
    text
}

/// Compares `computed` with the pinned file line by line, so a failure
/// names the first sample that changed rather than dumping both files.
fn compare(name: &str, pinned: &str, computed: &str) {
    let (mut pinned_lines, mut computed_lines) = (pinned.lines(), computed.lines());
    for line in 1.. {
        match (pinned_lines.next(), computed_lines.next()) {
            (None, None) => return,
            (want, got) => assert_eq!(
                got, want,
                "tests/golden/{name} line {line}: computed {got:?}, pinned {want:?} \
                 (an intended change is blessed: see the top of tests/golden.rs)"
            ),
        }
    }
}

#[test]
fn every_kind_is_pinned_at_every_case() {
    if blessing() {
        return;
    }
    for &kind in SamplerKind::ALL {
        for (n, pattern) in CASES {
            let prefix = format!("{kind} {n} {pattern:08x} ");
            let lines = SAMPLERS.lines().filter(|l| l.starts_with(&prefix)).count();
            assert_eq!(
                lines as u32,
                n.min(PINNED),
                "{kind} n = {n} pattern {pattern:#x}: pinned {lines} samples"
            );
        }
    }
}

#[test]
fn first_samples_are_pinned() {
    let computed = samplers_text();
    if blessing() {
        bless("samplers.txt", &computed);
        return;
    }
    compare("samplers.txt", SAMPLERS, &computed);
}

/// `fill` writes the pinned values too (the file is written through
/// `sample`).
#[test]
fn fill_gives_the_pinned_samples() {
    for &kind in SamplerKind::ALL {
        for (n, pattern) in CASES {
            let sampler = kind.build(n).unwrap();
            let mut filled = vec![Vec2::NAN; n.min(PINNED) as usize];
            sampler.fill(pattern, &mut filled);
            for (index, p) in (0..).zip(&filled) {
                let want = sampler.sample(index, pattern);
                assert_eq!(
                    [p.x.to_bits(), p.y.to_bits()],
                    [want.x.to_bits(), want.y.to_bits()],
                    "{kind} n = {n} pattern {pattern:#x} fill index {index}"
                );
            }
        }
    }
}

#[test]
fn pixel_samplers_are_pinned() {
    let computed = pixel_samplers_text();
    if blessing() {
        bless("pixel_samplers.txt", &computed);
        return;
    }
    compare("pixel_samplers.txt", PIXEL_SAMPLERS, &computed);
}

#[test]
fn domain_draws_are_pinned() {
    let computed = domains_text();
    if blessing() {
        bless("domains.txt", &computed);
        return;
    }
    compare("domains.txt", DOMAINS, &computed);
}

#[test]
fn nd_samplers_are_pinned() {
    let computed = nd_samplers_text();
    if blessing() {
        bless("nd_samplers.txt", &computed);
        return;
    }
    compare("nd_samplers.txt", ND_SAMPLERS, &computed);
}

#[test]
fn primitives_are_pinned() {
    let computed = primitives_text();
    if blessing() {
        bless("primitives.txt", &computed);
        return;
    }
    compare("primitives.txt", PRIMITIVES, &computed);
}

/// A few values from outside the bless mechanism, so that blessing cannot
/// silently rewrite them: two `ZSobol` samples from an independent Python
/// transcription of the algorithm in its docs, and primitives checked by
/// hand.
#[test]
fn independent_reference_values_hold() {
    // lowbias32 is xorshifts and multiplies with no added constant: 0 -> 0.
    assert_eq!(hash_u32(0), 0);
    assert_eq!(u32_to_unit_f32(0x8000_0000), 0.5);
    assert_eq!(u32_to_unit_f32(u32::MAX).to_bits(), 0x3f7f_ffff);
    // ZSobol, pixel (5, 9) of 64 x 48 at 16 spp, frame 0, draw 0, sample 0
    // (a Python transcription of ZSobol's construction and of the domain's
    // key, stream and prefix shuffle, written from their docs).
    let zsobol = ZSobol::new(16, [64, 48], 0).unwrap();
    let p = zsobol.sample_pixel([5, 9], 0, 0);
    assert_eq!([p.x.to_bits(), p.y.to_bits()], [0x3efd_745e, 0x3f0b_2a4e]);
    // The transcription computed this value for sample 7 under the
    // earlier prefix shuffle (three rounds on the block's low bits); the
    // current one gives its place to sample 5. Only the shuffle changed,
    // and it is checked on its own below.
    let p = ZSobol::new(8, [1920, 1080], 0xdead_beef)
        .unwrap()
        .sample_pixel([1000, 700], 5, 3);
    assert_eq!([p.x.to_bits(), p.y.to_bits()], [0x3f61_b773, 0x3f1a_2272]);
    // prefix_shuffle from a Python transcription of its docs.
    for (index, key, shuffled) in [
        (0x2, 0x1234_5678, 0x3),
        (0x5, 0xdead_beef, 0x4),
        (0xd, 0x9e37_79b9, 0x9),
        (0x3e8, 0xcafe_f00d, 0x3a6),
        (0x8000_1234, 0x0bad_5eed, 0xa44b_43e9),
        (u32::MAX, 0x7, 0x84d8_eaf4),
    ] {
        assert_eq!(prefix_shuffle(index, key), shuffled, "{index:#x} {key:#x}");
    }
}
