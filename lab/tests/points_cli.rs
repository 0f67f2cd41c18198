//! The `points` example's argument parsing and output, tested in-process
//! (Cargo gives integration tests no path to example binaries).

#[path = "../examples/points/cli.rs"]
mod cli;

use std::ffi::OsString;

use cli::shared::{self, Failure};
use cli::{Format, Options};
use wellspread::{Sampler2D, SamplerKind};

/// Runs the whole tool in-process: exit status, standard output, and the
/// one line it would print on standard error.
fn tool(args: &[&str]) -> (u8, String, String) {
    let mut stdout = Vec::new();
    let mut stderr = Vec::new();
    let result = cli::main_with(args.iter().map(OsString::from), &mut stdout);
    let status = shared::finish("points", result, &mut stderr);
    (
        status,
        String::from_utf8(stdout).unwrap(),
        String::from_utf8(stderr).unwrap(),
    )
}

fn options(args: &[&str]) -> Options {
    match cli::parse(args.iter().map(OsString::from), &mut Vec::new()) {
        Ok(Some(options)) => options,
        other => panic!("{args:?}: {other:?}"),
    }
}

fn output(args: &[&str]) -> String {
    let (status, out, err) = tool(args);
    assert_eq!((status, err.as_str()), (0, ""), "{args:?}");
    out
}

#[test]
fn every_sampler_name_parses_with_and_without_equals() {
    for &kind in SamplerKind::ALL {
        for o in [
            options(&["--sampler", kind.name(), "--n", "10"]),
            options(&[&format!("--sampler={kind}"), "--n=10"]),
        ] {
            assert_eq!(o.sampler.kind(), Some(kind));
            assert_eq!(o.sampler.len(), 10);
            assert_eq!((o.pattern, o.format, o.out), (0, Format::Csv, None));
        }
    }
}

