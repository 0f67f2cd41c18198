use glam::Vec2;

use super::{Sobol, fill_run, fill_set, set_size};
use crate::error::Error;
use crate::primitives::{
    hash_combine, hash_u32, owen_scramble_reversed, prefix_shuffle, salt, stratum_to_unit_f32,
    u32_to_unit_f32,
};
use crate::simd::Kernel;
use crate::traits::DomainSampler;
use crate::traits::{Sampler2D, Sequence2D};

/// Base-3 digits scrambled per sample: `3^15 = 14_348_907` strata, the most
/// that fit in the `2^24` f32 strata of `[0, 1)`.
const BASE3_DIGITS: u32 = 15;
/// `3^BASE3_DIGITS`.
const BASE3_STRATA: u32 = 14_348_907;

/// The Halton sequence in bases 2 and 3, Owen-scrambled in each base.
///
/// Point `index` is `(phi_2(index), phi_3(index))`, the radical inverses of
/// the index in bases 2 and 3 (its digits mirrored about the radix point),
/// with every digit permuted by a hash of the pattern and of the digits
/// above it (Owen's nested scramble):
///
/// - base 2 by [`owen_scramble_reversed`] (Burley 2020), whose reversed
///   input is the index itself;
/// - base 3 digit by digit: digit `k` of the index is mapped by one of the
///   six permutations of `{0, 1, 2}` (a reflection and a rotation), chosen by
///   a hash of the seed, `k` and digits `0..k` (one [`hash_u32`] per digit),
///   for the first 15 digits. Digits
///   below `3^-15` are a hash of the whole index and pattern, placed in the
///   stratum with [`stratum_to_unit_f32`] so the 15-digit stratum is exact.
///
/// # Properties
///
/// - A [`Sequence2D`]: every `index` in `0..2^32` is valid.
/// - Any run of `2^a 3^b` consecutive indices (not only a prefix;
///   `a <= 24`, `b <= 15`) has exactly one point in each cell of the
///   `2^a x 3^b` grid, checked exactly on the f32 values; in particular
///   any `2^a` consecutive points are one per column of `2^a`, any `3^b` one
///   per row of `3^b`.
/// - Low discrepancy at every `n` (star discrepancy `O(log^2 n / n)`),
///   each point uniform over `[0, 1)^2`.
///
/// # Cost
///
/// One Owen-scramble hash for x; for y, fifteen rounds of a divide by 3 (a
/// multiply) and one independent [`hash_u32`], then two more hashes for the
/// low digits and a fixed-point stratum conversion: about three times
/// [`Sobol`]'s operations.
///
/// # Limits
///
/// Base-3 strata are exact down to `3^-15`; finer digits are hashed jitter, so the index digits
/// beyond the fifteenth (indices from `3^15 = 14_348_907` on) only select
/// which jitter a point gets. Coordinates are multiples of `2^-24`.
///
/// Unlike [`Sobol`] the index is not shuffled: no shuffle
/// keeps every run of `2^a 3^b` indices a run. Two patterns therefore give
/// independently scrambled copies of the same points in the same order, so
/// two dimension pairs sampled at the same `index` are correlated in their
/// leading digits (their first base-2 digits agree or disagree for every
/// `index` at once). Use Halton for one pair per pixel, and
/// [`Sobol`] or [`Pmj02`](crate::Pmj02) for padded
/// dimension pairs.
///
/// # Examples
///
/// ```
/// use wellspread::{Halton, Sampler2D};
/// let halton = Halton::new(72)?;
/// // Any 72 = 8 x 9 consecutive points: one per cell of an 8 x 9 grid.
/// let mut seen = [false; 72];
/// for i in 1000..1072 {
///     let p = halton.sample(i, 5);
///     seen[(p.x * 8.0) as usize * 9 + (p.y * 9.0) as usize] = true;
/// }
/// assert!(seen.iter().all(|&s| s));
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Halton 1960, "On the efficiency of certain quasi-random sequences of
///   points in evaluating multi-dimensional integrals", Numer. Math. 2.
/// - Owen 1997, "Monte Carlo variance of scrambled net quadrature", SIAM J.
///   Numer. Anal. 34(5) (nested scrambling in any base).
/// - Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Halton {
    n: u32,
}

