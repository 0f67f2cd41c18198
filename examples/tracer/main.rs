//! The classic aliasing scenes rendered with every wellspread sampler, and
//! the speed/accuracy trade measured.
//!
//! ```sh
//! cargo run --release --example tracer                       # everything
//! cargo run --release --example tracer -- --scene moire --sampler regular,jittered --spp 16
//! cargo run --release --example tracer -- --help
//! ```
//!
//! For each scene, size, sampler and sample count it renders a frame, times
//! it, and measures its RMSE against a reference image computed (or loaded
//! from `out/`) with the same reconstruction filter. It writes every frame
//! as a PNG, a labelled contact sheet per sample count, a log-log
//! error-versus-time SVG per scene, prints the trade table in markdown, and
//! with `--report` writes the rows as JSON.

mod output;
mod reference;
mod render;
mod scenes;

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use wellspread::SamplerKind;

use crate::output::{Crop, Picture, Series, Tile, contact_sheet, trade_plot_svg, viewing_zoom};
use crate::render::{Filter, Image, Patterns, render};
use crate::scenes::SceneKind;

const USAGE: &str = "\
usage: tracer [--scene LIST] [--sampler LIST] [--spp LIST] [--size N|WxH]
              [--filter box|gaussian|mitchell] [--seed N] [--target RMSE]
              [--out DIR] [--report FILE.json]

Renders the aliasing scenes (checker, moire, polygon) with every sampler at
several sample counts, measures RMSE against a cached reference, writes PNGs,
contact sheets and error-vs-time plots under --out, and prints the trade table.

  --scene LIST    comma-separated scenes (default: all)
  --sampler LIST  comma-separated sampler names (default: all)
  --spp LIST      comma-separated samples per pixel (default: 1,4,16,64,256)
  --size N|WxH    film size for every scene (default: 192x192 for checker and
                  moire; 5x7 and 64x64 for polygon)
  --filter NAME   reconstruction filter: box (default), gaussian, mitchell
  --seed N        pattern seed, the `frame` of pattern_seed (default: 0)
  --target RMSE   error the \"to reach\" columns aim at (default: 0.01)
  --out DIR       output directory (default: out/)
  --report FILE   also write the rows as a JSON array to FILE
  --help          this text";

/// The default sample counts: powers of four, so every count is a square
/// and each step should cut the error of a stratified pattern by at least 2.
const DEFAULT_SPP: [u32; 5] = [1, 4, 16, 64, 256];

/// The largest count accepted on the command line: a 4096 x 4096 grid,
/// beyond which a single frame takes minutes anyway.
const MAX_SPP: u32 = 1 << 24;
const MAX_SIDE: u32 = 16_384;

#[derive(Clone, Debug, PartialEq)]
struct Options {
    scenes: Vec<SceneKind>,
    samplers: Vec<SamplerKind>,
    spps: Vec<u32>,
    size: Option<(u32, u32)>,
    filter: Filter,
    seed: u32,
    target: f64,
    out: PathBuf,
    report: Option<PathBuf>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            scenes: SceneKind::ALL.to_vec(),
            samplers: SamplerKind::ALL.to_vec(),
            spps: DEFAULT_SPP.to_vec(),
            size: None,
            filter: Filter::Box,
            seed: 0,
            target: 0.01,
            out: PathBuf::from("out"),
            report: None,
        }
    }
}

/// What the command line asked for: a run, or the help text.
#[derive(Debug, PartialEq)]
enum Command {
    Run(Options),
    Help,
}

