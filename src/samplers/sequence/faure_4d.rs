//! Faure's (0,s)-sequence over GF(4) in four dimensions, [`Faure4D`]: a
//! progressive set whose every pair of dimensions is stratified at 16
//! samples and every triple at 64, the progressive counterpart of an
//! orthogonal array's page.
//!
//! # Generator matrices
//!
//! Niederreiter's generalisation of Faure's construction to a prime power
//! `q`: dimension `j` has the matrix with `binom(c, r) a_j^(c - r)` in row
//! `r` and column `c` (`c >= r`), computed in GF(q), for distinct field
//! elements `a_j` (`a^0 = 1`). With `q = 4` and `a_j` = 0, 1, alpha,
//! alpha + 1 (`alpha^2 = alpha + 1`) the four dimensions are a
//! (0,4)-sequence in base 4: every block `[k 4^m, (k + 1) 4^m)` of indices is a (0,m,4)-net,
//! one point in every box `4^-k0 x .. x 4^-k3` with `k0 + .. + k3 = m`
//! (checked exactly below for `m <= 5`). No (0,s)-sequence in base 4 has
//! more than four dimensions, and none in base 2 more than two.
//!
//! A base-4 digit is two bits and GF(4)'s sum is their xor, so the
//! sequence is also a digital sequence over GF(2): a point is the xor of
//! one column per set index bit, and the crate's base-2 Owen scramble and
//! index shuffle apply (a base-4 box is a base-2 box of even depth). The
//! two bits of index digit `c` stand for alpha (bit `2c`) and 1 (bit
//! `2c + 1`), and an output digit's alpha coefficient is its high bit.
//!
//! Multiplying a matrix on the left by a nonsingular lower-triangular one
//! keeps the net property (the span of its first `k` rows is unchanged;
//! Tezuka's generalised Faure sequences), and two such choices matter in
//! base 2:
//!
//! - Digit 0 of dimension `j` is multiplied by `g_j` = 1, alpha,
//!   alpha + 1, 1. Inside each aligned block of 4 indices only index digit
//!   0 moves, and it reaches only output digit 0: unscaled, all four
//!   dimensions would have the same top digit up to a constant, so every
//!   pair's top bits would be tied (at 4 spp every pair in two diagonal
//!   quadrants). The top bit of `g x` is a different linear form of `x`'s
//!   two bits for each nonzero `g`, so at 4 samples every pair but (0, 3)
//!   fills the `2 x 2` grid: the film and the lens, film x with lens x
//!   (which depth of field couples), a light choice with the light
//!   sample, and the light sample's own pair. In base 2 no more is
//!   possible: a (0,2)-net has at most three dimensions.
//! - Every other diagonal entry is 1, so index bit `2c` sets the high bit
//!   of output digit `c` (alpha and `alpha^2 = alpha + 1` both have it):
//!   each dimension alone is stratified in `2^k` intervals at every
//!   power-of-two prefix `2^k`, odd `k` too, except dimension 2 at 2
//!   samples, whose `g = alpha + 1` maps alpha to 1, the low bit (both
//!   points fall in one half). A scale that kept it would tie a second
//!   pair at 4 samples: the 4-sample pairs were chosen over the 2-sample
//!   stratum of one dimension.
//!
//! Dimension 0 (`a = 0`, the identity) is the base-2 radical inverse.
//!
//! # Cost
//!
//! One column xor per set bit of the shuffled index (all four dimensions
//! in one 16-byte row: at 16 spp at most four), then one Owen scramble per
//! coordinate asked for.

use crate::error::Error;
use crate::primitives::{mix64, prefix_shuffle, salt};
use crate::samplers::nd::field::Field;
use crate::traits::{SamplerNd, check_nd_out};

use super::digital::{OwenSeeds, scrambled_unit, seeds_4d};

/// The scale of output digit 0 of each dimension (see the module docs).
const DIGIT_0_SCALE: [u32; 4] = [1, 2, 3, 1];

