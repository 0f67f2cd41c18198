//! The choices: `discrete` at the f32 edges and keeping strata, and the
//! weighted `Discrete` and `AliasTable` following their weights.

use super::*;

// ---------------------------------------------------------------------------
// Discrete choice.

#[test]
fn discrete_at_the_f32_edges() {
    let mut ns: Vec<u32> = vec![
        1,
        2,
        3,
        5,
        7,
        10,
        255,
        256,
        257,
        65_521,
        1 << 20,
        (1 << 24) - 1,
        1 << 24,
    ];
    ns.extend((1..200).map(|k| k * 7919));
    for n in ns {
        let (i, r) = discrete(LAST, n);
        assert_eq!(i, n - 1, "n = {n}");
        assert!((0.0..1.0).contains(&r), "n = {n}: {r}");
        assert_eq!(discrete(0.0, n), (0, 0.0));
        let (i, r) = discrete(f32::EPSILON / 2.0, n);
        assert!(i <= 1 && (0.0..1.0).contains(&r), "n = {n}");
    }
    // Above 2^24 choices, the exact floor is below n - 1 (documented).
    for n in [(1 << 24) + 1, 1 << 25, 1 << 31, u32::MAX] {
        let (i, r) = discrete(LAST, n);
        let expected = ((u64::from(n) * ((1 << 24) - 1)) >> 24) as u32;
        assert_eq!(i, expected, "n = {n}");
        assert!(i < n && (0.0..1.0).contains(&r));
    }
    assert_eq!(discrete(LAST, u32::MAX).0, u32::MAX - 256);
    // Subnormal and tiny inputs.
    for u in [f32::from_bits(1), f32::MIN_POSITIVE, 1e-30, 1e-12] {
        let (i, r) = discrete(u, u32::MAX);
        assert_eq!(i, 0);
        assert!(
            (0.0..1.0).contains(&r)
                && (f64::from(r) - f64::from(u) * f64::from(u32::MAX)).abs() <= 1e-6 * f64::from(r)
        );
    }
    assert_eq!(discrete_checked(0.3, 0), None);
    assert_eq!(discrete_pdf(0), 0.0);
    assert_eq!(discrete_pdf(3), 1.0 / 3.0);
}

#[test]
#[cfg(not(debug_assertions))]
fn discrete_out_of_range_input_in_release_is_a_choice() {
    assert_eq!(discrete(0.25, 0), (0, 0.25));
    assert_eq!(discrete(f32::NAN, 3), (0, 0.0));
    assert_eq!(discrete(-1.0, 3), (0, 0.0));
    assert_eq!(discrete(1.0, 3).0, 2);
}

#[test]
#[cfg(debug_assertions)]
#[should_panic(expected = "n = 0 has no valid choice")]
fn discrete_with_no_choice_panics_in_debug() {
    let _ = discrete(0.25, 0);
}

#[test]
fn discrete_remapped_values_keep_the_finer_strata() {
    // 2^12 Sobol x coordinates, 2^k choices: within each choice the 2^(12-k)
    // remapped values are one per interval of 2^-(12-k), so reusing them
    // (a point on the chosen light) is still stratified.
    let sobol = Sobol::new(1 << 12).unwrap();
    for pattern in [0, 5, 0xffff_ffff] {
        for k in [1u32, 3, 6] {
            let per_choice = 1usize << (12 - k);
            let mut seen = vec![vec![false; per_choice]; 1 << k];
            for i in 0..1 << 12 {
                let (choice, remapped) = discrete(sobol.sample(i, pattern).x, 1 << k);
                let stratum = (remapped * per_choice as f32) as usize;
                assert!(
                    !seen[choice as usize][stratum],
                    "k = {k}, choice {choice}, stratum {stratum}"
                );
                seen[choice as usize][stratum] = true;
            }
        }
    }
}

#[test]
fn discrete_keeps_one_dimensional_strata() {
    // 2^m Sobol x coordinates are one per interval of 2^-m: every power of
    // two n <= 2^m gets exactly 2^m / n, and any n within 2 of 2^m / n.
    let sobol = Sobol::new(1 << 12).unwrap();
    for pattern in [0, 1, 0xffff_ffff] {
        let xs: Vec<f32> = (0..1 << 12).map(|i| sobol.sample(i, pattern).x).collect();
        for n in [1u32, 2, 3, 7, 64, 100, 1000, 4096] {
            let mut counts = vec![0u32; n as usize];
            for &x in &xs {
                counts[discrete(x, n).0 as usize] += 1;
            }
            let expected = 4096.0 / f64::from(n);
            for (i, &c) in counts.iter().enumerate() {
                if n.is_power_of_two() {
                    assert_eq!(f64::from(c), expected, "n = {n}, choice {i}");
                } else {
                    assert!(
                        (f64::from(c) - expected).abs() < 2.0,
                        "n = {n}, choice {i}: {c}"
                    );
                }
            }
        }
    }
}

