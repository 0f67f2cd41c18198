//! The pixel filters of `wellspread::filter`: each axis is the inverse CDF
//! of `|f1|` (checked against the test's own f64 CDF of each filter), so
//! stratified and Latin sets stay stratified in the filter's measure; the
//! weights are exactly 1 for box, tent and Gaussian and within the stated
//! bounds of `weight_magnitude()` for the tabulated filters.
//!
//! Run with `--nocapture` to see the measured figures.

use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use wellspread::filter::*;
use wellspread::glam::Vec2;
use wellspread::{Error, Sampler2D, SamplerKind};

/// The largest f32 below 1.
const LAST: f32 = 1.0 - f32::EPSILON / 2.0;

// The filters' 1D profiles, written out again here (f64, unnormalised).

fn mitchell(x: f64, b: f64, c: f64) -> f64 {
    let x = x.abs();
    (if x < 1.0 {
        (12.0 - 9.0 * b - 6.0 * c) * x.powi(3) + (-18.0 + 12.0 * b + 6.0 * c) * x * x + 6.0
            - 2.0 * b
    } else if x < 2.0 {
        (-b - 6.0 * c) * x.powi(3)
            + (6.0 * b + 30.0 * c) * x * x
            + (-12.0 * b - 48.0 * c) * x
            + 8.0 * b
            + 24.0 * c
    } else {
        0.0
    }) / 6.0
}

fn sinc(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        (std::f64::consts::PI * x).sin() / (std::f64::consts::PI * x)
    }
}

fn blackman_harris(x: f64, r: f64) -> f64 {
    let t = 2.0 * std::f64::consts::PI * (x + r) / (2.0 * r);
    0.35875 - 0.48829 * t.cos() + 0.14128 * (2.0 * t).cos() - 0.01168 * (3.0 * t).cos()
}

/// A filter under test: the crate's filter, its 1D profile, its radius,
/// whether its weight is exactly 1, and the test's CDF of `|f1|`.
struct Case {
    name: &'static str,
    filter: Box<dyn Filter>,
    radius: f64,
    exact: bool,
    cdf: Cdf,
}

/// The CDF of `|f1|` over `[-r, r]` by composite Simpson on 2^16 panels
/// (error below 1e-9 here), with the partial panel integrated again by
/// Simpson.
struct Cdf {
    f: Box<dyn Fn(f64) -> f64>,
    r: f64,
    h: f64,
    cumulative: Vec<f64>,
    /// The integrals of `|f1|` and of `f1`.
    total_abs: f64,
    total: f64,
}

impl Cdf {
    fn new(r: f64, f: impl Fn(f64) -> f64 + 'static) -> Self {
        let panels = 1 << 16;
        let h = 2.0 * r / panels as f64;
        let simpson = |g: &dyn Fn(f64) -> f64, a: f64, b: f64| {
            (b - a) / 6.0 * (g(a) + 4.0 * g(0.5 * (a + b)) + g(b))
        };
        let mut cumulative = vec![0.0; panels + 1];
        let mut total = 0.0;
        for i in 0..panels {
            let a = -r + i as f64 * h;
            cumulative[i + 1] = cumulative[i] + simpson(&|x| f(x).abs(), a, a + h);
            total += simpson(&f, a, a + h);
        }
        let total_abs = cumulative[panels];
        Self {
            f: Box::new(f),
            r,
            h,
            cumulative,
            total_abs,
            total,
        }
    }

    /// `P(X <= x)` under `|f1|`.
    fn at(&self, x: f64) -> f64 {
        let x = x.clamp(-self.r, self.r);
        let k = (((x + self.r) / self.h) as usize).min(self.cumulative.len() - 2);
        let a = -self.r + k as f64 * self.h;
        let g = |t: f64| (self.f)(t).abs();
        let partial = (x - a) / 6.0 * (g(a) + 4.0 * g(0.5 * (a + x)) + g(x));
        (self.cumulative[k] + partial) / self.total_abs
    }
}

