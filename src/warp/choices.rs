//! Choices: one of `n` equally likely items ([`discrete`]) and weighted
//! choices by inverse CDF ([`Discrete`]) or by alias table
//! ([`AliasTable`]), each returning the number it used remapped to `[0,
//! 1)` for the next draw.

use super::clamp_unit;

/// A choice among `n` equally likely items from one number `u` in `[0,
/// 1)`, and `u` remapped to `[0, 1)` for reuse: `(floor(u n), frac(u n))`.
///
/// The remapped number is uniform and independent of the choice when `u`
/// is uniform, so one stratified dimension can pick a light and then a
/// point on it (pbrt's sample reuse). It carries the bits of `u` that the
/// choice did not use: with `u` a multiple of 2^-24 (every wellspread
/// sampler's output) and `n = 2^k`, it has `24 - k` bits left.
///
/// # Properties
///
/// - The choice is exactly `floor(u n)`, computed in integers from the
///   bits of `u` (no rounding), so each index gets exactly the measure
///   `1 / n` of `[0, 1)` ([`discrete_pdf`]) and a stratified `u` gives
///   stratified choices. `u = 1 - 2^-24` gives `n - 1` for every `n` up to
///   2^24.
/// - The remapped `u` is in `[0, 1)`: it is rounded to f32 and clamped to
///   [`ONE_MINUS_EPSILON`]; it is 0 at the left edge of each choice's
///   interval and monotone inside it. When the `u` of a pixel's `2^m`
///   samples are one per interval of `2^-m` (a sequence's 1D draws) and
///   `n = 2^k <= 2^m`, each choice's `2^(m-k)` remapped values are one per
///   interval of `2^-(m-k)`: the reuse keeps the strata.
///
/// # Limits
///
/// The f32 numbers below 1 are 2^-24 apart near 1, so above `n = 2^24` not
/// every choice is reachable: `u = 1 - 2^-24` picks `n - ceil(n / 2^24)`
/// (`u32::MAX - 256` for `n = u32::MAX`), and a sampler's 2^-24 grid
/// reaches every `ceil(n / 2^24)`-th choice. Split larger choices into two
/// draws.
///
/// `n = 0` has no valid choice: debug builds panic on it, release builds
/// return `(0, u)` as for `n = 1`; use [`discrete_checked`] where `n` can
/// be 0. A `u` outside `[0, 1)` is clamped into it (NaN to 0), also
/// checked in debug builds.
///
/// # Cost
///
/// A 24 x 32-bit integer multiply, two shifts and one int-to-float
/// conversion; no division.
///
/// # Examples
///
/// ```
/// use wellspread::warp::discrete;
/// assert_eq!(discrete(0.0, 3), (0, 0.0));
/// assert_eq!(discrete(0.5, 4), (2, 0.0));
/// let (light, u) = discrete(0.7, 2);
/// assert!(light == 1 && (u - 0.4).abs() < 1e-6);
/// // The largest u below 1 always picks the last item.
/// let last = 1.0 - f32::EPSILON / 2.0;
/// for n in [1, 3, 1000, 1 << 24] {
///     let (i, u) = discrete(last, n);
///     assert!(i == n - 1 && u < 1.0);
/// }
/// // Above 2^24 choices, f32 cannot reach the last ones.
/// assert_eq!(discrete(last, u32::MAX).0, u32::MAX - 256);
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.1 (sampling discrete distributions, remapping the sample).
///
/// [`ONE_MINUS_EPSILON`]: crate::primitives::ONE_MINUS_EPSILON
#[inline]
pub fn discrete(u: f32, n: u32) -> (u32, f32) {
    debug_assert!(n > 0, "discrete: n = 0 has no valid choice");
    debug_assert!(
        (0.0..1.0).contains(&u),
        "discrete: u = {u} is outside [0, 1)"
    );
    let n = n.max(1);
    let u = clamp_unit(u);
    // u = m 2^-shift exactly, with m below 2^24 (so u n = m n 2^-shift,
    // exact in 56 bits); subnormals have the smallest exponent.
    let bits = u.to_bits();
    let exponent = (bits >> 23) & 0xff;
    if exponent == 0 && bits & 0x007f_ffff == 0 {
        return (0, 0.0);
    }
    let (m, shift) = if exponent == 0 {
        (bits & 0x007f_ffff, 149)
    } else {
        ((bits & 0x007f_ffff) | 0x0080_0000, 150 - exponent)
    };
    // u < 1 means exponent <= 126, so shift >= 24.
    if shift >= 64 {
        // u n < 2^-8: the choice is 0, and the f32 product (two roundings)
        // is as accurate as the caller's u.
        return (0, clamp_unit(u * n as f32));
    }
    let scaled = u64::from(m) * u64::from(n);
    let index = (scaled >> shift) as u32;
    let rest = scaled & ((1u64 << shift) - 1);
    // rest 2^-shift, rounded once to f32 (the scaling by a power of two is exact).
    let remapped = (rest as f32) * f32::from_bits((127 - shift) << 23);
    (index, clamp_unit(remapped))
}

