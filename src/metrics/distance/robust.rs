//! The closest pair for sets that crowd the grid: a z-order bound, then
//! one pass over sorted cell keys.

use alloc::vec::Vec;

use glam::Vec2;

use super::{MARGIN, dist2};
use crate::metrics::{coord, radix_sort};
use crate::primitives::morton::morton_64;

/// Closest pair for sets that crowd the grid: a constant-factor upper bound
/// `δ0` on the answer from z-order neighbours, then one pass over a grid of
/// cells of side `δ0`, kept as sorted cell keys (so it has no empty cells).
///
/// The bound: Chan 1998 ("Approximate nearest neighbor queries revisited",
/// Discrete Comput. Geom. 20) shows that for points in a square shifted
/// along the diagonal by 0, 1/3 and 2/3 of its side, inside a quadtree of
/// twice its side, for one of the three shifts the closest pair lies in one
/// quadtree box of side O(δ); the points between them in z-order lie in that
/// box too, so some pair adjacent in one of the three z-orders is O(δ) apart.
/// Cells of side `δ0 = O(δ)` then hold O(1) points each (they are δ apart),
/// and the pass compares O(n) pairs. Coordinates are quantised to 31 bits of
/// the bounding box for the z-order (the pair distances themselves are
/// exact), so the bound holds while the closest pair is at least 2^-31 of the
/// bounding box apart; below that only the cell occupancy, not the result,
/// suffers.
///
/// On the torus, `δ0` (a plane distance) bounds the toroidal answer too;
/// points within `δ0` of a seam get ghost copies shifted by one period so
/// that pairs across the seams are neighbours in the grid, and every
/// candidate pair is measured with the toroidal distance of the originals.
pub(super) fn robust_closest_pair_squared(points: &[Vec2], torus: bool) -> f64 {
    let n = points.len();
    let plane = [false, false];
    let at = |i: u64| {
        let p = points[i as usize];
        (coord(p.x), coord(p.y))
    };
    let dist = |i: u64, j: u64, wrap: [bool; 2]| {
        let (a, b) = (at(i), at(j));
        dist2(a.0, a.1, b.0, b.1, wrap)
    };
    if n <= 32 {
        let wrap = [torus, torus];
        let mut best = f64::INFINITY;
        for i in 0..n as u64 {
            for j in i + 1..n as u64 {
                best = best.min(dist(i, j, wrap));
            }
        }
        return best;
    }

    // Quantise to 31 bits over the bounding square of the points (on the
    // fly: the coordinates are not stored).
    let (mut lo_x, mut lo_y, mut hi_x, mut hi_y) = (1.0f64, 1.0f64, 0.0f64, 0.0f64);
    for p in points {
        let (x, y) = (coord(p.x), coord(p.y));
        (lo_x, hi_x) = (lo_x.min(x), hi_x.max(x));
        (lo_y, hi_y) = (lo_y.min(y), hi_y.max(y));
    }
    let span = (hi_x - lo_x).max(hi_y - lo_y);
    let scale = if span > 0.0 {
        (2147483647.0) / span
    } else {
        0.0
    };
    let morton_of = |i: u64, shift: u32| {
        let p = points[i as usize];
        let q = |v: f64, lo: f64| (((v - lo) * scale) as u32).min(0x7fff_ffff);
        morton_64(q(coord(p.x), lo_x) + shift, q(coord(p.y), lo_y) + shift)
    };

    // δ0² from pairs adjacent in the z-order of a shift. The first shift
    // usually gives a bound within a small factor (it does for lines,
    // lattices and clusters); if the grid pass then meets more than `16 n`
    // pairs, the other two shifts make the bound a guaranteed one.
    //
    // Each key is the Morton code's top bits over the point's index, so one
    // u64 radix sort orders by (code prefix, index); runs that share a
    // prefix are then sorted by their whole code, ties by index, which is
    // the order of a stable sort by the code.
    let index_bits = 64 - (n as u64 - 1).leading_zeros();
    let index_mask = (1u64 << index_bits) - 1;
    let z_order_bound = |shifts: &[u32]| {
        let mut bound = f64::INFINITY;
        let mut keys: Vec<u64> = Vec::with_capacity(n);
        for &shift in shifts {
            keys.clear();
            keys.extend((0..n as u64).map(|i| (morton_of(i, shift) & !index_mask) | i));
            radix_sort(&mut keys, |&k| k, 64);
            refine_runs(
                &mut keys,
                index_bits,
                index_bits,
                |i| morton_of(i, shift),
                None,
            );
            for w in keys.windows(2) {
                bound = bound.min(dist(w[0] & index_mask, w[1] & index_mask, plane));
            }
        }
        bound
    };
    // Shifts by 0, 1/3 and 2/3 of the quantised square, inside a quadtree
    // of twice its side (keys of 2 x 32 bits).
    let first = z_order_bound(&[0]);
    if first == 0.0 {
        return 0.0;
    }
    if let Some(best) = grid_pass(points, torus, first, 16 * n as u64) {
        return best;
    }
    let bound = first.min(z_order_bound(&[0x2aaa_aaaa, 0x5555_5555]));
    if bound == 0.0 {
        return 0.0;
    }
    // No budget: the pass always finishes (its fallback value is never used).
    grid_pass(points, torus, bound, u64::MAX).unwrap_or(bound)
}

