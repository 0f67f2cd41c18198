//! The pictures and cost table of docs/warps.md: 256 Owen-scrambled Sobol
//! points (a (0,8,2)-net) mapped through every 2D warp and filter,
//! coloured by their 16 x 16 stratum of the square, and the time per call
//! of each warp and weighted choice.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example warps -- docs/images/warps.png
//! ```
//!
//! Without an argument it prints the cost table only. Times are
//! nanoseconds per call over 2^22 calls on inputs from a fixed-seed PCG,
//! through `black_box`, single-threaded; they vary with the machine. A
//! closed standard output (`warps | head`) stops it quietly.

use std::ffi::OsString;
use std::hint::black_box;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use wellspread::filter::{
    BlackmanHarrisFilter, BoxFilter, Filter, GaussianFilter, LanczosFilter, MitchellFilter,
    TentFilter,
};
use wellspread::glam::{Vec2, Vec3};
use wellspread::warp::{self, AliasTable, Discrete};
use wellspread::{Sampler2D, Sobol};

#[path = "shared/cli.rs"]
pub mod shared;

use shared::Failure;

/// The warps' contact sheet and cost table (docs/warps.md).
#[derive(Parser, Debug)]
pub struct Args {
    /// Also draw the contact sheet into this PNG (its folder is made if
    /// missing); without it only the cost table is printed
    #[arg(value_name = "PNG")]
    pub sheet: Option<PathBuf>,
}

/// Parses the arguments (without the program name): `Ok(None)` when the
/// help was written to `out`.
pub fn parse(
    args: impl IntoIterator<Item = OsString>,
    out: &mut dyn std::io::Write,
) -> Result<Option<Args>, Failure> {
    shared::parse::<Args>("warps", shared::EXIT_CODES, args, out)
}

const PANEL: u32 = 200;
const MARGIN: u32 = 8;

/// A panel: points in `[-1, 1]^2` (the caller scales its domain into it).
struct Panel {
    title: &'static str,
    points: Vec<(Vec2, [u8; 3])>,
}

/// The colour of a point of the square by its 16 x 16 stratum: hue from
/// the column, brightness from the row, so neighbouring strata differ.
fn stratum_colour(u: Vec2) -> [u8; 3] {
    let (i, j) = ((u.x * 16.0) as u32, (u.y * 16.0) as u32);
    let hue = i as f32 / 16.0 * 6.0;
    let c = 0.35 + 0.65 * (j as f32 + 1.0) / 16.0;
    let x = c * (1.0 - (hue % 2.0 - 1.0).abs());
    let (r, g, b) = match hue as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    [(r * 255.0) as u8, (g * 255.0) as u8, (b * 255.0) as u8]
}

fn panels() -> Vec<Panel> {
    let sobol = Sobol::new(256).unwrap();
    let us: Vec<Vec2> = (0..256).map(|i| sobol.sample(i, 1)).collect();
    let map = |title, f: &dyn Fn(Vec2) -> Vec2| Panel {
        title,
        points: us.iter().map(|&u| (f(u), stratum_colour(u))).collect(),
    };
    // The light warps are seen from the origin looking up +z: a direction
    // is drawn where it meets the plane z = 1.
    let on_plane = |w: Vec3| Vec2::new(w.x / w.z, w.y / w.z);
    let tri = [
        Vec3::new(-0.9, -0.8, 1.0),
        Vec3::new(0.9, -0.6, 1.0),
        Vec3::new(-0.2, 0.9, 1.0),
    ];
    let (corner, ex, ey) = (
        Vec3::new(-0.9, -0.9, 1.0),
        Vec3::new(1.8, 0.0, 0.0),
        Vec3::new(0.0, 1.8, 0.0),
    );
    let gaussian = GaussianFilter::new(1.5, 0.5).unwrap();
    let mitchell = MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0).unwrap();
    let lanczos = LanczosFilter::new(3.0, 3.0).unwrap();
    let tent = TentFilter::new(1.0).unwrap();
    let blackman = BlackmanHarrisFilter::new(2.0).unwrap();
    let filter = |f: &dyn Filter, u: Vec2| f.sample(u).offset / f.radius();
    vec![
        map("square (Sobol, 256)", &|u| 2.0 * u - Vec2::ONE),
        map("concentric_disk", &warp::concentric_disk),
        map("cosine_hemisphere (x, y)", &|u| {
            warp::cosine_hemisphere(u).truncate()
        }),
        map("uniform_hemisphere (x, y)", &|u| {
            warp::uniform_hemisphere(u).truncate()
        }),
        map("uniform_sphere (z, azimuth)", &|u| {
            let v = warp::uniform_sphere(u);
            Vec2::new(v.z, v.y.atan2(v.x) / std::f32::consts::PI)
        }),
        map("uniform_triangle", &|u| {
            let b = warp::uniform_triangle(u);
            b.x * Vec2::new(-1.0, -1.0) + b.y * Vec2::new(1.0, -1.0) + b.z * Vec2::new(0.0, 1.0)
        }),
        map("uniform_cone(0.5) (x, y)", &|u| {
            warp::uniform_cone(u, 0.5).truncate() / 0.87
        }),
        map("spherical_triangle (on z = 1)", &|u| {
            on_plane(warp::spherical_triangle(u, tri[0], tri[1], tri[2], Vec3::ZERO).direction)
        }),
        map("uniform_triangle, same light", &|u| {
            let b = warp::uniform_triangle(u);
            (b.x * tri[0] + b.y * tri[1] + b.z * tri[2]).truncate()
        }),
        map("spherical_rectangle (on z = 1)", &|u| {
            on_plane(warp::spherical_rectangle(u, corner, ex, ey, Vec3::ZERO).direction)
        }),
        map("tent filter", &|u| filter(&tent, u)),
        map("gaussian filter 1.5, 0.5", &|u| filter(&gaussian, u)),
        map("mitchell filter 1/3, 1/3", &|u| filter(&mitchell, u)),
        map("lanczos filter 3, 3", &|u| filter(&lanczos, u)),
        map("blackman-harris filter", &|u| filter(&blackman, u)),
    ]
}

