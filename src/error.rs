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
    /// A pixel sampler's film was given a zero width or height.
    ZeroResolution {
        /// The film size asked for, `[width, height]`.
        resolution: [u32; 2],
    },
    /// A grid was asked for with zero columns or zero rows.
    ZeroGridSide {
        /// Columns asked for.
        columns: u32,
        /// Rows asked for.
        rows: u32,
    },
    /// More samples (or grid cells) than the sampler can keep its guarantee for.
    TooManySamples {
        /// The sampler, by its [`SamplerKind`](crate::SamplerKind) name.
        sampler: &'static str,
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
        /// The sampler, by its [`SamplerKind`](crate::SamplerKind) name.
        sampler: &'static str,
        /// Columns of the grid.
        columns: u32,
        /// Rows of the grid.
        rows: u32,
    },
    /// More samples than an N-dimensional point set
    /// ([`LatinHypercube`](crate::LatinHypercube)) can keep its guarantee
    /// for.
    TooManyNdSamples {
        /// The sampler, as the docs name it.
        sampler: &'static str,
        /// How many were asked for.
        requested: u32,
        /// The largest count the sampler accepts.
        max: u32,
        /// Why the limit exists.
        reason: &'static str,
    },
    /// An N-dimensional point set was asked for 0 dimensions, or more than
    /// it can make.
    DimensionsOutOfRange {
        /// The sampler, as the docs name it.
        sampler: &'static str,
        /// Dimensions asked for.
        dimensions: u32,
        /// The most dimensions it accepts (at this sample count).
        max: u32,
        /// Why the limit exists.
        reason: &'static str,
    },
    /// An [`OrthogonalArray`](crate::OrthogonalArray) of a strength other
    /// than 2, 3 or 4.
    StrengthOutOfRange {
        /// The strength asked for.
        strength: u32,
    },
    /// An [`OrthogonalArray`](crate::OrthogonalArray) was asked for a count
    /// that is not `q^strength` for a prime power `q` (at most 2^24
    /// samples): the arrays have no other sizes, and rounding silently
    /// would change the caller's sample budget.
    NotOrthogonalArraySize {
        /// Samples asked for.
        n: u32,
        /// The strength asked for.
        strength: u32,
        /// The largest valid count below `n`, if any
        /// ([`OrthogonalArray::nearest_sizes`](crate::OrthogonalArray::nearest_sizes)).
        below: Option<u32>,
        /// The smallest valid count above `n`, if any.
        above: Option<u32>,
    },
    /// The `orthogonal` pixel sampler was asked for a count that is not
    /// `lambda q^2` for a prime power `q` (`lambda` passes of a `q^2`
    /// array): every count with a factor 4, 9, 25, 49, ... is one.
    NotOrthogonalPixelCount {
        /// Samples per pixel asked for.
        samples_per_pixel: u32,
        /// The largest valid count below, if any.
        below: Option<u32>,
        /// The smallest valid count above, if any.
        above: Option<u32>,
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
    /// A name that is not a sampler's ([`SamplerKind::from_str`](crate::SamplerKind)).
    UnknownSampler(UnknownName),
    /// A name that is not a pixel sampler's
    /// ([`PixelSamplerKind::from_str`](crate::PixelSamplerKind)).
    UnknownPixelSampler(UnknownName),
    /// [`ZSobol`](crate::ZSobol) was asked for a number of samples per
    /// pixel that is not a power of two.
    SamplesNotPowerOfTwo {
        /// Samples per pixel asked for.
        samples_per_pixel: u32,
    },
    /// [`ZSobol`](crate::ZSobol)'s index space, the resolution rounded up
    /// to a power-of-two square times the samples per pixel, exceeds the
    /// `2^32` indices of the sequence.
    IndexSpaceTooLarge {
        /// The film size, `[width, height]`.
        resolution: [u32; 2],
        /// Samples per pixel asked for.
        samples_per_pixel: u32,
        /// Bits the index space needs (at most 32 are available).
        index_bits: u32,
    },
    /// A weighted choice ([`warp::Discrete`](crate::warp::Discrete),
    /// [`warp::AliasTable`](crate::warp::AliasTable)) was given a negative
    /// weight (`-0.0` counts as `0.0` and is accepted).
    NegativeWeight {
        /// Index of the first such weight in the slice.
        index: usize,
        /// The weight.
        weight: f32,
    },
    /// A weighted choice was given a NaN or infinite weight.
    NonFiniteWeight {
        /// Index of the first such weight in the slice.
        index: usize,
        /// The weight.
        weight: f32,
    },
    /// A weighted choice was given no weights, or only zeros: there is
    /// nothing to choose.
    ZeroTotalWeight {
        /// How many weights were given.
        count: usize,
    },
    /// A weighted choice was given more weights than its `u32` indices
    /// can name.
    TooManyWeights {
        /// How many weights were given.
        count: usize,
    },
    /// A pixel column given to
    /// [`ExplicitColumns::new`](crate::blue_noise::ExplicitColumns::new) has a
    /// coordinate with more than 24 digits.
    PixelColumnTooWide {
        /// Its place in the list, 0 to 31.
        index: u32,
        /// The column, x then y.
        column: [u32; 2],
    },
    /// The pixel columns given to
    /// [`ExplicitColumns::new`](crate::blue_noise::ExplicitColumns::new), together
    /// with the 16 Sobol' sample columns, do not span all 48 digits of a
    /// shift, so two pixels of one tile would share a shift.
    DependentPixelColumns {
        /// How many of the 48 digits they span.
        rank: u32,
    },
    /// A name that is not a filter's
    /// ([`FilterKind::from_str`](crate::filter::FilterKind)).
    UnknownFilter(UnknownName),
    /// A pixel filter ([`filter`](crate::filter)) was given a parameter it
    /// cannot use.
    FilterParameter {
        /// The filter, as the tools spell it.
        filter: &'static str,
        /// The parameter.
        parameter: &'static str,
        /// Its value.
        value: f32,
        /// What the filter accepts.
        expected: &'static str,
    },
}

