//! The checks every sampler goes through, and the strategies that feed them.

use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use wellspread::glam::Vec2;
use wellspread::{AnySampler, Sampler2D, SamplerKind, metrics};

use crate::guarantees::{Offset, coarse_grid, guarantees};

/// Index of the stratum of width `1 / strata` that holds `x`, exactly.
pub(crate) fn stratum(x: f32, strata: u32) -> u64 {
    (x as f64 * strata as f64).floor() as u64
}

/// Position of `x` inside its stratum of width `1 / strata`, in `[0, 1)`.
pub(crate) fn offset_in_stratum(x: f32, strata: u32) -> f64 {
    let scaled = x as f64 * strata as f64;
    scaled - scaled.floor()
}

/// A bit per stratum, to check that no stratum is hit twice. With as many
/// points as strata, "never twice" is "exactly once" (pigeonhole).
#[derive(Clone)]
pub(crate) struct Occupancy {
    bits: Vec<u64>,
    len: u64,
}

impl Occupancy {
    pub(crate) fn new(len: u64) -> Self {
        Self {
            bits: vec![0; len.div_ceil(64) as usize],
            len,
        }
    }

    /// `false` if `slot` is out of range or was already taken.
    pub(crate) fn insert(&mut self, slot: u64) -> bool {
        if slot >= self.len {
            return false;
        }
        let (word, bit) = ((slot / 64) as usize, slot % 64);
        let fresh = self.bits[word] & (1 << bit) == 0;
        self.bits[word] |= 1 << bit;
        fresh
    }
}

pub(crate) fn in_unit_square(p: Vec2) -> bool {
    p.is_finite() && (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)
}

/// The largest power-of-two set whose net property the whole-set check
/// verifies (it keeps the points for that; larger sets are streamed).
pub(crate) const NET_CHECK_MAX: u32 = 1 << 20;

/// Checks a whole set, streamed through `sample` (no buffer, so it works at
/// 2^24 points): range, and every stratification the sampler promises,
/// including the net at powers of two up to [`NET_CHECK_MAX`].
pub(crate) fn check_whole_set(
    kind: SamplerKind,
    n: u32,
    pattern: u32,
) -> Result<(), TestCaseError> {
    let g = guarantees(kind);
    let sampler = kind
        .build(n)
        .map_err(|e| TestCaseError::fail(format!("{kind} n = {n}: {e}")))?;
    prop_assert_eq!(sampler.len(), n);
    prop_assert!(!sampler.is_empty());
    let grid = coarse_grid(&sampler);
    if g.strata {
        prop_assert!(grid.is_some(), "{kind} promises strata but has no grid");
    }
    let check_net = g.net_at_powers_of_two && n.is_power_of_two() && n <= NET_CHECK_MAX;
    let mut kept = Vec::with_capacity(if check_net { n as usize } else { 0 });
    let mut fine_x = Occupancy::new(n as u64);
    let mut fine_y = Occupancy::new(n as u64);
    let mut cells = Occupancy::new(n as u64);
    for index in 0..n {
        let p = sampler.sample(index, pattern);
        // Messages are formatted only on failure: this loop runs 2^24 times.
        let what = || format!("{kind} n = {n} pattern {pattern:#x} index {index}");
        prop_assert!(in_unit_square(p), "{}: {p:?} outside [0, 1)^2", what());
        if g.latin_x {
            prop_assert!(
                fine_x.insert(stratum(p.x, n)),
                "{}: fine column {} twice",
                what(),
                stratum(p.x, n)
            );
        }
        if g.latin_y {
            prop_assert!(
                fine_y.insert(stratum(p.y, n)),
                "{}: fine row {} twice",
                what(),
                stratum(p.y, n)
            );
        }
        if let (true, Some((columns, rows))) = (g.strata, grid) {
            let cell = stratum(p.y, rows) * columns as u64 + stratum(p.x, columns);
            prop_assert!(
                cells.insert(cell),
                "{}: coarse cell {cell} of {columns} x {rows} twice",
                what()
            );
        }
        if let (Some(Offset::Centre), Some((columns, rows))) = (g.offset, grid) {
            let centre_x = (stratum(p.x, columns) as f64 + 0.5) / columns as f64;
            let centre_y = (stratum(p.y, rows) as f64 + 0.5) / rows as f64;
            let step = 1.0 / 16_777_216.0;
            prop_assert!(
                (p.x as f64 - centre_x).abs() <= step && (p.y as f64 - centre_y).abs() <= step,
                "{}: {p:?} not at its cell centre",
                what()
            );
        }
        if check_net {
            kept.push(p);
        }
    }
    if check_net {
        prop_assert!(
            is_net_base2(&kept),
            "{kind} n = {n} pattern {pattern:#x}: not a (0,m,2)-net"
        );
    }
    Ok(())
}

/// `true` if `points` (a power-of-two count `2^m`) is a (0,m,2)-net in base
/// 2, by the crate's metric (itself checked against brute force in
/// `tests/metrics.rs`). Invalid input fails the test.
pub(crate) fn is_net_base2(points: &[Vec2]) -> bool {
    metrics::is_net_base2(points).expect("a power-of-two set of points in [0, 1)^2")
}

/// `true` if `points` has exactly one point in each cell of a
/// `columns x rows` grid (`columns * rows == points.len()`).
pub(crate) fn is_stratified(points: &[Vec2], columns: u32, rows: u32) -> bool {
    assert_eq!(points.len() as u64, columns as u64 * rows as u64);
    metrics::is_stratified(points, columns, rows).expect("points in [0, 1)^2 on a dividing grid")
}

