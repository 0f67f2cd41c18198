use glam::{Vec2, Vec3, Vec4};

use super::digital::{
    DigitalSequence, OwenSeeds, bits_to_point, scrambled_unit, sobol_4d_point, sobol_point_bits,
};
use super::{fill_run, fill_set, set_size};
use crate::error::Error;
use crate::primitives::{owen_scramble, prefix_shuffle};
use crate::simd::Kernel;
use crate::traits::DomainSampler;
use crate::traits::{Sampler2D, Sequence2D};

/// The first two dimensions of the Sobol sequence, Owen-scrambled with
/// Burley's hash and shuffled: a randomised base-2 (0,2)-sequence.
///
/// Sample `index` is computed as follows (Burley 2020):
///
/// 1. The index is shuffled, `s = owen_scramble(index, seed_index)`
///    ([`owen_scramble`]). Aligned blocks of `2^m` indices map onto aligned
///    blocks, so every power-of-two prefix is still an aligned block of the
///    sequence, while different patterns visit the blocks, and the points
///    inside them, in unrelated orders.
/// 2. Sobol dimension 0 of `s` is its radical inverse; dimension 1 is the
///    Pascal matrix mod 2 applied to the digits of `s`, computed without
///    tables by five xor-shift steps (see `pascal_reversed` in the source).
/// 3. Each coordinate is Owen-scrambled with its own seed
///    ([`owen_scramble_reversed`](crate::primitives::owen_scramble_reversed)) and truncated to 24 bits by
///    [`u32_to_unit_f32`](crate::primitives::u32_to_unit_f32).
///
/// All three seeds are hashes of `pattern`. For further dimension pairs
/// (lens, time, light) pass a pattern with the pair's number hashed in,
/// `pattern_seed(x, y, frame, dimension)`
/// ([`pattern_seed`](crate::primitives::pattern_seed)): the independent index
/// shuffle is what decorrelates pairs (Burley's "padding"), since two
/// pairs then see unrelated points of the sequence at the same `index`.
/// [`Padded`](crate::Padded) does this for a whole image.
///
/// # Properties
///
/// - A [`Sequence2D`]: every `index` in `0..2^32` is valid.
/// - Every power-of-two prefix `0..2^m` (`m <= 24`), and every aligned block
///   `k 2^m..(k + 1) 2^m`, is a (0,m,2)-net: each of the `2^m` boxes
///   `2^-a x 2^-(m-a)` of every shape `a = 0..=m` holds exactly one point,
///   checked exactly on the f32 values. So prefixes of length `4^k` are
///   stratified on `2^k x 2^k` and all are Latin (one point per row and
///   column of `2^m`).
/// - Each point is uniformly distributed over `[0, 1)^2` (Owen scrambling),
///   so estimates are unbiased; on smooth integrands the error at powers of
///   two falls like `n^-1.5` (Owen 1997).
///
/// # Cost
///
/// Four [`hash_u32`](crate::primitives::hash_u32) of the pattern (once per
/// [`fill`](Sampler2D::fill)), then per sample three Owen-scramble hashes of
/// four multiply-xor steps, four bit reversals and five xor-shift steps: no
/// loop, no table, no division.
///
/// # Limits
///
/// Coordinates are multiples of `2^-24`, so nets are exact for prefixes up
/// to `2^24` points; beyond that the boxes are narrower than the f32
/// spacing below 1.0 and two points can share a coordinate. No index
/// wraps: the `2^32` indices give `2^32` distinct points in 32-bit fixed
/// point, before the truncation to 24 bits.
///
/// # Examples
///
/// ```
/// use wellspread::{Sobol, Sampler2D};
/// let sobol = Sobol::new(16)?;
/// let points: Vec<_> = (0..16).map(|i| sobol.sample(i, 42)).collect();
/// // A (0,4,2)-net: one point in each box of every shape 2^-a x 2^-(4-a).
/// for a in 0..=4 {
///     let mut seen = [false; 16];
///     for p in &points {
///         let (col, row) = ((p.x * (1 << a) as f32) as usize, (p.y * (1 << (4 - a)) as f32) as usize);
///         seen[col << (4 - a) | row] = true;
///     }
///     assert!(seen.iter().all(|&s| s));
/// }
/// // A sequence: any index is valid.
/// assert!(sobol.sample(u32::MAX, 42).x < 1.0);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// Padding: one pattern per pixel, frame and dimension pair.
///
/// ```
/// use wellspread::{Sobol, Sampler2D, pattern_seed};
/// let sobol = Sobol::new(64)?;
/// let (px, py, frame) = (120, 45, 0);
/// for i in 0..sobol.len() {
///     let film = sobol.sample(i, pattern_seed(px, py, frame, 0));
///     let lens = sobol.sample(i, pattern_seed(px, py, frame, 1));
///     let time = sobol.sample(i, pattern_seed(px, py, frame, 2)).x;
///     assert!(film.max_element() < 1.0 && lens.max_element() < 1.0 && time < 1.0);
/// }
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Sobol 1967, "On the distribution of points in a cube and the
///   approximate evaluation of integrals", USSR Comput. Math. Math. Phys. 7(4).
/// - Owen 1997, "Monte Carlo variance of scrambled net quadrature", SIAM J.
///   Numer. Anal. 34(5).
/// - Laine & Karras 2011, "Stratified Sampling for Stochastic Transparency",
///   EGSR.
/// - Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4): the
///   scramble, the index shuffle and padding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sobol {
    n: u32,
}

