//! The contract over every kind: range, `fill == sample`, patterns, and
//! every promised stratification at small, edge and 2^24 sizes.

use proptest::prelude::*;
use wellspread::{Random, Sampler2D, SamplerKind};

use crate::checks::*;
use crate::guarantees::{coarse_grid, guarantees, must_accept};

proptest! {
    #![proptest_config(config())]

    #[test]
    fn whole_sets_keep_every_guarantee(n in small_n(), pattern in any_pattern()) {
        for &kind in SamplerKind::ALL {
            check_whole_set(kind, n, pattern)?;
            check_most_square(kind, n)?;
        }
    }

    #[test]
    fn fill_equals_sample(n in small_n(), pattern in any_pattern(), prefix in 0u32..=4096) {
        for &kind in SamplerKind::ALL {
            check_fill(kind, n, pattern, prefix)?;
        }
    }

    #[test]
    fn different_patterns_give_different_sets(
        (n, a, b) in (small_n(), any_pattern()).prop_flat_map(|(n, a)| (Just(n), Just(a), other_pattern(a)))
    ) {
        for &kind in SamplerKind::ALL {
            check_patterns_differ(kind, n, a, b)?;
        }
    }

    /// Any accepted n up to u32::MAX: a few indices, including the last.
    #[test]
    fn any_n_samples_stay_in_range(n in prop_oneof![1u32..=u32::MAX, 1u32..=1 << 24], pattern in any_pattern(), t in 0.0f64..1.0) {
        for &kind in SamplerKind::ALL {
            let built = kind.build(n);
            prop_assert_eq!(built.is_ok(), must_accept(kind, n), "{} n = {}: {:?}", kind, n, built);
            let Ok(sampler) = built else { continue };
            let middle = ((n - 1) as f64 * t) as u32;
            for index in [0, middle, n - 1] {
                let p = sampler.sample(index, pattern);
                prop_assert!(in_unit_square(p), "{kind} n = {n} index {index}: {p:?}");
                prop_assert_eq!(bits(p), bits(sampler.sample(index, pattern)));
            }
        }
    }
}

/// Sizes at the edges: primes, non-squares, powers of two, the largest n.
const EDGE_SIZES: &[u32] = &[
    1,
    2,
    3,
    4093,    // prime
    4099,    // prime
    8191,    // prime
    65_521,  // prime
    1 << 21, // 2^10 x 2^11
    1_000_003,
    1 << 20,
    (1 << 24) - 3, // the largest prime below 2^24
    1 << 24,
    (1 << 24) + 1, // 97 x 257 x 673: 673 x 24929
    u32::MAX - 4,  // the largest prime below 2^32
    u32::MAX,      // 65535 x 65537
];

#[test]
fn edge_sizes_stay_in_range() {
    for &kind in SamplerKind::ALL {
        for n in EDGE_SIZES.iter().copied().chain([guarantees(kind).max_n]) {
            let built = kind.build(n);
            assert_eq!(
                built.is_ok(),
                must_accept(kind, n),
                "{kind} n = {n}: {built:?}"
            );
            let Ok(sampler) = built else { continue };
            let stride = (n / 4096).max(1);
            let ends = (0..n.min(64)).chain(n - n.min(64)..n);
            for index in ends.chain((0..n).step_by(stride as usize)) {
                for pattern in [0, 1, 0xdead_beef, u32::MAX] {
                    let p = sampler.sample(index, pattern);
                    assert!(in_unit_square(p), "{kind} n = {n} index {index}: {p:?}");
                }
            }
        }
    }
}

#[test]
fn whole_sets_at_edge_sizes() {
    for &kind in SamplerKind::ALL {
        for n in [4093, 8191, 1 << 15, 65_521] {
            run(check_whole_set(kind, n, 0xdead_beef));
        }
        run(check_whole_set(kind, 1 << 20, 0));
        run(check_fill(kind, 65_521, u32::MAX, 1000));
    }
}

/// The f32 edge on whole sets: every Latin sampler at 2^24, the largest n
/// its columns and rows are promised for, and the grid samplers just past it
/// at 2^24 + 1 (a 673 x 24929 grid), so the limits in the docs are tested at
/// their edges. One thread per sampler (a few seconds each with debug
/// assertions): this is the longest test.
#[test]
fn whole_sets_at_2_pow_24() {
    std::thread::scope(|scope| {
        for &kind in SamplerKind::ALL {
            let g = guarantees(kind);
            if (g.latin_x || g.latin_y) && g.max_n >= 1 << 24 {
                scope.spawn(move || run(check_whole_set(kind, 1 << 24, 0xdead_beef)));
            } else if g.strata && g.max_n > 1 << 24 {
                scope.spawn(move || run(check_whole_set(kind, (1 << 24) + 1, u32::MAX)));
            }
        }
    });
}

/// n = 1, primes, non-squares and powers of two, at both pattern extremes.
#[test]
fn whole_sets_at_small_edges() {
    for &kind in SamplerKind::ALL {
        for n in [
            1, 2, 3, 5, 6, 7, 8, 12, 24, 31, 97, 127, 128, 360, 1021, 1024,
        ] {
            for pattern in [0, u32::MAX] {
                run(check_whole_set(kind, n, pattern));
                run(check_most_square(kind, n));
                run(check_fill(kind, n, pattern, n / 2));
            }
        }
    }
}

#[test]
fn correlated_multi_jitter_at_a_large_prime() {
    // A 1 x n coarse grid: the rook condition on its own, which
    // CorrelatedMultiJittered's docs promise (Kensler's padding loses it).
    // The largest prime below 2^20; near 2^24 takes 5 s and adds nothing
    // that `whole_sets_at_2_pow_24` and `edge_sizes_stay_in_range` miss.
    run(check_whole_set(
        SamplerKind::CorrelatedMultiJittered,
        (1 << 20) - 3,
        0,
    ));
}

#[test]
fn regular_and_jittered_take_the_largest_u32_grid() {
    for kind in [SamplerKind::Regular, SamplerKind::Jittered] {
        let sampler = kind.build(u32::MAX).unwrap();
        assert_eq!(coarse_grid(&sampler), Some((65_535, 65_537)));
        for index in u32::MAX - 1000..u32::MAX {
            let p = sampler.sample(index, 0x1234_5678);
            assert!(in_unit_square(p), "{kind} index {index}: {p:?}");
        }
    }
    let random = Random::new(u32::MAX).unwrap();
    for index in u32::MAX - 1000..u32::MAX {
        assert!(
            in_unit_square(random.sample(index, 7)),
            "random index {index}"
        );
    }
}

/// Small consecutive patterns (frame numbers, dimension indices) share no
/// point: a pattern mixed into the index symmetrically made sample i of
/// pattern p equal sample p of pattern i.
/// Accidental sharing needs two 24-bit coordinates to agree: below 1e-6
/// over this whole test.
#[test]
fn small_patterns_share_no_point() {
    for &kind in SamplerKind::ALL {
        if !guarantees(kind).pattern_changes_set {
            continue;
        }
        for n in [2, 3, 64] {
            let sampler = kind.build(n).unwrap();
            let mut seen = std::collections::HashMap::new();
            for pattern in 0..64 {
                for index in 0..n {
                    let p = bits(sampler.sample(index, pattern));
                    if let Some(earlier) = seen.insert(p, (pattern, index)) {
                        panic!(
                            "{kind} n = {n}: pattern {pattern} index {index} repeats {earlier:?}"
                        );
                    }
                }
            }
        }
    }
}
