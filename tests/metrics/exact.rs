//! Exact L2-star and centred L2 discrepancies of points on the 2^-32 grid,
//! in integer arithmetic: the reference the double-double code is held to.
//!
//! With `X = 2^32 x`, every sum in the two formulas is an integer over a
//! power of two, so the squared discrepancy is one 256-bit integer over a
//! known denominator; only the last step (one division) rounds. Written
//! independently of the library's code (different sums, different order).

use wellspread::glam::Vec2;

/// A non-negative integer below 2^256, four 64-bit limbs, lowest first.
/// Every operation panics on overflow or underflow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct U256([u64; 4]);

impl U256 {
    pub fn from_u128(v: u128) -> Self {
        U256([v as u64, (v >> 64) as u64, 0, 0])
    }

    pub fn add(self, o: Self) -> Self {
        let mut out = [0u64; 4];
        let mut carry = 0u128;
        for (k, limb) in out.iter_mut().enumerate() {
            let s = u128::from(self.0[k]) + u128::from(o.0[k]) + carry;
            *limb = s as u64;
            carry = s >> 64;
        }
        assert_eq!(carry, 0, "U256 overflow");
        U256(out)
    }

    pub fn sub(self, o: Self) -> Self {
        let mut out = [0u64; 4];
        let mut borrow = 0u64;
        for (k, limb) in out.iter_mut().enumerate() {
            let (d, b1) = self.0[k].overflowing_sub(o.0[k]);
            let (d, b2) = d.overflowing_sub(borrow);
            *limb = d;
            borrow = u64::from(b1 || b2);
        }
        assert_eq!(borrow, 0, "U256 underflow");
        U256(out)
    }

    pub fn mul_u64(self, m: u64) -> Self {
        let mut out = [0u64; 4];
        let mut carry = 0u128;
        for (k, limb) in out.iter_mut().enumerate() {
            let p = u128::from(self.0[k]) * u128::from(m) + carry;
            *limb = p as u64;
            carry = p >> 64;
        }
        assert_eq!(carry, 0, "U256 overflow");
        U256(out)
    }

    pub fn mul_u128(self, m: u128) -> Self {
        let high = self.mul_u64((m >> 64) as u64);
        assert_eq!(high.0[3], 0, "U256 overflow");
        let shifted = U256([0, high.0[0], high.0[1], high.0[2]]);
        self.mul_u64(m as u64).add(shifted)
    }

    /// Times `2^bits`.
    pub fn shl(self, bits: u32) -> Self {
        let mut v = self;
        for _ in 0..bits / 32 {
            v = v.mul_u64(1 << 32);
        }
        v.mul_u64(1 << (bits % 32))
    }

    /// The nearest f64, within a few units in the last place.
    pub fn to_f64(self) -> f64 {
        let limb = 18_446_744_073_709_551_616.0; // 2^64
        self.0
            .iter()
            .rev()
            .fold(0.0, |acc, &l| acc * limb + l as f64)
    }
}

/// `2^32 v`, which must be an integer (the point is on the 2^-32 grid).
fn fixed(v: f32) -> u64 {
    let scaled = f64::from(v) * 4_294_967_296.0;
    assert_eq!(scaled, scaled.floor(), "{v:e} is not on the 2^-32 grid");
    scaled as u64
}

/// `Σ_i Σ_j min(p_i, p_j) min(q_i, q_j)` over all ordered pairs, for
/// integers below 2^32 and at most 2^24 pairs `(p, q)`, exactly.
fn sum_min_min(values: &[(u64, u64)]) -> u128 {
    let n = values.len();
    let mut by_q: Vec<usize> = (0..n).collect();
    by_q.sort_by_key(|&i| values[i].1);
    let mut rank = vec![0usize; n];
    for (r, &i) in by_q.iter().enumerate() {
        rank[i] = r + 1;
    }
    let mut by_p: Vec<usize> = (0..n).collect();
    by_p.sort_by_key(|&i| std::cmp::Reverse(values[i].0));
    // Fenwick tree over q ranks: counts and sums of q (below 2^56).
    let (mut count, mut sum) = (vec![0u64; n + 1], vec![0u64; n + 1]);
    let mut total = 0u128;
    for (seen, &i) in by_p.iter().enumerate() {
        let (p, q) = values[i];
        let (mut below, mut below_sum) = (0u64, 0u64);
        let mut k = rank[i] - 1;
        while k > 0 {
            below += count[k];
            below_sum += sum[k];
            k &= k - 1;
        }
        let above = seen as u64 - below;
        // Twice for (i, j) and (j, i), plus the diagonal.
        let inner = u128::from(q) * u128::from(above) + u128::from(below_sum);
        total += 2 * u128::from(p) * inner + u128::from(p) * u128::from(q);
        let mut k = rank[i];
        while k <= n {
            count[k] += 1;
            sum[k] += q;
            k += k & k.wrapping_neg();
        }
    }
    total
}

