//! Hickernell's wrap-around L2 discrepancy: moment sums, sorted sweeps and
//! an exact dominance sum, and the direct O(n²) sum kept as its reference.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use super::{key_value, keys_in_place, pack_low_halves, packed, set_packed, sorted_keys};
use crate::error::Error;
use crate::metrics::double_double::{Dd, two_prod};
use crate::metrics::{coord, validate};

/// Wrap-around L2 discrepancy (Hickernell 1998): the L2 discrepancy over all
/// boxes of the torus,
///
/// `WD² = -(4/3)² + 1/n² Σ_i Σ_j Π_k (3/2 - |x_ik - x_jk| (1 - |x_ik - x_jk|))`.
///
/// Returns `WD` itself. Note that `scipy.stats.qmc.discrepancy(method="WD")`
/// returns `WD²` (scipy issue 19839); square this value to compare.
///
/// # Algorithm
///
/// With `g(d) = d² - d`, each factor is `3/2 + g(d)`, so
///
/// `n² WD² = 17/36 n² + 3/2 Σ Σ (g(dx) + g(dy)) + Σ Σ g(dx) g(dy)`,
///
/// and every double sum splits into sums of `dx² dy²`, `|dx| dy²`, `dx² |dy|`,
/// `|dx| |dy|` and their 1D parts:
///
/// - `dx²`, `dx² dy²`: products of the moments `Σ x^a y^b` (a, b <= 2);
/// - `|dx|`, `|dx| dy²`: one sweep in increasing x with prefix sums of
///   `x`, `y`, `y²`, `x y`, `x y²` (and `dx² |dy|` the same in y);
/// - `|dx| |dy|`: `|dy| = (y_i - y_j) + 2 (y_j - y_i) [y_i < y_j]` turns it into a
///   separable sum plus twice the dominance sum `Σ (x_j - x_i)(y_j - y_i)` over
///   the pairs with `x_i <= x_j` and `y_i < y_j`: a sweep in increasing x with
///   a Fenwick tree over the y ranks holding counts and sums of `x`, `y`, `x y`
///   (in exact 128-bit integers when every coordinate is a multiple of 2^-32,
///   as sampler output is; in double-double otherwise).
///
/// O(n log n) time (two radix sorts, one in place, and the sweeps), O(n)
/// memory: about 16 bytes a point at the peak beyond the input (20 for a set
/// with coordinates off the 2^-32 grid, whose double-double tree is larger).
/// The terms
/// are of order `n²` and cancel down to `n² WD²`, which is as small as `1e-8 n²`
/// for good sets at 2^14 points, so every sum is accumulated in double-double
/// arithmetic (Dekker 1971): products of f32 coordinates are exact there, and
/// the result keeps about 1e-14 relative accuracy even where `WD²` is 1e-16 of
/// the terms (tests compare it with the direct double sum to 1e-12).
///
/// # Errors
///
/// As [`star_discrepancy`](crate::metrics::star_discrepancy).
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::wraparound_l2_discrepancy};
/// // One point: WD² = (3/2)² - (4/3)² = 17/36.
/// let wd = wraparound_l2_discrepancy(&[Vec2::new(0.3, 0.9)])?;
/// assert!((wd - (17.0f64 / 36.0).sqrt()).abs() < 1e-15);
/// // Two points half a period apart on both axes: the pair's term is
/// // (3/2 - 1/4)² on either side of the diagonal's two (3/2)².
/// let two = [Vec2::new(0.0, 0.0), Vec2::new(0.5, 0.5)];
/// let direct = (2.25f64 + 1.25 * 1.25) / 2.0 - 16.0 / 9.0;
/// assert!((wraparound_l2_discrepancy(&two)? - direct.sqrt()).abs() < 1e-15);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn wraparound_l2_discrepancy(points: &[Vec2]) -> Result<f64, Error> {
    validate(points)?;
    Ok(libm::sqrt(wraparound_sweep(points).max(0.0)))
}

