//! The measurement lab: the classic aliasing scenes rendered with every
//! wellspread sampler, and the speed/accuracy trade measured. It writes the
//! tables of `docs/tracer.md`, `docs/zsobol.md` and `docs/blue_noise.md`.
//! A renderer author reads `path_tracer.rs` first: the same library calls
//! in one small file.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example tracer                       # a short run, seconds
//! cargo run --release -p wellspread-lab --example tracer -- --full             # everything
//! cargo run --release -p wellspread-lab --example tracer -- --scene moire --sampler regular,jittered --spp 16
//! cargo run --release -p wellspread-lab --example tracer -- --scene moire-resolved --sampler sobol,zsobol --spp 4,16 --frames 16
//! cargo run --release -p wellspread-lab --example tracer -- --help
//! ```
//!
//! For each scene, size, sampler and sample count it renders a frame (or
//! one per frame with `--frames K`), times it, and measures its RMSE and its
//! blurred RMSE against a reference image. Every sampler goes through the
//! library's [`PixelSampler`](wellspread::PixelSampler), by the names of
//! [`PixelSamplerKind`](wellspread::PixelSamplerKind): the library's
//! samplers padded across pixels, `zsobol` and `blue-noise`. The path-traced `cornell`
//! draws every number through a [`Domain`](wellspread::Domain), or, for the
//! baseline `pcg32` that is not the crate, from one `rand_pcg::Pcg32` per
//! pixel sample.
//! `--help` lists the files it writes.
//!
//! The modules: `cli` (options and their checks), `render` (samplers,
//! filters, the render loop), `scenes` and `reference` (what is rendered and
//! its reference image), `cornell` and `path` (the path-traced scene and the
//! domains that feed it), `analysis` (blurred RMSE, error spectra), `output`
//! (PNG, contact sheets, SVG plots) and `report` (tables, JSON, the
//! `--docs` page). This file runs them: per scene and size, per count, per
//! sampler, per frame.

mod analysis;
mod cli;
mod cornell;
#[path = "../shared/joint_sobol.rs"]
mod joint_sobol;
#[path = "../shared/machine.rs"]
mod machine;
mod output;
mod path;
mod reference;
mod render;
mod report;
mod scenes;
#[path = "../shared/cli.rs"]
mod shared;

