use glam::Vec2;

use super::{CellOffset, Grid, GridPattern, Jitter, fill_grid};
use crate::error::Error;
use crate::primitives::{InvariantDivisor, MAX_STRATA, Permutation, derived_key, hash_u32, salt};
use crate::samplers::SamplerKind;
use crate::traits::{DomainSampler, Sampler2D};

mod lattice_search;

use lattice_search::Shape;

/// Multi-jittered sampling with a guaranteed minimum distance: correlated
/// multi-jitter whose two shared shuffles are replaced by affine maps
/// coupled across the grid, chosen per `n` so that no two points come
/// close, and randomised per pattern by the symmetries that keep every
/// distance.
///
/// Cell `(row i, column j)` of the most square `c x r` grid holds the point
/// of fine column `j r + ((g i + q j + s) mod r)` and fine row `i c + ((h j
/// + p i + t) mod c)`, jittered inside that fine cell: `g`, `q`, `h`, `p`
/// are chosen once per `n`, the offsets, mirror images, translations, cell
/// order and jitter per pattern. The construction, the order in which the
/// constructor tries lattices, its diagonal test and the proof of the
/// bound are in `docs/blue_multi_jittered.md`.
///
/// # Properties
///
/// - Stratified: exactly one point in each cell of the `columns x rows`
///   grid. Latin: exactly one point in each of the `n` columns and `n` rows
///   of the fine grid. Both hold for every pattern, checked exactly on the
///   f32 values.
/// - A toroidal minimum distance of at least
///   [`min_distance_bound`](Self::min_distance_bound) for every pattern
///   (proved by an exhaustive enumeration over cell offsets; see
///   `docs/blue_multi_jittered.md`).
/// - That bound is at least 0.6 of the hexagonal-packing distance
///   `sqrt(2 / (sqrt(3) n))` (as
///   [`normalized_toroidal_min_distance`](crate::metrics::normalized_toroidal_min_distance)
///   measures it) for every `n` from 16 to 4096 but 24, where it is 0.586
///   (tested); below 16 it is the largest bound this lattice form reaches.
/// - Its integration error stays within 1.1x multi-jitter's on smooth
///   integrands (the constructor passes over lattices that line points up
///   with a diagonal); measured minima and errors are in
///   `docs/quality.md`.
///
/// # Cost
///
/// `sample`: one hash of the pattern, seven 5-operation key derivations and
/// the permutation of the cells (as [`CorrelatedMultiJittered`]), then per
/// point two multiply-adds reduced modulo `r` and `c` by multiply-high
/// division (where CMJ evaluates two hashed permutations), two
/// [`rand_u32`](crate::primitives::rand_u32) and two fixed-point stratum
/// conversions; no table. `fill` runs the same formula on 8 or 16 lanes at
/// once (AVX2 or AVX-512, detected at run time), bit for bit equal to
/// `sample`. The constructor tries at most 1600 lattices in order (every
/// one of at most 16,384 for a small `n` that needs the fallback), each by
/// an enumeration of `O(sqrt(n) / c + sqrt(n) / r)` pairs of cells (a few
/// million operations for a prime near 2^24, a few thousand at n = 256),
/// and scores those that keep the bound on the diagonal, `64 (c + r)` cell
/// visits each, until 2^20 visits are spent (after that, or when one score
/// alone would exceed that, as for a prime above 16,383, it takes the best
/// scored lattice, or the first that keeps the bound if none was scored);
/// [`min_distance_bound`](Self::min_distance_bound) repeats one
/// enumeration.
///
/// [`CorrelatedMultiJittered`]: crate::CorrelatedMultiJittered
///
/// # Limits
///
/// `n` at most 2^24 ([`BlueMultiJittered::MAX_SAMPLES`]), the number of f32
/// strata in `[0, 1)`. The set is a lattice-like structure: few distinct
/// sets per `n` up to the jitter (the offsets, translations and mirror
/// images give at most `8 n^2` of them), so its power spectrum keeps peaks,
/// like CMJ's. In release builds an index at or above `len()` returns one of
/// the set's points.
///
/// # Examples
///
/// ```
/// use wellspread::{BlueMultiJittered, Sampler2D, glam::Vec2, metrics};
/// let bmj = BlueMultiJittered::new(256)?; // 16 x 16 coarse
/// let mut points = vec![Vec2::ZERO; 256];
/// bmj.fill(3, &mut points);
/// let mut fine_columns = [0; 256];
/// for p in &points {
///     fine_columns[(p.x * 256.0) as usize] += 1;
/// }
/// assert_eq!(fine_columns, [1; 256]);
/// let d = metrics::toroidal_min_distance(&points)?;
/// assert!(d >= bmj.min_distance_bound());
/// assert!(bmj.min_distance_bound() / (2.0 / (3.0f64.sqrt() * 256.0)).sqrt() >= 0.6);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Kensler 2013, "Correlated Multi-Jittered Sampling", Pixar Technical Memo
/// 13-01 (the shared-shuffle structure). Roberts 2020, "A new method to
/// construct isotropic blue-noise sample point sets with uniform
/// projections" (extremelearning.com.au: replacing CMJ's random shuffles by
/// structured ones bounds the nearest-neighbour distance). Lagae & Dutré
/// 2008 for the normalisation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BlueMultiJittered {
    grid: Grid,
    lattice: Lattice,
    /// Width of the jitter window in sixteenths of a fine cell, 1 to 16.
    jitter: u32,
}

