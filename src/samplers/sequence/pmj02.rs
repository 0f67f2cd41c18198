use glam::{Vec2, Vec3, Vec4};

use super::digital::{DigitalSequence, OwenSeeds, bits_to_point, scrambled_bits};
use super::{Sobol, fill_run, fill_set, set_size};
use crate::error::Error;
use crate::primitives::{owen_scramble, prefix_shuffle};
use crate::simd::Kernel;
use crate::traits::DomainSampler;
use crate::traits::{Sampler2D, Sequence2D};

/// Progressive multi-jittered (0,2) sequence (pmj02, Christensen, Kensler &
/// Kilpatrick 2018), generated in O(1) per sample with no tables.
///
/// # Construction
///
/// Christensen et al. build pmj02 point by point, each new point drawn
/// uniformly in a randomly chosen stratum that keeps every elementary
/// interval filled. Helmer, Christensen & Kensler 2021 show that such
/// random choices amount to Owen scrambling of a digital base-2 sequence,
/// and generate pmj02 from "xor values" derived from its generator
/// matrices: the unsigned Stirling numbers of the first kind mod 2,
/// `C0[k][j] = c(j, k)` for x and `C1[k][j] = c(j + 1, k + 1)` for y (digit
/// `k` of the coordinate, bit `j` of the index). (Their recipe applied to
/// the matrices here reproduces their published pmj02 xor values; the unit
/// tests check the matrices against the Stirling recurrence and the
/// (0,2)-sequence rank condition for every `m <= 32`.) wellspread computes
/// that digital sequence directly:
///
/// - The generator matrices are evaluated for all 32 digits at once by a
///   few masked xor-shift steps, with no loop and no table; the derivation
///   is on `stirling_x` in the source.
/// - The index is shuffled and the coordinates Owen-scrambled exactly as in
///   [`Sobol`] (Burley 2020), so dimension pairs decorrelate
///   the same way: hash the pair into the pattern with
///   [`pattern_seed`](crate::primitives::pattern_seed).
///
/// No per-pattern or global table is needed. At power-of-two sizes the
/// point sets have the same distribution as Owen-scrambled [`Sobol`]
/// (Helmer et al. note this); the two differ in the order of points inside
/// each block, so their non-power-of-two prefixes differ.
///
/// [`Sobol`]: crate::Sobol
///
/// # Properties
///
/// - A [`Sequence2D`]: every `index` in `0..2^32` is valid.
/// - Progressive: every power-of-two prefix `0..2^m` (`m <= 24`), and every
///   aligned block of `2^m`, is a (0,m,2)-net, checked exactly on the f32
///   values. Prefixes of length `4^k` are therefore stratified on
///   `2^k x 2^k`, those of length `2 * 4^k` on `2^k x 2^(k+1)` and
///   `2^(k+1) x 2^k`, and every prefix of `2^m` is Latin on `2^m x 2^m`.
/// - Multi-jittered: each point is uniform in its smallest elementary box
///   (Owen scrambling randomises all 32 digits), and uniform over `[0, 1)^2`.
///
/// # Cost
///
/// As [`Sobol`] (three Owen-scramble hashes, four bit reversals) with about
/// twenty shift/mask/xor operations for the two generator matrices in place of
/// Sobol's fifteen: no loop, no table, no division.
///
/// # Limits
///
/// Coordinates are multiples of `2^-24`, so the net property is exact up to
/// `2^24` points; beyond that boxes are narrower than the f32 spacing below
/// 1.0. This is pmj02 without the blue-noise "best candidate" selection of
/// pmj02bn, which needs a search over previous points and so cannot be
/// random access.
///
/// # Examples
///
/// ```
/// use wellspread::{Pmj02, Sampler2D};
/// let pmj = Pmj02::new(64)?;
/// // Every prefix of 4^k points is stratified on 2^k x 2^k.
/// for k in 0..=3 {
///     let side = 1u32 << k;
///     let mut seen = vec![false; (side * side) as usize];
///     for i in 0..side * side {
///         let p = pmj.sample(i, 7);
///         let cell = (p.y * side as f32) as u32 * side + (p.x * side as f32) as u32;
///         assert!(!seen[cell as usize]);
///         seen[cell as usize] = true;
///     }
/// }
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Christensen, Kensler & Kilpatrick 2018, "Progressive Multi-Jittered
///   Sample Sequences", EGSR (Computer Graphics Forum 37(4)).
/// - Helmer, Christensen & Kensler 2021, "Stochastic Generation of (t, s)
///   Sample Sequences", EGSR, and its supplemental material (pmj02 as a
///   digital sequence with Stirling-number generator matrices).
/// - Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Pmj02 {
    n: u32,
}

