//! The loop a renderer writes on wellspread, in one small path tracer: a
//! sphere on a floor under a square light, depth of field, next-event
//! estimation. Read this first; the big `tracer` is the measurement lab.
//!
//! ```sh
//! cargo run --release -p wellspread-lab --example path_tracer -- --sampler blue-noise --spp 16
//! ```

use std::error::Error;
use std::f32::consts::PI;
use std::ffi::OsString;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Parser;
use wellspread::filter::FilterKind;
use wellspread::glam::Vec3;
use wellspread::{CameraSample, Domain, PixelSampler, PixelSamplerKind, warp};

#[path = "shared/cli.rs"]
pub mod shared;

/// Renders the scene into a PNG.
#[derive(Parser, Debug)]
pub struct Args {
    /// Pixel sampler: sobol, zsobol, blue-noise, cmj, random, ...
    #[arg(long, default_value = "sobol")]
    sampler: PixelSamplerKind,
    /// Samples per pixel
    #[arg(long, default_value_t = 16, value_parser = shared::whole_number)]
    spp: u32,
    /// Pixel filter: box, tent, gaussian, mitchell, lanczos, blackman-harris
    #[arg(long, default_value = "gaussian")]
    filter: FilterKind,
    /// The animation frame: each frame gets new patterns
    #[arg(long, default_value_t = 0, value_parser = shared::whole_number)]
    frame: u32,
    /// The PNG to write (missing folders are created)
    #[arg(long, default_value = "out/path_tracer.png")]
    out: PathBuf,
}

/// Parses the arguments (without the program name) as every tool does:
/// `Ok(None)` when the help was written to `out`, a one-line
/// [`shared::Failure::Input`] for a bad argument.
pub fn parse(
    args: impl IntoIterator<Item = OsString>,
    out: &mut dyn Write,
) -> Result<Option<Args>, shared::Failure> {
    shared::parse::<Args>("path_tracer", shared::EXIT_CODES, args, out)
}

const SIZE: [u32; 2] = [160, 120];
const BOUNCES: u32 = 4;
const LIGHT_SAMPLES: u32 = 2;
// Domain keys: any u32, one per purpose.
const BOUNCE: u32 = 1;
const LIGHT: u32 = 2;
// The light: a square facing down, one corner and two edges.
const CORNER: Vec3 = Vec3::new(-0.5, 2.0, -0.5);
const EDGE_X: Vec3 = Vec3::new(1.0, 0.0, 0.0);
const EDGE_Z: Vec3 = Vec3::new(0.0, 0.0, 1.0);
const EMITTED: f32 = 6.0;
const SKY: Vec3 = Vec3::new(0.05, 0.07, 0.1);
const SPHERE: (Vec3, f32) = (Vec3::new(0.0, 0.6, 0.0), 0.6);
const RED: Vec3 = Vec3::new(0.8, 0.3, 0.2); // the sphere
const GREY: Vec3 = Vec3::splat(0.7); // the floor
const EYE: Vec3 = Vec3::new(0.0, 1.0, 3.5);
const FOCUS: f32 = 3.5; // the sphere is in focus
const APERTURE: f32 = 0.05; // lens radius

/// The nearest surface along `origin + t dir` with `t > 1e-4`: its `t`,
/// normal and albedo, and whether it is the light.
fn intersect(origin: Vec3, dir: Vec3) -> Option<(f32, Vec3, Vec3, bool)> {
    let (centre, radius) = SPHERE;
    let oc = origin - centre;
    let (b, c) = (oc.dot(dir), oc.length_squared() - radius * radius);
    let sphere = -b - (b * b - c).sqrt(); // NaN on a miss
    // The floor (y = 0, 8 x 8) and the light (its underside).
    let (floor, ceiling) = (-origin.y / dir.y, (CORNER.y - origin.y) / dir.y);
    let (p, q) = (origin + floor * dir, origin + ceiling * dir - CORNER);
    let on_floor = p.x.abs().max(p.z.abs()) < 4.0;
    let on_light = (0.0..1.0).contains(&q.x) && (0.0..1.0).contains(&q.z) && dir.y > 0.0;
    let floor = if on_floor { floor } else { f32::NAN };
    let ceiling = if on_light { ceiling } else { f32::NAN };
    let sphere_normal = (oc + sphere * dir) / radius;
    [
        (sphere, sphere_normal, RED, false),
        (floor, Vec3::Y, GREY, false),
        (ceiling, Vec3::NEG_Y, Vec3::ZERO, true),
    ]
    .into_iter()
    .filter(|&(t, ..)| t > 1e-4 && t.is_finite())
    .min_by(|a, b| a.0.total_cmp(&b.0))
}

