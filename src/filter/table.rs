//! The table behind the filters without a closed-form inverse CDF: the
//! piecewise-linear interpolant of `|f1|` with a run of nodes per lobe,
//! inverted exactly (see the module docs of [`filter`](super)).

use super::split;

/// Segments of a filter table over the half-support `[0, radius]`.
const SEGMENTS: usize = 240;
/// The most lobes (runs between zeros of `f1`) a table accepts: each gets
/// at least 4 segments.
pub(super) const MAX_LOBES: usize = SEGMENTS / 8;

/// The tabulated inverse CDF of `|f1|` on the half-support `[0, radius]`
/// of a symmetric filter: the piecewise-linear interpolant of `|f1|`
/// through 241 nodes, with a node at every zero of `f1`, and its exact
/// integral at each node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Table {
    /// Node positions, increasing from 0 to the radius.
    x: [f32; SEGMENTS + 1],
    /// `|f1|` at the nodes (0 at the zeros of `f1`).
    value: [f32; SEGMENTS + 1],
    /// The integral of the interpolant from 0 to each node.
    cdf: [f64; SEGMENTS + 1],
    /// The integral of `f1` (signed) over the half-support.
    integral: f64,
}

impl Table {
    /// The normalised 1D filter `f1(x) / (2 integral)` inside the support
    /// `[-radius, radius]`, 0 outside: what every tabulated filter's
    /// `evaluate_1d` returns.
    #[inline]
    pub(super) fn density(&self, x: f64, radius: f64, f1: impl Fn(f64) -> f64) -> f64 {
        if x.abs() <= radius {
            f1(x) / (2.0 * self.integral)
        } else {
            0.0
        }
    }

