//! The Cornell box, path traced: where a renderer's noise really comes from
//! (lights, glass, depth of field, several bounces), and what a sample
//! pattern does about it.
//!
//! Five diffuse walls (red left, green right, white floor, ceiling and back
//! wall; the front is open), a rectangular area light just below the
//! ceiling, a glass sphere (dielectric, Fresnel) and a white diffuse
//! sphere, seen through a thin lens focused on the glass sphere.
//!
//! The path tracer uses next-event estimation to the light (a uniform point
//! on the rectangle) and cosine-weighted BSDF sampling on diffuse surfaces,
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
//! | bounce `b`: `root.branch(BOUNCE).branch(b)` | light choice (1D), light point (2D), BSDF (2D), roulette (1D), in this order, at every bounce |
//!
//! so the numbers of bounce `b` never depend on what earlier bounces did.
//! Two implementations feed it: [`Pairs`], over any
//! [`PixelSampler`]'s `sample_pixel` (film and lens are two independent
//! pairs, each branch a hashed dimension), and the library's `Domain`
//! (4D film and lens where the sampler has 4D sets), through the impl
//! sketched on [`PathSamples`].
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
/// The library's `Domain` fits as is (it is `Copy` and owns its sampler);
/// with it, `render_cornell(w, h, spp, &Domains(sampler))` renders film
/// and lens as one 4D point:
///
/// ```ignore
/// pub struct Domains<P>(pub P);
///
/// impl<P: PixelSampler + Copy> SampleSource for Domains<P> {
///     type Samples = wellspread::Domain<P>;
///     fn start(&self, pixel: [u32; 2], index: u32) -> wellspread::Domain<P> {
///         self.0.start(pixel, index)
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
pub trait PathSamples: Copy {
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

// ---------------------------------------------------------------------------
// The scene.

/// The light's emitted radiance, and below the walls' albedos: the RGB
/// values renderers commonly use for the Cornell box (the scene of Goral et
/// al. 1984, "Modeling the Interaction of Light Between Diffuse Surfaces").
pub const LIGHT_RADIANCE: Vec3 = Vec3::new(17.0, 12.0, 4.0);

const WHITE: Vec3 = Vec3::new(0.725, 0.71, 0.68);
const RED: Vec3 = Vec3::new(0.63, 0.065, 0.05);
const GREEN: Vec3 = Vec3::new(0.14, 0.45, 0.091);
/// The glass sphere's index of refraction.
const GLASS_IOR: f32 = 1.5;
/// How far a ray's origin is moved off its surface, in scene units (the box
/// is 2 wide).
const EPSILON: f32 = 1e-4;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Material {
    /// Lambertian, with this albedo.
    Diffuse(Vec3),
    /// A smooth dielectric with this index of refraction (outside is air).
    Glass(f32),
    /// The area light: emits [`LIGHT_RADIANCE`] downwards, reflects nothing.
    Light,
}

#[derive(Clone, Copy, Debug)]
struct Ray {
    origin: Vec3,
    /// Unit length.
    direction: Vec3,
}

impl Ray {
    fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
}

/// An axis-aligned rectangle: coordinate `axis` equals `position`, and the
/// next two coordinates (cyclically: y, z for x; z, x for y; x, y for z)
/// lie in `[min, max]`.
#[derive(Clone, Copy, Debug)]
struct Rect {
    axis: usize,
    position: f32,
    min: Vec2,
    max: Vec2,
    material: Material,
}

impl Rect {
    fn other_axes(&self) -> (usize, usize) {
        ((self.axis + 1) % 3, (self.axis + 2) % 3)
    }

    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
        let d = ray.direction[self.axis];
        if d == 0.0 {
            return None;
        }
        let t = (self.position - ray.origin[self.axis]) / d;
        if !(EPSILON..t_max).contains(&t) {
            return None;
        }
        let p = ray.at(t);
        let (a, b) = self.other_axes();
        let inside =
            (self.min.x..=self.max.x).contains(&p[a]) && (self.min.y..=self.max.y).contains(&p[b]);
        inside.then_some(t)
    }

    fn normal(&self) -> Vec3 {
        let mut n = Vec3::ZERO;
        n[self.axis] = 1.0;
        n
    }

