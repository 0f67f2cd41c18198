//! The Cornell box, path traced: where a renderer's noise really comes from
//! (lights, glass, depth of field, several bounces), and what a sample
//! pattern does about it.
//!
//! Five diffuse walls (red left, green right, white floor, ceiling and back
//! wall; the front is open), a rectangular area light just below the
//! ceiling, a glass sphere (dielectric, Fresnel) and a white diffuse
//! sphere, seen through a thin lens focused on the glass sphere.
//!
//! The path tracer uses next-event estimation to the light (by default a
//! direction uniform in the light's solid angle, `warp::spherical_rectangle`;
//! [`Light::Area`] takes a uniform point on the rectangle instead, see
//! [`Light`]) and cosine-weighted BSDF sampling on diffuse surfaces,
//! a Fresnel coin between reflection and refraction on glass, and Russian
//! roulette after bounce 3. Emission found by a BSDF-sampled ray counts only
//! after a camera or specular vertex, so light is never counted twice and
//! the estimate is unbiased (no MIS: the light is small and bright, and the
//! plain scheme keeps the dimension layout easy to follow).
//!
//! Every random number comes through [`PathSamples`], with a fixed layout:
//!
//! | where | draws |
//! | --- | --- |
//! | the sample's root domain | [`film_lens`](PathSamples::film_lens): film offset `xy` and lens point `zw` in one 4D draw |
//! | bounce `b`: `root.branch(BOUNCE).branch(b)`, one branch per purpose ([`Draws::Keyed`], the default) | light choice (1D, key [`LIGHT_CHOICE`]), light sample (2D, [`LIGHT_SAMPLE`]: a direction in the light's solid angle, or a point on it), BSDF (2D, [`BSDF`]), roulette (1D, [`ROULETTE`]), at every bounce |
//!
//! so the numbers of bounce `b` never depend on what earlier bounces did,
//! nor one purpose's on another's. [`Draws::CallOrder`] draws the same
//! numbers, in the same order, as successive draws of the root domain
//! instead (film and lens, then bounce 0's four, bounce 1's, ...): what
//! `pcg32` always does, and for a sampler whose successive draws take
//! consecutive dimensions of one set (`orthogonal`, `latin-hypercube`)
//! it stratifies film, lens and the first bounce's draws jointly.
//! `--max-depth N` ([`Tracing::max_depth`]) stops paths after bounce
//! `N - 1`: 1 is direct light only (emission seen by the camera ray and
//! next-event estimation at its hit).
//! Three implementations feed it: [`Pairs`], over any
//! [`PixelSampler`]'s `sample_pixel` (film and lens are two independent
//! pairs, each branch a hashed dimension), the library's `Domain`
//! (4D film and lens where the sampler has 4D sets), through the impl
//! sketched on [`PathSamples`], and the baseline `pcg32` (`path.rs`): one
//! `rand_pcg::Pcg32` per pixel sample, every number drawn from it in call
//! order (the layout then fixes only the order of the draws).
//!
//! Images are bit-identical for any thread count: each pixel is a fixed
//! sequence of f64 additions over its own samples, whichever thread runs
//! it.

// The CLI, reports and reference cache call into this module from main.rs.
#![allow(dead_code)]

use rayon::prelude::*;
use wellspread::PixelSampler;
use wellspread::glam::{Vec2, Vec3, Vec4};
use wellspread::primitives::hash_combine;
use wellspread::warp;

use crate::scenes::Rgb;

/// The key of the per-bounce branch: bounce `b` draws from
/// `root.branch(BOUNCE).branch(b)`.
pub const BOUNCE: u32 = 0x426f_756e; // "Boun"

/// The keys of a bounce's draws under [`Draws::Keyed`]: each purpose's
/// number is the first draw of `root.branch(BOUNCE).branch(b).branch(key)`.
pub const LIGHT_CHOICE: u32 = 0x4c43_686f; // "LCho"
/// See [`LIGHT_CHOICE`].
pub const LIGHT_SAMPLE: u32 = 0x4c69_6768; // "Ligh"
/// See [`LIGHT_CHOICE`].
pub const BSDF: u32 = 0x4273_6466; // "Bsdf"
/// See [`LIGHT_CHOICE`].
pub const ROULETTE: u32 = 0x526f_756c; // "Roul"

/// How a path takes its numbers from its sample's domains.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Draws {
    /// One branch key per purpose and bounce (see the module docs): no
    /// draw depends on how many others the path made.
    #[default]
    Keyed,
    /// Every number a successive draw of the root domain, in call order:
    /// film and lens, then each bounce's light choice, light sample, BSDF
    /// and roulette.
    CallOrder,
}

impl Draws {
    pub const ALL: [Draws; 2] = [Draws::Keyed, Draws::CallOrder];