proptest! {
    /// For `u = k 2^-24` (every sampler's output), the choice and the
    /// remapped value are exactly `k n >> 24` and the low 24 bits.
    #[test]
    fn discrete_is_the_exact_floor(k in 0u32..1 << 24, n in 1u32..=u32::MAX) {
        let u = k as f32 * (1.0 / 16_777_216.0);
        let (i, r) = discrete(u, n);
        let scaled = u64::from(k) * u64::from(n);
        prop_assert_eq!(i, (scaled >> 24) as u32);
        let rest = (scaled & 0xff_ffff) as f32 / 16_777_216.0;
        prop_assert_eq!(r, rest.min(LAST));
        prop_assert!(i < n && (0.0..1.0).contains(&r));
        // The inverse gives u back to f32 rounding of (i + r) / n.
        let back = discrete_inverse(i, r, n);
        prop_assert!((back - u).abs() <= f32::EPSILON * 2.0, "{} vs {}", back, u);
        if n.is_power_of_two() && n <= 1 << 24 {
            prop_assert_eq!(back, u);
        }
    }

    /// Any f32 in [0, 1), not only multiples of 2^-24, against an f64
    /// reference (exact while u n fits in 53 bits, n < 2^29).
    #[test]
    fn discrete_matches_f64_for_any_f32(u in 0.0f32..1.0, n in 1u32..1 << 29) {
        let (i, r) = discrete(u, n);
        let exact = f64::from(u) * f64::from(n);
        prop_assert_eq!(i, exact.floor() as u32);
        prop_assert_eq!(r, ((exact - exact.floor()) as f32).min(LAST));
    }
}

// ---------------------------------------------------------------------------
// Weighted discrete choice: Discrete (inverse CDF) and AliasTable (Vose).

/// 200 seeded weights spanning six decades, a quarter of them 0 (the first
/// and the last included).
fn test_weights() -> Vec<f32> {
    let mut rng = Pcg32::seed_from_u64(0x0027_0005);
    let mut weights: Vec<f32> = (0..200)
        .map(|_| {
            if rng.random::<f32>() < 0.25 {
                0.0
            } else {
                10f32.powf(rng.random::<f32>() * 6.0 - 3.0)
            }
        })
        .collect();
    weights[0] = 0.0;
    weights[199] = 0.0;
    weights
}

fn uniform_u(seed: u64, count: usize) -> Vec<f32> {
    random_points(seed, count / 2)
        .into_iter()
        .flat_map(|p| [p.x, p.y])
        .collect()
}

/// Both samplers choose each item with its weight's share (chi-square on
/// 2^20 random draws, false failure rate 1e-6 each) and never an item of
/// weight 0; the pmf they return is `pmf(index)`, and the remapped number
/// is in `[0, 1)`.
#[test]
fn weighted_choices_follow_their_weights() {
    let weights = test_weights();
    let total: f64 = weights.iter().map(|&w| f64::from(w)).sum();
    let inverse_cdf = Discrete::new(&weights).unwrap();
    let alias = AliasTable::new(&weights).unwrap();
    let us = uniform_u(0x0027_0006, 1 << 20);
    let expected: Vec<f64> = weights
        .iter()
        .map(|&w| f64::from(w) / total * us.len() as f64)
        .collect();
    for (name, sample, pmf) in [
        (
            "Discrete",
            &(|u| inverse_cdf.sample(u)) as &dyn Fn(f32) -> (u32, f32, f32),
            &(|i| inverse_cdf.pmf(i)) as &dyn Fn(u32) -> f32,
        ),
        ("AliasTable", &|u| alias.sample(u), &|i| alias.pmf(i)),
    ] {
        let mut counts = vec![0u64; weights.len()];
        for &u in &us {
            let (i, r, p) = sample(u);
            assert!((0.0..1.0).contains(&r), "{name}: remapped {r}");
            assert_eq!(p, pmf(i), "{name}");
            counts[i as usize] += 1;
        }
        for (i, &w) in weights.iter().enumerate() {
            let p = f64::from(pmf(i as u32));
            assert!(
                (p - f64::from(w) / total).abs() <= 1e-6 * p,
                "{name} pmf({i})"
            );
        }
        let (statistic, dof) = chi_square_against(&counts, &expected);
        let critical = chi_square_critical(dof);
        println!(
            "{name}: chi-square {statistic:.1} on {dof} dof (critical at p = 1e-6: {critical:.1})"
        );
        assert!(statistic < critical, "{name}: {statistic}");
    }
    // The test can fail: a uniform choice among the positive items is far off.
    let positive: Vec<u32> = (0..200).filter(|&i| weights[i as usize] > 0.0).collect();
    let mut counts = vec![0u64; weights.len()];
    for &u in &us {
        let (k, _) = discrete(u, positive.len() as u32);
        counts[positive[k as usize] as usize] += 1;
    }
    let (statistic, dof) = chi_square_against(&counts, &expected);
    assert!(statistic > 100.0 * chi_square_critical(dof), "{statistic}");
}

