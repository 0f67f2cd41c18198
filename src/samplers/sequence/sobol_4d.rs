//! Sobol' dimensions 2 and 3, so that a pixel sample can draw one point of
//! a 4D Owen-scrambled Sobol' set (dimensions 0 and 1 are the ones
//! [`Sobol`] uses: the identity and the Pascal matrix), and
//! that set as a [`SamplerNd`], [`Sobol4D`].
//!
//! # Direction numbers
//!
//! From Joe & Kuo's `new-joe-kuo-6.21201` table (S. Joe and F. Y. Kuo,
//! "Constructing Sobol sequences with better two-dimensional
//! projections", SIAM J. Sci. Comput. 30, 2008), the lines for their
//! dimensions 3 and 4 (`d s a m_i`):
//!
//! ```text
//! 3  2  1  1 3      x^2 + x + 1, m = 1, 3
//! 4  3  1  1 3 1    x^3 + x + 1, m = 1, 3, 1
//! ```
//!
//! The remaining `m_k` follow from the polynomial by the Bratley-Fox
//! recurrence `m_k = 2 a_1 m_(k-1) ^ 4 a_2 m_(k-2) ^ ... ^ 2^s m_(k-s) ^
//! m_(k-s)`, evaluated at compile time below; the same recurrence with
//! `x + 1` and `m_1 = 1` gives the Pascal matrix of dimension 1 (tested).
//!
//! # Net quality
//!
//! The primitive polynomials of dimensions 0 to 3 have degrees 1 (the
//! identity counts as degree 1), 1, 2 and 3, so the four dimensions form a
//! digital (t,4)-sequence with `t = 0 + 0 + 1 + 2 = 3`: every aligned block
//! of `2^m` indices, `m >= 3`, is a (3,m,4)-net, one point in every
//! elementary box of volume `2^(3-m)` (checked exactly below). The
//! projection on dimensions (0, 1) stays a (0,2)-sequence; the other five
//! 2D projections have `t <= 1` for (0, 2) and (1, 2) and `t <= 2`
//! otherwise (tested with the crate's `net_t_value`). Owen scrambling keeps
//! every one of these properties.
//!
//! # Cost
//!
//! Eight lookups in a 1 KiB table (four index bits each, both dimensions
//! packed in one u64) and eight xors, instead of a 32-step loop over the
//! index bits.

use glam::Vec4;

use crate::error::Error;
use crate::primitives::{mix64, salt};
use crate::samplers::Sobol;
use crate::traits::check_nd_out;
use crate::traits::{DomainSampler, SamplerNd};

/// Degree, coefficient bits `a` and initial `m_1..m_s` of a primitive
/// polynomial, as Joe & Kuo list them.
struct Polynomial {
    degree: u32,
    a: u32,
    m: [u64; 3],
}

/// Joe & Kuo's dimension 3 (our dimension 2): `x^2 + x + 1`, `m = 1, 3`.
const DIMENSION_2: Polynomial = Polynomial {
    degree: 2,
    a: 1,
    m: [1, 3, 0],
};

/// Joe & Kuo's dimension 4 (our dimension 3): `x^3 + x + 1`, `m = 1, 3, 1`.
const DIMENSION_3: Polynomial = Polynomial {
    degree: 3,
    a: 1,
    m: [1, 3, 1],
};

/// Joe & Kuo's dimension 2 (our dimension 1): `x + 1`, `m = 1`; used only
/// to check the recurrence against `pascal_reversed` (in `digital.rs`).
#[cfg(test)]
const DIMENSION_1: Polynomial = Polynomial {
    degree: 1,
    a: 0,
    m: [1, 0, 0],
};

/// The 32 generator-matrix columns of `p` in the crate's reversed-digit
/// form: column `j` (the image of index bit `j`) has bit `k` set when digit
/// `k + 1` (weight `2^-(k+1)`) of the point is set.
const fn columns(p: &Polynomial) -> [u32; 32] {
    let s = p.degree as usize;
    let mut m = [0u64; 33];
    let mut k = 1;
    while k <= 32 {
        if k <= s {
            m[k] = p.m[k - 1];
        } else {
            let mut v = m[k - s] ^ (m[k - s] << s);
            let mut i = 1;
            while i < s {
                // a's bits are a_1 .. a_(s-1), a_1 the most significant.
                if (p.a >> (s - 1 - i)) & 1 == 1 {
                    v ^= m[k - i] << i;
                }
                i += 1;
            }
            m[k] = v;
        }
        k += 1;
    }
    let mut out = [0u32; 32];
    let mut j = 0;
    while j < 32 {
        // v_(j+1) = m_(j+1) / 2^(j+1): in 0.32 fixed point m << (31 - j).
        let natural = (m[j + 1] << (31 - j)) as u32;
        out[j] = natural.reverse_bits();
        j += 1;
    }
    out
}