/// A name a parser did not know ([`Error::UnknownSampler`],
/// [`Error::UnknownPixelSampler`], [`Error::UnknownFilter`]): the text
/// given and the names that parser accepts, which the message lists, each
/// once. The text is kept as its first [`CAPACITY`](Self::CAPACITY)
/// bytes, cut at a character boundary, so that [`Error`] stays `Copy` and
/// needs no allocator.
///
/// ```
/// use wellspread::{Error, SamplerKind};
/// let Err(Error::UnknownSampler(unknown)) = "jitterd".parse::<SamplerKind>() else {
///     unreachable!()
/// };
/// assert_eq!(unknown.as_str(), "jitterd");
/// assert!(!unknown.is_truncated());
/// assert!(unknown.names().any(|name| name == "jittered"));
/// ```
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct UnknownName {
    bytes: [u8; UnknownName::CAPACITY],
    len: u8,
    truncated: bool,
    names: &'static [&'static str],
    aliases: &'static [&'static str],
}

impl UnknownName {
    /// Bytes of the text kept: longer than every name, short enough that
    /// an `Error` stays a few words.
    pub const CAPACITY: usize = 40;

    /// `input` (its first [`CAPACITY`](Self::CAPACITY) bytes, cut back to
    /// a character boundary) against the parser's `names` and `aliases`.
    pub(crate) fn new(
        input: &str,
        names: &'static [&'static str],
        aliases: &'static [&'static str],
    ) -> Self {
        let mut len = input.len().min(Self::CAPACITY);
        while !input.is_char_boundary(len) {
            len -= 1;
        }
        let mut bytes = [0; Self::CAPACITY];
        bytes[..len].copy_from_slice(&input.as_bytes()[..len]);
        Self {
            bytes,
            // len <= CAPACITY < 256.
            len: len as u8,
            truncated: len < input.len(),
            names,
            aliases,
        }
    }

    /// The text given: its first [`CAPACITY`](Self::CAPACITY) bytes, cut
    /// back to a character boundary.
    #[must_use]
    pub fn as_str(&self) -> &str {
        // `new` cut at a character boundary, so this never fails.
        core::str::from_utf8(&self.bytes[..usize::from(self.len)]).unwrap_or("")
    }

    /// `true` if the text given was longer than [`as_str`](Self::as_str).
    #[must_use]
    pub const fn is_truncated(&self) -> bool {
        self.truncated
    }

    /// The names the parser accepts, aliases last.
    pub fn names(&self) -> impl Iterator<Item = &'static str> + Clone {
        self.names.iter().chain(self.aliases).copied()
    }
}

/// The text given (not its buffer), whether it was cut, and the names.
impl fmt::Debug for UnknownName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("UnknownName")
            .field("input", &self.as_str())
            .field("truncated", &self.truncated)
            .field("names", &self.names)
            .field("aliases", &self.aliases)
            .finish()
    }
}