/// A stratified `u` stays stratified among the choices of `Discrete`: 2^12
/// Sobol x coordinates (one per interval of 2^-12) choose each item within
/// 2 of its expected count, and each item's remapped values are one per
/// interval of `1 / count` within that count's strata.
#[test]
fn discrete_choice_keeps_a_stratified_u_stratified() {
    let weights = test_weights();
    let d = Discrete::new(&weights).unwrap();
    let sobol = Sobol::new(1 << 12).unwrap();
    for pattern in [0, 7, 0xffff_ffff] {
        let mut counts = vec![0u32; weights.len()];
        for i in 0..1 << 12 {
            counts[d.sample(sobol.sample(i, pattern).x).0 as usize] += 1;
        }
        for (i, &c) in counts.iter().enumerate() {
            let expected = f64::from(d.pmf(i as u32)) * 4096.0;
            assert!(
                (f64::from(c) - expected).abs() < 2.0,
                "item {i}: {c} vs {expected}"
            );
        }
    }
    // Two items of weights 1 and 3: the 3072 remapped values of the second
    // are one per interval of 1/3072.
    let d = Discrete::new(&[1.0, 3.0]).unwrap();
    let mut seen = vec![false; 3072];
    for i in 0..1 << 12 {
        let (item, r, _) = d.sample(sobol.sample(i, 3).x);
        if item == 1 {
            let stratum = (f64::from(r) * 3072.0) as usize;
            assert!(!seen[stratum], "stratum {stratum} twice");
            seen[stratum] = true;
        }
    }
    assert!(seen.iter().all(|&s| s));
}

#[test]
fn weighted_choices_at_the_edges() {
    let weights = test_weights();
    let first = weights.iter().position(|&w| w > 0.0).unwrap() as u32;
    let last = weights.iter().rposition(|&w| w > 0.0).unwrap() as u32;
    let d = Discrete::new(&weights).unwrap();
    assert_eq!(d.len(), 200);
    assert!(!d.is_empty());
    assert_eq!(d.sample(0.0).0, first);
    assert_eq!(d.sample(LAST).0, last);
    assert!(d.sample(LAST).1 < 1.0);
    // Out-of-range input is clamped.
    assert_eq!(d.sample(f32::NAN), d.sample(0.0));
    assert_eq!(d.sample(-3.0), d.sample(0.0));
    assert_eq!(d.sample(1.0), d.sample(LAST));
    assert_eq!(d.pmf(200), 0.0);
    let a = AliasTable::new(&weights).unwrap();
    assert_eq!(a.len(), 200);
    assert_eq!(a.pmf(200), 0.0);
    for u in [0.0, f32::EPSILON / 2.0, 0.5, LAST, f32::NAN, -1.0, 1.0, 2.0] {
        let (i, r, p) = a.sample(u);
        assert!(
            weights[i as usize] > 0.0 && (0.0..1.0).contains(&r) && p > 0.0,
            "{u}"
        );
    }
    // One weight: always it.
    let one = Discrete::new(&[0.0, 5.0, 0.0]).unwrap();
    for u in [0.0, 0.3, LAST] {
        assert_eq!(one.sample(u), (1, u, 1.0));
    }
    assert_eq!(AliasTable::new(&[0.0, 5.0, 0.0]).unwrap().sample(0.5).0, 1);
    // A weight 1e-60 of the total still gets a pmf whose inverse is finite.
    for (i, _, p) in [
        Discrete::new(&[1e-30, 1e30]).unwrap().sample(0.0),
        AliasTable::new(&[1e-30, 1e30]).unwrap().sample(0.0),
    ] {
        assert!(p > 0.0 && (1.0 / p).is_finite(), "item {i}: pmf {p}");
    }
    // The 2^-24 grid: every u chooses an item of positive weight, sample
    // and inverse agree.
    for k in (0..1u32 << 24).step_by(4099) {
        let u = k as f32 / 16_777_216.0;
        let (i, r, p) = d.sample(u);
        assert!(weights[i as usize] > 0.0 && p > 0.0);
        let back = d.inverse(i, r);
        assert!((back - u).abs() <= 2.0 * f32::EPSILON, "{u} -> {back}");
        let (i, _, p) = a.sample(u);
        assert!(weights[i as usize] > 0.0 && p > 0.0);
    }
}

