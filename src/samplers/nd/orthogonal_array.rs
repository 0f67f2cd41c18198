use super::field::{self, ANY, BINARY, DIGITS, Field, PRIME, TABLED, prime_power};
use super::{check_dimensions, reduce_index};
use crate::error::Error;
use crate::primitives::{
    InvariantDivisor, MAX_STRATA, Permutation, derived_key, hash_combine, hash_u32, mix64, salt,
};
use crate::traits::{SamplerNd, check_nd_out};

/// Where inside its cell of the array an [`OrthogonalArray`] coordinate
/// lands (Jarosz et al. 2019, section 4).
///
/// Every style keeps the array's strength; the multi-jittered ones add
/// Latin 1D projections (Tang's 1993 OA-based Latin hypercube).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum OrthogonalArrayOffset {
    /// Uniform inside the level's stratum: each dimension is cut into `q`
    /// strata of `q^(t - 1)` points each, and nothing finer.
    Jittered,
    /// Latin in every dimension: the `q^(t - 1)` points that share a level
    /// of a dimension take its `q^(t - 1)` sub-strata in an order drawn
    /// for that level and dimension, then jitter inside the sub-stratum.
    /// A point's place in that order comes from the strata of `t - 1`
    /// partner dimensions (for strength 2, dimensions `2k` and `2k + 1`
    /// are each other's partners).
    MultiJittered,
    /// As [`MultiJittered`](Self::MultiJittered), with one sub-stratum
    /// order per dimension shared by all its levels (Kensler's 2013
    /// correlation: at strength 2, each pair of dimensions `2k, 2k + 1`
    /// is a correlated multi-jittered set): the default. On the coupled
    /// 4D integrand of `docs/quality.md` its error is within a few
    /// percent of Mitsuba 3's `orthogonal` sampler at every common count.
    #[default]
    CorrelatedMultiJittered,
}

