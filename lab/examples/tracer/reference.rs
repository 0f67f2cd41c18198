//! Reference images: what each pixel would be with infinitely many samples
//! under the same reconstruction filter, exact where the scene allows it.
//!
//! - `polygon`, box filter: exact, the polygon's area inside each pixel
//!   square (Sutherland-Hodgman clipping).
//! - `moire`, any filter: the filter-weighted integral by composite
//!   Gauss-Legendre quadrature, subdivided until every piece spans less than
//!   one wavelength of `sin(u^2 v^2)`: accurate to about 1e-6, far below any
//!   sampler's error.
//! - `checker`, box filter: exact by clipping each square's projected image
//!   against the pixel, for every pixel whose footprint meets at most 10^4
//!   squares. The few rows just below the horizon (and the horizon row,
//!   which sees squares out to infinity) are sampled densely, as below.
//! - `cornell` (box filter only): 4096 Sobol' samples per pixel through
//!   domains that no compared frame uses (`path.rs`), cached in a file named
//!   after a fingerprint of the path tracer.
//! - anything else (`checker` and `polygon` under a wide filter): the render
//!   itself with 4096 correlated multi-jittered samples per pixel (64 x 64
//!   strata) on a pattern dimension no compared image uses, 16 times the
//!   largest default count.
//!
//! References take seconds, so they are cached under `out/` keyed by
//! scene, size and filter, with a format tag that changes when a scene or
//! reference method does.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

use rayon::prelude::*;
use wellspread::filter::{AnyFilter, Filter, FilterKind};
use wellspread::{AnySampler, Padded, SamplerKind};

use crate::path;
use crate::render::{
    FilterMode, Image, REFERENCE_DIMENSION, box_pixel, breaks, gauss_legendre, render,
    tracer_filter,
};
use crate::scenes::{Built, Checker, Moire, Polygon, Scene, SceneKind};

/// Samples per pixel for Monte Carlo references: 16 times the largest
/// default count (a larger `--spp` outgrows the reference's accuracy).
pub const REFERENCE_SPP: u32 = 4096;

/// First bytes of a cache file. Bump the digit whenever a scene, a filter
/// or a reference method changes, so stale caches are recomputed.
const MAGIC: &[u8; 8] = b"wsref-3\n";

/// Where the reference for `scene` at `width x height` under `filter` is
/// cached.
pub fn cache_path(
    out: &Path,
    scene: SceneKind,
    width: u32,
    height: u32,
    filter: FilterKind,
) -> PathBuf {
    out.join(format!("reference-{scene}-{width}x{height}-{filter}.bin"))
}

/// The reference image, from the cache when it holds a valid one
/// (`max_depth`: the path-traced scene's depth, which the others ignore).
/// Returns the image and whether it was computed (not loaded).
pub fn load_or_compute(
    out: &Path,
    kind: SceneKind,
    scene: &Built,
    width: u32,
    height: u32,
    (filter, max_depth): (FilterKind, u32),
) -> io::Result<(Image, bool)> {
    let path = match scene {
        Built::Film(_) => cache_path(out, kind, width, height, filter),
        Built::PathTraced => out.join(format!(
            "reference-{kind}-{width}x{height}-{filter}-{:08x}.bin",
            path::fingerprint(max_depth)
        )),
    };
    if let Some(image) = read_cache(&path, width, height) {
        return Ok((image, false));
    }
    let image = match scene {
        Built::Film(scene) => compute(scene, width, height, filter),
        Built::PathTraced => path::reference(width, height, max_depth),
    };
    write_cache(&path, &image)?;
    Ok((image, true))
}

fn compute(scene: &Scene, width: u32, height: u32, filter: FilterKind) -> Image {
    match (scene, filter) {
        (Scene::Polygon(polygon), FilterKind::Box) => polygon_exact(polygon, width, height),
        (Scene::Moire(moire), _) => moire_quadrature(moire, width, height, filter),
        (Scene::Checker(checker), FilterKind::Box) => checker_box(checker, scene, width, height),
        _ => render(
            scene,
            width,
            height,
            &dense_sampler(),
            REFERENCE_DIMENSION,
            filter,
            FilterMode::Weighted,
        ),
    }
}