/// `WD²` by the O(n log n) decomposition of [`wraparound_l2_discrepancy`].
fn wraparound_sweep(points: &[Vec2]) -> f64 {
    let n = points.len();
    let nf = n as f64;
    // Moments S_ab = Σ x^a y^b. x y, x², y² are exact in f64 (f32 inputs);
    // x² y, x y², x² y² are exact as double-double products.
    let mut s = [[Dd::ZERO; 3]; 3];
    for p in points {
        let (x, y) = (coord(p.x), coord(p.y));
        let xy = x * y;
        s[1][0] = s[1][0].plus_f64(x);
        s[0][1] = s[0][1].plus_f64(y);
        s[2][0] = s[2][0].plus_f64(x * x);
        s[0][2] = s[0][2].plus_f64(y * y);
        s[1][1] = s[1][1].plus_f64(xy);
        s[2][1] = s[2][1].plus(two_prod(xy, x));
        s[1][2] = s[1][2].plus(two_prod(xy, y));
        s[2][2] = s[2][2].plus(two_prod(xy, xy));
    }
    // Ordered pairs, diagonal included (its terms are 0):
    // Σ Σ dx² = 2 n S20 - 2 S10².
    let sq = |a2: Dd, a1: Dd| a2.mul_f64(2.0 * nf).sub(a1.mul(a1).mul_f64(2.0));
    let sum_dx2 = sq(s[2][0], s[1][0]);
    let sum_dy2 = sq(s[0][2], s[0][1]);
    // Σ Σ dx² dy² = 2n S22 - 4 S21 S01 - 4 S12 S10 + 2 S20 S02 + 4 S11².
    let sum_dx2_dy2 = s[2][2]
        .mul_f64(2.0 * nf)
        .sub(s[2][1].mul(s[0][1]).mul_f64(4.0))
        .sub(s[1][2].mul(s[1][0]).mul_f64(4.0))
        .add(s[2][0].mul(s[0][2]).mul_f64(2.0))
        .add(s[1][1].mul(s[1][1]).mul_f64(4.0));

    // The x order first, kept as point indices packed two to a u64; then
    // the y order, kept as each rank's y and x bits; the indices of the x
    // order then become ranks. At most 16 bytes a point are alive.
    let keys_x = sorted_keys(points, |p| p.x);
    // The other coordinate is gathered first (as f32, 4 bytes a point) by
    // a short loop, whose random loads overlap.
    let gather = |keys: &[u64], axis: fn(&Vec2) -> f32| -> Vec<f32> {
        keys.iter()
            .map(|&k| axis(&points[k as u32 as usize]))
            .collect()
    };
    // The sweep along the keys' coordinate, the other one gathered.
    let sweep_along = |keys: &[u64], other: fn(&Vec2) -> f32| {
        let other_by_key = gather(keys, other);
        absolute_sweep(
            n,
            keys.iter()
                .zip(&other_by_key)
                .map(|(&k, &o)| (coord(key_value(k)), coord(o))),
        )
    };
    let (abs_dx, abs_dx_dy2) = sweep_along(&keys_x, |p| p.y);
    let mut order = pack_low_halves(keys_x);
    let mut by_rank = keys_in_place(points, |p| p.y);
    let (abs_dy, dx2_abs_dy) = sweep_along(&by_rank, |p| p.x);
    let fixed = fits_fixed(points);
    let mut rank = vec![0u32; n];
    for (r, key) in by_rank.iter_mut().enumerate() {
        let i = *key as u32 as usize;
        rank[i] = r as u32;
        *key = Sweep::encode(points[i], fixed);
    }
    for k in 0..n {
        let r = rank[packed(&order, k) as usize];
        set_packed(&mut order, k, r);
    }
    drop(rank);
    let sweep = Sweep {
        order: &order,
        by_rank: &by_rank,
    };
    let concordant = if fixed {
        dominance_sweep_fixed(&sweep)
    } else {
        dominance_sweep(&sweep)
    };
    // Σ_{i<j} (x_j - x_i)(y_j - y_i) over unordered pairs = n S11 - S10 S01.
    let product = s[1][1].mul_f64(nf).sub(s[1][0].mul(s[0][1]));
    // Unordered Σ |dx| |dy| = concordant part twice minus the product sum.
    let abs_dx_abs_dy = concordant.mul_f64(2.0).sub(product);

    // The |.| sums are over unordered pairs: double them.
    let g_x = sum_dx2.sub(abs_dx.mul_f64(2.0));
    let g_y = sum_dy2.sub(abs_dy.mul_f64(2.0));
    let h = sum_dx2_dy2
        .sub(dx2_abs_dy.mul_f64(2.0))
        .sub(abs_dx_dy2.mul_f64(2.0))
        .add(abs_dx_abs_dy.mul_f64(2.0));
    let total = Dd::ratio(17.0, 36.0)
        .mul_f64(nf * nf)
        .add(g_x.add(g_y).mul_f64(1.5))
        .add(h);
    total.value() / (nf * nf)
}

