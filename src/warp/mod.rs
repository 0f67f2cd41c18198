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
//! `n^-0.5` for random points (`tests/warp/` measures the slopes).
//!
//! Every function is pure and `no_std`; the trigonometry is
//! [`libm`](https://docs.rs/libm)'s, whatever the features, so the values
//! are the same in `std` and `no_std` builds. Directions are in a local
//! frame with the normal along `+z`; [`to_world`] carries them to the
//! world (see the last section).
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
//! positive and finite, so a renderer may divide by it: `tests/warp/`
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
//! # From the local frame to the world
//!
//! The hemisphere and cone maps return directions about `+z`: a BSDF's
//! local frame, with the shading normal as `z`, or a frame whose `z`
//! points at a spherical light's centre. To use one in world space,
//! complete the unit normal `n` to an orthonormal basis `t, b, n` and
//! take `x t + y b + z n`. [`to_world`] does that with glam's
//! [`Vec3::any_orthonormal_pair`](glam::Vec3::any_orthonormal_pair), the
//! branchless construction of Duff et al. 2017: continuous everywhere but
//! across the plane `n.z = 0`, where the sign of `n.z` flips the pair, and
//! right-handed (`t x b = n`).
//! [`to_local`] is its inverse, for a BSDF that evaluates in the local
//! frame. A renderer that keeps a tangent frame of its own (from the
//! mesh's UVs, for anisotropic materials) uses that one instead.
//!
//! ```
//! use wellspread::glam::{Vec2, Vec3};
//! use wellspread::warp;
//!
//! let normal = Vec3::new(0.0, 0.6, -0.8);
//! let local = warp::cosine_hemisphere(Vec2::new(0.3, 0.8));
//! let world = warp::to_world(normal, local);
//! // The cosine with the normal is the local z, and the pdf is the same.
//! assert!((world.dot(normal) - local.z).abs() < 1e-6);
//! assert!((world.length() - 1.0).abs() < 1e-6);
//! assert!((warp::to_local(normal, world) - local).length() < 1e-6);
//!
//! // The same by hand with glam: `t x b = n`, so the frame is right-handed.
//! let (t, b) = normal.any_orthonormal_pair();
//! assert!((t.cross(b) - normal).length() < 1e-6);
//! assert!((local.x * t + local.y * b + local.z * normal - world).length() < 1e-6);
//! ```
//!
//! # References
//!
//! - Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
//!   appendix A.5 (sampling multidimensional functions).
//! - Mitsuba 3's `warp.h` keeps each map, its pdf and its inverse together;
//!   this module follows that layout.
//! - Duff, Burgess, Christensen, Hery, Kensler, Liani & Villemin 2017,
//!   "Building an Orthonormal Basis, Revisited", Journal of Computer
//!   Graphics Techniques 6(1) (the frame of [`to_world`]).

mod choices;
mod frame;
mod lights;
mod shapes;

#[cfg(feature = "alloc")]
pub use choices::{AliasTable, Discrete};
pub use choices::{discrete, discrete_checked, discrete_inverse, discrete_pdf};
pub use frame::{to_local, to_world};
pub use lights::{
    RectangleLightSample, TriangleLightSample, spherical_rectangle, spherical_rectangle_pdf,
    spherical_triangle, spherical_triangle_inverse, spherical_triangle_pdf, uniform_cone,
    uniform_cone_inverse, uniform_cone_pdf,
};
pub use shapes::{
    concentric_disk, concentric_disk_inverse, concentric_disk_pdf, cosine_hemisphere,
    cosine_hemisphere_inverse, cosine_hemisphere_pdf, rectangle, rectangle_inverse, rectangle_pdf,
    uniform_ball, uniform_ball_inverse, uniform_ball_pdf, uniform_hemisphere,
    uniform_hemisphere_inverse, uniform_hemisphere_pdf, uniform_sphere, uniform_sphere_inverse,
    uniform_sphere_pdf, uniform_triangle, uniform_triangle_inverse, uniform_triangle_pdf,
};

use core::f32::consts::TAU;

use glam::Vec2;

use crate::primitives::ONE_MINUS_EPSILON;

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

/// The atan2 angle of `(x, y)` as a fraction of a turn, in `[0, 1)`.
#[inline]
fn turn_fraction(x: f32, y: f32) -> f32 {
    let phi = libm::atan2f(y, x) * (1.0 / TAU);
    // atan2 is in [-pi, pi]: negative angles wrap to the upper half.
    clamp_unit(if phi < 0.0 { phi + 1.0 } else { phi })
}
