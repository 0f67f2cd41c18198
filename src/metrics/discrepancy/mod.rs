//! Star discrepancy (exact) and the L2 discrepancies (Warnock's L2-star,
//! Hickernell's centred and wrap-around), one file per algorithm.

mod l2;
mod star;
mod wraparound;

pub use l2::{centered_l2_discrepancy, l2_star_discrepancy};
pub use star::star_discrepancy;
pub use wraparound::wraparound_l2_discrepancy;

use alloc::vec::Vec;

use glam::Vec2;

use super::{radix_sort, sort_keys_in_place};

/// The keys `bits << 32 | index` of `points` sorted, that is, the indices in
/// increasing order of one coordinate (`-0.0` as 0; ties in index order)
/// with each coordinate kept next to its index ([`key_value`] reads it
/// back), by a radix sort of the f32 bits, which order like the values for
/// the non-negative floats validation lets through.
pub(super) fn sorted_keys(points: &[Vec2], coordinate: impl Fn(&Vec2) -> f32) -> Vec<u64> {
    let mut keys: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (u64::from(coordinate(p).to_bits() & 0x7fff_ffff) << 32) | i as u64)
        .collect();
    radix_sort(&mut keys, |&k| k >> 32, 31);
    keys
}

/// The keys of [`sorted_keys`] in the same order, sorted in place by
/// [`sort_keys_in_place`] (no scratch copy, so 8 bytes a point at the peak
/// instead of 16).
pub(super) fn keys_in_place(points: &[Vec2], coordinate: impl Fn(&Vec2) -> f32) -> Vec<u64> {
    let mut keys: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (u64::from(coordinate(p).to_bits() & 0x7fff_ffff) << 32) | i as u64)
        .collect();
    sort_keys_in_place(&mut keys);
    keys
}

/// The coordinate of a [`sorted_keys`] key.
#[inline]
pub(super) fn key_value(key: u64) -> f32 {
    f32::from_bits((key >> 32) as u32)
}

#[doc(hidden)]
pub use wraparound::wraparound_l2_discrepancy_quadratic;