/// The items of `items`, taken `CHUNK` at a time: the random loads that
/// producing an item makes are then issued by one short loop, where they
/// overlap, rather than one per step of a sweep's long loop body.
fn read_ahead<T: Copy + Default>(mut items: impl Iterator<Item = T>) -> impl Iterator<Item = T> {
    const CHUNK: usize = 256;
    let mut buffer = [T::default(); CHUNK];
    let (mut len, mut next) = (0, 0);
    core::iter::from_fn(move || {
        if next == len {
            len = 0;
            for (slot, item) in buffer.iter_mut().zip(&mut items) {
                *slot = item;
                len += 1;
            }
            next = 0;
        }
        (next < len).then(|| {
            next += 1;
            buffer[next - 1]
        })
    })
}

/// Over the unordered pairs, with `u` in increasing order:
/// `(Σ |u_j - u_i|, Σ |u_j - u_i| (v_j - v_i)²)`, in double-double.
fn absolute_sweep(n: usize, uv: impl Iterator<Item = (f64, f64)>) -> (Dd, Dd) {
    let n = n as f64;
    let mut abs = Dd::ZERO;
    // Prefix sums over the earlier points: u, v, v², u v, u v².
    let (mut a, mut b, mut c, mut d, mut e) = (Dd::ZERO, Dd::ZERO, Dd::ZERO, Dd::ZERO, Dd::ZERO);
    // Σ_j of: u_j C, u_j v_j B, k u_j v_j², E, v_j D, v_j² A. Every factor
    // taken from the point is an f32 value (or the count k), so the products
    // are the cheap short ones.
    let mut p = [Dd::ZERO; 6];
    for (k, (uj, vj)) in uv.enumerate() {
        // The k-th smallest u is the larger of k pairs and the smaller of n-1-k.
        abs = abs.plus(two_prod(uj, 2.0 * k as f64 - n + 1.0));
        let uv = uj * vj;
        let v2 = vj * vj;
        let uv2 = Dd { hi: uv, lo: 0.0 }.mul_short(vj);
        p[0] = p[0].plus(c.mul_short(uj));
        p[1] = p[1].plus(b.mul_short(vj).mul_short(uj));
        p[2] = p[2].plus(uv2.mul(Dd {
            hi: k as f64,
            lo: 0.0,
        }));
        p[3] = p[3].plus(e);
        p[4] = p[4].plus(d.mul_short(vj));
        p[5] = p[5].plus(a.mul_short(vj).mul_short(vj));
        a = a.plus_f64(uj);
        b = b.plus_f64(vj);
        c = c.plus_f64(v2);
        d = d.plus_f64(uv);
        e = e.plus(uv2);
    }
    // Σ_{i<j} (u_j - u_i)(v_i² - 2 v_i v_j + v_j²).
    let weighted = p[0]
        .sub(p[1].mul_f64(2.0))
        .add(p[2])
        .sub(p[3])
        .add(p[4].mul_f64(2.0))
        .sub(p[5]);
    (abs, weighted)
}

