//! Minimum distances (plain and toroidal) against brute force, on seams,
//! grids and crowded sets.

use proptest::prelude::*;
use wellspread::glam::Vec2;
use wellspread::metrics::{min_distance, normalized_toroidal_min_distance, toroidal_min_distance};

use crate::common::{Mix, assert_close, random_points, unit_points};

fn brute_min_distance(points: &[Vec2], torus: bool) -> f64 {
    let mut best = f64::INFINITY;
    for i in 0..points.len() {
        for j in i + 1..points.len() {
            let mut dx = (f64::from(points[i].x) - f64::from(points[j].x)).abs();
            let mut dy = (f64::from(points[i].y) - f64::from(points[j].y)).abs();
            if torus {
                dx = dx.min(1.0 - dx);
                dy = dy.min(1.0 - dy);
            }
            best = best.min(dx * dx + dy * dy);
        }
    }
    best.sqrt()
}

#[test]
fn min_distances_match_brute_force_on_seams_and_grids() {
    let mut sets: Vec<Vec<Vec2>> = vec![
        random_points(2000, 21),
        random_points(3, 22),
        // Clustered along the seams: the closest pairs wrap around.
        (0..300)
            .map(|i| {
                let t = i as f32 / 300.0;
                if i % 2 == 0 {
                    Vec2::new(0.001 * t, t)
                } else {
                    Vec2::new(0.9995 - 0.001 * t, t + 0.0001)
                }
            })
            .collect(),
        // A regular grid: every distance is the same, wider than a cell.
        (0..256)
            .map(|i| Vec2::new((i % 16) as f32 / 16.0, (i / 16) as f32 / 16.0))
            .collect(),
        // A hexagonal-ish lattice.
        (0..300)
            .map(|i| {
                let (r, c) = (i / 20, i % 20);
                Vec2::new((c as f32 + 0.5 * (r % 2) as f32) / 20.0, r as f32 / 15.0)
            })
            .collect(),
        // Far apart: two points, and a corner pair.
        vec![Vec2::new(0.0, 0.0), Vec2::new(0.9, 0.9)],
        vec![
            Vec2::new(0.02, 0.98),
            Vec2::new(0.97, 0.01),
            Vec2::new(0.5, 0.5),
        ],
    ];
    // Clusters and degenerate boxes: a tiny cluster (bounding-box grid), one
    // column, one row, identical points, and a cluster straddling the corner.
    let tiny: Vec<Vec2> = random_points(2000, 24)
        .iter()
        .map(|p| Vec2::new(0.3 + p.x * 1e-4, 0.6 + p.y * 1e-4))
        .collect();
    sets.push(tiny);
    sets.push(
        random_points(500, 25)
            .iter()
            .map(|p| Vec2::new(0.25, p.y))
            .collect(),
    );
    sets.push(
        random_points(500, 26)
            .iter()
            .map(|p| Vec2::new(p.x, 0.75))
            .collect(),
    );
    sets.push(vec![Vec2::new(0.5, 0.5); 50]);
    sets.push(
        random_points(800, 27)
            .iter()
            .map(|p| Vec2::new((p.x * 0.02 + 0.99) % 1.0, (p.y * 0.02 + 0.99) % 1.0))
            .collect(),
    );
    // A narrow vertical strip: x is not wrapped, y is (pairs across y = 0).
    sets.push(
        random_points(3000, 31)
            .iter()
            .map(|p| Vec2::new(0.2 + p.x * 1e-3, p.y))
            .collect(),
    );
    // Half spread out, half in a strip: non-square cells.
    let mut strip = random_points(400, 28);
    strip.extend(
        random_points(400, 29)
            .iter()
            .map(|p| Vec2::new(p.x, 0.5 + p.y * 0.001)),
    );
    sets.push(strip);
    // Duplicates.
    let mut dup = random_points(100, 23);
    dup.push(dup[17]);
    sets.push(dup);
    for points in &sets {
        assert_eq!(
            min_distance(points).unwrap(),
            brute_min_distance(points, false)
        );
        assert_eq!(
            toroidal_min_distance(points).unwrap(),
            brute_min_distance(points, true)
        );
    }
}

