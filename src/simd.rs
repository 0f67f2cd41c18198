//! Batched `fill` with runtime dispatch to the widest SIMD instruction set
//! the CPU has: the crate's one module that needs `unsafe`.
//!
//! Every sampler writes its point formula once, as a [`Kernel`] that maps
//! `N` indices to `N` points with the same integer operations on every lane
//! and no branch that depends on a lane's value. `sample` runs it with one
//! lane; `fill` runs it over batches of lanes, and the compiler turns each
//! batch into SIMD instructions. Because every lane computes exactly what
//! one-lane `sample` computes (integer arithmetic, one rounding to f32 at
//! the end), every path gives bit-identical points; the tests below check
//! each path the running CPU supports against `sample` for every sampler.
//!
//! On x86 and x86-64 with `std` and the `simd` feature, [`Isa::best`]
//! picks AVX-512 (16 lanes), AVX2 (8 lanes) or the portable loop at run
//! time. Without `simd` this module has no `unsafe` and every path is the
//! portable loop. Without `std` (no CPU
//! detection) the portable loop is compiled for whatever
//! `cfg!(target_feature)` the build enables, for example with
//! `-C target-cpu=native`.

use glam::Vec2;

/// A sampler's pattern with its per-pattern work done, mapping indices to
/// points one lane per index.
pub(crate) trait Kernel {
    /// Points `index[0], ..., index[N - 1]`: lane `l` is exactly the point
    /// that `sample(index[l], pattern)` returns.
    fn points<const N: usize>(&self, index: [u32; N]) -> [Vec2; N];
}

/// A sampler whose points need no work shared across lanes (the sequences
/// and [`Random`](crate::Random)): one index in, one point out, with no
/// branch on the index.
///
/// Kernels are traits, not closures, throughout: a trait method can be
/// `#[inline(always)]`, so the whole batch is compiled inside the function
/// for the detected instruction set. (A closure, or the standard library's
/// array helpers, may stay an out-of-line call compiled without AVX2.)
pub(crate) trait PointKernel {
    /// The point of index `index`.
    fn point(&self, index: u32) -> Vec2;
}

/// A [`PointKernel`] as a [`Kernel`], one lane per index.
pub(crate) struct Pointwise<P>(pub(crate) P);

impl<P: PointKernel> Kernel for Pointwise<P> {
    #[inline(always)]
    fn points<const N: usize>(&self, index: [u32; N]) -> [Vec2; N] {
        let mut out = [Vec2::ZERO; N];
        for (point, &index) in out.iter_mut().zip(&index) {
            *point = self.0.point(index);
        }
        out
    }
}

/// An instruction set a batched `fill` can run on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Isa {
    /// Batches of 8 lanes compiled for the build's own target features.
    Portable,
    /// Batches of 8 lanes compiled with AVX2 enabled.
    Avx2,
    /// Batches of 16 lanes compiled with AVX-512 (F, BW, DQ, VL) enabled.
    Avx512,
    /// Batches of 16 lanes compiled like [`Isa::Portable`]: the AVX-512
    /// path's lane logic, testable on a CPU without AVX-512.
    #[cfg(test)]
    PortableWide,
}

impl Isa {
    /// Every instruction set, narrowest first.
    #[cfg(test)]
    pub(crate) const ALL: [Isa; 4] = [Isa::Portable, Isa::PortableWide, Isa::Avx2, Isa::Avx512];

    /// The widest instruction set this CPU runs (detected once by `std`
    /// and cached); [`Isa::Portable`] without `simd` or `std`, or off x86.
    /// In the crate's unit tests, the set `with_isa` forces on this
    /// thread, if any: the one test seam, so that every `fill` and
    /// `fill_from` is tested on every path through its ordinary call.
    #[inline]
    pub(crate) fn best() -> Isa {
        #[cfg(test)]
        if let Some(isa) = FORCED.with(core::cell::Cell::get) {
            return isa;
        }
        if Isa::Avx512.is_supported() {
            Isa::Avx512
        } else if Isa::Avx2.is_supported() {
            Isa::Avx2
        } else {
            Isa::Portable
        }
    }

