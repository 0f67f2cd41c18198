//! The light warps (the cone, and triangles and rectangles by solid
//! angle; the ball and the parallelogram beside them): uniform in their
//! measure, hitting what they report and inverted by their inverses, at
//! the square's edges, for small lights, and against area sampling.

use super::*;

// ---------------------------------------------------------------------------
// Lights: cone, ball, rectangle, spherical triangle and rectangle.

/// A triangle light and a rectangle light seen from the origin, used by the
/// light tests: not symmetric about the origin, and a tilted rectangle.
const TRI: [Vec3; 3] = [
    Vec3::new(-0.4, -0.2, 0.9),
    Vec3::new(1.1, 0.1, 0.7),
    Vec3::new(0.2, 0.8, 1.3),
];
const RECT_CORNER: Vec3 = Vec3::new(-0.5, -0.3, 0.8);
const RECT_EX: Vec3 = Vec3::new(1.2, 0.0, 0.3);
const RECT_EY: Vec3 = Vec3::new(0.0, 0.9, 0.0);

/// The point `b0 a + b1 b + b2 c` in f64.
fn barycentric_point(t: [Vec3; 3], b0: f64, b1: f64) -> [f64; 3] {
    let (a, b, c) = (dv(t[0]), dv(t[1]), dv(t[2]));
    let b2 = 1.0 - b0 - b1;
    [
        b0 * a[0] + b1 * b[0] + b2 * c[0],
        b0 * a[1] + b1 * b[1] + b2 * c[1],
        b0 * a[2] + b1 * b[2] + b2 * c[2],
    ]
}

/// The expected share of each [`triangle_bin`] slot under a map uniform in
/// solid angle: the sub-triangle's solid angle over the triangle's.
fn triangle_bin_solid_angles(t: [Vec3; 3]) -> Vec<f64> {
    let mut shares = vec![0.0; 512];
    let m = 16.0;
    for i in 0..16 {
        for j in 0..16 {
            let (x, y) = (i as f64 / m, j as f64 / m);
            let h = 1.0 / m;
            if i + j <= 15 {
                let up = solid_angle(
                    barycentric_point(t, x, y),
                    barycentric_point(t, x + h, y),
                    barycentric_point(t, x, y + h),
                );
                shares[(i * 16 + j) << 1] = up;
            }
            if i + j <= 14 {
                let down = solid_angle(
                    barycentric_point(t, x + h, y),
                    barycentric_point(t, x + h, y + h),
                    barycentric_point(t, x, y + h),
                );
                shares[((i * 16 + j) << 1) | 1] = down;
            }
        }
    }
    let total: f64 = shares.iter().sum();
    shares.iter().map(|s| s / total).collect()
}

/// The solid angle of the cell `[s0, s1] x [t0, t1]` of the rectangle,
/// seen from the origin (two triangles).
fn rectangle_cell_solid_angle(s0: f64, s1: f64, t0: f64, t1: f64) -> f64 {
    let at = |s: f64, t: f64| {
        let (c, x, y) = (dv(RECT_CORNER), dv(RECT_EX), dv(RECT_EY));
        [
            c[0] + s * x[0] + t * y[0],
            c[1] + s * x[1] + t * y[1],
            c[2] + s * x[2] + t * y[2],
        ]
    };
    solid_angle(at(s0, t0), at(s1, t0), at(s1, t1))
        + solid_angle(at(s0, t0), at(s1, t1), at(s0, t1))
}

/// `count` seeded uniform points of `[0, 1)^3` on the 2^-24 grid.
fn random_points_3d(seed: u64, count: usize) -> Vec<Vec3> {
    let mut rng = Pcg32::seed_from_u64(seed);
    let mut unit = || (rng.random::<u32>() >> 8) as f32 * (1.0 / 16_777_216.0);
    (0..count)
        .map(|_| Vec3::new(unit(), unit(), unit()))
        .collect()
}

