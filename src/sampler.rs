//! The one trait every sampler implements.

use glam::Vec2;

use crate::simd::Isa;

/// A set of `len()` well-distributed points in `[0, 1)^2`, with random access.
///
/// Sample `index` of pattern `pattern` is a pure function of the two: no
/// state, no tables, no allocation, so any thread rendering any tile gets the
/// same point. `pattern` picks one of 2^32 independent randomisations (one
/// per pixel and dimension pair, see [`pattern_seed`](crate::primitives::pattern_seed)).
///
/// Both coordinates of every point are in `[0, 1)` after f32 rounding, for
/// every index and pattern: the contract every sampler is tested against.
///
/// ```
/// use wellspread::{CorrelatedMultiJittered, Sampler2D};
/// let sampler = CorrelatedMultiJittered::new(16)?;
/// let mut points = [wellspread::glam::Vec2::ZERO; 16];
/// sampler.fill(7, &mut points);
/// assert_eq!(points[3], sampler.sample(3, 7));
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait Sampler2D {
    /// Number of samples in one pattern.
    fn len(&self) -> u32;

    /// Always `false`: constructors reject zero samples. Present because
    /// clippy and readers expect `is_empty` beside `len`.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Sample `index` of pattern `pattern`, in O(1).
    ///
    /// For a fixed-size set, `index` must be below [`len`](Sampler2D::len)
    /// (checked in debug builds); each sampler documents what a release build
    /// returns for a larger index, and it is always a point in `[0, 1)^2`.
    /// The progressive sequences ([`Sobol`](crate::Sobol),
    /// [`Pmj02`](crate::Pmj02), [`Halton`](crate::Halton)) accept every
    /// `u32` index: their `len` is only the set size `fill` and the tools use;
    /// their `unbounded()` constructors take no size, and their `fill_from`
    /// writes any run of indices (progressive rendering).
    fn sample(&self, index: u32, pattern: u32) -> Vec2;

    /// Writes samples `0..out.len()` of pattern `pattern` into `out`: exactly
    /// what [`sample`](Sampler2D::sample) returns for each index, possibly
    /// faster.
    ///
    /// # Panics
    ///
    /// If `out` is longer than [`len`](Sampler2D::len): a set never wraps
    /// around silently.
    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        for (index, point) in (0..).zip(out.iter_mut()) {
            *point = self.sample(index, pattern);
        }
    }
}

/// `fill` on a chosen instruction set: what every sampler's
/// [`Sampler2D::fill`] runs with [`Isa::best`], and what the tests run on
/// every instruction set the CPU has.
pub(crate) trait FillOn {
    /// [`Sampler2D::fill`] on `isa`.
    fn fill_on(&self, isa: Isa, pattern: u32, out: &mut [Vec2]);
}

/// Entries of the stack tables some `fill` overrides build for per-row or
/// per-column work (1 KiB of u32 each): enough for the coarse grid of every
/// n up to 65536, small enough for any stack.
pub(crate) const SMALL_TABLE: usize = 256;

/// `f(0), f(1), ..., f(len - 1)` in a stack table of [`SMALL_TABLE`]
/// entries (`len <= SMALL_TABLE`), for the per-row and per-column work a
/// `fill` hoists out of its loop.
#[inline(always)]
pub(crate) fn small_table(len: u32, f: impl Fn(u32) -> u32) -> [u32; SMALL_TABLE] {
    debug_assert!(len as usize <= SMALL_TABLE);
    let mut table = [0; SMALL_TABLE];
    for (i, entry) in (0..len).zip(table.iter_mut()) {
        *entry = f(i);
    }
    table
}

/// The index check every fixed-size `sample` shares (debug builds only;
/// each sampler documents what a release build does with a bad index).
#[inline(always)]
pub(crate) fn debug_check_index(index: u32, len: u32) {
    debug_assert!(index < len, "index {index} out of range 0..{len}");
}

/// The panic every `fill` shares, so the message is the same everywhere.
#[inline]
pub(crate) fn check_fill_len(requested: usize, len: u32) {
    assert!(
        requested <= len as usize,
        "fill asked for {requested} samples of a set of {len}"
    );
}

/// The panic every `fill_from` shares: indices `start..start + requested`
/// must lie in the sequence's `0..2^32`, which never wraps around.
#[inline]
pub(crate) fn check_fill_from(start: u32, requested: usize) {
    assert!(
        u64::from(start) + requested as u64 <= 1 << 32,
        "fill_from asked for indices {start}..{} past the sequence's last index 4294967295",
        u64::from(start) + requested as u64
    );
}
