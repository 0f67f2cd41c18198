//! The traits of the samplers ([`Sampler2D`] for every 2D one, [`Sequence2D`]
//! for the progressive sequences, [`SamplerNd`] for the point sets of many
//! dimensions, [`DomainSampler`] for the draws a [`Padded`](crate::Padded)
//! pixel sampler makes through a 2D sampler) and the checks and draws their
//! methods share.

use glam::{Vec2, Vec3, Vec4};

use crate::primitives::{locate_pass, mix64, permute, rand_u32, salt, stratum_to_unit_f32};

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
    /// The progressive sequences ([`Sequence2D`]) accept every `u32` index:
    /// their `len` is only the set size `fill` and the tools use.
    fn sample(&self, index: u32, pattern: u32) -> Vec2;

    /// Writes samples `0..out.len()` of pattern `pattern` into `out`: exactly
    /// what [`sample`](Sampler2D::sample) returns for each index, possibly
    /// faster.
    ///
    /// Every sampler writes its point formula once, as integer operations
    /// that are the same on every lane. `fill` runs that formula on 8 or 16
    /// lanes at once (AVX2 or AVX-512, detected at run time; the portable
    /// loop without the `simd` feature or off x86), so its points are bit
    /// for bit those of `sample`; the per-pattern work (hashes,
    /// permutation keys, small tables) is done once per call. Measured
    /// ratios to a `rand_pcg::Pcg32` fill are in `docs/performance.md`.
    ///
    /// # Panics
    ///
    /// If `out` is longer than [`len`](Sampler2D::len): a set never wraps
    /// around silently. The panic names the caller's line (every
    /// implementation is `#[track_caller]`).
    #[track_caller]
    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        check_fill_len(out.len(), self.len());
        for (index, point) in (0..).zip(out.iter_mut()) {
            *point = self.sample(index, pattern);
        }
    }
}

/// A set of `len()` well-distributed points in `[0, 1)^d`, `d =
/// dimensions()`, with random access to every coordinate: the point sets
/// whose guarantees span more than two dimensions
/// ([`LatinHypercube`](crate::LatinHypercube),
/// [`OrthogonalArray`](crate::OrthogonalArray),
/// [`Sobol4D`](crate::Sobol4D)).
///
/// The contract is [`Sampler2D`]'s, one coordinate at a time: coordinate
/// `dimension` of sample `index` of pattern `pattern` is a pure function of
/// the three, computed in O(1) with no state, no tables and no allocation,
/// and it is in `[0, 1)` after f32 rounding. `pattern` picks one of 2^32
/// independent randomisations of the whole set, all its dimensions at once:
/// the stratification that ties dimensions together (every 2D projection
/// of an orthogonal array of strength 2, say) holds within one pattern.
///
/// ```
/// use wellspread::{LatinHypercube, SamplerNd};
/// let cube = LatinHypercube::new(10, 5)?;
/// let mut point = [0.0; 5];
/// cube.sample(3, 7, &mut point);
/// assert_eq!(point[4], cube.coordinate(3, 7, 4));
/// assert!(point.iter().all(|x| (0.0..1.0).contains(x)));
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait SamplerNd {
    /// Number of samples in one pattern.
    fn len(&self) -> u32;

    /// Always `false`: constructors reject zero samples. Present because
    /// clippy and readers expect `is_empty` beside `len`.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Number of coordinates of each sample, at least 1.
    fn dimensions(&self) -> u32;

    /// Whether the set is a progressive sequence, whose prefixes are good
    /// sets ([`Sobol4D`](crate::Sobol4D), [`Faure4D`](crate::Faure4D)):
    /// built with no set size (`unbounded()`), it gives
    /// [`PaddedNd`](crate::PaddedNd) no sample count. `false` unless a
    /// type says otherwise.
    fn is_progressive(&self) -> bool {
        false
    }

    /// Coordinate `dimension` of sample `index` of pattern `pattern`, in
    /// O(1).
    ///
    /// `index` must be below [`len`](SamplerNd::len) and `dimension` below
    /// [`dimensions`](SamplerNd::dimensions) (both checked in debug
    /// builds); each type documents what a release build returns otherwise,
    /// and it is always a value in `[0, 1)`.
    fn coordinate(&self, index: u32, pattern: u32, dimension: u32) -> f32;

    /// Writes sample `index` of pattern `pattern` into
    /// `out[..dimensions()]`: exactly what
    /// [`coordinate`](SamplerNd::coordinate) returns for each dimension,
    /// with the per-pattern and per-sample work done once. Entries of `out`
    /// past `dimensions()` are left as they are.
    ///
    /// # Panics
    ///
    /// If `out` is shorter than [`dimensions`](SamplerNd::dimensions): a
    /// point cut short is a caller's bug, not a request for its first
    /// coordinates (use [`coordinate`](SamplerNd::coordinate) for those).
    #[track_caller]
    fn sample(&self, index: u32, pattern: u32, out: &mut [f32]) {
        let out = check_nd_out(out, self.dimensions());
        for (dimension, x) in (0..).zip(out.iter_mut()) {
            *x = self.coordinate(index, pattern, dimension);
        }
    }

    /// Coordinates `first .. first + out.len()` of sample `index` of
    /// pattern `pattern`, into `out`: exactly what
    /// [`coordinate`](SamplerNd::coordinate) returns for each, with the
    /// per-pattern and per-sample work done once (a domain's draw reads
    /// its values this way from [`PaddedNd`](crate::PaddedNd)'s page).
    /// The same edges as `coordinate` for dimensions past `dimensions()`.
    #[inline]
    fn coordinates(&self, index: u32, pattern: u32, first: u32, out: &mut [f32]) {
        for (dimension, x) in (first..).zip(out.iter_mut()) {
            *x = self.coordinate(index, pattern, dimension);
        }
    }
}

