//! The scenes by name: the classic aliasing scenes, each a function from a
//! film position (in pixels, `x` right and `y` down, pixel `(px, py)`
//! covering `[px, px + 1) x [py, py + 1)`) to linear RGB, and the
//! path-traced Cornell box (`cornell/`, fed by `path.rs`).
//!
//! Every scene is defined in resolution-independent terms and scaled to the
//! film size it is built for, so `--size` changes the sampling rate, not the
//! picture.

use std::fmt;
use std::str::FromStr;

/// Linear RGB radiance.
pub type Rgb = [f32; 3];

/// Which scene, by the name the command line uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneKind {
    /// An infinite checkerboard plane receding to the horizon.
    Checker,
    /// `1/2 (1 + sin(x^2 y^2))` over `[0, 10]^2`, the zone-plate-like
    /// moire test: beyond a third of the way out it is finer than a pixel.
    Moire,
    /// The same function over `[0, 3]^2`, which the pixels resolve: smooth
    /// inside every pixel, where screen-space error ordering (zsobol) pays.
    MoireResolved,
    /// A yellow polygon on a dark background, at tiny and small sizes.
    Polygon,
    /// The Cornell box, path traced: an area light, a glass sphere, a
    /// thin lens and several bounces, every number drawn from a `Domain`.
    Cornell,
}

impl SceneKind {
    /// Every scene, in the order the default run renders them.
    pub const ALL: [SceneKind; 5] = [
        SceneKind::Checker,
        SceneKind::Moire,
        SceneKind::MoireResolved,
        SceneKind::Polygon,
        SceneKind::Cornell,
    ];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            SceneKind::Checker => "checker",
            SceneKind::Moire => "moire",
            SceneKind::MoireResolved => "moire-resolved",
            SceneKind::Polygon => "polygon",
            SceneKind::Cornell => "cornell",
        }
    }

    /// Whether the scene draws a lens point, so that drawing film and lens
    /// as one 4D point or as two pairs can differ.
    pub fn has_lens(self) -> bool {
        match self {
            SceneKind::Checker
            | SceneKind::Moire
            | SceneKind::MoireResolved
            | SceneKind::Polygon => false,
            SceneKind::Cornell => true,
        }
    }

    /// The sample counts the default run renders: powers of four, so every
    /// count is a square and each step should cut the error of a
    /// stratified pattern by at least 2.
    pub fn default_spps(self) -> &'static [u32] {
        match self {
            SceneKind::Checker
            | SceneKind::Moire
            | SceneKind::MoireResolved
            | SceneKind::Polygon => &[1, 4, 16, 64, 256],
            // A path costs about six rays: 4 and 16 spp for every sampler
            // keep the default run near its minute.
            SceneKind::Cornell => &[4, 16],
        }
    }

    /// Frames per row in the default run. The path-traced scene's error is
    /// dominated by rare bright paths (caustics through the glass), so one
    /// frame's RMSE varies by several percent from frame to frame: four frames
    /// bring that under the differences its tables compare.
    pub fn default_frames(self) -> u32 {
        match self {
            SceneKind::Checker
            | SceneKind::Moire
            | SceneKind::MoireResolved
            | SceneKind::Polygon => 1,
            SceneKind::Cornell => 4,
        }
    }

    /// The film sizes (width, height) the default run renders. The default
    /// run (eleven samplers, 1 + 4 + 16 + 64 + 256 = 341 samples per pixel)
    /// shades about 12.6 M samples per sampler and scene at 192 x 192; the
    /// whole run is about 45 CPU seconds on the machine of
    /// `docs/tracer.md`, so it fits in well under a minute on two cores.
    /// The polygon is shown at 5 x 7, where one pixel is a large fraction
    /// of the shape, and at 64 x 64, where the staircase along its edges is
    /// plain. The Cornell box at 128 x 128, 4 and 16 spp and 4 frames traces
    /// about 16 M paths for twelve samplers, about 8 CPU seconds.
    pub fn default_sizes(self) -> &'static [(u32, u32)] {
        match self {
            SceneKind::Checker | SceneKind::Moire | SceneKind::MoireResolved => &[(192, 192)],
            SceneKind::Polygon => &[(5, 7), (64, 64)],
            SceneKind::Cornell => &[(128, 128)],
        }
    }

    /// The scene for a film of `width x height` pixels.
    pub fn build(self, width: u32, height: u32) -> Built {
        match self {
            SceneKind::Checker => Built::Film(Scene::Checker(Checker::new(width, height))),
            SceneKind::Moire => Built::Film(Scene::Moire(Moire::new(width, height, Moire::RANGE))),
            SceneKind::MoireResolved => Built::Film(Scene::Moire(Moire::new(
                width,
                height,
                Moire::RESOLVED_RANGE,
            ))),
            SceneKind::Polygon => Built::Film(Scene::Polygon(Polygon::new(width, height))),
            SceneKind::Cornell => Built::PathTraced,
        }
    }

    /// The film function of a 2D scene; `None` for the path-traced one.
    #[cfg(test)]
    pub fn film(self, width: u32, height: u32) -> Option<Scene> {
        match self.build(width, height) {
            Built::Film(scene) => Some(scene),
            Built::PathTraced => None,
        }
    }
}

