//! Star discrepancy (exact) and the L2 discrepancies (Warnock's L2-star,
//! Hickernell's centred and wrap-around).

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use super::double_double::{Dd, two_prod, two_sum};
use super::{Sum, coord, radix_sort, validate};
use crate::Error;

/// Exact star discrepancy of a 2D point set: the largest difference, over all
/// boxes anchored at the origin, between the fraction of points inside and the
/// box's area,
///
/// `D* = sup over a, b in [0, 1] of |#{i : x_i < a, y_i < b} / n - a b|`,
///
/// with open boxes `[0, a) x [0, b)` and closed boxes `[0, a] x [0, b]` both
/// considered (the supremum over half-open boxes is reached in the limit by one
/// or the other).
///
/// # Algorithm
///
/// The supremum is attained at critical boxes: open boxes whose right and top
/// edges lie on point coordinates or on 1 (too few points: `a b - count / n`),
/// and closed boxes whose edges lie on point coordinates (too many points:
/// `count / n - a b`). For a fixed right edge `a`, each candidate top edge
/// `b_j` is a line in `a` with slope `b_j` (or `-b_j`) and an intercept that
/// counts the points already swept. The sweep goes over the distinct x values
/// in increasing order; a point entering the sweep adds 1 to the intercepts of
/// a contiguous range of `b_j`, and the answer for each `a` is the upper
/// envelope of the lines at `a`, with `a` only growing.
///
/// Both operations run on a kinetic segment tree (a kinetic tournament in the
/// sense of Basch, Guibas & Hershberger 1999, with lazy range updates) over
/// the `b_j` sorted by slope: each node keeps the line that wins in its
/// subtree at the current `a` and the earliest `a` at which that can change
/// (when a steeper line from its right half overtakes). A range update is a
/// lazy intercept shift (it does not change the winners inside a covered
/// subtree) plus a re-evaluation of O(log n) ancestors; advancing `a`
/// re-evaluates only nodes whose certificate expired. The amortised bound
/// known for kinetic segment trees is O(log² n) per update, i.e. O(n log² n)
/// time in all, with O(n) memory; the measured scaling agrees (16 times the
/// points take 25 to 28 times as long from 2^16 to 2^20; n log² n predicts 25).
/// The leaves are buckets of 32 lines that keep their own upper hull, which
/// keeps the tree small enough for the cache. Structured sets (grids,
/// diagonals, Hammersley) take no longer than uniform random ones; timings
/// are in `docs/metrics.md`. Results are exact up to one f64 rounding per
/// candidate box.
///
/// Dobkin, Eppstein & Mitchell 1996 give the classic O(n²) 2D algorithm (and
/// the critical-box argument); the kinetic tree replaces their per-column scan.
///
/// # Errors
///
/// [`Error::EmptyPointSet`], [`Error::NonFinitePoint`] or
/// [`Error::PointOutOfRange`] (naming the first bad point). `-0.0` counts as 0.
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::star_discrepancy};
/// // One point: D* = max(1 - xy, x, y).
/// let d = star_discrepancy(&[Vec2::new(0.5, 0.25)])?;
/// assert!((d - 0.875).abs() < 1e-12);
/// // Centred 4 x 4 grid: 1/8 + 1/8 - 1/64.
/// let grid: Vec<Vec2> = (0..16)
///     .map(|i| Vec2::new((i % 4) as f32 / 4.0 + 0.125, (i / 4) as f32 / 4.0 + 0.125))
///     .collect();
/// assert!((star_discrepancy(&grid)? - (0.25 - 1.0 / 64.0)).abs() < 1e-12);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn star_discrepancy(points: &[Vec2]) -> Result<f64, Error> {
    validate(points)?;
    let n = points.len();
    let nf = n as f64;

    // Distinct y values sorted, and each point as (x, rank of its y), sorted
    // by x. Ranks come from one sort rather than a search per point.
    let mut by_y: Vec<(f64, f64)> = points.iter().map(|p| (coord(p.y), coord(p.x))).collect();
    by_y.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let mut ys: Vec<f64> = Vec::with_capacity(n);
    let mut pts: Vec<(f64, u32)> = Vec::with_capacity(n);
    for &(y, x) in &by_y {
        if ys.last() != Some(&y) {
            ys.push(y);
        }
        pts.push((x, (ys.len() - 1) as u32));
    }
    drop(by_y);
    pts.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let m = ys.len();

    // Too few points (open boxes): for each top edge b_j in ys and 1, the line
    // n a b_j - #{x < a, y < b_j}. A point with y rank r lowers slots r+1..=m.
    let mut best_open = f64::NEG_INFINITY;
    {
        let slopes: Vec<f64> = ys.iter().chain(&[1.0]).map(|&b| nf * b).collect();
        let mut tree = Kinetic::new(slopes);
        let mut i = 0;
        while i < n {
            let a = pts[i].0;
            tree.advance(a);
            best_open = best_open.max(tree.max_at(a));
            while i < n && pts[i].0 == a {
                tree.add(pts[i].1 as usize + 1, m + 1, -1.0, a);
                i += 1;
            }
        }
        tree.advance(1.0);
        best_open = best_open.max(tree.max_at(1.0));
    }

    // Too many points (closed boxes): for each top edge b_j in ys, the line
    // #{x <= a, y <= b_j} - n a b_j. Slots are stored in decreasing b (so the
    // slopes -n b increase); a point with y rank r raises b_r.. = slots 0..m-r.
    let mut best_closed = f64::NEG_INFINITY;
    {
        let slopes: Vec<f64> = ys.iter().rev().map(|&b| -nf * b).collect();
        let mut tree = Kinetic::new(slopes);
        let mut i = 0;
        while i < n {
            let a = pts[i].0;
            tree.advance(a);
            while i < n && pts[i].0 == a {
                tree.add(0, m - pts[i].1 as usize, 1.0, a);
                i += 1;
            }
            tree.advance(a);
            best_closed = best_closed.max(tree.max_at(a));
        }
    }

    Ok((best_open.max(best_closed) / nf).max(0.0))
}

