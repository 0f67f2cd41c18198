//! The candidates of the progressive joint-stratification study
//! (`docs/joint_study.md`): pixel samplers, built on the crate's
//! implementor face, whose successive draws of one domain take successive
//! dimensions of one Owen-scrambled Sobol' sequence, so that a bounce's
//! draws in call order are stratified jointly the way an orthogonal
//! array's page is, at any sample count.
//!
//! [`JointSobol`] reads a [`Candidate`]'s Sobol' dimensions, `block` of
//! them per copy: the domain's scalar dimension `d`
//! ([`Draw::dimension`]) reads dimension `d % block` of the sequence, and
//! each block `d / block` is an independent copy (its own index shuffle and
//! scrambles), which pads blocks as the crate pads pairs. `joint-sobol` is
//! pbrt-v4's `SobolSampler` read per pixel: every draw of a path one
//! dimension further along one sequence, Joe and Kuo's direction numbers
//! (`new-joe-kuo-6.21201`, their dimensions 1 to 21). `joint-sobol-4d` is
//! the nested 4D candidate (the crate's `Sobol4D` dimensions: a
//! (3,4)-sequence, (0,2) on its first pair). The study's winner, the
//! base-4 (0,4)-sequence, is the crate's `faure` kind (`Faure4D`).
//!
//! Per pixel sample and block the index goes through the crate's
//! `prefix_shuffle` (every power-of-two prefix stays one aligned block, so
//! each prefix of `2^m` samples is a net), keyed by the domain's key, and
//! each dimension is Owen-scrambled with its own seed: the same index
//! shuffle for every dimension of a block is what keeps the block's
//! dimensions jointly stratified.
//!
//! Not the crate: a study candidate, measured in the tracer's
//! direct-light scene and under `draw_cost`.

use wellspread::PixelSampler;
use wellspread::glam::{Vec2, Vec3, Vec4};
use wellspread::implement::{Draw, PixelSamplerHooks, Root};
use wellspread::primitives::{
    hash_combine, mix64, owen_scramble_reversed, prefix_shuffle, u32_to_unit_f32,
};

/// Dimensions of the one-sequence candidate: Joe and Kuo's first 21.
const MAX_BLOCK: u32 = 21;

/// Joe and Kuo's `s a m_1 .. m_s` for their dimensions 2 to 21 (the
/// first, the identity, has none); checked against SciPy's unscrambled
/// `qmc.Sobol` over the first 1024 points of every dimension.
const JOE_KUO: [(u32, u32, [u32; 7]); 20] = [
    (1, 0, [1, 0, 0, 0, 0, 0, 0]),
    (2, 1, [1, 3, 0, 0, 0, 0, 0]),
    (3, 1, [1, 3, 1, 0, 0, 0, 0]),
    (3, 2, [1, 1, 1, 0, 0, 0, 0]),
    (4, 1, [1, 1, 3, 3, 0, 0, 0]),
    (4, 4, [1, 3, 5, 13, 0, 0, 0]),
    (5, 2, [1, 1, 5, 5, 17, 0, 0]),
    (5, 4, [1, 1, 5, 5, 5, 0, 0]),
    (5, 7, [1, 1, 7, 11, 19, 0, 0]),
    (5, 11, [1, 1, 5, 1, 1, 0, 0]),
    (5, 13, [1, 1, 1, 3, 11, 0, 0]),
    (5, 14, [1, 3, 5, 5, 31, 0, 0]),
    (6, 1, [1, 3, 3, 9, 7, 49, 0]),
    (6, 13, [1, 1, 1, 15, 21, 21, 0]),
    (6, 16, [1, 3, 1, 13, 27, 49, 0]),
    (6, 19, [1, 1, 1, 15, 7, 5, 0]),
    (6, 22, [1, 3, 1, 15, 13, 25, 0]),
    (6, 25, [1, 1, 5, 5, 19, 61, 0]),
    (7, 1, [1, 3, 7, 11, 23, 15, 103]),
    (7, 4, [1, 3, 7, 13, 13, 15, 69]),
];