impl fmt::Display for SceneKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for SceneKind {
    type Err = String;

    fn from_str(name: &str) -> Result<Self, Self::Err> {
        crate::shared::by_name(&SceneKind::ALL, name, SceneKind::name, "scene")
    }
}

/// A scene built for one film size, as the render loop takes it.
#[derive(Clone, Debug)]
pub enum Built {
    /// A function of the film position, rendered by `render.rs` under any
    /// filter.
    Film(Scene),
    /// The Cornell box: `cornell/` builds its own geometry for the film
    /// size, `path.rs` feeds it the samples (box filter).
    PathTraced,
}

/// A 2D scene built for one film size. An enum rather than a trait object so
/// the per-sample call is a `match` the compiler can inline.
#[derive(Clone, Debug)]
pub enum Scene {
    /// See [`Checker`].
    Checker(Checker),
    /// See [`Moire`].
    Moire(Moire),
    /// See [`Polygon`].
    Polygon(Polygon),
}

impl Scene {
    /// Radiance arriving at film position `(x, y)`, in pixels.
    #[inline]
    pub fn radiance(&self, x: f64, y: f64) -> Rgb {
        match self {
            Scene::Checker(s) => s.radiance(x, y),
            Scene::Moire(s) => s.radiance(x, y),
            Scene::Polygon(s) => s.radiance(x, y),
        }
    }
}

/// An infinite checkerboard on the ground plane, seen by a pinhole camera
/// standing one unit above it and pitched slightly down, so the horizon
/// crosses the upper third of the frame.
///
/// Towards the horizon a pixel's footprint on the plane grows without bound
/// and eventually covers arbitrarily many squares, whose true average is a
/// flat grey: no finite sample count resolves those rows, and a regular grid
/// turns them into moire while stratified patterns turn them into fine noise.
/// The board is turned 30 degrees about the vertical so the square edges
/// cross pixel rows and columns at an angle (edges parallel to the pixel grid
/// would flatter every sampler).
#[derive(Clone, Debug)]
pub struct Checker {
    width: f64,
    height: f64,
    /// `tan(vertical field of view / 2)`.
    tan_half_fov: f64,
    aspect: f64,
    /// Camera basis in world space (y up): right, up, forward.
    right: [f64; 3],
    up: [f64; 3],
    forward: [f64; 3],
    /// Rotation of the board about the vertical, as (cos, sin).
    board_rotation: (f64, f64),
}

impl Checker {
    /// Height of the eye above the plane, in board units.
    const EYE_HEIGHT: f64 = 1.0;
    /// Side of one square. A quarter of the eye height puts about six
    /// squares across the bottom of the frame: big enough to read, small
    /// enough that aliasing starts halfway up the plane.
    const SQUARE: f64 = 0.25;
    pub const BLACK: Rgb = [0.02, 0.02, 0.02];
    pub const WHITE: Rgb = [0.9, 0.9, 0.9];
    pub const SKY: Rgb = [0.35, 0.5, 0.8];

    fn new(width: u32, height: u32) -> Self {
        let pitch = (-12.0f64).to_radians();
        let (sp, cp) = pitch.sin_cos();
        let yaw = 30.0f64.to_radians();
        Self {
            width: f64::from(width),
            height: f64::from(height),
            tan_half_fov: 25.0f64.to_radians().tan(),
            aspect: f64::from(width) / f64::from(height),
            right: [1.0, 0.0, 0.0],
            up: [0.0, cp, -sp],
            forward: [0.0, sp, cp],
            board_rotation: (yaw.cos(), yaw.sin()),
        }
    }

