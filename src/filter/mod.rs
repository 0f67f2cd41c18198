//! Pixel reconstruction filters, sampled: a point of `[0, 1)^2` becomes an
//! offset from the pixel centre distributed like the filter, with the
//! weight `f / pdf` to give its radiance.
//!
//! A pixel is not a little square: the filter decides how much aliasing
//! is left in the image. A renderer can weight box-distributed samples by
//! the filter, which wastes samples where the filter is small and spreads
//! the weights, or draw the samples from the filter itself
//! (filter-importance sampling, as pbrt-v4 and Mitsuba do). This module
//! does the second through a monotone map, so the sampler's strata survive:
//! every filter here is separable, `f(x, y) = f1(x) f1(y)`, and each axis
//! is mapped by its own inverse CDF of `|f1|`, increasing in `u`. A
//! stratified or Latin set in the square stays stratified in the filter's
//! measure (`tests/filter.rs` checks it for grids and sequences).
//!
//! | filter | `f1(x)` on `abs(x) <= radius` | map | weight |
//! | --- | --- | --- | --- |
//! | [`BoxFilter`] | 1 | exact | exactly 1 |
//! | [`TentFilter`] | `radius - abs(x)` | exact | exactly 1 |
//! | [`GaussianFilter`] | `exp(-x^2 / (2 sigma^2))`, truncated | exact (erf and its inverse) | exactly 1 |
//! | [`MitchellFilter`] | Mitchell-Netravali cubic `(B, C)` on `2 x / radius` | table | `+-c` within the stated bound |
//! | [`LanczosFilter`] | `sinc(x) sinc(x / tau)` | table | `+-c` within the stated bound |
//! | [`BlackmanHarrisFilter`] | the 4-term Blackman-Harris window | table | 1 within the stated bound |
//!
//! Every filter is normalised to integrate to 1 over its support, so a
//! positive filter sampled exactly has weight 1, and a filter with negative
//! lobes has weight `sign(f) c` with `c = (integral of |f|) / (integral of
//! f) >= 1` per axis ([`Filter::weight_magnitude`]). Where no closed-form
//! inverse exists, the filter builds a table at construction: the nodes
//! are placed so that each lobe of `|f1|` (between its zeros) gets its own
//! run of nodes, the density sampled is the piecewise-linear interpolant of
//! `|f1|` through them, inverted exactly (a quadratic per segment), and
//! the weight is `f / pdf` of that density: unbiased, and within the
//! bound each filter states of the constant `c` for its usual parameters
//! (at most 1.8% above it, for a Lanczos filter of radius 4 and `tau =
//! 3`; within 0.2% of it on at least 99.7% of the mass for every filter
//! tested). For every parameter a constructor accepts, the weights are
//! finite, carry the sign of `f` and are at most `2 c`: next to a zero of
//! a narrow lobe (4 table segments, as many lobes or two nearly
//! coincident zeros give) the interpolated density falls short of `|f|`,
//! by up to `4 / 3` for a lobe shaped like a parabola and 1.60 measured
//! for Mitchell near `b = c = 0` (`tests/filter.rs` checks `2 c` over
//! random parameters). A table counts as lobes the runs between the
//! zeros of `f1` where it changes sign and its touching zeros (valleys of
//! `|f1|`), and accepts at most 30. The tabulated inverse CDFs are
//! within 2e-5 of the exact ones, so a point crosses into a neighbouring
//! stratum only if it lies that close to the stratum's edge.
//!
//! # By name
//!
//! [`FilterKind`] names the filters (`"gaussian".parse()`, any case) and
//! builds each with pbrt-v4's default parameters; [`AnyFilter`] holds any
//! one of them, with its parameters, behind one type.
//!
//! # Memory and features
//!
//! No filter allocates: the tables are fixed-size arrays inside the
//! filter (3,864 bytes: 241 nodes with their f32 position and value and
//! an f64 CDF, and the integral), so every filter works without `alloc`.
//! The filters are `Copy`; the tabulated ones are under 4 KiB with their
//! parameters (`tests/filter.rs` checks the sizes), so pass them by
//! reference.
//!
//! # Examples
//!
//! ```
//! use wellspread::filter::{Filter, GaussianFilter, MitchellFilter};
//! use wellspread::{Sampler2D, Sobol};
//!
//! let gaussian = GaussianFilter::new(1.5, 0.5)?;
//! let mitchell = MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0)?;
//! let sobol = Sobol::new(64)?;
//! for index in 0..64 {
//!     let u = sobol.sample(index, 7);
//!     let s = gaussian.sample(u);
//!     assert_eq!(s.weight, 1.0);
//!     assert!(s.offset.abs().max_element() <= 1.5);
//!     // Mitchell's negative lobes: the weight carries the filter's sign,
//!     // and its magnitude is bounded.
//!     let m = mitchell.sample(u);
//!     assert!(m.weight * mitchell.evaluate(m.offset) >= 0.0);
//!     assert!(m.weight.abs() <= 1.01 * mitchell.weight_magnitude());
//! }
//! # Ok::<(), wellspread::Error>(())
//! ```
//!
//! # References
//!
//! - Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
//!   section 8.8 (image reconstruction, filter sampling).
//! - Mitchell & Netravali 1988, "Reconstruction Filters in Computer
//!   Graphics", SIGGRAPH 88.
//! - Harris 1978, "On the Use of Windows for Harmonic Analysis with the
//!   Discrete Fourier Transform", Proceedings of the IEEE 66(1).