/// `COLUMNS[k][j]`: the image of index bit `k` in dimension `j`, in the
/// crate's reversed-digit form (bit `i` is the digit of weight
/// `2^-(i+1)`), so that the row of a set bit holds all four dimensions.
const COLUMNS: [[u32; 4]; 32] = {
    // GF(4) with alpha^2 = alpha + 1, its one modulus; elements as two bits
    // (bit 0 the coefficient of 1, bit 1 that of alpha).
    let Some(gf4) = Field::new(4) else {
        panic!("GF(4) exists");
    };
    let mut out = [[0u32; 4]; 32];
    let mut k = 0;
    while k < 32 {
        // Index bit k is digit c = k / 2 with the value alpha (even k) or 1.
        let (c, value) = (k / 2, if k % 2 == 0 { 2 } else { 1 });
        let mut j = 0;
        while j < 4 {
            let a = j as u32;
            let mut natural = 0u32;
            let mut r = 0;
            while r <= c {
                // binom(c, r) mod 2 is 1 when r's bits are among c's (Lucas).
                if r & c == r {
                    let mut power = 1;
                    let mut i = 0;
                    while i < c - r {
                        power = gf4.mul(power, a);
                        i += 1;
                    }
                    let scale = if r == 0 { DIGIT_0_SCALE[j] } else { 1 };
                    // Output digit r has weight 4^-(r+1): bits 31 - 2r, 30 - 2r.
                    natural |= gf4.mul(scale, gf4.mul(power, value)) << (30 - 2 * r);
                }
                r += 1;
            }
            out[k][j] = natural.reverse_bits();
            j += 1;
        }
        k += 1;
    }
    out
};

/// The four dimensions of sequence index `s`, unscrambled, in
/// reversed-digit form.
#[inline(always)]
const fn columns_of(mut s: u32) -> [u32; 4] {
    let mut out = [0u32; 4];
    while s != 0 {
        let row = COLUMNS[s.trailing_zeros() as usize];
        out[0] ^= row[0];
        out[1] ^= row[1];
        out[2] ^= row[2];
        out[3] ^= row[3];
        s &= s - 1;
    }
    out
}

/// Faure's (0,4)-sequence in base 4 (Niederreiter's construction over
/// GF(4); the source's module docs derive it), Owen-scrambled and
/// shuffled, as a [`SamplerNd`] of four dimensions: what the `faure` pixel
/// sampler's domains read in pages of four, so a bounce's draws in call
/// order are stratified jointly at any sample count.
///
/// # Properties
///
/// - A sequence: every `u32` index is valid. Every prefix of `4^m` points
///   (`m <= 12`) is a (0,m,4)-net in base 4: at 16 points every pair of
///   dimensions fills the `4 x 4` grid and each dimension the 16 strata of
///   width 1/16; at 64 every triple fills `4 x 4 x 4`; at 256 every pair
///   `16 x 16` and all four `4 x 4 x 4 x 4`. A prefix of `2 x 4^m` points
///   is two such nets.
/// - Each dimension alone is stratified in `2^k` intervals at every
///   power-of-two prefix `2^k`, except dimension 2 at 2 samples. At 4
///   samples every pair but (0, 3) fills the `2 x 2` grid.
/// - Each pattern is an independent Owen scramble of all four dimensions
///   and an index shuffle inside dyadic blocks
///   ([`prefix_shuffle`]), which keeps
///   every power-of-two prefix the same set of points; between powers of
///   two a prefix ends in a random subset of its block.
/// - Against [`Sobol4D`](crate::Sobol4D), a (3,4)-sequence in base 2: its
///   pair (0, 1) is a (0,2)-sequence, finer at `2^(2m+1)` points (its
///   `2^m x 2^(m+1)` boxes), but its other pairs miss `4 x 4` at 16 points
///   where every pair here fills it.
///
/// # Cost
///
/// One [`mix64`] and one index shuffle per
/// pattern and index, one 16-byte xor per set bit of the shuffled index,
/// then one Owen scramble per coordinate:
/// [`coordinates`](SamplerNd::coordinates) does the shared part once.
///
/// # Limits
///
/// `len()` is only the set size that tools use. A `dimension` of 4 or
/// more is checked in debug builds and read modulo 4 in release builds.
/// Nets are exact up to `4^12 = 2^24` points (f32's resolution).
///
/// # Examples
///
/// ```
/// use wellspread::{Faure4D, SamplerNd};
/// let faure = Faure4D::new(16)?;
/// let points: Vec<[f32; 4]> = (0..16)
///     .map(|index| {
///         let mut point = [0.0; 4];
///         faure.sample(index, 7, &mut point);
///         point
///     })
///     .collect();
/// // Every pair of dimensions fills the 4 x 4 grid: here (1, 3).
/// let mut cells = [[0; 4]; 4];
/// for p in &points {
///     cells[(p[1] * 4.0) as usize][(p[3] * 4.0) as usize] += 1;
/// }
/// assert_eq!(cells, [[1; 4]; 4]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Faure 1982, "Discrépance de suites associées à un système de
///   numération (en dimension s)", Acta Arith. 41.
/// - Niederreiter 1987, "Point sets and sequences with small discrepancy",
///   Monatsh. Math. 104 (the construction over GF(q)).
/// - Burley 2020, "Practical Hash-based Owen Scrambling" (the scramble).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Faure4D {
    n: u32,
}

