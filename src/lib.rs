//! Well-distributed 2D sample patterns for anti-aliasing, with random access.
//!
//! A renderer shoots several rays per pixel and averages them; where those
//! rays go decides how much aliasing and noise the image has. wellspread
//! generates the patterns graphics engineers know (regular, random,
//! jittered, n-rooks, multi-jittered) and better ones (correlated
//! multi-jitter, the low-discrepancy [`Hammersley`] set of at most 2^24
//! points, and the progressive sequences [`Sobol`], [`Pmj02`] and
//! [`Halton`]), and measures them ([`metrics`]). The sequences
//! ([`Sequence2D`]) accept any index below 2^32 and keep their guarantees
//! at every power-of-two prefix.
//!
//! Every sampler kind implements [`Sampler2D`]: sample `index` of pattern
//! `pattern` in O(1), with no tables and no shared state, so any thread
//! rendering any tile gets the same sample. Every coordinate is in `[0, 1)`
//! after f32 rounding.
//!
//! Point sets whose guarantees span more dimensions implement [`SamplerNd`]
//! (any coordinate of any sample in O(1)): [`LatinHypercube`] (every 1D
//! projection stratified, any number of dimensions) and
//! [`OrthogonalArray`] (every 2D, 3D or 4D projection stratified, at
//! `q^t` samples for a prime power `q`).
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
//! # Pixel loops
//!
//! A renderer asks for samples by pixel, sample index and dimension pair
//! (film position, lens, time, light, ...): that is [`PixelSampler`].
//! [`Padded`] makes one of any [`Sampler2D`] that implements
//! [`DomainSampler`] (every sampler of the crate does; for one of your own,
//! an empty `impl DomainSampler for MySampler {}` takes the defaults), each
//! pixel and dimension pair an independent pattern from [`pattern_seed`];
//! [`ZSobol`] (at its power-of-two count) and [`BlueNoise`] (at every
//! prefix, any count) spread the error across pixels as blue noise. [`PixelSampler::start`]
//! makes a [`Domain`], the 32-byte state of one pixel sample that hands out
//! draws of one to four dimensions and keyed child domains
//! ([`PixelSampler`] shows a path tracer's loop), and [`warp`] maps those
//! draws onto disks, hemispheres, spheres, triangles, lights (by solid
//! angle) and discrete choices (uniform and weighted); [`filter`] draws the
//! film offset from a pixel reconstruction filter (tent, Gaussian,
//! Mitchell-Netravali, Lanczos, ...) through a monotone map, so the strata
//! survive; [`PixelSamplerKind`] picks a sampler by name:
//!
//! ```
//! use wellspread::{Padded, PixelSampler, Sobol, ZSobol};
//!
//! /// Box-filtered render of a toy scene seen through a lens, lit by an
//! /// area light: three dimension pairs per sample.
//! fn render(sampler: &(impl PixelSampler + Copy), width: u32, height: u32) -> Vec<f32> {
//!     let spp = sampler.samples_per_pixel().unwrap_or(16);
//!     let mut image = Vec::with_capacity((width * height) as usize);
//!     for py in 0..height {
//!         for px in 0..width {
//!             let mut sum = 0.0;
//!             for index in 0..spp {
//!                 let mut d = sampler.start([px, py], index);
//!                 let film = d.next_2d(); // offset in the pixel
//!                 let lens = d.next_2d(); // point on the lens
//!                 let light = d.next_2d(); // point on the light
//!                 let (x, y) = (px as f32 + film.x, py as f32 + film.y);
//!                 let blur = 0.5 * (lens.x - 0.5);
//!                 sum += ((x + blur) * 0.3).sin().abs() * (y * 0.2).cos().abs() * (0.5 + light.y);
//!             }
//!             image.push(sum / spp as f32);
//!         }
//!     }
//!     image
//! }
//!
//! let (width, height) = (32, 24);
//! let blue = render(&ZSobol::new(16, [width, height], 0)?, width, height);
//! let white = render(&Padded::new(Sobol::new(16)?, 0), width, height);
//! assert_eq!(blue.len(), white.len());
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
//! - `serde` (off): `Serialize` / `Deserialize` for [`SamplerKind`], as its
//!   kebab-case name (`"n-rooks"`), so settings files can name a sampler.
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
#[cfg(feature = "alloc")]
pub mod metrics;
mod pixel;
pub mod primitives;
mod samplers;
mod simd;
mod traits;
pub mod warp;
pub mod wgsl;

pub use error::{Error, InputText};
pub use pixel::{
    AnyPixelSampler, BlueNoise, Domain, Draw, ExplicitColumns, Padded, PaddedNd, PixelColumns,
    PixelSampler, PixelSamplerKind, PixelSamplerVisitor, Root, SearchedColumns, ZSobol,
};
pub use primitives::pattern_seed;
pub use samplers::{
    AnySampler, BlueMultiJittered, CorrelatedMultiJittered, Halton, Hammersley, Jittered,
    LatinHypercube, MultiJittered, NRooks, OrthogonalArray, OrthogonalArrayOffset, Pmj02, Random,
    Regular, SamplerKind, SamplerVisitor, Sobol, Sobol4D,
};
pub use traits::{DomainSampler, Sampler2D, SamplerNd, Sequence2D, second_stream, stratified_1d};

// The README's usage example runs as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