/// A randomised orthogonal array of strength `t`: `n = q^t` points in up
/// to `q + 1` dimensions whose every projection onto `t` dimensions is
/// stratified into `q^t` cells, one point each.
///
/// The array is Bush's (1952) over the finite field GF(q), `q` a prime or
/// a prime power: row `r`, with base-`q` digits `a_0 .. a_(t-1)`, is the
/// polynomial `f(x) = a_0 + a_1 x + ... + a_(t-1) x^(t-1)`; column `c < q`
/// holds `f(c)` and column `q` the leading coefficient `a_(t-1)`. Any `t`
/// columns determine the `t` coefficients (a polynomial of degree below
/// `t` is fixed by `t` values, or by `t - 1` values and its leading
/// coefficient), so every `t`-tuple of levels appears in exactly one row.
/// For `t = 2` this is Bose's (1938) array (`a_0 + a_1 c` and `a_1`).
///
/// Each pattern is a new random array: the rows are taken in a keyed
/// nonlinear order (a Feistel network on the row's base-`q` digits),
/// every dimension permutes its column's levels, and the dimensions take
/// consecutive columns (cyclically) from a random first one. Coordinate
/// `j` of a sample is then the permuted level's stratum `[level / q,
/// (level + 1) / q)`, with the [`OrthogonalArrayOffset`]
/// deciding where inside it: the multi-jittered offsets split that stratum
/// into `q^(t - 1)` sub-strata and tell the points sharing the level apart
/// by the strata of `t - 1` partner dimensions (dimensions `2k` and `2k +
/// 1` at strength 2), in an order drawn the same way.
///
/// A level permutation (and, at strength 2, a sub-stratum order) is a
/// keyed affine map `x -> a x + b` of GF(q), `a != 0`, not a shuffle of
/// all `q!` orders: the affine group is sharply 2-transitive, so the
/// images of any two levels are a uniformly random pair of distinct
/// levels, which is all that the variance of an estimate over the array
/// (Owen 1992) depends on, since it takes the points two at a time. It
/// costs one product and one sum in the field.
///
/// # Properties
///
/// - Strength `t`: for every `t` of the first `dimensions()` dimensions,
///   every cell of the `q x ... x q` grid of their projection holds
///   exactly one point; projections onto `k < t` dimensions hold
///   `q^(t - k)` points in each of their `q^k` cells. Checked exactly on
///   the f32 values, strength 3 and 4 included.
/// - With the (correlated) multi-jittered offsets, also Latin in every
///   dimension: one point in each of the `n` strata of `[0, 1)`.
/// - Each coordinate is uniform on `[0, 1)` (to the 2^-24 grid) over
///   patterns, so estimates are unbiased.
/// - Valid counts are `q^t` for a prime power `q`: for strength 2, 4, 9,
///   16, 25, 49, 64, 81, 121, 169, 256, 289, ...; for strength 3, 8, 27,
///   64, 125, 343, 512, ...; for strength 4, 16, 81, 256, 625, 2401, 4096,
///   .... Other counts are an error that names the nearest valid ones
///   ([`nearest_sizes`](Self::nearest_sizes)); nothing rounds silently.
///
/// # Cost
///
/// Per pattern: one [`mix64`] for the
/// pattern's hash, the row order's key and the first column. Per sample:
/// the row, `t` Feistel steps of about fifteen operations on its digits
/// (no cycle walk). Per coordinate: one `mix64` of the pattern's hash and
/// the dimension, which draws the level's affine map, the sub-stratum's
/// (an affine map at strength 2, a keyed permutation of the `q^(t - 1)`
/// sub-strata above) and the jitter's stream; the row's polynomial
/// evaluated in its own column (and, for the multi-jittered offsets, in
/// its `t - 1` partners'), each `t - 1` field products and sums; a
/// [`hash_u32`] of the index for the jitter
/// and a fixed-point stratum conversion. A field product is a multiply and a
/// remainder for an odd prime `q`, three table lookups for `q = 2^k` up to 256
/// (3 KiB of logarithms, built at compile time), `k` shift-and-xor steps
/// for larger powers of two and a few dozen digit operations for other
/// prime powers. [`sample`](SamplerNd::sample) and
/// [`coordinates`](SamplerNd::coordinates) pay the per-pattern work once
/// and evaluate each group of `t` partner dimensions' columns once for the
/// whole group, with the field's arithmetic and the strength chosen once
/// per call; [`coordinate`](SamplerNd::coordinate) pays all of it per
/// coordinate. The constructor searches `GF(q)`'s modulus by trial
/// division (a few thousand operations).
///
/// # Limits
///
/// `n = q^t` at most 2^24 ([`OrthogonalArray::MAX_SAMPLES`], so every
/// stratum of the Latin offsets holds an f32): `q` up to 4096 for strength
/// 2, 256 for strength 3, 64 for strength 4. At most `q + 1` dimensions
/// ([`max_dimensions`](Self::max_dimensions)); when `q + 1 < t` (16 points
/// at strength 4 have `q = 2`, so 3 dimensions) every projection onto the
/// available dimensions is still stratified as above. In release builds an
/// index at or above `len()` gives sample `index % n`, and a dimension at
/// or above `dimensions()` gives dimension `dimension % dimensions()`.
///
/// # Examples
///
/// Strength 3: every 3D projection of 64 points in 5 dimensions has one
/// point in each of its 4 x 4 x 4 cells.
///
/// ```
/// use wellspread::{OrthogonalArray, SamplerNd};
/// let array = OrthogonalArray::new(64, 5, 3)?;
/// let points: Vec<[f32; 5]> = (0..64)
///     .map(|index| {
///         let mut point = [0.0; 5];
///         array.sample(index, 9, &mut point);
///         point
///     })
///     .collect();
/// for (a, b, c) in [(0, 1, 2), (0, 3, 4), (1, 2, 4), (2, 3, 4)] {
///     let mut cells = [0; 64];
///     for p in &points {
///         let level = |x: f32| (x * 4.0) as usize;
///         cells[level(p[a]) * 16 + level(p[b]) * 4 + level(p[c])] += 1;
///     }
///     assert_eq!(cells, [1; 64]);
/// }
/// // 100 is not a cube of a prime power: the error names 64 and 125.
/// let message = OrthogonalArray::new(100, 3, 3).unwrap_err().to_string();
/// assert!(message.ends_with("use 64 or 125"), "{message}");
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Bose 1938, "On the application of the properties of Galois fields to
/// the problem of construction of hyper-Graeco-Latin squares", Sankhya;
/// Bush 1952, "Orthogonal arrays of index unity", Annals of Mathematical
/// Statistics; Owen 1992, "Orthogonal arrays for computer experiments,
/// integration and visualization", Statistica Sinica; Tang 1993,
/// "Orthogonal array-based Latin hypercubes", JASA; Jarosz, Enayet,
/// Kensler, Kilpatrick & Christensen 2019, "Orthogonal Array Sampling for
/// Monte Carlo Rendering", Computer Graphics Forum (EGSR).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct OrthogonalArray {
    field: Field,
    /// `t`, 2 to 4 (a byte, so the pixel sampler's domain stays small).
    strength: u8,
    dimensions: u32,
    offset: OrthogonalArrayOffset,
    /// `n = q^t`.
    n: InvariantDivisor,
    /// `q`, the levels of each column.
    q: InvariantDivisor,
    /// `q^(t - 1)`, the points that share a level of a column.
    sub: InvariantDivisor,
}

