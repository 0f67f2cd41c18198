//! What the progressive sequences ([`Sobol`], [`Pmj02`], [`Halton`]) share
//! apart from their point formulas: a set size that only bounds `fill`,
//! the constructor without one, `fill_from` for progressive rendering, and
//! the `Sampler2D` plumbing. Each sampler's file supplies `kernel(pattern)`,
//! its points as a [`Kernel`](crate::simd::Kernel); `sample` and every
//! `fill` path run that one kernel.
//!
//! [`Sobol`]: crate::Sobol
//! [`Pmj02`]: crate::Pmj02
//! [`Halton`]: crate::Halton

/// Implements the constructors, `fill_from`, [`Sampler2D`](crate::Sampler2D)
/// and `FillOn` for the sequence `$name` (a struct with one field
/// `n: u32`, the set size), named `$kind` by the tools.
macro_rules! sequence_sampler {
    ($name:ident, $kind:literal) => {
        impl $name {
            #[doc = concat!("The ", $kind, " sequence, with `n` as the set size for")]
            /// [`fill`](Sampler2D::fill) and the tools.
            ///
            /// # Errors
            ///
            /// [`Error::ZeroSamples`] for `n = 0`.
            pub fn new(n: u32) -> Result<Self, Error> {
                if n == 0 {
                    return Err(Error::ZeroSamples);
                }
                Ok(Self { n })
            }

            /// The sequence with no set size: every index in `0..2^32` is
            /// valid and [`len`](Sampler2D::len) is `u32::MAX`, so `fill`
            #[doc = concat!("writes any prefix. The same points as `", stringify!($name), "::new(n)`")]
            /// for every `n`: the size only bounds [`fill`](Sampler2D::fill).
            /// Use it with [`fill_from`](Self::fill_from) for progressive
            /// rendering.
            ///
            /// ```
            #[doc = concat!("use wellspread::{", stringify!($name), ", Sampler2D};")]
            #[doc = concat!("let sequence = ", stringify!($name), "::unbounded();")]
            #[doc = concat!("assert_eq!(sequence.sample(1000, 3), ", stringify!($name), "::new(16)?.sample(1000, 3));")]
            /// // Render 16 samples, look, then add 16 more.
            /// let mut points = vec![wellspread::glam::Vec2::ZERO; 32];
            /// sequence.fill(3, &mut points[..16]);
            /// sequence.fill_from(16, 3, &mut points[16..]);
            /// assert_eq!(points[20], sequence.sample(20, 3));
            /// # Ok::<(), wellspread::Error>(())
            /// ```
            #[must_use]
            pub const fn unbounded() -> Self {
                Self { n: u32::MAX }
            }

            /// Writes samples `start..start + out.len()` of pattern
            /// `pattern` into `out`: exactly what
            /// [`sample`](Sampler2D::sample) returns for each index, through
            /// the same batched path as [`fill`](Sampler2D::fill). The set
            /// size does not bound it; only the end of the index range does.
            ///
            /// # Panics
            ///
            /// If `start + out.len()` exceeds `2^32`: the sequence's last
            /// index is `u32::MAX`, and it never wraps around to index 0.
            #[inline]
            pub fn fill_from(&self, start: u32, pattern: u32, out: &mut [Vec2]) {
                $crate::sampler::check_fill_from(start, out.len());
                $crate::simd::fill_on(
                    $crate::simd::Isa::best(),
                    &Self::kernel(pattern),
                    start,
                    out,
                );
            }
        }

        impl Sampler2D for $name {
            #[inline]
            fn len(&self) -> u32 {
                self.n
            }

            /// Sample `index` of pattern `pattern`; every `index` below
            /// `2^32` is valid, including those at or above
            /// [`len`](Sampler2D::len).
            #[inline]
            fn sample(&self, index: u32, pattern: u32) -> Vec2 {
                use $crate::simd::Kernel;
                Self::kernel(pattern).points([index])[0]
            }

            #[inline]
            fn fill(&self, pattern: u32, out: &mut [Vec2]) {
                use $crate::sampler::FillOn;
                self.fill_on($crate::simd::Isa::best(), pattern, out);
            }
        }

        impl $crate::sampler::FillOn for $name {
            fn fill_on(&self, isa: $crate::simd::Isa, pattern: u32, out: &mut [Vec2]) {
                $crate::sampler::check_fill_len(out.len(), self.n);
                $crate::simd::fill_on(isa, &Self::kernel(pattern), 0, out);
            }
        }
    };
}

pub(crate) mod sobol_4d;
