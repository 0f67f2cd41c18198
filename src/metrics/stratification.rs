//! Stratification checks: Latin (n-rooks), m x k strata, (0, m, 2)-nets and
//! the t-value of a base-2 net.
//!
//! Cells are computed exactly from the f32 values: `floor(x * cells)` is
//! evaluated in integers from the f32's mantissa and exponent, so a point on a
//! cell's left edge is in that cell and no rounding can move it.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use super::validate;
use crate::error::Error;

/// `floor(v * cells)`, exactly, for `v` a finite f32 in `[0, 1)` (`-0.0` is 0).
#[inline]
pub(crate) fn cell_of(v: f32, cells: u64) -> u64 {
    let bits = v.to_bits() & 0x7fff_ffff;
    if bits == 0 {
        return 0;
    }
    let exponent = (bits >> 23) as i32;
    let fraction = u64::from(bits & 0x007f_ffff);
    // v = mantissa * 2^-shift, with shift >= 24 since v < 1.
    let (mantissa, shift) = if exponent == 0 {
        (fraction, 149)
    } else {
        (fraction | 0x0080_0000, 150 - exponent)
    };
    let product = u128::from(mantissa) * u128::from(cells);
    if shift >= 128 {
        0
    } else {
        (product >> shift) as u64
    }
}

/// Whether the set is Latin (n-rooks): each of the `n` columns
/// `[i/n, (i+1)/n)` and each of the `n` rows holds exactly one point.
///
/// O(n) time and O(n) memory (two bit sets). Cells are exact (see the module
/// docs): a point on a column's left edge belongs to that column.
///
/// # Errors
///
/// [`Error::EmptyPointSet`], [`Error::NonFinitePoint`] or
/// [`Error::PointOutOfRange`] (naming the first bad point). `-0.0` counts as 0.
///
/// # Examples
///
/// ```
/// use wellspread::{NRooks, Sampler2D, glam::Vec2, metrics::is_latin};
/// let rooks = NRooks::new(100)?;
/// let mut points = vec![Vec2::ZERO; 100];
/// rooks.fill(9, &mut points);
/// assert!(is_latin(&points)?);
/// assert!(!is_latin(&[Vec2::new(0.1, 0.1), Vec2::new(0.2, 0.9)])?);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn is_latin(points: &[Vec2]) -> Result<bool, Error> {
    validate(points)?;
    let n = points.len();
    let mut columns = vec![false; n];
    let mut rows = vec![false; n];
    for p in points {
        let c = cell_of(p.x, n as u64) as usize;
        let r = cell_of(p.y, n as u64) as usize;
        if columns[c] || rows[r] {
            return Ok(false);
        }
        columns[c] = true;
        rows[r] = true;
    }
    Ok(true)
}

/// Whether the set is stratified on a `columns x rows` grid: every cell
/// `[i/columns, (i+1)/columns) x [j/rows, (j+1)/rows)` holds exactly
/// `n / (columns rows)` points (one, for jittered sets of `columns rows` points).
///
/// O(n) time, O(columns rows) memory. Cells are exact (see the module docs).
///
/// # Errors
///
/// [`Error::ZeroGridSide`] if a side is 0, [`Error::GridDoesNotDivide`] if
/// `columns rows` does not divide n, and the point errors of [`is_latin`].
///
/// # Examples
///
/// ```
/// use wellspread::{Jittered, Sampler2D, glam::Vec2, metrics::is_stratified};
/// let jittered = Jittered::new(12)?; // 3 x 4 strata
/// let mut points = vec![Vec2::ZERO; 12];
/// jittered.fill(5, &mut points);
/// assert!(is_stratified(&points, 3, 4)? || is_stratified(&points, 4, 3)?);
/// assert!(is_stratified(&points, 1, 1)?);
/// assert!(is_stratified(&points, 5, 1).is_err());
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn is_stratified(points: &[Vec2], columns: u32, rows: u32) -> Result<bool, Error> {
    if columns == 0 || rows == 0 {
        return Err(Error::ZeroGridSide { columns, rows });
    }
    validate(points)?;
    let n = points.len();
    let cells = u64::from(columns) * u64::from(rows);
    if !(n as u64).is_multiple_of(cells) {
        return Err(Error::GridDoesNotDivide { columns, rows, n });
    }
    // cells divides n, so it fits in memory as counts.
    let per_cell = (n as u64 / cells) as u32;
    let mut counts = vec![0u32; cells as usize];
    for p in points {
        let c = cell_of(p.x, u64::from(columns));
        let r = cell_of(p.y, u64::from(rows));
        let count = &mut counts[(r * u64::from(columns) + c) as usize];
        if *count == per_cell {
            return Ok(false);
        }
        *count += 1;
    }
    // n points, none of the cells over per_cell, n = cells * per_cell: all full.
    Ok(true)
}

