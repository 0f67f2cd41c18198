//! The one error type: every way input to a constructor or a metric can be wrong.

use core::fmt;

use crate::SamplerKind;

/// What was wrong with the input to a sampler constructor or a metric.
///
/// Every variant carries the offending value so that the message can say what
/// to change. Hot per-sample paths never return errors; see each sampler's docs
/// for what an out-of-range index does.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A sampler was asked for zero samples.
    ZeroSamples,
    /// A grid was asked for with zero columns or zero rows.
    ZeroGridSide {
        /// Columns asked for.
        columns: u32,
        /// Rows asked for.
        rows: u32,
    },
    /// More samples (or grid cells) than the sampler can keep its guarantee for.
    TooManySamples {
        /// The sampler.
        sampler: SamplerKind,
        /// How many were asked for (columns x rows for a grid).
        requested: u64,
        /// The largest count the sampler accepts.
        max: u64,
        /// Why the limit exists.
        reason: &'static str,
    },
    /// A grid with a side above 2^24 strata, more than f32 coordinates in
    /// `[0, 1)` can tell apart (the most square grid of a prime `n` is `1 x n`).
    GridTooFine {
        /// The sampler.
        sampler: SamplerKind,
        /// Columns of the grid.
        columns: u32,
        /// Rows of the grid.
        rows: u32,
    },
    /// A metric was given no points.
    EmptyPointSet,
    /// A metric was given a point with a NaN or infinite coordinate.
    NonFinitePoint {
        /// Index of the first such point in the slice.
        index: usize,
        /// Its x coordinate.
        x: f32,
        /// Its y coordinate.
        y: f32,
    },
    /// A metric was given a point outside `[0, 1)^2` (1.0 and negative values
    /// included; `-0.0` counts as `0.0` and is accepted).
    PointOutOfRange {
        /// Index of the first such point in the slice.
        index: usize,
        /// Its x coordinate.
        x: f32,
        /// Its y coordinate.
        y: f32,
    },
    /// A metric needs more points than it was given (a distance needs a pair).
    TooFewPoints {
        /// The metric, as the tools spell it.
        metric: &'static str,
        /// The fewest points it accepts.
        needed: usize,
        /// How many it got.
        got: usize,
    },
    /// A stratification check was asked for a grid whose cell count does not
    /// divide the number of points.
    GridDoesNotDivide {
        /// Columns asked for.
        columns: u32,
        /// Rows asked for.
        rows: u32,
        /// Number of points.
        n: usize,
    },
    /// A check that needs `n = 2^m` points got another count.
    NotPowerOfTwo {
        /// Number of points.
        n: usize,
    },
    /// A power spectrum was asked for a largest frequency of 0 or above the
    /// largest one it accepts.
    FrequencyOutOfRange {
        /// The largest frequency asked for.
        max_frequency: u32,
        /// The largest value accepted.
        max: u32,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::ZeroSamples => f.write_str("a sampler needs at least one sample; got n = 0"),
            Error::ZeroGridSide { columns, rows } => write!(
                f,
                "a grid needs at least one column and one row; got {columns} x {rows}"
            ),
            Error::TooManySamples {
                sampler,
                requested,
                max,
                reason,
            } => write!(
                f,
                "{sampler} accepts at most {max} samples, got {requested}: {reason}"
            ),
            Error::GridTooFine {
                sampler,
                columns,
                rows,
            } => write!(
                f,
                "{sampler} cannot stratify a {columns} x {rows} grid: a side above 2^24 = 16777216 \
                 has more strata than f32 can tell apart in [0, 1) (the only grid of a prime n is \
                 1 x n); pick an n with a divisor near its square root, give the grid shape \
                 yourself, or use a sequence (sobol, pmj02) that takes any n"
            ),
            Error::EmptyPointSet => {
                f.write_str("a metric needs at least one point; got an empty set")
            }
            Error::NonFinitePoint { index, x, y } => write!(
                f,
                "point {index} is ({x}, {y}), which is not finite; \
                 metrics need coordinates in [0, 1)"
            ),
            Error::PointOutOfRange { index, x, y } => write!(
                f,
                "point {index} is ({x}, {y}), outside [0, 1)^2; \
                 wrap or clamp coordinates into [0, 1) before measuring"
            ),
            Error::TooFewPoints {
                metric,
                needed,
                got,
            } => write!(
                f,
                "{metric} needs at least {needed} points, got {got}; pass a larger set"
            ),
            Error::GridDoesNotDivide { columns, rows, n } => write!(
                f,
                "a {columns} x {rows} grid has {} cells, which does not divide n = {n}; \
                 pick columns and rows whose product divides the number of points",
                u64::from(columns) * u64::from(rows)
            ),
            Error::NotPowerOfTwo { n } => write!(
                f,
                "a (0,m,2)-net check needs n = 2^m points, got n = {n}; \
                 measure a power-of-two prefix"
            ),
            Error::FrequencyOutOfRange { max_frequency, max } => write!(
                f,
                "a power spectrum needs a largest frequency from 1 to {max}, \
                 got {max_frequency}"
            ),
        }
    }
}

impl core::error::Error for Error {}
