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
/// Points are bucketed by a counting sort into a `g x g` grid with
/// `g ≈ sqrt(n / 2)` (about two points per cell). A first pass compares each
/// point with the points of its own and the neighbouring cells, which yields
/// an upper bound `δ` on the answer; if `δ` exceeds the cell side, a second
/// pass widens the neighbourhood to `ceil(δ / side)` cells, which is at most 3
/// because `δ` came from neighbouring cells. O(n) expected time for any set
/// that is not packed into a tiny region (O(n²) in the degenerate worst case of
/// all points in one cell), O(n) memory; no distance matrix.
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
/// As [`min_distance`], with grid neighbours taken modulo the grid size.
/// O(n) expected time, O(n) memory.
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
/// the relative radius). Random points score near 0, jittered near 0.1 to
/// 0.2, good blue noise 0.75 to 0.85; 1 is the packing bound.
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

/// Points bucketed into a `g x g` grid: `start[c]..start[c + 1]` indexes the
/// points of cell `c = cy g + cx` in `xs`, `ys`.
struct Grid {
    g: usize,
    start: Vec<u32>,
    xs: Vec<f64>,
    ys: Vec<f64>,
}

impl Grid {
    fn new(points: &[Vec2]) -> Self {
        let n = points.len();
        // About two points per cell; at most 2^12 cells a side (64 MiB of
        // cell starts), beyond which cells just hold more points.
        let g = (libm::sqrt(n as f64 / 2.0) as usize).clamp(1, 1 << 12);
        let gf = g as f64;
        let cell_of = |v: f64| ((v * gf) as usize).min(g - 1);
        let cells: Vec<u32> = points
            .iter()
            .map(|p| (cell_of(coord(p.y)) * g + cell_of(coord(p.x))) as u32)
            .collect();
        let mut start = vec![0u32; g * g + 1];
        for &c in &cells {
            start[c as usize + 1] += 1;
        }
        for c in 0..g * g {
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
        Self { g, start, xs, ys }
    }

    fn cell(&self, c: usize) -> core::ops::Range<usize> {
        self.start[c] as usize..self.start[c + 1] as usize
    }
}

#[inline(always)]
fn dist2(ax: f64, ay: f64, bx: f64, by: f64, torus: bool) -> f64 {
    let mut dx = (ax - bx).abs();
    let mut dy = (ay - by).abs();
    if torus {
        dx = dx.min(1.0 - dx);
        dy = dy.min(1.0 - dy);
    }
    dx * dx + dy * dy
}

/// Squared closest-pair distance (needs at least two points).
fn closest_pair_squared(points: &[Vec2], torus: bool) -> f64 {
    let grid = Grid::new(points);
    let g = grid.g as isize;
    let side = 1.0 / grid.g as f64;
    let mut best = f64::INFINITY;

    // Pass 1: pairs within a cell, and with the four "forward" neighbours
    // (right, and the three above), so each neighbouring pair is seen once.
    for cy in 0..g {
        for cx in 0..g {
            let own = grid.cell((cy * g + cx) as usize);
            for i in own.clone() {
                for j in i + 1..own.end {
                    let d = dist2(grid.xs[i], grid.ys[i], grid.xs[j], grid.ys[j], torus);
                    best = best.min(d);
                }
            }
            for (ox, oy) in [(1, 0), (-1, 1), (0, 1), (1, 1)] {
                let Some(other) = neighbour(cx + ox, cy + oy, g, torus) else {
                    continue;
                };
                if other == (cy * g + cx) as usize {
                    continue;
                }
                for i in own.clone() {
                    for j in grid.cell(other) {
                        let d = dist2(grid.xs[i], grid.ys[i], grid.xs[j], grid.ys[j], torus);
                        best = best.min(d);
                    }
                }
            }
        }
    }
    // On a torus with fewer than 3 cells a side, forward neighbours wrap onto
    // each other; the general pass below covers such grids exhaustively.
    // The margins keep the cell arithmetic's roundings on the safe side.
    let exhaustive = torus && g < 3;
    if best * (1.0 + 1e-9) <= side * side && !exhaustive {
        return best;
    }

    // Pass 2: every pair closer than `best` lies within `reach` cells.
    let reach = if best.is_finite() {
        ((libm::sqrt(best) / side * (1.0 + 1e-9)).ceil() as isize).clamp(1, g)
    } else {
        g
    };
    for cy in 0..g {
        for cx in 0..g {
            let own = grid.cell((cy * g + cx) as usize);
            if own.is_empty() {
                continue;
            }
            let mut visit = |other: usize| {
                for i in own.clone() {
                    for j in grid.cell(other) {
                        if i != j {
                            let d = dist2(grid.xs[i], grid.ys[i], grid.xs[j], grid.ys[j], torus);
                            best = best.min(d);
                        }
                    }
                }
            };
            if torus && 2 * reach + 1 >= g {
                (0..(g * g) as usize).for_each(&mut visit);
            } else {
                for oy in -reach..=reach {
                    for ox in -reach..=reach {
                        if let Some(other) = neighbour(cx + ox, cy + oy, g, torus) {
                            visit(other);
                        }
                    }
                }
            }
        }
    }
    best
}

/// The cell at grid position `(x, y)`, wrapped on the torus, or `None` off
/// the square.
#[inline]
fn neighbour(x: isize, y: isize, g: isize, torus: bool) -> Option<usize> {
    if torus {
        Some((y.rem_euclid(g) * g + x.rem_euclid(g)) as usize)
    } else if (0..g).contains(&x) && (0..g).contains(&y) {
        Some((y * g + x) as usize)
    } else {
        None
    }
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