fn cases() -> Vec<Case> {
    let (b, c) = (1.0 / 3.0, 1.0 / 3.0);
    vec![
        Case {
            name: "box 0.5",
            filter: Box::new(BoxFilter::new(0.5).unwrap()),
            radius: 0.5,
            exact: true,
            cdf: Cdf::new(0.5, |_| 1.0),
        },
        Case {
            name: "tent 1",
            filter: Box::new(TentFilter::new(1.0).unwrap()),
            radius: 1.0,
            exact: true,
            cdf: Cdf::new(1.0, |x| 1.0 - x.abs()),
        },
        Case {
            name: "gaussian 1.5, 0.5",
            filter: Box::new(GaussianFilter::new(1.5, 0.5).unwrap()),
            radius: 1.5,
            exact: true,
            cdf: Cdf::new(1.5, |x| (-x * x / 0.5).exp()),
        },
        Case {
            name: "gaussian 3, 0.3 (tails)",
            filter: Box::new(GaussianFilter::new(3.0, 0.3).unwrap()),
            radius: 3.0,
            exact: true,
            cdf: Cdf::new(3.0, |x| (-x * x / 0.18).exp()),
        },
        Case {
            name: "mitchell 2, 1/3, 1/3",
            filter: Box::new(MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0).unwrap()),
            radius: 2.0,
            exact: false,
            cdf: Cdf::new(2.0, move |x| mitchell(x, b, c)),
        },
        Case {
            name: "catmull-rom 1.5",
            filter: Box::new(MitchellFilter::new(1.5, 0.0, 0.5).unwrap()),
            radius: 1.5,
            exact: false,
            cdf: Cdf::new(1.5, |x| mitchell(2.0 * x / 1.5, 0.0, 0.5)),
        },
        Case {
            name: "lanczos 3, 3",
            filter: Box::new(LanczosFilter::new(3.0, 3.0).unwrap()),
            radius: 3.0,
            exact: false,
            cdf: Cdf::new(3.0, |x| sinc(x) * sinc(x / 3.0)),
        },
        Case {
            name: "lanczos 4, 3 (pbrt-v3)",
            filter: Box::new(LanczosFilter::new(4.0, 3.0).unwrap()),
            radius: 4.0,
            exact: false,
            cdf: Cdf::new(4.0, |x| sinc(x) * sinc(x / 3.0)),
        },
        Case {
            name: "blackman-harris 2",
            filter: Box::new(BlackmanHarrisFilter::new(2.0).unwrap()),
            radius: 2.0,
            exact: false,
            cdf: Cdf::new(2.0, |x| blackman_harris(x, 2.0)),
        },
    ]
}

/// The offset's x for `u = (t, 1/2)`, whose y offset is 0.
fn offset_x(filter: &dyn Filter, t: f32) -> f64 {
    f64::from(filter.sample(Vec2::new(t, 0.5)).offset.x)
}

/// Each axis is the inverse CDF of `|f1|`: `F(x(u)) = u` within 2^-22
/// for the exact filters and within the table's error (measured, below
/// 5e-5) for the others, on 2^16 points of `[0, 1)` and its f32 edges;
/// and `x(u)` never decreases.
#[test]
fn each_axis_is_the_inverse_cdf_of_the_filter() {
    let mut ts: Vec<f32> = (0..1 << 16).map(|k| k as f32 / 65_536.0).collect();
    ts.extend([
        f32::EPSILON / 2.0,
        0.5 - f32::EPSILON / 4.0,
        0.5 + f32::EPSILON / 2.0,
        LAST,
    ]);
    ts.sort_by(f32::total_cmp);
    for case in cases() {
        let mut worst = 0.0f64;
        let mut previous = f64::NEG_INFINITY;
        for &t in &ts {
            let x = offset_x(case.filter.as_ref(), t);
            assert!(
                x >= previous,
                "{}: not monotone at {t}: {x} < {previous}",
                case.name
            );
            assert!(
                x.abs() <= case.radius,
                "{}: {x} outside the support",
                case.name
            );
            previous = x;
            worst = worst.max((case.cdf.at(x) - f64::from(t)).abs());
        }
        println!("{:<24} max |F(x(u)) - u| = {worst:.2e}", case.name);
        let bound = if case.exact {
            4.0 * f64::from(f32::EPSILON)
        } else {
            5e-5
        };
        assert!(worst < bound, "{}: {worst}", case.name);
    }
}

