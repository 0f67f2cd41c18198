//! Minimum distances (closest pair) in the unit square and on the torus, by
//! grid bucketing.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use super::{coord, validate};
use crate::Error;

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
/// search at once. O(n) expected time and O(n) memory for spread-out sets (no
/// distance matrix); a dense cluster of k distinct points inside one cell of a
/// spread-out set costs O(k²).
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
/// the points' extent. O(n) expected time, O(n) memory.
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
/// indexes the points of cell `c = cy gx + cx` in `xs`, `ys`.
struct Grid {
    gx: usize,
    gy: usize,
    /// Cell sides (meaningful only where the grid has more than one cell).
    side_x: f64,
    side_y: f64,
    start: Vec<u32>,
    xs: Vec<f64>,
    ys: Vec<f64>,
}

impl Grid {
    /// A grid of about `n / 2` cells over the rectangle at `(ox, oy)` with
    /// sides `(wx, wy)`, with cells as square as the rectangle allows.
    fn new(points: &[Vec2], [ox, oy, wx, wy]: [f64; 4]) -> Self {
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
        for c in 0..gx * gy {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        let (mut xs, mut ys) = (vec![0.0; n], vec![0.0; n]);
        for (p, &c) in points.iter().zip(&cells) {
            let slot = &mut fill[c as usize];
            xs[*slot as usize] = coord(p.x);
            ys[*slot as usize] = coord(p.y);
            *slot += 1;
        }
        Self {
            gx,
            gy,
            side_x: wx / gx as f64,
            side_y: wy / gy as f64,
            start,
            xs,
            ys,
        }
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
    let grid = Grid::new(points, bounds);
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
                    let d = dist2(grid.xs[i], grid.ys[i], grid.xs[j], grid.ys[j], wrap);
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
                        let d = dist2(grid.xs[i], grid.ys[i], grid.xs[j], grid.ys[j], wrap);
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
            ((libm::sqrt(best) / side * MARGIN).ceil() as isize).clamp(1, g)
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
                                let d = dist2(grid.xs[i], grid.ys[i], grid.xs[j], grid.ys[j], wrap);
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
    use super::*;

    #[test]
    fn two_points_across_the_seam() {
        let p = [Vec2::new(0.01, 0.5), Vec2::new(0.99, 0.5)];
        assert!((min_distance(&p).unwrap() - 0.98).abs() < 1e-6);
        assert!((toroidal_min_distance(&p).unwrap() - 0.02).abs() < 1e-6);
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
