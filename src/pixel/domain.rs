//! The per-sample state a renderer passes down its call tree.

use glam::{Vec2, Vec3, Vec4};

#[cfg(doc)]
use super::PixelSamplerHooks;
use super::{Draw, PixelSampler};
use crate::primitives::{child_key, salt};

/// One pixel sample's dimensions: the sampler (`S`, a reference or a
/// value), the sample index, a 64-bit key, a draw counter and the
/// sampler's pixel state. [`PixelSampler::start`] makes the borrowed form,
/// `Domain<&S>`, 32 bytes for every sampler: what a renderer passes down
/// its call tree. [`Domain::start`] by value makes the owned form
/// (`Copy + Send + Sync + 'static` when the sampler is), for a domain
/// that must outlive a borrow. Both give the same values.
///
/// A routine that draws takes `&mut Domain<&AnyPixelSampler>` (a renderer
/// that picks its sampler at run time), `&mut Domain<&Padded<Sobol>>` (one
/// sampler, statically), or is generic: `fn f<S: PixelSampler + Copy>(d:
/// &mut Domain<S>)` takes every form (`Copy` for `branch` and `split`).
///
/// # Model
///
/// A domain is a node of a tree (as in OpenQMC's domains). Each node has
/// a 64-bit key; [`branch`](Self::branch) and [`split`](Self::split) derive
/// children from the key alone, and the draws `next_1d` ... `next_4d` read
/// the node's draws 0, 1, 2, ... one per call, whatever their width. The
/// domain also counts the values its draws returned, for
/// [`PaddedNd`](crate::PaddedNd), whose draws take consecutive dimensions
/// of one set.
///
/// # Properties
///
/// - Draw `k` of a domain uses the pattern picked by `stream =
///   mix64(key + k W)`, the same for every sample index of the pixel: over
///   a pixel's samples each draw is one set of the sampler, with its
///   guarantees (see [`DomainSampler`](crate::implement::DomainSampler) for what each
///   width gives).
/// - **Independent draws.** Draws from different keys (`branch(k1)` and
///   `branch(k2)`, a branch and its parent's own draws, `split` children
///   and their siblings) and successive draws of one domain pair their
///   samples like independently shuffled stratified sets: measured per
///   pixel over its samples and tested for every pixel sampler
///   (`tests/pixel/independence.rs`). A progressive sequence keeps every
///   power-of-two prefix a net, which limits how freely two draws can pair
///   (about 1.1x the correlation of independent sets at 4 and 16 samples,
///   1.06x at 64: see [`prefix_shuffle`](crate::primitives::prefix_shuffle)).
/// - `d.branch(k)` depends only on `d`'s key, pixel state and index, never
///   on how many draws `d` made.
/// - `d.split(key, count, j)` is sample `index * count + j` of the child
///   keyed `key`: over `j < count` and the pixel's `n` sample indices, the
///   `n count` children are samples `0 .. n count` of one pattern. For the
///   sequences that is one (0,m,2)-net whenever `n count` is a power of
///   two; for fixed-size samplers it is `count` complete sets (passes, see
///   [`PixelSampler`]'s edges), each with its guarantees.
///
/// # Which draw for what
///
/// - **One key per purpose** (`branch(LIGHT)`, `branch(BOUNCE).branch(b)`)
///   when code that draws does not know what was drawn before it: a
///   light's sampling routine, a material's, bounce `b` of a path of any
///   depth. **Call order** (successive `next_*` of one domain) inside one
///   routine that always draws the same sequence. For every padded kind
///   both give independent draws and the same error (keys make the layout
///   robust to code changes); keys are needed wherever the number of
///   values drawn before varies (roulette, a material's lobe count).
/// - **Call order pays with a jointly stratified kind**: for `faure`
///   ([`PaddedNd`](crate::PaddedNd) over [`Faure4D`](crate::Faure4D)) and
///   `orthogonal` (over an [`OrthogonalArray`](crate::OrthogonalArray))
///   successive draws of one domain take consecutive dimensions of one
///   set, stratified pairwise, so a bounce's draws that feed one estimate
///   (film and lens, a light choice and a light point) are stratified
///   together: `faure` four dimensions a page at any count, progressively,
///   at about 1.5x a sequence draw; `orthogonal` `q + 1` a page at counts
///   `lambda q^2`, at several times. In the tracer's direct-light Cornell
///   box `faure` has the lowest error at 16 spp and per unit of time at 4
///   and 16 spp (`docs/joint_study.md`).
/// - **A discrete choice followed by a draw** (pick a light, then a point
///   on it): take the choice from a `next_1d` and the point from the next
///   draw (or from `branch(light_index)` if the point's routine belongs to
///   the light), rather than reusing the remapped remainder of the choice's
///   value: the stratification of a remapped value is only as fine as the
///   choice left it.
/// - **`next_4d` over two `next_2d`** when the four values feed one
///   integrand together (film and lens under depth of field, a light point
///   and a BSDF direction combined by MIS): for the sequences it is one
///   point of a 4D Owen-scrambled Sobol' set, stratified in all four
///   dimensions jointly, where two `next_2d` are each stratified but
///   paired like independent sets (never worse than white noise).
///
/// # Cost
///
/// `start`: the sampler's [`root`](PixelSamplerHooks::root) and
/// [`locate`](PixelSamplerHooks::locate) (for [`Padded`](crate::Padded) a few
/// integer operations, no hash). Each draw: one
/// [`mix64`](crate::primitives::mix64) and the sampler's kernel. `branch`
/// and `split`: one `mix64` and a multiply-add (`split` also the sampler's
/// `locate`). Through `&AnyPixelSampler` each draw also matches on the
/// kind and calls the kind's kernel out of line;
/// [`AnyPixelSampler::visit`](crate::AnyPixelSampler::visit) runs generic
/// code on the concrete type instead. `cargo bench -p wellspread-lab
/// --bench speed -- domain-ratio` measures `start` plus draws against a
/// PCG hash making two floats, per back end, and `lab/draw_cost.sh`
/// counts their instructions (`docs/performance.md`).
///
/// # Size
///
/// The sampler plus 24 bytes (a u64 key, the index, the draw and
/// dimension counters and the pixel state): 32 bytes borrowed, for every
/// sampler; owned, 32 bytes for `Padded<Sobol>` up to 120 for
/// `AnyPixelSampler`. `size_of` is tested per sampler in
/// `tests/pixel/domain.rs` and listed in `docs/performance.md`.
///
/// # Limits
///
/// - The draw counter wraps after 2^32 draws (no panic), after which the
///   streams repeat; the dimension counter wraps after 2^32 values.
/// - `split` with `count = 0` is a debug-build panic; a release build
///   treats it as `count = 1`. `j >= count` is a debug-build panic; a
///   release build uses `j` as given (sample `index * count + j`, which
///   overlaps another sample's children). `index * count + j` wraps at
///   2^32.
/// - Keys are any u32, 0 included; equal keys give equal children.
///
/// # Examples
///
/// See [`PixelSampler`] for a path tracer's loop.
///
/// ```
/// use wellspread::{Padded, PixelSampler, Sobol};
/// let pixels = Padded::new(Sobol::new(16)?, 0);
/// let mut d = pixels.start([3, 4], 5);
/// let light = d.branch(7);
/// d.next_2d();
/// d.next_4d();
/// assert_eq!(d.branch(7), light); // what the parent drew does not matter
/// assert_eq!(d.draws(), 2);
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Domain<S> {
    key: u64,
    index: u32,
    draws: u32,
    dimensions: u32,
    pixel_state: u32,
    sampler: S,
}