impl fmt::Display for UnknownName {
    /// `"x"; expected one of: ...`, the input escaped so that the message
    /// stays one line, a cut input ending in `...`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "\"{}", self.as_str().escape_debug())?;
        if self.is_truncated() {
            f.write_str("...")?;
        }
        f.write_str("\"; expected one of:")?;
        for name in self.names {
            write!(f, " {name}")?;
        }
        f.write_str(" (any case, with or without - _ or spaces")?;
        for (i, alias) in self.aliases.iter().enumerate() {
            write!(f, "{}{alias}", if i == 0 { "; aliases: " } else { ", " })?;
        }
        f.write_str(")")
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::ZeroSamples => f.write_str("a sampler needs at least one sample; got n = 0"),
            Error::ZeroResolution {
                resolution: [width, height],
            } => write!(
                f,
                "a film needs a width and a height of at least one pixel; got {width} x {height}"
            ),
            Error::ZeroGridSide { columns, rows } => write!(
                f,
                "a grid needs at least one column and one row; got {columns} x {rows}"
            ),
            Error::TooManySamples {
                sampler,
                requested,
                max,
                reason,
            } => too_many(f, &sampler, requested, max, reason),
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
            Error::TooManyNdSamples {
                sampler,
                requested,
                max,
                reason,
            } => too_many(f, &sampler, requested.into(), max.into(), reason),
            Error::DimensionsOutOfRange {
                sampler,
                dimensions: 0,
                max,
                ..
            } => write!(
                f,
                "{sampler} makes 1 to {max} dimensions, got 0: ask for at least one"
            ),
            Error::DimensionsOutOfRange {
                sampler,
                dimensions,
                max,
                reason,
            } => write!(
                f,
                "{sampler} makes 1 to {max} dimensions, got {dimensions}: {reason}"
            ),
            Error::StrengthOutOfRange { strength } => write!(
                f,
                "an orthogonal array has strength 2, 3 or 4, got {strength}; strength 1 is a \
                 Latin hypercube (LatinHypercube)"
            ),
            Error::NotOrthogonalPixelCount {
                samples_per_pixel,
                below,
                above,
            } => {
                write!(
                    f,
                    "orthogonal takes lambda q^2 samples per pixel (lambda passes of a q^2 \
                     array, q a prime power: any multiple of 4, 9, 25, 49, ...), and \
                     {samples_per_pixel} is not one; use "
                )?;
                match (below, above) {
                    (Some(below), Some(above)) => write!(f, "{below} or {above}"),
                    (Some(only), None) | (None, Some(only)) => write!(f, "{only}"),
                    (None, None) => f.write_str("another count"),
                }
            }
            Error::NotOrthogonalArraySize {
                n,
                strength,
                below,
                above,
            } => {
                write!(
                    f,
                    "an orthogonal array of strength {strength} has q^{strength} samples for a \
                     prime power q (at most 2^24 samples), and {n} is not one; use "
                )?;
                match (below, above) {
                    (Some(below), Some(above)) => write!(f, "{below} or {above}"),
                    (Some(only), None) | (None, Some(only)) => write!(f, "{only}"),
                    (None, None) => f.write_str("another strength"),
                }
            }
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
            Error::UnknownSampler(unknown) => write!(f, "unknown sampler {unknown}"),
            Error::UnknownPixelSampler(unknown) => write!(f, "unknown pixel sampler {unknown}"),
            Error::UnknownFilter(unknown) => write!(f, "unknown filter {unknown}"),
            Error::SamplesNotPowerOfTwo { samples_per_pixel } => {
                let above = u64::from(samples_per_pixel).next_power_of_two();
                write!(
                    f,
                    "zsobol needs a power-of-two number of samples per pixel (1, 2, 4, 8, ...), \
                     got {samples_per_pixel}; use {}",
                    above / 2
                )?;
                // Above 2^31 the next power of two does not fit in a u32.
                if above <= u64::from(u32::MAX) {
                    write!(f, " or {above}")?;
                }
                Ok(())
            }
            Error::IndexSpaceTooLarge {
                resolution: [width, height],
                samples_per_pixel,
                index_bits,
            } => {
                write!(
                    f,
                    "zsobol at {samples_per_pixel} samples per pixel on a {width} x {height} \
                     film needs 2^{index_bits} sequence indices (the film rounded up to a \
                     power-of-two square, times the samples per pixel), more than the 2^32 \
                     available; "
                )?;
                let film_bits = index_bits - samples_per_pixel.trailing_zeros();
                if film_bits <= 32 {
                    write!(
                        f,
                        "use at most {} samples per pixel per pass and average passes \
                         with different frames",
                        1u64 << (32 - film_bits)
                    )
                } else {
                    f.write_str("render films of at most 65536 pixels on a side")
                }
            }
            Error::NegativeWeight { index, weight } => write!(
                f,
                "weight {index} is {weight}, which is negative; a weighted choice needs weights \
                 >= 0 (give 0 to an item that must never be chosen)"
            ),
            Error::NonFiniteWeight { index, weight } => write!(
                f,
                "weight {index} is {weight}, which is not finite; a weighted choice needs finite \
                 weights (scale them down, or clamp a light's power before building the table)"
            ),
            Error::ZeroTotalWeight { count } => write!(
                f,
                "a weighted choice needs at least one positive weight; got {count} weights, \
                 none positive (skip the draw when there is nothing to choose, or use \
                 warp::discrete for a uniform choice)"
            ),
            Error::FilterParameter {
                filter,
                parameter,
                value,
                expected,
            } => write!(
                f,
                "the {filter} filter cannot use {parameter} = {value}; give {expected}"
            ),
            Error::PixelColumnTooWide { index, column } => write!(
                f,
                "pixel column {index} is [{:#x}, {:#x}], but a column has 24 digits per \
                 coordinate (each below 2^24 = 16777216); mask both with 0xffffff",
                column[0], column[1]
            ),
            Error::DependentPixelColumns { rank } => write!(
                f,
                "the 32 pixel columns and the 16 Sobol' sample columns span only {rank} of the \
                 48 digits, so pixels of one 65536 x 65536 tile would share a shift; redraw \
                 columns (the coarsest, at the end of the list, matter least) until they span \
                 all 48"
            ),
            Error::TooManyWeights { count } => write!(
                f,
                "a weighted choice takes at most 2^32 - 1 = 4294967295 weights, got {count}; \
                 group the items and choose in two draws"
            ),
        }
    }
}

