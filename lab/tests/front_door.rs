//! What a new user meets first: the links of the README and the pages
//! under `docs/`, the command that regenerates each page, and the files
//! `.ci/run` names. These are checks of the repository, not of the
//! library, so they live in the unpublished lab rather than in the
//! published crate's tests/ (whose package has no lab/, .ci/ or gpu/).

use std::path::{Path, PathBuf};

/// The repository's root: the lab is its `lab/` folder.
fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_owned()
}

fn read(path: &str) -> String {
    let full = repository().join(path);
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
    let root = repository();
    for page in [
        "README.md",
        "docs/tracer.md",
        "docs/quality.md",
        "docs/performance.md",
        "docs/metrics.md",
        "docs/zsobol.md",
        "docs/filters.md",
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
            "cargo run --release -p wellspread-lab --example tracer -- --full --docs docs/tracer.md",
        ),
        (
            "docs/quality.md",
            "cargo bench -p wellspread-lab --bench quality",
        ),
        (
            "docs/performance.md",
            "cargo bench -p wellspread-lab --bench speed -- ratio",
        ),
        (
            "docs/metrics.md",
            "cargo bench -p wellspread-lab --bench speed --",
        ),
        (
            "docs/zsobol.md",
            "cargo run --release -p wellspread-lab --example tracer --",
        ),
        (
            "docs/filters.md",
            "cargo run --release -p wellspread-lab --example tracer -- --scene checker,moire",
        ),
        (
            "docs/blue_noise.md",
            "cargo run --release -p wellspread-lab --example blue_noise --",
        ),
        (
            "docs/warps.md",
            "cargo run --release -p wellspread-lab --example warps -- docs/images/warps.png",
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
    let root = repository();
    let script = read(".ci/run");
    for word in script.split(|c: char| c.is_whitespace() || c == '(' || c == ')') {
        let word = word.trim_matches(|c: char| c == ',' || c == '.' || c == ':');
        if word.ends_with(".md") {
            assert!(root.join(word).exists(), ".ci/run names missing {word}");
        }
    }
}

/// The lab's programs that a page's command names: each `--example NAME`
/// and `--bench NAME` in the README, ARCHITECTURE.md and docs/ is a file of
/// `lab/` (the workspace member that holds them), and its command line
/// says `-p wellspread-lab`, since a plain `cargo run --example` at the
/// root finds nothing since the lab moved out of the library.
#[test]
fn commands_name_lab_programs_that_exist() {
    let root = repository();
    let mut pages = vec!["README.md".to_owned(), "ARCHITECTURE.md".to_owned()];
    for entry in std::fs::read_dir(root.join("docs")).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        if name.ends_with(".md") {
            pages.push(format!("docs/{name}"));
        }
    }
    let mut named = 0;
    for page in &pages {
        let text = read(page);
        // Commands wrap across lines in prose: read the page as one line.
        let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
        for (flag, folder) in [("--example ", "examples"), ("--bench ", "benches")] {
            for (at, _) in flat.match_indices(flag) {
                let name: String = flat[at + flag.len()..]
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                let single = root.join(format!("lab/{folder}/{name}.rs"));
                let folder_main = root.join(format!("lab/{folder}/{name}/main.rs"));
                assert!(
                    single.exists() || folder_main.exists(),
                    "{page} names {flag}{name}, which lab/{folder}/ lacks"
                );
                let start = flat[..at].rfind("cargo ").unwrap_or(0);
                assert!(
                    flat[start..at].contains("-p wellspread-lab"),
                    "{page}: `{}` lacks -p wellspread-lab",
                    &flat[start..at + flag.len() + name.len()]
                );
                named += 1;
            }
        }
    }
    assert!(named > 10, "only {named} commands found");
    // The README's first command is the tracer's short run; its second is the
    // library's `cargo test`, which builds none of the lab.
    let readme = read("README.md");
    let block = readme.split("```sh\n").nth(1).unwrap();
    let mut lines = block.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .starts_with("cargo run --release -p wellspread-lab --example tracer ")
    );
    assert!(lines.next().unwrap().starts_with("cargo test "));
    let manifest = read("Cargo.toml");
    assert!(manifest.contains("default-members = [\".\"]"), "Cargo.toml");
}
