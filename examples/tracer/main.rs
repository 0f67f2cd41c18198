//! The classic aliasing scenes rendered with every wellspread sampler, and
//! the speed/accuracy trade measured.
//!
//! ```sh
//! cargo run --release --example tracer                       # everything
//! cargo run --release --example tracer -- --scene moire --sampler regular,jittered --spp 16
//! cargo run --release --example tracer -- --scene moire-resolved --sampler sobol,zsobol --spp 4,16 --seeds 16
//! cargo run --release --example tracer -- --help
//! ```
//!
//! For each scene, size, sampler and sample count it renders a frame (or
//! one per seed with `--seeds K`), times it, and measures its RMSE and its
//! blurred RMSE against a reference image. Every sampler goes through the
//! library's [`PixelSampler`](wellspread::PixelSampler): the library's
//! samplers padded across pixels, and `zsobol`. See [`HELP`] for the files
//! it writes.

mod analysis;
mod cornell;
mod output;
mod reference;
mod render;
mod scenes;

use std::fmt::Write as _;
use std::fs;
use std::io::IsTerminal as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use wellspread::SamplerKind;

use crate::analysis::{blurred_rmse, error_spectrum};
use crate::output::{
    Crop, Picture, Series, Tile, contact_sheet, spectrum_svg, trade_plot_svg, viewing_zoom,
};
use crate::render::{FILM_DIMENSION, Filter, Image, TracerSampler, render};
use crate::scenes::SceneKind;

/// What the tracer writes and how it exits; shown under `--help`.
const HELP: &str = "\
Output, under --out (default out/), per scene as <scene>-<W>x<H>-<filter>/:
  reference.png              the reference image every RMSE is measured
                             against: what infinitely many samples would give
                             under the same filter (exact or quadrature where
                             the scene allows, else 4096 samples per pixel);
                             cached as out/reference-*.bin
  <sampler>-<spp>spp.png     each frame (the first seed's)
  contact-<spp>spp.png       the reference and every sampler, cropped to
                             where the scene aliases, labelled with RMSE
  error-<spp>spp.png         each sampler's error image (frame - reference),
                             same crop, grey = 0, black/white = -/+ 4x the
                             smallest RMSE in the sheet
  error-spectrum-<spp>spp.svg radially averaged periodogram of the error
                             image (frame - reference), one line per sampler,
                             low frequencies on the left, averaged over seeds
  trade.svg                  RMSE against seconds per frame, log-log
The markdown tables go to stdout; --report writes the rows as JSON
(scene, sampler, spp, rmse, blurred_rmse, low_frequency_power, seconds,
seeds, width, height) and --docs the tables as a markdown page headed by the
command and machine (on a page that has them, only the text between the
tracer's markers is replaced).
With --seeds K, rmse and blurred_rmse are root-mean-square over the K seeds.

Exit status: 0 success, 2 bad command line, 1 I/O error (output paths are
checked before rendering starts).";

/// The default sample counts: powers of four, so every count is a square
/// and each step should cut the error of a stratified pattern by at least 2.
const DEFAULT_SPP: [u32; 5] = [1, 4, 16, 64, 256];

/// The largest count accepted on the command line: a 4096 x 4096 grid,
/// beyond which a single frame takes minutes anyway.
const MAX_SPP: u32 = 1 << 24;
const MAX_SIDE: u32 = 16_384;
/// Most seeds per frame on the command line.
const MAX_SEEDS: u32 = 1024;
/// Bins of the radially averaged error spectrum.
const SPECTRUM_BINS: usize = 48;

/// Renders the aliasing scenes (checker, moire, moire-resolved, polygon)
/// with every sampler at several sample counts, measures RMSE and blurred
/// RMSE against a cached reference, writes PNGs, contact sheets,
/// error spectra and error-vs-time plots, and prints the trade table.
#[derive(Debug, Parser)]
#[command(name = "tracer", after_help = HELP)]
struct Cli {
    /// Comma-separated scenes: checker, moire, moire-resolved, polygon
    /// [default: all]
    #[arg(long = "scene", value_name = "LIST", value_delimiter = ',', value_parser = parse_scene)]
    scenes: Vec<SceneKind>,
    /// Comma-separated samplers: regular, random, jittered, n-rooks,
    /// multi-jittered, correlated-multi-jittered, hammersley, halton, sobol,
    /// pmj02, zsobol [default: all]
    #[arg(long = "sampler", value_name = "LIST", value_delimiter = ',', value_parser = parse_sampler)]
    samplers: Vec<TracerSampler>,
    /// Comma-separated samples per pixel, each in 1..=16777216
    /// [default: 1,4,16,64,256]
    #[arg(long = "spp", value_name = "LIST", value_delimiter = ',', value_parser = parse_spp)]
    spps: Vec<u32>,
    /// Film size for every scene, N or WxH, sides in 1..=16384 [default:
    /// 192x192 for checker and the moires; 5x7 and 64x64 for polygon]
    #[arg(long, value_name = "N|WxH", value_parser = parse_size)]
    size: Option<(u32, u32)>,
    /// Reconstruction filter: box, gaussian, mitchell
    #[arg(long, value_name = "NAME", default_value = "box", value_parser = parse_filter)]
    filter: Filter,
    /// First frame seed (the `frame` of pattern_seed, ZSobol's seed)
    #[arg(long, value_name = "N", default_value_t = 0)]
    seed: u32,
    /// Frames per row, with seeds seed..seed+K-1; errors are RMS over them
    #[arg(long, value_name = "K", default_value_t = 1,
          value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_SEEDS)))]
    seeds: u32,
    /// RMSE the "to reach" columns aim at (positive)
    #[arg(long, value_name = "RMSE", default_value_t = 0.01, value_parser = parse_target)]
    target: f64,
    /// Output directory
    #[arg(long, value_name = "DIR", default_value = "out")]
    out: PathBuf,
    /// Also write the rows as a JSON array to FILE
    #[arg(long, value_name = "FILE")]
    report: Option<PathBuf>,
    /// Also write the tables as a markdown page to FILE, headed by the
    /// command and the machine
    #[arg(long, value_name = "FILE")]
    docs: Option<PathBuf>,
}

