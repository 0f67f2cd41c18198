//! The filters sampled through a closed-form inverse CDF, weight exactly
//! 1: box, tent and Gaussian.

use core::f64::consts::PI;

use super::{Filter, clamp_unit_f64, scale, split};
use crate::error::Error;

/// The box filter: constant on `[-radius, radius]^2`; the offset is
/// `radius (2 u - 1)`, weight exactly 1.
///
/// # Properties
///
/// - Uniform on the square support: each axis is the affine map `x =
///   radius (2 u - 1)`, so strata of the square become equal squares of
///   the support.
/// - Weight exactly 1.
///
/// # Cost
///
/// Two multiply-adds per axis.
///
/// # Examples
///
/// ```
/// use wellspread::filter::{BoxFilter, Filter};
/// use wellspread::glam::Vec2;
/// let b = BoxFilter::new(0.5)?;
/// let s = b.sample(Vec2::new(0.25, 0.5));
/// assert_eq!((s.offset, s.weight), (Vec2::new(-0.25, 0.0), 1.0));
/// assert_eq!(b.evaluate(Vec2::ZERO), 1.0);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section 8.8.2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxFilter {
    radius: f64,
}

impl BoxFilter {
    /// The box of half-width `radius` (0.5 is the pixel itself).
    ///
    /// # Errors
    ///
    /// [`Error::FilterParameter`] unless `radius` is finite and at least
    /// [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE) (2^-32).
    pub fn new(radius: f32) -> Result<Self, Error> {
        Ok(Self {
            radius: scale("box", "radius", radius)?,
        })
    }
}

/// pbrt-v4's default box: radius 0.5, the pixel itself.
impl Default for BoxFilter {
    fn default() -> Self {
        Self { radius: 0.5 }
    }
}

impl Filter for BoxFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.radius as f32
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        if x.abs() <= self.radius {
            0.5 / self.radius
        } else {
            0.0
        }
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        (self.radius * (2.0 * clamp_unit_f64(u) - 1.0), 1.0)
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        1.0
    }
}

/// The tent (triangle) filter: `radius - |x|` per axis; sampled exactly,
/// weight exactly 1.
///
/// # Properties
///
/// - Each axis maps `u` to `x = +-radius (1 - sqrt(1 - |2 u - 1|))`, the
///   inverse CDF of the tent: increasing in `u`, so strata of the square
///   become cells of equal filter mass.
/// - Weight exactly 1.
///
/// # Cost
///
/// One square root per axis.
///
/// # Examples
///
/// ```
/// use wellspread::filter::{Filter, TentFilter};
/// use wellspread::glam::Vec2;
/// let t = TentFilter::new(1.0)?;
/// // Half the mass of each side lies within 1 - sqrt(1/2) of the centre.
/// let s = t.sample(Vec2::new(0.75, 0.5));
/// assert!((s.offset.x - (1.0 - 0.5f32.sqrt())).abs() < 1e-6 && s.offset.y == 0.0);
/// assert_eq!(s.weight, 1.0);
/// assert_eq!(t.evaluate(Vec2::ZERO), 1.0);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section 8.8.3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TentFilter {
    radius: f64,
}

impl TentFilter {
    /// The tent of half-width `radius`.
    ///
    /// # Errors
    ///
    /// [`Error::FilterParameter`] unless `radius` is finite and at least
    /// [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE) (2^-32).
    pub fn new(radius: f32) -> Result<Self, Error> {
        Ok(Self {
            radius: scale("tent", "radius", radius)?,
        })
    }
}

/// pbrt-v4's default triangle: radius 2.
impl Default for TentFilter {
    fn default() -> Self {
        Self { radius: 2.0 }
    }
}

impl Filter for TentFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.radius as f32
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        (self.radius - x.abs()).max(0.0) / (self.radius * self.radius)
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        let (sign, mass) = split(u);
        // The mass within |x| of the centre, on one side: 1 - (1 - |x|/r)^2.
        (sign * self.radius * (1.0 - libm::sqrt(1.0 - mass)), 1.0)
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        1.0
    }
}

