//! The radially averaged power spectrum (periodogram) of a point set.

use alloc::vec;
use alloc::vec::Vec;

use core::f64::consts::PI;

use glam::Vec2;

use super::{coord, validate};
use crate::error::Error;

/// The largest `max_frequency` [`radial_power_spectrum`] accepts.
pub const MAX_SPECTRUM_FREQUENCY: u32 = 1 << 16;

/// Frequencies held in memory at once (a band of rows of the half plane).
const BAND_ENTRIES: usize = 1 << 20;

/// Radially averaged power spectrum: the periodogram
///
/// `P(k) = |Σ_j exp(-2 π i k · x_j)|² / n`
///
/// over the integer frequencies `k = (kx, ky)` with `0 < |k| <= max_frequency`,
/// binned by `|k|` rounded to the nearest integer. Entry `r - 1` of the result
/// is the mean of `P(k)` over the `k` whose rounded length is `r`, for
/// `r = 1..=max_frequency`, so the result has `max_frequency` entries. (The
/// last bin holds only the `k` with `r - 1/2 <= |k| <= r`.)
///
/// # Properties
///
/// Independent uniform points have `E[P(k)] = 1` at every `k != 0`, so white
/// noise is flat at 1; blue-noise and stratified sets stay well below 1 at low
/// frequencies, and a regular grid of `s x s` points is 0 everywhere except at
/// multiples of `s` along the axes (where it is `n`). `P(-k) = P(k)`. To
/// average over several sets, the caller averages the returned vectors.
///
/// # Cost
///
/// `P(k)` is computed directly (no FFT, so points need not sit on a grid):
/// per point, `3 max_frequency + 2` sine-cosine pairs per band and one
/// complex multiply-add per frequency of the half plane `ky >= 0`, about
/// `(π / 2) max_frequency²` of them: O(n max_frequency²) time, and memory for
/// at most 2^20 frequencies at a time (larger spectra go in bands of rows,
/// each recomputing its sine-cosine pairs).
///
/// # Errors
///
/// [`Error::FrequencyOutOfRange`] unless `1 <= max_frequency <=`
/// [`MAX_SPECTRUM_FREQUENCY`], then [`Error::EmptyPointSet`],
/// [`Error::NonFinitePoint`] or [`Error::PointOutOfRange`] (naming the first
/// bad point).
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::radial_power_spectrum};
/// // An 8 x 8 grid of cell corners: its exponential sums vanish unless both
/// // frequency components are multiples of 8, where P(k) = n = 64.
/// let grid: Vec<Vec2> = (0..64)
///     .map(|i| Vec2::new((i % 8) as f32 / 8.0, (i / 8) as f32 / 8.0))
///     .collect();
/// let spectrum = radial_power_spectrum(&grid, 8)?;
/// assert_eq!(spectrum.len(), 8);
/// assert!(spectrum[..7].iter().all(|&p| p < 1e-9));
/// // 20 frequencies have 7.5 <= |k| <= 8; four of them are (±8, 0), (0, ±8).
/// assert!((spectrum[7] - 4.0 * 64.0 / 20.0).abs() < 1e-9);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Ulichney 1987, "Digital Halftoning", MIT Press (radially averaged power
/// spectrum); Lagae & Dutré 2008, "A comparison of methods for generating
/// Poisson disk distributions", Computer Graphics Forum 27(1).
pub fn radial_power_spectrum(points: &[Vec2], max_frequency: u32) -> Result<Vec<f64>, Error> {
    if !(1..=MAX_SPECTRUM_FREQUENCY).contains(&max_frequency) {
        return Err(Error::FrequencyOutOfRange {
            max_frequency,
            max: MAX_SPECTRUM_FREQUENCY,
        });
    }
    validate(points)?;
    let r = max_frequency as usize;
    let r2 = u64::from(max_frequency) * u64::from(max_frequency);
    let nf = points.len() as f64;
    // Row ky of the half plane holds kx in -r..=r (index kx + r).
    let width = 2 * r + 1;
    let band_rows = (BAND_ENTRIES / width).max(1);
    let mut power = vec![0.0f64; r];
    let mut counts = vec![0u64; r];
    let mut re = Vec::new();
    let mut im = Vec::new();
    let mut cx = vec![(0.0f64, 0.0f64); width];
    let mut cy = Vec::with_capacity(band_rows);
    let mut first = 0usize;
    while first <= r {
        let rows = band_rows.min(r + 1 - first);
        // Half width of each row: |kx| <= sqrt(r² - ky²).
        let half = |ky: usize| libm::sqrt((r2 - (ky as u64) * (ky as u64)) as f64) as usize;
        re.clear();
        re.resize(rows * width, 0.0);
        im.clear();
        im.resize(rows * width, 0.0);
        for p in points {
            let (x, y) = (coord(p.x), coord(p.y));
            for (i, c) in cx.iter_mut().enumerate() {
                let k = i as f64 - r as f64;
                let (s, co) = libm::sincos(-2.0 * PI * k * x);
                *c = (co, s);
            }
            cy.clear();
            for ky in first..first + rows {
                let (s, co) = libm::sincos(-2.0 * PI * ky as f64 * y);
                cy.push((co, s));
            }
            for (row, &(yr, yi)) in cy.iter().enumerate() {
                let h = half(first + row);
                let span = r - h..r + h + 1;
                let base = row * width;
                let (re_row, im_row) =
                    (&mut re[base..][span.clone()], &mut im[base..][span.clone()]);
                for ((a, b), &(xr, xi)) in re_row.iter_mut().zip(im_row).zip(&cx[span]) {
                    *a += xr * yr - xi * yi;
                    *b += xr * yi + xi * yr;
                }
            }
        }
        for row in 0..rows {
            let ky = first + row;
            let h = half(ky);
            for kx in r - h..=r + h {
                let fx = kx as i64 - r as i64;
                // Half plane: ky > 0, or ky = 0 and kx > 0 (P(-k) = P(k)).
                if ky == 0 && fx <= 0 {
                    continue;
                }
                let len2 = fx.unsigned_abs() * fx.unsigned_abs() + (ky as u64) * (ky as u64);
                if len2 > r2 {
                    continue;
                }
                // len2 is an integer, so sqrt(len2) is never exactly half-way.
                let bin = libm::round(libm::sqrt(len2 as f64)) as usize;
                let i = row * width + kx;
                power[bin - 1] += (re[i] * re[i] + im[i] * im[i]) / nf;
                counts[bin - 1] += 1;
            }
        }
        first += rows;
    }
    // Every bin r holds at least k = (r, 0).
    for (p, &c) in power.iter_mut().zip(&counts) {
        *p /= c as f64;
    }
    Ok(power)
}
