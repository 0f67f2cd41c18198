//! Wrap-around L2 discrepancy: the O(n log n) code against the direct
//! double sum, exact arithmetic and numerical integration.

use proptest::prelude::*;
use wellspread::glam::Vec2;
use wellspread::metrics::wraparound_l2_discrepancy;
use wellspread::{Pmj02, Sampler2D, Sobol};

use crate::common::{
    GRID, Mix, Sum, assert_close, close, dyadic_points, hammersley, random_points, unit_points,
};

fn direct_wraparound_sq(p: &[Vec2]) -> f64 {
    let n = p.len() as f64;
    let mut pairs = Sum::default();
    for a in p {
        for b in p {
            let f = |s: f32, t: f32| {
                let d = (f64::from(s) - f64::from(t)).abs();
                1.5 - d * (1.0 - d)
            };
            pairs.add(f(a.x, b.x) * f(a.y, b.y) - 16.0 / 9.0);
        }
    }
    pairs.get() / (n * n)
}

/// Wrap-around: for each axis, intervals J(s, t) = [s, t) or [s, 1) ∪ [0, t),
/// integrated over (s, t) in [0, 1]² by a grid aligned with the points'
/// coordinates (centroid rule on the two triangles of each diagonal cell),
/// exact for the piecewise linear integrands.
fn integrate_wraparound(points: &[Vec2]) -> f64 {
    let n = points.len();
    let m = 4 * GRID; // cell edges on every point coordinate
    let h = 1.0 / m as f64;
    // For each axis: Σ w, Σ w L², Σ w L 1_i, Σ w 1_i 1_j over quadrature nodes.
    struct Axis {
        l2: f64,
        l1: Vec<f64>,
        ii: Vec<f64>,
    }
    let axis = |coords: Vec<f64>| {
        // The length of J(s, t) is uniform on [0, 1], so ∫ L² = 1/3; the
        // other integrands are linear on each region and the rule is exact.
        let mut a = Axis {
            l2: 1.0 / 3.0,
            l1: vec![0.0; n],
            ii: vec![0.0; n * n],
        };
        let mut node = |s: f64, t: f64, w: f64| {
            let (len, member): (f64, Vec<bool>) = if s <= t {
                (t - s, coords.iter().map(|&v| s <= v && v < t).collect())
            } else {
                (
                    1.0 - s + t,
                    coords.iter().map(|&v| v >= s || v < t).collect(),
                )
            };
            for (i, &in_i) in member.iter().enumerate() {
                if in_i {
                    a.l1[i] += w * len;
                    for (j, &in_j) in member.iter().enumerate() {
                        if in_j {
                            a.ii[i * n + j] += w;
                        }
                    }
                }
            }
        };
        for i in 0..m {
            for j in 0..m {
                let (s0, t0) = (i as f64 * h, j as f64 * h);
                if i == j {
                    node(s0 + h / 3.0, t0 + 2.0 * h / 3.0, h * h / 2.0);
                    node(s0 + 2.0 * h / 3.0, t0 + h / 3.0, h * h / 2.0);
                } else {
                    node(s0 + h / 2.0, t0 + h / 2.0, h * h);
                }
            }
        }
        a
    };
    let ax = axis(points.iter().map(|p| f64::from(p.x)).collect());
    let ay = axis(points.iter().map(|p| f64::from(p.y)).collect());
    let nf = n as f64;
    let mut total = 0.0;
    // u = {x}, u = {y}: ∫ (L - c/n)², c = Σ_i 1_i.
    for a in [&ax, &ay] {
        let cross: f64 = a.l1.iter().sum();
        let count2: f64 = a.ii.iter().sum();
        total += a.l2 - 2.0 * cross / nf + count2 / (nf * nf);
    }
    // u = {x, y}: ∫ (Lx Ly - c/n)², c = Σ_i 1x_i 1y_i.
    let cross: f64 = (0..n).map(|i| ax.l1[i] * ay.l1[i]).sum();
    let count2: f64 = (0..n * n).map(|k| ax.ii[k] * ay.ii[k]).sum();
    total += ax.l2 * ay.l2 - 2.0 * cross / nf + count2 / (nf * nf);
    total
}

