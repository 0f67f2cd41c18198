//! What a run reports: the measured rows, the markdown trade tables and the
//! claims they support, the JSON report, and the `--docs` page.

use std::fmt::Write as _;

use wellspread::filter::FilterKind;
use wellspread::{PixelSamplerKind, SamplerKind};

use crate::cli::Options;
use crate::cornell::{Draws, Light, MAX_BOUNCES};
use crate::render::{FilterMode, SOBOL, TracerSampler, has_negative_lobes};
use crate::scenes::SceneKind;
use crate::{LIGHT_MARGIN, TOP_BRIGHTEST};

/// One measured row: a scene, size, sampler and count, over `frames` frames.
#[derive(Clone, Debug)]
pub struct Row {
    pub scene: SceneKind,
    pub width: u32,
    pub height: u32,
    pub sampler: TracerSampler,
    pub spp: u32,
    pub filter: FilterKind,
    pub mode: FilterMode,
    /// The reference's least and greatest value over every pixel and
    /// channel: a filter with negative lobes overshoots the scene's range
    /// at edges (ringing).
    pub reference_range: [f64; 2],
    /// How the path-traced scene sampled its light; `None` for the others.
    pub light: Option<Light>,
    /// The path-traced scene's draw layout where the run labels rows with
    /// it (a `--draws` comparison or a `--max-depth`; never pcg32, call
    /// order always); `None` otherwise.
    pub draws: Option<Draws>,
    /// The path-traced scene's depth; `None` for the others.
    pub max_depth: Option<u32>,
    /// Root-mean-square over the frames of each frame's RMSE.
    pub rmse: f64,
    /// The same over the top quarter of the film's rows only, the light's
    /// own pixels left out (see `TOP_ROWS_DIVISOR` in main.rs).
    pub top_rmse: f64,
    /// The same over the whole film, the light and its edge left out (see
    /// `LIGHT_MARGIN` in main.rs): at `--max-depth 1` the light's edge
    /// (film and lens draws) outweighs the lit surfaces' light-sampling
    /// error in `rmse`.
    pub off_light_rmse: f64,
    /// The same after the viewing blur ([`blurred_rmse`]).
    pub blurred_rmse: f64,
    /// Mean error power below 1/16 cycle per pixel, averaged over the
    /// frames ([`low_frequency_power`]).
    pub low_power: f64,
    /// The fastest of the frames' times, in seconds (a frame under 10 ms
    /// timed as its fastest of repeated renders).
    pub seconds: f64,
    pub frames: u32,
}

impl Row {
    /// What a table calls the row's series: the sampler, with its draw
    /// layout where the run labels it ("sobol (call order)").
    pub fn label(&self) -> String {
        series_label(self.sampler, self.draws)
    }
}

/// A series' name in the tables: `sampler`, then `(keyed)` or `(call
/// order)` where `draws` is given.
fn series_label(sampler: TracerSampler, draws: Option<Draws>) -> String {
    match draws {
        None => sampler.name().to_owned(),
        Some(draws) => format!("{sampler} ({})", draws.name().replace('-', " ")),
    }
}

/// ", max depth N" for a heading of rows rendered below the full depth.
fn depth_note(rows: &[&Row]) -> String {
    match rows.iter().find_map(|r| r.max_depth) {
        Some(depth) if depth != MAX_BOUNCES => format!(", max depth {depth}"),
        _ => String::new(),
    }
}

/// The series of `options` in `scene`, in table order: each sampler, per
/// draw layout where the run labels them.
fn series_for(options: &Options, scene: SceneKind) -> Vec<(TracerSampler, Option<Draws>)> {
    let labelled = options.labels_draws();
    options
        .samplers_for(scene)
        .into_iter()
        .flat_map(|kind| {
            let draws = options.draws_for(scene, kind);
            let labels: Vec<Option<Draws>> = if labelled && kind != TracerSampler::Pcg32 {
                draws.into_iter().map(Some).collect()
            } else {
                vec![None]
            };
            labels.into_iter().map(move |d| (kind, d))
        })
        .collect()
}