/// One node of the kinetic tree: the winning line of its subtree at the
/// current time, the time its win may end, and a pending intercept shift for
/// its children (for a leaf: the shift shared by its whole bucket).
#[derive(Clone, Copy, Debug)]
struct Node {
    /// Intercept of the winning line (all shifts at and below this node applied).
    intercept: f64,
    /// Earliest time at which some winner in this subtree may change.
    melt: f64,
    /// Shift still to be passed to the children; in a leaf, the bucket's
    /// shift (an integer count, exact in f64).
    lazy: f64,
    /// Slope of the winning line (kept here so that comparing children
    /// touches only the nodes).
    slope: f64,
}

/// Lines per leaf bucket. A bucket keeps the upper hull of its lines and a
/// pointer that only moves forward in time; rebuilding it after a partial
/// update costs O(BUCKET). Buckets cut the tree (and its cache misses) by
/// this factor.
const BUCKET: usize = 32;

/// Kinetic segment tree for the upper envelope of lines `slope[j] t + c_j`,
/// with range updates of the intercepts and a time `t` that only grows.
///
/// Leaves are buckets of [`BUCKET`] consecutive lines. Nodes are laid out in
/// DFS order: the node for buckets `[lo, hi)` at `v` has its left child at
/// `v + 1` and its right child at `v + 2 (mid - lo)`, so the tree uses exactly
/// `2 buckets - 1` nodes.
#[derive(Debug)]
struct Kinetic {
    /// Per line, strictly increasing.
    slope: Vec<f64>,
    /// Per line: the intercept without its bucket's shift.
    raw: Vec<f64>,
    /// Per bucket `b`: its upper hull in `hull[b BUCKET..][..hull_len[b]]`.
    hull: Vec<u32>,
    hull_len: Vec<u32>,
    /// Per bucket: the hull entry that wins at the current time.
    ptr: Vec<u32>,
    nodes: Vec<Node>,
}

impl Kinetic {
    /// Lines with the given slopes (strictly increasing) and zero intercepts, at time 0.
    fn new(slope: Vec<f64>) -> Self {
        debug_assert!(slope.windows(2).all(|w| w[0] < w[1]));
        let len = slope.len();
        let buckets = len.div_ceil(BUCKET);
        let leaf = Node {
            intercept: 0.0,
            melt: f64::INFINITY,
            lazy: 0.0,
            slope: 0.0,
        };
        let mut tree = Self {
            slope,
            raw: vec![0.0; len],
            hull: vec![0; len],
            hull_len: vec![0; buckets],
            ptr: vec![0; buckets],
            nodes: vec![leaf; 2 * buckets - 1],
        };
        tree.build(0, 0, buckets);
        tree
    }

    fn buckets(&self) -> usize {
        self.hull_len.len()
    }

    /// Slots of bucket `b`.
    fn slots(&self, b: usize) -> core::ops::Range<usize> {
        b * BUCKET..((b + 1) * BUCKET).min(self.slope.len())
    }

    fn build(&mut self, v: usize, lo: usize, hi: usize) {
        if hi - lo == 1 {
            self.rebuild_hull(lo);
            self.eval_leaf(v, lo, 0.0);
            return;
        }
        let mid = (lo + hi) / 2;
        let (left, right) = (v + 1, v + 2 * (mid - lo));
        self.build(left, lo, mid);
        self.build(right, mid, hi);
        self.pull(v, left, right, 0.0);
    }