    pub fn name(self) -> &'static str {
        match self {
            Draws::Keyed => "keyed",
            Draws::CallOrder => "call-order",
        }
    }
}

impl core::fmt::Display for Draws {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

impl core::str::FromStr for Draws {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        crate::shared::by_name(&Draws::ALL, text, Draws::name, "draw layout")
    }
}

/// How paths are traced: the light sampling, the draw layout and the
/// depth. A [`Light`] alone is the default layout and depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Tracing {
    pub light: Light,
    pub draws: Draws,
    /// Bounces a path makes at most (bounce 0 is the camera ray's hit):
    /// [`MAX_BOUNCES`] by default, 1 for direct light only.
    pub max_depth: u32,
}

impl From<Light> for Tracing {
    fn from(light: Light) -> Self {
        Self {
            light,
            draws: Draws::Keyed,
            max_depth: MAX_BOUNCES,
        }
    }
}

/// One bounce's numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
struct BounceDraws {
    light_choice: f32,
    light_sample: Vec2,
    bsdf: Vec2,
    roulette: f32,
}

impl BounceDraws {
    /// Four successive draws of `domain`.
    fn next<S: PathSamples>(domain: &mut S) -> Self {
        let light_choice = domain.next_1d();
        let light_sample = domain.next_2d();
        let bsdf = domain.next_2d();
        let roulette = domain.next_1d();
        Self {
            light_choice,
            light_sample,
            bsdf,
            roulette,
        }
    }

    /// Each number the first draw of its own branch of `domain` (a
    /// sequential generator's branches rejoin it, so it still draws in
    /// call order).
    fn keyed<S: PathSamples>(domain: &mut S) -> Self {
        fn first<S: PathSamples, T>(domain: &mut S, key: u32, draw: fn(&mut S) -> T) -> T {
            let mut child = domain.branch(key);
            let value = draw(&mut child);
            domain.rejoin(child);
            value
        }
        Self {
            light_choice: first(domain, LIGHT_CHOICE, S::next_1d),
            light_sample: first(domain, LIGHT_SAMPLE, S::next_2d),
            bsdf: first(domain, BSDF, S::next_2d),
            roulette: first(domain, ROULETTE, S::next_1d),
        }
    }
}

/// Paths stop after this many bounces even if the roulette has not ended
/// them. Only paths that stay on glass get this far (a diffuse bounce
/// multiplies the throughput by at most 0.725, and the roulette then ends
/// the path with probability 1 minus that); a sphere traps no ray by total
/// internal reflection, so they are rare.
pub const MAX_BOUNCES: u32 = 32;

/// Russian roulette starts at this bounce (0 is the camera ray's hit).
pub const ROULETTE_FROM: u32 = 3;

/// The random numbers of one path, handed out by domain.
///
/// A value is the state of one domain: draws advance it, [`branch`]
/// derives a child that depends only on this domain and `key`, never on
/// what was drawn before.
///
/// A sequential generator fits too (`path::Pcg32Samples`): its
/// `branch` hands the child the stream where it is, and [`rejoin`] takes
/// it back after the child's draws, so every draw of a path comes from one
/// stream in call order. That is the one place the path code tells the two
/// apart, and a domain's `rejoin` does nothing.
///
/// The library's `Domain` fits as is (it is `Copy`; with `P =
/// &AnyPixelSampler` it borrows the sampler); with it, `render_cornell(w,
/// h, spp, &Domains(&sampler))` renders film and lens as one 4D point:
///
/// ```ignore
/// pub struct Domains<P>(pub P);
///
/// impl<P: PixelSampler + Copy> SampleSource for Domains<P> {
///     type Samples = wellspread::Domain<P>;
///     fn start(&self, pixel: [u32; 2], index: u32) -> wellspread::Domain<P> {
///         wellspread::Domain::start(self.0, pixel, index)
///     }
/// }
///
/// impl<P: PixelSampler + Copy> PathSamples for wellspread::Domain<P> {
///     fn next_1d(&mut self) -> f32 { wellspread::Domain::next_1d(self) }
///     fn next_2d(&mut self) -> Vec2 { wellspread::Domain::next_2d(self) }
///     fn film_lens(&mut self) -> Vec4 { self.next_4d() }
///     fn branch(&self, key: u32) -> Self { wellspread::Domain::branch(self, key) }
/// }
/// ```
///
/// [`branch`]: PathSamples::branch
/// [`rejoin`]: PathSamples::rejoin
pub trait PathSamples: Clone {
    /// One number in `[0, 1)`.
    fn next_1d(&mut self) -> f32;
    /// Two numbers in `[0, 1)^2`.
    fn next_2d(&mut self) -> Vec2;
    /// The film offset inside the pixel (`x`, `y`) and the lens point
    /// (`z`, `w`), in `[0, 1)^4`: one 4D draw where the source has 4D sets.
    fn film_lens(&mut self) -> Vec4;
    /// The child domain `key`: decorrelated from this domain and from its
    /// other children, and the same whatever this domain drew before.
    fn branch(&self, key: u32) -> Self;
    /// Takes `child` (a branch of this domain) back once it has drawn:
    /// nothing for a domain, whose branches never depend on what was
    /// drawn; a sequential generator continues from where `child` stopped.
    #[inline]
    fn rejoin(&mut self, child: Self) {
        let _ = child;
    }
}