/// Chi-square of `bin(u)` over 2^20 random inputs against expected shares
/// (bins of share 0 must stay empty); asserts below the p = 1e-6 critical
/// value and returns the statistic.
fn check_shares(name: &str, inputs: &[Vec2], bin: impl Fn(Vec2) -> usize, shares: &[f64]) -> f64 {
    let mut counts = vec![0u64; shares.len()];
    for &u in inputs {
        counts[bin(u)] += 1;
    }
    let expected: Vec<f64> = shares.iter().map(|s| s * inputs.len() as f64).collect();
    let (statistic, dof) = chi_square_against(&counts, &expected);
    let critical = chi_square_critical(dof);
    println!(
        "chi-square {name:<32} {dof} dof: {statistic:8.1} (critical at p = 1e-6: {critical:.1})"
    );
    assert!(statistic < critical, "{name}: {statistic}");
    statistic
}

/// Each light warp is uniform in its measure: chi-square over 2^20
/// random inputs on bins of known measure (solid angle, volume, area),
/// each with a false failure rate of 1e-6. The cone is checked against the
/// sphere's and hemisphere's bins (which are not aligned with its
/// parameters) at `cos_theta_max = -1` and `0`, and on rings of equal
/// solid angle times sectors for a narrow cone.
#[test]
fn light_warps_are_uniform_in_their_measure() {
    let inputs = random_points(0x0027_0004, 1 << 20);
    let uniform = |bins: usize| vec![1.0 / bins as f64; bins];
    check_shares(
        "uniform_cone(-1) as a sphere",
        &inputs,
        |u| sphere_bin(uniform_cone(u, -1.0)),
        &uniform(256),
    );
    check_shares(
        "uniform_cone(0) as a hemisphere",
        &inputs,
        |u| hemisphere_bin(uniform_cone(u, 0.0)),
        &uniform(256),
    );
    let cos_max = 0.999_f32;
    check_shares(
        "uniform_cone(0.999)",
        &inputs,
        |u| {
            let v = uniform_cone(u, cos_max);
            let omc = f64::from(v.x * v.x + v.y * v.y) / (1.0 + f64::from(v.z));
            let ring = ((omc / f64::from(1.0 - cos_max)) * 16.0).clamp(0.0, 15.0) as usize;
            ring * 16 + sector(v.x, v.y, 2.0 * PI, 16)
        },
        &uniform(256),
    );
    check_shares(
        "rectangle",
        &inputs,
        |u| {
            // Axis-aligned 2 x 0.5 rectangle: 16 x 16 cells of its plane.
            let p = rectangle(
                u,
                Vec3::new(1.0, 2.0, 3.0),
                Vec3::new(2.0, 0.0, 0.0),
                Vec3::new(0.0, 0.0, 0.5),
            );
            let i = (f64::from(p.x - 1.0) / 2.0 * 16.0).clamp(0.0, 15.0) as usize;
            let j = (f64::from(p.z - 3.0) / 0.5 * 16.0).clamp(0.0, 15.0) as usize;
            i * 16 + j
        },
        &uniform(256),
    );
    let shares = triangle_bin_solid_angles(TRI);
    check_shares(
        "spherical_triangle",
        &inputs,
        |u| triangle_bin(spherical_triangle(u, TRI[0], TRI[1], TRI[2], Vec3::ZERO).barycentrics),
        &shares,
    );
    // The bins' solid angles are far from equal (equal areas of the
    // triangle): a map uniform in area would fail (checked below).
    let positive = shares.iter().copied().filter(|&s| s > 0.0);
    let spread = positive.clone().fold(0.0, f64::max) / positive.fold(1.0, f64::min);
    assert!(spread > 2.0, "{spread}");
    let triangle_shares = shares;
    let mut shares = vec![0.0; 256];
    for i in 0..16 {
        for j in 0..16 {
            let (s, t) = (i as f64 / 16.0, j as f64 / 16.0);
            shares[i * 16 + j] = rectangle_cell_solid_angle(s, s + 1.0 / 16.0, t, t + 1.0 / 16.0);
        }
    }
    let total: f64 = shares.iter().sum();
    shares.iter_mut().for_each(|s| *s /= total);
    check_shares(
        "spherical_rectangle",
        &inputs,
        |u| {
            let st = spherical_rectangle(u, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO).st;
            let i = (st.x * 16.0).clamp(0.0, 15.0) as usize;
            let j = (st.y * 16.0).clamp(0.0, 15.0) as usize;
            i * 16 + j
        },
        &shares,
    );
    // The ball: 4 shells of equal volume times the 256 sphere bins.
    let mut counts = vec![0u64; 1024];
    for u in random_points_3d(0x0027_0044, 1 << 20) {
        let p = uniform_ball(u);
        let r3 = f64::from(p.length()).powi(3);
        let shell = (r3 * 4.0).clamp(0.0, 3.0) as usize;
        counts[shell * 256 + sphere_bin(p.normalize_or(Vec3::Z))] += 1;
    }
    let statistic = chi_square(&counts);
    println!(
        "chi-square uniform_ball 1023 dof: {statistic:.1} (critical {:.1})",
        chi_square_critical(1023)
    );
    assert!(statistic < chi_square_critical(1023), "ball {statistic}");
    // The test can fail: area sampling of the triangle, binned against
    // solid angle, is rejected.
    let (counts, expected) = {
        let mut counts = vec![0u64; 512];
        for &u in &inputs {
            counts[triangle_bin(uniform_triangle(u))] += 1;
        }
        let expected: Vec<f64> = triangle_shares
            .iter()
            .map(|s| s * inputs.len() as f64)
            .collect();
        (counts, expected)
    };
    let (statistic, dof) = chi_square_against(&counts, &expected);
    assert!(
        statistic > 10.0 * chi_square_critical(dof),
        "area sampling passed as solid angle: {statistic}"
    );
}