    /// Upper hull of bucket `b`'s lines (monotone chain; slopes are sorted).
    fn rebuild_hull(&mut self, b: usize) {
        let slots = self.slots(b);
        let base = slots.start;
        let mut len = 0usize;
        for j in slots {
            let (sl, cl) = (self.slope[j], self.raw[j]);
            while len >= 2 {
                let (i1, i2) = (
                    self.hull[base + len - 2] as usize,
                    self.hull[base + len - 1] as usize,
                );
                let (s1, c1, s2, c2) = (self.slope[i1], self.raw[i1], self.slope[i2], self.raw[i2]);
                // Line 2 never wins if line l overtakes it no later than it
                // overtakes line 1.
                if (c1 - c2) * (sl - s2) >= (c2 - cl) * (s2 - s1) {
                    len -= 1;
                } else {
                    break;
                }
            }
            self.hull[base + len] = j as u32;
            len += 1;
        }
        self.hull_len[b] = len as u32;
        self.ptr[b] = 0;
    }

    /// Moves bucket `b`'s pointer to time `t` and stores its winner in leaf `v`.
    #[inline]
    fn eval_leaf(&mut self, v: usize, b: usize, t: f64) {
        let base = b * BUCKET;
        let len = self.hull_len[b] as usize;
        let mut p = self.ptr[b] as usize;
        let value = |j: u32| self.slope[j as usize] * t + self.raw[j as usize];
        let mut current = value(self.hull[base + p]);
        while p + 1 < len {
            let next = value(self.hull[base + p + 1]);
            if next < current {
                break;
            }
            current = next;
            p += 1;
        }
        self.ptr[b] = p as u32;
        let w = self.hull[base + p] as usize;
        let melt = if p + 1 < len {
            let n = self.hull[base + p + 1] as usize;
            (self.raw[w] - self.raw[n]) / (self.slope[n] - self.slope[w])
        } else {
            f64::INFINITY
        };
        let node = &mut self.nodes[v];
        node.slope = self.slope[w];
        node.intercept = self.raw[w] + node.lazy;
        node.melt = melt;
    }

    /// Recomputes node `v`'s winner and certificate from its children at time `t`.
    #[inline]
    fn pull(&mut self, v: usize, left: usize, right: usize, t: f64) {
        let (l, r) = (self.nodes[left], self.nodes[right]);
        let (sl, sr) = (l.slope, r.slope);
        let (vl, vr) = (sl * t + l.intercept, sr * t + r.intercept);
        let mut melt = l.melt.min(r.melt);
        let node = &mut self.nodes[v];
        // The right child's lines are all steeper: once it wins it keeps
        // winning as t grows; while the left wins, the right overtakes at `cross`.
        if vl > vr {
            let cross = (l.intercept - r.intercept) / (sr - sl);
            if cross > t {
                melt = melt.min(cross);
                node.slope = sl;
                node.intercept = l.intercept;
                node.melt = melt;
                return;
            }
        }
        node.slope = sr;
        node.intercept = r.intercept;
        node.melt = melt;
    }

    #[inline]
    fn push(&mut self, v: usize, left: usize, right: usize) {
        let lazy = self.nodes[v].lazy;
        if lazy != 0.0 {
            for child in [left, right] {
                self.nodes[child].intercept += lazy;
                self.nodes[child].lazy += lazy;
            }
            self.nodes[v].lazy = 0.0;
        }
    }

    /// Adds `delta` (±1) to the intercepts of lines `lo..hi`, at time `t`
    /// (the tree must already be advanced to `t`).
    fn add(&mut self, lo: usize, hi: usize, delta: f64, t: f64) {
        if lo < hi {
            self.add_in(0, 0, self.buckets(), (lo, hi), delta, t);
        }
    }

    fn add_in(&mut self, v: usize, lo: usize, hi: usize, range: (usize, usize), d: f64, t: f64) {
        let (first, end) = (lo * BUCKET, (hi * BUCKET).min(self.slope.len()));
        let (ql, qr) = range;
        if qr <= first || end <= ql {
            return;
        }
        if ql <= first && end <= qr {
            // A uniform shift keeps every winner inside the subtree.
            self.nodes[v].intercept += d;
            self.nodes[v].lazy += d;
            return;
        }
        if hi - lo == 1 {
            for c in &mut self.raw[ql.max(first)..qr.min(end)] {
                *c += d;
            }
            self.rebuild_hull(lo);
            self.eval_leaf(v, lo, t);
            return;
        }
        let mid = (lo + hi) / 2;
        let (left, right) = (v + 1, v + 2 * (mid - lo));
        self.push(v, left, right);
        self.add_in(left, lo, mid, range, d, t);
        self.add_in(right, mid, hi, range, d, t);
        self.pull(v, left, right, t);
    }

