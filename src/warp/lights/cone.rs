//! A cone of directions: a spherical light seen from outside it.

use core::f32::consts::TAU;

use glam::{Vec2, Vec3};

use crate::primitives::ONE_MINUS_EPSILON;
use crate::warp::{clamp_unit, clamp_unit2, turn_fraction};

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
/// light's centre ([`to_world`]).
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
///
/// [`uniform_sphere`]: crate::warp::uniform_sphere
/// [`to_world`]: crate::warp::to_world
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
///
/// [`uniform_sphere_inverse`]: crate::warp::uniform_sphere_inverse
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
