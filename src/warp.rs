//! Maps from the unit square to the domains a renderer samples (disk,
//! hemisphere, sphere, triangle, lights: a cone, a ball, a rectangle, and
//! triangles and rectangles by solid angle) and discrete choices (uniform
//! and weighted), each with its pdf and, where one exists, its inverse.
//!
//! A well-distributed pattern pays off only if the map that carries it to
//! the lens, the light or the BSDF keeps its stratification. Every map here
//! is measure-preserving (a uniform point on the square gives a point with
//! the stated pdf, checked by chi-square tests on equal-measure bins) and
//! continuous, so strata of the square become connected cells of equal
//! measure on the target, compact away from the sphere maps' poles: warped
//! Owen-scrambled [`Sobol`](crate::Sobol) points keep converging faster than
//! random ones. On a smooth integrand, the RMSE of 2^4 to 2^12 warped Sobol
//! points falls like `n^-1.25` to `n^-1.35` for every map here, against
//! `n^-0.5` for random points (`tests/warp.rs` measures the slopes).
//!
//! Every function is pure and `no_std`; the trigonometry is
//! [`libm`](https://docs.rs/libm)'s, whatever the features, so the values
//! are the same in `std` and `no_std` builds. Directions are in a local
//! frame with the normal along `+z`.
//!
//! | map | pdf | measure | inverse |
//! | --- | --- | --- | --- |
//! | [`concentric_disk`] | `1 / pi` | area on the unit disk | [`concentric_disk_inverse`] |
//! | [`cosine_hemisphere`] | `cos(theta) / pi` | solid angle | [`cosine_hemisphere_inverse`] |
//! | [`uniform_hemisphere`] | `1 / (2 pi)` | solid angle | [`uniform_hemisphere_inverse`] |
//! | [`uniform_sphere`] | `1 / (4 pi)` | solid angle | [`uniform_sphere_inverse`] |
//! | [`uniform_triangle`] | `1 / area` | area on the triangle | [`uniform_triangle_inverse`] |
//! | [`uniform_cone`] | `1 / (2 pi (1 - cos_theta_max))` | solid angle | [`uniform_cone_inverse`] |
//! | [`uniform_ball`] (from `[0, 1)^3`) | `3 / (4 pi)` | volume of the unit ball | [`uniform_ball_inverse`] |
//! | [`rectangle`] | `1 / abs(ex x ey)` | area on the parallelogram | [`rectangle_inverse`] |
//! | [`spherical_triangle`] | `1 / omega` | solid angle of a triangle light | [`spherical_triangle_inverse`] |
//! | [`spherical_rectangle`] | `1 / omega` | solid angle of a rectangle light | none |
//! | [`discrete`] | `1 / n` | counting | [`discrete_inverse`] |
//! | [`Discrete`] (`alloc`) | `w_i / sum w` | counting | [`Discrete::inverse`] |
//! | [`AliasTable`] (`alloc`) | `w_i / sum w` | counting | none (not monotone) |
//!
//! Inputs are points of `[0, 1)^2` (or `[0, 1)` for [`discrete`]), as every
//! wellspread sampler returns them. Inverses return points of `[0, 1)`,
//! clamped to [`ONE_MINUS_EPSILON`] where rounding would reach 1.
//!
//! # The pdf where the map lands
//!
//! For every input of `[0, 1)^k`, each map's pdf at the point it returns is
//! positive and finite, so a renderer may divide by it: `tests/warp.rs`
//! sweeps the whole 2^-24 grid along every edge of the square (the four
//! edges, 2^26 points per map) and checks it. The density functions accept
//! the few ulps by which a map's rounding lands outside its exact domain
//! (the concentric disk overshoots the unit circle by up to 2^-23).
//!
//! # Out-of-range input
//!
//! Every map clamps its input into `[0, 1)` before using it, coordinate by
//! coordinate: a negative number (and NaN) is read as 0, a number at or
//! above 1 as [`ONE_MINUS_EPSILON`]. Out-of-range input therefore gives a
//! point of the domain with a valid pdf, in debug and release builds alike
//! ([`discrete`] also asserts the range in debug builds, as documented
//! there). The clamp costs two comparisons per coordinate and changes
//! nothing for input inside `[0, 1)`.
//!
//! ```
//! use wellspread::{Sampler2D, Sobol, warp};
//!
//! // A thin lens of radius 0.1 and a cosine-weighted bounce, from one set.
//! let sobol = Sobol::new(16)?;
//! for index in 0..16 {
//!     let lens = 0.1 * warp::concentric_disk(sobol.sample(index, 1));
//!     let bounce = warp::cosine_hemisphere(sobol.sample(index, 2));
//!     assert!(lens.length() <= 0.1 + 1e-6 && bounce.z >= 0.0);
//!     let weight = 1.0 / warp::cosine_hemisphere_pdf(bounce.z);
//!     assert!(weight.is_finite());
//! }
//! # Ok::<(), wellspread::Error>(())
//! ```
//!
//! # References
//!
//! - Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
//!   appendix A.5 (sampling multidimensional functions).
//! - Mitsuba 3's `warp.h` keeps each map, its pdf and its inverse together;
//!   this module follows that layout.

use core::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

use glam::{DVec2, DVec3, Vec2, Vec3};

use crate::primitives::ONE_MINUS_EPSILON;

/// `4 / pi`, the inverse of the wedge angle per unit of the concentric map.
const FOUR_OVER_PI: f32 = 4.0 / PI;

/// Clamps a coordinate to `[0, ONE_MINUS_EPSILON]`: inverses round, and a
/// sample coordinate must stay below 1.
#[inline]
#[allow(clippy::manual_clamp)] // `clamp` keeps a NaN; `max` first maps it to 0.
pub(crate) fn clamp_unit(x: f32) -> f32 {
    x.max(0.0).min(ONE_MINUS_EPSILON)
}

/// Clamps both coordinates of a map's input into `[0, 1)` (NaN to 0).
#[inline]
fn clamp_unit2(u: Vec2) -> Vec2 {
    Vec2::new(clamp_unit(u.x), clamp_unit(u.y))
}

/// How far past the unit circle [`concentric_disk`]'s rounding may land,
/// in squared length: `|p| <= 1 + 2^-23` gives `|p|^2 <= 1 + 2^-22 +
/// 2^-46`, and computing `|p|^2` in f32 adds up to two more roundings.
const DISK_SLACK: f32 = 4.0 * f32::EPSILON;

/// The atan2 angle of `(x, y)` as a fraction of a turn, in `[0, 1)`.
#[inline]
fn turn_fraction(x: f32, y: f32) -> f32 {
    let phi = libm::atan2f(y, x) * (1.0 / TAU);
    // atan2 is in [-pi, pi]: negative angles wrap to the upper half.
    clamp_unit(if phi < 0.0 { phi + 1.0 } else { phi })
}

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
///   against the square (`tests/warp.rs` measures the slope).
/// - `u = (0.5, 0.5)` maps to the centre; `|p| <= 1` within 2^-23 (one
///   rounding of `cos` and `sin`), tested at every edge of the square;
///   [`concentric_disk_pdf`] is `1 / pi` at every point the map returns,
///   including those few ulps outside the circle.
/// - Input outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// One division, one `sin` and one `cos` (libm), a few multiplies; no
/// square root. About 70 x86-64 instructions a call (callgrind, release
/// build), most of them libm's `sincosf`.
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
/// [`concentric_disk`] and one square root: about 80 x86-64 instructions.
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
/// One square root, one `sin` and one `cos` (libm): about 70 x86-64
/// instructions.
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
/// One square root, one `sin` and one `cos` (libm): about 65 x86-64
/// instructions.
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
/// One comparison, two multiplies, two subtractions: no square root, a
/// handful of instructions.
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

/// A choice among `n` equally likely items from one number `u` in `[0,
/// 1)`, and `u` remapped to `[0, 1)` for reuse: `(floor(u n), frac(u n))`.
///
/// The remapped number is uniform and independent of the choice when `u`
/// is uniform, so one stratified dimension can pick a light and then a
/// point on it (pbrt's sample reuse). It carries the bits of `u` that the
/// choice did not use: with `u` a multiple of 2^-24 (every wellspread
/// sampler's output) and `n = 2^k`, it has `24 - k` bits left.
///
/// # Properties
///
/// - The choice is exactly `floor(u n)`, computed in integers from the
///   bits of `u` (no rounding), so each index gets exactly the measure
///   `1 / n` of `[0, 1)` ([`discrete_pdf`]) and a stratified `u` gives
///   stratified choices. `u = 1 - 2^-24` gives `n - 1` for every `n` up to
///   2^24.
/// - The remapped `u` is in `[0, 1)`: it is rounded to f32 and clamped to
///   [`ONE_MINUS_EPSILON`]; it is 0 at the left edge of each choice's
///   interval and monotone inside it. When the `u` of a pixel's `2^m`
///   samples are one per interval of `2^-m` (a sequence's 1D draws) and
///   `n = 2^k <= 2^m`, each choice's `2^(m-k)` remapped values are one per
///   interval of `2^-(m-k)`: the reuse keeps the strata.
///
/// # Limits
///
/// The f32 numbers below 1 are 2^-24 apart near 1, so above `n = 2^24` not
/// every choice is reachable: `u = 1 - 2^-24` picks `n - ceil(n / 2^24)`
/// (`u32::MAX - 256` for `n = u32::MAX`), and a sampler's 2^-24 grid
/// reaches every `ceil(n / 2^24)`-th choice. Split larger choices into two
/// draws.
///
/// `n = 0` has no valid choice: debug builds panic on it, release builds
/// return `(0, u)` as for `n = 1`; use [`discrete_checked`] where `n` can
/// be 0. A `u` outside `[0, 1)` is clamped into it (NaN to 0), also
/// checked in debug builds.
///
/// # Cost
///
/// A 24 x 32-bit integer multiply, two shifts and one int-to-float
/// conversion; no division. About 25 x86-64 instructions.
///
/// # Examples
///
/// ```
/// use wellspread::warp::discrete;
/// assert_eq!(discrete(0.0, 3), (0, 0.0));
/// assert_eq!(discrete(0.5, 4), (2, 0.0));
/// let (light, u) = discrete(0.7, 2);
/// assert!(light == 1 && (u - 0.4).abs() < 1e-6);
/// // The largest u below 1 always picks the last item.
/// let last = 1.0 - f32::EPSILON / 2.0;
/// for n in [1, 3, 1000, 1 << 24] {
///     let (i, u) = discrete(last, n);
///     assert!(i == n - 1 && u < 1.0);
/// }
/// // Above 2^24 choices, f32 cannot reach the last ones.
/// assert_eq!(discrete(last, u32::MAX).0, u32::MAX - 256);
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.1 (sampling discrete distributions, remapping the sample).
#[inline]
pub fn discrete(u: f32, n: u32) -> (u32, f32) {
    debug_assert!(n > 0, "discrete: n = 0 has no valid choice");
    debug_assert!(
        (0.0..1.0).contains(&u),
        "discrete: u = {u} is outside [0, 1)"
    );
    let n = n.max(1);
    let u = clamp_unit(u);
    // u = m 2^-shift exactly, with m below 2^24 (so u n = m n 2^-shift,
    // exact in 56 bits); subnormals have the smallest exponent.
    let bits = u.to_bits();
    let exponent = (bits >> 23) & 0xff;
    if exponent == 0 && bits & 0x007f_ffff == 0 {
        return (0, 0.0);
    }
    let (m, shift) = if exponent == 0 {
        (bits & 0x007f_ffff, 149)
    } else {
        ((bits & 0x007f_ffff) | 0x0080_0000, 150 - exponent)
    };
    // u < 1 means exponent <= 126, so shift >= 24.
    if shift >= 64 {
        // u n < 2^-8: the choice is 0, and the f32 product (two roundings)
        // is as accurate as the caller's u.
        return (0, clamp_unit(u * n as f32));
    }
    let scaled = u64::from(m) * u64::from(n);
    let index = (scaled >> shift) as u32;
    let rest = scaled & ((1u64 << shift) - 1);
    // rest 2^-shift, rounded once to f32 (the scaling by a power of two is exact).
    let remapped = (rest as f32) * f32::from_bits((127 - shift) << 23);
    (index, clamp_unit(remapped))
}

