//! The `points` example's argument parsing and output, tested in-process
//! (Cargo gives integration tests no path to example binaries).

#[path = "../examples/points/cli.rs"]
mod cli;

use std::ffi::OsString;

use cli::{Command, Format, Options};
use wellspread::{Sampler2D, SamplerKind};

fn parse(args: &[&str]) -> Result<Command, String> {
    cli::parse(args.iter().map(OsString::from))
}

fn options(args: &[&str]) -> Options {
    match parse(args) {
        Ok(Command::Run(options)) => options,
        other => panic!("{args:?}: {other:?}"),
    }
}

fn output(args: &[&str]) -> String {
    let mut out = Vec::new();
    cli::write_points(&options(args), &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn every_sampler_name_parses() {
    for &kind in SamplerKind::ALL {
        let o = options(&["--sampler", kind.name(), "--n", "10"]);
        assert_eq!(o.sampler.kind(), kind);
        assert_eq!(o.sampler.len(), 10);
        assert_eq!((o.pattern, o.format, o.out), (0, Format::Csv, None));
    }
}

#[test]
fn options_parse_in_any_order() {
    let o = options(&[
        "--format",
        "svg",
        "--out",
        "a.svg",
        "--pattern",
        "0xDEADbeef",
        "--n",
        "4294967295",
        "--sampler",
        "random",
    ]);
    assert_eq!(o.sampler.len(), u32::MAX);
    assert_eq!(o.pattern, 0xdead_beef);
    assert_eq!(o.format, Format::Svg);
    assert_eq!(o.out, Some(OsString::from("a.svg")));
    assert_eq!(
        options(&[
            "--sampler",
            "jittered",
            "--n",
            "3",
            "--pattern",
            "4294967295"
        ])
        .pattern,
        u32::MAX
    );
}

#[test]
fn help_wins_and_lists_the_samplers() {
    for args in [&["--help"][..], &["-h"], &["--sampler", "nope", "--help"]] {
        assert_eq!(parse(args), Ok(Command::Help), "{args:?}");
    }
    let usage = cli::usage();
    for &kind in SamplerKind::ALL {
        assert!(usage.contains(kind.name()), "{usage}");
    }
}

#[test]
fn bad_arguments_are_one_line_errors() {
    let cases: &[(&[&str], &str)] = &[
        (&["--sampler", "nope", "--n", "4"], "unknown sampler"),
        (&["--sampler", "jittered", "--n", "0"], "n = 0"),
        (
            &["--sampler", "jittered", "--n", "-3"],
            "not a whole number",
        ),
        (
            &["--sampler", "jittered", "--n", "lots"],
            "not a whole number",
        ),
        (
            &["--sampler", "jittered", "--n", "4294967296"],
            "not a whole number",
        ),
        (
            &["--sampler", "n-rooks", "--n", "16777217"],
            "at most 16777216",
        ),
        (&["--sampler", "regular", "--n", "16777259"], "2^24"),
        (
            &["--sampler", "random", "--n", "4", "--pattern", "x"],
            "--pattern",
        ),
        (
            &[
                "--sampler",
                "random",
                "--n",
                "4",
                "--pattern",
                "0x1_0000_0000",
            ],
            "--pattern",
        ),
        (
            &["--sampler", "random", "--n", "4", "--pattern", "4294967296"],
            "--pattern",
        ),
        (
            &["--sampler", "random", "--n", "4", "--format", "png"],
            "csv or svg",
        ),
        (&["--sampler", "random", "--n"], "--n needs a value"),
        (&["--sampler"], "--sampler needs a value"),
        (
            &["--sampler", "random", "--n", "4", "--bogus"],
            "unknown argument",
        ),
        (&["random", "--n", "4"], "unknown argument"),
        (&["--n", "4"], "--sampler NAME is required"),
        (&["--sampler", "random"], "--n N is required"),
        (&[], "is required"),
        (
            &["--sampler", "random", "--n", "4", "--n", "5"],
            "given twice",
        ),
    ];
    for &(args, expected) in cases {
        match parse(args) {
            Err(message) => {
                assert!(
                    message.contains(expected),
                    "{args:?}: {message:?} lacks {expected:?}"
                );
                assert!(
                    !message.contains('\n'),
                    "{args:?}: {message:?} is not one line"
                );
            }
            Ok(command) => panic!("{args:?} parsed as {command:?}"),
        }
    }
}

#[test]
fn csv_is_every_point_round_tripped() {
    for &kind in SamplerKind::ALL {
        let csv = output(&["--sampler", kind.name(), "--n", "37", "--pattern", "99"]);
        let sampler = kind.build(37).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 37, "{kind}: no header, one line per point");
        for (index, line) in (0..).zip(lines) {
            let (x, y) = line.split_once(',').unwrap();
            let p = sampler.sample(index, 99);
            assert_eq!(x.parse::<f32>().unwrap().to_bits(), p.x.to_bits(), "{line}");
            assert_eq!(y.parse::<f32>().unwrap().to_bits(), p.y.to_bits(), "{line}");
            assert_eq!(line, format!("{},{}", p.x, p.y));
        }
    }
}

fn count(haystack: &str, needle: &str) -> usize {
    haystack.matches(needle).count()
}

/// The lines inside the `<g id="...">` group, or 0 if there is none.
fn lines_in_group(svg: &str, id: &str) -> usize {
    let Some(start) = svg.find(&format!(r#"<g id="{id}">"#)) else {
        return 0;
    };
    let group = &svg[start..];
    count(&group[..group.find("</g>").unwrap()], "<line ")
}

#[test]
fn svg_draws_points_and_the_promised_strata() {
    // (sampler, n, coarse lines, fine lines): m x k coarse cells need
    // (m - 1) + (k - 1) lines, an n x n fine grid 2 (n - 1), drawn up to 64.
    let cases = [
        ("regular", 16, 6, 0),
        ("regular", 100, 18, 0),
        ("random", 16, 0, 0),
        ("jittered", 12, 5, 0),
        ("n-rooks", 16, 0, 30),
        ("n-rooks", 100, 0, 0),
        ("multi-jittered", 16, 6, 30),
        ("multi-jittered", 100, 18, 0),
        ("correlated-multi-jittered", 13, 12, 24),
        ("correlated-multi-jittered", 64, 14, 126),
    ];
    for (name, n, coarse, fine) in cases {
        let svg = output(&["--sampler", name, "--n", &n.to_string(), "--format", "svg"]);
        assert!(
            svg.starts_with("<svg ") && svg.ends_with("</svg>\n"),
            "{name}"
        );
        assert_eq!(count(&svg, "<circle "), n, "{name} n = {n}");
        assert_eq!(
            lines_in_group(&svg, "coarse-grid"),
            coarse,
            "{name} n = {n}"
        );
        assert_eq!(lines_in_group(&svg, "fine-grid"), fine, "{name} n = {n}");
        // Every point inside the drawn square (16 to 528 user units).
        for circle in svg.split("<circle ").skip(1) {
            for attribute in ["cx=\"", "cy=\""] {
                let start = circle.find(attribute).unwrap() + attribute.len();
                let value: f64 = circle[start..start + circle[start..].find('"').unwrap()]
                    .parse()
                    .unwrap();
                assert!((16.0..=528.0).contains(&value), "{name}: {circle}");
            }
        }
    }
}

#[test]
fn out_writes_the_file() {
    let path = std::env::temp_dir().join(format!("wellspread-points-{}.csv", std::process::id()));
    let path_text = path.to_str().unwrap();
    let args = [
        "--sampler",
        "multi-jittered",
        "--n",
        "25",
        "--out",
        path_text,
    ];
    cli::run(&options(&args)).unwrap();
    let written = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(written, output(&args));
    assert_eq!(written.lines().count(), 25);
    let missing = [
        "--sampler",
        "random",
        "--n",
        "2",
        "--out",
        "/nonexistent-dir/x.csv",
    ];
    assert!(cli::run(&options(&missing)).is_err());
}