/// The points in increasing x (ties in index order) as their y ranks
/// (packed two to a u64), and per y rank the point's coordinates as
/// `y << 32 | x`, each as its f32 bits or, for [`dominance_sweep_fixed`],
/// as `2^32` times its value.
struct Sweep<'a> {
    order: &'a [u64],
    by_rank: &'a [u64],
}

impl Sweep<'_> {
    /// A point's entry of `by_rank`.
    fn encode(p: Vec2, fixed: bool) -> u64 {
        let code = |v: f32| {
            if fixed {
                (coord(v) * 4_294_967_296.0) as u32
            } else {
                f32::to_bits(v) & 0x7fff_ffff
            }
        };
        u64::from(code(p.y)) << 32 | u64::from(code(p.x))
    }

    fn len(&self) -> usize {
        self.by_rank.len()
    }

    /// The y rank of the k-th point in x order.
    #[inline]
    fn rank(&self, k: usize) -> usize {
        packed(self.order, k) as usize
    }

    /// The coordinates of the point of y rank `r`, as encoded.
    #[inline]
    fn point(&self, r: usize) -> (u32, u32) {
        let key = self.by_rank[r];
        (key as u32, (key >> 32) as u32)
    }

    /// The coordinates of the point of y rank `r`, of f32 bits.
    #[inline]
    fn float_point(&self, r: usize) -> (f64, f64) {
        let (x, y) = self.point(r);
        (f64::from(f32::from_bits(x)), f64::from(f32::from_bits(y)))
    }
}

/// `Σ (x_j - x_i)(y_j - y_i)` over the pairs with `x_i <= x_j` and `y_i < y_j`
/// (pairs tied in x or y add 0 whichever way they are counted), given the
/// points in increasing x with the ranks of their y, in double-double
/// ([`FloatSums`]) or, for the points of [`fits_fixed`] sets, exactly
/// ([`FixedSums`]).
///
/// Two levels: a Fenwick tree over blocks of `S::RUN` consecutive ranks,
/// and per block a bit per rank whose point is inserted (its coordinates
/// come from `sweep`). The partial block below a rank is a short scan, and
/// the tree is `S::RUN` times smaller, so fewer of its levels miss the
/// cache.
fn dominance_sweep_with<S: DominanceSums>(sweep: &Sweep) -> Dd {
    let n = sweep.len();
    let blocks = n.div_ceil(S::RUN);
    let mut tree = vec![S::default(); blocks + 1];
    let mut inserted = vec![0u16; blocks];
    // Σ_j of: count x_j y_j, x_j Σy, y_j Σx, Σ x y over the points below j.
    let mut t = [S::Total::default(); 4];
    for (r, (xj, yj)) in read_ahead((0..n).map(|k| {
        let r = sweep.rank(k);
        (r, S::point(sweep, r))
    })) {
        let block = r / S::RUN;
        let mut below = S::default();
        // The inserted ranks of the block below r, in increasing order (an
        // empty rank would add zeros).
        let mut bits = inserted[block] & ((1u32 << (r % S::RUN)) - 1) as u16;
        while bits != 0 {
            let (x, y) = S::point(sweep, block * S::RUN + bits.trailing_zeros() as usize);
            bits &= bits - 1;
            below.insert(x, y);
        }
        let mut b = block;
        while b > 0 {
            below.merge(&tree[b]);
            b &= b - 1;
        }
        below.accumulate(&mut t, xj, yj);
        inserted[block] |= 1 << (r % S::RUN);
        let mut b = block + 1;
        while b <= blocks {
            tree[b].insert(xj, yj);
            b += b & b.wrapping_neg();
        }
    }
    S::finish(t)
}

