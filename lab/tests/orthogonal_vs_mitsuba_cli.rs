//! The `orthogonal_vs_mitsuba` example's arguments and its Mitsuba CSV:
//! `--help`, an unknown flag or a bad CSV line stop it with one line
//! before the minute of measuring (it used to panic on a bad line and
//! read every other argument as the CSV's path).

#[allow(dead_code)] // the measurement itself, run by the example's `main`
#[path = "../examples/orthogonal_vs_mitsuba.rs"]
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
fn the_csv_and_the_svg_parse() {
    let (Ok(Some(args)), _) = parse(&[]) else {
        panic!("no arguments must parse");
    };
    assert_eq!((args.csv, args.svg), (None, None));
    let (Ok(Some(args)), _) = parse(&["m.csv", "--svg", "p.svg"]) else {
        panic!("a CSV and --svg must parse");
    };
    assert_eq!(args.csv, Some(PathBuf::from("m.csv")));
    assert_eq!(args.svg, Some(PathBuf::from("p.svg")));
}

#[test]
fn help_and_unknown_flags_stop_before_measuring() {
    let (result, out) = parse(&["--help"]);
    assert!(matches!(result, Ok(None)), "{result:?}");
    for word in ["--svg", "CSV", "Exit status"] {
        assert!(out.contains(word), "--help lacks {word}: {out}");
    }
    let (result, _) = parse(&["--bogus"]);
    let Err(Failure::Input(message)) = result else {
        panic!("an unknown flag must be an input error: {result:?}");
    };
    assert!(message.contains("--bogus"), "{message}");
    assert!(!message.contains('\n'), "one line: {message:?}");
    let (result, _) = parse(&["a.csv", "b.csv"]);
    assert!(matches!(result, Err(Failure::Input(_))), "{result:?}");
}

#[test]
fn the_shipped_csv_reads_and_a_bad_line_is_named() {
    let shipped =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/orthogonal_vs_mitsuba.csv");
    let table = tool::read_mitsuba(&shipped).expect("the shipped CSV reads");
    assert_eq!(
        table.get(&(9, "coupled-4d".to_owned())),
        Some(&(9, 1.4689e-2))
    );

    let dir = std::env::temp_dir().join(format!("ovm-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.csv");
    std::fs::write(
        &bad,
        "requested,used,integrand,rmse\n9,9,coupled-4d,0.1\n9,9,product-6d\n",
    )
    .unwrap();
    let Err(Failure::Input(message)) = tool::read_mitsuba(&bad) else {
        panic!("a short line must be an input error");
    };
    assert!(message.contains("line 3"), "{message}");
    assert!(message.contains("\"9,9,product-6d\""), "{message}");
    std::fs::write(&bad, "requested,used,integrand,rmse\n9,9,coupled-4d,NaN\n").unwrap();
    assert!(matches!(tool::read_mitsuba(&bad), Err(Failure::Input(_))));
    let missing = dir.join("missing.csv");
    assert!(matches!(tool::read_mitsuba(&missing), Err(Failure::Io(_))));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_oversized_csv_is_named_as_a_mitsuba_csv_not_a_docs_page() {
    let dir = std::env::temp_dir().join(format!("ovm-big-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let big = dir.join("big.csv");
    let limit = usize::try_from(tool::shared::MAX_PAGE).unwrap();
    std::fs::write(&big, vec![b'9'; limit + 1]).unwrap();
    let result = tool::read_mitsuba(&big);
    std::fs::remove_dir_all(&dir).unwrap();
    let Err(failure @ Failure::Input(_)) = result else {
        panic!("an oversized CSV must be an input error: {result:?}");
    };
    let message = failure.to_string();
    assert!(
        message.ends_with("big.csv is larger than 4 MiB, the limit for a Mitsuba CSV"),
        "{message}"
    );
    assert!(!message.contains("docs page"), "{message}");
    assert_eq!(failure.status(), 2);
}
