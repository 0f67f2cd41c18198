//! Sample patterns for renderers: stratified, low-discrepancy and
//! blue-noise pixel samplers with O(1) random access, the warps and
//! filters that keep their stratification, and the metrics that measure
//! them.
//!
//! # A renderer's loop
//!
//! Pick a pixel sampler and a filter by name, start a [`Domain`] per pixel
//! sample, take the camera sample first (film through the filter, lens, time), then
//! give each purpose its own keyed branch:
//!
//! ```
//! use wellspread::filter::FilterKind;
//! use wellspread::{PixelSampler, PixelSamplerKind, warp};
//!
//! const BOUNCE: u32 = 1; // domain keys: any u32, one per purpose
//!
//! let sampler = "sobol".parse::<PixelSamplerKind>()?.build(16, [64, 48], 0)?;
//! let filter = "gaussian".parse::<FilterKind>()?.build(); // pbrt-v4's defaults
//! let pixel = [12, 34];
//! let (mut sum, mut weights) = (0.0, 0.0);
//! for index in 0..16 {
//!     let mut d = sampler.start(pixel, index); // 32 bytes, borrows the sampler
//!     let camera = d.camera_sample(pixel, &filter);
//!     let mut radiance = 0.0;
//!     for b in 0..4 {
//!         // Bounce b's draws never depend on what the bounces before it drew.
//!         let mut bounce = d.branch(BOUNCE).branch(b);
//!         let direction = warp::cosine_hemisphere(bounce.next_2d());
//!         radiance += direction.z * (1.0 + camera.lens.x) * 0.25;
//!     }
//!     sum += camera.filter_weight * radiance;
//!     weights += camera.filter_weight;
//! }
//! assert!((sum / weights).is_finite());
//! # Ok::<(), wellspread::Error>(())
//! ```
//!
//! What a renderer uses:
//!
//! - [`PixelSamplerKind`] and [`AnyPixelSampler`]: every pixel sampler by
//!   name, built for a sample count and a film. [`Padded`] makes one of
//!   any pattern below (an independent pattern per pixel, frame and
//!   draw); [`ZSobol`] and [`BlueNoise`] spread the error across pixels as
//!   blue noise; [`PaddedNd`] reads an [`OrthogonalArray`] or a
//!   [`LatinHypercube`] across a domain's draws.
//! - [`Domain`]: one pixel sample's draws, 1D to 4D, keyed branches and
//!   splits, and [`camera_sample`](Domain::camera_sample). Its docs say
//!   which draw to use for what; [`PixelSampler`] states the edges.
//! - [`warp`]: the unit square onto disks, hemispheres, spheres,
//!   triangles, lights (by solid angle) and discrete choices, with pdfs
//!   and inverses; [`filter`]: pixel reconstruction filters, sampled
//!   through a monotone map so the strata survive.
//! - [`metrics`]: exact discrepancies, distances, spectra and
//!   stratification checks for any `&[Vec2]`; [`Error`]: what was wrong
//!   with an input, for every constructor and metric.
//!
//! A new sampler implements the hooks in [`implement`].
//!
//! # The patterns underneath
//!
//! Every 2D pattern implements [`Sampler2D`]: sample `index` of pattern
//! `pattern` in O(1), with no tables and no shared state, so any thread
//! rendering any tile gets the same sample. Every coordinate is in `[0, 1)`
//! after f32 rounding. The kinds are the ones graphics engineers know
//! (regular, random, jittered, n-rooks, multi-jittered) and better ones
//! (correlated multi-jitter, blue multi-jitter, the [`Hammersley`] set and
//! the progressive sequences [`Sobol`], [`Pmj02`] and [`Halton`], which
//! accept any index below 2^32 and keep their guarantees at every
//! power-of-two prefix); [`SamplerKind`] names them. Sets whose
//! guarantees span more dimensions implement [`SamplerNd`].
//!
//! ```
//! use wellspread::{CorrelatedMultiJittered, Sampler2D, glam::Vec2, metrics};
//!
//! let mut points = vec![Vec2::ZERO; 256];
//! CorrelatedMultiJittered::new(256)?.fill(7, &mut points); // pattern 7
//! assert!(metrics::is_latin(&points)? && metrics::is_stratified(&points, 16, 16)?);
//! # Ok::<(), wellspread::Error>(())
//! ```
//!
//! # glam, and renderers on other math crates
//!
//! Points are [`glam::Vec2`]. glam is re-exported as [`wellspread::glam`](glam):
//! name the type through that path and the versions always match. Each
//! wellspread release depends on one glam minor version (now 0.30); moving
//! to a newer one is a breaking change of wellspread, released as a new
//! minor version before 1.0 and listed in the CHANGELOG.
//!
//! A renderer on another math crate needs no glam in its own code: every
//! point converts to a plain `[f32; 2]`.
//!
//! ```
//! use wellspread::{Sampler2D, Sobol};
//! let sobol = Sobol::new(16)?;
//! let [x, y] = sobol.sample(3, 7).to_array();
//! let offset: [f32; 2] = sobol.sample(4, 7).into();
//! assert!(x < 1.0 && y < 1.0 && offset[0] < 1.0);
//! # Ok::<(), wellspread::Error>(())
//! ```
//!
//! # Features
//!
//! - `std` (default): the standard library; implies `alloc`.
//! - `alloc` (default through `std`): heap allocation for the metrics.
//! - `simd` (default): `fill` on AVX2 or AVX-512 when the CPU has them
//!   (detected at run time, with `std`). Without it the crate is
//!   `#![forbid(unsafe_code)]` and `fill` runs the portable loop only, with
//!   bit-identical values: a build for auditors.
//! - `serde` (off): `Serialize` / `Deserialize` for [`SamplerKind`],
//!   [`PixelSamplerKind`] and [`FilterKind`](filter::FilterKind), as their
//!   kebab-case names (`"n-rooks"`), so settings files can name them.
//! - `rand` (off): [`Domain`] implements `rand_core::RngCore` (0.9), each
//!   `next_u32` one 1D draw with the draw's 24 bits on top, so a renderer
//!   written against `rand::Rng` gets `random::<f32>() == next_1d()`.
//!
//! With neither, the crate is `no_std` and the samplers and hashes still
//! work. No feature changes a sample value.
#![no_std]
#![cfg_attr(docsrs, feature(doc_cfg))]
// `unsafe` is denied everywhere but in `simd`, the one audited module:
// calling a function compiled for AVX2 or AVX-512 after detecting the CPU.
// Without the `simd` feature there is none at all.
#![cfg_attr(feature = "simd", deny(unsafe_code))]
#![cfg_attr(not(feature = "simd"), forbid(unsafe_code))]
#![deny(missing_docs, missing_debug_implementations)]
#![doc(test(attr(deny(warnings))))]

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(any(feature = "std", test))]
extern crate std;

