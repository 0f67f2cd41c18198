//! The filters sampled through a table (see the module docs of
//! [`filter`](super)): Mitchell-Netravali, Lanczos and Blackman-Harris,
//! whose weights carry the sign of the filter.

use core::f64::consts::PI;

use super::table::{MAX_LOBES, Table};
use super::{Filter, SCALE_RANGE, scale};
use crate::error::Error;

/// The Mitchell-Netravali cubic `k(x)` on its standard support `[-2, 2]`
/// (Mitchell & Netravali 1988, "Reconstruction Filters in Computer
/// Graphics"), unnormalised: `b = c = 1/3` is their recommended filter.
/// [`MitchellFilter`] scales it to its radius and samples it.
///
/// ```
/// use wellspread::filter::mitchell_netravali;
/// let (b, c) = (1.0 / 3.0, 1.0 / 3.0);
/// assert!((mitchell_netravali(0.0, b, c) - (6.0 - 2.0 * b) / 6.0).abs() < 1e-12);
/// assert_eq!(mitchell_netravali(2.5, b, c), 0.0);
/// assert!(mitchell_netravali(1.5, b, c) < 0.0); // the negative lobe
/// ```
#[inline]
#[must_use]
pub fn mitchell_netravali(x: f64, b: f64, c: f64) -> f64 {
    let x = x.abs();
    let value = if x < 1.0 {
        (12.0 - 9.0 * b - 6.0 * c) * x * x * x
            + (-18.0 + 12.0 * b + 6.0 * c) * x * x
            + (6.0 - 2.0 * b)
    } else if x < 2.0 {
        (-b - 6.0 * c) * x * x * x
            + (6.0 * b + 30.0 * c) * x * x
            + (-12.0 * b - 48.0 * c) * x
            + (8.0 * b + 24.0 * c)
    } else {
        0.0
    };
    value / 6.0
}

/// The largest `|b|` and `|c|` [`MitchellFilter::new`] accepts, 2^20: the
/// cubic's values grow like `11 |b| + 48 |c|`, so its peak (and
/// [`Filter::evaluate`], its square over `radius^2`) and the weights stay
/// finite in f32 down to [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE).
/// Mitchell and Netravali's filters have `b` and `c` in `[0, 1]`.
pub const MITCHELL_MAX_BC: f32 = 1_048_576.0;

/// The Mitchell-Netravali filter: the cubic with parameters `(B, C)` on
/// `2 x / radius` per axis. `B = C = 1/3` is the authors' recommendation;
/// `B = 0, C = 1/2` is Catmull-Rom.
///
/// # Properties
///
/// - Sampled from `|f|` through a table (see the module docs): each axis
///   is increasing in `u`, so strata of the square become cells of equal
///   `|f|` mass, up to the table's interpolation.
/// - The weight is `f / pdf` of the density actually sampled (unbiased),
///   with the sign of `f`; its magnitude is within 0.2% of
///   [`weight_magnitude`](Filter::weight_magnitude) `c` on all but 0.02%
///   of the `|f|` mass at `B = C = 1/3` (0.05% for Catmull-Rom), and at
///   most `1.0025 c` (`1.0062 c` for Catmull-Rom; `1.047 c` at worst
///   for `b`, `c` in `[-4, 4]`, and at most `2 c` for every accepted `b`
///   and `c`, see the module docs); it falls toward 0 only
///   in the last table segment before a zero where `f` is flat
///   (`tests/filter.rs` measures these).
/// - The inverse CDF is within 4e-6 of the exact one (in `|f|` mass).
///
/// # Cost
///
/// Per axis: a binary search over 241 f64, one square root and one
/// cubic. Construction: 4096 + 1200 cubic evaluations and a bisection per
/// zero.
///
/// # Examples
///
/// ```
/// use wellspread::filter::{Filter, MitchellFilter};
/// use wellspread::glam::Vec2;
/// let m = MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0)?;
/// // The integral of |f| over that of f: 1.07 per axis, 1.145 in 2D.
/// let c = m.weight_magnitude();
/// assert!(c > 1.14 && c < 1.15);
/// // Far out on x the negative lobe: a negative weight.
/// let s = m.sample(Vec2::new(0.999, 0.5));
/// assert!(s.offset.x > 1.0 && s.weight < 0.0);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Mitchell & Netravali 1988, "Reconstruction Filters in Computer
/// Graphics", SIGGRAPH 88.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MitchellFilter {
    radius: f64,
    b: f64,
    c: f64,
    table: Table,
}

