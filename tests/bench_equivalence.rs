//! Speed work must not move a single sample: every sampler's `sample` and
//! `fill` are compared bit for bit against a frozen copy of the formulas as
//! they were before any fast path existed (`reference` below), over many `n`
//! (1..300, primes, powers of two and their neighbours, up to 2^24) and
//! patterns, and `fill` against `sample` for whole and partial sets.
//!
//! The reference is deliberately the slow, obviously-correct code: u64
//! divisions and a `%` rotation in `permute`. Do not "optimise" it.

use wellspread::glam::Vec2;
use wellspread::hash;
use wellspread::{
    CorrelatedMultiJittered, Jittered, MultiJittered, NRooks, Random, Regular, Sampler2D,
};

mod reference {
    use wellspread::glam::Vec2;
    use wellspread::hash::{hash_combine, hash_u32, rand_u32};

    pub const ORDER: u32 = 0x51633e2d;
    pub const SHUFFLE_X: u32 = 0xa511e9b3;
    pub const SHUFFLE_Y: u32 = 0x63d83595;
    pub const JITTER_X: u32 = 0xa399d265;
    pub const JITTER_Y: u32 = 0x711ad6a5;

    pub fn permute(index: u32, len: u32, pattern: u32) -> u32 {
        let mut w = len.wrapping_sub(1);
        w |= w >> 1;
        w |= w >> 2;
        w |= w >> 4;
        w |= w >> 8;
        w |= w >> 16;
        let bits = 32 - w.leading_zeros();
        let half = bits.div_ceil(2);
        let rounds = match bits {
            1..=3 => 13,
            4..=5 => 5,
            _ => 4,
        };
        let mut key = pattern ^ 0x9e37_79b9;
        key ^= key >> 16;
        key = key.wrapping_mul(0x7feb_352d);
        key ^= key >> 15;
        key = key.wrapping_mul(0x846c_a68b);
        key ^= key >> 16;
        let p = pattern;
        let mut i = if index < len { index } else { index % len };
        loop {
            for r in 0..rounds {
                let k = key.rotate_right(7 * r);
                i = i.wrapping_add(k);
                i = i.wrapping_mul(k.rotate_right(11) | 1) & w;
                i ^= i >> half;
                i ^= (i >> 1) & k.rotate_right(22);
            }
            if i < len {
                break;
            }
        }
        ((i as u64 + p as u64) % len as u64) as u32
    }

    pub fn stratum_to_unit_f32(stratum: u32, strata: u32, bits: u32) -> f32 {
        let strata = strata as u64;
        let start = ((stratum as u64) << 24).div_ceil(strata);
        let end = ((stratum as u64 + 1) << 24).div_ceil(strata);
        let t = start + ((end.saturating_sub(start) * bits as u64) >> 32);
        let t = if t < 1 << 24 { t } else { (1 << 24) - 1 };
        t as f32 * (1.0 / (1u32 << 24) as f32)
    }