use std::ffi::OsString;
use std::fs;
use std::io::{IsTerminal as _, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use wellspread::filter::FilterKind;

use crate::analysis::{blurred_rmse, error_spectrum};
use crate::cli::Options;
use crate::cornell::{Draws, Light, Tracing};
use crate::output::{
    Crop, Picture, Series, Tile, contact_sheet, spectrum_svg, stack_rows, trade_plot_svg,
    viewing_zoom,
};
use crate::path::FrameSampler;
use crate::render::{FILM_DIMENSION, FilterMode, Image, TracerSampler, render};
use crate::report::{
    Row, docs_block_name, docs_page_from, json_report, low_frequency_power, markdown_tables,
};
use crate::scenes::{Built, SceneKind};
use crate::shared::Failure;

/// A row's `top_rmse` is over the top `1 / TOP_ROWS_DIVISOR` of the film's
/// rows, leaving out the pixels where the reference passes
/// [`TOP_BRIGHTEST`] in a channel: in cornell the ceiling and the top of
/// the walls and back wall, the shading points nearest the light, without
/// the light itself and its defocused edge (whose error comes from the
/// film and lens, not from light sampling).
/// A row's `off_light_rmse` is over the whole film without the pixels
/// within [`LIGHT_MARGIN`] pixels (horizontally, vertically or
/// diagonally) of one whose reference passes [`TOP_BRIGHTEST`]: the light
/// and its defocused edge, whose error the film and lens draws make.
const TOP_ROWS_DIVISOR: u32 = 4;
pub const LIGHT_MARGIN: u32 = 3;
pub const TOP_BRIGHTEST: f32 = 1.0;

/// Bins of the radially averaged error spectrum.
const SPECTRUM_BINS: usize = 48;

fn main() -> ExitCode {
    let result = main_with(std::env::args_os().skip(1), &mut std::io::stdout().lock());
    shared::exit("tracer", result)
}

/// The whole tool but the exit: parses `args` (after the program name),
/// renders, and writes the tables (or `--help`) to `stdout`.
fn main_with(
    args: impl IntoIterator<Item = OsString>,
    stdout: &mut dyn Write,
) -> Result<(), Failure> {
    match cli::parse(args, stdout)? {
        Some(options) => run(&options, stdout),
        None => Ok(()),
    }
}

/// A failed write of `path`, exit status 1.
fn write_error(path: &Path, e: std::io::Error) -> Failure {
    Failure::Io(format!("cannot write {}: {e}", path.display()))
}

fn run(options: &Options, stdout: &mut dyn Write) -> Result<(), Failure> {
    let started = Instant::now();
    let out = &options.out;
    fs::create_dir_all(out)
        .map_err(|e| Failure::Io(format!("cannot create {}: {e}", out.display())))?;
    if let Some(path) = &options.docs {
        shared::check_page_path("--docs", path)?;
    }
    for path in options.report.iter().chain(&options.docs) {
        claim_output(path)?;
    }
    let frames: usize = options
        .scenes
        .iter()
        .map(|&s| {
            options.lights_for(s).len()
                * options.sizes_for(s).len()
                * options.spps_for(s).len()
                * options
                    .samplers_for(s)
                    .into_iter()
                    .map(|k| options.draws_for(s, k).len())
                    .sum::<usize>()
                * options.frames_for(s) as usize
        })
        .sum::<usize>()
        * options.filters.len()
        * options.modes.len();
    let progress = Progress::new(frames as u64);
    for note in &options.notes {
        progress.note(note);
    }
    let threads = rayon::current_num_threads();
    let names = |items: Vec<&str>| items.join(",");
    progress.note(&format!(
        "{threads} threads, filter {} ({}), writing to {}",
        names(options.filters.iter().map(|f| f.name()).collect()),
        names(options.modes.iter().map(|m| m.name()).collect()),
        out.display()
    ));
    let mut rows = Vec::new();
    let mut runs = Vec::new();
    for &filter in &options.filters {
        for &mode in &options.modes {
            for &scene_kind in &options.scenes {
                let lights = options.lights_for(scene_kind);
                for (width, height) in options.sizes_for(scene_kind) {
                    for run in run_scene(
                        options,
                        &progress,
                        scene_kind,
                        width,
                        height,
                        (filter, mode, &lights),
                    )? {
                        rows.extend(run.rows.iter().cloned());
                        runs.push(run);
                    }
                }
            }
        }
    }
    if options.filters.len() * options.modes.len() > 1 {
        write_filter_sheets(options, &runs)?;
    }
    progress.finish();
    let tables = markdown_tables(options, &rows);
    writeln!(stdout, "{tables}\n{}", pictures_written(&runs))
        .map_err(|e| Failure::Io(format!("cannot write the tables: {e}")))?;
    if let Some(path) = &options.report {
        fs::write(path, json_report(&rows)).map_err(|e| write_error(path, e))?;
    }
    if let Some(path) = &options.docs {
        let existing = shared::read_page(path)?;
        fs::write(
            path,
            docs_page_from(&existing, &tables, docs_block_name(options)),
        )
        .map_err(|e| write_error(path, e))?;
    }
    progress.note(&format!(
        "done in {:.1} s on {threads} threads",
        started.elapsed().as_secs_f64()
    ));
    Ok(())
}

/// The closing lines of a run's stdout: per scene directory, the contact
/// and error sheets of each count, then the full frames and reference.
fn pictures_written(runs: &[SceneRun]) -> String {
    let mut text = String::from("Pictures written:\n");
    for run in runs {
        let dir = run.dir.display();
        let mut frames = Vec::new();
        for &(spp, ..) in &run.firsts {
            text.push_str(&format!(
                "- {dir}/contact-{spp}spp.png: contact sheet, the reference and every sampler, cropped\n\
                 - {dir}/error-{spp}spp.png: each sampler's error image, same crop\n"
            ));
            let samplers = run.rows.iter().filter(|r| r.spp == spp);
            frames.extend(samplers.map(|r| format!("{}-{spp}spp.png", r.sampler)));
        }
        text.push_str(&format!(
            "- {dir}/: full frames {}, reference.png\n",
            frames.join(", ")
        ));
    }
    text
}

/// One scene at one size under one filter and mode: its rows, its
/// reference, and per count the first sampler's first frame (for the
/// filters' contact sheet).
struct SceneRun {
    kind: SceneKind,
    /// Where its pictures went.
    dir: PathBuf,
    width: u32,
    height: u32,
    filter: FilterKind,
    mode: FilterMode,
    rows: Vec<Row>,
    reference: Image,
    /// `(spp, sampler, first frame, its RMSE)` of the first sampler.
    firsts: Vec<(u32, TracerSampler, Image, f64)>,
}

/// Renders one scene at one size under `filter` and `mode` with every
/// requested sampler and count, once per light sampling in `lights` and
/// draw layout of `--draws`, and writes its pictures: one run per light
/// and layout. They take turns at each sampler and count, so their frame
/// times are measured seconds apart and a change in the machine's load
/// falls on all alike.
fn run_scene(
    options: &Options,
    progress: &Progress,
    kind: SceneKind,
    width: u32,
    height: u32,
    (filter, mode, lights): (FilterKind, FilterMode, &[Light]),
) -> Result<Vec<SceneRun>, Failure> {
    let draws = match kind.build(1, 1) {
        Built::PathTraced => options.draws.clone(),
        Built::Film(_) => vec![Draws::default()],
    };
    let jobs = lights
        .iter()
        .flat_map(|&light| draws.iter().map(move |&draws| (light, draws)))
        .map(|(light, draws)| {
            let tracing = Tracing {
                light,
                draws,
                max_depth: options.depth(),
            };
            SceneJob::prepare(
                options,
                progress,
                kind,
                width,
                height,
                (filter, mode, tracing),
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut rows = vec![Vec::new(); jobs.len()];
    let mut firsts = vec![Vec::new(); jobs.len()];
    for spp in options.spps_for(kind) {
        let mut frames: Vec<Vec<Frames>> = jobs.iter().map(|_| Vec::new()).collect();
        for sampler in options.samplers_for(kind) {
            for (j, job) in jobs.iter().enumerate() {
                if !options
                    .draws_for(kind, sampler)
                    .contains(&job.tracing.draws)
                {
                    continue;
                }
                if let Some(f) = job.measure(sampler, spp)? {
                    rows[j].push(f.row.clone());
                    frames[j].push(f);
                }
            }
        }
        for (j, job) in jobs.iter().enumerate() {
            // Nothing to show if every sampler rejected this count.
            if let Some(first) = frames[j].first() {
                job.write_sheets(spp, &frames[j])?;
                firsts[j].push((
                    spp,
                    first.row.sampler,
                    first.image.clone(),
                    first.first_rmse,
                ));
            }
        }
    }
    let mut runs = Vec::new();
    for ((job, rows), firsts) in jobs.into_iter().zip(rows).zip(firsts) {
        if !rows.is_empty() {
            job.write_trade_plot(&rows)?;
        }
        progress.note(&format!("{}: wrote {}", job.label, job.dir.display()));
        runs.push(SceneRun {
            kind,
            dir: job.dir.clone(),
            width,
            height,
            filter,
            mode,
            rows,
            reference: job.reference,
            firsts,
        });
    }
    Ok(runs)
}

/// `filters-<scene>-<W>x<H>-<spp>spp.png` under `--out`: per scene, size
/// and count, one row per filter of the same crop, enlarged: the
/// reference, then the first sampler's frame in each mode.
fn write_filter_sheets(options: &Options, runs: &[SceneRun]) -> Result<(), Failure> {
    let mut jobs: Vec<(SceneKind, u32, u32)> = Vec::new();
    for run in runs {
        if !jobs.contains(&(run.kind, run.width, run.height)) {
            jobs.push((run.kind, run.width, run.height));
        }
    }
    for (kind, width, height) in jobs {
        let crop = filter_crop_for(kind, width, height);
        let zoom = (96 / crop.2.max(crop.3)).max(1);
        for spp in options.spps_for(kind) {
            let mut sheet_rows = Vec::new();
            for &filter in &options.filters {
                let mine = |mode: FilterMode| {
                    runs.iter().find(|r| {
                        (r.kind, r.width, r.height, r.filter, r.mode)
                            == (kind, width, height, filter, mode)
                    })
                };
                let Some(reference) = options.modes.iter().find_map(|&m| mine(m)) else {
                    continue;
                };
                let mut tiles = vec![Tile {
                    image: &reference.reference,
                    label: vec![filter.name().into(), "reference".into()],
                }];
                for &mode in &options.modes {
                    let Some(run) = mine(mode) else { continue };
                    if let Some((_, sampler, image, rmse)) =
                        run.firsts.iter().find(|(s, ..)| *s == spp)
                    {
                        tiles.push(Tile {
                            image,
                            label: vec![
                                format!("{mode} {sampler}"),
                                format!("{spp} spp rmse {rmse:.4}"),
                            ],
                        });
                    }
                }
                sheet_rows.push(contact_sheet(&tiles, crop, zoom));
            }
            if sheet_rows.is_empty() {
                continue;
            }
            let path = options
                .out
                .join(format!("filters-{kind}-{width}x{height}-{spp}spp.png"));
            stack_rows(&sheet_rows)
                .write_png(&path)
                .map_err(|e| write_error(&path, e))?;
        }
    }
    Ok(())
}

/// The small crop the filters' contact sheet enlarges: one edge where
/// the filters differ. On the checker, the near squares' edges at the
/// bottom of the film (sharp, a few pixels apart, where ringing and blur
/// show); elsewhere the centre of the scene's own crop.
fn filter_crop_for(scene: SceneKind, width: u32, height: u32) -> Crop {
    let (fx, fy, fw, fh) = match scene {
        SceneKind::Checker => (0.40, 0.80, 0.125, 0.125),
        _ => (0.42, 0.42, 0.125, 0.125),
    };
    let fraction = |f: f64, n: u32| ((f * f64::from(n)) as u32).min(n - 1);
    let (x, y) = (fraction(fx, width), fraction(fy, height));
    let w = ((fw * f64::from(width)).ceil() as u32).clamp(1, width - x);
    let h = ((fh * f64::from(height)).ceil() as u32).clamp(1, height - y);
    (x, y, w, h)
}

/// One scene at one size: where its files go and the reference every
/// frame is measured against.
struct SceneJob<'a> {
    options: &'a Options,
    progress: &'a Progress,
    kind: SceneKind,
    width: u32,
    height: u32,
    filter: FilterKind,
    mode: FilterMode,
    /// How the path-traced scene traces its paths (unused by the others).
    tracing: Tracing,
    /// `<scene>-<W>x<H>-<filter>`, with `-importance` for that mode and
    /// `-area-light` for cornell's area sampling, `-call-order` and
    /// `-depth<N>` for its draws and depth, the directory's name.
    label: String,
    dir: PathBuf,
    scene: Built,
    reference: Image,
    /// Pixels per film pixel in the full-frame PNGs.
    zoom: u32,
    /// Per pixel: whether it counts in `off_light_rmse` ([`off_light`]).
    off_light: Vec<bool>,
}

/// Per pixel of `reference`: whether no pixel within [`LIGHT_MARGIN`] of
/// it passes [`TOP_BRIGHTEST`] in a channel.
fn off_light(reference: &Image) -> Vec<bool> {
    let (w, h) = (reference.width as i64, reference.height as i64);
    let bright = |x: i64, y: i64| {
        (0..w).contains(&x)
            && (0..h).contains(&y)
            && reference.pixels[(y * w + x) as usize]
                .iter()
                .any(|&v| v > TOP_BRIGHTEST)
    };
    let m = i64::from(LIGHT_MARGIN);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| !(-m..=m).any(|dy| (-m..=m).any(|dx| bright(x + dx, y + dy))))
        .collect()
}

/// One sampler's frames at one count: its row, and what the pictures need.
struct Frames {
    row: Row,
    /// The first frame's image.
    image: Image,
    /// The first frame's RMSE (the row's is RMS over the frames).
    first_rmse: f64,
    /// The error spectrum, averaged over the frames.
    spectrum: Vec<f64>,
}

impl<'a> SceneJob<'a> {
    /// Creates the scene's directory, loads or computes its reference and
    /// writes `reference.png`.
    fn prepare(
        options: &'a Options,
        progress: &'a Progress,
        kind: SceneKind,
        width: u32,
        height: u32,
        (filter, mode, tracing): (FilterKind, FilterMode, Tracing),
    ) -> Result<Self, Failure> {
        let mut label = match mode {
            FilterMode::Weighted => format!("{kind}-{width}x{height}-{filter}"),
            _ => format!("{kind}-{width}x{height}-{filter}-{mode}"),
        };
        let path_traced = matches!(kind.build(1, 1), Built::PathTraced);
        if path_traced && tracing.light != Light::default() {
            label.push_str(&format!("-{}-light", tracing.light));
        }
        if path_traced && tracing.draws != Draws::default() {
            label.push_str(&format!("-{}", tracing.draws));
        }
        if path_traced && options.max_depth.is_some() {
            label.push_str(&format!("-depth{}", tracing.max_depth));
        }
        let dir = options.out.join(&label);
        fs::create_dir_all(&dir).map_err(|e| write_error(&dir, e))?;
        let scene = kind.build(width, height);
        let t = Instant::now();
        let (reference, computed) = reference::load_or_compute(
            &options.out,
            kind,
            &scene,
            width,
            height,
            (filter, tracing.max_depth),
        )
        .map_err(|e| Failure::Io(format!("reference for {label}: {e}")))?;
        let frames = options.frame_range(kind);
        progress.note(&format!(
            "{label}: reference {} in {:.2} s; frames {}..={}",
            if computed { "computed" } else { "loaded" },
            t.elapsed().as_secs_f64(),
            frames.start(),
            frames.end()
        ));
        let zoom = viewing_zoom(width, height);
        let path = dir.join("reference.png");
        Picture::from_image(&reference, zoom)
            .write_png(&path)
            .map_err(|e| write_error(&path, e))?;
        Ok(Self {
            options,
            progress,
            kind,
            width,
            height,
            filter,
            mode,
            tracing,
            label,
            dir,
            scene,
            off_light: off_light(&reference),
            reference,
            zoom,
        })
    }

    /// Renders `sampler` at `spp` for every frame, writes the first
    /// frame's image, and measures the row. `None` when the sampler rejects the
    /// count (zsobol needs powers of two, say): that row is skipped, the
    /// rest of the run goes on.
    fn measure(&self, sampler: TracerSampler, spp: u32) -> Result<Option<Frames>, Failure> {
        let options = self.options;
        let (width, height) = (self.width, self.height);
        let mut squares = (0.0, 0.0);
        let mut top_squares = 0.0;
        let mut off_light_squares = 0.0;
        let mut spectrum = vec![0.0; SPECTRUM_BINS];
        let mut first: Option<(Image, f64)> = None;
        let mut fastest = f64::INFINITY;
        let frames = options.frames_for(self.kind);
        for (offset, frame) in options.frame_range(self.kind).enumerate() {
            let frame_sampler = match FrameSampler::new(sampler, spp, (width, height), frame) {
                Ok(frame_sampler) => frame_sampler,
                Err(e) => {
                    let label = &self.label;
                    self.progress
                        .note(&format!("{label}: skipping {sampler} at {spp} spp: {e}"));
                    for _ in 0..frames {
                        self.progress.frame_done();
                    }
                    return Ok(None);
                }
            };
            let draw = || match (&self.scene, frame_sampler) {
                (Built::Film(scene), FrameSampler::Pixel(pixels)) => render(
                    scene,
                    width,
                    height,
                    &pixels,
                    FILM_DIMENSION,
                    self.filter,
                    self.mode,
                ),
                (Built::Film(_), FrameSampler::Pcg32(_) | FrameSampler::JointSobol(_)) => {
                    unreachable!(
                        "pcg32 and the study's candidates render the path-traced scene only \
                         (TracerSampler::renders)"
                    )
                }
                (Built::PathTraced, frame_sampler) => path::render(
                    width,
                    height,
                    spp,
                    frame_sampler,
                    sampler.film_lens(),
                    self.tracing,
                ),
            };
            // Every frame is timed and the row keeps the fastest: a row's
            // frames do about the same work, so the fastest is the one other
            // work on the machine disturbed least.
            let (image, seconds) = timed(draw);
            fastest = fastest.min(seconds);
            let rmse = image.rmse(&self.reference);
            squares.0 += rmse * rmse;
            let top_pixels = (height.div_ceil(TOP_ROWS_DIVISOR) * width) as usize;
            let reference = &self.reference.pixels;
            let top = image.rmse_where(&self.reference, |i| {
                i < top_pixels && reference[i].iter().all(|&v| v <= TOP_BRIGHTEST)
            });
            top_squares += top * top;
            let off_light = image.rmse_where(&self.reference, |i| self.off_light[i]);
            off_light_squares += off_light * off_light;
            let blurred = blurred_rmse(&image, &self.reference);
            squares.1 += blurred * blurred;
            let frame_spectrum = error_spectrum(&image, &self.reference, SPECTRUM_BINS);
            for (sum, p) in spectrum.iter_mut().zip(frame_spectrum) {
                *sum += p / f64::from(frames);
            }
            if offset == 0 {
                first = Some((image, rmse));
            }
            self.progress.frame_done();
        }
        let Some((image, first_rmse)) = first else {
            return Ok(None);
        };
        let path = self.dir.join(format!("{sampler}-{spp}spp.png"));
        Picture::from_image(&image, self.zoom)
            .write_png(&path)
            .map_err(|e| write_error(&path, e))?;
        let count = f64::from(frames);
        let path_traced = matches!(self.scene, Built::PathTraced);
        let row = Row {
            scene: self.kind,
            width,
            height,
            sampler,
            spp,
            filter: self.filter,
            mode: self.mode,
            reference_range: self
                .reference
                .pixels
                .iter()
                .flatten()
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[low, high], &v| {
                    [low.min(f64::from(v)), high.max(f64::from(v))]
                }),
            light: path_traced.then_some(self.tracing.light),
            draws: (path_traced && options.labels_draws() && sampler != TracerSampler::Pcg32)
                .then_some(self.tracing.draws),
            max_depth: path_traced.then_some(self.tracing.max_depth),
            rmse: (squares.0 / count).sqrt(),
            top_rmse: (top_squares / count).sqrt(),
            off_light_rmse: (off_light_squares / count).sqrt(),
            blurred_rmse: (squares.1 / count).sqrt(),
            low_power: low_frequency_power(&spectrum),
            seconds: fastest,
            frames,
        };
        Ok(Some(Frames {
            row,
            image,
            first_rmse,
            spectrum,
        }))
    }

    /// The pictures of one count: the contact sheet (the reference, then
    /// each sampler's frame), the error images on one scale, and the error
    /// spectra.
    fn write_sheets(&self, spp: u32, frames: &[Frames]) -> Result<(), Failure> {
        let crop = crop_for(self.kind, self.width, self.height);
        let crop_zoom = (192 / crop.2.max(crop.3)).max(1);
        let mut tiles = vec![Tile {
            image: &self.reference,
            label: vec!["reference".into(), self.label.clone()],
        }];
        tiles.extend(frames.iter().map(|f| Tile {
            image: &f.image,
            label: vec![
                f.row.sampler.name().into(),
                format!("{spp} spp rmse {:.4}", f.first_rmse),
            ],
        }));
        let path = self.dir.join(format!("contact-{spp}spp.png"));
        contact_sheet(&tiles, crop, crop_zoom)
            .write_png(&path)
            .map_err(|e| write_error(&path, e))?;
        // Mid grey is no error; black / white are -/+ 4 times the smallest
        // RMSE in the sheet.
        let smallest = frames
            .iter()
            .map(|f| f.first_rmse)
            .fold(f64::INFINITY, f64::min);
        let errors: Vec<Image> = frames
            .iter()
            .map(|f| error_image(&f.image, &self.reference, 4.0 * smallest))
            .collect();
        let error_tiles: Vec<Tile<'_>> = frames
            .iter()
            .zip(&errors)
            .map(|(f, image)| Tile {
                image,
                label: vec![f.row.sampler.name().into(), format!("{spp} spp error")],
            })
            .collect();
        let path = self.dir.join(format!("error-{spp}spp.png"));
        contact_sheet(&error_tiles, crop, crop_zoom)
            .write_png(&path)
            .map_err(|e| write_error(&path, e))?;
        let series: Vec<(&str, Vec<f64>)> = frames
            .iter()
            .map(|f| (f.row.sampler.name(), f.spectrum.clone()))
            .collect();
        let frames = self.options.frames_for(self.kind);
        let title = format!(
            "{}: error spectrum at {spp} spp, {frames} frame{}",
            self.label,
            if frames == 1 { "" } else { "s" }
        );
        let path = self.dir.join(format!("error-spectrum-{spp}spp.svg"));
        fs::write(&path, spectrum_svg(&title, &series)).map_err(|e| write_error(&path, e))
    }

    /// `trade.svg`: each sampler's RMSE against seconds per frame.
    fn write_trade_plot(&self, rows: &[Row]) -> Result<(), Failure> {
        let series: Vec<Series<'_>> = self
            .options
            .samplers_for(self.kind)
            .into_iter()
            .map(|sampler| Series {
                name: sampler.name(),
                points: rows
                    .iter()
                    .filter(|r| r.sampler == sampler)
                    .map(|r| (r.spp, r.rmse, r.seconds))
                    .collect(),
            })
            .filter(|s| !s.points.is_empty())
            .collect();
        let title = format!("{}: RMSE vs time per frame", self.label);
        let path = self.dir.join("trade.svg");
        fs::write(&path, trade_plot_svg(&title, &series, self.options.target))
            .map_err(|e| write_error(&path, e))
    }
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
        // The glass sphere and the wall behind it, out of focus: caustic,
        // refraction and the lens blur in one square.
        SceneKind::Cornell => (0.5, 0.45, 0.5, 0.5),
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

/// Creates `path`'s directory and opens the file for writing (creating it
/// empty if absent, keeping what it holds), so that a bad output path
/// fails before any rendering.
fn claim_output(path: &Path) -> Result<(), Failure> {
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        fs::create_dir_all(parent)
            .map_err(|e| Failure::Io(format!("cannot create {}: {e}", parent.display())))?;
    }
    fs::OpenOptions::new()
        .append(true)
        .create(true)
        .open(path)
        .map(drop)
        .map_err(|e| write_error(path, e))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::tests::run_options;

    #[test]
    fn bad_output_paths_fail_before_rendering() {
        let out = std::env::temp_dir().join(format!("tracer-test-{}", std::process::id()));
        let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
        options.out = out.clone();
        // A report "inside" a regular file cannot be created.
        options.report = Some(PathBuf::from("Cargo.toml/report.json"));
        let failure = run(&options, &mut Vec::new()).unwrap_err();
        assert!(
            matches!(&failure, Failure::Io(m) if m.contains("Cargo.toml")),
            "{failure}"
        );
        assert_eq!(failure.status(), 1);
        // Nothing was rendered: the scene's directory does not exist.
        assert!(!out.join("polygon-4x4-box").exists());
        let _ = fs::remove_dir_all(&out);
    }

    #[test]
    fn an_oversized_docs_page_is_refused_at_the_size_limit() {
        // `--docs /dev/zero` grew to 4.2 GB: the page is read with a limit
        // (a device is now refused before rendering; a regular file past
        // the limit still reaches it).
        let out = std::env::temp_dir().join(format!("tracer-docs-{}", std::process::id()));
        fs::create_dir_all(&out).unwrap();
        let page = out.join("big.md");
        fs::write(&page, vec![b'x'; shared::MAX_PAGE as usize + 1]).unwrap();
        let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
        options.out = out.join("frames");
        options.docs = Some(page);
        let failure = run(&options, &mut Vec::new()).unwrap_err();
        let _ = fs::remove_dir_all(&out);
        assert_eq!(failure.status(), 2, "{failure}");
        assert!(
            failure
                .to_string()
                .ends_with("big.md is larger than 4 MiB, the limit for a docs page"),
            "{failure}"
        );
    }

    #[test]
    fn a_docs_path_that_is_not_a_regular_file_is_refused_before_rendering() {
        // `--docs FIFO` blocked forever opening the FIFO; `/dev/zero` and
        // `/dev/full` were refused only after the render.
        if !cfg!(target_os = "linux") {
            return;
        }
        let out = std::env::temp_dir().join(format!("tracer-fifo-{}", std::process::id()));
        fs::create_dir_all(&out).unwrap();
        let fifo = out.join("page.fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        let mut refused = vec![
            (PathBuf::from("/dev/zero"), "a device"),
            (PathBuf::from("/dev/full"), "a device"),
            (out.clone(), "a directory"),
        ];
        if made.is_ok_and(|status| status.success()) {
            refused.push((fifo, "a FIFO"));
        }
        for (path, kind) in refused {
            let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
            options.out = out.join("frames");
            options.docs = Some(path.clone());
            let failure = run(&options, &mut Vec::new()).unwrap_err();
            let message = failure.to_string();
            assert_eq!(failure.status(), 2, "{message}");
            assert_eq!(
                message,
                format!(
                    "--docs {}: {kind}, not a regular file; a page to rewrite must be one",
                    path.display()
                )
            );
            // Nothing was rendered.
            assert!(!out.join("frames/polygon-4x4-box").exists(), "{message}");
        }
        // A page that does not exist yet is made.
        let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
        options.out = out.join("frames");
        options.docs = Some(out.join("new/page.md"));
        run(&options, &mut Vec::new()).unwrap();
        let page = fs::read_to_string(out.join("new/page.md")).unwrap();
        let _ = fs::remove_dir_all(&out);
        assert!(page.contains("polygon"), "{page}");
    }

    #[test]
    fn a_missing_report_folder_is_made() {
        // One behaviour for every tool: missing output folders are created.
        let out = std::env::temp_dir().join(format!("tracer-report-{}", std::process::id()));
        let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
        options.out = out.join("frames");
        let report = out.join("missing/folder/report.json");
        options.report = Some(report.clone());
        run(&options, &mut Vec::new()).unwrap();
        let written = fs::read_to_string(&report).unwrap();
        let _ = fs::remove_dir_all(&out);
        assert!(written.starts_with('['), "{written}");
    }

    #[test]
    fn a_run_ends_by_listing_the_pictures_it_wrote() {
        let out = std::env::temp_dir().join(format!("tracer-pictures-{}", std::process::id()));
        let mut options = run_options(&["--scene", "polygon", "--spp", "1", "--size", "4"]);
        options.out = out.clone();
        let mut stdout = Vec::new();
        run(&options, &mut stdout).unwrap();
        let stdout = String::from_utf8(stdout).unwrap();
        let (_, list) = stdout.split_once("Pictures written:\n").unwrap();
        let dir = out.join("polygon-4x4-box");
        let contact = dir.join("contact-1spp.png");
        assert!(
            list.contains(&format!("- {}:", contact.display())),
            "{list}"
        );
        assert!(contact.is_file() && dir.join("error-1spp.png").is_file());
        assert!(list.contains("sobol-1spp.png"), "{list}");
        assert!(dir.join("sobol-1spp.png").is_file());
        assert!(stdout.trim_end().ends_with("reference.png"), "{stdout}");
        let _ = fs::remove_dir_all(&out);
    }

    #[test]
    fn help_and_bad_arguments_render_nothing() {
        let mut stdout = Vec::new();
        main_with(["--help"].map(OsString::from), &mut stdout).unwrap();
        let help = String::from_utf8(stdout).unwrap();
        assert!(help.contains("Usage: tracer [OPTIONS]"), "{help}");
        let failure = main_with(["--size", "3x"].map(OsString::from), &mut Vec::new()).unwrap_err();
        assert_eq!(failure.status(), 2, "{failure}");
    }

    #[test]
    fn off_light_leaves_out_the_light_and_its_margin() {
        let mut reference = Image {
            width: 12,
            height: 9,
            pixels: vec![[0.5; 3]; 12 * 9],
        };
        reference.pixels[4 * 12 + 5] = [0.5, 17.0, 0.5];
        let mask = off_light(&reference);
        for y in 0..9u32 {
            for x in 0..12u32 {
                let near = x.abs_diff(5) <= LIGHT_MARGIN && y.abs_diff(4) <= LIGHT_MARGIN;
                assert_eq!(mask[(y * 12 + x) as usize], !near, "{x} {y}");
            }
        }
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