/// The inverse of `erf` on `(-1, 1)`, in f64: Winitzki's closed-form
/// approximation (relative error about 2e-3), then two Halley steps on
/// `erf(y) - t`, which converge cubically (to about 1e-8, then to the
/// f64 root).
fn erf_inv(t: f64) -> f64 {
    let t = t.clamp(-1.0 + f64::EPSILON, 1.0 - f64::EPSILON);
    // Winitzki 2008: a = 0.147 fits the tails and the centre.
    let a = 0.147;
    let ln = libm::log((1.0 - t) * (1.0 + t));
    let b = 2.0 / (PI * a) + 0.5 * ln;
    let mut y = libm::sqrt(libm::sqrt(b * b - ln / a) - b).copysign(t);
    for _ in 0..2 {
        let e = libm::erf(y) - t;
        let slope = 2.0 / libm::sqrt(PI) * libm::exp(-y * y);
        let step = e / slope;
        // Halley: erf'' / erf' = -2 y.
        y -= step / (1.0 + y * step);
    }
    y
}

/// The Gaussian filter, truncated at its radius: `exp(-x^2 / (2
/// sigma^2))` per axis on `[-radius, radius]`, sampled through its exact
/// inverse CDF, weight exactly 1.
///
/// pbrt subtracts the value at the radius so that the filter reaches 0
/// there; this one does not (it is the truncated normal density), so that
/// its inverse CDF is the closed form `x = sigma sqrt(2) erfinv((2 u - 1)
/// erf(radius / (sigma sqrt(2))))`.
///
/// # Properties
///
/// - Increasing in `u`: strata of the square become cells of equal
///   Gaussian mass.
/// - The inverse of `erf` is found to f64 precision (an approximation
///   refined by two Halley steps on libm's `erf`), then rounded once to
///   f32, so the weight is exactly 1; `tests/filter.rs` finds the offsets
///   within 2.4e-8 of the exact inverse CDF (in mass).
///
/// # Cost
///
/// Per axis: one `log`, two square roots, and two `erf` and `exp`
/// evaluations (f64): the dearest filter to sample here
/// (`docs/warps.md` has the measured times of all of them).
///
/// # Examples
///
/// ```
/// use wellspread::filter::{Filter, GaussianFilter};
/// use wellspread::glam::Vec2;
/// let g = GaussianFilter::new(1.5, 0.5)?;
/// let s = g.sample(Vec2::new(0.5, 0.5));
/// assert_eq!((s.offset, s.weight), (Vec2::ZERO, 1.0));
/// // About 68% of an untruncated normal lies within one sigma.
/// let s = g.sample(Vec2::new(0.5 + 0.6827 / 2.0, 0.5));
/// assert!((s.offset.x - 0.5).abs() < 0.01);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
///   section 8.8.4.
/// - Winitzki 2008, "A handy approximation for the error function and its
///   inverse" (the starting point of the inverse).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaussianFilter {
    radius: f64,
    sigma: f64,
    /// `erf(radius / (sigma sqrt(2)))`, the mass inside the support.
    erf_radius: f64,
}

impl GaussianFilter {
    /// The Gaussian of standard deviation `sigma`, truncated at `radius`
    /// (pbrt's defaults are 1.5 and 0.5).
    ///
    /// # Errors
    ///
    /// [`Error::FilterParameter`] unless both are finite and at least
    /// [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE) (2^-32).
    pub fn new(radius: f32, sigma: f32) -> Result<Self, Error> {
        let radius = scale("gaussian", "radius", radius)?;
        let sigma = scale("gaussian", "sigma", sigma)?;
        Ok(Self::with(radius, sigma))
    }

    /// The filter of checked parameters.
    fn with(radius: f64, sigma: f64) -> Self {
        let erf_radius = libm::erf(radius / (sigma * core::f64::consts::SQRT_2));
        Self {
            radius,
            sigma,
            erf_radius,
        }
    }
}

/// pbrt-v4's default Gaussian: radius 1.5, sigma 0.5.
impl Default for GaussianFilter {
    fn default() -> Self {
        Self::with(1.5, 0.5)
    }
}

impl Filter for GaussianFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.radius as f32
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        if x.abs() <= self.radius {
            let norm = self.sigma * libm::sqrt(2.0 * PI) * self.erf_radius;
            libm::exp(-x * x / (2.0 * self.sigma * self.sigma)) / norm
        } else {
            0.0
        }
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        let t = (2.0 * clamp_unit_f64(u) - 1.0) * self.erf_radius;
        let x = self.sigma * core::f64::consts::SQRT_2 * erf_inv(t);
        (x.clamp(-self.radius, self.radius), 1.0)
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        1.0
    }
}