/// Draws the sheet into `path`, listing each panel's title on `out`.
fn write_sheet(path: &Path, out: &mut dyn Write) -> Result<(), Failure> {
    let panels = panels();
    let columns = 5;
    let rows = panels.len().div_ceil(columns) as u32;
    let (width, height) = (
        columns as u32 * (PANEL + MARGIN) + MARGIN,
        rows * (PANEL + MARGIN) + MARGIN,
    );
    let mut rgb = vec![[40u8, 40, 40]; (width * height) as usize];
    for (k, panel) in panels.iter().enumerate() {
        let (x0, y0) = (
            MARGIN + (k % columns) as u32 * (PANEL + MARGIN),
            MARGIN + (k / columns) as u32 * (PANEL + MARGIN),
        );
        for y in 0..PANEL {
            for x in 0..PANEL {
                rgb[((y0 + y) * width + x0 + x) as usize] = [250, 250, 250];
            }
        }
        for &(p, colour) in &panel.points {
            let cx = x0 as f32 + (0.5 + 0.48 * p.x) * PANEL as f32;
            // y up.
            let cy = y0 as f32 + (0.5 - 0.48 * p.y) * PANEL as f32;
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (x, y) = (cx as i64 + dx, cy as i64 + dy);
                    if x >= i64::from(x0)
                        && x < i64::from(x0 + PANEL)
                        && y >= i64::from(y0)
                        && y < i64::from(y0 + PANEL)
                    {
                        rgb[(y as u32 * width + x as u32) as usize] = colour;
                    }
                }
            }
        }
        shared::to_stdout(writeln!(out, "panel {k}: {}", panel.title))?;
    }
    let cannot =
        |e: &dyn std::fmt::Display| Failure::Io(format!("cannot write {}: {e}", path.display()));
    let file = std::io::BufWriter::new(shared::create_file(path)?);
    let mut encoder = png::Encoder::new(file, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| cannot(&e))?;
    writer
        .write_image_data(rgb.as_flattened())
        .map_err(|e| cannot(&e))?;
    writer.finish().map_err(|e| cannot(&e))
}

/// Nanoseconds per call of `f` over the inputs, best of 3 passes.
fn time<T>(inputs: &[Vec2], f: impl Fn(Vec2) -> T) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let start = Instant::now();
        for &u in inputs {
            black_box(f(black_box(u)));
        }
        best = best.min(start.elapsed().as_secs_f64() * 1e9 / inputs.len() as f64);
    }
    best
}

fn main() -> ExitCode {
    let args = match parse(std::env::args_os().skip(1), &mut std::io::stdout().lock()) {
        Ok(Some(args)) => args,
        Ok(None) => return ExitCode::SUCCESS,
        Err(failure) => return shared::exit("warps", Err(failure)),
    };
    shared::exit("warps", run(&args, &mut std::io::stdout().lock()))
}