/// Stratified and Latin sets stay stratified in the filter's measure: for
/// jittered (16 x 16), n-rooks, correlated multi-jittered and Sobol sets
/// of 256 points, `floor(256 F(x))` is a permutation (Latin) on each axis,
/// and for the jittered grid `(floor(16 F(x)), floor(16 F(y)))` is one
/// point per cell. A point whose `u` is within the inverse CDF's error of a
/// stratum edge may cross it; the test counts those and allows only them.
#[test]
fn stratified_sets_stay_stratified_in_the_filter_measure() {
    for case in cases() {
        let tolerance = if case.exact {
            4.0 * f64::from(f32::EPSILON)
        } else {
            5e-5
        };
        let mut crossed = 0;
        for kind in [
            SamplerKind::Jittered,
            SamplerKind::NRooks,
            SamplerKind::CorrelatedMultiJittered,
            SamplerKind::Sobol,
        ] {
            let sampler = kind.build(256).unwrap();
            for pattern in [0, 1, 0xdead_beef] {
                let (mut xs, mut ys) = (vec![false; 256], vec![false; 256]);
                let mut cells = vec![false; 256];
                for index in 0..256 {
                    let u = sampler.sample(index, pattern);
                    let o = case.filter.sample(u).offset;
                    let (fx, fy) = (case.cdf.at(f64::from(o.x)), case.cdf.at(f64::from(o.y)));
                    for (f, t, seen) in [(fx, u.x, &mut xs), (fy, u.y, &mut ys)] {
                        let (stratum, expected) =
                            ((f * 256.0) as usize, (f64::from(t) * 256.0) as usize);
                        if stratum != expected {
                            let edge = (f64::from(t) * 256.0).round() / 256.0;
                            assert!(
                                (f64::from(t) - edge).abs() <= tolerance,
                                "{} {kind}: u {t} -> F {f}",
                                case.name
                            );
                            crossed += 1;
                        }
                        seen[expected.min(255)] = true;
                    }
                    if kind == SamplerKind::Jittered {
                        let cell =
                            ((fx * 16.0) as usize).min(15) * 16 + ((fy * 16.0) as usize).min(15);
                        let expected = ((u.x * 16.0) as usize) * 16 + (u.y * 16.0) as usize;
                        if cell != expected {
                            crossed += 1;
                        } else {
                            assert!(!cells[cell], "{} jittered: cell {cell} twice", case.name);
                        }
                        cells[cell] = true;
                    }
                }
                // Jittered sets are stratified on the 16 x 16 grid only.
                if kind != SamplerKind::Jittered {
                    assert!(
                        xs.iter().all(|&s| s) && ys.iter().all(|&s| s),
                        "{} {kind}: not Latin",
                        case.name
                    );
                }
            }
        }
        println!(
            "{:<24} points within the CDF error of a stratum edge that crossed it: {crossed}",
            case.name
        );
        if case.exact {
            assert_eq!(crossed, 0, "{}", case.name);
        }
    }
}

