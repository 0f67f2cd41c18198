use glam::Vec2;

use crate::Error;
use crate::hash::{Length, Permutation, hash_u32, rand_u32, salt};
use crate::sampler::{Sampler2D, check_fill_len, debug_check_index, most_square_grid};
use crate::samplers::regular::check_grid;

/// One uniformly random point in each cell of a `columns x rows` grid
/// (stratified or "jittered" sampling).
///
/// # Properties
///
/// - Stratified: exactly one point in each cell `[c / columns, (c + 1) /
///   columns) x [r / rows, (r + 1) / rows)`, checked exactly on the f32
///   values.
/// - The x and y projections are not Latin: up to `rows` points can share a
///   column of width `1 / n` (use [`MultiJittered`](crate::MultiJittered) for
///   both guarantees).
/// - Error falls as about `n^-3/4` on discontinuous integrands and `n^-1` on
///   smooth ones, against `n^-1/2` for [`Random`](crate::Random).
///
/// [`Jittered::new`] picks the most square grid with `columns <= rows` and
/// `columns * rows = n`; for a prime `n` that is `1 x n` strips, stratified in
/// y only. [`Jittered::with_grid`] takes any shape.
///
/// # Cost
///
/// One hash, one [`permute`](crate::hash::permute) (expected under two
/// rounds) and two [`rand_u32`] per sample, plus two fixed-point stratum
/// conversions; no division (the sampler stores reciprocals of its lengths).
/// `fill` hashes the pattern once.
///
/// # Limits
///
/// `columns` and `rows` at most 2^24 and `columns * rows` at most `u32::MAX`.
/// Inside a cell the offset is quantised to the `2^-24` grid. In release
/// builds an index at or above `len()` returns a point of the set's grid.
///
/// # Examples
///
/// ```
/// use wellspread::{Jittered, Sampler2D};
/// let jittered = Jittered::new(16)?; // 4 x 4
/// let mut cells = [false; 16];
/// for i in 0..16 {
///     let p = jittered.sample(i, 5);
///     cells[(p.y * 4.0) as usize * 4 + (p.x * 4.0) as usize] = true;
/// }
/// assert!(cells.iter().all(|&hit| hit));
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Cook, Porter & Carpenter 1984, "Distributed ray tracing"; Cook 1986,
/// "Stochastic sampling in computer graphics", ACM TOG 5(1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Jittered {
    // Lengths carry their reciprocals, so no sample needs a division.
    columns: Length,
    rows: Length,
    n: Length,
}

impl Jittered {
    /// `n` jittered points on the most square grid that has `n` cells.
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

    /// Jittered points on a `columns x rows` grid.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroGridSide`] if either side is 0; [`Error::TooManySamples`]
    /// if a side exceeds 2^24 or `columns * rows` exceeds `u32::MAX`.
    pub fn with_grid(columns: u32, rows: u32) -> Result<Self, Error> {
        check_grid("jittered", columns, rows)?;
        Ok(Self {
            columns: Length::new(columns),
            rows: Length::new(rows),
            n: Length::new(columns * rows),
        })
    }

    /// Number of grid columns (strata along x).
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns.get()
    }

    /// Number of grid rows (strata along y).
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows.get()
    }
}

impl Jittered {
    /// Sample `index` given the pattern's hash `seed` and order permutation:
    /// the one formula `sample` and `fill` share. `POW2` promises a
    /// power-of-two `n` (so grid sides too), for a branch-free `fill` loop.
    #[inline(always)]
    fn point<const POW2: bool>(&self, seed: u32, order: &Permutation, index: u32) -> Vec2 {
        let cell = order.apply(index);
        let (row, column) = self.columns.div_rem_in::<POW2>(cell);
        Vec2::new(
            self.columns
                .stratum_to_unit_f32_in::<POW2>(column, rand_u32(cell, seed ^ salt::JITTER_X)),
            self.rows
                .stratum_to_unit_f32_in::<POW2>(row, rand_u32(cell, seed ^ salt::JITTER_Y)),
        )
    }

    fn fill_in<const POW2: bool>(&self, seed: u32, order: &Permutation, out: &mut [Vec2]) {
        for (index, point) in (0..).zip(out.iter_mut()) {
            *point = self.point::<POW2>(seed, order, index);
        }
    }
}

impl Sampler2D for Jittered {
    #[inline]
    fn len(&self) -> u32 {
        self.n.get()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_check_index(index, self.len());
        let seed = hash_u32(pattern);
        self.point::<false>(seed, &self.n.permutation(seed ^ salt::ORDER), index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        // The pattern hash and the permutation's rotation once per set.
        let seed = hash_u32(pattern);
        let order = self.n.permutation(seed ^ salt::ORDER);
        if self.n.is_power_of_two() {
            self.fill_in::<true>(seed, &order, out);
        } else {
            self.fill_in::<false>(seed, &order, out);
        }
    }
}
