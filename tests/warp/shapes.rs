//! The shape warps (disk, hemispheres, sphere, triangle, and the ball and
//! parallelogram among the area and cone properties): measure-preserving,
//! inside their domain at the f32 edges, pdf and inverse consistent, and
//! keeping the stratification of Owen-scrambled Sobol points.

use super::*;

// ---------------------------------------------------------------------------
// Chi-square on equal-measure bins.

/// Rings of equal area (`r^2` uniform) times equal sectors on the unit disk:
/// 16 x 16 bins, each of area pi / 256.
fn disk_bin(p: Vec2) -> usize {
    let r2 = f64::from(p.length_squared()).min(1.0 - 1e-12);
    let phi = f64::from(p.y).atan2(f64::from(p.x)).rem_euclid(2.0 * PI);
    let ring = (r2 * 16.0) as usize;
    let sector = ((phi / (2.0 * PI) * 16.0) as usize).min(15);
    ring * 16 + sector
}

/// Cosine-weighted measure is area on the projected disk: disk bins of
/// `(x, y)`.
fn cosine_bin(v: Vec3) -> usize {
    disk_bin(Vec2::new(v.x, v.y))
}

/// The valid slots of [`triangle_bin`].
fn triangle_slots() -> Vec<usize> {
    let mut slots = Vec::new();
    for i in 0..16 {
        for j in 0..16 {
            if i + j <= 15 {
                slots.push((i * 16 + j) << 1);
            }
            if i + j <= 14 {
                slots.push(((i * 16 + j) << 1) | 1);
            }
        }
    }
    assert_eq!(slots.len(), 256);
    slots
}

/// The first `count` points of one Owen-scrambled Sobol pattern (a
/// (0,m,2)-net when `count = 2^m`). A grid of cell centres would put whole
/// rows of points exactly on bin edges (the concentric map sends the
/// square's diagonals to the rays at multiples of pi / 4, which are sector
/// edges), where rounding picks a side for all of them at once.
fn sobol_points(count: u32) -> Vec<Vec2> {
    let sobol = Sobol::new(count).unwrap();
    (0..count).map(|i| sobol.sample(i, 0x0017)).collect()
}

struct Case<T: 'static> {
    name: &'static str,
    warp: fn(Vec2) -> T,
    bin: Binner<T>,
}

fn check_chi_square<T>(case: &Case<T>, slots: &[usize]) {
    let critical = chi_square_critical(slots.len() - 1);
    // 2^20 random points, ~4096 per bin: a density off by 5% on one bin
    // alone adds ~10 to the statistic, on a quarter of the domain ~640.
    let random = chi_square(&counts(
        &random_points(0x5eed_0017, 1 << 20),
        case.warp,
        case.bin,
        slots,
    ));
    // A 2^20-point Sobol net: far more even than random, so its statistic
    // is far below the chi-square law's, and a tenth of its mean is a
    // deterministic bound that a density off by 1% on every bin (about 0.4
    // per bin) would break.
    let net = chi_square(&counts(&sobol_points(1 << 20), case.warp, case.bin, slots));
    println!(
        "chi-square {:<20} {} bins: random 2^20 {random:8.1}, sobol 2^20 {net:8.1} (critical at p = 1e-6: {critical:.1})",
        case.name,
        slots.len()
    );
    assert!(random < critical, "{}: chi-square {random}", case.name);
    assert!(
        net < 0.1 * (slots.len() - 1) as f64,
        "{}: sobol chi-square {net}",
        case.name
    );
}

