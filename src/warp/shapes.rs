//! Shapes: the disk, the hemispheres and the sphere (directions about
//! `+z`), the triangle (barycentrics), the ball and the parallelogram
//! (points), each with its pdf and inverse.

use core::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

use glam::{Vec2, Vec3};

use super::{clamp_unit, clamp_unit2, turn_fraction};

/// `4 / pi`, the inverse of the wedge angle per unit of the concentric map.
const FOUR_OVER_PI: f32 = 4.0 / PI;

/// How far past the unit circle [`concentric_disk`]'s rounding may land,
/// in squared length: `|p| <= 1 + 2^-23` gives `|p|^2 <= 1 + 2^-22 +
/// 2^-46`, and computing `|p|^2` in f32 adds up to two more roundings.
const DISK_SLACK: f32 = 4.0 * f32::EPSILON;

/// The concentric map of Shirley and Chiu: the unit square onto the unit
/// disk, square rings onto circular rings.
///
/// `u` is moved to `[-1, 1)^2`; the triangular quarter of the square it
/// falls in (`|x| >= |y|` or not) becomes a quarter wedge of the disk, with
/// radius the larger coordinate and angle proportional to the ratio of the
/// two.
///
/// # Properties
///
/// - Measure-preserving: a uniform `u` gives a uniform point on the disk,
///   pdf [`concentric_disk_pdf`] `= 1 / pi` with respect to area.
/// - Continuous and bijective from the open square onto the open disk,
///   with bounded area distortion (it is exactly area-preserving) and
///   bounded aspect-ratio distortion away from the centre: the strata of a
///   stratified or (0,m,2)-net pattern become compact cells of equal area.
///   The kinks along the square's diagonals cost a little convergence
///   against the square (`tests/warp/` measures the slope).
/// - `u = (0.5, 0.5)` maps to the centre; `|p| <= 1` within 2^-23 (one
///   rounding of `cos` and `sin`), tested at every edge of the square;
///   [`concentric_disk_pdf`] is `1 / pi` at every point the map returns,
///   including those few ulps outside the circle.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// One division, one `sin` and one `cos` (libm), a few multiplies; no
/// square root.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{concentric_disk, concentric_disk_inverse};
/// use wellspread::glam::Vec2;
/// assert_eq!(concentric_disk(Vec2::new(0.5, 0.5)), Vec2::ZERO);
/// // The right edge of the square is the rim of the disk.
/// let rim = concentric_disk(Vec2::new(1.0 - f32::EPSILON / 2.0, 0.3));
/// assert!((rim.length() - 1.0).abs() < 1e-6);
/// let u = Vec2::new(0.2, 0.7);
/// assert!((concentric_disk_inverse(concentric_disk(u)) - u).abs().max_element() < 1e-6);
/// ```
///
/// # References
///
/// Shirley & Chiu 1997, "A Low Distortion Map Between Disk and Square",
/// Journal of Graphics Tools 2(3).
#[inline]
pub fn concentric_disk(u: Vec2) -> Vec2 {
    let o = 2.0 * clamp_unit2(u) - Vec2::ONE;
    if o.x == 0.0 && o.y == 0.0 {
        return Vec2::ZERO;
    }
    let (r, theta) = if o.x.abs() > o.y.abs() {
        (o.x, FRAC_PI_4 * (o.y / o.x))
    } else {
        (o.y, FRAC_PI_2 - FRAC_PI_4 * (o.x / o.y))
    };
    let (sin, cos) = libm::sincosf(theta);
    Vec2::new(r * cos, r * sin)
}