/// The run, with defaults filled in and lists deduplicated.
#[derive(Clone, Debug, PartialEq)]
struct Options {
    scenes: Vec<SceneKind>,
    samplers: Vec<TracerSampler>,
    spps: Vec<u32>,
    size: Option<(u32, u32)>,
    filter: Filter,
    seed: u32,
    seeds: u32,
    target: f64,
    out: PathBuf,
    report: Option<PathBuf>,
    docs: Option<PathBuf>,
}

/// `items` without repeats, or `all` when `items` is empty.
fn or_all<T: PartialEq>(items: Vec<T>, all: Vec<T>) -> Vec<T> {
    if items.is_empty() { all } else { dedup(items) }
}

fn dedup<T: PartialEq>(items: Vec<T>) -> Vec<T> {
    let mut list = Vec::new();
    for item in items {
        if !list.contains(&item) {
            list.push(item);
        }
    }
    list
}

impl From<Cli> for Options {
    fn from(cli: Cli) -> Self {
        let mut spps = or_all(cli.spps, DEFAULT_SPP.to_vec());
        // Ascending, for the log-log interpolation between counts.
        spps.sort_unstable();
        Self {
            scenes: or_all(cli.scenes, SceneKind::ALL.to_vec()),
            samplers: or_all(cli.samplers, TracerSampler::all()),
            spps,
            size: cli.size,
            filter: cli.filter,
            seed: cli.seed,
            seeds: cli.seeds,
            target: cli.target,
            out: cli.out,
            report: cli.report,
            docs: cli.docs,
        }
    }
}

fn parse_scene(text: &str) -> Result<SceneKind, String> {
    text.parse()
}

fn parse_sampler(text: &str) -> Result<TracerSampler, String> {
    text.parse()
}

fn parse_filter(text: &str) -> Result<Filter, String> {
    text.parse()
}

fn parse_count(text: &str, max: u32) -> Result<u32, String> {
    match text.parse::<u32>() {
        Ok(n) if (1..=max).contains(&n) => Ok(n),
        _ => Err(format!("{text:?} is not an integer in 1..={max}")),
    }
}

fn parse_spp(text: &str) -> Result<u32, String> {
    parse_count(text, MAX_SPP)
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text.split_once('x').unwrap_or((text, text));
    let side = |s| parse_count(s, MAX_SIDE).map_err(|e| format!("{e} (use N or WxH)"));
    Ok((side(w)?, side(h)?))
}

fn parse_target(text: &str) -> Result<f64, String> {
    text.parse()
        .ok()
        .filter(|t: &f64| t.is_finite() && *t > 0.0)
        .ok_or_else(|| format!("{text:?} is not a positive number"))
}

/// One measured row: a scene, size, sampler and count, over `seeds` frames.
#[derive(Clone, Debug)]
struct Row {
    scene: SceneKind,
    width: u32,
    height: u32,
    sampler: TracerSampler,
    spp: u32,
    /// Root-mean-square over the seeds of each frame's RMSE.
    rmse: f64,
    /// The same after the viewing blur ([`blurred_rmse`]).
    blurred_rmse: f64,
    /// Mean error power below 1/16 cycle per pixel, averaged over the
    /// seeds ([`low_frequency_power`]).
    low_power: f64,
    /// Fastest time for the first seed's frame.
    seconds: f64,
    seeds: u32,
}

/// The spp and seconds at which a sampler's error first reaches `target`,
/// interpolating log-log between the two measured counts that bracket it
/// (error falls roughly as a power of spp and of time). `points` are
/// `(spp, rmse, seconds)` in increasing spp. `None`: not reached.
fn to_reach(points: &[(u32, f64, f64)], target: f64) -> Option<(f64, f64)> {
    let (first_spp, first_rmse, first_seconds) = *points.first()?;
    if first_rmse <= target {
        return Some((f64::from(first_spp), first_seconds));
    }
    points.windows(2).find_map(|pair| {
        let ((s0, e0, t0), (s1, e1, t1)) = (pair[0], pair[1]);
        if e0 > target && e1 <= target {
            let f = (target.ln() - e0.ln()) / (e1.ln() - e0.ln());
            let lerp_log = |a: f64, b: f64| (a.ln() + f * (b.ln() - a.ln())).exp();
            Some((lerp_log(f64::from(s0), f64::from(s1)), lerp_log(t0, t1)))
        } else {
            None
        }
    })
}

