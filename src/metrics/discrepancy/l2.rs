//! Warnock's L2-star and Hickernell's centred L2 discrepancy: sorted sweeps
//! with a Fenwick tree.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use crate::Error;
use crate::metrics::{Sum, coord, validate};

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
}