/// Where the [`PathSamples`] of each pixel sample come from.
pub trait SampleSource: Sync {
    /// One path's samples.
    type Samples: PathSamples;
    /// The root domain of sample `index` of `pixel`.
    fn start(&self, pixel: [u32; 2], index: u32) -> Self::Samples;
}

/// [`PathSamples`] over any [`PixelSampler`]'s `sample_pixel`, one
/// dimension pair per draw.
///
/// The root's film offset is dimension pair 0 (the pair the 2D scenes use
/// for the film) and its lens pair 2 (pair 1 is kept for Monte Carlo
/// references). Every other draw `k` of the domain with key `c` is the
/// pair `hash_combine(c, k)`, moved above 2, and a branch's key is
/// `hash_combine(c ^ BRANCH, key)`: branches depend only on their parent's
/// key. 1D draws share pairs: the first `next_1d` of a domain takes a pair
/// and returns its `x`, the second returns its `y`, and so on, so a
/// bounce's light choice and roulette are one pair, each stratified as the
/// sampler's 1D projections are (3 pairs per bounce, not 4).
pub struct Pairs<'a, P: ?Sized>(pub &'a P);

/// The state of one domain of [`Pairs`].
pub struct PairSamples<'a, P: ?Sized> {
    sampler: &'a P,
    pixel: [u32; 2],
    index: u32,
    /// The domain's key; the root's is [`ROOT_KEY`].
    key: u32,
    /// Pairs taken from this domain so far.
    draws: u32,
    /// The `y` of the last pair a `next_1d` took, if no `next_1d` has
    /// used it yet.
    pending: Option<f32>,
}

// By hand: derives would ask `P: Copy`, but only the reference is copied.
impl<P: ?Sized> Clone for PairSamples<'_, P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: ?Sized> Copy for PairSamples<'_, P> {}

/// The key of every sample's root domain in [`Pairs`].
const ROOT_KEY: u32 = 0;
/// Mixed into a parent's key before a branch key, so that a parent's
/// branch keys and its draws' dimensions hash different inputs.
const BRANCH: u32 = 0xb4a2_c3d1;
/// The dimension pairs the root's film and lens use.
const FILM_PAIR: u32 = 0;
const LENS_PAIR: u32 = 2;
/// Hashed pairs start here, above the fixed ones.
const FIRST_HASHED_PAIR: u32 = 3;

impl<'a, P: PixelSampler + ?Sized> SampleSource for Pairs<'a, P> {
    type Samples = PairSamples<'a, P>;

    fn start(&self, pixel: [u32; 2], index: u32) -> PairSamples<'a, P> {
        PairSamples::new(self.0, pixel, index)
    }
}

impl<'a, P: PixelSampler + ?Sized> PairSamples<'a, P> {
    /// The root domain of sample `index` of `pixel`.
    pub fn new(sampler: &'a P, pixel: [u32; 2], index: u32) -> Self {
        Self {
            sampler,
            pixel,
            index,
            key: ROOT_KEY,
            draws: 0,
            pending: None,
        }
    }

    /// The dimension pair of the next draw.
    fn next_pair(&mut self) -> u32 {
        let k = self.draws;
        self.draws = self.draws.wrapping_add(1);
        let hashed = hash_combine(self.key, k);
        // Keep hashed pairs off the fixed ones (a shift of 3 in 2^32).
        hashed.max(FIRST_HASHED_PAIR)
    }

    fn pair(&self, dimension: u32) -> Vec2 {
        self.sampler.sample_pixel(self.pixel, self.index, dimension)
    }
}

impl<P: PixelSampler + ?Sized> PathSamples for PairSamples<'_, P> {
    fn next_1d(&mut self) -> f32 {
        match self.pending.take() {
            Some(y) => y,
            None => {
                let pair = self.next_2d();
                self.pending = Some(pair.y);
                pair.x
            }
        }
    }

    fn next_2d(&mut self) -> Vec2 {
        let dimension = self.next_pair();
        self.pair(dimension)
    }

    fn film_lens(&mut self) -> Vec4 {
        let (film, lens) = if self.key == ROOT_KEY && self.draws == 0 {
            self.draws = 2;
            (self.pair(FILM_PAIR), self.pair(LENS_PAIR))
        } else {
            (self.next_2d(), self.next_2d())
        };
        Vec4::new(film.x, film.y, lens.x, lens.y)
    }

    fn branch(&self, key: u32) -> Self {
        Self {
            key: hash_combine(self.key ^ BRANCH, key),
            draws: 0,
            pending: None,
            ..*self
        }
    }
}
mod scene;

