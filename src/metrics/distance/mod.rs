//! Minimum distances (closest pair) in the unit square and on the torus, by
//! grid bucketing, with a z-order bound and a sorted-cell grid for sets that
//! crowd the grid.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

mod robust;

use super::{coord, validate};
use crate::error::Error;
use robust::robust_closest_pair_squared;

/// Smallest Euclidean distance between two points of the set (0 when two
/// points coincide).
///
/// # Algorithm
///
/// Points are bucketed by a counting sort into a grid of about `n / 2` cells
/// (about two points per cell) over their bounding box. A first pass compares
/// each point with the points of its own and the neighbouring cells, which
/// yields an upper bound `δ` on the answer; if `δ` exceeds a cell side, a
/// second pass widens the neighbourhood to `ceil(δ / side)` cells, which is at
/// most 3 because `δ` came from neighbouring cells. Coincident points end the
/// search at once. O(n) time and memory for spread-out sets (no distance
/// matrix): about 16 bytes a point beyond the input.
///
/// If the cells hold more than `4 n` pairs in all (a diagonal, a dense
/// cluster, a few lattice blobs), the grid is abandoned before any pair is
/// compared: a z-order of the points (Morton codes, radix-sorted) gives an
/// upper bound from the pairs adjacent in it, within a constant factor of the
/// answer for one of three diagonal shifts (Chan 1998, "Approximate nearest
/// neighbor queries revisited"), and one pass over the occupied cells of side
/// that bound, kept as radix-sorted cell keys, compares O(1) pairs per point.
/// The first shift alone is tried first; the other two are added only if
/// that pass meets more than `16 n` pairs. Every step is a linear pass or a
/// radix sort of 64-bit keys (six linear passes) that hold a key's top bits
/// over the point's index; keys that share those bits are then sorted by
/// their whole key, computed again from the point (O(r log r) for r of
/// them). The peak is about 16 bytes a
/// point, and 16 more for each ghost copy on the torus. The worst case is
/// within O(n log n), in fact linear, for sets whose closest pair is at
/// least 2^-31 of their bounding box apart (below that the z-order cannot
/// see the pair and the pass may compare more pairs; the result stays
/// exact).
///
/// # Errors
///
/// [`Error::TooFewPoints`] for fewer than 2 points, and otherwise as
/// [`star_discrepancy`](super::star_discrepancy).
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::min_distance};
/// let points = [Vec2::new(0.1, 0.1), Vec2::new(0.9, 0.1), Vec2::new(0.5, 0.4)];
/// assert!((min_distance(&points)? - 0.5).abs() < 1e-7);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn min_distance(points: &[Vec2]) -> Result<f64, Error> {
    check(points, "min_distance")?;
    Ok(libm::sqrt(closest_pair_squared(points, false)))
}

/// Smallest distance between two points on the unit torus, where coordinates
/// wrap around: per axis the distance is `min(|d|, 1 - |d|)`, so pairs across
/// the seams (and the corners) count.
///
/// # Algorithm
///
/// As [`min_distance`]. On an axis where the points span more than 1/2 the
/// grid covers all of `[0, 1)` and neighbours wrap modulo the grid size; on a
/// narrower axis no pair is closer across the seam, and the grid covers just
/// the points' extent. On crowded sets, the points within the bound of a seam
/// get ghost copies one period away, and every candidate pair is measured
/// with the toroidal distance. O(n) time on spread-out sets, O(n log n) worst
/// case, O(n) memory.
///
/// # Errors
///
/// As [`min_distance`].
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::toroidal_min_distance};
/// // Close across the corner of the torus.
/// let points = [Vec2::new(0.05, 0.05), Vec2::new(0.95, 0.95), Vec2::new(0.5, 0.5)];
/// assert!((toroidal_min_distance(&points)? - 0.1f64.hypot(0.1)).abs() < 1e-7);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn toroidal_min_distance(points: &[Vec2]) -> Result<f64, Error> {
    check(points, "toroidal_min_distance")?;
    Ok(libm::sqrt(closest_pair_squared(points, true)))
}

