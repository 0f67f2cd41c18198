use glam::Vec2;

use crate::Error;
use crate::hash::{hash_u32, permute, rand_u32, salt, stratum_to_unit_f32};
use crate::sampler::{Sampler2D, most_square_grid};
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
/// One hash, one [`permute`] (expected under two rounds) and two
/// [`rand_u32`] per sample, plus two fixed-point stratum conversions.
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
    columns: u32,
    rows: u32,
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
        Ok(Self { columns, rows })
    }

    /// Number of grid columns (strata along x).
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns
    }

    /// Number of grid rows (strata along y).
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows
    }
}

impl Sampler2D for Jittered {
    #[inline]
    fn len(&self) -> u32 {
        self.columns * self.rows
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        debug_assert!(
            index < self.len(),
            "index {index} out of range 0..{}",
            self.len()
        );
        let seed = hash_u32(pattern);
        let cell = permute(index, self.len(), seed ^ salt::ORDER);
        let (column, row) = (cell % self.columns, cell / self.columns);
        Vec2::new(
            stratum_to_unit_f32(column, self.columns, rand_u32(cell, seed ^ salt::JITTER_X)),
            stratum_to_unit_f32(row, self.rows, rand_u32(cell, seed ^ salt::JITTER_Y)),
        )
    }
}
