//! Screen-space blue noise at every prefix: the blurred and per-pixel RMSE
//! of `BlueNoise` and `ZSobol` against `Padded<Sobol>` at every prefix of
//! one render, the frame-to-frame error correlation, and pictures of the
//! error at a short prefix.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example blue_noise -- --frames 16 --docs docs/blue_noise.md --images docs/images
//! ```
//!
//! Each sampler renders a `size x size` film (256 by default) at `spp`
//! samples per pixel (16); after every prefix `n = 1..=spp` the error image
//! (estimate minus exact pixel value) is blurred by a Gaussian of
//! `sigma = 2` pixels (wrapping around the film's edges) and its root mean
//! square taken. The figures are root-mean-square over `frames` frames,
//! as ratios to `Padded<Sobol>` on the same prefixes. Two integrands: the
//! same Gaussian bump in every pixel (`gauss`), and a smooth image whose
//! footprint differs from pixel to pixel (`footprint`); each on dimension
//! pair 0, pair 2, a 1D draw (the first coordinate of pair 1), and the lens
//! half of a domain's first 4D draw (film and lens drawn together).

use std::ffi::OsString;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use rayon::prelude::*;
use wellspread::glam::Vec2;
use wellspread::{BlueNoise, Padded, PixelSampler, Sobol, ZSobol};

#[path = "shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// Blue-noise error at every prefix: ratio tables and error pictures.
#[derive(Parser, Debug)]
pub struct Args {
    /// Film side in pixels, 1 to 4096
    #[arg(long, default_value_t = 256, value_parser = shared::whole_number)]
    size: u32,
    /// Samples per pixel of the render whose prefixes are measured: a power
    /// of two from 4 to 256 (ZSobol is compared at its own count; the
    /// tables show prefixes 1, 2 and spp, the pictures 2 and 3)
    #[arg(long, default_value_t = 16, value_parser = shared::whole_number)]
    spp: u32,
    /// Frames to average over (at least 2, for the frame correlation)
    #[arg(long, default_value_t = 8, value_parser = shared::whole_number)]
    frames: u32,
    /// Rewrite the generated block of this Markdown file
    #[arg(long, value_name = "FILE")]
    docs: Option<PathBuf>,
    /// Write error pictures (PNG) at prefixes 2 and 3 into this folder
    /// (made if missing)
    #[arg(long, value_name = "DIR")]
    images: Option<PathBuf>,
}

/// What one sample integrates.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Integrand {
    /// `exp(-|u - 1/2|^2)` in every pixel.
    Gauss,
    /// `1/2 + sin(0.9 (x + u)) sin(0.7 (y + v)) / 2` at pixel `(x, y)`.
    Footprint,
}

/// Which dimensions the integrand sees.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Draw {
    /// Dimension pair `d`.
    Pair(u32),
    /// The first coordinate of pair 1.
    OneD,
    /// The lens half (last two coordinates) of a domain's first 4D draw
    /// (`start(pixel, i).next_4d()`), film and lens stratified together.
    Lens,
}

impl Draw {
    fn name(self) -> String {
        match self {
            Draw::Pair(d) => format!("pair {d}"),
            Draw::OneD => "1D".into(),
            Draw::Lens => "4D lens".into(),
        }
    }
}