/// The density of [`concentric_disk`] with respect to area on the unit
/// disk: `1 / pi`, for every point of the disk.
///
/// A point outside the unit disk has density 0. The disk's boundary is
/// taken with a slack of `4 f32::EPSILON` in squared length (`|p| <= 1 +
/// 2^-22`), so that every point [`concentric_disk`] returns, rounding
/// included, has density `1 / pi`: `concentric_disk(2^-24, 0)` lands at
/// squared length `1 + 2^-23`.
///
/// ```
/// use wellspread::warp::{concentric_disk, concentric_disk_pdf};
/// use wellspread::glam::Vec2;
/// assert_eq!(concentric_disk_pdf(Vec2::new(0.3, -0.4)), core::f32::consts::FRAC_1_PI);
/// assert_eq!(concentric_disk_pdf(Vec2::new(1.0, 1.0)), 0.0);
/// // A point of the map just outside the circle still has the disk's density.
/// let p = concentric_disk(Vec2::new(f32::EPSILON / 2.0, 0.0));
/// assert!(p.length_squared() > 1.0);
/// assert_eq!(concentric_disk_pdf(p), core::f32::consts::FRAC_1_PI);
/// ```
#[inline]
pub fn concentric_disk_pdf(p: Vec2) -> f32 {
    if p.length_squared() <= 1.0 + DISK_SLACK {
        core::f32::consts::FRAC_1_PI
    } else {
        0.0
    }
}

/// The inverse of [`concentric_disk`]: a point of the unit disk back to
/// the square, in `[0, 1)^2`.
///
/// # Properties
///
/// `concentric_disk_inverse(concentric_disk(u))` is `u` within a few
/// 2^-24 (one `atan` and a few roundings; tested). Points outside the disk
/// map to the square's boundary ring nearest them, clamped below 1.
///
/// # Cost
///
/// One square root, one division, one `atan` (libm).
///
/// ```
/// use wellspread::warp::{concentric_disk, concentric_disk_inverse};
/// use wellspread::glam::Vec2;
/// let u = concentric_disk_inverse(Vec2::new(0.0, -0.5));
/// assert!((concentric_disk(u) - Vec2::new(0.0, -0.5)).length() < 1e-6);
/// ```
#[inline]
pub fn concentric_disk_inverse(p: Vec2) -> Vec2 {
    let r = p.length();
    let o = if p.x.abs() > p.y.abs() {
        // The wedges around the x axis: radius |o.x|, angle pi/4 o.y/o.x.
        let ox = r.copysign(p.x);
        Vec2::new(ox, ox * FOUR_OVER_PI * libm::atanf(p.y / p.x))
    } else if p.y != 0.0 {
        // The wedges around the y axis: radius |o.y|, angle pi/2 - pi/4 o.x/o.y.
        let oy = r.copysign(p.y);
        Vec2::new(oy * FOUR_OVER_PI * libm::atanf(p.x / p.y), oy)
    } else {
        Vec2::ZERO
    };
    let u = 0.5 * (o + Vec2::ONE);
    Vec2::new(clamp_unit(u.x), clamp_unit(u.y))
}

/// Cosine-weighted directions on the hemisphere `z >= 0` (Malley's
/// method): a [`concentric_disk`] point lifted to the hemisphere,
/// `z = sqrt(1 - x^2 - y^2)`.
///
/// # Properties
///
/// - Density [`cosine_hemisphere_pdf`] `= cos(theta) / pi = z / pi` with
///   respect to solid angle: the projection of the direction onto the
///   `z = 0` plane is uniform on the disk (Nusselt's analog), so the
///   estimator of irradiance from a Lambertian BSDF has weight `pi`.
/// - Continuous, and the strata of the square become cells of equal
///   projected solid angle: what the concentric map keeps, this keeps.
/// - `z >= 2^-12` always, so [`cosine_hemisphere_pdf`]`(z)` is positive
///   and finite at every direction the map returns; `|v| = 1` within 2^-22
///   (tested at the square's edges and over random inputs). The exact map
///   reaches the rim `z = 0` on the square's boundary (`u.x = 0`, or `u.y
///   = 0`), and the rounding of the disk point can take it there from a
///   few 2^-24 inside; wherever `1 - |d|^2 < 2^-24`, `z` is lifted to
///   `2^-12` (the exact `z` one 2^-24 step inside the square is about
///   `2^-11`). The inputs this touches are a set of measure 0 in the
///   limit and of about 2^-22 of the 2^-24 grid. An estimator may still
///   prefer the cancelled weight (`f cos / pdf = pi f`) to a division.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// [`concentric_disk`] and one square root.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{cosine_hemisphere, cosine_hemisphere_inverse, cosine_hemisphere_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// assert_eq!(cosine_hemisphere(Vec2::new(0.5, 0.5)), Vec3::Z);
/// let v = cosine_hemisphere(Vec2::new(0.9, 0.25));
/// assert!(v.z > 0.0 && (v.length() - 1.0).abs() < 1e-6);
/// assert_eq!(cosine_hemisphere_pdf(v.z), v.z / core::f32::consts::PI);
/// let u = cosine_hemisphere_inverse(v);
/// assert!((u - Vec2::new(0.9, 0.25)).abs().max_element() < 1e-5);
/// ```
///
/// # References
///
/// - Malley 1988, "A shading method for computer generated images",
///   Master's thesis, University of Utah.
/// - Shirley & Chiu 1997, "A Low Distortion Map Between Disk and Square",
///   Journal of Graphics Tools 2(3).
#[inline]
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let d = concentric_disk(u);
    // 1 - |d|^2 >= 2^-24: z >= 2^-12 where the disk point is on (or a
    // rounding past) the rim.
    let z = libm::sqrtf((1.0 - d.length_squared()).max(f32::EPSILON / 2.0));
    Vec3::new(d.x, d.y, z)
}

