//! Property tests: one generic harness over [`SamplerKind::ALL`].
//!
//! Every sampler gets the contract checks (points finite and in `[0, 1)^2`,
//! `fill == sample`, determinism, different patterns give different sets, a
//! histogram no worse than random) by being in `SamplerKind::ALL`. What it
//! guarantees beyond that (Latin columns and rows, coarse strata, offsets
//! inside strata, nets in base 2, sequence indices past `n`) is one line in
//! [`guarantees::guarantees`], an exhaustive match: a new kind does not
//! compile until it has its line.
//!
//! Stratum membership is computed exactly, in f64, from the f32 values:
//! `floor(x as f64 * strata as f64)`. Both factors are below 2^32 and `x` is a
//! multiple of 2^-24 with 24 significant bits, so the product is exact.
//!
//! The exact checks cannot fail by chance; the statistical ones use fixed
//! patterns and state their false-failure rates. The longest tests are the
//! whole sets at 2^24 (one thread per sampler) and the sequences' 2^24
//! prefix. The release-only test (`#[cfg(not(debug_assertions))]`) runs in
//! `.ci/run`'s `cargo test --release` step.

mod blue_multi_jittered;
mod checks;
mod construction;
mod contract;
mod fill_from;
mod guarantees;
mod sequences;
mod statistics;
