//! The constructor's search for
//! [`BlueMultiJittered`](crate::BlueMultiJittered)'s lattice: the
//! enumeration that proves a lattice's minimum-distance bound, the
//! preference order over `(g, q, h, p)`, the diagonal test, and the
//! widest jitter that keeps the bound (`docs/blue_multi_jittered.md` has
//! the construction and the proof).

use super::Lattice;
use crate::primitives::{MAX_STRATA, hash_u32};
use crate::samplers::grid::Grid;

/// The normalised bound the constructor asks for.
const TARGET: f64 = 0.6;

/// The narrowest jitter window (in sixteenths) at which a lattice must reach
/// [`TARGET`] to be taken in preference order.
const MIN_JITTER: u32 = 4;

/// The grid's sides as signed integers, for the constructor's search and the
/// bound's enumeration.
#[derive(Clone, Copy)]
pub(super) struct Shape {
    c: i64,
    r: i64,
}

/// `1 / phi^2`, where `phi` is the golden ratio: the most irrational
/// rotation, whose lattices have the fewest short vectors.
const INV_PHI_SQUARED: f64 = 0.381_966_011_250_105_1;

/// The coupling multipliers, in preference order: `q = k r / gcd(c, r)`,
/// `p = k c / gcd(c, r)` (multiples of those keep the torus seamless).
const COUPLINGS: [i64; 5] = [-1, -2, 1, 2, 0];

/// The offsets `(s, t)` the diagonal score averages over.
const OFFSETS: u32 = 16;

/// The most cell visits the constructor spends on diagonal scores.
const SCORE_BUDGET: u64 = 1 << 20;

/// A lattice passes the diagonal test when its mean squared counting error
/// is at most this share of independent uniform points'.
const DIAGONAL_SHARE: f64 = 0.5;

/// One of the sets the diagonal score counts: offsets `s`, `t` and mirror
/// images.
#[derive(Clone, Copy)]
struct View {
    s: i64,
    t: i64,
    mirror_x: bool,
    mirror_y: bool,
}

/// The most candidates per axis.
const CANDIDATES: usize = 8;

impl Shape {
    pub(super) fn of(grid: &Grid) -> Self {
        Self {
            c: grid.columns() as i64,
            r: grid.rows() as i64,
        }
    }

    /// The slack per axis, in fine cells, of a jitter window `width`
    /// sixteenths wide: the window plus four 2^-24 steps of fixed-point
    /// rounding each side; exactly one cell at full width (the stratum
    /// conversion stays inside its fine cell).
    pub(super) fn slack(self, width: u32) -> f64 {
        if width >= 16 {
            return 1.0;
        }
        let n = (self.c * self.r) as f64;
        (f64::from(width) / 16.0 + 8.0 * n / f64::from(MAX_STRATA)).min(1.0)
    }

    /// `T^2 2 n / sqrt(3)`: the squared target in fine cells.
    fn target_squared(self) -> f64 {
        let n = (self.c * self.r) as f64;
        TARGET * TARGET * 2.0 * n / 1.732_050_807_568_877_2
    }