/// Runs `f` repeatedly until 10 ms have passed and returns its last result
/// and the fastest run: frames of a few microseconds (the 5 x 7 polygon)
/// cannot be timed once, and the minimum is the run least disturbed by other
/// work on a shared machine.
fn timed<T>(mut f: impl FnMut() -> T) -> (T, f64) {
    let budget = Duration::from_millis(10);
    let started = Instant::now();
    let mut best = f64::INFINITY;
    loop {
        let t = Instant::now();
        let result = f();
        best = best.min(t.elapsed().as_secs_f64());
        if started.elapsed() >= budget {
            return (result, best);
        }
    }
}

/// The part of the film each contact sheet shows, as fractions of the film:
/// where the scene's aliasing is.
fn crop_for(scene: SceneKind, width: u32, height: u32) -> Crop {
    let (fx, fy, fw, fh) = match scene {
        // Around the horizon, where the squares shrink below a pixel.
        SceneKind::Checker => (0.3, 0.22, 0.375, 0.375),
        // Just beyond the Nyquist contour, on the diagonal: where a regular
        // grid paints false rings and correlated patterns show structure.
        SceneKind::Moire => (0.3, 0.3, 0.375, 0.375),
        // The middle of the resolved bands, where zsobol's error is blue.
        SceneKind::MoireResolved => (0.3, 0.3, 0.375, 0.375),
        SceneKind::Polygon => (0.0, 0.0, 1.0, 1.0),
    };
    let fraction = |f: f64, n: u32| ((f * f64::from(n)) as u32).min(n - 1);
    let (x, y) = (fraction(fx, width), fraction(fy, height));
    let w = ((fw * f64::from(width)).ceil() as u32).clamp(1, width - x);
    let h = ((fh * f64::from(height)).ceil() as u32).clamp(1, height - y);
    (x, y, w, h)
}

/// Where progress and notes go: an indicatif bar on stderr when stderr is
/// a terminal, plain lines otherwise (logs, CI, pipes).
struct Progress {
    bar: Option<ProgressBar>,
}

impl Progress {
    fn new(total: u64) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(total);
            if let Ok(style) =
                ProgressStyle::with_template("{bar:40} {pos}/{len} frames, {elapsed} ({eta} left)")
            {
                bar.set_style(style);
            }
            bar
        });
        Self { bar }
    }

    fn note(&self, message: &str) {
        match &self.bar {
            Some(bar) => bar.println(format!("tracer: {message}")),
            None => eprintln!("tracer: {message}"),
        }
    }

    fn frame_done(&self) {
        if let Some(bar) = &self.bar {
            bar.inc(1);
        }
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

fn main() -> ExitCode {
    // clap prints usage errors and exits with status 2, and --help with 0.
    let options = Options::from(Cli::parse());
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("tracer: {message}");
            ExitCode::FAILURE
        }
    }
}

