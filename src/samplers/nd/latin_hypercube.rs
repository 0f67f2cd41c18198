use super::{check_dimensions, debug_check_dimension, reduce_index};
use crate::error::Error;
use crate::primitives::{InvariantDivisor, MAX_STRATA, Permutation, hash_u32, mix64};
use crate::traits::{SamplerNd, check_nd_out};

/// A Latin hypercube of `n` points in `dimensions` dimensions: every 1D
/// projection has exactly one point in each of its `n` strata.
///
/// Coordinate `dimension` of sample `index` lies in stratum
/// `permute_dimension(index)` of `n`, jittered uniformly inside it: one
/// keyed permutation of `0..n` per dimension, drawn from the pattern and
/// the dimension, so no table is stored and any coordinate is computed
/// alone. In two dimensions it has the guarantee of
/// [`NRooks`](crate::NRooks), which stays the 2D [`Sampler2D`](crate::Sampler2D)
/// (with other values).
///
/// # Properties
///
/// - Latin in every dimension: for every `dimension < dimensions()` and
///   every `j < n`, exactly one sample has `floor(x * n) = j`, checked
///   exactly on the f32 values.
/// - Nothing beyond 1D: pairs of dimensions are as independent as two
///   random permutations (use [`OrthogonalArray`](crate::OrthogonalArray)
///   for stratified 2D to 4D projections).
/// - Each coordinate is uniform on `[0, 1)` (to the 2^-24 grid) over
///   patterns, so estimates are unbiased; different dimensions and
///   different patterns use independent permutations and jitter.
/// - Any `n` from 1 to 2^24 and any dimension count from 1 to 2^16.
///
/// # Cost
///
/// Per coordinate: one [`mix64`] of the
/// pattern's hash and the dimension (the permutation's key and the
/// jitter's), one permutation of `n` (its setup and one application: an
/// exact shuffle for `n <= 8`, else four or five hash rounds times the
/// expected cycle walk, under 2), one
/// [`hash_u32`] of the index for the jitter
/// and a fixed-point stratum conversion by a stored reciprocal (no
/// division). [`sample`](SamplerNd::sample) and
/// [`coordinates`](SamplerNd::coordinates) hash the pattern once per
/// call instead of once per coordinate.
///
/// # Limits
///
/// `n` at most 2^24 ([`LatinHypercube::MAX_SAMPLES`]): beyond that f32
/// cannot hold a value in each of `n` strata. At most 2^16 dimensions
/// ([`LatinHypercube::MAX_DIMENSIONS`]). In release builds an index at or
/// above `len()` gives the coordinate of sample `index % n`, and a
/// dimension at or above `dimensions()` a further independent Latin
/// dimension (its own permutation).
///
/// # Examples
///
/// ```
/// use wellspread::{LatinHypercube, SamplerNd};
/// let cube = LatinHypercube::new(7, 6)?;
/// let mut counts = [[0; 7]; 6];
/// let mut point = [0.0; 6];
/// for index in 0..7 {
///     cube.sample(index, 42, &mut point);
///     for (dimension, x) in point.iter().enumerate() {
///         counts[dimension][(x * 7.0) as usize] += 1;
///     }
/// }
/// assert_eq!(counts, [[1; 7]; 6]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// McKay, Beckman & Conover 1979, "A comparison of three methods for
/// selecting values of input variables in the analysis of output from a
/// computer code", Technometrics; Shirley 1991 (n-rooks in graphics).
/// Random access through Kensler's (2013) hashed permutations instead of a
/// shuffled table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LatinHypercube {
    n: InvariantDivisor,
    dimensions: u32,
}

impl LatinHypercube {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

    /// The most dimensions accepted: 2^16.
    pub const MAX_DIMENSIONS: u32 = 1 << 16;

