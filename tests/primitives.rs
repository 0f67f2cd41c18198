//! Measurements of `primitives::permute`: that it is a bijection, and that
//! the 2^32 patterns reach the permutations of short lengths often and
//! evenly.
//!
//! Lengths 2 to 8 are exact shuffles, proven over all 2^32 patterns; longer
//! lengths are measured. Kensler's 2013 hash fails every reach and
//! uniformity test below (a length of 4 reaches 8 of its 24 permutations,
//! and `NRooks` at n = 4 would give one rook arrangement for every
//! pattern). Patterns
//! are `hash_u32(k)` for consecutive `k`, so every test is deterministic;
//! each statistical one states the chance that a truly uniform permutation
//! family would fail it.

use std::collections::HashSet;
use wellspread::primitives::{hash_u32, permute};
use wellspread::{CorrelatedMultiJittered, MultiJittered, NRooks, Sampler2D};

/// The chi-square value a uniform family exceeds with probability 1e-6 for
/// `df` degrees of freedom (Wilson-Hilferty approximation, z = 4.753; for
/// df = 1 it gives 27.5 against the exact 23.9, so it errs towards passing
/// by a hair there and is within 1% from df = 20 up).
fn chi2_critical(df: f64) -> f64 {
    let a = 2.0 / (9.0 * df);
    df * (1.0 - a + 4.753 * a.sqrt()).powi(3)
}

/// Chi-square statistic of `counts` against equal expected counts.
fn chi2(counts: &[u64]) -> f64 {
    let total: u64 = counts.iter().sum();
    let expected = total as f64 / counts.len() as f64;
    counts
        .iter()
        .map(|&c| (c as f64 - expected).powi(2) / expected)
        .sum()
}

fn factorial(n: u32) -> u64 {
    (1..=n as u64).product()
}

/// Lehmer-code rank of a permutation of `[0, len)`, in `[0, len!)`.
fn rank(perm: &[u32]) -> usize {
    let mut r = 0;
    for (i, &x) in perm.iter().enumerate() {
        let smaller = perm[i + 1..].iter().filter(|&&y| y < x).count();
        r = r * (perm.len() - i) + smaller;
    }
    r
}

fn permutation(len: u32, pattern: u32) -> Vec<u32> {
    (0..len).map(|i| permute(i, len, pattern)).collect()
}

#[test]
fn permute_is_a_bijection() {
    let mut patterns = vec![0, 1, u32::MAX];
    patterns.extend((0..5).map(hash_u32));
    for len in 1..=300 {
        for &pattern in &patterns {
            let mut seen = vec![false; len as usize];
            for i in 0..len {
                let j = permute(i, len, pattern) as usize;
                assert!(!seen[j], "len {len} pattern {pattern:#x}: {j} twice");
                seen[j] = true;
            }
        }
    }
    for (len, patterns) in [
        ((1 << 16) - 1, &patterns[..]),
        ((1 << 16) + 1, &patterns[..]),
        (1 << 24, &patterns[..2]),
    ] {
        for &pattern in patterns {
            let mut seen = vec![false; len as usize];
            for i in 0..len {
                let j = permute(i, len, pattern) as usize;
                assert!(!seen[j], "len {len} pattern {pattern:#x}: {j} twice");
                seen[j] = true;
            }
        }
    }
    // Near u32::MAX: spot checks that values stay in range and never repeat.
    for len in [u32::MAX, u32::MAX - 1, (1 << 31) + 1] {
        for &pattern in &patterns {
            let mut seen = HashSet::new();
            for i in (0..2000).chain(len - 2000..len) {
                let j = permute(i, len, pattern);
                assert!(j < len);
                assert!(seen.insert(j), "len {len} pattern {pattern:#x}: {j} twice");
            }
        }
    }
}

