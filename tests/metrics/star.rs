//! Star discrepancy against an O(n^3) brute force and closed forms.

use proptest::prelude::*;
use wellspread::glam::Vec2;
use wellspread::metrics::star_discrepancy;

use crate::common::{assert_close, close, hammersley, random_points, unit_points};

/// O(n^3) star discrepancy over every critical box, written independently of
/// the library: open boxes with edges on coordinates or 1, closed boxes with
/// edges on coordinates.
fn brute_star(points: &[Vec2]) -> f64 {
    let n = points.len() as f64;
    let xs: Vec<f64> = points.iter().map(|p| f64::from(p.x)).collect();
    let ys: Vec<f64> = points.iter().map(|p| f64::from(p.y)).collect();
    let mut best: f64 = 0.0;
    let edges_x: Vec<f64> = xs.iter().copied().chain([1.0]).collect();
    let edges_y: Vec<f64> = ys.iter().copied().chain([1.0]).collect();
    for &a in &edges_x {
        for &b in &edges_y {
            let open = xs
                .iter()
                .zip(&ys)
                .filter(|&(&x, &y)| x < a && y < b)
                .count();
            best = best.max(a * b - open as f64 / n);
            let closed = xs
                .iter()
                .zip(&ys)
                .filter(|&(&x, &y)| x <= a && y <= b)
                .count();
            best = best.max(closed as f64 / n - a * b);
        }
    }
    best
}

#[test]
fn star_one_point() {
    for (x, y) in [
        (0.5, 0.25),
        (0.0, 0.0),
        (0.999, 0.001),
        (0.3, 0.7),
        (0.75, 0.75),
    ] {
        let want = (1.0 - f64::from(x) * f64::from(y))
            .max(f64::from(x))
            .max(f64::from(y));
        let got = star_discrepancy(&[Vec2::new(x, y)]).unwrap();
        assert_close("one point", got, want, 1e-12);
    }
}

#[test]
fn star_centred_and_corner_grids() {
    for m in [1u32, 2, 4, 8, 16, 32] {
        for k in [1u32, 2, 4, 8, 64] {
            let centred: Vec<Vec2> = (0..m * k)
                .map(|i| {
                    Vec2::new(
                        ((i % m) as f32 + 0.5) / m as f32,
                        ((i / m) as f32 + 0.5) / k as f32,
                    )
                })
                .collect();
            let (mf, kf) = (f64::from(m), f64::from(k));
            let want = 1.0 / (2.0 * mf) + 1.0 / (2.0 * kf) - 1.0 / (4.0 * mf * kf);
            assert_close(
                "centred grid",
                star_discrepancy(&centred).unwrap(),
                want,
                1e-12,
            );
        }
        let corner: Vec<Vec2> = (0..m * m)
            .map(|i| Vec2::new((i % m) as f32 / m as f32, (i / m) as f32 / m as f32))
            .collect();
        let mf = f64::from(m);
        let want = (2.0 * mf - 1.0) / (mf * mf);
        assert_close(
            "corner grid",
            star_discrepancy(&corner).unwrap(),
            want,
            1e-12,
        );
    }
    // A grid whose f32 coordinates are rounded: close to the closed form.
    let (m, k) = (7u32, 5u32);
    let centred: Vec<Vec2> = (0..m * k)
        .map(|i| {
            Vec2::new(
                ((i % m) as f32 + 0.5) / m as f32,
                ((i / m) as f32 + 0.5) / k as f32,
            )
        })
        .collect();
    let want = 1.0 / 14.0 + 1.0 / 10.0 - 1.0 / 140.0;
    assert_close(
        "7 x 5 grid",
        star_discrepancy(&centred).unwrap(),
        want,
        1e-6,
    );
    assert_close(
        "7 x 5 grid brute",
        star_discrepancy(&centred).unwrap(),
        brute_star(&centred),
        1e-12,
    );
}

#[test]
fn star_hammersley_closed_form() {
    for m in 2..=14 {
        let points = hammersley(m);
        let n = f64::from(1u32 << m);
        let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
        let want = (f64::from(m) / 3.0 + 13.0 / 9.0 - 4.0 * sign / (9.0 * n)) / n;
        assert_close(
            &format!("Hammersley m = {m}"),
            star_discrepancy(&points).unwrap(),
            want,
            1e-12,
        );
    }
}

#[test]
fn star_matches_brute_force_on_structured_sets() {
    // Many repeated coordinates, points on 0, and the 24-bit edge below 1.
    let top = f32::from_bits(0x3f7f_ffff);
    let sets: Vec<Vec<Vec2>> = vec![
        vec![Vec2::ZERO; 5],
        vec![Vec2::new(top, top); 3],
        vec![Vec2::new(0.0, top), Vec2::new(top, 0.0)],
        (0..40)
            .map(|i| Vec2::new((i % 3) as f32 / 3.0, (i % 7) as f32 / 7.0))
            .collect(),
        (0..33).map(|i| Vec2::new(0.5, (i as f32) / 33.0)).collect(),
        (0..33)
            .map(|i| Vec2::new((i as f32) / 33.0, 0.25))
            .collect(),
        (0..50)
            .map(|i| Vec2::new(i as f32 / 50.0, i as f32 / 50.0))
            .collect(),
        (0..50)
            .map(|i| Vec2::new(i as f32 / 50.0, (49 - i) as f32 / 50.0))
            .collect(),
    ];
    for points in &sets {
        assert_close(
            "structured",
            star_discrepancy(points).unwrap(),
            brute_star(points),
            1e-12,
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn star_matches_brute_force(points in unit_points(64)) {
        let got = star_discrepancy(&points).unwrap();
        let want = brute_star(&points);
        prop_assert!(close(got, want, 1e-12), "got {got}, want {want}");
    }
}

#[test]
fn star_random_sets_match_brute_force_at_moderate_n() {
    for (n, seed) in [(200, 1), (257, 2), (300, 3)] {
        let points = random_points(n, seed);
        assert_close(
            "random",
            star_discrepancy(&points).unwrap(),
            brute_star(&points),
            1e-12,
        );
    }
}