/// Each warp's random-input statistic is chi-square with 255 degrees of
/// freedom if the warp is measure-preserving, so each of these assertions
/// fails for a correct warp with probability 1e-6 over seeds (5e-6 for the
/// five).
#[test]
fn warps_are_measure_preserving() {
    let all: Vec<usize> = (0..256).collect();
    check_chi_square(
        &Case {
            name: "concentric_disk",
            warp: concentric_disk,
            bin: disk_bin,
        },
        &all,
    );
    check_chi_square(
        &Case {
            name: "cosine_hemisphere",
            warp: cosine_hemisphere,
            bin: cosine_bin,
        },
        &all,
    );
    check_chi_square(
        &Case {
            name: "uniform_hemisphere",
            warp: uniform_hemisphere,
            bin: hemisphere_bin,
        },
        &all,
    );
    check_chi_square(
        &Case {
            name: "uniform_sphere",
            warp: uniform_sphere,
            bin: sphere_bin,
        },
        &all,
    );
    check_chi_square(
        &Case {
            name: "uniform_triangle",
            warp: uniform_triangle,
            bin: triangle_bin,
        },
        &triangle_slots(),
    );
}

/// The test can fail: maps that are not measure-preserving are rejected by
/// a wide margin.
#[test]
fn chi_square_rejects_maps_that_are_not_measure_preserving() {
    let all: Vec<usize> = (0..256).collect();
    let critical = chi_square_critical(255);
    let points = random_points(3, 1 << 20);
    // Polar with a linear radius: too dense at the centre.
    let naive_disk = |u: Vec2| {
        let phi = 2.0 * std::f32::consts::PI * u.y;
        u.x * Vec2::new(phi.cos(), phi.sin())
    };
    let naive = chi_square(&counts(&points, naive_disk, disk_bin, &all));
    // The cosine map binned as if it were uniform.
    let cosine_as_uniform = chi_square(&counts(&points, cosine_hemisphere, hemisphere_bin, &all));
    // Barycentrics (u.x, u.y (1 - u.x)): dense at vertex 1.
    let naive_triangle = |u: Vec2| Vec3::new(u.x, u.y * (1.0 - u.x), (1.0 - u.x) * (1.0 - u.y));
    let slots = triangle_slots();
    let triangle = chi_square(&counts(&points, naive_triangle, triangle_bin, &slots));
    println!(
        "chi-square of wrong maps: linear-radius disk {naive:.0}, cosine as uniform {cosine_as_uniform:.0}, naive triangle {triangle:.0} (critical {critical:.1})"
    );
    for statistic in [naive, cosine_as_uniform, triangle] {
        assert!(statistic > 10.0 * critical, "{statistic}");
    }
}

// ---------------------------------------------------------------------------
// The f32 edges of the square.

/// Points on every edge and corner of `[0, 1)^2`, with coordinates 0, the
/// smallest step 2^-24, the largest f32 below 1 and a sweep between.
fn edge_points() -> Vec<Vec2> {
    let mut ts: Vec<f32> = (0..=4096).map(|k| (k as f32 / 4096.0).min(LAST)).collect();
    ts.extend([
        f32::EPSILON / 2.0,
        0.5 - f32::EPSILON / 4.0,
        0.5 + f32::EPSILON / 2.0,
        LAST,
    ]);
    let mut points = Vec::new();
    for &t in &ts {
        for edge in [0.0, f32::EPSILON / 2.0, LAST, 1.0 - f32::EPSILON] {
            points.push(Vec2::new(edge, t));
            points.push(Vec2::new(t, edge));
        }
        // The diagonals, where the concentric and triangle maps switch branch.
        points.push(Vec2::new(t, t));
        points.push(Vec2::new(t, LAST - t));
    }
    points
}

#[test]
fn warps_stay_inside_their_domain_at_the_edges() {
    let points = edge_points();
    let (mut disk, mut dir, mut tri) = (0.0f32, 0.0f32, 0.0f32);
    for &u in &points {
        let p = concentric_disk(u);
        assert!(p.is_finite(), "{u}");
        disk = disk.max(p.length() - 1.0);
        for v in [
            cosine_hemisphere(u),
            uniform_hemisphere(u),
            uniform_sphere(u),
        ] {
            assert!(v.is_finite(), "{u}");
            dir = dir.max((v.length() - 1.0).abs());
        }
        assert!(cosine_hemisphere(u).z >= 0.0, "{u}");
        assert!(uniform_hemisphere(u).z >= 0.0, "{u}");
        let b = uniform_triangle(u);
        assert!(b.min_element() >= 0.0, "{u}: {b}");
        assert!(b.z >= f32::EPSILON / 2.0, "{u}: {b}");
        tri = tri.max((b.x + b.y + b.z - 1.0).abs());
    }
    println!(
        "edges ({} points): disk |p| - 1 <= {disk:e}, directions ||v| - 1| <= {dir:e}, triangle |sum - 1| <= {tri:e}",
        points.len()
    );
    // The documented tolerances: 2^-23 for the disk, 2^-22 for unit
    // directions, 2^-23 for the barycentric sum.
    assert!(disk <= f32::EPSILON, "{disk}");
    assert!(dir <= 2.0 * f32::EPSILON, "{dir}");
    assert!(tri <= f32::EPSILON, "{tri}");
}

