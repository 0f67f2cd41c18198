//! The pixel-level interface, one file per pixel sampler as in `src/pixel/`:
//! `PixelSampler` implementations keep their per-pixel guarantees in every
//! dimension pair, and dimension pairs are decorrelated; `domain` checks the
//! `Domain` draws, branches and splits. The dependence measure the
//! decorrelation tests share is below.

mod blue_noise;
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