/// [`discrete`] for an `n` that may be 0: `None` for `n = 0`, otherwise
/// `Some(discrete(u, n))`.
///
/// ```
/// use wellspread::warp::discrete_checked;
/// assert_eq!(discrete_checked(0.5, 0), None);
/// assert_eq!(discrete_checked(0.5, 2), Some((1, 0.0)));
/// ```
#[inline]
pub fn discrete_checked(u: f32, n: u32) -> Option<(u32, f32)> {
    (n > 0).then(|| discrete(u, n))
}

/// The probability of each choice of [`discrete`]: `1 / n` (0 for
/// `n = 0`, which has no choice).
///
/// ```
/// use wellspread::warp::discrete_pdf;
/// assert_eq!(discrete_pdf(4), 0.25);
/// assert_eq!(discrete_pdf(0), 0.0);
/// ```
#[inline]
pub fn discrete_pdf(n: u32) -> f32 {
    if n == 0 { 0.0 } else { 1.0 / n as f32 }
}

/// The inverse of [`discrete`]: `(index + remapped) / n`, computed in f64
/// and rounded once to f32, clamped to [`ONE_MINUS_EPSILON`]. With `n =
/// 0` it returns `remapped`, as [`discrete`] treats `n = 0` as 1.
///
/// `discrete_inverse(discrete(u, n), n)` is `u` up to the rounding of the
/// remapped value (exactly `u` when `u` is a multiple of 2^-24 and `n` a
/// power of two up to 2^24).
///
/// ```
/// use wellspread::warp::{discrete, discrete_inverse};
/// let (i, r) = discrete(0.8125, 8);
/// assert_eq!(discrete_inverse(i, r, 8), 0.8125);
/// ```
#[inline]
pub fn discrete_inverse(index: u32, remapped: f32, n: u32) -> f32 {
    let n = n.max(1);
    clamp_unit(((f64::from(index) + f64::from(remapped)) / f64::from(n)) as f32)
}

// ---------------------------------------------------------------------------
// Lights: a cone of directions, a ball, a rectangle, and triangles and
// rectangles sampled by solid angle.

/// `cos_theta_max` of a cone, clamped to `[-1, ONE_MINUS_EPSILON]` (NaN to
/// -1): the cone is never empty, so its pdf is finite.
#[inline]
#[allow(clippy::manual_clamp)] // `clamp` keeps a NaN; `max` first maps it to -1.
fn cone_cos(cos_theta_max: f32) -> f32 {
    cos_theta_max.max(-1.0).min(ONE_MINUS_EPSILON)
}

/// Uniform directions in the cone of half-angle `theta_max` around `+z`:
/// `1 - cos(theta) = u.x (1 - cos_theta_max)`, azimuth `2 pi u.y`.
///
/// The directions toward a spherical light of radius `r` at distance `d`
/// from the shading point fill the cone with `cos_theta_max = sqrt(1 -
/// (r / d)^2)`; rotate the result into a frame whose `z` points at the
/// light's centre.
///
/// # Properties
///
/// - Density [`uniform_cone_pdf`] `= 1 / (2 pi (1 - cos_theta_max))` with
///   respect to solid angle, constant in the cone: the map is
///   [`uniform_sphere`]'s zones cut at `cos_theta_max` (Archimedes), so it
///   is exactly area-preserving and strata of the square become equal
///   solid angles. `cos_theta_max = -1` is [`uniform_sphere`] (up to
///   rounding), `0` a hemisphere.
/// - `1 - cos(theta)` is computed directly and the radius as `sqrt((1 -
///   cos)(1 + cos))`, so narrow cones (`cos_theta_max` near 1) keep their
///   relative accuracy; `z >= cos_theta_max` up to one rounding, `|v| = 1`
///   within 2^-22.
/// - `u.x = 0` is the axis `+z`; the rim is approached as `u.x -> 1`.
/// - `cos_theta_max` is clamped to `[-1, 1 - 2^-24]` (NaN to -1): a cone
///   too narrow for f32 is sampled as the narrowest one it has, so the pdf
///   is at most `2^24 / (2 pi)`. Input `u` outside `[0, 1)^2` is clamped
///   into it (NaN to 0).
///
/// # Cost
///
/// One square root, one `sin` and one `cos` (libm), a few multiplies.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{uniform_cone, uniform_cone_inverse, uniform_cone_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// let cos_max = 0.9;
/// assert_eq!(uniform_cone(Vec2::ZERO, cos_max), Vec3::Z);
/// let v = uniform_cone(Vec2::new(0.999, 0.3), cos_max);
/// assert!(v.z >= cos_max - 1e-6 && (v.length() - 1.0).abs() < 1e-6);
/// let pdf = uniform_cone_pdf(cos_max);
/// assert!((pdf - 1.0 / (2.0 * core::f32::consts::PI * 0.1)).abs() < 1e-3 * pdf);
/// let u = Vec2::new(0.4, 0.7);
/// assert!((uniform_cone_inverse(uniform_cone(u, cos_max), cos_max) - u).abs().max_element() < 1e-5);
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.5.4 (sampling a cone).
#[inline]
pub fn uniform_cone(u: Vec2, cos_theta_max: f32) -> Vec3 {
    let u = clamp_unit2(u);
    let one_minus_cos = u.x * (1.0 - cone_cos(cos_theta_max));
    let r = libm::sqrtf((one_minus_cos * (2.0 - one_minus_cos)).max(0.0));
    let (sin, cos) = libm::sincosf(TAU * u.y);
    Vec3::new(r * cos, r * sin, 1.0 - one_minus_cos)
}

/// The density of [`uniform_cone`] with respect to solid angle, `1 / (2 pi
/// (1 - cos_theta_max))`, for every direction of the cone; `cos_theta_max`
/// is clamped as [`uniform_cone`] clamps it, so the value is positive and
/// finite for every argument.
///
/// ```
/// use wellspread::warp::uniform_cone_pdf;
/// use core::f32::consts::PI;
/// assert_eq!(uniform_cone_pdf(0.0), 0.5 / PI);
/// assert_eq!(uniform_cone_pdf(-1.0), 0.25 / PI);
/// assert!(uniform_cone_pdf(1.0).is_finite());
/// ```
#[inline]
pub fn uniform_cone_pdf(cos_theta_max: f32) -> f32 {
    0.5 * core::f32::consts::FRAC_1_PI / (1.0 - cone_cos(cos_theta_max))
}

