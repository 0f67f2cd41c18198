//! Lights: a cone of directions (a spherical light), and triangles and
//! rectangles sampled uniformly in the solid angle they cover as seen
//! from a shading point. This file holds what the two planar lights
//! share: when a point sees a light at all ([`sees_plane`]) and the pdf of
//! a solid angle.

mod cone;
mod spherical_rectangle;
mod spherical_triangle;

pub use cone::{uniform_cone, uniform_cone_inverse, uniform_cone_pdf};
pub use spherical_rectangle::{RectangleLightSample, spherical_rectangle, spherical_rectangle_pdf};
pub use spherical_triangle::{
    TriangleLightSample, spherical_triangle, spherical_triangle_inverse, spherical_triangle_pdf,
};

use glam::DVec3;

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

/// How far from a planar light's plane a shading point must be, relative
/// to its distance from the light's farthest vertex, to see the light at
/// all: 2^-20, sixteen roundings of an f32 coordinate (2^-24). Nearer the
/// plane (on the light, on an edge or a vertex, or in the plane outside
/// it, up to that margin) the light's solid angle is decided by the
/// rounding of the point's coordinates, and the edges' directions from the
/// point are too nearly opposite to be computed: the light warps return
/// pdf 0. At 2^-24 the triangle map's directions still missed the light
/// by more than 1e-6 rad for points just off the plane (`tests/warp/`'s
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
/// directions missed the light by more than 1e-6 rad (`tests/warp/`'s
/// property tests found a sliver of 1.5e-6 seen from 1.1e-6 above its
/// plane missing by 2e-5 rad).
const SLIVER_IN_PLANE: f64 = 1.0 / 1_073_741_824.0;

/// The thinnest planar light the light warps sample: its area at least
/// 2^-20 of its longest side squared (a 1 mm wide strip may be 1 km long).
const SLIVER: f64 = 1.0 / 1_048_576.0;
