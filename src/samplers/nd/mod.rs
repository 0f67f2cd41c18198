//! The N-dimensional family ([`LatinHypercube`], [`OrthogonalArray`]) and
//! its core: the per-dimension keys, the salts of the per-dimension
//! choices, and the index and dimension checks. Each sampler's file holds
//! its constructors, its coordinate formula and its [`SamplerNd`] impl.
//!
//! A family of its own rather than part of `grid`: these samplers answer
//! one coordinate at a time through [`SamplerNd`], with no `columns x
//! rows` cells and no 2D `fill`, so none of the grid core applies; what
//! they share is how a dimension gets its own randomisation.
//!
//! [`LatinHypercube`]: crate::LatinHypercube
//! [`OrthogonalArray`]: crate::OrthogonalArray
//! [`SamplerNd`]: crate::SamplerNd

pub(crate) mod field;
mod latin_hypercube;
mod orthogonal_array;

pub use latin_hypercube::LatinHypercube;
pub use orthogonal_array::{OrthogonalArray, OrthogonalArrayOffset};

use crate::error::Error;
use crate::primitives::InvariantDivisor;
use crate::traits::debug_check_index;

/// `index`, checked against the set size in debug builds and reduced
/// modulo it in release builds.
#[inline(always)]
fn reduce_index(index: u32, n: InvariantDivisor) -> u32 {
    debug_check_index(index, n.get());
    if index < n.get() {
        index
    } else {
        n.div_rem(index).1
    }
}

/// The dimension check every `coordinate` shares (debug builds only).
#[inline(always)]
fn debug_check_dimension(dimension: u32, dimensions: u32) {
    debug_assert!(
        dimension < dimensions,
        "dimension {dimension} out of range 0..{dimensions}"
    );
}

/// `Ok` if `dimensions` is from 1 to `max`, else the error naming `sampler`
/// and `reason` (why `max` is the limit).
fn check_dimensions(
    sampler: &'static str,
    dimensions: u32,
    max: u32,
    reason: &'static str,
) -> Result<(), Error> {
    if (1..=max).contains(&dimensions) {
        Ok(())
    } else {
        Err(Error::DimensionsOutOfRange {
            sampler,
            dimensions,
            max,
            reason,
        })
    }
}