/// Weights: exactly 1 for box, tent and Gaussian; for the tabulated
/// filters, the sign of `f` and a magnitude within the documented bound of
/// `weight_magnitude()`: never above 1.01 times it, and within 0.2% of it
/// for at least 99% of the `|f|` mass (the `u` on a 2^16 grid are uniform
/// in that mass).
#[test]
fn weights_are_one_or_bounded() {
    for case in cases() {
        let c = f64::from(case.filter.weight_magnitude());
        let c1 = c.sqrt();
        let expected_c = case.cdf.total_abs / case.cdf.total;
        assert!(
            (c1 - expected_c).abs() < 1e-4 * expected_c,
            "{}: c {c1} vs {expected_c}",
            case.name
        );
        let (mut max_ratio, mut off) = (0.0f64, 0usize);
        let count = 1 << 16;
        for k in 0..count {
            let t = (k as f32 + 0.5) / count as f32;
            let s = case.filter.sample(Vec2::new(t, 0.5));
            let w = f64::from(s.weight);
            if case.exact {
                assert_eq!(s.weight, 1.0, "{} at {t}", case.name);
                continue;
            }
            // The sign of f.
            let f = case.filter.evaluate(s.offset);
            assert!(w * f64::from(f) >= 0.0, "{}: weight {w}, f {f}", case.name);
            // y = 0 is a table node: the y weight is c1 to f32 rounding.
            let ratio = w.abs() / c;
            max_ratio = max_ratio.max(ratio);
            if (ratio - 1.0).abs() > 2e-3 {
                off += 1;
            }
        }
        if !case.exact {
            let share = off as f64 / count as f64;
            println!(
                "{:<24} c = {c:.4} (per axis {c1:.4}); |weight| / c <= {max_ratio:.5}; off by > 0.2% on {:.3}% of the mass",
                case.name,
                100.0 * share
            );
            assert!(max_ratio <= 1.02, "{}: {max_ratio}", case.name);
            assert!(share <= 0.01, "{}: {share}", case.name);
        }
    }
}

/// The weight is unbiased: the mean of `weight g(offset)` over 2^20
/// random points is the integral of the normalised filter times `g`, for a
/// smooth `g` (against the test's Simpson integral; 5 standard errors).
#[test]
fn weighted_samples_integrate_the_filter() {
    let mut rng = Pcg32::seed_from_u64(0x0027_0002);
    let us: Vec<Vec2> = (0..1 << 20)
        .map(|_| {
            Vec2::new(
                (rng.random::<u32>() >> 8) as f32 / 16_777_216.0,
                (rng.random::<u32>() >> 8) as f32 / 16_777_216.0,
            )
        })
        .collect();
    for case in cases() {
        let g = |x: f64| 1.0 + 0.5 * (1.7 * x).cos() + 0.3 * x;
        // 1D: the y axis contributes its mean weight (1 for a normalised filter).
        let (mut sum, mut sum2, mut wy_sum) = (0.0, 0.0, 0.0);
        for &u in &us {
            let s = case.filter.sample(u);
            let v = f64::from(s.weight) * g(f64::from(s.offset.x));
            sum += v;
            sum2 += v * v;
            let sy = case.filter.sample(Vec2::new(0.5, u.y));
            wy_sum += f64::from(sy.weight);
        }
        let n = us.len() as f64;
        let mean = sum / n;
        let se = ((sum2 / n - mean * mean) / n).sqrt();
        // The reference: integral of f1 g / integral of f1 (Simpson).
        let panels = 1 << 14;
        let h = 2.0 * case.radius / f64::from(panels);
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..panels {
            let a = -case.radius + f64::from(i) * h;
            for (x, w) in [(a, 1.0), (a + 0.5 * h, 4.0), (a + h, 1.0)] {
                let f = (case.cdf.f)(x);
                num += w * f * g(x);
                den += w * f;
            }
        }
        let reference = num / den;
        let wy = wy_sum / n / f64::from(case.filter.weight_magnitude()).sqrt();
        println!(
            "{:<24} mean {mean:.5} vs {reference:.5} (se {se:.1e}); y weight / sqrt(c) {wy:.4}",
            case.name
        );
        // The y weights at x = 0 average to about 1 (their sign varies).
        assert!(
            (mean - reference).abs() < 5.0 * se + 1e-6,
            "{}: {mean} vs {reference}",
            case.name
        );
    }
}