mod exact;
mod kind;
mod table;
mod tabulated;

use glam::Vec2;

use crate::error::Error;

pub use exact::{BoxFilter, GaussianFilter, TentFilter};
pub use kind::{AnyFilter, FilterKind};
pub use tabulated::{
    BlackmanHarrisFilter, LanczosFilter, MITCHELL_MAX_BC, MitchellFilter, mitchell_netravali,
};

/// One filter sample: where the sample goes relative to the pixel centre,
/// and the weight its radiance gets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterSample {
    /// The offset from the pixel centre, inside `[-radius, radius]^2`.
    pub offset: Vec2,
    /// `f(offset) / pdf(offset)` for the filter normalised to integrate to
    /// 1: exactly 1 for the exactly sampled positive filters, `sign(f)
    /// c` (within the filter's stated bound) for the tabulated ones.
    pub weight: f32,
}

/// A separable pixel reconstruction filter that can be sampled.
///
/// Implemented by every filter of this module and by [`AnyFilter`]. A
/// filter is `f(x, y) = f1(x) f1(y)`: an implementation gives the 1D
/// profile `f1` ([`radius`](Self::radius),
/// [`evaluate_1d`](Self::evaluate_1d), [`sample_1d`](Self::sample_1d),
/// [`weight_magnitude_1d`](Self::weight_magnitude_1d)), and the 2D
/// methods are provided over them.
///
/// An estimator of a pixel's value from `n` samples is `sum(weight
/// L(offset)) / n` (unbiased for the normalised filter), or `sum(weight L)
/// / sum(weight)` (pbrt's weighted average, which hides the variance of
/// the weights).
pub trait Filter {
    /// The half-width of the filter's square support.
    fn radius(&self) -> f32;

    /// The 1D profile `f1(x)` in f64, normalised to integrate to 1 over
    /// `[-radius, radius]` (0 outside it): `evaluate(p)` is `f1(p.x)
    /// f1(p.y)`. For a renderer that weights box-distributed samples by
    /// the filter instead of sampling it.
    ///
    /// ```
    /// use wellspread::filter::{Filter, TentFilter};
    /// let tent = TentFilter::new(1.0)?;
    /// assert_eq!(tent.evaluate_1d(0.0), 1.0);
    /// assert_eq!(tent.evaluate_1d(0.5), 0.5);
    /// assert_eq!(tent.evaluate_1d(-1.5), 0.0);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    fn evaluate_1d(&self, x: f64) -> f64;