    fn area(&self) -> f32 {
        let size = self.max - self.min;
        size.x * size.y
    }

    /// The point of the rectangle at `u` in `[0, 1)^2`, uniform in area.
    fn point(&self, u: Vec2) -> Vec3 {
        let (a, b) = self.other_axes();
        let q = self.min + u * (self.max - self.min);
        let mut p = Vec3::ZERO;
        p[self.axis] = self.position;
        p[a] = q.x;
        p[b] = q.y;
        p
    }
}

#[derive(Clone, Copy, Debug)]
struct Sphere {
    centre: Vec3,
    radius: f32,
    material: Material,
}

impl Sphere {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
        let oc = ray.origin - self.centre;
        let b = oc.dot(ray.direction);
        let c = oc.length_squared() - self.radius * self.radius;
        let discriminant = b * b - c;
        if discriminant < 0.0 {
            return None;
        }
        let root = discriminant.sqrt();
        [-b - root, -b + root]
            .into_iter()
            .find(|t| (EPSILON..t_max).contains(t))
    }
}

#[derive(Clone, Copy, Debug)]
struct Hit {
    point: Vec3,
    /// The surface's geometric normal: outward for spheres, along the
    /// positive axis for rectangles.
    normal: Vec3,
    material: Material,
}

/// The box: x in [-1, 1] (red at -1, green at +1), y in [0, 2] (floor to
/// ceiling), z in [-1, 1] (back wall at -1, open at +1).
#[derive(Clone, Debug)]
struct Scene {
    rects: [Rect; 6],
    spheres: [Sphere; 2],
    /// The light, also `rects[5]`.
    light: Rect,
}

impl Scene {
    fn cornell() -> Self {
        let wall = |axis, position, material| Rect {
            axis,
            position,
            min: Vec2::new(if axis == 1 { -1.0 } else { 0.0 }, -1.0),
            max: Vec2::new(if axis == 1 { 1.0 } else { 2.0 }, 1.0),
            material,
        };
        // Walls along x span (y, z) = [0, 2] x [-1, 1]; along y, (z, x) =
        // [-1, 1]^2; along z, (x, y) = [-1, 1] x [0, 2].
        let back = Rect {
            axis: 2,
            position: -1.0,
            min: Vec2::new(-1.0, 0.0),
            max: Vec2::new(1.0, 2.0),
            material: Material::Diffuse(WHITE),
        };
        let light = Rect {
            axis: 1,
            // Just below the ceiling, so the ceiling never shadows it.
            position: 2.0 - 1e-3,
            min: Vec2::new(-0.2, -0.25),
            max: Vec2::new(0.2, 0.25),
            material: Material::Light,
        };
        Self {
            rects: [
                wall(0, -1.0, Material::Diffuse(RED)),
                wall(0, 1.0, Material::Diffuse(GREEN)),
                wall(1, 0.0, Material::Diffuse(WHITE)),
                wall(1, 2.0, Material::Diffuse(WHITE)),
                back,
                light,
            ],
            spheres: [
                Sphere {
                    centre: Vec3::new(0.42, 0.4, 0.25),
                    radius: 0.4,
                    material: Material::Glass(GLASS_IOR),
                },
                Sphere {
                    centre: Vec3::new(-0.45, 0.35, -0.35),
                    radius: 0.35,
                    material: Material::Diffuse(WHITE),
                },
            ],
            light,
        }
    }

    /// The nearest hit closer than `t_max`.
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut nearest = t_max;
        for rect in &self.rects {
            if let Some(t) = rect.intersect(ray, nearest) {
                nearest = t;
                best = Some(Hit {
                    point: ray.at(t),
                    normal: rect.normal(),
                    material: rect.material,
                });
            }
        }
        for sphere in &self.spheres {
            if let Some(t) = sphere.intersect(ray, nearest) {
                nearest = t;
                let point = ray.at(t);
                best = Some(Hit {
                    point,
                    normal: (point - sphere.centre) / sphere.radius,
                    material: sphere.material,
                });
            }
        }
        best
    }

    /// Whether nothing lies between `from` and `to` (exclusive).
    fn visible(&self, from: Vec3, to: Vec3) -> bool {
        let offset = to - from;
        let distance = offset.length();
        let ray = Ray {
            origin: from,
            direction: offset / distance,
        };
        self.intersect(&ray, distance * (1.0 - 1e-4)).is_none()
    }
}