/// [`discrete`] for an `n` that may be 0: `None` for `n = 0`, otherwise
/// `Some(discrete(u, n))`.
///
/// ```
/// use wellspread::warp::discrete_checked;
/// assert_eq!(discrete_checked(0.5, 0), None);
/// assert_eq!(discrete_checked(0.5, 2), Some((1, 0.0)));
/// ```
#[inline]
pub fn discrete_checked(u: f32, n: u32) -> Option<(u32, f32)> {
    (n > 0).then(|| discrete(u, n))
}

/// The probability of each choice of [`discrete`]: `1 / n` (0 for
/// `n = 0`, which has no choice).
///
/// ```
/// use wellspread::warp::discrete_pdf;
/// assert_eq!(discrete_pdf(4), 0.25);
/// assert_eq!(discrete_pdf(0), 0.0);
/// ```
#[inline]
pub fn discrete_pdf(n: u32) -> f32 {
    if n == 0 { 0.0 } else { 1.0 / n as f32 }
}

/// The inverse of [`discrete`]: `(index + remapped) / n`, computed in f64
/// and rounded once to f32, clamped to [`ONE_MINUS_EPSILON`]. With `n =
/// 0` it returns `remapped`, as [`discrete`] treats `n = 0` as 1.
///
/// `discrete_inverse(discrete(u, n), n)` is `u` up to the rounding of the
/// remapped value (exactly `u` when `u` is a multiple of 2^-24 and `n` a
/// power of two up to 2^24).
///
/// ```
/// use wellspread::warp::{discrete, discrete_inverse};
/// let (i, r) = discrete(0.8125, 8);
/// assert_eq!(discrete_inverse(i, r, 8), 0.8125);
/// ```
///
/// [`ONE_MINUS_EPSILON`]: crate::primitives::ONE_MINUS_EPSILON
#[inline]
pub fn discrete_inverse(index: u32, remapped: f32, n: u32) -> f32 {
    let n = n.max(1);
    clamp_unit(((f64::from(index) + f64::from(remapped)) / f64::from(n)) as f32)
}

// Weighted choices (alloc).

/// Checks a list of weights for [`Discrete::new`] and [`AliasTable::new`]
/// and returns their sum in f64 (no overflow: at most 2^32 terms below
/// 2^128 each).
#[cfg(feature = "alloc")]
fn checked_total(weights: &[f32]) -> Result<f64, crate::error::Error> {
    use crate::error::Error;
    if weights.len() > u32::MAX as usize {
        return Err(Error::TooManyWeights {
            count: weights.len(),
        });
    }
    let mut total = 0.0f64;
    for (index, &weight) in weights.iter().enumerate() {
        if !weight.is_finite() {
            return Err(Error::NonFiniteWeight { index, weight });
        }
        if weight < 0.0 {
            return Err(Error::NegativeWeight { index, weight });
        }
        total += f64::from(weight);
    }
    if total > 0.0 {
        Ok(total)
    } else {
        Err(Error::ZeroTotalWeight {
            count: weights.len(),
        })
    }
}