#[test]
fn wraparound_matches_numerical_integration() {
    for (n, seed) in [(1, 10), (2, 11), (5, 12), (9, 13)] {
        let points = dyadic_points(n, seed);
        let wrap = integrate_wraparound(&points);
        assert_close(
            "wrap-around",
            wraparound_l2_discrepancy(&points).unwrap(),
            wrap.sqrt(),
            1e-10,
        );
    }
}

#[test]
fn wraparound_matches_the_direct_formula_at_4096() {
    for points in [random_points(4096, 7), hammersley(12)] {
        assert_close(
            "wrap-around",
            wraparound_l2_discrepancy(&points).unwrap(),
            direct_wraparound_sq(&points).sqrt(),
            1e-9,
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn wraparound_matches_the_direct_formula(points in unit_points(64)) {
        let got = wraparound_l2_discrepancy(&points).unwrap();
        let want = direct_wraparound_sq(&points).sqrt();
        prop_assert!(close(got, want, 1e-12), "got {got}, want {want}");
    }
}

/// The families the O(n log n) wrap-around code must agree on with the
/// direct double sum: random, lattices, duplicates, ties, clusters, nets.
fn wraparound_families(n: usize) -> Vec<(&'static str, Vec<Vec2>)> {
    let nf = n as f32;
    let mut rng = Mix(n as u64);
    // Rank-1 lattice with a golden-ratio generator.
    let g = ((n as f64) * 0.618_033_988_749_895).round() as usize | 1;
    let lattice: Vec<Vec2> = (0..n)
        .map(|i| Vec2::new(i as f32 / nf, ((i * g) % n) as f32 / nf))
        .collect();
    let side = (n as f64).sqrt().ceil() as usize;
    let grid: Vec<Vec2> = (0..n)
        .map(|i| {
            Vec2::new(
                (i % side) as f32 / side as f32,
                (i / side) as f32 / side as f32,
            )
        })
        .collect();
    let few: Vec<Vec2> = (0..n)
        .map(|_| Vec2::new((rng.next() % 5) as f32 / 5.0, (rng.next() % 3) as f32 / 3.0))
        .collect();
    let mut duplicated = random_points(n.div_ceil(4), 77);
    duplicated = duplicated.iter().cycle().take(n).copied().collect();
    let cluster: Vec<Vec2> = (0..n)
        .map(|_| Vec2::new(0.7 + rng.unit() * 1e-4, 0.2 + rng.unit() * 1e-4))
        .collect();
    let tiny: Vec<Vec2> = (0..n)
        .map(|_| {
            Vec2::new(
                rng.unit() * 1e-30,
                f32::from_bits((rng.next() % 0x3f80_0000) as u32),
            )
        })
        .collect();
    let two_blobs: Vec<Vec2> = (0..n)
        .map(|i| {
            let o = if i % 2 == 0 { 0.1 } else { 0.85 };
            Vec2::new(o + rng.unit() * 0.01, o + rng.unit() * 0.01)
        })
        .collect();
    let mut sobol = vec![Vec2::ZERO; n];
    Sobol::new(n as u32).unwrap().fill(9, &mut sobol);
    let mut pmj = vec![Vec2::ZERO; n];
    Pmj02::new(n as u32).unwrap().fill(9, &mut pmj);
    let diagonal: Vec<Vec2> = (0..n).map(|i| Vec2::splat(i as f32 / nf)).collect();
    vec![
        ("random", random_points(n, 12)),
        ("lattice", lattice),
        ("grid", grid),
        ("few values", few),
        ("duplicated", duplicated),
        ("one point repeated", vec![Vec2::new(0.3, 0.8); n]),
        ("cluster", cluster),
        ("tiny and any f32", tiny),
        ("two blobs", two_blobs),
        ("sobol", sobol),
        ("pmj02", pmj),
        ("diagonal", diagonal),
    ]
}

#[test]
fn wraparound_of_a_lattice_matches_exact_arithmetic() {
    // The rank-1 lattice of `wraparound_families(4096)`: coordinates are
    // multiples of 2^-12, so n² WD² + 16/9 n² is an integer over 2^50, summed
    // exactly with Python integers (Fraction) to WD = 2.551246374788195e-4.
    let (name, lattice) = wraparound_families(4096).swap_remove(1);
    assert_eq!(name, "lattice");
    assert_close(
        "lattice",
        wraparound_l2_discrepancy(&lattice).unwrap(),
        2.551246374788195e-4,
        4e-16,
    );
}