pub use glam;

mod error;
pub mod filter;
pub mod implement;
#[cfg(feature = "alloc")]
pub mod metrics;
mod pixel;
pub mod primitives;
mod samplers;
mod simd;
mod traits;
pub mod warp;
pub mod wgsl;

pub use error::{Error, UnknownName};
pub use pixel::{
    AnyPixelSampler, BlueNoise, CameraSample, Domain, Padded, PaddedNd, PixelSampler,
    PixelSamplerKind, PixelSamplerVisitor, ZSobol,
};
pub use primitives::pattern_seed;

/// [`BlueNoise`]'s pixel columns, the research knob: which column of its
/// 64 x 64 ranking tile each pixel reads. [`BlueNoise::new`] uses the
/// searched columns built in; [`BlueNoise::with_columns`] takes any
/// [`PixelColumns`](blue_noise::PixelColumns).
pub mod blue_noise {
    pub use crate::pixel::blue_noise::{ExplicitColumns, PixelColumns, SearchedColumns};
}
pub use samplers::{
    AnySampler, BlueMultiJittered, CorrelatedMultiJittered, Faure4D, Halton, Hammersley, Jittered,
    LatinHypercube, MultiJittered, NRooks, OrthogonalArray, OrthogonalArrayOffset, Pmj02, Random,
    Regular, SamplerKind, SamplerVisitor, Sobol, Sobol4D,
};
pub use traits::{Sampler2D, SamplerNd, Sequence2D};

// The README's usage example runs as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