/// The f32 edges: `u = 0`, 2^-24 and `1 - 2^-24` on either axis give
/// offsets inside the support and finite weights; out-of-range input is
/// clamped.
#[test]
fn filters_at_the_edges() {
    let edges = [
        0.0,
        f32::EPSILON / 2.0,
        0.5,
        0.5 - f32::EPSILON / 4.0,
        LAST,
        1.0 - f32::EPSILON,
    ];
    for case in cases() {
        for &a in &edges {
            for &b in &edges {
                let s = case.filter.sample(Vec2::new(a, b));
                assert!(
                    s.offset.abs().max_element() <= case.radius as f32,
                    "{}: {:?}",
                    case.name,
                    s
                );
                assert!(s.weight.is_finite(), "{}: {:?}", case.name, s);
            }
        }
        let clamp = |x: f32| {
            if x.is_nan() || x < 0.0 {
                0.0
            } else {
                x.min(LAST)
            }
        };
        for bad in [f32::NAN, -1.0, 1.0, 3.0, f32::INFINITY] {
            let u = Vec2::new(bad, 0.3);
            assert_eq!(
                case.filter.sample(u),
                case.filter.sample(Vec2::new(clamp(bad), 0.3)),
                "{}",
                case.name
            );
        }
        assert_eq!(case.filter.radius(), case.radius as f32);
        assert_eq!(
            case.filter
                .evaluate(Vec2::new(case.radius as f32 * 1.01, 0.0)),
            0.0
        );
    }
    // The exact maps reach the ends of the support.
    let tent = TentFilter::new(1.0).unwrap();
    assert_eq!(tent.sample(Vec2::ZERO).offset, Vec2::splat(-1.0));
    let b = BoxFilter::new(0.5).unwrap();
    assert_eq!(b.sample(Vec2::ZERO).offset, Vec2::splat(-0.5));
}

#[test]
fn filters_reject_bad_parameters() {
    for (result, parameter) in [
        (BoxFilter::new(0.0).map(|_| ()), "radius"),
        (TentFilter::new(-1.0).map(|_| ()), "radius"),
        (GaussianFilter::new(1.5, f32::NAN).map(|_| ()), "sigma"),
        (
            GaussianFilter::new(f32::INFINITY, 0.5).map(|_| ()),
            "radius",
        ),
        (MitchellFilter::new(2.0, f32::NAN, 0.3).map(|_| ()), "b"),
        (
            MitchellFilter::new(2.0, 0.3, f32::INFINITY).map(|_| ()),
            "c",
        ),
        (LanczosFilter::new(100.0, 3.0).map(|_| ()), "radius"),
        (LanczosFilter::new(3.0, 0.0).map(|_| ()), "tau"),
        (BlackmanHarrisFilter::new(-0.0).map(|_| ()), "radius"),
    ] {
        match result {
            Err(Error::FilterParameter { parameter: p, .. }) => assert_eq!(p, parameter),
            other => panic!("{parameter}: {other:?}"),
        }
    }
    let message = BoxFilter::new(0.0).unwrap_err().to_string();
    assert_eq!(
        message,
        "the box filter cannot use radius = 0; give a finite number from 2^-32 (about 2.3e-10) to f32::MAX"
    );
    let message = LanczosFilter::new(100.0, 3.0).unwrap_err().to_string();
    assert!(message.contains("at most 30 lobes"), "{message}");
}

/// The tables fit the 4 KiB budget, inside each filter (and `AnyFilter`):
/// no allocation.
#[test]
fn tabulated_filters_fit_in_4_kib() {
    use std::mem::size_of;
    for (name, size) in [
        ("mitchell", size_of::<MitchellFilter>()),
        ("lanczos", size_of::<LanczosFilter>()),
        ("blackman-harris", size_of::<BlackmanHarrisFilter>()),
        ("any", size_of::<AnyFilter>()),
    ] {
        println!("{name}: {size} bytes");
        assert!(size <= 4096, "{name}: {size} bytes");
    }
    assert!(size_of::<GaussianFilter>() <= 32 && size_of::<BoxFilter>() <= 8);
}