    fn unit(bits: u32) -> f32 {
        (bits >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }

    pub fn regular(columns: u32, rows: u32, index: u32, pattern: u32) -> Vec2 {
        let cell = permute(index, columns * rows, hash_u32(pattern) ^ ORDER);
        let (column, row) = (cell % columns, cell / columns);
        Vec2::new(
            stratum_to_unit_f32(column, columns, 1 << 31),
            stratum_to_unit_f32(row, rows, 1 << 31),
        )
    }

    pub fn random(index: u32, pattern: u32) -> Vec2 {
        let seed = hash_u32(pattern);
        let bits_x = hash_combine(seed ^ JITTER_X, index);
        let bits_y = hash_u32(bits_x ^ JITTER_Y);
        Vec2::new(unit(bits_x), unit(bits_y))
    }

    pub fn jittered(columns: u32, rows: u32, index: u32, pattern: u32) -> Vec2 {
        let seed = hash_u32(pattern);
        let cell = permute(index, columns * rows, seed ^ ORDER);
        let (column, row) = (cell % columns, cell / columns);
        Vec2::new(
            stratum_to_unit_f32(column, columns, rand_u32(cell, seed ^ JITTER_X)),
            stratum_to_unit_f32(row, rows, rand_u32(cell, seed ^ JITTER_Y)),
        )
    }

    pub fn n_rooks(n: u32, index: u32, pattern: u32) -> Vec2 {
        let seed = hash_u32(pattern);
        let column = permute(index, n, seed ^ SHUFFLE_X);
        let row = permute(index, n, seed ^ SHUFFLE_Y);
        Vec2::new(
            stratum_to_unit_f32(column, n, rand_u32(index, seed ^ JITTER_X)),
            stratum_to_unit_f32(row, n, rand_u32(index, seed ^ JITTER_Y)),
        )
    }

    pub fn multi_jittered(columns: u32, rows: u32, index: u32, pattern: u32) -> Vec2 {
        let n = columns * rows;
        let seed = hash_u32(pattern);
        let cell = permute(index, n, seed ^ ORDER);
        let (column, row) = (cell % columns, cell / columns);
        let sub_column = permute(row, rows, hash_combine(seed ^ SHUFFLE_X, column));
        let sub_row = permute(column, columns, hash_combine(seed ^ SHUFFLE_Y, row));
        Vec2::new(
            stratum_to_unit_f32(
                column * rows + sub_column,
                n,
                rand_u32(cell, seed ^ JITTER_X),
            ),
            stratum_to_unit_f32(row * columns + sub_row, n, rand_u32(cell, seed ^ JITTER_Y)),
        )
    }

    pub fn correlated_multi_jittered(columns: u32, rows: u32, index: u32, pattern: u32) -> Vec2 {
        let n = columns * rows;
        let seed = hash_u32(pattern);
        let cell = permute(index, n, seed ^ ORDER);
        let (column, row) = (cell % columns, cell / columns);
        let sub_column = permute(row, rows, seed ^ SHUFFLE_X);
        let sub_row = permute(column, columns, seed ^ SHUFFLE_Y);
        Vec2::new(
            stratum_to_unit_f32(
                column * rows + sub_column,
                n,
                rand_u32(cell, seed ^ JITTER_X),
            ),
            stratum_to_unit_f32(row * columns + sub_row, n, rand_u32(cell, seed ^ JITTER_Y)),
        )
    }
}

/// A small deterministic generator for test inputs (SplitMix32-style).
struct Inputs(u32);

impl Inputs {
    fn next(&mut self) -> u32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9);
        hash::hash_u32(self.0)
    }
}

const PATTERNS: [u32; 5] = [0, 1, 7, 0xdead_beef, u32::MAX];

/// 1..300, then primes, powers of two and their neighbours, squares and
/// products of awkward factors, up to 2^24.
fn sizes() -> Vec<u32> {
    let mut sizes: Vec<u32> = (1..300).collect();
    sizes.extend([
        509, 1021, 4093, 4099, 65_521, 65_537, 1_000_003, 16_777_213, 16_777_215, 16_777_216,
    ]);
    for k in 9..=24 {
        let p = 1u32 << k;
        sizes.extend([p - 1, p, p + 1]);
    }
    sizes.extend([
        300 * 301,
        4095 * 4097,
        3 * 5 * 7 * 11 * 13,
        1 << 24 >> 1 | 1,
    ]);
    sizes.retain(|&n| n <= 1 << 24);
    sizes.sort_unstable();
    sizes.dedup();
    sizes
}

/// Indices to check for a set of `n`: all of them for small `n`, else the
/// ends and a few hundred scattered ones.
fn indices(n: u32, rng: &mut Inputs) -> Vec<u32> {
    if n <= 1024 {
        return (0..n).collect();
    }
    let mut v: Vec<u32> = vec![0, 1, n / 2, n - 2, n - 1];
    v.extend((0..300).map(|_| rng.next() % n));
    v
}

fn bits(p: Vec2) -> (u32, u32) {
    (p.x.to_bits(), p.y.to_bits())
}

