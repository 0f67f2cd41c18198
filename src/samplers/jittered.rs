use glam::Vec2;

use crate::primitives::{Permutation, derived_key, hash_u32, salt};
use crate::sampler::Sampler2D;
use crate::samplers::grid::{Grid, GridPattern, Jitter};
use crate::{Error, SamplerKind};

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
/// Per sample: one permutation of the cells (a nibble lookup for n <= 8, else
/// four or five rounds of about eight integer operations), two
/// [`rand_u32`](crate::primitives::rand_u32) for the jitter, two fixed-point
/// stratum conversions; no division. `sample` adds one hash of the pattern and
/// one 5-operation key derivation. `fill` runs the same formula on 8 or 16 lanes at once (AVX2 or AVX-512,
/// detected at run time), bit for bit equal to `sample`; measured ratios to a
/// `rand_pcg::Pcg32` fill are in `docs/performance.md`.
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
    grid: Grid,
}

grid_constructors!(cells Jittered, Jittered, "jittered points");

grid_sampler!(Jittered, fill_on);

impl Jittered {
    #[inline(always)]
    fn pattern(&self, pattern: u32) -> JitteredPattern<'_> {
        let seed = hash_u32(pattern);
        JitteredPattern {
            grid: &self.grid,
            order: Permutation::new(self.len(), derived_key(seed, salt::ORDER)),
            jitter: Jitter::new(seed),
        }
    }
}

/// One pattern of [`Jittered`]: the order of the cells and the jitter.
struct JitteredPattern<'a> {
    grid: &'a Grid,
    order: Permutation,
    jitter: Jitter,
}

impl GridPattern for JitteredPattern<'_> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let mut out = [Vec2::ZERO; N];
        for (point, cell) in out.iter_mut().zip(self.order.apply_lanes(index)) {
            *point = self.grid.cell_point::<POW2>(cell, self.jitter.bits(cell));
        }
        out
    }
}