    /// Moves time forward to `t`, re-evaluating the nodes whose winner may
    /// have changed.
    fn advance(&mut self, t: f64) {
        self.advance_in(0, 0, self.buckets(), t);
    }

    fn advance_in(&mut self, v: usize, lo: usize, hi: usize, t: f64) {
        if self.nodes[v].melt > t {
            return;
        }
        if hi - lo == 1 {
            self.eval_leaf(v, lo, t);
            return;
        }
        let mid = (lo + hi) / 2;
        let (left, right) = (v + 1, v + 2 * (mid - lo));
        self.push(v, left, right);
        self.advance_in(left, lo, mid, t);
        self.advance_in(right, mid, hi, t);
        self.pull(v, left, right, t);
    }

    /// The upper envelope at time `t` (the tree must be advanced to `t`).
    fn max_at(&self, t: f64) -> f64 {
        let root = self.nodes[0];
        root.slope * t + root.intercept
    }
}

/// L2-star discrepancy (Warnock 1972): the root mean square of the local
/// discrepancy over all anchored boxes,
///
/// `T² = ∫∫ (#{x_i < a, y_i < b} / n - a b)² da db
///     = 1/9 - 1/(2n) Σ_i (1 - x_i²)(1 - y_i²)
///       + 1/n² Σ_i Σ_j (1 - max(x_i, x_j))(1 - max(y_i, y_j))`.
///
/// Returns `T` itself, as `scipy.stats.qmc.discrepancy(method="L2-star")` does.
///
/// # Algorithm
///
/// The double sum is `Σ min(1 - x_i, 1 - x_j) min(1 - y_i, 1 - y_j)`: a sweep in
/// decreasing `1 - x` with a Fenwick tree over the ranks of `1 - y` (counts and
/// compensated sums) evaluates it in O(n log n) time and O(n) memory, the 2D
/// case of Heinrich's 1996 algorithm. The three terms nearly cancel; they are
/// summed with compensation, so the absolute error of `T²` stays near 1e-16
/// and the relative error of `T` near `1e-16 / T²`.
///
/// # Errors
///
/// As [`star_discrepancy`].
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::l2_star_discrepancy};
/// // One point at the origin: T² = 1/9 - 1/2 + 1 = 11/18.
/// let t = l2_star_discrepancy(&[Vec2::ZERO])?;
/// assert!((t - (11.0f64 / 18.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn l2_star_discrepancy(points: &[Vec2]) -> Result<f64, Error> {
    validate(points)?;
    let nf = points.len() as f64;
    let mut single = Sum::default();
    let mut p = Vec::with_capacity(points.len());
    let mut q = Vec::with_capacity(points.len());
    for pt in points {
        let (x, y) = (coord(pt.x), coord(pt.y));
        single.add((1.0 - x * x) * (1.0 - y * y));
        p.push(1.0 - x);
        q.push(1.0 - y);
    }
    let pairs = sum_min_min(&p, &q);
    let mut total = Sum::default();
    total.add(1.0 / 9.0);
    total.add(-single.value() / (2.0 * nf));
    total.add(pairs / (nf * nf));
    Ok(total.value().max(0.0).sqrt())
}

