//! Everything the tracer writes besides the table: PNGs (8-bit sRGB),
//! labelled contact sheets, and the error-versus-time plot as hand-written
//! SVG.

use std::fmt::Write as _;
use std::fs::File;
use std::io::{self, BufWriter};
use std::path::Path;

use crate::render::Image;

/// An 8-bit sRGB picture ready for PNG.
#[derive(Clone, Debug)]
pub struct Picture {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<[u8; 3]>,
}

/// Linear to sRGB-encoded 8-bit: the scenes are in linear radiance (the
/// filters average light, not display values), so this is the one place
/// the display curve is applied.
fn encode_srgb(linear: f32) -> u8 {
    let l = f64::from(linear.clamp(0.0, 1.0));
    let encoded = if l <= 0.003_130_8 {
        12.92 * l
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round() as u8
}

impl Picture {
    /// `image` enlarged `zoom` times by pixel replication (nearest
    /// neighbour), so tiny renders stay honest: every film pixel is a block.
    pub fn from_image(image: &Image, zoom: u32) -> Self {
        let (width, height) = (image.width * zoom, image.height * zoom);
        let rgb = (0..width * height)
            .map(|i| {
                let (x, y) = ((i % width) / zoom, (i / width) / zoom);
                image.pixels[(y * image.width + x) as usize].map(encode_srgb)
            })
            .collect();
        Self { width, height, rgb }
    }

    fn blank(width: u32, height: u32, colour: [u8; 3]) -> Self {
        Self {
            width,
            height,
            rgb: vec![colour; (width * height) as usize],
        }
    }

    /// Copies the `w x h` window at `(x0, y0)` of `source` to `(x, y)`.
    fn blit(&mut self, source: &Picture, (x0, y0, w, h): (u32, u32, u32, u32), x: u32, y: u32) {
        for row in 0..h {
            for column in 0..w {
                let from = ((y0 + row) * source.width + x0 + column) as usize;
                let to = ((y + row) * self.width + x + column) as usize;
                self.rgb[to] = source.rgb[from];
            }
        }
    }

    pub fn write_png(&self, path: &Path) -> io::Result<()> {
        let mut encoder =
            png::Encoder::new(BufWriter::new(File::create(path)?), self.width, self.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        let mut writer = encoder.write_header().map_err(io::Error::other)?;
        writer
            .write_image_data(self.rgb.as_flattened())
            .map_err(io::Error::other)?;
        writer.finish().map_err(io::Error::other)
    }
}

/// How much to enlarge an image for viewing: tiny films (the 5 x 7 polygon)
/// up to about 256 pixels on their long side, others as they are.
pub fn viewing_zoom(width: u32, height: u32) -> u32 {
    (256 / width.max(height)).max(1)
}

/// A crop of the film, in film pixels: (x, y, width, height).
pub type Crop = (u32, u32, u32, u32);

/// One tile of a contact sheet: an image, its label lines.
pub struct Tile<'a> {
    pub image: &'a Image,
    pub label: Vec<String>,
}

/// `rows` one above the other, left-aligned on the sheets' background.
pub fn stack_rows(rows: &[Picture]) -> Picture {
    let width = rows.iter().map(|p| p.width).max().unwrap_or(1);
    let height = rows.iter().map(|p| p.height).sum::<u32>().max(1);
    let mut sheet = Picture::blank(width, height, [24, 24, 28]);
    let mut y = 0;
    for row in rows {
        sheet.blit(row, (0, 0, row.width, row.height), 0, y);
        y += row.height;
    }
    sheet
}

/// `line` broken into pieces of at most `max_chars` characters, after a
/// `-` or at a space where possible ("correlated-multi-jittered" becomes
/// "correlated-" / "multi-jittered"), so labels never run into the next tile.
pub fn wrap_label(line: &str, max_chars: usize) -> Vec<String> {
    let max_chars = max_chars.max(1);
    let mut pieces = Vec::new();
    let mut rest: Vec<char> = line.chars().collect();
    while rest.len() > max_chars {
        let window = &rest[..=max_chars];
        let cut = window[..max_chars]
            .iter()
            .rposition(|&c| c == '-')
            .map(|i| i + 1)
            .or_else(|| window.iter().rposition(|&c| c == ' '))
            .filter(|&i| i > 0)
            .unwrap_or(max_chars);
        pieces.push(rest[..cut].iter().collect::<String>().trim_end().to_owned());
        rest.drain(..cut);
        while rest.first() == Some(&' ') {
            rest.remove(0);
        }
    }
    pieces.push(rest.into_iter().collect());
    pieces
}

/// The same `crop` of every tile's image side by side, each enlarged
/// `zoom` times, with its label lines underneath in the built-in font,
/// wrapped to the tile width (at least 14 characters).
pub fn contact_sheet(tiles: &[Tile<'_>], crop: Crop, zoom: u32) -> Picture {
    const GAP: u32 = 8;
    const TEXT_SCALE: u32 = 2;
    const MIN_CHARS: u32 = 14;
    let line_height = (GLYPH_HEIGHT + 2) * TEXT_SCALE;
    let (cw, ch) = (crop.2 * zoom, crop.3 * zoom);
    let advance = (GLYPH_WIDTH + 1) * TEXT_SCALE;
    let max_chars = (cw / advance).max(MIN_CHARS) as usize;
    let labels: Vec<Vec<String>> = tiles
        .iter()
        .map(|t| {
            t.label
                .iter()
                .flat_map(|l| wrap_label(l, max_chars))
                .collect()
        })
        .collect();
    let label_width = labels
        .iter()
        .flatten()
        .map(|line| text_width(line, TEXT_SCALE))
        .max()
        .unwrap_or(0);
    let lines = labels.iter().map(Vec::len).max().unwrap_or(0) as u32;
    let tile_width = cw.max(label_width);
    let width = GAP + tiles.len() as u32 * (tile_width + GAP);
    let height = GAP + ch + GAP + lines * line_height + GAP;
    let mut sheet = Picture::blank(width, height, [24, 24, 28]);
    for (i, tile) in tiles.iter().enumerate() {
        let x = GAP + i as u32 * (tile_width + GAP);
        let zoomed = Picture::from_image(tile.image, zoom);
        sheet.blit(&zoomed, (crop.0 * zoom, crop.1 * zoom, cw, ch), x, GAP);
        for (line_index, line) in labels[i].iter().enumerate() {
            let y = GAP + ch + GAP + line_index as u32 * line_height;
            draw_text(&mut sheet, line, x, y, TEXT_SCALE, [230, 230, 230]);
        }
    }
    sheet
}

const GLYPH_WIDTH: u32 = 3;
const GLYPH_HEIGHT: u32 = 5;

/// A 3 x 5 pixel font drawn for this example: lower-case letters (drawn as
/// small capitals, which read better at this size), digits and the few
/// signs labels use. Each glyph is five rows of three cells, `#` = ink.
fn glyph(c: char) -> [&'static str; 5] {
    match c.to_ascii_lowercase() {
        'a' => [".#.", "#.#", "###", "#.#", "#.#"],
        'b' => ["##.", "#.#", "##.", "#.#", "##."],
        'c' => [".##", "#..", "#..", "#..", ".##"],
        'd' => ["##.", "#.#", "#.#", "#.#", "##."],
        'e' => ["###", "#..", "##.", "#..", "###"],
        'f' => ["###", "#..", "##.", "#..", "#.."],
        'g' => [".##", "#..", "#.#", "#.#", ".##"],
        'h' => ["#.#", "#.#", "###", "#.#", "#.#"],
        'i' => ["###", ".#.", ".#.", ".#.", "###"],
        'j' => ["..#", "..#", "..#", "#.#", ".#."],
        'k' => ["#.#", "#.#", "##.", "#.#", "#.#"],
        'l' => ["#..", "#..", "#..", "#..", "###"],
        'm' => ["#.#", "###", "###", "#.#", "#.#"],
        'n' => ["##.", "#.#", "#.#", "#.#", "#.#"],
        'o' => [".#.", "#.#", "#.#", "#.#", ".#."],
        'p' => ["##.", "#.#", "##.", "#..", "#.."],
        'q' => [".#.", "#.#", "#.#", "##.", ".##"],
        'r' => ["##.", "#.#", "##.", "#.#", "#.#"],
        's' => [".##", "#..", ".#.", "..#", "##."],
        't' => ["###", ".#.", ".#.", ".#.", ".#."],
        'u' => ["#.#", "#.#", "#.#", "#.#", "###"],
        'v' => ["#.#", "#.#", "#.#", "#.#", ".#."],
        'w' => ["#.#", "#.#", "###", "###", "#.#"],
        'x' => ["#.#", "#.#", ".#.", "#.#", "#.#"],
        'y' => ["#.#", "#.#", ".#.", ".#.", ".#."],
        'z' => ["###", "..#", ".#.", "#..", "###"],
        '0' => ["###", "#.#", "#.#", "#.#", "###"],
        '1' => [".#.", "##.", ".#.", ".#.", "###"],
        '2' => ["##.", "..#", ".#.", "#..", "###"],
        '3' => ["##.", "..#", ".#.", "..#", "##."],
        '4' => ["#.#", "#.#", "###", "..#", "..#"],
        '5' => ["###", "#..", "##.", "..#", "##."],
        '6' => [".##", "#..", "###", "#.#", "###"],
        '7' => ["###", "..#", ".#.", ".#.", ".#."],
        '8' => ["###", "#.#", "###", "#.#", "###"],
        '9' => ["###", "#.#", "###", "..#", "##."],
        '-' => ["...", "...", "###", "...", "..."],
        '.' => ["...", "...", "...", "...", ".#."],
        ':' => ["...", ".#.", "...", ".#.", "..."],
        '=' => ["...", "###", "...", "###", "..."],
        _ => ["...", "...", "...", "...", "..."],
    }
}

fn text_width(text: &str, scale: u32) -> u32 {
    text.chars().count() as u32 * (GLYPH_WIDTH + 1) * scale
}

fn draw_text(picture: &mut Picture, text: &str, x: u32, y: u32, scale: u32, colour: [u8; 3]) {
    for (i, c) in text.chars().enumerate() {
        let gx = x + i as u32 * (GLYPH_WIDTH + 1) * scale;
        for (row, cells) in glyph(c).iter().enumerate() {
            for (column, cell) in cells.bytes().enumerate() {
                if cell != b'#' {
                    continue;
                }
                for dy in 0..scale {
                    for dx in 0..scale {
                        let px = gx + column as u32 * scale + dx;
                        let py = y + row as u32 * scale + dy;
                        if px < picture.width && py < picture.height {
                            picture.rgb[(py * picture.width + px) as usize] = colour;
                        }
                    }
                }
            }
        }
    }
}

/// One line of the error-versus-time plot: a sampler's (seconds, RMSE)
/// points in increasing spp, labelled with the spp.
pub struct Series<'a> {
    pub name: &'a str,
    pub points: Vec<(u32, f64, f64)>,
}

/// The layout both plots share: the canvas, and the plot area inside its
/// margins (the right one holds the legend).
const WIDTH: f64 = 760.0;
const HEIGHT: f64 = 480.0;
const LEFT: f64 = 70.0;
const RIGHT: f64 = 230.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 50.0;

/// An SVG of the shared layout, opened, on white, with its title.
fn svg_start(title: &str) -> String {
    let plot_w = WIDTH - LEFT - RIGHT;
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="22" text-anchor="middle" font-size="15">{}</text>"#,
        LEFT + plot_w / 2.0,
        escape(title)
    );
    svg
}