/// A probability as the f32 a caller divides by: 0 stays 0, anything
/// positive is at least `f32::MIN_POSITIVE`, so `1 / pmf` is finite.
#[cfg(feature = "alloc")]
#[inline]
fn positive_pmf(p: f64) -> f32 {
    if p > 0.0 {
        (p as f32).max(f32::MIN_POSITIVE)
    } else {
        0.0
    }
}

/// A weighted choice among `n` items by inverse CDF: item `i` is chosen
/// with probability `weights[i] / sum(weights)`, and the number that chose
/// it is remapped to `[0, 1)` for the next draw.
///
/// Item `i` owns the interval `[cdf[i], cdf[i + 1])` of `[0, 1)`, in item
/// order; [`sample`](Self::sample) finds the interval of `u` by binary
/// search and returns the item, `u`'s position inside the interval and the
/// item's probability.
///
/// # Properties
///
/// - Monotone: sorted `u` choose items in order, and within one item the
///   remapped values are sorted. So a stratified `u` (one per interval of
///   `1 / N`, a sequence's 1D draws) chooses item `i` within 2 of `N
///   pmf(i)` times, and the remapped values of one item keep the strata
///   that fell inside its interval: the choice of a light and the point on
///   it can share one dimension.
/// - An item of weight 0 owns an empty interval and is never chosen; its
///   [`pmf`](Self::pmf) is 0. Every chosen item's pmf is at least
///   `f32::MIN_POSITIVE`, so `1 / pmf` is finite.
/// - The interval ends are prefix sums in f64 divided by their total, so
///   the last end is exactly 1 and a `u` of `[0, 1)` always chooses an
///   item of positive weight. Under `u` on the f32 grid of 2^-24 (every
///   sampler's output) each item's probability is its pmf within 2^-24.
/// - Input outside `[0, 1)` is clamped into it (NaN to 0).
///
/// # Cost
///
/// Construction: one pass over the weights and a table of `n + 1` f64
/// (`8 (n + 1)` bytes). [`sample`](Self::sample): a binary search (about
/// `log2(n)` dependent loads) and one f64 division. [`AliasTable`] is
/// O(1) per draw but does not keep the strata.
///
/// # Limits
///
/// Needs the `alloc` feature. Weights must be finite and `>= 0`, at least
/// one positive, at most `2^32 - 1` of them; anything else is a typed
/// [`Error`](crate::Error) from [`new`](Self::new), never a panic. A
/// positive weight below about 2^-53 of the sum of the weights before it
/// vanishes in the f64 prefix sum: its interval is empty, it is never
/// chosen and its pmf is 0 (the pmf stays the probability of the choice).
///
/// # Examples
///
/// ```
/// use wellspread::warp::Discrete;
/// // Three lights with powers 1, 0 and 3: the second is never chosen.
/// let lights = Discrete::new(&[1.0, 0.0, 3.0])?;
/// assert_eq!(lights.pmf(0), 0.25);
/// assert_eq!(lights.pmf(1), 0.0);
/// let (light, u, pmf) = lights.sample(0.5);
/// assert_eq!((light, pmf), (2, 0.75));
/// // 0.5 is a third of the way into the last light's interval [0.25, 1).
/// assert!((u - 1.0 / 3.0).abs() < 1e-6);
/// assert_eq!(lights.inverse(light, u), 0.5);
/// // Stratified u stay stratified: 8 strata, 2 to the first light, 6 to the last.
/// let mut counts = [0; 3];
/// for k in 0..8 {
///     counts[lights.sample((k as f32 + 0.5) / 8.0).0 as usize] += 1;
/// }
/// assert_eq!(counts, [2, 0, 6]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// Pharr, Jakob & Humphreys 2023, *Physically Based Rendering*, 4th ed.,
/// section A.1 (sampling discrete distributions, remapping the sample).
#[cfg_attr(docsrs, doc(cfg(feature = "alloc")))]
#[cfg(feature = "alloc")]
#[derive(Clone, Debug, PartialEq)]
pub struct Discrete {
    /// `n + 1` interval ends: `cdf[0] = 0`, `cdf[n] = 1`, non-decreasing.
    cdf: alloc::boxed::Box<[f64]>,
}

