//! The `metrics` example run in-process (Cargo gives integration tests no
//! path to example binaries): input parsing, the JSON it prints and its
//! exit codes.

#[allow(dead_code)] // the example's `main`
#[path = "../examples/metrics.rs"]
mod tool;

// Both tools include examples/shared/cli.rs, each as its own module.
#[allow(clippy::duplicate_mod)]
#[path = "../examples/points/cli.rs"]
mod points;

use std::ffi::OsString;

/// Exit status, standard output and standard error of one run.
fn run(args: &[&str], stdin: &[u8]) -> (u8, String, String) {
    let mut stdout = Vec::new();
    let mut stderr = Vec::new();
    let result = tool::main_with(
        args.iter().map(OsString::from),
        &mut &stdin[..],
        &mut stdout,
    );
    let status = tool::shared::finish("metrics", result, &mut stderr);
    (
        status,
        String::from_utf8(stdout).unwrap(),
        String::from_utf8(stderr).unwrap(),
    )
}

/// The fields of the JSON line, in order, as (name, raw value).
fn fields(json: &str) -> Vec<(String, String)> {
    let body = json.trim_end().strip_prefix('{').unwrap().strip_suffix('}');
    body.unwrap()
        .split(", ")
        .map(|field| {
            let (name, value) = field.split_once(": ").unwrap();
            (name.trim_matches('"').to_owned(), value.to_owned())
        })
        .collect()
}

fn field(json: &str, name: &str) -> String {
    let found = fields(json).into_iter().find(|(k, _)| k == name);
    found.unwrap_or_else(|| panic!("no {name} in {json}")).1
}

fn ok(args: &[&str], stdin: &[u8]) -> String {
    let (status, out, err) = run(args, stdin);
    assert_eq!((status, err.as_str()), (0, ""), "{args:?}");
    assert_eq!(out.lines().count(), 1, "{out}");
    out
}

const ALL_FIELDS: [&str; 11] = [
    "n",
    "star_discrepancy",
    "l2_star_discrepancy",
    "centered_l2_discrepancy",
    "wraparound_l2_discrepancy",
    "min_distance",
    "toroidal_min_distance",
    "normalized_toroidal_min_distance",
    "is_latin",
    "is_net_base2",
    "t_value",
];

#[test]
fn a_byte_order_mark_and_a_header_are_skipped() {
    let plain = ok(&[], b"0.5,0.5\n0.25,0.75\n");
    assert_eq!(field(&plain, "n"), "2");
    for input in [
        &b"\xef\xbb\xbf0.5,0.5\n0.25,0.75\n"[..],
        b"x,y\n0.5,0.5\n0.25,0.75\n",
        b"\xef\xbb\xbf\"x\", \"y\"\r\n0.5,0.5\r\n\r\n0.25,0.75",
        b"\n\nx,y,label\n0.5,0.5\n0.25,0.75\n",
    ] {
        assert_eq!(ok(&[], input), plain, "{}", String::from_utf8_lossy(input));
    }
}

