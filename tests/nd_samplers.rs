//! The N-dimensional point sets ([`LatinHypercube`], [`OrthogonalArray`], [`Faure4D`],
//! [`Sobol4D`]) through [`SamplerNd`]: range, `sample == coordinate`, and the
//! stratification of every projection, checked exactly on the f32 values
//! over many sizes, dimension counts, offsets and patterns (0 and
//! `u32::MAX` included).

use wellspread::glam::Vec2;
use wellspread::metrics::is_net_base2;
use wellspread::{
    Error, Faure4D, LatinHypercube, OrthogonalArray, OrthogonalArrayOffset, SamplerNd, Sobol4D,
};

const PATTERNS: [u32; 4] = [0, 1, 0xdead_beef, u32::MAX];

const OFFSETS: [OrthogonalArrayOffset; 3] = [
    OrthogonalArrayOffset::Jittered,
    OrthogonalArrayOffset::MultiJittered,
    OrthogonalArrayOffset::CorrelatedMultiJittered,
];

/// Every point of pattern `pattern`, `dimensions()` coordinates each, in
/// one flat vector; checks that each is in `[0, 1)` and equals what
/// `coordinate` gives.
fn points(sampler: &impl SamplerNd, pattern: u32) -> Vec<f32> {
    let d = sampler.dimensions() as usize;
    let mut out = vec![f32::NAN; sampler.len() as usize * d];
    for (index, point) in (0..).zip(out.chunks_exact_mut(d)) {
        sampler.sample(index, pattern, point);
        for (dimension, &x) in (0..).zip(point.iter()) {
            assert!(
                (0.0..1.0).contains(&x),
                "index {index} dimension {dimension}: {x}"
            );
            // Spot-check `coordinate` and the runs `coordinates` gives
            // from this dimension (all of it for small sets).
            if index < 64 || index % 97 == 0 {
                let alone = sampler.coordinate(index, pattern, dimension);
                assert_eq!(
                    alone.to_bits(),
                    x.to_bits(),
                    "index {index} dimension {dimension}"
                );
                let run = &point[dimension as usize..(dimension as usize + 4).min(d)];
                let mut from = vec![f32::NAN; run.len()];
                sampler.coordinates(index, pattern, dimension, &mut from);
                assert_eq!(from, run, "index {index} coordinates from {dimension}");
            }
        }
    }
    out
}

/// The stratum of `x` among `strata` equal strata of `[0, 1)`, exactly:
/// `x` is a multiple of 2^-24 and `strata <= 2^24`, so the f64 product is
/// exact.
fn stratum(x: f32, strata: u32) -> u32 {
    (f64::from(x) * f64::from(strata)).floor() as u32
}

/// Whether every one of the `strata` strata of dimension `dimension` holds
/// exactly `n / strata` points.
fn assert_1d(points: &[f32], d: usize, dimension: usize, strata: u32, what: &str) {
    let n = points.len() / d;
    let mut counts = vec![0u32; strata as usize];
    for point in points.chunks_exact(d) {
        counts[stratum(point[dimension], strata) as usize] += 1;
    }
    let each = (n / strata as usize) as u32;
    if let Some(bad) = counts.iter().position(|&c| c != each) {
        panic!(
            "{what}: dimension {dimension}, stratum {bad} of {strata} holds {} points, not {each}",
            counts[bad]
        );
    }
}

/// Every set of `k` distinct dimensions below `d`, as increasing tuples.
fn subsets(d: usize, k: usize) -> Vec<Vec<usize>> {
    let mut all = Vec::new();
    let mut pick: Vec<usize> = (0..k).collect();
    if k > d {
        return all;
    }
    loop {
        all.push(pick.clone());
        let Some(i) = (0..k).rev().find(|&i| pick[i] < d - k + i) else {
            return all;
        };
        pick[i] += 1;
        for j in i + 1..k {
            pick[j] = pick[j - 1] + 1;
        }
    }
}

