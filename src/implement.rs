//! The implementor's face: what a new sampler implements and the pieces
//! it builds its draws from. A renderer needs none of it; it holds a
//! [`PixelSampler`](crate::PixelSampler) and draws through
//! [`Domain`](crate::Domain).
//!
//! # Adding a sampler
//!
//! 1. **A point set.** Implement [`Sampler2D`](crate::Sampler2D) (or
//!    [`SamplerNd`](crate::SamplerNd) for N-dimensional points): `len`,
//!    and `sample(index, pattern)` as a pure function of its arguments,
//!    every coordinate in `[0, 1)`. Give it a checked constructor that
//!    returns [`Error`](crate::Error) for sizes it cannot keep its
//!    guarantees at.
//! 2. **Its draws.** Implement [`DomainSampler`]; an empty impl takes the
//!    defaults: `domain_2d(index, stream)` is `sample(index, stream as
//!    u32)`, the 1D draw is [`stratified_1d`], the 3D and 4D draws pad
//!    pairs with a [`second_stream`], and indices past `len` start a new
//!    pass (return `true` from `is_progressive` for a sequence). Override
//!    a draw to make it better (derive its keys from the 64-bit stream).
//!    Then [`Padded`](crate::Padded)`<YourSampler>` is a
//!    [`PixelSampler`](crate::PixelSampler), and every draw of a
//!    [`Domain`](crate::Domain) is an independent pattern of your set.
//! 3. **Or a pixel sampler of its own** (a sampler that knows the pixel,
//!    as [`ZSobol`](crate::ZSobol) and [`BlueNoise`](crate::BlueNoise)
//!    do): implement [`PixelSampler`](crate::PixelSampler)'s
//!    `samples_per_pixel` and [`PixelSamplerHooks`]: `root` (the key and
//!    pixel state [`Domain`](crate::Domain)'s start computes once),
//!    optionally `locate` (the pass rule for indices beyond the count) and
//!    `draw_2d` (plus the other widths to make them better than padded
//!    pairs), each a pure function of the [`Draw`] it is given.
//! 4. **Tests.** Every guarantee the docs state, with real numbers
//!    (stratification, nets, the edges: n = 1, primes, 2^24, patterns 0
//!    and `u32::MAX`), `fill == sample` bit for bit, and a golden line
//!    per kind once it joins [`SamplerKind`](crate::SamplerKind).
//!
//! ```
//! use wellspread::glam::Vec2;
//! use wellspread::implement::{Draw, PixelSamplerHooks, Root};
//! use wellspread::{Domain, Padded, PixelSampler, Sobol};
//!
//! /// A pixel sampler that forwards to a padded Sobol' and mirrors x.
//! struct Mirrored(Padded<Sobol>);
//!
//! impl PixelSampler for Mirrored {
//!     fn samples_per_pixel(&self) -> Option<u32> {
//!         self.0.samples_per_pixel()
//!     }
//! }
//!
//! impl PixelSamplerHooks for Mirrored {
//!     fn root(&self, pixel: [u32; 2]) -> Root {
//!         self.0.root(pixel)
//!     }
//!     fn draw_2d(&self, draw: Draw) -> Vec2 {
//!         let p = self.0.draw_2d(draw);
//!         Vec2::new(1.0 - p.x - f32::EPSILON / 2.0, p.y).max(Vec2::ZERO)
//!     }
//! }
//!
//! let mirrored = Mirrored(Padded::new(Sobol::new(16)?, 0));
//! let mut d: Domain<&Mirrored> = mirrored.start([1, 2], 3);
//! let p = d.next_2d();
//! assert!((0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y));
//! # Ok::<(), wellspread::Error>(())
//! ```

pub use crate::pixel::{Draw, PixelSamplerHooks, Root};
pub use crate::traits::{DomainSampler, second_stream, stratified_1d};