/// Whether the set is a (0, m, 2)-net in base 2: `n = 2^m` and every
/// elementary interval `[i/2^k, (i+1)/2^k) x [j/2^(m-k), (j+1)/2^(m-k))` of
/// area `1/n`, for all `m + 1` shapes `k = 0..=m`, holds exactly one point.
///
/// O(n log n) time (one pass per shape over exact integer cell indices), O(n)
/// memory (12 bytes a point: the cells as two u32 and a u32 stamp). f32
/// values just below 1 are `2^-24` apart, so no f32 set of more than 2^24
/// points is a net (its narrowest columns near 1 are empty).
///
/// # Errors
///
/// [`Error::NotPowerOfTwo`] if `n` is not a power of two, and the point errors
/// of [`is_latin`].
///
/// # Examples
///
/// ```
/// use wellspread::{glam::Vec2, metrics::is_net_base2};
/// // The Hammersley set (i / n, bit-reversed i) is a (0, m, 2)-net.
/// let m = 6;
/// let points: Vec<Vec2> = (0u32..1 << m)
///     .map(|i| Vec2::new(i as f32 / 64.0, (i.reverse_bits() >> (32 - m)) as f32 / 64.0))
///     .collect();
/// assert!(is_net_base2(&points)?);
/// # Ok::<(), wellspread::Error>(())
/// ```
pub fn is_net_base2(points: &[Vec2]) -> Result<bool, Error> {
    let m = net_order(points)?;
    let n = points.len();
    Ok(match packed_cells(points, m) {
        Some(cells) => is_net_of(n, m, || unpacked(&cells)),
        None => is_net_of(n, m, || computed_cells(points, m)),
    })
}

/// [`is_net_base2`] of the `n` points of `cells` (see [`packed_cells`]).
fn is_net_of<I: Iterator<Item = (u64, u64)>>(n: usize, m: u32, cells: impl Fn() -> I) -> bool {
    let mut stamp = vec![u32::MAX; n];
    for k in 0..=m {
        let (drop_x, drop_y) = (m - k, k);
        for (x, y) in cells() {
            // Top k bits of x, then top m - k bits of y: an index below 2^m.
            let id = (((x >> drop_x) << (m - k)) | (y >> drop_y)) as usize;
            if stamp[id] == k {
                return false;
            }
            stamp[id] = k;
        }
    }
    true
}