/// A vertical grid line at `x` with its label under the plot.
fn x_grid_line(svg: &mut String, x: f64, label: &str) {
    let plot_h = HEIGHT - TOP - BOTTOM;
    let _ = writeln!(
        svg,
        r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{:.1}" stroke="#ddd"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{label}</text>"##,
        TOP + plot_h,
        TOP + plot_h + 18.0
    );
}

/// The decade grid of a log y axis from `10^lo` to `10^hi` (`sy` maps a
/// value to its y), the plot frame, and both axis labels.
fn log_y_axis_and_frame(
    svg: &mut String,
    (y_lo, y_hi): (f64, f64),
    sy: impl Fn(f64) -> f64,
    x_label: &str,
    y_label: &str,
) {
    let (plot_w, plot_h) = (WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM);
    for decade in y_lo as i32..=y_hi as i32 {
        let y = sy(10f64.powi(decade));
        let _ = writeln!(
            svg,
            r##"<line x1="{LEFT}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="#ddd"/><text x="{:.1}" y="{:.1}" text-anchor="end">1e{decade}</text>"##,
            LEFT + plot_w,
            LEFT - 6.0,
            y + 4.0
        );
    }
    let _ = writeln!(
        svg,
        r##"<rect x="{LEFT}" y="{TOP}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#444"/>"##
    );
    let _ = writeln!(
        svg,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{x_label}</text>"#,
        LEFT + plot_w / 2.0,
        HEIGHT - 10.0
    );
    let _ = writeln!(
        svg,
        r#"<text transform="translate(16 {:.1}) rotate(-90)" text-anchor="middle">{y_label}</text>"#,
        TOP + plot_h / 2.0
    );
}