#[test]
fn every_input_error_names_its_line() {
    let cases: &[(&[u8], &str)] = &[
        // A first line with a numeric field is data, not a header.
        (
            b"0.5,0.5,extra\n0.25,0.75\n",
            "line 1, column 9: expected `x,y` (two numbers), got 3 fields in `0.5,0.5,extra`",
        ),
        (
            b"x,0.5\n0.25,0.75\n",
            "line 1, column 1: x = `x` is not a number",
        ),
        (
            b"0.5,0.5\nx,y\n",
            "line 2, column 1: x = `x` is not a number",
        ),
        (
            b"\xef\xbb\xbf0.5\n",
            "line 1, column 4: expected `x,y` (two numbers), got 1 fields",
        ),
        (
            b"x,y\n\n0.5,0.5\n1,0.5\n",
            "line 4, column 1: x = 1 is outside [0, 1)",
        ),
        (
            b"0.5,0.5\n0.5,-0.25\n",
            "line 2, column 5: y = -0.25 is outside [0, 1)",
        ),
        (
            b"0.5,0.5\n0.5,0.5\nNaN,0.5\n",
            "line 3, column 1: x = NaN is not finite",
        ),
        (b"0.5, inf\n", "line 1, column 6: y = inf is not finite"),
        (
            b"0.5,0.99999999\n",
            "line 1, column 5: y = 0.99999999 rounds to 1 in f32",
        ),
        (
            b"0.5,0.5\n0.5,0.5\n\xff,0.5\n",
            "line 3, column 1: not UTF-8 text",
        ),
        (
            b"0.5,0.5\n0.5,\xc3\xa9\xff\n",
            "line 2, column 6: not UTF-8 text",
        ),
        // Below 1, but it rounds to 1 in f32 and f64 alike.
        (
            b"0.999999999999999999999,0.5\n",
            "line 1, column 1: x = 0.999999999999999999999 rounds to 1 in f32",
        ),
        (
            b"0.5,9.99999999e-1\n",
            "line 1, column 5: y = 9.99999999e-1 rounds to 1",
        ),
        (
            b"0.5,1.000000001\n",
            "line 1, column 5: y = 1.000000001 is outside [0, 1)",
        ),
        (b"0.5,1e0\n", "line 1, column 5: y = 1e0 is outside [0, 1)"),
        (b"", "no points in the input"),
        (b"x,y\n\n", "no points in the input"),
    ];
    for &(input, expected) in cases {
        let (status, out, err) = run(&[], input);
        let shown = String::from_utf8_lossy(input);
        assert_eq!((status, out.as_str()), (2, ""), "{shown:?}: {err}");
        assert!(
            err.starts_with("metrics: ") && err.contains(expected),
            "{shown:?}: {err:?} lacks {expected:?}"
        );
        assert_eq!(err.lines().count(), 1, "{err:?}");
    }
}

#[test]
fn one_point_reports_every_defined_metric_and_null_for_the_rest() {
    let json = ok(&["--stratified", "1x1"], b"0.5,0.5\n");
    let names: Vec<String> = fields(&json).into_iter().map(|(k, _)| k).collect();
    assert_eq!(names[..11], ALL_FIELDS, "{json}");
    assert_eq!(names[11], "is_stratified");
    // One point is a (0, 0, 2)-net.
    assert_eq!(field(&json, "t_value"), "0");
    // One point at the centre: the box [0, 1) x [0, 0.5] holds it with
    // volume just over 1/4, so D* = 3/4.
    assert_eq!(field(&json, "n"), "1");
    assert_eq!(field(&json, "star_discrepancy"), "0.75");
    for name in [
        "min_distance",
        "toroidal_min_distance",
        "normalized_toroidal_min_distance",
    ] {
        assert_eq!(field(&json, name), "null", "{name}");
    }
    for name in ["is_latin", "is_net_base2", "is_stratified"] {
        assert_eq!(field(&json, name), "true", "{name}");
    }
    for name in [
        "l2_star_discrepancy",
        "centered_l2_discrepancy",
        "wraparound_l2_discrepancy",
    ] {
        let value: f64 = field(&json, name).parse().unwrap();
        assert!(value > 0.0 && value < 1.0, "{name} = {value}");
    }
    // n = 3 is not a power of two: only the net check is undefined.
    let json = ok(&[], b"0.1,0.2\n0.5,0.6\n0.7,0.9\n");
    assert_eq!(field(&json, "is_net_base2"), "null");
    assert_eq!(field(&json, "t_value"), "null");
    assert_eq!(field(&json, "is_latin"), "true");
    // The closest pair is (0.5, 0.6) and (0.7, 0.9): sqrt(0.2^2 + 0.3^2).
    let min_distance: f64 = field(&json, "min_distance").parse().unwrap();
    assert!(
        (min_distance - 0.13f64.sqrt()).abs() < 1e-6,
        "{min_distance}"
    );
}