/// `sample` equals the reference, and `fill` (whole for small sets, else a
/// prefix) equals `sample`, for every pattern.
fn check<S: Sampler2D>(name: &str, sampler: &S, reference: impl Fn(u32, u32) -> Vec2) {
    let n = sampler.len();
    let mut rng = Inputs(n);
    let extra = rng.next();
    for pattern in PATTERNS.into_iter().chain([extra]) {
        for index in indices(n, &mut rng) {
            assert_eq!(
                bits(sampler.sample(index, pattern)),
                bits(reference(index, pattern)),
                "{name} n={n} index={index} pattern={pattern:#x}"
            );
        }
        // Whole sets up to 2^16 for one pattern, else prefixes (a partial
        // fill is also a path of its own); sized to keep the test quick.
        let whole = if pattern == 7 { 1 << 16 } else { 1 << 10 };
        for len in [n.min(whole), n.min(5), (n / 3).min(1 << 10)] {
            let mut out = vec![Vec2::splat(-1.0); len as usize];
            sampler.fill(pattern, &mut out);
            for (index, &p) in (0..).zip(&out) {
                assert_eq!(
                    bits(p),
                    bits(sampler.sample(index, pattern)),
                    "{name} fill n={n} len={len} index={index} pattern={pattern:#x}"
                );
            }
        }
    }
}

#[test]
fn permute_matches_reference() {
    let mut rng = Inputs(1);
    let mut lens: Vec<u32> = sizes();
    lens.extend([
        u32::MAX,
        u32::MAX - 1,
        1 << 31,
        (1 << 31) + 1,
        3_000_000_019,
    ]);
    for len in lens {
        for _ in 0..64 {
            let pattern = rng.next();
            let index = rng.next() % len;
            assert_eq!(
                hash::permute(index, len, pattern),
                reference::permute(index, len, pattern),
                "len {len} index {index} pattern {pattern:#x}"
            );
        }
    }
}

#[test]
fn stratum_to_unit_f32_matches_reference() {
    let mut rng = Inputs(2);
    for strata in sizes() {
        for _ in 0..64 {
            let stratum = rng.next() % strata;
            let b = rng.next();
            for (s, bits) in [
                (stratum, b),
                (0, 0),
                (strata - 1, u32::MAX),
                (stratum, 1 << 31),
            ] {
                assert_eq!(
                    hash::stratum_to_unit_f32(s, strata, bits).to_bits(),
                    reference::stratum_to_unit_f32(s, strata, bits).to_bits(),
                    "strata {strata} stratum {s} bits {bits:#x}"
                );
            }
        }
    }
}

#[test]
fn regular_matches_reference() {
    for n in sizes() {
        let s = Regular::new(n).unwrap();
        check("regular", &s, |i, p| {
            reference::regular(s.columns(), s.rows(), i, p)
        });
    }
    for (columns, rows) in [(1, 7), (7, 1), (3, 300), (256, 255), (1 << 12, 1 << 12)] {
        let s = Regular::with_grid(columns, rows).unwrap();
        check("regular grid", &s, |i, p| {
            reference::regular(columns, rows, i, p)
        });
    }
}

#[test]
fn random_matches_reference() {
    for n in sizes() {
        check("random", &Random::new(n).unwrap(), reference::random);
    }
}

#[test]
fn jittered_matches_reference() {
    for n in sizes() {
        let s = Jittered::new(n).unwrap();
        check("jittered", &s, |i, p| {
            reference::jittered(s.columns(), s.rows(), i, p)
        });
    }
    for (columns, rows) in [(1, 7), (7, 1), (3, 300), (257, 255), (1 << 12, 1 << 12)] {
        let s = Jittered::with_grid(columns, rows).unwrap();
        check("jittered grid", &s, |i, p| {
            reference::jittered(columns, rows, i, p)
        });
    }
}

#[test]
fn n_rooks_matches_reference() {
    for n in sizes() {
        check("n-rooks", &NRooks::new(n).unwrap(), |i, p| {
            reference::n_rooks(n, i, p)
        });
    }
}

#[test]
fn multi_jittered_matches_reference() {
    for n in sizes() {
        let s = MultiJittered::new(n).unwrap();
        check("multi-jittered", &s, |i, p| {
            reference::multi_jittered(s.columns(), s.rows(), i, p)
        });
    }
}

#[test]
fn correlated_multi_jittered_matches_reference() {
    for n in sizes() {
        let s = CorrelatedMultiJittered::new(n).unwrap();
        check("correlated-multi-jittered", &s, |i, p| {
            reference::correlated_multi_jittered(s.columns(), s.rows(), i, p)
        });
    }
}