    /// The lattice and jitter width for this grid (see the type's docs).
    pub(super) fn choose(self) -> (Lattice, u32) {
        let (gs, g_len) = candidates(self.r, INV_PHI_SQUARED);
        let (hs, h_len) = candidates(self.c, 1.0 - INV_PHI_SQUARED);
        let (gs, hs) = (&gs[..g_len], &hs[..h_len]);
        // (g, h) pairs by their distance from the golden targets.
        let mut pairs = [(0.0f64, 0u32, 0u32); CANDIDATES * CANDIDATES];
        let mut count = 0;
        for &g in gs {
            for &h in hs {
                let dev = (g as f64 / self.r as f64 - INV_PHI_SQUARED).abs()
                    + if self.c > 1 {
                        (h as f64 / self.c as f64 - 1.0 + INV_PHI_SQUARED).abs()
                    } else {
                        0.0
                    };
                pairs[count] = (dev, g, h);
                count += 1;
            }
        }
        let pairs = &mut pairs[..count];
        // Insertion sort: stable, at most 64 entries, no allocation.
        for a in 1..pairs.len() {
            let mut b = a;
            while b > 0 && pairs[b - 1].0 > pairs[b].0 {
                pairs.swap(b - 1, b);
                b -= 1;
            }
        }
        let target = self.target_squared();
        let narrow_slack = self.slack(MIN_JITTER);
        let mut fallback = (
            f64::NEG_INFINITY,
            Lattice {
                g: 1,
                q: 0,
                h: 0,
                p: 0,
            },
        );
        let uncoupled = COUPLINGS.len() - 1;
        let cost = self.score_cost();
        let mut budget = SCORE_BUDGET;
        let mut ranked: Option<(f64, Lattice)> = None;
        'tiers: for tier in 0..COUPLINGS.len() {
            if tier == uncoupled && ranked.is_some() {
                break;
            }
            for &(_, g, h) in pairs.iter() {
                for (iq, &kq) in COUPLINGS.iter().enumerate().take(tier + 1) {
                    for (ip, &kp) in COUPLINGS.iter().enumerate().take(tier + 1) {
                        // Each distinct coupling once (on coprime sides they
                        // are all 0).
                        if iq.max(ip) != tier || !self.first_coupling(iq, ip) {
                            continue;
                        }
                        let lattice = self.lattice(g, h, kq, kp);
                        let bound = self.bound_squared(&lattice, narrow_slack);
                        if bound >= target {
                            if tier == uncoupled || cost > budget {
                                if ranked.is_some() {
                                    break 'tiers;
                                }
                                return (lattice, self.widest_jitter(&lattice, MIN_JITTER));
                            }
                            budget -= cost;
                            let (score, independent) = self.diagonal_score(&lattice);
                            if score <= DIAGONAL_SHARE * independent {
                                return (lattice, self.widest_jitter(&lattice, MIN_JITTER));
                            }
                            if ranked.is_none_or(|(best, _)| score < best) {
                                ranked = Some((score, lattice));
                            }
                            continue;
                        }
                        let least = self.bound_squared(&lattice, self.slack(1));
                        if least > fallback.0 {
                            fallback = (least, lattice);
                        }
                    }
                }
            }
        }
        if let Some((_, lattice)) = ranked {
            return (lattice, self.widest_jitter(&lattice, MIN_JITTER));
        }
        // Small sets: every lattice.
        let (c, r) = (self.c as u32, self.r as u32);
        if u64::from(c) * u64::from(r) <= 256 {
            for g in (1..r.max(2)).filter(|&g| r == 1 || gcd(g.into(), r.into()) == 1) {
                for h in (1..c.max(2)).filter(|&h| c == 1 || gcd(h.into(), c.into()) == 1) {
                    for q in 0..r {
                        for p in 0..c {
                            let lattice = Lattice {
                                g: g % r,
                                q,
                                h: h % c,
                                p,
                            };
                            let least = self.bound_squared(&lattice, self.slack(1));
                            if least > fallback.0 {
                                fallback = (least, lattice);
                            }
                        }
                    }
                }
            }
        }
        (fallback.1, self.widest_jitter(&fallback.1, 1))
    }

    /// Whether couplings `iq`, `ip` give a `(q, p)` no earlier pair of
    /// indices gives.
    fn first_coupling(self, iq: usize, ip: usize) -> bool {
        let d = gcd(self.c, self.r);
        let q = |i: usize| (COUPLINGS[i] * (self.r / d)).rem_euclid(self.r);
        let p = |i: usize| (COUPLINGS[i] * (self.c / d)).rem_euclid(self.c);
        (0..iq).all(|i| q(i) != q(iq)) && (0..ip).all(|i| p(i) != p(ip))
    }

    /// The widest jitter (in sixteenths, at least `least`) whose bound
    /// still reaches the target, or `least`.
    fn widest_jitter(self, lattice: &Lattice, least: u32) -> u32 {
        let target = self.target_squared();
        (least + 1..=16)
            .rev()
            .find(|&width| self.bound_squared(lattice, self.slack(width)) >= target)
            .unwrap_or(least)
    }

    /// The lattice with multipliers `g`, `h` and couplings `kq`, `kp`.
    fn lattice(self, g: u32, h: u32, kq: i64, kp: i64) -> Lattice {
        let d = gcd(self.c, self.r);
        Lattice {
            g,
            q: (kq * (self.r / d)).rem_euclid(self.r) as u32,
            h,
            p: (kp * (self.c / d)).rem_euclid(self.c) as u32,
        }
    }

    /// The centre, in fine cells, of the unjittered point in cell `(i, j)`
    /// of the set with offsets `s`, `t`, mirrored as the flags say.
    fn centre(self, lattice: &Lattice, view: View, i: i64, j: i64) -> (f64, f64) {
        let Self { c, r } = self;
        let n = c * r;
        let i0 = if view.mirror_y { r - 1 - i } else { i };
        let j0 = if view.mirror_x { c - 1 - j } else { j };
        let (g, q, h, p) = lattice.signed();
        let mut x = j0 * r + (g * i0 + q * j0 + view.s).rem_euclid(r);
        let mut y = i0 * c + (h * j0 + p * i0 + view.t).rem_euclid(c);
        if view.mirror_x {
            x = n - 1 - x;
        }
        if view.mirror_y {
            y = n - 1 - y;
        }
        (x as f64 + 0.5, y as f64 + 0.5)
    }

    /// The counting error (points) of the set on the half-plane below the
    /// diagonal `y = x` (only the cells the diagonal crosses can err), the
    /// variance the jitter adds on ties, and the variance of independent
    /// uniform points in those cells.
    fn diagonal_error(self, lattice: &Lattice, view: View) -> (f64, f64, f64) {
        let Self { c, r } = self;
        let (mut error, mut ties, mut independent) = (0.0, 0.0, 0.0);
        for j in 0..c {
            // Rows whose cells the diagonal crosses in column j.
            let first = (j * r) / c;
            let last = (((j + 1) * r - 1) / c).min(r - 1);
            for i in first..=last {
                let (x0, y0) = ((j * r) as f64, (i * c) as f64);
                let (x1, y1) = (x0 + r as f64, y0 + c as f64);
                // Area below y = x in the cell: integral of clamp(x - y0, 0, c).
                let lo = x0.max(y0).min(x1);
                let hi = x0.max(y1).min(x1);
                let area = 0.5 * (lo - y0 + hi - y0).max(0.0) * (hi - lo) + c as f64 * (x1 - hi);
                let (x, y) = self.centre(lattice, view, i, j);
                let (below, tie_variance) = below_diagonal(x, y);
                ties += tie_variance;
                let fraction = area / (c * r) as f64;
                error += below - fraction;
                independent += fraction * (1.0 - fraction);
            }
        }
        (error, ties, independent)
    }

    /// The cells [`diagonal_score`](Self::diagonal_score) visits, at most.
    fn score_cost(self) -> u64 {
        u64::from(OFFSETS) * 4 * (self.c + self.r) as u64
    }

    /// The mean squared counting error of `lattice` (points^2) on the
    /// half-plane below the diagonal, over [`OFFSETS`] offsets and the four
    /// mirror images (which turn the diagonal into the anti-diagonal), and
    /// the same for independent uniform points in the cells.
    fn diagonal_score(self, lattice: &Lattice) -> (f64, f64) {
        let (mut score, mut independent) = (0.0, 0.0);
        for o in 0..OFFSETS {
            let bits = hash_u32(o);
            let s = ((u64::from(bits) * self.r as u64) >> 32) as i64;
            let t = ((u64::from(bits.rotate_left(16)) * self.c as u64) >> 32) as i64;
            for flags in 0..4 {
                let view = View {
                    s,
                    t,
                    mirror_x: flags & 1 == 1,
                    mirror_y: flags & 2 == 2,
                };
                let (error, ties, variance) = self.diagonal_error(lattice, view);
                score += error * error + ties;
                independent += variance;
            }
        }
        let views = f64::from(OFFSETS * 4);
        (score / views, independent / views)
    }

    /// The square of the bound (in fine cells) with `slack` per axis;
    /// infinite for a single cell.
    pub(super) fn bound_squared(self, lattice: &Lattice, slack: f64) -> f64 {
        // A first pass over cells up to about the packing distance away
        // (in fine cells, `1.2 sqrt(n)` covers it) finds the scale.
        let wide = 1.2 * libm::sqrt((self.c * self.r) as f64);
        let first = |side: i64| libm::ceil(wide / side as f64) as i64 + 1;
        let near = self.min_over(lattice, slack, first(self.c), first(self.r));
        if !near.is_finite() {
            return near;
        }
        // Pairs whose rows are more than `reach` apart on the torus are at
        // least `(k - 1) c + 1 - slack > near` apart in y alone (likewise
        // columns), so they cannot lower the minimum.
        let reach =
            |side: i64| libm::floor((libm::sqrt(near) + slack - 1.0) / side as f64) as i64 + 1;
        self.min_over(lattice, slack, reach(self.c).max(1), reach(self.r).max(1))
    }

    /// The minimum of the pair bound over the cell offsets `(k, l)` whose
    /// torus distance is at most `reach_k` rows and `reach_l` columns.
    fn min_over(self, lattice: &Lattice, slack: f64, reach_k: i64, reach_l: i64) -> f64 {
        let Self { c, r } = self;
        let n = c * r;
        let (g, q, h, p) = lattice.signed();
        let torus = |d: i64| {
            let m = d.rem_euclid(n);
            m.min(n - m) as f64
        };
        let mut best = f64::INFINITY;
        for kd in 0..=reach_k.min(r - 1) {
            for k in [kd, -kd, r - kd, kd - r] {
                if k.abs() >= r {
                    continue;
                }
                for ld in 0..=reach_l.min(c - 1) {
                    for l in [ld, -ld, c - ld, ld - c] {
                        if l.abs() >= c || (k == 0 && l == 0) {
                            continue;
                        }
                        let a = (g * k + q * l).rem_euclid(r);
                        let b = (h * l + p * k).rem_euclid(c);
                        // A sub-column difference is A or A - r, and only 0
                        // for A = 0 (likewise rows).
                        let a_choices = if a == 0 { 1 } else { 2 };
                        let b_choices = if b == 0 { 1 } else { 2 };
                        for a in [a, a - r].into_iter().take(a_choices) {
                            for b in [b, b - c].into_iter().take(b_choices) {
                                let dx = (torus(l * r + a) - slack).max(0.0);
                                let dy = (torus(k * c + b) - slack).max(0.0);
                                best = best.min(dx * dx + dy * dy);
                            }
                        }
                    }
                }
            }
        }
        best
    }
}

