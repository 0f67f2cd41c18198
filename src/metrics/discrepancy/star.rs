//! Exact star discrepancy: a sweep over a kinetic segment tree.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use crate::Error;
use crate::metrics::{coord, validate};

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
/// time in all, with O(n) memory. The leaves are buckets of 32 lines that
/// keep their own upper hull, which divides the tree's size (and its cache
/// misses) by 32. Structured sets (grids, diagonals, Hammersley) cost no more
/// than uniform random ones. Results are exact up to one f64 rounding per
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

#[cfg(test)]
mod tests {
    use super::*;

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