pub use scene::LIGHT_RADIANCE;
use scene::*;

/// How next-event estimation samples the light: both estimators are
/// unbiased and converge to the same image, with different noise and cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Light {
    /// A direction uniform in the solid angle the light covers from the
    /// shading point (`warp::spherical_rectangle`): no `1 / r^2` or light
    /// cosine in the estimate, only the surface's cosine.
    #[default]
    SolidAngle,
    /// A point uniform in the light's area (`Rect::point`), weighted by
    /// `cos_surface cos_light / r^2` over the area pdf.
    Area,
}

impl Light {
    pub const ALL: [Light; 2] = [Light::SolidAngle, Light::Area];

    pub fn name(self) -> &'static str {
        match self {
            Light::SolidAngle => "solid-angle",
            Light::Area => "area",
        }
    }
}

impl core::fmt::Display for Light {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

impl core::str::FromStr for Light {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        Light::ALL
            .into_iter()
            .find(|l| l.name().eq_ignore_ascii_case(text))
            .ok_or_else(|| format!("{text:?} is not a light sampling: use solid-angle or area"))
    }
}

/// Next-event estimation at a diffuse vertex at `origin` (normal `n`) from
/// one light sample `u`: the weight `cos_surface G / pdf` (for area
/// sampling `G = cos_light / r^2` and the pdf per area; for solid angle
/// `G = 1` and the pdf per steradian) by which the BSDF times the light's
/// radiance is multiplied, or zero where the light is hidden or faces
/// away. `rays` counts the shadow ray.
fn next_event(scene: &Scene, light: Light, u: Vec2, origin: Vec3, n: Vec3, rays: &mut u32) -> f32 {
    let rect = &scene.light;
    // The light emits downwards only (normal -y): from on or above its
    // plane it sends nothing, and its solid angle from there is 0 (pdf 0).
    if origin.y >= rect.position {
        return 0.0;
    }
    let choice = warp::discrete_pdf(1);
    let (target, weight) = match light {
        Light::Area => {
            let target = rect.point(u);
            let to_light = target - origin;
            let distance2 = to_light.length_squared();
            let wi = to_light / distance2.sqrt();
            // The light's normal is -y: its cosine is wi.y.
            let (cos_surface, cos_light) = (n.dot(wi), wi.y);
            if cos_surface <= 0.0 || cos_light <= 0.0 {
                return 0.0;
            }
            let pdf = choice / rect.area();
            (target, cos_surface * cos_light / distance2 / pdf)
        }
        Light::SolidAngle => {
            let (corner, ex, ey) = rect.edges();
            let sample = warp::spherical_rectangle(u, corner, ex, ey, origin);
            let (wi, pdf, st) = (sample.direction, sample.pdf, sample.st);
            let cos_surface = n.dot(wi);
            if pdf <= 0.0 || cos_surface <= 0.0 {
                return 0.0;
            }
            (corner + st.x * ex + st.y * ey, cos_surface / (choice * pdf))
        }
    };
    *rays += 1;
    if scene.visible(origin, target) {
        weight
    } else {
        0.0
    }
}

/// What one path found: its radiance and how many rays it cast (camera,
/// bounce and shadow rays), the unit of its cost.
#[derive(Clone, Copy, Debug)]
struct PathResult {
    radiance: Vec3,
    rays: u32,
}