/// Creates `path`'s directory and opens the file for writing (creating it
/// empty if absent, keeping what it holds), so that a bad output path
/// fails before any rendering.
fn claim_output(path: &Path) -> Result<(), String> {
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        fs::create_dir_all(parent)
            .map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
    }
    fs::OpenOptions::new()
        .append(true)
        .create(true)
        .open(path)
        .map(drop)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn run(options: &Options) -> Result<(), String> {
    let started = Instant::now();
    let out = &options.out;
    fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    for path in options.report.iter().chain(&options.docs) {
        claim_output(path)?;
    }
    let sizes_of = |scene: SceneKind| match options.size {
        Some(size) => vec![size],
        None => scene.default_sizes().to_vec(),
    };
    let frames: usize = options
        .scenes
        .iter()
        .map(|&s| sizes_of(s).len())
        .sum::<usize>()
        * options.spps.len()
        * options.samplers.len()
        * options.seeds as usize;
    let progress = Progress::new(frames as u64);
    let threads = rayon::current_num_threads();
    progress.note(&format!(
        "{threads} threads, filter {}, seeds {}..={}, writing to {}",
        options.filter,
        options.seed,
        u64::from(options.seed) + u64::from(options.seeds) - 1,
        out.display()
    ));
    let mut rows = Vec::new();
    for &scene_kind in &options.scenes {
        for (width, height) in sizes_of(scene_kind) {
            rows.extend(run_scene(options, &progress, scene_kind, width, height)?);
        }
    }
    progress.finish();
    let tables = markdown_tables(options, &rows);
    println!("{tables}");
    if let Some(path) = &options.report {
        fs::write(path, json_report(&rows))
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    if let Some(path) = &options.docs {
        let existing =
            fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        fs::write(path, docs_page_from(&existing, &tables))
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    eprintln!(
        "tracer: done in {:.1} s on {threads} threads",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// One sampler's frames at one count: its rows' numbers and what the
/// pictures need.
struct Frames {
    sampler: TracerSampler,
    /// The first seed's frame.
    image: Image,
    rmse: f64,
    /// The error spectrum, averaged over the seeds.
    spectrum: Vec<f64>,
}

/// Renders one scene at one size with every requested sampler and count.
fn run_scene(
    options: &Options,
    progress: &Progress,
    scene_kind: SceneKind,
    width: u32,
    height: u32,
) -> Result<Vec<Row>, String> {
    let io_error = |path: &Path, e: std::io::Error| format!("cannot write {}: {e}", path.display());
    let label = format!("{scene_kind}-{width}x{height}-{}", options.filter);
    let dir = options.out.join(&label);
    fs::create_dir_all(&dir).map_err(|e| io_error(&dir, e))?;
    let scene = scene_kind.build(width, height);

    let t = Instant::now();
    let (reference, computed) = reference::load_or_compute(
        &options.out,
        scene_kind,
        &scene,
        width,
        height,
        options.filter,
    )
    .map_err(|e| format!("reference for {label}: {e}"))?;
    progress.note(&format!(
        "{label}: reference {} in {:.2} s",
        if computed { "computed" } else { "loaded" },
        t.elapsed().as_secs_f64()
    ));
    let zoom = viewing_zoom(width, height);
    let path = dir.join("reference.png");
    Picture::from_image(&reference, zoom)
        .write_png(&path)
        .map_err(|e| io_error(&path, e))?;

    let crop = crop_for(scene_kind, width, height);
    let crop_zoom = (192 / crop.2.max(crop.3)).max(1);
    let mut rows = Vec::new();
    for &spp in &options.spps {
        let mut frames: Vec<Frames> = Vec::new();
        for &kind in &options.samplers {
            let mut squares = (0.0, 0.0);
            let mut spectrum = vec![0.0; SPECTRUM_BINS];
            let mut first: Option<(Image, f64, f64)> = None;
            for seed_offset in 0..options.seeds {
                // `seed + offset` wraps past u32::MAX: seeds are labels.
                let seed = options.seed.wrapping_add(seed_offset);
                // A sampler may reject a count (zsobol needs powers of
                // two, say): skip that row, keep the rest.
                let sampler = match kind.build(spp, width, height, seed) {
                    Ok(sampler) => sampler,
                    Err(e) => {
                        progress.note(&format!("{label}: skipping {kind} at {spp} spp: {e}"));
                        break;
                    }
                };
                let draw = || {
                    render(
                        &scene,
                        width,
                        height,
                        &sampler,
                        FILM_DIMENSION,
                        options.filter,
                    )
                };
                let (image, seconds) = if seed_offset == 0 {
                    timed(draw)
                } else {
                    (draw(), 0.0)
                };
                let rmse = image.rmse(&reference);
                squares.0 += rmse * rmse;
                let blurred = blurred_rmse(&image, &reference);
                squares.1 += blurred * blurred;
                for (sum, p) in
                    spectrum
                        .iter_mut()
                        .zip(error_spectrum(&image, &reference, SPECTRUM_BINS))
                {
                    *sum += p / f64::from(options.seeds);
                }
                if seed_offset == 0 {
                    first = Some((image, rmse, seconds));
                }
                progress.frame_done();
            }
            let Some((image, first_rmse, seconds)) = first else {
                for _ in 0..options.seeds {
                    progress.frame_done();
                }
                continue;
            };
            let path = dir.join(format!("{kind}-{spp}spp.png"));
            Picture::from_image(&image, zoom)
                .write_png(&path)
                .map_err(|e| io_error(&path, e))?;
            let count = f64::from(options.seeds);
            rows.push(Row {
                scene: scene_kind,
                width,
                height,
                sampler: kind,
                spp,
                rmse: (squares.0 / count).sqrt(),
                blurred_rmse: (squares.1 / count).sqrt(),
                low_power: low_frequency_power(&spectrum),
                seconds,
                seeds: options.seeds,
            });
            frames.push(Frames {
                sampler: kind,
                image,
                rmse: first_rmse,
                spectrum,
            });
        }
        if frames.is_empty() {
            continue;
        }
        // The contact sheet: the reference, then each sampler's frame.
        let mut tiles = vec![Tile {
            image: &reference,
            label: vec!["reference".into(), label.clone()],
        }];
        tiles.extend(frames.iter().map(|f| Tile {
            image: &f.image,
            label: vec![
                f.sampler.name().into(),
                format!("{spp} spp rmse {:.4}", f.rmse),
            ],
        }));
        let path = dir.join(format!("contact-{spp}spp.png"));
        contact_sheet(&tiles, crop, crop_zoom)
            .write_png(&path)
            .map_err(|e| io_error(&path, e))?;
        // The error images, same crop, on one scale: mid grey is no error
        // and black / white are -/+ 4 times the smallest RMSE in the sheet.
        let smallest = frames.iter().map(|f| f.rmse).fold(f64::INFINITY, f64::min);
        let errors: Vec<Image> = frames
            .iter()
            .map(|f| error_image(&f.image, &reference, 4.0 * smallest))
            .collect();
        let error_tiles: Vec<Tile<'_>> = frames
            .iter()
            .zip(&errors)
            .map(|(f, image)| Tile {
                image,
                label: vec![f.sampler.name().into(), format!("{spp} spp error")],
            })
            .collect();
        let path = dir.join(format!("error-{spp}spp.png"));
        contact_sheet(&error_tiles, crop, crop_zoom)
            .write_png(&path)
            .map_err(|e| io_error(&path, e))?;
        let series: Vec<(&str, Vec<f64>)> = frames
            .iter()
            .map(|f| (f.sampler.name(), f.spectrum.clone()))
            .collect();
        let title = format!(
            "{label}: error spectrum at {spp} spp, {} seed{}",
            options.seeds,
            if options.seeds == 1 { "" } else { "s" }
        );
        let path = dir.join(format!("error-spectrum-{spp}spp.svg"));
        fs::write(&path, spectrum_svg(&title, &series)).map_err(|e| io_error(&path, e))?;
    }

    let series: Vec<Series<'_>> = options
        .samplers
        .iter()
        .map(|&kind| Series {
            name: kind.name(),
            points: rows
                .iter()
                .filter(|r| r.sampler == kind)
                .map(|r| (r.spp, r.rmse, r.seconds))
                .collect(),
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    // Nothing to plot if every sampler rejected every count.
    if !rows.is_empty() {
        let title = format!("{label}: RMSE vs time per frame");
        let path = dir.join("trade.svg");
        fs::write(&path, trade_plot_svg(&title, &series, options.target))
            .map_err(|e| io_error(&path, e))?;
    }
    progress.note(&format!("{label}: wrote {}", dir.display()));
    Ok(rows)
}

/// `frame - reference` as a picture: linear 1/2 where they agree, 0 and 1
/// at `-range` and `+range` (clamped), on the sRGB curve's inverse so the
/// display shows the error linearly.
fn error_image(frame: &Image, reference: &Image, range: f64) -> Image {
    let range = if range > 0.0 { range } else { 1.0 };
    let pixels = frame
        .pixels
        .iter()
        .zip(&reference.pixels)
        .map(|(a, b)| {
            std::array::from_fn(|c| {
                let shown =
                    (0.5 + 0.5 * (f64::from(a[c]) - f64::from(b[c])) / range).clamp(0.0, 1.0);
                srgb_to_linear(shown) as f32
            })
        })
        .collect();
    Image {
        width: frame.width,
        height: frame.height,
        pixels,
    }
}

/// The inverse of the sRGB encoding `Picture` applies.
fn srgb_to_linear(encoded: f64) -> f64 {
    if encoded <= 0.040_45 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// An error for a table cell: five decimals, or three significant figures
/// in scientific notation below 0.001 (the resolved scene at high counts).
fn format_error(value: f64) -> String {
    if value >= 1e-3 || value == 0.0 {
        format!("{value:.5}")
    } else {
        format!("{value:.2e}")
    }
}

/// Milliseconds with three significant figures, for table cells.
fn format_ms(seconds: f64) -> String {
    let ms = seconds * 1e3;
    if ms >= 100.0 {
        format!("{ms:.0} ms")
    } else if ms >= 10.0 {
        format!("{ms:.1} ms")
    } else if ms >= 1.0 {
        format!("{ms:.2} ms")
    } else {
        format!("{ms:.3} ms")
    }
}

/// One table per scene and size: RMSE, blurred RMSE and ms per frame at
/// each spp, then the spp and time needed to reach the target RMSE; then
/// the claims this run has the evidence for.
fn markdown_tables(options: &Options, rows: &[Row]) -> String {
    let mut text = String::new();
    let seeds = if options.seeds == 1 {
        "one seed".to_owned()
    } else {
        format!("RMS over {} seeds", options.seeds)
    };
    for (scene, width, height) in jobs(rows) {
        let _ = writeln!(
            text,
            "\n### {scene} {width}x{height}, {} filter: RMSE / blurred RMSE (ms per frame), {seeds}; what reaching RMSE {} costs\n",
            options.filter, options.target
        );
        let mut header = String::from("| sampler |");
        let mut rule = String::from("| --- |");
        for spp in &options.spps {
            let _ = write!(header, " {spp} spp |");
            rule.push_str(" ---: |");
        }
        header.push_str(" spp to reach | time to reach |");
        rule.push_str(" ---: | ---: |");
        let _ = writeln!(text, "{header}\n{rule}");
        for &kind in &options.samplers {
            let mine: Vec<&Row> = rows
                .iter()
                .filter(|r| (r.scene, r.width, r.height, r.sampler) == (scene, width, height, kind))
                .collect();
            let mut line = format!("| {kind} |");
            for spp in &options.spps {
                match mine.iter().find(|r| r.spp == *spp) {
                    Some(r) => {
                        let _ = write!(
                            line,
                            " {} / {} ({}) |",
                            format_error(r.rmse),
                            format_error(r.blurred_rmse),
                            format_ms(r.seconds)
                        );
                    }
                    None => line.push_str(" skipped |"),
                }
            }
            let points: Vec<_> = mine.iter().map(|r| (r.spp, r.rmse, r.seconds)).collect();
            match to_reach(&points, options.target) {
                Some((spp, seconds)) => {
                    let _ = write!(line, " {spp:.1} | {} |", format_ms(seconds));
                }
                None => line.push_str(" not reached | not reached |"),
            }
            let _ = writeln!(text, "{line}");
        }
    }
    if let Some(claim) = versus_random(rows) {
        let _ = writeln!(text, "\n{claim}");
    }
    if let Some(table) = zsobol_versus_sobol(rows) {
        let _ = writeln!(text, "\n{table}");
    }
    text
}

/// The (scene, width, height) triples of `rows`, in order of appearance.
fn jobs(rows: &[Row]) -> Vec<(SceneKind, u32, u32)> {
    let mut jobs = Vec::new();
    for r in rows {
        if !jobs.contains(&(r.scene, r.width, r.height)) {
            jobs.push((r.scene, r.width, r.height));
        }
    }
    jobs
}

/// The row of `sampler` matching `r`'s scene, size and count.
fn partner<'a>(rows: &'a [Row], r: &Row, sampler: TracerSampler) -> Option<&'a Row> {
    rows.iter().find(|q| {
        (q.scene, q.width, q.height, q.spp, q.sampler)
            == (r.scene, r.width, r.height, r.spp, sampler)
    })
}

/// From 16 spp up, does every other sampler beat `random` on RMSE at equal
/// spp? Lists the exceptions rather than hiding them. `None` when the run
/// has no such comparison (random, or every other sampler, not rendered at
/// 16 spp or more).
fn versus_random(rows: &[Row]) -> Option<String> {
    let random = TracerSampler::Padded(SamplerKind::Random);
    let compared: Vec<(&Row, &Row)> = rows
        .iter()
        .filter(|r| r.spp >= 16 && r.sampler != random)
        .filter_map(|r| Some((r, partner(rows, r, random)?)))
        .collect();
    if compared.is_empty() {
        return None;
    }
    let exceptions: Vec<String> = compared
        .iter()
        .filter(|(r, random)| r.rmse >= random.rmse)
        .map(|(r, random)| {
            format!(
                "{} on {} {}x{} at {} spp ({:.5} vs {:.5})",
                r.sampler, r.scene, r.width, r.height, r.spp, r.rmse, random.rmse
            )
        })
        .collect();
    Some(if exceptions.is_empty() {
        format!(
            "From 16 spp up, every other sampler rendered here has a lower RMSE than `random` \
             at equal spp ({} comparisons).",
            compared.len()
        )
    } else {
        format!(
            "Not below `random` at equal spp (16 spp and up): {}.",
            exceptions.join("; ")
        )
    })
}

/// Mean of the lowest eighth of the spectrum's bins (frequencies below
/// 1/16 cycle per pixel): the error a blurred view keeps.
fn low_frequency_power(spectrum: &[f64]) -> f64 {
    let low = &spectrum[..(spectrum.len() / 8).max(1)];
    low.iter().sum::<f64>() / low.len() as f64
}

/// zsobol against sobol, row by row: the ratio of blurred RMSE, of RMSE,
/// and of low-frequency error power. `None` unless both were rendered.
fn zsobol_versus_sobol(rows: &[Row]) -> Option<String> {
    let sobol = TracerSampler::Padded(SamplerKind::Sobol);
    let pairs: Vec<(&Row, &Row)> = rows
        .iter()
        .filter(|r| r.sampler == TracerSampler::ZSobol)
        .filter_map(|r| Some((r, partner(rows, r, sobol)?)))
        .collect();
    if pairs.is_empty() {
        return None;
    }
    let mut text = String::from(
        "#### zsobol / sobol\n\n| scene | spp | seeds | blurred RMSE ratio | RMSE ratio | low-frequency power ratio |\n| --- | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for (z, s) in pairs {
        // A film too small for a spectrum (the 5 x 7 polygon) has no
        // low-frequency power: "-" rather than NaN.
        let low = z.low_power / s.low_power;
        let low = if low.is_finite() {
            format!("{low:.3}")
        } else {
            "-".to_owned()
        };
        let _ = writeln!(
            text,
            "| {} {}x{} | {} | {} | {:.3} | {:.3} | {low} |",
            z.scene,
            z.width,
            z.height,
            z.spp,
            z.seeds,
            z.blurred_rmse / s.blurred_rmse,
            z.rmse / s.rmse,
        );
    }
    text += "\n\"-\": the film is too small for an error spectrum.\n";
    Some(text)
}

/// The rows as a JSON array.
fn json_report(rows: &[Row]) -> String {
    let items: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                r#"  {{"scene": "{}", "sampler": "{}", "spp": {}, "rmse": {:e}, "blurred_rmse": {:e}, "low_frequency_power": {}, "seconds": {:e}, "seeds": {}, "width": {}, "height": {}}}"#,
                r.scene,
                r.sampler.name(),
                r.spp,
                r.rmse,
                r.blurred_rmse,
                // JSON has no NaN: a film too small for a spectrum is null.
                if r.low_power.is_finite() {
                    format!("{:e}", r.low_power)
                } else {
                    "null".to_owned()
                },
                r.seconds,
                r.seeds,
                r.width,
                r.height
            )
        })
        .collect();
    format!("[\n{}\n]\n", items.join(",\n"))
}

/// Marks the part of a `--docs` page the tracer owns: on a re-run only the
/// text between the markers is replaced, so prose around it survives.
const DOCS_BEGIN: &str = "<!-- tracer: generated from here; edit outside the markers -->";
const DOCS_END: &str = "<!-- tracer: generated up to here -->";

/// The command that reproduces this run, as a shell line.
fn command_line() -> String {
    let mut line = String::from("cargo run --release --example tracer");
    let args: Vec<String> = std::env::args().skip(1).collect();
    if !args.is_empty() {
        line.push_str(" --");
        for arg in args {
            let plain = arg
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "-_=,./:".contains(c));
            if plain {
                let _ = write!(line, " {arg}");
            } else {
                let _ = write!(line, " '{}'", arg.replace('\'', r"'\''"));
            }
        }
    }
    line
}

/// The CPU model (from /proc/cpuinfo where there is one), OS and threads.
fn machine() -> String {
    let cpu = fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines().find_map(|l| {
                l.strip_prefix("model name")
                    .map(|v| v.trim_start_matches([' ', '\t', ':']).to_owned())
            })
        })
        .unwrap_or_else(|| "unknown CPU".to_owned());
    format!(
        "{cpu}, {} {}, {} rayon threads",
        std::env::consts::OS,
        std::env::consts::ARCH,
        rayon::current_num_threads()
    )
}