impl Pmj02 {
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

impl Sampler2D for Pmj02 {
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

impl Sequence2D for Pmj02 {
    #[inline]
    fn fill_from(&self, start: u32, pattern: u32, out: &mut [Vec2]) {
        fill_run(&Self::kernel(pattern), start, out);
    }
}

/// The digits, in reversed bit order (bit `k` has weight `2^-(k+1)`), of the
/// Stirling generator matrix `C0` applied to the bits of `index`.
///
/// Split the index into its even bits `2a`, the coefficients `e_a` of a
/// polynomial `E`, and its odd bits `2a + 1`, the coefficients `o_a` of `O`.
/// Column `2a` is `x^a (1 + x)^a = z^a` and column `2a + 1` is `x z^a`, with
/// `z = x + x^2`, so the result is the polynomial `E(z) + x O(z)`. Since squaring is linear mod 2,
/// `z^(2^b) = x^(2^b) + x^(2^(b+1))`, and splitting each block of `2^(b+1)`
/// coefficients into low and high halves `L + z^(2^b) H` gives
/// `L(z) + (x^(2^b) + x^(2^(b+1))) H(z)`. With coefficient `a` stored at bit
/// `2a`, the high half already sits at offset `2^(b+1)`, so step `b` only
/// adds a copy of it shifted down by `2^b`: the masks select the high half
/// of each block of `2^(b+2)` bits (`0xcccc..`: bits 2-3 of every 4;
/// `0xf0f0..`: bits 4-7 of every 8; ...). Each transformed block of `2^b`
/// coefficients has degree below `2^(b+1)`, so blocks never overlap, and the
/// odd half (one bit up) rides along in the same steps. Sixteen coefficients
/// of each half fit in 32 bits, so four steps do.
#[inline(always)]
pub(crate) const fn stirling_x(index: u32) -> u32 {
    let mut w = index;
    w ^= (w & 0xcccc_cccc) >> 1;
    w ^= (w & 0xf0f0_f0f0) >> 2;
    w ^= (w & 0xff00_ff00) >> 4;
    w ^= (w & 0xffff_0000) >> 8;
    w
}

/// The digits, in reversed bit order, of `C1` applied to the bits of
/// `index`. Column `j` of `C1` is column `j + 1` of `C0` one digit down, so
/// this is [`stirling_x`] of the index shifted up one bit, shifted back
/// down, plus the column of bit 31, which the shift drops: column 32 of
/// `C0` is `x^16 (1 + x)^16 = x^16 + x^32`, one digit down bits 15 and 31.
#[inline(always)]
pub(crate) const fn stirling_y(index: u32) -> u32 {
    (stirling_x(index << 1) >> 1) ^ (0u32.wrapping_sub(index >> 31) & 0x8000_8000)
}

/// Point `s` (an already shuffled index) of the pmj02 sequence,
/// Owen-scrambled by `seeds`, in natural-order 0.32 fixed point.
#[inline(always)]
const fn pmj02_point_bits(s: u32, seeds: OwenSeeds) -> (u32, u32) {
    scrambled_bits(stirling_x(s), stirling_y(s), seeds)
}

impl DigitalSequence for Pmj02 {
    /// Sample `index` of the sequence, in natural-order 0.32 fixed point.
    #[inline(always)]
    fn point_bits(index: u32, seeds: OwenSeeds) -> (u32, u32) {
        pmj02_point_bits(owen_scramble(index, seeds.index), seeds)
    }
}

/// A domain's draws: 2D draws are pmj02 at the index read through a
/// [`prefix_shuffle`]; 1D, 3D and 4D draws are the Owen-scrambled Sobol'
/// ones (pmj02 has no 4D construction; its 1D projection is Sobol's
/// dimension 0 anyway). Every power-of-two prefix and every dyadic block
/// `[2^m, 2^(m+1))` of a draw's indices is a (0,m,2)-net; unlike the bare
/// sequence's, other aligned blocks are not, and a prefix between two
/// powers of two ends in a random subset of its block
/// ([`DomainSampler`]'s section on which ranges are nets).
impl DomainSampler for Pmj02 {
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
        let seeds = OwenSeeds::from_stream(stream);
        bits_to_point(pmj02_point_bits(prefix_shuffle(index, seeds.index), seeds))
    }
    #[inline]
    fn domain_3d(&self, index: u32, stream: u64) -> Vec3 {
        Sobol::unbounded().domain_3d(index, stream)
    }
    #[inline]
    fn domain_4d(&self, index: u32, stream: u64) -> Vec4 {
        Sobol::unbounded().domain_4d(index, stream)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unsigned Stirling numbers of the first kind mod 2, from the
    /// recurrence `c(n, k) = c(n-1, k-1) + (n-1) c(n-1, k)`: `table[n]` has
    /// bit `k` set when `c(n, k)` is odd.
    fn stirling_mod2_rows() -> [u64; 34] {
        let mut rows = [0u64; 34];
        rows[0] = 1;
        for n in 1..34 {
            let prev = rows[n - 1];
            let times = if (n - 1) % 2 == 1 { prev } else { 0 };
            rows[n] = (prev << 1) ^ times;
        }
        rows
    }

    #[test]
    fn butterfly_is_the_stirling_matrix() {
        let rows = stirling_mod2_rows();
        for (j, &row) in rows.iter().enumerate().take(32) {
            assert_eq!(stirling_x(1 << j) as u64, row, "column {j} of C0");
            assert_eq!(
                stirling_y(1 << j) as u64,
                rows[j + 1] >> 1,
                "column {j} of C1"
            );
        }
        // Linear, so the columns determine everything.
        let (a, b) = (0x8765_4321u32, 0x1357_9bdf);
        assert_eq!(stirling_x(a ^ b), stirling_x(a) ^ stirling_x(b));
        assert_eq!(stirling_y(a ^ b), stirling_y(a) ^ stirling_y(b));
    }

    #[test]
    fn pmj02_is_a_02_sequence_up_to_2_to_the_32() {
        assert!(crate::samplers::sequence::digital::tests::is_02_sequence(
            |j| stirling_x(1 << j),
            |j| stirling_y(1 << j),
        ));
    }

    #[test]
    fn first_digits_are_pmj02s_first_strata() {
        // Unscrambled, the first four points of the digital sequence sit in
        // the four quadrants, the first two in opposite ones.
        let quadrant = |i: u32| (stirling_x(i) & 1, stirling_y(i) & 1);
        assert_eq!(quadrant(0), (0, 0));
        assert_eq!(quadrant(1), (1, 1));
        let mut q: std::vec::Vec<_> = (0..4).map(quadrant).collect();
        q.sort_unstable();
        assert_eq!(q, [(0, 0), (0, 1), (1, 0), (1, 1)]);
    }
}