/// The strengths built: 2 (Bose), 3 and 4 (Bush).
const STRENGTHS: core::ops::RangeInclusive<u32> = 2..=4;

/// `r` with `r^t = n`, if there is one.
fn exact_root(n: u32, t: u32) -> Option<u32> {
    let guess = libm::round(libm::pow(f64::from(n), 1.0 / f64::from(t))) as u64;
    // The rounded f64 root is exact or one off for n < 2^32.
    (guess.saturating_sub(1)..=guess + 1)
        .find(|&r| r.checked_pow(t) == Some(u64::from(n)))
        .map(|r| r as u32)
}

impl OrthogonalArray {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

    /// A randomised orthogonal array of `n = q^strength` points (`q` a
    /// prime power) in `dimensions` dimensions, with
    /// [`CorrelatedMultiJittered`](OrthogonalArrayOffset::CorrelatedMultiJittered)
    /// offsets (change them with [`with_offset`](Self::with_offset)).
    ///
    /// # Errors
    ///
    /// [`Error::StrengthOutOfRange`] unless `strength` is 2, 3 or 4;
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::NotOrthogonalArraySize`]
    /// (with the nearest valid counts) when `n` is not `q^strength` for a
    /// prime power `q`, or is above [`MAX_SAMPLES`](Self::MAX_SAMPLES);
    /// [`Error::DimensionsOutOfRange`] for 0 dimensions or more than `q +
    /// 1`.
    ///
    /// ```
    /// use wellspread::{Error, OrthogonalArray};
    /// assert!(OrthogonalArray::new(256, 17, 2).is_ok()); // q = 16
    /// assert_eq!(
    ///     OrthogonalArray::new(100, 2, 2),
    ///     Err(Error::NotOrthogonalArraySize { n: 100, strength: 2, below: Some(81), above: Some(121) })
    /// );
    /// assert!(matches!(
    ///     OrthogonalArray::new(25, 7, 2),
    ///     Err(Error::DimensionsOutOfRange { dimensions: 7, max: 6, .. })
    /// ));
    /// ```
    pub fn new(n: u32, dimensions: u32, strength: u32) -> Result<Self, Error> {
        if !STRENGTHS.contains(&strength) {
            return Err(Error::StrengthOutOfRange { strength });
        }
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        let field = exact_root(n, strength)
            .filter(|_| n <= Self::MAX_SAMPLES)
            .and_then(Field::new)
            .ok_or_else(|| {
                let (below, above) = Self::nearest_sizes(n, strength);
                Error::NotOrthogonalArraySize {
                    n,
                    strength,
                    below,
                    above,
                }
            })?;
        let q = field.order();
        check_dimensions(
            "OrthogonalArray",
            dimensions,
            q + 1,
            "an orthogonal array of q^t points has q + 1 columns \
             (pick a larger n, or pad further dimensions with another pattern)",
        )?;
        Ok(Self {
            field,
            // 2 to 4, checked above.
            strength: strength as u8,
            dimensions,
            offset: OrthogonalArrayOffset::default(),
            n: InvariantDivisor::new(n),
            q: InvariantDivisor::new(q),
            sub: InvariantDivisor::new(n / q),
        })
    }

    /// The same array with offsets `offset`.
    ///
    /// ```
    /// use wellspread::{OrthogonalArray, OrthogonalArrayOffset, SamplerNd};
    /// let array = OrthogonalArray::new(25, 6, 2)?.with_offset(OrthogonalArrayOffset::Jittered);
    /// assert_eq!(array.offset(), OrthogonalArrayOffset::Jittered);
    /// assert_eq!((array.len(), array.dimensions()), (25, 6));
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[must_use]
    pub const fn with_offset(self, offset: OrthogonalArrayOffset) -> Self {
        Self { offset, ..self }
    }

    /// The offset style.
    #[must_use]
    pub const fn offset(&self) -> OrthogonalArrayOffset {
        self.offset
    }

    /// The strength `t`: every `t`-dimensional projection is stratified.
    #[must_use]
    pub const fn strength(&self) -> u32 {
        self.strength as u32
    }

    /// The levels `q` per dimension (`n = q^t`).
    #[must_use]
    pub const fn levels(&self) -> u32 {
        self.q.get()
    }

    /// The most dimensions an array of this size has: `q + 1`.
    #[must_use]
    pub const fn max_dimensions(&self) -> u32 {
        self.q.get() + 1
    }

