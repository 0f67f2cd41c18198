//! The search for `BlueNoise`'s pixel columns: a deterministic hill-climb
//! over the top digits of the columns of the four finest Morton levels
//! (2 x 2 to 16 x 16), scoring each candidate by running `BlueNoise`
//! itself with those columns (`BlueNoise::with_columns` and
//! `ExplicitColumns`), so the score is that of exactly the sampler that
//! would ship them.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example blue_noise_search
//! ```
//!
//! It prints the 32 columns (x digits, y digits), one per line, as
//! `PIXEL_COLUMNS` in `src/pixel/blue_noise.rs` holds them, and on
//! standard error the scores of its start, of the columns `BlueNoise`
//! ships (`SearchedColumns`) and of each sweep: about 11 minutes on two
//! loaded cores (7.5 minutes of CPU). It climbs the top 10 digits of the
//! 8 finest columns from [`START`], those of an earlier search's table;
//! the coarser 24 are the shipped ones and stay as they are. The shipped
//! table is this search's output with the default three sweeps (score
//! 0.758 at the start, then 0.736, 0.730 and 0.725: the climb had not
//! converged, more sweeps would go on). Each candidate is scored
//! on 16 frames of a 96 x 96 film, on dimension pairs 0 and 2 and the 1D
//! draw (the first coordinate of pair 1), on the per-pixel Gaussian and
//! the footprint integrand of `examples/blue_noise.rs`: the mean of every
//! blurred RMSE ratio to `Padded<Sobol>` divided by its target (0.9, 0.6
//! at powers of two, 0.45 at 16), a penalty on any ratio above 0.88, and
//! one on a chi-square of two unrelated pairs at one pixel above 350
//! (blue noise bought with a shift pattern that all pairs share would
//! relate a pixel's draws). A candidate `ExplicitColumns::new` refuses
//! (its columns and the Sobol' columns do not span all 48 digits, so two
//! pixels of a tile would share a shift) is skipped. Starts and restarts
//! are fixed (`--restarts` sets the number of random restarts of the
//! searched columns, 0 by default; `--sweeps` caps the climb's sweeps, 3
//! by default), so every run prints the same table. `--help` lists them;
//! a bad or unknown argument stops it before the search starts.

use std::ffi::OsString;
use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use rayon::prelude::*;
use wellspread::blue_noise::{ExplicitColumns, PixelColumns, SearchedColumns};
use wellspread::glam::Vec2;
use wellspread::primitives::hash_u32;
use wellspread::{BlueNoise, Padded, PixelSampler, Sobol};

#[path = "shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// The search for `BlueNoise`'s pixel-shift table (minutes: see the top of
/// the file).
#[derive(Parser, Debug)]
pub struct Args {
    /// Random restarts of the searched levels, kept if they beat the start
    #[arg(long, value_name = "N", default_value = "0", value_parser = shared::whole_number)]
    pub restarts: u32,
    /// The most sweeps of the hill-climb
    #[arg(long, value_name = "N", default_value = "3", value_parser = shared::whole_number)]
    pub sweeps: u32,
}

/// Parses the arguments (without the program name): `Ok(None)` when the
/// help was written to `out`.
pub fn parse(
    args: impl IntoIterator<Item = OsString>,
    out: &mut dyn std::io::Write,
) -> Result<Option<Args>, Failure> {
    shared::parse::<Args>("blue_noise_search", shared::EXIT_CODES, args, out)
}

const SIZE: u32 = 96;
const SPP: usize = 16;
const FRAMES: u32 = 16;
/// Generator vectors searched (four Morton levels); the rest are fixed.
const SEARCHED: usize = 8;
/// Digits of each searched vector the climb flips.
const DIGITS: u32 = 10;

