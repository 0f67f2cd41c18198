//! Constructors, names and errors: what a caller sees before the first sample.

use wellspread::glam::Vec2;
use wellspread::{
    AnySampler, CorrelatedMultiJittered, Error, Halton, Hammersley, Jittered, MultiJittered,
    NRooks, Pmj02, Random, Regular, Sampler2D, SamplerKind, Sobol,
};

use crate::checks::*;
use crate::guarantees::guarantees;

#[test]
fn samplers_are_plain_values() {
    fn plain<T: Copy + Send + Sync + std::fmt::Debug + PartialEq>() {}
    plain::<Regular>();
    plain::<Random>();
    plain::<Jittered>();
    plain::<NRooks>();
    plain::<MultiJittered>();
    plain::<CorrelatedMultiJittered>();
    plain::<Hammersley>();
    plain::<Halton>();
    plain::<Sobol>();
    plain::<Pmj02>();
    plain::<AnySampler>();
}

/// One parser: `SamplerKind` takes any case, `-`, `_` or spaces, and the
/// aliases the README lists, as `PixelSamplerKind` does.
#[test]
fn kinds_parse_in_any_case_with_any_separator_and_by_alias() {
    for (name, kind) in [
        ("Sobol", SamplerKind::Sobol),
        ("CMJ", SamplerKind::CorrelatedMultiJittered),
        ("n_rooks", SamplerKind::NRooks),
        ("N Rooks", SamplerKind::NRooks),
        ("Multi-Jittered", SamplerKind::MultiJittered),
        ("multi-jittered ", SamplerKind::MultiJittered),
        ("cmj", SamplerKind::CorrelatedMultiJittered),
        ("mj", SamplerKind::MultiJittered),
        ("pmj", SamplerKind::Pmj02),
        ("rooks", SamplerKind::NRooks),
        ("stratified", SamplerKind::Jittered),
        ("white", SamplerKind::Random),
        ("BLUE_MULTI_JITTERED", SamplerKind::BlueMultiJittered),
    ] {
        assert_eq!(name.parse::<SamplerKind>(), Ok(kind), "{name:?}");
    }
    // The error lists the names and the aliases, from the one table.
    let message = "nope".parse::<SamplerKind>().unwrap_err().to_string();
    for expected in ["sobol", "n-rooks", "cmj", "stratified", "any case"] {
        assert!(message.contains(expected), "{message}");
    }
    assert!(!message.contains('\n'));
}