/// The t-value of a base-2 net: the smallest `t` for which the set of
/// `n = 2^m` points is a (t, m, 2)-net in base 2, that is, every elementary
/// interval `[i/2^a, (i+1)/2^a) x [j/2^b, (j+1)/2^b)` with `a + b = m - t` (area
/// `2^(t-m)`) holds exactly `2^t` points.
///
/// # Properties
///
/// `0 <= t <= m`, and `t = 0` exactly when [`is_net_base2`] holds. Every
/// power-of-two prefix of [`Sobol`](crate::Sobol) and [`Pmj02`](crate::Pmj02)
/// has `t = 0`; `m` identical points have `t = m` (only the unit square itself
/// holds all of them). A (t, m, 2)-net is also a (t + 1, m, 2)-net (each larger
/// elementary interval is the union of two smaller ones), which is what makes a
/// binary search over `t` valid.
///
/// # Cost
///
/// One counting pass over exact integer cell indices per shape, O(n) time
/// each; a check of one `t` visits at most its `m - t + 1` shapes (a failing
/// one usually stops early), and a galloping then binary search over `t`
/// checks O(log m) values, starting with `t = 0`, so a (0, m, 2)-net costs
/// one check: O(n m log m) time in all, O(n) memory (12 bytes a point, as
/// for [`is_net_base2`]). Cells are exact (see
/// the module docs).
///
/// # Limits
///
/// f32 values just below 1 are `2^-24` apart, so a set of more than 2^24
/// points has `t > 0`.
///
/// # Errors
///
/// [`Error::NotPowerOfTwo`] if `n` is not a power of two, and the point errors
/// of [`is_latin`].
///
/// # Examples
///
/// ```
/// use wellspread::{Sampler2D, Sobol, glam::Vec2, metrics::net_t_value};
/// let sobol = Sobol::new(256)?;
/// let mut points = vec![Vec2::ZERO; 256];
/// sobol.fill(3, &mut points);
/// assert_eq!(net_t_value(&points)?, 0);
/// // A 16 x 16 grid of cell corners is a (4, 8, 2)-net: columns 1/32 wide
/// // are empty or hold 16 points, but every elementary interval of area 1/16
/// // holds 16.
/// let grid: Vec<Vec2> = (0..256)
///     .map(|i| Vec2::new((i % 16) as f32 / 16.0, (i / 16) as f32 / 16.0))
///     .collect();
/// assert_eq!(net_t_value(&grid)?, 4);
/// assert!(net_t_value(&grid[..100]).is_err());
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Niederreiter 1992, "Random Number Generation and Quasi-Monte Carlo
/// Methods", SIAM, chapter 4 ((t, m, s)-nets).
pub fn net_t_value(points: &[Vec2]) -> Result<u32, Error> {
    let m = net_order(points)?;
    let n = points.len();
    Ok(match packed_cells(points, m) {
        Some(cells) => net_t_value_of(n, || unpacked(&cells), m),
        None => net_t_value_of(n, || computed_cells(points, m), m),
    })
}

/// [`net_t_value`] of the `n` points of `cells` (see [`packed_cells`]).
fn net_t_value_of<I: Iterator<Item = (u64, u64)>>(n: usize, cells: impl Fn() -> I, m: u32) -> u32 {
    let mut counts = vec![0u32; n];
    let check = |t: u32, counts: &mut [u32]| is_net_with_t(&cells, m, t, counts);
    // Galloping search from t = 0 (the answer for good sets, which then costs
    // one check), then a binary search. A failing check usually stops early.
    // Invariant: the set is a (hi, m, 2)-net and not a (lo - 1, m, 2)-net.
    let (mut lo, mut hi) = (0, m);
    let mut step = 1;
    while lo < hi {
        if check(lo, &mut counts) {
            hi = lo;
            break;
        }
        let next = (lo + step).min(hi);
        if check(next, &mut counts) {
            (lo, hi) = (lo + 1, next);
            break;
        }
        lo = next + 1;
        step *= 2;
    }
    while lo < hi {
        let t = lo + (hi - lo) / 2;
        if check(t, &mut counts) {
            hi = t;
        } else {
            lo = t + 1;
        }
    }
    lo
}

