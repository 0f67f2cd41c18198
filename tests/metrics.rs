//! Metrics against independent brute force, closed forms and numerical
//! integration, and against hostile input.

use proptest::prelude::*;
use wellspread::glam::Vec2;
use wellspread::metrics::{
    Error, MAX_SPECTRUM_FREQUENCY, centered_l2_discrepancy, is_latin, is_net_base2, is_stratified,
    l2_star_discrepancy, min_distance, net_t_value, normalized_toroidal_min_distance,
    radial_power_spectrum, star_discrepancy, toroidal_min_distance, wraparound_l2_discrepancy,
    wraparound_l2_discrepancy_quadratic,
};
use wellspread::{Pmj02, Sampler2D, Sobol};

// ---------------------------------------------------------------- helpers

fn close(got: f64, want: f64, rel: f64) -> bool {
    (got - want).abs() <= rel * want.abs().max(1e-300)
}

fn assert_close(what: &str, got: f64, want: f64, rel: f64) {
    assert!(
        close(got, want, rel),
        "{what}: got {got:e}, want {want:e} (rel. diff {:e})",
        (got - want).abs() / want.abs()
    );
}

/// A small deterministic generator (SplitMix64), so tests need no RNG crate.
struct Mix(u64);
impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform on the 24-bit grid in [0, 1).
    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u32 << 24) as f32
    }
}

fn random_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Mix(seed);
    (0..n).map(|_| Vec2::new(rng.unit(), rng.unit())).collect()
}

fn hammersley(m: u32) -> Vec<Vec2> {
    let n = 1u32 << m;
    (0..n)
        .map(|i| {
            let y = if m == 0 {
                0
            } else {
                i.reverse_bits() >> (32 - m)
            };
            Vec2::new(i as f32 / n as f32, y as f32 / n as f32)
        })
        .collect()
}

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

/// Neumaier sum, for the O(n^2) reference formulas.
#[derive(Default)]
struct Sum(f64, f64);
impl Sum {
    fn add(&mut self, v: f64) {
        let t = self.0 + v;
        self.1 += if self.0.abs() >= v.abs() {
            (self.0 - t) + v
        } else {
            (v - t) + self.0
        };
        self.0 = t;
    }
    fn get(&self) -> f64 {
        self.0 + self.1
    }
}

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

// ------------------------------------------- numerical integration (squared)

/// Cell boundaries of a 1/16 grid; test points lie on it, so counts are
/// constant inside every cell and the polynomial parts integrate exactly.
const GRID: usize = 16;

fn dyadic_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Mix(seed);
    (0..n)
        .map(|_| {
            let x = (rng.next() % GRID as u64) as f32 / GRID as f32;
            let y = (rng.next() % GRID as u64) as f32 / GRID as f32;
            Vec2::new(x, y)
        })
        .collect()
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

// ------------------------------------------------------- star discrepancy

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

fn unit_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        // Anywhere on the 24-bit grid.
        (0u32..1 << 24).prop_map(|i| i as f32 / (1u32 << 24) as f32),
        // Few distinct values, so x and y repeat.
        (0u32..6).prop_map(|i| i as f32 / 6.0),
        // Any f32 in [0, 1), subnormals included.
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
    ]
}