/// What a [`dominance_sweep_with`] keeps per Fenwick node and per rank:
/// how many points and the sums of their x, y and x y.
trait DominanceSums: Copy + Default {
    /// Ranks per block of the two-level tree, at most 16.
    const RUN: usize;
    /// One coordinate as the sweep reads it.
    type Coord: Copy + Default;
    /// One of the four sums over `j`.
    type Total: Copy + Default;
    /// The coordinates of the point of y rank `r`.
    fn point(sweep: &Sweep, r: usize) -> (Self::Coord, Self::Coord);
    /// Adds one point.
    fn insert(&mut self, x: Self::Coord, y: Self::Coord);
    /// Adds a node's sums.
    fn merge(&mut self, node: &Self);
    /// Adds point `j`'s terms against the points below it (`self`).
    fn accumulate(&self, t: &mut [Self::Total; 4], xj: Self::Coord, yj: Self::Coord);
    /// `t[0] - t[1] - t[2] + t[3]`, the sum over the pairs.
    fn finish(t: [Self::Total; 4]) -> Dd;
}

/// [`DominanceSums`] in double-double, for any f32 coordinates.
#[derive(Clone, Copy, Debug, Default)]
#[repr(align(64))]
struct FloatSums {
    count: f64,
    x: Dd,
    y: Dd,
    xy: Dd,
}

impl DominanceSums for FloatSums {
    const RUN: usize = 8;
    type Coord = f64;
    type Total = Dd;

    #[inline(always)]
    fn point(sweep: &Sweep, r: usize) -> (f64, f64) {
        sweep.float_point(r)
    }

    #[inline(always)]
    fn insert(&mut self, x: f64, y: f64) {
        self.count += 1.0;
        self.x = self.x.plus_f64(x);
        self.y = self.y.plus_f64(y);
        self.xy = self.xy.plus_f64(x * y);
    }

    #[inline(always)]
    fn merge(&mut self, node: &Self) {
        self.count += node.count;
        self.x = self.x.plus(node.x);
        self.y = self.y.plus(node.y);
        self.xy = self.xy.plus(node.xy);
    }

    #[inline(always)]
    fn accumulate(&self, t: &mut [Dd; 4], xj: f64, yj: f64) {
        t[0] = t[0].plus(two_prod(self.count, xj * yj));
        t[1] = t[1].plus(self.y.mul_short(xj));
        t[2] = t[2].plus(self.x.mul_short(yj));
        t[3] = t[3].plus(self.xy);
    }

    fn finish(t: [Dd; 4]) -> Dd {
        t[0].sub(t[1]).sub(t[2]).add(t[3])
    }
}

/// [`DominanceSums`] in exact integer arithmetic, with `X = 2^32 x`, for
/// the points of [`fits_fixed`] sets. The Fenwick sums of `X`, `Y` and
/// `X Y` and the four sums over `j` stay below `n² 2^64`, so u128 holds
/// them exactly for n up to 2^31; being exact, they do not depend on the
/// tree's shape, whose blocks are twice as long here.
#[derive(Clone, Copy, Default)]
struct FixedSums {
    count: u64,
    x: u64,
    y: u64,
    xy: u128,
}

impl DominanceSums for FixedSums {
    const RUN: usize = 16;
    type Coord = u32;
    type Total = u128;

    #[inline(always)]
    fn point(sweep: &Sweep, r: usize) -> (u32, u32) {
        sweep.point(r)
    }

    #[inline(always)]
    fn insert(&mut self, x: u32, y: u32) {
        self.count += 1;
        self.x += u64::from(x);
        self.y += u64::from(y);
        self.xy += u128::from(x) * u128::from(y);
    }

    #[inline(always)]
    fn merge(&mut self, node: &Self) {
        self.count += node.count;
        self.x += node.x;
        self.y += node.y;
        self.xy += node.xy;
    }