/// One path of the pixel sample whose root domain is `root`, through the
/// film and lens point of its `camera` sample: every random number comes
/// from the domain or from its children. The domain is 32 bytes and
/// borrows the sampler (`PixelSampler::start`); a routine that draws takes
/// it by `&mut`. Generic over the sampler (`S: PixelSampler + Copy`, Copy
/// for `branch` and `split`), so `Domain<&AnyPixelSampler>` and a concrete
/// `Domain<&Padded<Sobol>>` both fit.
fn radiance<S: PixelSampler + Copy>(root: &mut Domain<S>, camera: &CameraSample) -> Vec3 {
    let film = camera.film / SIZE[1] as f32;
    let aspect = SIZE[0] as f32 / SIZE[1] as f32;
    let lens = APERTURE * camera.lens;
    let focus = EYE + FOCUS * Vec3::new(0.8 * (film.x - 0.5 * aspect), 0.8 * (0.5 - film.y), -1.0);
    let mut origin = EYE + lens.extend(0.0);
    let mut dir = (focus - origin).normalize();
    let (mut throughput, mut sum) = (Vec3::ONE, Vec3::ZERO);
    for b in 0..BOUNCES {
        let Some((t, normal, albedo, light)) = intersect(origin, dir) else {
            return sum + throughput * SKY;
        };
        let point = origin + t * dir;
        if light {
            // Seen directly; later bounces counted the light by sampling it.
            return sum + Vec3::splat(if b == 0 { EMITTED } else { 0.0 });
        }
        // Bounce b's draws never depend on what the bounces before it drew.
        let mut bounce = root.branch(BOUNCE).branch(b);
        let brdf = albedo / PI;
        for j in 0..LIGHT_SAMPLES {
            // Sub-sample j of LIGHT_SAMPLES: together, a stratified set.
            let u = bounce.split(LIGHT, LIGHT_SAMPLES, j).next_2d();
            let on_light = warp::rectangle(u, CORNER, EDGE_X, EDGE_Z);
            let to_light = on_light - point;
            let (distance2, wi) = (to_light.length_squared(), to_light.normalize());
            let (cos_surface, cos_light) = (normal.dot(wi), wi.y);
            let shadowed = intersect(point, wi).is_some_and(|(.., light)| !light);
            if cos_surface > 0.0 && cos_light > 0.0 && !shadowed {
                // The area pdf turned into a solid-angle pdf.
                let pdf = warp::rectangle_pdf(EDGE_X, EDGE_Z) * distance2 / cos_light;
                sum += throughput * brdf * EMITTED * cos_surface / (pdf * LIGHT_SAMPLES as f32);
            }
        }
        // The next direction: cosine-weighted about the normal.
        let local = warp::cosine_hemisphere(bounce.next_2d());
        let pdf = warp::cosine_hemisphere_pdf(local.z);
        let (tangent, bitangent) = normal.any_orthonormal_pair();
        dir = (local.x * tangent + local.y * bitangent + local.z * normal).normalize();
        throughput *= brdf * local.z / pdf;
        origin = point;
    }
    sum
}

fn main() -> ExitCode {
    let args = match parse(std::env::args_os().skip(1), &mut io::stdout()) {
        Ok(Some(args)) => args,
        Ok(None) => return ExitCode::SUCCESS,
        Err(failure) => return shared::exit("path_tracer", Err(failure)),
    };
    let (kind, spp) = (args.sampler, args.spp);
    let Ok(sampler) = kind.build(spp, SIZE, args.frame).inspect_err(|e| {
        eprintln!("path_tracer: --sampler {kind} --spp {spp}: {e}");
    }) else {
        return ExitCode::from(2);
    };
    let filter = args.filter.build(); // pbrt-v4's parameters
    let mut bytes = Vec::with_capacity((SIZE[0] * SIZE[1] * 3) as usize);
    // Gamma 2.2, clamped to 8 bits.
    let encode = |c: f32| (255.0 * c.max(0.0).powf(1.0 / 2.2)).min(255.0) as u8;
    for y in 0..SIZE[1] {
        for x in 0..SIZE[0] {
            let (mut sum, mut weights) = (Vec3::ZERO, 0.0);
            for i in 0..args.spp {
                let mut d = sampler.start([x, y], i);
                // Film (through the filter) and lens from one 4D draw,
                // stratified together, then the time.
                let camera = d.camera_sample([x, y], &filter);
                sum += camera.filter_weight * radiance(&mut d, &camera);
                weights += camera.filter_weight;
            }
            // pbrt's weighted average: sum(w L) / sum(w).
            bytes.extend((sum / weights).to_array().map(encode));
        }
    }
    if let Err(e) = write_png(&args.out, &bytes) {
        eprintln!("path_tracer: {}: {e}", args.out.display());
        return ExitCode::FAILURE;
    }
    // A closed standard output (`| head`) is not a failure: the PNG is written.
    match writeln!(io::stdout(), "{}", args.out.display()) {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
            eprintln!("path_tracer: standard output: {e}");
            ExitCode::FAILURE
        }
        _ => ExitCode::SUCCESS,
    }
}

/// Writes the RGB `bytes` as a PNG at `path`, making its folder if missing.
fn write_png(path: &Path, bytes: &[u8]) -> Result<(), Box<dyn Error>> {
    if let Some(folder) = path.parent() {
        std::fs::create_dir_all(folder)?;
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut encoder = png::Encoder::new(file, SIZE[0], SIZE[1]);
    encoder.set_color(png::ColorType::Rgb);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(bytes)?;
    writer.finish()?;
    Ok(())
}