/// [`toroidal_min_distance`] divided by `sqrt(2 / (sqrt(3) n))`, the minimum
/// distance of n points in hexagonal packing on the unit torus (Lagae & Dutré
/// 2008, "A comparison of methods for generating Poisson disk distributions",
/// the relative radius). Uniform random sets tend to 0 as n grows, good
/// Poisson-disk (blue-noise) sets score about 0.65 to 0.85, and 1 is the
/// packing bound.
///
/// # Errors
///
/// As [`min_distance`].
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::normalized_toroidal_min_distance};
/// let grid: Vec<Vec2> = (0..64)
///     .map(|i| Vec2::new((i % 8) as f32 / 8.0, (i / 8) as f32 / 8.0))
///     .collect();
/// let expected = (1.0f64 / 8.0) / (2.0 / (3.0f64.sqrt() * 64.0)).sqrt();
/// assert!((normalized_toroidal_min_distance(&grid)? - expected).abs() < 1e-12);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn normalized_toroidal_min_distance(points: &[Vec2]) -> Result<f64, Error> {
    check(points, "normalized_toroidal_min_distance")?;
    let d = libm::sqrt(closest_pair_squared(points, true));
    let n = points.len() as f64;
    Ok(d / libm::sqrt(2.0 / (libm::sqrt(3.0) * n)))
}

fn check(points: &[Vec2], metric: &'static str) -> Result<(), Error> {
    validate(points)?;
    if points.len() < 2 {
        return Err(Error::TooFewPoints {
            metric,
            needed: 2,
            got: points.len(),
        });
    }
    Ok(())
}

/// Points bucketed into a `gx x gy` grid over a rectangle: `start[c]..start[c + 1]`
/// indexes the points of cell `c = cy gx + cx` in `xs`, `ys` (f32, as the
/// input: 8 bytes a point, read back exactly as f64).
struct Grid {
    gx: usize,
    gy: usize,
    /// Cell sides (meaningful only where the grid has more than one cell).
    side_x: f64,
    side_y: f64,
    start: Vec<u32>,
    xs: Vec<f32>,
    ys: Vec<f32>,
}