/// The coarse grid is `columns x rows = n` with `columns <= rows` and no
/// divisor of `n` strictly between `columns` and `sqrt(n)`: the most square
/// factorisation (so a prime gives `1 x n`).
pub(crate) fn check_most_square(kind: SamplerKind, n: u32) -> Result<(), TestCaseError> {
    let sampler = kind
        .build(n)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    if let Some((columns, rows)) = coarse_grid(&sampler) {
        prop_assert_eq!(columns as u64 * rows as u64, n as u64);
        prop_assert!(columns <= rows, "{kind} n = {n}: {columns} x {rows}");
        for d in columns + 1..=n.isqrt() {
            prop_assert!(
                !n.is_multiple_of(d),
                "{kind} n = {n}: {columns} x {rows}, but {d} divides n"
            );
        }
    }
    Ok(())
}

/// `fill` writes what `sample` returns, bit for bit, for whole sets and
/// prefixes, and two calls agree.
pub(crate) fn check_fill(
    kind: SamplerKind,
    n: u32,
    pattern: u32,
    prefix: u32,
) -> Result<(), TestCaseError> {
    let sampler = kind
        .build(n)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    let mut whole = vec![Vec2::NAN; n as usize];
    sampler.fill(pattern, &mut whole);
    let mut again = vec![Vec2::NAN; n as usize];
    sampler.fill(pattern, &mut again);
    let mut part = vec![Vec2::NAN; prefix.min(n) as usize];
    sampler.fill(pattern, &mut part);
    for (index, p) in (0..n).zip(&whole) {
        let q = sampler.sample(index, pattern);
        prop_assert!(
            bits(*p) == bits(q) && bits(q) == bits(sampler.sample(index, pattern)),
            "{kind} n = {n} pattern {pattern:#x} index {index}: fill {p:?}, sample {q:?}"
        );
        prop_assert_eq!(bits(*p), bits(again[index as usize]));
        if let Some(r) = part.get(index as usize) {
            prop_assert_eq!(bits(*p), bits(*r), "prefix fill differs at {}", index);
        }
    }
    Ok(())
}

pub(crate) fn bits(p: Vec2) -> [u32; 2] {
    [p.x.to_bits(), p.y.to_bits()]
}

pub(crate) fn sorted_bits(sampler: &AnySampler, pattern: u32) -> Vec<[u32; 2]> {
    let mut v: Vec<_> = (0..sampler.len())
        .map(|i| bits(sampler.sample(i, pattern)))
        .collect();
    v.sort_unstable();
    v
}

/// Two different patterns give different sets, or for `Regular` the same
/// set in another order.
pub(crate) fn check_patterns_differ(
    kind: SamplerKind,
    n: u32,
    a: u32,
    b: u32,
) -> Result<(), TestCaseError> {
    let sampler = kind
        .build(n)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    let (set_a, set_b) = (sorted_bits(&sampler, a), sorted_bits(&sampler, b));
    if guarantees(kind).pattern_changes_set {
        // Two jittered sets coincide only if every jitter does: at most
        // 2^-24 per coordinate for n <= 4096 (2^24 / n >= 4096 positions).
        prop_assert_ne!(
            set_a,
            set_b,
            "{} n = {}: patterns {:#x} and {:#x} agree",
            kind,
            n,
            a,
            b
        );
    } else {
        prop_assert_eq!(&set_a, &set_b);
        // Orders are permute(_, n, _), which for n >= 256 repeats for two
        // random patterns with probability below 1e-7 (measured: 145
        // coincidences among 10^5 patterns at n = 256, none at n = 1000).
        if n >= 256 {
            let order = |p| {
                (0..n)
                    .map(|i| bits(sampler.sample(i, p)))
                    .collect::<Vec<_>>()
            };
            prop_assert_ne!(order(a), order(b), "{} n = {}: same order", kind, n);
        }
    }
    Ok(())
}

pub(crate) fn config() -> ProptestConfig {
    let base = ProptestConfig::default();
    ProptestConfig {
        // At least 1,000; PROPTEST_CASES can ask for more.
        cases: base.cases.max(1000),
        ..base
    }
}

pub(crate) fn small_n() -> impl Strategy<Value = u32> {
    prop_oneof![1u32..=64, 1u32..=4096]
}

pub(crate) fn any_pattern() -> impl Strategy<Value = u32> {
    prop_oneof![Just(0u32), Just(u32::MAX), any::<u32>()]
}

/// A second pattern: a neighbour (one bit flipped, or the next pixel's seed)
/// as often as an unrelated one, since those are the ones a weak hash confuses.
pub(crate) fn other_pattern(a: u32) -> impl Strategy<Value = u32> {
    prop_oneof![
        (0u32..32).prop_map(move |bit| a ^ (1 << bit)),
        Just(a.wrapping_add(1)),
        any::<u32>().prop_filter("a different pattern", move |&b| b != a),
    ]
}

pub(crate) fn points(
    sampler: &impl Sampler2D,
    indices: core::ops::Range<u32>,
    pattern: u32,
) -> Vec<Vec2> {
    indices.map(|i| sampler.sample(i, pattern)).collect()
}

pub(crate) fn run(result: Result<(), TestCaseError>) {
    if let Err(e) = result {
        panic!("{e}");
    }
}
