//! The per-sample state a renderer passes down its call tree.

use glam::{Vec2, Vec3, Vec4};

use super::{Draw, PixelSampler};
use crate::primitives::{hash_combine, hash_u32};

/// Weyl increment between the streams of consecutive draws: the fraction
/// bits of sqrt(2), odd, so `key + d W` visits every u32 before repeating.
const WEYL: u32 = 0x6a09_e667;

/// One pixel sample's dimensions, owned: the sampler by value, the pixel,
/// the sample index, a key and a dimension counter (`Copy + Send + Sync +
/// 'static` when the sampler is). Made by [`PixelSampler::start`].
///
/// # Model
///
/// A domain is a node of a tree (as in OpenQMC's domains). Each node has
/// a 32-bit key; [`branch`](Self::branch) and [`split`](Self::split) derive
/// children from the key alone, and the draws `next_1d` ... `next_4d` read
/// the node's dimensions 0, 1, 2, ... one per call, whatever their width.
/// So a light's code can take its own samples from `d.branch(LIGHT)` without
/// knowing what the caller drew, and bounce `b` of a path of any depth uses
/// `d.branch(BOUNCE).branch(b)`.
///
/// # Properties
///
/// - Draw `k` of a domain uses the pattern picked by `stream =
///   hash(key + k W)`, the same for every sample index of the pixel: over a
///   pixel's samples each draw is one set of the sampler, with its
///   guarantees (see each sampler's `draw_*` for what each width gives).
/// - `d.branch(k)` depends only on `d`'s key, pixel and index, never on
///   how many draws `d` made; siblings `branch(k1)`, `branch(k2)` and the
///   parent's own draws use unrelated patterns.
/// - `d.split(key, count, j)` is sample `index * count + j` of the child
///   keyed `key`: over `j < count` and the pixel's `n` sample indices, the
///   `n count` children are samples `0 .. n count` of one pattern. For the
///   sequences that is one (0,m,2)-net whenever `n count` is a power of
///   two; for fixed-size samplers it is `count` complete sets (passes, see
///   [`PixelSampler`]'s edges), each with its guarantees.
///
/// # Cost
///
/// `start`: the sampler's [`root`](PixelSampler::root) (for [`Padded`](crate::Padded)
/// one 64-bit mix of the pixel). Each draw: one multiply-add, one
/// [`hash_u32`] and the sampler's kernel. `branch`: one
/// [`hash_combine`]; `split`: one more, a multiply and the sampler's
/// [`locate`](PixelSampler::locate). `cargo bench --bench speed --
/// domain-ratio` measures `start` plus one draw against a PCG hash making
/// two floats, per back end.
///
/// # Limits
///
/// - The dimension counter wraps after 2^32 draws (no panic), after which
///   the streams repeat.
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
/// assert_eq!(d.dimension(), 2);
/// # Ok::<(), wellspread::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Domain<S> {
    sampler: S,
    pixel: [u32; 2],
    pixel_state: u32,
    index: u32,
    key: u32,
    dimension: u32,
}

impl<S: PixelSampler> Domain<S> {
    /// Sample `index` of `pixel` of `sampler`, at dimension 0 of the root
    /// domain; [`PixelSampler::start`] calls this.
    #[inline(always)]
    pub fn start(sampler: S, pixel: [u32; 2], index: u32) -> Self {
        let root = sampler.root(pixel);
        let (index, key) = sampler.locate(index, root.key);
        Self {
            sampler,
            pixel,
            pixel_state: root.pixel,
            index,
            key,
            dimension: 0,
        }
    }

    /// The sampler.
    #[inline]
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The pixel, `[x, y]`.
    #[inline]
    pub const fn pixel(&self) -> [u32; 2] {
        self.pixel
    }

    /// The sample index within its set (after the edge rule of
    /// [`PixelSampler::locate`] and any [`split`](Self::split)).
    #[inline]
    pub const fn index(&self) -> u32 {
        self.index
    }

    /// This domain's key.
    #[inline]
    pub const fn key(&self) -> u32 {
        self.key
    }

    /// How many draws this domain has made (the next draw's dimension).
    #[inline]
    pub const fn dimension(&self) -> u32 {
        self.dimension
    }

    /// The next draw's inputs; advances the dimension counter.
    #[inline(always)]
    fn advance(&mut self) -> Draw {
        let stream = hash_u32(self.key.wrapping_add(self.dimension.wrapping_mul(WEYL)));
        self.dimension = self.dimension.wrapping_add(1);
        Draw {
            pixel: self.pixel,
            pixel_state: self.pixel_state,
            index: self.index,
            stream,
        }
    }

    /// The next dimension as one value in `[0, 1)`, stratified in 1D over
    /// the pixel's samples where the sampler allows (see its `draw_1d`).
    #[inline]
    pub fn next_1d(&mut self) -> f32 {
        let draw = self.advance();
        self.sampler.draw_1d(draw)
    }

    /// The next dimension as a point in `[0, 1)^2`.
    #[inline]
    pub fn next_2d(&mut self) -> Vec2 {
        let draw = self.advance();
        self.sampler.draw_2d(draw)
    }

    /// The next dimension as a point in `[0, 1)^3` (one draw: the counter
    /// advances by one whatever the width).
    #[inline]
    pub fn next_3d(&mut self) -> Vec3 {
        let draw = self.advance();
        self.sampler.draw_3d(draw)
    }

    /// The next dimension as a point in `[0, 1)^4`: for the sequences one
    /// point of a 4D Owen-scrambled Sobol' set, for the others two padded
    /// pairs (see each sampler's `draw_4d`).
    #[inline]
    pub fn next_4d(&mut self) -> Vec4 {
        let draw = self.advance();
        self.sampler.draw_4d(draw)
    }

    /// The child domain keyed `key`: same pixel and index, a key derived
    /// from this domain's key alone, dimension 0.
    #[inline]
    #[must_use]
    pub fn branch(&self, key: u32) -> Self
    where
        S: Copy,
    {
        Self {
            key: hash_combine(self.key, key),
            dimension: 0,
            ..*self
        }
    }

    /// Sub-sample `j` of `count` of the child keyed `key`: the domain of
    /// sample `index * count + j` (see the type's Properties and Limits).
    #[inline]
    #[must_use]
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
            .locate(child, hash_combine(self.key, key ^ SPLIT_SALT));
        Self {
            index,
            key,
            dimension: 0,
            ..*self
        }
    }
}

/// Keeps `split(k, ..)` and `branch(k)` apart (fraction bits of sqrt(3)).
const SPLIT_SALT: u32 = 0xbb67_ae85;