/// Radiance along `ray`, drawing every number from `root` as
/// `tracing.draws` says (see the module docs for the layout), for at most
/// `tracing.max_depth` bounces.
fn trace<S: PathSamples>(
    scene: &Scene,
    tracing: Tracing,
    mut ray: Ray,
    root: &mut S,
) -> PathResult {
    let light = tracing.light;
    let mut bounces = root.branch(BOUNCE);
    let mut throughput = Vec3::ONE;
    let mut radiance = Vec3::ZERO;
    let mut rays = 0;
    // Emission found by the next ray counts: true after the camera and
    // after glass, false after a diffuse vertex (whose light came by NEE).
    let mut count_emission = true;
    for bounce in 0..tracing.max_depth {
        let BounceDraws {
            light_choice,
            light_sample,
            bsdf,
            roulette,
        } = match tracing.draws {
            Draws::Keyed => {
                let mut domain = bounces.branch(bounce);
                let draws = BounceDraws::keyed(&mut domain);
                bounces.rejoin(domain);
                draws
            }
            Draws::CallOrder => BounceDraws::next(root),
        };

        rays += 1;
        let Some(hit) = scene.intersect(&ray, f32::INFINITY) else {
            break;
        };
        match hit.material {
            Material::Light => {
                // One-sided: the light faces down.
                if count_emission && ray.direction.y > 0.0 {
                    radiance += throughput * LIGHT_RADIANCE;
                }
                break;
            }
            Material::Diffuse(albedo) => {
                let n = if hit.normal.dot(ray.direction) > 0.0 {
                    -hit.normal
                } else {
                    hit.normal
                };
                let origin = hit.point + EPSILON * n;
                // Next-event estimation: one light, chosen by `discrete` so
                // the layout holds for more.
                let (light_index, _) = warp::discrete(light_choice, 1);
                debug_assert_eq!(light_index, 0);
                let weight = next_event(scene, light, light_sample, origin, n, &mut rays);
                if weight > 0.0 {
                    radiance += throughput
                        * albedo
                        * core::f32::consts::FRAC_1_PI
                        * LIGHT_RADIANCE
                        * weight;
                }
                // BSDF sampling: cos / pi over the pdf cos / pi leaves the albedo.
                let local = warp::cosine_hemisphere(bsdf);
                let (t, b) = frame(n);
                ray = Ray {
                    origin,
                    direction: (local.x * t + local.y * b + local.z * n).normalize(),
                };
                throughput *= albedo;
                count_emission = false;
            }
            Material::Glass(ior) => {
                let cos = -hit.normal.dot(ray.direction);
                let (n, eta, cos_i) = if cos > 0.0 {
                    (hit.normal, 1.0 / ior, cos)
                } else {
                    (-hit.normal, ior, -cos)
                };
                // The Fresnel coin: reflect with probability F, so the
                // weight F / F (or (1 - F) / (1 - F)) is 1. Radiance also
                // scales by eta^2 at each crossing, but a path reaches the
                // light (outside) only after leaving the sphere as often as
                // it entered, so the factors cancel and are left out.
                let reflectance = fresnel(cos_i, eta);
                ray = if bsdf.x < reflectance {
                    Ray {
                        origin: hit.point + EPSILON * n,
                        direction: ray.direction + 2.0 * cos_i * n,
                    }
                } else {
                    let cos_t = (1.0 - eta * eta * (1.0 - cos_i * cos_i)).sqrt();
                    Ray {
                        origin: hit.point - EPSILON * n,
                        direction: (eta * ray.direction + (eta * cos_i - cos_t) * n).normalize(),
                    }
                };
                count_emission = true;
            }
        }
        if bounce >= ROULETTE_FROM {
            let survive = throughput.max_element().clamp(0.05, 1.0);
            if roulette >= survive {
                break;
            }
            throughput /= survive;
        }
    }
    PathResult { radiance, rays }
}

/// The mean over samples `0..spp` of pixel `(px, py)`, and the rays cast.
fn pixel<S: SampleSource>(
    scene: &Scene,
    tracing: Tracing,
    camera: &Camera,
    source: &S,
    spp: u32,
    [px, py]: [u32; 2],
) -> (Rgb, u64) {
    let mut sum = [0.0f64; 3];
    let mut rays = 0u64;
    for index in 0..spp {
        let mut root = source.start([px, py], index);
        let film_lens = root.film_lens();
        let film = Vec2::new(px as f32 + film_lens.x, py as f32 + film_lens.y);
        let ray = camera.ray(film, Vec2::new(film_lens.z, film_lens.w));
        let path = trace(scene, tracing, ray, &mut root);
        rays += u64::from(path.rays);
        for (s, v) in sum.iter_mut().zip(path.radiance.to_array()) {
            *s += f64::from(v);
        }
    }
    let n = f64::from(spp.max(1));
    (sum.map(|s| (s / n) as f32), rays)
}

/// The Cornell box on a `width x height` film (row-major, row 0 at the top)
/// with samples `0..spp` of each pixel from `source`, box-filtered, the
/// paths traced as `tracing` says (a [`Light`] alone: the default layout
/// and depth): each pixel is the mean radiance of its own samples, in
/// linear RGB.
///
/// Bit-identical for any thread count: rows run on the current rayon pool,
/// each pixel a fixed sequence of f64 additions. `spp = 0` gives a black
/// image.
pub fn render_cornell<S: SampleSource>(
    width: u32,
    height: u32,
    spp: u32,
    source: &S,
    tracing: impl Into<Tracing>,
) -> Vec<Rgb> {
    render_counting(width, height, spp, source, tracing).0
}