/// `TABLE[q][nibble]`: the xor of the columns of dimensions 2 (low half)
/// and 3 (high half) for the index bits `4 q .. 4 q + 3` set in `nibble`.
const TABLE: [[u64; 16]; 8] = {
    let c2 = columns(&DIMENSION_2);
    let c3 = columns(&DIMENSION_3);
    let mut table = [[0u64; 16]; 8];
    let mut q = 0;
    while q < 8 {
        let mut nibble = 0;
        while nibble < 16 {
            let mut v = 0u64;
            let mut b = 0;
            while b < 4 {
                if (nibble >> b) & 1 == 1 {
                    let j = 4 * q + b;
                    v ^= c2[j] as u64 | (c3[j] as u64) << 32;
                }
                b += 1;
            }
            table[q][nibble] = v;
            nibble += 1;
        }
        q += 1;
    }
    table
};

/// Sobol' dimensions 2 and 3 of sequence index `index`, unscrambled, in
/// reversed-digit form (ready for
/// [`owen_scramble_reversed`](crate::primitives::owen_scramble_reversed)).
#[inline(always)]
pub(crate) const fn dimensions_2_3_reversed(index: u32) -> (u32, u32) {
    let mut v = 0u64;
    let mut q = 0;
    while q < 8 {
        v ^= TABLE[q][((index >> (4 * q)) & 15) as usize];
        q += 1;
    }
    (v as u32, (v >> 32) as u32)
}

/// The 4D Owen-scrambled Sobol' sequence as a [`SamplerNd`]: the set a
/// [`Domain`](crate::Domain)'s `next_4d` draws from for
/// [`Sobol`] and [`Pmj02`](crate::Pmj02), one pattern at a
/// time.
///
/// # Properties
///
/// - A sequence, like [`Sobol`]: every `u32` index is valid,
///   and every power-of-two prefix `0..2^m`, and every dyadic block
///   `2^m..2^(m+1)`, is a (3,m,4)-net for `m >= 3`: `2^3` points in every
///   elementary box of volume `2^(3-m)` (see the module docs for the
///   derivation). Other aligned blocks are not: the index shuffle mixes
///   them inside their dyadic block.
/// - Dimensions (0, 1) are a (0,2)-sequence; (0, 2) and (1, 2) have `t <=
///   1`, the other 2D projections `t <= 2`.
/// - Each pattern is an independent Owen scramble of all four dimensions
///   and an index shuffle inside dyadic blocks
///   ([`prefix_shuffle`](crate::primitives::prefix_shuffle)), which keeps
///   every prefix the same set of points.
/// - Point `index` of pattern `pattern` is
///   [`DomainSampler::domain_4d`] of
///   [`Sobol`] at the stream `mix64(pattern ^ salt)`: one
///   formula for both.
///
/// # Cost
///
/// One [`mix64`], the index shuffle, the four
/// generator matrices (a 1 KiB table for dimensions 2 and 3) and four Owen
/// scrambles per point; [`sample`](SamplerNd::sample) computes the point
/// once, [`coordinate`](SamplerNd::coordinate) once per coordinate.
///
/// # Limits
///
/// `len()` is only the set size that tools use; a `dimension` of 4 or more
/// is checked in debug builds and read modulo 4 in release builds. The net
/// property is exact for prefixes up to 2^24 points (f32's resolution).
///
/// # Examples
///
/// ```
/// use wellspread::{SamplerNd, Sobol4D, glam::Vec2, metrics::is_net_base2};
/// let sobol = Sobol4D::new(64)?;
/// let points: Vec<[f32; 4]> = (0..64)
///     .map(|index| {
///         let mut point = [0.0; 4];
///         sobol.sample(index, 7, &mut point);
///         point
///     })
///     .collect();
/// // A (3,6,4)-net: every elementary box of volume 2^-3 holds 8 points,
/// // here the 2 x 2 x 2 boxes of dimensions 0, 2 and 3.
/// let mut cells = [0; 8];
/// for p in &points {
///     let half = |x: f32| (x * 2.0) as usize;
///     cells[half(p[0]) * 4 + half(p[2]) * 2 + half(p[3])] += 1;
/// }
/// assert_eq!(cells, [8; 8]);
/// // Dimensions 0 and 1 are a (0,6,2)-net.
/// let pairs: Vec<Vec2> = points.iter().map(|p| Vec2::new(p[0], p[1])).collect();
/// assert!(is_net_base2(&pairs)?);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Joe & Kuo 2008 (direction numbers); Owen 1995 (scrambling); Burley
/// 2020, "Practical Hash-based Owen Scrambling" (the hash-based scramble
/// and shuffle).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sobol4D {
    n: u32,
}