/// Directions are unit, inside the light, consistent with the point they
/// report, and the pdf is the inverse of the map's Jacobian on the sphere.
#[test]
fn light_warps_hit_what_they_report() {
    let omega_tri = solid_angle(dv(TRI[0]), dv(TRI[1]), dv(TRI[2]));
    let pdf_tri = spherical_triangle_pdf(TRI[0], TRI[1], TRI[2], Vec3::ZERO);
    assert!(
        (f64::from(pdf_tri) * omega_tri - 1.0).abs() < 1e-6,
        "{pdf_tri}"
    );
    let omega_rect = rectangle_cell_solid_angle(0.0, 1.0, 0.0, 1.0);
    let pdf_rect = spherical_rectangle_pdf(RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO);
    assert!(
        (f64::from(pdf_rect) * omega_rect - 1.0).abs() < 1e-6,
        "{pdf_rect}"
    );
    let (mut worst_tri, mut worst_rect, mut worst_jacobian) = (0.0f64, 0.0f64, 0.0f64);
    for u in random_points(0x0027_0041, 1 << 14) {
        let TriangleLightSample {
            direction: w,
            pdf,
            barycentrics: b,
        } = spherical_triangle(u, TRI[0], TRI[1], TRI[2], Vec3::ZERO);
        assert_eq!(pdf, pdf_tri);
        assert!((w.length() - 1.0).abs() <= f32::EPSILON, "{w}");
        assert!(b.min_element() >= 0.0 && (b.x + b.y + b.z - 1.0).abs() <= f32::EPSILON);
        let hit = unit3(barycentric_point(TRI, f64::from(b.x), f64::from(b.y)));
        worst_tri = worst_tri.max(dot(sub(hit, dv(w)), sub(hit, dv(w))).sqrt());
        let RectangleLightSample {
            direction: w,
            pdf,
            st,
        } = spherical_rectangle(u, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO);
        assert_eq!(pdf, pdf_rect);
        assert!((w.length() - 1.0).abs() <= f32::EPSILON, "{w}");
        assert!(st.min_element() >= 0.0 && st.max_element() <= 1.0);
        let hit = unit3(dv(RECT_CORNER + st.x * RECT_EX + st.y * RECT_EY));
        worst_rect = worst_rect.max(dot(sub(hit, dv(w)), sub(hit, dv(w))).sqrt());
        // pdf |J| = 1 away from the square's edges.
        if u.min_element() > 0.01 && u.max_element() < 0.99 {
            let h = 1.0 / 1024.0;
            let j = area_scale(
                |u| spherical_triangle(u, TRI[0], TRI[1], TRI[2], Vec3::ZERO).direction,
                v3,
                u,
                h,
            );
            worst_jacobian = worst_jacobian.max((j * f64::from(pdf_tri) - 1.0).abs());
            let j = area_scale(
                |u| spherical_rectangle(u, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO).direction,
                v3,
                u,
                h,
            );
            worst_jacobian = worst_jacobian.max((j * f64::from(pdf_rect) - 1.0).abs());
            for cos_max in [-1.0, 0.3, 0.99] {
                let j = area_scale(|u| uniform_cone(u, cos_max), v3, u, h);
                worst_jacobian =
                    worst_jacobian.max((j * f64::from(uniform_cone_pdf(cos_max)) - 1.0).abs());
            }
        }
    }
    println!(
        "hit point vs direction: triangle {worst_tri:e}, rectangle {worst_rect:e}; |pdf |J| - 1| <= {worst_jacobian:e}"
    );
    assert!(worst_tri < 1e-6 && worst_rect < 1e-6);
    assert!(worst_jacobian < 0.02, "{worst_jacobian}");
}