impl Integrand {
    fn name(self) -> &'static str {
        match self {
            Integrand::Gauss => "gauss",
            Integrand::Footprint => "footprint",
        }
    }

    /// The integrand at sample `p` of pixel `(x, y)`.
    fn value(self, draw: Draw, [x, y]: [u32; 2], p: Vec2) -> f64 {
        let (u, v) = (f64::from(p.x), f64::from(p.y));
        let (x, y) = (f64::from(x), f64::from(y));
        match (self, draw) {
            (Integrand::Gauss, Draw::Pair(_) | Draw::Lens) => {
                (-((u - 0.5).powi(2) + (v - 0.5).powi(2))).exp()
            }
            (Integrand::Gauss, Draw::OneD) => (-(u - 0.5).powi(2)).exp(),
            (Integrand::Footprint, Draw::Pair(_) | Draw::Lens) => {
                0.5 + 0.5 * (0.9 * (x + u)).sin() * (0.7 * (y + v)).sin()
            }
            (Integrand::Footprint, Draw::OneD) => 0.5 + 0.5 * (0.9 * (x + u) + 0.7 * y).sin(),
        }
    }

    /// The exact pixel value.
    fn exact(self, draw: Draw, [x, y]: [u32; 2]) -> f64 {
        let (x, y) = (f64::from(x), f64::from(y));
        // The integral of exp(-t^2) over [-1/2, 1/2].
        let g1 = core::f64::consts::PI.sqrt() * erf(0.5);
        match (self, draw) {
            (Integrand::Gauss, Draw::Pair(_) | Draw::Lens) => g1 * g1,
            (Integrand::Gauss, Draw::OneD) => g1,
            (Integrand::Footprint, Draw::Pair(_) | Draw::Lens) => {
                let ix = ((0.9 * x).cos() - (0.9 * (x + 1.0)).cos()) / 0.9;
                let iy = ((0.7 * y).cos() - (0.7 * (y + 1.0)).cos()) / 0.7;
                0.5 + 0.5 * ix * iy
            }
            (Integrand::Footprint, Draw::OneD) => {
                let a = 0.9 * x + 0.7 * y;
                0.5 + 0.5 * (a.cos() - (a + 0.9).cos()) / 0.9
            }
        }
    }
}

/// The error function (Abramowitz & Stegun 7.1.26 is too coarse here, so a
/// Taylor series: |t| <= 1/2 converges in a few dozen terms).
fn erf(t: f64) -> f64 {
    let mut term = t;
    let mut sum = t;
    for k in 1..40 {
        term *= -t * t / f64::from(k);
        sum += term / f64::from(2 * k + 1);
    }
    sum * 2.0 / core::f64::consts::PI.sqrt()
}

/// The three pixel samplers compared, for one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Which {
    Padded,
    ZSobol,
    BlueNoise,
}

impl Which {
    fn name(self) -> &'static str {
        match self {
            Which::Padded => "padded sobol",
            Which::ZSobol => "zsobol",
            Which::BlueNoise => "blue-noise",
        }
    }
}

/// Error images after every prefix `1..=spp` of one frame, row-major.
fn error_images(
    which: Which,
    frame: u32,
    args: &Args,
    integrand: Integrand,
    draw: Draw,
) -> Vec<Vec<f64>> {
    let size = args.size;
    let padded = Padded::new(Sobol::new(args.spp).unwrap(), frame);
    let zsobol = ZSobol::new(args.spp, [size, size], frame).unwrap();
    let blue = BlueNoise::new(args.spp, [size, size], frame).unwrap();
    let sampler: &dyn PixelSampler = match which {
        Which::Padded => &padded,
        Which::ZSobol => &zsobol,
        Which::BlueNoise => &blue,
    };
    let mut images = vec![vec![0.0; (size * size) as usize]; args.spp as usize];
    for y in 0..size {
        for x in 0..size {
            let exact = integrand.exact(draw, [x, y]);
            let mut sum = 0.0;
            for i in 0..args.spp {
                let p = match draw {
                    Draw::Pair(d) => sampler.sample_pixel([x, y], i, d),
                    Draw::OneD => Vec2::splat(sampler.sample_pixel([x, y], i, 1).x),
                    Draw::Lens => match which {
                        Which::Padded => lens(padded, [x, y], i),
                        Which::ZSobol => lens(zsobol, [x, y], i),
                        Which::BlueNoise => lens(blue, [x, y], i),
                    },
                };
                sum += integrand.value(draw, [x, y], p);
                images[i as usize][(y * size + x) as usize] = sum / f64::from(i + 1) - exact;
            }
        }
    }
    images
}