/// A log-log plot of RMSE against seconds per frame, one polyline per
/// sampler: lower-left is better, and a line's slope is the convergence
/// rate measured in time rather than samples.
pub fn trade_plot_svg(title: &str, series: &[Series<'_>], target: f64) -> String {
    // Tiny times and errors are clamped so log10 stays finite.
    let positive = |v: f64| v.max(1e-9);
    let all = || series.iter().flat_map(|s| &s.points);
    let decade_range = |values: Vec<f64>| {
        let lo = values
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min)
            .log10()
            .floor();
        let hi = values
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max)
            .log10()
            .ceil();
        (lo, hi.max(lo + 1.0))
    };
    let (x_lo, x_hi) = decade_range(all().map(|p| positive(p.2)).collect());
    let mut errors: Vec<f64> = all().map(|p| positive(p.1)).collect();
    errors.push(target);
    let (y_lo, y_hi) = decade_range(errors);
    let plot_w = WIDTH - LEFT - RIGHT;
    let plot_h = HEIGHT - TOP - BOTTOM;
    let sx = |seconds: f64| LEFT + (positive(seconds).log10() - x_lo) / (x_hi - x_lo) * plot_w;
    let sy = |rmse: f64| TOP + (y_hi - positive(rmse).log10()) / (y_hi - y_lo) * plot_h;

    let mut svg = svg_start(title);
    // Decade grid lines and labels.
    for decade in x_lo as i32..=x_hi as i32 {
        x_grid_line(&mut svg, sx(10f64.powi(decade)), &format!("1e{decade}"));
    }
    log_y_axis_and_frame(
        &mut svg,
        (y_lo, y_hi),
        sy,
        "seconds per frame (log)",
        "RMSE vs reference (log)",
    );
    // The target RMSE the table's "to reach" columns use.
    let ty = sy(target);
    let _ = writeln!(
        svg,
        r##"<line x1="{LEFT}" y1="{ty:.1}" x2="{:.1}" y2="{ty:.1}" stroke="#888" stroke-dasharray="5 4"/><text x="{:.1}" y="{:.1}" fill="#666">target {target}</text>"##,
        LEFT + plot_w,
        LEFT + 4.0,
        ty - 4.0
    );
    for (i, s) in series.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let points: Vec<String> = s
            .points
            .iter()
            .map(|&(_, rmse, seconds)| format!("{:.1},{:.1}", sx(seconds), sy(rmse)))
            .collect();
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2"/>"#,
            points.join(" ")
        );
        for &(spp, rmse, seconds) in &s.points {
            let _ = writeln!(
                svg,
                r#"<circle cx="{:.1}" cy="{:.1}" r="3" fill="{colour}"><title>{} {spp} spp: RMSE {rmse:.5}, {seconds:.4} s</title></circle>"#,
                sx(seconds),
                sy(rmse),
                escape(s.name)
            );
        }
        legend_entry(&mut svg, i, plot_w, colour, s.name);
    }
    let _ = writeln!(
        svg,
        r##"<text x="{:.1}" y="{:.1}" fill="#666">points: increasing spp</text>"##,
        LEFT + plot_w + 14.0,
        TOP + 14.0 + series.len() as f64 * 18.0
    );
    svg.push_str("</svg>\n");
    svg
}

