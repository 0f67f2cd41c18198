//! The radial power spectrum against its definition.

use proptest::prelude::*;
use wellspread::Error;
use wellspread::glam::Vec2;
use wellspread::metrics::{MAX_SPECTRUM_FREQUENCY, radial_power_spectrum};

use crate::common::{hammersley, random_points, unit_points};

/// The spectrum straight from its definition: every k of the full plane with
/// 0 < |k| <= r, its own exponential sum, binned by the rounded length.
fn direct_spectrum(points: &[Vec2], r: i64) -> Vec<f64> {
    let n = points.len() as f64;
    let mut power = vec![0.0; r as usize];
    let mut count = vec![0u32; r as usize];
    for kx in -r..=r {
        for ky in -r..=r {
            let len = ((kx * kx + ky * ky) as f64).sqrt();
            if kx * kx + ky * ky == 0 || len > r as f64 {
                continue;
            }
            let (mut re, mut im) = (0.0f64, 0.0f64);
            for p in points {
                let phase = -2.0
                    * std::f64::consts::PI
                    * (kx as f64 * f64::from(p.x) + ky as f64 * f64::from(p.y));
                re += phase.cos();
                im += phase.sin();
            }
            let bin = len.round() as usize - 1;
            power[bin] += (re * re + im * im) / n;
            count[bin] += 1;
        }
    }
    power
        .iter()
        .zip(&count)
        .map(|(p, &c)| p / f64::from(c))
        .collect()
}

#[test]
fn spectrum_matches_direct_evaluation() {
    let sets = [
        random_points(1, 40),
        random_points(57, 41),
        random_points(300, 42),
        hammersley(7),
        vec![Vec2::new(0.25, 0.75); 9],
    ];
    for (s, points) in sets.iter().enumerate() {
        for r in [1u32, 2, 7, 20] {
            let got = radial_power_spectrum(points, r).unwrap();
            let want = direct_spectrum(points, i64::from(r));
            assert_eq!(got.len(), r as usize);
            for (bin, (&g, &w)) in got.iter().zip(&want).enumerate() {
                // Sums of n unit phasors: absolute error near n 1e-16 per term.
                assert!(
                    (g - w).abs() <= 1e-10 * w.max(1.0),
                    "set {s}, r = {r}, bin {bin}: {g} vs {w}"
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn spectrum_matches_direct_evaluation_on_any_set(
        points in unit_points(24),
        r in 1u32..=6,
    ) {
        let got = radial_power_spectrum(&points, r).unwrap();
        let want = direct_spectrum(&points, i64::from(r));
        prop_assert_eq!(got.len(), r as usize);
        for (g, w) in got.iter().zip(&want) {
            prop_assert!((g - w).abs() <= 1e-10 * w.max(1.0), "{g} vs {w}");
        }
    }
}

#[test]
fn spectrum_in_bands_matches_one_band() {
    // 2^20 frequencies per band: at r = 600 the half plane takes two bands.
    let points = random_points(5, 43);
    let big = radial_power_spectrum(&points, 600).unwrap();
    let small = radial_power_spectrum(&points, 300).unwrap();
    assert_eq!(big.len(), 600);
    for (bin, (&a, &b)) in big.iter().zip(&small).take(299).enumerate() {
        assert!((a - b).abs() <= 1e-9 * b.max(1.0), "bin {bin}: {a} vs {b}");
    }
    let want = direct_spectrum(&points, 600);
    for bin in [0, 299, 300, 450, 599] {
        assert!(
            (big[bin] - want[bin]).abs() <= 1e-9 * want[bin].max(1.0),
            "bin {bin}"
        );
    }
}

#[test]
fn spectrum_of_random_points_is_flat() {
    // P(k) of independent uniform points is close to exponential with mean 1,
    // and P(-k) = P(k): bin r has about pi r independent values per set, so
    // over 64 sets its mean has standard deviation about 1 / sqrt(64 pi r).
    // Five of them: false-failure rate about 2e-5 over the 29 bins checked.
    let r = 32;
    let mut mean = vec![0.0; r as usize];
    for seed in 0..64 {
        let s = radial_power_spectrum(&random_points(256, 1000 + seed), r).unwrap();
        for (m, v) in mean.iter_mut().zip(s) {
            *m += v / 64.0;
        }
    }
    for (bin, &m) in mean.iter().enumerate().skip(3) {
        let sigma = 1.0 / (64.0 * std::f64::consts::PI * (bin + 1) as f64).sqrt();
        assert!((m - 1.0).abs() < 5.0 * sigma, "bin {}: {m}", bin + 1);
    }
}

#[test]
fn spectrum_rejects_bad_frequencies() {
    let points = random_points(10, 44);
    for f in [0, MAX_SPECTRUM_FREQUENCY + 1, u32::MAX] {
        assert_eq!(
            radial_power_spectrum(&points, f),
            Err(Error::FrequencyOutOfRange {
                max_frequency: f,
                max: MAX_SPECTRUM_FREQUENCY
            })
        );
    }
    assert_eq!(radial_power_spectrum(&[], 4), Err(Error::EmptyPointSet));
    let msg = radial_power_spectrum(&points, 0).unwrap_err().to_string();
    assert!(
        msg.contains("from 1 to 65536") && msg.contains("got 0"),
        "{msg}"
    );
}
