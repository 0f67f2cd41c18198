use glam::Vec2;

use crate::Error;
use crate::hash::{Length, MAX_STRATA, Permutation, hash_u32, salt};
use crate::sampler::{Sampler2D, check_fill_len, debug_check_index, most_square_grid};

/// Cell centres of a `columns x rows` grid: the deterministic baseline that
/// aliases.
///
/// # Properties
///
/// - Stratified: exactly one point in each cell of the `columns x rows` grid,
///   at its centre (to within `2^-24`, the f32 grid step below 1.0).
/// - Every pattern gives the same set; the pattern only shuffles the order in
///   which indices visit the cells, so that further dimension pairs padded
///   with other patterns are not correlated with this one.
///
/// [`Regular::new`] picks the most square grid with `columns <= rows` and
/// `columns * rows = n`: `4 x 4` for 16, `4 x 8` for 32, and `1 x n` strips
/// for a prime `n`. [`Regular::with_grid`] takes any shape.
///
/// # Cost
///
/// One hash and one [`permute`](crate::hash::permute) (expected under two
/// rounds) per sample, plus two fixed-point stratum conversions; no division
/// (the sampler stores reciprocals of its lengths). `fill` hashes the pattern
/// once.
///
/// # Limits
///
/// `columns` and `rows` at most 2^24 (f32 cannot separate more strata) and
/// `columns * rows` at most `u32::MAX`. In release builds an index at or above
/// `len()` returns one of the set's points.
///
/// # Examples
///
/// ```
/// use wellspread::{Regular, Sampler2D};
/// let regular = Regular::new(4)?; // 2 x 2
/// let mut xs: Vec<f32> = (0..4).map(|i| regular.sample(i, 9).x).collect();
/// xs.sort_by(f32::total_cmp);
/// assert_eq!(xs, [0.25, 0.25, 0.75, 0.75]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Mitchell 1987, "Generating antialiased images at low sampling densities"
/// (why regular grids alias); Shirley 1991 uses it as the baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Regular {
    // Lengths carry their reciprocals, so no sample needs a division.
    columns: Length,
    rows: Length,
    n: Length,
}

impl Regular {
    /// A grid of `n` cells, the most square factorisation of `n`.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] when the
    /// grid would have more than 2^24 rows (a prime above 2^24, or twice one).
    pub fn new(n: u32) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroSamples);
        }
        let (columns, rows) = most_square_grid(n);
        Self::with_grid(columns, rows)
    }

    /// A `columns x rows` grid.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroGridSide`] if either side is 0; [`Error::TooManySamples`]
    /// if a side exceeds 2^24 or `columns * rows` exceeds `u32::MAX`.
    pub fn with_grid(columns: u32, rows: u32) -> Result<Self, Error> {
        check_grid("regular", columns, rows)?;
        Ok(Self {
            columns: Length::new(columns),
            rows: Length::new(rows),
            n: Length::new(columns * rows),
        })
    }

    /// Number of grid columns (cells along x).
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns.get()
    }

    /// Number of grid rows (cells along y).
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows.get()
    }
}

/// Validation shared by the grid-shaped samplers (regular, jittered).
pub(crate) fn check_grid(sampler: &'static str, columns: u32, rows: u32) -> Result<(), Error> {
    if columns == 0 || rows == 0 {
        return Err(Error::ZeroGridSide { columns, rows });
    }
    let cells = columns as u64 * rows as u64;
    if columns > MAX_STRATA || rows > MAX_STRATA {
        return Err(Error::TooManySamples {
            sampler,
            requested: cells,
            max: u32::MAX as u64,
            reason: "its grid would have a side above 2^24 cells, which f32 coordinates cannot tell apart (the most square grid of a prime n is 1 x n); pick an n with a divisor near its square root",
        });
    }
    if cells > u32::MAX as u64 {
        return Err(Error::TooManySamples {
            sampler,
            requested: cells,
            max: u32::MAX as u64,
            reason: "sample indices are u32",
        });
    }
    Ok(())
}

impl Regular {
    /// Sample `index` given the pattern's order permutation: the one formula
    /// `sample` and `fill` share. `POW2` promises a power-of-two `n` (so
    /// grid sides too), for a branch-free `fill` loop.
    #[inline(always)]
    fn point<const POW2: bool>(&self, order: &Permutation, index: u32) -> Vec2 {
        let cell = order.apply(index);
        let (row, column) = self.columns.div_rem_in::<POW2>(cell);
        // Half-way bits put the point at the cell's centre, to within 2^-24.
        Vec2::new(
            self.columns.stratum_to_unit_f32_in::<POW2>(column, 1 << 31),
            self.rows.stratum_to_unit_f32_in::<POW2>(row, 1 << 31),
        )
    }
}

impl Sampler2D for Regular {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        self.point::<false>(&self.n.permutation(hash_u32(pattern) ^ salt::ORDER), index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        // The permutation (its pattern hash and rotation) once per set.
        let order = self.n.permutation(hash_u32(pattern) ^ salt::ORDER);
        if self.n.is_power_of_two() {
            for (index, point) in (0..).zip(out.iter_mut()) {
                *point = self.point::<true>(&order, index);
            }
        } else {
            for (index, point) in (0..).zip(out.iter_mut()) {
                *point = self.point::<false>(&order, index);
            }
        }
    }
}
