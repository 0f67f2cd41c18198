//! Exact star discrepancy: a sweep over a kinetic segment tree.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use super::{key_value, keys_in_place, sorted_keys};
use crate::error::Error;
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
/// time in all, with O(n) memory: about 18 bytes a point beyond the input at
/// the peak (the distinct y values as f32, each point's x and y rank in one
/// u64, a u32 count per line and the nodes). The leaves are buckets of 32
/// lines that
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

    // The distinct y values, sorted: the candidate top edges; and each
    // point as `x bits << 32 | rank of its y` in increasing x (ties in index
    // order), read in sequence by both sweeps.
    let (ys, sweep) = distinct_and_sweep(points);
    let x_at = |k: usize| coord(key_value(sweep[k]));
    let rank_at = |k: usize| sweep[k] as u32 as usize;
    let m = ys.len();

    // Too few points (open boxes): for each top edge b_j in ys and 1, the line
    // n a b_j - #{x < a, y < b_j}. A point with y rank r lowers slots r+1..=m.
    let mut best_open = f64::NEG_INFINITY;
    let buffers = {
        let mut tree = Kinetic::<true>::new(&ys, nf, Buffers::default());
        let mut k = 0;
        while k < n {
            let a = x_at(k);
            tree.advance(a);
            best_open = best_open.max(tree.max_at(a));
            while k < n && x_at(k) == a {
                tree.add(rank_at(k) + 1, m + 1, a);
                k += 1;
            }
        }
        tree.advance(1.0);
        best_open = best_open.max(tree.max_at(1.0));
        tree.into_buffers()
    };

    // Too many points (closed boxes): for each top edge b_j in ys, the line
    // #{x <= a, y <= b_j} - n a b_j. Slots are stored in decreasing b (so the
    // slopes -n b increase); a point with y rank r raises b_r.. = slots 0..m-r.
    let mut best_closed = f64::NEG_INFINITY;
    {
        // The open sweep's buffers, reset: freeing them and allocating the
        // same sizes again would leave a freed copy resident under glibc's
        // dynamic mmap threshold.
        let mut tree = Kinetic::<false>::new(&ys, -nf, buffers);
        let mut k = 0;
        while k < n {
            let a = x_at(k);
            tree.advance(a);
            while k < n && x_at(k) == a {
                tree.add(0, m - rank_at(k), a);
                k += 1;
            }
            tree.advance(a);
            best_closed = best_closed.max(tree.max_at(a));
        }
    }

    Ok((best_open.max(best_closed) / nf).max(0.0))
}

/// The distinct y coordinates of `points` in increasing order (`-0.0` as 0),
/// and the points as `x bits << 32 | rank of y among them` sorted (by x,
/// then index). At most 16 bytes a point are alive on the way.
fn distinct_and_sweep(points: &[Vec2]) -> (Vec<f32>, Vec<u64>) {
    let keys = sorted_keys(points, |p| p.y);
    let mut ys: Vec<f32> = Vec::with_capacity(keys.len());
    let mut rank = vec![0u32; keys.len()];
    for &key in &keys {
        let y = key_value(key);
        if ys.last() != Some(&y) {
            ys.push(y);
        }
        rank[key as u32 as usize] = (ys.len() - 1) as u32;
    }
    drop(keys);
    ys.shrink_to_fit();
    let mut sweep = keys_in_place(points, |p| p.x);
    for key in &mut sweep {
        *key = (*key & !0xffff_ffff) | u64::from(rank[*key as u32 as usize]);
    }
    (ys, sweep)
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

/// Lines per leaf bucket. A bucket keeps the upper hull of its lines (as a
/// bit mask) and a pointer that only moves forward in time; rebuilding it
/// after a partial update costs O(BUCKET). Buckets cut the tree (and its
/// cache misses) by this factor.
const BUCKET: usize = 32;

/// Kinetic segment tree for the upper envelope of the star discrepancy's
/// lines `slope_j t + c_j`, with range updates of the intercepts and a time
/// `t` that only grows.
///
/// The lines are those of one sweep: with `OPEN`, slopes `scale b_j` over the
/// sorted distinct `ys` then `scale` (the top edge 1), and intercepts that
/// only go down by 1; otherwise slopes `scale b_j` over `ys` in reverse (with
/// `scale < 0`, so they increase) and intercepts that only go up by 1. Slopes
/// are computed from `ys` when needed and intercepts kept as counts, so a
/// line costs 4 bytes plus its share of the nodes.
///
/// Leaves are buckets of [`BUCKET`] consecutive lines. Nodes are laid out in
/// DFS order: the node for buckets `[lo, hi)` at `v` has its left child at
/// `v + 1` and its right child at `v + 2 (mid - lo)`, so the tree uses exactly
/// `2 buckets - 1` nodes.
/// The storage of a [`Kinetic`] tree, handed from one sweep to the next.
#[derive(Debug, Default)]
struct Buffers {
    count: Vec<u32>,
    hull: Vec<u32>,
    ptr: Vec<u8>,
    nodes: Vec<Node>,
}

#[derive(Debug)]
struct Kinetic<'a, const OPEN: bool> {
    ys: &'a [f32],
    scale: f64,
    /// Per line: how many unit shifts its intercept got, not counting its
    /// bucket's shift.
    count: Vec<u32>,
    /// Per bucket: bit `o` is set when line `o` of the bucket is on its upper hull.
    hull: Vec<u32>,
    /// Per bucket: the offset of the hull line that wins at the current time.
    ptr: Vec<u8>,
    nodes: Vec<Node>,
}