/// Sorts each run of `keys` (a key prefix over a `code_bits`-bit code)
/// that shares its prefix by the `dropped` low bits of the code's `full`
/// key, then by code: the order of a sort by (full key, code). Where those
/// bits fit beside the code, each key of such a run becomes them over the
/// code and the run is sorted as plain u64 (the code stays in the low
/// bits); otherwise the run is sorted by keys computed on demand. A run of
/// r keys costs O(r log r). With `cells`, pushes each key's full key there
/// in the new order.
pub(super) fn refine_runs(
    keys: &mut [u64],
    code_bits: u32,
    dropped: u32,
    full: impl Fn(u64) -> u64,
    mut cells: Option<&mut Vec<u64>>,
) {
    let code_mask = u64::MAX >> (64 - code_bits);
    let low_mask = u64::MAX >> (64 - dropped);
    let packs = dropped + code_bits <= 64;
    let mut start = 0;
    while start < keys.len() {
        let head = keys[start] >> code_bits;
        let mut end = start + 1;
        while end < keys.len() && keys[end] >> code_bits == head {
            end += 1;
        }
        let run = &mut keys[start..end];
        if run.len() == 1 {
            if let Some(cells) = cells.as_deref_mut() {
                cells.push(full(run[0] & code_mask));
            }
        } else if packs {
            for k in run.iter_mut() {
                let code = *k & code_mask;
                *k = ((full(code) & low_mask) << code_bits) | code;
            }
            run.sort_unstable();
            if let Some(cells) = cells.as_deref_mut() {
                cells.extend(run.iter().map(|&k| (head << dropped) | (k >> code_bits)));
            }
        } else {
            run.sort_unstable_by_key(|&k| (full(k & code_mask), k & code_mask));
            if let Some(cells) = cells.as_deref_mut() {
                cells.extend(run.iter().map(|&k| full(k & code_mask)));
            }
        }
        start = end;
    }
}

/// Calls `f(code, x, y)` for the point `(x, y)` of index `i` and, on the
/// torus, for each copy of it one period away across a seam it is within
/// `side` of (right; right and down; up; right and up: ghost kinds 1 to 4
/// in the low 3 bits of the code).
#[inline(always)]
fn for_entries(
    i: u64,
    (x, y): (f64, f64),
    torus: bool,
    side: f64,
    mut f: impl FnMut(u64, f64, f64),
) {
    if !torus {
        f(i, x, y);
        return;
    }
    let code = i << 3;
    f(code, x, y);
    let (near_x0, near_y0, near_y1) = (x < side, y < side, y > 1.0 - side);
    if near_x0 {
        f(code | 1, x + 1.0, y);
        if near_y1 {
            f(code | 2, x + 1.0, y - 1.0);
        }
    }
    if near_y0 {
        f(code | 3, x, y + 1.0);
        if near_x0 {
            f(code | 4, x + 1.0, y + 1.0);
        }
    }
}

