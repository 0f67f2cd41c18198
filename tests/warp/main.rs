//! The warps of `wellspread::warp`: measure-preserving (chi-square on
//! equal-measure bins), inside their domain at the f32 edges of the square,
//! consistent with their pdf and inverse, and keeping the stratification of
//! Owen-scrambled Sobol points (convergence slopes).
//!
//! Statistical tests use fixed seeds, so they are deterministic; each
//! states the false-failure rate it would have over random seeds. Run with
//! `--nocapture` to see the measured figures.
//!
//! The files follow `src/warp/`: `shapes`, `lights` (and `light_geometry`,
//! the light warps on degenerate and huge geometry), `choices` and
//! `frame`. This one holds what several of them use: the chi-square
//! statistics and bins, the edge-grid sweeps, the f64 vector helpers and
//! the `u` strategies of the property tests.

use std::f64::consts::PI;

use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use wellspread::glam::{Vec2, Vec3};
use wellspread::warp::*;
use wellspread::{Sampler2D, Sobol};

/// The largest f32 below 1.
const LAST: f32 = 1.0 - f32::EPSILON / 2.0;

mod choices;
mod frame;
mod light_geometry;
mod lights;
mod shapes;

// ---------------------------------------------------------------------------
// Chi-square on equal-measure bins.

/// The upper `p = 1e-6` quantile of chi-square with `dof` degrees of
/// freedom (Wilson-Hilferty; within 1% of the exact value for dof >= 30).
fn chi_square_critical(dof: usize) -> f64 {
    let k = dof as f64;
    let z = 4.753_424; // the standard normal's upper 1e-6 quantile
    let a = 2.0 / (9.0 * k);
    k * (1.0 - a + z * a.sqrt()).powi(3)
}

/// Pearson's statistic of `counts` against equal expected counts.
fn chi_square(counts: &[u64]) -> f64 {
    let total: u64 = counts.iter().sum();
    let expected = total as f64 / counts.len() as f64;
    counts
        .iter()
        .map(|&c| (c as f64 - expected).powi(2) / expected)
        .sum()
}

/// A point's bin among `bins` equal-measure bins of the target domain.
type Binner<T> = fn(T) -> usize;

/// The angle of `(a, b)` in `[0, 2 pi)` as a fraction of `[0, span)`, into
/// `count` sectors.
fn sector(a: f32, b: f32, span: f64, count: usize) -> usize {
    let phi = f64::from(b).atan2(f64::from(a)).rem_euclid(2.0 * PI);
    ((phi / span * count as f64) as usize).min(count - 1)
}

/// The unit sphere in 16 slabs of equal width along x (equal area by
/// Archimedes) times 16 sectors around the x axis: not aligned with the
/// map's own `(z, azimuth)` parameters.
fn sphere_bin(v: Vec3) -> usize {
    let slab = ((f64::from(v.x) + 1.0) * 8.0).clamp(0.0, 15.0) as usize;
    slab * 16 + sector(v.y, v.z, 2.0 * PI, 16)
}

/// The hemisphere `z >= 0` in 16 slabs along x (each half of a sphere
/// slab, so equal area) times 16 sectors of the half turn around the x axis.
fn hemisphere_bin(v: Vec3) -> usize {
    let slab = ((f64::from(v.x) + 1.0) * 8.0).clamp(0.0, 15.0) as usize;
    // z >= 0: the angle of (y, z) is in [0, pi].
    slab * 16 + sector(v.y, v.z, PI, 16)
}

/// The triangle `b0, b1 >= 0, b0 + b1 <= 1` cut into 4^4 = 256 congruent
/// sub-triangles: 16 x 16 grid cells of `(b0, b1)`, the lower-left half of
/// each cell pointing up and the upper-right half (inside the triangle when
/// `i + j <= 14`) pointing down. Bins are numbered over the 2 x 256 slots;
/// the unused ones stay empty and are skipped.
fn triangle_bin(b: Vec3) -> usize {
    let m = 16.0;
    let (x, y) = (f64::from(b.x) * m, f64::from(b.y) * m);
    let (i, j) = (x.floor().clamp(0.0, 15.0), y.floor().clamp(0.0, 15.0));
    let down = (x - i) + (y - j) >= 1.0 && i + j <= 14.0;
    ((i as usize * 16 + j as usize) << 1) | usize::from(down)
}

/// Counts of `warp` on `inputs` into the slots `slots` of `bin`.
fn counts<T>(inputs: &[Vec2], warp: fn(Vec2) -> T, bin: Binner<T>, slots: &[usize]) -> Vec<u64> {
    let size = slots.iter().max().unwrap() + 1;
    let mut all = vec![0u64; size];
    for &u in inputs {
        all[bin(warp(u))] += 1;
    }
    let kept: Vec<u64> = slots.iter().map(|&s| all[s]).collect();
    assert_eq!(
        kept.iter().sum::<u64>(),
        inputs.len() as u64,
        "a point fell in an unused bin"
    );
    kept
}

