//! A rectangle light sampled uniformly in its solid angle (Urena, Fajardo
//! & King 2013), evaluated in f32 where that is accurate and in f64
//! elsewhere.
//!
//! The two evaluations are different formulas, not one written twice:
//! the f64 one is the paper's (the corner angles as `acos` of the edge
//! planes' normals, the solid angle as their sum), the f32 one closed
//! forms in the rectangle's frame (the corner angles as arguments of
//! complex numbers, the solid angle by Van Oosterom & Strackee over two
//! triangles, `k` through its sine and cosine, squared distances where the
//! f64 one takes roots). [`RectangleLight::new`] picks one per rectangle
//! and shading point, and both `sample` steps give a
//! [`RectangleLightSample`].

use core::ops::{Add, Neg};

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{NEEDLE, sees_plane, solid_angle_pdf};
use crate::warp::clamp_unit2;

/// A direction toward a rectangle light, as [`spherical_rectangle`]
/// returns it: where it points, how likely it was, and where it meets the
/// light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RectangleLightSample {
    /// The unit direction from the shading point `p` toward the light
    /// (within 2^-23 of unit length); toward the centre when the light has
    /// no solid angle from `p`.
    pub direction: Vec3,
    /// The density of `direction` with respect to solid angle, `1 /
    /// omega`, the same as [`spherical_rectangle_pdf`] bit for bit; 0 for a
    /// light of no solid angle from `p`, which a renderer skips.
    pub pdf: f32,
    /// The `(s, t)` of the point where `direction` meets the light,
    /// `corner + s ex + t ey`, in `[0, 1]^2` (`(0.5, 0.5)`, the centre,
    /// with pdf 0): the light's texture coordinates, or the point itself
    /// for its distance.
    pub st: Vec2,
}

/// The vector arithmetic of [`in_frame`], for glam's `Vec3` (the f32
/// evaluation) and `DVec3` (the f64 one).
trait FrameVector: Copy + Neg<Output = Self> {
    /// The vector's float.
    type Float: Copy + Default + PartialOrd + Neg<Output = Self::Float> + Add<Output = Self::Float>;
    /// The dot product.
    fn dot(self, other: Self) -> Self::Float;
}

impl FrameVector for Vec3 {
    type Float = f32;
    #[inline]
    fn dot(self, other: Self) -> f32 {
        Vec3::dot(self, other)
    }
}

impl FrameVector for DVec3 {
    type Float = f64;
    #[inline]
    fn dot(self, other: Self) -> f64 {
        DVec3::dot(self, other)
    }
}

/// The rectangle measured from the point in its frame `[x, y, z]` (unit
/// vectors, `x` along `ex`, `y` along the part of `ey` perpendicular to
/// it), as both evaluations take it: `d = corner - p` gives `x0 = d . x`,
/// `y0 = d . y`, `z0 = d . z`, and the far edges are `x1 = x0 + ex_len`
/// and `y1 = y0 + ey_len`. `z` is flipped where `z0` is positive, so that
/// `z0 <= 0`; returns that `z` and `[x0, x1, y0, y1, z0]`.
#[inline]
fn in_frame<V: FrameVector>(
    d: V,
    [x, y, z]: [V; 3],
    ex_len: V::Float,
    ey_len: V::Float,
) -> (V, [V::Float; 5]) {
    let (x0, y0) = (d.dot(x), d.dot(y));
    let z0 = d.dot(z);
    let (z, z0) = if z0 > V::Float::default() {
        (-z, -z0)
    } else {
        (z, z0)
    };
    (z, [x0, x0 + ex_len, y0, y0 + ey_len, z0])
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
        let z = x.cross(y);
        let d = corner.as_dvec3() - o;
        let (z, [x0, x1, y0, y1, z0]) = in_frame(d, [x, y, z], ex_len, ey_len);
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
    fn sample(&self, u: Vec2) -> RectangleLightSample {
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
        RectangleLightSample {
            direction: w.as_vec3(),
            pdf: solid_angle_pdf(r.area),
            st: st.clamp(DVec2::ZERO, DVec2::ONE).as_vec2(),
        }
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
        let z = xd.cross(yd).as_vec3();
        let (z, [x0, x1, y0, y1, z0]) = in_frame(d, [x, y, z], ex_len, ey_len);
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
    fn sample(&self, u: Vec2) -> RectangleLightSample {
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
        RectangleLightSample {
            direction: w.as_vec3(),
            pdf: 1.0 / r.area,
            st: st.clamp(Vec2::ZERO, Vec2::ONE),
        }
    }
}

/// Uniform directions from `p` in the solid angle of the rectangle
/// `corner + s ex + t ey`, `s, t` in `[0, 1]` (Urena, Fajardo & King
/// 2013): returns a [`RectangleLightSample`], the direction (unit
/// length), its pdf with respect to solid angle and the `(s, t)` of the
/// point it hits.
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
///   1e-4 rad (the f32 evaluation's accuracy; `tests/warp/` checks it
///   over random, degenerate and edge geometry at scales 1e-6 to 1e18).
/// - Input `u` outside `[0, 1)^2` is clamped into it (NaN to 0).
///
/// # Cost
///
/// The f32 evaluation: about 150 f32 operations with 15 square roots,
/// one `atan2` and one `sincos` (no inverse cosines: in the rectangle's
/// frame its corner angles and solid angle have closed forms), fewer than
/// the f64 evaluation's and still many more than [`rectangle`]'s (area
/// sampling; `docs/warps.md` has the measurements). The f64
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
/// rectangles: its relative error (measured in `tests/warp/`) is below
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
/// let sample = spherical_rectangle(Vec2::new(0.5, 0.5), corner, ex, ey, p);
/// assert_eq!(sample.pdf, pdf);
/// assert!((sample.direction - Vec3::Z).length() < 1e-6);
/// assert!((sample.st - Vec2::splat(0.5)).length() < 1e-6);
/// // The point hit is corner + s ex + t ey, on the direction.
/// let sample = spherical_rectangle(Vec2::new(0.9, 0.2), corner, ex, ey, p);
/// let hit = corner + sample.st.x * ex + sample.st.y * ey;
/// assert!((hit.normalize() - sample.direction).length() < 1e-6);
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
///
/// [`rectangle`]: crate::warp::rectangle
/// [`spherical_triangle`]: crate::warp::spherical_triangle
#[inline]
pub fn spherical_rectangle(
    u: Vec2,
    corner: Vec3,
    ex: Vec3,
    ey: Vec3,
    p: Vec3,
) -> RectangleLightSample {
    let u = clamp_unit2(u);
    match RectangleLight::new(corner, ex, ey, p) {
        RectangleLight::F32(r) => r.sample(u),
        RectangleLight::F64(r) => r.sample(u),
        RectangleLight::Degenerate => {
            let centre = corner + 0.5 * (ex + ey);
            RectangleLightSample {
                direction: (centre - p).normalize_or(Vec3::Z),
                pdf: 0.0,
                st: Vec2::splat(0.5),
            }
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
    /// [`IN_PLANE`](super::IN_PLANE), which takes in its edges and
    /// corners), a zero edge, a solid angle whose inverse is not a finite
    /// f32, or non-finite input.
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives::ONE_MINUS_EPSILON;

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
                    let (s32, s64) = (fast.sample(u), fine.sample(u));
                    let moved = (s32.st - s64.st).abs().max_element();
                    worst = worst.max(f64::from(moved));
                    worst_w = worst_w.max((s32.direction - s64.direction).length());
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