/// The density of [`cosine_hemisphere`] with respect to solid angle,
/// `cos(theta) / pi`, from `cos_theta` (the direction's `z` in the local
/// frame). Directions below the surface (`cos_theta < 0`) have density 0.
///
/// ```
/// use wellspread::warp::cosine_hemisphere_pdf;
/// use core::f32::consts::FRAC_1_PI;
/// assert_eq!(cosine_hemisphere_pdf(1.0), FRAC_1_PI);
/// assert_eq!(cosine_hemisphere_pdf(-0.5), 0.0);
/// ```
#[inline]
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) * core::f32::consts::FRAC_1_PI
}

/// The inverse of [`cosine_hemisphere`]: a direction (unit length, `z >=
/// 0`) back to the square, through [`concentric_disk_inverse`] of its `x`
/// and `y`.
///
/// ```
/// use wellspread::warp::{cosine_hemisphere, cosine_hemisphere_inverse};
/// use wellspread::glam::Vec2;
/// let u = Vec2::new(0.125, 0.5);
/// assert!((cosine_hemisphere_inverse(cosine_hemisphere(u)) - u).abs().max_element() < 1e-5);
/// ```
#[inline]
pub fn cosine_hemisphere_inverse(v: Vec3) -> Vec2 {
    concentric_disk_inverse(Vec2::new(v.x, v.y))
}

/// Uniform directions on the hemisphere `z >= 0`: `z = u.x`, azimuth
/// `2 pi u.y` (Archimedes' hat-box theorem: the cylinder's area projects
/// onto the sphere's).
///
/// # Properties
///
/// - Density [`uniform_hemisphere_pdf`] `= 1 / (2 pi)` with respect to
///   solid angle.
/// - Exactly area-preserving and smooth in the interior: each stratum
///   `[a, b) x [c, d)` of the square is the zone `a <= z < b` cut between
///   two azimuths, of solid angle `2 pi (b - a)(d - c)`. The strata near the
///   pole (`u.x` near 1) are thin slivers, and the map's derivative grows
///   like `1 / sqrt(1 - z)` there.
/// - `z` in `[0, 1)`; `|v| = 1` within 2^-22, using `1 - z^2 =
///   (1 - z)(1 + z)` so the radius stays accurate near the pole.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// One square root, one `sin` and one `cos` (libm).
///
/// # Examples
///
/// ```
/// use wellspread::warp::{uniform_hemisphere, uniform_hemisphere_inverse};
/// use wellspread::glam::Vec2;
/// let v = uniform_hemisphere(Vec2::new(0.0, 0.25));
/// assert!(v.z == 0.0 && (v.y - 1.0).abs() < 1e-6);
/// let u = Vec2::new(0.6, 0.8);
/// assert!((uniform_hemisphere_inverse(uniform_hemisphere(u)) - u).abs().max_element() < 1e-5);
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.5.2.
#[inline]
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let u = clamp_unit2(u);
    let z = u.x;
    let r = libm::sqrtf(((1.0 - z) * (1.0 + z)).max(0.0));
    let (sin, cos) = libm::sincosf(TAU * u.y);
    Vec3::new(r * cos, r * sin, z)
}

