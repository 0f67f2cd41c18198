//! Every metric on hostile input: the typed error naming the first bad
//! point, never a panic.

use proptest::prelude::*;
use wellspread::Error;
use wellspread::glam::Vec2;
use wellspread::metrics::{
    centered_l2_discrepancy, is_latin, is_net_base2, is_stratified, l2_star_discrepancy,
    min_distance, net_t_value, normalized_toroidal_min_distance, radial_power_spectrum,
    star_discrepancy, toroidal_min_distance, wraparound_l2_discrepancy,
};

fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(1.0f32),
        Just(-0.0f32),
        Just(0.0f32),
        Just(f32::MIN_POSITIVE),
        Just(f32::from_bits(1)),
        Just(f32::from_bits(0x3f7f_ffff)),
        Just(-f32::from_bits(1)),
        any::<f32>(),
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
    ]
}

/// The error each metric must return, or None when the set is valid.
fn expected_error(points: &[Vec2]) -> Option<Error> {
    if points.is_empty() {
        return Some(Error::EmptyPointSet);
    }
    for (index, p) in points.iter().enumerate() {
        if !p.x.is_finite() || !p.y.is_finite() {
            return Some(Error::NonFinitePoint {
                index,
                x: p.x,
                y: p.y,
            });
        }
        if !(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0) {
            return Some(Error::PointOutOfRange {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    None
}

fn same_error(got: &Error, want: &Error) -> bool {
    match (got, want) {
        (Error::NonFinitePoint { index: a, .. }, Error::NonFinitePoint { index: b, .. })
        | (Error::PointOutOfRange { index: a, .. }, Error::PointOutOfRange { index: b, .. }) => {
            a == b
        }
        _ => got == want,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn hostile_input_never_panics(
        coords in prop::collection::vec((any_f32(), any_f32()), 0..24),
        columns in 0u32..5,
        rows in 0u32..5,
    ) {
        let points: Vec<Vec2> = coords.iter().map(|&(x, y)| Vec2::new(x, y)).collect();
        let want = expected_error(&points);
        let check = |name: &str, got: Result<(), Error>, want: Option<Error>| {
            match (&got, &want) {
                (Ok(()), None) => Ok(()),
                (Err(g), Some(w)) if same_error(g, w) => Ok(()),
                _ => Err(TestCaseError::fail(format!("{name}: got {got:?}, want {want:?}"))),
            }
        };
        let f = |r: Result<f64, Error>| r.map(|v| assert!(v.is_finite() && v >= 0.0));
        let b = |r: Result<bool, Error>| r.map(|_| ());
        check("star", f(star_discrepancy(&points)), want)?;
        check("l2", f(l2_star_discrepancy(&points)), want)?;
        check("cd", f(centered_l2_discrepancy(&points)), want)?;
        check("wd", f(wraparound_l2_discrepancy(&points)), want)?;
        check("latin", b(is_latin(&points)), want)?;
        let too_few = (want.is_none() && points.len() < 2).then_some(());
        for (name, r) in [
            ("min", min_distance(&points)),
            ("torus", toroidal_min_distance(&points)),
            ("normalised", normalized_toroidal_min_distance(&points)),
        ] {
            if too_few.is_some() {
                prop_assert!(matches!(r, Err(Error::TooFewPoints { needed: 2, got: 1, .. })), "{name}");
            } else {
                check(name, f(r), want)?;
            }
        }
        let net_want = want.or_else(|| {
            (!points.len().is_power_of_two()).then_some(Error::NotPowerOfTwo { n: points.len() })
        });
        check("net", b(is_net_base2(&points)), net_want)?;
        check("t", net_t_value(&points).map(|t| assert!(1usize << t <= points.len())), net_want)?;
        let spectrum = radial_power_spectrum(&points, 3)
            .map(|s| assert!(s.len() == 3 && s.iter().all(|p| p.is_finite() && *p >= 0.0)));
        check("spectrum", spectrum, want)?;
        let strat_want = if columns == 0 || rows == 0 {
            Some(Error::ZeroGridSide { columns, rows })
        } else {
            want.or_else(|| {
                (!points.len().is_multiple_of((columns * rows) as usize)).then_some(Error::GridDoesNotDivide {
                    columns,
                    rows,
                    n: points.len(),
                })
            })
        };
        check("stratified", b(is_stratified(&points, columns, rows)), strat_want)?;
    }
}

#[test]
fn error_messages_name_the_point() {
    let points = [Vec2::new(0.5, 0.5), Vec2::new(1.0, 0.25)];
    let err = star_discrepancy(&points).unwrap_err();
    assert!(matches!(err, Error::PointOutOfRange { index: 1, .. }));
    let msg = err.to_string();
    assert!(
        msg.contains("point 1") && msg.contains("(1, 0.25)"),
        "{msg}"
    );
    let err = min_distance(&[Vec2::new(0.5, f32::NAN)]).unwrap_err();
    assert!(matches!(err, Error::NonFinitePoint { index: 0, .. }));
    assert!(matches!(
        l2_star_discrepancy(&[]),
        Err(Error::EmptyPointSet)
    ));
    // -0.0 is 0.0.
    let neg = [Vec2::new(-0.0, 0.5), Vec2::new(0.5, -0.0)];
    let pos = [Vec2::new(0.0, 0.5), Vec2::new(0.5, 0.0)];
    assert_eq!(
        star_discrepancy(&neg).unwrap(),
        star_discrepancy(&pos).unwrap()
    );
    assert_eq!(
        l2_star_discrepancy(&neg).unwrap(),
        l2_star_discrepancy(&pos).unwrap()
    );
    assert_eq!(min_distance(&neg).unwrap(), min_distance(&pos).unwrap());
    assert!(is_latin(&neg).unwrap());
}