impl MitchellFilter {
    /// The Mitchell-Netravali filter of half-width `radius` with
    /// parameters `b` and `c`.
    ///
    /// # Errors
    ///
    /// [`Error::FilterParameter`] unless `radius` is finite and at least
    /// [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE) (2^-32), and `b`
    /// and `c` are finite and at most [`MITCHELL_MAX_BC`] (2^20) in
    /// magnitude.
    pub fn new(radius: f32, b: f32, c: f32) -> Result<Self, Error> {
        let radius = scale("mitchell", "radius", radius)?;
        for (parameter, value) in [("b", b), ("c", c)] {
            if value.is_nan() || value.abs() > MITCHELL_MAX_BC {
                return Err(Error::FilterParameter {
                    filter: "mitchell",
                    parameter,
                    value,
                    expected: "a number from -2^20 to 2^20 (1/3 is Mitchell and Netravali's choice)",
                });
            }
        }
        let (bb, cc) = (f64::from(b), f64::from(c));
        let table = Table::new(radius, |x| mitchell_netravali(2.0 * x / radius, bb, cc)).ok_or(
            Error::FilterParameter {
                filter: "mitchell",
                parameter: "b",
                value: b,
                expected: "b and c giving a filter of positive integral",
            },
        )?;
        Ok(Self {
            radius,
            b: bb,
            c: cc,
            table,
        })
    }

    #[inline]
    fn f1(&self, x: f64) -> f64 {
        mitchell_netravali(2.0 * x / self.radius, self.b, self.c)
    }
}

/// pbrt-v4's default Mitchell-Netravali filter: radius 2, `B = C = 1/3`.
impl Default for MitchellFilter {
    fn default() -> Self {
        Self::new(2.0, 1.0 / 3.0, 1.0 / 3.0).expect("pbrt-v4's Mitchell parameters make a table")
    }
}

impl Filter for MitchellFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.radius as f32
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        self.table.density(x, self.radius, |x| self.f1(x))
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        self.table.sample(u, |x| self.f1(x))
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        self.table.magnitude()
    }
}

/// `sin(pi x) / (pi x)`, 1 at 0.
#[inline]
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-5 {
        1.0 - (PI * x) * (PI * x) / 6.0
    } else {
        libm::sin(PI * x) / (PI * x)
    }
}

/// The Lanczos (windowed sinc) filter: `sinc(x) sinc(x / tau)` per axis,
/// truncated at `radius` (pbrt's `LanczosSincFilter`; `radius = tau` is
/// the classic Lanczos-`tau` kernel).
///
/// # Properties
///
/// - Sampled from `|f|` through a table with a node at every zero (the
///   integers), increasing in `u` on each axis.
/// - The weight is `f / pdf` of the density sampled, with the sign of
///   `f`; its magnitude is within 0.2% of
///   [`weight_magnitude`](Filter::weight_magnitude) `c` on all but 0.07%
///   of the `|f|` mass at `radius = tau = 3` (0.23% at `radius = 4, tau =
///   3`), and at most `1.012 c` (`1.018 c`) (`tests/filter.rs`). With
///   many lobes (`sinc^2` at radius 30: `1.045 c`) or a narrow one (two
///   nearly coincident zeros, or a zero just inside the radius: up to
///   `4/3 c` next to it) the bound is looser; at most `2 c` for every
///   accepted radius and `tau`.
/// - The inverse CDF is within 9e-6 (1.6e-5) of the exact one.
///
/// # Cost
///
/// Per axis: a binary search over 241 f64, one square root and two
/// `sin` (f64). Construction: about 5300 evaluations of the filter.
///
/// # Limits
///
/// At most 30 lobes on each side of the centre: each lobe gets at least 4
/// of the table's 240 segments. The lobes end at the zeros of `sinc(x)`
/// (the integers) and of `sinc(x / tau)` (the multiples of `tau`) inside
/// the radius, touching ones included: with `tau = 1` (`sinc^2`, whose
/// zeros touch 0 without a change of sign) as with any other `tau`, the
/// radius is at most about 30 (less for `tau < 1`, whose window adds its
/// own zeros).
///
/// # Examples
///
/// ```
/// use wellspread::filter::{Filter, LanczosFilter};
/// use wellspread::glam::Vec2;
/// let l = LanczosFilter::new(3.0, 3.0)?;
/// let s = l.sample(Vec2::new(0.5, 0.5));
/// assert_eq!(s.offset, Vec2::ZERO);
/// assert!((s.weight - l.weight_magnitude()).abs() < 0.01 * l.weight_magnitude());
/// assert!(LanczosFilter::new(100.0, 3.0).is_err());
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Duchon 1979, "Lanczos Filtering in One and Two Dimensions", Journal of
/// Applied Meteorology 18(8); Pharr, Jakob & Humphreys 2023, section 8.8.6.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LanczosFilter {
    radius: f64,
    tau: f64,
    table: Table,
}