#[test]
fn weighted_choices_reject_bad_weights() {
    use wellspread::Error;
    for (weights, error) in [
        (
            &[1.0, -0.5][..],
            Error::NegativeWeight {
                index: 1,
                weight: -0.5,
            },
        ),
        (
            &[1.0, 2.0, f32::INFINITY],
            Error::NonFiniteWeight {
                index: 2,
                weight: f32::INFINITY,
            },
        ),
        (
            &[f32::NEG_INFINITY],
            Error::NonFiniteWeight {
                index: 0,
                weight: f32::NEG_INFINITY,
            },
        ),
        (&[0.0, -0.0, 0.0], Error::ZeroTotalWeight { count: 3 }),
        (&[], Error::ZeroTotalWeight { count: 0 }),
    ] {
        assert_eq!(Discrete::new(weights), Err(error));
        assert_eq!(AliasTable::new(weights), Err(error));
    }
    // NaN != NaN: match the variant.
    assert!(matches!(
        Discrete::new(&[1.0, f32::NAN]),
        Err(Error::NonFiniteWeight { index: 1, weight }) if weight.is_nan()
    ));
    assert!(matches!(
        AliasTable::new(&[f32::NAN]),
        Err(Error::NonFiniteWeight { index: 0, .. })
    ));
    // The messages say what to do.
    let message = Error::NegativeWeight {
        index: 1,
        weight: -0.5,
    }
    .to_string();
    assert!(
        message.contains("weight 1 is -0.5") && message.contains(">= 0"),
        "{message}"
    );
    let message = Error::ZeroTotalWeight { count: 3 }.to_string();
    assert!(
        message.contains("got 3 weights, none positive"),
        "{message}"
    );
    let message = Error::NonFiniteWeight {
        index: 2,
        weight: f32::INFINITY,
    }
    .to_string();
    assert!(
        message.contains("weight 2 is inf") && message.contains("finite"),
        "{message}"
    );
    let message = Error::TooManyWeights { count: 1 << 33 }.to_string();
    assert!(
        message.contains("8589934592") && message.contains("two draws"),
        "{message}"
    );
}

// ---------------------------------------------------------------------------
// Light warps on degenerate and huge geometry: regressions and properties.

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20000))]

    /// Weighted choices over weights from 0 to f32::MAX: built, every
    /// choice has a positive finite pmf; refused, a typed error.
    #[test]
    fn weighted_choices_choose_what_has_weight(
        weights in proptest::collection::vec(prop_oneof![Just(0.0f32), Just(f32::MIN_POSITIVE), Just(f32::MAX), Just(1e-30), 0.0f32..10.0], 1..40),
        u in edge_coordinate(),
    ) {
        match (Discrete::new(&weights), AliasTable::new(&weights)) {
            (Ok(d), Ok(t)) => {
                for (i, r, pmf, own) in [(d.sample(u), d.pmf(d.sample(u).0)), (t.sample(u), t.pmf(t.sample(u).0))]
                    .map(|((i, r, pmf), own)| (i, r, pmf, own))
                {
                    prop_assert!(weights[i as usize] > 0.0 && pmf.is_finite() && pmf > 0.0, "{} {}", i, pmf);
                    prop_assert!((0.0..1.0).contains(&r));
                    prop_assert_eq!(pmf, own);
                }
            }
            (Err(_), Err(_)) => prop_assert!(weights.iter().all(|&w| w == 0.0)),
            (d, t) => prop_assert!(false, "{:?} {:?}", d.err(), t.err()),
        }
    }
}