/// Every point of the 2^-24 grid on the four edges of `[0, 1)^2` (`x` or
/// `y` is 0 or `1 - 2^-24`, the other coordinate `k 2^-24`): 2^26 points,
/// where every wellspread sampler's output can land. Returns how many fail
/// `ok` and the first that does, in parallel over chunks of `k`.
fn sweep_edge_grid(ok: impl Fn(Vec2) -> bool + Sync) -> (u64, Option<Vec2>) {
    sweep_edge_grid_every(1, ok)
}

/// Item 1 of issue 27: at every point a 2D warp produces from the 2^-24
/// edge grid, its pdf is positive and finite (a renderer divides by it).
#[test]
fn pdfs_are_positive_and_finite_on_the_edge_grid() {
    let checks: [(&str, &(dyn Fn(Vec2) -> bool + Sync)); 5] = [
        ("concentric_disk", &|u| {
            let p = concentric_disk(u);
            p.is_finite() && valid_pdf(concentric_disk_pdf(p))
        }),
        ("cosine_hemisphere", &|u| {
            let v = cosine_hemisphere(u);
            v.is_finite() && valid_pdf(cosine_hemisphere_pdf(v.z))
        }),
        ("uniform_hemisphere", &|u| {
            let v = uniform_hemisphere(u);
            v.is_finite() && valid_pdf(uniform_hemisphere_pdf(v))
        }),
        ("uniform_sphere", &|u| {
            let v = uniform_sphere(u);
            v.is_finite() && valid_pdf(uniform_sphere_pdf(v))
        }),
        ("uniform_triangle", &|u| {
            let b = uniform_triangle(u);
            b.is_finite() && b.min_element() >= 0.0 && valid_pdf(uniform_triangle_pdf(0.5))
        }),
    ];
    for (name, ok) in checks {
        let (failed, first) = sweep_edge_grid(ok);
        assert_eq!(
            failed, 0,
            "{name}: {failed} edge points with a bad pdf, first {first:?}"
        );
    }
}

/// The sweep can fail: the disk pdf as it was (`|p|^2 <= 1`, no slack) is
/// 0 at about 1.2 M of the 2^26 edge points (issue 27's fuzz figure).
#[test]
fn the_edge_grid_sweep_finds_the_old_disk_pdf_bug() {
    let (failed, first) = sweep_edge_grid(|u| concentric_disk(u).length_squared() <= 1.0);
    println!("old disk pdf: 0 at {failed} of 2^26 edge points, first {first:?}");
    assert!(failed > 1_000_000, "{failed}");
    assert_eq!(
        concentric_disk_pdf(concentric_disk(Vec2::new(f32::EPSILON / 2.0, 0.0))),
        core::f32::consts::FRAC_1_PI
    );
}

