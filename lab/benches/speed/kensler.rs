//! Kensler's 2013 listing, written from the memo, as the speed baseline for
//! `CorrelatedMultiJittered::sample`.
//!
//! Kensler 2013, "Correlated Multi-Jittered Sampling", Pixar Technical Memo
//! 13-01: `permute(i, l, p)` (a hashed bijection of `[0, l)`, cycle-walking
//! on the next power of two), `randfloat(i, p)` (a hash scaled into
//! `[0, 1)`), and `cmj(s, m, n, p)` with the memo's sample-order shuffle
//! `s = permute(s, N, p * 0x51633e2d)`. It is C with 32-bit unsigned
//! wrapping arithmetic; Rust spells the wraps out. Nothing here is tuned:
//! the point is to time the memo's own code.
//!
//! Known limits of the listing, kept on purpose: `(s + jy) / N` in f32 can
//! round to 1.0 and across a stratum edge at large `N`, and `p = 0` makes
//! every `p * constant` seed 0. The bench only times it.

use wellspread::glam::Vec2;

/// The memo's `permute(i, l, p)`: element `i` of a permutation of `[0, l)`
/// chosen by `p`. A hash that is a bijection on the smallest power of two
/// `>= l` (xorshifts masked to that width and odd multiplies), repeated
/// until the value falls below `l` (cycle walking), then rotated by `p`.
pub fn permute(mut i: u32, l: u32, p: u32) -> u32 {
    let mut w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    loop {
        i ^= p;
        i = i.wrapping_mul(0xe170_893d);
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i = i.wrapping_mul(0x0929_eb3f);
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i = i.wrapping_mul(1 | p >> 27);
        i = i.wrapping_mul(0x6935_fa69);
        i ^= (i & w) >> 11;
        i = i.wrapping_mul(0x74dc_b303);
        i ^= (i & w) >> 2;
        i = i.wrapping_mul(0x9e50_1cc3);
        i ^= (i & w) >> 2;
        i = i.wrapping_mul(0xc860_a3df);
        i &= w;
        i ^= i >> 5;
        if i < l {
            break;
        }
    }
    i.wrapping_add(p) % l
}

/// The memo's `randfloat(i, p)`: a hash of `i` keyed by `p`, times
/// `1 / 4294967808` (so that the f32 product stays below 1.0).
pub fn randfloat(mut i: u32, p: u32) -> f32 {
    i ^= p;
    i ^= i >> 17;
    i ^= i >> 10;
    i = i.wrapping_mul(0xb365_34e5);
    i ^= i >> 12;
    i ^= i >> 21;
    i = i.wrapping_mul(0x93fc_4795);
    i ^= 0xdf6e_307f;
    i ^= i >> 17;
    i = i.wrapping_mul(1 | p >> 18);
    i as f32 * (1.0 / 4_294_967_808.0)
}

/// The memo's `cmj(s, m, n, p)`: sample `s` of an `m x n` correlated
/// multi-jittered set (`m` columns), pattern `p`, with the sample order
/// shuffled. Three `permute` and two `randfloat` calls per sample.
pub fn cmj(s: u32, m: u32, n: u32, p: u32) -> Vec2 {
    let big_n = m * n;
    let s = permute(s, big_n, p.wrapping_mul(0x5163_3e2d));
    let sx = permute(s % m, m, p.wrapping_mul(0x68bc_21eb));
    let sy = permute(s / m, n, p.wrapping_mul(0x02e5_be93));
    let jx = randfloat(s, p.wrapping_mul(0x967a_889b));
    let jy = randfloat(s, p.wrapping_mul(0x368c_c8b7));
    Vec2::new(
        (sx as f32 + (sy as f32 + jx) / n as f32) / m as f32,
        (s as f32 + jy) / big_n as f32,
    )
}

/// Panics unless the transcription above makes what the memo promises, for
/// small sets where its f32 arithmetic is exact enough: a Latin hypercube on
/// the fine `N x N` grid, and one point per cell of the coarse `m x n` grid.
/// Run before timing, so a baseline that does less work than the memo's
/// cannot pass unnoticed.
pub fn check(m: u32, n: u32) {
    let big_n = (m * n) as usize;
    for p in [1, 2, 0xdead_beef, u32::MAX] {
        let mut fine_x = vec![false; big_n];
        let mut fine_y = vec![false; big_n];
        let mut coarse = vec![false; big_n];
        for s in 0..m * n {
            let q = cmj(s, m, n, p);
            assert!(
                (0.0..1.0).contains(&q.x) && (0.0..1.0).contains(&q.y),
                "kensler::cmj({s}, {m}, {n}, {p:#x}) = {q:?}"
            );
            let at = |x: f32, strata: u32| (f64::from(x) * f64::from(strata)) as usize;
            let cell = at(q.y, n) * m as usize + at(q.x, m);
            for (seen, slot, what) in [
                (&mut fine_x, at(q.x, m * n), "fine column"),
                (&mut fine_y, at(q.y, m * n), "fine row"),
                (&mut coarse, cell, "coarse cell"),
            ] {
                assert!(
                    !seen[slot],
                    "kensler::cmj {m} x {n} pattern {p:#x}: {what} {slot} twice"
                );
                seen[slot] = true;
            }
        }
    }
}