/// Parses `--flag value` and `--flag=value` arguments. Errors are one line.
fn parse_args(args: impl IntoIterator<Item = String>) -> Result<Command, String> {
    let mut options = Options::default();
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        if arg == "--help" || arg == "-h" {
            return Ok(Command::Help);
        }
        let (flag, inline_value) = match arg.split_once('=') {
            Some((flag, value)) => (flag.to_owned(), Some(value.to_owned())),
            None => (arg.clone(), None),
        };
        let known = [
            "--scene",
            "--sampler",
            "--spp",
            "--size",
            "--filter",
            "--seed",
            "--target",
            "--out",
            "--report",
        ];
        if !known.contains(&flag.as_str()) {
            return Err(format!("unknown argument {arg:?} (try --help)"));
        }
        let value = match inline_value {
            Some(value) => value,
            None => args
                .next()
                .ok_or_else(|| format!("{flag} needs a value (try --help)"))?,
        };
        match flag.as_str() {
            "--scene" => options.scenes = parse_list(&flag, &value, |s| s.parse())?,
            "--sampler" => {
                options.samplers =
                    parse_list(&flag, &value, |s| s.parse().map_err(|e| format!("{e}")))?;
            }
            "--spp" => {
                let mut spps = parse_list(&flag, &value, |s| parse_count(s, MAX_SPP))?;
                // Ascending, for the log-log interpolation between counts.
                spps.sort_unstable();
                options.spps = spps;
            }
            "--size" => options.size = Some(parse_size(&value)?),
            "--filter" => options.filter = value.parse().map_err(|e| format!("--filter: {e}"))?,
            "--seed" => {
                options.seed = value.parse().map_err(|_| {
                    format!("--seed: {value:?} is not an integer in 0..=4294967295")
                })?;
            }
            "--target" => {
                options.target = value
                    .parse()
                    .ok()
                    .filter(|t: &f64| t.is_finite() && *t > 0.0)
                    .ok_or_else(|| format!("--target: {value:?} is not a positive number"))?;
            }
            "--out" => options.out = PathBuf::from(value),
            "--report" => options.report = Some(PathBuf::from(value)),
            _ => unreachable!("checked against `known` above"),
        }
    }
    Ok(Command::Run(options))
}

/// A comma-separated list, each item parsed by `item`, duplicates dropped.
fn parse_list<T: PartialEq>(
    flag: &str,
    value: &str,
    item: impl Fn(&str) -> Result<T, String>,
) -> Result<Vec<T>, String> {
    let mut list = Vec::new();
    for part in value.split(',') {
        if part.is_empty() {
            return Err(format!("{flag}: empty item in {value:?}"));
        }
        let parsed = item(part).map_err(|e| format!("{flag}: {e}"))?;
        if !list.contains(&parsed) {
            list.push(parsed);
        }
    }
    Ok(list)
}

fn parse_count(text: &str, max: u32) -> Result<u32, String> {
    match text.parse::<u32>() {
        Ok(n) if (1..=max).contains(&n) => Ok(n),
        _ => Err(format!("{text:?} is not an integer in 1..={max}")),
    }
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text.split_once('x').unwrap_or((text, text));
    let side = |s| parse_count(s, MAX_SIDE).map_err(|e| format!("--size: {e} (use N or WxH)"));
    Ok((side(w)?, side(h)?))
}

/// One measured frame.
#[derive(Clone, Debug)]
struct Row {
    scene: SceneKind,
    width: u32,
    height: u32,
    sampler: SamplerKind,
    spp: u32,
    rmse: f64,
    seconds: f64,
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
        SceneKind::Polygon => (0.0, 0.0, 1.0, 1.0),
    };
    let fraction = |f: f64, n: u32| ((f * f64::from(n)) as u32).min(n - 1);
    let (x, y) = (fraction(fx, width), fraction(fy, height));
    let w = ((fw * f64::from(width)).ceil() as u32).clamp(1, width - x);
    let h = ((fh * f64::from(height)).ceil() as u32).clamp(1, height - y);
    (x, y, w, h)
}