/// Out-of-range input is clamped into `[0, 1)` (NaN to 0), in debug and
/// release builds: the same point as the clamped input, with a valid pdf.
#[test]
fn warps_clamp_out_of_range_input() {
    let bad = [
        f32::NAN,
        -1.0,
        -0.0,
        -f32::MIN_POSITIVE,
        1.0,
        1.0 + f32::EPSILON,
        7.5,
        f32::INFINITY,
        f32::NEG_INFINITY,
    ];
    let clamp = |x: f32| {
        if x.is_nan() || x <= 0.0 {
            0.0
        } else {
            x.min(LAST)
        }
    };
    for &a in &bad {
        for b in [0.25, a] {
            for u in [Vec2::new(a, b), Vec2::new(b, a)] {
                let c = Vec2::new(clamp(u.x), clamp(u.y));
                assert_eq!(concentric_disk(u), concentric_disk(c), "{u}");
                assert_eq!(cosine_hemisphere(u), cosine_hemisphere(c), "{u}");
                assert_eq!(uniform_hemisphere(u), uniform_hemisphere(c), "{u}");
                assert_eq!(uniform_sphere(u), uniform_sphere(c), "{u}");
                assert_eq!(uniform_triangle(u), uniform_triangle(c), "{u}");
                assert!(valid_pdf(concentric_disk_pdf(concentric_disk(u))), "{u}");
                assert!(
                    valid_pdf(cosine_hemisphere_pdf(cosine_hemisphere(u).z)),
                    "{u}"
                );
            }
        }
    }
}

#[test]
fn warps_hit_the_documented_points() {
    assert_eq!(concentric_disk(Vec2::splat(0.5)), Vec2::ZERO);
    assert_eq!(cosine_hemisphere(Vec2::splat(0.5)), Vec3::Z);
    assert_eq!(uniform_sphere(Vec2::ZERO), Vec3::Z);
    assert_eq!(uniform_hemisphere(Vec2::ZERO), Vec3::X);
    // The concentric map's corners go to the diagonals of the disk.
    let corner = concentric_disk(Vec2::ZERO);
    assert!((corner - Vec2::splat(-core::f32::consts::FRAC_1_SQRT_2)).length() < 1e-6);
    // The triangle's corners: (0, 0) is vertex 2, the diagonal end vertex
    // 0 and 1 shares.
    assert_eq!(uniform_triangle(Vec2::ZERO), Vec3::Z);
    let near_one = uniform_triangle(Vec2::new(LAST, 0.0));
    assert!((near_one - Vec3::X).length() < 1e-6);
    let top = uniform_triangle(Vec2::new(0.0, LAST));
    assert!((top - Vec3::Y).length() < 1e-6);
}

// ---------------------------------------------------------------------------
// pdf and inverse, over random inputs.

fn v2(p: Vec2) -> [f64; 3] {
    [f64::from(p.x), f64::from(p.y), 0.0]
}