/// A progressive sequence: a [`Sampler2D`] whose points form one infinite
/// (`2^32`-point) sequence, so that any prefix, and any run of indices, is
/// a good set ([`Sobol`](crate::Sobol), [`Pmj02`](crate::Pmj02),
/// [`Halton`](crate::Halton)).
///
/// The contract, tested for every implementor:
///
/// - [`sample`](Sampler2D::sample) accepts every `index` in `0..2^32`,
///   whatever [`len`](Sampler2D::len) is; `len` is only the set size that
///   [`fill`](Sampler2D::fill) and the tools use.
/// - Each type's `new(n)` takes any set size from 1 to `u32::MAX`
///   ([`Error::ZeroSamples`](crate::Error::ZeroSamples) for 0), and its
///   `unbounded()` has `len() == u32::MAX`: all give the same points.
/// - [`fill_from`](Sequence2D::fill_from) writes any run of indices, so a
///   progressive renderer can add samples to a pixel without recomputing
///   the first ones.
///
/// [`Hammersley`](crate::Hammersley) is not a sequence: it is a fixed set
/// of at most 2^24 points whose x coordinate depends on `n`.
///
/// ```
/// use wellspread::{Sampler2D, Sequence2D, Sobol};
/// let sequence = Sobol::unbounded();
/// // Render 16 samples, look, then add 16 more.
/// let mut points = vec![wellspread::glam::Vec2::ZERO; 32];
/// sequence.fill(3, &mut points[..16]);
/// sequence.fill_from(16, 3, &mut points[16..]);
/// assert_eq!(points[20], sequence.sample(20, 3));
/// ```
///
/// The set size changes `len` only:
///
/// ```
/// use wellspread::{Halton, Pmj02, Sampler2D, Sobol};
/// assert_eq!(Sobol::unbounded().sample(1000, 3), Sobol::new(16)?.sample(1000, 3));
/// assert_eq!(Pmj02::unbounded().sample(1000, 3), Pmj02::new(16)?.sample(1000, 3));
/// assert_eq!(Halton::unbounded().sample(1000, 3), Halton::new(16)?.sample(1000, 3));
/// # Ok::<(), wellspread::Error>(())
/// ```
pub trait Sequence2D: Sampler2D {
    /// Writes samples `start..start + out.len()` of pattern `pattern` into
    /// `out`: exactly what [`sample`](Sampler2D::sample) returns for each
    /// index, through the same batched path as [`fill`](Sampler2D::fill).
    /// The set size does not bound it; only the end of the index range does.
    ///
    /// # Panics
    ///
    /// If `start + out.len()` exceeds `2^32`: the sequence's last index is
    /// `u32::MAX`, and it never wraps around to index 0. The panic names
    /// the caller's line (every implementation is `#[track_caller]`).
    #[track_caller]
    fn fill_from(&self, start: u32, pattern: u32, out: &mut [Vec2]);
}