/// The sampler for Monte Carlo references: 4096 samples on a 64 x 64
/// multi-jittered grid, frame 0, used on dimension pair
/// [`REFERENCE_DIMENSION`], which no compared image uses, so a reference
/// is never correlated with what it measures.
fn dense_sampler() -> Padded<AnySampler> {
    let sampler = SamplerKind::CorrelatedMultiJittered
        .build(REFERENCE_SPP)
        .expect("4096 is a valid sample count");
    Padded::new(sampler, 0)
}

/// Most squares one pixel's exact checker value may clip against; pixels
/// nearer the horizon are sampled densely instead. 10^4 squares cost about
/// a millisecond, and the dense fallback is then left with the last few
/// rows below the horizon, where every sampler's error is noise-like.
const MAX_SQUARES_PER_PIXEL: u64 = 10_000;

/// The box-filtered checker: exact (clipping) for every pixel whose
/// footprint meets at most [`MAX_SQUARES_PER_PIXEL`] squares, dense
/// sampling for the rest.
fn checker_box(checker: &Checker, scene: &Scene, width: u32, height: u32) -> Image {
    let sampler = dense_sampler();
    let pixels = (0..width * height)
        .into_par_iter()
        .map(|i| {
            let (px, py) = (i % width, i / width);
            checker
                .exact_pixel(px, py, MAX_SQUARES_PER_PIXEL)
                .unwrap_or_else(|| box_pixel(scene, &sampler, REFERENCE_DIMENSION, px, py))
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

fn polygon_exact(polygon: &Polygon, width: u32, height: u32) -> Image {
    let pixels = (0..width * height)
        .into_par_iter()
        .map(|i| {
            let coverage = polygon.coverage(i % width, i / width);
            std::array::from_fn(|c| {
                let (inside, outside) = (Polygon::YELLOW[c], Polygon::BACKGROUND[c]);
                (f64::from(outside) + coverage * f64::from(inside - outside)) as f32
            })
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

/// `sum(w f) / sum(w)` for each pixel, by quadrature over the filter's
/// support clipped to the film (samples never fall outside it, so the
/// rendered images normalise over the same region).
fn moire_quadrature(moire: &Moire, width: u32, height: u32, filter: FilterKind) -> Image {
    let rule = gauss_legendre::<8>();
    let filter = &tracer_filter(filter);
    let pixels = (0..width * height)
        .into_par_iter()
        .map(|i| {
            let f = moire_pixel(moire, width, height, filter, &rule, i % width, i / width);
            let f = f as f32;
            [f, f, f]
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

/// One pixel of [`moire_quadrature`], with the Gauss-Legendre `rule`.
fn moire_pixel(
    moire: &Moire,
    width: u32,
    height: u32,
    filter: &AnyFilter,
    (nodes, weights): &([f64; 8], [f64; 8]),
    px: u32,
    py: u32,
) -> f64 {
    // Split an interval at the filter's kinks around `centre`, clipped to
    // [0, limit]: the filter is smooth on each piece.
    let pieces = |centre: f64, limit: f64| -> Vec<(f64, f64)> {
        breaks(filter.kind())
            .windows(2)
            .map(|pair| ((centre + pair[0]).max(0.0), (centre + pair[1]).min(limit)))
            .filter(|(a, b)| b > a)
            .collect()
    };
    let (cx, cy) = (f64::from(px) + 0.5, f64::from(py) + 0.5);
    let (mut weighted, mut total) = (0.0, 0.0);
    for &(x0, x1) in &pieces(cx, f64::from(width)) {
        for &(y0, y1) in &pieces(cy, f64::from(height)) {
            // Enough sub-cells that each spans under one wavelength (2 pi
            // radians), where 8 Gauss points are accurate to about 1e-6; at
            // least 2 for the filter's curvature.
            let (span_x, span_y) = moire.phase_span(x0, x1, y0, y1);
            let cells = |span: f64| (span / std::f64::consts::TAU).ceil().max(2.0) as u32;
            let (mx, my) = (cells(span_x), cells(span_y));
            let (hx, hy) = ((x1 - x0) / f64::from(mx), (y1 - y0) / f64::from(my));
            for cell_y in 0..my {
                let ya = y0 + f64::from(cell_y) * hy;
                for (ny, gauss_y) in nodes.iter().zip(weights) {
                    let y = ya + (ny + 1.0) * 0.5 * hy;
                    let wy = gauss_y * 0.5 * hy * filter.evaluate_1d(y - cy);
                    for cell_x in 0..mx {
                        let xa = x0 + f64::from(cell_x) * hx;
                        for (nx, gauss_x) in nodes.iter().zip(weights) {
                            let x = xa + (nx + 1.0) * 0.5 * hx;
                            let w = wy * gauss_x * 0.5 * hx * filter.evaluate_1d(x - cx);
                            weighted += w * moire.value(x, y);
                            total += w;
                        }
                    }
                }
            }
        }
    }
    weighted / total
}

fn read_cache(path: &Path, width: u32, height: u32) -> Option<Image> {
    let bytes = fs::read(path).ok()?;
    let header = MAGIC.len() + 8;
    let (head, body) = bytes.split_at_checked(header)?;
    let size = |at: usize| u32::from_le_bytes(head[at..at + 4].try_into().unwrap());
    let count = width as usize * height as usize;
    if &head[..MAGIC.len()] != MAGIC
        || size(MAGIC.len()) != width
        || size(MAGIC.len() + 4) != height
        || body.len() != count * 12
    {
        return None;
    }
    let values: Vec<f32> = body
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes(b.try_into().unwrap()))
        .collect();
    let pixels = values.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    Some(Image {
        width,
        height,
        pixels,
    })
}

fn write_cache(path: &Path, image: &Image) -> io::Result<()> {
    let mut bytes = Vec::with_capacity(16 + image.pixels.len() * 12);
    bytes.extend_from_slice(MAGIC);
    bytes.extend_from_slice(&image.width.to_le_bytes());
    bytes.extend_from_slice(&image.height.to_le_bytes());
    for value in image.pixels.iter().flatten() {
        bytes.extend_from_slice(&value.to_le_bytes());
    }
    // Write then rename, so an interrupted run never leaves a truncated
    // cache that a later run would have to detect.
    let partial = path.with_extension("bin.partial");
    fs::write(&partial, bytes)?;
    fs::rename(partial, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moire_quadrature_matches_dense_sampling_on_a_smooth_corner() {
        // The bottom-left pixels are well below Nyquist: a 64 x 64 midpoint
        // rule there must agree with the quadrature to a few 1e-4.
        let (width, height) = (32, 32);
        let scene = SceneKind::Moire.film(width, height);
        let Some(Scene::Moire(moire)) = &scene else {
            unreachable!()
        };
        for &kind in FilterKind::ALL {
            let filter = &tracer_filter(kind);
            let (px, py) = (3u32, 28u32);
            let rule = gauss_legendre::<8>();
            let quadrature = moire_pixel(moire, width, height, filter, &rule, px, py);
            let r = f64::from(filter.radius());
            let n = 256;
            let (mut weighted, mut total) = (0.0, 0.0);
            for j in 0..n {
                for i in 0..n {
                    let dx = -r + (f64::from(i) + 0.5) * 2.0 * r / f64::from(n);
                    let dy = -r + (f64::from(j) + 0.5) * 2.0 * r / f64::from(n);
                    let (x, y) = (f64::from(px) + 0.5 + dx, f64::from(py) + 0.5 + dy);
                    if x < 0.0 || y < 0.0 || x >= 32.0 || y >= 32.0 {
                        continue;
                    }
                    let w = filter.evaluate_1d(dx) * filter.evaluate_1d(dy);
                    weighted += w * moire.value(x, y);
                    total += w;
                }
            }
            let dense = weighted / total;
            assert!(
                (dense - quadrature).abs() < 3e-4,
                "{kind}: {dense} vs {quadrature}"
            );
        }
    }
}