/// The spp and seconds at which a sampler's error first reaches `target`,
/// interpolating log-log between the two measured counts that bracket it
/// (error falls roughly as a power of spp and of time). `points` are
/// `(spp, rmse, seconds)` in increasing spp. `None`: not reached.
pub fn to_reach(points: &[(u32, f64, f64)], target: f64) -> Option<(f64, f64)> {
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

/// An error for a table cell: five decimals, or three significant figures
/// in scientific notation below 0.001 (the resolved scene at high counts).
pub fn format_error(value: f64) -> String {
    if value >= 1e-3 || value == 0.0 {
        format!("{value:.5}")
    } else {
        format!("{value:.2e}")
    }
}

/// Milliseconds with three significant figures, for table cells.
pub fn format_ms(seconds: f64) -> String {
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
pub fn markdown_tables(options: &Options, rows: &[Row]) -> String {
    if options.lights.len() > 1 {
        return light_tables(options, rows);
    }
    if options.filters.len() * options.modes.len() > 1 {
        return filter_tables(options, rows);
    }
    let mode = match options.modes[0] {
        FilterMode::Weighted => String::new(),
        mode => format!(" ({mode})"),
    };
    let mut text = String::new();
    for (scene, width, height) in jobs(rows) {
        let frames = frames_label(options.frames_for(scene));
        let here: Vec<&Row> = rows
            .iter()
            .filter(|r| (r.scene, r.width, r.height) == (scene, width, height))
            .collect();
        let _ = writeln!(
            text,
            "\n### {scene} {width}x{height}, {} filter{mode}{}: RMSE / blurred RMSE (ms per frame), {frames}; what reaching RMSE {} costs\n",
            options.filters[0],
            depth_note(&here),
            options.target
        );
        let spps = options.spps_for(scene);
        let mut header = String::from("| sampler |");
        let mut rule = String::from("| --- |");
        for spp in &spps {
            let _ = write!(header, " {spp} spp |");
            rule.push_str(" ---: |");
        }
        header.push_str(" spp to reach | time to reach |");
        rule.push_str(" ---: | ---: |");
        let _ = writeln!(text, "{header}\n{rule}");
        for (kind, draws) in series_for(options, scene) {
            let mine: Vec<&Row> = here
                .iter()
                .copied()
                .filter(|r| (r.sampler, r.draws) == (kind, draws))
                .collect();
            let mut line = format!("| {} |", series_label(kind, draws));
            for spp in &spps {
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
    let sections = [
        versus_random(rows),
        zsobol_versus_sobol(rows),
        joint_versus_pairs(rows),
        call_order_versus_keyed(rows),
        versus_pcg32(rows),
    ];
    for section in sections.into_iter().flatten() {
        // One blank line before each, whatever newlines it starts or ends with.
        let _ = writeln!(text, "\n{}", section.trim_matches('\n'));
    }
    text
}

/// A row's figures over a baseline row's: RMSE, time per frame, and
/// RMSE^2 x time, the time to an equal error where the error falls as
/// 1 / sqrt(time) (below 1 where the row is ahead).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Ratios {
    rmse: f64,
    time: f64,
    efficiency: f64,
    /// The RMSE ratio off the light ([`Row::off_light_rmse`]).
    off_light: f64,
}

impl Ratios {
    fn of(row: &Row, baseline: &Row) -> Self {
        let rmse = row.rmse / baseline.rmse;
        let time = row.seconds / baseline.seconds;
        Self {
            off_light: row.off_light_rmse / baseline.off_light_rmse,
            rmse,
            time,
            efficiency: rmse * rmse * time,
        }
    }
}

impl Ratios {
    /// RMSE^2 x time off the light.
    fn off_light_efficiency(&self) -> f64 {
        self.off_light * self.off_light * self.time
    }
}

/// Every sampler against `pcg32`, the baseline that is not the crate (a
/// renderer's own `rand_pcg::Pcg32` per pixel sample), per scene and size
/// where it was rendered: RMSE, time and RMSE^2 x time over pcg32's at
/// each count, then which sampler wins per unit of time at each count
/// and by how much. `None` unless pcg32 and another sampler were both
/// rendered.
fn versus_pcg32(rows: &[Row]) -> Option<String> {
    let mut text = String::new();
    for (scene, width, height) in jobs(rows) {
        let here: Vec<&Row> = rows
            .iter()
            .filter(|r| (r.scene, r.width, r.height) == (scene, width, height))
            .collect();
        let mut samplers: Vec<(TracerSampler, Option<Draws>)> = Vec::new();
        let mut spps: Vec<u32> = Vec::new();
        for r in &here {
            let series = (r.sampler, r.draws);
            if r.sampler != TracerSampler::Pcg32 && !samplers.contains(&series) {
                samplers.push(series);
            }
            if !spps.contains(&r.spp) {
                spps.push(r.spp);
            }
        }
        spps.sort_unstable();
        let compared = |series: (TracerSampler, Option<Draws>), spp: u32| {
            let r = here
                .iter()
                .find(|r| ((r.sampler, r.draws), r.spp) == (series, spp))?;
            Some((r, Ratios::of(r, partner(rows, r, TracerSampler::Pcg32)?)))
        };
        if !samplers
            .iter()
            .any(|&s| spps.iter().any(|&spp| compared(s, spp).is_some()))
        {
            continue;
        }
        // A run labelled with draw layouts (cornell at a --max-depth, or
        // keyed against call order) also compares the RMSE off the light.
        let off_light = here.iter().any(|r| r.draws.is_some());
        let (extra_header, extra_rule) = if off_light {
            (
                " off-light RMSE / pcg32 | off-light RMSE^2 x time / pcg32 |",
                " ---: | ---: |",
            )
        } else {
            ("", "")
        };
        let _ = writeln!(
            text,
            "\n#### {scene} {width}x{height}{}: each sampler over pcg32 (`rand_pcg::Pcg32` per pixel sample, a renderer's own random numbers), below 1 where the sampler is ahead\n\n| sampler | spp | RMSE / pcg32 | time / pcg32 | RMSE^2 x time / pcg32 |{extra_header}\n| --- | ---: | ---: | ---: | ---: |{extra_rule}",
            depth_note(&here)
        );
        for &series in &samplers {
            for &spp in &spps {
                if let Some((r, ratios)) = compared(series, spp) {
                    let mut line = format!(
                        "| {} | {spp} | {:.3} | {:.3} | {:.3} |",
                        r.label(),
                        ratios.rmse,
                        ratios.time,
                        ratios.efficiency
                    );
                    if off_light {
                        let _ = write!(
                            line,
                            " {:.3} | {:.3} |",
                            ratios.off_light,
                            ratios.off_light_efficiency()
                        );
                    }
                    let _ = writeln!(text, "{line}");
                }
            }
        }
        let verdicts = |efficiency: fn(&Ratios) -> f64| -> Vec<String> {
            spps.iter()
                .filter_map(|&spp| {
                    let ranked: Vec<(String, f64)> = samplers
                        .iter()
                        .filter_map(|&s| {
                            let (r, ratios) = compared(s, spp)?;
                            Some((r.label(), efficiency(&ratios)))
                        })
                        .collect();
                    verdict(spp, ranked)
                })
                .collect()
        };
        let _ = writeln!(
            text,
            "\nPer unit of time (RMSE^2 x time, lower is better) on {scene} {width}x{height}{}: {}.",
            depth_note(&here),
            verdicts(|r| r.efficiency).join("; ")
        );
        if off_light {
            let _ = writeln!(
                text,
                "\nOff the light (RMSE^2 x time over the pixels more than {LIGHT_MARGIN} pixels from any whose reference passes {TOP_BRIGHTEST}): {}.",
                verdicts(Ratios::off_light_efficiency).join("; ")
            );
        }
    }
    (!text.is_empty()).then_some(text)
}

/// Which series wins at `spp` by `ranked`'s efficiency (RMSE^2 x time
/// over pcg32's), by how much, and the runner-up; `None` when nothing was
/// compared.
fn verdict(spp: u32, mut ranked: Vec<(String, f64)>) -> Option<String> {
    ranked.sort_by(|a, b| a.1.total_cmp(&b.1));
    let (best, e) = ranked.first()?;
    Some(if *e < 1.0 {
        let runner_up = ranked
            .get(1)
            .map_or(String::new(), |(s, e)| format!(", ahead of `{s}` ({e:.3})"));
        format!(
            "at {spp} spp `{best}` wins, {e:.3} of pcg32's RMSE^2 x time \
             (pcg32 takes {:.2}x as long to the same error){runner_up}",
            1.0 / e
        )
    } else {
        format!(
            "at {spp} spp pcg32 wins: the best of the others, `{best}`, \
             has {e:.3}x its RMSE^2 x time"
        )
    })
}

/// The run of several filters or modes: one table per scene and size,
/// a line per filter and sampler, RMSE / blurred RMSE per count and mode
/// side by side; then, for each sampled mode run beside `weighted`, the
/// geometric mean over the counts of its RMSE over weighted's; then ms
/// per frame at the largest count, per mode.
fn filter_tables(options: &Options, rows: &[Row]) -> String {
    let mut text = String::new();
    let compared: Vec<FilterMode> = if options.modes.contains(&FilterMode::Weighted) {
        options
            .modes
            .iter()
            .copied()
            .filter(|&m| m != FilterMode::Weighted)
            .collect()
    } else {
        Vec::new()
    };
    for (scene, width, height) in jobs(rows) {
        let frames = frames_label(options.frames_for(scene));
        let _ = writeln!(
            text,
            "\n### {scene} {width}x{height}: RMSE / blurred RMSE per filter and mode, {frames}\n"
        );
        let spps = options.spps_for(scene);
        let largest = spps.last().copied().unwrap_or(1);
        let mut header = String::from("| filter | sampler |");
        let mut rule = String::from("| --- | --- |");
        for spp in &spps {
            for mode in &options.modes {
                let _ = write!(header, " {spp} spp {mode} |");
                rule.push_str(" ---: |");
            }
        }
        for mode in &compared {
            let _ = write!(header, " {mode} / weighted RMSE |");
            rule.push_str(" ---: |");
        }
        for mode in &options.modes {
            let _ = write!(header, " ms at {largest} spp {mode} |");
            rule.push_str(" ---: |");
        }
        let _ = writeln!(text, "{header}\n{rule}");
        for &filter in &options.filters {
            for kind in options.samplers_for(scene) {
                let find = |spp: u32, mode: FilterMode| {
                    rows.iter().find(|r| {
                        (
                            r.scene, r.width, r.height, r.sampler, r.spp, r.filter, r.mode,
                        ) == (scene, width, height, kind, spp, filter, mode)
                    })
                };
                let mut line = if has_negative_lobes(filter) {
                    format!("| {filter} (negative lobes) | {kind} |")
                } else {
                    format!("| {filter} | {kind} |")
                };
                for &spp in &spps {
                    for &mode in &options.modes {
                        match find(spp, mode) {
                            Some(r) => {
                                let _ = write!(
                                    line,
                                    " {} / {} |",
                                    format_error(r.rmse),
                                    format_error(r.blurred_rmse)
                                );
                            }
                            None => line.push_str(" skipped |"),
                        }
                    }
                }
                for &mode in &compared {
                    let logs: Vec<f64> = spps
                        .iter()
                        .filter_map(|&spp| {
                            let (w, i) = (find(spp, FilterMode::Weighted)?, find(spp, mode)?);
                            (w.rmse > 0.0 && i.rmse > 0.0).then(|| (i.rmse / w.rmse).ln())
                        })
                        .collect();
                    if logs.is_empty() {
                        line.push_str(" - |");
                    } else {
                        let ratio = (logs.iter().sum::<f64>() / logs.len() as f64).exp();
                        let _ = write!(line, " {ratio:.3} |");
                    }
                }
                for &mode in &options.modes {
                    match find(largest, mode) {
                        Some(r) => {
                            let _ = write!(line, " {} |", format_ms(r.seconds));
                        }
                        None => line.push_str(" - |"),
                    }
                }
                let _ = writeln!(text, "{line}");
            }
        }
        // Ringing: how far each filter's reference leaves the scene's own
        // range, which the box reference (an average) cannot leave.
        let mut ranges = Vec::new();
        for &filter in &options.filters {
            if let Some(r) = rows
                .iter()
                .find(|r| (r.scene, r.width, r.height, r.filter) == (scene, width, height, filter))
            {
                let [low, high] = r.reference_range;
                ranges.push(format!("{filter} [{low:.4}, {high:.4}]"));
            }
        }
        let _ = writeln!(
            text,
            "\nReference range (least and greatest pixel value): {}.",
            ranges.join(", ")
        );
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

/// The row of `sampler` matching `r`'s scene, size and count, and its draw
/// layout (pcg32's, call order always, matches any).
fn partner<'a>(rows: &'a [Row], r: &Row, sampler: TracerSampler) -> Option<&'a Row> {
    let draws = if sampler == TracerSampler::Pcg32 {
        None
    } else {
        r.draws
    };
    rows.iter().find(|q| {
        (q.scene, q.width, q.height, q.spp, q.sampler, q.draws)
            == (r.scene, r.width, r.height, r.spp, sampler, draws)
    })
}

/// From 16 spp up, does every other sampler beat `random` on RMSE at equal
/// spp? Lists the exceptions rather than hiding them. `None` when the run
/// has no such comparison (random, or every other sampler, not rendered at
/// 16 spp or more).
fn versus_random(rows: &[Row]) -> Option<String> {
    let random = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Random));
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
pub fn low_frequency_power(spectrum: &[f64]) -> f64 {
    let low = &spectrum[..(spectrum.len() / 8).max(1)];
    low.iter().sum::<f64>() / low.len() as f64
}

/// zsobol against sobol, row by row: the ratio of blurred RMSE, of RMSE,
/// and of low-frequency error power. `None` unless both were rendered.
fn zsobol_versus_sobol(rows: &[Row]) -> Option<String> {
    let pairs: Vec<(&Row, &Row)> = rows
        .iter()
        .filter(|r| r.sampler == TracerSampler::Pixel(PixelSamplerKind::ZSobol))
        .filter_map(|r| Some((r, partner(rows, r, SOBOL)?)))
        .collect();
    if pairs.is_empty() {
        return None;
    }
    let mut text = String::from(
        "#### zsobol / sobol\n\n| scene | spp | frames | blurred RMSE ratio | RMSE ratio | low-frequency power ratio |\n| --- | ---: | ---: | ---: | ---: | ---: |\n",
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
            "| {} | {} | {} | {:.3} | {:.3} | {low} |",
            scene_cell(z),
            z.spp,
            z.frames,
            z.blurred_rmse / s.blurred_rmse,
            z.rmse / s.rmse,
        );
    }
    text += "\n\"-\": the film is too small for an error spectrum.\n";
    Some(text)
}

/// A ratio table's first cell: the scene and size, and the draw layout
/// where the run labels rows with it.
fn scene_cell(r: &Row) -> String {
    let layout = r
        .draws
        .map_or(String::new(), |d| format!(" ({})", d.name()));
    format!("{} {}x{}{layout}", r.scene, r.width, r.height)
}

/// A ratio table: `heading`, then a line per pair of rows, the scene and
/// size (and the first row's layout, where `layout` says), then
/// `columns` filled by `cells`. `None` when there is no pair.
fn pair_table(
    heading: &str,
    columns: &[&str],
    (pairs, layout): (&[(&Row, &Row)], bool),
    cells: impl Fn(&Row, &Row) -> String,
) -> Option<String> {
    if pairs.is_empty() {
        return None;
    }
    let rule: Vec<&str> = columns
        .iter()
        .map(|c| if *c == "sampler" { "---" } else { "---:" })
        .collect();
    let mut text = format!(
        "#### {heading}\n\n| scene | {} |\n| --- | {} |\n",
        columns.join(" | "),
        rule.join(" | ")
    );
    for (a, b) in pairs {
        let scene = if layout {
            scene_cell(a)
        } else {
            format!("{} {}x{}", a.scene, a.width, a.height)
        };
        let _ = writeln!(text, "| {scene} | {} |", cells(a, b));
    }
    Some(text)
}

/// Film and lens as one 4D Sobol' draw (`sobol`) against two pairs
/// (`sobol-pairs`), row by row: the ratio of RMSE, blurred RMSE and time,
/// below 1 where the 4D draw is better. `None` unless both were rendered.
fn joint_versus_pairs(rows: &[Row]) -> Option<String> {
    let pairs: Vec<(&Row, &Row)> = rows
        .iter()
        .filter(|r| r.sampler == SOBOL)
        .filter_map(|r| Some((r, partner(rows, r, TracerSampler::SobolPairs)?)))
        .collect();
    pair_table(
        "Film and lens: one 4D draw (sobol) / two pairs (sobol-pairs)",
        &[
            "spp",
            "frames",
            "RMSE ratio",
            "blurred RMSE ratio",
            "time ratio",
        ],
        (&pairs, true),
        |joint, paired| {
            format!(
                "{} | {} | {:.3} | {:.3} | {:.2}",
                joint.spp,
                joint.frames,
                joint.rmse / paired.rmse,
                joint.blurred_rmse / paired.blurred_rmse,
                joint.seconds / paired.seconds,
            )
        },
    )
}

/// Each sampler's call-order rows over its keyed ones (cornell, `--draws
/// keyed,call-order`): RMSE, RMSE off the light and time ratios, below 1
/// where call order is ahead. `None` unless both layouts were rendered.
fn call_order_versus_keyed(rows: &[Row]) -> Option<String> {
    let pairs: Vec<(&Row, &Row)> = rows
        .iter()
        .filter(|r| r.draws == Some(Draws::CallOrder))
        .filter_map(|r| {
            let keyed = Row {
                draws: Some(Draws::Keyed),
                ..r.clone()
            };
            Some((r, partner(rows, &keyed, r.sampler)?))
        })
        .collect();
    pair_table(
        "Call order / keyed draws, per sampler and count (below 1: call order ahead)",
        &[
            "sampler",
            "spp",
            "RMSE ratio",
            "off-light RMSE ratio",
            "time ratio",
        ],
        (&pairs, false),
        |call_order, keyed| {
            format!(
                "{} | {} | {:.3} | {:.3} | {:.2}",
                keyed.sampler,
                keyed.spp,
                call_order.rmse / keyed.rmse,
                call_order.off_light_rmse / keyed.off_light_rmse,
                call_order.seconds / keyed.seconds,
            )
        },
    )
}

/// The run of several light samplings (cornell only): one table per size,
/// a line per sampler and count with each light's RMSE / blurred RMSE, the
/// RMSE over the film's top quarter without the light's own pixels (the
/// ceiling and the top of the walls, the shading points nearest the
/// light) and ms per frame, then
/// each other light against the first: the RMSE ratio, the top-quarter
/// RMSE ratio, the time ratio and the efficiency ratio RMSE^2 x time,
/// below 1 where the other light sampling is ahead.
fn light_tables(options: &Options, rows: &[Row]) -> String {
    let lights = &options.lights;
    let (first, others) = (lights[0], &lights[1..]);
    let mut text = String::new();
    for (scene, width, height) in jobs(rows) {
        let frames = frames_label(options.frames_for(scene));
        let _ = writeln!(
            text,
            "\n### {scene} {width}x{height}, light sampling: RMSE / blurred RMSE, top-quarter RMSE (the light left out), ms per frame ({frames}); ratios {} / {first}\n",
            others
                .iter()
                .map(|l| l.name())
                .collect::<Vec<_>>()
                .join(", "),
        );
        let mut header = String::from("| sampler | spp |");
        let mut rule = String::from("| --- | ---: |");
        for light in lights {
            let _ = write!(header, " {light} | {light} top | {light} ms |");
            rule.push_str(" ---: | ---: | ---: |");
        }
        for light in others {
            let _ = write!(
                header,
                " RMSE ratio {light} | top ratio {light} | time ratio {light} | RMSE^2 x time ratio {light} |"
            );
            rule.push_str(" ---: | ---: | ---: | ---: |");
        }
        let _ = writeln!(text, "{header}\n{rule}");
        for kind in options.samplers_for(scene) {
            for spp in options.spps_for(scene) {
                let find = |light: Light| {
                    rows.iter().find(|r| {
                        (r.scene, r.width, r.height, r.sampler, r.spp, r.light)
                            == (scene, width, height, kind, spp, Some(light))
                    })
                };
                let mut line = format!("| {kind} | {spp} |");
                for &light in lights {
                    match find(light) {
                        Some(r) => {
                            let _ = write!(
                                line,
                                " {} / {} | {} | {} |",
                                format_error(r.rmse),
                                format_error(r.blurred_rmse),
                                format_error(r.top_rmse),
                                format_ms(r.seconds)
                            );
                        }
                        None => line.push_str(" skipped | | |"),
                    }
                }
                for &light in others {
                    match (find(first), find(light)) {
                        (Some(a), Some(b)) => {
                            let ratios = Ratios::of(b, a);
                            let _ = write!(
                                line,
                                " {:.4} | {:.3} | {:.2} | {:.2} |",
                                ratios.rmse,
                                b.top_rmse / a.top_rmse,
                                ratios.time,
                                ratios.efficiency,
                            );
                        }
                        _ => line.push_str(" - | - | - | - |"),
                    }
                }
                let _ = writeln!(text, "{line}");
            }
        }
    }
    text
}

/// The rows as a JSON array.
pub fn json_report(rows: &[Row]) -> String {
    let items: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                r#"  {{"scene": "{}", "filter": "{}", "filter_mode": "{}", "light": {}, "draws": {}, "max_depth": {}, "sampler": "{}", "spp": {}, "rmse": {:e}, "blurred_rmse": {:e}, "top_rmse": {:e}, "off_light_rmse": {:e}, "low_frequency_power": {}, "seconds": {:e}, "frames": {}, "width": {}, "height": {}}}"#,
                r.scene,
                r.filter,
                r.mode,
                r.light.map_or("null".to_owned(), |l| format!("\"{l}\"")),
                r.draws.map_or("null".to_owned(), |d| format!("\"{d}\"")),
                r.max_depth.map_or("null".to_owned(), |d| d.to_string()),
                r.sampler.name(),
                r.spp,
                r.rmse,
                r.blurred_rmse,
                r.top_rmse,
                r.off_light_rmse,
                // JSON has no NaN: a film too small for a spectrum is null.
                if r.low_power.is_finite() {
                    format!("{:e}", r.low_power)
                } else {
                    "null".to_owned()
                },
                r.seconds,
                r.frames,
                r.width,
                r.height
            )
        })
        .collect();
    format!("[\n{}\n]\n", items.join(",\n"))
}

