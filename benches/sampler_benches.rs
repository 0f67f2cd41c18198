//! Sampler speed: `sample` and `fill` against constant, Pcg32 and sobol_burley baselines.

use criterion::{Criterion, criterion_group};

fn samplers(_c: &mut Criterion) {}

criterion_group!(benches, samplers);
