//! The `warps` example's arguments: at most one PNG path; `--help`, an
//! unknown flag or a second path stop it with one line before the
//! seconds of timing (a second argument used to be ignored).

#[allow(dead_code)] // the sheet and the timings, run by the example's `main`
#[path = "../examples/warps.rs"]
mod tool;

use std::ffi::OsString;
use std::path::PathBuf;

use tool::shared::Failure;

fn parse(args: &[&str]) -> (Result<Option<tool::Args>, Failure>, String) {
    let mut out = Vec::new();
    let result = tool::parse(args.iter().map(OsString::from), &mut out);
    (result, String::from_utf8(out).unwrap())
}

#[test]
fn the_sheet_is_optional() {
    let (Ok(Some(args)), _) = parse(&[]) else {
        panic!("no arguments must parse");
    };
    assert_eq!(args.sheet, None);
    let (Ok(Some(args)), _) = parse(&["docs/images/warps.png"]) else {
        panic!("a path must parse");
    };
    assert_eq!(args.sheet, Some(PathBuf::from("docs/images/warps.png")));
}

#[test]
fn help_extra_paths_and_unknown_flags_stop_it() {
    let (result, out) = parse(&["--help"]);
    assert!(matches!(result, Ok(None)), "{result:?}");
    assert!(out.contains("PNG") && out.contains("Exit status"), "{out}");
    for args in [&["a.png", "b.png"][..], &["--bogus"][..]] {
        let (result, _) = parse(args);
        let Err(Failure::Input(message)) = result else {
            panic!("{args:?} must be an input error: {result:?}");
        };
        assert!(!message.contains('\n'), "one line: {message:?}");
    }
}

/// A standard output that the reader has closed (`warps | head -1`).
struct ClosedPipe;

impl std::io::Write for ClosedPipe {
    fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
        Err(std::io::ErrorKind::BrokenPipe.into())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn a_closed_standard_output_stops_it_quietly() {
    let (Ok(Some(args)), _) = parse(&[]) else {
        panic!("no arguments must parse");
    };
    // Stops at the table's first line, before any timing.
    let result = tool::run(&args, &mut ClosedPipe);
    assert_eq!(result, Err(Failure::OutputClosed));
    let mut stderr = Vec::new();
    assert_eq!(tool::shared::finish("warps", result, &mut stderr), 0);
    assert!(stderr.is_empty(), "{}", String::from_utf8_lossy(&stderr));
    // Any other write error is exit status 1 with one line.
    let full = tool::shared::to_stdout(Err(std::io::ErrorKind::StorageFull.into()));
    let mut stderr = Vec::new();
    assert_eq!(tool::shared::finish("warps", full, &mut stderr), 1);
    let message = String::from_utf8(stderr).unwrap();
    assert!(
        message.starts_with("warps: cannot write to standard output")
            && message.lines().count() == 1,
        "{message}"
    );
}