/// Mark the part of a `--docs` page the tracer owns: on a re-run only the
/// text between the markers of the run's block is replaced, so prose (and
/// the other block) around it survives. `block` is [`DOCS_BLOCK`], or
/// [`LIGHT_BLOCK`] for a run comparing light sampling.
fn docs_markers(block: &str) -> (String, String) {
    (
        format!("<!-- {block}: generated from here; edit outside the markers -->"),
        format!("<!-- {block}: generated up to here -->"),
    )
}

/// The block of the default run's tables.
pub const DOCS_BLOCK: &str = "tracer";
/// The block of the light sampling comparison (`--light area,solid-angle`).
pub const LIGHT_BLOCK: &str = "tracer light";
/// The block of a run whose rows are labelled with their draw layout
/// (`--draws keyed,call-order`, or a `--max-depth`).
pub const DRAWS_BLOCK: &str = "tracer draws";

/// The `--docs` block a run writes.
pub fn docs_block_name(options: &Options) -> &'static str {
    if options.lights.len() > 1 {
        LIGHT_BLOCK
    } else if options.labels_draws() {
        DRAWS_BLOCK
    } else {
        DOCS_BLOCK
    }
}

/// The command that reproduces this run, as a shell line.
fn command_line() -> String {
    let mut line = String::from("cargo run --release -p wellspread-lab --example tracer");
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
    let cpu = crate::machine::cpu_model().unwrap_or_else(|| "unknown CPU".to_owned());
    format!(
        "{cpu}, {} {}, {} rayon threads",
        std::env::consts::OS,
        std::env::consts::ARCH,
        rayon::current_num_threads()
    )
}

