//! The building blocks every sampler is made of, one file per idea, and the
//! only source of randomness in wellspread.
//!
//! - Hashing and pattern seeds: [`hash_u32`], [`hash_combine`],
//!   [`pattern_seed`], [`rand_u32`], [`mix64`].
//! - Permutations of `[0, len)`: [`permute`]; of a sequence's indices
//!   that keep every power-of-two prefix: [`prefix_shuffle`].
//! - Morton codes of pixels (crate-private).
//! - The unit conversion from bits to `[0, 1)`: [`u32_to_unit_f32`],
//!   [`stratum_to_unit_f32`], with [`UNIT_BITS`], [`MAX_STRATA`] and
//!   [`ONE_MINUS_EPSILON`].
//! - Owen scrambling for the base-2 sequences: [`owen_scramble`],
//!   [`owen_scramble_reversed`].
//! - Invariant division (crate-private): the reciprocals samplers store so
//!   that no sample divides.
//!
//! Every sample is a pure function of `(index, pattern)` built from these,
//! so it is the same on every thread, machine and run. Each function names
//! its source, and each magic constant says why it is there.

mod division;
mod hash;
pub(crate) mod morton;
mod owen;
mod permutation;
mod unit;

pub(crate) use division::InvariantDivisor;
pub(crate) use hash::{child_key, locate_pass, salt};
pub use hash::{hash_combine, hash_u32, mix64, pattern_seed, rand_u32};
pub use owen::{owen_scramble, owen_scramble_reversed};
pub(crate) use permutation::SHORT_LEN;
pub use permutation::permute;
pub use permutation::prefix_shuffle;
pub(crate) use permutation::{Permutation, derived_key};
pub use unit::{MAX_STRATA, ONE_MINUS_EPSILON, UNIT_BITS, stratum_to_unit_f32, u32_to_unit_f32};
