//! The Cornell box's geometry, materials and camera: five walls, an area
//! light, a glass and a diffuse sphere, and a thin lens.

use wellspread::glam::{Vec2, Vec3};
use wellspread::warp;

/// The light's emitted radiance, and below the walls' albedos: the RGB
/// values renderers commonly use for the Cornell box (the scene of Goral et
/// al. 1984, "Modeling the Interaction of Light Between Diffuse Surfaces").
pub const LIGHT_RADIANCE: Vec3 = Vec3::new(17.0, 12.0, 4.0);

pub(super) const WHITE: Vec3 = Vec3::new(0.725, 0.71, 0.68);
pub(super) const RED: Vec3 = Vec3::new(0.63, 0.065, 0.05);
pub(super) const GREEN: Vec3 = Vec3::new(0.14, 0.45, 0.091);
/// The glass sphere's index of refraction.
pub(super) const GLASS_IOR: f32 = 1.5;
/// How far a ray's origin is moved off its surface, in scene units (the box
/// is 2 wide).
pub(super) const EPSILON: f32 = 1e-4;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Material {
    /// Lambertian, with this albedo.
    Diffuse(Vec3),
    /// A smooth dielectric with this index of refraction (outside is air).
    Glass(f32),
    /// The area light: emits [`LIGHT_RADIANCE`] downwards, reflects nothing.
    Light,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct Ray {
    pub(super) origin: Vec3,
    /// Unit length.
    pub(super) direction: Vec3,
}

impl Ray {
    pub(super) fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
}

/// An axis-aligned rectangle: coordinate `axis` equals `position`, and the
/// next two coordinates (cyclically: y, z for x; z, x for y; x, y for z)
/// lie in `[min, max]`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rect {
    pub(super) axis: usize,
    pub(super) position: f32,
    pub(super) min: Vec2,
    pub(super) max: Vec2,
    pub(super) material: Material,
}

impl Rect {
    pub(super) fn other_axes(&self) -> (usize, usize) {
        ((self.axis + 1) % 3, (self.axis + 2) % 3)
    }

    pub(super) fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
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

    pub(super) fn normal(&self) -> Vec3 {
        let mut n = Vec3::ZERO;
        n[self.axis] = 1.0;
        n
    }

    pub(super) fn area(&self) -> f32 {
        let size = self.max - self.min;
        size.x * size.y
    }

    /// The rectangle as `corner + s ex + t ey`, `s, t` in `[0, 1]`: `corner`
    /// is [`Rect::point`] of `(0, 0)`, `ex` and `ey` run along the next
    /// two axes, so `(s, t)` is the `u` of [`Rect::point`].
    pub(super) fn edges(&self) -> (Vec3, Vec3, Vec3) {
        let (a, b) = self.other_axes();
        let size = self.max - self.min;
        let (mut ex, mut ey) = (Vec3::ZERO, Vec3::ZERO);
        ex[a] = size.x;
        ey[b] = size.y;
        (self.point(Vec2::ZERO), ex, ey)
    }

    /// The point of the rectangle at `u` in `[0, 1)^2`, uniform in area.
    pub(super) fn point(&self, u: Vec2) -> Vec3 {
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
pub(super) struct Sphere {
    pub(super) centre: Vec3,
    pub(super) radius: f32,
    pub(super) material: Material,
}

impl Sphere {
    pub(super) fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
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
pub(super) struct Hit {
    pub(super) point: Vec3,
    /// The surface's geometric normal: outward for spheres, along the
    /// positive axis for rectangles.
    pub(super) normal: Vec3,
    pub(super) material: Material,
}

/// The box: x in [-1, 1] (red at -1, green at +1), y in [0, 2] (floor to
/// ceiling), z in [-1, 1] (back wall at -1, open at +1).
#[derive(Clone, Debug)]
pub(super) struct Scene {
    pub(super) rects: [Rect; 6],
    pub(super) spheres: [Sphere; 2],
    /// The light, also `rects[5]`.
    pub(super) light: Rect,
}

impl Scene {
    pub(super) fn cornell() -> Self {
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
    pub(super) fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
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
    pub(super) fn visible(&self, from: Vec3, to: Vec3) -> bool {
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
pub(super) struct Camera {
    pub(super) origin: Vec3,
    /// Half the film's extent at unit distance: `(aspect tan(fov/2),
    /// tan(fov/2))`.
    pub(super) half: Vec2,
    pub(super) film: Vec2,
    /// Lens radius, in scene units.
    pub(super) aperture: f32,
    /// Distance of the plane in focus, along the view axis `-z`.
    pub(super) focus: f32,
}

impl Camera {
    pub(super) fn new(width: u32, height: u32) -> Self {
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
    pub(super) fn ray(&self, film: Vec2, lens: Vec2) -> Ray {
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
pub(super) fn frame(n: Vec3) -> (Vec3, Vec3) {
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
pub(super) fn fresnel(cos_i: f32, eta: f32) -> f32 {
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (s * s + p * p)
}