/// A [`Sampler2D`] that [`Padded`](crate::Padded) draws
/// [`Domain`](crate::Domain) dimensions from: one set per draw, picked by
/// the draw's `stream` (a well-mixed u64 that is the same for every sample
/// index of a pixel), in 1 to 4 dimensions.
///
/// Every method has a default, so a grid sampler, or a [`Sampler2D`] of
/// your own, needs only `impl DomainSampler for MySampler {}`: 2D draws are
/// `sample(index, pattern)` with the stream's low 32 bits as the pattern,
/// 1D draws the stratified draw below, 3D and 4D padded from a second,
/// unrelated stream. Each sampler's file overrides what it does better:
///
/// | sampler | `domain_1d` | `domain_2d` | `domain_3d` / `domain_4d` |
/// | --- | --- | --- | --- |
/// | grid family, [`Hammersley`](crate::Hammersley) | the `n` samples in `n` distinct strata of `[0, 1)` (a keyed permutation of the index, jittered inside the stratum; centred for [`Regular`](crate::Regular)) | the sampler's own set (Hammersley's index keyed-permuted first, since its order is the same for every pattern) | padded: a pair and a 1D draw, or two pairs, from unrelated streams |
/// | [`Sobol`](crate::Sobol), [`Pmj02`](crate::Pmj02) | Owen-scrambled Sobol' dimension 0: a (0,m,1)-net on every power-of-two prefix | the sampler's own (0,2)-sequence | one Owen-scrambled 4D Sobol' set: (3,m,4)-nets on every power-of-two prefix (`m >= 3`), dimensions (0, 1) a (0,2)-sequence; 3D is its first three coordinates |
/// | [`Halton`](crate::Halton) | as Sobol's 1D | the sampler's own set | padded |
/// | [`Random`](crate::Random) | one independent uniform value | independent uniform points (the two halves of one 64-bit mix; not `sample`'s values) | padded |
///
/// The progressive sequences read their index through a
/// [`prefix_shuffle`](crate::primitives::prefix_shuffle) keyed by the
/// stream, so every power-of-two prefix of a pixel keeps its net while two
/// draws pair their samples as freely as prefixes allow.
///
/// # Which index ranges of a draw are nets
///
/// For [`Sobol`](crate::Sobol) and [`Pmj02`](crate::Pmj02) draws (and
/// [`ZSobol`](crate::ZSobol)'s and [`BlueNoise`](crate::BlueNoise)'s
/// inside a pixel), over one stream's indices:
///
/// - every power-of-two prefix `0 .. 2^m` and every dyadic block
///   `[2^m, 2^(m+1))` is a (0,m,2)-net (1D draws a (0,m,1)-net; for
///   [`Halton`](crate::Halton) the same ranges keep their `2^m` columns of
///   x, not its base-3 rows);
/// - no other aligned block: `[j 2^k, (j + 1) 2^k)` with `j >= 2` is a
///   subset of `2^k` of the `2^m` indices of the dyadic block that holds it,
///   and many such blocks are not nets (`tests/pixel` counts them);
/// - a prefix `n` that is not a power of two, `2^m < n < 2^(m+1)`, is the
///   net `0 .. 2^m` plus a uniformly random subset of `n - 2^m` indices of
///   the block `[2^m, 2^(m+1))`: the error of its last `n - 2^m` samples is
///   that of random ones from the block's net, not the finer structure the
///   unshuffled sequence had there (`docs/quality.md`, section Prefixes
///   between powers of two, measures the trade with independence).
///
/// So a renderer that renders progressive passes picks one of:
///
/// - **Doubling passes** (pass 0 is index 0, pass `m` the block
///   `[2^m, 2^(m+1))`): every pass and every total so far is a net.
/// - **Passes of `2^k` samples that are nets each**: pass `p` is samples
///   `0 .. 2^k` of its own key, `start(pixel, i).branch(p)` for `i < 2^k`
///   (or a fixed-size sampler such as [`ZSobol`](crate::ZSobol), whose
///   pass rule keys each pass by `p`): independent nets, like the passes
///   of any fixed-size set.
/// - **The pass rule of a sequence** (`samples_per_pixel() = Some(2^k)`,
///   pass `p` the indices `p 2^k .. (p + 1) 2^k`) continues one sequence:
///   passes 0 and 1 are nets, and the first `2^a` passes together are, but
///   a single pass `p >= 2` is not.
/// - **[`Domain::split`](crate::Domain::split)** when the samples of a
///   pixel are taken together: the `n count` children are samples
///   `0 .. n count` of one pattern, one net when `n count` is a power of
///   two.
pub trait DomainSampler: Sampler2D {
    /// Whether indices past [`len`](Sampler2D::len) continue one sequence
    /// (`true`: the [`Sequence2D`] implementors, whose own docs say why)
    /// or start a new pass of a fixed-size set (`false`, the default).
    /// This is the crate's one progressive flag: [`locate`](Self::locate)
    /// and [`Padded`](crate::Padded)'s
    /// [`samples_per_pixel`](crate::PixelSampler::samples_per_pixel) read
    /// it, and a test holds it equal to "implements [`Sequence2D`]" for
    /// every [`SamplerKind`](crate::SamplerKind).
    #[inline]
    fn is_progressive(&self) -> bool {
        false
    }