/// The lens half of the first 4D draw of sample `index` of `pixel`.
fn lens<S: PixelSampler + Copy>(sampler: S, pixel: [u32; 2], index: u32) -> Vec2 {
    let v = sampler.start(pixel, index).next_4d();
    Vec2::new(v.z, v.w)
}

/// A Gaussian blur of `sigma = 2` pixels, wrapping around the edges.
fn blur(image: &[f64], size: usize) -> Vec<f64> {
    let sigma: f64 = 2.0;
    let radius = 8isize;
    let mut kernel: Vec<f64> = (-radius..=radius)
        .map(|t| (-(t * t) as f64 / (2.0 * sigma * sigma)).exp())
        .collect();
    let total: f64 = kernel.iter().sum();
    kernel.iter_mut().for_each(|k| *k /= total);
    let wrap = |i: isize| i.rem_euclid(size as isize) as usize;
    let mut rows = vec![0.0; size * size];
    for y in 0..size {
        for x in 0..size {
            rows[y * size + x] = (-radius..=radius)
                .zip(&kernel)
                .map(|(t, k)| k * image[y * size + wrap(x as isize + t)])
                .sum();
        }
    }
    let mut out = vec![0.0; size * size];
    for y in 0..size {
        for x in 0..size {
            out[y * size + x] = (-radius..=radius)
                .zip(&kernel)
                .map(|(t, k)| k * rows[wrap(y as isize + t) * size + x])
                .sum();
        }
    }
    out
}

fn mean_square(image: &[f64]) -> f64 {
    image.iter().map(|e| e * e).sum::<f64>() / image.len() as f64
}

/// Per prefix: mean squared blurred error, mean squared error, summed over
/// frames; and the frame-to-frame correlation of the error images, summed
/// over consecutive frame pairs.
struct Measured {
    blurred: Vec<f64>,
    pixel: Vec<f64>,
    correlation: Vec<f64>,
    /// The squares of those correlations, summed.
    correlation_squared: Vec<f64>,
    /// Mean squared error of the average of all frames, per prefix.
    averaged: Vec<f64>,
}

fn measure(which: Which, args: &Args, integrand: Integrand, draw: Draw) -> Measured {
    let spp = args.spp as usize;
    let size = args.size as usize;
    let frames: Vec<Vec<Vec<f64>>> = (0..args.frames)
        .into_par_iter()
        .map(|f| error_images(which, f, args, integrand, draw))
        .collect();
    let mut m = Measured {
        blurred: vec![0.0; spp],
        pixel: vec![0.0; spp],
        correlation: vec![0.0; spp],
        correlation_squared: vec![0.0; spp],
        averaged: vec![0.0; spp],
    };
    for n in 0..spp {
        let stats: Vec<(f64, f64)> = frames
            .par_iter()
            .map(|f| (mean_square(&blur(&f[n], size)), mean_square(&f[n])))
            .collect();
        for (b, p) in stats {
            m.blurred[n] += b;
            m.pixel[n] += p;
        }
        for pair in frames.windows(2) {
            let (a, b) = (&pair[0][n], &pair[1][n]);
            let ab: f64 = a.iter().zip(b).map(|(a, b)| a * b).sum();
            let aa: f64 = a.iter().map(|a| a * a).sum();
            let bb: f64 = b.iter().map(|b| b * b).sum();
            let rho = ab / (aa * bb).sqrt();
            m.correlation[n] += rho;
            m.correlation_squared[n] += rho * rho;
        }
        let average: Vec<f64> = (0..size * size)
            .map(|i| frames.iter().map(|f| f[n][i]).sum::<f64>() / frames.len() as f64)
            .collect();
        m.averaged[n] = mean_square(&average);
    }
    m
}

fn ratio_row(label: &str, num: &[f64], den: &[f64]) -> String {
    let mut row = format!("| {label} |");
    for (a, b) in num.iter().zip(den) {
        write!(row, " {:.2} |", (a / b).sqrt()).unwrap();
    }
    row
}