    /// One axis of [`sample`](Self::sample): the offset `x` in `[-radius,
    /// radius]` drawn from `|f1|` by the monotone map of `u` (increasing
    /// in `u`), and its weight `f1(x) / pdf(x)`, as `(x, weight)`. Input
    /// outside `[0, 1)` is clamped into it (NaN to 0).
    ///
    /// ```
    /// use wellspread::filter::{BoxFilter, Filter};
    /// let b = BoxFilter::new(0.5)?;
    /// assert_eq!(b.sample_1d(0.25), (-0.25, 1.0));
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    fn sample_1d(&self, u: f32) -> (f64, f64);

    /// The constant `c` the magnitude of [`sample_1d`](Self::sample_1d)'s
    /// weights equals (or approaches, for a table): `(integral of |f1|) /
    /// (integral of f1)`, 1 for a profile without negative lobes.
    fn weight_magnitude_1d(&self) -> f64;

    /// The filter at `p`, normalised to integrate to 1 over its support (0
    /// outside it): `f1(p.x) f1(p.y)`, rounded once to f32.
    #[inline]
    fn evaluate(&self, p: Vec2) -> f32 {
        (self.evaluate_1d(f64::from(p.x)) * self.evaluate_1d(f64::from(p.y))) as f32
    }

    /// The offset drawn from `|f|` by the monotone map of `u` (each axis
    /// by its own inverse CDF, [`sample_1d`](Self::sample_1d)), and its
    /// weight, the product of the axes' weights. Input outside `[0, 1)^2`
    /// is clamped into it (NaN to 0).
    #[inline]
    fn sample(&self, u: Vec2) -> FilterSample {
        let (x, wx) = self.sample_1d(u.x);
        let (y, wy) = self.sample_1d(u.y);
        FilterSample {
            offset: Vec2::new(x as f32, y as f32),
            weight: (wx * wy) as f32,
        }
    }

    /// The constant `c` the weights' magnitude equals (or approaches,
    /// for a table): `(integral of |f| / integral of f)`, the square of
    /// [`weight_magnitude_1d`](Self::weight_magnitude_1d), 1 for a filter
    /// without negative lobes.
    #[inline]
    fn weight_magnitude(&self) -> f32 {
        let c = self.weight_magnitude_1d();
        (c * c) as f32
    }
}

/// Clamps a coordinate to `[0, ONE_MINUS_EPSILON]` (NaN to 0) as the warps
/// do, and widens it.
#[inline]
fn clamp_unit_f64(x: f32) -> f64 {
    f64::from(crate::warp::clamp_unit(x))
}

/// The smallest radius (and Gaussian sigma) a filter accepts, 2^-32
/// (about 2.3e-10 pixels). The normalised filter's peak grows like `1 /
/// radius` per axis and [`Filter::evaluate`] is its square in f32, which
/// overflows below about 5e-20; 2^-32 leaves room for Mitchell's largest
/// `b` and `c` ([`MITCHELL_MAX_BC`]).
pub const MIN_FILTER_SCALE: f32 = 1.0 / 4_294_967_296.0;

/// What [`Error::FilterParameter`] says a radius or sigma must be.
const SCALE_RANGE: &str = "a finite number from 2^-32 (about 2.3e-10) to f32::MAX";

/// A filter's length parameter (a radius or a sigma): finite and at least
/// [`MIN_FILTER_SCALE`].
fn scale(filter: &'static str, parameter: &'static str, value: f32) -> Result<f64, Error> {
    if value.is_finite() && value >= MIN_FILTER_SCALE {
        Ok(f64::from(value))
    } else {
        Err(Error::FilterParameter {
            filter,
            parameter,
            value,
            expected: SCALE_RANGE,
        })
    }
}

/// `u` in `[0, 1)` as a side and a mass: `s = 2 u - 1`, its sign and `|s|`
/// in `[0, 1]`; `u < 1/2` is the negative half of a symmetric support, so
/// the map stays increasing.
#[inline]
fn split(u: f32) -> (f64, f64) {
    let s = 2.0 * clamp_unit_f64(u) - 1.0;
    (if s < 0.0 { -1.0 } else { 1.0 }, s.abs())
}