    /// Where sample `index` of a domain keyed `key` lives: `(index in the
    /// set, key of the set)`. A progressive sampler
    /// ([`is_progressive`](Self::is_progressive)) returns `(index, key)`:
    /// indices past the count continue the sequence. A fixed-size set
    /// follows the pass rule: indices `p n .. (p + 1) n` are pass `p`, a
    /// complete set keyed by `p`.
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        if self.is_progressive() {
            (index, key)
        } else {
            locate_pass(index, self.len(), key)
        }
    }

    /// Sample `index` of the 1D set picked by `stream`. The default is
    /// [`stratified_1d`] with jitter.
    #[inline]
    fn domain_1d(&self, index: u32, stream: u64) -> f32 {
        stratified_1d(index, self.len(), stream, true)
    }

    /// Sample `index` of the 2D set picked by `stream`: by default
    /// `sample(index, stream as u32)`.
    #[inline]
    fn domain_2d(&self, index: u32, stream: u64) -> Vec2 {
        self.sample(index, stream as u32)
    }

    /// Sample `index` of the 3D set picked by `stream`: by default a pair
    /// and a 1D draw of the [`second_stream`].
    #[inline]
    fn domain_3d(&self, index: u32, stream: u64) -> Vec3 {
        let a = self.domain_2d(index, stream);
        a.extend(self.domain_1d(index, second_stream(stream)))
    }

    /// Sample `index` of the 4D set picked by `stream`: by default two
    /// pairs, the second from the [`second_stream`].
    #[inline]
    fn domain_4d(&self, index: u32, stream: u64) -> Vec4 {
        let a = self.domain_2d(index, stream);
        let b = self.domain_2d(index, second_stream(stream));
        Vec4::new(a.x, a.y, b.x, b.y)
    }
}

