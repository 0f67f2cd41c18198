//! A triangle light sampled uniformly in its solid angle (Arvo 1995).

use glam::{DVec3, Vec2, Vec3};

use super::{NEEDLE, sees_plane, solid_angle_pdf};
use crate::warp::{clamp_unit, clamp_unit2};

/// A direction toward a triangle light, as [`spherical_triangle`] returns
/// it: where it points, how likely it was, and where it meets the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleLightSample {
    /// The unit direction from the shading point `p` toward the light
    /// (within 2^-23 of unit length); toward the centroid when the light
    /// has no solid angle from `p`.
    pub direction: Vec3,
    /// The density of `direction` with respect to solid angle, `1 /
    /// omega`, the same as [`spherical_triangle_pdf`]; 0 for a light of no
    /// solid angle from `p`, which a renderer skips.
    pub pdf: f32,
    /// The barycentrics `(b0, b1, b2)` of the point where `direction`
    /// meets the triangle, `b0 a + b1 b + b2 c`: each `>= 0`, summing to 1
    /// within 2^-23 (1/3 each, the centroid, with pdf 0). Interpolate the
    /// light's normal, texture coordinates or emission with them, or
    /// rebuild the point to get its distance.
    pub barycentrics: Vec3,
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

/// The spherical triangle of a light triangle seen from a point: the unit
/// directions to its vertices and its solid angle, or `None` when that is
/// 0 (the point is in the triangle's plane, up to [`IN_PLANE`](super::IN_PLANE), which
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
fn degenerate_triangle(a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> TriangleLightSample {
    let centroid = (a + b + c) / 3.0;
    TriangleLightSample {
        direction: (centroid - p).normalize_or(Vec3::Z),
        pdf: 0.0,
        barycentrics: Vec3::splat(1.0 / 3.0),
    }
}

/// Uniform directions from `p` in the solid angle of the triangle `a b c`
/// (Arvo 1995): returns a [`TriangleLightSample`], the direction (unit
/// length), its pdf with respect to solid angle and the barycentrics `(b0,
/// b1, b2)` of the point where the direction meets the triangle (`b0 a +
/// b1 b + b2 c`).
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
///   its f32 rounding (`tests/warp/` checks 1e-6 rad over random,
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
/// (`tests/warp/`). What limits a small light is the f32 direction
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
/// let sample = spherical_triangle(u, a, b, c, p);
/// let (w, bary) = (sample.direction, sample.barycentrics);
/// assert!((w.length() - 1.0).abs() < 1e-6 && bary.min_element() >= 0.0);
/// assert_eq!(sample.pdf, spherical_triangle_pdf(a, b, c, p));
/// // The direction hits the triangle at the barycentric point.
/// let hit = bary.x * a + bary.y * b + bary.z * c;
/// assert!((hit.normalize() - w).length() < 1e-5);
/// assert!((spherical_triangle_inverse(w, a, b, c, p) - u).abs().max_element() < 1e-5);
/// // Seen edge-on, the triangle has no solid angle: pdf 0.
/// assert_eq!(spherical_triangle(u, a, b, c, Vec3::new(5.0, 0.0, 1.0)).pdf, 0.0);
/// ```
///
/// # References
///
/// - Arvo 1995, "Stratified Sampling of Spherical Triangles", SIGGRAPH
///   95, pp. 437-438.
/// - Van Oosterom & Strackee 1983, "The Solid Angle of a Plane Triangle",
///   IEEE Transactions on Biomedical Engineering 30(2).
///
/// [`uniform_triangle`]: crate::warp::uniform_triangle
#[inline]
pub fn spherical_triangle(u: Vec2, a: Vec3, b: Vec3, c: Vec3, p: Vec3) -> TriangleLightSample {
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
    TriangleLightSample {
        direction: w.as_vec3(),
        pdf: solid_angle_pdf(t.area),
        barycentrics: triangle_barycentrics(w, a, b, c, p),
    }
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
/// let w = spherical_triangle(u, a, b, c, p).direction;
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
