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
    let mut keys = unsorted_keys(points, coordinate);
    radix_sort(&mut keys, |&k| k >> 32, 31);
    keys
}

/// The keys `bits << 32 | index` of `points`, in index order.
fn unsorted_keys(points: &[Vec2], coordinate: impl Fn(&Vec2) -> f32) -> Vec<u64> {
    points
        .iter()
        .enumerate()
        .map(|(i, p)| (u64::from(coordinate(p).to_bits() & 0x7fff_ffff) << 32) | i as u64)
        .collect()
}

/// The keys of [`sorted_keys`] in the same order, sorted in place by
/// [`sort_keys_in_place`] (no scratch copy, so 8 bytes a point at the peak
/// instead of 16).
pub(super) fn keys_in_place(points: &[Vec2], coordinate: impl Fn(&Vec2) -> f32) -> Vec<u64> {
    let mut keys = unsorted_keys(points, coordinate);
    sort_keys_in_place(&mut keys);
    keys
}

/// The low halves of `keys` (the point indices of [`sorted_keys`] keys),
/// packed in place two to a u64, index `k` in the low half of word `k / 2`
/// when `k` is even: 4 bytes a point. [`packed`] reads them.
pub(super) fn pack_low_halves(mut keys: Vec<u64>) -> Vec<u64> {
    let n = keys.len();
    // Word k / 2 is written only after key k / 2 (<= k) has been read.
    for k in 0..n {
        let index = keys[k] & 0xffff_ffff;
        let word = &mut keys[k / 2];
        *word = if k % 2 == 0 {
            index
        } else {
            *word | index << 32
        };
    }
    keys.truncate(n.div_ceil(2));
    keys.shrink_to_fit();
    keys
}

/// Value `k` of a [`pack_low_halves`] array.
#[inline]
pub(super) fn packed(words: &[u64], k: usize) -> u32 {
    (words[k / 2] >> (32 * (k % 2))) as u32
}

/// Sets value `k` of a [`pack_low_halves`] array.
#[inline]
pub(super) fn set_packed(words: &mut [u64], k: usize, value: u32) {
    let shift = 32 * (k % 2);
    let word = &mut words[k / 2];
    *word = (*word & !(0xffff_ffff << shift)) | u64::from(value) << shift;
}

/// The coordinate of a [`sorted_keys`] key.
#[inline]
pub(super) fn key_value(key: u64) -> f32 {
    f32::from_bits((key >> 32) as u32)
}
