//! The progressive sequences through [`Sequence2D`]: `fill_from` equals
//! `sample` index for index, up to the last index of the sequence, and
//! never wraps around. One generic test covers every kind that
//! `AnySampler::as_sequence` finds.

use wellspread::glam::Vec2;
use wellspread::{Halton, Pmj02, Sampler2D, SamplerKind, Sequence2D, Sobol};

use crate::guarantees::guarantees;

/// Every kind that is a sequence, as its widest set (`len() == u32::MAX`,
/// what `unbounded()` gives).
fn sequences() -> impl Iterator<Item = (SamplerKind, wellspread::AnySampler)> {
    SamplerKind::ALL.iter().filter_map(|&kind| {
        let sampler = kind.build(u32::MAX).ok()?;
        sampler.as_sequence().is_some().then_some((kind, sampler))
    })
}

/// The sequences are exactly the kinds whose guarantees say "any index".
#[test]
fn sequences_are_the_kinds_that_take_any_index() {
    for &kind in SamplerKind::ALL {
        let is_sequence = kind.build(16).unwrap().as_sequence().is_some();
        assert_eq!(is_sequence, guarantees(kind).any_index, "{kind}");
    }
    assert_eq!(sequences().count(), 3);
}

/// `fill_from(start, ..)` equals `sample(start + i, ..)` for lengths around
/// the batch widths (8 and 16 lanes) and starts up to the last index.
#[test]
fn fill_from_equals_sample() {
    for (kind, sampler) in sequences() {
        let sequence = sampler.as_sequence().unwrap();
        assert_eq!(sequence.len(), u32::MAX);
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
                sequence.fill_from(start, 42, &mut out);
                for (offset, p) in (0..).zip(&out) {
                    assert_eq!(
                        *p,
                        sequence.sample(start + offset, 42),
                        "{kind} start {start} count {count} offset {offset}"
                    );
                }
            }
        }
        // The very last index is reachable, and is a point in [0, 1)^2.
        let mut last = [Vec2::NAN; 1];
        sequence.fill_from(u32::MAX, 7, &mut last);
        assert!(
            last[0].x < 1.0 && last[0].y < 1.0 && last[0].min_element() >= 0.0,
            "{kind}: {:?}",
            last[0]
        );
    }
}

/// `fill_from` past index `u32::MAX` panics with one message for every
/// sequence, rather than wrapping to index 0.
#[test]
fn fill_from_never_wraps() {
    for (kind, sampler) in sequences() {
        for (start, count) in [(u32::MAX - 5, 8usize), (u32::MAX, 2)] {
            let result = std::panic::catch_unwind(|| {
                let mut out = vec![Vec2::ZERO; count];
                sampler.as_sequence().unwrap().fill_from(start, 0, &mut out);
            });
            let payload = result.expect_err("fill_from wrapped around");
            let message = payload
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| payload.downcast_ref::<&str>().copied())
                .unwrap_or_default();
            let end = u64::from(start) + count as u64;
            assert_eq!(
                message,
                format!(
                    "fill_from asked for indices {start}..{end} past the sequence's last index 4294967295"
                ),
                "{kind}"
            );
        }
    }
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
    assert_eq!(Sobol::unbounded(), Sobol::new(u32::MAX).unwrap());
    // A sized sequence's fill_from is not bounded by its size.
    let sized = Sobol::new(16).unwrap();
    let mut out = [Vec2::ZERO; 16];
    sized.fill_from(16, 3, &mut out);
    assert_eq!(out[15], sized.sample(31, 3));
}