    /// The valid counts nearest `n` at strength `strength`: the largest
    /// `q^strength` at most `n` and the smallest at least `n` (`q` a prime
    /// power, counts at most [`MAX_SAMPLES`](Self::MAX_SAMPLES)); both are
    /// `n` when `n` is valid, and `None` where there is none (below 2^t,
    /// above the largest valid count, or a strength other than 2, 3 or 4).
    ///
    /// ```
    /// use wellspread::OrthogonalArray;
    /// assert_eq!(OrthogonalArray::nearest_sizes(100, 2), (Some(81), Some(121)));
    /// assert_eq!(OrthogonalArray::nearest_sizes(64, 3), (Some(64), Some(64)));
    /// assert_eq!(OrthogonalArray::nearest_sizes(1000, 4), (Some(625), Some(2401)));
    /// assert_eq!(OrthogonalArray::nearest_sizes(1, 2), (None, Some(4)));
    /// ```
    #[must_use]
    pub fn nearest_sizes(n: u32, strength: u32) -> (Option<u32>, Option<u32>) {
        let (mut below, mut above) = (None, None);
        if !STRENGTHS.contains(&strength) {
            return (below, above);
        }
        for q in 2..=field::MAX_ORDER {
            let size = u64::from(q).pow(strength);
            if size > u64::from(Self::MAX_SAMPLES) {
                break;
            }
            if prime_power(q).is_none() {
                continue;
            }
            // size <= 2^24 fits in u32.
            let size = size as u32;
            if size <= n {
                below = Some(size);
            }
            if size >= n {
                above = Some(size);
                break;
            }
        }
        (below, above)
    }

    /// The levels `q` of the strength-2 array whose passes make `n`
    /// samples: the largest prime power `q` with `q^2` at most
    /// [`MAX_SAMPLES`](Self::MAX_SAMPLES) dividing `n` (`n = lambda q^2`),
    /// or `None` if `n` has no such square factor.
    pub(crate) fn pass_levels(n: u32) -> Option<u32> {
        let top = n.isqrt().min(field::MAX_ORDER);
        (2..=top)
            .rev()
            .find(|&q| prime_power(q).is_some() && n.is_multiple_of(q * q))
    }

    /// The counts nearest `n` that [`pass_levels`](Self::pass_levels)
    /// accepts: the largest below `n` and the smallest above it (every
    /// multiple of 4 is one, so each is at most 3 away, where it fits in
    /// a u32).
    pub(crate) fn nearest_pass_counts(n: u32) -> (Option<u32>, Option<u32>) {
        let valid = |m: &u32| Self::pass_levels(*m).is_some();
        let below = (n.saturating_sub(4)..n).rev().find(valid);
        let above = (n.saturating_add(1)..=n.saturating_add(4)).find(valid);
        (below.filter(|&m| m < n), above.filter(|&m| m > n))
    }

    /// The per-pattern work: the pattern's hash, its row order and its
    /// choice of columns.
    #[inline(always)]
    fn prepare(&self, pattern: u32) -> ArrayPattern {
        // One hash for the three: the pattern's hash (which keys every
        // dimension), the row order's key, and the first column, by
        // multiply-high from the bits between them.
        let bits = mix64(u64::from(pattern) ^ salt::ND_PATTERN);
        let first_column = (bits >> 16) as u32;
        ArrayPattern {
            hash: bits as u32,
            row_key: (bits >> 32) as u32,
            first_column: ((u64::from(first_column) * u64::from(self.q.get() + 1)) >> 32) as u32,
        }
    }

    /// The row that sample `index` (`< n`) takes in `pattern`: a keyed
    /// bijection of `0..n`, at strength `t`.
    #[inline(always)]
    fn row(&self, pattern: &ArrayPattern, index: u32) -> u32 {
        let q = self.q.get();
        let join = |digits: &[u32]| digits.iter().rev().fold(0, |row, &digit| row * q + digit);
        match self.strength {
            2 => join(&self.row_digits::<2>(pattern.row_key, index)),
            3 => join(&self.row_digits::<3>(pattern.row_key, index)),
            _ => join(&self.row_digits::<4>(pattern.row_key, index)),
        }
    }

    /// The base-`q` digits, lowest first, of [`row`](Self::row) at
    /// strength `T`: a Feistel network on the `T` digits of `index`. Step
    /// `j` adds to digit `j`, modulo `q`, a keyed hash of the other digits
    /// (those before it already updated) reduced to `0..q`; each step is a
    /// bijection whatever the hash (subtracting the same value undoes it),
    /// so the row order is one. The hash is nonlinear, so two patterns'
    /// row orders are not related by an affine map of the digits, which
    /// would tie a column of one array to a column of the other (the
    /// reason a linear order of the rows cannot serve); and for a fixed
    /// sample the row is uniform over patterns (tested). Every guarantee
    /// of the array holds for any order of its rows. Cost: `T` steps of
    /// about fifteen operations, against four or five hash rounds and a
    /// cycle walk for a keyed permutation of `n`.
    #[inline(always)]
    fn row_digits<const T: usize>(&self, key: u32, index: u32) -> [u32; T] {
        let q = self.q.get();
        let mut digits = self.digits::<T>(index);
        for j in 0..T {
            let mut others = 0;
            for (k, &digit) in digits.iter().enumerate() {
                if k != j {
                    others = others * q + digit;
                }
            }
            let h = (others ^ key.rotate_left(11 * j as u32)).wrapping_mul(0x7feb_352d);
            let h = (h ^ (h >> 15)).wrapping_mul(0x846c_a68b);
            let shift = ((u64::from(h) * u64::from(q)) >> 32) as u32;
            let sum = digits[j] + shift;
            digits[j] = if sum >= q { sum - q } else { sum };
        }
        digits
    }