#[test]
fn points_piped_into_metrics() {
    let mut csv = Vec::new();
    let args = ["--sampler", "multi-jittered", "--n", "64", "--pattern", "3"];
    points::main_with(args.map(OsString::from), &mut csv).unwrap();
    for grid in [&["--stratified", "8x8"][..], &["--stratified=8x8", "-"]] {
        let json = ok(grid, &csv);
        assert_eq!(field(&json, "n"), "64");
        assert_eq!(field(&json, "is_latin"), "true");
        assert_eq!(field(&json, "is_stratified"), "true");
        let d_star: f64 = field(&json, "star_discrepancy").parse().unwrap();
        assert!(d_star > 1.0 / 64.0 && d_star < 0.1, "{d_star}");
    }
    // Sobol and pmj02 prefixes are (0, m, 2)-nets; four points stacked in
    // one column of width 1/4 are only a (2, 2, 2)-net.
    for sampler in ["sobol", "pmj02"] {
        let mut csv = Vec::new();
        let args = ["--sampler", sampler, "--n", "256"];
        points::main_with(args.map(OsString::from), &mut csv).unwrap();
        assert_eq!(field(&ok(&[], &csv), "t_value"), "0", "{sampler}");
    }
    let column = ok(&[], b"0.1,0.1\n0.1,0.3\n0.1,0.6\n0.1,0.9\n");
    assert_eq!(field(&column, "t_value"), "2");
    let random = ["--sampler", "random", "--n", "64"];
    let mut csv = Vec::new();
    points::main_with(random.map(OsString::from), &mut csv).unwrap();
    assert_eq!(field(&ok(&[], &csv), "is_latin"), "false");
}

#[test]
fn a_file_argument_and_its_io_failure() {
    let path = std::env::temp_dir().join(format!("wellspread-metrics-{}.csv", std::process::id()));
    std::fs::write(&path, "0.5,0.5\n0.25,0.75\n").unwrap();
    let from_file = ok(&[path.to_str().unwrap()], b"ignored");
    std::fs::remove_file(&path).unwrap();
    assert_eq!(from_file, ok(&[], b"0.5,0.5\n0.25,0.75\n"));
    let (status, out, err) = run(&["/nonexistent-dir/points.csv"], b"");
    assert_eq!((status, out.as_str()), (1, ""));
    assert!(
        err.starts_with("metrics: cannot read /nonexistent-dir/points.csv: "),
        "{err}"
    );
}