impl Sobol {
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
}

impl Sampler2D for Sobol {
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

impl Sequence2D for Sobol {
    #[inline]
    fn fill_from(&self, start: u32, pattern: u32, out: &mut [Vec2]) {
        fill_run(&Self::kernel(pattern), start, out);
    }
}

impl DigitalSequence for Sobol {
    #[inline(always)]
    fn point_bits(index: u32, seeds: OwenSeeds) -> (u32, u32) {
        sobol_point_bits(owen_scramble(index, seeds.index), seeds)
    }
}

/// Draw `k` of a domain: Sobol' dimensions (0, 1) at the index read
/// through a [`prefix_shuffle`] (so every power-of-two prefix of a pixel,
/// and every dyadic block `[2^m, 2^(m+1))`, is a net and two draws pair
/// their samples freely), 1D draws dimension 0, 3D and 4D draws the 4D set
/// ([`DomainSampler`]'s table). Unlike the bare sequence's, other aligned
/// blocks of a draw's indices are not nets, and a prefix between two powers
/// of two ends in a random subset of its block: [`DomainSampler`]'s section
/// on which ranges are nets says what a progressive renderer should use.
impl DomainSampler for Sobol {
    #[inline]
    fn is_progressive(&self) -> bool {
        true
    }
    #[inline]
    fn domain_1d(&self, index: u32, stream: u64) -> f32 {
        let seeds = OwenSeeds::from_stream(stream);
        scrambled_unit(prefix_shuffle(index, seeds.index), seeds.x)
    }
    #[inline]
    fn domain_2d(&self, index: u32, stream: u64) -> Vec2 {
        let seeds = OwenSeeds::from_stream(stream);
        bits_to_point(sobol_point_bits(prefix_shuffle(index, seeds.index), seeds))
    }
    #[inline]
    fn domain_3d(&self, index: u32, stream: u64) -> Vec3 {
        self.domain_4d(index, stream).truncate()
    }
    #[inline]
    fn domain_4d(&self, index: u32, stream: u64) -> Vec4 {
        let s = prefix_shuffle(index, OwenSeeds::from_stream(stream).index);
        sobol_4d_point(s, stream, [0; 4])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::sequence::digital::pascal_reversed;
    use crate::samplers::sequence::digital::tests::is_02_sequence;

    #[test]
    fn sobol_is_a_02_sequence_up_to_2_to_the_32() {
        assert!(is_02_sequence(|j| 1 << j, |j| pascal_reversed(1 << j)));
        // And the check has teeth: two equal matrices are not.
        assert!(!is_02_sequence(|j| 1 << j, |j| 1 << j));
    }

    #[test]
    fn fill_in_lanes_covers_every_length() {
        let sobol = Sobol::new(100).unwrap();
        for len in [0, 1, 7, 8, 9, 16, 17, 100] {
            let mut out = std::vec![Vec2::ZERO; len];
            sobol.fill(3, &mut out);
            for (i, p) in (0..).zip(&out) {
                assert_eq!(*p, sobol.sample(i, 3), "len {len} index {i}");
            }
        }
    }

    #[test]
    fn pascal_matches_the_direction_numbers_of_x_plus_1() {
        let mut v = 1u32 << 31;
        for j in 0..32 {
            assert_eq!(pascal_reversed(1 << j).reverse_bits(), v, "column {j}");
            v ^= v >> 1;
        }
        // Linear: the xor of columns.
        assert_eq!(
            pascal_reversed(0b1011),
            pascal_reversed(0b1000) ^ pascal_reversed(0b10) ^ pascal_reversed(1)
        );
    }

    #[test]
    fn unscrambled_start_is_the_sobol_sequence() {
        // The first eight points of Sobol dimensions 0 and 1 in index order,
        // in 1/8ths (Sobol 1967; Joe & Kuo's tables give the same).
        let expect = [
            (0, 0),
            (4, 4),
            (2, 6),
            (6, 2),
            (1, 5),
            (5, 1),
            (3, 3),
            (7, 7),
        ];
        for (i, &(x, y)) in expect.iter().enumerate() {
            let i = i as u32;
            assert_eq!(i.reverse_bits() >> 29, x, "x of {i}");
            assert_eq!(pascal_reversed(i).reverse_bits() >> 29, y, "y of {i}");
        }
    }
}