fn write_png(file: std::fs::File, image: &[f64], size: u32, scale: f64) -> std::io::Result<()> {
    let file = std::io::BufWriter::new(file);
    let mut encoder = png::Encoder::new(file, size, size);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
    let bytes: Vec<u8> = image
        .iter()
        .map(|e| (128.0 + e * scale).round().clamp(0.0, 255.0) as u8)
        .collect();
    writer
        .write_image_data(&bytes)
        .map_err(std::io::Error::other)
}

const BEGIN: &str = "<!-- begin generated by examples/blue_noise.rs -->";
const END: &str = "<!-- end generated -->";

/// The checks clap's parsers cannot make alone: one line each, exit 2.
fn check(args: &Args) -> Result<(), Failure> {
    if args.frames < 2 {
        return Err(Failure::Input(format!(
            "--frames {}: need at least 2 frames (the frame correlation pairs them)",
            args.frames
        )));
    }
    if !(4..=256).contains(&args.spp) || !args.spp.is_power_of_two() {
        return Err(Failure::Input(format!(
            "--spp {}: need a power of two from 4 to 256 (the tables show prefixes 1, 2 and \
             spp, the pictures 2 and 3)",
            args.spp
        )));
    }
    if args.size == 0 || args.size > 4096 {
        return Err(Failure::Input(format!(
            "--size {}: need 1 to 4096 pixels",
            args.size
        )));
    }
    Ok(())
}

