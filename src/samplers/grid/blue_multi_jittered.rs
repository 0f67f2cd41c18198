use glam::Vec2;

use super::{CellOffset, Grid, GridPattern, Jitter, fill_grid};
use crate::primitives::{InvariantDivisor, MAX_STRATA, Permutation, derived_key, hash_u32};
use crate::traits::{DomainSampler, Sampler2D};
use crate::{Error, SamplerKind};

mod lattice_search;

use lattice_search::Shape;

/// Multi-jittered sampling with a guaranteed minimum distance: correlated
/// multi-jitter whose two shared shuffles are replaced by affine maps
/// coupled across the grid, chosen per `n` so that no two points come
/// close, and randomised per pattern by the symmetries that keep every
/// distance.
///
/// Cell `(row i, column j)` of the `columns x rows` grid (`c x r`, the most
/// square factorisation, `c <= r`) holds the point of fine column
/// `j r + ((g i + q j + s) mod r)` and fine row `i c + ((h j + p i + t) mod
/// c)`, jittered inside that fine cell. The constructor picks `g`, `q`, `h`,
/// `p` once per `n` (see below); a pattern picks the offsets `s`, `t`, a
/// translation by whole coarse cells, a mirror image in x and in y, a
/// transposition (square grids), the order of the cells and the jitter.
/// `g` near `r / phi^2` and `h` near `c / phi` make each column's sequence of
/// sub-columns a golden-ratio lattice rather than Kensler's random shuffle,
/// and the coupling `q = -r / gcd(c, r)`, `p = -c / gcd(c, r)` (taken first
/// when it keeps the bound) shifts that sequence from one column to the next,
/// which cancels most of the error correlated multi-jitter makes on smooth
/// integrands.
///
/// # Properties
///
/// - Stratified: exactly one point in each cell of the `columns x rows`
///   grid. Latin: exactly one point in each of the `n` columns and `n` rows
///   of the fine grid. Both hold for every pattern because `g` is coprime to
///   `r` and `h` to `c` (each column's sub-columns and each row's sub-rows
///   are a permutation), checked exactly on the f32 values.
/// - A toroidal minimum distance of at least
///   [`min_distance_bound`](Self::min_distance_bound) for every pattern.
///   Proof: two points in cells `k` rows and `l` columns apart differ by
///   `l r + a` fine columns and `k c + b` fine rows, where `a` is `A = (g k +
///   q l) mod r` or `A - r` and `b` is `B = (h l + p k) mod c` or `B - c`,
///   whatever `s`, `t` and the cells are (the mod is affine). The pattern's
///   mirror images, translations and transposition are isometries of the
///   torus, and the jitter moves each coordinate by less than the slack `S`
///   (one fine cell at full jitter, less when it is narrowed). So every pair
///   is at least `sqrt(max(0, |l r + a|_n - S)^2 + max(0, |k c + b|_n - S)^2)
///   / n` apart, `|.|_n` the distance to the nearest multiple of `n`. The
///   bound is the minimum of that over every `(k, l, a, b)`; the
///   enumeration stops at `|k| > (U + S - 1) / c + 1` (likewise `l`), `U` the
///   minimum over the cells within `1.2 sqrt(n)` fine cells, since farther
///   pairs are more than `U` apart in y (or x) alone.
/// - The constructor walks the `(g, q, h, p)` in the order above and keeps
///   those whose bound divided by `sqrt(2 / (sqrt(3) n))` (the
///   hexagonal-packing distance, as
///   [`normalized_toroidal_min_distance`](crate::metrics::normalized_toroidal_min_distance))
///   is at least 0.6 with the jitter narrowed to a quarter of a fine cell.
///   Of those it takes the first that passes a diagonal test: a lattice
///   with short vectors near `(1, 1)` or `(1, -1)` puts whole rows of points
///   on one side of an edge along `y = x` together, and the mirror images
///   turn the anti-diagonal into the diagonal. The test is
///   exact counting: the mean squared error, in points, of the unjittered
///   set on the half-plane `y < x` (only the cells the diagonal crosses can
///   err; a point on the diagonal counts half, plus the variance of its
///   jitter), over 16 fixed offsets `s`, `t` and the four mirror images,
///   must be at most half that of independent uniform points in the same
///   cells. If no coupled lattice (`q` and `p` from the first four
///   multipliers; on coprime sides all of them give `q = p = 0`) passes, it
///   takes the scored one with the least error (scores stop when their
///   budget, see Cost, is spent); the uncoupled ones (`k = 0` on one side)
///   come only when no coupled lattice keeps the bound. Then it widens the
///   jitter (in sixteenths, up to the whole fine cell) as far as the bound
///   allows. The test changes only which lattice is taken, so the bound and
///   its proof are as above. For every `n` from 16 to 4096 but 24 the
///   normalised bound is at least 0.6 (tested); measured minima and the
///   integration errors are in `docs/quality.md`.
/// - Where no lattice in that order reaches 0.6 at a quarter cell (some `n`
///   below 16, and n = 24), the constructor takes the largest bound with the
///   jitter at 1/16 of a fine cell, over every lattice for `n <= 256` (over
///   the ordered ones above that), and widens the jitter as far as 0.6
///   allows. The bound stays proved, but falls short of 0.6: 0.586 at n =
///   24, the only such n from 16 to 4096 (no lattice of this form does
///   better on a 4 x 6 grid with any jitter at all; unjittered points would
///   reach 0.60, but then patterns could repeat whole sets).
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

/// Salts for the per-pattern choices, in the style of the crate's salts: odd, about
/// half their bits set, distinct top five bits (the rotation
/// [`derived_key`] applies).
mod choice {
    pub(super) const OFFSET_X: u32 = 0x2f6b_4a93;
    pub(super) const OFFSET_Y: u32 = 0x4c1d_e357;
    pub(super) const SHIFT_X: u32 = 0x6a3c_95e1;
    pub(super) const SHIFT_Y: u32 = 0x8e57_1ab3;
    pub(super) const FLAGS: u32 = 0xb4d2_6c8f;
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
    /// `sqrt(2 / (sqrt(3) n))` for the normalised form. The proof is in the
    /// type's docs; computed by one enumeration (see Cost), rounded down.
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
        let flags = derived_key(pattern_hash, choice::FLAGS);
        BlueMultiJitteredPattern {
            grid,
            lattice: self.lattice,
            order: grid.cell_order(pattern_hash),
            offset_x: pick(choice::OFFSET_X, rows),
            offset_y: pick(choice::OFFSET_Y, columns),
            shift_x: pick(choice::SHIFT_X, columns),
            shift_y: pick(choice::SHIFT_Y, rows),
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