/// A thin-lens camera in front of the box's open side, looking into it,
/// focused on the glass sphere.
#[derive(Clone, Copy, Debug)]
struct Camera {
    origin: Vec3,
    /// Half the film's extent at unit distance: `(aspect tan(fov/2),
    /// tan(fov/2))`.
    half: Vec2,
    film: Vec2,
    /// Lens radius, in scene units.
    aperture: f32,
    /// Distance of the plane in focus, along the view axis `-z`.
    focus: f32,
}

impl Camera {
    fn new(width: u32, height: u32) -> Self {
        let tan = (20.0f32).to_radians().tan();
        let aspect = width as f32 / height.max(1) as f32;
        let origin = Vec3::new(0.0, 1.0, 3.6);
        Self {
            origin,
            half: Vec2::new(aspect * tan, tan),
            film: Vec2::new(width as f32, height as f32),
            aperture: 0.12,
            focus: origin.z - 0.25,
        }
    }

    /// The ray through film position `film` (pixels, row 0 at the top) and
    /// lens point `lens` in `[0, 1)^2`.
    fn ray(&self, film: Vec2, lens: Vec2) -> Ray {
        let ndc = Vec2::new(
            2.0 * film.x / self.film.x - 1.0,
            1.0 - 2.0 * film.y / self.film.y,
        );
        // Right is +x, up is +y, the view axis -z: the pinhole direction
        // has z = -1, so the focal plane is reached at `focus` times it.
        let pinhole = Vec3::new(ndc.x * self.half.x, ndc.y * self.half.y, -1.0);
        let in_focus = self.origin + self.focus * pinhole;
        let on_lens = self.aperture * warp::concentric_disk(lens);
        let origin = self.origin + Vec3::new(on_lens.x, on_lens.y, 0.0);
        Ray {
            origin,
            direction: (in_focus - origin).normalize(),
        }
    }
}

// ---------------------------------------------------------------------------
// The path tracer.