    #[inline(always)]
    fn accumulate(&self, t: &mut [u128; 4], xj: u32, yj: u32) {
        t[0] += u128::from(self.count) * (u128::from(xj) * u128::from(yj));
        t[1] += u128::from(self.y) * u128::from(xj);
        t[2] += u128::from(self.x) * u128::from(yj);
        t[3] += self.xy;
    }

    /// Σ (X_j - X_i)(Y_j - Y_i) >= 0 over the pairs, exactly, then times
    /// 2^-64.
    fn finish(t: [u128; 4]) -> Dd {
        const ONE: f64 = 4_294_967_296.0; // 2^32
        let total = (t[0] + t[3]) - (t[1] + t[2]);
        let hi = total as f64;
        let rest = total as i128 - hi as i128;
        let scale = 1.0 / (ONE * ONE);
        Dd {
            hi: hi * scale,
            lo: rest as f64 * scale,
        }
    }
}

/// The sweep for any f32 coordinates.
fn dominance_sweep(sweep: &Sweep) -> Dd {
    dominance_sweep_with::<FloatSums>(sweep)
}

/// The exact sweep for the points of [`fits_fixed`] sets.
fn dominance_sweep_fixed(sweep: &Sweep) -> Dd {
    dominance_sweep_with::<FixedSums>(sweep)
}

/// Whether [`dominance_sweep_fixed`] applies: every coordinate a multiple
/// of 2^-32 (as every sampler's output and every f32 at or above 2^-8 is),
/// and n below 2^31.
fn fits_fixed(points: &[Vec2]) -> bool {
    let on_grid = |v: f32| {
        let scaled = coord(v) * 4_294_967_296.0;
        scaled == libm::floor(scaled)
    };
    points.len() < 1 << 31 && points.iter().all(|p| on_grid(p.x) && on_grid(p.y))
}

/// The direct O(n²) double sum for [`wraparound_l2_discrepancy`], kept as the
/// reference its unit tests compare against (test builds only).
///
/// Every pair term, `(4/3)²` subtracted and the sum are in double-double
/// (f64 terms have rounding errors that add up systematically on lattices,
/// to 1e-11 relative at 4096 points), in a
/// vectorisable inner loop: about 90 flops per pair.
#[cfg(test)]
pub(crate) fn wraparound_l2_discrepancy_quadratic(points: &[Vec2]) -> Result<f64, Error> {
    validate(points)?;
    let n = points.len();
    let nf = n as f64;
    let xs: Vec<f64> = points.iter().map(|p| coord(p.x)).collect();
    let ys: Vec<f64> = points.iter().map(|p| coord(p.y)).collect();
    let mut off_diagonal = Dd::ZERO;
    for i in 0..n {
        off_diagonal = off_diagonal.add(wraparound_row(&xs, &ys, i));
    }
    // Diagonal: (3/2)² - (4/3)² = 17/36 per point.
    let total = Dd::ratio(17.0, 36.0)
        .mul_f64(nf)
        .add(off_diagonal.mul_f64(2.0));
    Ok(libm::sqrt((total.value() / (nf * nf)).max(0.0)))
}