#[cfg(feature = "alloc")]
impl Discrete {
    /// The choice among `weights.len()` items with these weights.
    ///
    /// # Errors
    ///
    /// [`Error::NonFiniteWeight`](crate::Error::NonFiniteWeight) or
    /// [`Error::NegativeWeight`](crate::Error::NegativeWeight) naming the
    /// first bad weight, [`Error::ZeroTotalWeight`](crate::Error::ZeroTotalWeight)
    /// for an empty or all-zero list, and
    /// [`Error::TooManyWeights`](crate::Error::TooManyWeights) above
    /// `2^32 - 1` weights.
    ///
    /// ```
    /// use wellspread::{Error, warp::Discrete};
    /// assert_eq!(
    ///     Discrete::new(&[1.0, -2.0]),
    ///     Err(Error::NegativeWeight { index: 1, weight: -2.0 })
    /// );
    /// assert_eq!(Discrete::new(&[0.0, 0.0]), Err(Error::ZeroTotalWeight { count: 2 }));
    /// assert_eq!(Discrete::new(&[]), Err(Error::ZeroTotalWeight { count: 0 }));
    /// assert!(matches!(
    ///     Discrete::new(&[1.0, f32::INFINITY]),
    ///     Err(Error::NonFiniteWeight { index: 1, .. })
    /// ));
    /// ```
    pub fn new(weights: &[f32]) -> Result<Self, crate::error::Error> {
        let total = checked_total(weights)?;
        let mut cdf = alloc::vec::Vec::with_capacity(weights.len() + 1);
        cdf.push(0.0);
        // The same additions in the same order as `total`: the last prefix
        // is `total`, so the last end is exactly 1 (and so is every end
        // after the last positive weight).
        let mut sum = 0.0f64;
        for &weight in weights {
            sum += f64::from(weight);
            cdf.push(sum / total);
        }
        Ok(Self {
            cdf: cdf.into_boxed_slice(),
        })
    }

    /// The number of items (the length of the weights).
    #[must_use]
    pub fn len(&self) -> u32 {
        // `new` accepts at most u32::MAX weights.
        (self.cdf.len() - 1) as u32
    }

    /// Always `false`: [`new`](Self::new) rejects an empty list.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.cdf.len() <= 1
    }

    /// The item chosen by `u`, `u` remapped to `[0, 1)` inside the item's
    /// interval, and the item's probability [`pmf`](Self::pmf), positive.
    ///
    /// ```
    /// use wellspread::warp::Discrete;
    /// let d = Discrete::new(&[2.0, 6.0])?;
    /// assert_eq!(d.sample(0.0), (0, 0.0, 0.25));
    /// assert_eq!(d.sample(0.625), (1, 0.5, 0.75));
    /// let (i, u, pmf) = d.sample(1.0 - f32::EPSILON / 2.0);
    /// assert!(i == 1 && u < 1.0 && pmf == 0.75);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn sample(&self, u: f32) -> (u32, f32, f32) {
        let x = f64::from(clamp_unit(u));
        // The number of ends after the first that are <= x: the interval
        // [cdf[i], cdf[i + 1]) holding x, skipping empty ones. cdf[n] = 1 > x.
        let index = self.cdf[1..].partition_point(|&end| end <= x);
        let (lo, hi) = (self.cdf[index], self.cdf[index + 1]);
        let width = hi - lo;
        let remapped = clamp_unit(((x - lo) / width) as f32);
        (index as u32, remapped, positive_pmf(width))
    }

    /// The probability of choosing item `index`: its weight over the sum of
    /// the weights (0 for a weight of 0, and for an index out of range).
    #[inline]
    #[must_use]
    pub fn pmf(&self, index: u32) -> f32 {
        let i = index as usize;
        match (self.cdf.get(i), self.cdf.get(i + 1)) {
            (Some(&lo), Some(&hi)) => positive_pmf(hi - lo),
            _ => 0.0,
        }
    }

    /// The inverse of [`sample`](Self::sample): the `u` that chooses
    /// `index` with this remapped value, `cdf[index] + remapped pmf`,
    /// computed in f64 and rounded once, in `[0, 1)`. An index out of range
    /// is read as the last item.
    ///
    /// ```
    /// use wellspread::warp::Discrete;
    /// let d = Discrete::new(&[1.0, 1.0, 2.0])?;
    /// let (i, r, _) = d.sample(0.3);
    /// assert_eq!(d.inverse(i, r), 0.3);
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn inverse(&self, index: u32, remapped: f32) -> f32 {
        let i = (index as usize).min(self.cdf.len() - 2);
        let (lo, hi) = (self.cdf[i], self.cdf[i + 1]);
        clamp_unit((lo + f64::from(clamp_unit(remapped)) * (hi - lo)) as f32)
    }
}

