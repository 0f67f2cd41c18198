//! `FilterKind` and `AnyFilter`: the filters by name, their default
//! parameters (pbrt-v4's), and `AnyFilter` giving the concrete filters'
//! values bit for bit. The serde round trip is
//! `filter_kinds_serialize_as_their_names` in `tests/samplers`, which the
//! CI's serde step runs.

use wellspread::Error;
use wellspread::filter::*;
use wellspread::glam::Vec2;

#[test]
fn every_name_parses_in_any_case() {
    for &kind in FilterKind::ALL {
        let name = kind.name();
        for spelling in [
            name.to_string(),
            name.to_uppercase(),
            name[..1].to_uppercase() + &name[1..],
            name.replace('-', "_"),
            name.replace('-', ""),
        ] {
            assert_eq!(spelling.parse::<FilterKind>(), Ok(kind), "{spelling}");
        }
    }
    assert_eq!("BlackmanHarris".parse(), Ok(FilterKind::BlackmanHarris));
}

#[test]
fn display_round_trips_through_parse_for_every_kind() {
    let mut names = Vec::new();
    for &kind in FilterKind::ALL {
        assert_eq!(kind.to_string(), kind.name());
        assert_eq!(kind.to_string().parse::<FilterKind>(), Ok(kind));
        assert_eq!(kind.build().kind(), kind);
        names.push(kind.name());
    }
    assert_eq!(
        names,
        [
            "box",
            "tent",
            "gaussian",
            "mitchell",
            "lanczos",
            "blackman-harris"
        ]
    );
}

#[test]
fn an_unknown_name_is_a_typed_error_listing_each_name_once() {
    let error = "sinc".parse::<FilterKind>().unwrap_err();
    let Error::UnknownFilter(unknown) = error else {
        panic!("{error:?}");
    };
    assert_eq!(unknown.as_str(), "sinc");
    let expected: Vec<&str> = FilterKind::ALL.iter().map(|kind| kind.name()).collect();
    assert_eq!(unknown.names().collect::<Vec<_>>(), expected);
    let message = error.to_string();
    assert!(
        message.starts_with("unknown filter \"sinc\"; expected one of: box tent"),
        "{message}"
    );
    for &kind in FilterKind::ALL {
        let listed = message
            .split([' ', ':', ';', '('])
            .filter(|word| *word == kind.name())
            .count();
        assert_eq!(listed, 1, "{kind}: {message}");
    }
    // One line, however the name is spelt; a long one is cut.
    let message = "tent\nbox".parse::<FilterKind>().unwrap_err().to_string();
    assert!(
        message.starts_with(r#"unknown filter "tent\nbox";"#),
        "{message}"
    );
    let message = "x"
        .repeat(500)
        .parse::<FilterKind>()
        .unwrap_err()
        .to_string();
    assert!(message.contains("xxx...\"; expected"), "{message}");
    assert!("".parse::<FilterKind>().is_err());
    assert!("gaussian ".parse::<FilterKind>().is_ok()); // separators are ignored
}

/// pbrt-v4's `Create` defaults (`src/pbrt/filters.cpp`): box `xradius`
/// 0.5; triangle 2; gaussian 1.5 with `sigma` 0.5; mitchell 2 with `B =
/// C = 1/3`; sinc (`LanczosSincFilter`) 4 with `tau` 3. pbrt-v4 has no
/// Blackman-Harris filter: its default radius is 2.
#[test]
fn the_defaults_are_pbrt_v4s() {
    assert_eq!(BoxFilter::default(), BoxFilter::new(0.5).unwrap());
    assert_eq!(TentFilter::default(), TentFilter::new(2.0).unwrap());
    assert_eq!(
        GaussianFilter::default(),
        GaussianFilter::new(1.5, 0.5).unwrap()
    );
    assert_eq!(
        MitchellFilter::default(),
        MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0).unwrap()
    );
    assert_eq!(
        LanczosFilter::default(),
        LanczosFilter::new(4.0, 3.0).unwrap()
    );
    assert_eq!(
        BlackmanHarrisFilter::default(),
        BlackmanHarrisFilter::new(2.0).unwrap()
    );
    let radii: Vec<f32> = FilterKind::ALL
        .iter()
        .map(|kind| kind.build().radius())
        .collect();
    assert_eq!(radii, [0.5, 2.0, 1.5, 2.0, 4.0, 2.0]);
}

/// The bits of everything a filter returns, at inputs across and outside
/// the square and the support.
fn fingerprint(filter: &dyn Filter) -> Vec<u64> {
    let mut bits = vec![
        u64::from(filter.radius().to_bits()),
        u64::from(filter.weight_magnitude().to_bits()),
        filter.weight_magnitude_1d().to_bits(),
    ];
    let r = filter.radius();
    for i in 0..500u32 {
        let u = Vec2::new((i as f32 * 0.618_034).fract(), i as f32 / 500.0);
        let s = filter.sample(u);
        let p = (u * 2.0 - 1.0) * 1.1 * r;
        let (x, w) = filter.sample_1d(u.x);
        bits.extend([
            u64::from(s.offset.x.to_bits()),
            u64::from(s.offset.y.to_bits()),
            u64::from(s.weight.to_bits()),
            u64::from(filter.evaluate(p).to_bits()),
            filter.evaluate_1d(f64::from(p.x)).to_bits(),
            x.to_bits(),
            w.to_bits(),
        ]);
    }
    for u in [f32::NAN, -1.0, 1.0, 2.0] {
        bits.push(u64::from(filter.sample(Vec2::splat(u)).offset.x.to_bits()));
    }
    bits
}

#[test]
fn build_gives_the_concrete_filters_values() {
    let concrete: [&dyn Filter; 6] = [
        &BoxFilter::new(0.5).unwrap(),
        &TentFilter::new(2.0).unwrap(),
        &GaussianFilter::new(1.5, 0.5).unwrap(),
        &MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0).unwrap(),
        &LanczosFilter::new(4.0, 3.0).unwrap(),
        &BlackmanHarrisFilter::new(2.0).unwrap(),
    ];
    for (&kind, filter) in FilterKind::ALL.iter().zip(concrete) {
        assert_eq!(fingerprint(&kind.build()), fingerprint(filter), "{kind}");
    }
    // Explicit parameters go through the checked constructors and `From`.
    let lanczos3 = LanczosFilter::new(3.0, 3.0).unwrap();
    let any = AnyFilter::from(lanczos3);
    assert_eq!(any.kind(), FilterKind::Lanczos);
    assert_eq!(fingerprint(&any), fingerprint(&lanczos3));
    assert_ne!(any, FilterKind::Lanczos.build());
    let catmull_rom = MitchellFilter::new(2.0, 0.0, 0.5).unwrap();
    assert_eq!(
        fingerprint(&AnyFilter::from(catmull_rom)),
        fingerprint(&catmull_rom)
    );
}
