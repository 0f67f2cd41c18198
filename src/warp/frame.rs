//! The local frame of the hemisphere and cone maps, `+z` along a normal,
//! carried to the world and back.

use glam::Vec3;

/// The world direction of `local`, a direction in the frame whose `z` is
/// the unit vector `normal` ([`cosine_hemisphere`](super::cosine_hemisphere),
/// [`uniform_cone`](super::uniform_cone)): `local.x t + local.y b +
/// local.z normal`, with `(t, b)` glam's
/// [`any_orthonormal_pair`](Vec3::any_orthonormal_pair) of `normal` (Duff
/// et al. 2017).
///
/// The frame is orthonormal and right-handed (`t x b = normal`) for a unit
/// `normal`, so lengths, angles and solid angles are kept: a map's pdf is
/// the same in the world, and `to_world(normal, local).dot(normal)` is
/// `local.z`. It is continuous in `normal` except across `normal.z = 0`,
/// where `t` and `b` change sign. `normal` must have unit length; glam
/// checks it only with its `glam-assert` feature, and a longer or shorter
/// one gives a frame that is not orthonormal.
///
/// ```
/// use wellspread::warp::to_world;
/// use wellspread::glam::Vec3;
/// assert_eq!(to_world(Vec3::Z, Vec3::new(0.6, 0.0, 0.8)), Vec3::new(0.6, 0.0, 0.8));
/// let n = Vec3::new(1.0, 2.0, 2.0) / 3.0;
/// assert!((to_world(n, Vec3::Z) - n).length() < 1e-6);
/// ```
#[inline]
#[must_use]
pub fn to_world(normal: Vec3, local: Vec3) -> Vec3 {
    let (t, b) = normal.any_orthonormal_pair();
    local.x * t + local.y * b + local.z * normal
}

/// The inverse of [`to_world`]: the direction `world` in the frame whose
/// `z` is the unit vector `normal`, the same frame `(t, b, normal)`, as
/// `(world . t, world . b, world . normal)`.
///
/// ```
/// use wellspread::warp::{to_local, to_world};
/// use wellspread::glam::Vec3;
/// let n = Vec3::new(0.0, -0.8, 0.6);
/// assert!((to_local(n, n) - Vec3::Z).length() < 1e-6);
/// let v = Vec3::new(0.48, 0.6, 0.64);
/// assert!((to_local(n, to_world(n, v)) - v).length() < 1e-6);
/// ```
#[inline]
#[must_use]
pub fn to_local(normal: Vec3, world: Vec3) -> Vec3 {
    let (t, b) = normal.any_orthonormal_pair();
    Vec3::new(world.dot(t), world.dot(b), world.dot(normal))
}