fn unit_points(max: usize) -> impl Strategy<Value = Vec<Vec2>> {
    prop::collection::vec(
        (unit_f32(), unit_f32()).prop_map(|(x, y)| Vec2::new(x, y)),
        1..=max,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn star_matches_brute_force(points in unit_points(64)) {
        let got = star_discrepancy(&points).unwrap();
        let want = brute_star(&points);
        prop_assert!(close(got, want, 1e-12), "got {got}, want {want}");
    }

    #[test]
    fn min_distances_match_brute_force(points in unit_points(80)) {
        prop_assume!(points.len() >= 2);
        let want = brute_min_distance(&points, false);
        prop_assert_eq!(min_distance(&points).unwrap(), want);
        let want = brute_min_distance(&points, true);
        prop_assert_eq!(toroidal_min_distance(&points).unwrap(), want);
    }

    #[test]
    fn l2_forms_match_direct_formulas(points in unit_points(64)) {
        let pairs = [
            (l2_star_discrepancy(&points).unwrap(), direct_l2_star_sq(&points)),
            (centered_l2_discrepancy(&points).unwrap(), direct_centered_sq(&points)),
            (wraparound_l2_discrepancy(&points).unwrap(), direct_wraparound_sq(&points)),
        ];
        for (got, want_sq) in pairs {
            prop_assert!(close(got, want_sq.sqrt(), 1e-12), "got {got}, want {}", want_sq.sqrt());
        }
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

// -------------------------------------------------------- L2 discrepancies

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
        assert_close(
            "wrap-around",
            wraparound_l2_discrepancy(&points).unwrap(),
            direct_wraparound_sq(&points).sqrt(),
            1e-9,
        );
    }
}

#[cfg(feature = "rayon")]
#[test]
fn wraparound_does_not_depend_on_the_thread_count() {
    let points = random_points(3000, 5);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| wraparound_l2_discrepancy_quadratic(&points).unwrap())
    };
    let one = run(1);
    assert_eq!(one.to_bits(), run(2).to_bits());
    assert_eq!(one.to_bits(), run(3).to_bits());
    assert_close("rayon", one, direct_wraparound_sq(&points).sqrt(), 1e-12);
}

// ---------------------------------------------------------- min distances

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

// ------------------------------------------------------- stratification

#[test]
fn stratification_checks() {
    // Hammersley sets are (0, m, 2)-nets, hence Latin and stratified.
    for m in 0..=12 {
        let points = hammersley(m);
        assert!(is_net_base2(&points).unwrap(), "m = {m}");
        assert!(is_latin(&points).unwrap());
        assert!(is_stratified(&points, 1 << (m / 2), 1 << (m - m / 2)).unwrap());
    }
    // Swapping two y values of a net breaks it.
    let mut broken = hammersley(6);
    let (a, b) = (broken[1].y, broken[2].y);
    broken[1].y = b;
    broken[2].y = a;
    assert!(is_latin(&broken).unwrap());
    assert!(!is_net_base2(&broken).unwrap());
    // The centre of each cell of a 3 x 5 grid: stratified on 3 x 5, not 5 x 3.
    let grid: Vec<Vec2> = (0..15)
        .map(|i| Vec2::new(((i % 3) as f32 + 0.5) / 3.0, ((i / 3) as f32 + 0.5) / 5.0))
        .collect();
    assert!(is_stratified(&grid, 3, 5).unwrap());
    assert!(!is_stratified(&grid, 5, 3).unwrap());
    assert!(is_stratified(&grid, 1, 5).unwrap());
    assert!(is_stratified(&grid, 3, 1).unwrap());
    assert!(!is_latin(&grid).unwrap());
    // Two points per cell.
    let doubled: Vec<Vec2> = grid.iter().chain(grid.iter()).copied().collect();
    assert!(is_stratified(&doubled, 3, 5).unwrap());
    // A point on a cell's left edge is in that cell.
    let edges: Vec<Vec2> = (0..16)
        .map(|i| Vec2::new(i as f32 / 16.0, (15 - i) as f32 / 16.0))
        .collect();
    assert!(is_latin(&edges).unwrap());
    // Cells come from the exact f32 values: 0.6f32 is just above 6/10 and
    // 0.7f32 just below 7/10 (as is 0.9f32 below 9/10), so 0.6 and 0.7 share
    // column 6 and the tenths are not Latin.
    let tenths: Vec<Vec2> = (0..10)
        .map(|i| Vec2::new(i as f32 / 10.0, (i as f32 + 0.5) / 10.0))
        .collect();
    assert!(!is_latin(&tenths).unwrap());
    let mut fixed = tenths.clone();
    fixed[7].x = f32::from_bits(0.7f32.to_bits() + 1);
    fixed[9].x = f32::from_bits(0.9f32.to_bits() + 1);
    assert!(is_latin(&fixed).unwrap());
    // Errors.
    assert!(matches!(
        is_stratified(&grid, 0, 5),
        Err(Error::ZeroGridSide { .. })
    ));
    assert!(matches!(
        is_stratified(&grid, 2, 5),
        Err(Error::GridDoesNotDivide { n: 15, .. })
    ));
    assert!(matches!(
        is_stratified(&grid, u32::MAX, u32::MAX),
        Err(Error::GridDoesNotDivide { .. })
    ));
    assert!(matches!(
        is_net_base2(&grid),
        Err(Error::NotPowerOfTwo { n: 15 })
    ));
}