/// The sheet if asked for, then the cost table, on `out`.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), Failure> {
    if let Some(path) = &args.sheet {
        write_sheet(path, out)?;
        shared::to_stdout(writeln!(out, "wrote {}", path.display()))?;
    }
    costs(out)
}

/// Prints the cost table: nanoseconds per call of every map and choice.
fn costs(out: &mut dyn Write) -> Result<(), Failure> {
    let mut rng = Pcg32::seed_from_u64(0x0027);
    let inputs: Vec<Vec2> = (0..1 << 22)
        .map(|_| {
            Vec2::new(
                (rng.random::<u32>() >> 8) as f32 / 16_777_216.0,
                (rng.random::<u32>() >> 8) as f32 / 16_777_216.0,
            )
        })
        .collect();
    let tri = [
        Vec3::new(-0.4, -0.2, 0.9),
        Vec3::new(1.1, 0.1, 0.7),
        Vec3::new(0.2, 0.8, 1.3),
    ];
    let (corner, ex, ey) = (
        Vec3::new(-0.5, -0.3, 0.8),
        Vec3::new(1.2, 0.0, 0.3),
        Vec3::new(0.0, 0.9, 0.0),
    );
    shared::to_stdout(writeln!(out, "| map | ns per call |\n| --- | ---: |"))?;
    let mut row = |name: &str, ns: f64| shared::to_stdout(writeln!(out, "| {name} | {ns:.1} |"));
    row("concentric_disk", time(&inputs, warp::concentric_disk))?;
    row("cosine_hemisphere", time(&inputs, warp::cosine_hemisphere))?;
    row(
        "uniform_hemisphere",
        time(&inputs, warp::uniform_hemisphere),
    )?;
    row("uniform_sphere", time(&inputs, warp::uniform_sphere))?;
    row("uniform_triangle", time(&inputs, warp::uniform_triangle))?;
    row(
        "uniform_cone",
        time(&inputs, |u| warp::uniform_cone(u, 0.9)),
    )?;
    row(
        "uniform_ball (u.x reused as u.z)",
        time(&inputs, |u| warp::uniform_ball(u.extend(u.x))),
    )?;
    row(
        "rectangle",
        time(&inputs, |u| warp::rectangle(u, corner, ex, ey)),
    )?;
    row(
        "spherical_triangle",
        time(&inputs, |u| {
            warp::spherical_triangle(u, tri[0], tri[1], tri[2], Vec3::ZERO)
        }),
    )?;
    row(
        "spherical_triangle_inverse",
        time(&inputs, |u| {
            warp::spherical_triangle_inverse(u.extend(1.0), tri[0], tri[1], tri[2], Vec3::ZERO)
        }),
    )?;
    row(
        "spherical_rectangle",
        time(&inputs, |u| {
            warp::spherical_rectangle(u, corner, ex, ey, Vec3::ZERO)
        }),
    )?;
    let filters: [(&str, Box<dyn Filter>); 6] = [
        ("BoxFilter::sample", Box::new(BoxFilter::new(0.5).unwrap())),
        (
            "TentFilter::sample",
            Box::new(TentFilter::new(1.0).unwrap()),
        ),
        (
            "GaussianFilter::sample",
            Box::new(GaussianFilter::new(1.5, 0.5).unwrap()),
        ),
        (
            "MitchellFilter::sample",
            Box::new(MitchellFilter::new(2.0, 1.0 / 3.0, 1.0 / 3.0).unwrap()),
        ),
        (
            "LanczosFilter::sample",
            Box::new(LanczosFilter::new(3.0, 3.0).unwrap()),
        ),
        (
            "BlackmanHarrisFilter::sample",
            Box::new(BlackmanHarrisFilter::new(2.0).unwrap()),
        ),
    ];
    for (name, f) in &filters {
        row(name, time(&inputs, |u| f.sample(u)))?;
    }
    shared::to_stdout(writeln!(
        out,
        "\n| choice among n | discrete(u, n) | Discrete::sample | AliasTable::sample |\n| ---: | ---: | ---: | ---: |"
    ))?;
    for n in [8u32, 1024, 65_536] {
        let weights: Vec<f32> = (0..n).map(|_| rng.random::<f32>() + 0.01).collect();
        let d = Discrete::new(&weights).unwrap();
        let a = AliasTable::new(&weights).unwrap();
        shared::to_stdout(writeln!(
            out,
            "| {n} | {:.1} | {:.1} | {:.1} |",
            time(&inputs, |u| warp::discrete(u.x, n)),
            time(&inputs, |u| d.sample(u.x)),
            time(&inputs, |u| a.sample(u.x)),
        ))?;
    }
    Ok(())
}