    /// The `T` base-`q` digits of `value` (`< q^T`), lowest first.
    #[inline(always)]
    fn digits<const T: usize>(&self, value: u32) -> [u32; T] {
        let mut digits = [0; T];
        let mut rest = value;
        for digit in &mut digits {
            (rest, *digit) = self.q.div_rem(rest);
        }
        digits
    }

    /// `f(x)` for the row's polynomial `f`, whose coefficients are the
    /// row's base-`q` digits (lowest first), by Horner's rule in GF(q),
    /// at strength `T` (its loops unrolled) in a field whose arithmetic
    /// is `A`.
    #[inline(always)]
    fn evaluate_at<const T: usize, const A: u8>(&self, digits: [u32; T], x: u32) -> u32 {
        let mut value = digits[T - 1];
        for &digit in digits[..T - 1].iter().rev() {
            value = self
                .field
                .add_as::<A>(self.field.mul_as::<A>(value, x), digit);
        }
        value
    }

    /// The column of dimension `dimension` (`< q + 1`) in `pattern`.
    #[inline(always)]
    fn column(&self, pattern: &ArrayPattern, dimension: u32) -> u32 {
        let (column, columns) = (pattern.first_column + dimension, self.q.get() + 1);
        if column >= columns {
            column - columns
        } else {
            column
        }
    }

    /// The level of row `row` in column `column`, before the level
    /// permutation ([`raw_level_at`](Self::raw_level_at) on its digits).
    #[inline(always)]
    fn raw_level(&self, row: u32, column: u32) -> u32 {
        match self.strength {
            2 => self.raw_level_at::<2, ANY>(self.digits(row), column),
            3 => self.raw_level_at::<3, ANY>(self.digits(row), column),
            _ => self.raw_level_at::<4, ANY>(self.digits(row), column),
        }
    }

    /// The raw level in column `column` of the row whose base-`q` digits
    /// are `digits`, at strength `T`, in a field whose arithmetic is `A`:
    /// `f(column)`, or the leading coefficient in column `q`.
    #[inline(always)]
    fn raw_level_at<const T: usize, const A: u8>(&self, digits: [u32; T], column: u32) -> u32 {
        if column == self.q.get() {
            digits[T - 1]
        } else {
            self.evaluate_at::<T, A>(digits, column)
        }
    }

    /// Which of the `q^(t - 1)` rows that share row `row`'s level in
    /// dimension `dimension` (column `column`) this is: the raw levels of
    /// its `t - 1` partners, the other dimensions of its group of `t`
    /// (dimensions `t floor(dimension / t)` onwards, wrapping around the
    /// `q + 1` columns), as a base-`q` number. Any `t - 1` other columns
    /// take each of their `q^(t - 1)` level tuples exactly once on the
    /// rows that share a level of `column` (strength `t`), so this is a
    /// bijection. At strength 2, dimensions `2k` and `2k + 1` each take
    /// their sub-stratum from the other's stratum: Kensler's (2013)
    /// correlated multi-jitter within each pair. (Arrays with fewer
    /// columns than `t`, such as 16 points at strength 4, use the row's
    /// other coefficients instead.)
    #[inline(always)]
    fn sub_index(&self, row: u32, pattern: &ArrayPattern, dimension: u32, column: u32) -> u32 {
        let (q, t) = (self.q.get(), self.strength());
        if t > q + 1 {
            // The coefficients other than the one the level fixes: a_1 ..
            // a_(t-1) for an evaluation, a_0 .. a_(t-2) for column q.
            return if column == q {
                self.sub.div_rem(row).1
            } else {
                self.q.div_rem(row).0
            };
        }
        let base = dimension - dimension % t;
        let mut index = 0;
        for k in 0..t {
            // Distinct from `dimension` and from each other: all lie in
            // `base .. base + t`, and `t <= q + 1`.
            let partner = (base + k) % (q + 1);
            if partner != dimension {
                index = index * q + self.raw_level(row, self.column(pattern, partner));
            }
        }
        index
    }