impl core::error::Error for Error {}

/// `a` and `b` equal ignoring ASCII case and the separators `-`, `_`, ` `:
/// the one rule for the names of sampler and filter kinds.
pub(crate) fn same_name(a: &str, b: &str) -> bool {
    fn key(s: &str) -> impl Iterator<Item = u8> + '_ {
        s.bytes()
            .filter(|c| !matches!(c, b'-' | b'_' | b' '))
            .map(|c| c.to_ascii_lowercase())
    }
    key(a).eq(key(b))
}

/// Deserializes a kind named by a string (`SamplerKind`, `FilterKind`;
/// feature `serde`) through its `FromStr`, so that a settings file gets the
/// same error as a command line; `expecting` is what serde says it wanted
/// when given no string.
#[cfg(feature = "serde")]
pub(crate) fn deserialize_name<'de, D, T>(
    deserializer: D,
    expecting: &'static str,
) -> Result<T, D::Error>
where
    D: serde::Deserializer<'de>,
    T: core::str::FromStr<Err = Error>,
{
    struct Name<T>(&'static str, core::marker::PhantomData<T>);
    impl<T: core::str::FromStr<Err = Error>> serde::de::Visitor<'_> for Name<T> {
        type Value = T;

        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str(self.0)
        }

        fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<T, E> {
            name.parse().map_err(E::custom)
        }
    }
    deserializer.deserialize_str(Name(expecting, core::marker::PhantomData))
}

/// The message of [`Error::TooManySamples`] and [`Error::TooManyNdSamples`].
fn too_many(
    f: &mut fmt::Formatter<'_>,
    sampler: &dyn fmt::Display,
    requested: u64,
    max: u64,
    reason: &str,
) -> fmt::Result {
    write!(
        f,
        "{sampler} accepts at most {max} samples, got {requested}: {reason}"
    )
}

#[cfg(all(test, feature = "alloc"))]
mod tests {
    use super::*;
    use alloc::string::ToString;

    #[test]
    fn samples_per_pixel_suggestions_fit_in_u32() {
        // What `ZSobol::new(u32::MAX, ..)` returns (tests/pixel/domain.rs).
        let message = Error::SamplesNotPowerOfTwo {
            samples_per_pixel: u32::MAX,
        }
        .to_string();
        assert!(
            message.ends_with("got 4294967295; use 2147483648"),
            "{message}"
        );
        // Both neighbours where both fit.
        let message = Error::SamplesNotPowerOfTwo {
            samples_per_pixel: 6,
        }
        .to_string();
        assert!(message.ends_with("got 6; use 4 or 8"), "{message}");
        // 2^31 + 1 lies between 2^31 and 2^32.
        let message = Error::SamplesNotPowerOfTwo {
            samples_per_pixel: (1 << 31) + 1,
        }
        .to_string();
        assert!(message.ends_with("use 2147483648"), "{message}");
    }
}