/// `evaluate_1d` is the normalised profile of the test's own formula
/// (`f1 / integral of f1`), and `evaluate` is its product over the axes.
#[test]
fn evaluate_1d_is_the_normalised_profile() {
    for case in cases() {
        let r = case.radius;
        for i in 0..=64 {
            let x = -r + 2.0 * r * f64::from(i) / 64.0;
            let expected = (case.cdf.f)(x) / case.cdf.total;
            let got = case.filter.evaluate_1d(x);
            assert!(
                (got - expected).abs() <= 1e-6 * expected.abs().max(1.0),
                "{} at {x}: {got} vs {expected}",
                case.name
            );
            let y = 0.3 * r;
            let product = (got * case.filter.evaluate_1d(y)) as f32;
            let p = Vec2::new(x as f32, y as f32);
            assert!(
                (case.filter.evaluate(p) - product).abs() <= 1e-5 * product.abs().max(1.0),
                "{} at {p}",
                case.name
            );
        }
        assert_eq!(case.filter.evaluate_1d(r * 1.01), 0.0, "{}", case.name);
    }
}

// ---------------------------------------------------------------------------
// Every accepted parameter, and the range refused.

/// `integral of evaluate_1d` over `[-extent, extent]` by 3-point
/// Gauss-Legendre on 4096 panels (exact for the box and tent up to the
/// panel holding their ends; the lobes of the others are at least 1/150
/// of the extent wide).
fn integral_1d(filter: &dyn Filter, extent: f64) -> f64 {
    let panels = 4096;
    let h = 2.0 * extent / panels as f64;
    let (t, w) = ((0.6f64).sqrt(), [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0]);
    (0..panels)
        .map(|k| {
            let mid = -extent + (k as f64 + 0.5) * h;
            0.5 * h
                * (w[0] * filter.evaluate_1d(mid - 0.5 * h * t)
                    + w[1] * filter.evaluate_1d(mid)
                    + w[2] * filter.evaluate_1d(mid + 0.5 * h * t))
        })
        .sum()
}

/// The largest `|weight| / weight_magnitude()` over 2048 `u.x` (and `u.y`
/// = 1/2, a table node), with the checks every sample must pass: a finite
/// offset in the support, a finite weight with the sign of `evaluate`,
/// and a finite `evaluate`.
fn worst_weight(filter: &dyn Filter) -> Result<f64, String> {
    let c = f64::from(filter.weight_magnitude());
    // 1 for a positive filter up to the table's interpolation error.
    if !(c.is_finite() && c >= 1.0 - 1e-4) {
        return Err(format!("weight_magnitude {c}"));
    }
    let r = filter.radius();
    let mut worst = 0.0f64;
    let samples: Vec<(f32, FilterSample, f32)> = (0..2048)
        .map(|k| {
            let t = if k == 2047 { LAST } else { k as f32 / 2047.0 };
            let s = filter.sample(Vec2::new(t, 0.5));
            (t, s, filter.evaluate(s.offset))
        })
        .collect();
    // At a zero of f the f32 offset and the f64 point the weight was
    // computed at may round to opposite signs: only |f| above 1e-6 of the
    // largest is held to the weight's sign.
    let largest = samples.iter().map(|s| s.2.abs()).fold(0.0f32, f32::max);
    for &(t, s, f) in &samples {
        if !(s.offset.is_finite() && s.offset.abs().max_element() <= r) {
            return Err(format!("u.x {t}: offset {}", s.offset));
        }
        let sign_ok = f64::from(s.weight) * f64::from(f) >= 0.0 || f.abs() <= 1e-6 * largest;
        if !(s.weight.is_finite() && f.is_finite() && sign_ok) {
            return Err(format!("u.x {t}: weight {}, evaluate {f}", s.weight));
        }
        worst = worst.max(f64::from(s.weight.abs()) / c);
    }
    let peak = filter.evaluate(Vec2::ZERO);
    if !peak.is_finite() {
        return Err(format!("evaluate(0) = {peak}"));
    }
    Ok(worst)
}

/// The bound Blackman-Harris's weights keep, `|weight| <= (1 +
/// WEIGHT_SLACK) weight_magnitude()` (its docs: at most 1.00002).
const WEIGHT_SLACK: f64 = 0.018;