/// The closest pair given an upper bound `bound` on its squared distance,
/// or `None` once more than `budget` pairs have been compared.
///
/// Each entry (a point, or on the torus a ghost copy) is one u64: its cell
/// key's top bits over its entry code (the point's index, and on the torus
/// 3 bits of ghost kind). After a radix sort, and a sort of the runs that
/// share a key prefix when the cell key does not fit whole, the runs of
/// equal cell keys are the occupied cells in key order; the pass walks them
/// reading coordinates from `points`. 16 bytes an entry: the keys, with the
/// radix sort's scratch while it sorts and then the whole cell keys.
pub(super) fn grid_pass(points: &[Vec2], torus: bool, bound: f64, budget: u64) -> Option<f64> {
    let n = points.len();
    let at = |i: u64| {
        let p = points[i as usize];
        (coord(p.x), coord(p.y))
    };
    let side = libm::sqrt(bound) * MARGIN;
    let ghost_bits = if torus { 3 } else { 0 };
    let (mut ox, mut oy, mut ex, mut ey) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    let mut entries = 0usize;
    for i in 0..n as u64 {
        for_entries(i, at(i), torus, side, |_, x, y| {
            (ox, ex) = (ox.min(x), ex.max(x));
            (oy, ey) = (oy.min(y), ey.max(y));
            entries += 1;
        });
    }
    // Cells of side at least δ0, at most 2^30 per axis; keys cy gx + cx.
    let side_cell = side.max((ex - ox).max(ey - oy) / f64::from(1u32 << 30));
    let cell = |v: f64, o: f64| ((v - o) / side_cell) as u64;
    let gx = cell(ex, ox) + 2;
    let key_bits = 64 - (gx * (cell(ey, oy) + 2)).leading_zeros();
    let cell_key = |x: f64, y: f64| cell(y, oy) * gx + cell(x, ox);
    let cell_of = |code: u64| {
        let (x, y) = at(code >> ghost_bits);
        let mut key = 0;
        for_entries(code >> ghost_bits, (x, y), torus, side, |c, x, y| {
            if c == code {
                key = cell_key(x, y);
            }
        });
        key
    };
    let max_code = ((n as u64 - 1) << ghost_bits) | if torus { 7 } else { 1 };
    let code_bits = 64 - max_code.leading_zeros();
    let code_mask = (1u64 << code_bits) - 1;
    // Low cell-key bits dropped to fit the code (0 when the key fits whole).
    let dropped = (key_bits + code_bits).saturating_sub(64);
    let mut keys: Vec<u64> = Vec::with_capacity(entries);
    for i in 0..n as u64 {
        for_entries(i, at(i), torus, side, |code, x, y| {
            keys.push(((cell_key(x, y) >> dropped) << code_bits) | code);
        });
    }
    radix_sort(&mut keys, |&k| k, (key_bits - dropped + code_bits).min(64));
    // The whole cell key of each entry in cell order (the radix scratch is
    // gone, so this keeps the peak at 16 bytes an entry).
    let mut cells: Vec<u64> = Vec::with_capacity(keys.len());
    if dropped == 0 {
        cells.extend(keys.iter().map(|&k| k >> code_bits));
    } else {
        refine_runs(&mut keys, code_bits, dropped, cell_of, Some(&mut cells));
    }
    let key_at = |p: usize| cells[p];
    // The end of the cell starting at `s` with key `key`, and the next
    // cell's key.
    let run_end = |s: usize, key: u64| {
        let mut e = s + 1;
        while e < keys.len() {
            let k = key_at(e);
            if k != key {
                return (e, k);
            }
            e += 1;
        }
        (e, u64::MAX)
    };

    let wrap = [torus, torus];
    let mut best = bound;
    let mut compared = 0u64;
    let compare = |a: &[u64], b: &[u64], best: &mut f64, compared: &mut u64| {
        *compared += (a.len() * b.len()) as u64;
        for &ca in a {
            let i = (ca & code_mask) >> ghost_bits;
            let (ax, ay) = at(i);
            for &cb in b {
                let j = (cb & code_mask) >> ghost_bits;
                if i != j {
                    let (bx, by) = at(j);
                    *best = best.min(dist2(ax, ay, bx, by, wrap));
                }
            }
        }
    };
    // `above` walks the cells of the next row, one cell start at a time.
    let (mut s, mut key) = (0, key_at(0));
    let (mut above, mut above_key) = (0, key);
    while s < keys.len() {
        let (e, next) = run_end(s, key);
        let own = &keys[s..e];
        for k in 0..own.len() {
            compare(&own[k..k + 1], &own[k + 1..], &mut best, &mut compared);
        }
        // Cell (cx + 1, cy); cx + 1 < gx, so the key stays in its row.
        if e < keys.len() && next == key + 1 {
            let (e2, _) = run_end(e, next);
            compare(own, &keys[e..e2], &mut best, &mut compared);
        }
        // Cells (cx - 1 ..= cx + 1, cy + 1); cx + 1 < gx and cx >= 1 there.
        let first = key + gx - u64::from(key % gx != 0);
        let last = key + gx + 1;
        while above < keys.len() && above_key < first {
            (above, above_key) = run_end(above, above_key);
        }
        let (mut a, mut a_key) = (above, above_key);
        while a < keys.len() && a_key <= last {
            let (a_end, a_next) = run_end(a, a_key);
            compare(own, &keys[a..a_end], &mut best, &mut compared);
            (a, a_key) = (a_end, a_next);
        }
        if compared > budget {
            return None;
        }
        (s, key) = (e, next);
    }
    Some(best)
}