/// [`render_cornell`], and the mean number of rays cast per sample: the
/// cost of a frame in units that do not depend on the machine.
pub fn render_counting<S: SampleSource>(
    width: u32,
    height: u32,
    spp: u32,
    source: &S,
    tracing: impl Into<Tracing>,
) -> (Vec<Rgb>, f64) {
    let tracing = tracing.into();
    let scene = Scene::cornell();
    let camera = Camera::new(width, height);
    let mut pixels = vec![([0.0f32; 3], 0u64); width as usize * height as usize];
    if width > 0 {
        pixels
            .par_chunks_mut(width as usize)
            .enumerate()
            .for_each(|(py, row)| {
                for (value, px) in row.iter_mut().zip(0..width) {
                    *value = pixel(&scene, tracing, &camera, source, spp, [px, py as u32]);
                }
            });
    }
    let rays: u64 = pixels.iter().map(|p| p.1).sum();
    let samples = (pixels.len() as u64 * u64::from(spp)).max(1);
    (
        pixels.into_iter().map(|p| p.0).collect(),
        rays as f64 / samples as f64,
    )
}

/// Rec. 709 luminance of linear RGB.
pub fn luminance([r, g, b]: Rgb) -> f32 {
    0.2126 * r + 0.7152 * g + 0.0722 * b
}

#[cfg(test)]
mod tests {
    use std::time::Instant;

    use wellspread::{Padded, PixelSamplerKind, SamplerKind, Sobol};

    use super::*;
    use crate::render::{TracerSampler, one_and_two_threads, pixel_bits};

    #[test]
    fn the_image_is_finite_non_negative_and_shows_the_light() {
        let (width, height) = (64, 64);
        let sampler = Padded::new(Sobol::new(16).unwrap(), 0);
        let image = render_cornell(width, height, 16, &Pairs(&sampler), Light::SolidAngle);
        assert_eq!(image.len(), 64 * 64);
        assert!(image.iter().flatten().all(|v| v.is_finite() && *v >= 0.0));
        let at = |x: usize, y: usize| image[y * width as usize + x];
        // The light covers rows 6 to 8 and columns 26 to 37 of the film:
        // every sample of pixel (32, 7) sees it, directly.
        let light = at(32, 7);
        for c in 0..3 {
            assert!(
                (light[c] - LIGHT_RADIANCE[c]).abs() <= 1e-3 * LIGHT_RADIANCE[c],
                "{light:?}"
            );
        }
        // The left wall is red, the right one green: 5 x 17 pixel blocks at
        // mid-height near the film's edges, where the camera sees the side
        // walls. The light is warm (red 17 against green 12) and the red
        // wall lights the green one, so the green wall's red is 0.6 of its
        // green (at 16 spp), against 0.31 in its albedo.
        let block = |x0: usize| {
            let mut sum = [0.0f32; 3];
            for y in 24..41 {
                for x in x0..x0 + 5 {
                    for (s, v) in sum.iter_mut().zip(at(x, y)) {
                        *s += v;
                    }
                }
            }
            sum
        };
        let (left, right) = (block(1), block(58));
        assert!(
            left[0] > 4.0 * left[1] && right[1] > 1.3 * right[0],
            "{left:?} {right:?}"
        );
        // The box is lit: its mean luminance is that of a dim interior,
        // well below the light's and well above black.
        let mean = image.iter().map(|&p| f64::from(luminance(p))).sum::<f64>() / image.len() as f64;
        println!(
            "cornell 64x64 at 16 spp: mean luminance {mean:.3}, light pixel {light:?}, left wall {left:?}, right wall {right:?}"
        );
        assert!((0.1..2.0).contains(&mean), "{mean}");
        // spp = 0 is black, not NaN.
        assert!(
            render_cornell(4, 4, 0, &Pairs(&sampler), Light::SolidAngle)
                .iter()
                .flatten()
                .all(|&v| v == 0.0)
        );
    }