#[test]
fn kinds_round_trip_through_their_names() {
    for &kind in SamplerKind::ALL {
        assert_eq!(kind.name().parse::<SamplerKind>(), Ok(kind));
        assert_eq!(kind.to_string(), kind.name());
        assert_eq!(kind.build(9).unwrap().kind(), kind);
    }
    for bad in [
        "",
        "-",
        "jitter",
        "jitterd",
        "n-rook",
        "sobol2",
        "zsobol",
        "latin-hypercube",
        "lhs",
    ] {
        let Err(Error::UnknownSampler(unknown)) = bad.parse::<SamplerKind>() else {
            panic!("{bad:?} parsed");
        };
        assert_eq!(unknown.as_str(), bad);
        let message = Error::UnknownSampler(unknown).to_string();
        assert!(message.contains(&format!("\"{bad}\"")), "{message}");
        for &kind in SamplerKind::ALL {
            assert!(message.contains(kind.name()), "{message}");
        }
    }
    // A long input is kept to its first bytes, cut at a character
    // boundary, and the message says it was cut.
    let long = "é".repeat(30);
    let Err(Error::UnknownSampler(unknown)) = long.parse::<SamplerKind>() else {
        panic!("parsed");
    };
    assert!(unknown.is_truncated() && long.starts_with(unknown.as_str()));
    assert_eq!(unknown.as_str().len(), 40);
    assert!(
        Error::UnknownSampler(unknown)
            .to_string()
            .contains("é...\"")
    );
    let long = "x".repeat(10_000);
    let message = long.parse::<SamplerKind>().unwrap_err().to_string();
    let quoted = &message[..message.find(';').unwrap()];
    assert_eq!(quoted, format!("unknown sampler \"{}...\"", &long[..40]));
    // Escaped: a newline or a quote in the name keeps the message one line.
    let message = "jit\ntered\""
        .parse::<SamplerKind>()
        .unwrap_err()
        .to_string();
    assert!(!message.contains('\n'), "{message}");
    assert!(
        message.starts_with(r#"unknown sampler "jit\ntered\""; expected"#),
        "{message}"
    );
}

/// Every name an error message lists, each exactly once, and each one
/// parses: the padded 2D Latin hypercube is `n-rooks` (alias `rooks`),
/// `latin-hypercube` (alias `lhs`) is the N-dimensional pixel sampler.
#[test]
fn every_error_lists_each_name_once_and_each_parses() {
    use wellspread::PixelSamplerKind;
    let Err(Error::UnknownSampler(unknown)) = "nope".parse::<SamplerKind>() else {
        panic!("parsed");
    };
    let names: Vec<_> = unknown.names().collect();
    assert_eq!(
        names,
        [
            "regular",
            "random",
            "jittered",
            "n-rooks",
            "multi-jittered",
            "correlated-multi-jittered",
            "blue-multi-jittered",
            "hammersley",
            "halton",
            "sobol",
            "pmj02",
            "cmj",
            "mj",
            "pmj",
            "rooks",
            "stratified",
            "white"
        ]
    );
    for name in &names {
        assert!(name.parse::<SamplerKind>().is_ok(), "{name}");
    }
    let Err(Error::UnknownPixelSampler(unknown)) = "nope".parse::<PixelSamplerKind>() else {
        panic!("parsed");
    };
    let pixel_names: Vec<_> = unknown.names().collect();
    for name in &pixel_names {
        assert!(name.parse::<PixelSamplerKind>().is_ok(), "{name}");
    }
    let message = Error::UnknownPixelSampler(unknown).to_string();
    for list in [&names, &pixel_names] {
        let mut sorted = list.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), list.len(), "{list:?}");
    }
    for name in &pixel_names {
        let words = message
            .split([' ', ',', ')', ':'])
            .filter(|word| word == name)
            .count();
        assert_eq!(words, 1, "{name} in {message}");
    }
    assert_eq!(
        pixel_names.len(),
        PixelSamplerKind::ALL.len() + names.len() - SamplerKind::ALL.len() + 1
    );
    for name in ["latin-hypercube", "LHS", "Latin_Hypercube"] {
        assert_eq!(
            name.parse::<PixelSamplerKind>(),
            Ok(PixelSamplerKind::LatinHypercube)
        );
    }
    for name in ["n-rooks", "rooks"] {
        assert_eq!(
            name.parse::<PixelSamplerKind>(),
            Ok(PixelSamplerKind::Padded(SamplerKind::NRooks))
        );
    }
}

#[test]
fn any_sampler_is_eq_and_hash() {
    let set: std::collections::HashSet<AnySampler> = SamplerKind::ALL
        .iter()
        .flat_map(|kind| {
            [
                kind.build(16).unwrap(),
                kind.build(16).unwrap(),
                kind.build(25).unwrap(),
            ]
        })
        .collect();
    assert_eq!(set.len(), 2 * SamplerKind::ALL.len());
}

/// Every kind of `all` serializes as its name and back; `unknown` fails
/// with `message`, and a number is refused.
#[cfg(feature = "serde")]
fn serialize_as_names<T>(all: &[T], unknown: &str, message: &str)
where
    T: serde::Serialize + serde::de::DeserializeOwned + PartialEq + std::fmt::Debug + ToString,
{
    for kind in all {
        let json = serde_json::to_string(kind).unwrap();
        assert_eq!(json, format!("\"{}\"", kind.to_string()));
        assert_eq!(&serde_json::from_str::<T>(&json).unwrap(), kind);
    }
    let error = serde_json::from_str::<T>(unknown).unwrap_err();
    assert!(error.to_string().contains(message), "{error}");
    assert!(serde_json::from_str::<T>("3").is_err());
}

#[cfg(feature = "serde")]
#[test]
fn kinds_serialize_as_their_names() {
    serialize_as_names(SamplerKind::ALL, "\"sobel\"", "unknown sampler \"sobel\"");
}