/// Whether the projection onto `dims` is stratified into `q^len` cells
/// with the same number of points in each.
fn assert_projection(points: &[f32], d: usize, dims: &[usize], q: u32, what: &str) {
    let n = points.len() / d;
    let cells = (q as usize).pow(dims.len() as u32);
    let each = (n / cells) as u32;
    let mut counts = vec![0u32; cells];
    for point in points.chunks_exact(d) {
        let cell = dims.iter().fold(0usize, |cell, &j| {
            cell * q as usize + stratum(point[j], q) as usize
        });
        counts[cell] += 1;
    }
    if let Some(bad) = counts.iter().position(|&c| c != each) {
        panic!(
            "{what}: projection {dims:?}, cell {bad} of {cells} holds {} points, not {each}",
            counts[bad]
        );
    }
}

#[test]
fn latin_hypercubes_are_latin_in_every_dimension() {
    for n in [
        1, 2, 3, 5, 7, 8, 9, 16, 24, 97, 100, 256, 1000, 4093, 4097, 65_537,
    ] {
        for d in [1, 2, 5, 33] {
            let cube = LatinHypercube::new(n, d).unwrap();
            assert_eq!((cube.len(), cube.dimensions()), (n, d));
            for pattern in PATTERNS {
                let points = points(&cube, pattern);
                for dimension in 0..d as usize {
                    let what = format!("latin hypercube n {n} d {d} pattern {pattern:#x}");
                    assert_1d(&points, d as usize, dimension, n, &what);
                }
            }
        }
    }
}

#[test]
fn latin_hypercubes_are_latin_at_the_largest_counts() {
    // 2^24 (the limit) and the prime just below it, where 2^24 / n is not
    // an integer: every one of the n strata of [0, 1) holds one f32 value
    // (one dimension each, for time: every dimension runs the same code).
    for (n, dimension) in [(1 << 24, 0), (16_777_213, 1)] {
        let cube = LatinHypercube::new(n, 2).unwrap();
        let mut seen = vec![false; n as usize];
        for index in 0..n {
            let x = cube.coordinate(index, u32::MAX, dimension);
            let s = stratum(x, n) as usize;
            assert!(!seen[s], "n {n} dimension {dimension}: stratum {s} twice");
            seen[s] = true;
        }
    }
}

#[test]
fn latin_hypercube_dimensions_are_independent_permutations() {
    // Two dimensions of one pattern, and one dimension of two patterns,
    // are not the same permutation (they would be with a shared key).
    let cube = LatinHypercube::new(64, 3).unwrap();
    let column = |pattern: u32, dimension: u32| -> Vec<u32> {
        (0..64)
            .map(|i| stratum(cube.coordinate(i, pattern, dimension), 64))
            .collect()
    };
    assert_ne!(column(5, 0), column(5, 1));
    assert_ne!(column(5, 1), column(5, 2));
    assert_ne!(column(5, 0), column(6, 0));
}

/// The prime-power counts `q^t` the array tests run at: every prime and
/// prime power `q` with `q^t` at most `max_n`.
fn array_sizes(t: u32, max_n: u32) -> Vec<(u32, u32)> {
    (2u32..)
        .map(|q| (q, q.pow(t)))
        .take_while(|&(_, n)| n <= max_n)
        .filter(|&(q, _)| {
            let p = (2..=q).find(|p| q % p == 0).unwrap();
            let mut rest = q;
            while rest % p == 0 {
                rest /= p;
            }
            rest == 1
        })
        .collect()
}

