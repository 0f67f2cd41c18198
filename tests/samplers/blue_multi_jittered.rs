//! `BlueMultiJittered`'s guarantees: Latin on the `n x n` fine grid,
//! stratified on its `columns x rows` grid, a toroidal minimum distance of at
//! least its proved bound for every pattern, that bound at least 0.6 of the
//! hexagonal-packing distance for every n from 16 to 4096 (0.586 at n = 24),
//! measured means at least 0.6 and minima at least 0.5, `fill == sample`,
//! every point in `[0, 1)^2`, and an integration error at most 1.1x
//! multi-jitter's at n = 64, 256 and 1024.
//!
//! Every check is exact (stratum membership in f64 from the f32 values, as in
//! `tests/samplers/`) or seeded, so none can fail by chance. The generic harness in
//! `tests/samplers/` also runs this sampler through the contract checks on
//! every instruction set.

use proptest::prelude::*;
use wellspread::glam::Vec2;
use wellspread::{BlueMultiJittered, Sampler2D, metrics};

/// The hexagonal-packing distance of `n` points on the unit torus.
fn packing(n: u32) -> f64 {
    (2.0 / (3.0f64.sqrt() * f64::from(n))).sqrt()
}

fn set(sampler: &BlueMultiJittered, pattern: u32) -> Vec<Vec2> {
    let mut out = vec![Vec2::ZERO; sampler.len() as usize];
    sampler.fill(pattern, &mut out);
    out
}

/// `floor(v * strata)`, exact: `v` has 24 significant bits, `strata` < 2^25.
fn stratum(v: f32, strata: u32) -> u64 {
    (f64::from(v) * f64::from(strata)).floor() as u64
}

/// Every guarantee but the distance target on one set, exactly.
fn check_set(sampler: &BlueMultiJittered, pattern: u32) -> Result<(), TestCaseError> {
    let n = sampler.len();
    let (columns, rows) = (sampler.columns(), sampler.rows());
    prop_assert_eq!(u64::from(columns) * u64::from(rows), u64::from(n));
    prop_assert!(columns <= rows);
    let points = set(sampler, pattern);
    let mut fine_x = vec![false; n as usize];
    let mut fine_y = vec![false; n as usize];
    let mut cells = vec![false; n as usize];
    for (index, p) in (0..).zip(&points) {
        prop_assert!(
            (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y),
            "{p} at {index}"
        );
        prop_assert_eq!(
            p.to_array().map(f32::to_bits),
            sampler.sample(index, pattern).to_array().map(f32::to_bits)
        );
        let (x, y) = (stratum(p.x, n) as usize, stratum(p.y, n) as usize);
        prop_assert!(
            !fine_x[x],
            "fine column {} twice (n = {}, pattern {})",
            x,
            n,
            pattern
        );
        prop_assert!(
            !fine_y[y],
            "fine row {} twice (n = {}, pattern {})",
            y,
            n,
            pattern
        );
        fine_x[x] = true;
        fine_y[y] = true;
        let cell = (stratum(p.y, rows) * u64::from(columns) + stratum(p.x, columns)) as usize;
        prop_assert!(
            !cells[cell],
            "coarse cell {} twice (n = {}, pattern {})",
            cell,
            n,
            pattern
        );
        cells[cell] = true;
    }
    if n >= 2 {
        let d = metrics::toroidal_min_distance(&points).unwrap();
        let bound = sampler.min_distance_bound();
        prop_assert!(
            d >= bound,
            "n = {}, pattern {}: {} < bound {}",
            n,
            pattern,
            d,
            bound
        );
    } else {
        prop_assert_eq!(sampler.min_distance_bound(), f64::INFINITY);
    }
    Ok(())
}

/// Sizes: 1, primes, squares, non-squares, powers of two, the range the
/// distance target covers, and a few larger sets.
fn sizes() -> impl Strategy<Value = u32> {
    prop_oneof![
        Just(1u32),
        prop::sample::select(vec![2u32, 3, 5, 7, 13, 17, 31, 97, 101, 1021, 4093, 65_521]),
        prop::sample::select(vec![
            4u32, 9, 12, 18, 24, 32, 48, 50, 96, 200, 510, 1000, 2046, 2048
        ]),
        16u32..=4096,
        prop::sample::select(vec![16_384u32, 65_536, 100_000, 131_071]),
    ]
}

fn patterns() -> impl Strategy<Value = u32> {
    prop_oneof![Just(0u32), Just(u32::MAX), any::<u32>()]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn latin_stratified_in_range_fill_is_sample_and_above_the_bound(n in sizes(), pattern in patterns()) {
        let sampler = BlueMultiJittered::new(n).unwrap();
        check_set(&sampler, pattern)?;
    }

    #[test]
    fn scattered_samples_agree_with_fill(n in sizes(), pattern in patterns(), picks in prop::collection::vec(any::<u32>(), 8)) {
        let sampler = BlueMultiJittered::new(n).unwrap();
        let points = set(&sampler, pattern);
        for pick in picks {
            let index = pick % n;
            prop_assert_eq!(sampler.sample(index, pattern).to_array().map(f32::to_bits), points[index as usize].to_array().map(f32::to_bits));
        }
    }
}