    /// Whether the running CPU has this instruction set.
    #[inline]
    pub(crate) fn is_supported(self) -> bool {
        match self {
            Isa::Portable => true,
            #[cfg(test)]
            Isa::PortableWide => true,
            #[cfg(all(
                feature = "simd",
                feature = "std",
                any(target_arch = "x86", target_arch = "x86_64")
            ))]
            Isa::Avx2 => std::is_x86_feature_detected!("avx2"),
            #[cfg(all(
                feature = "simd",
                feature = "std",
                any(target_arch = "x86", target_arch = "x86_64")
            ))]
            Isa::Avx512 => {
                std::is_x86_feature_detected!("avx512f")
                    && std::is_x86_feature_detected!("avx512bw")
                    && std::is_x86_feature_detected!("avx512dq")
                    && std::is_x86_feature_detected!("avx512vl")
            }
            #[cfg(not(all(
                feature = "simd",
                feature = "std",
                any(target_arch = "x86", target_arch = "x86_64")
            )))]
            Isa::Avx2 | Isa::Avx512 => false,
        }
    }
}

#[cfg(test)]
std::thread_local! {
    /// The instruction set [`with_isa`] forces on this thread.
    static FORCED: core::cell::Cell<Option<Isa>> = const { core::cell::Cell::new(None) };
}

/// Runs `f` with [`Isa::best`] returning `isa` on this thread (the tests'
/// override; a set the CPU lacks runs the portable loop).
#[cfg(test)]
pub(crate) fn with_isa<R>(isa: Isa, f: impl FnOnce() -> R) -> R {
    let previous = FORCED.with(|forced| forced.replace(Some(isa)));
    let result = f();
    FORCED.with(|forced| forced.set(previous));
    result
}

/// Writes `kernel`'s points `start, start + 1, ...` into `out` on
/// [`Isa::best`]. Callers keep `start + out.len() <= 2^32`.
pub(crate) fn fill<K: Kernel>(kernel: &K, start: u32, out: &mut [Vec2]) {
    debug_assert!(start as u64 + out.len() as u64 <= 1 << 32);
    let isa = Isa::best();
    #[cfg(all(
        feature = "simd",
        feature = "std",
        any(target_arch = "x86", target_arch = "x86_64")
    ))]
    match isa {
        Isa::Avx512 if Isa::Avx512.is_supported() => {
            // SAFETY: `fill_avx512` only requires that the CPU supports the
            // target features it is compiled with (AVX-512 F, BW, DQ, VL),
            // which `is_supported` has just detected at run time. It does
            // nothing else unsafe.
            #[allow(unsafe_code)]
            unsafe {
                fill_avx512(kernel, start, out);
            }
            return;
        }
        Isa::Avx2 if Isa::Avx2.is_supported() => {
            // SAFETY: `fill_avx2` only requires that the CPU supports AVX2,
            // the target feature it is compiled with, which `is_supported`
            // has just detected at run time. It does nothing else unsafe.
            #[allow(unsafe_code)]
            unsafe {
                fill_avx2(kernel, start, out);
            }
            return;
        }
        _ => {}
    }
    #[cfg(test)]
    if isa == Isa::PortableWide {
        return fill_lanes::<K, 16>(kernel, start, out);
    }
    let _ = isa;
    fill_lanes::<K, 8>(kernel, start, out);
}

#[cfg(all(
    feature = "simd",
    feature = "std",
    any(target_arch = "x86", target_arch = "x86_64")
))]
#[target_feature(enable = "avx2")]
fn fill_avx2<K: Kernel>(kernel: &K, start: u32, out: &mut [Vec2]) {
    fill_lanes::<K, 8>(kernel, start, out);
}

#[cfg(all(
    feature = "simd",
    feature = "std",
    any(target_arch = "x86", target_arch = "x86_64")
))]
#[target_feature(enable = "avx512f,avx512bw,avx512dq,avx512vl")]
fn fill_avx512<K: Kernel>(kernel: &K, start: u32, out: &mut [Vec2]) {
    fill_lanes::<K, 16>(kernel, start, out);
}