/// The generated block of a `--docs` page.
fn docs_block(tables: &str) -> String {
    format!(
        "{DOCS_BEGIN}\n\nRegenerate with:\n\n```sh\n{}\n```\n\nMachine: {}. Times are the fastest of repeated renders of one frame; other work on the machine inflates them.\n{tables}\n{DOCS_END}\n",
        command_line(),
        machine()
    )
}

/// The `--docs` page: `existing` with its generated block replaced, or
/// with the block appended when it has none (a new page when empty).
fn docs_page_from(existing: &str, tables: &str) -> String {
    let block = docs_block(tables);
    match (existing.find(DOCS_BEGIN), existing.find(DOCS_END)) {
        (Some(begin), Some(end)) if end > begin => format!(
            "{}{block}{}",
            &existing[..begin],
            existing[end + DOCS_END.len()..].trim_start_matches('\n')
        ),
        _ if existing.trim().is_empty() => format!("# Tracer measurements\n\n{block}"),
        // A page of prose with no block yet: the block goes at its end.
        _ => format!("{}\n\n{block}", existing.trim_end()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run_options(list: &[&str]) -> Options {
        let args = std::iter::once("tracer").chain(list.iter().copied());
        match Cli::try_parse_from(args) {
            Ok(cli) => Options::from(cli),
            Err(e) => panic!("{list:?}: {e}"),
        }
    }

    fn parse_error(list: &[&str]) -> clap::Error {
        let args = std::iter::once("tracer").chain(list.iter().copied());
        Cli::try_parse_from(args).expect_err(&format!("{list:?} should fail"))
    }

    #[test]
    fn no_arguments_mean_everything() {
        let options = run_options(&[]);
        assert_eq!(options.scenes, SceneKind::ALL);
        assert_eq!(options.samplers, TracerSampler::all());
        assert!(options.samplers.contains(&TracerSampler::ZSobol));
        assert_eq!(options.spps, DEFAULT_SPP);
        assert_eq!(options.filter, Filter::Box);
        assert_eq!((options.seed, options.seeds), (0, 1));
        assert_eq!(options.out, PathBuf::from("out"));
    }

    #[test]
    fn lists_narrow_the_run() {
        let options = run_options(&[
            "--scene",
            "moire,checker,moire",
            "--sampler=regular,n-rooks,zsobol",
            "--spp",
            "16,4",
            "--size",
            "32x8",
            "--filter",
            "mitchell",
            "--seed",
            "9",
            "--seeds=4",
            "--report",
            "r.json",
            "--docs",
            "d.md",
        ]);
        assert_eq!(options.scenes, [SceneKind::Moire, SceneKind::Checker]);
        assert_eq!(
            options.samplers,
            [
                TracerSampler::Padded(SamplerKind::Regular),
                TracerSampler::Padded(SamplerKind::NRooks),
                TracerSampler::ZSobol
            ]
        );
        assert_eq!(options.spps, [4, 16]);
        assert_eq!(options.size, Some((32, 8)));
        assert_eq!(options.filter, Filter::Mitchell);
        assert_eq!((options.seed, options.seeds), (9, 4));
        assert_eq!(options.report, Some(PathBuf::from("r.json")));
        assert_eq!(options.docs, Some(PathBuf::from("d.md")));
        assert_eq!(run_options(&["--size", "100"]).size, Some((100, 100)));
        assert_eq!(
            run_options(&["--scene", "moire-resolved"]).scenes,
            [SceneKind::MoireResolved]
        );
    }

    #[test]
    fn bad_values_are_usage_errors_that_name_the_item() {
        for bad in [
            &["--scene", "teapot"][..],
            &["--sampler", "best"],
            &["--spp", "0"],
            &["--spp", "4,,16"],
            &["--size", "0x4"],
            &["--size", "big"],
            &["--filter", "lanczos"],
            &["--seed", "-1"],
            &["--seeds", "0"],
            &["--target", "0"],
            &["--spp"],
            &["--frobnicate"],
        ] {
            let error = parse_error(bad);
            // Usage errors exit with status 2.
            assert_eq!(error.exit_code(), 2, "{bad:?}");
        }
        let message = parse_error(&["--sampler", "regular, jittered"]).to_string();
        assert!(
            message.contains("unknown sampler \" jittered\""),
            "{message}"
        );
        assert!(message.contains("zsobol"), "{message}");
    }

    #[test]
    fn help_lists_every_option_and_the_outputs() {
        let error = parse_error(&["--spp", "4", "--help"]);
        assert_eq!(error.exit_code(), 0);
        let help = error.to_string();
        for option in [
            "--scene",
            "--sampler",
            "--spp",
            "--size",
            "--filter",
            "--seed ",
            "--seeds",
            "--target",
            "--out",
            "--report",
            "--docs",
            "--help",
        ] {
            assert!(help.contains(option), "{option} missing from --help");
        }
        for text in ["reference.png", "error-spectrum", "Exit status"] {
            assert!(help.contains(text), "{text} missing from --help");
        }
    }

    #[test]
    fn bad_output_paths_fail_before_rendering() {
        let out = std::env::temp_dir().join(format!("tracer-test-{}", std::process::id()));
        let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
        options.out = out.clone();
        // A report "inside" a regular file cannot be created.
        options.report = Some(PathBuf::from("Cargo.toml/report.json"));
        let message = run(&options).unwrap_err();
        assert!(message.contains("Cargo.toml"), "{message}");
        // Nothing was rendered: the scene's directory does not exist.
        assert!(!out.join("polygon-4x4-box").exists());
        let _ = fs::remove_dir_all(&out);
    }

    fn row(sampler: TracerSampler, spp: u32, rmse: f64) -> Row {
        Row {
            scene: SceneKind::Moire,
            width: 8,
            height: 8,
            sampler,
            spp,
            rmse,
            blurred_rmse: rmse / 2.0,
            low_power: rmse * rmse,
            seconds: 0.001,
            seeds: 1,
        }
    }

    #[test]
    fn claims_need_their_evidence() {
        let sobol = TracerSampler::Padded(SamplerKind::Sobol);
        let random = TracerSampler::Padded(SamplerKind::Random);
        // No random in the run: no claim about random.
        assert_eq!(versus_random(&[row(sobol, 16, 0.01)]), None);
        // Random only below 16 spp: no claim either.
        assert_eq!(
            versus_random(&[row(sobol, 4, 0.01), row(random, 4, 0.02)]),
            None
        );
        let claim = versus_random(&[row(sobol, 16, 0.01), row(random, 16, 0.02)]).unwrap();
        assert!(claim.contains("every other sampler"), "{claim}");
        let claim = versus_random(&[row(sobol, 16, 0.03), row(random, 16, 0.02)]).unwrap();
        assert!(claim.starts_with("Not below"), "{claim}");
        // zsobol against sobol only when both ran.
        assert_eq!(zsobol_versus_sobol(&[row(sobol, 16, 0.01)]), None);
        let table =
            zsobol_versus_sobol(&[row(sobol, 16, 0.02), row(TracerSampler::ZSobol, 16, 0.01)])
                .unwrap();
        assert!(table.contains("| 0.500 | 0.500 | 0.250 |"), "{table}");
    }

    #[test]
    fn docs_pages_keep_the_prose_around_the_generated_block() {
        let fresh = docs_page_from("", "TABLES");
        assert!(fresh.starts_with("# Tracer measurements") && fresh.contains("TABLES"));
        let page =
            format!("# Mine\n\nprose before\n\n{DOCS_BEGIN}\nold\n{DOCS_END}\n\nprose after\n");
        let updated = docs_page_from(&page, "NEW");
        assert!(updated.starts_with("# Mine\n\nprose before\n\n"));
        assert!(updated.contains("NEW") && !updated.contains("old"));
        assert!(updated.ends_with("prose after\n"));
        assert!(updated.contains("cargo run --release --example tracer"));
        let appended = docs_page_from("# Prose\n\ntext\n", "T");
        assert!(appended.starts_with("# Prose\n\ntext\n\n") && appended.contains(DOCS_END));
    }

    #[test]
    fn to_reach_interpolates_log_log() {
        // Error halves per 4x spp: RMSE 0.04 at 16, 0.02 at 64; 0.02 * sqrt(2)
        // lies halfway in log, at 32 spp.
        let points = [(16, 0.04, 0.1), (64, 0.02, 0.4)];
        let (spp, seconds) = to_reach(&points, 0.02 * 2f64.sqrt()).unwrap();
        assert!((spp - 32.0).abs() < 1e-9 && (seconds - 0.2).abs() < 1e-9);
        assert_eq!(to_reach(&points, 0.05), Some((16.0, 0.1)));
        assert_eq!(to_reach(&points, 0.01), None);
    }

    #[test]
    fn crops_stay_inside_the_film() {
        for scene in SceneKind::ALL {
            for (w, h) in [(1, 1), (5, 7), (64, 64), (256, 256), (300, 17)] {
                let (x, y, cw, ch) = crop_for(scene, w, h);
                assert!(
                    cw >= 1 && ch >= 1 && x + cw <= w && y + ch <= h,
                    "{scene} {w}x{h}"
                );
            }
        }
    }
}