impl Halton {
    /// The sequence with set size `n` (see [`Sequence2D`]).
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`.
    pub fn new(n: u32) -> Result<Self, Error> {
        set_size(n).map(|n| Self { n })
    }

    /// The sequence with no set size, `len() == u32::MAX` (see
    /// [`Sequence2D`]).
    #[must_use]
    pub const fn unbounded() -> Self {
        Self { n: u32::MAX }
    }

    /// The points of pattern `pattern`, as a lane kernel.
    #[inline(always)]
    fn kernel(pattern: u32) -> impl Kernel {
        HaltonSeeds::new(pattern)
    }
}

impl Sampler2D for Halton {
    #[inline]
    fn len(&self) -> u32 {
        self.n
    }

    #[inline]
    fn sample(&self, index: u32, pattern: u32) -> Vec2 {
        Self::kernel(pattern).points([index])[0]
    }

    #[inline]
    fn fill(&self, pattern: u32, out: &mut [Vec2]) {
        fill_set(&Self::kernel(pattern), self.n, out);
    }
}

/// A domain's draws: the sampler's own points at the index read through a
/// [`prefix_shuffle`] keyed by the stream (Halton visits its points in the
/// same order for every pattern, so unshuffled draws would pair their
/// samples), 1D draws Sobol's, 3D and 4D padded. The shuffle keeps the sets
/// of indices of every power-of-two prefix and every dyadic block
/// `[2^m, 2^(m+1))` (one point per column of `2^m`), not the runs of `3^b`
/// indices nor other aligned blocks, and a prefix between two powers of two
/// ends in a random subset of its block ([`DomainSampler`]'s section on
/// which ranges are nets).
impl DomainSampler for Halton {
    #[inline]
    fn is_progressive(&self) -> bool {
        true
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u64) -> f32 {
        Sobol::unbounded().domain_1d(index, stream)
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u64) -> Vec2 {
        let s = prefix_shuffle(index, (stream >> 32) as u32);
        self.sample(s, stream as u32)
    }
}

impl Sequence2D for Halton {
    #[inline]
    fn fill_from(&self, start: u32, pattern: u32, out: &mut [Vec2]) {
        fill_run(&Self::kernel(pattern), start, out);
    }
}

#[derive(Clone, Copy, Debug)]
struct HaltonSeeds {
    x: u32,
    y: u32,
}

impl HaltonSeeds {
    #[inline]
    const fn new(pattern: u32) -> Self {
        let pattern_hash = hash_u32(pattern);
        Self {
            x: hash_u32(pattern_hash ^ salt::JITTER_X),
            y: hash_u32(pattern_hash ^ salt::JITTER_Y),
        }
    }
}

/// Owen-scrambled base-3 radical inverses of `index[lane]` as floats, one
/// lane each, with seed `seed`: the digit loop outside, the lanes inside,
/// so that a batch runs in SIMD registers.
#[inline(always)]
fn scrambled_radical_inverse_3<const N: usize>(index: [u32; N], seed: u32) -> [f32; N] {
    let mut rest = index;
    let mut stratum = [0u32; N];
    // The node of the digit tree above digit k is named by the level k and
    // the value of digits 0..k, `prefix = index mod 3^k`; hashing the pair
    // picks the permutation of digit k, so it depends on those digits only
    // (the nested scramble). Unlike a hash chained from node to node, the
    // fifteen hashes are independent and run in parallel.
    let mut prefix = [0u32; N];
    let mut weight = 1u32;
    let mut level_seed = seed;
    for _ in 0..BASE3_DIGITS {
        for lane in 0..N {
            let digit = rest[lane] % 3;
            rest[lane] /= 3;
            let h = hash_u32(prefix[lane] ^ level_seed);
            // One of the six permutations of {0, 1, 2}: reflect if the top
            // bit is set, then rotate by a value in 0..3 from the other bits
            // (a multiply-shift, bias below 2^-30).
            let reflected = if h >> 31 == 1 { 2 - digit } else { digit };
            let rotation = (((h << 1) as u64 * 3) >> 32) as u32;
            stratum[lane] = stratum[lane] * 3 + (reflected + rotation) % 3;
            // prefix < 3^15 and weight <= 3^15: no overflow.
            prefix[lane] += digit * weight;
        }
        weight *= 3;
        // A new seed per level (the golden-ratio step, odd and with about
        // half its bits set), so equal prefixes of different lengths differ.
        level_seed = level_seed.wrapping_add(salt::GOLDEN_32);
    }
    // The remaining index digits and the pattern pick the position inside
    // the finest stratum.
    let mut y = [0.0; N];
    for lane in 0..N {
        y[lane] = stratum_to_unit_f32(
            stratum[lane],
            BASE3_STRATA,
            hash_combine(hash_u32(prefix[lane] ^ level_seed), rest[lane]),
        );
    }
    y
}

impl Kernel for HaltonSeeds {
    #[inline(always)]
    fn points<const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let y = scrambled_radical_inverse_3(index, self.y);
        let mut out = [Vec2::ZERO; N];
        for (lane, point) in out.iter_mut().enumerate() {
            // In reversed bit order the base-2 radical inverse of `index` is
            // `index`.
            let x = owen_scramble_reversed(index[lane], self.x).reverse_bits();
            *point = Vec2::new(u32_to_unit_f32(x), y[lane]);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // The most base-3 digits whose strata are all distinct f32 strata.
    const _: () = assert!(BASE3_STRATA <= crate::primitives::MAX_STRATA);
    const _: () = assert!(BASE3_STRATA * 3 > crate::primitives::MAX_STRATA);

    #[test]
    fn base3_strata_constant() {
        assert_eq!(3u32.pow(BASE3_DIGITS), BASE3_STRATA);
    }

    #[test]
    fn every_run_of_27_is_one_per_row() {
        for start in [0, 1, 5, 1000, u32::MAX - 27] {
            let mut seen = [false; 27];
            for i in start..start + 27 {
                let [y] = scrambled_radical_inverse_3([i], 12345);
                seen[(y as f64 * 27.0) as usize] = true;
            }
            assert!(seen.iter().all(|&s| s), "start {start}");
        }
    }
}