proptest! {
    /// The pdf is the inverse of the map's area scale: `pdf(warp(u)) |J(u)|
    /// = 1`, by central differences of step 2^-10 (2% tolerance: f32
    /// rounding over the step, and curvature for directions), away from the
    /// concentric map's diagonal kinks, the poles and the hemisphere's rim.
    #[test]
    fn pdf_is_the_inverse_jacobian(x in 0.002f32..0.998, y in 0.002f32..0.998) {
        let u = Vec2::new(x, y);
        let h = 1.0 / 1024.0;
        let o = 2.0 * u - Vec2::ONE;
        let off_kink = (o.x.abs() - o.y.abs()).abs() > 4.0 * h;
        if off_kink {
            let j = area_scale(concentric_disk, v2, u, h);
            prop_assert!((j * f64::from(concentric_disk_pdf(concentric_disk(u))) - 1.0).abs() < 0.02, "disk {}", j);
            let v = cosine_hemisphere(u);
            // Near the rim z changes like sqrt(1 - r^2) over one step.
            if v.z > 0.3 {
                let j = area_scale(cosine_hemisphere, v3, u, h);
                prop_assert!((j * f64::from(cosine_hemisphere_pdf(v.z)) - 1.0).abs() < 0.02, "cosine {}", j);
            }
        }
        if x < 0.99 && x > 0.01 {
            let j = area_scale(uniform_hemisphere, v3, u, h);
            prop_assert!((j * f64::from(uniform_hemisphere_pdf(uniform_hemisphere(u))) - 1.0).abs() < 0.02, "hemisphere {}", j);
            let j = area_scale(uniform_sphere, v3, u, h);
            prop_assert!((j * f64::from(uniform_sphere_pdf(uniform_sphere(u))) - 1.0).abs() < 0.02, "sphere {}", j);
        }
        if (x - y).abs() > 2.0 * h {
            // Barycentrics (b0, b1) in the reference triangle of area 1/2.
            let j = area_scale(uniform_triangle, |b: Vec3| [f64::from(b.x), f64::from(b.y), 0.0], u, h);
            prop_assert!((j * f64::from(uniform_triangle_pdf(0.5)) - 1.0).abs() < 0.02, "triangle {}", j);
        }
    }

    /// `inverse(warp(u)) = u`, within a few 2^-24 (and `~2^-23 / r` for
    /// the azimuth of the sphere maps, `r` the distance from the axis).
    #[test]
    fn inverse_undoes_the_warp(kx in 0u32..1 << 24, ky in 0u32..1 << 24) {
        let u = Vec2::new(kx as f32, ky as f32) * (1.0 / 16_777_216.0);
        let tol = 4.0 * f32::EPSILON;
        let back = concentric_disk_inverse(concentric_disk(u));
        prop_assert!((back - u).abs().max_element() <= tol, "disk {} -> {}", u, back);
        let back = cosine_hemisphere_inverse(cosine_hemisphere(u));
        prop_assert!((back - u).abs().max_element() <= tol, "cosine {} -> {}", u, back);
        let v = uniform_hemisphere(u);
        let back = uniform_hemisphere_inverse(v);
        let r = v.truncate().length().max(1e-6);
        prop_assert!((back.x - u.x).abs() <= tol, "hemisphere {} -> {}", u, back);
        prop_assert!(periodic_distance(back.y, u.y) <= tol / r, "hemisphere {} -> {}", u, back);
        let v = uniform_sphere(u);
        let back = uniform_sphere_inverse(v);
        let r = v.truncate().length().max(1e-6);
        prop_assert!((back.x - u.x).abs() <= tol, "sphere {} -> {}", u, back);
        prop_assert!(periodic_distance(back.y, u.y) <= tol / r, "sphere {} -> {}", u, back);
        let back = uniform_triangle_inverse(uniform_triangle(u));
        prop_assert!((back - u).abs().max_element() <= tol, "triangle {} -> {}", u, back);
        for w in [back, concentric_disk_inverse(concentric_disk(u))] {
            prop_assert!(w.min_element() >= 0.0 && w.max_element() < 1.0);
        }
    }

    /// Random inputs stay in the domain with the documented tolerances.
    #[test]
    fn warps_stay_inside_their_domain(x in 0.0f32..1.0, y in 0.0f32..1.0) {
        let u = Vec2::new(x, y);
        prop_assert!(concentric_disk(u).length() <= 1.0 + f32::EPSILON);
        for v in [cosine_hemisphere(u), uniform_hemisphere(u), uniform_sphere(u)] {
            prop_assert!((v.length() - 1.0).abs() <= 2.0 * f32::EPSILON, "{}", v);
        }
        prop_assert!(cosine_hemisphere(u).z >= 0.0 && uniform_hemisphere(u).z >= 0.0);
        let b = uniform_triangle(u);
        prop_assert!(b.min_element() >= 0.0 && (b.x + b.y + b.z - 1.0).abs() <= f32::EPSILON);
    }
}

// ---------------------------------------------------------------------------
// Stratification survives: convergence of warped Sobol.

/// Gauss-Legendre nodes and weights on `[a, b]` (Newton on the Legendre
/// recurrence, converged to f64 precision).
fn gauss_legendre(n: usize, a: f64, b: f64) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 0.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let step = p1 / dp;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            (0.5 * (a + b) + 0.5 * (b - a) * x, 0.5 * (b - a) * w)
        })
        .collect()
}

/// A smooth, non-symmetric function of a point of space.
fn smooth(x: f64, y: f64, z: f64) -> f64 {
    (0.7 * x - 0.4 * y + 0.5 * z).exp() * (1.0 + 0.3 * (1.7 * x + 2.3 * y - 0.9 * z).sin())
}