impl Faure4D {
    /// The sequence with set size `n`.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroSamples`] for `n = 0`.
    pub fn new(n: u32) -> Result<Self, Error> {
        super::set_size(n).map(|n| Self { n })
    }

    /// The sequence with no set size, `len() == u32::MAX`.
    #[must_use]
    pub const fn unbounded() -> Self {
        Self { n: u32::MAX }
    }

    /// The unscrambled digits (reversed) of point `index` of `pattern`,
    /// and its four scramble seeds.
    #[inline(always)]
    fn digits(index: u32, pattern: u32) -> ([u32; 4], [u32; 4]) {
        let stream = mix64(u64::from(pattern) ^ salt::FAURE_SET);
        let s = prefix_shuffle(index, OwenSeeds::from_stream(stream).index);
        (columns_of(s), seeds_4d(stream))
    }
}

impl SamplerNd for Faure4D {
    #[inline]
    fn len(&self) -> u32 {
        self.n
    }

    #[inline]
    fn dimensions(&self) -> u32 {
        4
    }

    #[inline]
    fn is_progressive(&self) -> bool {
        true
    }

    #[inline]
    fn coordinate(&self, index: u32, pattern: u32, dimension: u32) -> f32 {
        let mut x = [0.0];
        self.coordinates(index, pattern, dimension, &mut x);
        x[0]
    }

    #[inline]
    #[track_caller]
    fn sample(&self, index: u32, pattern: u32, out: &mut [f32]) {
        self.coordinates(index, pattern, 0, check_nd_out(out, 4));
    }