impl Sobol4D {
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

    /// Point `index` of `pattern`.
    #[inline]
    fn point(index: u32, pattern: u32) -> Vec4 {
        let stream = mix64(u64::from(pattern) ^ salt::SOBOL_SET);
        Sobol::unbounded().domain_4d(index, stream)
    }
}

impl SamplerNd for Sobol4D {
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
        debug_assert!(dimension < 4, "dimension {dimension} out of range 0..4");
        Self::point(index, pattern)[dimension as usize % 4]
    }

    #[inline]
    #[track_caller]
    fn sample(&self, index: u32, pattern: u32, out: &mut [f32]) {
        let out = check_nd_out(out, 4);
        out.copy_from_slice(&Self::point(index, pattern).to_array());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::sequence::digital::pascal_reversed;

    #[test]
    fn the_recurrence_gives_the_pascal_matrix_for_x_plus_1() {
        let c1 = columns(&DIMENSION_1);
        for (j, &c) in c1.iter().enumerate() {
            assert_eq!(c, pascal_reversed(1 << j), "column {j}");
        }
    }

    #[test]
    fn first_points_match_joe_kuo() {
        // Joe & Kuo's dimensions 3 and 4 for indices 1..8 in 1/8ths: the
        // direction numbers v_1 = 1/2, v_2 = 3/4 (dim 3), 3/4 (dim 4),
        // v_3 = 5/8 (dim 3: m_3 = 2 m_2 ^ 4 m_1 ^ m_1 = 6 ^ 5 = 3, so 3/8),
        // written out from the table's m values by hand.
        let natural = |i: u32| {
            let (a, b) = dimensions_2_3_reversed(i);
            (a.reverse_bits() >> 29, b.reverse_bits() >> 29)
        };
        // Index 1 -> v_1 in both: 1/2.
        assert_eq!(natural(1), (4, 4));
        // Index 2 -> v_2: m_2 = 3 -> 3/4 in both.
        assert_eq!(natural(2), (6, 6));
        // Index 4 -> v_3: dim 2: m_3 = (2 m_2) ^ (4 m_1) ^ m_1 = 6 ^ 4 ^ 1 = 3
        // -> 3/8; dim 3: m_3 = 1 -> 1/8.
        assert_eq!(natural(4), (3, 1));
        // Linear: index 3 = v_1 ^ v_2.
        assert_eq!(natural(3), (2, 2));
    }

    #[test]
    fn the_table_is_the_column_sum() {
        let (c2, c3) = (columns(&DIMENSION_2), columns(&DIMENSION_3));
        for index in [0u32, 1, 2, 3, 0x8000_0000, 0xdead_beef, u32::MAX, 12345] {
            let (mut a, mut b) = (0, 0);
            for j in 0..32 {
                if index >> j & 1 == 1 {
                    a ^= c2[j];
                    b ^= c3[j];
                }
            }
            assert_eq!(dimensions_2_3_reversed(index), (a, b), "{index:#x}");
        }
    }

    /// Elementary-interval check of the unscrambled 4D set on indices
    /// `start .. start + 2^m`: every box of `2^-d0 x ... x 2^-d3` with
    /// `d0 + ... + d3 = m - t` holds exactly `2^t` points.
    fn is_4d_net(start: u32, m: u32, t: u32) -> bool {
        let points: std::vec::Vec<[u32; 4]> = (start..start + (1 << m))
            .map(|i| {
                let (a, b) = dimensions_2_3_reversed(i);
                [i, pascal_reversed(i), a, b].map(u32::reverse_bits)
            })
            .collect();
        let total = m - t;
        for d0 in 0..=total {
            for d1 in 0..=total - d0 {
                for d2 in 0..=total - d0 - d1 {
                    let d = [d0, d1, d2, total - d0 - d1 - d2];
                    let mut counts = std::collections::HashMap::new();
                    for p in &points {
                        let mut cell = 0u64;
                        for k in 0..4 {
                            let digits = if d[k] == 0 { 0 } else { p[k] >> (32 - d[k]) };
                            cell = cell << d[k] | u64::from(digits);
                        }
                        *counts.entry(cell).or_insert(0u32) += 1;
                    }
                    if counts.len() != 1 << total || counts.values().any(|&c| c != 1 << t) {
                        return false;
                    }
                }
            }
        }
        true
    }

    #[test]
    fn aligned_blocks_are_3_m_4_nets() {
        for m in 3..=11 {
            for block in [0u32, 1, 5, 1000] {
                assert!(is_4d_net(block << m, m, 3), "m {m} block {block}");
            }
        }
        // t = 3 is the best for these four dimensions: some m fails at t = 2.
        assert!((3..=11).any(|m| !is_4d_net(0, m, 2)));
    }
}