fn main() -> ExitCode {
    let options = match parse_args(std::env::args().skip(1)) {
        Ok(Command::Run(options)) => options,
        Ok(Command::Help) => {
            println!("{USAGE}");
            return ExitCode::SUCCESS;
        }
        Err(message) => {
            eprintln!("tracer: {message}");
            return ExitCode::from(2);
        }
    };
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("tracer: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run(options: &Options) -> Result<(), String> {
    let started = Instant::now();
    let out = &options.out;
    fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let threads = rayon::current_num_threads();
    eprintln!(
        "tracer: {threads} threads, filter {}, seed {}, writing to {}",
        options.filter,
        options.seed,
        out.display()
    );
    let mut rows = Vec::new();
    for &scene_kind in &options.scenes {
        let sizes = match options.size {
            Some(size) => vec![size],
            None => scene_kind.default_sizes().to_vec(),
        };
        for (width, height) in sizes {
            rows.extend(run_scene(options, scene_kind, width, height)?);
        }
    }
    println!("{}", markdown_table(options, &rows));
    if let Some(path) = &options.report {
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            fs::create_dir_all(parent)
                .map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
        }
        fs::write(path, json_report(&rows))
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    eprintln!(
        "tracer: done in {:.1} s on {threads} threads",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// Renders one scene at one size with every requested sampler and count.
fn run_scene(
    options: &Options,
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
    eprintln!(
        "tracer: {label}: reference {} in {:.2} s",
        if computed { "computed" } else { "loaded" },
        t.elapsed().as_secs_f64()
    );
    let zoom = viewing_zoom(width, height);
    let path = dir.join("reference.png");
    Picture::from_image(&reference, zoom)
        .write_png(&path)
        .map_err(|e| io_error(&path, e))?;

    let crop = crop_for(scene_kind, width, height);
    let crop_zoom = (192 / crop.2.max(crop.3)).max(1);
    let mut rows = Vec::new();
    for &spp in &options.spps {
        let mut frames: Vec<(SamplerKind, Image, f64)> = Vec::new();
        for &kind in &options.samplers {
            // A sampler may reject a count (say, one that needs powers of
            // two, asked for 3 spp): skip that frame, keep the rest.
            let sampler = match kind.build(spp) {
                Ok(sampler) => sampler,
                Err(e) => {
                    eprintln!("tracer: {label}: skipping {kind} at {spp} spp: {e}");
                    continue;
                }
            };
            let patterns = Patterns {
                seed: options.seed,
                dimension: 0,
            };
            let (image, seconds) =
                timed(|| render(&scene, width, height, &sampler, patterns, options.filter));
            let rmse = image.rmse(&reference);
            let path = dir.join(format!("{kind}-{spp}spp.png"));
            Picture::from_image(&image, zoom)
                .write_png(&path)
                .map_err(|e| io_error(&path, e))?;
            rows.push(Row {
                scene: scene_kind,
                width,
                height,
                sampler: kind,
                spp,
                rmse,
                seconds,
            });
            frames.push((kind, image, rmse));
        }
        // The contact sheet: the reference, then each sampler's frame.
        let mut tiles = vec![Tile {
            image: &reference,
            label: vec!["reference".into(), label.clone()],
        }];
        tiles.extend(frames.iter().map(|(kind, image, rmse)| Tile {
            image,
            label: vec![kind.name().into(), format!("{spp} spp rmse {rmse:.4}")],
        }));
        let path = dir.join(format!("contact-{spp}spp.png"));
        contact_sheet(&tiles, crop, crop_zoom)
            .write_png(&path)
            .map_err(|e| io_error(&path, e))?;
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
        .collect();
    // Nothing to plot if every sampler rejected every count.
    if !rows.is_empty() {
        let title = format!("{label}: RMSE vs time per frame");
        let path = dir.join("trade.svg");
        fs::write(&path, trade_plot_svg(&title, &series, options.target))
            .map_err(|e| io_error(&path, e))?;
    }
    eprintln!("tracer: {label}: wrote {}", dir.display());
    Ok(rows)
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

/// One table per scene and size: RMSE (and ms per frame) at each spp, then
/// the spp and time needed to reach the target RMSE.
fn markdown_table(options: &Options, rows: &[Row]) -> String {
    let mut text = String::new();
    let mut jobs: Vec<(SceneKind, u32, u32)> = Vec::new();
    for r in rows {
        if !jobs.contains(&(r.scene, r.width, r.height)) {
            jobs.push((r.scene, r.width, r.height));
        }
    }
    for (scene, width, height) in jobs {
        let _ = writeln!(
            text,
            "\n### {scene} {width}x{height}, {} filter: RMSE (ms per frame), and what reaching RMSE {} costs\n",
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
                        let _ = write!(line, " {:.5} ({}) |", r.rmse, format_ms(r.seconds));
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
    let _ = writeln!(text, "\n{}", versus_random(rows));
    text
}

/// The check the tracer exists to make: from 16 spp up, does every
/// stratified sampler beat `random` on RMSE at equal spp? Lists the
/// exceptions rather than hiding them.
fn versus_random(rows: &[Row]) -> String {
    let exceptions: Vec<String> = rows
        .iter()
        .filter(|r| r.spp >= 16 && r.sampler != SamplerKind::Random)
        .filter_map(|r| {
            let random = rows.iter().find(|q| {
                (q.scene, q.width, q.height, q.spp, q.sampler)
                    == (r.scene, r.width, r.height, r.spp, SamplerKind::Random)
            })?;
            (r.rmse >= random.rmse).then(|| {
                format!(
                    "{} on {} {}x{} at {} spp ({:.5} vs {:.5})",
                    r.sampler, r.scene, r.width, r.height, r.spp, r.rmse, random.rmse
                )
            })
        })
        .collect();
    if exceptions.is_empty() {
        "From 16 spp up, every other sampler has a lower RMSE than `random` at equal spp.".into()
    } else {
        format!(
            "Not below `random` at equal spp (16 spp and up): {}.",
            exceptions.join("; ")
        )
    }
}

/// The rows as a JSON array. Besides the five documented keys each row
/// carries `width` and `height`, since `polygon` runs at two sizes.
fn json_report(rows: &[Row]) -> String {
    let items: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                r#"  {{"scene": "{}", "sampler": "{}", "spp": {}, "rmse": {:e}, "seconds": {:e}, "width": {}, "height": {}}}"#,
                r.scene,
                r.sampler.name(),
                r.spp,
                r.rmse,
                r.seconds,
                r.width,
                r.height
            )
        })
        .collect();
    format!("[\n{}\n]\n", items.join(",\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    fn run_options(list: &[&str]) -> Options {
        match parse_args(args(list)) {
            Ok(Command::Run(options)) => options,
            other => panic!("{list:?}: {other:?}"),
        }
    }

    #[test]
    fn no_arguments_mean_everything() {
        let options = run_options(&[]);
        assert_eq!(options.scenes, SceneKind::ALL);
        assert_eq!(options.samplers, SamplerKind::ALL);
        assert_eq!(options.spps, DEFAULT_SPP);
        assert_eq!(options.filter, Filter::Box);
        assert_eq!(options.out, PathBuf::from("out"));
    }

    #[test]
    fn lists_narrow_the_run() {
        let options = run_options(&[
            "--scene",
            "moire,checker",
            "--sampler=regular,n-rooks",
            "--spp",
            "16,4",
            "--size",
            "32x8",
            "--filter",
            "mitchell",
            "--seed",
            "9",
            "--report",
            "r.json",
        ]);
        assert_eq!(options.scenes, [SceneKind::Moire, SceneKind::Checker]);
        assert_eq!(
            options.samplers,
            [SamplerKind::Regular, SamplerKind::NRooks]
        );
        assert_eq!(options.spps, [4, 16]);
        assert_eq!(options.size, Some((32, 8)));
        assert_eq!(options.filter, Filter::Mitchell);
        assert_eq!(options.seed, 9);
        assert_eq!(options.report, Some(PathBuf::from("r.json")));
        assert_eq!(run_options(&["--size", "100"]).size, Some((100, 100)));
    }

    #[test]
    fn bad_values_are_errors_and_help_is_not() {
        for bad in [
            &["--scene", "teapot"][..],
            &["--sampler", "best"],
            &["--spp", "0"],
            &["--spp", "4,,16"],
            &["--size", "0x4"],
            &["--size", "big"],
            &["--filter", "lanczos"],
            &["--seed", "-1"],
            &["--target", "0"],
            &["--spp"],
            &["--frobnicate"],
        ] {
            let result = parse_args(args(bad));
            let message = result.expect_err(&format!("{bad:?} should fail"));
            assert!(!message.contains('\n'), "{bad:?}: {message}");
        }
        assert_eq!(
            parse_args(args(&["--spp", "4", "--help"])),
            Ok(Command::Help)
        );
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