#[test]
fn orthogonal_arrays_stratify_every_t_dimensional_projection() {
    // Strength 2 to 4, every prime and prime power q up to a few thousand
    // points, dimension counts 1, t and q + 1 (and 12 for large q), every
    // offset, four patterns: every t-subset of the dimensions is
    // stratified into q^t cells; with fewer than t dimensions, the whole
    // projection into q^d cells of q^(t - d) points each. The multi-jittered
    // offsets are also Latin (n strata per dimension) and the jittered ones
    // stratified into q strata.
    let mut checked = 0u64;
    for (t, max_n) in [(2, 4096), (3, 4096), (4, 4096)] {
        for (q, n) in array_sizes(t, max_n) {
            let mut dimension_counts = vec![1, t.min(q + 1), (q + 1).min(12), q + 1];
            dimension_counts.dedup();
            for d in dimension_counts {
                for offset in OFFSETS {
                    let array = OrthogonalArray::new(n, d, t).unwrap().with_offset(offset);
                    assert_eq!((array.len(), array.levels(), array.strength()), (n, q, t));
                    for pattern in PATTERNS {
                        let what =
                            format!("array n {n} = {q}^{t} d {d} {offset:?} pattern {pattern:#x}");
                        let points = points(&array, pattern);
                        let d = d as usize;
                        // Large q at q + 1 dimensions: the first 12 only.
                        let projected = d.min(12);
                        for dims in subsets(projected, (t as usize).min(projected)) {
                            assert_projection(&points, d, &dims, q, &what);
                            checked += 1;
                        }
                        for dimension in 0..d {
                            let strata = match offset {
                                OrthogonalArrayOffset::Jittered => q,
                                _ => n,
                            };
                            assert_1d(&points, d, dimension, strata, &what);
                        }
                    }
                }
            }
        }
    }
    // So that a filter bug cannot pass the test vacuously.
    assert!(checked > 10_000, "{checked} projections");
}

#[test]
fn power_of_two_arrays_at_renderer_counts() {
    // 16 = 4^2, 64 = 8^2 (and 4^3), 256 = 16^2 (and 4^4), 1024 = 32^2,
    // 4096 = 64^2 (and 16^3, 8^4): all their dimensions, all 2D (or t-D)
    // projections, Latin in 1D.
    for (n, t) in [
        (16, 2),
        (64, 2),
        (64, 3),
        (256, 2),
        (256, 4),
        (1024, 2),
        (4096, 3),
        (4096, 4),
    ] {
        let q = OrthogonalArray::new(n, 1, t).unwrap().levels();
        let array = OrthogonalArray::new(n, q + 1, t).unwrap();
        for pattern in [0, 7, u32::MAX] {
            let what = format!("array n {n} t {t} pattern {pattern}");
            let points = points(&array, pattern);
            let d = (q + 1) as usize;
            for dims in subsets(d.min(9), t as usize) {
                assert_projection(&points, d, &dims, q, &what);
            }
            for dimension in 0..d {
                assert_1d(&points, d, dimension, n, &what);
            }
        }
    }
}

#[test]
fn the_largest_array_is_latin_and_stratified() {
    // n = 4096^2 = 2^24 over GF(2^12): the 2D projection holds one point
    // per cell of 4096 x 4096, and each dimension one per stratum of 2^24.
    let n = 1 << 24;
    let array = OrthogonalArray::new(n, 2, 2).unwrap();
    assert_eq!(array.levels(), 4096);
    let mut cells = vec![false; n as usize];
    let mut strata = [vec![false; n as usize], vec![false; n as usize]];
    let mut point = [0.0; 2];
    for index in 0..n {
        array.sample(index, u32::MAX, &mut point);
        let cell = stratum(point[0], 4096) * 4096 + stratum(point[1], 4096);
        assert!(!cells[cell as usize], "index {index}: cell {cell} twice");
        cells[cell as usize] = true;
        for (seen, x) in strata.iter_mut().zip(point) {
            let s = stratum(x, n) as usize;
            assert!(!seen[s], "index {index}: stratum {s} twice");
            seen[s] = true;
        }
    }
}

