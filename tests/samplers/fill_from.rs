//! The progressive sequences without a set size: `unbounded()` and
//! `fill_from`, which must equal `sample` index for index, up to the last
//! index of the sequence.

use wellspread::glam::Vec2;
use wellspread::{Halton, Pmj02, Sampler2D, Sobol};

/// `fill_from(start, ..)` equals `sample(start + i, ..)` for lengths around
/// the batch width and starts up to the last index.
fn check_fill_from(
    len: u32,
    fill_from: impl Fn(u32, u32, &mut [Vec2]),
    sample: impl Fn(u32, u32) -> Vec2,
) {
    assert_eq!(len, u32::MAX);
    for start in [
        0,
        1,
        7,
        8,
        1000,
        1 << 31,
        u32::MAX - 100,
        u32::MAX - 16,
        u32::MAX - 8,
        u32::MAX - 1,
        u32::MAX,
    ] {
        for count in [0u32, 1, 7, 8, 9, 16, 17, 33] {
            if u64::from(start) + u64::from(count) > 1 << 32 {
                continue;
            }
            let mut out = vec![Vec2::NAN; count as usize];
            fill_from(start, 42, &mut out);
            for (offset, p) in (0..).zip(&out) {
                assert_eq!(
                    *p,
                    sample(start + offset, 42),
                    "start {start} count {count} offset {offset}"
                );
            }
        }
    }
    // The very last index is reachable, and is a point in [0, 1)^2.
    let mut last = [Vec2::NAN; 1];
    fill_from(u32::MAX, 7, &mut last);
    assert!(last[0].x < 1.0 && last[0].y < 1.0 && last[0].min_element() >= 0.0);
}

#[test]
fn sobol_fill_from_equals_sample() {
    let s = Sobol::unbounded();
    check_fill_from(
        s.len(),
        |a, b, c| s.fill_from(a, b, c),
        |i, p| s.sample(i, p),
    );
}

#[test]
fn pmj02_fill_from_equals_sample() {
    let s = Pmj02::unbounded();
    check_fill_from(
        s.len(),
        |a, b, c| s.fill_from(a, b, c),
        |i, p| s.sample(i, p),
    );
}

#[test]
fn halton_fill_from_equals_sample() {
    let s = Halton::unbounded();
    check_fill_from(
        s.len(),
        |a, b, c| s.fill_from(a, b, c),
        |i, p| s.sample(i, p),
    );
}

#[test]
fn unbounded_is_the_same_sequence() {
    for i in [0, 5, 1 << 20, u32::MAX] {
        assert_eq!(
            Sobol::unbounded().sample(i, 1),
            Sobol::new(4).unwrap().sample(i, 1)
        );
        assert_eq!(
            Pmj02::unbounded().sample(i, 1),
            Pmj02::new(4).unwrap().sample(i, 1)
        );
        assert_eq!(
            Halton::unbounded().sample(i, 1),
            Halton::new(4).unwrap().sample(i, 1)
        );
    }
    // A sized sequence's fill_from is not bounded by its size.
    let sized = Sobol::new(16).unwrap();
    let mut out = [Vec2::ZERO; 16];
    sized.fill_from(16, 3, &mut out);
    assert_eq!(out[15], sized.sample(31, 3));
}

#[test]
#[should_panic(
    expected = "fill_from asked for indices 4294967290..4294967298 past the sequence's last index 4294967295"
)]
fn sobol_fill_from_never_wraps() {
    let mut out = [Vec2::ZERO; 8];
    Sobol::unbounded().fill_from(u32::MAX - 5, 0, &mut out);
}

#[test]
#[should_panic(expected = "past the sequence's last index")]
fn pmj02_fill_from_never_wraps() {
    let mut out = [Vec2::ZERO; 2];
    Pmj02::unbounded().fill_from(u32::MAX, 0, &mut out);
}

#[test]
#[should_panic(expected = "past the sequence's last index")]
fn halton_fill_from_never_wraps() {
    let mut out = [Vec2::ZERO; 2];
    Halton::unbounded().fill_from(u32::MAX, 0, &mut out);
}
