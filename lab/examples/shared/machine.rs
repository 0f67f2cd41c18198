//! The machine a measurement ran on, for the headers of generated tables:
//! included by the tracer and by both benches with
//! `#[path = ".../shared/machine.rs"] mod machine;`.

/// The CPU's model name from `/proc/cpuinfo` (its first `model name`
/// line), or `None` where there is no such file or line.
pub fn cpu_model() -> Option<String> {
    let info = std::fs::read_to_string("/proc/cpuinfo").ok()?;
    info.lines()
        .find(|line| line.starts_with("model name"))
        .and_then(|line| line.split_once(':'))
        .map(|(_, model)| model.trim().to_owned())
}