    /// A Latin hypercube of `n` points in `dimensions` dimensions.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`, [`Error::TooManyNdSamples`]
    /// above [`MAX_SAMPLES`](Self::MAX_SAMPLES), and
    /// [`Error::DimensionsOutOfRange`] for 0 dimensions or more than
    /// [`MAX_DIMENSIONS`](Self::MAX_DIMENSIONS).
    ///
    /// ```
    /// use wellspread::{Error, LatinHypercube};
    /// assert_eq!(LatinHypercube::new(0, 3), Err(Error::ZeroSamples));
    /// assert!(matches!(
    ///     LatinHypercube::new(16, 0),
    ///     Err(Error::DimensionsOutOfRange { dimensions: 0, max: 65536, .. })
    /// ));
    /// ```
    pub fn new(n: u32, dimensions: u32) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        if n > Self::MAX_SAMPLES {
            return Err(Error::TooManyNdSamples {
                sampler: "LatinHypercube",
                requested: n,
                max: Self::MAX_SAMPLES,
                reason: "every dimension needs n distinct f32 strata in [0, 1), \
                         and f32 has 2^24 at equal spacing",
            });
        }
        check_dimensions(
            "LatinHypercube",
            dimensions,
            Self::MAX_DIMENSIONS,
            "more than 2^16 = 65536 dimensions is taken for a caller's mistake \
             (a path draws far fewer)",
        )?;
        Ok(Self {
            n: InvariantDivisor::new(n),
            dimensions,
        })
    }

    /// Coordinate `dimension` of sample `index` (already reduced) of the
    /// pattern whose hash is `pattern_hash`: one [`mix64`] of the hash and
    /// the dimension keys the stratum permutation (its low half) and the
    /// jitter (its high half).
    #[inline(always)]
    fn coordinate_of(&self, index: u32, pattern_hash: u32, dimension: u32) -> f32 {
        debug_check_dimension(dimension, self.dimensions);
        let key = mix64((u64::from(pattern_hash) << 32) | u64::from(dimension));
        let stratum = Permutation::new(self.n.get(), key as u32).apply(index);
        let bits = hash_u32(index ^ (key >> 32) as u32);
        self.n.stratum_to_unit_f32(stratum, bits)
    }
}

impl SamplerNd for LatinHypercube {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn dimensions(&self) -> u32 {
        self.dimensions
    }

    #[inline]
    fn coordinate(&self, index: u32, pattern: u32, dimension: u32) -> f32 {
        self.coordinate_of(reduce_index(index, self.n), hash_u32(pattern), dimension)
    }

    /// The pattern hashed once for all of `out`.
    #[inline(always)]
    fn coordinates(&self, index: u32, pattern: u32, first: u32, out: &mut [f32]) {
        let (index, pattern_hash) = (reduce_index(index, self.n), hash_u32(pattern));
        for (dimension, x) in (first..).zip(out.iter_mut()) {
            *x = self.coordinate_of(index, pattern_hash, dimension);
        }
    }

    #[track_caller]
    fn sample(&self, index: u32, pattern: u32, out: &mut [f32]) {
        let out = check_nd_out(out, self.dimensions);
        self.coordinates(index, pattern, 0, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constructor_limits() {
        assert_eq!(LatinHypercube::new(0, 1), Err(Error::ZeroSamples));
        assert!(LatinHypercube::new(1, 1).is_ok());
        assert!(LatinHypercube::new(MAX_STRATA, 1 << 16).is_ok());
        let Err(err) = LatinHypercube::new(MAX_STRATA + 1, 2) else {
            panic!("accepted 2^24 + 1 samples");
        };
        let message = std::format!("{err}");
        assert!(message.contains("at most 16777216"), "{message}");
        let message = std::format!("{}", LatinHypercube::new(4, 0).unwrap_err());
        assert_eq!(
            message,
            "LatinHypercube makes 1 to 65536 dimensions, got 0: ask for at least one"
        );
        let Err(err) = LatinHypercube::new(4, (1 << 16) + 1) else {
            panic!("accepted 2^16 + 1 dimensions");
        };
        let message = std::format!("{err}");
        assert!(
            message.starts_with("LatinHypercube makes 1 to 65536 dimensions, got 65537"),
            "{message}"
        );
    }

    #[test]
    #[should_panic(expected = "needs room for 3 coordinates, got a slice of 2")]
    fn a_short_output_slice_panics() {
        let cube = LatinHypercube::new(4, 3).unwrap();
        cube.sample(0, 0, &mut [0.0; 2]);
    }
}
