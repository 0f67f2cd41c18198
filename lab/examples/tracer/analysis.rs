//! How the error of a frame looks, beyond its RMSE: after the blur a viewer
//! applies at a distance, and as a power spectrum across the screen.

use rustfft::FftPlanner;
use rustfft::num_complex::Complex;

use crate::render::Image;

/// Standard deviation of the viewing blur, in pixels.
pub const BLUR_SIGMA: f64 = 1.0;

/// The error image `frame - reference`, one plane per channel, row-major.
fn error_planes(frame: &Image, reference: &Image) -> [Vec<f64>; 3] {
    assert_eq!(
        (frame.width, frame.height),
        (reference.width, reference.height)
    );
    std::array::from_fn(|c| {
        frame
            .pixels
            .iter()
            .zip(&reference.pixels)
            .map(|(a, b)| f64::from(a[c]) - f64::from(b[c]))
            .collect()
    })
}

/// A normalised Gaussian kernel of standard deviation `sigma` pixels, cut
/// at 4 sigma (the tails beyond hold 6e-5 of the weight).
fn gaussian_kernel(sigma: f64) -> Vec<f64> {
    let radius = (4.0 * sigma).ceil() as i64;
    let weights: Vec<f64> = (-radius..=radius)
        .map(|d| (-(d * d) as f64 / (2.0 * sigma * sigma)).exp())
        .collect();
    let total: f64 = weights.iter().sum();
    weights.into_iter().map(|w| w / total).collect()
}

/// `plane` (`width x height`) convolved with `kernel` along x then y. Near
/// the border the kernel is cut to the film and renormalised, as a viewer
/// sees no pixels beyond it.
fn blur(plane: &[f64], width: usize, height: usize, kernel: &[f64]) -> Vec<f64> {
    let radius = (kernel.len() / 2) as i64;
    let pass = |source: &[f64], step: usize, len: usize, lines: usize, line_step: usize| {
        let mut out = vec![0.0; source.len()];
        for line in 0..lines {
            for i in 0..len {
                let (mut sum, mut weight) = (0.0, 0.0);
                for (k, w) in kernel.iter().enumerate() {
                    let j = i as i64 + k as i64 - radius;
                    if (0..len as i64).contains(&j) {
                        sum += w * source[line * line_step + j as usize * step];
                        weight += w;
                    }
                }
                out[line * line_step + i * step] = sum / weight;
            }
        }
        out
    };
    let rows = pass(plane, 1, width, height, width);
    pass(&rows, width, height, width, 1)
}

/// RMSE between `frame` and `reference` after both are blurred by a
/// Gaussian of sigma [`BLUR_SIGMA`] (the blur is linear, so this blurs
/// their difference): the error a viewer sees from a distance, where
/// high-frequency (blue) error cancels and low-frequency error stays.
pub fn blurred_rmse(frame: &Image, reference: &Image) -> f64 {
    let (width, height) = (frame.width as usize, frame.height as usize);
    let kernel = gaussian_kernel(BLUR_SIGMA);
    let mut sum = 0.0;
    for plane in error_planes(frame, reference) {
        sum += blur(&plane, width, height, &kernel)
            .iter()
            .map(|e| e * e)
            .sum::<f64>();
    }
    (sum / (3 * width * height) as f64).sqrt()
}

