//! What a new user meets first: the links of the README and the pages
//! under `docs/`, the command that regenerates each page, and the files
//! `.ci/run` names.

use std::path::Path;

fn read(path: &str) -> String {
    let full = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{}: {e}", full.display()))
}

/// The targets of the Markdown links and images in `text`: `](target)`.
fn link_targets(text: &str) -> Vec<&str> {
    text.split("](")
        .skip(1)
        .map(|rest| &rest[..rest.find(')').unwrap()])
        .collect()
}

#[test]
fn every_relative_link_in_the_readme_and_docs_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for page in [
        "README.md",
        "docs/tracer.md",
        "docs/quality.md",
        "docs/performance.md",
        "docs/metrics.md",
        "docs/zsobol.md",
        "docs/blue_noise.md",
        "docs/warps.md",
        "docs/gpu.md",
    ] {
        let dir = root.join(page).parent().unwrap().to_owned();
        let text = read(page);
        let page_lines = text.lines().next().unwrap_or_default();
        assert!(page_lines.starts_with("# "), "{page} has a title");
        for target in link_targets(&text) {
            if target.contains("://") || target.starts_with('#') {
                continue;
            }
            let file = target.split('#').next().unwrap();
            assert!(dir.join(file).exists(), "{page} links to missing {target}");
        }
    }
}

#[test]
fn docs_pages_start_with_their_regeneration_command_and_machine() {
    for (page, command) in [
        (
            "docs/tracer.md",
            "cargo run --release --example tracer -- --docs docs/tracer.md",
        ),
        ("docs/quality.md", "cargo bench --bench quality"),
        ("docs/performance.md", "cargo bench --bench speed -- ratio"),
        ("docs/metrics.md", "cargo bench --bench speed --"),
        ("docs/zsobol.md", "cargo run --release --example tracer --"),
        (
            "docs/blue_noise.md",
            "cargo run --release --example blue_noise --",
        ),
        (
            "docs/warps.md",
            "cargo run --release --example warps -- docs/images/warps.png",
        ),
        (
            "docs/gpu.md",
            "REQUIRE_GPU=1 cargo test -p wellspread-gpu -- --nocapture",
        ),
    ] {
        let text = read(page);
        let head: String = text.lines().take(16).collect::<Vec<_>>().join("\n");
        assert!(
            head.contains(command),
            "{page} does not start with {command}"
        );
        assert!(head.contains("Machine"), "{page} does not name its machine");
    }
}

#[test]
fn ci_script_names_only_files_that_exist() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let script = read(".ci/run");
    for word in script.split(|c: char| c.is_whitespace() || c == '(' || c == ')') {
        let word = word.trim_matches(|c: char| c == ',' || c == '.' || c == ':');
        if word.ends_with(".md") {
            assert!(root.join(word).exists(), ".ci/run names missing {word}");
        }
    }
}