impl<S: PixelSampler> Domain<S> {
    /// Sample `index` of `pixel` of `sampler`, at draw 0 of the root
    /// domain, the sampler moved in: the owned form, `'static` when the
    /// sampler is, for a domain that outlives any borrow. Pass `&sampler`
    /// for the borrowed form [`PixelSampler::start`] returns; both give the
    /// same values.
    #[inline(always)]
    pub fn start(sampler: S, pixel: [u32; 2], index: u32) -> Self {
        let root = Self::located_root(&sampler, pixel, index);
        Self::at_root(sampler, root)
    }

    /// The root's `(key, index, pixel_state)`: the sampler's `root`, then
    /// its `locate`.
    #[inline(always)]
    fn located_root(sampler: &S, pixel: [u32; 2], index: u32) -> (u64, u32, u32) {
        let root = sampler.root(pixel);
        let (index, key) = sampler.locate(index, root.key);
        (key, index, root.pixel_state)
    }

    /// The root domain of `sampler` at `(key, index, pixel_state)`.
    #[inline(always)]
    const fn at_root(sampler: S, (key, index, pixel_state): (u64, u32, u32)) -> Self {
        Self {
            key,
            index,
            draws: 0,
            dimensions: 0,
            pixel_state,
            sampler,
        }
    }