/// Centred L2 discrepancy (Hickernell 1998), with `u = x - 1/2`:
///
/// `CD² = (13/12)² - 2/n Σ_i Π_k (1 + |u_ik|/2 - u_ik²/2)
///        + 1/n² Σ_i Σ_j Π_k (1 + |u_ik|/2 + |u_jk|/2 - |x_ik - x_jk|/2)`.
///
/// Returns `CD` itself. Note that `scipy.stats.qmc.discrepancy(method="CD")`
/// returns `CD²` (scipy issue 19839); square this value to compare.
///
/// # Algorithm
///
/// Each pair factor is `1 + min(|u_i|, |u_j|)` when both points lie on the same
/// side of 1/2 and 1 otherwise, so the double sum splits into 1D sums over
/// each half and 2D sums of `min · min` over each quadrant, each evaluated by
/// a sorted sweep with a Fenwick tree: O(n log n) time, O(n) memory,
/// compensated sums.
///
/// # Errors
///
/// As [`star_discrepancy`].
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::centered_l2_discrepancy};
/// // One point at the centre: CD² = (13/12)² - 2 + 1.
/// let cd = centered_l2_discrepancy(&[Vec2::splat(0.5)])?;
/// assert!((cd - (169.0f64 / 144.0 - 1.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn centered_l2_discrepancy(points: &[Vec2]) -> Result<f64, Error> {
    validate(points)?;
    let nf = points.len() as f64;
    // Factors written as 1 + g, so the constants cancel exactly up front:
    // (13/12)² - 2 + 1 = 25/144.
    let mut single = Sum::default();
    // |u| per point, grouped by side in x, in y, and by quadrant.
    let mut halves_x: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    let mut halves_y: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    let mut quadrants: [(Vec<f64>, Vec<f64>); 4] = Default::default();
    for pt in points {
        let (ux, uy) = (coord(pt.x) - 0.5, coord(pt.y) - 0.5);
        let (ax, ay) = (ux.abs(), uy.abs());
        let gx = 0.5 * ax - 0.5 * ux * ux;
        let gy = 0.5 * ay - 0.5 * uy * uy;
        single.add(gx + gy + gx * gy);
        let (sx, sy) = (usize::from(ux >= 0.0), usize::from(uy >= 0.0));
        halves_x[sx].push(ax);
        halves_y[sy].push(ay);
        let quadrant = &mut quadrants[2 * sx + sy];
        quadrant.0.push(ax);
        quadrant.1.push(ay);
    }
    let mut pairs = Sum::default();
    for half in halves_x.iter_mut().chain(halves_y.iter_mut()) {
        pairs.add(sum_min_1d(half));
    }
    for (p, q) in &quadrants {
        pairs.add(sum_min_min(p, q));
    }
    let mut total = Sum::default();
    total.add(25.0 / 144.0);
    total.add(-2.0 * single.value() / nf);
    total.add(pairs.value() / (nf * nf));
    Ok(total.value().max(0.0).sqrt())
}

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
/// O(n log n) time (two radix sorts and the sweeps; measured, no slower than
/// [`l2_star_discrepancy`] from 2^10 to 2^20 points), O(n) memory. The terms
/// are of order `n²` and cancel down to `n² WD²`, which is as small as `1e-8 n²`
/// for good sets at 2^14 points, so every sum is accumulated in double-double
/// arithmetic (Dekker 1971): products of f32 coordinates are exact there, and
/// the result keeps about 1e-14 relative accuracy even where `WD²` is 1e-16 of
/// the terms (tests compare it with the direct double sum to 1e-12).
///
/// # Errors
///
/// As [`star_discrepancy`].
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
    Ok(wraparound_sweep(points).max(0.0).sqrt())
}