/// The density of [`uniform_hemisphere`] with respect to solid angle,
/// `1 / (2 pi)` for every direction with `z >= 0` (0 below).
///
/// ```
/// use wellspread::warp::uniform_hemisphere_pdf;
/// use wellspread::glam::Vec3;
/// assert_eq!(uniform_hemisphere_pdf(Vec3::Z), 0.5 / core::f32::consts::PI);
/// assert_eq!(uniform_hemisphere_pdf(-Vec3::Z), 0.0);
/// ```
#[inline]
pub fn uniform_hemisphere_pdf(v: Vec3) -> f32 {
    if v.z >= 0.0 {
        0.5 * core::f32::consts::FRAC_1_PI
    } else {
        0.0
    }
}

/// The inverse of [`uniform_hemisphere`]: `(z, azimuth / 2 pi)`, in
/// `[0, 1)^2`.
///
/// The azimuth of the pole is undefined; there the result's `y` is
/// whatever `atan2` gives, and near it `y` is ill-conditioned (an error
/// of `e` in the direction moves it by about `e / r`, with `r` the
/// distance from the axis).
///
/// ```
/// use wellspread::warp::{uniform_hemisphere, uniform_hemisphere_inverse};
/// use wellspread::glam::Vec2;
/// let u = Vec2::new(0.3, 0.1);
/// assert!((uniform_hemisphere_inverse(uniform_hemisphere(u)) - u).abs().max_element() < 1e-5);
/// ```
#[inline]
pub fn uniform_hemisphere_inverse(v: Vec3) -> Vec2 {
    Vec2::new(clamp_unit(v.z), turn_fraction(v.x, v.y))
}

/// Uniform directions on the whole sphere: `z = 1 - 2 u.x`, azimuth
/// `2 pi u.y` (the Lambert cylindrical equal-area projection).
///
/// # Properties
///
/// - Density [`uniform_sphere_pdf`] `= 1 / (4 pi)` with respect to solid
///   angle.
/// - Exactly area-preserving and smooth in the interior, as
///   [`uniform_hemisphere`], with the same slivers at both poles.
/// - `z` in `(-1, 1]`; `|v| = 1` within 2^-22, the radius computed as
///   `2 sqrt(u.x (1 - u.x))`, accurate at both poles.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// One square root, one `sin` and one `cos` (libm).
///
/// # Examples
///
/// ```
/// use wellspread::warp::{uniform_sphere, uniform_sphere_inverse, uniform_sphere_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// assert_eq!(uniform_sphere(Vec2::new(0.0, 0.0)), Vec3::Z);
/// let v = uniform_sphere(Vec2::new(0.75, 0.5));
/// assert!(v.z == -0.5 && (v.length() - 1.0).abs() < 1e-6);
/// assert_eq!(uniform_sphere_pdf(v), 0.25 / core::f32::consts::PI);
/// assert!((uniform_sphere_inverse(v) - Vec2::new(0.75, 0.5)).abs().max_element() < 1e-6);
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.5.2.
#[inline]
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let u = clamp_unit2(u);
    let z = 1.0 - 2.0 * u.x;
    // 1 - z^2 = 4 u.x (1 - u.x): no cancellation near either pole.
    let r = 2.0 * libm::sqrtf((u.x * (1.0 - u.x)).max(0.0));
    let (sin, cos) = libm::sincosf(TAU * u.y);
    Vec3::new(r * cos, r * sin, z)
}

/// The density of [`uniform_sphere`] with respect to solid angle,
/// `1 / (4 pi)`, for every direction (the argument is there for symmetry
/// with [`uniform_hemisphere_pdf`], whose density depends on it).
///
/// ```
/// use wellspread::warp::uniform_sphere_pdf;
/// use wellspread::glam::Vec3;
/// assert_eq!(uniform_sphere_pdf(Vec3::X), 0.25 / core::f32::consts::PI);
/// ```
#[inline]
pub fn uniform_sphere_pdf(v: Vec3) -> f32 {
    let _ = v;
    0.25 * core::f32::consts::FRAC_1_PI
}