/// Inverses undo their maps (the spherical triangle's at small solid
/// angles: `light_warps_stay_uniform_for_small_lights`).
#[test]
fn light_inverses_undo_the_warps() {
    let mut worst = [0.0f32; 3];
    for u in random_points(0x0027_0042, 1 << 14) {
        let w = spherical_triangle(u, TRI[0], TRI[1], TRI[2], Vec3::ZERO).direction;
        let back = spherical_triangle_inverse(w, TRI[0], TRI[1], TRI[2], Vec3::ZERO);
        worst[0] = worst[0].max((back - u).abs().max_element());
        for cos_max in [-1.0, 0.5, 0.999_99] {
            let v = uniform_cone(u, cos_max);
            let back = uniform_cone_inverse(v, cos_max);
            // The azimuth is ill-conditioned near the axis, as for the sphere.
            let r = v.truncate().length().max(1e-7) / (1.0 - cos_max).sqrt();
            worst[1] = worst[1].max((back.x - u.x).abs());
            assert!(
                periodic_distance(back.y, u.y) <= 4.0 * f32::EPSILON / r,
                "{u} -> {back}"
            );
        }
        let u3 = u.extend(u.x * 0.5 + 0.25);
        worst[2] = worst[2].max(
            (uniform_ball_inverse(uniform_ball(u3)) - u3)
                .abs()
                .max_element(),
        );
        let corner = Vec3::new(1.0, 2.0, 3.0);
        let back = rectangle_inverse(
            rectangle(u, corner, RECT_EX, RECT_EY),
            corner,
            RECT_EX,
            RECT_EY,
        );
        assert!((back - u).abs().max_element() < 1e-6, "{u} -> {back}");
    }
    println!(
        "inverse errors: spherical triangle {:e}, cone 1 - cos {:e}, ball {:e}",
        worst[0], worst[1], worst[2]
    );
    assert!(worst[0] < 1e-5, "{}", worst[0]);
    assert!(worst[1] < 1e-5, "{}", worst[1]);
    assert!(worst[2] < 1e-5, "{}", worst[2]);
}

