//! Latin, stratification and net checks, and the t-value against a brute
//! force count of elementary intervals.

use proptest::prelude::*;
use wellspread::Error;
use wellspread::glam::Vec2;
use wellspread::metrics::{is_latin, is_net_base2, is_stratified, net_t_value};
use wellspread::{Pmj02, Sampler2D, Sobol};

use crate::common::{hammersley, random_points};

#[test]
fn stratification_checks() {
    // Hammersley sets are (0, m, 2)-nets, hence Latin and stratified.
    for m in 0..=12 {
        let points = hammersley(m);
        assert!(is_net_base2(&points).unwrap(), "m = {m}");
        assert!(is_latin(&points).unwrap());
        assert!(is_stratified(&points, 1 << (m / 2), 1 << (m - m / 2)).unwrap());
    }
    // Swapping two y values of a net breaks it.
    let mut broken = hammersley(6);
    let (a, b) = (broken[1].y, broken[2].y);
    broken[1].y = b;
    broken[2].y = a;
    assert!(is_latin(&broken).unwrap());
    assert!(!is_net_base2(&broken).unwrap());
    // The centre of each cell of a 3 x 5 grid: stratified on 3 x 5, not 5 x 3.
    let grid: Vec<Vec2> = (0..15)
        .map(|i| Vec2::new(((i % 3) as f32 + 0.5) / 3.0, ((i / 3) as f32 + 0.5) / 5.0))
        .collect();
    assert!(is_stratified(&grid, 3, 5).unwrap());
    assert!(!is_stratified(&grid, 5, 3).unwrap());
    assert!(is_stratified(&grid, 1, 5).unwrap());
    assert!(is_stratified(&grid, 3, 1).unwrap());
    assert!(!is_latin(&grid).unwrap());
    // Two points per cell.
    let doubled: Vec<Vec2> = grid.iter().chain(grid.iter()).copied().collect();
    assert!(is_stratified(&doubled, 3, 5).unwrap());
    // A point on a cell's left edge is in that cell.
    let edges: Vec<Vec2> = (0..16)
        .map(|i| Vec2::new(i as f32 / 16.0, (15 - i) as f32 / 16.0))
        .collect();
    assert!(is_latin(&edges).unwrap());
    // Cells come from the exact f32 values: 0.6f32 is just above 6/10 and
    // 0.7f32 just below 7/10 (as is 0.9f32 below 9/10), so 0.6 and 0.7 share
    // column 6 and the tenths are not Latin.
    let tenths: Vec<Vec2> = (0..10)
        .map(|i| Vec2::new(i as f32 / 10.0, (i as f32 + 0.5) / 10.0))
        .collect();
    assert!(!is_latin(&tenths).unwrap());
    let mut fixed = tenths.clone();
    fixed[7].x = f32::from_bits(0.7f32.to_bits() + 1);
    fixed[9].x = f32::from_bits(0.9f32.to_bits() + 1);
    assert!(is_latin(&fixed).unwrap());
    // Errors.
    assert!(matches!(
        is_stratified(&grid, 0, 5),
        Err(Error::ZeroGridSide { .. })
    ));
    assert!(matches!(
        is_stratified(&grid, 2, 5),
        Err(Error::GridDoesNotDivide { n: 15, .. })
    ));
    assert!(matches!(
        is_stratified(&grid, u32::MAX, u32::MAX),
        Err(Error::GridDoesNotDivide { .. })
    ));
    assert!(matches!(
        is_net_base2(&grid),
        Err(Error::NotPowerOfTwo { n: 15 })
    ));
}

/// The smallest t for which every elementary interval of area 2^(t-m) holds
/// 2^t points, by counting each interval over all points with f64
/// comparisons (scaling by a power of two is exact).
fn brute_t_value(points: &[Vec2]) -> u32 {
    let n = points.len();
    let m = n.trailing_zeros();
    'next_t: for t in 0..=m {
        for a in 0..=m - t {
            let b = m - t - a;
            for i in 0..1u64 << a {
                for j in 0..1u64 << b {
                    let inside = points
                        .iter()
                        .filter(|p| {
                            let (x, y) = (
                                f64::from(p.x) * (1u64 << a) as f64,
                                f64::from(p.y) * (1u64 << b) as f64,
                            );
                            x.floor() as u64 == i && y.floor() as u64 == j
                        })
                        .count();
                    if inside != 1 << t {
                        continue 'next_t;
                    }
                }
            }
        }
        return t;
    }
    unreachable!("every set of 2^m points is an (m, m, 2)-net")
}