/// An orthonormal frame `(t, b, n)` around the unit vector `n`, without a
/// branch on a reference axis (Duff et al. 2017, "Building an Orthonormal
/// Basis, Revisited", JCGT 6(1)).
fn frame(n: Vec3) -> (Vec3, Vec3) {
    let sign = 1.0f32.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        Vec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

/// The unpolarised Fresnel reflectance of a smooth dielectric, for
/// `cos_i` the cosine of incidence and `eta` the ratio of indices
/// (incident over transmitted); 1 under total internal reflection.
fn fresnel(cos_i: f32, eta: f32) -> f32 {
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (s * s + p * p)
}

/// What one path found: its radiance and how many rays it cast (camera,
/// bounce and shadow rays), the unit of its cost.
#[derive(Clone, Copy, Debug)]
struct PathResult {
    radiance: Vec3,
    rays: u32,
}

/// Radiance along `ray`, drawing every number from `root`'s bounce
/// branches (see the module docs for the layout).
fn trace<S: PathSamples>(scene: &Scene, mut ray: Ray, root: &S) -> PathResult {
    let bounces = root.branch(BOUNCE);
    let mut throughput = Vec3::ONE;
    let mut radiance = Vec3::ZERO;
    let mut rays = 0;
    // Emission found by the next ray counts: true after the camera and
    // after glass, false after a diffuse vertex (whose light came by NEE).
    let mut count_emission = true;
    for bounce in 0..MAX_BOUNCES {
        let mut domain = bounces.branch(bounce);
        let light_choice = domain.next_1d();
        let light_point = domain.next_2d();
        let bsdf = domain.next_2d();
        let roulette = domain.next_1d();

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
                let light = &scene.light;
                let target = light.point(light_point);
                let to_light = target - origin;
                let distance2 = to_light.length_squared();
                let wi = to_light / distance2.sqrt();
                // The light's normal is -y: its cosine is wi.y.
                let (cos_surface, cos_light) = (n.dot(wi), wi.y);
                if cos_surface > 0.0 && cos_light > 0.0 {
                    rays += 1;
                    if scene.visible(origin, target) {
                        let pdf = warp::discrete_pdf(1) / light.area();
                        let geometry = cos_surface * cos_light / distance2;
                        radiance += throughput
                            * albedo
                            * core::f32::consts::FRAC_1_PI
                            * LIGHT_RADIANCE
                            * (geometry / pdf);
                    }
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
        let path = trace(scene, ray, &root);
        rays += u64::from(path.rays);
        for (s, v) in sum.iter_mut().zip(path.radiance.to_array()) {
            *s += f64::from(v);
        }
    }
    let n = f64::from(spp.max(1));
    (sum.map(|s| (s / n) as f32), rays)
}

/// The Cornell box on a `width x height` film (row-major, row 0 at the top)
/// with samples `0..spp` of each pixel from `source`, box-filtered: each
/// pixel is the mean radiance of its own samples, in linear RGB.
///
/// Bit-identical for any thread count: rows run on the current rayon pool,
/// each pixel a fixed sequence of f64 additions. `spp = 0` gives a black
/// image.
pub fn render_cornell<S: SampleSource>(width: u32, height: u32, spp: u32, source: &S) -> Vec<Rgb> {
    render_counting(width, height, spp, source).0
}

/// [`render_cornell`], and the mean number of rays cast per sample: the
/// cost of a frame in units that do not depend on the machine.
pub fn render_counting<S: SampleSource>(
    width: u32,
    height: u32,
    spp: u32,
    source: &S,
) -> (Vec<Rgb>, f64) {
    let scene = Scene::cornell();
    let camera = Camera::new(width, height);
    let mut pixels = vec![([0.0f32; 3], 0u64); width as usize * height as usize];
    if width > 0 {
        pixels
            .par_chunks_mut(width as usize)
            .enumerate()
            .for_each(|(py, row)| {
                for (value, px) in row.iter_mut().zip(0..width) {
                    *value = pixel(&scene, &camera, source, spp, [px, py as u32]);
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
    use crate::render::TracerSampler;

    fn bits(image: &[Rgb]) -> Vec<u32> {
        image.iter().flatten().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn the_image_is_finite_non_negative_and_shows_the_light() {
        let (width, height) = (64, 64);
        let sampler = Padded::new(Sobol::new(16).unwrap(), 0);
        let image = render_cornell(width, height, 16, &Pairs(&sampler));
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
            render_cornell(4, 4, 0, &Pairs(&sampler))
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
        let (a, error) = mean_and_error(&render_cornell(width, height, spp, &Pairs(&random)));
        let (b, _) = mean_and_error(&render_cornell(width, height, spp, &Pairs(&sobol)));
        println!("mean luminance: random {a:.4} +- {error:.4}, sobol {b:.4}");
        // The per-pixel spread includes the image's own structure, so this
        // error bound is conservative.
        assert!((a - b).abs() < 4.0 * error, "{a} vs {b} (error {error})");
    }

    #[test]
    fn images_are_bit_identical_for_one_and_two_threads() {
        let pool = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
        };
        let (one, two) = (pool(1), pool(2));
        let (width, height) = (24, 20);
        for kind in [
            TracerSampler::Pixel(PixelSamplerKind::Padded(SamplerKind::Sobol)),
            TracerSampler::Pixel(PixelSamplerKind::Padded(
                SamplerKind::CorrelatedMultiJittered,
            )),
            TracerSampler::Pixel(PixelSamplerKind::ZSobol),
        ] {
            let sampler = kind.build(16, width, height, 3).unwrap();
            let a = one.install(|| render_cornell(width, height, 16, &Pairs(&sampler)));
            let b = two.install(|| render_cornell(width, height, 16, &Pairs(&sampler)));
            assert_eq!(bits(&a), bits(&b), "{kind}");
        }
    }

    /// Every pixel sampler at 4 and 16 spp on a 64 x 64 film: the cost in
    /// rays is bounded (deterministic), and the wall time is printed.
    #[test]
    fn every_sampler_renders_within_the_budget() {
        let (width, height) = (64, 64);
        let start = Instant::now();
        let mut worst = 0.0f64;
        for kind in TracerSampler::all() {
            for spp in [4, 16] {
                let sampler = kind.build(spp, width, height, 0).unwrap();
                let (image, rays) = render_counting(width, height, spp, &Pairs(&sampler));
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
            TracerSampler::all().len()
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
