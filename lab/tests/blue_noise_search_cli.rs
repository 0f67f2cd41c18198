//! The `blue_noise_search` example's arguments: `--help` and an unknown or
//! non-numeric argument stop it before the minutes-long search starts
//! (they used to be ignored, or silently became the defaults).

#[allow(dead_code)] // the search itself, run by the example's `main`
#[path = "../examples/blue_noise_search.rs"]
mod tool;

use std::ffi::OsString;

use tool::shared::Failure;

fn parse(args: &[&str]) -> (Result<Option<tool::Args>, Failure>, String) {
    let mut out = Vec::new();
    let result = tool::parse(args.iter().map(OsString::from), &mut out);
    (result, String::from_utf8(out).unwrap())
}

#[test]
fn defaults_and_flags() {
    let (Ok(Some(args)), _) = parse(&[]) else {
        panic!("no arguments must parse");
    };
    assert_eq!((args.restarts, args.sweeps), (0, 3));
    let (Ok(Some(args)), _) = parse(&["--restarts", "2", "--sweeps=5"]) else {
        panic!("flags must parse");
    };
    assert_eq!((args.restarts, args.sweeps), (2, 5));
}

#[test]
fn help_stops_before_the_search() {
    let (result, out) = parse(&["--help"]);
    assert!(matches!(result, Ok(None)), "{result:?}");
    for word in ["--restarts", "--sweeps", "Exit status"] {
        assert!(out.contains(word), "--help lacks {word}: {out}");
    }
}

#[test]
fn bad_arguments_are_one_line_errors_with_status_2() {
    for (args, expected) in [
        (&["--frobnicate"][..], "'--frobnicate'"),
        (&["2"], "'2'"),
        (&["--restarts", "two"], "\"two\" is not a whole number"),
        (
            &["--sweeps", "-1"],
            "the value must be non-negative, got \"-1\"",
        ),
        (&["--sweeps"], "--sweeps <N>"),
    ] {
        let (result, out) = parse(args);
        let Err(failure) = result else {
            panic!("{args:?} must fail: {result:?}");
        };
        assert_eq!((failure.status(), out.as_str()), (2, ""), "{args:?}");
        let message = failure.to_string();
        assert!(
            message.contains(expected),
            "{args:?}: {message:?} lacks {expected:?}"
        );
        assert_eq!(message.lines().count(), 1, "{args:?}: {message:?}");
    }
}