/// Whether the points, given as m-bit cell indices, form a (t, m, 2)-net:
/// for every shape `a + b = m - t`, no elementary interval holds more than
/// `2^t` points (with `2^m` points in `2^(m-t)` intervals, then all hold
/// exactly `2^t`).
fn is_net_with_t<I: Iterator<Item = (u64, u64)>>(
    cells: &impl Fn() -> I,
    m: u32,
    t: u32,
    counts: &mut [u32],
) -> bool {
    let d = m - t;
    let cap = 1u32 << t;
    for a in 0..=d {
        let b = d - a;
        let counts = &mut counts[..1 << d];
        counts.fill(0);
        for (x, y) in cells() {
            let id = (((x >> (m - a)) << b) | (y >> (m - b))) as usize;
            counts[id] += 1;
            if counts[id] > cap {
                return false;
            }
        }
    }
    true
}

/// `m` for `n = 2^m` points, after checking them.
fn net_order(points: &[Vec2]) -> Result<u32, Error> {
    validate(points)?;
    let n = points.len();
    if !n.is_power_of_two() {
        return Err(Error::NotPowerOfTwo { n });
    }
    Ok(n.trailing_zeros())
}

/// Each point's fine cell `(column, row)` on the `n x n` grid, `n = 2^m`,
/// in fixed point, so that the cell in a `2^k`-wide column is the top `k`
/// of its `m` bits: kept as two u32 (8 bytes a point) while `m <= 32`
/// (cells below `2^32`); `None` beyond, where [`computed_cells`] recomputes
/// them at each pass.
fn packed_cells(points: &[Vec2], m: u32) -> Option<Vec<(u32, u32)>> {
    let n = 1u64 << m;
    (m <= 32).then(|| {
        points
            .iter()
            .map(|p| (cell_of(p.x, n) as u32, cell_of(p.y, n) as u32))
            .collect()
    })
}

/// The cells of [`packed_cells`], widened.
fn unpacked(cells: &[(u32, u32)]) -> impl Iterator<Item = (u64, u64)> + '_ {
    cells.iter().map(|&(x, y)| (u64::from(x), u64::from(y)))
}

/// The cells of [`packed_cells`], computed from the points.
fn computed_cells(points: &[Vec2], m: u32) -> impl Iterator<Item = (u64, u64)> + '_ {
    let n = 1u64 << m;
    points
        .iter()
        .map(move |p| (cell_of(p.x, n), cell_of(p.y, n)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cell_of_is_exact() {
        assert_eq!(cell_of(0.0, 10), 0);
        assert_eq!(cell_of(-0.0, 10), 0);
        assert_eq!(cell_of(0.5, 2), 1);
        assert_eq!(cell_of(f32::from_bits(0x3effffff), 2), 0); // just below 1/2
        assert_eq!(cell_of(0.999_999_94, 1 << 24), (1 << 24) - 1);
        assert_eq!(cell_of(f32::from_bits(1), u64::MAX), 0);
        // 0.1f32 * 10 is 1.0000000149..., so floor is 1.
        assert_eq!(cell_of(0.1, 10), 1);
        // 0.3f32 = 0.300000011920928955078125 -> 3 of 10; 0.7f32 is below 0.7.
        assert_eq!(cell_of(0.3, 10), 3);
        assert_eq!(cell_of(0.7, 10), 6);
        for n in [3u64, 7, 1000, 12_345_678, u32::MAX as u64] {
            for i in 0..200u32 {
                let v = f32::from_bits(0x3f00_0000 + i * 40_000) - 0.5;
                let exact = cell_of(v, n);
                let approx = (f64::from(v) * n as f64).floor() as u64;
                assert!(exact.abs_diff(approx) <= 1);
            }
        }
    }

    #[test]
    fn zero_grid_side_is_an_error() {
        assert!(matches!(
            is_stratified(&[Vec2::ZERO], 0, 1),
            Err(Error::ZeroGridSide {
                columns: 0,
                rows: 1
            })
        ));
        assert!(matches!(
            is_stratified(&[Vec2::ZERO; 3], 2, 1),
            Err(Error::GridDoesNotDivide { n: 3, .. })
        ));
    }
}