/// The tables, and the pictures and page asked for.
pub fn run(args: &Args) -> Result<String, Failure> {
    check(args)?;
    // The page is read, and its block found, before the measurement: a
    // FIFO, a device or a page without the block fails at once.
    let page = match &args.docs {
        Some(path) => {
            shared::check_page_path("--docs", path)?;
            let page = shared::read_page(path)?;
            let (Some(start), Some(end)) = (page.find(BEGIN), page.find(END)) else {
                return Err(Failure::Input(format!(
                    "{}: no generated block ({BEGIN} ... {END}) to rewrite",
                    path.display()
                )));
            };
            Some((path, page, start, end))
        }
        None => None,
    };
    let mut out = String::new();
    let spp = args.spp as usize;
    writeln!(
        out,
        "{size} x {size} pixels, prefixes n = 1..{spp} of one {spp}-sample render, {frames} frames, \
         Gaussian blur sigma = 2 px (wrapping).\n",
        size = args.size,
        frames = args.frames
    )
    .unwrap();
    let header: String = (1..=spp).map(|n| format!(" {n} |")).collect();
    let rule: String = (0..=spp).map(|_| " --- |").collect();
    let mut blurred = format!(
        "### Blurred RMSE / Padded<Sobol>'s\n\n| sampler, integrand, draw |{header}\n|{rule}\n"
    );
    let mut pixel = format!(
        "### Per-pixel RMSE / Padded<Sobol>'s\n\n| sampler, integrand, draw |{header}\n|{rule}\n"
    );
    let mut frames = format!(
        "### Frames\n\nCorrelation of consecutive frames' error images at prefixes 1, 2 and {spp}: \
         the mean over the {p} frame pairs, then its root mean square (how large one pair's \
         correlation typically is). Then the RMSE of the {f}-frame average divided by \
         (one frame's RMSE / sqrt({f})): 1 means white in time, below 1 blue in time.\n\n\
         | sampler, integrand, draw | mean n = 1 | n = 2 | n = {spp} | rms n = 1 | n = 2 | n = {spp} \
         | averaged n = 1 | n = 2 | n = {spp} |\n\
         | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
        f = args.frames,
        p = args.frames - 1
    );
    let mut worst = [0.0f64; 3];
    for draw in [Draw::Pair(0), Draw::Pair(2), Draw::OneD, Draw::Lens] {
        for integrand in [Integrand::Gauss, Integrand::Footprint] {
            let base = measure(Which::Padded, args, integrand, draw);
            for which in [Which::BlueNoise, Which::ZSobol] {
                let m = measure(which, args, integrand, draw);
                let label = format!("{}, {}, {}", which.name(), integrand.name(), draw.name());
                blurred.push_str(&ratio_row(&label, &m.blurred, &base.blurred));
                blurred.push('\n');
                pixel.push_str(&ratio_row(&label, &m.pixel, &base.pixel));
                pixel.push('\n');
                if which == Which::BlueNoise {
                    for n in 0..spp {
                        let r = (m.blurred[n] / base.blurred[n]).sqrt();
                        worst[0] = worst[0].max(r);
                        if (n + 1).is_power_of_two() {
                            worst[1] = worst[1].max(r);
                        }
                        if n + 1 == spp {
                            worst[2] = worst[2].max(r);
                        }
                    }
                }
                for (name, mm) in [(which.name(), &m), ("padded sobol", &base)] {
                    if which == Which::ZSobol && name == "padded sobol" {
                        continue;
                    }
                    let pairs = f64::from(args.frames - 1);
                    let white = |n: usize| {
                        (mm.averaged[n] / (mm.pixel[n] / f64::from(args.frames))
                            * f64::from(args.frames))
                        .sqrt()
                    };
                    let rms = |n: usize| (mm.correlation_squared[n] / pairs).sqrt();
                    writeln!(
                        frames,
                        "| {name}, {}, {} | {:.3} | {:.3} | {:.3} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} |",
                        integrand.name(),
                        draw.name(),
                        mm.correlation[0] / pairs,
                        mm.correlation[1] / pairs,
                        mm.correlation[spp - 1] / pairs,
                        rms(0),
                        rms(1),
                        rms(spp - 1),
                        white(0),
                        white(1),
                        white(spp - 1),
                    )
                    .unwrap();
                }
            }
        }
    }
    writeln!(
        out,
        "{blurred}\nWorst blue-noise blurred ratio: {:.2} over every prefix (target 0.9), \
         {:.2} over n = 1, 2, 4, ... (target 0.6), {:.2} at n = {spp} (target 0.45).\n\n{pixel}\n{frames}",
        worst[0], worst[1], worst[2]
    )
    .unwrap();
    if let Some(dir) = &args.images {
        for which in [Which::Padded, Which::ZSobol, Which::BlueNoise] {
            let images = error_images(which, 0, args, Integrand::Footprint, Draw::Pair(0));
            let name = which.name().replace(' ', "-");
            for n in [2usize, 3] {
                let path = dir.join(format!("blue-noise-error-{name}-{n}spp.png"));
                let file = shared::create_file(&path)?;
                write_png(file, &images[n - 1], args.size, 600.0)
                    .map_err(|e| Failure::Io(format!("cannot write {}: {e}", path.display())))?;
            }
        }
    }
    if let Some((path, page, start, end)) = page {
        let page = format!("{}{BEGIN}\n{out}{}", &page[..start], &page[end..]);
        std::fs::write(path, page)
            .map_err(|e| Failure::Io(format!("cannot write {}: {e}", path.display())))?;
    }
    Ok(out)
}

/// The whole tool: parses `args`, runs, and writes the tables (or the
/// help) to `stdout`.
pub fn main_with(
    args: impl IntoIterator<Item = OsString>,
    stdout: &mut dyn std::io::Write,
) -> Result<(), Failure> {
    let Some(args) = shared::parse::<Args>("blue_noise", shared::EXIT_CODES, args, stdout)? else {
        return Ok(());
    };
    let out = run(&args)?;
    write!(stdout, "{out}").map_err(|e| Failure::Io(format!("cannot write the tables: {e}")))
}

fn main() -> ExitCode {
    let result = main_with(std::env::args_os().skip(1), &mut std::io::stdout().lock());
    shared::exit("blue_noise", result)
}