/// Where the climb starts: the 8 finest columns of the table `BlueNoise`
/// shipped before this search's first run, from an earlier two-stage
/// search (a climb under a fixed arrangement per 16 x 16 block, then one
/// scored with a copy of an earlier form of `BlueNoise`'s randomisation,
/// before the prefix shuffle and the code's translation). The other 24
/// columns are the shipped ones, which the climb never changes: that
/// search's pseudo-random start, 24 random digits each, so the coarse
/// levels flip the top digits too.
const START: [[u32; 2]; SEARCHED] = [
    [0xd459e5, 0xe7e552],
    [0x7878d4, 0xbe5f6b],
    [0x0a02b8, 0x6ffd15],
    [0x9ba7b0, 0x4a162b],
    [0x350c48, 0x66b51e],
    [0x65ae75, 0x6bcb34],
    [0x6ae98f, 0x14e66a],
    [0x632e2b, 0x74de50],
];

/// `BlueNoise` with the columns `columns` on a `size x size` film.
fn blue_noise(columns: ExplicitColumns, size: u32, frame: u32) -> BlueNoise<ExplicitColumns> {
    BlueNoise::unbounded([size, size], frame)
        .expect("the film is not empty")
        .with_columns(columns)
}

/// The draws scored: pairs 0 and 2, and the first coordinate of pair 1.
const DRAWS: [Option<u32>; 3] = [Some(0), Some(2), None];

/// Integrand `c` (0: Gaussian, 1: footprint) at sample `p` of pixel `(x, y)`.
fn value(c: usize, pair: bool, x: f64, y: f64, p: Vec2) -> f64 {
    let (u, v) = (f64::from(p.x), f64::from(p.y));
    match (c, pair) {
        (0, true) => (-((u - 0.5).powi(2) + (v - 0.5).powi(2))).exp(),
        (0, false) => (-(u - 0.5).powi(2)).exp(),
        (_, true) => 0.5 + 0.5 * (0.9 * (x + u)).sin() * (0.7 * (y + v)).sin(),
        (_, false) => 0.5 + 0.5 * (0.9 * (x + u) + 0.7 * y).sin(),
    }
}

fn exact(c: usize, pair: bool, x: f64, y: f64) -> f64 {
    // sqrt(pi) erf(1/2), the integral of exp(-t^2) over [-1/2, 1/2].
    let g1 = 0.922_562_427_258_656_3_f64;
    match (c, pair) {
        (0, true) => g1 * g1,
        (0, false) => g1,
        (_, true) => {
            let ix = ((0.9 * x).cos() - (0.9 * (x + 1.0)).cos()) / 0.9;
            let iy = ((0.7 * y).cos() - (0.7 * (y + 1.0)).cos()) / 0.7;
            0.5 + 0.5 * ix * iy
        }
        (_, false) => {
            let a = 0.9 * x + 0.7 * y;
            0.5 + 0.5 * (a.cos() - (a + 0.9).cos()) / 0.9
        }
    }
}

/// Mean squared blurred error (sigma = 2 px, wrapping) of one image.
fn blurred_mean_square(e: &[f64], kernel: &[f64; 17]) -> f64 {
    let size = SIZE as usize;
    let mut rows = vec![0.0; size * size];
    for y in 0..size {
        for x in 0..size {
            rows[y * size + x] = (0..17)
                .map(|t| kernel[t] * e[y * size + (x + size + t - 8) % size])
                .sum();
        }
    }
    let mut total = 0.0;
    for y in 0..size {
        for x in 0..size {
            let b: f64 = (0..17)
                .map(|t| kernel[t] * rows[((y + size + t - 8) % size) * size + x])
                .sum();
            total += b * b;
        }
    }
    total / (size * size) as f64
}

/// Blurred mean squared error per draw, integrand and prefix, summed over
/// the frames.
type Table = [[[f64; SPP]; 2]; 3];