/// Here rather than in `tests/filter_kind.rs` so that the CI's serde step
/// (`--test samplers -- kinds_serialize`) runs it.
#[cfg(feature = "serde")]
#[test]
fn filter_kinds_serialize_as_their_names() {
    use wellspread::filter::FilterKind;
    serialize_as_names(FilterKind::ALL, "\"sinc\"", "unknown filter \"sinc\"");
    assert_eq!(
        serde_json::from_str::<FilterKind>("\"Blackman-Harris\"").unwrap(),
        FilterKind::BlackmanHarris
    );
}

/// Pixel samplers in settings files too: every kind as its name, aliases
/// and any case accepted, an unknown name the parser's error.
#[cfg(feature = "serde")]
#[test]
fn pixel_sampler_kinds_serialize_as_their_names() {
    use wellspread::PixelSamplerKind;
    let all: Vec<PixelSamplerKind> = PixelSamplerKind::all().collect();
    serialize_as_names(&all, "\"zsobl\"", "unknown pixel sampler \"zsobl\"");
    assert_eq!(
        serde_json::from_str::<PixelSamplerKind>("\"LHS\"").unwrap(),
        PixelSamplerKind::LatinHypercube
    );
}

// ---- Constructors and errors ----

#[test]
fn zero_samples_is_an_error() {
    for &kind in SamplerKind::ALL {
        assert_eq!(kind.build(0), Err(Error::ZeroSamples), "{kind}");
    }
    assert_eq!(Regular::new(0), Err(Error::ZeroSamples));
    assert_eq!(Random::new(0), Err(Error::ZeroSamples));
    assert_eq!(Jittered::new(0), Err(Error::ZeroSamples));
    assert_eq!(NRooks::new(0), Err(Error::ZeroSamples));
    assert_eq!(MultiJittered::new(0), Err(Error::ZeroSamples));
    assert_eq!(CorrelatedMultiJittered::new(0), Err(Error::ZeroSamples));
}

#[test]
fn above_the_largest_n_is_an_error() {
    for &kind in SamplerKind::ALL {
        let max = guarantees(kind).max_n;
        let largest = kind.build(max);
        assert!(largest.is_ok(), "{kind} rejects its own max {max}");
        assert_eq!(largest.unwrap().len(), max, "{kind}");
        if max < u32::MAX {
            for n in [max + 1, u32::MAX] {
                match kind.build(n) {
                    Err(Error::TooManySamples {
                        sampler,
                        requested,
                        max: m,
                        ..
                    }) => {
                        assert_eq!(sampler, kind.name());
                        assert_eq!(requested, n as u64);
                        assert_eq!(m, max as u64);
                    }
                    other => panic!("{kind} n = {n}: {other:?}"),
                }
            }
        }
    }
    for n in [(1 << 24) + 1, u32::MAX] {
        assert!(matches!(NRooks::new(n), Err(Error::TooManySamples { .. })));
        assert!(matches!(
            MultiJittered::new(n),
            Err(Error::TooManySamples { .. })
        ));
        assert!(matches!(
            CorrelatedMultiJittered::new(n),
            Err(Error::TooManySamples { .. })
        ));
    }
}

#[test]
fn grids_with_a_side_above_2_pow_24_are_errors() {
    // Primes above 2^24 (and twice one) have only 1 x n or 2 x n/2 grids.
    for n in [16_777_259, 2 * 16_777_259, u32::MAX - 4] {
        for result in [Regular::new(n).map(|_| ()), Jittered::new(n).map(|_| ())] {
            assert!(
                matches!(result, Err(Error::GridTooFine { columns, rows, .. }) if columns as u64 * rows as u64 == n as u64),
                "n = {n}: {result:?}"
            );
        }
        assert!(Random::new(n).is_ok());
    }
    // Composite n above 2^24 with a squarer grid are fine.
    assert!(Regular::new((1 << 24) + 1).is_ok());
    assert!(Jittered::new(1 << 30).is_ok());
}

