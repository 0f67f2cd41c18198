//! The pixel-level interface, one file per pixel sampler as in `src/pixel/`:
//! `PixelSampler` implementations keep their per-pixel guarantees in every
//! dimension pair, and dimension pairs are decorrelated; `domain` checks the
//! `Domain` draws, branches and splits. The dependence measure the
//! decorrelation tests share, and the quad error the screen-space tests
//! share, are below.

mod blue_noise;
mod camera;
mod domain;
mod independence;
mod padded;
mod padded_nd;
mod zsobol;

use wellspread::PixelSampler;
use wellspread::glam::Vec2;

/// Chi-square statistic of `pairs` in a 16 x 16 grid of equal cells.
fn chi_square_16x16(pairs: &[(f32, f32)]) -> f64 {
    let mut counts = [0u32; 256];
    for &(a, b) in pairs {
        counts[(a * 16.0) as usize * 16 + (b * 16.0) as usize] += 1;
    }
    let expected = pairs.len() as f64 / 256.0;
    counts
        .iter()
        .map(|&c| (f64::from(c) - expected).powi(2) / expected)
        .sum()
}

/// Pearson correlation of the two coordinates of `pairs`.
fn correlation(pairs: &[(f32, f32)]) -> f64 {
    let n = pairs.len() as f64;
    let (ma, mb) = pairs.iter().fold((0.0, 0.0), |(a, b), &(x, y)| {
        (a + f64::from(x) / n, b + f64::from(y) / n)
    });
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for &(x, y) in pairs {
        let (da, db) = (f64::from(x) - ma, f64::from(y) - mb);
        sab += da * db;
        saa += da * da;
        sbb += db * db;
    }
    sab / (saa * sbb).sqrt()
}

/// Picks two coordinates out of a sample's two dimension pairs.
type Pairing = fn(&(Vec2, Vec2)) -> (f32, f32);

/// The worst chi-square and |correlation| over the coordinate pairings
/// (a.x, b.x), (a.y, b.y), (a.x, b.y), (a.y, b.x) of dimension pairs `a`
/// and `b`, over every sample of a 32 x 32 film at 16 spp (16384 samples).
pub fn dependence(sampler: &impl PixelSampler, a: u32, b: u32) -> (f64, f64) {
    let mut samples = Vec::new();
    for y in 0..32 {
        for x in 0..32 {
            for i in 0..sampler.samples_per_pixel().unwrap() {
                samples.push((
                    sampler.sample_pixel([x, y], i, a),
                    sampler.sample_pixel([x, y], i, b),
                ));
            }
        }
    }
    let pairings: [Pairing; 4] = [
        |(p, q)| (p.x, q.x),
        |(p, q)| (p.y, q.y),
        |(p, q)| (p.x, q.y),
        |(p, q)| (p.y, q.x),
    ];
    pairings.iter().fold((0.0f64, 0.0f64), |(chi, r), pairing| {
        let pairs: Vec<(f32, f32)> = samples.iter().map(pairing).collect();
        (
            chi.max(chi_square_16x16(&pairs)),
            r.max(correlation(&pairs).abs()),
        )
    })
}

/// The error of each 2 x 2 quad's mean estimate of a smooth integrand,
/// the same in every pixel, root-mean-square over the quads of a 64 x 64
/// film: what a blur keeps of the per-pixel error. `point(pixel, index)`
/// is the sample's point (a `sample_pixel`, or a draw of a domain).
pub fn quad_error(spp: u32, point: impl Fn([u32; 2], u32) -> Vec2) -> f64 {
    // exp(-x^2 - y^2) over [0, 1)^2 (Christensen et al. 2018's Gaussian).
    let exact = 0.557_746_285_351_033_f64;
    let mut sum_squares = 0.0;
    for qy in 0..32 {
        for qx in 0..32 {
            let mut sum = 0.0;
            for [dx, dy] in [[0, 0], [1, 0], [0, 1], [1, 1]] {
                for i in 0..spp {
                    let p = point([2 * qx + dx, 2 * qy + dy], i);
                    sum += (-(p.x * p.x + p.y * p.y) as f64).exp();
                }
            }
            let error = sum / f64::from(4 * spp) - exact;
            sum_squares += error * error;
        }
    }
    (sum_squares / 1024.0).sqrt()
}

/// Whether the points `point(i)`, `i` in `range` (a power-of-two count),
/// are a (0,m,2)-net.
fn is_net_over(point: &impl Fn(u32) -> Vec2, range: core::ops::Range<u32>) -> bool {
    let points: Vec<Vec2> = range.map(point).collect();
    wellspread::metrics::is_net_base2(&points).unwrap()
}

/// The index ranges the progressive kinds document as nets: every prefix
/// `0 .. 2^m` and every dyadic block `[2^m, 2^(m+1))` for `m <= max_m`.
/// Returns the first range that is not a net.
pub fn first_documented_range_not_a_net(
    point: impl Fn(u32) -> Vec2,
    max_m: u32,
) -> Option<core::ops::Range<u32>> {
    (0..=max_m)
        .flat_map(|m| [0..1 << m, 1 << m..2 << m])
        .find(|range| !is_net_over(&point, range.clone()))
}

/// How many of the aligned blocks `[j 2^k, (j + 1) 2^k)` with `j >= 2`
/// below `end` are nets, of how many: the ranges the docs say are not nets
/// in general.
pub fn other_aligned_blocks_that_are_nets(
    point: impl Fn(u32) -> Vec2,
    k: u32,
    end: u32,
) -> (usize, usize) {
    let blocks: Vec<u32> = (2..end >> k).collect();
    let nets = blocks
        .iter()
        .filter(|&&j| is_net_over(&point, j << k..(j + 1) << k))
        .count();
    (nets, blocks.len())
}

/// Progressive pass `p` of `spp` samples drawn as the docs recommend for
/// the sequences: samples `0 .. spp` of `start(pixel, i).branch(p)`.
pub fn branch_pass(sampler: &dyn PixelSampler, pixel: [u32; 2], p: u32, spp: u32) -> Vec<Vec2> {
    (0..spp)
        .map(|i| {
            wellspread::Domain::start(sampler, pixel, i)
                .branch(p)
                .next_2d()
        })
        .collect()
}