/// A weighted choice among `n` items in O(1) per draw, by Walker's alias
/// method built with Vose's algorithm: each of `n` equal slots holds its
/// own item with some probability and one other item (its alias) with the
/// rest.
///
/// [`sample`](Self::sample) picks a slot with [`discrete`]`(u, n)` and
/// compares the remapped number with the slot's threshold; the part of
/// the number the comparison did not use is remapped again to `[0, 1)`.
///
/// # Properties
///
/// - Item `i` is chosen with probability `weights[i] / sum(weights)`
///   ([`pmf`](Self::pmf)), within 2^-24 per slot the item occupies for
///   `u` on the f32 grid of 2^-24 (the thresholds are f32, and the
///   remapped number a slot compares with them is on a grid of `n
///   2^-24`).
/// - An item of weight 0 has threshold 0 in its slot and is nobody's
///   alias: it is never chosen, and its pmf is 0. Every chosen item's pmf
///   is at least `f32::MIN_POSITIVE`, so `1 / pmf` is finite.
/// - Not monotone in `u`: an item's measure is split over up to `n`
///   slots, so a stratified `u` is stratified over slots, not over items.
///   Where the strata matter more than the table's O(log n) search, use
///   [`Discrete`].
/// - Input outside `[0, 1)` is clamped into it (NaN to 0).
///
/// # Cost
///
/// Construction: O(n), with two work lists of `n` u32 and a table of `n`
/// slots (threshold f32, alias u32) plus `n` f32 pmfs, `12 n` bytes.
/// [`sample`](Self::sample): one [`discrete`], one load, one comparison,
/// one division: O(1) whatever `n`.
///
/// # Limits
///
/// Needs the `alloc` feature; the same weight checks and typed errors as
/// [`Discrete::new`]. With more than 2^24 items, not every slot is
/// reachable by a `u` on the 2^-24 grid ([`discrete`]'s limit).
///
/// # Examples
///
/// ```
/// use wellspread::warp::AliasTable;
/// let lights = AliasTable::new(&[1.0, 0.0, 3.0])?;
/// assert_eq!((lights.pmf(0), lights.pmf(1), lights.pmf(2)), (0.25, 0.0, 0.75));
/// let mut counts = [0u32; 3];
/// for k in 0..1024 {
///     let (light, u, pmf) = lights.sample((k as f32 + 0.5) / 1024.0);
///     assert!(u < 1.0 && pmf == lights.pmf(light));
///     counts[light as usize] += 1;
/// }
/// // The middle light has weight 0; the others get their share.
/// assert_eq!(counts, [256, 0, 768]);
/// # Ok::<(), wellspread::Error>(())
/// ```
///
/// # References
///
/// - Walker 1977, "An Efficient Method for Generating Discrete Random
///   Variables with General Distributions", ACM TOMS 3(3).
/// - Vose 1991, "A Linear Algorithm for Generating Random Numbers with a
///   Given Distribution", IEEE Transactions on Software Engineering 17(9).
#[cfg_attr(docsrs, doc(cfg(feature = "alloc")))]
#[cfg(feature = "alloc")]
#[derive(Clone, Debug, PartialEq)]
pub struct AliasTable {
    /// Per slot: the probability of keeping the slot's own item, and the
    /// alias chosen otherwise.
    slots: alloc::boxed::Box<[(f32, u32)]>,
    /// Per item: its probability, as [`AliasTable::pmf`] returns it.
    pmf: alloc::boxed::Box<[f32]>,
}