#[test]
fn bad_arguments_are_one_line_errors_with_status_2() {
    let four = b"0.1,0.1\n0.6,0.1\n0.1,0.6\n0.6,0.6\n";
    let cases: &[(&[&str], &str)] = &[
        (&["--stratified", "8"], "\"8\" is not a grid MxK"),
        (&["--stratified=0x4"], "\"0x4\" is not a grid MxK"),
        (
            &["--stratified", "3x1"],
            "--stratified 3x1: its 3 cells do not divide n = 4",
        ),
        (&["--stratified"], "--stratified <MxK>"),
        (&["--bogus"], "'--bogus'"),
        (&["a.csv", "b.csv"], "'b.csv'"),
    ];
    for &(args, expected) in cases {
        let (status, out, err) = run(args, four);
        assert_eq!((status, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(
            err.contains(expected),
            "{args:?}: {err:?} lacks {expected:?}"
        );
        assert_eq!(err.lines().count(), 1, "{err:?}");
    }
    assert_eq!(
        field(&ok(&["--stratified", "2X2"], four), "is_stratified"),
        "true"
    );
}

#[test]
fn help_lists_the_options_the_formats_and_the_exit_codes() {
    for args in [&["--help"][..], &["-h"]] {
        let (status, help, err) = run(args, b"");
        assert_eq!((status, err.as_str()), (0, ""));
        for needle in [
            "--stratified",
            "[FILE]",
            "Input:",
            "byte-order mark",
            "Output:",
            "null",
            "Exit status",
            " 2 ",
            " 1 ",
        ] {
            assert!(help.contains(needle), "{args:?} lacks {needle:?}:\n{help}");
        }
        if args == ["--help"] {
            for name in ALL_FIELDS.iter().chain(&["is_stratified"]) {
                assert!(help.contains(&format!("`{name}`")), "{name}");
            }
        }
    }
}

/// `count` copies of `pattern`, then `tail`, produced on the fly so that
/// the test itself holds none of it.
struct Repeat {
    pattern: &'static [u8],
    count: usize,
    at: usize,
    tail: &'static [u8],
}

impl std::io::Read for Repeat {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let mut written = 0;
        while written < buf.len() {
            let total = self.pattern.len() * self.count;
            let byte = if self.at < total {
                self.pattern[self.at % self.pattern.len()]
            } else if let Some(&b) = self.tail.get(self.at - total) {
                b
            } else {
                break;
            };
            buf[written] = byte;
            written += 1;
            self.at += 1;
        }
        Ok(written)
    }
}

/// The peak resident memory of this test process so far, in bytes.
#[cfg(target_os = "linux")]
fn peak_rss() -> usize {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status.lines().find(|l| l.starts_with("VmHWM:")).unwrap();
    let kb: usize = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    kb * 1024
}

#[test]
fn huge_lines_give_short_messages_in_bounded_memory() {
    // A 100 MB field, and a line of 25 million fields (50 MB), each after a
    // good line; neither is kept whole.
    let cases: [(Repeat, &str); 3] = [
        (
            Repeat {
                pattern: b"9",
                count: 100_000_000,
                at: 0,
                tail: b"\n",
            },
            "line 1, column 1025: a line of more than the 1024 bytes allowed",
        ),
        (
            Repeat {
                pattern: b"0,",
                count: 25_000_000,
                at: 0,
                tail: b"0\n0.5,0.5\n",
            },
            "line 1, column 1025: a line of more than the 1024 bytes allowed",
        ),
        (
            Repeat {
                pattern: b"x",
                count: 1000,
                at: 0,
                tail: b",0.5\n",
            },
            "line 1, column 1: x = `xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...` is not a number",
        ),
    ];
    for (mut input, expected) in cases {
        let mut stdout = Vec::new();
        let result = tool::main_with(std::iter::empty::<OsString>(), &mut input, &mut stdout);
        let Err(tool::shared::Failure::Input(message)) = result else {
            panic!("{expected}: {result:?}");
        };
        assert!(message.starts_with(expected), "{message}");
        // The message quotes at most 80 characters of the input.
        assert!(
            message.len() < 300,
            "{} bytes: {message:.300}",
            message.len()
        );
    }
    #[cfg(target_os = "linux")]
    {
        let peak = peak_rss();
        assert!(peak < 64 << 20, "peak resident memory {} MB", peak >> 20);
    }
}

#[test]
fn an_endless_line_stops_at_the_limit() {
    // `metrics /dev/zero`: one line that never ends. The reader stops at
    // the line limit instead of reading on to learn the line's length.
    let mut endless = std::io::BufReader::new(std::io::repeat(0));
    let result = tool::read_points(&mut endless, 0);
    let Err(tool::ReadError::Input(message)) = result else {
        panic!("{result:?}");
    };
    assert!(
        message.starts_with("line 1, column 1025: a line of more than the 1024 bytes allowed"),
        "{message}"
    );
    // The zero bytes are escaped in the quote, never copied raw.
    assert!(
        !message.contains('\0') && message.contains("\\u{0}"),
        "{message}"
    );
    if cfg!(target_os = "linux") {
        let (status, out, err) = run(&["/dev/zero"], b"");
        assert_eq!((status, out.as_str()), (2, ""), "{err}");
        assert_eq!(err.lines().count(), 1, "{err:?}");
    }
}

#[test]
fn control_characters_in_the_input_are_escaped() {
    for (input, shown) in [
        (&b"0.5,0\x005\n"[..], "y = `0\\u{0}5` is not a number"),
        (b"\x1b[31m0.5,0.5\n", "x = `\\u{1b}[31m0.5` is not a number"),
        (b"0.5,0.5\n0.5,0.2\x07\n", "y = `0.2\\u{7}` is not a number"),
    ] {
        let (status, _, err) = run(&[], input);
        assert_eq!(status, 2, "{err}");
        assert!(err.contains(shown), "{err:?} lacks {shown:?}");
        assert!(
            !err.contains(['\0', '\x1b', '\x07']),
            "{err:?} copies a control character"
        );
        assert_eq!(err.lines().count(), 1, "{err:?}");
    }
}

#[test]
fn only_a_first_line_without_digits_is_a_header() {
    // A typo'd first point (letter O for zero) is an error, not a header.
    let (status, _, err) = run(&[], b"O.5,O.5\n0.25,0.75\n");
    assert_eq!(status, 2, "{err}");
    assert!(
        err.contains("line 1, column 1: x = `O.5` is not a number"),
        "{err}"
    );
    // A header with digits (`x1,x2`) is an error too: say it or drop it.
    let (status, _, err) = run(&[], b"x1,x2\n0.25,0.75\n");
    assert_eq!(status, 2, "{err}");
    assert!(err.contains("line 1, column 1"), "{err}");
    // Words alone are a header, as before.
    assert_eq!(field(&ok(&[], b"x,y\n0.25,0.75\n"), "n"), "1");
}

#[test]
fn a_field_that_fits_is_quoted_to_80_characters() {
    let mut input = b"0.5,".to_vec();
    input.extend(std::iter::repeat_n(b'7', 500));
    input.extend(b"x\n");
    let (status, _, err) = run(&[], &input);
    assert_eq!(status, 2);
    let expected = format!(
        "metrics: line 1, column 5: y = `{}...` is not a number\n",
        "7".repeat(80)
    );
    assert_eq!(err, expected);
}

#[test]
fn a_long_bad_argument_is_quoted_to_80_characters() {
    let long = format!("{}\nx4", "9".repeat(1000));
    let (status, out, err) = run(&["--stratified", &long], b"0.5,0.5\n");
    assert_eq!((status, out.as_str()), (2, ""));
    assert_eq!(err.lines().count(), 1, "{err:?}");
    assert!(
        err.contains(&format!("\"{}...\" is not a grid", "9".repeat(80))),
        "{err}"
    );
    assert!(err.len() < 300, "{} bytes", err.len());
}

/// The CSV of `points` run with `args`.
fn points_csv(args: &[&str]) -> Vec<u8> {
    let mut csv = Vec::new();
    points::main_with(args.iter().map(OsString::from), &mut csv).unwrap();
    csv
}

#[test]
fn n_dimensional_sets_are_checked_projection_by_projection() {
    // Strength 3 at 64 = 4^3 in 5 dimensions: Latin, and every 1D, 2D and
    // 3D projection stratified on 4 levels.
    let csv = points_csv(&[
        "--sampler",
        "orthogonal",
        "--n",
        "64",
        "--dimensions",
        "5",
        "--strength",
        "3",
    ]);
    let json = ok(
        &["--dimensions", "5", "--levels", "4", "--strength", "3"],
        &csv,
    );
    let names: Vec<String> = fields(&json).into_iter().map(|(k, _)| k).collect();
    assert_eq!(
        names,
        [
            "n",
            "dimensions",
            "is_latin",
            "non_latin_dimension",
            "stratified_1d",
            "unstratified_1d",
            "stratified_2d",
            "unstratified_2d",
            "stratified_3d",
            "unstratified_3d"
        ]
    );
    for name in [
        "is_latin",
        "stratified_1d",
        "stratified_2d",
        "stratified_3d",
    ] {
        assert_eq!(field(&json, name), "true", "{name}: {json}");
    }
    assert_eq!(field(&json, "unstratified_3d"), "null");
    // A strength-2 array of 25 points: every pair on 5 x 5, and 5^3 cells
    // do not divide 25 (null).
    let csv = points_csv(&["--sampler", "orthogonal", "--n", "25", "--dimensions", "6"]);
    let json = ok(
        &["--dimensions", "6", "--levels", "5", "--strength", "3"],
        &csv,
    );
    assert_eq!(field(&json, "stratified_2d"), "true");
    assert_eq!(field(&json, "stratified_3d"), "null");
    // A Latin hypercube is Latin, but some pair misses cells; the first
    // such pair is named.
    let csv = points_csv(&[
        "--sampler",
        "latin-hypercube",
        "--n",
        "25",
        "--dimensions",
        "6",
    ]);
    let json = ok(&["--dimensions", "6", "--levels", "5"], &csv);
    assert_eq!(field(&json, "is_latin"), "true");
    assert_eq!(field(&json, "stratified_1d"), "true");
    assert_eq!(field(&json, "stratified_2d"), "false");
    assert!(field(&json, "unstratified_2d").starts_with('['), "{json}");
    // Jittered offsets are not Latin: dimension 0 is named.
    let csv = points_csv(&[
        "--sampler",
        "orthogonal",
        "--n",
        "25",
        "--dimensions",
        "3",
        "--offset",
        "jittered",
    ]);
    let json = ok(&["--dimensions", "3"], &csv);
    assert_eq!(field(&json, "is_latin"), "false");
    assert_eq!(field(&json, "non_latin_dimension"), "0");
    // One dimension, by hand: 0.1 and 0.6 are Latin on 2 strata; the
    // pair (0, 1) fills two of the four cells of 2 x 2 (one per row).
    let json = ok(&["--dimensions", "1", "--levels", "2"], b"0.1\n0.6\n");
    assert_eq!(field(&json, "is_latin"), "true");
    assert_eq!(field(&json, "stratified_2d"), "null");
    let json = ok(
        &["--dimensions", "3", "--levels", "2", "--strength", "2"],
        b"0.1,0.2,0.3\n0.6,0.7,0.2\n0.2,0.8,0.9\n0.7,0.3,0.6\n",
    );
    assert_eq!(field(&json, "stratified_2d"), "true", "{json}");
    let json = ok(
        &["--dimensions", "3", "--levels", "2"],
        b"0.1,0.2,0.3\n0.6,0.7,0.2\n0.2,0.3,0.9\n0.7,0.8,0.6\n",
    );
    assert_eq!(field(&json, "stratified_2d"), "false", "{json}");
    assert_eq!(field(&json, "unstratified_2d"), "[0,1]", "{json}");
}

#[test]
fn n_dimensional_input_errors_name_the_line() {
    for (args, input, expected) in [
        (
            &["--dimensions", "3"][..],
            &b"0.1,0.2\n"[..],
            "line 1, column 8: expected 3 numbers, got 2 fields",
        ),
        (
            &["--dimensions", "3"],
            b"0.1,0.2,1.5\n",
            "line 1, column 9: dimension 2 = 1.5 is outside [0, 1)",
        ),
        (
            &["--dimensions", "3"],
            b"a,b,c\n",
            "no points in the input (expected 3-number lines)",
        ),
        (&["--dimensions", "0"], b"", "at least 1 dimension"),
        (
            &["--dimensions", "3", "--strength", "5"],
            b"",
            "1 to 4 dimensions",
        ),
        (
            &["--dimensions", "3", "--levels", "0"],
            b"",
            "at least 1 level",
        ),
        (
            &["--levels", "4"],
            b"0.5,0.5\n",
            "--levels checks N-dimensional sets",
        ),
    ] {
        let (status, out, err) = run(args, input);
        assert_eq!((status, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(
            err.contains(expected),
            "{args:?}: {err:?} lacks {expected:?}"
        );
        assert_eq!(err.lines().count(), 1, "{err:?}");
    }
}

#[test]
fn lines_as_long_as_points_writes_are_read_at_every_dimension_count() {
    // `points --dimensions D | metrics --dimensions D` failed from D = 55,
    // where the lines pass 1,024 bytes; points writes up to 65,536.
    for d in ["55", "80", "1000", "65536"] {
        let csv = points_csv(&[
            "--sampler",
            "latin-hypercube",
            "--n",
            "4",
            "--dimensions",
            d,
        ]);
        let longest = csv.split(|&b| b == b'\n').map(<[u8]>::len).max();
        assert!(longest > Some(tool::MAX_LINE), "{d}: {longest:?}");
        let json = ok(&["--dimensions", d], &csv);
        assert_eq!(field(&json, "n"), "4", "{d}");
        assert_eq!(field(&json, "dimensions"), d);
        assert_eq!(field(&json, "is_latin"), "true", "{d}");
    }
}

#[test]
fn a_line_past_the_limit_names_the_dimension_count_it_was_given() {
    // The limit grows with --dimensions, 128 bytes a number; the message
    // asked for `x,y` whatever the count.
    assert_eq!(tool::line_limit(2), 1024);
    assert_eq!(tool::line_limit(80), 10_240);
    let long = "0.5,".repeat(3000);
    let (status, out, err) = run(&["--dimensions", "80"], long.as_bytes());
    assert_eq!((status, out.as_str()), (2, ""), "{err}");
    assert!(
        err.starts_with(
            "metrics: line 1, column 10241: a line of more than the 10240 bytes allowed; \
             expected 80 numbers, got `0.5,0.5,"
        ),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err:?}");
    // An endless line at the most dimensions stops at its 8 MiB limit.
    let mut endless = std::io::BufReader::new(std::io::repeat(b'0'));
    let mut rows = tool::Rows {
        dimensions: tool::MAX_DIMENSIONS,
        values: Vec::new(),
    };
    let result = tool::read_records(&mut endless, 0, tool::MAX_DIMENSIONS, &mut rows);
    let Err(tool::ReadError::Input(message)) = result else {
        panic!("{result:?}");
    };
    assert!(
        message.starts_with(
            "line 1, column 8388609: a line of more than the 8388608 bytes allowed; \
             expected 65536 numbers"
        ),
        "{message:.200}"
    );
    // More dimensions than points writes are refused, and --help says the
    // limit.
    let (status, _, err) = run(&["--dimensions", "65537"], b"");
    assert_eq!(status, 2, "{err}");
    assert!(
        err.contains("at most 65536 dimensions (the most points writes), got 65537"),
        "{err}"
    );
    let (_, help, _) = run(&["--help"], b"");
    assert!(help.contains("128 bytes per number"), "{help}");
}

#[test]
fn a_negative_grid_side_is_non_negative_not_an_unknown_flag() {
    // `--stratified -1x2` read as an unknown flag `-1`, where the other
    // tools say the value must be non-negative.
    for (args, expected) in [
        (&["--stratified", "-1x2"][..], "\"-1x2\""),
        (&["--stratified", "2x-2"], "\"2x-2\""),
        (&["--dimensions", "-3"], "\"-3\""),
    ] {
        let (status, out, err) = run(args, b"0.5,0.5\n");
        assert_eq!((status, out.as_str()), (2, ""), "{args:?}: {err}");
        assert_eq!(
            err,
            format!(
                "metrics: {} <{}>: the value must be non-negative, got {expected} (try --help)\n",
                args[0],
                if args[0] == "--stratified" {
                    "MxK"
                } else {
                    "D"
                }
            )
        );
    }
}