    // Inlined into the caller's loop, which knows how many coordinates it
    // asks for (a domain's draw: one to four).
    #[inline(always)]
    fn coordinates(&self, index: u32, pattern: u32, first: u32, out: &mut [f32]) {
        let (digits, seeds) = Self::digits(index, pattern);
        for (dimension, x) in (first..).zip(out.iter_mut()) {
            debug_assert!(dimension < 4, "dimension {dimension} out of range 0..4");
            let j = dimension as usize % 4;
            *x = scrambled_unit(digits[j], seeds[j]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// Whether the unscrambled points `start .. start + 4^m` put one point
    /// in every base-4 box of volume `4^-m`.
    fn is_base4_net(start: u32, m: u32) -> bool {
        let points: Vec<[u32; 4]> = (0..1u32 << (2 * m))
            .map(|offset| columns_of(start + offset).map(u32::reverse_bits))
            .collect();
        for shape in 0..(m + 1).pow(4) {
            let k: Vec<u32> = (0..4).map(|d| shape / (m + 1).pow(d) % (m + 1)).collect();
            if k.iter().sum::<u32>() != m {
                continue;
            }
            let mut seen = std::vec![false; points.len()];
            for p in &points {
                let cell = (0..4).fold(0usize, |cell, d| {
                    let digits = if k[d] == 0 {
                        0
                    } else {
                        p[d] >> (32 - 2 * k[d])
                    };
                    cell << (2 * k[d]) | digits as usize
                });
                if std::mem::replace(&mut seen[cell], true) {
                    return false;
                }
            }
        }
        true
    }

    #[test]
    fn aligned_blocks_of_4_to_the_m_are_0_m_4_nets() {
        for m in 0..=5 {
            for block in [0u32, 1, 3, 1000] {
                assert!(is_base4_net(block << (2 * m), m), "m {m} block {block}");
            }
        }
        assert!(is_base4_net(u32::MAX - 255, 4), "the last block");
    }

    #[test]
    fn dimension_0_is_the_radical_inverse() {
        for i in [0u32, 1, 2, 3, 6, 0x8000_0000, 0xdead_beef, u32::MAX] {
            assert_eq!(columns_of(i)[0], i, "{i:#x}");
        }
    }

    #[test]
    fn scrambled_prefixes_are_nets_and_each_dimension_is_stratified() {
        let faure = Faure4D::unbounded();
        for pattern in [0, 1, 0x1234_5678, u32::MAX] {
            let points = |n: u32| -> Vec<[f32; 4]> {
                (0..n)
                    .map(|i| {
                        let mut p = [0.0; 4];
                        faure.sample(i, pattern, &mut p);
                        p
                    })
                    .collect()
            };
            // Each dimension at every power-of-two prefix, 2^0 .. 2^12, but
            // dimension 2 at 2 points.
            for k in 0..=12 {
                let n = 1usize << k;
                for d in 0..4 {
                    let mut seen = std::vec![false; n];
                    let stratified = points(n as u32)
                        .iter()
                        .all(|p| !std::mem::replace(&mut seen[(p[d] * n as f32) as usize], true));
                    assert_eq!(stratified, (k, d) != (1, 2), "2^{k}, dimension {d}");
                }
            }
            // At 4 points every pair but (0, 3) fills the 2 x 2 grid.
            let p = points(4);
            for a in 0..4 {
                for b in a + 1..4 {
                    let mut seen = [0u32; 4];
                    for q in &p {
                        seen[(q[a] * 2.0) as usize * 2 + (q[b] * 2.0) as usize] += 1;
                    }
                    assert_eq!(seen == [1; 4], (a, b) != (0, 3), "({a}, {b}): {seen:?}");
                }
            }
            // Every pair at 16 and 256, every triple at 64, on the f32 values.
            for (n, side, dims) in [(16u32, 4usize, 2u32), (256, 16, 2), (64, 4, 3)] {
                let p = points(n);
                for mask in (0..16u32).filter(|m| m.count_ones() == dims) {
                    let chosen: Vec<usize> = (0..4).filter(|d| mask >> d & 1 == 1).collect();
                    let mut seen = std::vec![0u32; side.pow(dims)];
                    for q in &p {
                        let cell = chosen
                            .iter()
                            .fold(0, |c, &d| c * side + (q[d] * side as f32) as usize);
                        seen[cell] += 1;
                    }
                    assert!(seen.iter().all(|&c| c == 1), "{n} points, {chosen:?}");
                }
            }
        }
    }

    #[test]
    fn coordinates_match_coordinate_and_stay_below_one() {
        let faure = Faure4D::new(16).unwrap();
        for index in [0, 1, 15, 1 << 24, u32::MAX] {
            for pattern in [0, 7, u32::MAX] {
                let mut all = [0.0; 4];
                faure.sample(index, pattern, &mut all);
                for d in 0..4 {
                    assert_eq!(all[d as usize], faure.coordinate(index, pattern, d));
                    assert!((0.0..1.0).contains(&all[d as usize]));
                }
                let mut tail = [0.0; 2];
                faure.coordinates(index, pattern, 2, &mut tail);
                assert_eq!(tail, [all[2], all[3]]);
            }
        }
        assert_eq!(Faure4D::new(0), Err(Error::ZeroSamples));
    }
}