#[cfg(feature = "alloc")]
impl AliasTable {
    /// The table for `weights.len()` items with these weights (Vose's
    /// algorithm, in f64).
    ///
    /// # Errors
    ///
    /// As [`Discrete::new`]: a NaN, infinite or negative weight, no
    /// positive weight, or more than `2^32 - 1` weights.
    ///
    /// ```
    /// use wellspread::{Error, warp::AliasTable};
    /// assert_eq!(
    ///     AliasTable::new(&[0.5, -0.0, -1e-9]),
    ///     Err(Error::NegativeWeight { index: 2, weight: -1e-9 })
    /// );
    /// ```
    pub fn new(weights: &[f32]) -> Result<Self, crate::error::Error> {
        use alloc::vec::Vec;
        let total = checked_total(weights)?;
        let n = weights.len();
        let scale = n as f64 / total;
        // Each item's share in slots: 1 is one whole slot.
        let mut share: Vec<f64> = weights.iter().map(|&w| f64::from(w) * scale).collect();
        let mut slots: Vec<(f32, u32)> = (0..n as u32).map(|i| (1.0, i)).collect();
        let (mut small, mut large): (Vec<u32>, Vec<u32>) =
            (0..n as u32).partition(|&i| share[i as usize] < 1.0);
        while let (Some(&s), Some(&l)) = (small.last(), large.last()) {
            small.pop();
            // Slot s keeps item s with probability share[s]; item l fills
            // the rest, and gives that much of its own share away.
            slots[s as usize] = ((share[s as usize] as f32).clamp(0.0, 1.0), l);
            share[l as usize] = (share[l as usize] + share[s as usize]) - 1.0;
            if share[l as usize] < 1.0 {
                large.pop();
                small.push(l);
            }
        }
        // What is left is a whole slot up to rounding, and keeps its own
        // item; an item of weight 0 can only be left over if rounding lost
        // a whole slot, and even then is never kept.
        let heaviest = (0..n)
            .max_by(|&a, &b| weights[a].total_cmp(&weights[b]))
            .unwrap_or(0) as u32;
        for i in small.into_iter().chain(large) {
            slots[i as usize] = if weights[i as usize] > 0.0 {
                (1.0, i)
            } else {
                (0.0, heaviest)
            };
        }
        let pmf = weights
            .iter()
            .map(|&w| positive_pmf(f64::from(w) / total))
            .collect();
        Ok(Self {
            slots: slots.into_boxed_slice(),
            pmf,
        })
    }

    /// The number of items (the length of the weights).
    #[must_use]
    pub fn len(&self) -> u32 {
        // `new` accepts at most u32::MAX weights.
        self.slots.len() as u32
    }

    /// Always `false`: [`new`](Self::new) rejects an empty list.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.slots.is_empty()
    }

    /// The item chosen by `u`, the part of `u` the choice did not use
    /// remapped to `[0, 1)`, and the item's probability
    /// [`pmf`](Self::pmf), positive.
    ///
    /// ```
    /// use wellspread::warp::AliasTable;
    /// let t = AliasTable::new(&[1.0, 3.0])?;
    /// let (i, u, pmf) = t.sample(0.9);
    /// assert!(i < 2 && u < 1.0 && pmf == t.pmf(i));
    /// # Ok::<(), wellspread::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn sample(&self, u: f32) -> (u32, f32, f32) {
        let (slot, r) = discrete(clamp_unit(u), self.len());
        let (keep, alias) = self.slots[slot as usize];
        let (index, remapped) = if r < keep {
            (slot, r / keep)
        } else {
            // r >= keep, and r < 1, so keep < 1.
            (alias, (r - keep) / (1.0 - keep))
        };
        (index, clamp_unit(remapped), self.pmf[index as usize])
    }

    /// The probability of choosing item `index`: its weight over the sum of
    /// the weights (0 for a weight of 0, and for an index out of range).
    #[inline]
    #[must_use]
    pub fn pmf(&self, index: u32) -> f32 {
        self.pmf.get(index as usize).copied().unwrap_or(0.0)
    }
}