impl<'a, const OPEN: bool> Kinetic<'a, OPEN> {
    /// The unit shift of an update.
    const DELTA: f64 = if OPEN { -1.0 } else { 1.0 };

    /// The sweep's lines over `ys` (sorted, distinct), with zero intercepts,
    /// at time 0, in `buffers` (whatever they held; their capacity is reused).
    fn new(ys: &'a [f32], scale: f64, buffers: Buffers) -> Self {
        let len = ys.len() + usize::from(OPEN);
        let buckets = len.div_ceil(BUCKET);
        let leaf = Node {
            intercept: 0.0,
            melt: f64::INFINITY,
            lazy: 0.0,
            slope: 0.0,
        };
        let Buffers {
            mut count,
            mut hull,
            mut ptr,
            mut nodes,
        } = buffers;
        /// `len` copies of `value`, in `v`'s allocation.
        fn reset<T: Clone>(v: &mut Vec<T>, len: usize, value: T) {
            v.clear();
            v.resize(len, value);
        }
        reset(&mut count, len, 0);
        reset(&mut hull, buckets, 0);
        reset(&mut ptr, buckets, 0);
        reset(&mut nodes, 2 * buckets - 1, leaf);
        let mut tree = Self {
            ys,
            scale,
            count,
            hull,
            ptr,
            nodes,
        };
        debug_assert!((1..len).all(|j| tree.slope(j - 1) < tree.slope(j)));
        tree.build(0, 0, buckets);
        tree
    }

    /// The tree's storage, for the next sweep.
    fn into_buffers(self) -> Buffers {
        Buffers {
            count: self.count,
            hull: self.hull,
            ptr: self.ptr,
            nodes: self.nodes,
        }
    }

    /// Slope of line `j`.
    #[inline]
    fn slope(&self, j: usize) -> f64 {
        if OPEN {
            match self.ys.get(j) {
                Some(&b) => self.scale * f64::from(b),
                None => self.scale,
            }
        } else {
            self.scale * f64::from(self.ys[self.ys.len() - 1 - j])
        }
    }

    /// Intercept of line `j` without its bucket's shift.
    #[inline]
    fn raw(&self, j: usize) -> f64 {
        let c = f64::from(self.count[j]);
        if OPEN { 0.0 - c } else { c }
    }

    fn buckets(&self) -> usize {
        self.hull.len()
    }

    /// Slots of bucket `b`.
    fn slots(&self, b: usize) -> core::ops::Range<usize> {
        b * BUCKET..((b + 1) * BUCKET).min(self.count.len())
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
        let (mut slope, mut raw) = ([0.0; BUCKET], [0.0; BUCKET]);
        // Straight loops over slices, which the compiler vectorises.
        let m = self.ys.len();
        if OPEN {
            let ys = &self.ys[base.min(m)..slots.end.min(m)];
            for (s, &b) in slope.iter_mut().zip(ys) {
                *s = self.scale * f64::from(b);
            }
            if slots.end > m {
                slope[m - base] = self.scale;
            }
        } else {
            let ys = &self.ys[m - slots.end..m - base];
            for (s, &b) in slope.iter_mut().zip(ys.iter().rev()) {
                *s = self.scale * f64::from(b);
            }
        }
        for (r, &c) in raw.iter_mut().zip(&self.count[slots.clone()]) {
            *r = if OPEN {
                0.0 - f64::from(c)
            } else {
                f64::from(c)
            };
        }
        // The hull so far: each line's offset, slope and intercept.
        let (mut offset, mut hs, mut hc) = ([0u8; BUCKET], [0.0; BUCKET], [0.0; BUCKET]);
        let mut len = 0usize;
        for o in 0..slots.len() {
            let (sl, cl) = (slope[o], raw[o]);
            while len >= 2 {
                let (s1, c1, s2, c2) = (hs[len - 2], hc[len - 2], hs[len - 1], hc[len - 1]);
                // Line 2 never wins if line l overtakes it no later than it
                // overtakes line 1.
                if (c1 - c2) * (sl - s2) >= (c2 - cl) * (s2 - s1) {
                    len -= 1;
                } else {
                    break;
                }
            }
            (offset[len], hs[len], hc[len]) = (o as u8, sl, cl);
            len += 1;
        }
        self.hull[b] = offset[..len].iter().fold(0, |mask, &o| mask | 1 << o);
        // The first line is never popped.
        self.ptr[b] = 0;
    }

