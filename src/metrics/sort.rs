//! The radix sorts the metrics share: an in-place MSD sort of coordinate
//! keys and a stable LSD sort by any integer key.

/// Sorts keys `coordinate bits << 32 | index` (coordinate bits below 2^31)
/// in place by their whole value, with no scratch copy: an MSD radix sort
/// (the American flag sort of McIlroy, Bostic & McIlroy 1993, "Engineering
/// radix sort") on the coordinate bits in digits of 8, 8, 8 and 7 bits, and a
/// comparison sort for buckets of at most 32 keys and for each run of equal
/// coordinates. O(n) passes for spread-out values, O(n log n) at worst.
pub(crate) fn sort_keys_in_place(keys: &mut [u64]) {
    sort_digits(keys, 0);
}

/// [`sort_keys_in_place`] from the digit at `level` on (0 the most significant).
fn sort_digits(keys: &mut [u64], level: usize) {
    // The lowest bit of each digit; digit 3 also reads bit 39, which the
    // keys of one bucket share.
    const LOW: [u32; 4] = [55, 47, 39, 32];
    if keys.len() <= 32 || level == LOW.len() {
        keys.sort_unstable();
        return;
    }
    let low = LOW[level];
    let digit = |k: u64| ((k >> low) & 0xff) as usize;
    let mut count = [0usize; 256];
    for &k in keys.iter() {
        count[digit(k)] += 1;
    }
    if count.contains(&keys.len()) {
        sort_digits(keys, level + 1);
        return;
    }
    let (mut head, mut end) = ([0usize; 256], [0usize; 256]);
    let mut total = 0;
    for d in 0..256 {
        head[d] = total;
        total += count[d];
        end[d] = total;
    }
    // Each key moves once, along cycles, to the next free slot of its digit.
    for d in 0..256 {
        while head[d] < end[d] {
            let mut key = keys[head[d]];
            let mut to = digit(key);
            while to != d {
                core::mem::swap(&mut key, &mut keys[head[to]]);
                head[to] += 1;
                to = digit(key);
            }
            keys[head[d]] = key;
            head[d] += 1;
        }
    }
    let mut start = 0;
    for &c in &count {
        sort_digits(&mut keys[start..start + c], level + 1);
        start += c;
    }
}

/// Stable LSD radix sort of `items` by the low `bits` bits of `key`, in
/// passes of 11 bits (all digit counts taken in one first pass; digits that
/// are the same for every item are skipped): O(n bits / 11) time, one scratch
/// copy of `items`.
pub(crate) fn radix_sort<T: Copy + Default>(
    items: &mut alloc::vec::Vec<T>,
    key: impl Fn(&T) -> u64,
    bits: u32,
) {
    const DIGIT: u32 = 11;
    const MASK: u64 = (1 << DIGIT) - 1;
    let passes = bits.div_ceil(DIGIT) as usize;
    let mut counts = alloc::vec![[0usize; 1 << DIGIT]; passes];
    for item in items.iter() {
        let k = key(item);
        for (pass, count) in counts.iter_mut().enumerate() {
            count[((k >> (pass as u32 * DIGIT)) & MASK) as usize] += 1;
        }
    }
    let mut scratch = alloc::vec![T::default(); items.len()];
    for (pass, start) in counts.iter_mut().enumerate() {
        if start.contains(&items.len()) {
            continue;
        }
        let mut total = 0;
        for c in start.iter_mut() {
            (*c, total) = (total, total + *c);
        }
        let shift = pass as u32 * DIGIT;
        for item in items.iter() {
            let d = ((key(item) >> shift) & MASK) as usize;
            scratch[start[d]] = *item;
            start[d] += 1;
        }
        core::mem::swap(items, &mut scratch);
    }
}
