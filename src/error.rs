//! The one error type: every way input to a constructor or a metric can be wrong.

use core::fmt;

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
        /// The sampler's name, as the tools spell it.
        sampler: &'static str,
        /// How many were asked for (columns x rows for a grid).
        requested: u64,
        /// The largest count the sampler accepts.
        max: u64,
        /// Why the limit exists.
        reason: &'static str,
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
        }
    }
}

impl core::error::Error for Error {}