/// `WD²` by the O(n log n) decomposition of [`wraparound_l2_discrepancy`].
fn wraparound_sweep(points: &[Vec2]) -> f64 {
    let n = points.len();
    let nf = n as f64;
    let xs: Vec<f64> = points.iter().map(|p| coord(p.x)).collect();
    let ys: Vec<f64> = points.iter().map(|p| coord(p.y)).collect();

    // Moments S_ab = Σ x^a y^b. x y, x², y² are exact in f64 (f32 inputs);
    // x² y, x y², x² y² are exact as double-double products.
    let mut s = [[Dd::ZERO; 3]; 3];
    for (&x, &y) in xs.iter().zip(&ys) {
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

    let order_x = order_by(points, |p| p.x);
    let order_y = order_by(points, |p| p.y);
    // The sweeps read the coordinates in sorted order, gathered once so that
    // they stream through memory.
    let gather =
        |order: &[u32], a: &[f64]| -> Vec<f64> { order.iter().map(|&i| a[i as usize]).collect() };
    let (x_by_x, y_by_x) = (gather(&order_x, &xs), gather(&order_x, &ys));
    let (abs_dy, dx2_abs_dy) = absolute_sweep(&gather(&order_y, &ys), &gather(&order_y, &xs));
    let (abs_dx, abs_dx_dy2) = absolute_sweep(&x_by_x, &y_by_x);
    let mut rank = vec![0u32; n];
    for (r, &i) in order_y.iter().enumerate() {
        rank[i as usize] = r as u32;
    }
    let rank_by_x: Vec<u32> = order_x.iter().map(|&i| rank[i as usize]).collect();
    drop((order_x, order_y, rank));
    let concordant = dominance_sweep_fixed(&x_by_x, &y_by_x, &rank_by_x)
        .unwrap_or_else(|| dominance_sweep(&x_by_x, &y_by_x, &rank_by_x));
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

/// Indices of `points` in increasing order of one coordinate (`-0.0` as 0;
/// ties in index order), by a radix sort of the f32 bits, which order like
/// the values for the non-negative floats validation lets through.
fn order_by(points: &[Vec2], coordinate: impl Fn(&Vec2) -> f32) -> Vec<u32> {
    let mut keys: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (u64::from(coordinate(p).to_bits() & 0x7fff_ffff) << 32) | i as u64)
        .collect();
    radix_sort(&mut keys, |&k| k >> 32, 31);
    keys.into_iter().map(|k| k as u32).collect()
}

/// Over the unordered pairs, with `u` in increasing order:
/// `(Σ |u_j - u_i|, Σ |u_j - u_i| (v_j - v_i)²)`, in double-double.
fn absolute_sweep(u: &[f64], v: &[f64]) -> (Dd, Dd) {
    let n = u.len() as f64;
    let mut abs = Dd::ZERO;
    // Prefix sums over the earlier points: u, v, v², u v, u v².
    let (mut a, mut b, mut c, mut d, mut e) = (Dd::ZERO, Dd::ZERO, Dd::ZERO, Dd::ZERO, Dd::ZERO);
    // Σ_j of: u_j C, u_j v_j B, k u_j v_j², E, v_j D, v_j² A. Every factor
    // taken from the point is an f32 value (or the count k), so the products
    // are the cheap short ones.
    let mut p = [Dd::ZERO; 6];
    for (k, (&uj, &vj)) in u.iter().zip(v).enumerate() {
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

/// One Fenwick node: how many points and the sums of their x, y and x y.
#[derive(Clone, Copy, Debug, Default)]
#[repr(align(64))]
struct DominanceNode {
    count: f64,
    x: Dd,
    y: Dd,
    xy: Dd,
}

/// `Σ (x_j - x_i)(y_j - y_i)` over the pairs with `x_i <= x_j` and `y_i < y_j`
/// (pairs tied in x or y add 0 whichever way they are counted), given the
/// points in increasing x with the ranks of their y.
fn dominance_sweep(xs: &[f64], ys: &[f64], ranks: &[u32]) -> Dd {
    let n = xs.len();
    // Two levels: a Fenwick tree over blocks of RUN consecutive ranks, and
    // per rank the point's x and y once inserted (and a 1 for the count).
    // The partial block below a rank is a short scan of one or two cache
    // lines, and the tree is RUN times smaller, so fewer of its levels miss
    // the cache.
    const RUN: usize = 8;
    let blocks = n.div_ceil(RUN);
    let mut tree = vec![DominanceNode::default(); blocks + 1];
    let mut slots = vec![[0.0f64; 3]; n];
    // Σ_j of: count x_j y_j, x_j Σy, y_j Σx, Σ x y over the points below j.
    let mut t = [Dd::ZERO; 4];
    for ((&xj, &yj), &r) in xs.iter().zip(ys).zip(ranks) {
        let r = r as usize;
        let block = r / RUN;
        let mut below = DominanceNode::default();
        for &[x, y, c] in &slots[block * RUN..r] {
            below.count += c;
            below.x = below.x.plus_f64(x);
            below.y = below.y.plus_f64(y);
            below.xy = below.xy.plus_f64(x * y);
        }
        let mut k = block;
        while k > 0 {
            let node = &tree[k];
            below.count += node.count;
            below.x = below.x.plus(node.x);
            below.y = below.y.plus(node.y);
            below.xy = below.xy.plus(node.xy);
            k &= k - 1;
        }
        let xy = xj * yj;
        t[0] = t[0].plus(two_prod(below.count, xy));
        t[1] = t[1].plus(below.y.mul_short(xj));
        t[2] = t[2].plus(below.x.mul_short(yj));
        t[3] = t[3].plus(below.xy);
        slots[r] = [xj, yj, 1.0];
        let mut k = block + 1;
        while k <= blocks {
            let node = &mut tree[k];
            node.count += 1.0;
            node.x = node.x.plus_f64(xj);
            node.y = node.y.plus_f64(yj);
            node.xy = node.xy.plus_f64(xy);
            k += k & k.wrapping_neg();
        }
    }
    t[0].sub(t[1]).sub(t[2]).add(t[3])
}

/// [`dominance_sweep`] in exact integer arithmetic, for the usual case where
/// every coordinate is a multiple of 2^-32 (as every sampler's output and
/// every f32 at or above 2^-8 is); `None` otherwise. With `X = 2^32 x`, the
/// Fenwick sums of `X`, `Y` and `X Y` and the four sums over `j` stay below
/// `n² 2^64`, so u128 holds them exactly for n up to 2^31.
fn dominance_sweep_fixed(xs: &[f64], ys: &[f64], ranks: &[u32]) -> Option<Dd> {
    const ONE: f64 = 4_294_967_296.0; // 2^32
    let n = xs.len();
    if n >= 1 << 31 {
        return None;
    }
    let fixed = |v: f64| {
        let scaled = v * ONE;
        (scaled == libm::floor(scaled)).then_some(scaled as u64)
    };
    let mut points = Vec::with_capacity(n);
    for ((&x, &y), &r) in xs.iter().zip(ys).zip(ranks) {
        points.push((fixed(x)?, fixed(y)?, r));
    }
    #[derive(Clone, Copy, Default)]
    struct Node {
        count: u64,
        x: u64,
        y: u64,
        xy: u128,
    }
    // As in `dominance_sweep`: a tree over blocks of RUN ranks, and per rank
    // the inserted point's X, Y and a 1.
    const RUN: usize = 8;
    let blocks = n.div_ceil(RUN);
    let mut tree = vec![Node::default(); blocks + 1];
    let mut slots = vec![[0u64; 3]; n];
    let mut t = [0u128; 4];
    for (xj, yj, r) in points {
        let r = r as usize;
        let block = r / RUN;
        let mut below = Node::default();
        for &[x, y, c] in &slots[block * RUN..r] {
            below.count += c;
            below.x += x;
            below.y += y;
            below.xy += u128::from(x) * u128::from(y);
        }
        let mut k = block;
        while k > 0 {
            let node = &tree[k];
            below.count += node.count;
            below.x += node.x;
            below.y += node.y;
            below.xy += node.xy;
            k &= k - 1;
        }
        let xy = u128::from(xj) * u128::from(yj);
        t[0] += u128::from(below.count) * xy;
        t[1] += u128::from(below.y) * u128::from(xj);
        t[2] += u128::from(below.x) * u128::from(yj);
        t[3] += below.xy;
        slots[r] = [xj, yj, 1];
        let mut k = block + 1;
        while k <= blocks {
            let node = &mut tree[k];
            node.count += 1;
            node.x += xj;
            node.y += yj;
            node.xy += xy;
            k += k & k.wrapping_neg();
        }
    }
    // Σ (X_j - X_i)(Y_j - Y_i) >= 0 over the pairs, exactly, then times 2^-64.
    let total = (t[0] + t[3]) - (t[1] + t[2]);
    let hi = total as f64;
    let rest = total as i128 - hi as i128;
    let scale = 1.0 / (ONE * ONE);
    Some(Dd {
        hi: hi * scale,
        lo: rest as f64 * scale,
    })
}

/// The direct O(n²) double sum for [`wraparound_l2_discrepancy`], kept as the
/// reference its tests compare against (not part of the API).
///
/// Every pair term, `(4/3)²` subtracted and the sum are in double-double
/// (f64 terms have rounding errors that add up systematically on lattices,
/// to 1e-11 relative at 4096 points), in a
/// vectorisable inner loop: about 90 flops per pair. Rows are summed in fixed
/// chunks of 64 and the chunk sums added in order; with the `rayon` feature
/// the chunks run in parallel, and the result is bit-for-bit the same for any
/// number of threads (and without `rayon`).
#[doc(hidden)]
pub fn wraparound_l2_discrepancy_quadratic(points: &[Vec2]) -> Result<f64, Error> {
    validate(points)?;
    let n = points.len();
    let nf = n as f64;
    let xs: Vec<f64> = points.iter().map(|p| coord(p.x)).collect();
    let ys: Vec<f64> = points.iter().map(|p| coord(p.y)).collect();
    const ROWS: usize = 64;
    let chunks = n.div_ceil(ROWS);
    let chunk_sum = |c: usize| {
        let mut s = Dd::ZERO;
        for i in c * ROWS..((c + 1) * ROWS).min(n) {
            s = s.add(wraparound_row(&xs, &ys, i));
        }
        s
    };
    #[cfg(feature = "rayon")]
    let sums: Vec<Dd> = {
        use rayon::prelude::*;
        (0..chunks).into_par_iter().map(chunk_sum).collect()
    };
    #[cfg(not(feature = "rayon"))]
    let sums: Vec<Dd> = (0..chunks).map(chunk_sum).collect();
    let mut off_diagonal = Dd::ZERO;
    for s in sums {
        off_diagonal = off_diagonal.add(s);
    }
    // Diagonal: (3/2)² - (4/3)² = 17/36 per point.
    let total = Dd::ratio(17.0, 36.0)
        .mul_f64(nf)
        .add(off_diagonal.mul_f64(2.0));
    Ok((total.value() / (nf * nf)).max(0.0).sqrt())
}

/// `Σ_{j > i} (f(dx) f(dy) - 16/9)` with `f(d) = 3/2 - d (1 - d)`, each term
/// and the sum in double-double.
fn wraparound_row(xs: &[f64], ys: &[f64], i: usize) -> Dd {
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

/// `Σ_i Σ_j min(p_i, p_j)` over all ordered pairs (the diagonal included);
/// sorts `p`.
fn sum_min_1d(p: &mut [f64]) -> f64 {
    // In decreasing order the k-th value is the minimum of 2k + 1 ordered pairs.
    p.sort_unstable_by(|a, b| b.total_cmp(a));
    let mut s = Sum::default();
    for (k, &v) in p.iter().enumerate() {
        s.add(v * (2 * k + 1) as f64);
    }
    s.value()
}

/// `Σ_i Σ_j min(p_i, p_j) min(q_i, q_j)` over all ordered pairs (the diagonal
/// included), in O(n log n).
///
/// Points are swept in decreasing `p`, so every earlier point has the larger
/// `p`; a Fenwick tree over the ranks of `q` returns how many earlier points
/// have a larger `q` (each contributes `q_i`) and the sum of the smaller ones.
fn sum_min_min(p: &[f64], q: &[f64]) -> f64 {
    let n = p.len();
    if n == 0 {
        return 0.0;
    }
    let mut by_q: Vec<u32> = (0..n as u32).collect();
    by_q.sort_unstable_by(|&a, &b| q[a as usize].total_cmp(&q[b as usize]));
    let mut rank = vec![0u32; n];
    for (r, &i) in by_q.iter().enumerate() {
        rank[i as usize] = r as u32;
    }
    let mut by_p: Vec<u32> = (0..n as u32).collect();
    by_p.sort_unstable_by(|&a, &b| p[b as usize].total_cmp(&p[a as usize]));

    let mut counts = vec![0u32; n + 1];
    let mut sums = vec![Sum::default(); n + 1];
    let mut off = Sum::default();
    let mut diagonal = Sum::default();
    for (seen, &i) in by_p.iter().enumerate() {
        let i = i as usize;
        let (pi, qi) = (p[i], q[i]);
        let r = rank[i] as usize;
        // Earlier points with a lower q rank: their count and q sum.
        let (mut below, mut below_sum) = (0usize, Sum::default());
        let mut k = r;
        while k > 0 {
            below += counts[k] as usize;
            below_sum.add(sums[k].value());
            k &= k - 1;
        }
        let above = seen - below;
        off.add(pi * (qi * above as f64 + below_sum.value()));
        diagonal.add(pi * qi);
        let mut k = r + 1;
        while k <= n {
            counts[k] += 1;
            sums[k].add(qi);
            k += k & k.wrapping_neg();
        }
    }
    let mut total = Sum::default();
    total.add(2.0 * off.value());
    total.add(diagonal.value());
    total.value()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute_min_min(p: &[f64], q: &[f64]) -> f64 {
        let mut s = 0.0;
        for i in 0..p.len() {
            for j in 0..p.len() {
                s += p[i].min(p[j]) * q[i].min(q[j]);
            }
        }
        s
    }

    #[test]
    fn sum_min_min_matches_brute_force_with_ties() {
        let p = [0.5, 0.25, 0.5, 0.75, 0.0, 0.25];
        let q = [0.125, 0.125, 0.875, 0.5, 0.5, 0.125];
        assert!((sum_min_min(&p, &q) - brute_min_min(&p, &q)).abs() < 1e-14);
        let mut p1 = p;
        let ones = [1.0; 6];
        assert!((sum_min_1d(&mut p1) - brute_min_min(&p, &ones)).abs() < 1e-14);
    }

    #[test]
    fn dominance_sweeps_agree() {
        let mut state = 7u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            state
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
            let fixed = dominance_sweep_fixed(&xs, &ys, &ranks).unwrap();
            let float = dominance_sweep(&xs, &ys, &ranks);
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
        assert_eq!(dominance_sweep_fixed(&[1e-30], &[0.5], &[0]), None);
    }

    #[test]
    fn kinetic_tree_tracks_the_envelope() {
        // Lines j t + c_j for a few slopes, with range updates.
        // Enough lines for several buckets; a fixed pseudo-random update stream.
        let len = 5 * BUCKET + 3;
        let slopes: Vec<f64> = (0..len).map(|j| j as f64 * 0.37 - 20.0).collect();
        let mut tree = Kinetic::new(slopes.clone());
        let mut c = vec![0.0; len];
        let mut state = 12345u64;
        let mut t = 0.0;
        for _ in 0..400 {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let a = (state >> 33) as usize % (len + 1);
            let b = (state >> 13) as usize % (len + 1);
            let (lo, hi) = (a.min(b), a.max(b));
            let d = if state & 1 == 0 { 1.0 } else { -1.0 };
            tree.advance(t);
            tree.add(lo, hi, d, t);
            for cj in &mut c[lo..hi] {
                *cj += d;
            }
            tree.advance(t);
            let want = (0..len)
                .map(|j| slopes[j] * t + c[j])
                .fold(f64::MIN, f64::max);
            assert!((tree.max_at(t) - want).abs() < 1e-9, "t = {t}");
            t += ((state >> 40) % 7) as f64 * 0.01;
        }
    }
}
