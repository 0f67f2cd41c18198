//! The discrepancies against closed forms from the literature (evaluated
//! here, not by the library) and against exact integer evaluation of the
//! f32 inputs, to 1e-12 relative, up to 2^20 points.
//!
//! The tests at 2^16 and 2^20 take seconds each, so they run in release
//! builds only: `.ci/run`'s release step runs them by the `at_2_16_and_2_20`
//! filter and fails if one of them did not run.

use wellspread::glam::Vec2;
use wellspread::metrics::{centered_l2_discrepancy, l2_star_discrepancy, star_discrepancy};
use wellspread::{Sampler2D, Sobol};

use crate::common::{assert_close, hammersley, random_points};
use crate::exact::{centered_l2_squared, l2_star_squared};

/// The textbook Hammersley set of `2^m` points, `(i / N, φ_2(i))` with `φ_2`
/// the base-2 radical inverse (`common::hammersley`), the convention of both
/// closed forms below (checked in exact rationals for m = 1..=7). The
/// crate's `Hammersley` sampler is a randomised version, so it is not used.
fn textbook_hammersley(m: u32) -> Vec<Vec2> {
    let points = hammersley(m);
    let n = 1u32 << m;
    for (i, p) in (0..n).zip(&points) {
        assert_eq!(f64::from(p.x), f64::from(i) / f64::from(n));
        let radical = (0..m).map(|b| f64::from((i >> b) & 1) / f64::from(2u32 << b));
        assert_eq!(f64::from(p.y), radical.sum::<f64>());
    }
    points
}

/// Halton & Zaremba 1969: `(N T)² = m²/64 + 29m/192 + 3/8 - m/2^(m+4)
/// + 1/2^(m+2) - 1/(72 4^m)` for the 2^m-point Hammersley set.
fn halton_zaremba(m: u32) -> f64 {
    let (mf, n) = (f64::from(m), 2f64.powi(m as i32));
    let nt2 = mf * mf / 64.0 + 29.0 * mf / 192.0 + 3.0 / 8.0 - mf / (16.0 * n) + 1.0 / (4.0 * n)
        - 1.0 / (72.0 * n * n);
    nt2.sqrt() / n
}

/// De Clerck 1986: `N D* = m/3 + 13/9 - (-1)^m 4/(9N)` for m >= 2.
fn de_clerck(m: u32) -> f64 {
    let n = 2f64.powi(m as i32);
    let sign = if m.is_multiple_of(2) { 1.0 } else { -1.0 };
    (f64::from(m) / 3.0 + 13.0 / 9.0 - sign * 4.0 / (9.0 * n)) / n
}

/// The centred `k x k` grid `((2a + 1)/(2k), (2b + 1)/(2k))`, exact in f32
/// for k a power of two up to 2^23.
fn centred_grid(k: u32) -> Vec<Vec2> {
    (0..k * k)
        .map(|i| {
            let c = |a: u32| (2 * a + 1) as f32 / (2 * k) as f32;
            Vec2::new(c(i % k), c(i / k))
        })
        .collect()
}

/// `(T², CD²)` of the centred `k x k` grid, derived in exact rationals.
///
/// Both formulas factor over the axes for a product grid. With
/// `x_a = (2a + 1)/(2k)`: `Σ_a (1 - x_a²) = (8k² + 1)/(12k)` and
/// `Σ_a Σ_b (1 - max(x_a, x_b)) = (2k² + 1)/6`, so
/// `T² = 1/9 - ((8k² + 1)/(12k))²/(2k²) + ((2k² + 1)/6)²/k⁴ = (16k² + 7)/(288k⁴)`.
/// With `u_a = x_a - 1/2`: `Σ u² = (k² - 1)/(12k)`, `Σ |u| = k/4` (k even) or
/// `(k² - 1)/(4k)` (k odd), `Σ_a Σ_b |x_a - x_b| = (k² - 1)/3`, so the
/// single sum per axis is `C = k + Σ|u|/2 - Σu²/2` and the pair sum
/// `D = k² + k Σ|u| - (k² - 1)/6`, and `CD² = (13/12)² - 2 C²/k² + D²/k⁴`:
/// `(52k² + 7)/(288k⁴)` for even k, `(26k² - 1)/(144k⁴)` for odd k.
/// (k = 1: `T² = 23/288` and `CD² = 25/144`, which the one-point formulas
/// give directly.)
fn centred_grid_squared(k: u32) -> (f64, f64) {
    let k2 = f64::from(k) * f64::from(k);
    let t2 = (16.0 * k2 + 7.0) / (288.0 * k2 * k2);
    let cd2 = if k.is_multiple_of(2) {
        (52.0 * k2 + 7.0) / (288.0 * k2 * k2)
    } else {
        (26.0 * k2 - 1.0) / (144.0 * k2 * k2)
    };
    (t2, cd2)
}

fn check_hammersley(m: u32) {
    let points = textbook_hammersley(m);
    let what = format!("Hammersley 2^{m}");
    let t = l2_star_discrepancy(&points).unwrap();
    assert_close(&format!("{what} L2-star"), t, halton_zaremba(m), 1e-12);
    assert_close(
        &format!("{what} exact L2-star"),
        t,
        l2_star_squared(&points).sqrt(),
        1e-12,
    );
    if m >= 2 {
        let d = star_discrepancy(&points).unwrap();
        assert_close(&format!("{what} star"), d, de_clerck(m), 1e-12);
    }
}

