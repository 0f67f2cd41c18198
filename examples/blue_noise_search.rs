//! The generator of `BlueNoise`'s pixel-shift table: a deterministic
//! hill-climb over the top digits of the 32 generator vectors (one per
//! Morton bit of the pixel), scoring each candidate by the blurred RMSE
//! ratios to `Padded<Sobol>` at prefixes 1..=16 on a small film.
//!
//! ```sh
//! cargo run --release --example blue_noise_search
//! ```
//!
//! It prints the 32 columns (x digits, y digits), one per line, as
//! `PIXEL_COLUMNS` in `src/pixel/blue_noise.rs` holds them. The search
//! fixes its frames, its pseudo-random start and its two random restarts
//! (the optional argument changes their number), so every run prints the
//! same table; it takes about four minutes of one core. Candidates are
//! scored without the per-frame shuffle of the Morton code's high bits,
//! which leaves each 16 x 16 block's arrangement, the part searched, as
//! it is.

use wellspread::glam::Vec2;
use wellspread::primitives::{hash_u32, owen_scramble, owen_scramble_reversed};
use wellspread::{Padded, PixelSampler, Sobol};

const SIZE: usize = 128;
const SPP: usize = 16;
const FRAMES: u32 = 8;
/// Generator vectors searched (four Morton levels); the rest are fixed.
const SEARCHED: usize = 8;
/// Digits of each searched vector the climb flips.
const DIGITS: u32 = 10;

fn pascal_reversed(index: u32) -> u32 {
    let mut y = index;
    y ^= (y >> 1) & 0x5555_5555;
    y ^= (y >> 2) & 0x3333_3333;
    y ^= (y >> 4) & 0x0f0f_0f0f;
    y ^= (y >> 8) & 0x00ff_00ff;
    y ^= y >> 16;
    y
}

fn gauss(p: Vec2, _x: usize, _y: usize) -> f64 {
    let (u, v) = (f64::from(p.x) - 0.5, f64::from(p.y) - 0.5);
    (-(u * u + v * v)).exp()
}

fn footprint(p: Vec2, x: usize, y: usize) -> f64 {
    0.5 + 0.5
        * (0.9 * (x as f64 + f64::from(p.x))).sin()
        * (0.7 * (y as f64 + f64::from(p.y))).sin()
}

/// Mean squared blurred error per prefix, summed over frames, for both integrands.
fn blurred(points: &dyn Fn(u32, usize, usize, u32) -> Vec2, exact: &[[f64; 2]]) -> [[f64; SPP]; 2] {
    let sigma: f64 = 2.0;
    let kernel: Vec<f64> = {
        let k: Vec<f64> = (-8i32..=8)
            .map(|t| (-(t * t) as f64 / (2.0 * sigma * sigma)).exp())
            .collect();
        let s: f64 = k.iter().sum();
        k.into_iter().map(|v| v / s).collect()
    };
    let mut out = [[0.0; SPP]; 2];
    let mut sums = vec![[0.0f64; 2]; SIZE * SIZE];
    let mut errs = vec![vec![[0.0f64; 2]; SIZE * SIZE]; SPP];
    for frame in 0..FRAMES {
        sums.iter_mut().for_each(|s| *s = [0.0; 2]);
        for y in 0..SIZE {
            for x in 0..SIZE {
                let px = y * SIZE + x;
                for (i, err) in (0u32..).zip(errs.iter_mut()) {
                    let p = points(frame, x, y, i);
                    sums[px][0] += gauss(p, x, y);
                    sums[px][1] += footprint(p, x, y);
                    let count = f64::from(i + 1);
                    err[px] = [
                        sums[px][0] / count - exact[px][0],
                        sums[px][1] / count - exact[px][1],
                    ];
                }
            }
        }
        for (i, e) in errs.iter().enumerate() {
            let mut rows = vec![[0.0f64; 2]; SIZE * SIZE];
            for y in 0..SIZE {
                for x in 0..SIZE {
                    for (t, k) in kernel.iter().enumerate() {
                        let xx = (x + SIZE + t - 8) % SIZE;
                        for c in 0..2 {
                            rows[y * SIZE + x][c] += k * e[y * SIZE + xx][c];
                        }
                    }
                }
            }
            for y in 0..SIZE {
                for x in 0..SIZE {
                    let mut b = [0.0; 2];
                    for (t, k) in kernel.iter().enumerate() {
                        let yy = (y + SIZE + t - 8) % SIZE;
                        for c in 0..2 {
                            b[c] += k * rows[yy * SIZE + x][c];
                        }
                    }
                    for c in 0..2 {
                        out[c][i] += b[c] * b[c];
                    }
                }
            }
        }
    }
    out
}

