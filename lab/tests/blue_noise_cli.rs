//! The `blue_noise` example run in-process: its argument errors are one
//! line with exit status 2, I/O failures exit 1, and the smallest runs it
//! accepts finish (`--size 8 --spp 1 --frames 2` panicked with an index out
//! of bounds before it was rejected up front).

#[allow(dead_code)] // the example's `main`
#[path = "../examples/blue_noise.rs"]
mod tool;

use std::ffi::OsString;

/// Exit status, standard output and standard error of one run.
fn run(args: &[&str]) -> (u8, String, String) {
    let mut stdout = Vec::new();
    let mut stderr = Vec::new();
    let result = tool::main_with(args.iter().map(OsString::from), &mut stdout);
    let status = tool::shared::finish("blue_noise", result, &mut stderr);
    (
        status,
        String::from_utf8(stdout).unwrap(),
        String::from_utf8(stderr).unwrap(),
    )
}

#[test]
fn bad_arguments_are_one_line_errors_with_status_2() {
    for (args, expected) in [
        (
            &["--size", "8", "--spp", "1", "--frames", "2"][..],
            "--spp 1: need a power of two from 4",
        ),
        (
            &["--size", "8", "--spp", "2", "--frames", "2"],
            "--spp 2: need a power of two from 4",
        ),
        (&["--spp", "12"], "--spp 12: need a power of two"),
        (&["--spp", "512"], "--spp 512"),
        (&["--frames", "1"], "--frames 1: need at least 2 frames"),
        (&["--size", "0"], "--size 0: need 1 to 4096 pixels"),
        (
            &["--size", "-8"],
            "the value must be non-negative, got \"-8\"",
        ),
        (&["--size", "big"], "\"big\" is not a whole number"),
        (&["--bogus"], "'--bogus'"),
        (&["--frames"], "--frames <FRAMES>"),
    ] {
        let (status, out, err) = run(args);
        assert_eq!((status, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(
            err.starts_with("blue_noise: ") && err.contains(expected),
            "{args:?}: {err:?} lacks {expected:?}"
        );
        assert_eq!(err.lines().count(), 1, "{args:?}: {err:?} is not one line");
    }
}

#[test]
fn help_is_printed_with_status_0_and_names_the_exit_codes() {
    let (status, out, err) = run(&["--help"]);
    assert_eq!((status, err.as_str()), (0, ""));
    for word in [
        "--size",
        "--spp",
        "--frames",
        "--docs",
        "--images",
        "Exit status",
    ] {
        assert!(out.contains(word), "--help lacks {word}: {out}");
    }
}

#[test]
fn the_smallest_run_finishes_and_writes_its_pictures() {
    let dir = std::env::temp_dir().join(format!("wellspread-blue-noise-{}", std::process::id()));
    let images = dir.join("missing/folder");
    let args = ["--size", "8", "--spp", "4", "--frames", "2", "--images"];
    let (status, out, err) = run(&[&args[..], &[images.to_str().unwrap()]].concat());
    assert_eq!((status, err.as_str()), (0, ""));
    assert!(out.contains("8 x 8 pixels, prefixes n = 1..4"), "{out}");
    assert!(out.contains("| blue-noise, gauss, pair 0 |"), "{out}");
    // The missing folder is made, as every tool does.
    assert!(images.join("blue-noise-error-zsobol-2spp.png").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn io_failures_exit_1_and_a_bad_page_exits_2() {
    let small = ["--size", "4", "--spp", "4", "--frames", "2"];
    // A folder that cannot be made.
    let (status, out, err) = run(&[&small[..], &["--images", "/dev/null/x"]].concat());
    assert_eq!((status, out.as_str()), (1, ""), "{err}");
    assert!(
        err.starts_with("blue_noise: cannot create /dev/null"),
        "{err}"
    );
    // A page that does not exist.
    let (status, _, err) = run(&[&small[..], &["--docs", "/nonexistent/page.md"]].concat());
    assert_eq!(status, 1, "{err}");
    assert!(
        err.starts_with("blue_noise: cannot read /nonexistent/page.md"),
        "{err}"
    );
    // A device or a FIFO is refused before the measurement (a FIFO's
    // opening blocked until a reader came).
    if cfg!(target_os = "linux") {
        let dir = std::env::temp_dir().join(format!("blue-noise-fifo-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("page.fifo");
        let mut refused = vec![(std::path::PathBuf::from("/dev/zero"), "a device")];
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|status| status.success()) {
            refused.push((fifo, "a FIFO"));
        }
        for (path, kind) in refused {
            let path = path.to_str().unwrap();
            // 256 x 256 at 256 spp and 64 frames would take minutes: the
            // refusal comes first.
            let big = ["--size", "256", "--spp", "256", "--frames", "64"];
            let (status, _, err) = run(&[&big[..], &["--docs", path]].concat());
            assert_eq!(status, 2, "{err}");
            assert!(
                err.contains(&format!("--docs {path}: {kind}, not a regular file")),
                "{err}"
            );
            assert_eq!(err.lines().count(), 1, "{err:?}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
    // A page over the size limit is refused before the measurement, not
    // read into memory.
    let dir = std::env::temp_dir().join(format!("blue-noise-big-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let big_page = dir.join("page.md");
    std::fs::write(&big_page, vec![b'x'; 4 * 1024 * 1024 + 1]).unwrap();
    let (status, _, err) = run(&[&small[..], &["--docs", big_page.to_str().unwrap()]].concat());
    assert_eq!(status, 2, "{err}");
    assert!(err.contains("is larger than 4 MiB"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