    #[inline]
    fn radiance(&self, x: f64, y: f64) -> Rgb {
        match self.board_hit(x, y) {
            None => Self::SKY,
            Some((u, v)) => Self::square_colour(u.floor(), v.floor()),
        }
    }

    /// Colour of square `(i, j)` (integer-valued floats). f64 keeps the
    /// parity exact far past where f32 would fail (2^53 squares); a grazing
    /// ray reaches about 10^7 squares at 4k sizes.
    #[inline]
    fn square_colour(i: f64, j: f64) -> Rgb {
        if (i + j).rem_euclid(2.0) == 0.0 {
            Self::WHITE
        } else {
            Self::BLACK
        }
    }

    /// Where the ray through film position `(x, y)` meets the board, in
    /// square units `(u, v)`; `None` for the sky.
    #[inline]
    fn board_hit(&self, x: f64, y: f64) -> Option<(f64, f64)> {
        // Film to the image plane at distance 1 along `forward`.
        let sx = (2.0 * x / self.width - 1.0) * self.tan_half_fov * self.aspect;
        let sy = (1.0 - 2.0 * y / self.height) * self.tan_half_fov;
        let d: [f64; 3] =
            std::array::from_fn(|i| self.forward[i] + sx * self.right[i] + sy * self.up[i]);
        // The right vector is horizontal (no roll), so only d.y decides
        // whether the ray goes down to the plane.
        if d[1] >= 0.0 {
            return None;
        }
        let t = Self::EYE_HEIGHT / -d[1];
        let (wx, wz) = (t * d[0], t * d[2]);
        let (c, s) = self.board_rotation;
        Some((
            (c * wx - s * wz) / Self::SQUARE,
            (s * wx + c * wz) / Self::SQUARE,
        ))
    }

    /// The film position where board point `(u, v)` (square units) appears,
    /// or `None` if it is not in front of the camera.
    fn project(&self, u: f64, v: f64) -> Option<[f64; 2]> {
        let (c, s) = self.board_rotation;
        // Inverse of the rotation in `board_hit`, relative to the eye.
        let q = [
            Self::SQUARE * (c * u + s * v),
            -Self::EYE_HEIGHT,
            Self::SQUARE * (-s * u + c * v),
        ];
        let dot = |a: &[f64; 3]| a[0] * q[0] + a[1] * q[1] + a[2] * q[2];
        let depth = dot(&self.forward);
        if depth <= 1e-9 {
            return None;
        }
        let sx = dot(&self.right) / depth / (self.tan_half_fov * self.aspect);
        let sy = dot(&self.up) / depth / self.tan_half_fov;
        Some([
            (sx + 1.0) * self.width / 2.0,
            (1.0 - sy) * self.height / 2.0,
        ])
    }