#[test]
fn t_value_of_sobol_and_pmj02_prefixes_is_zero() {
    let n = 1u32 << 14;
    let mut points = vec![Vec2::ZERO; n as usize];
    for pattern in [0u32, 1, 77, 0xdead_beef] {
        Sobol::new(n).unwrap().fill(pattern, &mut points);
        for m in 0..=14 {
            assert_eq!(
                net_t_value(&points[..1 << m]).unwrap(),
                0,
                "sobol {pattern} 2^{m}"
            );
        }
        Pmj02::new(n).unwrap().fill(pattern, &mut points);
        for m in 0..=14 {
            assert_eq!(
                net_t_value(&points[..1 << m]).unwrap(),
                0,
                "pmj02 {pattern} 2^{m}"
            );
        }
    }
}

#[test]
fn t_value_of_constructed_sets() {
    // A 2^a x 2^b grid of cell corners: intervals of shape (c, d) hold equal
    // counts exactly when c <= a and d <= b, so t = m - min(a, b) = max(a, b).
    for (a, b) in [(0, 0), (1, 0), (0, 3), (2, 2), (3, 5), (6, 6), (1, 9)] {
        let grid: Vec<Vec2> = (0..1u32 << (a + b))
            .map(|i| {
                Vec2::new(
                    (i % (1 << a)) as f32 / (1u32 << a) as f32,
                    (i >> a) as f32 / (1u32 << b) as f32,
                )
            })
            .collect();
        assert_eq!(net_t_value(&grid).unwrap(), a.max(b), "{a} x {b} grid");
    }
    // Two copies of a (0, m - 1, 2)-net are a (1, m, 2)-net and no better.
    for m in 1..=12 {
        let half = hammersley(m - 1);
        let twice: Vec<Vec2> = half.iter().chain(&half).copied().collect();
        assert_eq!(net_t_value(&twice).unwrap(), 1, "m = {m}");
        assert_eq!(net_t_value(&hammersley(m)).unwrap(), 0);
    }
    // n identical points: only the unit square holds them all.
    for m in 0..=10 {
        let same = vec![Vec2::new(0.3, 0.6); 1 << m];
        assert_eq!(net_t_value(&same).unwrap(), m);
    }
    // Moving one point of a Hammersley set out of its column breaks t = 0;
    // the brute force says by how much.
    let mut moved = hammersley(6);
    moved[5].x = 0.999;
    assert_eq!(net_t_value(&moved).unwrap(), brute_t_value(&moved));
    assert!(net_t_value(&moved).unwrap() > 0);
}

#[test]
fn t_value_needs_a_power_of_two() {
    for n in [3usize, 6, 100, 1000] {
        assert_eq!(
            net_t_value(&random_points(n, 3)),
            Err(Error::NotPowerOfTwo { n })
        );
    }
    assert_eq!(net_t_value(&[]), Err(Error::EmptyPointSet));
}

/// Points on the 2^-bits grid, so small sets are often nets of some small t.
fn dyadic_set(log2_n: u32, bits: u32) -> impl Strategy<Value = Vec<Vec2>> {
    let coord = (0u32..1 << bits).prop_map(move |i| i as f32 / (1u32 << bits) as f32);
    prop::collection::vec((coord.clone(), coord), 1 << log2_n)
        .prop_map(|v| v.into_iter().map(|(x, y)| Vec2::new(x, y)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn t_value_matches_brute_force(
        points in (0u32..=6, 1u32..=7).prop_flat_map(|(m, bits)| dyadic_set(m, bits)),
    ) {
        prop_assert_eq!(net_t_value(&points).unwrap(), brute_t_value(&points));
    }

    #[test]
    fn t_value_of_scrambled_nets_matches_brute_force(pattern in any::<u32>(), m in 0u32..=7) {
        let mut points = vec![Vec2::ZERO; 1 << m];
        Sobol::new(1 << m).unwrap().fill(pattern, &mut points);
        // Swap the x of two points: usually no longer a (0, m, 2)-net.
        let last = points.len() - 1;
        let x0 = points[0].x;
        points[0].x = points[last].x;
        points[last].x = x0;
        points[0].y = points[last / 2].y;
        prop_assert_eq!(net_t_value(&points).unwrap(), brute_t_value(&points));
    }
}