/// `Σ_i Σ_j min(a_i, a_j)` over all ordered pairs, exactly.
fn sum_min(values: &mut [u64]) -> u128 {
    values.sort_unstable_by(|a, b| b.cmp(a));
    (0..values.len())
        .map(|k| u128::from(values[k]) * (2 * k as u128 + 1))
        .sum()
}

/// The exact `T²` (L2-star, Warnock's formula) of points on the 2^-32 grid,
/// rounded once to f64.
///
/// With `P = 2^32 (1 - x)`: `18 n² 2^128 T² = 2 n² 2^128
/// - 9 n Σ (2^64 - X²)(2^64 - Y²) + 18 2^64 Σ Σ min(P) min(Q)`.
pub fn l2_star_squared(points: &[Vec2]) -> f64 {
    let n = points.len() as u64;
    let one = 1u64 << 32;
    let mut single = U256::from_u128(0);
    let mut mins = Vec::with_capacity(points.len());
    for p in points {
        let (x, y) = (fixed(p.x), fixed(p.y));
        let fx = (1u128 << 64) - u128::from(x) * u128::from(x);
        let fy = (1u128 << 64) - u128::from(y) * u128::from(y);
        single = single.add(U256::from_u128(fx).mul_u128(fy));
        mins.push((one - x, one - y));
    }
    let pairs = sum_min_min(&mins);
    let numerator = U256::from_u128(u128::from(2 * n * n))
        .shl(128)
        .add(U256::from_u128(pairs).mul_u64(18).shl(64))
        .sub(single.mul_u64(9 * n));
    numerator.to_f64() / (18.0 * (n * n) as f64) / 2f64.powi(128)
}

/// The exact `CD²` (Hickernell's centred L2) of points on the 2^-32 grid,
/// rounded once to f64.
///
/// With `A = 2^32 |x - 1/2|` and `G = 2^32 A - A²` (so `|u|/2 - u²/2 = G 2^-65`):
/// `144 n² 2^130 CD² = 25 n² 2^130 - 288 n Σ ((Gx + Gy) 2^65 + Gx Gy)
/// + 144 2^66 (2^32 Σ_halves Σ Σ min(A) + Σ_quadrants Σ Σ min(Ax) min(Ay))`.
pub fn centered_l2_squared(points: &[Vec2]) -> f64 {
    let n = points.len() as u64;
    let half = 1u64 << 31;
    let mut single = U256::from_u128(0);
    let mut halves: [Vec<u64>; 4] = Default::default();
    let mut quadrants: [Vec<(u64, u64)>; 4] = Default::default();
    for p in points {
        let (x, y) = (fixed(p.x), fixed(p.y));
        let (ax, ay) = (x.abs_diff(half), y.abs_diff(half));
        let g = |a: u64| (u128::from(a) << 32) - u128::from(a) * u128::from(a);
        let (gx, gy) = (g(ax), g(ay));
        single = single
            .add(U256::from_u128(gx + gy).shl(65))
            .add(U256::from_u128(gx).mul_u128(gy));
        let (sx, sy) = (usize::from(x >= half), usize::from(y >= half));
        halves[sx].push(ax);
        halves[2 + sy].push(ay);
        quadrants[2 * sx + sy].push((ax, ay));
    }
    let one_d: u128 = halves.iter_mut().map(|h| sum_min(h)).sum();
    let two_d: u128 = quadrants.iter().map(|q| sum_min_min(q)).sum();
    let pairs = U256::from_u128(one_d).shl(32).add(U256::from_u128(two_d));
    let numerator = U256::from_u128(u128::from(25 * n * n))
        .shl(130)
        .add(pairs.mul_u64(144).shl(66))
        .sub(single.mul_u64(288 * n));
    numerator.to_f64() / (144.0 * (n * n) as f64) / 2f64.powi(130)
}

#[test]
fn exact_forms_of_one_point() {
    // T² = 1/9 - 1/2 + 1 at the origin; CD² = (13/12)² - 2 + 1 at the centre.
    assert_eq!(l2_star_squared(&[Vec2::ZERO]), 11.0 / 18.0);
    assert_eq!(centered_l2_squared(&[Vec2::splat(0.5)]), 25.0 / 144.0);
    // One point at (1/4, 3/4): T² = 1/9 - (15/16)(7/16)/2 + (3/4)(1/4),
    // CD² = (13/12)² - 2 (1 + 1/8 - 1/32)² + (1 + 1/4)².
    let p = [Vec2::new(0.25, 0.75)];
    let t2 = 1.0 / 9.0 - 105.0 / 512.0 + 3.0 / 16.0;
    assert!((l2_star_squared(&p) - t2).abs() <= 1e-16 * t2);
    let cd2 = (13.0f64 / 12.0).powi(2) - 2.0 * (35.0f64 / 32.0).powi(2) + 1.5625;
    assert!((centered_l2_squared(&p) - cd2).abs() <= 1e-15 * cd2);
}