    /// Moves bucket `b`'s pointer to time `t` and stores its winner in leaf `v`.
    #[inline]
    fn eval_leaf(&mut self, v: usize, b: usize, t: f64) {
        let base = b * BUCKET;
        let mask = u64::from(self.hull[b]);
        // The hull line after offset `p`, if any.
        let next_on_hull = |p: usize| {
            let above = mask >> (p + 1);
            (above != 0).then(|| p + 1 + above.trailing_zeros() as usize)
        };
        let value = |o: usize| self.slope(base + o) * t + self.raw(base + o);
        let mut p = self.ptr[b] as usize;
        let mut current = value(p);
        while let Some(q) = next_on_hull(p) {
            let next = value(q);
            if next < current {
                break;
            }
            current = next;
            p = q;
        }
        self.ptr[b] = p as u8;
        let w = base + p;
        let melt = match next_on_hull(p) {
            Some(q) => {
                let n = base + q;
                (self.raw(w) - self.raw(n)) / (self.slope(n) - self.slope(w))
            }
            None => f64::INFINITY,
        };
        let (slope, raw) = (self.slope(w), self.raw(w));
        let node = &mut self.nodes[v];
        node.slope = slope;
        node.intercept = raw + node.lazy;
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

    /// Shifts the intercepts of lines `lo..hi` by one unit ([`Self::DELTA`]),
    /// at time `t` (the tree must already be advanced to `t`).
    fn add(&mut self, lo: usize, hi: usize, t: f64) {
        if lo < hi {
            self.add_in(0, 0, self.buckets(), (lo, hi), t);
        }
    }

    fn add_in(&mut self, v: usize, lo: usize, hi: usize, range: (usize, usize), t: f64) {
        let (first, end) = (lo * BUCKET, (hi * BUCKET).min(self.count.len()));
        let (ql, qr) = range;
        if qr <= first || end <= ql {
            return;
        }
        if ql <= first && end <= qr {
            // A uniform shift keeps every winner inside the subtree.
            self.nodes[v].intercept += Self::DELTA;
            self.nodes[v].lazy += Self::DELTA;
            return;
        }
        if hi - lo == 1 {
            for c in &mut self.count[ql.max(first)..qr.min(end)] {
                *c += 1;
            }
            self.rebuild_hull(lo);
            self.eval_leaf(v, lo, t);
            return;
        }
        let mid = (lo + hi) / 2;
        let (left, right) = (v + 1, v + 2 * (mid - lo));
        self.push(v, left, right);
        self.add_in(left, lo, mid, range, t);
        self.add_in(right, mid, hi, range, t);
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

    /// The tree's envelope against a direct maximum over the lines, under a
    /// fixed pseudo-random stream of range updates, for one sweep direction.
    fn tracks_the_envelope<const OPEN: bool>(scale: f64) {
        // Enough lines for several buckets.
        let ys: Vec<f32> = (0..5 * BUCKET + 2)
            .map(|j| (j as f32 * 0.37 + 0.1) / 64.0)
            .collect();
        let mut tree = Kinetic::<OPEN>::new(&ys, scale, Buffers::default());
        let len = ys.len() + usize::from(OPEN);
        let slope = |j: usize| match (OPEN, ys.get(j)) {
            (true, Some(&b)) => scale * f64::from(b),
            (true, None) => scale,
            (false, _) => scale * f64::from(ys[ys.len() - 1 - j]),
        };
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
            tree.advance(t);
            tree.add(lo, hi, t);
            for cj in &mut c[lo..hi] {
                *cj += Kinetic::<OPEN>::DELTA;
            }
            tree.advance(t);
            let want = (0..len)
                .map(|j| slope(j) * t + c[j])
                .fold(f64::MIN, f64::max);
            assert!((tree.max_at(t) - want).abs() < 1e-9, "t = {t}");
            t += ((state >> 40) % 7) as f64 * 0.01;
        }
    }

    #[test]
    fn kinetic_tree_tracks_the_envelope() {
        tracks_the_envelope::<true>(40.0);
        tracks_the_envelope::<false>(-40.0);
    }
}