/// The inverse of [`uniform_sphere`]: `((1 - z) / 2, azimuth / 2 pi)`, in
/// `[0, 1)^2`. The azimuth is undefined at the poles and ill-conditioned
/// near them, as for [`uniform_hemisphere_inverse`].
///
/// ```
/// use wellspread::warp::{uniform_sphere, uniform_sphere_inverse};
/// use wellspread::glam::Vec2;
/// let u = Vec2::new(0.9, 0.6);
/// assert!((uniform_sphere_inverse(uniform_sphere(u)) - u).abs().max_element() < 1e-5);
/// ```
#[inline]
pub fn uniform_sphere_inverse(v: Vec3) -> Vec2 {
    Vec2::new(clamp_unit(0.5 * (1.0 - v.z)), turn_fraction(v.x, v.y))
}

/// Uniform barycentric coordinates `(b0, b1, b2)` on a triangle, by
/// Heitz's low-distortion map: the square is cut along its diagonal and
/// each half is sheared onto the triangle.
///
/// Below the diagonal (`u.x >= u.y`), `b1 = u.y / 2` and `b0 = u.x - b1`;
/// above it, `b0 = u.x / 2` and `b1 = u.y - b0`; in both, `b2 = 1 -
/// max(u.x, u.y)`. The point `b0 p0 + b1 p1 + b2 p2` is then uniform on
/// the triangle `p0 p1 p2`.
///
/// # Properties
///
/// - Measure-preserving: piecewise linear with constant Jacobian, so the
///   point is uniform on the triangle, pdf [`uniform_triangle_pdf`]`(area)
///   = 1 / area` with respect to area, whatever the triangle.
/// - Continuous across the diagonal, and each half is affine: strata of
///   the square become triangles and quadrilaterals of equal area and
///   bounded shape distortion, unlike the square-root map (`b0 = 1 -
///   sqrt(u.x)`), which squeezes strata into slivers near a vertex.
/// - Every coordinate is `>= 0` (`b2 >= 2^-24` for `u` in `[0, 1)^2`) and
///   `b0 + b1 + b2 = 1` within 2^-23, tested at every edge of the square.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// One comparison, two multiplies, two subtractions: no square root.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{uniform_triangle, uniform_triangle_inverse, uniform_triangle_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// let b = uniform_triangle(Vec2::new(0.5, 0.5));
/// assert_eq!(b, Vec3::new(0.25, 0.25, 0.5));
/// // A point on the triangle (0,0), (2,0), (0,1), of area 1.
/// let (p0, p1, p2) = (Vec2::ZERO, Vec2::new(2.0, 0.0), Vec2::new(0.0, 1.0));
/// let b = uniform_triangle(Vec2::new(0.3, 0.8));
/// let p = b.x * p0 + b.y * p1 + b.z * p2;
/// assert!(p.x >= 0.0 && p.y >= 0.0 && p.x / 2.0 + p.y <= 1.0);
/// assert_eq!(uniform_triangle_pdf(1.0), 1.0);
/// assert!((uniform_triangle_inverse(b) - Vec2::new(0.3, 0.8)).abs().max_element() < 1e-6);
/// ```
///
/// # References
///
/// Heitz 2019, "A Low-Distortion Map Between Triangle and Square",
/// technical report, Unity Technologies (hal-02073696).
#[inline]
pub fn uniform_triangle(u: Vec2) -> Vec3 {
    let u = clamp_unit2(u);
    if u.x < u.y {
        let b0 = 0.5 * u.x;
        Vec3::new(b0, u.y - b0, 1.0 - u.y)
    } else {
        let b1 = 0.5 * u.y;
        Vec3::new(u.x - b1, b1, 1.0 - u.x)
    }
}

/// The density of [`uniform_triangle`]'s point with respect to area on a
/// triangle of area `area`: `1 / area`.
///
/// The barycentrics are the same for every triangle; only this density
/// depends on it. A degenerate triangle (`area = 0`) gives `+inf`, which
/// makes a light-sampling weight `1 / pdf` zero, as it should be for a
/// light with no area.
///
/// ```
/// use wellspread::warp::uniform_triangle_pdf;
/// assert_eq!(uniform_triangle_pdf(0.5), 2.0);
/// assert_eq!(uniform_triangle_pdf(0.0), f32::INFINITY);
/// ```
#[inline]
pub fn uniform_triangle_pdf(area: f32) -> f32 {
    1.0 / area
}