    /// The exact box-filtered value of pixel `(px, py)`, when it can be had
    /// cheaply; `None` for pixels that straddle the horizon or see more than
    /// `max_squares` candidate squares (the caller samples those densely).
    ///
    /// A pinhole maps the board to the film by a projective map, which keeps
    /// straight lines straight: each square appears as a quadrilateral, so
    /// its exact share of the pixel is a polygon clip. If all four pixel
    /// corners see the same square, the convex pixel lies inside that
    /// (convex) square's image and the pixel is one flat colour.
    pub fn exact_pixel(&self, px: u32, py: u32, max_squares: u64) -> Option<Rgb> {
        let (x0, y0) = (f64::from(px), f64::from(py));
        let corners = [
            (x0, y0),
            (x0 + 1.0, y0),
            (x0, y0 + 1.0),
            (x0 + 1.0, y0 + 1.0),
        ];
        let hits: Vec<Option<(f64, f64)>> =
            corners.iter().map(|&(x, y)| self.board_hit(x, y)).collect();
        if hits.iter().all(Option::is_none) {
            // The sky is the half-plane above the horizon line: convex.
            return Some(Self::SKY);
        }
        // A pixel on the horizon sees squares out to infinity.
        let hits: Vec<(f64, f64)> = hits.into_iter().collect::<Option<_>>()?;
        let fold = |f: fn(f64, f64) -> f64, start: f64, pick: fn(&(f64, f64)) -> f64| {
            hits.iter().map(pick).fold(start, f)
        };
        let (i_lo, i_hi) = (
            fold(f64::min, f64::INFINITY, |h| h.0).floor(),
            fold(f64::max, f64::NEG_INFINITY, |h| h.0).floor(),
        );
        let (j_lo, j_hi) = (
            fold(f64::min, f64::INFINITY, |h| h.1).floor(),
            fold(f64::max, f64::NEG_INFINITY, |h| h.1).floor(),
        );
        let count = (i_hi - i_lo + 1.0) * (j_hi - j_lo + 1.0);
        if count > max_squares as f64 {
            return None;
        }
        // White area by clipping every white square's image; the rest of
        // the (fully board-covered) pixel is black.
        let mut white = 0.0;
        let mut j = j_lo;
        while j <= j_hi {
            let mut i = i_lo;
            while i <= i_hi {
                if Self::square_colour(i, j) == Self::WHITE {
                    let quad = [(i, j), (i + 1.0, j), (i + 1.0, j + 1.0), (i, j + 1.0)]
                        .map(|(u, v)| self.project(u, v));
                    let quad: Vec<[f64; 2]> = quad.into_iter().collect::<Option<_>>()?;
                    white += area_in_pixel(&quad, px, py);
                }
                i += 1.0;
            }
            j += 1.0;
        }
        let white = white.clamp(0.0, 1.0);
        Some(std::array::from_fn(|c| {
            let (w, b) = (f64::from(Self::WHITE[c]), f64::from(Self::BLACK[c]));
            (b + white * (w - b)) as f32
        }))
    }
}

/// `f(u, v) = 1/2 (1 + sin(u^2 v^2))` over `u, v in [0, range]`, origin at
/// the bottom left: `range` is 10 for `moire` and 3 for `moire-resolved`.
///
/// Over `[0, 3]^2` the highest local frequency, `2 uv sqrt(u^2 + v^2)` at
/// the far corner, is about 76 radians per unit, 1.2 radians per pixel at
/// 192 pixels: below Nyquist (pi) everywhere, so the image is resolved and
/// smooth inside each pixel.
///
/// The local frequency grows like `|grad(u^2 v^2)| = 2uv sqrt(u^2 + v^2)`
/// radians per unit. With the classic range of 10 units across, the Nyquist
/// contour (pi radians per pixel) crosses the diagonal at about 2.8 units
/// at 192 pixels (the default) and 3.8 at 512: the bottom-left third shows the clean
/// hyperbolic bands, everything beyond it is finer than a pixel and should
/// average to a flat 1/2. A regular grid instead paints false rings there
/// (strong aliasing even at 512 x 512); random-based patterns paint noise.
#[derive(Clone, Debug)]
pub struct Moire {
    /// Domain units per pixel along x and y.
    scale_x: f64,
    scale_y: f64,
    height: f64,
}

impl Moire {
    /// Side of the square domain `[0, RANGE]^2` of `moire`.
    pub const RANGE: f64 = 10.0;
    /// Side of the domain of `moire-resolved`.
    pub const RESOLVED_RANGE: f64 = 3.0;

    fn new(width: u32, height: u32, range: f64) -> Self {
        Self {
            scale_x: range / f64::from(width),
            scale_y: range / f64::from(height),
            height: f64::from(height),
        }
    }

    /// Film position to domain coordinates, `v` growing upwards.
    #[inline]
    fn domain(&self, x: f64, y: f64) -> (f64, f64) {
        (x * self.scale_x, (self.height - y) * self.scale_y)
    }

    /// The scalar `f`, exposed for the quadrature reference.
    #[inline]
    pub fn value(&self, x: f64, y: f64) -> f64 {
        let (u, v) = self.domain(x, y);
        let uv = u * v;
        0.5 * (1.0 + (uv * uv).sin())
    }