fn blurred<S: PixelSampler>(sampler: impl Fn(u32) -> S + Sync) -> Table {
    let mut kernel = [0.0; 17];
    for (t, k) in kernel.iter_mut().enumerate() {
        let d = t as f64 - 8.0;
        *k = (-d * d / 8.0).exp();
    }
    let total: f64 = kernel.iter().sum();
    kernel.iter_mut().for_each(|k| *k /= total);
    let n_px = (SIZE * SIZE) as usize;
    let tables: Vec<Table> = (0..FRAMES)
        .into_par_iter()
        .map(|frame| {
            let sampler = sampler(frame);
            let mut out = [[[0.0; SPP]; 2]; 3];
            let mut images = vec![vec![0.0f64; n_px]; 2 * SPP];
            for (d, draw) in DRAWS.iter().enumerate() {
                let pair = draw.is_some();
                for y in 0..SIZE {
                    for x in 0..SIZE {
                        let (fx, fy) = (f64::from(x), f64::from(y));
                        let px = (y * SIZE + x) as usize;
                        let mut sums = [0.0; 2];
                        for i in 0..SPP as u32 {
                            let p = match draw {
                                Some(k) => sampler.sample_pixel([x, y], i, *k),
                                None => Vec2::splat(sampler.sample_pixel([x, y], i, 1).x),
                            };
                            for (c, sum) in sums.iter_mut().enumerate() {
                                *sum += value(c, pair, fx, fy, p);
                                images[2 * i as usize + c][px] =
                                    *sum / f64::from(i + 1) - exact(c, pair, fx, fy);
                            }
                        }
                    }
                }
                for (k, image) in images.iter().enumerate() {
                    out[d][k % 2][k / 2] = blurred_mean_square(image, &kernel);
                }
            }
            out
        })
        .collect();
    let mut sum = [[[0.0; SPP]; 2]; 3];
    for table in tables {
        for d in 0..3 {
            for c in 0..2 {
                for n in 0..SPP {
                    sum[d][c][n] += table[d][c][n];
                }
            }
        }
    }
    sum
}

/// The largest chi-square, over 16 frames each with two dimension pairs
/// picked by unrelated hashes, of the first coordinates of the two pairs
/// at the same pixel and index: 16 x 16 cells over a 64 x 64 film at 16
/// samples per pixel (255 degrees of freedom; independent pairs stay near
/// 255). Frames and pairs other than those `tests/pixel/blue_noise.rs` checks.
fn pair_chi_square(columns: ExplicitColumns) -> f64 {
    (0..16u32)
        .into_par_iter()
        .map(|k| {
            let sampler = blue_noise(columns, 64, 1000 + k);
            let (a, b) = (hash_u32(k ^ 0x51ed_270b), hash_u32(k ^ 0x0b4f_3c59));
            let mut counts = [0u32; 256];
            for p in 0..64 * 64 {
                for i in 0..16 {
                    let u = sampler.sample_pixel([p % 64, p / 64], i, a).x;
                    let v = sampler.sample_pixel([p % 64, p / 64], i, b).x;
                    counts[(u * 16.0) as usize * 16 + (v * 16.0) as usize] += 1;
                }
            }
            counts
                .iter()
                .map(|&c| (f64::from(c) - 256.0).powi(2) / 256.0)
                .sum::<f64>()
        })
        .reduce(|| 0.0, f64::max)
}

/// The score of columns `g`: [`score`] plus a penalty on a largest pair
/// chi-square above 350, so the climb cannot buy blue noise with a shift
/// pattern that two pairs share.
fn evaluate(columns: ExplicitColumns, base: &Table) -> (f64, Table) {
    let (s, ratio) = score(&blurred(|frame| blue_noise(columns, SIZE, frame)), base);
    (
        s + 0.001 * (pair_chi_square(columns) - 350.0).max(0.0),
        ratio,
    )
}

fn target(n: usize) -> f64 {
    if n == SPP {
        0.45
    } else if n.is_power_of_two() {
        0.6
    } else {
        0.9
    }
}