fn check_centred_grid(k: u32) {
    let points = centred_grid(k);
    let (t2, cd2) = centred_grid_squared(k);
    let what = format!("centred {k} x {k} grid");
    let t = l2_star_discrepancy(&points).unwrap();
    let cd = centered_l2_discrepancy(&points).unwrap();
    // For k not a power of two the f32 coordinates are rounded (by up to
    // 2^-25), which moves the values by about 1e-8 relative.
    let rel = if k.is_power_of_two() { 1e-12 } else { 1e-6 };
    assert_close(&format!("{what} L2-star"), t, t2.sqrt(), rel);
    assert_close(&format!("{what} centred L2"), cd, cd2.sqrt(), rel);
    let exact = (l2_star_squared(&points), centered_l2_squared(&points));
    assert_close(&format!("{what} exact L2-star"), exact.0, t2, rel);
    assert_close(&format!("{what} exact CD"), exact.1, cd2, rel);
    check_exact(&what, &points);
}

/// Both L2 forms against the exact integer evaluation of the same f32 points.
fn check_exact(what: &str, points: &[Vec2]) {
    assert_close(
        &format!("{what}: L2-star"),
        l2_star_discrepancy(points).unwrap(),
        l2_star_squared(points).sqrt(),
        1e-12,
    );
    assert_close(
        &format!("{what}: centred L2"),
        centered_l2_discrepancy(points).unwrap(),
        centered_l2_squared(points).sqrt(),
        1e-12,
    );
}

/// Sets whose discrepancy is small (so cancellation is at its worst) or
/// structured: a Sobol' net, a rank-1 (Fibonacci) lattice, uniform points,
/// a grid with every point doubled, a set with n not a power of two.
fn exact_families(m: u32) -> Vec<(String, Vec<Vec2>)> {
    let n = 1usize << m;
    let sobol = Sobol::new(n as u32).unwrap();
    let mut scrambled = vec![Vec2::ZERO; n];
    sobol.fill(7, &mut scrambled);
    // Rank-1 lattice (i/n, {i g / n}) with g the Fibonacci-like generator
    // nearest n / golden ratio, odd so that it is coprime to n.
    let g = ((n as f64 / 1.618_033_988_749_895) as u64) | 1;
    let lattice: Vec<Vec2> = (0..n as u64)
        .map(|i| Vec2::new(i as f32 / n as f32, ((i * g) % n as u64) as f32 / n as f32))
        .collect();
    let mut doubled = centred_grid(1 << (m / 2));
    doubled.extend(doubled.clone());
    vec![
        (format!("Sobol' 2^{m}"), scrambled),
        (format!("lattice 2^{m}"), lattice),
        (format!("uniform 2^{m}"), random_points(n, u64::from(m))),
        (format!("doubled grid 2^{m}"), doubled),
        (format!("uniform 2^{m} + 3"), random_points(n + 3, 99)),
    ]
}

#[test]
fn closed_forms_up_to_2_12() {
    for m in 0..=12 {
        check_hammersley(m);
    }
    for k in [1, 2, 3, 4, 5, 7, 32, 64] {
        check_centred_grid(k);
    }
}

#[test]
#[cfg_attr(debug_assertions, ignore = "release only (.ci/run): seconds per set")]
fn closed_forms_at_2_16_and_2_20() {
    for m in [16, 20] {
        check_hammersley(m);
    }
    for k in [256, 1024] {
        check_centred_grid(k);
    }
}

#[test]
fn l2_forms_are_exact_on_f32_inputs_up_to_2_12() {
    for m in [0, 1, 5, 10, 12] {
        for (what, points) in exact_families(m) {
            check_exact(&what, &points);
        }
    }
}

#[test]
#[cfg_attr(debug_assertions, ignore = "release only (.ci/run): seconds per set")]
fn l2_forms_are_exact_on_f32_inputs_at_2_16_and_2_20() {
    for m in [16, 20] {
        for (what, points) in exact_families(m) {
            check_exact(&what, &points);
        }
    }
}

#[test]
fn coordinates_below_the_2_32_grid_are_exact_too() {
    // Coordinates far below 2^-32 (subnormals included): each moves T² and
    // CD² by at most 2 t / n from the same set with that coordinate at 0
    // (below 1e-26 in all, against T² near 1e-7), which the integer form
    // evaluates exactly; the double-double code must agree to 1e-12.
    let tiny = [f32::from_bits(1), 1e-38, 1e-30, 3e-25];
    let base = textbook_hammersley(12);
    let mut perturbed = base.clone();
    let mut zeroed = base;
    for (k, p) in perturbed.iter_mut().enumerate().step_by(97) {
        let t = tiny[k % tiny.len()];
        if p.x == 0.0 || k.is_multiple_of(2) {
            p.x = t;
            zeroed[k].x = 0.0;
        } else {
            p.y = t;
            zeroed[k].y = 0.0;
        }
    }
    assert_close(
        "tiny L2-star",
        l2_star_discrepancy(&perturbed).unwrap(),
        l2_star_squared(&zeroed).sqrt(),
        1e-12,
    );
    assert_close(
        "tiny centred L2",
        centered_l2_discrepancy(&perturbed).unwrap(),
        centered_l2_squared(&zeroed).sqrt(),
        1e-12,
    );
}