impl LanczosFilter {
    /// The windowed sinc of half-width `radius` and window `tau`.
    ///
    /// # Errors
    ///
    /// [`Error::FilterParameter`] unless both are finite and at least
    /// [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE) (2^-32), with at
    /// most 30 lobes inside the radius (see Limits) and a positive
    /// integral.
    pub fn new(radius: f32, tau: f32) -> Result<Self, Error> {
        let r = scale("lanczos", "radius", radius)?;
        let t = scale("lanczos", "tau", tau)?;
        // Each of sinc(x) and sinc(x / tau) alone has a zero at every
        // integer (multiple of tau) inside the radius: more than 29 of
        // either is too many lobes, however narrow (the table's scan could
        // not see them). Their union is counted by the scan.
        let few_zeros = r <= MAX_LOBES as f64 && r <= MAX_LOBES as f64 * t;
        let table = few_zeros.then(|| Table::new(r, |x| sinc(x) * sinc(x / t)));
        let table = table.flatten().ok_or(Error::FilterParameter {
            filter: "lanczos",
            parameter: "radius",
            value: radius,
            expected: "a radius with at most 30 lobes inside it (zeros of sinc(x) and sinc(x / tau), \
                       touching ones too: a radius up to about 30 for tau >= 1), with a positive integral",
        })?;
        Ok(Self {
            radius: r,
            tau: t,
            table,
        })
    }

    #[inline]
    fn f1(&self, x: f64) -> f64 {
        sinc(x) * sinc(x / self.tau)
    }
}

/// pbrt-v4's default `LanczosSincFilter`: radius 4, `tau = 3`.
impl Default for LanczosFilter {
    fn default() -> Self {
        Self::new(4.0, 3.0).expect("pbrt-v4's Lanczos parameters make a table")
    }
}

impl Filter for LanczosFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.radius as f32
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        self.table.density(x, self.radius, |x| self.f1(x))
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        self.table.sample(u, |x| self.f1(x))
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        self.table.magnitude()
    }
}

/// The 4-term Blackman-Harris window on `[-radius, radius]`.
#[inline]
fn blackman_harris_1d(x: f64, radius: f64) -> f64 {
    let t = 2.0 * PI * (x / (2.0 * radius) + 0.5);
    0.358_75 - 0.488_29 * libm::cos(t) + 0.141_28 * libm::cos(2.0 * t)
        - 0.011_68 * libm::cos(3.0 * t)
}

/// The Blackman-Harris filter: the 4-term Blackman-Harris window (92 dB
/// side lobes) stretched over `[-radius, radius]` per axis. It is
/// positive everywhere in its support (6e-5 of its peak at the ends), so
/// the weight approaches 1.
///
/// # Properties
///
/// - Sampled through a table, increasing in `u` on each axis.
/// - The weight is `f / pdf` of the density sampled: within 0.2% of 1 on
///   all but 0.003% of the mass, and at most 1.00002 (`tests/filter.rs`).
/// - The inverse CDF is within 5e-6 of the exact one.
///
/// # Cost
///
/// Per axis: a binary search over 241 f64, one square root and three
/// `cos` (f64).
///
/// # Examples
///
/// ```
/// use wellspread::filter::{BlackmanHarrisFilter, Filter};
/// use wellspread::glam::Vec2;
/// let f = BlackmanHarrisFilter::new(2.0)?;
/// assert_eq!(f.weight_magnitude(), 1.0);
/// let s = f.sample(Vec2::new(0.3, 0.9));
/// assert!((s.weight - 1.0).abs() < 0.01 && s.offset.x < 0.0 && s.offset.y > 0.0);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Harris 1978, "On the Use of Windows for Harmonic Analysis with the
/// Discrete Fourier Transform", Proceedings of the IEEE 66(1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlackmanHarrisFilter {
    radius: f64,
    table: Table,
}

impl BlackmanHarrisFilter {
    /// The Blackman-Harris filter of half-width `radius`.
    ///
    /// # Errors
    ///
    /// [`Error::FilterParameter`] unless `radius` is finite and at least
    /// [`MIN_FILTER_SCALE`](super::MIN_FILTER_SCALE) (2^-32).
    pub fn new(radius: f32) -> Result<Self, Error> {
        let r = scale("blackman-harris", "radius", radius)?;
        let table = Table::new(r, |x| blackman_harris_1d(x, r)).ok_or(Error::FilterParameter {
            filter: "blackman-harris",
            parameter: "radius",
            value: radius,
            expected: SCALE_RANGE,
        })?;
        Ok(Self { radius: r, table })
    }
}

/// Radius 2. pbrt-v4 has no Blackman-Harris filter; this is the
/// radius the lab's tracer renders with (the same support as pbrt's
/// default Mitchell filter).
impl Default for BlackmanHarrisFilter {
    fn default() -> Self {
        Self::new(2.0).expect("radius 2 makes a table")
    }
}

impl Filter for BlackmanHarrisFilter {
    #[inline]
    fn radius(&self) -> f32 {
        self.radius as f32
    }

    #[inline]
    fn evaluate_1d(&self, x: f64) -> f64 {
        self.table
            .density(x, self.radius, |x| blackman_harris_1d(x, self.radius))
    }

    #[inline]
    fn sample_1d(&self, u: f32) -> (f64, f64) {
        self.table.sample(u, |x| blackman_harris_1d(x, self.radius))
    }

    #[inline]
    fn weight_magnitude_1d(&self) -> f64 {
        // Positive everywhere: the magnitude is 1 (the table's ratio is 1
        // up to its interpolation error).
        1.0
    }
}