/// The four integers of the point formula (see [`BlueMultiJittered`]):
/// sub-column `(g i + q j + s) mod r`, sub-row `(h j + p i + t) mod c`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Lattice {
    g: u32,
    q: u32,
    h: u32,
    p: u32,
}

impl Lattice {
    /// `(g, q, h, p)` as signed integers, for the search's arithmetic.
    fn signed(&self) -> (i64, i64, i64, i64) {
        (
            i64::from(self.g),
            i64::from(self.q),
            i64::from(self.h),
            i64::from(self.p),
        )
    }
}

impl BlueMultiJittered {
    /// The largest `n` accepted: 2^24, the number of distinct f32 strata.
    pub const MAX_SAMPLES: u32 = MAX_STRATA;

    /// A blue multi-jittered set of `n` points on the most square
    /// `columns x rows` grid.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`; [`Error::TooManySamples`] above
    /// [`BlueMultiJittered::MAX_SAMPLES`].
    pub fn new(n: u32) -> Result<Self, Error> {
        let grid = Grid::latin(SamplerKind::BlueMultiJittered, n)?;
        let shape = Shape::of(&grid);
        let (lattice, jitter) = shape.choose();
        Ok(Self {
            grid,
            lattice,
            jitter,
        })
    }

    /// Number of coarse grid columns (strata along x).
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.grid.columns()
    }

    /// Number of coarse grid rows (strata along y).
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.grid.rows()
    }

    /// A lower bound on the toroidal minimum distance of every pattern's
    /// set (as [`toroidal_min_distance`](crate::metrics::toroidal_min_distance)
    /// measures it on the f32 values), in units of the unit square;
    /// `f64::INFINITY` for `n = 1`, which has no pairs. Divide by
    /// `sqrt(2 / (sqrt(3) n))` for the normalised form. The proof is in
    /// `docs/blue_multi_jittered.md`; computed by one enumeration (see Cost), rounded down.
    #[must_use]
    pub fn min_distance_bound(&self) -> f64 {
        let shape = Shape::of(&self.grid);
        let n = f64::from(self.grid.len());
        let fine = libm::sqrt(shape.bound_squared(&self.lattice, shape.slack(self.jitter)));
        // The metric's f64 rounding and this one's: far below a 2^-24 step.
        fine / n * (1.0 - 1e-12)
    }

    /// The pattern with its per-pattern choices made.
    #[inline(always)]
    fn prepare(&self, pattern: u32) -> BlueMultiJitteredPattern<'_> {
        let pattern_hash = hash_u32(pattern);
        let grid = &self.grid;
        let (columns, rows) = (grid.columns(), grid.rows());
        let pick = |salt: u32, len: u32| {
            ((derived_key(pattern_hash, salt) as u64 * len as u64) >> 32) as u32
        };
        let flags = derived_key(pattern_hash, salt::LATTICE_FLAGS);
        BlueMultiJitteredPattern {
            grid,
            lattice: self.lattice,
            order: grid.cell_order(pattern_hash),
            offset_x: pick(salt::LATTICE_OFFSET_X, rows),
            offset_y: pick(salt::LATTICE_OFFSET_Y, columns),
            shift_x: pick(salt::LATTICE_SHIFT_X, columns),
            shift_y: pick(salt::LATTICE_SHIFT_Y, rows),
            // The top bits: derived keys are weakest in their low bits.
            mirror_x: flags >> 31 == 1,
            mirror_y: (flags >> 30) & 1 == 1,
            transpose: columns == rows && (flags >> 29) & 1 == 1,
            jitter: Jitter::new(pattern_hash),
            width: self.jitter,
        }
    }
}