#[test]
fn normalized_toroidal_min_distance_of_a_grid() {
    let grid: Vec<Vec2> = (0..1024)
        .map(|i| Vec2::new((i % 32) as f32 / 32.0, (i / 32) as f32 / 32.0))
        .collect();
    let want = (1.0 / 32.0) / (2.0 / (3.0f64.sqrt() * 1024.0)).sqrt();
    assert_close(
        "normalised",
        normalized_toroidal_min_distance(&grid).unwrap(),
        want,
        1e-12,
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn min_distances_match_brute_force(points in unit_points(80)) {
        prop_assume!(points.len() >= 2);
        let want = brute_min_distance(&points, false);
        prop_assert_eq!(min_distance(&points).unwrap(), want);
        let want = brute_min_distance(&points, true);
        prop_assert_eq!(toroidal_min_distance(&points).unwrap(), want);
    }
}

/// Sets that put many points in few cells of a bounding-box grid: the
/// diagonal, dense lattice blobs (also across the seams), a line of random
/// points, a cluster inside a spread-out set.
fn crowded_families() -> Vec<(&'static str, Vec<Vec2>)> {
    let mut rng = Mix(61);
    let n = 3000;
    let diagonal: Vec<Vec2> = (0..n).map(|i| Vec2::splat(i as f32 / n as f32)).collect();
    let anti: Vec<Vec2> = (0..n)
        .map(|i| Vec2::new(i as f32 / n as f32, 1.0 - (i + 1) as f32 / n as f32))
        .collect();
    let spacing = 1.0 / (1u32 << 17) as f32;
    let blob = |ox: f32, oy: f32, side: usize| -> Vec<Vec2> {
        (0..side * side)
            .map(|i| {
                let x = ox + (i % side) as f32 * spacing;
                let y = oy + (i / side) as f32 * spacing;
                Vec2::new(x % 1.0, y % 1.0)
            })
            .collect()
    };
    let mut blobs = blob(0.25, 0.25, 40);
    blobs.extend(blob(0.75, 0.75, 40));
    // Across the corner of the torus: the blob wraps around both seams.
    let mut corner = blob(1.0 - 20.5 * spacing, 1.0 - 20.5 * spacing, 40);
    corner.extend(blob(0.5, 0.5, 30));
    let line: Vec<Vec2> = (0..n)
        .map(|_| {
            let t = rng.unit();
            Vec2::new(t, (0.3 + 0.4 * t).min(0.999))
        })
        .collect();
    let mut cluster = random_points(2000, 62);
    cluster.extend((0..2000).map(|_| Vec2::new(0.5 + rng.unit() * 1e-5, 0.5 + rng.unit() * 1e-5)));
    // Two far clusters hugging opposite seams: close only on the torus.
    let seams: Vec<Vec2> = (0..n)
        .map(|i| {
            let t = rng.unit() * 1e-3;
            if i % 2 == 0 {
                Vec2::new(t, 0.5 + t)
            } else {
                Vec2::new(1.0 - spacing - t, 0.5 + t * 0.5)
            }
        })
        .collect();
    vec![
        ("diagonal", diagonal),
        ("anti-diagonal", anti),
        ("two blobs", blobs),
        ("corner blob", corner),
        ("line", line),
        ("cluster", cluster),
        ("seams", seams),
    ]
}

#[test]
fn min_distances_match_brute_force_on_crowded_sets() {
    for (name, points) in crowded_families() {
        assert_eq!(
            min_distance(&points).unwrap(),
            brute_min_distance(&points, false),
            "{name}"
        );
        assert_eq!(
            toroidal_min_distance(&points).unwrap(),
            brute_min_distance(&points, true),
            "{name}, torus"
        );
    }
}

/// Sets of up to 300 points crowded onto a line, a few cells or a corner.
fn crowded_points() -> impl Strategy<Value = Vec<Vec2>> {
    let shape = 0u32..4;
    let ts = prop::collection::vec((0u32..1 << 24, 0u32..1 << 24), 2..300);
    (shape, ts).prop_map(|(shape, ts)| {
        ts.iter()
            .map(|&(a, b)| {
                let (u, v) = (
                    a as f32 / (1u32 << 24) as f32,
                    b as f32 / (1u32 << 24) as f32,
                );
                match shape {
                    0 => Vec2::new(u, u),
                    1 => Vec2::new(u, (u * 0.5 + v * 1e-6).min(0.999)),
                    2 => Vec2::new((0.999 + u * 1e-3) % 1.0, (0.999 + v * 1e-3) % 1.0),
                    _ => Vec2::new((a % 3) as f32 / 3.0 + v * 1e-4, (b % 2) as f32 / 2.0),
                }
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn min_distances_on_crowded_sets_match_brute_force(points in crowded_points()) {
        prop_assert_eq!(min_distance(&points).unwrap(), brute_min_distance(&points, false));
        prop_assert_eq!(toroidal_min_distance(&points).unwrap(), brute_min_distance(&points, true));
    }
}