/// The radially averaged error power spectra of one sample count, one
/// line per sampler: frequency in cycles per pixel (0 to 0.5, low on the
/// left) against power on a log scale. `series` holds (name, bins), bin `k`
/// of `n` centred at `(k + 1/2) 0.5 / n`.
pub fn spectrum_svg(title: &str, series: &[(&str, Vec<f64>)]) -> String {
    let values = || {
        series
            .iter()
            .flat_map(|(_, bins)| bins.iter().copied())
            .filter(|p| p.is_finite() && *p > 0.0)
    };
    let lo = values()
        .fold(f64::INFINITY, f64::min)
        .max(1e-30)
        .log10()
        .floor();
    let hi = values().fold(0.0, f64::max).max(1e-30).log10().ceil();
    let (y_lo, y_hi) = if lo.is_finite() {
        (lo, hi.max(lo + 1.0))
    } else {
        (-6.0, 0.0)
    };
    let plot_w = WIDTH - LEFT - RIGHT;
    let plot_h = HEIGHT - TOP - BOTTOM;
    let sx = |f: f64| LEFT + f / 0.5 * plot_w;
    let sy = |p: f64| TOP + (y_hi - p.max(1e-30).log10()) / (y_hi - y_lo) * plot_h;
    let mut svg = svg_start(title);
    for tick in 0..=5 {
        let f = f64::from(tick) * 0.1;
        x_grid_line(&mut svg, sx(f), &format!("{f:.1}"));
    }
    log_y_axis_and_frame(
        &mut svg,
        (y_lo, y_hi),
        sy,
        "frequency (cycles per pixel, radially averaged)",
        "error power (log)",
    );
    for (i, (name, bins)) in series.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let n = bins.len() as f64;
        let points: Vec<String> = bins
            .iter()
            .enumerate()
            .filter(|(_, p)| p.is_finite())
            .map(|(k, &p)| format!("{:.1},{:.1}", sx((k as f64 + 0.5) * 0.5 / n), sy(p)))
            .collect();
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2"/>"#,
            points.join(" ")
        );
        legend_entry(&mut svg, i, plot_w, colour, name);
    }
    svg.push_str("</svg>\n");
    svg
}