#[test]
fn options_parse_in_any_order() {
    let o = options(&[
        "--format",
        "svg",
        "--out=a.svg",
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
    assert_eq!(o.out, Some("a.svg".into()));
    assert_eq!(
        options(&["--sampler", "jittered", "--n", "3", "--pattern=4294967295"]).pattern,
        u32::MAX
    );
}

#[test]
fn help_lists_every_option_the_samplers_the_format_and_the_exit_codes() {
    for args in [&["--help"][..], &["-h"], &["--sampler", "random", "--help"]] {
        let (status, help, err) = tool(args);
        assert_eq!((status, err.as_str()), (0, ""), "{args:?}");
        for needle in [
            "--sampler",
            "--n ",
            "--pattern",
            "--format",
            "--out",
            "--help",
            "csv",
            "svg",
            "Exit status",
            " 2 ",
            " 1 ",
        ] {
            assert!(help.contains(needle), "{args:?} lacks {needle:?}:\n{help}");
        }
        for &kind in SamplerKind::ALL {
            assert!(help.contains(kind.name()), "{args:?} lacks {kind}");
        }
    }
}

#[test]
fn bad_arguments_are_one_line_errors_with_status_2() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--sampler", "nope", "--n", "4"],
            "unknown sampler \"nope\"",
        ),
        (
            &["--sampler", "regular, jittered", "--n", "4"],
            "unknown sampler \"regular, jittered\"",
        ),
        (&["--sampler", "jittered", "--n", "0"], "n = 0"),
        (
            &["--sampler", "jittered", "--n", "-3"],
            "--n <N>: the value must be non-negative, got \"-3\"",
        ),
        (
            &["--sampler", "random", "--n", "4", "--pattern", "-1"],
            "--pattern <P>: the value must be non-negative, got \"-1\"",
        ),
        (
            &[
                "--sampler",
                "latin-hypercube",
                "--n",
                "4",
                "--dimensions",
                "3",
                "--projection",
                "-1,2",
            ],
            "--projection <I,J>: the value must be non-negative, got \"-1\"",
        ),
        (
            &["--sampler", "jittered", "--n=lots"],
            "\"lots\" is not a whole number",
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
            "\"0x1_0000_0000\" is not a number",
        ),
        (
            &["--sampler", "random", "--n", "4", "--pattern", "4294967296"],
            "--pattern",
        ),
        (
            &["--sampler", "random", "--n", "4", "--format", "png"],
            "csv, svg",
        ),
        (&["--sampler", "random", "--n"], "--n <N>"),
        (&["--sampler"], "--sampler <NAME>"),
        (&["--sampler", "random", "--n", "4", "--bogus"], "'--bogus'"),
        (&["random", "--n", "4"], "'random'"),
        (&["--n", "4"], "--sampler <NAME>"),
        (&["--sampler", "random"], "--n <N>"),
        (&[], "--sampler <NAME> --n <N>"),
        (&["--sampler", "random", "--n", "4", "--n", "5"], "--n <N>"),
    ];
    for &(args, expected) in cases {
        let (status, out, err) = tool(args);
        assert_eq!((status, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(
            err.starts_with("points: ") && err.contains(expected),
            "{args:?}: {err:?} lacks {expected:?}"
        );
        assert_eq!(err.lines().count(), 1, "{args:?}: {err:?} is not one line");
    }
}

/// How a tool with a list flag (the tracer's `--sampler`) declares it.
#[derive(clap::Parser, Debug)]
struct ListArgs {
    #[arg(long, value_name = "LIST", value_parser = shared::sampler_list)]
    sampler: shared::SamplerList,
}

#[test]
fn sampler_lists_name_the_unknown_item() {
    let parse = |args: &[&str]| {
        shared::parse::<ListArgs>("list", "", args.iter().map(OsString::from), &mut Vec::new())
    };
    let parsed = parse(&["--sampler=regular,jittered,regular"])
        .unwrap()
        .unwrap();
    assert_eq!(
        parsed.sampler.0,
        [SamplerKind::Regular, SamplerKind::Jittered]
    );
    let cases = [
        (
            "regular, jitterd",
            "item 2 of \"regular, jitterd\": unknown sampler \" jitterd\"",
        ),
        (
            "jittered,jitterd",
            "item 2 of \"jittered,jitterd\": unknown sampler \"jitterd\";",
        ),
        ("sobol,,pmj02", "item 2 of \"sobol,,pmj02\": empty name"),
        (
            "halton2",
            "unknown sampler \"halton2\"; expected one of: regular random",
        ),
    ];
    // Names follow SamplerKind's rule: spaces around them, case and `_`
    // do not matter.
    assert!(shared::sampler_list("regular, Jittered").is_ok());
    for (value, expected) in cases {
        let err = shared::sampler_list(value).unwrap_err();
        assert!(err.starts_with(expected), "{value:?}: {err:?}");
        match parse(&["--sampler", value]) {
            Err(Failure::Input(message)) => {
                assert!(message.contains(expected), "{message}");
                assert!(!message.contains('\n'), "{message}");
            }
            other => panic!("{value:?}: {other:?}"),
        }
    }
}

#[test]
fn failures_map_to_the_documented_exit_codes() {
    assert_eq!(Failure::Input(String::new()).status(), 2);
    assert_eq!(Failure::Io(String::new()).status(), 1);
    let mut stderr = Vec::new();
    assert_eq!(shared::finish("t", Ok(()), &mut stderr), 0);
    assert!(stderr.is_empty());
}

#[test]
fn csv_round_trips_exactly_through_f32_and_f64_parsers() {
    for &kind in SamplerKind::ALL {
        let csv = output(&["--sampler", kind.name(), "--n", "37", "--pattern", "99"]);
        let sampler = kind.build(37).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 37, "{kind}: no header, one line per point");
        for (index, line) in (0..).zip(lines) {
            let (x, y) = line.split_once(',').unwrap();
            let p = sampler.sample(index, 99);
            for (text, v) in [(x, p.x), (y, p.y)] {
                assert_eq!(
                    text.parse::<f32>().unwrap().to_bits(),
                    v.to_bits(),
                    "{line}"
                );
                assert_eq!(text.parse::<f64>().unwrap(), f64::from(v), "{line}");
            }
        }
    }
    // The value from the issue: 3543/4096 printed as the shortest f32,
    // `0.86499023`, reads as 0.86499022999... in f64, below 3543/4096.
    assert_eq!(cli::csv_value(3543.0 / 4096.0), "0.864990234375");
    assert!("0.86499023".parse::<f64>().unwrap() < 3543.0 / 4096.0);
}