    /// The table of `f1` on `[0, radius]`, or `None` if `f1` has more than
    /// [`MAX_LOBES`] lobes there (found on a scan of 4096 points) or a
    /// non-positive integral.
    ///
    /// A lobe ends at every zero of `f1` where it changes sign and at
    /// every valley of `|f1|` without one (a touching zero, as in
    /// `sinc(x)^2`, or two zeros closer than the scan's step): a dip of
    /// more than 1e-6 of the largest `|f1|` on the scan, placed at its
    /// minimum. Counting sign changes alone let a filter of any number of
    /// touching zeros through, with too few segments per lobe.
    pub(super) fn new(radius: f64, f1: impl Fn(f64) -> f64) -> Option<Self> {
        // The lobes' ends inside (0, radius), and whether each is a zero
        // where f1 changes sign (a node of value 0 exactly).
        let mut ends = [0.0f64; MAX_LOBES + 1];
        let mut sign_change = [false; MAX_LOBES + 1];
        let mut lobes = 0;
        const SCAN: usize = 4096;
        let at = |i: usize| radius * i as f64 / SCAN as f64;
        let dip = 1e-6 * (0..=SCAN).map(|i| f1(at(i)).abs()).fold(0.0, f64::max);
        let mut previous = f1(0.0);
        // Valleys of |f1|: falling from the last peak (tracking the lowest
        // point) or rising from the last valley (tracking the highest).
        let (mut falling, mut low, mut low_at, mut high) = (true, previous.abs(), 0, 0.0);
        for i in 1..SCAN {
            let value = f1(at(i));
            let magnitude = value.abs();
            let end = if (previous < 0.0 && value > 0.0) || (previous > 0.0 && value < 0.0) {
                let (mut lo, mut hi) = (at(i - 1), at(i));
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if (f1(mid) > 0.0) == (f1(lo) > 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                // The zero is the valley: rising from it.
                (falling, high) = (false, magnitude);
                Some((0.5 * (lo + hi), true))
            } else if falling {
                if magnitude < low {
                    (low, low_at) = (magnitude, i);
                    None
                } else if magnitude > low + dip {
                    (falling, high) = (false, magnitude);
                    // The minimum of |f1| around the lowest scan point.
                    (low_at > 0).then(|| (valley(&f1, at(low_at - 1), at(low_at + 1)), false))
                } else {
                    None
                }
            } else {
                if magnitude > high {
                    high = magnitude;
                } else if magnitude < high - dip {
                    (falling, low, low_at) = (true, magnitude, i);
                }
                None
            };
            if let Some((x, exact_zero)) = end
                && x > ends[lobes]
            {
                lobes += 1;
                if lobes >= MAX_LOBES {
                    return None;
                }
                ends[lobes] = x;
                sign_change[lobes] = exact_zero;
            }
            if value != 0.0 {
                previous = value;
            }
        }
        lobes += 1;
        ends[lobes] = radius;
        // Segments per lobe: 4 each, the rest in proportion to its width.
        let spare = SEGMENTS - 4 * lobes;
        let mut counts = [0usize; MAX_LOBES];
        let mut used = 0;
        for (j, count) in counts.iter_mut().enumerate().take(lobes) {
            *count = 4 + (spare as f64 * (ends[j + 1] - ends[j]) / radius) as usize;
            used += *count;
        }
        let widest = (0..lobes)
            .max_by(|&a, &b| (ends[a + 1] - ends[a]).total_cmp(&(ends[b + 1] - ends[b])))
            .unwrap_or(0);
        counts[widest] += SEGMENTS - used;
        let mut table = Self {
            x: [0.0; SEGMENTS + 1],
            value: [0.0; SEGMENTS + 1],
            cdf: [0.0; SEGMENTS + 1],
            integral: 0.0,
        };
        let mut node = 0;
        for j in 0..lobes {
            for k in 0..counts[j] {
                let x = ends[j] + (ends[j + 1] - ends[j]) * k as f64 / counts[j] as f64;
                table.x[node] = x as f32;
                // A zero of f1 is a node of value 0 exactly.
                table.value[node] = if k == 0 && sign_change[j] {
                    0.0
                } else {
                    f1(f64::from(table.x[node])).abs() as f32
                };
                node += 1;
            }
        }
        table.x[SEGMENTS] = radius as f32;
        table.value[SEGMENTS] = f1(f64::from(table.x[SEGMENTS])).abs() as f32;
        // The exact integral of the interpolant, and f1's by Gauss-Legendre
        // (5 points per segment: exact for polynomials of degree 9).
        const NODES: [f64; 5] = [
            0.0,
            -0.538_469_310_105_683_1,
            0.538_469_310_105_683_1,
            -0.906_179_845_938_664,
            0.906_179_845_938_664,
        ];
        const WEIGHTS: [f64; 5] = [
            0.568_888_888_888_888_9,
            0.478_628_670_499_366_5,
            0.478_628_670_499_366_5,
            0.236_926_885_056_189_1,
            0.236_926_885_056_189_1,
        ];
        for i in 0..SEGMENTS {
            let (a, b) = (f64::from(table.x[i]), f64::from(table.x[i + 1]));
            let h = b - a;
            table.cdf[i + 1] = table.cdf[i]
                + 0.5 * h * (f64::from(table.value[i]) + f64::from(table.value[i + 1]));
            let mid = 0.5 * (a + b);
            for (t, w) in NODES.iter().zip(WEIGHTS) {
                table.integral += 0.5 * h * w * f1(mid + 0.5 * h * t);
            }
        }
        (table.integral > 0.0 && table.cdf[SEGMENTS] > 0.0).then_some(table)
    }

    /// The `x` in `[0, radius]` where the interpolant's integral from 0 is
    /// `mass` times the whole, and the interpolant there.
    #[inline]
    fn invert(&self, mass: f64) -> (f64, f64) {
        let target = mass * self.cdf[SEGMENTS];
        // The segment holding the target, skipping empty ones.
        let i = self.cdf[1..SEGMENTS].partition_point(|&c| c <= target);
        let (a, b) = (f64::from(self.x[i]), f64::from(self.x[i + 1]));
        let (va, vb) = (f64::from(self.value[i]), f64::from(self.value[i + 1]));
        let h = b - a;
        let m = (target - self.cdf[i]).max(0.0);
        // Solve va h t + (vb - va) h t^2 / 2 = m for t in [0, 1], in the
        // form without cancellation: t = 2 m' / (va + sqrt(va^2 + 2 (vb - va) m')).
        let m_per_h = m / h;
        let root = libm::sqrt((va * va + 2.0 * (vb - va) * m_per_h).max(0.0));
        let t = if va + root > 0.0 {
            (2.0 * m_per_h / (va + root)).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let x = a + t * h;
        (x, va + t * (vb - va))
    }

    /// The offset and weight of `u` for the symmetric filter `f1`.
    #[inline]
    pub(super) fn sample(&self, u: f32, f1: impl Fn(f64) -> f64) -> (f64, f64) {
        let (sign, mass) = split(u);
        let (x, density) = self.invert(mass);
        // f1 / pdf with pdf = density / (2 cdf_total), for f1 / (2 integral).
        let weight = if density > 0.0 {
            f1(x) * self.cdf[SEGMENTS] / (self.integral * density)
        } else {
            0.0
        };
        (sign * x, weight)
    }

    /// The constant `(integral of |f1|) / (integral of f1)` the weights
    /// approach.
    #[inline]
    pub(super) fn magnitude(&self) -> f64 {
        self.cdf[SEGMENTS] / self.integral
    }
}

/// The `x` in `[lo, hi]` where `|f1|` is least, by golden-section search
/// (80 steps: to f64 resolution of the interval), for a lobe's end at a
/// valley of `|f1|`.
fn valley(f1: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    const SHORT: f64 = 0.381_966_011_250_105_1; // 1 - 1 / golden ratio
    for _ in 0..80 {
        let (a, b) = (lo + SHORT * (hi - lo), hi - SHORT * (hi - lo));
        if f1(a).abs() < f1(b).abs() {
            hi = b;
        } else {
            lo = a;
        }
    }
    0.5 * (lo + hi)
}
