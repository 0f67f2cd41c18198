//! Quality report: discrepancy, minimum distance and integration error per
//! sampler. `cargo bench --bench quality [-- --quick]`.

fn main() {}
