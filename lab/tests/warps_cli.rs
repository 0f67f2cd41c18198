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