fn linear(g: &[[u32; 2]; 32], frame: u32, x: usize, y: usize, index: u32) -> Vec2 {
    let s = hash_u32(frame.wrapping_mul(0x9e37_79b9) ^ 0x1234_5678);
    let i = owen_scramble(index, hash_u32(s ^ 1));
    let mut px = i.reverse_bits() >> 8;
    let mut py = pascal_reversed(i).reverse_bits() >> 8;
    for j in 0..16 {
        if x >> j & 1 == 1 {
            px ^= g[2 * j][0];
            py ^= g[2 * j][1];
        }
        if y >> j & 1 == 1 {
            px ^= g[2 * j + 1][0];
            py ^= g[2 * j + 1][1];
        }
    }
    let ox = owen_scramble_reversed((px << 8).reverse_bits(), hash_u32(s ^ 2)).reverse_bits() >> 8;
    let oy = owen_scramble_reversed((py << 8).reverse_bits(), hash_u32(s ^ 3)).reverse_bits() >> 8;
    Vec2::new(ox as f32 / 16_777_216.0, oy as f32 / 16_777_216.0)
}

fn score(r: &[[f64; SPP]; 2], base: &[[f64; SPP]; 2]) -> (f64, [[f64; SPP]; 2]) {
    let mut worst = 0.0f64;
    let mut ratio = [[0.0; SPP]; 2];
    for c in 0..2 {
        for n in 0..SPP {
            ratio[c][n] = (r[c][n] / base[c][n]).sqrt();
            let target = if n + 1 == SPP {
                0.45
            } else if (n + 1).is_power_of_two() {
                0.6
            } else {
                0.9
            };
            worst = worst.max(ratio[c][n] / target);
        }
    }
    (worst, ratio)
}

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u32 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 33) as u32
    }
}

fn main() {
    // The integral of exp(-t^2) over [-1/2, 1/2] is sqrt(pi) erf(1/2).
    let erf_half = 0.520_499_877_813_046_5;
    let gi = (core::f64::consts::PI.sqrt() * erf_half).powi(2);
    let exact: Vec<[f64; 2]> = (0..SIZE * SIZE)
        .map(|p| {
            let (x, y) = ((p % SIZE) as f64, (p / SIZE) as f64);
            let ix = ((0.9 * x).cos() - (0.9 * (x + 1.0)).cos()) / 0.9;
            let iy = ((0.7 * y).cos() - (0.7 * (y + 1.0)).cos()) / 0.7;
            [gi, 0.5 + 0.5 * ix * iy]
        })
        .collect();
    let base = blurred(
        &|frame, x, y, i| {
            Padded::new(Sobol::unbounded(), frame).sample_pixel([x as u32, y as u32], i, 0)
        },
        &exact,
    );
    let mut rng = Rng(0x5eed);
    let mut g = [[0u32; 2]; 32];
    for v in g.iter_mut() {
        *v = [rng.next() >> 8, rng.next() >> 8];
    }
    let args: Vec<String> = std::env::args().collect();
    let restarts: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(2);
    let mut best = (f64::MAX, [[0.0; SPP]; 2]);
    // Random restarts of the searched levels, then a climb from the best.
    for _ in 0..restarts {
        let mut cand = g;
        for v in cand.iter_mut().take(SEARCHED) {
            *v = [rng.next() >> 8, rng.next() >> 8];
        }
        let s = score(
            &blurred(&|f, x, y, i| linear(&cand, f, x, y, i), &exact),
            &base,
        );
        if s.0 < best.0 {
            best = s;
            g = cand;
            eprintln!("start {:.3}", s.0);
        }
    }
    loop {
        let mut improved = false;
        for w in 0..SEARCHED {
            for c in 0..2 {
                for bit in 24 - DIGITS..24 {
                    let mut cand = g;
                    cand[w][c] ^= 1 << bit;
                    let s = score(
                        &blurred(&|f, x, y, i| linear(&cand, f, x, y, i), &exact),
                        &base,
                    );
                    if s.0 < best.0 - 1e-9 {
                        best = s;
                        g = cand;
                        improved = true;
                        eprintln!("climb {:.3}", s.0);
                    }
                }
            }
        }
        if !improved {
            break;
        }
    }
    for c in 0..2 {
        eprintln!(
            "{}",
            best.1[c]
                .iter()
                .map(|r| format!("{r:.2}"))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    for v in &g {
        println!("{:06x} {:06x}", v[0], v[1]);
    }
}