    /// Coordinate `dimension` of sample `index` (reduced), which is row
    /// `row` of the array, of `pattern`.
    #[inline(always)]
    fn coordinate_of(&self, index: u32, row: u32, pattern: &ArrayPattern, dimension: u32) -> f32 {
        super::debug_check_dimension(dimension, self.dimensions);
        let dimension = if dimension < self.dimensions {
            dimension
        } else {
            dimension % self.dimensions
        };
        let column = self.column(pattern, dimension);
        self.place::<ANY>(
            index,
            Self::dimension_key(pattern, dimension),
            self.raw_level(row, column),
            || self.sub_index(row, pattern, dimension, column),
        )
    }

    /// The key of dimension `dimension` of `pattern`: one
    /// [`mix64`] of the pattern's hash and the dimension, whose low half
    /// draws the level permutation, high half the sub-stratum order, and
    /// middle bits the jitter's stream, so every choice made for one
    /// dimension alone costs one hash.
    #[inline(always)]
    fn dimension_key(pattern: &ArrayPattern, dimension: u32) -> u64 {
        mix64((u64::from(pattern.hash) << 32) | u64::from(dimension))
    }

    /// The coordinate of sample `index` in the dimension keyed `key`
    /// ([`dimension_key`](Self::dimension_key)), whose raw level is
    /// `value` and whose place among the rows sharing that level is
    /// `sub_index()` (asked for only by the multi-jittered offsets): the
    /// level permutation, then the offset, in a field whose arithmetic is
    /// `A`.
    #[inline(always)]
    fn place<const A: u8>(
        &self,
        index: u32,
        key: u64,
        value: u32,
        sub_index: impl FnOnce() -> u32,
    ) -> f32 {
        let (low, high) = (key as u32, (key >> 32) as u32);
        let level = self.field.apply_keyed_as::<A>(low, value);
        let bits = hash_u32(index ^ (key >> 16) as u32);
        let sub_key = match self.offset {
            OrthogonalArrayOffset::Jittered => return self.q.stratum_to_unit_f32(level, bits),
            OrthogonalArrayOffset::MultiJittered => {
                derived_key(hash_combine(high, level), salt::ND_SUB_STRATA)
            }
            OrthogonalArrayOffset::CorrelatedMultiJittered => high,
        };
        let sub = if self.strength == 2 {
            // q sub-strata, one per level of the partner: GF(q) again.
            self.field.apply_keyed_as::<A>(sub_key, sub_index())
        } else {
            Permutation::new(self.sub.get(), sub_key).apply(sub_index())
        };
        self.n
            .stratum_to_unit_f32(level * self.sub.get() + sub, bits)
    }

    /// Coordinates `first ..` (within `dimensions()`) for the
    /// multi-jittered offsets with partners (`t <= q + 1`): each group of
    /// `t` dimensions evaluates its `t` columns once and shares the raw
    /// levels among its members, so the values are those of
    /// [`coordinate_of`](Self::coordinate_of) with a `t`-th of its
    /// evaluations.
    #[inline(always)]
    fn coordinates_by_groups(&self, index: u32, pattern: u32, first: u32, out: &mut [f32]) {
        match self.field.arithmetic() {
            PRIME => self.groups_in::<PRIME>(index, pattern, first, out),
            TABLED => self.groups_in::<TABLED>(index, pattern, first, out),
            BINARY => self.groups_in::<BINARY>(index, pattern, first, out),
            _ => self.groups_in::<DIGITS>(index, pattern, first, out),
        }
    }

    /// [`coordinates_by_groups`](Self::coordinates_by_groups) in a field
    /// whose arithmetic is `A`.
    #[inline(always)]
    fn groups_in<const A: u8>(&self, index: u32, pattern: u32, first: u32, out: &mut [f32]) {
        match self.strength {
            2 => self.coordinates_by_pairs::<A>(index, pattern, first, out),
            3 => self.coordinates_by_groups_at::<3, A>(index, pattern, first, out),
            _ => self.coordinates_by_groups_at::<4, A>(index, pattern, first, out),
        }
    }