/// `count` seeded uniform points of `[0, 1)^2`, on the f32 grid of 2^-24.
fn random_points(seed: u64, count: usize) -> Vec<Vec2> {
    let mut rng = Pcg32::seed_from_u64(seed);
    let mut unit = || (rng.random::<u32>() >> 8) as f32 * (1.0 / 16_777_216.0);
    (0..count).map(|_| Vec2::new(unit(), unit())).collect()
}

// ---------------------------------------------------------------------------
// The f32 edges of the square.

/// [`sweep_edge_grid`] on every `stride`-th `k` and the 4096 first and
/// last of each edge (where the corners are), for the maps that cost
/// hundreds of f64 operations (2^26 calls of those take tens of seconds).
fn sweep_edge_grid_every(stride: u32, ok: impl Fn(Vec2) -> bool + Sync) -> (u64, Option<Vec2>) {
    use rayon::prelude::*;
    const STEP: f32 = 1.0 / 16_777_216.0;
    (0u32..1 << 10)
        .into_par_iter()
        .map(|chunk| {
            let (mut failed, mut first) = (0u64, None);
            for k in chunk << 14..(chunk + 1) << 14 {
                if k % stride != 0 && (4096..(1 << 24) - 4096).contains(&k) {
                    continue;
                }
                let t = k as f32 * STEP;
                for u in [
                    Vec2::new(0.0, t),
                    Vec2::new(LAST, t),
                    Vec2::new(t, 0.0),
                    Vec2::new(t, LAST),
                ] {
                    if !ok(u) {
                        failed += 1;
                        first = first.or(Some(u));
                    }
                }
            }
            (failed, first)
        })
        .reduce(|| (0, None), |a, b| (a.0 + b.0, a.1.or(b.1)))
}

/// `pdf` is positive and finite.
fn valid_pdf(pdf: f32) -> bool {
    pdf.is_finite() && pdf > 0.0
}

// ---------------------------------------------------------------------------
// pdf and inverse, over random inputs.

/// `|d/du x d/dv|` of a map by central differences in f64 around `u`,
/// evaluated through the f32 map.
fn area_scale<T>(warp: impl Fn(Vec2) -> T, to3: impl Fn(T) -> [f64; 3], u: Vec2, h: f32) -> f64 {
    let at = |du: f32, dv: f32| to3(warp(u + Vec2::new(du, dv)));
    let (xp, xm, yp, ym) = (at(h, 0.0), at(-h, 0.0), at(0.0, h), at(0.0, -h));
    let d = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let (a, b) = (d(xp, xm), d(yp, ym));
    let cross = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    (cross[0].powi(2) + cross[1].powi(2) + cross[2].powi(2)).sqrt() / (4.0 * f64::from(h).powi(2))
}

fn v3(v: Vec3) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

fn periodic_distance(a: f32, b: f32) -> f32 {
    let d = (a - b).abs();
    d.min(1.0 - d)
}

// ---------------------------------------------------------------------------
// Weighted discrete choice: Discrete (inverse CDF) and AliasTable (Vose).

/// Pearson's statistic of `counts` against `expected` (bins expecting 0
/// must be empty and are left out), with its degrees of freedom.
fn chi_square_against(counts: &[u64], expected: &[f64]) -> (f64, usize) {
    let mut statistic = 0.0;
    let mut bins = 0;
    for (&c, &e) in counts.iter().zip(expected) {
        if e == 0.0 {
            assert_eq!(c, 0, "a bin of probability 0 was hit");
        } else {
            statistic += (c as f64 - e).powi(2) / e;
            bins += 1;
        }
    }
    (statistic, bins - 1)
}

// ---------------------------------------------------------------------------
// Lights: cone, ball, rectangle, spherical triangle and rectangle.

fn dv(v: Vec3) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn unit3(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

/// The solid angle of the planar triangle `a b c` seen from the origin, in
/// f64 (Van Oosterom & Strackee), the test's own reference.
fn solid_angle(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    let (a, b, c) = (unit3(a), unit3(b), unit3(c));
    2.0 * dot(a, cross(b, c))
        .abs()
        .atan2(1.0 + dot(a, b) + dot(b, c) + dot(c, a))
}

// ---------------------------------------------------------------------------
// Light warps on degenerate and huge geometry: regressions and properties.

/// A coordinate of `u`: the square's edges (0 and `1 - 2^-24`), its
/// middle, and anything.
fn edge_coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![Just(0.0f32), Just(LAST), Just(0.5), 0.0f32..1.0]
}

fn edge_u() -> impl Strategy<Value = Vec2> {
    (edge_coordinate(), edge_coordinate()).prop_map(|(x, y)| Vec2::new(x, y))
}