/// The inverse of [`uniform_triangle`]: barycentrics back to the square,
/// in `[0, 1)^2`. Only `b0` and `b1` are read (`b2 = 1 - b0 - b1`).
///
/// `b1 > b0` came from above the diagonal, `(2 b0, b0 + b1)`; otherwise
/// from below it, `(b0 + b1, 2 b1)`; both agree on the diagonal. Exact up
/// to one rounding of the sum.
///
/// ```
/// use wellspread::warp::{uniform_triangle, uniform_triangle_inverse};
/// use wellspread::glam::{Vec2, Vec3};
/// assert_eq!(uniform_triangle_inverse(Vec3::new(0.25, 0.25, 0.5)), Vec2::new(0.5, 0.5));
/// let u = Vec2::new(0.125, 0.875);
/// assert_eq!(uniform_triangle_inverse(uniform_triangle(u)), u);
/// ```
#[inline]
pub fn uniform_triangle_inverse(b: Vec3) -> Vec2 {
    let sum = clamp_unit(b.x + b.y);
    if b.x < b.y {
        Vec2::new(clamp_unit(2.0 * b.x), sum)
    } else {
        Vec2::new(sum, clamp_unit(2.0 * b.y))
    }
}

/// Uniform points in the unit ball: the direction of [`uniform_sphere`]
/// from `(u.x, u.y)` at radius `cbrt(u.z)`.
///
/// # Properties
///
/// - Density [`uniform_ball_pdf`] `= 3 / (4 pi)` with respect to volume:
///   the volume inside radius `r` is `r^3` of the ball's, so `r =
///   cbrt(u.z)` makes it uniform, and the direction is uniform and
///   independent. Strata of the cube become shells cut into equal solid
///   angles, of equal volume. A renderer's fuzzy reflection draws it from
///   one 3D draw (`Domain::next_3d`), which keeps the three dimensions
///   stratified together.
/// - `|p| <= 1` within 2^-22; `u.z = 0` is the centre.
/// - Input outside `[0, 1)^3` is clamped into it (NaN to 0).
///
/// # Cost
///
/// [`uniform_sphere`] and one `cbrt` (libm).
///
/// # Examples
///
/// ```
/// use wellspread::warp::{uniform_ball, uniform_ball_inverse, uniform_ball_pdf};
/// use wellspread::glam::Vec3;
/// assert_eq!(uniform_ball(Vec3::new(0.3, 0.6, 0.0)), Vec3::ZERO);
/// let p = uniform_ball(Vec3::new(0.3, 0.6, 0.125));
/// assert!((p.length() - 0.5).abs() < 1e-6);
/// assert_eq!(uniform_ball_pdf(p), 0.75 * core::f32::consts::FRAC_1_PI);
/// assert!((uniform_ball_inverse(p) - Vec3::new(0.3, 0.6, 0.125)).abs().max_element() < 1e-5);
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.5.2 (the sphere), with the radius by inversion of `r^3`.
#[inline]
pub fn uniform_ball(u: Vec3) -> Vec3 {
    libm::cbrtf(clamp_unit(u.z)) * uniform_sphere(Vec2::new(u.x, u.y))
}

/// The density of [`uniform_ball`] with respect to volume, `3 / (4 pi)`
/// inside the unit ball (with a slack of a few ulps for the map's
/// rounding, `|p|^2 <= 1 + 2^-20`) and 0 outside.
///
/// ```
/// use wellspread::warp::uniform_ball_pdf;
/// use wellspread::glam::Vec3;
/// assert_eq!(uniform_ball_pdf(Vec3::new(0.5, 0.5, 0.5)), 0.75 * core::f32::consts::FRAC_1_PI);
/// assert_eq!(uniform_ball_pdf(Vec3::ONE), 0.0);
/// ```
#[inline]
pub fn uniform_ball_pdf(p: Vec3) -> f32 {
    if p.length_squared() <= 1.0 + 2.0 * DISK_SLACK {
        0.75 * core::f32::consts::FRAC_1_PI
    } else {
        0.0
    }
}

/// The inverse of [`uniform_ball`]: [`uniform_sphere_inverse`] of the
/// direction and `|p|^3`, in `[0, 1)^3`. The centre (no direction) gives
/// `(0, 0, 0)`.
///
/// ```
/// use wellspread::warp::{uniform_ball, uniform_ball_inverse};
/// use wellspread::glam::Vec3;
/// let u = Vec3::new(0.8, 0.1, 0.5);
/// assert!((uniform_ball_inverse(uniform_ball(u)) - u).abs().max_element() < 1e-5);
/// ```
#[inline]
pub fn uniform_ball_inverse(p: Vec3) -> Vec3 {
    let r = p.length();
    if r == 0.0 {
        return Vec3::ZERO;
    }
    uniform_sphere_inverse(p / r).extend(clamp_unit(r * r * r))
}