/// Every permutation of a short length appears, with chi-square-uniform
/// frequency over `20,000 * len!` patterns (`10,000 * 720` for length 6, to
/// keep the test near four seconds; false failure rate 1e-6 per length).
/// The test notices a family whose frequencies are off by about 1% (root
/// mean square; 1.5% at length 6); Kensler's hash reached 8 of the 24
/// permutations of length 4 (chi-square in the millions).
#[test]
fn short_lengths_reach_every_permutation_uniformly() {
    let mut k = 0;
    for len in 2..=6 {
        let cells = factorial(len) as usize;
        let mut counts = vec![0u64; cells];
        let per_cell = if len < 6 { 20_000 } else { 10_000 };
        for _ in 0..per_cell * cells {
            counts[rank(&permutation(len, hash_u32(k)))] += 1;
            k += 1;
        }
        let missing = counts.iter().filter(|&&c| c == 0).count();
        assert_eq!(missing, 0, "len {len}: {missing} of {cells} never appear");
        let (stat, critical) = (chi2(&counts), chi2_critical(cells as f64 - 1.0));
        assert!(
            stat < critical,
            "len {len}: chi-square {stat} >= {critical}"
        );
    }
}

/// The inverse of `hash_u32` (lowbias32: xorshifts and odd multipliers are
/// each invertible), so that a test can pick the pattern with a given key.
fn unhash_u32(mut x: u32) -> u32 {
    // The inverse of an odd multiplier modulo 2^32, by Newton's iteration.
    let inverse = |m: u32| {
        let mut y = m;
        for _ in 0..5 {
            y = y.wrapping_mul(2u32.wrapping_sub(m.wrapping_mul(y)));
        }
        y
    };
    x ^= x >> 16;
    x = x.wrapping_mul(inverse(0x846c_a68b));
    x ^= (x >> 15) ^ (x >> 30);
    x = x.wrapping_mul(inverse(0x7feb_352d));
    x ^ (x >> 16)
}

/// Lengths 2 to 8 are exact Fisher-Yates shuffles: the key of pattern `p`
/// is `hash_u32(p ^ 0x9e37_79b9)`, a bijection, and the key's rank
/// `floor(key * len! / 2^32)` picks the permutation, so each of the `len!`
/// permutations owns one block of `floor(2^32 / len!)` or
/// `ceil(2^32 / len!)` consecutive keys, and so as many patterns. Checked
/// over all 2^32 patterns without enumerating them: for every rank, the
/// patterns at both ends of its key block and one inside it (found through
/// the inverse hash) give the same permutation, the blocks' sizes are as
/// stated, and the `len!` blocks give `len!` distinct permutations.
#[test]
fn short_lengths_are_exactly_uniform_over_all_patterns() {
    assert_eq!(unhash_u32(hash_u32(0x1234_5678)), 0x1234_5678);
    let pattern_of_key = |key: u64| unhash_u32(key as u32) ^ 0x9e37_79b9;
    for len in 2..=8u32 {
        let total = factorial(len);
        let first_key = |r: u64| (r << 32).div_ceil(total);
        let mut seen = vec![false; total as usize];
        for r in 0..total {
            let (first, last) = (first_key(r), first_key(r + 1) - 1);
            let size = last - first + 1;
            assert!(size == (1 << 32) / total || size == (1 << 32) / total + 1);
            let rank_of = |key: u64| rank(&permutation(len, pattern_of_key(key)));
            let mid = first + hash_u32(r as u32) as u64 % size;
            let ranks = [rank_of(first), rank_of(mid), rank_of(last)];
            assert!(
                ranks.iter().all(|&x| x == ranks[0]),
                "len {len} block {r}: {ranks:?}"
            );
            assert!(
                !seen[ranks[0]],
                "len {len}: block {r} repeats a permutation"
            );
            seen[ranks[0]] = true;
        }
    }
}

/// For longer lengths: where each index lands is uniform (chi-square over
/// the len x len position matrix from 10,000 patterns, false failure 1e-6),
/// and the 10,000 patterns give distinct permutations. For len 8 only
/// 40,320 exist: a uniform family gives 40,320 (1 - e^(-10000/40320)) =
/// 8,858 distinct (standard deviation 29); the test allows 6 deviations
/// (false failure below 1e-8). Longer lengths expect 10,000 (a collision
/// among 16! is a 2.4e-6 chance). Kensler's hash gave 1,024 for len 8 and
/// 7,469 for len 16.
#[test]
fn longer_lengths_are_uniform_and_distinct() {
    for len in [8u32, 16, 64, 1000] {
        let patterns = 10_000u32;
        let mut positions = vec![0u64; (len * len) as usize];
        let mut distinct = HashSet::new();
        for k in 0..patterns {
            let perm = permutation(len, hash_u32(k ^ 0x5555_5555));
            for (i, &j) in perm.iter().enumerate() {
                positions[i * len as usize + j as usize] += 1;
            }
            distinct.insert(perm);
        }
        let df = (len as f64 - 1.0).powi(2);
        let (stat, critical) = (chi2(&positions), chi2_critical(df));
        assert!(
            stat < critical,
            "len {len}: chi-square {stat} >= {critical}"
        );
        let distinct = distinct.len();
        if len == 8 {
            assert!(distinct.abs_diff(8_858) < 172, "len 8: {distinct} distinct");
        } else {
            assert_eq!(distinct, 10_000, "len {len}");
        }
    }
}