/// The direction numbers `v_1 .. v_32` of every dimension, in 0.32 fixed
/// point with their bits reversed (bit 0 the digit of weight 1/2), so that
/// a point is the xor of the columns of its index's set bits and
/// `owen_scramble_reversed` applies to it directly.
const COLUMNS: [[u32; 32]; MAX_BLOCK as usize] = {
    let mut out = [[0u32; 32]; MAX_BLOCK as usize];
    let mut k = 0;
    while k < 32 {
        out[0][k] = 1 << k; // the identity: v_k = 2^-k
        k += 1;
    }
    let mut d = 1;
    while d < MAX_BLOCK as usize {
        let (s, a, m) = JOE_KUO[d - 1];
        let s = s as usize;
        // v in natural order, v_k = m_k 2^(32 - k), by Bratley and Fox's
        // v_k = v_(k-s) ^ (v_(k-s) >> s) ^ sum_i a_i v_(k-i).
        let mut v = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            v[k] = if k < s {
                m[k] << (31 - k)
            } else {
                let mut x = v[k - s] ^ (v[k - s] >> s);
                let mut i = 1;
                while i < s {
                    if (a >> (s - 1 - i)) & 1 == 1 {
                        x ^= v[k - i];
                    }
                    i += 1;
                }
                x
            };
            out[d][k] = v[k].reverse_bits();
            k += 1;
        }
        d += 1;
    }
    out
};

/// The study's candidates: Joe and Kuo's Sobol' dimensions, read `block`
/// of them per copy.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Candidate {
    /// pbrt-v4's `SobolSampler` read per pixel: Joe and Kuo's first 21
    /// Sobol' dimensions, then a new copy.
    Sobol,
    /// Sobol' dimensions 0 to 3 (the crate's `Sobol4D`), a new copy every
    /// four.
    Sobol4D,
}

impl Candidate {
    /// Every candidate, in the order tables list them.
    pub const ALL: [Candidate; 2] = [Candidate::Sobol, Candidate::Sobol4D];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            Candidate::Sobol => "joint-sobol",
            Candidate::Sobol4D => "joint-sobol-4d",
        }
    }

    /// The candidate named `name`, if any.
    pub fn from_name(name: &str) -> Option<Candidate> {
        Candidate::ALL.into_iter().find(|c| c.name() == name)
    }

    /// Dimensions per copy.
    fn block(self) -> u32 {
        match self {
            Candidate::Sobol => MAX_BLOCK,
            Candidate::Sobol4D => 4,
        }
    }
}

/// A candidate: successive dimensions of one Owen-scrambled Sobol'
/// sequence per pixel sample, `block` dimensions before the next
/// independent copy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JointSobol {
    frame: u32,
    block: u32,
}

impl JointSobol {
    /// The study's candidate `candidate` for frame `frame`.
    pub fn candidate(candidate: Candidate, frame: u32) -> Self {
        Self {
            frame,
            block: candidate.block(),
        }
    }

    /// Scalar dimensions `draw.dimension ..` of the draw's sample: one
    /// `mix64` and one index shuffle per copy the draw reaches (once,
    /// unless it crosses into the next block), one table walk and scramble
    /// per dimension.
    #[inline(always)]
    fn values<const W: usize>(&self, draw: Draw) -> [f32; W] {
        let mut out = [0.0; W];
        let mut block: Option<(u32, u64, u32)> = None;
        for (dimension, x) in (draw.dimension..).zip(&mut out) {
            let (copy, within) = (dimension / self.block, dimension % self.block);
            let (h, mut i) = match block {
                Some((c, h, i)) if c == copy => (h, i),
                _ => {
                    let (h, i) = self.copy(draw, copy);
                    block = Some((copy, h, i));
                    (h, i)
                }
            };
            let column = &COLUMNS[within as usize];
            let mut point = 0u32;
            while i != 0 {
                point ^= column[i.trailing_zeros() as usize];
                i &= i - 1;
            }
            let seed = hash_combine((h >> 32) as u32, within);
            *x = u32_to_unit_f32(owen_scramble_reversed(point, seed).reverse_bits());
        }
        out
    }

    /// Copy `copy` of the draw's domain: its hash (the shuffle key in the
    /// low half, the scrambles' seed in the high half) and the shuffled
    /// index.
    #[inline(always)]
    fn copy(&self, draw: Draw, copy: u32) -> (u64, u32) {
        let h = mix64(draw.key ^ u64::from(copy).wrapping_mul(0x9e37_79b9_7f4a_7c15));
        (h, prefix_shuffle(draw.index, h as u32))
    }
}

impl PixelSampler for JointSobol {
    /// Progressive: any count.
    fn samples_per_pixel(&self) -> Option<u32> {
        None
    }
}

impl PixelSamplerHooks for JointSobol {
    fn root(&self, [x, y]: [u32; 2]) -> Root {
        Root {
            key: mix64((u64::from(y) << 32 | u64::from(x)) ^ u64::from(self.frame) << 48),
            pixel_state: 0,
        }
    }

    fn draw_1d(&self, draw: Draw) -> f32 {
        let [x] = self.values(draw);
        x
    }