/// Uniform points on the parallelogram (a rectangle when the edges are
/// perpendicular) `corner + s ex + t ey`, `s, t` in `[0, 1)`: `s = u.x`,
/// `t = u.y`.
///
/// # Properties
///
/// - Affine, so exactly measure-preserving: density [`rectangle_pdf`] `=
///   1 / |ex x ey|` with respect to area, and strata of the square become
///   equal parallelograms.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// Two multiply-adds per coordinate.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{rectangle, rectangle_inverse, rectangle_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// let (corner, ex, ey) = (Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.5, 0.0, 0.0), Vec3::new(0.0, 0.0, 0.25));
/// let p = rectangle(Vec2::new(0.5, 0.5), corner, ex, ey);
/// assert_eq!(p, Vec3::new(0.25, 2.0, 0.125));
/// assert_eq!(rectangle_pdf(ex, ey), 8.0);
/// assert_eq!(rectangle_inverse(p, corner, ex, ey), Vec2::new(0.5, 0.5));
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section 12.5 (area lights).
#[inline]
pub fn rectangle(u: Vec2, corner: Vec3, ex: Vec3, ey: Vec3) -> Vec3 {
    let u = clamp_unit2(u);
    corner + u.x * ex + u.y * ey
}

/// The density of [`rectangle`]'s point with respect to area, `1 / |ex x
/// ey|`, computed in f64 and rounded once, so it is right for every f32
/// edge (in f32, `|ex x ey|^2` overflows from edges of about 1e10 and
/// underflows below about 1e-10). A degenerate parallelogram (parallel or
/// zero edges), or one of area below about 3e-39 (where `1 / area`
/// overflows f32), gives `+inf`, as [`uniform_triangle_pdf`] does for a
/// triangle of area 0.
///
/// ```
/// use wellspread::warp::rectangle_pdf;
/// use wellspread::glam::Vec3;
/// assert_eq!(rectangle_pdf(Vec3::X, 4.0 * Vec3::Y), 0.25);
/// assert_eq!(rectangle_pdf(Vec3::X, Vec3::X), f32::INFINITY);
/// ```
#[inline]
pub fn rectangle_pdf(ex: Vec3, ey: Vec3) -> f32 {
    (1.0 / ex.as_dvec3().cross(ey.as_dvec3()).length()) as f32
}

/// The inverse of [`rectangle`]: the `(s, t)` of a point of the
/// parallelogram's plane, by the 2 x 2 normal equations in f64 (the point
/// is projected onto the plane first), clamped into `[0, 1)^2`. A
/// degenerate parallelogram gives `(0, 0)`.
///
/// ```
/// use wellspread::warp::{rectangle, rectangle_inverse};
/// use wellspread::glam::{Vec2, Vec3};
/// // A parallelogram, not a rectangle.
/// let (corner, ex, ey) = (Vec3::ONE, Vec3::new(2.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 1.0));
/// let u = Vec2::new(0.25, 0.75);
/// assert!((rectangle_inverse(rectangle(u, corner, ex, ey), corner, ex, ey) - u).abs().max_element() < 1e-6);
/// ```
#[inline]
pub fn rectangle_inverse(p: Vec3, corner: Vec3, ex: Vec3, ey: Vec3) -> Vec2 {
    let (d, ex, ey) = ((p - corner).as_dvec3(), ex.as_dvec3(), ey.as_dvec3());
    let (xx, xy, yy) = (ex.dot(ex), ex.dot(ey), ey.dot(ey));
    let (bx, by) = (d.dot(ex), d.dot(ey));
    let det = xx * yy - xy * xy;
    if det.is_nan() || det <= 0.0 {
        return Vec2::ZERO;
    }
    Vec2::new(
        clamp_unit(((bx * yy - by * xy) / det) as f32),
        clamp_unit(((by * xx - bx * xy) / det) as f32),
    )
}