#[test]
fn orthogonal_array_coordinates_are_uniform_over_patterns() {
    // Sample 0, dimensions 0 and 2 of a 25-point array (q = 5), over 2^16
    // patterns: each of the 25 x 25 joint fine cells of (x0, x2) at
    // resolution 1/25 (the Latin strata) should be hit 2^16 / 625 = 104.9
    // times. Chi-square with 624 degrees of freedom: mean 624, standard
    // deviation 35.3; the bound 624 + 6 sd = 836 fails by chance with
    // probability below 1e-6. Checks the row order, the level and
    // sub-stratum permutations and the column choice at once: a fixed
    // column or an unpermuted level would pile points up.
    for offset in OFFSETS {
        let array = OrthogonalArray::new(25, 6, 2).unwrap().with_offset(offset);
        let mut counts = vec![0u32; 625];
        let patterns = 1u32 << 16;
        for pattern in 0..patterns {
            let x0 = stratum(array.coordinate(0, pattern, 0), 25);
            let x2 = stratum(array.coordinate(0, pattern, 2), 25);
            counts[(x0 * 25 + x2) as usize] += 1;
        }
        let expected = f64::from(patterns) / 625.0;
        let chi2: f64 = counts
            .iter()
            .map(|&c| (f64::from(c) - expected).powi(2) / expected)
            .sum();
        assert!(chi2 < 836.0, "{offset:?}: chi-square {chi2:.1}");
    }
}

#[test]
fn latin_hypercube_coordinates_are_uniform_over_patterns() {
    // Sample 3 of a 10-point cube, 2^16 patterns, 100 joint cells of
    // (x0, x1) at 1/10: chi-square, 99 degrees of freedom, bound
    // 99 + 6 * 14.1 = 184 (false failure below 1e-6).
    let cube = LatinHypercube::new(10, 2).unwrap();
    let mut counts = [0u32; 100];
    let patterns = 1u32 << 16;
    for pattern in 0..patterns {
        let x0 = stratum(cube.coordinate(3, pattern, 0), 10);
        let x1 = stratum(cube.coordinate(3, pattern, 1), 10);
        counts[(x0 * 10 + x1) as usize] += 1;
    }
    let expected = f64::from(patterns) / 100.0;
    let chi2: f64 = counts
        .iter()
        .map(|&c| (f64::from(c) - expected).powi(2) / expected)
        .sum();
    assert!(chi2 < 184.0, "chi-square {chi2:.1}");
}

#[test]
fn nearest_sizes_agree_with_the_constructor() {
    // For every n up to 5000 and every strength: `new` accepts exactly the
    // counts `nearest_sizes` calls valid, and the neighbours it names are
    // valid, bracket n, and have no valid count between them.
    for t in 2..=4 {
        let valid: Vec<u32> = (1..=5000)
            .filter(|&n| OrthogonalArray::new(n, 1, t).is_ok())
            .collect();
        for n in 1..=5000u32 {
            let (below, above) = OrthogonalArray::nearest_sizes(n, t);
            match OrthogonalArray::new(n, 1, t) {
                Ok(_) => assert_eq!((below, above), (Some(n), Some(n))),
                Err(Error::NotOrthogonalArraySize {
                    below: b, above: a, ..
                }) => {
                    assert_eq!((b, a), (below, above));
                    let want_below = valid.iter().rev().find(|&&v| v < n).copied();
                    assert_eq!(below, want_below, "t {t} n {n}");
                    if let Some(a) = above
                        && a <= 5000
                    {
                        assert_eq!(valid.iter().find(|&&v| v > n), Some(&a), "t {t} n {n}");
                    }
                }
                Err(e) => panic!("t {t} n {n}: {e}"),
            }
        }
    }
    // Strength 2 counts below 300, as documented.
    let squares: Vec<u32> = (1..300)
        .filter(|&n| OrthogonalArray::new(n, 1, 2).is_ok())
        .collect();
    assert_eq!(squares, [4, 9, 16, 25, 49, 64, 81, 121, 169, 256, 289]);
}