/// Degenerate lights (seen edge-on, or a zero edge) give pdf 0 and a
/// finite direction; out-of-range input is clamped; the cone's
/// `cos_theta_max` is clamped to a non-empty cone.
#[test]
fn light_warps_at_the_edges() {
    let u = Vec2::new(0.3, 0.7);
    let TriangleLightSample {
        direction: w,
        pdf,
        barycentrics: b,
    } = spherical_triangle(u, Vec3::X, Vec3::Y, Vec3::ZERO, Vec3::new(3.0, -1.0, 0.0));
    assert!(w.is_finite() && pdf == 0.0 && b == Vec3::splat(1.0 / 3.0));
    let TriangleLightSample {
        direction: w, pdf, ..
    } = spherical_triangle(u, Vec3::X, Vec3::Y, Vec3::Z, Vec3::X);
    assert!(w.is_finite() && pdf == 0.0, "p on a vertex");
    let RectangleLightSample {
        direction: w,
        pdf,
        st,
    } = spherical_rectangle(u, RECT_CORNER, RECT_EX, Vec3::ZERO, Vec3::ZERO);
    assert!(w.is_finite() && pdf == 0.0 && st == Vec2::splat(0.5));
    let RectangleLightSample {
        direction: w, pdf, ..
    } = spherical_rectangle(u, Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(0.5, 3.0, 0.0));
    assert!(w.is_finite() && pdf == 0.0, "in the plane");
    for bad in [f32::NAN, -1.0, 1.0, 2.0] {
        let u = Vec2::new(bad, 0.4);
        let c = Vec2::new(if bad > 0.5 { LAST } else { 0.0 }, 0.4);
        assert_eq!(uniform_cone(u, 0.3), uniform_cone(c, 0.3));
        assert_eq!(
            rectangle(u, RECT_CORNER, RECT_EX, RECT_EY),
            rectangle(c, RECT_CORNER, RECT_EX, RECT_EY)
        );
        assert_eq!(
            spherical_triangle(u, TRI[0], TRI[1], TRI[2], Vec3::ZERO),
            spherical_triangle(c, TRI[0], TRI[1], TRI[2], Vec3::ZERO)
        );
        assert_eq!(
            spherical_rectangle(u, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO),
            spherical_rectangle(c, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO)
        );
        assert_eq!(uniform_ball(u.extend(bad)), uniform_ball(c.extend(c.x)));
    }
    for cos_max in [1.0, 2.0, f32::NAN, -3.0] {
        let pdf = uniform_cone_pdf(cos_max);
        assert!(valid_pdf(pdf), "{cos_max}: {pdf}");
        assert!(uniform_cone(Vec2::new(LAST, 0.5), cos_max).is_finite());
    }
    // The corners of the square are the documented points.
    assert_eq!(uniform_cone(Vec2::ZERO, 0.5), Vec3::Z);
    let rim = uniform_cone(Vec2::new(LAST, 0.0), 0.5);
    assert!((rim.z - 0.5).abs() < 1e-6 && rim.z >= 0.5 - f32::EPSILON);
    let TriangleLightSample { direction: w, .. } =
        spherical_triangle(Vec2::ZERO, TRI[0], TRI[1], TRI[2], Vec3::ZERO);
    assert!(
        (w - TRI[1].normalize()).length() < 1e-6,
        "u = 0 is vertex b: {w}"
    );
    let TriangleLightSample { direction: w, .. } =
        spherical_triangle(Vec2::new(0.0, LAST), TRI[0], TRI[1], TRI[2], Vec3::ZERO);
    assert!(
        (w - TRI[0].normalize()).length() < 1e-5,
        "u = (0, 1) is vertex a: {w}"
    );
    let TriangleLightSample { direction: w, .. } =
        spherical_triangle(Vec2::new(LAST, LAST), TRI[0], TRI[1], TRI[2], Vec3::ZERO);
    assert!(
        (w - TRI[2].normalize()).length() < 1e-5,
        "u = (1, 1) is vertex c: {w}"
    );
    let RectangleLightSample { st, .. } =
        spherical_rectangle(Vec2::ZERO, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO);
    assert!(st.length() < 1e-6, "{st}");
    let RectangleLightSample { st, .. } =
        spherical_rectangle(Vec2::splat(LAST), RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO);
    assert!((st - Vec2::ONE).length() < 1e-5, "{st}");
    let p = uniform_ball(Vec3::splat(LAST));
    assert!(p.length() <= 1.0 + f32::EPSILON && valid_pdf(uniform_ball_pdf(p)));
}