    /// The estimator does not depend on the sampler beyond its noise: the
    /// mean luminance of the whole film agrees between random and Sobol
    /// samples within 4 standard errors of the random one's (the standard
    /// error estimated from its per-pixel spread), a 6e-5 false-failure rate
    /// for a normal mean.
    #[test]
    fn samplers_agree_on_the_mean() {
        let (width, height, spp) = (32, 32, 16);
        let random = Padded::new(wellspread::Random::new(spp).unwrap(), 1);
        let sobol = Padded::new(Sobol::new(spp).unwrap(), 1);
        let mean_and_error = |image: &[Rgb]| {
            let values: Vec<f64> = image.iter().map(|&p| f64::from(luminance(p))).collect();
            let n = values.len() as f64;
            let mean = values.iter().sum::<f64>() / n;
            let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean, (variance / n).sqrt())
        };
        let (a, error) = mean_and_error(&render_cornell(
            width,
            height,
            spp,
            &Pairs(&random),
            Light::SolidAngle,
        ));
        let (b, _) = mean_and_error(&render_cornell(
            width,
            height,
            spp,
            &Pairs(&sobol),
            Light::SolidAngle,
        ));
        println!("mean luminance: random {a:.4} +- {error:.4}, sobol {b:.4}");
        // The per-pixel spread includes the image's own structure, so this
        // error bound is conservative.
        assert!((a - b).abs() < 4.0 * error, "{a} vs {b} (error {error})");
    }

    /// Light sampling by solid angle and by area estimate the same image:
    /// over a 32 x 32 film at 16 spp (random samples of two frames, so the
    /// two renders' errors are independent), the mean of the per-pixel
    /// luminance differences is within 4 of its standard errors (estimated
    /// from the differences' spread, pixels being independent) of 0, a
    /// 6e-5 false-failure rate for a normal mean; and so is the mean over
    /// the film's top quarter, where shading points are nearest the light.
    /// No pixel is NaN, infinite or negative under either, though shading
    /// points on the ceiling see the light's plane from above (pdf 0).
    #[test]
    fn solid_angle_and_area_light_sampling_agree_in_expectation() {
        let (width, height, spp) = (32, 32, 16);
        let frame = |f| Padded::new(wellspread::Random::new(spp).unwrap(), f);
        let (frame_a, frame_b) = (frame(5), frame(6));
        let solid = render_cornell(width, height, spp, &Pairs(&frame_a), Light::SolidAngle);
        let area = render_cornell(width, height, spp, &Pairs(&frame_b), Light::Area);
        for image in [&solid, &area] {
            assert!(image.iter().flatten().all(|v| v.is_finite() && *v >= 0.0));
        }
        let top = (width * height / 4) as usize;
        for (what, pixels) in [("film", solid.len()), ("top quarter", top)] {
            let differences: Vec<f64> = solid[..pixels]
                .iter()
                .zip(&area[..pixels])
                .map(|(&a, &b)| f64::from(luminance(a)) - f64::from(luminance(b)))
                .collect();
            let n = differences.len() as f64;
            let mean = differences.iter().sum::<f64>() / n;
            let variance = differences.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (n - 1.0);
            let error = (variance / n).sqrt();
            println!(
                "{what}: mean luminance difference (solid angle - area) {mean:.5} +- {error:.5}"
            );
            assert!(mean.abs() < 4.0 * error, "{what}: {mean} (error {error})");
        }
    }

    #[test]
    fn images_are_bit_identical_for_one_and_two_threads() {
        let (one, two) = one_and_two_threads();
        let (width, height) = (24, 20);
        for kind in [
            TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Sobol)),
            TracerSampler::Pixel(PixelSamplerKind::Padded(
                SamplerKind::CorrelatedMultiJittered,
            )),
            TracerSampler::Pixel(PixelSamplerKind::ZSobol),
        ] {
            let sampler = kind.build(16, width, height, 3).unwrap();
            for light in Light::ALL {
                let a = one.install(|| render_cornell(width, height, 16, &Pairs(&sampler), light));
                let b = two.install(|| render_cornell(width, height, 16, &Pairs(&sampler), light));
                assert_eq!(pixel_bits(&a), pixel_bits(&b), "{kind} {light}");
            }
        }
    }

    /// Every library pixel sampler at 4 and 16 spp on a 64 x 64 film (the
    /// `pcg32` baseline renders in path.rs's tests): the cost in rays is
    /// bounded (deterministic), and the wall time is printed.
    #[test]
    fn every_sampler_renders_within_the_budget() {
        let (width, height) = (64, 64);
        let start = Instant::now();
        let mut worst = 0.0f64;
        let kinds: Vec<TracerSampler> = TracerSampler::all()
            .into_iter()
            .filter(|kind| kind.pixel_kind().is_some())
            .collect();
        for &kind in &kinds {
            for spp in [4, 16] {
                let sampler = kind.build(spp, width, height, 0).unwrap();
                let (image, rays) =
                    render_counting(width, height, spp, &Pairs(&sampler), Light::SolidAngle);
                assert!(
                    image.iter().flatten().all(|v| v.is_finite() && *v >= 0.0),
                    "{kind} {spp}"
                );
                worst = worst.max(rays);
            }
        }
        let seconds = start.elapsed().as_secs_f64();
        println!(
            "cornell 64x64, {} samplers at 4 and 16 spp: {seconds:.2} s, at most {worst:.2} rays per sample",
            kinds.len()
        );
        // Camera plus bounces plus shadow rays: the roulette keeps paths
        // short (about 4 bounces, most with a shadow ray).
        assert!(worst < 12.0, "{worst} rays per sample");
    }

    #[test]
    fn pair_branches_ignore_earlier_draws_and_keys_differ() {
        let sampler = Padded::new(Sobol::new(16).unwrap(), 0);
        let source = Pairs(&sampler);
        let mut root = source.start([5, 6], 3);
        let fresh = root.branch(BOUNCE).branch(2).next_2d();
        let film_lens = root.film_lens();
        let _ = root.next_2d();
        assert_eq!(root.branch(BOUNCE).branch(2).next_2d(), fresh);
        assert_ne!(root.branch(BOUNCE).branch(3).next_2d(), fresh);
        // The root's film is pair 0 and its lens pair 2.
        assert_eq!(
            film_lens.truncate().truncate(),
            sampler.sample_pixel([5, 6], 3, 0)
        );
        assert_eq!(
            Vec2::new(film_lens.z, film_lens.w),
            sampler.sample_pixel([5, 6], 3, 2)
        );
        // Successive draws of one domain differ; two 1D draws share a pair.
        let mut d = root.branch(7);
        assert_ne!(d.next_2d(), d.next_2d());
        let mut d = root.branch(7);
        let (x, pair, y) = (d.next_1d(), d.next_2d(), d.next_1d());
        let mut e = root.branch(7);
        let shared = e.next_2d();
        assert_eq!((x, y), (shared.x, shared.y));
        assert_eq!(pair, e.next_2d());
    }

    /// Samples that count the draws of a path (every branch shares the
    /// count) and return mid-range values.
    #[derive(Clone)]
    struct Counting(std::rc::Rc<std::cell::Cell<u32>>);

    impl PathSamples for Counting {
        fn next_1d(&mut self) -> f32 {
            self.0.set(self.0.get() + 1);
            0.3
        }
        fn next_2d(&mut self) -> Vec2 {
            Vec2::new(self.next_1d(), 0.6)
        }
        fn film_lens(&mut self) -> Vec4 {
            self.0.set(self.0.get() + 1);
            Vec4::splat(0.5)
        }
        fn branch(&self, _key: u32) -> Self {
            self.clone()
        }
    }

    /// `--max-depth 1` is direct light: a path makes one bounce's four
    /// draws (light choice, light sample, BSDF, roulette) under either
    /// layout, where the full depth goes on bouncing; and with keyed draws
    /// a depth-1 pixel is the first term of the full-depth pixel's sum,
    /// so no pixel of it is brighter and the indirect light is missing.
    #[test]
    fn depth_one_paths_make_one_bounce_of_draws() {
        let scene = Scene::cornell();
        let camera = Camera::new(16, 16);
        for draws in Draws::ALL {
            let count = |max_depth: u32, film: Vec2| {
                let mut root = Counting(Default::default());
                let tracing = Tracing {
                    light: Light::SolidAngle,
                    draws,
                    max_depth,
                };
                let ray = camera.ray(film, Vec2::splat(0.5));
                let path = trace(&scene, tracing, ray, &mut root);
                (root.0.get(), path.rays)
            };
            // The white floor (bottom centre) and the back wall.
            for film in [Vec2::new(8.0, 15.0), Vec2::new(4.0, 8.0)] {
                let (drawn, rays) = count(1, film);
                assert_eq!(drawn, 4, "{draws} {film}");
                // The camera ray and at most one shadow ray.
                assert!(rays <= 2, "{draws} {film}: {rays}");
                assert!(count(MAX_BOUNCES, film).0 > 4, "{draws} {film}");
            }
        }
        let (width, height, spp) = (16, 16, 4);
        let sampler = Padded::new(Sobol::new(spp).unwrap(), 0);
        let direct = Tracing {
            max_depth: 1,
            ..Tracing::from(Light::SolidAngle)
        };
        let one = render_cornell(width, height, spp, &Pairs(&sampler), direct);
        let full = render_cornell(width, height, spp, &Pairs(&sampler), Light::SolidAngle);
        assert!(
            one.iter()
                .flatten()
                .zip(full.iter().flatten())
                .all(|(a, b)| a <= b)
        );
        let sum = |image: &[Rgb]| image.iter().map(|&p| f64::from(luminance(p))).sum::<f64>();
        assert!(sum(&one) < 0.9 * sum(&full), "{} {}", sum(&one), sum(&full));
    }

    #[test]
    fn fresnel_and_frame_are_right() {
        // Normal incidence from air into glass: ((1.5 - 1) / 2.5)^2 = 0.04.
        assert!((fresnel(1.0, 1.0 / 1.5) - 0.04).abs() < 1e-6);
        // Total internal reflection beyond the critical angle (41.8 degrees).
        assert_eq!(fresnel(0.5, 1.5), 1.0);
        // Grazing incidence reflects everything.
        assert!(fresnel(1e-4, 1.0 / 1.5) > 0.99);
        for n in [
            Vec3::X,
            Vec3::Y,
            Vec3::Z,
            -Vec3::Z,
            Vec3::new(0.6, -0.48, 0.64),
            Vec3::new(0.0, 0.0, -1.0 + 1e-7).normalize(),
        ] {
            let (t, b) = frame(n);
            for (u, v) in [(t, b), (t, n), (b, n)] {
                assert!(u.dot(v).abs() < 1e-5, "{n}");
            }
            assert!(
                (t.length() - 1.0).abs() < 1e-5 && (b.length() - 1.0).abs() < 1e-5,
                "{n}"
            );
        }
    }
}