#[test]
fn dimension_limits_follow_the_field() {
    for (n, t, q) in [
        (4, 2, 2),
        (16, 2, 4),
        (25, 2, 5),
        (8, 3, 2),
        (16, 4, 2),
        (4096, 2, 64),
    ] {
        let array = OrthogonalArray::new(n, 1, t).unwrap();
        assert_eq!(array.max_dimensions(), q + 1);
        assert!(OrthogonalArray::new(n, q + 1, t).is_ok());
        assert!(matches!(
            OrthogonalArray::new(n, q + 2, t),
            Err(Error::DimensionsOutOfRange { max, .. }) if max == q + 1
        ));
    }
}

#[cfg(debug_assertions)]
#[test]
#[should_panic(expected = "index 25 out of range 0..25")]
fn an_index_past_the_set_panics_in_debug_builds() {
    let _ = OrthogonalArray::new(25, 3, 2).unwrap().coordinate(25, 0, 0);
}

#[cfg(debug_assertions)]
#[test]
#[should_panic(expected = "dimension 3 out of range 0..3")]
fn a_dimension_past_the_set_panics_in_debug_builds() {
    let _ = LatinHypercube::new(25, 3).unwrap().coordinate(0, 0, 3);
}

// Release builds only (debug builds reject the index or dimension): what
// the docs promise instead of a panic.
#[cfg(not(debug_assertions))]
#[test]
fn out_of_range_requests_give_documented_values_in_release_builds() {
    let array = OrthogonalArray::new(25, 3, 2).unwrap();
    let cube = LatinHypercube::new(25, 3).unwrap();
    for pattern in PATTERNS {
        for index in [25, 26, 49, u32::MAX] {
            for dimension in 0..3 {
                assert_eq!(
                    array.coordinate(index, pattern, dimension).to_bits(),
                    array.coordinate(index % 25, pattern, dimension).to_bits()
                );
                assert_eq!(
                    cube.coordinate(index, pattern, dimension).to_bits(),
                    cube.coordinate(index % 25, pattern, dimension).to_bits()
                );
            }
        }
        for dimension in [3, 4, 100, u32::MAX] {
            assert_eq!(
                array.coordinate(7, pattern, dimension).to_bits(),
                array.coordinate(7, pattern, dimension % 3).to_bits()
            );
            assert!((0.0..1.0).contains(&cube.coordinate(7, pattern, dimension)));
        }
    }
}

/// Whether the 4D points are a (t,m,4)-net: every elementary box of volume
/// `2^(t - m)` (sides `2^-d_k`, `d_0 + ... + d_3 = m - t`) holds `2^t`
/// points.
fn is_net_4d(points: &[[f32; 4]], t: u32) -> bool {
    let m = points.len().trailing_zeros();
    let k = m - t;
    for d0 in 0..=k {
        for d1 in 0..=k - d0 {
            for d2 in 0..=k - d0 - d1 {
                let d = [d0, d1, d2, k - d0 - d1 - d2];
                let mut cells = vec![0u32; 1 << k];
                for p in points {
                    let mut cell = 0usize;
                    for (x, bits) in p.iter().zip(d) {
                        let stratum = (f64::from(*x) * f64::from(1u32 << bits)) as usize;
                        cell = (cell << bits) | stratum;
                    }
                    cells[cell] += 1;
                }
                if cells.iter().any(|&c| c != 1 << t) {
                    return false;
                }
            }
        }
    }
    true
}

/// Points `start..start + n` of `sobol`'s pattern `pattern`, each checked
/// in `[0, 1)` and against `coordinate`.
fn sobol_points(sobol: &Sobol4D, pattern: u32, start: u32, n: u32) -> Vec<[f32; 4]> {
    (start..=start + (n - 1))
        .map(|index| {
            let mut p = [f32::NAN; 4];
            sobol.sample(index, pattern, &mut p);
            for (dimension, &x) in (0..).zip(&p) {
                assert!((0.0..1.0).contains(&x), "index {index}: {x}");
                let alone = sobol.coordinate(index, pattern, dimension);
                assert_eq!(alone.to_bits(), x.to_bits());
            }
            p
        })
        .collect()
}