/// Item 1 for the light warps: on the 2^-24 edge grid, every direction is
/// finite and unit and the pdf positive and finite. The whole grid for the
/// cone and the rectangle; for the spherical triangle and rectangle (about
/// 300 ns a call) every 61st point and the 4096 nearest each corner.
#[test]
fn light_pdfs_are_positive_and_finite_on_the_edge_grid() {
    let unit_dir = |v: Vec3| v.is_finite() && (v.length() - 1.0).abs() <= 2.0 * f32::EPSILON;
    let checks: [(&str, &(dyn Fn(Vec2) -> bool + Sync)); 5] = [
        ("uniform_cone(0.5)", &|u| {
            unit_dir(uniform_cone(u, 0.5)) && valid_pdf(uniform_cone_pdf(0.5))
        }),
        ("uniform_cone(1 - 1e-6)", &|u| {
            let v = uniform_cone(u, 1.0 - 1e-6);
            unit_dir(v) && v.z >= 1.0 - 2e-6
        }),
        ("rectangle", &|u| {
            rectangle(u, RECT_CORNER, RECT_EX, RECT_EY).is_finite()
                && valid_pdf(rectangle_pdf(RECT_EX, RECT_EY))
        }),
        ("spherical_triangle", &|u| {
            let TriangleLightSample {
                direction: w,
                pdf,
                barycentrics: b,
            } = spherical_triangle(u, TRI[0], TRI[1], TRI[2], Vec3::ZERO);
            unit_dir(w) && valid_pdf(pdf) && b.min_element() >= 0.0
        }),
        ("spherical_rectangle", &|u| {
            let RectangleLightSample {
                direction: w,
                pdf,
                st,
            } = spherical_rectangle(u, RECT_CORNER, RECT_EX, RECT_EY, Vec3::ZERO);
            unit_dir(w) && valid_pdf(pdf) && st.is_finite()
        }),
    ];
    for (name, ok) in checks {
        let stride = if name.starts_with("spherical") { 61 } else { 1 };
        let (failed, first) = sweep_edge_grid_every(stride, ok);
        assert_eq!(
            failed, 0,
            "{name}: {failed} edge points failed, first {first:?}"
        );
    }
}