    /// An upper bound on the phase change of `sin(u^2 v^2)` across the film
    /// rectangle `[x0, x1] x [y0, y1]` along x and along y, in radians: the
    /// quadrature reference subdivides until each piece spans under one
    /// wavelength.
    pub fn phase_span(&self, x0: f64, x1: f64, y0: f64, y1: f64) -> (f64, f64) {
        let (u_max, _) = self.domain(x1, y1);
        let (_, v_max) = self.domain(x0, y0);
        // d/du (u^2 v^2) = 2 u v^2 and d/dv = 2 u^2 v, both largest at the
        // rectangle's far corner.
        let along_x = 2.0 * u_max * v_max * v_max * (x1 - x0) * self.scale_x;
        let along_y = 2.0 * u_max * u_max * v_max * (y1 - y0) * self.scale_y;
        (along_x, along_y)
    }

    #[inline]
    fn radiance(&self, x: f64, y: f64) -> Rgb {
        let f = self.value(x, y) as f32;
        [f, f, f]
    }
}

/// A yellow, slightly concave polygon on a dark background: the textbook
/// jaggies. Its vertices are fractions of the film, so the 5 x 7 and the
/// 64 x 64 renders show the same shape.
#[derive(Clone, Debug)]
pub struct Polygon {
    /// Vertices in film pixels, counter-clockwise on screen (y down).
    vertices: Vec<[f64; 2]>,
}

impl Polygon {
    /// The shape as fractions of the film width and height. Long, shallow
    /// edges at angles near 10 and 60 degrees make the steps obvious; the
    /// notch on the right makes it concave, which clipping must handle.
    const SHAPE: [[f64; 2]; 5] = [
        [0.12, 0.18],
        [0.86, 0.08],
        [0.62, 0.48],
        [0.90, 0.90],
        [0.22, 0.78],
    ];
    pub const YELLOW: Rgb = [1.0, 0.85, 0.05];
    pub const BACKGROUND: Rgb = [0.03, 0.03, 0.08];

    fn new(width: u32, height: u32) -> Self {
        let (w, h) = (f64::from(width), f64::from(height));
        Self {
            vertices: Self::SHAPE.iter().map(|&[u, v]| [u * w, v * h]).collect(),
        }
    }

    /// Even-odd inside test (crossing number along +x).
    #[inline]
    fn contains(&self, x: f64, y: f64) -> bool {
        let mut inside = false;
        let mut previous = self.vertices[self.vertices.len() - 1];
        for &current in &self.vertices {
            let ([x0, y0], [x1, y1]) = (previous, current);
            // Half-open in y so a vertex on the scan line counts once.
            if (y0 > y) != (y1 > y) {
                let crossing = x0 + (y - y0) / (y1 - y0) * (x1 - x0);
                if x < crossing {
                    inside = !inside;
                }
            }
            previous = current;
        }
        inside
    }

    #[inline]
    fn radiance(&self, x: f64, y: f64) -> Rgb {
        if self.contains(x, y) {
            Self::YELLOW
        } else {
            Self::BACKGROUND
        }
    }

    /// The exact fraction of pixel `(px, py)` the polygon covers: the
    /// polygon clipped against the pixel square (Sutherland & Hodgman 1974),
    /// then the shoelace area. Clipping a concave polygon against a convex
    /// window can leave zero-width slivers along the window's edges, but
    /// they add no area, so the result is still exact.
    pub fn coverage(&self, px: u32, py: u32) -> f64 {
        area_in_pixel(&self.vertices, px, py)
    }
}

/// The area of `poly` (film pixels, any orientation) inside pixel
/// `(px, py)`: clip against the pixel's four sides, then the shoelace
/// formula.
pub fn area_in_pixel(poly: &[[f64; 2]], px: u32, py: u32) -> f64 {
    let (x0, y0) = (f64::from(px), f64::from(py));
    let (x1, y1) = (x0 + 1.0, y0 + 1.0);
    // Keep the half-plane where `inside` holds; `cut` finds where the
    // segment crosses the boundary.
    let poly = clip(poly, |p| p[0] >= x0, |a, b| lerp_at(a, b, 0, x0));
    let poly = clip(&poly, |p| p[0] <= x1, |a, b| lerp_at(a, b, 0, x1));
    let poly = clip(&poly, |p| p[1] >= y0, |a, b| lerp_at(a, b, 1, y0));
    let poly = clip(&poly, |p| p[1] <= y1, |a, b| lerp_at(a, b, 1, y1));
    shoelace_area(&poly).abs()
}