/// Points parsed as f64, the way numpy or pandas read the CSV.
fn read_f64(args: &[&str]) -> Vec<(f64, f64)> {
    output(args)
        .lines()
        .map(|line| {
            let (x, y) = line.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// Whether every one of `cells` (by `cell(x, y)`) holds exactly one point.
fn one_per_cell(points: &[(f64, f64)], cells: usize, cell: impl Fn(f64, f64) -> usize) -> bool {
    let mut seen = vec![false; cells];
    points.len() == cells
        && points.iter().all(|&(x, y)| {
            let c = cell(x, y);
            c < cells && !std::mem::replace(&mut seen[c], true)
        })
}

#[test]
fn strata_hold_exactly_on_csv_read_as_f64() {
    // x * n is exact in f64 for these n: x has at most 24 significant bits.
    let stratum = |v: f64, parts: u32| (v * f64::from(parts)).floor() as usize;
    let rooks = |points: &[(f64, f64)], n: u32| {
        let n_usize = n as usize;
        one_per_cell(points, n_usize, |x, _| stratum(x, n))
            && one_per_cell(points, n_usize, |_, y| stratum(y, n))
    };
    let grid = |points: &[(f64, f64)], columns: u32, rows: u32| {
        one_per_cell(points, (columns * rows) as usize, |x, y| {
            stratum(y, rows) * columns as usize + stratum(x, columns)
        })
    };
    // The issue's case: n-rooks at n = 4096, pattern 0.
    let points = read_f64(&["--sampler", "n-rooks", "--n", "4096"]);
    assert!(rooks(&points, 4096));
    for (n, columns, rows) in [(4096, 64, 64), (1000, 25, 40), (12, 3, 4)] {
        let count = n.to_string();
        let jittered = read_f64(&["--sampler", "jittered", "--n", &count, "--pattern", "7"]);
        assert!(grid(&jittered, columns, rows), "jittered n = {n}");
        for name in ["multi-jittered", "correlated-multi-jittered"] {
            let points = read_f64(&["--sampler", name, "--n", &count, "--pattern", "7"]);
            assert!(grid(&points, columns, rows), "{name} n = {n}");
            assert!(rooks(&points, n), "{name} n = {n}");
        }
    }
    // The check is strict enough to fail: random points are not Latin.
    let random = read_f64(&["--sampler", "random", "--n", "4096"]);
    assert!(!rooks(&random, 4096));
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
fn out_writes_the_file_and_io_failure_is_status_1() {
    let path = std::env::temp_dir().join(format!("wellspread-points-{}.csv", std::process::id()));
    let path_text = path.to_str().unwrap();
    let args = ["--sampler", "multi-jittered", "--n", "25"];
    let (status, out, err) = tool(&[&args[..], &["--out", path_text]].concat());
    assert_eq!((status, out.as_str(), err.as_str()), (0, "", ""));
    let written = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(written, output(&args));
    assert_eq!(written.lines().count(), 25);
    // A missing folder is created, as the tracer's --out and --report do.
    let dir = std::env::temp_dir().join(format!("wellspread-points-dir-{}", std::process::id()));
    let nested = dir.join("a/b/x.csv");
    let (status, out, err) = tool(&[&args[..], &["--out", nested.to_str().unwrap()]].concat());
    assert_eq!((status, out.as_str(), err.as_str()), (0, "", ""));
    assert_eq!(std::fs::read_to_string(&nested).unwrap(), output(&args));
    std::fs::remove_dir_all(&dir).unwrap();
    // A folder that cannot be made is an I/O failure: one line, exit 1.
    let (status, out, err) = tool(&[
        "--sampler",
        "random",
        "--n",
        "2",
        "--out",
        "/dev/null/x.csv",
    ]);
    assert_eq!((status, out.as_str()), (1, ""));
    assert!(
        err.starts_with("points: cannot create /dev/null: "),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
}

/// Points of an N-dimensional set read back as f64, one row per line.
fn read_rows(args: &[&str]) -> Vec<Vec<f64>> {
    output(args)
        .lines()
        .map(|line| line.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

#[test]
fn n_dimensional_sets_write_one_value_per_dimension() {
    let stratum = |v: f64, parts: u32| (v * f64::from(parts)).floor() as usize;
    // A Latin hypercube: every column Latin.
    let rows = read_rows(&[
        "--sampler",
        "latin-hypercube",
        "--n",
        "97",
        "--dimensions",
        "5",
    ]);
    assert_eq!(rows.len(), 97);
    for d in 0..5 {
        let mut seen = [false; 97];
        for row in &rows {
            assert_eq!(row.len(), 5);
            assert!(!std::mem::replace(&mut seen[stratum(row[d], 97)], true));
        }
    }
    // An orthogonal array of strength 3 at 64 = 4^3 in 5 dimensions: every
    // 3D projection one point per cell of 4 x 4 x 4, every column Latin.
    let rows = read_rows(&[
        "--sampler",
        "orthogonal",
        "--n",
        "64",
        "--dimensions",
        "5",
        "--strength",
        "3",
        "--offset",
        "multi-jittered",
        "--pattern",
        "9",
    ]);
    for a in 0..5 {
        for b in a + 1..5 {
            for c in b + 1..5 {
                let mut seen = [false; 64];
                for row in &rows {
                    let cell =
                        stratum(row[a], 4) * 16 + stratum(row[b], 4) * 4 + stratum(row[c], 4);
                    assert!(!std::mem::replace(&mut seen[cell], true), "{a} {b} {c}");
                }
            }
        }
        let mut seen = [false; 64];
        for row in &rows {
            assert!(!std::mem::replace(&mut seen[stratum(row[a], 64)], true));
        }
    }
    // The SVG shows the chosen projection with the q x q grid.
    let svg = output(&[
        "--sampler",
        "orthogonal",
        "--n",
        "25",
        "--dimensions",
        "6",
        "--projection",
        "3,5",
        "--format",
        "svg",
    ]);
    assert_eq!(count(&svg, "<circle "), 25);
    assert_eq!(lines_in_group(&svg, "coarse-grid"), 8);
    assert_eq!(lines_in_group(&svg, "fine-grid"), 48);
    assert!(svg.contains("6 dimensions, 3 across and 5 up"), "{svg}");
    // The 4D Sobol' set at 64 points: a (3,6,4)-net, so every box of
    // 2 x 2 x 2 in dimensions 1, 2 and 3 holds 8 points.
    let rows = read_rows(&["--sampler", "sobol-4d", "--n", "64", "--dimensions", "4"]);
    let mut cells = [0; 8];
    for row in &rows {
        assert_eq!(row.len(), 4);
        cells[stratum(row[1], 2) * 4 + stratum(row[2], 2) * 2 + stratum(row[3], 2)] += 1;
    }
    assert_eq!(cells, [8; 8]);
    // Faure's (0,4)-sequence at 16 points: every pair fills 4 x 4, here
    // dimensions 0 and 3.
    let rows = read_rows(&["--sampler", "faure-4d", "--n", "16", "--dimensions", "4"]);
    let mut cells = [0; 16];
    for row in &rows {
        assert_eq!(row.len(), 4);
        cells[stratum(row[0], 4) * 4 + stratum(row[3], 4)] += 1;
    }
    assert_eq!(cells, [1; 16]);
}

#[test]
fn n_dimensional_options_are_checked() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--sampler", "jittered", "--n", "4", "--dimensions", "3"],
            "jittered is a 2D sampler",
        ),
        (&["--sampler", "orthogonal", "--n", "24"], "use 16 or 25"),
        (
            &["--sampler", "orthogonal", "--n", "25", "--dimensions", "7"],
            "makes 1 to 6 dimensions",
        ),
        (
            &["--sampler", "orthogonal", "--n", "25", "--strength", "5"],
            "strength 2, 3 or 4",
        ),
        (
            &[
                "--sampler",
                "latin-hypercube",
                "--n",
                "4",
                "--dimensions",
                "0",
            ],
            "makes 1 to 65536 dimensions",
        ),
        (
            &[
                "--sampler",
                "latin-hypercube",
                "--n",
                "4",
                "--format",
                "svg",
                "--projection",
                "0,2",
            ],
            "two different dimensions below 2",
        ),
        (
            &[
                "--sampler",
                "latin-hypercube",
                "--n",
                "4",
                "--projection",
                "1",
            ],
            "is not two dimensions I,J",
        ),
        (
            &["--sampler", "latin", "--n", "4"],
            "N-dimensional: latin-hypercube orthogonal sobol-4d faure-4d",
        ),
        (
            &["--sampler", "sobol-4d", "--n", "4", "--dimensions", "3"],
            "sobol-4d has 4 dimensions",
        ),
        (
            &["--sampler", "faure-4d", "--n", "16", "--dimensions", "2"],
            "faure-4d has 4 dimensions",
        ),
        (
            &["--sampler", "faure-4d", "--n", "0", "--dimensions", "4"],
            "--n 0",
        ),
    ];
    for &(args, expected) in cases {
        let (status, out, err) = tool(args);
        assert_eq!((status, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(
            err.contains(expected),
            "{args:?}: {err:?} lacks {expected:?}"
        );
        assert_eq!(err.lines().count(), 1, "{args:?}: {err:?}");
    }
    let (_, help, _) = tool(&["--help"]);
    for needle in [
        "--dimensions",
        "--strength",
        "--offset",
        "--projection",
        "latin-hypercube",
        "orthogonal",
    ] {
        assert!(help.contains(needle), "help lacks {needle}");
    }
}

#[test]
fn out_help_says_missing_folders_are_created() {
    // `--out /nonexistent/x.csv` creates the folder: --help says so.
    let (status, help, err) = tool(&["--help"]);
    assert_eq!((status, err.as_str()), (0, ""));
    let (_, after) = help.split_once("--out <FILE>").unwrap();
    let text = after.split("\n  -").next().unwrap();
    let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(text.contains("missing folders are created"), "{text}");
}