/// Small lights: a triangle and a rectangle from 0.5 sr down to 1e-12 sr
/// (a 1 cm light 10 km away). The forward maps stay uniform (chi-square on
/// 2^18 draws, 256 bins of known solid angle, false failure rate 1e-6
/// each), the pdf matches the test's own solid angle, and the inverse of
/// an f32 direction is as good as the f32 direction allows: its error is
/// within `2^-23 / sqrt(omega)` (the f32 step over the light's angular
/// size), `u.x`'s error weighted by `sqrt(u.y)` (near vertex `b`, `u.y ->
/// 0`, every `u.x` gives nearly the same direction).
#[test]
fn light_warps_stay_uniform_for_small_lights() {
    let centre = (TRI[0] + TRI[1] + TRI[2]) / 3.0;
    let inputs = random_points(0x0027_0043, 1 << 18);
    for (distance, size) in [
        (1.0f32, 1.0f32),
        (10.0, 0.1),
        (100.0, 0.1),
        (1000.0, 0.1),
        (10000.0, 0.01),
    ] {
        // The triangle.
        let t: [Vec3; 3] = core::array::from_fn(|i| centre * distance + (TRI[i] - centre) * size);
        let omega = solid_angle(dv(t[0]), dv(t[1]), dv(t[2]));
        let pdf_error =
            f64::from(spherical_triangle_pdf(t[0], t[1], t[2], Vec3::ZERO)) * omega - 1.0;
        let shares = triangle_bin_solid_angles(t);
        let statistic = check_shares(
            &format!("spherical_triangle {omega:.1e} sr"),
            &inputs,
            |u| triangle_bin(spherical_triangle(u, t[0], t[1], t[2], Vec3::ZERO).barycentrics),
            &shares,
        );
        let floor = f64::from(f32::EPSILON) / omega.sqrt();
        let mut worst = 0.0f64;
        for &u in inputs.iter().step_by(16) {
            let w = spherical_triangle(u, t[0], t[1], t[2], Vec3::ZERO).direction;
            let back = spherical_triangle_inverse(w, t[0], t[1], t[2], Vec3::ZERO);
            let ex = f64::from((back.x - u.x).abs()) * f64::from(u.y).sqrt();
            worst = worst.max(ex.max(f64::from((back.y - u.y).abs())));
        }
        println!(
            "  triangle {omega:.1e} sr: pdf error {pdf_error:.1e}, inverse error {worst:.1e} (bound {floor:.1e}), chi-square {statistic:.0}"
        );
        assert!(pdf_error.abs() < 1e-6, "{pdf_error}");
        assert!(worst < floor, "{worst} vs {floor}");
        // The rectangle.
        let (c, ex, ey) = (RECT_CORNER * distance, RECT_EX * size, RECT_EY * size);
        let at = |s: f64, t: f64| {
            let (c, x, y) = (dv(c), dv(ex), dv(ey));
            [
                c[0] + s * x[0] + t * y[0],
                c[1] + s * x[1] + t * y[1],
                c[2] + s * x[2] + t * y[2],
            ]
        };
        let mut shares = vec![0.0; 256];
        for i in 0..16 {
            for j in 0..16 {
                let (s0, t0) = (i as f64 / 16.0, j as f64 / 16.0);
                let (s1, t1) = (s0 + 1.0 / 16.0, t0 + 1.0 / 16.0);
                shares[i * 16 + j] = solid_angle(at(s0, t0), at(s1, t0), at(s1, t1))
                    + solid_angle(at(s0, t0), at(s1, t1), at(s0, t1));
            }
        }
        let omega: f64 = shares.iter().sum();
        shares.iter_mut().for_each(|s| *s /= omega);
        let pdf_error = f64::from(spherical_rectangle_pdf(c, ex, ey, Vec3::ZERO)) * omega - 1.0;
        let statistic = check_shares(
            &format!("spherical_rectangle {omega:.1e} sr"),
            &inputs,
            |u| {
                let st = spherical_rectangle(u, c, ex, ey, Vec3::ZERO).st;
                (st.x * 16.0).clamp(0.0, 15.0) as usize * 16
                    + (st.y * 16.0).clamp(0.0, 15.0) as usize
            },
            &shares,
        );
        println!(
            "  rectangle {omega:.1e} sr: pdf error {pdf_error:.1e}, chi-square {statistic:.0}"
        );
        // The rectangle's solid angle is a cancelling sum of four angles.
        let bound = if omega > 1e-9 { 1e-6 } else { 1e-2 };
        assert!(pdf_error.abs() < bound, "{pdf_error}");
    }
}

/// The irradiance at the origin (normal `+z`) from a polygon of unit
/// radiance above its horizon, exactly (Lambert's formula): half the sum
/// over the edges of the edge's angle times the z of its plane's normal.
fn polygon_irradiance(vertices: &[[f64; 3]]) -> f64 {
    let mut sum = 0.0;
    for i in 0..vertices.len() {
        let (a, b) = (
            unit3(vertices[i]),
            unit3(vertices[(i + 1) % vertices.len()]),
        );
        let angle = dot(a, b).clamp(-1.0, 1.0).acos();
        sum += angle * unit3(cross(a, b))[2];
    }
    0.5 * sum.abs()
}