    /// The sampler.
    #[inline]
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The sample index within its set (after the edge rule of
    /// [`PixelSamplerHooks::locate`] and any [`split`](Self::split)).
    #[inline]
    pub const fn index(&self) -> u32 {
        self.index
    }

    /// This domain's key.
    #[inline]
    pub const fn key(&self) -> u64 {
        self.key
    }

    /// How many draws this domain has made, whatever their widths (the
    /// next draw's number).
    #[inline]
    pub const fn draws(&self) -> u32 {
        self.draws
    }

    /// How many values this domain's draws have returned (1 per
    /// `next_1d`, 2 per `next_2d`, ...): the next draw's first scalar
    /// dimension, which [`PaddedNd`](crate::PaddedNd) reads.
    #[inline]
    pub const fn dimensions(&self) -> u32 {
        self.dimensions
    }

    /// The inputs of the next draw, `width` values wide; advances the
    /// draw and dimension counters.
    #[inline(always)]
    fn advance(&mut self, width: u32) -> Draw {
        let draw = Draw::new(
            self.key,
            self.draws,
            self.dimensions,
            self.index,
            self.pixel_state,
        );
        self.draws = self.draws.wrapping_add(1);
        self.dimensions = self.dimensions.wrapping_add(width);
        draw
    }

    /// The next draw as one value in `[0, 1)`, stratified in 1D over the
    /// pixel's samples where the sampler allows (see its `draw_1d`).
    #[inline]
    pub fn next_1d(&mut self) -> f32 {
        let draw = self.advance(1);
        self.sampler.draw_1d(draw)
    }

    /// The next draw as a point in `[0, 1)^2`.
    #[inline]
    pub fn next_2d(&mut self) -> Vec2 {
        let draw = self.advance(2);
        self.sampler.draw_2d(draw)
    }

    /// The next draw as a point in `[0, 1)^3` (one draw: the counter
    /// advances by one whatever the width).
    #[inline]
    pub fn next_3d(&mut self) -> Vec3 {
        let draw = self.advance(3);
        self.sampler.draw_3d(draw)
    }

    /// The next draw as a point in `[0, 1)^4`: for the sequences one
    /// point of a 4D Owen-scrambled Sobol' set, for the others two padded
    /// pairs (see each sampler's `draw_4d`).
    #[inline]
    pub fn next_4d(&mut self) -> Vec4 {
        let draw = self.advance(4);
        self.sampler.draw_4d(draw)
    }

    /// The child domain keyed `key`: same pixel and index, a key derived
    /// from this domain's key alone, draw 0.
    #[inline]
    #[must_use]
    pub fn branch(&self, key: u32) -> Self
    where
        S: Copy,
    {
        Self {
            key: child_key(self.key, salt::BRANCH, key),
            draws: 0,
            dimensions: 0,
            ..*self
        }
    }

    /// Sub-sample `j` of `count` of the child keyed `key`: the domain of
    /// sample `index * count + j` (see the type's Properties and Limits).
    #[inline]
    #[must_use]
    #[track_caller]
    pub fn split(&self, key: u32, count: u32, j: u32) -> Self
    where
        S: Copy,
    {
        debug_assert!(count > 0, "split count must be at least 1");
        debug_assert!(j < count, "split sub-sample {j} out of range 0..{count}");
        let count = count.max(1);
        let child = self.index.wrapping_mul(count).wrapping_add(j);
        let (index, key) = self
            .sampler
            .locate(child, child_key(self.key, salt::SPLIT, key));
        Self {
            key,
            index,
            draws: 0,
            dimensions: 0,
            ..*self
        }
    }
}