/// The generated block `name` of a `--docs` page.
fn docs_block(tables: &str, name: &str) -> String {
    let (begin, end) = docs_markers(name);
    format!(
        "{begin}\n\nRegenerate with:\n\n```sh\n{}\n```\n\nMachine: {}. Times are the fastest render of a row's frames (a frame under 10 ms is repeated for 10 ms); other work on the machine inflates them.\n{tables}\n{end}\n",
        command_line(),
        machine()
    )
}

/// The `--docs` page: `existing` with its generated block `name` replaced,
/// or with the block appended when it has none (a new page when empty).
pub fn docs_page_from(existing: &str, tables: &str, name: &str) -> String {
    let block = docs_block(tables, name);
    let (begin_marker, end_marker) = docs_markers(name);
    match (existing.find(&begin_marker), existing.find(&end_marker)) {
        (Some(begin), Some(end)) if end > begin => format!(
            "{}{block}{}",
            &existing[..begin],
            existing[end + end_marker.len()..].trim_start_matches('\n')
        ),
        _ if existing.trim().is_empty() => format!("# Tracer measurements\n\n{block}"),
        // A page of prose with no block yet: the block goes at its end.
        _ => format!("{}\n\n{block}", existing.trim_end()),
    }
}

/// How a table's figures combine frames: "one frame" or "RMS over k
/// frames".
fn frames_label(frames: u32) -> String {
    match frames {
        1 => "one frame".to_owned(),
        k => format!("RMS over {k} frames"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(sampler: TracerSampler, spp: u32, rmse: f64) -> Row {
        Row {
            scene: SceneKind::Moire,
            width: 8,
            height: 8,
            sampler,
            spp,
            filter: FilterKind::Box,
            mode: FilterMode::Weighted,
            reference_range: [0.0, 1.0],
            light: None,
            draws: None,
            max_depth: None,
            rmse,
            top_rmse: rmse,
            off_light_rmse: rmse,
            blurred_rmse: rmse / 2.0,
            low_power: rmse * rmse,
            seconds: 0.001,
            frames: 1,
        }
    }

    #[test]
    fn claims_need_their_evidence() {
        let sobol = SOBOL;
        let random = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Random));
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
        let table = zsobol_versus_sobol(&[
            row(sobol, 16, 0.02),
            row(TracerSampler::Pixel(PixelSamplerKind::ZSobol), 16, 0.01),
        ])
        .unwrap();
        assert!(table.contains("| 0.500 | 0.500 | 0.250 |"), "{table}");
        // sobol against sobol-pairs only when both ran.
        assert_eq!(joint_versus_pairs(&[row(SOBOL, 16, 0.01)]), None);
        let table = joint_versus_pairs(&[
            row(SOBOL, 16, 0.01),
            row(TracerSampler::SobolPairs, 16, 0.02),
        ])
        .unwrap();
        assert!(
            table.contains("| 16 | 1 | 0.500 | 0.500 | 1.00 |"),
            "{table}"
        );
    }

    /// `row` with its time per frame.
    fn timed(sampler: TracerSampler, spp: u32, rmse: f64, seconds: f64) -> Row {
        Row {
            seconds,
            ..row(sampler, spp, rmse)
        }
    }

    #[test]
    fn the_pcg32_table_divides_by_pcg32_and_names_the_winner_per_count() {
        let (pcg32, zsobol) = (
            TracerSampler::Pcg32,
            TracerSampler::Pixel(PixelSamplerKind::ZSobol),
        );
        // No pcg32, or pcg32 alone: no table.
        assert_eq!(versus_pcg32(&[timed(SOBOL, 4, 0.1, 0.02)]), None);
        assert_eq!(versus_pcg32(&[timed(pcg32, 4, 0.1, 0.02)]), None);
        let rows = [
            timed(pcg32, 4, 0.2, 0.01),
            timed(SOBOL, 4, 0.1, 0.02),
            timed(zsobol, 4, 0.1, 0.01),
            timed(pcg32, 16, 0.1, 0.04),
            timed(SOBOL, 16, 0.2, 0.02),
            timed(zsobol, 16, 0.1, 0.06),
            // No pcg32 row at 64 spp: no ratio there.
            timed(SOBOL, 64, 0.05, 0.08),
        ];
        let table = versus_pcg32(&rows).unwrap();
        for line in [
            "| sobol | 4 | 0.500 | 2.000 | 0.500 |",
            "| sobol | 16 | 2.000 | 0.500 | 2.000 |",
            "| zsobol | 4 | 0.500 | 1.000 | 0.250 |",
            "| zsobol | 16 | 1.000 | 1.500 | 1.500 |",
        ] {
            assert!(table.contains(&format!("\n{line}\n")), "{line}: {table}");
        }
        assert!(
            !table.contains("| pcg32 |") && !table.contains("| 64 |"),
            "{table}"
        );
        assert!(
            table.contains(
                "on moire 8x8: at 4 spp `zsobol` wins, 0.250 of pcg32's RMSE^2 x time \
                 (pcg32 takes 4.00x as long to the same error), ahead of `sobol` (0.500); \
                 at 16 spp pcg32 wins: the best of the others, `zsobol`, has 1.500x its \
                 RMSE^2 x time.\n"
            ),
            "{table}"
        );
        assert_eq!(
            Ratios::of(&rows[1], &rows[0]),
            Ratios {
                rmse: 0.5,
                time: 2.0,
                efficiency: 0.5,
                off_light: 0.5,
            }
        );
    }

    #[test]
    fn rows_labelled_with_their_draws_are_compared_per_layout_and_with_pcg32() {
        let labelled = |sampler, draws, spp, rmse, seconds| Row {
            scene: SceneKind::Cornell,
            draws,
            max_depth: Some(1),
            off_light_rmse: rmse / 10.0,
            ..timed(sampler, spp, rmse, seconds)
        };
        let orthogonal = TracerSampler::Pixel(PixelSamplerKind::Orthogonal);
        let (keyed, call) = (Some(Draws::Keyed), Some(Draws::CallOrder));
        let rows = [
            labelled(TracerSampler::Pcg32, None, 4, 0.2, 0.01),
            labelled(orthogonal, keyed, 4, 0.1, 0.02),
            labelled(orthogonal, call, 4, 0.05, 0.02),
        ];
        let table = versus_pcg32(&rows).unwrap();
        assert!(
            table.contains("cornell 8x8, max depth 1: each sampler"),
            "{table}"
        );
        for line in [
            "| orthogonal (keyed) | 4 | 0.500 | 2.000 | 0.500 | 0.500 | 0.500 |",
            "| orthogonal (call order) | 4 | 0.250 | 2.000 | 0.125 | 0.250 | 0.125 |",
        ] {
            assert!(table.contains(&format!("\n{line}\n")), "{line}: {table}");
        }
        assert!(
            table.contains("at 4 spp `orthogonal (call order)` wins, 0.125 of pcg32's"),
            "{table}"
        );
        assert!(table.contains("\nOff the light ("), "{table}");
        let ratios = call_order_versus_keyed(&rows).unwrap();
        assert!(
            ratios.contains("| cornell 8x8 | orthogonal | 4 | 0.500 | 0.500 | 1.00 |"),
            "{ratios}"
        );
        // Unlabelled rows: neither the layout table nor the off-light columns.
        assert_eq!(call_order_versus_keyed(&[row(SOBOL, 4, 0.1)]), None);
        let plain = versus_pcg32(&[
            timed(TracerSampler::Pcg32, 4, 0.2, 0.01),
            timed(SOBOL, 4, 0.1, 0.01),
        ]);
        assert!(!plain.unwrap().contains("off-light"));
        // The run's tables and docs block.
        let options = crate::cli::tests::run_options(&[
            "--scene",
            "cornell",
            "--max-depth",
            "1",
            "--draws",
            "keyed,call-order",
            "--sampler",
            "orthogonal,pcg32",
            "--spp",
            "4",
        ]);
        assert_eq!(docs_block_name(&options), DRAWS_BLOCK);
        let rows = rows.map(|r| Row { width: 8, ..r });
        let tables = markdown_tables(&options, &rows);
        assert!(
            tables.contains("| orthogonal (call order) | 0.05000 /"),
            "{tables}"
        );
        assert!(tables.contains("| pcg32 | 0.20000 /"), "{tables}");
        assert_eq!(
            docs_block_name(&crate::cli::tests::run_options(&["--full"])),
            DOCS_BLOCK
        );
    }

    #[test]
    fn the_default_tables_and_page_have_no_doubled_blank_lines() {
        let options = crate::cli::tests::run_options(&["--scene", "moire", "--spp", "16"]);
        let random = TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Random));
        let zsobol = TracerSampler::Pixel(PixelSamplerKind::ZSobol);
        // Every section: the claim on random and the three ratio tables.
        let rows = [
            row(random, 16, 0.03),
            row(SOBOL, 16, 0.01),
            row(zsobol, 16, 0.02),
            row(TracerSampler::SobolPairs, 16, 0.02),
            row(TracerSampler::Pcg32, 16, 0.04),
        ];
        let tables = markdown_tables(&options, &rows);
        for heading in ["#### zsobol / sobol", "#### Film and lens", "over pcg32"] {
            assert!(tables.contains(heading), "{heading}: {tables}");
        }
        assert!(!tables.contains("\n\n\n"), "{tables}");
        let page = docs_page_from("# Page\n\nprose\n", &tables, DOCS_BLOCK);
        assert!(!page.contains("\n\n\n"), "{page}");
    }

    #[test]
    fn docs_pages_keep_the_prose_around_the_generated_block() {
        let fresh = docs_page_from("", "TABLES", DOCS_BLOCK);
        assert!(fresh.starts_with("# Tracer measurements") && fresh.contains("TABLES"));
        let (begin, end) = docs_markers(DOCS_BLOCK);
        let (light_begin, light_end) = docs_markers(LIGHT_BLOCK);
        let page = format!(
            "# Mine\n\nprose before\n\n{begin}\nold\n{end}\n\nprose after\n\n{light_begin}\nlight\n{light_end}\n"
        );
        let updated = docs_page_from(&page, "NEW", DOCS_BLOCK);
        assert!(updated.starts_with("# Mine\n\nprose before\n\n"));
        assert!(updated.contains("NEW") && !updated.contains("old"));
        assert!(updated.contains("prose after\n") && updated.contains("\nlight\n"));
        assert!(updated.contains("cargo run --release -p wellspread-lab --example tracer"));
        // The light block is replaced on its own, the default one kept.
        let lit = docs_page_from(&updated, "LIT", LIGHT_BLOCK);
        assert!(lit.contains("NEW") && lit.contains("LIT") && !lit.contains("\nlight\n"));
        let appended = docs_page_from("# Prose\n\ntext\n", "T", DOCS_BLOCK);
        assert!(appended.starts_with("# Prose\n\ntext\n\n") && appended.contains(&end));
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
}
