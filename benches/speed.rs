//! Speed of every sampler and metric, side by side with baselines, in one
//! criterion run: `cargo bench --bench speed`.

use criterion::criterion_main;

mod metric_benches;
mod sampler_benches;

criterion_main!(sampler_benches::benches, metric_benches::benches);