#[test]
fn sobol_4d_prefixes_are_3_m_4_nets_with_a_0_2_sequence_in_front() {
    let sobol = Sobol4D::unbounded();
    assert_eq!((sobol.len(), sobol.dimensions()), (u32::MAX, 4));
    for pattern in PATTERNS {
        for m in 3..=11 {
            // The prefix 0..2^m and the dyadic block 2^m..2^(m+1): the
            // index shuffle keeps both as sets.
            for start in [0, 1 << m] {
                let points = sobol_points(&sobol, pattern, start, 1 << m);
                assert!(
                    is_net_4d(&points, 3),
                    "pattern {pattern} m {m} from {start}"
                );
                let front: Vec<Vec2> = points.iter().map(|p| Vec2::new(p[0], p[1])).collect();
                assert!(
                    is_net_base2(&front).unwrap(),
                    "pattern {pattern} m {m} from {start}"
                );
            }
        }
        // The last indices are points too.
        sobol_points(&sobol, pattern, u32::MAX - 63, 64);
    }
    // The check has teeth: t = 2 fails at some m (Joe & Kuo's dimensions
    // give t = 3, not better).
    assert!((3..=11).any(|m| !is_net_4d(&sobol_points(&sobol, 0, 0, 1 << m), 2)));
}

#[test]
fn sobol_4d_patterns_are_independent_and_sizes_are_checked() {
    assert_eq!(Sobol4D::new(0), Err(Error::ZeroSamples));
    assert_eq!(Sobol4D::new(16).unwrap().len(), 16);
    // A set size changes `len` only.
    let (a, b) = (Sobol4D::new(16).unwrap(), Sobol4D::unbounded());
    assert_eq!(a.coordinate(1000, 3, 2), b.coordinate(1000, 3, 2));
    // Different patterns share no value over 256 points.
    let values = |pattern| -> Vec<u32> {
        (0..256)
            .flat_map(|i| (0..4).map(move |d| b.coordinate(i, pattern, d).to_bits()))
            .collect()
    };
    let (p, q) = (values(0), values(1));
    let shared = p.iter().filter(|v| q.contains(v)).count();
    assert!(shared < 8, "{shared} shared values");
}

/// How many of the six pairs of dimensions of `sampler`'s first 16 points
/// of `pattern` fill the 4 x 4 grid.
fn pairs_filling_4x4(sampler: &impl SamplerNd, pattern: u32) -> usize {
    let points: Vec<[f32; 4]> = (0..16)
        .map(|i| {
            let mut p = [f32::NAN; 4];
            sampler.sample(i, pattern, &mut p);
            assert!(p.iter().all(|x| (0.0..1.0).contains(x)), "{p:?}");
            p
        })
        .collect();
    let mut filled = 0;
    for a in 0..4 {
        for b in a + 1..4 {
            let mut cells = [0; 16];
            for p in &points {
                cells[(p[a] * 4.0) as usize * 4 + (p[b] * 4.0) as usize] += 1;
            }
            filled += usize::from(cells == [1; 16]);
        }
    }
    filled
}

#[test]
fn faure_4d_fills_every_pair_where_sobol_4d_does_not() {
    let faure = Faure4D::unbounded();
    assert_eq!((faure.len(), faure.dimensions()), (u32::MAX, 4));
    assert!(faure.is_progressive() && !OrthogonalArray::new(16, 5, 2).unwrap().is_progressive());
    for pattern in PATTERNS {
        assert_eq!(pairs_filling_4x4(&faure, pattern), 6, "pattern {pattern}");
        assert!(pairs_filling_4x4(&Sobol4D::unbounded(), pattern) < 6);
    }
    assert_eq!(Faure4D::new(0), Err(Error::ZeroSamples));
    assert_eq!(Faure4D::new(5).unwrap().len(), 5);
}