/// The fine-grid cell of every point of one set, in index order (from
/// `fill`, which `tests/samplers/` checks equals `sample`).
fn cells<S: Sampler2D>(sampler: &S, n: u32, pattern: u32) -> Vec<(u32, u32)> {
    let mut points = vec![wellspread::glam::Vec2::ZERO; sampler.len() as usize];
    sampler.fill(pattern, &mut points);
    points
        .iter()
        .map(|p| ((p.x * n as f32) as u32, (p.y * n as f32) as u32))
        .collect()
}

/// Whole sets: `NRooks` at n = 4 has 24 rook arrangements (as sets of
/// cells) and `CorrelatedMultiJittered` at n = 16 has 24 x 24 = 576 (one
/// shared shuffle of length 4 per axis); over 1,000 patterns per cell both
/// reach all and are chi-square uniform (false failure 1e-6 each). With
/// the sample order too, 1,000 patterns give at least 990 distinct
/// sequences for CMJ and multi-jittered (a uniform family repeats with
/// chance below 1e-9), and n-rooks reaches all 576 of its sequences. Kensler's hash gave one `NRooks` set and 8 CMJ sets.
#[test]
fn sampler_sets_are_many_and_uniform() {
    let rooks = NRooks::new(4).unwrap();
    let cmj = CorrelatedMultiJittered::new(16).unwrap();
    let mj = MultiJittered::new(16).unwrap();
    for (name, sets, set_of) in [
        (
            "n-rooks",
            24usize,
            &(|p| sorted(cells(&rooks, 4, p))) as &dyn Fn(u32) -> Vec<(u32, u32)>,
        ),
        ("cmj", 576, &|p| sorted(cells(&cmj, 16, p))),
    ] {
        let mut counts = std::collections::HashMap::new();
        for pattern in 0..1000 * sets as u32 {
            *counts.entry(set_of(pattern)).or_insert(0u64) += 1;
        }
        assert_eq!(counts.len(), sets, "{name}: sets reached");
        let counts: Vec<u64> = counts.into_values().collect();
        let (stat, critical) = (chi2(&counts), chi2_critical(sets as f64 - 1.0));
        assert!(stat < critical, "{name}: chi-square {stat} >= {critical}");
    }
    let sequences = |f: &dyn Fn(u32) -> Vec<(u32, u32)>| -> usize {
        (0..1000).map(f).collect::<HashSet<_>>().len()
    };
    // n-rooks at n = 4 in index order: a column and a row permutation, so
    // 24 x 24 = 576 sequences; 24,000 patterns reach all (a uniform family
    // misses one with chance 576 e^(-41.7), below 1e-15).
    let rook_sequences: HashSet<_> = (0..24_000).map(|p| cells(&rooks, 4, p)).collect();
    assert_eq!(rook_sequences.len(), 576, "n-rooks sequences");
    assert!(sequences(&|p| cells(&cmj, 16, p)) >= 990, "cmj");
    assert!(sequences(&|p| cells(&mj, 16, p)) >= 990, "mj");
    // Multi-jittered sets (a shuffle of length 4 per coarse column and row):
    // 1,000 patterns give 1,000 distinct sets.
    assert_eq!(
        (0..1000)
            .map(|p| sorted(cells(&mj, 16, p)))
            .collect::<HashSet<_>>()
            .len(),
        1000,
        "mj sets"
    );
}

fn sorted(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
    v.sort_unstable();
    v
}