/// The inverse of [`uniform_cone`]: a direction of the cone back to `[0,
/// 1)^2`. `1 - cos(theta)` is taken as `(x^2 + y^2) / (1 + z)` in the upper
/// hemisphere, so narrow cones invert accurately; the azimuth is
/// ill-conditioned near the axis, as for [`uniform_sphere_inverse`].
///
/// ```
/// use wellspread::warp::{uniform_cone, uniform_cone_inverse};
/// use wellspread::glam::Vec2;
/// let cos_max = 0.999_99;
/// let u = Vec2::new(0.25, 0.6);
/// assert!((uniform_cone_inverse(uniform_cone(u, cos_max), cos_max) - u).abs().max_element() < 1e-5);
/// ```
#[inline]
pub fn uniform_cone_inverse(v: Vec3, cos_theta_max: f32) -> Vec2 {
    let one_minus_cos = if v.z > 0.0 {
        (v.x * v.x + v.y * v.y) / (1.0 + v.z)
    } else {
        1.0 - v.z
    };
    Vec2::new(
        clamp_unit(one_minus_cos / (1.0 - cone_cos(cos_theta_max))),
        turn_fraction(v.x, v.y),
    )
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

/// The pdf of a uniform choice in a solid angle `omega` (steradians), as
/// f32: `1 / omega`, or 0 where `omega` is not positive or so small that
/// `1 / omega` is not a finite f32 (the light is degenerate as seen from
/// the shading point).
#[inline]
fn solid_angle_pdf(omega: f64) -> f32 {
    let pdf = (1.0 / omega) as f32;
    if omega > 0.0 && pdf.is_finite() {
        pdf
    } else {
        0.0
    }
}

/// The solid angle of the spherical triangle of unit vectors `a, b, c`
/// (Van Oosterom & Strackee 1983): `2 atan2(|a . (b x c)|, 1 + a.b + b.c +
/// c.a)`, accurate for small triangles, where the angle-sum formula
/// (`alpha + beta + gamma - pi`) cancels.
#[inline]
fn spherical_triangle_area(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let det = a.dot(b.cross(c)).abs();
    2.0 * libm::atan2(det, 1.0 + a.dot(b) + b.dot(c) + c.dot(a))
}

/// `v` with its component along the unit vector `axis` removed, normalised
/// (zero if nothing is left).
#[inline]
fn perpendicular(v: DVec3, axis: DVec3) -> DVec3 {
    (v - v.dot(axis) * axis).normalize_or_zero()
}

/// How far from a planar light's plane a shading point must be, relative
/// to its distance from the light's farthest vertex, to see the light at
/// all: 2^-20, sixteen roundings of an f32 coordinate (2^-24). Nearer the
/// plane (on the light, on an edge or a vertex, or in the plane outside
/// it, up to that margin) the light's solid angle is decided by the
/// rounding of the point's coordinates, and the edges' directions from the
/// point are too nearly opposite to be computed: the light warps return
/// pdf 0. At 2^-24 the triangle map's directions still missed the light
/// by more than 1e-6 rad for points just off the plane (`tests/warp.rs`'s
/// property tests found them); at 2^-20 none of their cases does.
const IN_PLANE: f64 = 1.0 / 1_048_576.0;

/// The thinnest spherical triangle or rectangle the light warps sample:
/// its solid angle at least 2^-20 of its longest side's squared chord.
/// The maps place the direction through the angles at the corners and the
/// arcs between them, which lose their digits in f64 for a needle (a thin
/// light seen at a grazing angle, or a short edge far from the others, as
/// seen from `p`); such a light is sampled as degenerate, pdf 0, as one in
/// its plane is.
const NEEDLE: f64 = 1.0 / 1_048_576.0;

/// Whether a shading point sees a planar light off its plane: `to_light`
/// is from the point to a point of the light, `normal` the light's normal
/// (any length; zero for a degenerate light), `reach` the point's
/// distance to the light's farthest vertex (or a bound of it within a
/// small factor). False in the plane up to [`IN_PLANE`], for a zero normal
/// and for NaN. The one place the triangle and rectangle lights decide
/// that a point is in their plane, for their sample and pdf alike.
///
/// It also refuses a light thinner than [`SLIVER`]: `longest` is its
/// longest side, and `|normal| <= SLIVER longest^2` (twice the area of a
/// triangle, the area of a rectangle) is a needle or a sliver, or a
/// degenerate light that f32 rounding made a sliver of, whose plane the
/// coordinates do not fix.
///
/// The two conditions compound (a sliver seen from near its plane and
/// its line): their product must pass [`SLIVER_IN_PLANE`] too.
#[inline]
fn sees_plane(to_light: DVec3, normal: DVec3, reach: f64, longest: f64) -> bool {
    let area = normal.length();
    let off = to_light.dot(normal).abs() / (area * reach);
    let thin = area / (longest * longest);
    off > IN_PLANE && thin > SLIVER && off * thin > SLIVER_IN_PLANE
}

/// The least product of a light's thinness (area over longest side
/// squared) and the point's height over its plane (over its distance),
/// 2^-30: their f64 errors multiply, and below it the triangle map's
/// directions missed the light by more than 1e-6 rad (`tests/warp.rs`'s
/// property tests found a sliver of 1.5e-6 seen from 1.1e-6 above its
/// plane missing by 2e-5 rad).
const SLIVER_IN_PLANE: f64 = 1.0 / 1_073_741_824.0;

/// The thinnest planar light the light warps sample: its area at least
/// 2^-20 of its longest side squared (a 1 mm wide strip may be 1 km long).
const SLIVER: f64 = 1.0 / 1_048_576.0;

/// The spherical triangle of a light triangle seen from a point: the unit
/// directions to its vertices and its solid angle, or `None` when that is
/// 0 (the point is in the triangle's plane, up to [`IN_PLANE`], which
/// takes in its edges and vertices) or not finite.
struct SphericalTriangle {
    a: DVec3,
    b: DVec3,
    c: DVec3,
    area: f64,
}

impl SphericalTriangle {
    #[inline]
    fn new(a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> Option<Self> {
        let p = p.as_dvec3();
        let (a, b, c) = (a.as_dvec3() - p, b.as_dvec3() - p, c.as_dvec3() - p);
        let reach = a.length().max(b.length()).max(c.length());
        let longest = (b - a).length().max((c - b).length()).max((a - c).length());
        if !sees_plane(a, (b - a).cross(c - a), reach, longest) {
            return None;
        }
        let (a, b, c) = (a.normalize(), b.normalize(), c.normalize());
        let area = spherical_triangle_area(a, b, c);
        // A needle as seen from p: too thin for Arvo's map in f64.
        let longest = (a - b)
            .length_squared()
            .max((b - c).length_squared())
            .max((c - a).length_squared());
        (solid_angle_pdf(area) > 0.0 && area >= NEEDLE * longest).then_some(Self { a, b, c, area })
    }
}

/// What [`spherical_triangle`] returns for a light of no solid angle: the
/// direction to the centroid (`+z` if that is `p`), pdf 0, the centroid's
/// barycentrics.
#[inline]
fn degenerate_triangle(a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> (Vec3, f32, Vec3) {
    let centroid = (a + b + c) / 3.0;
    (
        (centroid - p).normalize_or(Vec3::Z),
        0.0,
        Vec3::splat(1.0 / 3.0),
    )
}

/// Uniform directions from `p` in the solid angle of the triangle `a b c`
/// (Arvo 1995): returns the direction (unit length), its pdf with respect
/// to solid angle and the barycentrics `(b0, b1, b2)` of the point where
/// the direction meets the triangle (`b0 a + b1 b + b2 c`).
///
/// From `p` the triangle is a spherical triangle `A B C` of solid angle
/// `omega`. `u.x` picks the point `C'` on the arc `A C` that cuts off the
/// sub-triangle `A B C'` of solid angle `u.x omega` (Arvo's closed form);
/// `u.y` then picks a point on the arc `B C'` with `1 - cos` of its
/// distance to `B` uniform, so the sub-triangle's area grows linearly in
/// both coordinates.
///
/// # Properties
///
/// - Uniform in solid angle: density [`spherical_triangle_pdf`] `= 1 /
///   omega`, constant over the triangle, so a light of constant radiance
///   has an estimator of radiance `L cos(theta) omega`: no `1 / r^2` noise
///   near the light, which area sampling ([`uniform_triangle`]) has.
/// - Continuous and monotone in each coordinate (the sub-triangle `A B C'`
///   grows with `u.x`, the point moves away from `B` with `u.y`), so strata
///   of the square become cells of equal solid angle.
///   [`spherical_triangle_inverse`] undoes it.
/// - Computed in f64 and rounded once: the direction is within 2^-23 of
///   unit length, the barycentrics are `>= 0` and sum to 1 within 2^-23.
///   For every `u` of `[0, 1)^2` the pdf is the same positive finite value
///   (the 2^-24 edge grid is tested).
/// - A triangle of no solid angle from `p` (`p` in its plane, which takes
///   in its edges and vertices, a degenerate triangle, or a solid angle
///   below about 3e-39 sr, where `1 / omega` overflows f32) has no
///   direction to give: the result is the direction to the centroid with
///   pdf 0, which a renderer skips (or samples the triangle by area).
///   [`spherical_triangle_pdf`] decides it in the same place and returns 0
///   too. "In the plane" is up to a few f32 roundings: a `p` within 2^-20
///   of its distance to the farthest vertex from the plane counts as in
///   it (its f32 coordinates barely say on which side it is). So is a sliver
///   (area below 2^-20 of the longest side squared) and a needle as seen
///   from `p` (solid angle below 2^-20 of the longest side's squared
///   chord), where Arvo's map loses its digits in f64, and a thin light
///   seen from near its plane (the product of its area over its longest
///   side squared and `p`'s relative height below 2^-30). Otherwise the
///   direction is finite and within the triangle as seen from `p` up to
///   its f32 rounding (`tests/warp.rs` checks 1e-6 rad over random,
///   degenerate and edge geometry at scales 1e-6 to 1e18). The vertex
///   order does not matter.
/// - Input `u` outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// About 200 f64 operations: three normalisations, one `atan2` for the
/// solid angle, one for the angle at `A`, one `sin` and one `cos`, three
/// square roots, and a ray-triangle solve for the barycentrics. The
/// triangle's part (everything but the `sin`/`cos` and the last two
/// normalisations) could be shared across samples of one shading point;
/// it is recomputed per call to keep the function pure.
///
/// # Limits
///
/// The map is computed in f64 and holds up for small lights: at solid
/// angles from 0.5 sr down to 5e-13 sr (a 1 cm light 10 km away), the
/// directions pass a chi-square test on 256 bins of known solid angle
/// (2^18 draws) and the pdf is within 4e-7 of the exact `1 / omega`
/// (`tests/warp.rs`). What limits a small light is the f32 direction
/// returned: its rounding is 2^-24, about `2^-24 / sqrt(omega)` of the
/// light's angular size. pbrt-v4 samples lights below `3e-4` sr by area
/// instead, where area sampling's `1 / r^2` noise no longer matters;
/// either choice works here.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{spherical_triangle, spherical_triangle_inverse, spherical_triangle_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// let (a, b, c) = (Vec3::new(-1.0, -1.0, 1.0), Vec3::new(1.0, -1.0, 1.0), Vec3::new(0.0, 1.0, 1.0));
/// let p = Vec3::ZERO;
/// let u = Vec2::new(0.3, 0.6);
/// let (w, pdf, bary) = spherical_triangle(u, a, b, c, p);
/// assert!((w.length() - 1.0).abs() < 1e-6 && bary.min_element() >= 0.0);
/// assert_eq!(pdf, spherical_triangle_pdf(a, b, c, p));
/// // The direction hits the triangle at the barycentric point.
/// let hit = bary.x * a + bary.y * b + bary.z * c;
/// assert!((hit.normalize() - w).length() < 1e-5);
/// assert!((spherical_triangle_inverse(w, a, b, c, p) - u).abs().max_element() < 1e-5);
/// // Seen edge-on, the triangle has no solid angle: pdf 0.
/// assert_eq!(spherical_triangle(u, a, b, c, Vec3::new(5.0, 0.0, 1.0)).1, 0.0);
/// ```
///
/// # References
///
/// - Arvo 1995, "Stratified Sampling of Spherical Triangles", SIGGRAPH
///   95, pp. 437-438.
/// - Van Oosterom & Strackee 1983, "The Solid Angle of a Plane Triangle",
///   IEEE Transactions on Biomedical Engineering 30(2).
#[inline]
pub fn spherical_triangle(u: Vec2, a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> (Vec3, f32, Vec3) {
    let Some(t) = SphericalTriangle::new(a, b, c, p) else {
        return degenerate_triangle(a, b, c, p);
    };
    let u = clamp_unit2(u).as_dvec2();
    // The angle alpha at A, between the planes of A B and A C:
    // |(A x B) x (A x C)| = |A . (B x C)|.
    let (nab, nac) = (t.a.cross(t.b), t.a.cross(t.c));
    let (sin_alpha, cos_alpha) = {
        let scale = nab.length() * nac.length();
        (nab.cross(nac).length() / scale, nab.dot(nac) / scale)
    };
    // Arvo's closed form for the cosine of the arc A C' that cuts off a
    // sub-triangle of area u.x omega.
    let (sin, cos) = libm::sincos(u.x * t.area - libm::atan2(sin_alpha, cos_alpha));
    let cos_ab = t.a.dot(t.b);
    let m = cos - cos_alpha;
    let n = sin + sin_alpha * cos_ab;
    let q = (((n * cos - m * sin) * cos_alpha - n) / ((n * sin + m * cos) * sin_alpha))
        .clamp(-1.0, 1.0);
    let c_prime = q * t.a + libm::sqrt((1.0 - q) * (1.0 + q)) * perpendicular(t.c, t.a);
    // On the arc B C': 1 - cos of the distance to B is u.y of its whole;
    // 1 - x . y = |x - y|^2 / 2 for unit vectors, without cancellation.
    let one_minus_z = u.y * 0.5 * (c_prime - t.b).length_squared();
    let z = 1.0 - one_minus_z;
    let w = z * t.b
        + libm::sqrt((one_minus_z * (2.0 - one_minus_z)).max(0.0)) * perpendicular(c_prime, t.b);
    let w = w.normalize();
    (
        w.as_vec3(),
        solid_angle_pdf(t.area),
        triangle_barycentrics(w, a, b, c, p),
    )
}

/// The barycentrics of the point where the ray `p + s w` meets the plane
/// of `a b c` (Moller-Trumbore, in f64), clamped to be `>= 0` and
/// renormalised to sum to 1.
#[inline]
fn triangle_barycentrics(w: DVec3, a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> Vec3 {
    let a = a.as_dvec3();
    let (e1, e2, s) = (b.as_dvec3() - a, c.as_dvec3() - a, p.as_dvec3() - a);
    let h = w.cross(e2);
    let det = e1.dot(h);
    let q = s.cross(e1);
    let b1 = (s.dot(h) / det).max(0.0);
    let b2 = (w.dot(q) / det).max(0.0);
    let b0 = (1.0 - b1 - b2).max(0.0);
    let sum = b0 + b1 + b2;
    if sum > 0.0 && sum.is_finite() {
        (DVec3::new(b0, b1, b2) / sum).as_vec3()
    } else {
        Vec3::splat(1.0 / 3.0)
    }
}

/// The density of [`spherical_triangle`] with respect to solid angle, `1
/// / omega` for `omega` the solid angle of the triangle `a b c` seen from
/// `p` (in f64, Van Oosterom & Strackee), the same for every direction in
/// it; 0 for a triangle of no solid angle.
///
/// ```
/// use wellspread::warp::spherical_triangle_pdf;
/// use wellspread::glam::Vec3;
/// // An octant of the sphere: a solid angle of pi / 2.
/// let pdf = spherical_triangle_pdf(Vec3::X, Vec3::Y, Vec3::Z, Vec3::ZERO);
/// assert!((pdf - 2.0 / core::f32::consts::PI).abs() < 1e-6);
/// // Seen from a point in its plane, a triangle has no solid angle.
/// assert_eq!(spherical_triangle_pdf(Vec3::X, Vec3::Y, Vec3::ZERO, Vec3::new(2.0, 3.0, 0.0)), 0.0);
/// ```
#[inline]
pub fn spherical_triangle_pdf(a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> f32 {
    SphericalTriangle::new(a, b, c, p).map_or(0.0, |t| solid_angle_pdf(t.area))
}

/// The inverse of [`spherical_triangle`]: the `u` of `[0, 1)^2` whose
/// direction from `p` is `w` (need not be unit length).
///
/// The great circle through `B` and `w` meets the arc `A C` at `C'`;
/// `u.x` is the solid angle of `A B C'` over the triangle's, and `u.y` is
/// `(1 - w . B) / (1 - C' . B)`, both computed in f64 with the differences
/// of unit vectors (`1 - x . y = |x - y|^2 / 2`), so directions near `B`
/// invert accurately. A direction outside the triangle gives the `u` of
/// the nearest point of the same construction, clamped into the square;
/// `w = B` (every `u.x` reaches it) gives `(0, 0)`, and a triangle of no
/// solid angle gives `(0, 0)`.
///
/// # Cost
///
/// About the cost of [`spherical_triangle`]: two solid angles (`atan2`),
/// three normalisations and a few cross products, in f64.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{spherical_triangle, spherical_triangle_inverse};
/// use wellspread::glam::{Vec2, Vec3};
/// let (a, b, c, p) = (Vec3::X, Vec3::Y, Vec3::Z, Vec3::ZERO);
/// let u = Vec2::new(0.7, 0.2);
/// let w = spherical_triangle(u, a, b, c, p).0;
/// assert!((spherical_triangle_inverse(w, a, b, c, p) - u).abs().max_element() < 1e-6);
/// ```
///
/// # References
///
/// Arvo 1995 (the forward map); pbrt-v4 offers the same inverse as
/// `InvertSphericalTriangleSample` (Pharr, Jakob & Humphreys 2023,
/// section 6.5.4). This one is derived from the forward map above.
#[inline]
pub fn spherical_triangle_inverse(w: Vec3, a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> Vec2 {
    let Some(t) = SphericalTriangle::new(a, b, c, p) else {
        return Vec2::ZERO;
    };
    let w = w.as_dvec3().normalize_or_zero();
    let nbw = t.b.cross(w);
    if nbw.length_squared() == 0.0 {
        return Vec2::ZERO;
    }
    // C' is on both great circles; of the two antipodes, the one on the
    // minor arc A C.
    let mut c_prime = nbw.cross(t.a.cross(t.c)).normalize_or_zero();
    if c_prime.dot(t.a + t.c) < 0.0 {
        c_prime = -c_prime;
    }
    let ux = spherical_triangle_area(t.a, t.b, c_prime) / t.area;
    let uy = (w - t.b).length_squared() / (c_prime - t.b).length_squared();
    Vec2::new(clamp_unit(ux as f32), clamp_unit(uy as f32))
}

/// The spherical rectangle of a light rectangle seen from a point, in the
/// rectangle's frame (Urena, Fajardo & King 2013, section 3): what the
/// sampler needs of it, and its solid angle.
struct SphericalRectangle {
    /// The rectangle's frame: `x` along `ex`, `y` along the part of `ey`
    /// perpendicular to it, `z` from the rectangle away from the point.
    x: DVec3,
    y: DVec3,
    z: DVec3,
    /// The rectangle, measured from the point in that frame: `x0 <= x <=
    /// x1`, `y0 <= y <= y1` at `z = z0 < 0` (`z` is flipped to make it so).
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
    z0: f64,
    /// `n0.z` and `n2.z` of the paper: the normals of the planes through
    /// the point and the edges `y = y0` and `y = y1`.
    b0: f64,
    b1: f64,
    /// The paper's `k = 2 pi - g2 - g3`.
    k: f64,
    /// The solid angle.
    area: f64,
}

impl SphericalRectangle {
    #[inline]
    fn new(corner: Vec3, ex: Vec3, ey: Vec3, p: Vec3) -> Option<Self> {
        let (ex, ey, o) = (ex.as_dvec3(), ey.as_dvec3(), p.as_dvec3());
        let ex_len = ex.length();
        let x = ex / ex_len;
        let ey = ey - ey.dot(x) * x;
        let ey_len = ey.length();
        let y = ey / ey_len;
        let mut z = x.cross(y);
        let d = corner.as_dvec3() - o;
        let (x0, y0) = (d.dot(x), d.dot(y));
        let mut z0 = d.dot(z);
        if z0 > 0.0 {
            z0 = -z0;
            z = -z;
        }
        let (x1, y1) = (x0 + ex_len, y0 + ey_len);
        // The four corners as seen from the point, and the normals of the
        // planes through the point and each edge, pointing inward.
        let (v00, v01) = (DVec3::new(x0, y0, z0), DVec3::new(x0, y1, z0));
        let (v10, v11) = (DVec3::new(x1, y0, z0), DVec3::new(x1, y1, z0));
        let n0 = v00.cross(v10).normalize_or_zero();
        let n1 = v10.cross(v11).normalize_or_zero();
        let n2 = v11.cross(v01).normalize_or_zero();
        let n3 = v01.cross(v00).normalize_or_zero();
        // The spherical rectangle's interior angles.
        let angle = |a: DVec3, b: DVec3| libm::acos((-a.dot(b)).clamp(-1.0, 1.0));
        let (g0, g1, g2, g3) = (angle(n0, n1), angle(n1, n2), angle(n2, n3), angle(n3, n0));
        let k = core::f64::consts::TAU - g2 - g3;
        let area = g0 + g1 - k;
        let fine = z0 < 0.0 && ex_len > 0.0 && ey_len > 0.0 && solid_angle_pdf(area) > 0.0;
        fine.then_some(Self {
            x,
            y,
            z,
            x0,
            x1,
            y0,
            y1,
            z0,
            b0: n0.z,
            b1: n2.z,
            k,
            area,
        })
    }

    /// The direction, pdf and `(s, t)` of `u` (already in `[0, 1)^2`).
    #[inline]
    fn sample(&self, u: Vec2) -> (Vec3, f32, Vec2) {
        let (r, u) = (self, u.as_dvec2());
        // The line x = xu: the solid angle left of it is u.x omega.
        let au = u.x * r.area + r.k;
        let (sin_au, cos_au) = libm::sincos(au);
        let fu = (cos_au * r.b0 - r.b1) / sin_au;
        let cu = (1.0 / libm::sqrt(fu * fu + r.b0 * r.b0))
            .copysign(fu)
            .clamp(-1.0, 1.0);
        let xu = (-(cu * r.z0) / libm::sqrt((1.0 - cu) * (1.0 + cu)).max(f64::MIN_POSITIVE))
            .clamp(r.x0, r.x1);
        // Along the line, the height of the direction is uniform.
        let d = libm::sqrt(xu * xu + r.z0 * r.z0);
        let h0 = r.y0 / libm::sqrt(d * d + r.y0 * r.y0);
        let h1 = r.y1 / libm::sqrt(d * d + r.y1 * r.y1);
        let hv = h0 + u.y * (h1 - h0);
        let hv2 = hv * hv;
        let yv = if hv2 < 1.0 {
            (hv * d / libm::sqrt(1.0 - hv2)).clamp(r.y0, r.y1)
        } else {
            r.y1
        };
        let local = xu * r.x + yv * r.y + r.z0 * r.z;
        let w = local.normalize();
        let st = DVec2::new((xu - r.x0) / (r.x1 - r.x0), (yv - r.y0) / (r.y1 - r.y0));
        (
            w.as_vec3(),
            solid_angle_pdf(r.area),
            st.clamp(DVec2::ZERO, DVec2::ONE).as_vec2(),
        )
    }
}

/// Below this solid angle (2^-10 sr, about 1e-3 sr: a light of size 1
/// seen from 30 away), [`spherical_rectangle`] leaves its f32 evaluation
/// for the f64 one. The f32 map places `u.x` with an absolute error of a
/// few f32 steps of the corner angles (about 1e-6 rad), an error of about
/// `1e-6 / omega` as a fraction of the solid angle.
const RECTANGLE_F32_MIN_SOLID_ANGLE: f32 = 1.0 / 1024.0;

/// Below this squared modulus of `d_i + i det_i` (one of the rectangle's two
/// triangles, Van Oosterom & Strackee's `tan(omega_i / 2) = det_i / d_i`),
/// the f32 solid angle would err by more than about 1e-6 relative (the
/// error in `omega_i / 2` is about `1e-7 / modulus`), and the f64
/// evaluation takes over. It happens where two corners are nearly opposite
/// as seen from the point: a point close to the rectangle's plane, over the
/// rectangle or beside a long one.
const RECTANGLE_F32_MIN_MODULUS2: f32 = 1.0 / 64.0;

/// Below this `z0^2 / (y^2 + z0^2)` for either edge `y = y0`, `y1` (the
/// squared sine of the angle at which the point sees the edge over the
/// rectangle's plane: a grazing view), the f32 map's `u.x -> x` step
/// cancels (`cos(au) b0 - b1` with `|b0|`, `|b1|` near 1); its `(s, t)`
/// error is about `2e-7` over this ratio, so at `2^-9` (about 2.6 degrees
/// of grazing) it is below 1e-4, and the f64 evaluation takes over below.
const RECTANGLE_F32_MIN_GRAZING: f32 = 1.0 / 512.0;

/// The spherical rectangle of a light rectangle seen from a point, in f32,
/// where that is accurate (see [`SphericalRectangleF32::new`]): the
/// fields of [`SphericalRectangle`] in closed form, with no inverse
/// trigonometry but one `atan2`. In the rectangle's frame each edge plane's
/// normal has two non-zero coordinates, so the corner angles are arguments
/// of complex numbers made of the corner's coordinates; the solid angle is
/// Van Oosterom & Strackee's over the two triangles (no cancelling sum of
/// angles), and `k` enters the sampler only through its sine and cosine.
struct SphericalRectangleF32 {
    x: Vec3,
    y: Vec3,
    z: Vec3,
    x0: f32,
    x1: f32,
    y0: f32,
    y1: f32,
    z0: f32,
    b0: f32,
    b1: f32,
    /// `cos k` and `sin k`, `k = 2 pi - g2 - g3` of [`SphericalRectangle`].
    cos_k: f32,
    sin_k: f32,
    area: f32,
}

impl SphericalRectangleF32 {
    /// `None` where the f64 evaluation must take over: a degenerate or
    /// non-finite rectangle, one below [`RECTANGLE_F32_MIN_SOLID_ANGLE`],
    /// seen grazing ([`RECTANGLE_F32_MIN_GRAZING`]) or with two corners
    /// nearly opposite ([`RECTANGLE_F32_MIN_MODULUS2`]).
    #[inline]
    fn new(corner: Vec3, ex: Vec3, ey: Vec3, p: Vec3) -> Option<Self> {
        // The solid angle and the map do not change with the scale: scale
        // the lengths by a power of two (exact) so that the largest
        // coordinate is in [1/2, 1), and no square or product below
        // overflows or underflows, whatever the rectangle's size.
        let d = corner - p;
        let largest = d.abs().max(ex.abs()).max(ey.abs()).max_element();
        if !(largest.is_finite() && largest >= f32::MIN_POSITIVE) {
            return None;
        }
        let scale = libm::scalbnf(1.0, -libm::frexpf(largest).1);
        let (d, ex, ey) = (d * scale, ex * scale, ey * scale);
        // The frame in f64, rounded once: the part of ey perpendicular to
        // ex cancels in f32 when the two are nearly parallel.
        let (exd, eyd) = (ex.as_dvec3(), ey.as_dvec3());
        let xd = exd / exd.length();
        let eyd = eyd - eyd.dot(xd) * xd;
        let yd = eyd / eyd.length();
        let (ex_len, ey_len) = (exd.length() as f32, eyd.length() as f32);
        let (x, y) = (xd.as_vec3(), yd.as_vec3());
        let mut z = xd.cross(yd).as_vec3();
        let (x0, y0) = (d.dot(x), d.dot(y));
        let mut z0 = d.dot(z);
        if z0 > 0.0 {
            z0 = -z0;
            z = -z;
        }
        let (x1, y1) = (x0 + ex_len, y0 + ey_len);
        let depth = -z0;
        let z2 = z0 * z0;
        // The corners' distances from the point.
        let (xx0, xx1, yy0, yy1) = (x0 * x0, x1 * x1, y0 * y0, y1 * y1);
        let r00 = libm::sqrtf(xx0 + yy0 + z2);
        let r01 = libm::sqrtf(xx0 + yy1 + z2);
        let r10 = libm::sqrtf(xx1 + yy0 + z2);
        let r11 = libm::sqrtf(xx1 + yy1 + z2);
        // The solid angle, triangles (v00, v10, v11) and (v00, v11, v01) of
        // unit corners: tan(omega_i / 2) = det_i / d_i, and omega / 2 (below
        // pi) is the argument of (d_1 + i det_1)(d_2 + i det_2).
        let det = depth * ex_len * ey_len / (r00 * r11);
        let dot = |xa: f32, ya: f32, ra: f32, xb: f32, yb: f32, rb: f32| {
            (xa * xb + ya * yb + z2) / (ra * rb)
        };
        let d00_11 = dot(x0, y0, r00, x1, y1, r11);
        let d1 = 1.0 + dot(x0, y0, r00, x1, y0, r10) + dot(x1, y0, r10, x1, y1, r11) + d00_11;
        let d2 = 1.0 + d00_11 + dot(x1, y1, r11, x0, y1, r01) + dot(x0, y0, r00, x0, y1, r01);
        let (det1, det2) = (det / r10, det / r01);
        // The imaginary part is positive (omega / 2 < pi), but rounds
        // below 0 near a hemisphere.
        let im = (det1 * d2 + det2 * d1).max(0.0);
        let area = 2.0 * libm::atan2f(im, d1 * d2 - det1 * det2);
        // pi - g2 and pi - g3, the exterior angles at the corners (x0, y1)
        // and (x0, y0), are the arguments of (-x0 y1, |z0| r01) and (x0 y0,
        // |z0| r00), of lengths sqrt(x0^2 + z0^2) sqrt(y^2 + z0^2); k is
        // their sum.
        let (rx0, ry0, ry1) = (
            libm::sqrtf(xx0 + z2),
            libm::sqrtf(yy0 + z2),
            libm::sqrtf(yy1 + z2),
        );
        let (c2, s2) = (-x0 * y1 / (rx0 * ry1), depth * r01 / (rx0 * ry1));
        let (c3, s3) = (x0 * y0 / (rx0 * ry0), depth * r00 / (rx0 * ry0));
        let fine = ex_len > 0.0
            && ey_len > 0.0
            && z0 < 0.0
            && area >= RECTANGLE_F32_MIN_SOLID_ANGLE
            // |d_i + i det_i|^2 = 2 (1 + a.b)(1 + b.c)(1 + c.a): near 0 when
            // two corners are nearly opposite, where d_i cancels in f32.
            && d1 * d1 + det1 * det1 >= RECTANGLE_F32_MIN_MODULUS2
            && d2 * d2 + det2 * det2 >= RECTANGLE_F32_MIN_MODULUS2
            // Grazing: the sine squared of the angles at which the point
            // sees the edges y = y0 and y = y1 over the plane.
            && z2 >= RECTANGLE_F32_MIN_GRAZING * (yy0 + z2)
            && z2 >= RECTANGLE_F32_MIN_GRAZING * (yy1 + z2)
            // Every intermediate that could overflow or divide by 0.
            && (det + d1 + d2 + det1 + det2 + im).is_finite()
            && (c2 + c3 + s2 + s3).is_finite()
            && (x + y + d).is_finite();
        fine.then(|| Self {
            x,
            y,
            z,
            x0,
            x1,
            y0,
            y1,
            z0,
            b0: -y0 / ry0,
            b1: y1 / ry1,
            cos_k: c2 * c3 - s2 * s3,
            sin_k: s2 * c3 + c2 * s3,
            area,
        })
    }

    /// The direction, pdf and `(s, t)` of `u` (already in `[0, 1)^2`).
    #[inline]
    fn sample(&self, u: Vec2) -> (Vec3, f32, Vec2) {
        let r = self;
        // au = u.x omega + k, through its sine and cosine.
        let (sin_a, cos_a) = libm::sincosf(u.x * r.area);
        let sin_au = sin_a * r.cos_k + cos_a * r.sin_k;
        let cos_au = cos_a * r.cos_k - sin_a * r.sin_k;
        let fu = (cos_au * r.b0 - r.b1) / sin_au;
        let cu = (1.0 / libm::sqrtf(fu * fu + r.b0 * r.b0))
            .copysign(fu)
            .clamp(-1.0, 1.0);
        // NaN (fu = 0 / 0) is dropped by max and min: x0.
        let xu = (-(cu * r.z0) / libm::sqrtf((1.0 - cu) * (1.0 + cu)).max(f32::MIN_POSITIVE))
            .max(r.x0)
            .min(r.x1);
        let d2 = xu * xu + r.z0 * r.z0;
        let h0 = r.y0 / libm::sqrtf(d2 + r.y0 * r.y0);
        let h1 = r.y1 / libm::sqrtf(d2 + r.y1 * r.y1);
        let hv = h0 + u.y * (h1 - h0);
        let hv2 = hv * hv;
        let yv = if hv2 < 1.0 {
            (hv * libm::sqrtf(d2 / (1.0 - hv2))).max(r.y0).min(r.y1)
        } else {
            r.y1
        };
        // Normalised in f64, so the direction is within 2^-23 of unit
        // length (one rounding), as the f64 path gives it.
        let w = (xu * r.x + yv * r.y + r.z0 * r.z).as_dvec3().normalize();
        let st = Vec2::new((xu - r.x0) / (r.x1 - r.x0), (yv - r.y0) / (r.y1 - r.y0));
        (w.as_vec3(), 1.0 / r.area, st.clamp(Vec2::ZERO, Vec2::ONE))
    }
}

/// Uniform directions from `p` in the solid angle of the rectangle
/// `corner + s ex + t ey`, `s, t` in `[0, 1]` (Urena, Fajardo & King
/// 2013): returns the direction (unit length), its pdf with respect to
/// solid angle and the `(s, t)` of the point it hits.
///
/// `u.x` picks the line `x = x_u` of the rectangle such that the part of
/// the spherical rectangle left of it has solid angle `u.x omega`; `u.y`
/// picks the point on that line whose direction's height `h = y /
/// sqrt(x_u^2 + y^2 + z_0^2)` is uniform between the line's ends, which
/// is uniform in solid angle along the line.
///
/// # Properties
///
/// - Uniform in solid angle: density [`spherical_rectangle_pdf`] `= 1 /
///   omega`, constant over the rectangle (no `1 / r^2` noise near the
///   light, unlike [`rectangle`]).
/// - Continuous and monotone in each coordinate (`s` grows with `u.x`, `t`
///   with `u.y`), so strata of the square become cells of equal solid
///   angle.
/// - Computed in f32 where that is accurate, else in f64 (see Limits);
///   `(s, t)` is in `[0, 1]^2`, the direction within 2^-23 of unit length.
///   For every `u` of `[0, 1)^2` the pdf is the same positive finite value
///   (the 2^-24 edge grid is tested), and [`spherical_rectangle_pdf`]
///   returns that same value.
/// - `ex` and `ey` should be perpendicular (a rectangle). For a
///   parallelogram, the part of `ey` perpendicular to `ex` is used: the
///   directions cover the rectangle spanned by `ex` and that part.
/// - A rectangle of no solid angle from `p` (`p` in its plane, which
///   takes in its edges and corners, a zero edge, or below about 3e-39
///   sr) gives the direction to its centre with pdf 0 and `(s, t) = (0.5,
///   0.5)`; [`spherical_rectangle_pdf`] decides it in the same place and
///   returns 0 too. "In the plane" is up to a few f32 roundings, as for
///   [`spherical_triangle`]: within 2^-20 of `p`'s distance to the
///   farthest corner (bounded by `|corner - p| + |ex| + |ey|`). So are
///   slivers and needles, as for [`spherical_triangle`]. Otherwise the
///   direction is finite and within the rectangle as seen from `p` within
///   1e-4 rad (the f32 evaluation's accuracy; `tests/warp.rs` checks it
///   over random, degenerate and edge geometry at scales 1e-6 to 1e18).
/// - Input `u` outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// The f32 evaluation: about 150 f32 operations with 15 square roots,
/// one `atan2` and one `sincos` (no inverse cosines: in the rectangle's
/// frame its corner angles and solid angle have closed forms), about 0.83
/// of the f64 evaluation's instructions and 0.75 of its time; against
/// [`rectangle`] (area sampling) it is still about 70 times the time. The f64
/// evaluation, where the f32 one would be inaccurate: about 250 f64
/// operations, four `acos`, one `sincos` and square roots, after the f32
/// attempt. The rectangle's part could be shared across samples of one
/// shading point; it is recomputed per call to keep the function pure.
///
/// # Limits
///
/// Both evaluations work at any scale f32 holds (coordinates from about
/// 1e-38 to 3e38): the f32 one first scales the lengths by a power of two
/// (exact, so its values do not change) to bring the largest coordinate
/// to `[1/2, 1)`, and hands over to the f64 one if any intermediate is
/// not finite.
///
/// The f32 evaluation is used where the rectangle covers at least 2^-10
/// sr (about 1e-3), is seen at more than about 2.6 degrees above its
/// plane from both edges `y = y0` and `y = y1` of its frame, and no two
/// of its corners are nearly opposite as seen from `p`; there its pdf is
/// within 1e-6 relative of the f64 one and its directions within 1e-4 of
/// the f64 directions (measured in the unit tests: at most 1.5e-5 over
/// lights near, far, long, off to the side and grazing). Elsewhere (small,
/// far, grazing or nearly hemispherical lights) the f64 evaluation runs,
/// whose solid angle is a sum of four angles that cancels for small
/// rectangles: its relative error (measured in `tests/warp.rs`) is below
/// 1e-7 down to 1e-8 sr, 9e-6 at 1e-10 sr and 7e-4 at 1e-12 sr; the
/// directions pass a chi-square test on 256 bins of known solid angle at
/// all of these. Use [`rectangle`] (area sampling) for lights that small;
/// pbrt-v4 switches below `3e-4` sr.
///
/// # Examples
///
/// ```
/// use wellspread::warp::{spherical_rectangle, spherical_rectangle_pdf};
/// use wellspread::glam::{Vec2, Vec3};
/// // A 2 x 2 square light 1 above the point: 2 pi / 3 sr.
/// let (corner, ex, ey) = (Vec3::new(-1.0, -1.0, 1.0), 2.0 * Vec3::X, 2.0 * Vec3::Y);
/// let p = Vec3::ZERO;
/// let pdf = spherical_rectangle_pdf(corner, ex, ey, p);
/// assert!((pdf - 1.5 / core::f32::consts::PI).abs() < 1e-6);
/// let (w, pdf_w, st) = spherical_rectangle(Vec2::new(0.5, 0.5), corner, ex, ey, p);
/// assert_eq!(pdf_w, pdf);
/// assert!((w - Vec3::Z).length() < 1e-6 && (st - Vec2::splat(0.5)).length() < 1e-6);
/// // The point hit is corner + s ex + t ey, on the direction.
/// let (w, _, st) = spherical_rectangle(Vec2::new(0.9, 0.2), corner, ex, ey, p);
/// let hit = corner + st.x * ex + st.y * ey;
/// assert!((hit.normalize() - w).length() < 1e-6);
/// ```
///
/// # References
///
/// Urena, Fajardo & King 2013, "An Area-Preserving Parametrization for
/// Spherical Rectangles", Computer Graphics Forum 32(4) (EGSR 2013); the
/// f32 solid angle is Van Oosterom & Strackee 1983's, "The Solid Angle of
/// a Plane Triangle", IEEE Trans. Biomedical Engineering 30(2), over the
/// rectangle's two triangles. pbrt-v4's `SampleSphericalRectangle`
/// (Pharr, Jakob & Humphreys 2023) evaluates the paper's map in f32.
#[inline]
pub fn spherical_rectangle(
    u: Vec2,
    corner: Vec3,
    ex: Vec3,
    ey: Vec3,
    p: Vec3,
) -> (Vec3, f32, Vec2) {
    let u = clamp_unit2(u);
    match RectangleLight::new(corner, ex, ey, p) {
        RectangleLight::F32(r) => r.sample(u),
        RectangleLight::F64(r) => r.sample(u),
        RectangleLight::Degenerate => {
            let centre = corner + 0.5 * (ex + ey);
            ((centre - p).normalize_or(Vec3::Z), 0.0, Vec2::splat(0.5))
        }
    }
}

/// The density of [`spherical_rectangle`] with respect to solid angle, `1
/// / omega` for `omega` the solid angle of the rectangle seen from `p`
/// (in f32 or f64, as [`spherical_rectangle`] computes it, so the two
/// agree bit for bit), the same for every direction in it; 0 for a
/// rectangle of no solid angle.
///
/// ```
/// use wellspread::warp::spherical_rectangle_pdf;
/// use wellspread::glam::Vec3;
/// // A face of a cube seen from its centre: 4 pi / 6 sr.
/// let pdf = spherical_rectangle_pdf(Vec3::new(-1.0, -1.0, 1.0), 2.0 * Vec3::X, 2.0 * Vec3::Y, Vec3::ZERO);
/// assert!((pdf - 1.5 / core::f32::consts::PI).abs() < 1e-6);
/// ```
#[inline]
pub fn spherical_rectangle_pdf(corner: Vec3, ex: Vec3, ey: Vec3, p: Vec3) -> f32 {
    match RectangleLight::new(corner, ex, ey, p) {
        RectangleLight::F32(r) => 1.0 / r.area,
        RectangleLight::F64(r) => solid_angle_pdf(r.area),
        RectangleLight::Degenerate => 0.0,
    }
}

/// A rectangle light seen from a point, as [`spherical_rectangle`] and
/// [`spherical_rectangle_pdf`] both evaluate it: decided in this one place.
enum RectangleLight {
    /// The f32 evaluation, where it is accurate.
    F32(SphericalRectangleF32),
    /// The f64 evaluation elsewhere.
    F64(SphericalRectangle),
    /// No solid angle: the point in the rectangle's plane (up to
    /// [`IN_PLANE`], which takes in its edges and corners), a zero edge,
    /// a solid angle whose inverse is not a finite f32, or non-finite
    /// input.
    Degenerate,
}

impl RectangleLight {
    #[inline]
    fn new(corner: Vec3, ex: Vec3, ey: Vec3, p: Vec3) -> Self {
        let (d, dx, dy) = (
            corner.as_dvec3() - p.as_dvec3(),
            ex.as_dvec3(),
            ey.as_dvec3(),
        );
        let (lx, ly) = (dx.length(), dy.length());
        if !sees_plane(d, dx.cross(dy), d.length() + lx + ly, lx.max(ly)) {
            return Self::Degenerate;
        }
        let light = if let Some(r) = SphericalRectangleF32::new(corner, ex, ey, p) {
            Self::F32(r)
        } else {
            SphericalRectangle::new(corner, ex, ey, p).map_or(Self::Degenerate, Self::F64)
        };
        // A needle as seen from p (see NEEDLE): the diagonals' squared
        // chords bound the longest side's.
        let area = match &light {
            Self::F32(r) => f64::from(r.area),
            Self::F64(r) => r.area,
            Self::Degenerate => return light,
        };
        let (c00, c11) = (d.normalize(), (d + dx + dy).normalize());
        let (c10, c01) = ((d + dx).normalize(), (d + dy).normalize());
        let longest = (c00 - c11)
            .length_squared()
            .max((c10 - c01).length_squared());
        if area >= NEEDLE * longest {
            light
        } else {
            Self::Degenerate
        }
    }
}

// ---------------------------------------------------------------------------
// Weighted discrete choice (alloc).

/// Checks a list of weights for [`Discrete::new`] and [`AliasTable::new`]
/// and returns their sum in f64 (no overflow: at most 2^32 terms below
/// 2^128 each).
#[cfg(feature = "alloc")]
fn checked_total(weights: &[f32]) -> Result<f64, crate::error::Error> {
    use crate::error::Error;
    if weights.len() > u32::MAX as usize {
        return Err(Error::TooManyWeights {
            count: weights.len(),
        });
    }
    let mut total = 0.0f64;
    for (index, &weight) in weights.iter().enumerate() {
        if !weight.is_finite() {
            return Err(Error::NonFiniteWeight { index, weight });
        }
        if weight < 0.0 {
            return Err(Error::NegativeWeight { index, weight });
        }
        total += f64::from(weight);
    }
    if total > 0.0 {
        Ok(total)
    } else {
        Err(Error::ZeroTotalWeight {
            count: weights.len(),
        })
    }
}

/// A probability as the f32 a caller divides by: 0 stays 0, anything
/// positive is at least `f32::MIN_POSITIVE`, so `1 / pmf` is finite.
#[cfg(feature = "alloc")]
#[inline]
fn positive_pmf(p: f64) -> f32 {
    if p > 0.0 {
        (p as f32).max(f32::MIN_POSITIVE)
    } else {
        0.0
    }
}

/// A weighted choice among `n` items by inverse CDF: item `i` is chosen
/// with probability `weights[i] / sum(weights)`, and the number that chose
/// it is remapped to `[0, 1)` for the next draw.
///
/// Item `i` owns the interval `[cdf[i], cdf[i + 1])` of `[0, 1)`, in item
/// order; [`sample`](Self::sample) finds the interval of `u` by binary
/// search and returns the item, `u`'s position inside the interval and the
/// item's probability.
///
/// # Properties
///
/// - Monotone: sorted `u` choose items in order, and within one item the
///   remapped values are sorted. So a stratified `u` (one per interval of
///   `1 / N`, a sequence's 1D draws) chooses item `i` within 2 of `N
///   pmf(i)` times, and the remapped values of one item keep the strata
///   that fell inside its interval: the choice of a light and the point on
///   it can share one dimension.
/// - An item of weight 0 owns an empty interval and is never chosen; its
///   [`pmf`](Self::pmf) is 0. Every chosen item's pmf is at least
///   `f32::MIN_POSITIVE`, so `1 / pmf` is finite.
/// - The interval ends are prefix sums in f64 divided by their total, so
///   the last end is exactly 1 and a `u` of `[0, 1)` always chooses an
///   item of positive weight. Under `u` on the f32 grid of 2^-24 (every
///   sampler's output) each item's probability is its pmf within 2^-24.
/// - Input outside `[0, 1)` is clamped into it (NaN to 0).
///
/// # Cost
///
/// Construction: one pass over the weights and a table of `n + 1` f64
/// (`8 (n + 1)` bytes). [`sample`](Self::sample): a binary search (about
/// `log2(n)` dependent loads) and one f64 division. [`AliasTable`] is
/// O(1) per draw but does not keep the strata.
///
/// # Limits
///
/// Needs the `alloc` feature. Weights must be finite and `>= 0`, at least
/// one positive, at most `2^32 - 1` of them; anything else is a typed
/// [`Error`](crate::Error) from [`new`](Self::new), never a panic. A
/// positive weight below about 2^-53 of the sum of the weights before it
/// vanishes in the f64 prefix sum: its interval is empty, it is never
/// chosen and its pmf is 0 (the pmf stays the probability of the choice).
///
/// # Examples
///
/// ```
/// use wellspread::warp::Discrete;
/// // Three lights with powers 1, 0 and 3: the second is never chosen.
/// let lights = Discrete::new(&[1.0, 0.0, 3.0])?;
/// assert_eq!(lights.pmf(0), 0.25);
/// assert_eq!(lights.pmf(1), 0.0);
/// let (light, u, pmf) = lights.sample(0.5);
/// assert_eq!((light, pmf), (2, 0.75));
/// // 0.5 is a third of the way into the last light's interval [0.25, 1).
/// assert!((u - 1.0 / 3.0).abs() < 1e-6);
/// assert_eq!(lights.inverse(light, u), 0.5);
/// // Stratified u stay stratified: 8 strata, 2 to the first light, 6 to the last.
/// let mut counts = [0; 3];
/// for k in 0..8 {
///     counts[lights.sample((k as f32 + 0.5) / 8.0).0 as usize] += 1;
/// }
/// assert_eq!(counts, [2, 0, 6]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.1 (sampling discrete distributions, remapping the sample).
#[cfg_attr(docsrs, doc(cfg(feature = "alloc")))]
#[cfg(feature = "alloc")]
#[derive(Clone, Debug, PartialEq)]
pub struct Discrete {
    /// `n + 1` interval ends: `cdf[0] = 0`, `cdf[n] = 1`, non-decreasing.
    cdf: alloc::boxed::Box<[f64]>,
}

#[cfg(feature = "alloc")]
impl Discrete {
    /// The choice among `weights.len()` items with these weights.
    ///
    /// # Errors
    ///
    /// [`Error::NonFiniteWeight`](crate::Error::NonFiniteWeight) or
    /// [`Error::NegativeWeight`](crate::Error::NegativeWeight) naming the
    /// first bad weight, [`Error::ZeroTotalWeight`](crate::Error::ZeroTotalWeight)
    /// for an empty or all-zero list, and
    /// [`Error::TooManyWeights`](crate::Error::TooManyWeights) above
    /// `2^32 - 1` weights.
    ///
    /// ```
    /// use wellspread::{Error, warp::Discrete};
    /// assert_eq!(
    ///     Discrete::new(&[1.0, -2.0]),
    ///     Err(Error::NegativeWeight { index: 1, weight: -2.0 })
    /// );
    /// assert_eq!(Discrete::new(&[0.0, 0.0]), Err(Error::ZeroTotalWeight { count: 2 }));
    /// assert_eq!(Discrete::new(&[]), Err(Error::ZeroTotalWeight { count: 0 }));
    /// assert!(matches!(
    ///     Discrete::new(&[1.0, f32::INFINITY]),
    ///     Err(Error::NonFiniteWeight { index: 1, .. })
    /// ));
    /// ```
    pub fn new(weights: &[f32]) -> Result<Self, crate::error::Error> {
        let total = checked_total(weights)?;
        let mut cdf = alloc::vec::Vec::with_capacity(weights.len() + 1);
        cdf.push(0.0);
        // The same additions in the same order as `total`: the last prefix
        // is `total`, so the last end is exactly 1 (and so is every end
        // after the last positive weight).
        let mut sum = 0.0f64;
        for &weight in weights {
            sum += f64::from(weight);
            cdf.push(sum / total);
        }
        Ok(Self {
            cdf: cdf.into_boxed_slice(),
        })
    }

    /// The number of items (the length of the weights).
    #[must_use]
    pub fn len(&self) -> u32 {
        // `new` accepts at most u32::MAX weights.
        (self.cdf.len() - 1) as u32
    }

    /// Always `false`: [`new`](Self::new) rejects an empty list.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.cdf.len() <= 1
    }

    /// The item chosen by `u`, `u` remapped to `[0, 1)` inside the item's
    /// interval, and the item's probability [`pmf`](Self::pmf), positive.
    ///
    /// ```
    /// use wellspread::warp::Discrete;
    /// let d = Discrete::new(&[2.0, 6.0])?;
    /// assert_eq!(d.sample(0.0), (0, 0.0, 0.25));
    /// assert_eq!(d.sample(0.625), (1, 0.5, 0.75));
    /// let (i, u, pmf) = d.sample(1.0 - f32::EPSILON / 2.0);
    /// assert!(i == 1 && u < 1.0 && pmf == 0.75);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn sample(&self, u: f32) -> (u32, f32, f32) {
        let x = f64::from(clamp_unit(u));
        // The number of ends after the first that are <= x: the interval
        // [cdf[i], cdf[i + 1]) holding x, skipping empty ones. cdf[n] = 1 > x.
        let index = self.cdf[1..].partition_point(|&end| end <= x);
        let (lo, hi) = (self.cdf[index], self.cdf[index + 1]);
        let width = hi - lo;
        let remapped = clamp_unit(((x - lo) / width) as f32);
        (index as u32, remapped, positive_pmf(width))
    }

    /// The probability of choosing item `index`: its weight over the sum of
    /// the weights (0 for a weight of 0, and for an index out of range).
    #[inline]
    #[must_use]
    pub fn pmf(&self, index: u32) -> f32 {
        let i = index as usize;
        match (self.cdf.get(i), self.cdf.get(i + 1)) {
            (Some(&lo), Some(&hi)) => positive_pmf(hi - lo),
            _ => 0.0,
        }
    }

    /// The inverse of [`sample`](Self::sample): the `u` that chooses
    /// `index` with this remapped value, `cdf[index] + remapped pmf`,
    /// computed in f64 and rounded once, in `[0, 1)`. An index out of range
    /// is read as the last item.
    ///
    /// ```
    /// use wellspread::warp::Discrete;
    /// let d = Discrete::new(&[1.0, 1.0, 2.0])?;
    /// let (i, r, _) = d.sample(0.3);
    /// assert_eq!(d.inverse(i, r), 0.3);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn inverse(&self, index: u32, remapped: f32) -> f32 {
        let i = (index as usize).min(self.cdf.len() - 2);
        let (lo, hi) = (self.cdf[i], self.cdf[i + 1]);
        clamp_unit((lo + f64::from(clamp_unit(remapped)) * (hi - lo)) as f32)
    }
}

/// A weighted choice among `n` items in O(1) per draw, by Walker's alias
/// method built with Vose's algorithm: each of `n` equal slots holds its
/// own item with some probability and one other item (its alias) with the
/// rest.
///
/// [`sample`](Self::sample) picks a slot with [`discrete`]`(u, n)` and
/// compares the remapped number with the slot's threshold; the part of
/// the number the comparison did not use is remapped again to `[0, 1)`.
///
/// # Properties
///
/// - Item `i` is chosen with probability `weights[i] / sum(weights)`
///   ([`pmf`](Self::pmf)), within 2^-24 per slot the item occupies for
///   `u` on the f32 grid of 2^-24 (the thresholds are f32, and the
///   remapped number a slot compares with them is on a grid of `n
///   2^-24`).
/// - An item of weight 0 has threshold 0 in its slot and is nobody's
///   alias: it is never chosen, and its pmf is 0. Every chosen item's pmf
///   is at least `f32::MIN_POSITIVE`, so `1 / pmf` is finite.
/// - Not monotone in `u`: an item's measure is split over up to `n`
///   slots, so a stratified `u` is stratified over slots, not over items.
///   Where the strata matter more than the table's O(log n) search, use
///   [`Discrete`].
/// - Input outside `[0, 1)` is clamped into it (NaN to 0).
///
/// # Cost
///
/// Construction: O(n), with two work lists of `n` u32 and a table of `n`
/// slots (threshold f32, alias u32) plus `n` f32 pmfs, `12 n` bytes.
/// [`sample`](Self::sample): one [`discrete`], one load, one comparison,
/// one division: O(1) whatever `n`.
///
/// # Limits
///
/// Needs the `alloc` feature; the same weight checks and typed errors as
/// [`Discrete::new`]. With more than 2^24 items, not every slot is
/// reachable by a `u` on the 2^-24 grid ([`discrete`]'s limit).
///
/// # Examples
///
/// ```
/// use wellspread::warp::AliasTable;
/// let lights = AliasTable::new(&[1.0, 0.0, 3.0])?;
/// assert_eq!((lights.pmf(0), lights.pmf(1), lights.pmf(2)), (0.25, 0.0, 0.75));
/// let mut counts = [0u32; 3];
/// for k in 0..1024 {
///     let (light, u, pmf) = lights.sample((k as f32 + 0.5) / 1024.0);
///     assert!(u < 1.0 && pmf == lights.pmf(light));
///     counts[light as usize] += 1;
/// }
/// // The middle light has weight 0; the others get their share.
/// assert_eq!(counts, [256, 0, 768]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Walker 1977, "An Efficient Method for Generating Discrete Random
///   Variables with General Distributions", ACM TOMS 3(3).
/// - Vose 1991, "A Linear Algorithm for Generating Random Numbers with a
///   Given Distribution", IEEE Transactions on Software Engineering 17(9).
#[cfg_attr(docsrs, doc(cfg(feature = "alloc")))]
#[cfg(feature = "alloc")]
#[derive(Clone, Debug, PartialEq)]
pub struct AliasTable {
    /// Per slot: the probability of keeping the slot's own item, and the
    /// alias chosen otherwise.
    slots: alloc::boxed::Box<[(f32, u32)]>,
    /// Per item: its probability, as [`AliasTable::pmf`] returns it.
    pmf: alloc::boxed::Box<[f32]>,
}

#[cfg(feature = "alloc")]
impl AliasTable {
    /// The table for `weights.len()` items with these weights (Vose's
    /// algorithm, in f64).
    ///
    /// # Errors
    ///
    /// As [`Discrete::new`]: a NaN, infinite or negative weight, no
    /// positive weight, or more than `2^32 - 1` weights.
    ///
    /// ```
    /// use wellspread::{Error, warp::AliasTable};
    /// assert_eq!(
    ///     AliasTable::new(&[0.5, -0.0, -1e-9]),
    ///     Err(Error::NegativeWeight { index: 2, weight: -1e-9 })
    /// );
    /// ```
    pub fn new(weights: &[f32]) -> Result<Self, crate::error::Error> {
        use alloc::vec::Vec;
        let total = checked_total(weights)?;
        let n = weights.len();
        let scale = n as f64 / total;
        // Each item's share in slots: 1 is one whole slot.
        let mut share: Vec<f64> = weights.iter().map(|&w| f64::from(w) * scale).collect();
        let mut slots: Vec<(f32, u32)> = (0..n as u32).map(|i| (1.0, i)).collect();
        let (mut small, mut large): (Vec<u32>, Vec<u32>) =
            (0..n as u32).partition(|&i| share[i as usize] < 1.0);
        while let (Some(&s), Some(&l)) = (small.last(), large.last()) {
            small.pop();
            // Slot s keeps item s with probability share[s]; item l fills
            // the rest, and gives that much of its own share away.
            slots[s as usize] = ((share[s as usize] as f32).clamp(0.0, 1.0), l);
            share[l as usize] = (share[l as usize] + share[s as usize]) - 1.0;
            if share[l as usize] < 1.0 {
                large.pop();
                small.push(l);
            }
        }
        // What is left is a whole slot up to rounding, and keeps its own
        // item; an item of weight 0 can only be left over if rounding lost
        // a whole slot, and even then is never kept.
        let heaviest = (0..n)
            .max_by(|&a, &b| weights[a].total_cmp(&weights[b]))
            .unwrap_or(0) as u32;
        for i in small.into_iter().chain(large) {
            slots[i as usize] = if weights[i as usize] > 0.0 {
                (1.0, i)
            } else {
                (0.0, heaviest)
            };
        }
        let pmf = weights
            .iter()
            .map(|&w| positive_pmf(f64::from(w) / total))
            .collect();
        Ok(Self {
            slots: slots.into_boxed_slice(),
            pmf,
        })
    }

    /// The number of items (the length of the weights).
    #[must_use]
    pub fn len(&self) -> u32 {
        // `new` accepts at most u32::MAX weights.
        self.slots.len() as u32
    }

    /// Always `false`: [`new`](Self::new) rejects an empty list.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.slots.is_empty()
    }

    /// The item chosen by `u`, the part of `u` the choice did not use
    /// remapped to `[0, 1)`, and the item's probability
    /// [`pmf`](Self::pmf), positive.
    ///
    /// ```
    /// use wellspread::warp::AliasTable;
    /// let t = AliasTable::new(&[1.0, 3.0])?;
    /// let (i, u, pmf) = t.sample(0.9);
    /// assert!(i < 2 && u < 1.0 && pmf == t.pmf(i));
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn sample(&self, u: f32) -> (u32, f32, f32) {
        let (slot, r) = discrete(clamp_unit(u), self.len());
        let (keep, alias) = self.slots[slot as usize];
        let (index, remapped) = if r < keep {
            (slot, r / keep)
        } else {
            // r >= keep, and r < 1, so keep < 1.
            (alias, (r - keep) / (1.0 - keep))
        };
        (index, clamp_unit(remapped), self.pmf[index as usize])
    }

    /// The probability of choosing item `index`: its weight over the sum of
    /// the weights (0 for a weight of 0, and for an index out of range).
    #[inline]
    #[must_use]
    pub fn pmf(&self, index: u32) -> f32 {
        self.pmf.get(index as usize).copied().unwrap_or(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The f32 evaluation of [`spherical_rectangle`] against the f64 one
    /// wherever it is used (solid angle at least
    /// [`RECTANGLE_F32_MIN_SOLID_ANGLE`]): the same pdf within 1e-6
    /// relative, and the same direction within 1e-4, on a 65 x 65 grid of
    /// `u` with the square's edges, for lights near, far, grazing, long and
    /// off to the side.
    #[test]
    fn f32_rectangle_agrees_with_f64_where_used() {
        let cases: [(Vec3, Vec3, Vec3, Vec3); 8] = [
            (
                Vec3::new(-0.5, -0.3, 0.8),
                Vec3::new(1.2, 0.0, 0.3),
                Vec3::new(0.0, 0.9, 0.0),
                Vec3::ZERO,
            ),
            // 0.1 under the centre of a unit square: 3.9 sr.
            (Vec3::new(-0.5, -0.5, 0.1), Vec3::X, Vec3::Y, Vec3::ZERO),
            // A unit square 25 away: 1.6e-3 sr.
            (Vec3::new(-0.5, -0.5, 25.0), Vec3::X, Vec3::Y, Vec3::ZERO),
            // Grazing: 0.05 below the plane of a light 0.2 to 0.5 away
            // (3.2 degrees at its far edge).
            (
                Vec3::new(-0.5, 0.05, 0.2),
                Vec3::X,
                0.3 * Vec3::Z,
                Vec3::ZERO,
            ),
            // Long and off to the side.
            (
                Vec3::new(10.0, -0.5, 1.0),
                Vec3::new(100.0, 0.0, 0.0),
                Vec3::Y,
                Vec3::ZERO,
            ),
            (
                Vec3::new(-1.0, 0.2, 0.3),
                Vec3::new(4.0, 0.0, 0.0),
                Vec3::new(0.0, 0.5, 0.0),
                Vec3::ZERO,
            ),
            // The Cornell box's light from near the top of a side wall.
            (
                Vec3::new(-0.25, 1.999, -0.2),
                Vec3::new(0.0, 0.0, 0.4),
                Vec3::new(0.5, 0.0, 0.0),
                Vec3::new(-1.0, 1.9, 0.0),
            ),
            // A light far from the origin, seen from nearby.
            (
                Vec3::new(1000.0, 2000.0, 3000.0),
                Vec3::new(0.0, 2.0, 0.0),
                Vec3::new(0.0, 0.0, 1.0),
                Vec3::new(1001.0, 2000.5, 3000.1),
            ),
        ];
        for (corner, ex, ey, p) in cases {
            let fast = SphericalRectangleF32::new(corner, ex, ey, p).expect("the f32 path");
            let fine = SphericalRectangle::new(corner, ex, ey, p).expect("a light");
            let omega = fine.area;
            let pdf_error = f64::from(fast.area) / omega - 1.0;
            assert!(pdf_error.abs() < 1e-6, "{corner} {p}: pdf {pdf_error:e}");
            let (mut worst, mut worst_w) = (0.0f64, 0.0f32);
            for i in 0..=64 {
                for j in 0..=64 {
                    let u = Vec2::new(i as f32 / 64.0, j as f32 / 64.0)
                        .min(Vec2::splat(ONE_MINUS_EPSILON));
                    let (w32, _, st32) = fast.sample(u);
                    let (w64, _, st64) = fine.sample(u);
                    let moved = (st32 - st64).abs().max_element();
                    worst = worst.max(f64::from(moved));
                    worst_w = worst_w.max((w32 - w64).length());
                }
            }
            std::println!(
                "omega {omega:.2e}: pdf error {pdf_error:.1e}, direction error {worst_w:.1e}, (s, t) error {worst:.1e}"
            );
            assert!(worst_w < 1e-4, "{corner} {p}: direction error {worst_w:e}");
        }
        // Where f32 would err, f64 takes over: 1e-4 under the centre of a
        // unit square (nearly a hemisphere), a unit square 40 away (6e-4
        // sr), and 0.01 below the plane of a unit square 1 away (grazing).
        for (corner, ey) in [
            (Vec3::new(-0.5, -0.5, 1e-4), Vec3::Y),
            (Vec3::new(-0.5, -0.5, 40.0), Vec3::Y),
            (Vec3::new(-0.5, 0.01, 1.0), Vec3::Z),
        ] {
            assert!(SphericalRectangleF32::new(corner, Vec3::X, ey, Vec3::ZERO).is_none());
        }
    }
}