/// The batch loop every path runs: `N` consecutive indices a batch, then
/// the remainder one lane at a time.
#[inline(always)]
fn fill_lanes<K: Kernel, const N: usize>(kernel: &K, start: u32, out: &mut [Vec2]) {
    let mut chunks = out.chunks_exact_mut(N);
    let mut base = start;
    for chunk in &mut chunks {
        let mut index = [base; N];
        for (lane, index) in (0..).zip(&mut index) {
            *index = base.wrapping_add(lane);
        }
        chunk.copy_from_slice(&kernel.points(index));
        base = base.wrapping_add(N as u32);
    }
    for (lane, point) in chunks.into_remainder().iter_mut().enumerate() {
        *point = kernel.points([base.wrapping_add(lane as u32)])[0];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::SamplerKind;
    use crate::traits::Sampler2D;

    /// Asserts that `fill` wrote exactly `sample`'s bits.
    fn assert_bits(got: &[Vec2], expected: &[Vec2], what: &dyn core::fmt::Display) {
        for (i, (a, b)) in got.iter().zip(expected).enumerate() {
            assert_eq!(
                (a.x.to_bits(), a.y.to_bits()),
                (b.x.to_bits(), b.y.to_bits()),
                "{what} index {i}"
            );
        }
    }

    #[test]
    fn every_path_is_bit_identical_to_sample() {
        let supported: std::vec::Vec<Isa> = Isa::ALL
            .into_iter()
            .filter(|isa| isa.is_supported())
            .collect();
        std::println!("instruction sets on this CPU: {supported:?}");
        for &kind in SamplerKind::ALL {
            // Powers of two, squares, primes and non-squares, with lengths
            // that leave remainders after 8- and 16-lane batches.
            for n in [
                1, 2, 3, 5, 7, 8, 12, 16, 17, 31, 64, 100, 256, 257, 1000, 4096,
            ] {
                let sampler = kind.build(n).unwrap();
                for pattern in [0, 1, 0x9e37_79b9, u32::MAX] {
                    let expected: std::vec::Vec<Vec2> =
                        (0..n).map(|i| sampler.sample(i, pattern)).collect();
                    for &isa in &supported {
                        let mut out = std::vec![Vec2::NAN; n as usize];
                        with_isa(isa, || sampler.fill(pattern, &mut out));
                        let what =
                            std::format!("{kind} n {n} pattern {pattern:#x} fill on {isa:?}");
                        assert_bits(&out, &expected, &what);
                    }
                }
            }
        }
    }

    #[test]
    fn every_path_of_fill_from_is_bit_identical_to_sample() {
        let supported: std::vec::Vec<Isa> = Isa::ALL
            .into_iter()
            .filter(|isa| isa.is_supported())
            .collect();
        for &kind in SamplerKind::ALL {
            let sampler = kind.build(16).unwrap();
            let Some(sequence) = sampler.as_sequence() else {
                continue;
            };
            // Runs that start off a batch boundary, cross 2^24 and end at
            // the last index, with remainders after 8 and 16 lanes.
            for (start, len) in [
                (0, 100),
                (5, 37),
                (1000, 17),
                ((1 << 24) - 9, 40),
                (u32::MAX - 40, 41),
            ] {
                for pattern in [0, 0x9e37_79b9] {
                    let expected: std::vec::Vec<Vec2> = (0..len)
                        .map(|i| sequence.sample(start + i, pattern))
                        .collect();
                    for &isa in &supported {
                        let mut out = std::vec![Vec2::NAN; len as usize];
                        with_isa(isa, || sequence.fill_from(start, pattern, &mut out));
                        let what = std::format!(
                            "{kind} start {start} pattern {pattern:#x} fill_from on {isa:?}"
                        );
                        assert_bits(&out, &expected, &what);
                    }
                }
            }
        }
    }

    #[test]
    fn the_override_reaches_isa_best_and_is_undone() {
        let outside = Isa::best();
        with_isa(Isa::PortableWide, || {
            assert_eq!(Isa::best(), Isa::PortableWide)
        });
        assert_eq!(Isa::best(), outside);
    }
}