    /// [`coordinates_by_groups`](Self::coordinates_by_groups) at strength
    /// 2, written out for its one partner: the pair `2k, 2k + 1` shares
    /// the row's two raw levels and each member takes its sub-stratum
    /// from the other's level. The values are
    /// [`coordinate_of`](Self::coordinate_of)'s (tests/nd_samplers.rs
    /// compares the two for every array size).
    #[inline(always)]
    fn coordinates_by_pairs<const A: u8>(
        &self,
        index: u32,
        pattern: u32,
        first: u32,
        out: &mut [f32],
    ) {
        let q = self.q.get();
        let pattern = &self.prepare(pattern);
        let digits = self.row_digits::<2>(pattern.row_key, index);
        let raw_level = |dimension: u32| {
            // The pair after dimension q - 1 wraps round to dimension 0.
            let dimension = if dimension > q { 0 } else { dimension };
            self.raw_level_at::<2, A>(digits, self.column(pattern, dimension))
        };
        let (mut pair, mut levels) = (u32::MAX, [0; 2]);
        for (dimension, x) in (first..).zip(out.iter_mut()) {
            let base = dimension & !1;
            if base != pair {
                pair = base;
                levels = [raw_level(base), raw_level(base + 1)];
            }
            let k = (dimension & 1) as usize;
            let key = Self::dimension_key(pattern, dimension);
            *x = self.place::<A>(index, key, levels[k], || levels[1 - k]);
        }
    }

    /// [`coordinates_by_groups`](Self::coordinates_by_groups) at strength
    /// `T`, its loops over a group unrolled, in a field whose arithmetic is
    /// `A`.
    #[inline(always)]
    fn coordinates_by_groups_at<const T: usize, const A: u8>(
        &self,
        index: u32,
        pattern: u32,
        first: u32,
        out: &mut [f32],
    ) {
        let (q, t) = (self.q.get(), T as u32);
        let pattern = &self.prepare(pattern);
        let digits = self.row_digits::<T>(pattern.row_key, index);
        let (mut group, mut levels) = (u32::MAX, [0; T]);
        for (dimension, x) in (first..).zip(out.iter_mut()) {
            let base = dimension - dimension % t;
            if base != group {
                group = base;
                for (k, level) in (0..t).zip(levels.iter_mut()) {
                    let column = self.column(pattern, (base + k) % (q + 1));
                    *level = self.raw_level_at::<T, A>(digits, column);
                }
            }
            let k = dimension - base;
            // The partners in `sub_index`'s order: the group's other
            // members, lowest first.
            let sub_index = || {
                (0..t)
                    .filter(|&j| j != k)
                    .fold(0, |index, j| index * q + levels[j as usize])
            };
            let key = Self::dimension_key(pattern, dimension);
            *x = self.place::<A>(index, key, levels[k as usize], sub_index);
        }
    }

    /// Whether [`coordinates_by_groups`](Self::coordinates_by_groups)
    /// serves coordinates `first .. first + len`.
    #[inline(always)]
    fn by_groups(&self, first: u32, len: usize) -> bool {
        self.offset != OrthogonalArrayOffset::Jittered
            && self.strength() <= self.q.get() + 1
            && u64::from(first) + len as u64 <= u64::from(self.dimensions)
    }
}

/// One pattern of an [`OrthogonalArray`] with its per-pattern work done.
struct ArrayPattern {
    hash: u32,
    /// The key of the row order ([`OrthogonalArray::row`]).
    row_key: u32,
    /// The column of dimension 0; dimension `j` takes the `j`-th after it,
    /// cyclically ([`OrthogonalArray::column`]).
    first_column: u32,
}

