//! L2-star and centred L2 discrepancy against the direct O(n^2) formulas
//! and numerical integration of their definitions.

use proptest::prelude::*;
use wellspread::glam::Vec2;
use wellspread::metrics::{centered_l2_discrepancy, l2_star_discrepancy};

use crate::common::{
    GRID, Sum, assert_close, close, dyadic_points, hammersley, random_points, unit_points,
};

/// The textbook O(n^2) formulas, squared values.
fn direct_l2_star_sq(p: &[Vec2]) -> f64 {
    let n = p.len() as f64;
    let (mut single, mut pairs) = (Sum::default(), Sum::default());
    for a in p {
        let (x, y) = (f64::from(a.x), f64::from(a.y));
        single.add((1.0 - x * x) * (1.0 - y * y));
        for b in p {
            let (u, v) = (f64::from(b.x), f64::from(b.y));
            pairs.add((1.0 - x.max(u)) * (1.0 - y.max(v)));
        }
    }
    1.0 / 9.0 - single.get() / (2.0 * n) + pairs.get() / (n * n)
}

fn direct_centered_sq(p: &[Vec2]) -> f64 {
    let n = p.len() as f64;
    let (mut single, mut pairs) = (Sum::default(), Sum::default());
    for a in p {
        let (x, y) = (f64::from(a.x), f64::from(a.y));
        let f = |t: f64| 1.0 + 0.5 * (t - 0.5).abs() - 0.5 * (t - 0.5) * (t - 0.5);
        single.add(f(x) * f(y));
        for b in p {
            let (u, v) = (f64::from(b.x), f64::from(b.y));
            let g = |s: f64, t: f64| {
                1.0 + 0.5 * (s - 0.5).abs() + 0.5 * (t - 0.5).abs() - 0.5 * (s - t).abs()
            };
            pairs.add(g(x, u) * g(y, v) - 1.0);
        }
    }
    let mut t = Sum::default();
    t.add((13.0f64 / 12.0).powi(2));
    t.add(-2.0 * single.get() / n);
    t.add(1.0);
    t.add(pairs.get() / (n * n));
    t.get()
}

/// `∫ over a cell [a0, a1] of ℓ and of ℓ²` for ℓ linear.
fn moments(l0: f64, l1: f64, h: f64) -> (f64, f64) {
    (h * (l0 + l1) / 2.0, h * (l0 * l0 + l0 * l1 + l1 * l1) / 3.0)
}

/// `Σ over non-empty u of ∫ (vol(J_u) - count/n)²` where, per axis, the
/// interval at `a` is `interval(a)` (as a half-open range) with length linear
/// in `a` on each grid cell. With `full_only`, only u = {1, 2}.
fn integrate_local_discrepancy(
    points: &[Vec2],
    interval: impl Fn(f64) -> (f64, f64),
    full_only: bool,
) -> f64 {
    let n = points.len() as f64;
    let h = 1.0 / GRID as f64;
    let inside = |v: f32, a: f64| {
        let (lo, hi) = interval(a);
        (lo..hi).contains(&f64::from(v))
    };
    let len = |a: f64| {
        let (lo, hi) = interval(a);
        hi - lo
    };
    // Per cell: the length at both ends (limits from inside) and the
    // membership at the cell's midpoint.
    let cell = |k: usize| {
        let (a0, a1) = (k as f64 * h, (k + 1) as f64 * h);
        let mid = (a0 + a1) / 2.0;
        // The length is linear inside the cell; evaluate it at interior points.
        let (e0, e1) = (a0 + h * 1e-9, a1 - h * 1e-9);
        let slope = (len(e1) - len(e0)) / (e1 - e0);
        let l0 = len(mid) - slope * h / 2.0;
        let l1 = len(mid) + slope * h / 2.0;
        (moments(l0, l1, h), mid)
    };
    let mut total = 0.0;
    // 2D term.
    for i in 0..GRID {
        let ((i1a, i2a), ma) = cell(i);
        for j in 0..GRID {
            let ((i1b, i2b), mb) = cell(j);
            let c = points
                .iter()
                .filter(|p| inside(p.x, ma) && inside(p.y, mb))
                .count() as f64
                / n;
            total += i2a * i2b - 2.0 * c * i1a * i1b + c * c * h * h;
        }
    }
    if !full_only {
        for axis in 0..2 {
            for i in 0..GRID {
                let ((i1, i2), ma) = cell(i);
                let c = points
                    .iter()
                    .filter(|p| inside(if axis == 0 { p.x } else { p.y }, ma))
                    .count() as f64
                    / n;
                total += i2 - 2.0 * c * i1 + c * c * h;
            }
        }
    }
    total
}

#[test]
fn l2_forms_match_numerical_integration() {
    for (n, seed) in [(1, 10), (2, 11), (5, 12), (9, 13)] {
        let points = dyadic_points(n, seed);
        let star = integrate_local_discrepancy(&points, |a| (0.0, a), true);
        assert_close(
            "L2-star",
            l2_star_discrepancy(&points).unwrap(),
            star.sqrt(),
            1e-12,
        );
        let centred = integrate_local_discrepancy(
            &points,
            |a| if a < 0.5 { (0.0, a) } else { (a, 1.0) },
            false,
        );
        assert_close(
            "centred",
            centered_l2_discrepancy(&points).unwrap(),
            centred.sqrt(),
            1e-12,
        );
    }
}

#[test]
fn l2_forms_match_direct_formulas_at_4096() {
    for points in [random_points(4096, 7), hammersley(12)] {
        assert_close(
            "L2-star",
            l2_star_discrepancy(&points).unwrap(),
            direct_l2_star_sq(&points).sqrt(),
            1e-9,
        );
        assert_close(
            "centred",
            centered_l2_discrepancy(&points).unwrap(),
            direct_centered_sq(&points).sqrt(),
            1e-9,
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn l2_forms_match_direct_formulas(points in unit_points(64)) {
        let pairs = [
            (l2_star_discrepancy(&points).unwrap(), direct_l2_star_sq(&points)),
            (centered_l2_discrepancy(&points).unwrap(), direct_centered_sq(&points)),
        ];
        for (got, want_sq) in pairs {
            prop_assert!(close(got, want_sq.sqrt(), 1e-12), "got {got}, want {}", want_sq.sqrt());
        }
    }
}