#[test]
fn the_bound_is_at_least_0_6_of_packing_at_every_n_from_16_to_4096_but_24() {
    for n in 16..=4096 {
        let sampler = BlueMultiJittered::new(n).unwrap();
        let normalised = sampler.min_distance_bound() / packing(n);
        // The one shortfall the docs state.
        let target = if n == 24 { 0.585 } else { 0.6 };
        assert!(
            normalised >= target,
            "n = {n}: normalised bound {normalised}"
        );
    }
}

#[test]
fn measured_distances_meet_the_targets() {
    // 64 patterns per n (as docs/quality.md): mean at least 0.6, every
    // pattern at least 0.5 (the bound already implies both).
    let mut sizes: Vec<u32> = (16..=4096).step_by(97).collect();
    sizes.extend([16, 18, 64, 256, 1024, 4096, 4093, 2046]);
    for n in sizes {
        let sampler = BlueMultiJittered::new(n).unwrap();
        let (mut sum, mut worst) = (0.0, f64::INFINITY);
        for pattern in 0..64 {
            let d = metrics::normalized_toroidal_min_distance(&set(&sampler, pattern)).unwrap();
            sum += d;
            worst = worst.min(d);
        }
        assert!(sum / 64.0 >= 0.6, "n = {n}: mean {}", sum / 64.0);
        assert!(worst >= 0.5, "n = {n}: worst {worst}");
    }
}

#[test]
fn small_sets_have_a_positive_bound_and_keep_the_guarantees() {
    for n in 1..16 {
        let sampler = BlueMultiJittered::new(n).unwrap();
        assert!(sampler.min_distance_bound() > 0.0, "n = {n}");
        for pattern in [0, 1, 2, 3, u32::MAX] {
            check_set(&sampler, pattern).unwrap();
        }
    }
}

#[test]
fn a_prime_near_2_pow_24_and_2_pow_24_itself() {
    for n in [16_777_213u32, 1 << 24] {
        let sampler = BlueMultiJittered::new(n).unwrap();
        assert!(sampler.min_distance_bound() / packing(n) >= 0.6, "n = {n}");
        for index in [0, 1, n / 2, n - 1] {
            let p = sampler.sample(index, u32::MAX);
            assert!((0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y));
        }
    }
    assert!(BlueMultiJittered::new((1 << 24) + 1).is_err());
    assert!(BlueMultiJittered::new(0).is_err());
}

/// RMSE over the quality bench's 256 patterns (`pattern_seed(r, n, 0, 0)`)
/// of the disk, triangle, Gaussian and bilinear integrands of
/// `docs/quality.md`.
fn integrand_rmse(sampler: &impl Sampler2D, n: u32) -> [f64; 4] {
    let sq = |v: f32| f64::from(v) * f64::from(v);
    let exact = [0.5, 0.5, 0.557_746_285_351_033, 0.25];
    let mut points = vec![Vec2::ZERO; n as usize];
    let mut sum_sq = [0.0f64; 4];
    for r in 0..256 {
        sampler.fill(
            wellspread::primitives::pattern_seed(r, n, 0, 0),
            &mut points,
        );
        let mut sums = [0.0f64; 4];
        for p in &points {
            sums[0] += f64::from(u8::from(sq(p.x) + sq(p.y) < 2.0 / std::f64::consts::PI));
            sums[1] += f64::from(u8::from(p.y < p.x));
            sums[2] += (-sq(p.x) - sq(p.y)).exp();
            sums[3] += f64::from(p.x) * f64::from(p.y);
        }
        for k in 0..4 {
            sum_sq[k] += (sums[k] / f64::from(n) - exact[k]).powi(2);
        }
    }
    sum_sq.map(|s| (s / 256.0).sqrt())
}

#[test]
fn integration_error_is_at_most_1_1_times_multi_jitter_at_64_256_and_1024() {
    // Seeded, so exact: the same values as the quality bench's tables. The
    // triangle at n = 64 is the case the diagonal test in the constructor
    // exists for (1.49x with the first lattice that keeps the bound).
    for n in [64, 256, 1024] {
        let blue = integrand_rmse(&BlueMultiJittered::new(n).unwrap(), n);
        let multi = integrand_rmse(&wellspread::MultiJittered::new(n).unwrap(), n);
        for (k, name) in ["disk", "triangle", "gaussian", "bilinear"]
            .iter()
            .enumerate()
        {
            let ratio = blue[k] / multi[k];
            assert!(
                ratio <= 1.1,
                "n = {n}, {name}: {ratio:.3}x multi-jitter's RMSE"
            );
        }
    }
}