/// The bound every accepted Mitchell and Lanczos filter keeps (the module
/// docs): `|weight| <= 2 c`. Next to a zero of a narrow lobe (4 table
/// segments) the interpolated pdf falls short of `f`: up to `4 / 3` for a
/// lobe shaped like a parabola, 1.60 measured for Mitchell near `b = c =
/// 0` (a lobe of 1e-6 of the peak beside a double zero).
const ANY_WEIGHT_SLACK: f64 = 1.0;

/// A filter length (radius or sigma) from the accepted range, log-uniform
/// over its exponents, and its edges.
fn accepted_scale() -> impl Strategy<Value = f32> {
    prop_oneof![
        (-32i32..=127, 1.0f32..2.0).prop_map(|(e, m)| (m * 2f32.powi(e)).min(f32::MAX)),
        Just(MIN_FILTER_SCALE),
        Just(f32::MAX),
        (0.25f32..4.0),
    ]
}

fn check_accepted(filter: &dyn Filter, extent: f64, slack: f64) -> Result<f64, TestCaseError> {
    let worst = worst_weight(filter).map_err(TestCaseError::fail)?;
    prop_assert!(worst <= 1.0 + slack, "|weight| / c = {}", worst);
    let integral = integral_1d(filter, extent);
    prop_assert!(
        (integral - 1.0).abs() < 0.01,
        "integral of evaluate_1d {}",
        integral
    );
    Ok(worst)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Box, tent and Blackman-Harris over their whole radius range.
    #[test]
    fn every_accepted_radius_gives_a_good_filter(radius in accepted_scale()) {
        let r = f64::from(radius);
        check_accepted(&BoxFilter::new(radius).unwrap(), r, 0.0)?;
        check_accepted(&TentFilter::new(radius).unwrap(), r, 0.0)?;
        check_accepted(&BlackmanHarrisFilter::new(radius).unwrap(), r, WEIGHT_SLACK)?;
    }

    /// The Gaussian over both ranges (its mass beyond 40 sigma is below
    /// 1e-300, so the integral stops there).
    #[test]
    fn every_accepted_gaussian_is_a_good_filter(radius in accepted_scale(), sigma in accepted_scale()) {
        let g = GaussianFilter::new(radius, sigma).unwrap();
        check_accepted(&g, f64::from(radius).min(40.0 * f64::from(sigma)), 0.0)?;
    }

    /// Mitchell over its radius range and `|b|, |c| <= 2^20`.
    #[test]
    fn every_accepted_mitchell_is_a_good_filter(
        radius in accepted_scale(),
        b in prop_oneof![-MITCHELL_MAX_BC..=MITCHELL_MAX_BC, -2.0f32..2.0, Just(MITCHELL_MAX_BC), Just(0.0)],
        c in prop_oneof![-MITCHELL_MAX_BC..=MITCHELL_MAX_BC, -2.0f32..2.0, Just(-MITCHELL_MAX_BC), Just(0.5)],
    ) {
        match MitchellFilter::new(radius, b, c) {
            Ok(m) => { check_accepted(&m, f64::from(radius), ANY_WEIGHT_SLACK)?; }
            Err(Error::FilterParameter { parameter: "b", .. }) => {}
            Err(e) => prop_assert!(false, "{}", e),
        }
    }

    /// Lanczos wherever the constructor accepts it (and the refusal says
    /// the lobe limit): radii to 40, windows from 2^-32 up, `tau = 1`
    /// (touching zeros) and next to it.
    #[test]
    fn every_accepted_lanczos_is_a_good_filter(
        radius in prop_oneof![(0.25f32..40.0), (1u32..=40).prop_map(|k| k as f32), accepted_scale()],
        tau in prop_oneof![Just(1.0f32), Just(1.0 + 1e-6), Just(1.0 - 1e-6), (0.05f32..8.0), accepted_scale()],
    ) {
        match LanczosFilter::new(radius, tau) {
            Ok(l) => {
                check_accepted(&l, f64::from(radius), ANY_WEIGHT_SLACK)?;
            }
            Err(e @ Error::FilterParameter { parameter: "radius", .. }) => {
                prop_assert!(e.to_string().contains("at most 30 lobes"), "{}", e);
            }
            Err(e) => prop_assert!(false, "{}", e),
        }
    }

    /// Below the range, and non-finite: an error that states the range.
    #[test]
    fn scales_below_the_range_are_refused_with_the_range(
        tiny in prop_oneof![Just(0.0f32), Just(-0.0), (-60i32..-32).prop_map(|e| 1.5 * 2f32.powi(e)), Just(f32::MIN_POSITIVE), Just(-1.0), Just(f32::NAN), Just(f32::INFINITY)],
    ) {
        let refusals = [
            BoxFilter::new(tiny).map(|_| ()),
            TentFilter::new(tiny).map(|_| ()),
            GaussianFilter::new(tiny, 0.5).map(|_| ()),
            GaussianFilter::new(1.5, tiny).map(|_| ()),
            MitchellFilter::new(tiny, 1.0 / 3.0, 1.0 / 3.0).map(|_| ()),
            LanczosFilter::new(tiny, 3.0).map(|_| ()),
            LanczosFilter::new(3.0, tiny).map(|_| ()),
            BlackmanHarrisFilter::new(tiny).map(|_| ()),
        ];
        for refusal in refusals {
            match refusal {
                Err(e @ Error::FilterParameter { .. }) => {
                    prop_assert!(e.to_string().contains("from 2^-32 (about 2.3e-10) to f32::MAX"), "{}", e);
                }
                other => prop_assert!(false, "{}: {:?}", tiny, other),
            }
        }
    }
}