/// The score (lower is better) and the ratios: the mean over every draw,
/// integrand and prefix of the ratio divided by its target, plus a
/// penalty on any ratio above 0.88 (the 0.9 target with a margin), so the
/// climb lowers all of them together instead of the one it cannot reach.
fn score(r: &Table, base: &Table) -> (f64, Table) {
    let mut worst = 0.0f64;
    let mut mean = 0.0;
    let mut ratio = [[[0.0; SPP]; 2]; 3];
    for d in 0..3 {
        for c in 0..2 {
            for n in 0..SPP {
                ratio[d][c][n] = (r[d][c][n] / base[d][c][n]).sqrt();
                worst = worst.max(ratio[d][c][n]);
                mean += ratio[d][c][n] / target(n + 1) / (3 * 2 * SPP) as f64;
            }
        }
    }
    (mean + 4.0 * (worst - 0.88).max(0.0), ratio)
}

/// A 64-bit LCG; `next` returns the high 32 bits of its state.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u32 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 32) as u32
    }

    /// A column: 24 random digits per coordinate.
    fn column(&mut self) -> [u32; 2] {
        [self.next() >> 8, self.next() >> 8]
    }
}

fn main() -> ExitCode {
    let mut stdout = std::io::stdout().lock();
    match parse(std::env::args_os().skip(1), &mut stdout) {
        Ok(Some(args)) => {
            let columns = search(args.restarts as usize, args.sweeps as usize);
            let table = columns
                .iter()
                .try_for_each(|v| writeln!(stdout, "{:06x} {:06x}", v[0], v[1]));
            shared::exit("blue_noise_search", shared::to_stdout(table))
        }
        Ok(None) => ExitCode::SUCCESS,
        Err(failure) => shared::exit("blue_noise_search", Err(failure)),
    }
}

/// The search: progress on standard error; returns the columns, which
/// `main` prints as the table.
fn search(restarts: usize, sweeps: usize) -> [[u32; 2]; 32] {
    let started = std::time::Instant::now();
    let base = blurred(|frame| Padded::new(Sobol::unbounded(), frame));
    let mut g = SearchedColumns.columns();
    g[..SEARCHED].copy_from_slice(&START);
    let start = ExplicitColumns::new(g).expect("the start passes the check");
    let mut best = evaluate(start, &base);
    let shipped = ExplicitColumns::new(SearchedColumns.columns()).expect("checked in the library");
    eprintln!(
        "start {:.3}, the shipped columns {:.3}",
        best.0,
        evaluate(shipped, &base).0
    );
    // Candidates `BlueNoise` would refuse are skipped (`None`).
    let scored = |cand: &[[u32; 2]; 32]| {
        ExplicitColumns::new(*cand)
            .ok()
            .map(|columns| evaluate(columns, &base))
    };
    // Random restarts of the searched levels, kept if they beat it.
    let mut rng = Rng(0x5eed);
    for _ in 0..restarts {
        let mut cand = g;
        for v in cand.iter_mut().take(SEARCHED) {
            *v = rng.column();
        }
        match scored(&cand) {
            Some(s) => {
                eprintln!("restart {:.3}", s.0);
                if s.0 < best.0 {
                    best = s;
                    g = cand;
                }
            }
            None => eprintln!("restart refused: its columns do not span all 48 digits"),
        }
    }
    for sweep in 0..sweeps {
        let mut improved = false;
        for w in 0..SEARCHED {
            for c in 0..2 {
                for bit in 24 - DIGITS..24 {
                    let mut cand = g;
                    cand[w][c] ^= 1 << bit;
                    if let Some(s) = scored(&cand).filter(|s| s.0 < best.0 - 1e-9) {
                        best = s;
                        g = cand;
                        improved = true;
                    }
                }
            }
        }
        eprintln!(
            "sweep {sweep}: {:.3} after {:.0} s",
            best.0,
            started.elapsed().as_secs_f64()
        );
        if !improved {
            break;
        }
    }
    for (d, name) in ["pair 0", "pair 2", "1D"].iter().enumerate() {
        for (c, integrand) in ["gauss", "footprint"].iter().enumerate() {
            let row: Vec<String> = best.1[d][c].iter().map(|r| format!("{r:.2}")).collect();
            eprintln!("{name}, {integrand}: {}", row.join(" "));
        }
    }
    g
}