/// `Σ_{j > i} (f(dx) f(dy) - 16/9)` with `f(d) = 3/2 - d (1 - d)`, each term
/// and the sum in double-double.
#[cfg(test)]
fn wraparound_row(xs: &[f64], ys: &[f64], i: usize) -> Dd {
    use crate::metrics::double_double::two_sum;
    let mean = Dd::ratio(16.0, 9.0);
    // f(d) = 3/2 + (d² - d) as hi + lo; d itself is exact for f32 inputs
    // whose exponents differ by less than 29.
    #[inline(always)]
    fn factor(d: f64) -> (f64, f64) {
        let sq = two_prod(d, d);
        let (g, g_err) = two_sum(sq.hi, -d);
        let (f, f_err) = two_sum(1.5, g);
        (f, f_err + g_err + sq.lo)
    }
    #[inline(always)]
    fn term(xi: f64, yi: f64, xj: f64, yj: f64, mean: Dd) -> (f64, f64) {
        let (fx, fx_lo) = factor((xi - xj).abs());
        let (fy, fy_lo) = factor((yi - yj).abs());
        let p = two_prod(fx, fy);
        // p.hi and mean.hi are both in [1.5, 2.25]: their difference is exact.
        (p.hi - mean.hi, p.lo + fx * fy_lo + fx_lo * fy - mean.lo)
    }
    let (xi, yi) = (xs[i], ys[i]);
    let (rx, ry) = (&xs[i + 1..], &ys[i + 1..]);
    // Four lanes (vectorisable) of TwoSum-compensated sums per block of 64
    // terms; the block sums are added in double-double.
    const BLOCK: usize = 64;
    let mut row = Dd::ZERO;
    let (bx, by) = (rx.chunks(BLOCK), ry.chunks(BLOCK));
    for (cx, cy) in bx.zip(by) {
        let mut hi = [0.0f64; 4];
        let mut lo = [0.0f64; 4];
        let (qx, qy) = (cx.chunks_exact(4), cy.chunks_exact(4));
        let (tail_x, tail_y) = (qx.remainder(), qy.remainder());
        for (ax, ay) in qx.zip(qy) {
            for l in 0..4 {
                let (t, t_lo) = term(xi, yi, ax[l], ay[l], mean);
                let (s, e) = two_sum(hi[l], t);
                hi[l] = s;
                lo[l] += e + t_lo;
            }
        }
        for (&xj, &yj) in tail_x.iter().zip(tail_y) {
            let (t, t_lo) = term(xi, yi, xj, yj, mean);
            let (s, e) = two_sum(hi[0], t);
            hi[0] = s;
            lo[0] += e + t_lo;
        }
        for l in 0..4 {
            row = row.add(Dd {
                hi: hi[l],
                lo: lo[l],
            });
        }
    }
    row
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dominance_sweeps_agree() {
        let mut state = 7u64;
        let mut next = || {
            state += 1;
            crate::primitives::mix64(state)
        };
        for n in [1usize, 2, 9, 100, 3000] {
            // On the 2^-32 grid, with ties in both coordinates.
            let mut xs: Vec<f64> = (0..n)
                .map(|_| f64::from((next() >> 40) as u32 & !0xf) / 16_777_216.0)
                .collect();
            let ys: Vec<f64> = (0..n)
                .map(|_| f64::from((next() >> 40) as u32 % 50) / 64.0)
                .collect();
            xs.sort_by(f64::total_cmp);
            let mut by_y: Vec<usize> = (0..n).collect();
            by_y.sort_by(|&a, &b| ys[a].total_cmp(&ys[b]));
            let mut ranks = vec![0u32; n];
            for (r, &i) in by_y.iter().enumerate() {
                ranks[i] = r as u32;
            }
            let mut order = vec![0u64; n.div_ceil(2)];
            let (mut fixed_by_rank, mut float_by_rank) = (vec![0u64; n], vec![0u64; n]);
            for k in 0..n {
                set_packed(&mut order, k, ranks[k]);
                let p = Vec2::new(xs[k] as f32, ys[k] as f32);
                fixed_by_rank[ranks[k] as usize] = Sweep::encode(p, true);
                float_by_rank[ranks[k] as usize] = Sweep::encode(p, false);
            }
            let fixed = dominance_sweep_fixed(&Sweep {
                order: &order,
                by_rank: &fixed_by_rank,
            });
            let float = dominance_sweep(&Sweep {
                order: &order,
                by_rank: &float_by_rank,
            });
            let mut brute = 0.0;
            for j in 0..n {
                for i in 0..j {
                    if ys[i] < ys[j] {
                        brute += (xs[j] - xs[i]) * (ys[j] - ys[i]);
                    }
                }
            }
            let diff = fixed.sub(float).value().abs();
            assert!(diff <= 1e-28 * fixed.value().max(1.0), "n = {n}: {diff:e}");
            assert!((fixed.value() - brute).abs() <= 1e-12 * brute.max(1.0));
        }
        assert!(fits_fixed(&[Vec2::new(0.25, 0.5), Vec2::new(0.0, 0.75)]));
        assert!(!fits_fixed(&[Vec2::new(0.25, 0.5), Vec2::new(1e-30, 0.5)]));
    }

    /// Point sets the fast sum's cancellation is hardest on, from
    /// `mix64` so the test needs no RNG.
    fn hard_families(n: usize) -> Vec<(&'static str, Vec<Vec2>)> {
        let unit = |i: usize, salt: u64| {
            (crate::primitives::mix64(i as u64 ^ salt) >> 40) as f32 / 16_777_216.0
        };
        let nf = n as f32;
        let g = ((n as f64) * 0.618_033_988_749_895).round() as usize | 1;
        let mut sobol = vec![Vec2::ZERO; n];
        crate::traits::Sampler2D::fill(
            &crate::samplers::Sobol::new(n as u32).unwrap(),
            9,
            &mut sobol,
        );
        let mut pmj = vec![Vec2::ZERO; n];
        crate::traits::Sampler2D::fill(
            &crate::samplers::Pmj02::new(n as u32).unwrap(),
            9,
            &mut pmj,
        );
        vec![
            (
                "random",
                (0..n).map(|i| Vec2::new(unit(i, 1), unit(i, 2))).collect(),
            ),
            (
                "lattice",
                (0..n)
                    .map(|i| Vec2::new(i as f32 / nf, ((i * g) % n) as f32 / nf))
                    .collect(),
            ),
            (
                "few values",
                (0..n)
                    .map(|i| {
                        Vec2::new(
                            (unit(i, 3) * 5.0).floor() / 5.0,
                            (unit(i, 4) * 3.0).floor() / 3.0,
                        )
                    })
                    .collect(),
            ),
            (
                "duplicated",
                (0..n)
                    .map(|i| Vec2::new(unit(i % n.div_ceil(4), 5), unit(i % n.div_ceil(4), 6)))
                    .collect(),
            ),
            (
                "cluster",
                (0..n)
                    .map(|i| Vec2::new(0.7 + unit(i, 7) * 1e-4, 0.2 + unit(i, 8) * 1e-4))
                    .collect(),
            ),
            ("one point repeated", vec![Vec2::new(0.3, 0.8); n]),
            (
                "diagonal",
                (0..n).map(|i| Vec2::splat(i as f32 / nf)).collect(),
            ),
            (
                "tiny and any f32",
                (0..n)
                    .map(|i| {
                        let bits = crate::primitives::mix64(i as u64 ^ 9) % 0x3f80_0000;
                        Vec2::new(unit(i, 10) * 1e-30, f32::from_bits(bits as u32))
                    })
                    .collect(),
            ),
            ("sobol", sobol),
            ("pmj02", pmj),
        ]
    }

    #[test]
    fn the_fast_sum_matches_the_direct_sum_on_hard_families() {
        // The direct sum takes about 1.5 s at 2^14: only the first five
        // families run there.
        for n in [1usize, 2, 3, 16, 100, 1000, 4096, 1 << 14] {
            let families = hard_families(n);
            let take = if n > 4096 { 5 } else { families.len() };
            for (name, points) in families.into_iter().take(take) {
                let fast = wraparound_l2_discrepancy(&points).unwrap();
                let direct = wraparound_l2_discrepancy_quadratic(&points).unwrap();
                assert!(
                    (fast - direct).abs() <= 1e-12 * direct.abs().max(1e-300),
                    "{name}, n = {n}: fast {fast:e}, direct {direct:e}"
                );
            }
        }
    }
}
