//! Metric speed at n = 2^10 to 2^20.

use criterion::{Criterion, criterion_group};

fn metrics(_c: &mut Criterion) {}

criterion_group!(benches, metrics);
