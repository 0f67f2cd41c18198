//! The tracer's command line: the options, their parsing and checks, and
//! the help text. Errors are one line with exit status 2, through the
//! examples' shared plumbing (`examples/shared/cli.rs`).

use std::ffi::OsString;
use std::io::Write;
use std::path::PathBuf;

use clap::Parser;
use wellspread::filter::FilterKind;

use crate::cornell::{Draws, Light, MAX_BOUNCES};
use crate::render::{FilterMode, TracerSampler};
use crate::scenes::{Built, SceneKind};
use crate::shared::{self, Failure};

/// What the tracer writes and how it exits; shown under `--help`.
const HELP: &str = "\
What runs: with none of --scene, --sampler, --spp, --full and --docs, a
short run (seconds on two cores, the references included): checker
192x192 and cornell 64x64 at 16 spp with random, jittered, sobol and
zsobol (and pcg32 in cornell), the trade tables on stdout, then the paths
of the pictures and contact sheets it wrote. --full is the measurement
run: every scene at its sizes, every sampler, each scene's counts (1, 4,
16, 64, 256; 4, 16 for cornell at 128x128). With --scene, --sampler or
--spp, a list not given is the full one (every scene, every sampler, each
scene's counts and sizes). --docs writes the docs page's tables, so it
implies --full.

Output, under --out (default out/), per scene as <scene>-<W>x<H>-<filter>/
(<scene>-<W>x<H>-<filter>-<mode>/ for the sampled --filter-mode values,
cornell-<W>x<H>-box-area-light/ for --light area, -call-order and
-depth<N> added for --draws call-order and --max-depth N):
  reference.png              the reference image every RMSE is measured
                             against: what infinitely many samples would give
                             under the same filter (exact or quadrature where
                             the scene allows, else 4096 samples per pixel;
                             cornell: 4096 Sobol' samples per pixel);
                             cached as out/reference-*.bin
  <sampler>-<spp>spp.png     each frame (the first one's)
  contact-<spp>spp.png       the reference and every sampler, cropped to
                             where the scene aliases, labelled with RMSE
  error-<spp>spp.png         each sampler's error image (frame - reference),
                             same crop, grey = 0, black/white = -/+ 4x the
                             smallest RMSE in the sheet
  error-spectrum-<spp>spp.svg radially averaged periodogram of the error
                             image (frame - reference), one line per sampler,
                             low frequencies on the left, averaged over frames
  trade.svg                  RMSE against seconds per frame, log-log
With more than one filter or filter mode, one table compares them (RMSE /
blurred RMSE per sampler and filter, each mode side by side), and
filters-<scene>-<W>x<H>-<spp>spp.png under --out is a contact sheet of
the first sampler's crop: one row per filter, the reference then each mode.
The markdown tables go to stdout; --report writes the rows as JSON
(scene, filter, filter_mode, light, draws, max_depth, sampler, spp, rmse,
blurred_rmse, top_rmse, off_light_rmse, low_frequency_power, seconds, frames, width,
height) and --docs
the tables as a markdown page headed by the command and machine (on a page
that has them, only the text between the tracer's markers is replaced; a
--light comparison and a --draws or --max-depth run have markers of their
own).
With two --light values the cornell frames of the two take turns at each
sampler and count, so that their times meet the same machine load.
With --frames K (default 1, 4 for cornell, whose path-traced error is
noisier), rmse and blurred_rmse are root-mean-square over the K frames.

Output paths are checked before rendering starts.";

/// The largest count accepted on the command line: a 4096 x 4096 grid,
/// beyond which a single frame takes minutes anyway.
const MAX_SPP: u32 = 1 << 24;
const MAX_SIDE: u32 = 16_384;
/// Most frames per row on the command line.
const MAX_FRAMES: u32 = 1024;

/// Renders the aliasing scenes (checker, moire, moire-resolved, polygon)
/// and a path-traced Cornell box (cornell) with every pixel sampler at
/// several sample counts, measures RMSE and blurred
/// RMSE against a cached reference, writes PNGs, contact sheets,
/// error spectra and error-vs-time plots, and prints the trade table.
#[derive(Debug, Parser)]
pub struct Cli {
    /// Comma-separated scenes: checker, moire, moire-resolved, polygon,
    /// cornell (box filter only) [default: all]
    #[arg(long = "scene", value_name = "LIST", value_delimiter = ',', value_parser = parse_scene)]
    scenes: Vec<SceneKind>,
    /// Comma-separated samplers, from those listed below [default: all]
    #[arg(long = "sampler", value_name = "LIST", value_delimiter = ',', value_parser = parse_sampler)]
    samplers: Vec<TracerSampler>,
    /// Comma-separated samples per pixel for every scene, each in
    /// 1..=16777216 [default: 1,4,16,64,256; 4,16 for cornell]
    #[arg(long = "spp", value_name = "LIST", value_delimiter = ',', value_parser = parse_spp)]
    spps: Vec<u32>,
    /// Film size for every scene, N or WxH, sides in 1..=16384 [default:
    /// 192x192 for checker and the moires; 5x7 and 64x64 for polygon;
    /// 128x128 for cornell]
    #[arg(long, value_name = "N|WxH", value_parser = parse_size)]
    size: Option<(u32, u32)>,
    /// Comma-separated reconstruction filters: box, tent, gaussian,
    /// mitchell, lanczos, blackman-harris [default: box]
    #[arg(long = "filter", value_name = "LIST", value_delimiter = ',', value_parser = parse_filter)]
    filters: Vec<FilterKind>,
    /// Comma-separated filter modes: weighted (box samples splatted with
    /// the filter's weight), importance (samples drawn from the filter,
    /// pbrt-v4's sum(w L) / sum(w)), importance-mean (the same samples,
    /// sum(w L) / n) [default: weighted]
    #[arg(long = "filter-mode", value_name = "LIST", value_delimiter = ',', value_parser = parse_filter_mode)]
    modes: Vec<FilterMode>,
    /// Comma-separated light sampling of cornell's next-event estimation:
    /// solid-angle (directions uniform in the light's solid angle,
    /// warp::spherical_rectangle), area (points uniform on the light);
    /// with both, cornell alone renders under each and one table compares
    /// them [default: solid-angle]
    #[arg(long = "light", value_name = "LIST", value_delimiter = ',', value_parser = parse_light)]
    lights: Vec<Light>,
    /// Comma-separated draw layouts of cornell's paths: keyed (one branch
    /// key per bounce and purpose), call-order (every number a successive
    /// draw of the sample's root domain); pcg32 is call order always and
    /// renders once. With both, or with --max-depth, the tables label each
    /// row with its layout [default: keyed]
    #[arg(long = "draws", value_name = "LIST", value_delimiter = ',', value_parser = parse_draws)]
    draws: Vec<Draws>,
    /// Bounces a cornell path makes at most, 1..=32: 1 is direct light
    /// only (the camera ray's hit, next-event estimation there); its
    /// reference is rendered at the same depth [default: 32]
    #[arg(long = "max-depth", value_name = "N", value_parser = parse_depth)]
    max_depth: Option<u32>,
    /// First frame (what a renderer passes per frame: the `frame` of
    /// pattern_seed, Padded, ZSobol and BlueNoise), 0 to 4294967295
    #[arg(long, alias = "seed", value_name = "N", default_value = "0", value_parser = shared::whole_number)]
    frame: u32,
    /// Frames per row, frame..=frame+K-1 (which must not pass
    /// 4294967295); errors are RMS over them [default: 1; 4 for cornell]
    #[arg(long, alias = "seeds", value_name = "K", value_parser = parse_frames)]
    frames: Option<u32>,
    /// RMSE the "to reach" columns aim at (positive)
    #[arg(long, value_name = "RMSE", default_value_t = 0.01, value_parser = parse_target)]
    target: f64,
    /// Output directory (missing folders are created)
    #[arg(long, value_name = "DIR", default_value = "out")]
    out: PathBuf,
    /// Also write the rows as a JSON array to FILE (missing folders are
    /// created)
    #[arg(long, value_name = "FILE")]
    report: Option<PathBuf>,
    /// Also write the tables as a markdown page to FILE, headed by the
    /// command and the machine (missing folders are created; an existing
    /// FILE must be a regular file)
    #[arg(long, value_name = "FILE")]
    docs: Option<PathBuf>,
    /// The measurement run: every scene, sampler and count (the default
    /// without --scene, --sampler, --spp is a short run instead)
    #[arg(long)]
    full: bool,
}

/// The short run's scenes, samplers (pcg32 renders cornell only) and
/// count: what the README's first command renders, a few seconds on two
/// cores including the references a fresh clone has not cached.
const SHORT_SCENES: [SceneKind; 2] = [SceneKind::Checker, SceneKind::Cornell];
const SHORT_SAMPLERS: [&str; 5] = ["random", "jittered", "sobol", "zsobol", "pcg32"];
const SHORT_SPP: u32 = 16;
/// cornell in the short run: a quarter of the full run's pixels, so that
/// its reference (4096 samples per pixel) takes seconds, not a minute.
const SHORT_CORNELL_SIZE: (u32, u32) = (64, 64);

/// The run, with defaults filled in and lists deduplicated.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    pub scenes: Vec<SceneKind>,
    pub samplers: Vec<TracerSampler>,
    /// The counts `--spp` asked for, ascending; `None`: each scene's own.
    pub spps: Option<Vec<u32>>,
    pub size: Option<(u32, u32)>,
    /// The filters, in the order given.
    pub filters: Vec<FilterKind>,
    /// The filter modes, in the order given.
    pub modes: Vec<FilterMode>,
    /// How cornell samples its light, in the order given.
    pub lights: Vec<Light>,
    /// cornell's draw layouts, in the order given.
    pub draws: Vec<Draws>,
    /// The `--max-depth` asked for; `None`: [`MAX_BOUNCES`].
    pub max_depth: Option<u32>,
    pub frame: u32,
    /// The `--frames` asked for; `None`: each scene's own.
    pub frames: Option<u32>,
    pub target: f64,
    pub out: PathBuf,
    pub report: Option<PathBuf>,
    pub docs: Option<PathBuf>,
    /// The short run (no --scene, --sampler, --spp, --full or --docs):
    /// cornell renders at [`SHORT_CORNELL_SIZE`] unless --size says.
    pub short: bool,
    /// One-line notes for standard error: the samplers asked for that do
    /// not apply to a scene of the run, and the scenes left out for it.
    pub notes: Vec<String>,
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

impl Options {
    /// The run `cli` asks for. The one check clap cannot make alone: the
    /// frames `frame..=frame + frames - 1` must all be u32s, for every scene's
    /// count. They are rejected rather than wrapped to 0, 1, ..., so that
    /// the range the run reports is the range it renders.
    fn from_cli(cli: Cli) -> Result<Self, Failure> {
        // The path tracer has no wide filters: a run of every scene leaves
        // it out, and asking for it is an error.
        let path_traced = |scene: &SceneKind| matches!(scene.build(1, 1), Built::PathTraced);
        let filters = if cli.filters.is_empty() {
            vec![FilterKind::Box]
        } else {
            dedup(cli.filters)
        };
        let modes = if cli.modes.is_empty() {
            vec![FilterMode::Weighted]
        } else {
            dedup(cli.modes)
        };
        let box_only = filters == [FilterKind::Box] && modes == [FilterMode::Weighted];
        if !box_only && let Some(scene) = cli.scenes.iter().find(|s| path_traced(s)) {
            let names: Vec<&str> = filters.iter().map(|f| f.name()).collect();
            let mode_names: Vec<&str> = modes.iter().map(|m| m.name()).collect();
            return Err(Failure::Input(format!(
                "--scene {scene} renders with the box filter, weighted, only, not --filter {} --filter-mode {}",
                names.join(","),
                mode_names.join(",")
            )));
        }
        let short = !cli.full
            && cli.docs.is_none()
            && cli.scenes.is_empty()
            && cli.samplers.is_empty()
            && cli.spps.is_empty();
        let default_scenes: &[SceneKind] = if short {
            &SHORT_SCENES
        } else {
            &SceneKind::ALL
        };
        let all_scenes: Vec<SceneKind> = default_scenes
            .iter()
            .copied()
            .filter(|scene| box_only || !path_traced(scene))
            .collect();
        let spps = if short { vec![SHORT_SPP] } else { cli.spps };
        let spps = (!spps.is_empty()).then(|| {
            let mut spps = dedup(spps);
            // Ascending, for the log-log interpolation between counts.
            spps.sort_unstable();
            spps
        });
        let scenes = or_all(cli.scenes, all_scenes);
        let asked_samplers = !cli.samplers.is_empty();
        let all_samplers = if short {
            let parse = |name: &str| name.parse().expect("a short-run sampler name");
            SHORT_SAMPLERS.map(parse).to_vec()
        } else {
            TracerSampler::all()
        };
        let samplers = or_all(cli.samplers, all_samplers);
        let (scenes, notes) = scenes_with_samplers(scenes, &samplers, asked_samplers)?;
        let lights = or_all(cli.lights, vec![Light::default()]);
        if lights.len() > 1
            && let Some(scene) = scenes.iter().find(|s| !path_traced(s))
        {
            let names: Vec<&str> = lights.iter().map(|l| l.name()).collect();
            return Err(Failure::Input(format!(
                "--light {} compares light sampling in cornell only, not in {scene}: add --scene cornell",
                names.join(",")
            )));
        }
        let draws = or_all(cli.draws, vec![Draws::default()]);
        let path_options = draws != [Draws::default()] || cli.max_depth.is_some();
        if path_options && let Some(scene) = scenes.iter().find(|s| !path_traced(s)) {
            return Err(Failure::Input(format!(
                "--draws and --max-depth trace cornell's paths only, not {scene}'s: add --scene cornell"
            )));
        }
        if draws.len() > 1 && lights.len() > 1 {
            return Err(Failure::Input(
                "compare --light or --draws, one at a time: give one of them a single value"
                    .to_owned(),
            ));
        }
        let frames = cli.frames.unwrap_or_else(|| {
            let most = scenes.iter().map(|s| s.default_frames()).max();
            most.unwrap_or(1)
        });
        let last_frame = u64::from(cli.frame) + u64::from(frames) - 1;
        if last_frame > u64::from(u32::MAX) {
            let what = match cli.frames {
                Some(k) => format!("--frames {k}"),
                None => format!("the default {frames} frames"),
            };
            return Err(Failure::Input(format!(
                "--frame {} with {what} runs to frame {last_frame}, past the last one, {}; \
                 use a --frame of at most {} or fewer --frames",
                cli.frame,
                u32::MAX,
                u32::MAX - (frames - 1),
            )));
        }
        Ok(Self {
            scenes,
            samplers,
            spps,
            size: cli.size,
            filters,
            modes,
            lights,
            draws,
            max_depth: cli.max_depth,
            frame: cli.frame,
            frames: cli.frames,
            target: cli.target,
            out: cli.out,
            report: cli.report,
            docs: cli.docs,
            short,
            notes,
        })
    }

    /// The samplers `scene` renders with, in the order given
    /// (`sobol-pairs` only where there is a lens).
    pub fn samplers_for(&self, scene: SceneKind) -> Vec<TracerSampler> {
        self.samplers
            .iter()
            .copied()
            .filter(|sampler| sampler.renders(scene))
            .collect()
    }

    /// The sample counts `scene` renders at, ascending.
    pub fn spps_for(&self, scene: SceneKind) -> Vec<u32> {
        self.spps
            .clone()
            .unwrap_or_else(|| scene.default_spps().to_vec())
    }

    /// The film sizes `scene` renders at.
    pub fn sizes_for(&self, scene: SceneKind) -> Vec<(u32, u32)> {
        match self.size {
            Some(size) => vec![size],
            None if self.short && scene == SceneKind::Cornell => vec![SHORT_CORNELL_SIZE],
            None => scene.default_sizes().to_vec(),
        }
    }

    /// Frames per row for `scene`.
    pub fn frames_for(&self, scene: SceneKind) -> u32 {
        self.frames.unwrap_or_else(|| scene.default_frames())
    }

    /// How `scene` samples its light, one render per entry: the `--light`
    /// list for the path-traced scene, the default (unused) for the others.
    pub fn lights_for(&self, scene: SceneKind) -> Vec<Light> {
        match scene.build(1, 1) {
            Built::PathTraced => self.lights.clone(),
            Built::Film(_) => vec![Light::default()],
        }
    }

    /// The bounces a cornell path makes at most.
    pub fn depth(&self) -> u32 {
        self.max_depth.unwrap_or(MAX_BOUNCES)
    }

    /// Whether the tables label rows with their draw layout: a comparison
    /// of layouts, or a depth asked for.
    pub fn labels_draws(&self) -> bool {
        self.draws.len() > 1 || self.max_depth.is_some()
    }

    /// The draw layouts `scene` renders `sampler` with: cornell's
    /// `--draws` list, but pcg32, call order whatever the layout, once
    /// (under `call-order` when the list has it); one (unused) layout for
    /// the other scenes.
    pub fn draws_for(&self, scene: SceneKind, sampler: TracerSampler) -> Vec<Draws> {
        match scene.build(1, 1) {
            Built::Film(_) => vec![Draws::default()],
            Built::PathTraced if sampler == TracerSampler::Pcg32 => {
                let call_order = self.draws.contains(&Draws::CallOrder);
                vec![if call_order {
                    Draws::CallOrder
                } else {
                    self.draws[0]
                }]
            }
            Built::PathTraced => self.draws.clone(),
        }
    }

    /// The frames of `scene`'s rows, in order: `frame..=frame + frames -
    /// 1`, which [`Options::from_cli`] checked to fit in a u32.
    pub fn frame_range(&self, scene: SceneKind) -> std::ops::RangeInclusive<u32> {
        self.frame..=self.frame + (self.frames_for(scene) - 1)
    }
}

/// The scenes of `scenes` that some sampler of `samplers` renders, a note
/// for the scenes left out, and one for each sampler `asked` for by name
/// that does not apply to a scene kept (`sobol-pairs` renders cornell
/// only). A run that no sampler applies to is an input error.
fn scenes_with_samplers(
    scenes: Vec<SceneKind>,
    samplers: &[TracerSampler],
    asked: bool,
) -> Result<(Vec<SceneKind>, Vec<String>), Failure> {
    let names = |scenes: &mut dyn Iterator<Item = &SceneKind>| {
        scenes
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (kept, left_out): (Vec<SceneKind>, Vec<SceneKind>) = scenes
        .into_iter()
        .partition(|&scene| samplers.iter().any(|s| s.renders(scene)));
    let sampler_names: Vec<&str> = samplers.iter().map(|s| s.name()).collect();
    if kept.is_empty() {
        return Err(Failure::Input(format!(
            "no sampler of --sampler {} applies to --scene {}: nothing to render",
            sampler_names.join(","),
            names(&mut left_out.iter()).replace(", ", ",")
        )));
    }
    let mut notes = Vec::new();
    if !left_out.is_empty() {
        notes.push(format!(
            "note: no sampler of --sampler {} applies to {}: left out",
            sampler_names.join(","),
            names(&mut left_out.iter())
        ));
    }
    for &sampler in samplers.iter().filter(|_| asked) {
        let skipped = names(&mut kept.iter().filter(|&&s| !sampler.renders(s)));
        if !skipped.is_empty() {
            let renders = names(&mut SceneKind::ALL.iter().filter(|&&s| sampler.renders(s)));
            notes.push(format!(
                "note: --sampler {sampler} does not apply to {skipped} \
                 (it renders {renders} only): skipped there"
            ));
        }
    }
    Ok((kept, notes))
}

/// Parses the arguments after the program name. `Ok(None)`: `--help` was
/// written to `help_out` and the tool stops with status 0. Every error is
/// [`Failure::Input`], one line, exit status 2.
pub fn parse(
    args: impl IntoIterator<Item = OsString>,
    help_out: &mut dyn Write,
) -> Result<Option<Options>, Failure> {
    let names: Vec<&str> = TracerSampler::all().iter().map(|s| s.name()).collect();
    let after_help = format!(
        "Samplers: {}\n(the library's pixel samplers, any case or alias such as cmj; in cornell\n\
         each draws film and lens as one 4D point, and sobol-pairs, cornell only, is\n\
         sobol drawing them as two 2D pairs; pcg32, cornell only, is not the crate:\n\
         rand_pcg's Pcg32 per pixel sample, every number of a path in call order,\n\
         the baseline of the ratio table; joint-sobol and joint-sobol-4d,\n\
         cornell only, are the candidates of docs/joint_study.md, not the crate)\n\n{HELP}\n\n{}",
        names.join(" "),
        shared::EXIT_CODES
    );
    match shared::parse::<Cli>("tracer", &after_help, args, help_out)? {
        Some(cli) => Options::from_cli(cli).map(Some),
        None => Ok(None),
    }
}

fn parse_scene(text: &str) -> Result<SceneKind, String> {
    text.parse()
}

fn parse_sampler(text: &str) -> Result<TracerSampler, String> {
    text.parse()
}

fn parse_filter(text: &str) -> Result<FilterKind, String> {
    text.parse()
        .map_err(|error: wellspread::Error| error.to_string())
}

fn parse_filter_mode(text: &str) -> Result<FilterMode, String> {
    text.parse()
}

fn parse_light(text: &str) -> Result<Light, String> {
    text.parse()
}

fn parse_draws(text: &str) -> Result<Draws, String> {
    text.parse()
}

fn parse_depth(text: &str) -> Result<u32, String> {
    parse_count(text, MAX_BOUNCES)
}

fn parse_count(text: &str, max: u32) -> Result<u32, String> {
    shared::non_negative(text)?;
    match text.parse::<u32>() {
        Ok(n) if (1..=max).contains(&n) => Ok(n),
        _ => Err(format!("{text:?} is not an integer in 1..={max}")),
    }
}

fn parse_spp(text: &str) -> Result<u32, String> {
    parse_count(text, MAX_SPP)
}

fn parse_frames(text: &str) -> Result<u32, String> {
    parse_count(text, MAX_FRAMES)
}

/// `N` or `WxH`. The error quotes the whole value, whichever side is bad.
fn parse_size(text: &str) -> Result<(u32, u32), String> {
    shared::non_negative(text)?;
    let (w, h) = text.split_once('x').unwrap_or((text, text));
    let side = |s: &str| s.parse::<u32>().ok().filter(|n| (1..=MAX_SIDE).contains(n));
    match (side(w), side(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(format!(
            "{text:?} is not a film size: use N or WxH with whole sides in 1..={MAX_SIDE}"
        )),
    }
}

fn parse_target(text: &str) -> Result<f64, String> {
    shared::non_negative(text)?;
    text.parse()
        .ok()
        .filter(|t: &f64| t.is_finite() && *t > 0.0)
        .ok_or_else(|| format!("{} is not a positive number", shared::quoted(text)))
}
#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::render::SOBOL;
    use wellspread::{PixelSamplerKind, SamplerKind};

    fn args(list: &[&str]) -> Vec<OsString> {
        list.iter().map(OsString::from).collect()
    }

    pub(crate) fn run_options(list: &[&str]) -> Options {
        match parse(args(list), &mut Vec::new()) {
            Ok(Some(options)) => options,
            other => panic!("{list:?}: {other:?}"),
        }
    }

    /// The message of a bad command line, checked to be a one-line input
    /// failure that `tracer: ` prefixes and that exits with status 2.
    fn usage_error(list: &[&str]) -> String {
        match parse(args(list), &mut Vec::new()) {
            Err(failure @ Failure::Input(_)) => {
                let mut stderr = Vec::new();
                let status = shared::finish("tracer", Err(failure.clone()), &mut stderr);
                let stderr = String::from_utf8(stderr).unwrap();
                assert_eq!(status, 2, "{list:?}");
                assert_eq!(stderr.lines().count(), 1, "{list:?}: {stderr}");
                assert!(stderr.starts_with("tracer: "), "{list:?}: {stderr}");
                failure.to_string()
            }
            other => panic!("{list:?} should be a usage error, got {other:?}"),
        }
    }

    #[test]
    fn no_arguments_mean_the_short_run() {
        let options = run_options(&[]);
        assert!(options.short);
        assert_eq!(options.scenes, [SceneKind::Checker, SceneKind::Cornell]);
        let names: Vec<&str> = options.samplers.iter().map(|s| s.name()).collect();
        assert_eq!(names, ["random", "jittered", "sobol", "zsobol", "pcg32"]);
        assert_eq!(options.spps, Some(vec![16]));
        assert_eq!(options.sizes_for(SceneKind::Checker), [(192, 192)]);
        assert_eq!(options.sizes_for(SceneKind::Cornell), [(64, 64)]);
        // pcg32 is cornell's only: no note, as for every default list.
        assert_eq!(options.samplers_for(SceneKind::Checker).len(), 4);
        assert_eq!(options.notes, Vec::<String>::new());
        assert_eq!(options.frame_range(SceneKind::Cornell), 0..=3);
        assert_eq!(options.out, PathBuf::from("out"));
        // --size and the other modifiers keep the short selection.
        let options = run_options(&["--size", "32", "--frames", "1"]);
        assert!(options.short);
        assert_eq!(options.sizes_for(SceneKind::Cornell), [(32, 32)]);
        assert_eq!(options.spps, Some(vec![16]));
        // A wide filter leaves cornell out of the short run too.
        assert_eq!(
            run_options(&["--filter", "tent"]).scenes,
            [SceneKind::Checker]
        );
    }

    #[test]
    fn full_and_docs_mean_everything() {
        for list in [
            &["--full"][..],
            &["--docs", "d.md"],
            &["--full", "--docs", "d.md"],
        ] {
            let options = run_options(list);
            assert!(!options.short, "{list:?}");
            assert_eq!(options.scenes, SceneKind::ALL);
            assert_eq!(options.samplers, TracerSampler::all());
            assert!(
                options
                    .samplers
                    .contains(&TracerSampler::Pixel(PixelSamplerKind::ZSobol))
            );
            assert_eq!(options.spps, None);
            for scene in SceneKind::ALL {
                assert_eq!(options.spps_for(scene), scene.default_spps());
                assert_eq!(options.sizes_for(scene), scene.default_sizes());
            }
            assert_eq!(options.filters, [FilterKind::Box]);
            assert_eq!(options.modes, [FilterMode::Weighted]);
            assert_eq!((options.frame, options.frames), (0, None));
            assert_eq!(options.frame_range(SceneKind::Moire), 0..=0);
            assert_eq!(options.frame_range(SceneKind::Cornell), 0..=3);
        }
        // Any list flag is a measurement run: the lists not given are full.
        for (flag, value) in [
            ("--scene", "cornell"),
            ("--sampler", "sobol"),
            ("--spp", "4"),
        ] {
            let options = run_options(&[flag, value]);
            assert!(!options.short, "{flag}");
            assert_eq!(
                options.sizes_for(SceneKind::Cornell),
                [(128, 128)],
                "{flag}"
            );
        }
        let options = run_options(&["--scene", "cornell"]);
        assert_eq!(options.samplers, TracerSampler::all());
        assert_eq!(options.spps_for(SceneKind::Cornell), [4, 16]);
        let options = run_options(&["--spp", "4"]);
        assert_eq!(options.scenes, SceneKind::ALL);
        assert_eq!(options.samplers, TracerSampler::all());
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
            "--frame",
            "9",
            "--frames=4",
            "--report",
            "r.json",
            "--docs",
            "d.md",
        ]);
        assert_eq!(options.scenes, [SceneKind::Moire, SceneKind::Checker]);
        assert_eq!(
            options.samplers,
            [
                TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Regular)),
                TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::NRooks)),
                TracerSampler::Pixel(PixelSamplerKind::ZSobol)
            ]
        );
        assert_eq!(options.spps_for(SceneKind::Moire), [4, 16]);
        assert_eq!(options.size, Some((32, 8)));
        assert_eq!(options.filters, [FilterKind::Mitchell]);
        assert_eq!((options.frame, options.frames), (9, Some(4)));
        assert_eq!(options.frame_range(SceneKind::Moire), 9..=12);
        assert_eq!(options.report, Some(PathBuf::from("r.json")));
        assert_eq!(options.docs, Some(PathBuf::from("d.md")));
        assert_eq!(run_options(&["--size", "100"]).size, Some((100, 100)));
        assert_eq!(
            run_options(&["--scene", "moire-resolved"]).scenes,
            [SceneKind::MoireResolved]
        );
    }

    #[test]
    fn bad_command_lines_are_one_line_with_status_2_and_name_the_item() {
        for (bad, named) in [
            (&["--scene", "teapot"][..], "teapot"),
            (&["--sampler", "best"], "best"),
            (&["--spp", "0"], "\"0\""),
            (&["--spp", "4,,16"], "\"\""),
            (&["--size", "0x4"], "\"0x4\""),
            (&["--size", "big"], "\"big\""),
            (&["--filter", "sinc"], "sinc"),
            (&["--filter-mode", "splat"], "splat"),
            (&["--frame", "-1"], "must be non-negative"),
            (
                &["--spp", "4,-1"],
                "the value must be non-negative, got \"-1\"",
            ),
            (
                &["--spp", "-1"],
                "the value must be non-negative, got \"-1\"",
            ),
            (
                &["--size", "-4"],
                "the value must be non-negative, got \"-4\"",
            ),
            (
                &["--size", "8x-8"],
                "the value must be non-negative, got \"8x-8\"",
            ),
            (
                &["--frames", "-1"],
                "the value must be non-negative, got \"-1\"",
            ),
            (
                &["--seeds", "-1"],
                "--frames <K>: the value must be non-negative, got \"-1\"",
            ),
            (&["--frame", "4294967296"], "4294967296"),
            (&["--frames", "0"], "0"),
            (&["--frames", "1025"], "1025"),
            (&["--target", "0"], "\"0\""),
            (
                &["--target", "-1"],
                "--target <RMSE>: the value must be non-negative, got \"-1\"",
            ),
            (&["--spp"], "--spp"),
            (&["--frobnicate"], "--frobnicate"),
        ] {
            let message = usage_error(bad);
            assert!(message.contains(named), "{bad:?}: {message}");
        }
        let message = usage_error(&["--sampler", "regular,jitterd"]);
        assert!(message.contains("unknown sampler \"jitterd\""), "{message}");
        for sampler in TracerSampler::all() {
            assert!(message.contains(sampler.name()), "{sampler}: {message}");
        }
    }

    #[test]
    fn a_sampler_that_does_not_apply_to_a_scene_is_a_note_and_none_is_an_error() {
        // sobol-pairs renders cornell only: it used to be dropped silently.
        let options = run_options(&["--scene", "moire,cornell", "--sampler", "sobol,sobol-pairs"]);
        assert_eq!(options.scenes, [SceneKind::Moire, SceneKind::Cornell]);
        assert_eq!(options.samplers_for(SceneKind::Moire), [SOBOL]);
        assert_eq!(
            options.notes,
            [
                "note: --sampler sobol-pairs does not apply to moire (it renders cornell only): \
              skipped there"
            ]
        );
        // A scene no sampler applies to is left out, with a note.
        let options = run_options(&["--scene", "polygon,cornell", "--sampler", "sobol-pairs"]);
        assert_eq!(options.scenes, [SceneKind::Cornell]);
        assert_eq!(
            options.notes,
            ["note: no sampler of --sampler sobol-pairs applies to polygon: left out"]
        );
        // No sampler at all: exit status 2.
        let message = usage_error(&["--scene", "moire,checker", "--sampler", "sobol-pairs"]);
        assert_eq!(
            message,
            "no sampler of --sampler sobol-pairs applies to --scene moire,checker: nothing to render"
        );
        // Every sampler by default: no notes, even where sobol-pairs is
        // left out.
        let options = run_options(&["--scene", "moire"]);
        assert_eq!(options.notes, Vec::<String>::new());
        assert!(options.samplers.contains(&TracerSampler::SobolPairs));
        // A note per fact, each one line.
        let options = run_options(&["--sampler", "sobol-pairs"]);
        assert_eq!(options.scenes, [SceneKind::Cornell]);
        assert_eq!(options.notes.len(), 1, "{:?}", options.notes);
        assert!(!options.notes[0].contains('\n'), "{:?}", options.notes);
    }

    #[test]
    fn every_output_option_says_missing_folders_are_created() {
        let mut out = Vec::new();
        parse(args(&["--help"]), &mut out).unwrap();
        let help = String::from_utf8(out).unwrap();
        for option in ["--out <DIR>", "--report <FILE>", "--docs <FILE>"] {
            let (_, after) = help.split_once(option).unwrap();
            let text = after.split("\n  -").next().unwrap();
            let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
            assert!(
                text.contains("missing folders are created"),
                "{option}: {text}"
            );
        }
    }

    #[test]
    fn light_sampling_is_solid_angle_unless_asked() {
        assert_eq!(run_options(&[]).lights, [Light::SolidAngle]);
        let options = run_options(&["--scene", "cornell", "--light", "area,solid-angle,area"]);
        assert_eq!(options.lights, [Light::Area, Light::SolidAngle]);
        assert_eq!(options.lights_for(SceneKind::Cornell), options.lights);
        assert_eq!(
            run_options(&["--light", "Area"]).lights_for(SceneKind::Moire),
            [Light::SolidAngle]
        );
        let message = usage_error(&["--scene", "cornell", "--light", "sphere"]);
        assert!(
            message.contains("\"sphere\" is not a light sampling: use solid-angle or area"),
            "{message}"
        );
        // A comparison renders cornell alone.
        let message = usage_error(&["--light", "area,solid-angle"]);
        assert!(message.contains("add --scene cornell"), "{message}");
    }

    #[test]
    fn draws_and_max_depth_parse_as_cornell_options() {
        let options = run_options(&[]);
        assert_eq!(
            (options.draws.as_slice(), options.max_depth),
            (&[Draws::Keyed][..], None)
        );
        assert_eq!(options.depth(), MAX_BOUNCES);
        assert!(!options.labels_draws());
        let options = run_options(&[
            "--scene",
            "cornell",
            "--draws",
            "call-order,keyed,call-order",
            "--max-depth",
            "1",
        ]);
        assert_eq!(options.draws, [Draws::CallOrder, Draws::Keyed]);
        assert_eq!((options.max_depth, options.depth()), (Some(1), 1));
        assert!(options.labels_draws());
        // pcg32 renders once, under call order; the others under each.
        let pcg32 = TracerSampler::Pcg32;
        assert_eq!(
            options.draws_for(SceneKind::Cornell, pcg32),
            [Draws::CallOrder]
        );
        assert_eq!(options.draws_for(SceneKind::Cornell, SOBOL), options.draws);
        let keyed = run_options(&["--scene", "cornell", "--max-depth", "32"]);
        assert!(keyed.labels_draws());
        assert_eq!(keyed.draws_for(SceneKind::Cornell, pcg32), [Draws::Keyed]);
        // Bad values: one line, status 2, the value named.
        for (bad, named) in [
            (
                &["--scene", "cornell", "--draws", "random"][..],
                "unknown draw layout \"random\"",
            ),
            (&["--scene", "cornell", "--draws", "keyed,"], "\"\""),
            (
                &["--scene", "cornell", "--max-depth", "0"],
                "\"0\" is not an integer in 1..=32",
            ),
            (&["--scene", "cornell", "--max-depth", "33"], "\"33\""),
            (
                &["--scene", "cornell", "--max-depth", "-1"],
                "must be non-negative",
            ),
            (&["--scene", "cornell", "--max-depth", "one"], "\"one\""),
        ] {
            let message = usage_error(bad);
            assert!(message.contains(named), "{bad:?}: {message}");
        }
        let message = usage_error(&["--scene", "cornell", "--draws", "x"]);
        assert!(
            message.contains("keyed") && message.contains("call-order"),
            "{message}"
        );
        // cornell's paths only.
        for flags in [&["--max-depth", "1"][..], &["--draws", "call-order"]] {
            let message = usage_error(flags);
            assert!(
                message.contains("add --scene cornell"),
                "{flags:?}: {message}"
            );
            let message = usage_error(&[&["--scene", "moire"][..], flags].concat());
            assert!(message.contains("not moire's"), "{flags:?}: {message}");
        }
        let message = usage_error(&[
            "--scene",
            "cornell",
            "--light",
            "area,solid-angle",
            "--draws",
            "keyed,call-order",
        ]);
        assert!(message.contains("one at a time"), "{message}");
    }

    #[test]
    fn cornell_is_box_filtered_only() {
        let message = usage_error(&["--scene", "moire,cornell", "--filter", "gaussian"]);
        assert!(message.contains("--scene cornell"), "{message}");
        // A run of every scene under a wide filter leaves cornell out.
        let options = run_options(&["--full", "--filter", "mitchell"]);
        assert!(!options.scenes.contains(&SceneKind::Cornell));
        assert_eq!(options.scenes.len(), SceneKind::ALL.len() - 1);
        assert!(run_options(&[]).scenes.contains(&SceneKind::Cornell));
        // sobol-pairs renders cornell only.
        let options = run_options(&["--sampler", "sobol,sobol-pairs"]);
        assert_eq!(options.samplers_for(SceneKind::Moire), [SOBOL]);
        assert_eq!(
            options.samplers_for(SceneKind::Cornell),
            [SOBOL, TracerSampler::SobolPairs]
        );
    }

    #[test]
    fn every_filter_and_mode_parses_as_a_list() {
        let options = run_options(&[
            "--scene",
            "moire",
            "--filter",
            "box,tent,gaussian,mitchell,lanczos,blackman-harris,tent",
            "--filter-mode",
            "importance,weighted,importance-mean",
        ]);
        assert_eq!(options.filters, FilterKind::ALL);
        assert_eq!(
            options.modes,
            [
                FilterMode::Importance,
                FilterMode::Weighted,
                FilterMode::ImportanceMean
            ]
        );
        for &filter in FilterKind::ALL {
            assert_eq!(filter.name().parse(), Ok(filter));
        }
        let message = usage_error(&["--filter", "box,sinc"]);
        for filter in FilterKind::ALL {
            assert!(message.contains(filter.name()), "{filter}: {message}");
        }
        // Importance-sampled box is not the path tracer's mode either.
        let message = usage_error(&["--scene", "cornell", "--filter-mode", "importance"]);
        assert!(message.contains("--scene cornell"), "{message}");
    }

    #[test]
    fn a_bad_size_quotes_the_whole_value() {
        // Not the empty height after the `x`: the value as typed.
        for bad in ["3x", "x3", "3x0", "3x16385", "3y3", "3x3x3", ""] {
            let message = usage_error(&["--size", bad]);
            assert!(
                message.contains(&format!("{bad:?} is not a film size")),
                "{bad:?}: {message}"
            );
        }
        assert_eq!(run_options(&["--size", "16384x1"]).size, Some((16384, 1)));
    }

    #[test]
    fn frames_past_u32_max_are_rejected_not_wrapped() {
        let message = usage_error(&["--frame", "4294967295", "--frames", "3"]);
        assert!(message.contains("4294967297"), "{message}");
        assert!(message.contains("at most 4294967293"), "{message}");
        // The last frames that fit are accepted, and reported as used.
        let options = run_options(&["--frame", "4294967293", "--frames", "3"]);
        assert_eq!(
            options.frame_range(SceneKind::Checker),
            4294967293..=u32::MAX
        );
        // cornell's default 4 frames count too, unless it is left out.
        let message = usage_error(&["--frame", "4294967295"]);
        assert!(message.contains("the default 4 frames"), "{message}");
        assert!(message.contains("at most 4294967292"), "{message}");
        let options = run_options(&["--frame", "4294967295", "--scene", "moire"]);
        assert_eq!(options.frame_range(SceneKind::Moire), u32::MAX..=u32::MAX);
    }

    #[test]
    fn the_old_seed_flags_are_hidden_aliases() {
        // `frame`, never `seed`, for what a renderer passes per frame; the
        // old spellings still parse, and --help shows only the new ones.
        let options = run_options(&["--seed", "9", "--seeds", "4"]);
        assert_eq!((options.frame, options.frames), (9, Some(4)));
        let mut out = Vec::new();
        parse(args(&["--help"]), &mut out).unwrap();
        let help = String::from_utf8(out).unwrap();
        assert!(!help.contains("--seed"), "{help}");
    }

    #[test]
    fn help_lists_every_option_sampler_and_output() {
        let mut out = Vec::new();
        let parsed = parse(args(&["--spp", "4", "--help"]), &mut out).unwrap();
        assert_eq!(parsed, None);
        let help = String::from_utf8(out).unwrap();
        for option in [
            "--scene",
            "--sampler",
            "--spp",
            "--size",
            "--filter",
            "--filter-mode",
            "--light",
            "--draws",
            "--max-depth",
            "--frame ",
            "--frames",
            "--target",
            "--out",
            "--report",
            "--docs",
            "--full",
            "--help",
        ] {
            assert!(help.contains(option), "{option} missing from --help");
        }
        for sampler in TracerSampler::all() {
            assert!(
                help.contains(sampler.name()),
                "{sampler} missing from --help"
            );
        }
        for text in ["reference.png", "error-spectrum", "Exit status"] {
            assert!(help.contains(text), "{text} missing from --help");
        }
    }
}
