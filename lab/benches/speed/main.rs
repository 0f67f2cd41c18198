//! Speed of every sampler and metric, side by side with baselines, in one
//! criterion run: `cargo bench -p wellspread-lab --bench speed`. The table of speed targets
//! (ratios to Pcg32, Kensler's listing and sobol_burley) comes last;
//! `cargo bench -p wellspread-lab --bench speed -- ratio` runs only the groups it needs.

use criterion::criterion_main;

mod domain_benches;
mod kensler;
#[path = "../../examples/shared/machine.rs"]
mod machine;
mod metric_benches;
mod ratio_benches;
mod sampler_benches;

criterion_main!(
    sampler_benches::benches,
    metric_benches::benches,
    ratio_benches::benches,
    domain_benches::benches
);