impl Grid {
    /// A grid of about `n / 2` cells over the rectangle at `(ox, oy)` with
    /// sides `(wx, wy)`, with cells as square as the rectangle allows, or
    /// `None` if its cells would hold more than `4 n` pairs, which the passes
    /// below would compare one by one (uniform points give about `n`; a
    /// diagonal or a dense cluster up to `n² / 2`).
    fn new(points: &[Vec2], [ox, oy, wx, wy]: [f64; 4]) -> Option<Self> {
        let n = points.len();
        let cells = (n / 2).clamp(1, 1 << 24);
        let (gx, gy) = if wx > 0.0 && wy > 0.0 {
            let gx = (libm::sqrt(cells as f64 * wx / wy) as usize).clamp(1, cells);
            (gx, (cells / gx).max(1))
        } else if wx > 0.0 {
            (cells, 1)
        } else if wy > 0.0 {
            (1, cells)
        } else {
            (1, 1)
        };
        let axis = |v: f64, o: f64, w: f64, g: usize| {
            if g == 1 {
                0
            } else {
                (((v - o) / w * g as f64) as usize).min(g - 1)
            }
        };
        let cells: Vec<u32> = points
            .iter()
            .map(|p| {
                let cx = axis(coord(p.x), ox, wx, gx);
                let cy = axis(coord(p.y), oy, wy, gy);
                (cy * gx + cx) as u32
            })
            .collect();
        let mut start = vec![0u32; gx * gy + 1];
        for &c in &cells {
            start[c as usize + 1] += 1;
        }
        let pairs: u64 = start
            .iter()
            .map(|&c| u64::from(c) * u64::from(c.saturating_sub(1)) / 2)
            .sum();
        if pairs > 4 * n as u64 {
            return None;
        }
        for c in 0..gx * gy {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        let (mut xs, mut ys) = (vec![0.0; n], vec![0.0; n]);
        for (p, &c) in points.iter().zip(&cells) {
            let slot = &mut fill[c as usize];
            // `+ 0.0` turns -0.0 into 0.0, as `coord` does.
            xs[*slot as usize] = p.x + 0.0;
            ys[*slot as usize] = p.y + 0.0;
            *slot += 1;
        }
        Some(Self {
            gx,
            gy,
            side_x: wx / gx as f64,
            side_y: wy / gy as f64,
            start,
            xs,
            ys,
        })
    }

    /// Point `i` of the cell order.
    #[inline(always)]
    fn at(&self, i: usize) -> (f64, f64) {
        (f64::from(self.xs[i]), f64::from(self.ys[i]))
    }

    fn cell(&self, c: usize) -> core::ops::Range<usize> {
        self.start[c] as usize..self.start[c + 1] as usize
    }

    /// The cell at grid position `(x, y)`, wrapped on the axes that wrap, or
    /// `None` off the grid.
    #[inline]
    fn neighbour(&self, x: isize, y: isize, wrap: [bool; 2]) -> Option<usize> {
        let fold = |v: isize, g: usize, wrap: bool| {
            let g = g as isize;
            if wrap {
                Some(v.rem_euclid(g))
            } else {
                (0..g).contains(&v).then_some(v)
            }
        };
        let x = fold(x, self.gx, wrap[0])?;
        let y = fold(y, self.gy, wrap[1])?;
        Some((y * self.gx as isize + x) as usize)
    }
}

impl Grid {
    /// [`dist2`] between points `i` and `j` of the cell order.
    #[inline(always)]
    fn dist2(&self, i: usize, j: usize, wrap: [bool; 2]) -> f64 {
        let ((ax, ay), (bx, by)) = (self.at(i), self.at(j));
        dist2(ax, ay, bx, by, wrap)
    }
}

/// Squared distance, with the toroidal difference `min(d, 1 - d)` on the
/// axes that wrap.
#[inline(always)]
fn dist2(ax: f64, ay: f64, bx: f64, by: f64, wrap: [bool; 2]) -> f64 {
    let mut dx = (ax - bx).abs();
    let mut dy = (ay - by).abs();
    if wrap[0] {
        dx = dx.min(1.0 - dx);
    }
    if wrap[1] {
        dy = dy.min(1.0 - dy);
    }
    dx * dx + dy * dy
}

/// Margin on cell arithmetic, so that its roundings stay on the safe side.
const MARGIN: f64 = 1.0 + 1e-9;

/// Squared closest-pair distance (needs at least two points).
fn closest_pair_squared(points: &[Vec2], torus: bool) -> f64 {
    let (mut lo_x, mut lo_y, mut hi_x, mut hi_y) = (1.0f64, 1.0f64, 0.0f64, 0.0f64);
    for p in points {
        let (x, y) = (coord(p.x), coord(p.y));
        (lo_x, hi_x) = (lo_x.min(x), hi_x.max(x));
        (lo_y, hi_y) = (lo_y.min(y), hi_y.max(y));
    }
    let (wx, wy) = (hi_x - lo_x, hi_y - lo_y);
    // On an axis where the points span no more than 1/2, every difference d
    // has d <= 1 - d, so the toroidal and plain differences agree bit for bit
    // and the grid can cover just the points' extent (which keeps clusters
    // and strips fast). Only wider axes wrap, over all of [0, 1).
    let wrap = [torus && wx > 0.5, torus && wy > 0.5];
    let (ox, wx) = if wrap[0] { (0.0, 1.0) } else { (lo_x, wx) };
    let (oy, wy) = if wrap[1] { (0.0, 1.0) } else { (lo_y, wy) };
    let bounds = [ox, oy, wx, wy];
    let Some(grid) = Grid::new(points, bounds) else {
        return robust_closest_pair_squared(points, torus);
    };
    let (gx, gy) = (grid.gx as isize, grid.gy as isize);
    let mut best = f64::INFINITY;

    // Pass 1: pairs within a cell, and with the four "forward" neighbours
    // (right, and the three above), so each neighbouring pair is seen once.
    for cy in 0..gy {
        for cx in 0..gx {
            let here = (cy * gx + cx) as usize;
            let own = grid.cell(here);
            for i in own.clone() {
                for j in i + 1..own.end {
                    let d = grid.dist2(i, j, wrap);
                    best = best.min(d);
                }
                if best == 0.0 {
                    return 0.0;
                }
            }
            for (ox, oy) in [(1, 0), (-1, 1), (0, 1), (1, 1)] {
                let Some(other) = grid.neighbour(cx + ox, cy + oy, wrap) else {
                    continue;
                };
                if other == here {
                    continue;
                }
                for i in own.clone() {
                    for j in grid.cell(other) {
                        let d = grid.dist2(i, j, wrap);
                        best = best.min(d);
                    }
                }
            }
        }
    }
    // Pass 1 suffices when every pair closer than `best` is in neighbouring
    // cells. On a wrapping axis with fewer than 3 cells, forward neighbours
    // wrap onto each other, so pass 2 covers such grids exhaustively.
    let covered = |g: usize, side: f64| g == 1 || best * MARGIN <= side * side;
    let exhaustive = (wrap[0] && gx < 3) || (wrap[1] && gy < 3);
    if covered(grid.gx, grid.side_x) && covered(grid.gy, grid.side_y) && !exhaustive {
        return best;
    }

    // Pass 2: every pair closer than `best` lies within `reach` cells per axis.
    let reach = |g: isize, side: f64| {
        if g == 1 {
            0
        } else if best.is_finite() {
            (libm::ceil(libm::sqrt(best) / side * MARGIN) as isize).clamp(1, g)
        } else {
            g
        }
    };
    let (rx, ry) = (reach(gx, grid.side_x), reach(gy, grid.side_y));
    // On the torus an axis whose window covers the whole grid is visited once
    // per cell, not once per wrap.
    let span = |c: isize, r: isize, g: isize, wrap: bool| {
        if wrap && 2 * r + 1 >= g {
            0..g
        } else {
            c - r..c + r + 1
        }
    };
    for cy in 0..gy {
        for cx in 0..gx {
            let own = grid.cell((cy * gx + cx) as usize);
            if own.is_empty() {
                continue;
            }
            for y in span(cy, ry, gy, wrap[1]) {
                for x in span(cx, rx, gx, wrap[0]) {
                    let Some(other) = grid.neighbour(x, y, wrap) else {
                        continue;
                    };
                    for i in own.clone() {
                        for j in grid.cell(other) {
                            if i != j {
                                let d = grid.dist2(i, j, wrap);
                                best = best.min(d);
                            }
                        }
                    }
                }
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::robust::{grid_pass, refine_runs};
    use super::*;

    #[test]
    fn two_points_across_the_seam() {
        let p = [Vec2::new(0.01, 0.5), Vec2::new(0.99, 0.5)];
        assert!((min_distance(&p).unwrap() - 0.98).abs() < 1e-6);
        assert!((toroidal_min_distance(&p).unwrap() - 0.02).abs() < 1e-6);
    }

    fn brute(points: &[Vec2], torus: bool) -> f64 {
        let mut best = f64::INFINITY;
        for (i, a) in points.iter().enumerate() {
            for b in &points[i + 1..] {
                let w = [torus, torus];
                best = best.min(dist2(coord(a.x), coord(a.y), coord(b.x), coord(b.y), w));
            }
        }
        best
    }

    /// The z-order path on every kind of set, crowded or not (the public
    /// functions take it only for crowded ones).
    #[test]
    fn robust_path_matches_brute_force() {
        let mut state = 99u64;
        let mut unit = || {
            state += 1;
            (crate::primitives::mix64(state) >> 40) as f32 / (1u32 << 24) as f32
        };
        for case in 0..300 {
            let n = 2 + case % 97;
            let (scale, ox, oy) = match case % 5 {
                0 => (1.0, 0.0, 0.0),
                1 => (0.01, 0.995, 0.3),
                2 => (0.02, 0.99, 0.99),
                3 => (1e-5, 0.5, 0.0),
                _ => (0.3, 0.0, 0.8),
            };
            let points: Vec<Vec2> = (0..n)
                .map(|i| {
                    let (u, v) = (unit(), unit());
                    let p = match case % 3 {
                        0 => Vec2::new(u, v),
                        1 => Vec2::new(u, u),
                        _ => Vec2::new((i % 4) as f32 / 4.0, v),
                    };
                    Vec2::new((ox + p.x * scale) % 1.0, (oy + p.y * scale) % 1.0)
                })
                .collect();
            for torus in [false, true] {
                assert_eq!(
                    robust_closest_pair_squared(&points, torus),
                    brute(&points, torus),
                    "case {case}, torus {torus}"
                );
            }
        }
    }

    #[test]
    fn grid_pass_stops_at_its_budget() {
        let points: Vec<Vec2> = (0..100u32)
            .map(|i| Vec2::new((i * 37 % 100) as f32 / 100.0, (i * 61 % 97) as f32 / 97.0))
            .collect();
        for torus in [false, true] {
            // A loose bound: cells as large as the square, all pairs in one.
            assert_eq!(grid_pass(&points, torus, 2.0, 100), None);
            assert_eq!(
                grid_pass(&points, torus, 2.0, u64::MAX),
                Some(brute(&points, torus))
            );
        }
    }

    /// Cells of 2^-30 of the extent: the cell keys do not fit beside the
    /// entry codes in one u64, so runs sharing a key prefix are sorted by
    /// their whole key (a row of tiny cells, a cluster at a seam, and one
    /// far point).
    #[test]
    fn grid_pass_with_cell_keys_wider_than_the_word() {
        let mut points: Vec<Vec2> = (0..40u16)
            .map(|k| Vec2::new(f32::from(k) * 1e-9 + 1e-6, f32::from(k % 3) * 5e-10))
            .collect();
        points.extend((0..30u16).map(|k| Vec2::new(1.0 - f32::from(k + 1) * 2e-6, 0.5)));
        points.push(Vec2::new(0.9, 0.9));
        for torus in [false, true] {
            let exact = brute(&points, torus);
            assert!(exact > 0.0 && exact < 1e-16, "{exact}");
            for factor in [1.0, 4.0, 1e6] {
                assert_eq!(
                    grid_pass(&points, torus, exact * factor, u64::MAX),
                    Some(exact),
                    "torus {torus}, bound {factor} x"
                );
            }
            assert_eq!(robust_closest_pair_squared(&points, torus), exact);
        }
    }

    /// Both ways of sorting the runs: the dropped bits packed beside the
    /// code, and (when they do not fit) keys computed on demand.
    #[test]
    fn refined_runs_follow_the_whole_key() {
        // Seven prefixes over hashed low bits, codes 0..300.
        for (code_bits, dropped) in [(9, 7), (9, 55), (40, 30)] {
            let full = |c: u64| {
                ((c % 7) << dropped) | (c.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> (64 - dropped))
            };
            let mut keys: Vec<u64> = (0..300u64)
                .map(|c| ((full(c) >> dropped) << code_bits) | c)
                .collect();
            keys.sort_unstable();
            refine_runs(&mut keys, code_bits, dropped, full, None);
            let codes: Vec<u64> = keys.iter().map(|k| k & ((1 << code_bits) - 1)).collect();
            let mut expected: Vec<u64> = (0..300).collect();
            expected.sort_by_key(|&c| (full(c), c));
            assert_eq!(codes, expected, "code bits {code_bits}, dropped {dropped}");
        }
    }

    #[test]
    fn one_point_is_an_error() {
        assert!(matches!(
            min_distance(&[Vec2::ZERO]),
            Err(Error::TooFewPoints {
                needed: 2,
                got: 1,
                ..
            })
        ));
    }
}