impl<S: DomainSampler + ?Sized> DomainSampler for &S {
    #[inline]
    fn is_progressive(&self) -> bool {
        (**self).is_progressive()
    }
    #[inline]
    fn locate(&self, index: u32, key: u64) -> (u32, u64) {
        (**self).locate(index, key)
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u64) -> f32 {
        (**self).domain_1d(index, stream)
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u64) -> Vec2 {
        (**self).domain_2d(index, stream)
    }
    #[inline]
    fn domain_3d(&self, index: u32, stream: u64) -> Vec3 {
        (**self).domain_3d(index, stream)
    }
    #[inline]
    fn domain_4d(&self, index: u32, stream: u64) -> Vec4 {
        (**self).domain_4d(index, stream)
    }
}

impl<S: Sampler2D + ?Sized> Sampler2D for &S {
    #[inline]
    fn len(&self) -> u32 {
        (**self).len()
    }
    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        (**self).sample(index, pattern)
    }
    #[inline]
    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        (**self).fill(pattern, out)
    }
}

/// A stream unrelated to `stream` (one [`mix64`]): the second pattern of a
/// padded 3D or 4D draw.
#[inline(always)]
#[must_use]
pub const fn second_stream(stream: u64) -> u64 {
    mix64(stream ^ salt::SECOND)
}

/// Sample `index` of `n` in 1D: stratum `permute(index, n, key)` of `n`
/// equal strata of `[0, 1)` (a keyed uniform permutation, so every sample
/// lands in its own stratum), at a hashed position inside it (`jitter`)
/// or at its centre; key and jitter come from the two halves of `stream`.
/// Exact on the f32 values for `n <= 2^24`
/// ([`stratum_to_unit_f32`]); an
/// index at or past `n` is reduced modulo `n`.
#[inline]
#[must_use]
pub fn stratified_1d(index: u32, n: u32, stream: u64, jitter: bool) -> f32 {
    let n = n.clamp(1, crate::primitives::MAX_STRATA);
    let index = if index < n { index } else { index % n };
    let stratum = permute(index, n, stream as u32);
    let bits = if jitter {
        rand_u32(index, (stream >> 32) as u32 ^ salt::JITTER_1D)
    } else {
        1 << 31
    };
    stratum_to_unit_f32(stratum, n, bits)
}

/// The index check every fixed-size `sample` shares (debug builds only;
/// each sampler documents what a release build does with a bad index).
#[inline(always)]
#[track_caller]
pub(crate) fn debug_check_index(index: u32, len: u32) {
    debug_assert!(index < len, "index {index} out of range 0..{len}");
}

/// The panic every `fill` shares, so the message is the same everywhere.
#[inline]
#[track_caller]
pub(crate) fn check_fill_len(requested: usize, len: u32) {
    assert!(
        requested <= len as usize,
        "fill asked for {requested} samples of a set of {len}"
    );
}

/// The panic every `fill_from` shares: indices `start..start + requested`
/// must lie in the sequence's `0..2^32`, which never wraps around.
#[inline]
#[track_caller]
pub(crate) fn check_fill_from(start: u32, requested: usize) {
    assert!(
        u64::from(start) + requested as u64 <= 1 << 32,
        "fill_from asked for indices {start}..{} past the sequence's last index 4294967295",
        u64::from(start) + requested as u64
    );
}

/// The panic every [`SamplerNd::sample`] shares: `out` must hold a whole
/// point. Returns `out[..dimensions]`.
#[inline]
#[track_caller]
pub(crate) fn check_nd_out(out: &mut [f32], dimensions: u32) -> &mut [f32] {
    let len = out.len();
    match out.get_mut(..dimensions as usize) {
        Some(point) => point,
        None => panic!(
            "SamplerNd::sample needs room for {dimensions} coordinates, got a slice of {len}"
        ),
    }
}