/// The integrand of the triangle case, in barycentrics.
fn smooth_barycentric(b0: f64, b1: f64) -> f64 {
    smooth(b0 - 0.3, b1 + 0.2, 1.0 - b0 - b1)
}

/// `integral of f(theta, phi) sin(theta)` over `theta` in `[0, top]`:
/// Gauss-Legendre in theta, the trapezoid rule (exponentially accurate for
/// periodic integrands) in phi.
fn spherical_integral(top: f64, f: impl Fn(f64, f64) -> f64) -> f64 {
    let phis = 512;
    let mut sum = 0.0;
    for (theta, w) in gauss_legendre(96, 0.0, top) {
        for k in 0..phis {
            let phi = 2.0 * PI * k as f64 / phis as f64;
            sum += w * theta.sin() * f(theta, phi) * (2.0 * PI / phis as f64);
        }
    }
    sum
}

fn direction(theta: f64, phi: f64) -> (f64, f64, f64) {
    (
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}

/// The exact means of the integrands under each warp's density.
fn references() -> [f64; 5] {
    let mut disk = 0.0;
    for (r, w) in gauss_legendre(64, 0.0, 1.0) {
        for k in 0..512 {
            let phi = 2.0 * PI * k as f64 / 512.0;
            disk += w * r * smooth(r * phi.cos(), r * phi.sin(), 0.0) * (2.0 * PI / 512.0);
        }
    }
    let cosine = spherical_integral(PI / 2.0, |t, p| {
        let (x, y, z) = direction(t, p);
        smooth(x, y, z) * z / PI
    });
    let hemisphere = spherical_integral(PI / 2.0, |t, p| {
        let (x, y, z) = direction(t, p);
        smooth(x, y, z)
    }) / (2.0 * PI);
    let sphere = spherical_integral(PI, |t, p| {
        let (x, y, z) = direction(t, p);
        smooth(x, y, z)
    }) / (4.0 * PI);
    // Duffy: (s, t) -> (s (1 - t), s t), Jacobian s; the triangle's area is 1/2.
    let mut triangle = 0.0;
    let nodes = gauss_legendre(48, 0.0, 1.0);
    for &(s, ws) in &nodes {
        for &(t, wt) in &nodes {
            triangle += ws * wt * s * smooth_barycentric(s * (1.0 - t), s * t);
        }
    }
    [disk / PI, cosine, hemisphere, sphere, 2.0 * triangle]
}

const NAMES: [&str; 5] = [
    "concentric_disk",
    "cosine_hemisphere",
    "uniform_hemisphere",
    "uniform_sphere",
    "uniform_triangle",
];

/// The integrands composed with each warp, as functions of the square.
fn integrands(u: Vec2) -> [f64; 5] {
    let p = concentric_disk(u);
    let c = cosine_hemisphere(u);
    let h = uniform_hemisphere(u);
    let s = uniform_sphere(u);
    let b = uniform_triangle(u);
    let f = |v: Vec3| smooth(f64::from(v.x), f64::from(v.y), f64::from(v.z));
    [
        smooth(f64::from(p.x), f64::from(p.y), 0.0),
        f(c),
        f(h),
        f(s),
        smooth_barycentric(f64::from(b.x), f64::from(b.y)),
    ]
}

/// The least-squares slope of `log2(rmse)` against `log2(n)`.
fn slope(rmse: &[(u32, f64)]) -> f64 {
    let pts: Vec<(f64, f64)> = rmse
        .iter()
        .map(|&(m, e)| (f64::from(m), e.log2()))
        .collect();
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / pts.len() as f64;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / pts.len() as f64;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

/// RMSE over `patterns` patterns at n = 2^4 .. 2^12, for every integrand,
/// with points from `point(index, pattern)` (each power-of-two prefix of a
/// pattern is one set).
fn rmse_curves(patterns: u32, point: impl Fn(u32, u32) -> Vec2) -> [Vec<(u32, f64)>; 5] {
    let exact = references();
    let mut squared = [[0.0f64; 13]; 5];
    for pattern in 0..patterns {
        let mut sums = [0.0f64; 5];
        for index in 0..1u32 << 12 {
            let values = integrands(point(index, pattern));
            for (sum, v) in sums.iter_mut().zip(values) {
                *sum += v;
            }
            let n = index + 1;
            if n.is_power_of_two() && n >= 16 {
                let m = n.trailing_zeros() as usize;
                for k in 0..5 {
                    squared[k][m] += (sums[k] / f64::from(n) - exact[k]).powi(2);
                }
            }
        }
    }
    std::array::from_fn(|k| {
        (4..=12)
            .map(|m| (m as u32, (squared[k][m] / f64::from(patterns)).sqrt()))
            .collect()
    })
}

/// Warped Owen-scrambled Sobol keeps converging faster than n^-1 on smooth
/// integrands: RMSE over 64 patterns at n = 2^4 .. 2^12, slope -1.15 or
/// steeper on every domain. Random points at the same n give about -0.5,
/// checked too, so the slope measures the pattern and not the integrand.
///
/// The RMSE of each n is estimated from 64 patterns (relative standard
/// error about 9%), so the fitted slope has a standard error of about
/// 0.02. Over four sets of 64 patterns (0, 1000, 5000 and 77777 onwards)
/// the slopes moved by at most 0.04; the closest to the bound, -1.22
/// (cosine hemisphere), is 0.07 (3.5 standard errors) from -1.15, a
/// false-failure rate of about 2e-4 over pattern sets.
#[test]
fn warped_sobol_keeps_converging() {
    let sobol = Sobol::new(1 << 12).unwrap();
    let curves = rmse_curves(64, |index, pattern| sobol.sample(index, pattern));
    let random = rmse_curves(64, |index, pattern| {
        // A fresh seeded stream per pattern; index order is the stream's.
        let mut rng = Pcg32::seed_from_u64(u64::from(pattern) << 32 | u64::from(index));
        Vec2::new(
            (rng.random::<u32>() >> 8) as f32 / 16_777_216.0,
            (rng.random::<u32>() >> 8) as f32 / 16_777_216.0,
        )
    });
    for k in 0..5 {
        let s = slope(&curves[k]);
        let r = slope(&random[k]);
        let rmse: Vec<String> = curves[k]
            .iter()
            .map(|(m, e)| format!("2^{m}: {e:.2e}"))
            .collect();
        println!(
            "slope {:<20} sobol {s:6.3}  random {r:6.3}   [{}]",
            NAMES[k],
            rmse.join(", ")
        );
        assert!(s <= -1.15, "{}: slope {s}", NAMES[k]);
        assert!(
            (-0.65..=-0.35).contains(&r),
            "{}: random slope {r}",
            NAMES[k]
        );
    }
}

// ---------------------------------------------------------------------------
// Light warps on degenerate and huge geometry: regressions and properties.

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20000))]

    /// The direction maps of the unit shapes at the square's edges: in
    /// their domain with a positive finite pdf there.
    #[test]
    fn shape_warps_are_finite_with_a_positive_pdf(u in edge_u(), n in prop_oneof![Just(1u32), Just(u32::MAX), 1u32..1000]) {
        let good = |pdf: f32| pdf.is_finite() && pdf > 0.0;
        let d = concentric_disk(u);
        prop_assert!(d.is_finite() && good(concentric_disk_pdf(d)));
        let v = cosine_hemisphere(u);
        prop_assert!(v.is_finite() && good(cosine_hemisphere_pdf(v.z)) || u.x == 0.0 && v.z == 0.0 || v.z <= 1e-3, "{}", v);
        let v = uniform_hemisphere(u);
        prop_assert!(v.is_finite() && good(uniform_hemisphere_pdf(v)));
        let v = uniform_sphere(u);
        prop_assert!(v.is_finite() && good(uniform_sphere_pdf(v)));
        let (i, r) = discrete(u.x, n);
        prop_assert!(i < n && (0.0..1.0).contains(&r) && good(discrete_pdf(n)));
    }
}