/// The case: `sinc^2` (`tau = 1`) has touching zeros, which are
/// lobes: radius 31 and up is refused (the 1D integral was 4.14 at 4096,
/// the weights infinite at 1e30, and 1.2-1.59 times `weight_magnitude()`
/// at 64-100); radius 30 is accepted and keeps the bound.
#[test]
fn lanczos_counts_touching_zeros_as_lobes() {
    for radius in [31.0, 64.0, 100.0, 4096.0, 1e30] {
        let e = LanczosFilter::new(radius, 1.0).unwrap_err();
        assert!(e.to_string().contains("at most 30 lobes"), "{radius}: {e}");
    }
    for tau in [1.0 + 1e-6, 1.0 - 1e-6] {
        assert!(LanczosFilter::new(64.0, tau).is_err(), "tau {tau}");
    }
    let l = LanczosFilter::new(30.0, 1.0).unwrap();
    let worst = worst_weight(&l).unwrap();
    println!("lanczos(30, 1): |weight| / c <= {worst:.5}");
    assert!(worst <= 1.05, "{worst}");
    assert!((integral_1d(&l, 30.0) - 1.0).abs() < 1e-3);
}

/// The case: a radius or sigma of 1e-20 gave `evaluate = +inf`;
/// it is refused, and the smallest accepted one evaluates finitely.
#[test]
fn filters_refuse_scales_that_overflow_evaluate() {
    assert!(BoxFilter::new(1e-20).is_err() && TentFilter::new(5e-20).is_err());
    assert!(
        GaussianFilter::new(1.5, 1e-20).is_err() && MitchellFilter::new(1e-20, 0.3, 0.3).is_err()
    );
    let filters: [Box<dyn Filter>; 4] = [
        Box::new(BoxFilter::new(MIN_FILTER_SCALE).unwrap()),
        Box::new(TentFilter::new(MIN_FILTER_SCALE).unwrap()),
        Box::new(GaussianFilter::new(1.5, MIN_FILTER_SCALE).unwrap()),
        Box::new(MitchellFilter::new(MIN_FILTER_SCALE, MITCHELL_MAX_BC, -MITCHELL_MAX_BC).unwrap()),
    ];
    for f in &filters {
        assert!(f.evaluate(Vec2::ZERO).is_finite() && f.evaluate(Vec2::ZERO) > 0.0);
    }
}
