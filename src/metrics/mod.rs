//! Quality metrics for point sets in `[0, 1)^2`: discrepancies, minimum
//! distances and stratification checks. They take `&[Vec2]` and know nothing
//! about samplers.
//!
//! | metric | what it measures | time | memory (heap beyond the input, at the peak; measured in `tests/metric_memory.rs`) |
//! | --- | --- | --- | --- |
//! | [`star_discrepancy`] | worst anchored box, exact | O(n log² n) amortised | O(n): 18n bytes |
//! | [`l2_star_discrepancy`] | RMS of the local discrepancy (Warnock) | O(n log n) | O(n): 17n bytes |
//! | [`centered_l2_discrepancy`] | Hickernell's centred L2 | O(n log n) | O(n): 16n bytes |
//! | [`wraparound_l2_discrepancy`] | Hickernell's wrap-around L2 | O(n log n) | O(n): 16n bytes (20n off the 2^-32 grid) |
//! | [`min_distance`] | closest pair | O(n) spread out, O(n log n) worst case | O(n): 16n bytes, about 16.5n clustered |
//! | [`toroidal_min_distance`] | closest pair on the torus | O(n) spread out, O(n log n) worst case | O(n): 16n bytes, about 16.5n clustered |
//! | [`normalized_toroidal_min_distance`] | the above over the hexagonal bound | as above | as above |
//! | [`is_latin`] | one point per row and column of n x n | O(n) | O(n): 2n bytes |
//! | [`is_stratified`] | n / (columns rows) points per cell | O(n) | O(columns rows) |
//! | [`is_net_base2`] | (0, m, 2)-net in base 2 | O(n log n) | O(n): 12n bytes |
//! | [`net_t_value`] | smallest t of a (t, m, 2)-net in base 2 | O(n log n log log n) | O(n): 12n bytes |
//! | [`radial_power_spectrum`] | periodogram averaged over rings of \|k\| | O(n K²) for K frequencies | O(min(K², 2^20)) |
//!
//! Every metric checks its input first and returns an [`Error`] naming the
//! first offending point for an empty set, a NaN or infinite coordinate, or a
//! coordinate outside `[0, 1)` (1.0 and negative values included). `-0.0` is
//! accepted and treated as `0.0`. No metric panics on any input.
//!
//! The L2 discrepancies cancel terms of order 1 down to values near 1e-14, so
//! they are computed in double-double or exact integer arithmetic and stay
//! within 1e-12 relative of the exact value of the f32 inputs (tested up to
//! 2^20 points); the distances and the checks are exact. `docs/metrics.md`
//! has the accuracy of every metric and the tests that hold it.
//!
//! ```
//! use wellspread::{CorrelatedMultiJittered, Sampler2D, glam::Vec2, metrics};
//!
//! let sampler = CorrelatedMultiJittered::new(256)?;
//! let mut points = vec![Vec2::ZERO; 256];
//! sampler.fill(1, &mut points);
//! assert!(metrics::is_latin(&points)?);
//! assert!(metrics::is_stratified(&points, 16, 16)?);
//! assert!(metrics::star_discrepancy(&points)? < 0.05);
//! # Ok::<(), wellspread::Error>(())
//! ```
#![cfg_attr(docsrs, doc(cfg(feature = "alloc")))]

mod discrepancy;
mod distance;
mod double_double;
mod sort;
mod spectrum;
mod stratification;

use glam::Vec2;

use crate::error::Error;
pub(crate) use sort::{radix_sort, sort_keys_in_place};

pub use discrepancy::{
    centered_l2_discrepancy, l2_star_discrepancy, star_discrepancy, wraparound_l2_discrepancy,
};
pub use distance::{min_distance, normalized_toroidal_min_distance, toroidal_min_distance};
pub use spectrum::{MAX_SPECTRUM_FREQUENCY, radial_power_spectrum};
pub use stratification::{is_latin, is_net_base2, is_stratified, net_t_value};

/// Checks that `points` is non-empty and inside `[0, 1)^2`, naming the first
/// offending point. `-0.0` passes (it compares equal to `0.0`).
pub(crate) fn validate(points: &[Vec2]) -> Result<(), Error> {
    if points.is_empty() {
        return Err(Error::EmptyPointSet);
    }
    for (index, p) in points.iter().enumerate() {
        if !p.x.is_finite() || !p.y.is_finite() {
            return Err(Error::NonFinitePoint {
                index,
                x: p.x,
                y: p.y,
            });
        }
        if !(0.0..1.0).contains(&p.x) || !(0.0..1.0).contains(&p.y) {
            return Err(Error::PointOutOfRange {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    Ok(())
}

/// A coordinate as f64, with `-0.0` turned into `0.0` (so sorting by bits or
/// by `total_cmp` sees one zero).
#[inline]
pub(crate) fn coord(v: f32) -> f64 {
    f64::from(v) + 0.0
}
