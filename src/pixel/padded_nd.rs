//! Any [`SamplerNd`] as a pixel sampler: a domain's draws take
//! consecutive dimensions of one set.

use glam::{Vec2, Vec3, Vec4};

use super::padded::packed_root;
use super::{Draw, PixelSampler, PixelSamplerHooks, Root};
use crate::primitives::{child_key, hash_combine, locate_pass, salt};
use crate::traits::SamplerNd;

/// Any [`SamplerNd`] ([`OrthogonalArray`](crate::OrthogonalArray),
/// [`LatinHypercube`](crate::LatinHypercube), [`Faure4D`](crate::Faure4D))
/// as a [`PixelSampler`]: the
/// draws of a [`Domain`](crate::Domain) take consecutive dimensions of one
/// set per pixel (draw `k` of width `w` takes the next `w`), so the
/// guarantees that tie dimensions together hold across draws: with an
/// orthogonal array of strength 2, the film from one `next_2d` and the
/// lens from the next are stratified jointly in every pair of their four
/// dimensions.
///
/// # Properties
///
/// - A domain's values are read in pages of `D = dimensions()` dimensions:
///   dimensions `p D .. (p + 1) D` of the domain are one pattern of the
///   set, keyed by the domain's key and `p`. Over a pixel's `len()`
///   samples each page is one set, with all its guarantees.
/// - A draw that would cross the end of a page takes a fresh pattern of
///   its own instead (its first `w` dimensions, keyed by the draw's
///   stream): padding, as in [`Padded`](crate::Padded). The next draw
///   goes on in the next page.
/// - Keyed children ([`branch`](crate::Domain::branch),
///   [`split`](crate::Domain::split)) start at dimension 0 of their own
///   pattern, unrelated to their parent's.
/// - Different pixels and frames get unrelated patterns.
///
/// # Cost
///
/// `start` as [`Padded`](crate::Padded)'s (no hash). A draw of width `w`:
/// one [`mix64`](crate::primitives::mix64) for the page's pattern and one
/// call of [`SamplerNd::coordinates`] for its `w` dimensions, which does
/// the set's per-pattern work once (for an orthogonal array the row order,
/// then per coordinate two affine maps of GF(q) and the row's polynomial).
/// A draw that pads pays [`SamplerNd::coordinate`] per dimension. Measured
/// against the other pixel samplers in `docs/performance.md`.
///
/// # Limits
///
/// Every `[u32; 2]` is a pixel. For a fixed-size set an index at or
/// beyond `len()` is pass `index / len()`, an independent set (the
/// fixed-size rule of [`PixelSampler`]); a progressive sequence
/// ([`SamplerNd::is_progressive`]) goes on along the sequence. [`sample_pixel`](PixelSampler::sample_pixel)`(_, _,
/// pair)` is the `pair`-th `next_2d` after `pair` calls of `next_2d` (it
/// reads dimensions `2 pair`, `2 pair + 1`): a domain that mixed widths
/// reads other dimensions.
///
/// # Examples
///
/// ```
/// use wellspread::{OrthogonalArray, PaddedNd, PixelSampler};
/// // 16 samples, strength 2: all 5 dimensions pairwise stratified.
/// let pixels = PaddedNd::new(OrthogonalArray::new(16, 5, 2)?, 0);
/// let mut cells = [[0; 4]; 4];
/// for index in 0..16 {
///     let mut d = pixels.start([3, 4], index);
///     let film = d.next_2d();
///     let lens = d.next_2d();
///     // Film x and lens y, from two draws, share one 4 x 4 grid.
///     cells[(film.x * 4.0) as usize][(lens.y * 4.0) as usize] += 1;
/// }
/// assert_eq!(cells, [[1; 4]; 4]);
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PaddedNd<S> {
    sampler: S,
    frame: u32,
    /// How many passes of the set `samples_per_pixel` counts (1 from
    /// `new`).
    passes: u32,
}

impl<S: SamplerNd> PaddedNd<S> {
    /// `sampler` for every pixel; `frame` (a frame number, say) picks one
    /// of 2^32 unrelated sets of patterns.
    #[inline]
    pub const fn new(sampler: S, frame: u32) -> Self {
        Self {
            sampler,
            frame,
            passes: 1,
        }
    }

    /// The same pixel sampler counting `passes` passes of its set as its
    /// samples per pixel: what `PixelSamplerKind::Orthogonal` builds for
    /// a count `lambda q^2`. The draws are unchanged (an index past the
    /// set is always a further pass, keyed independently); only
    /// `samples_per_pixel` reads it. `passes` times the set's length must
    /// fit in a u32.
    #[inline]
    pub(crate) fn with_passes(self, passes: u32) -> Self {
        Self { passes, ..self }
    }

    /// The wrapped sampler.
    #[inline]
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The frame it was built with.
    #[inline]
    pub const fn frame(&self) -> u32 {
        self.frame
    }

    /// The `W` values of `draw`: the page's dimensions when the draw fits
    /// in what is left of its page, else a fresh pattern of its own. Not
    /// inlined: its `W` coordinates cost far more than a call, and inlined
    /// into [`AnyPixelSampler`](crate::AnyPixelSampler)'s dispatch they
    /// would make every other sampler's draws through it slower.
    #[inline(never)]
    fn values<const W: usize>(&self, draw: Draw) -> [f32; W] {
        let page_len = self.sampler.dimensions();
        let (page, first) = (draw.dimension / page_len, draw.dimension % page_len);
        let mut out = [0.0; W];
        if first as usize + W <= page_len as usize {
            let pattern = child_key(draw.key, salt::PAGE, page) as u32;
            self.sampler
                .coordinates(draw.index, pattern, first, &mut out);
        } else {
            // A set of fewer than `W` dimensions pads across patterns.
            for (j, x) in (0..).zip(&mut out) {
                let pattern = hash_combine(draw.stream as u32, j / page_len);
                *x = self.sampler.coordinate(draw.index, pattern, j % page_len);
            }
        }
        out
    }
}

impl<S: SamplerNd + Send + Sync> PixelSampler for PaddedNd<S> {
    /// `None` for a progressive sequence built with no set size
    /// ([`SamplerNd::is_progressive`], `len() == u32::MAX`); otherwise the
    /// set's `len()` times the passes counted.
    #[inline]
    fn samples_per_pixel(&self) -> Option<u32> {
        let n = self.sampler.len();
        if self.sampler.is_progressive() && n == u32::MAX {
            None
        } else {
            Some(n.wrapping_mul(self.passes))
        }
    }
}

impl<S: SamplerNd + Send + Sync> PixelSamplerHooks for PaddedNd<S> {
    /// [`Padded`](crate::Padded)'s root: the pixel packed into the key,
    /// xored with a multiple of the frame.
    #[inline(always)]
    fn root(&self, pixel: [u32; 2]) -> Root {
        packed_root(pixel, self.frame)
    }

    /// A fixed-size set's passes; a progressive sequence continues.
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        if self.sampler.is_progressive() {
            (index, key)
        } else {
            locate_pass(index, self.sampler.len(), key)
        }
    }

    #[inline]
    fn draw_1d(&self, draw: Draw) -> f32 {
        let [x] = self.values(draw);
        x
    }

    #[inline]
    fn draw_2d(&self, draw: Draw) -> Vec2 {
        Vec2::from_array(self.values(draw))
    }

    #[inline]
    fn draw_3d(&self, draw: Draw) -> Vec3 {
        Vec3::from_array(self.values(draw))
    }

    #[inline]
    fn draw_4d(&self, draw: Draw) -> Vec4 {
        Vec4::from_array(self.values(draw))
    }
}