/// One Sutherland-Hodgman pass: the part of `poly` inside one half-plane.
fn clip(
    poly: &[[f64; 2]],
    inside: impl Fn([f64; 2]) -> bool,
    cut: impl Fn([f64; 2], [f64; 2]) -> [f64; 2],
) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(poly.len() + 2);
    let Some(&last) = poly.last() else {
        return out;
    };
    let mut previous = last;
    for &current in poly {
        match (inside(previous), inside(current)) {
            (true, true) => out.push(current),
            (true, false) => out.push(cut(previous, current)),
            (false, true) => {
                out.push(cut(previous, current));
                out.push(current);
            }
            (false, false) => {}
        }
        previous = current;
    }
    out
}

/// The point of segment `a -> b` whose coordinate `axis` equals `value`.
fn lerp_at(a: [f64; 2], b: [f64; 2], axis: usize, value: f64) -> [f64; 2] {
    let t = (value - a[axis]) / (b[axis] - a[axis]);
    let mut p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    // Snap exactly onto the clip line so later passes see it inside.
    p[axis] = value;
    p
}

/// Signed area of a simple (or sliver-carrying) polygon.
fn shoelace_area(poly: &[[f64; 2]]) -> f64 {
    let Some(&last) = poly.last() else {
        return 0.0;
    };
    let mut previous = last;
    let mut twice = 0.0;
    for &current in poly {
        twice += previous[0] * current[1] - current[0] * previous[1];
        previous = current;
    }
    twice / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coverage_sums_to_the_polygon_area() {
        let polygon = Polygon::new(64, 64);
        let total: f64 = (0..64)
            .flat_map(|py| (0..64).map(move |px| (px, py)))
            .map(|(px, py)| polygon.coverage(px, py))
            .sum();
        let exact = shoelace_area(&polygon.vertices).abs();
        assert!((total - exact).abs() < 1e-9, "{total} vs {exact}");
    }

    #[test]
    fn coverage_agrees_with_the_inside_test() {
        // A 256 x 256 grid of point tests inside one edge pixel of the 5 x 7
        // film estimates its coverage to within a few grid cells.
        let polygon = Polygon::new(5, 7);
        for (px, py) in [(0, 1), (2, 3), (4, 0), (3, 5)] {
            let n = 256;
            let hits = (0..n * n)
                .filter(|i| {
                    let x = f64::from(px) + (f64::from(i % n) + 0.5) / f64::from(n);
                    let y = f64::from(py) + (f64::from(i / n) + 0.5) / f64::from(n);
                    polygon.contains(x, y)
                })
                .count();
            let estimate = hits as f64 / f64::from(n * n);
            let exact = polygon.coverage(px, py);
            assert!(
                (estimate - exact).abs() < 0.01,
                "({px}, {py}): {estimate} vs {exact}"
            );
        }
    }

    #[test]
    fn checker_exact_pixels_agree_with_dense_sampling() {
        let checker = Checker::new(64, 64);
        let mut checked = 0;
        for py in 0..64 {
            for px in (0..64).step_by(7) {
                let Some(exact) = checker.exact_pixel(px, py, 10_000) else {
                    continue;
                };
                let n = 128;
                let mut sum = 0.0;
                for i in 0..n * n {
                    let x = f64::from(px) + (f64::from(i % n) + 0.5) / f64::from(n);
                    let y = f64::from(py) + (f64::from(i / n) + 0.5) / f64::from(n);
                    sum += f64::from(checker.radiance(x, y)[0]);
                }
                let dense = sum / f64::from(n * n);
                let exact = f64::from(exact[0]);
                assert!(
                    (dense - exact).abs() < 0.01,
                    "({px}, {py}): {dense} vs {exact}"
                );
                checked += 1;
            }
        }
        assert!(checked > 400, "{checked}");
    }

    #[test]
    fn checker_projection_inverts_the_ray() {
        let checker = Checker::new(256, 256);
        let (u, v) = checker.board_hit(100.25, 200.75).unwrap();
        let [x, y] = checker.project(u, v).unwrap();
        assert!((x - 100.25).abs() < 1e-9 && (y - 200.75).abs() < 1e-9);
    }

    #[test]
    fn checker_shows_sky_above_the_horizon_and_board_below() {
        let checker = Checker::new(256, 256);
        assert_eq!(checker.radiance(128.0, 2.0), Checker::SKY);
        assert_ne!(checker.radiance(128.0, 250.0), Checker::SKY);
    }
}