/// Up to [`CANDIDATES`] multipliers coprime to `side` nearest `fraction *
/// side`; on sides of 16 and more, not within `side / 8` of 0 or `side`
/// (slowly varying sequences) nor within `side / 10` of `side / 2` (points
/// along the diagonals), unless that leaves none. `[0]` for
/// a side of 1.
fn candidates(side: i64, fraction: f64) -> ([u32; CANDIDATES], usize) {
    let mut out = [0u32; CANDIDATES];
    if side == 1 {
        return (out, 1);
    }
    let centre = libm::round(fraction * side as f64) as i64;
    for strict in [true, false] {
        let mut len = 0;
        let admissible = |g: i64| {
            g >= 1
                && g < side
                && gcd(g, side) == 1
                && (!strict
                    || side < 16
                    || (8 * g > side && 8 * g < 7 * side && (10 * g - 5 * side).abs() >= side))
        };
        // Outward from the centre: centre, centre + 1, centre - 1, ...
        for step in 0..2 * side {
            let g = if step % 2 == 0 {
                centre + step / 2
            } else {
                centre - (step + 1) / 2
            };
            if admissible(g) {
                out[len] = g as u32;
                len += 1;
                if len == CANDIDATES {
                    break;
                }
            }
        }
        if len > 0 {
            return (out, len);
        }
    }
    // Unreachable: 1 is coprime to every side.
    out[0] = 1;
    (out, 1)
}