#[test]
fn with_grid_checks_both_sides() {
    for (columns, rows) in [(0, 5), (5, 0), (0, 0)] {
        assert_eq!(
            Regular::with_grid(columns, rows),
            Err(Error::ZeroGridSide { columns, rows })
        );
        assert_eq!(
            Jittered::with_grid(columns, rows),
            Err(Error::ZeroGridSide { columns, rows })
        );
    }
    for (columns, rows) in [
        (1 << 24 | 1, 1),
        (1, 1 << 24 | 1),
        (65_536, 65_536),
        (1 << 24, 256),
    ] {
        // A side above 2^24 is too fine for f32; 2^32 cells too many for u32.
        let expected = |result: Result<(), Error>| match result {
            Err(Error::GridTooFine { .. }) => columns > 1 << 24 || rows > 1 << 24,
            Err(Error::TooManySamples { .. }) => columns as u64 * rows as u64 > u32::MAX as u64,
            _ => false,
        };
        assert!(expected(Regular::with_grid(columns, rows).map(|_| ())));
        assert!(expected(Jittered::with_grid(columns, rows).map(|_| ())));
    }
    for (columns, rows) in [
        (1, 1),
        (3, 2),
        (1 << 24, 1),
        (1, 1 << 24),
        (1 << 24, 255),
        (65_535, 65_537),
    ] {
        let regular = Regular::with_grid(columns, rows).unwrap();
        assert_eq!(
            (regular.columns(), regular.rows(), regular.len()),
            (columns, rows, columns * rows)
        );
        let jittered = Jittered::with_grid(columns, rows).unwrap();
        assert_eq!((jittered.columns(), jittered.rows()), (columns, rows));
    }
    // A wide grid keeps its shape: columns > rows is allowed here.
    let wide = Jittered::with_grid(7, 2).unwrap();
    let mut cells = Occupancy::new(14);
    for i in 0..14 {
        let p = wide.sample(i, 3);
        assert!(cells.insert(stratum(p.y, 2) * 7 + stratum(p.x, 7)));
    }
}

#[test]
fn error_messages_say_what_is_wrong() {
    let zero = Error::ZeroSamples.to_string();
    assert!(
        zero.contains("at least one sample") && zero.contains("n = 0"),
        "{zero}"
    );
    let side = Error::ZeroGridSide {
        columns: 0,
        rows: 5,
    }
    .to_string();
    assert!(side.contains("0 x 5") && side.contains("column"), "{side}");
    let too_many = NRooks::new(20_000_000).unwrap_err().to_string();
    for part in ["n-rooks", "16777216", "20000000", "f32"] {
        assert!(too_many.contains(part), "{too_many:?} lacks {part:?}");
    }
    let prime = Jittered::new(16_777_259).unwrap_err().to_string();
    for part in ["jittered", "16777259", "2^24"] {
        assert!(prime.contains(part), "{prime:?} lacks {part:?}");
    }
    let cells = Regular::with_grid(65_536, 65_536).unwrap_err().to_string();
    for part in ["regular", "4294967296", "4294967295"] {
        assert!(cells.contains(part), "{cells:?} lacks {part:?}");
    }
}

#[test]
#[should_panic(expected = "fill asked for 17 samples of a set of 16")]
fn fill_past_the_end_panics() {
    let mut out = [Vec2::ZERO; 17];
    CorrelatedMultiJittered::new(16).unwrap().fill(0, &mut out);
}

#[test]
fn every_sampler_panics_on_fill_past_the_end() {
    for &kind in SamplerKind::ALL {
        for n in [1, 16, 100] {
            let sampler = kind.build(n).unwrap();
            let result = std::panic::catch_unwind(|| {
                let mut out = vec![Vec2::ZERO; n as usize + 1];
                sampler.fill(5, &mut out);
            });
            assert!(result.is_err(), "{kind} n = {n}: fill wrote past the end");
        }
    }
}

/// Release builds only (debug builds assert): an index past the end still
/// terminates with a point in the square.
#[cfg(not(debug_assertions))]
#[test]
fn out_of_range_index_in_release_is_a_point() {
    for &kind in SamplerKind::ALL {
        for n in [1, 3, 5, 16, 100] {
            let sampler = kind.build(n).unwrap();
            for index in (n..4 * n).chain([u32::MAX]) {
                for pattern in 0..64 {
                    let p = sampler.sample(index, pattern);
                    assert!(in_unit_square(p), "{kind} n = {n} index {index}: {p:?}");
                }
            }
        }
    }
}