    fn draw_2d(&self, draw: Draw) -> Vec2 {
        Vec2::from_array(self.values(draw))
    }

    fn draw_3d(&self, draw: Draw) -> Vec3 {
        Vec3::from_array(self.values(draw))
    }

    fn draw_4d(&self, draw: Draw) -> Vec4 {
        Vec4::from_array(self.values(draw))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wellspread::Domain;

    /// The points of one pixel in call order: `dims` successive 1D draws.
    fn points(sampler: &JointSobol, n: u32, dims: u32) -> Vec<Vec<f32>> {
        (0..n)
            .map(|i| {
                let mut d: Domain<&JointSobol> = Domain::start(sampler, [3, 5], i);
                (0..dims).map(|_| d.next_1d()).collect()
            })
            .collect()
    }

    /// Whether the pairs `(a, b)` of `points` put one point in each cell
    /// of a `cells x (n / cells)` grid, for every such split.
    fn is_net_pair(points: &[Vec<f32>], a: usize, b: usize) -> bool {
        let n = points.len();
        let mut cells = 1;
        while cells <= n {
            let rows = n / cells;
            let mut seen = vec![false; n];
            for p in points {
                let c = (p[a] * cells as f32) as usize * rows + (p[b] * rows as f32) as usize;
                if std::mem::replace(&mut seen[c], true) {
                    return false;
                }
            }
            cells *= 2;
        }
        true
    }

    #[test]
    fn first_pair_is_a_net_at_every_power_of_two_prefix() {
        let s = JointSobol::candidate(Candidate::Sobol, 7);
        for m in 0..=8 {
            let p = points(&s, 1 << m, 2);
            assert!(is_net_pair(&p, 0, 1), "prefix 2^{m}");
        }
    }

    #[test]
    fn dimensions_across_draws_are_stratified_together() {
        // Dimensions 0 and 4 of one sequence (the film's x and the light
        // choice in the tracer's call order): Joe and Kuo's dimensions 1
        // and 5, whose first 64 points fill every cell of the 8 x 8 grid
        // (SciPy's unscrambled points agree; the pair (0, 5) does not).
        let s = JointSobol::candidate(Candidate::Sobol, 2);
        let p = points(&s, 64, 5);
        let mut seen = [[0u32; 8]; 8];
        for q in &p {
            seen[(q[0] * 8.0) as usize][(q[4] * 8.0) as usize] += 1;
        }
        assert!(seen.iter().flatten().all(|&c| c == 1), "{seen:?}");
        // Blocks of 4: dimensions 0 and 4 are in different copies.
        let blocks = JointSobol::candidate(Candidate::Sobol4D, 2);
        let p = points(&blocks, 64, 5);
        let mut seen = [[0u32; 8]; 8];
        for q in &p {
            seen[(q[0] * 8.0) as usize][(q[4] * 8.0) as usize] += 1;
        }
        assert!(seen.iter().flatten().any(|&c| c != 1));
    }

    #[test]
    fn columns_match_the_first_points_of_joe_and_kuo() {
        // Dimension 2 (x^2 + x + 1, m = 1, 3): natural points 0, 1/2,
        // 1/4, 3/4, 3/8, 7/8, 1/8, 5/8 in natural index order.
        let eighths: Vec<u32> = (0..8u32)
            .map(|i| {
                let mut x = 0;
                for (k, column) in COLUMNS[2].iter().take(3).enumerate() {
                    if i >> k & 1 == 1 {
                        x ^= column;
                    }
                }
                x.reverse_bits() >> 29
            })
            .collect();
        assert_eq!(eighths, [0, 4, 6, 2, 3, 7, 5, 1]);
    }

    #[test]
    fn wide_draws_match_one_dimension_at_a_time() {
        // A draw's copy is computed once per block it reaches: the values
        // are those of successive 1D draws, across block ends too.
        for candidate in Candidate::ALL {
            let s = JointSobol::candidate(candidate, 9);
            for index in [0, 1, 5, 63, u32::MAX] {
                let mut wide: Domain<&JointSobol> = Domain::start(&s, [7, 2], index);
                let mut narrow: Domain<&JointSobol> = Domain::start(&s, [7, 2], index);
                let mut got = Vec::new();
                got.extend(wide.next_4d().to_array());
                got.extend(wide.next_3d().to_array());
                got.extend(wide.next_2d().to_array());
                got.push(wide.next_1d());
                got.extend(wide.next_4d().to_array());
                let want: Vec<f32> = (0..got.len()).map(|_| narrow.next_1d()).collect();
                assert_eq!(got, want, "{candidate:?}, index {index}");
            }
        }
    }
}