impl Sampler2D for BlueMultiJittered {
    #[inline]
    fn len(&self) -> u32 {
        self.grid.len()
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        self.prepare(pattern).point(index)
    }

    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        fill_grid(&self.prepare(pattern), out);
    }
}

/// A domain's draws: 2D the sampler's own set, 1D stratified, 3D and 4D
/// padded ([`DomainSampler`]'s defaults).
impl DomainSampler for BlueMultiJittered {}

/// One pattern of [`BlueMultiJittered`]: the lattice, the pattern's offsets
/// `s` (`offset_x`, in `[0, r)`) and `t` (`offset_y`, in `[0, c)`), its
/// translation by whole coarse columns and rows, its mirror images and
/// transposition, the order of the cells, and the jitter.
struct BlueMultiJitteredPattern<'a> {
    grid: &'a Grid,
    lattice: Lattice,
    order: Permutation,
    offset_x: u32,
    offset_y: u32,
    shift_x: u32,
    shift_y: u32,
    mirror_x: bool,
    mirror_y: bool,
    transpose: bool,
    jitter: Jitter,
    width: u32,
}

/// `x mod d` for `x < 2^49`.
#[inline(always)]
fn rem(d: InvariantDivisor, x: u64) -> u32 {
    (x - d.div(x) * d.get() as u64) as u32
}

/// `(a + b) mod m` for `a, b < m`.
#[inline(always)]
const fn add_mod(a: u32, b: u32, m: u32) -> u32 {
    let sum = a + b;
    if sum >= m { sum - m } else { sum }
}

/// Random bits narrowed to the centred window of `width` sixteenths of
/// `[0, 2^32)`: `(16 - width) 2^27 + (bits >> 4) width`, below `2^32`.
#[inline(always)]
const fn narrow(bits: u32, width: u32) -> u32 {
    ((16 - width) << 27) + (bits >> 4) * width
}

impl GridPattern for BlueMultiJitteredPattern<'_> {
    fn grid(&self) -> &Grid {
        self.grid
    }

    #[inline(always)]
    fn points<const POW2: bool, const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let cell = self.order.apply_lanes(index);
        let (row, column) = self.grid.cells::<POW2, N>(cell);
        let (columns, rows) = (self.grid.columns(), self.grid.rows());
        let n = self.grid.len();
        let Lattice { g, q, h, p } = self.lattice;
        let mut out = [Vec2::ZERO; N];
        for (lane, point) in out.iter_mut().enumerate() {
            let (i, j) = (row[lane], column[lane]);
            // g, q, s < r and i < r, j < c <= r: below 2^49 for r <= 2^24.
            let sub_column = rem(
                self.grid.rows,
                g as u64 * i as u64 + q as u64 * j as u64 + self.offset_x as u64,
            );
            let sub_row = rem(
                self.grid.columns,
                h as u64 * j as u64 + p as u64 * i as u64 + self.offset_y as u64,
            );
            let mut x = add_mod(j, self.shift_x, columns) * rows + sub_column;
            let mut y = add_mod(i, self.shift_y, rows) * columns + sub_row;
            if self.mirror_x {
                x = n - 1 - x;
            }
            if self.mirror_y {
                y = n - 1 - y;
            }
            if self.transpose {
                (x, y) = (y, x);
            }
            let (x_bits, y_bits) = self.jitter.bits(cell[lane]);
            *point = Vec2::new(
                self.grid
                    .n
                    .stratum_to_unit_f32_in::<POW2>(x, narrow(x_bits, self.width)),
                self.grid
                    .n
                    .stratum_to_unit_f32_in::<POW2>(y, narrow(y_bits, self.width)),
            );
        }
        out
    }
}
