//! Well-distributed 2D sample patterns for anti-aliasing, with random access.
//!
//! A renderer shoots several rays per pixel and averages them; where those
//! rays go decides how much aliasing and noise the image has. wellspread
//! generates the patterns graphics engineers know (regular, random,
//! jittered, n-rooks, multi-jittered) and better ones (correlated
//! multi-jitter, and the progressive low-discrepancy sequences [`Sobol`],
//! [`Pmj02`], [`Halton`] and [`Hammersley`]), and measures them
//! ([`metrics`]). The sequences accept any index below 2^32 and keep their
//! guarantees at every power-of-two prefix.
//!
//! Every sampler implements [`Sampler2D`]: sample `index` of pattern
//! `pattern` in O(1), with no tables and no shared state, so any thread
//! rendering any tile gets the same sample. Every coordinate is in `[0, 1)`
//! after f32 rounding.
//!
//! ```
//! use wellspread::{CorrelatedMultiJittered, Sampler2D, pattern_seed};
//!
//! let sampler = CorrelatedMultiJittered::new(16)?;
//! let (px, py) = (120, 45);
//! let pattern = pattern_seed(px, py, 0, 0);
//! for index in 0..sampler.len() {
//!     let offset = sampler.sample(index, pattern);
//!     assert!(offset.x < 1.0 && offset.y < 1.0);
//!     let _film = (px as f32 + offset.x, py as f32 + offset.y);
//! }
//! # Ok::<(), wellspread::Error>(())
//! ```
//!
//! # Features
//!
//! - `std` (default): the standard library; implies `alloc`.
//! - `alloc` (default through `std`): heap allocation for the metrics.
//! - `rayon` (off): runs the quadratic metric (the wrap-around L2
//!   discrepancy) on rayon's thread pool; results do not depend on the
//!   thread count.
//!
//! With neither, the crate is `no_std` and the samplers and hashes still
//! work. No feature changes a sample value.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs, missing_debug_implementations)]
#![doc(test(attr(deny(warnings))))]

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(any(feature = "std", test))]
extern crate std;

pub use glam;

mod error;
#[cfg(feature = "alloc")]
pub mod metrics;
mod pixel;
pub mod primitives;
mod sampler;
mod samplers;

/// The primitives under their first name: `wellspread::hash::pattern_seed`
/// and the rest keep working. New code should use [`primitives`].
pub mod hash {
    pub use crate::primitives::{
        MAX_STRATA, ONE_MINUS_EPSILON, UNIT_BITS, hash_combine, hash_u32, owen_scramble,
        owen_scramble_reversed, pattern_seed, permute, radical_inverse_2, rand_u32,
        stratum_to_unit_f32, u32_to_unit_f32,
    };
}

pub use error::{Error, InputText};
pub use pixel::{Padded, PixelCursor, PixelSampler};
pub use primitives::pattern_seed;
pub use sampler::Sampler2D;
pub use samplers::{
    AnySampler, CorrelatedMultiJittered, Halton, Hammersley, Jittered, LatinHypercube,
    MultiJittered, NRooks, Pmj02, Random, Regular, SamplerKind, Sobol, ZSobol,
};

// The README's usage example runs as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
