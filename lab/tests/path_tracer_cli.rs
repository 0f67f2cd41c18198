//! The `path_tracer` example's arguments, parsed in-process as the other
//! tools' are: a bad one is one line with status 2 before any rendering.

#[allow(dead_code)] // the render itself, run by the example's `main`
#[path = "../examples/path_tracer.rs"]
mod tool;

use std::ffi::OsString;

use tool::shared;

/// The outcome of parsing `args`: the exit status and the line on standard
/// error, or `None` if they parse.
fn refused(args: &[&str]) -> Option<(u8, String)> {
    match tool::parse(args.iter().map(OsString::from), &mut Vec::new()) {
        Ok(_) => None,
        Err(failure) => {
            let mut stderr = Vec::new();
            let status = shared::finish("path_tracer", Err(failure), &mut stderr);
            Some((status, String::from_utf8(stderr).unwrap()))
        }
    }
}

#[test]
fn bad_arguments_are_one_line_and_negative_numbers_must_be_non_negative() {
    // clap's errors were several lines, and `--spp -1` an "unexpected
    // argument".
    for (args, expected) in [
        (
            &["--spp", "-1"][..],
            "path_tracer: --spp <SPP>: the value must be non-negative, got \"-1\" (try --help)\n",
        ),
        (
            &["--frame", "-3"],
            "path_tracer: --frame <FRAME>: the value must be non-negative, got \"-3\" (try --help)\n",
        ),
        (
            &["--bogus"],
            "path_tracer: unexpected argument '--bogus' found (try --help)\n",
        ),
    ] {
        assert_eq!(refused(args), Some((2, expected.to_owned())), "{args:?}");
    }
    let Some((status, err)) = refused(&["--sampler", "best"]) else {
        panic!("an unknown sampler must be refused");
    };
    assert_eq!(status, 2, "{err}");
    assert_eq!(err.lines().count(), 1, "{err:?}");
    assert!(
        err.starts_with("path_tracer: --sampler <SAMPLER>: "),
        "{err}"
    );
}

#[test]
fn good_arguments_and_help_parse() {
    assert_eq!(
        refused(&["--sampler", "blue-noise", "--spp", "4", "--frame", "2"]),
        None
    );
    let mut out = Vec::new();
    let parsed = tool::parse(["--help"].map(OsString::from), &mut out);
    assert!(matches!(parsed, Ok(None)), "{parsed:?}");
    let help = String::from_utf8(out).unwrap();
    for text in ["--spp", "missing folders are created", "Exit status"] {
        assert!(help.contains(text), "--help lacks {text}: {help}");
    }
}