/// The radially averaged periodogram of the error image, averaged over
/// the three channels: bin `k` of `bins` holds the mean of
/// `|DFT(error)|^2 / (width height)` over the frequencies whose radius,
/// in cycles per pixel, is in `[k, k + 1) * 0.5 / bins`. The zero
/// frequency (the mean error) is left out; frequencies beyond 0.5 (the
/// corners of the spectrum) too. White noise of variance `v` gives `v` in
/// every bin; blue noise rises from near zero at the left.
pub fn error_spectrum(frame: &Image, reference: &Image, bins: usize) -> Vec<f64> {
    let (width, height) = (frame.width as usize, frame.height as usize);
    let mut planner = FftPlanner::<f64>::new();
    let row_fft = planner.plan_fft_forward(width);
    let column_fft = planner.plan_fft_forward(height);
    let mut power = vec![0.0; width * height];
    for plane in error_planes(frame, reference) {
        let mut data: Vec<Complex<f64>> = plane.iter().map(|&e| Complex::new(e, 0.0)).collect();
        for row in data.chunks_exact_mut(width) {
            row_fft.process(row);
        }
        let mut column = vec![Complex::new(0.0, 0.0); height];
        for x in 0..width {
            for (y, c) in column.iter_mut().enumerate() {
                *c = data[y * width + x];
            }
            column_fft.process(&mut column);
            for (y, c) in column.iter().enumerate() {
                data[y * width + x] = *c;
            }
        }
        for (p, c) in power.iter_mut().zip(&data) {
            *p += c.norm_sqr() / (3 * width * height) as f64;
        }
    }
    let mut sums = vec![0.0; bins];
    let mut counts = vec![0u32; bins];
    // Signed frequency of DFT index k of n, in cycles per pixel.
    let frequency = |k: usize, n: usize| {
        let k = if k > n / 2 {
            k as f64 - n as f64
        } else {
            k as f64
        };
        k / n as f64
    };
    for y in 0..height {
        for x in 0..width {
            if x == 0 && y == 0 {
                continue;
            }
            let radius = frequency(x, width).hypot(frequency(y, height));
            let bin = (radius / 0.5 * bins as f64) as usize;
            if bin < bins {
                sums[bin] += power[y * width + x];
                counts[bin] += 1;
            }
        }
    }
    sums.iter()
        .zip(&counts)
        .map(|(s, &n)| if n > 0 { s / f64::from(n) } else { f64::NAN })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(width: u32, height: u32, f: impl Fn(u32, u32) -> f32) -> Image {
        let pixels = (0..width * height)
            .map(|i| {
                let v = f(i % width, i / width);
                [v, v, v]
            })
            .collect();
        Image {
            width,
            height,
            pixels,
        }
    }

    #[test]
    fn blur_keeps_constants_and_cancels_checkerboards() {
        let zero = image(32, 32, |_, _| 0.0);
        // A constant error survives the blur, border included.
        let constant = image(32, 32, |_, _| 0.25);
        assert!((blurred_rmse(&constant, &zero) - 0.25).abs() < 1e-12);
        // A pixel checkerboard (the bluest error there is) almost vanishes:
        // the Gaussian's response at 0.5 cycles per pixel is
        // exp(-2 pi^2 sigma^2 0.25) = 0.007 per axis, so well under 1% of
        // the RMSE survives away from the border.
        let checker = image(32, 32, |x, y| if (x + y) % 2 == 0 { 0.1 } else { -0.1 });
        assert!(blurred_rmse(&checker, &zero) < 0.1 * 0.05);
    }

    #[test]
    fn spectrum_of_white_noise_is_flat_and_of_a_checkerboard_is_a_corner() {
        // Hash-based white noise of variance 1/12: every bin near 1/12.
        let noise = image(64, 64, |x, y| {
            let h = wellspread::primitives::hash_u32(x * 977 + y * 131_071);
            (f64::from(h) / 2f64.powi(32) - 0.5) as f32
        });
        let zero = image(64, 64, |_, _| 0.0);
        let spectrum = error_spectrum(&noise, &zero, 8);
        for (k, p) in spectrum.iter().enumerate() {
            assert!((p * 12.0 - 1.0).abs() < 0.35, "bin {k}: {p}");
        }
        // A checkerboard's power is all at (0.5, 0.5), beyond radius 0.5.
        let checker = image(64, 64, |x, y| if (x + y) % 2 == 0 { 1.0 } else { -1.0 });
        assert!(
            error_spectrum(&checker, &zero, 8)
                .iter()
                .all(|&p| p < 1e-20)
        );
    }
}