/// Distinct colours for up to twelve lines (Tableau-like, picked by hand).
const PALETTE: [&str; 12] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
    "#7f7f7f", "#bcbd22", "#000000", "#aec7e8",
];

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Entry `i` of a plot's legend, right of a plot `plot_w` wide: a line in
/// `colour` and the series' name.
fn legend_entry(svg: &mut String, i: usize, plot_w: f64, colour: &str, name: &str) {
    let ly = TOP + 10.0 + i as f64 * 18.0;
    let lx = LEFT + plot_w + 14.0;
    let _ = writeln!(
        svg,
        r#"<line x1="{lx}" y1="{ly}" x2="{}" y2="{ly}" stroke="{colour}" stroke-width="3"/><text x="{}" y="{}">{}</text>"#,
        lx + 20.0,
        lx + 26.0,
        ly + 4.0,
        escape(name)
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_encoding_hits_the_ends_and_the_middle_grey() {
        assert_eq!(encode_srgb(0.0), 0);
        assert_eq!(encode_srgb(1.0), 255);
        // Linear 0.2159 is the sRGB mid-grey 128.
        assert_eq!(encode_srgb(0.2159), 128);
    }

    #[test]
    fn long_labels_wrap_after_hyphens_and_fit() {
        assert_eq!(
            wrap_label("correlated-multi-jittered", 14),
            ["correlated-", "multi-jittered"]
        );
        assert_eq!(
            wrap_label("16 spp rmse 0.0123", 14),
            ["16 spp rmse", "0.0123"]
        );
        assert_eq!(wrap_label("zsobol", 14), ["zsobol"]);
        assert_eq!(wrap_label("abcdefghij", 4), ["abcd", "efgh", "ij"]);
        for line in wrap_label("moire-resolved-192x192-box", 14) {
            assert!(line.chars().count() <= 14, "{line}");
        }
    }

    #[test]
    fn every_label_character_has_a_glyph() {
        for c in "abcdefghijklmnopqrstuvwxyz0123456789-.:=".chars() {
            assert!(glyph(c).iter().any(|row| row.contains('#')), "{c}");
        }
    }
}
