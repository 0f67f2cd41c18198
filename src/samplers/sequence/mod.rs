//! The progressive sequences ([`Sobol`], [`Pmj02`], [`Halton`]) and what
//! they share apart from their point formulas: a set size that only bounds
//! `fill`, and the checked runs of `fill` and
//! [`fill_from`](crate::Sequence2D::fill_from). Each sampler has a
//! `kernel(pattern)`, its points as a [`Kernel`] (Halton's own;
//! `digital::DigitalSequence` builds Sobol's and Pmj02's from their point
//! formulas); `sample` and every `fill` path run that one kernel.
//!
//! [`Sobol`]: crate::Sobol
//! [`Pmj02`]: crate::Pmj02
//! [`Halton`]: crate::Halton

pub(crate) mod digital;
mod faure_4d;
mod halton;
pub(crate) mod pmj02;
pub(crate) mod sobol;
pub(crate) mod sobol_4d;

pub use faure_4d::Faure4D;
pub use halton::Halton;
pub use pmj02::Pmj02;
pub use sobol::Sobol;
pub use sobol_4d::Sobol4D;

use glam::Vec2;

use crate::error::Error;
use crate::simd::{self, Kernel};
use crate::traits::{check_fill_from, check_fill_len};

/// The set size of a sequence's `new(n)`: any `n >= 1`.
#[inline]
pub(crate) const fn set_size(n: u32) -> Result<u32, Error> {
    if n == 0 {
        Err(Error::ZeroSamples)
    } else {
        Ok(n)
    }
}

/// `fill` of a sequence of set size `len`: points `0..out.len()` of
/// `kernel`, which must not exceed the set.
#[inline]
#[track_caller]
pub(crate) fn fill_set<K: Kernel>(kernel: &K, len: u32, out: &mut [Vec2]) {
    check_fill_len(out.len(), len);
    simd::fill(kernel, 0, out);
}

/// `fill_from` of a sequence: points `start..start + out.len()` of
/// `kernel`, which must not run past index `u32::MAX`.
#[inline]
#[track_caller]
pub(crate) fn fill_run<K: Kernel>(kernel: &K, start: u32, out: &mut [Vec2]) {
    check_fill_from(start, out.len());
    simd::fill(kernel, start, out);
}