/// Stratification through the solid-angle warps, measured: the RMSE of a
/// light's irradiance estimate (unit radiance, a surface at the origin
/// facing `+z`) with solid-angle sampling against area sampling, for four
/// samplers at 4, 16 and 64 samples over 512 patterns. Near the light
/// (height 0.05 under a light of size 1) the solid-angle warp must win;
/// far from it (height 20) it must not lose by more than 5%.
#[test]
fn solid_angle_sampling_beats_area_sampling_near_lights() {
    use wellspread::SamplerKind;
    let base_tri = [
        Vec3::new(-0.6, -0.4, 0.0),
        Vec3::new(0.7, -0.3, 0.0),
        Vec3::new(0.1, 0.6, 0.0),
    ];
    let (base_corner, ex, ey) = (
        Vec3::new(-0.5, -0.4, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 0.8, 0.0),
    );
    let kinds = [
        SamplerKind::Sobol,
        SamplerKind::CorrelatedMultiJittered,
        SamplerKind::Jittered,
        SamplerKind::Random,
    ];
    println!(
        "light       height  sampler                     n   RMSE solid angle  RMSE area   ratio"
    );
    for height in [0.05f32, 20.0] {
        let lift = Vec3::new(0.05, 0.0, height);
        let tri = base_tri.map(|v| v + lift);
        let corner = base_corner + lift;
        let tri_area = 0.5 * (tri[1] - tri[0]).cross(tri[2] - tri[0]).length();
        let rect_area = ex.cross(ey).length();
        let exact_tri = polygon_irradiance(&tri.map(dv));
        let exact_rect =
            polygon_irradiance(&[corner, corner + ex, corner + ex + ey, corner + ey].map(dv));
        // Estimates from one u: (solid angle, area), for each light.
        let tri_estimates = |u: Vec2| {
            let TriangleLightSample {
                direction: w, pdf, ..
            } = spherical_triangle(u, tri[0], tri[1], tri[2], Vec3::ZERO);
            let solid = f64::from(w.z.max(0.0)) / f64::from(pdf);
            let b = uniform_triangle(u);
            let x = (b.x * tri[0] + b.y * tri[1] + b.z * tri[2]).as_dvec3();
            let r2 = x.length_squared();
            let w = x / r2.sqrt();
            (solid, w.z.max(0.0) * w.z.abs() / r2 * f64::from(tri_area))
        };
        let rect_estimates = |u: Vec2| {
            let RectangleLightSample {
                direction: w, pdf, ..
            } = spherical_rectangle(u, corner, ex, ey, Vec3::ZERO);
            let solid = f64::from(w.z.max(0.0)) / f64::from(pdf);
            let x = rectangle(u, corner, ex, ey).as_dvec3();
            let r2 = x.length_squared();
            let w = x / r2.sqrt();
            (solid, w.z.max(0.0) * w.z.abs() / r2 * f64::from(rect_area))
        };
        for (light, exact, estimates) in [
            (
                "triangle",
                exact_tri,
                &tri_estimates as &dyn Fn(Vec2) -> (f64, f64),
            ),
            ("rectangle", exact_rect, &rect_estimates),
        ] {
            for kind in kinds {
                for n in [4u32, 16, 64] {
                    let sampler = kind.build(n).unwrap();
                    let (mut sq_solid, mut sq_area) = (0.0, 0.0);
                    let patterns = 512;
                    for pattern in 0..patterns {
                        let (mut solid, mut area) = (0.0, 0.0);
                        for i in 0..n {
                            let (s, a) = estimates(sampler.sample(i, pattern));
                            solid += s;
                            area += a;
                        }
                        sq_solid += (solid / f64::from(n) / exact - 1.0).powi(2);
                        sq_area += (area / f64::from(n) / exact - 1.0).powi(2);
                    }
                    let (rmse_solid, rmse_area) = (
                        (sq_solid / f64::from(patterns)).sqrt(),
                        (sq_area / f64::from(patterns)).sqrt(),
                    );
                    let ratio = rmse_solid / rmse_area;
                    println!(
                        "{light:<10} {height:7.2}  {:<26} {n:3}   {rmse_solid:14.3e}  {rmse_area:10.3e}  {ratio:6.3}",
                        kind.to_string()
                    );
                    if height < 1.0 {
                        assert!(ratio < 1.0, "{light} near, {kind} n = {n}: {ratio}");
                    } else {
                        assert!(ratio < 1.05, "{light} far, {kind} n = {n}: {ratio}");
                    }
                }
            }
        }
    }
}