impl SamplerNd for OrthogonalArray {
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
        let (index, pattern) = (reduce_index(index, self.n), self.prepare(pattern));
        self.coordinate_of(index, self.row(&pattern, index), &pattern, dimension)
    }

    /// The pattern's row order and column choice once for all of `out`,
    /// and each group's raw levels once (see `sample`).
    #[inline(always)]
    fn coordinates(&self, index: u32, pattern: u32, first: u32, out: &mut [f32]) {
        let index = reduce_index(index, self.n);
        if self.by_groups(first, out.len()) {
            self.coordinates_by_groups(index, pattern, first, out);
            return;
        }
        let pattern = self.prepare(pattern);
        let row = self.row(&pattern, index);
        for (dimension, x) in (first..).zip(out.iter_mut()) {
            *x = self.coordinate_of(index, row, &pattern, dimension);
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
    fn exact_roots() {
        assert_eq!(exact_root(4, 2), Some(2));
        assert_eq!(exact_root(5, 2), None);
        assert_eq!(exact_root(4096 * 4096, 2), Some(4096));
        assert_eq!(exact_root(256 * 256 * 256, 3), Some(256));
        assert_eq!(exact_root(255 * 255 * 255 + 1, 3), None);
        assert_eq!(exact_root(64 * 64 * 64 * 64, 4), Some(64));
        assert_eq!(exact_root(u32::MAX, 2), None);
        assert_eq!(exact_root(65_535 * 65_535, 2), Some(65_535));
    }

    #[test]
    fn every_row_of_the_unrandomised_array_is_a_distinct_t_tuple() {
        // The array itself, before any randomisation, at every strength,
        // for a prime, a power of two and an odd prime power: every set of
        // t columns (the evaluations and the leading coefficient) sees
        // every t-tuple of levels exactly once.
        for (n, t) in [
            (25, 2),
            (16, 2),
            (81, 2),
            (27, 3),
            (64, 3),
            (125, 3),
            (81, 4),
            (256, 4),
        ] {
            let array = OrthogonalArray::new(n, 1, t).unwrap();
            let q = array.levels();
            let level = |row: u32, column: u32| array.raw_level(row, column);
            // Every set of t distinct columns, as the increasing t-tuples
            // of 0..=q.
            let t = t as usize;
            for tuple in 0..(q + 1).pow(t as u32) {
                let pick: std::vec::Vec<u32> = (0..t)
                    .map(|i| tuple / (q + 1).pow(i as u32) % (q + 1))
                    .collect();
                if pick.windows(2).any(|w| w[0] >= w[1]) {
                    continue;
                }
                let mut seen = std::vec![false; n as usize];
                for row in 0..n {
                    let cell = pick.iter().fold(0, |cell, &c| cell * q + level(row, c));
                    assert!(!seen[cell as usize], "n {n} t {t} columns {pick:?}");
                    seen[cell as usize] = true;
                }
            }
        }
    }

    #[test]
    fn row_orders_are_bijections_uniform_over_patterns() {
        // Every strength, a prime, a power of two and an odd prime power:
        // each pattern's row order is a bijection of 0..n, and the row of
        // one sample over 2^14 patterns is uniform on 0..n (chi-square
        // with n - 1 degrees of freedom under mean + 6 sd).
        for (n, t) in [(4, 2), (16, 2), (25, 2), (81, 2), (27, 3), (64, 3), (81, 4)] {
            let array = OrthogonalArray::new(n, 2, t).unwrap();
            for pattern in [0, 1, 7, u32::MAX] {
                let pattern = array.prepare(pattern);
                let mut seen = std::vec![false; n as usize];
                for index in 0..n {
                    let row = array.row(&pattern, index);
                    assert!(row < n && !seen[row as usize], "n {n} t {t} row {row}");
                    seen[row as usize] = true;
                }
            }
            for index in [0, n / 2, n - 1] {
                let mut counts = std::vec![0u32; n as usize];
                let patterns = 1u32 << 14;
                for pattern in 0..patterns {
                    counts[array.row(&array.prepare(pattern), index) as usize] += 1;
                }
                let expected = f64::from(patterns) / f64::from(n);
                let chi2: f64 = counts
                    .iter()
                    .map(|&c| (f64::from(c) - expected).powi(2) / expected)
                    .sum();
                let df = f64::from(n - 1);
                let bound = df + 6.0 * (2.0 * df).sqrt();
                assert!(
                    chi2 < bound,
                    "n {n} t {t} index {index}: chi-square {chi2:.1}"
                );
            }
        }
    }

    #[test]
    fn constructor_errors_say_what_to_use() {
        assert_eq!(
            OrthogonalArray::new(16, 2, 1),
            Err(Error::StrengthOutOfRange { strength: 1 })
        );
        assert_eq!(
            OrthogonalArray::new(16, 2, 5),
            Err(Error::StrengthOutOfRange { strength: 5 })
        );
        assert_eq!(OrthogonalArray::new(0, 2, 2), Err(Error::ZeroSamples));
        assert_eq!(
            OrthogonalArray::new(1, 2, 2),
            Err(Error::NotOrthogonalArraySize {
                n: 1,
                strength: 2,
                below: None,
                above: Some(4)
            })
        );
        // 36 = 6^2, and 6 is not a prime power.
        assert_eq!(OrthogonalArray::nearest_sizes(36, 2), (Some(25), Some(49)));
        let message = std::format!("{}", OrthogonalArray::new(36, 2, 2).unwrap_err());
        assert!(message.ends_with("use 25 or 49"), "{message}");
        // Above 2^24: only a count below.
        let message = std::format!("{}", OrthogonalArray::new(u32::MAX, 2, 2).unwrap_err());
        assert!(message.ends_with("use 16777216"), "{message}");
        let (below, above) = OrthogonalArray::nearest_sizes(16_777_217, 3);
        assert_eq!((below, above), (Some(256 * 256 * 256), None));
        assert_eq!(
            OrthogonalArray::nearest_sizes(1 << 24, 4),
            (Some(1 << 24), Some(1 << 24))
        );
        let message = std::format!("{}", OrthogonalArray::new(9, 5, 2).unwrap_err());
        assert!(
            message.starts_with("OrthogonalArray makes 1 to 4 dimensions, got 5"),
            "{message}"
        );
        assert!(OrthogonalArray::new(9, 0, 2).is_err());
    }
}
