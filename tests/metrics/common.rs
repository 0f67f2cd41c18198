//! Helpers shared by the metric tests: tolerances, a seeded generator,
//! point sets and proptest strategies, a compensated sum.

use proptest::prelude::*;
use wellspread::glam::Vec2;

pub fn close(got: f64, want: f64, rel: f64) -> bool {
    (got - want).abs() <= rel * want.abs().max(1e-300)
}

pub fn assert_close(what: &str, got: f64, want: f64, rel: f64) {
    assert!(
        close(got, want, rel),
        "{what}: got {got:e}, want {want:e} (rel. diff {:e})",
        (got - want).abs() / want.abs()
    );
}

/// A small deterministic generator (SplitMix64), so tests need no RNG crate.
pub struct Mix(pub u64);
impl Mix {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform on the 24-bit grid in [0, 1).
    pub fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u32 << 24) as f32
    }
}

pub fn random_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Mix(seed);
    (0..n).map(|_| Vec2::new(rng.unit(), rng.unit())).collect()
}

pub fn hammersley(m: u32) -> Vec<Vec2> {
    let n = 1u32 << m;
    (0..n)
        .map(|i| {
            let y = if m == 0 {
                0
            } else {
                i.reverse_bits() >> (32 - m)
            };
            Vec2::new(i as f32 / n as f32, y as f32 / n as f32)
        })
        .collect()
}

/// Neumaier sum, for the O(n^2) reference formulas.
#[derive(Default)]
pub struct Sum(f64, f64);
impl Sum {
    pub fn add(&mut self, v: f64) {
        let t = self.0 + v;
        self.1 += if self.0.abs() >= v.abs() {
            (self.0 - t) + v
        } else {
            (v - t) + self.0
        };
        self.0 = t;
    }
    pub fn get(&self) -> f64 {
        self.0 + self.1
    }
}

// ------------------------------------------- numerical integration (squared)

/// Cell boundaries of a 1/16 grid; test points lie on it, so counts are
/// constant inside every cell and the polynomial parts integrate exactly.
pub const GRID: usize = 16;

pub fn dyadic_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Mix(seed);
    (0..n)
        .map(|_| {
            let x = (rng.next() % GRID as u64) as f32 / GRID as f32;
            let y = (rng.next() % GRID as u64) as f32 / GRID as f32;
            Vec2::new(x, y)
        })
        .collect()
}

pub fn unit_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        // Anywhere on the 24-bit grid.
        (0u32..1 << 24).prop_map(|i| i as f32 / (1u32 << 24) as f32),
        // Few distinct values, so x and y repeat.
        (0u32..6).prop_map(|i| i as f32 / 6.0),
        // Any f32 in [0, 1), subnormals included.
        (0u32..0x3f80_0000).prop_map(f32::from_bits),
    ]
}

pub fn unit_points(max: usize) -> impl Strategy<Value = Vec<Vec2>> {
    prop::collection::vec(
        (unit_f32(), unit_f32()).prop_map(|(x, y)| Vec2::new(x, y)),
        1..=max,
    )
}