// ------------------------------------------------------------ bad input

fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(1.0f32),
        Just(-0.0f32),
        Just(0.0f32),
        Just(f32::MIN_POSITIVE),
        Just(f32::from_bits(1)),
        Just(f32::from_bits(0x3f7f_ffff)),
        Just(-f32::from_bits(1)),
        any::<f32>(),
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
    ]
}

/// The error each metric must return, or None when the set is valid.
fn expected_error(points: &[Vec2]) -> Option<Error> {
    if points.is_empty() {
        return Some(Error::EmptyPointSet);
    }
    for (index, p) in points.iter().enumerate() {
        if !p.x.is_finite() || !p.y.is_finite() {
            return Some(Error::NonFinitePoint {
                index,
                x: p.x,
                y: p.y,
            });
        }
        if !(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0) {
            return Some(Error::PointOutOfRange {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    None
}

fn same_error(got: &Error, want: &Error) -> bool {
    match (got, want) {
        (Error::NonFinitePoint { index: a, .. }, Error::NonFinitePoint { index: b, .. })
        | (Error::PointOutOfRange { index: a, .. }, Error::PointOutOfRange { index: b, .. }) => {
            a == b
        }
        _ => got == want,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn hostile_input_never_panics(
        coords in prop::collection::vec((any_f32(), any_f32()), 0..24),
        columns in 0u32..5,
        rows in 0u32..5,
    ) {
        let points: Vec<Vec2> = coords.iter().map(|&(x, y)| Vec2::new(x, y)).collect();
        let want = expected_error(&points);
        let check = |name: &str, got: Result<(), Error>, want: Option<Error>| {
            match (&got, &want) {
                (Ok(()), None) => Ok(()),
                (Err(g), Some(w)) if same_error(g, w) => Ok(()),
                _ => Err(TestCaseError::fail(format!("{name}: got {got:?}, want {want:?}"))),
            }
        };
        let f = |r: Result<f64, Error>| r.map(|v| assert!(v.is_finite() && v >= 0.0));
        let b = |r: Result<bool, Error>| r.map(|_| ());
        check("star", f(star_discrepancy(&points)), want)?;
        check("l2", f(l2_star_discrepancy(&points)), want)?;
        check("cd", f(centered_l2_discrepancy(&points)), want)?;
        check("wd", f(wraparound_l2_discrepancy(&points)), want)?;
        check("latin", b(is_latin(&points)), want)?;
        let too_few = (want.is_none() && points.len() < 2).then_some(());
        for (name, r) in [
            ("min", min_distance(&points)),
            ("torus", toroidal_min_distance(&points)),
            ("normalised", normalized_toroidal_min_distance(&points)),
        ] {
            if too_few.is_some() {
                prop_assert!(matches!(r, Err(Error::TooFewPoints { needed: 2, got: 1, .. })), "{name}");
            } else {
                check(name, f(r), want)?;
            }
        }
        let net_want = want.or_else(|| {
            (!points.len().is_power_of_two()).then_some(Error::NotPowerOfTwo { n: points.len() })
        });
        check("net", b(is_net_base2(&points)), net_want)?;
        check("t", net_t_value(&points).map(|t| assert!(1usize << t <= points.len())), net_want)?;
        let spectrum = radial_power_spectrum(&points, 3)
            .map(|s| assert!(s.len() == 3 && s.iter().all(|p| p.is_finite() && *p >= 0.0)));
        check("spectrum", spectrum, want)?;
        let strat_want = if columns == 0 || rows == 0 {
            Some(Error::ZeroGridSide { columns, rows })
        } else {
            want.or_else(|| {
                (!points.len().is_multiple_of((columns * rows) as usize)).then_some(Error::GridDoesNotDivide {
                    columns,
                    rows,
                    n: points.len(),
                })
            })
        };
        check("stratified", b(is_stratified(&points, columns, rows)), strat_want)?;
    }
}

#[test]
fn error_messages_name_the_point() {
    let points = [Vec2::new(0.5, 0.5), Vec2::new(1.0, 0.25)];
    let err = star_discrepancy(&points).unwrap_err();
    assert!(matches!(err, Error::PointOutOfRange { index: 1, .. }));
    let msg = err.to_string();
    assert!(
        msg.contains("point 1") && msg.contains("(1, 0.25)"),
        "{msg}"
    );
    let err = min_distance(&[Vec2::new(0.5, f32::NAN)]).unwrap_err();
    assert!(matches!(err, Error::NonFinitePoint { index: 0, .. }));
    assert!(matches!(
        l2_star_discrepancy(&[]),
        Err(Error::EmptyPointSet)
    ));
    // -0.0 is 0.0.
    let neg = [Vec2::new(-0.0, 0.5), Vec2::new(0.5, -0.0)];
    let pos = [Vec2::new(0.0, 0.5), Vec2::new(0.5, 0.0)];
    assert_eq!(
        star_discrepancy(&neg).unwrap(),
        star_discrepancy(&pos).unwrap()
    );
    assert_eq!(
        l2_star_discrepancy(&neg).unwrap(),
        l2_star_discrepancy(&pos).unwrap()
    );
    assert_eq!(min_distance(&neg).unwrap(), min_distance(&pos).unwrap());
    assert!(is_latin(&neg).unwrap());
}

// ------------------------------------------------------------ net t-value

/// The smallest t for which every elementary interval of area 2^(t-m) holds
/// 2^t points, by counting each interval over all points with f64
/// comparisons (scaling by a power of two is exact).
fn brute_t_value(points: &[Vec2]) -> u32 {
    let n = points.len();
    let m = n.trailing_zeros();
    'next_t: for t in 0..=m {
        for a in 0..=m - t {
            let b = m - t - a;
            for i in 0..1u64 << a {
                for j in 0..1u64 << b {
                    let inside = points
                        .iter()
                        .filter(|p| {
                            let (x, y) = (
                                f64::from(p.x) * (1u64 << a) as f64,
                                f64::from(p.y) * (1u64 << b) as f64,
                            );
                            x.floor() as u64 == i && y.floor() as u64 == j
                        })
                        .count();
                    if inside != 1 << t {
                        continue 'next_t;
                    }
                }
            }
        }
        return t;
    }
    unreachable!("every set of 2^m points is an (m, m, 2)-net")
}

#[test]
fn t_value_of_sobol_and_pmj02_prefixes_is_zero() {
    let n = 1u32 << 14;
    let mut points = vec![Vec2::ZERO; n as usize];
    for pattern in [0u32, 1, 77, 0xdead_beef] {
        Sobol::new(n).unwrap().fill(pattern, &mut points);
        for m in 0..=14 {
            assert_eq!(
                net_t_value(&points[..1 << m]).unwrap(),
                0,
                "sobol {pattern} 2^{m}"
            );
        }
        Pmj02::new(n).unwrap().fill(pattern, &mut points);
        for m in 0..=14 {
            assert_eq!(
                net_t_value(&points[..1 << m]).unwrap(),
                0,
                "pmj02 {pattern} 2^{m}"
            );
        }
    }
}

#[test]
fn t_value_of_constructed_sets() {
    // A 2^a x 2^b grid of cell corners: intervals of shape (c, d) hold equal
    // counts exactly when c <= a and d <= b, so t = m - min(a, b) = max(a, b).
    for (a, b) in [(0, 0), (1, 0), (0, 3), (2, 2), (3, 5), (6, 6), (1, 9)] {
        let grid: Vec<Vec2> = (0..1u32 << (a + b))
            .map(|i| {
                Vec2::new(
                    (i % (1 << a)) as f32 / (1u32 << a) as f32,
                    (i >> a) as f32 / (1u32 << b) as f32,
                )
            })
            .collect();
        assert_eq!(net_t_value(&grid).unwrap(), a.max(b), "{a} x {b} grid");
    }
    // Two copies of a (0, m - 1, 2)-net are a (1, m, 2)-net and no better.
    for m in 1..=12 {
        let half = hammersley(m - 1);
        let twice: Vec<Vec2> = half.iter().chain(&half).copied().collect();
        assert_eq!(net_t_value(&twice).unwrap(), 1, "m = {m}");
        assert_eq!(net_t_value(&hammersley(m)).unwrap(), 0);
    }
    // n identical points: only the unit square holds them all.
    for m in 0..=10 {
        let same = vec![Vec2::new(0.3, 0.6); 1 << m];
        assert_eq!(net_t_value(&same).unwrap(), m);
    }
    // Moving one point of a Hammersley set out of its column breaks t = 0;
    // the brute force says by how much.
    let mut moved = hammersley(6);
    moved[5].x = 0.999;
    assert_eq!(net_t_value(&moved).unwrap(), brute_t_value(&moved));
    assert!(net_t_value(&moved).unwrap() > 0);
}

#[test]
fn t_value_needs_a_power_of_two() {
    for n in [3usize, 6, 100, 1000] {
        assert_eq!(
            net_t_value(&random_points(n, 3)),
            Err(Error::NotPowerOfTwo { n })
        );
    }
    assert_eq!(net_t_value(&[]), Err(Error::EmptyPointSet));
}

/// Points on the 2^-bits grid, so small sets are often nets of some small t.
fn dyadic_set(log2_n: u32, bits: u32) -> impl Strategy<Value = Vec<Vec2>> {
    let coord = (0u32..1 << bits).prop_map(move |i| i as f32 / (1u32 << bits) as f32);
    prop::collection::vec((coord.clone(), coord), 1 << log2_n)
        .prop_map(|v| v.into_iter().map(|(x, y)| Vec2::new(x, y)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn t_value_matches_brute_force(
        points in (0u32..=6, 1u32..=7).prop_flat_map(|(m, bits)| dyadic_set(m, bits)),
    ) {
        prop_assert_eq!(net_t_value(&points).unwrap(), brute_t_value(&points));
    }

    #[test]
    fn t_value_of_scrambled_nets_matches_brute_force(pattern in any::<u32>(), m in 0u32..=7) {
        let mut points = vec![Vec2::ZERO; 1 << m];
        Sobol::new(1 << m).unwrap().fill(pattern, &mut points);
        // Swap the x of two points: usually no longer a (0, m, 2)-net.
        let last = points.len() - 1;
        let x0 = points[0].x;
        points[0].x = points[last].x;
        points[last].x = x0;
        points[0].y = points[last / 2].y;
        prop_assert_eq!(net_t_value(&points).unwrap(), brute_t_value(&points));
    }
}

// ---------------------------------------------------------- power spectrum

/// The spectrum straight from its definition: every k of the full plane with
/// 0 < |k| <= r, its own exponential sum, binned by the rounded length.
fn direct_spectrum(points: &[Vec2], r: i64) -> Vec<f64> {
    let n = points.len() as f64;
    let mut power = vec![0.0; r as usize];
    let mut count = vec![0u32; r as usize];
    for kx in -r..=r {
        for ky in -r..=r {
            let len = ((kx * kx + ky * ky) as f64).sqrt();
            if kx * kx + ky * ky == 0 || len > r as f64 {
                continue;
            }
            let (mut re, mut im) = (0.0f64, 0.0f64);
            for p in points {
                let phase = -2.0
                    * std::f64::consts::PI
                    * (kx as f64 * f64::from(p.x) + ky as f64 * f64::from(p.y));
                re += phase.cos();
                im += phase.sin();
            }
            let bin = len.round() as usize - 1;
            power[bin] += (re * re + im * im) / n;
            count[bin] += 1;
        }
    }
    power
        .iter()
        .zip(&count)
        .map(|(p, &c)| p / f64::from(c))
        .collect()
}

#[test]
fn spectrum_matches_direct_evaluation() {
    let sets = [
        random_points(1, 40),
        random_points(57, 41),
        random_points(300, 42),
        hammersley(7),
        vec![Vec2::new(0.25, 0.75); 9],
    ];
    for (s, points) in sets.iter().enumerate() {
        for r in [1u32, 2, 7, 20] {
            let got = radial_power_spectrum(points, r).unwrap();
            let want = direct_spectrum(points, i64::from(r));
            assert_eq!(got.len(), r as usize);
            for (bin, (&g, &w)) in got.iter().zip(&want).enumerate() {
                // Sums of n unit phasors: absolute error near n 1e-16 per term.
                assert!(
                    (g - w).abs() <= 1e-10 * w.max(1.0),
                    "set {s}, r = {r}, bin {bin}: {g} vs {w}"
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn spectrum_matches_direct_evaluation_on_any_set(
        points in unit_points(24),
        r in 1u32..=6,
    ) {
        let got = radial_power_spectrum(&points, r).unwrap();
        let want = direct_spectrum(&points, i64::from(r));
        prop_assert_eq!(got.len(), r as usize);
        for (g, w) in got.iter().zip(&want) {
            prop_assert!((g - w).abs() <= 1e-10 * w.max(1.0), "{g} vs {w}");
        }
    }
}

#[test]
fn spectrum_in_bands_matches_one_band() {
    // 2^20 frequencies per band: at r = 600 the half plane takes two bands.
    let points = random_points(5, 43);
    let big = radial_power_spectrum(&points, 600).unwrap();
    let small = radial_power_spectrum(&points, 300).unwrap();
    assert_eq!(big.len(), 600);
    for (bin, (&a, &b)) in big.iter().zip(&small).take(299).enumerate() {
        assert!((a - b).abs() <= 1e-9 * b.max(1.0), "bin {bin}: {a} vs {b}");
    }
    let want = direct_spectrum(&points, 600);
    for bin in [0, 299, 300, 450, 599] {
        assert!(
            (big[bin] - want[bin]).abs() <= 1e-9 * want[bin].max(1.0),
            "bin {bin}"
        );
    }
}

#[test]
fn spectrum_of_random_points_is_flat() {
    // P(k) of independent uniform points is close to exponential with mean 1,
    // and P(-k) = P(k): bin r has about pi r independent values per set, so
    // over 64 sets its mean has standard deviation about 1 / sqrt(64 pi r).
    // Five of them: false-failure rate about 2e-5 over the 29 bins checked.
    let r = 32;
    let mut mean = vec![0.0; r as usize];
    for seed in 0..64 {
        let s = radial_power_spectrum(&random_points(256, 1000 + seed), r).unwrap();
        for (m, v) in mean.iter_mut().zip(s) {
            *m += v / 64.0;
        }
    }
    for (bin, &m) in mean.iter().enumerate().skip(3) {
        let sigma = 1.0 / (64.0 * std::f64::consts::PI * (bin + 1) as f64).sqrt();
        assert!((m - 1.0).abs() < 5.0 * sigma, "bin {}: {m}", bin + 1);
    }
}

#[test]
fn spectrum_rejects_bad_frequencies() {
    let points = random_points(10, 44);
    for f in [0, MAX_SPECTRUM_FREQUENCY + 1, u32::MAX] {
        assert_eq!(
            radial_power_spectrum(&points, f),
            Err(Error::FrequencyOutOfRange {
                max_frequency: f,
                max: MAX_SPECTRUM_FREQUENCY
            })
        );
    }
    assert_eq!(radial_power_spectrum(&[], 4), Err(Error::EmptyPointSet));
    let msg = radial_power_spectrum(&points, 0).unwrap_err().to_string();
    assert!(
        msg.contains("from 1 to 65536") && msg.contains("got 0"),
        "{msg}"
    );
}

// --------------------------------------------- wrap-around, fast vs direct

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

#[test]
fn wraparound_matches_the_direct_sum_on_hard_families() {
    // The direct sum takes about 1.5 s at 2^14: the five families the
    // cancellation is hardest on run there, all of them below.
    let hardest = ["random", "lattice", "few values", "duplicated", "cluster"];
    for n in [1usize, 2, 3, 16, 100, 1000, 4096, 1 << 14] {
        for (name, points) in wraparound_families(n) {
            if n > 4096 && !hardest.contains(&name) {
                continue;
            }
            let fast = wraparound_l2_discrepancy(&points).unwrap();
            let direct = wraparound_l2_discrepancy_quadratic(&points).unwrap();
            assert_close(&format!("{name}, n = {n}"), fast, direct, 1e-12);
        }
    }
}

// ------------------------------------------- min distance, crowded sets

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