const fn gcd(mut a: i64, mut b: i64) -> i64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.abs()
}

/// How much a point at `(x, y)` counts below the diagonal `y = x`: 1 below
/// it, 0 above, and a half on it, with the variance (1/4) of that half.
fn below_diagonal(x: f64, y: f64) -> (f64, f64) {
    if y < x {
        (1.0, 0.0)
    } else if y == x {
        (0.5, 0.25)
    } else {
        (0.0, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::{BlueMultiJittered, SamplerKind};

    #[test]
    fn candidates_are_coprime_and_near_the_target() {
        let (gs, len) = candidates(16, INV_PHI_SQUARED);
        assert_eq!(&gs[..len], &[5, 3, 11, 13]);
        let (gs, len) = candidates(7, INV_PHI_SQUARED);
        assert_eq!(&gs[..len], &[3, 2, 4, 1, 5, 6]);
        assert_eq!(candidates(1, 0.5).1, 1);
    }

    /// The squared toroidal minimum distance, in fine cells, of the
    /// unjittered points of `lattice` with offsets `s`, `t`, by brute force.
    fn brute_force(shape: Shape, lattice: &Lattice, s: i64, t: i64) -> f64 {
        let Shape { c, r } = shape;
        let n = c * r;
        let (g, q, h, p) = lattice.signed();
        let points: std::vec::Vec<(i64, i64)> = (0..n)
            .map(|cell| {
                let (i, j) = (cell / c, cell % c);
                (
                    j * r + (g * i + q * j + s).rem_euclid(r),
                    i * c + (h * j + p * i + t).rem_euclid(c),
                )
            })
            .collect();
        let torus = |d: i64| {
            let m = d.rem_euclid(n);
            m.min(n - m)
        };
        let mut best = i64::MAX;
        for (a, &(x0, y0)) in points.iter().enumerate() {
            for &(x1, y1) in &points[a + 1..] {
                let (dx, dy) = (torus(x1 - x0), torus(y1 - y0));
                best = best.min(dx * dx + dy * dy);
            }
        }
        best as f64
    }

    #[test]
    fn the_diagonal_error_is_the_brute_force_count() {
        // Every grid of 2 to 120 cells, square or not, a few lattices, every
        // mirror image: counting only the cells the diagonal crosses, against
        // their exact areas, gives the error of counting every point.
        for n in 2..=120u32 {
            let grid = Grid::latin(SamplerKind::BlueMultiJittered, n).unwrap();
            let shape = Shape::of(&grid);
            let Shape { c, r } = shape;
            for (g, q, h, p) in [(1, 0, 0, 0), (3, 1, 1, 2), (5, 7, 2, 1)] {
                let lattice = Lattice {
                    g: g % r as u32,
                    q: q % r as u32,
                    h: h % c as u32,
                    p: p % c as u32,
                };
                for (s, t, flags) in [(0, 0, 0), (1, 0, 1), (r - 1, c - 1, 2), (r / 2, 0, 3)] {
                    let view = View {
                        s,
                        t,
                        mirror_x: flags & 1 == 1,
                        mirror_y: flags & 2 == 2,
                    };
                    let mut below = 0.0;
                    let mut ties = 0.0;
                    for i in 0..r {
                        for j in 0..c {
                            let (x, y) = shape.centre(&lattice, view, i, j);
                            let (count, tie_variance) = below_diagonal(x, y);
                            below += count;
                            ties += tie_variance;
                        }
                    }
                    let (error, tie_variance, independent) = shape.diagonal_error(&lattice, view);
                    let brute = below - f64::from(n) / 2.0;
                    assert!(
                        (error - brute).abs() < 1e-9,
                        "n = {n}, {lattice:?}, {s} {t} {flags}: {error} against {brute}"
                    );
                    assert_eq!(tie_variance, ties);
                    // c + r - 1 crossed cells at most, each adding at most 1/4.
                    assert!(independent > 0.0 && independent <= (c + r) as f64 / 4.0);
                }
            }
        }
    }

    #[test]
    fn the_diagonal_test_picks_a_lattice_that_does_not_line_up_with_the_diagonals() {
        // On 8 x 8 every lattice that keeps the bound in the first coupling
        // tier lines its points up with a diagonal; the constructor passes
        // over them. Where the first lattice already passes (16 x 16 and
        // up), it is kept.
        for (n, passes) in [
            (64, true),
            (256, true),
            (1024, true),
            (4096, true),
            (16, false),
        ] {
            let bmj = BlueMultiJittered::new(n).unwrap();
            let shape = Shape::of(&bmj.grid);
            let (score, independent) = shape.diagonal_score(&bmj.lattice);
            assert_eq!(
                score <= DIAGONAL_SHARE * independent,
                passes,
                "n = {n}: {score} of {independent}"
            );
        }
        let shape = Shape::of(&BlueMultiJittered::new(64).unwrap().grid);
        let first = shape.lattice(3, 7, -1, -1);
        assert!(shape.bound_squared(&first, shape.slack(MIN_JITTER)) >= shape.target_squared());
        let (score, independent) = shape.diagonal_score(&first);
        assert!(score > 1.5 * independent, "{score} of {independent}");
        assert_ne!(BlueMultiJittered::new(64).unwrap().lattice, first);
    }

    #[test]
    fn the_enumerated_bound_is_the_brute_force_minimum_without_jitter() {
        // Every grid of 2 to 120 cells, several lattices each (coprime g and
        // h, every coupling), several offsets: the enumeration with no slack
        // is a lower bound, and equal to the minimum over the offsets in at least 99% of the cases
        // (it counts a few pairs of cell offsets that no pair of points has).
        let (mut tight, mut total) = (0, 0);
        for n in 2..=120u32 {
            let grid = Grid::latin(SamplerKind::BlueMultiJittered, n).unwrap();
            let shape = Shape::of(&grid);
            let (gs, g_len) = candidates(shape.r, INV_PHI_SQUARED);
            let (hs, h_len) = candidates(shape.c, 0.6);
            for &g in gs[..g_len].iter().take(3) {
                for &h in hs[..h_len].iter().take(3) {
                    for kq in COUPLINGS {
                        for kp in COUPLINGS {
                            let lattice = shape.lattice(g, h, kq, kp);
                            let bound = shape.bound_squared(&lattice, 0.0);
                            let mut least = f64::INFINITY;
                            for (s, t) in [
                                (0, 0),
                                (1, 0),
                                (0, 1),
                                (shape.r - 1, shape.c - 1),
                                (shape.r / 2, shape.c / 2),
                            ] {
                                let measured = brute_force(shape, &lattice, s, t);
                                assert!(
                                    measured >= bound,
                                    "n = {n}, {lattice:?}, s = {s}, t = {t}: {measured} < {bound}"
                                );
                                least = least.min(measured);
                            }
                            total += 1;
                            if least == bound {
                                tight += 1;
                            }
                        }
                    }
                }
            }
        }
        // Measured: tight in 16456 of 16475.
        assert!(
            tight * 100 >= total * 99,
            "tight in only {tight} of {total}"
        );
    }
}
