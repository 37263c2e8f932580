//! The path tracer's estimator of the rendering equation (Lecture 2, Kajiya 1986):
//!
//! L_o(p, w_o) = L_e(p, w_o) + integral over the hemisphere of f_r L_i cos theta_i
//! dw_i.
//!
//! One sample of the integral follows one direction; L_i in that direction is again
//! L_o of the next surface, so the estimate is a path, followed vertex by vertex
//! ([`Path`]), that keeps a throughput beta (the product of f_r cos / pdf so far);
//! [`radiance`] adds up beta L_e at every vertex where light is found. Four ways to
//! find it, from worst to best in most scenes:
//!
//! - `UniformHemisphere`: directions with density 1 / (2 pi);
//! - `Cosine`: density cos / pi, which cancels the cosine of the integrand;
//! - `NextEvent`: next event estimation, at every diffuse vertex also a sample aimed
//!   at a light (with a shadow ray); emission found by the cosine-sampled bounce
//!   after a diffuse vertex is then not counted, or it would be counted twice;
//! - `Mis`: both, each weighted by Veach's power heuristic with beta = 2 (Veach and
//!   Guibas 1995; Veach's thesis 1997, section 9.2).
//!
//! Mirror and glass reflect into a single direction, which a light sample cannot
//! hit: after a specular bounce emission always counts fully. The environment (the
//! scene's background, a uniform sky) is not a light that can be sampled, so every
//! strategy counts it fully when a ray escapes. The scene's point light is the
//! opposite case, a light only a sample aimed at it can find: no random direction
//! meets a point, so every strategy, the first two included, counts it by a shadow
//! ray at every diffuse vertex ([`crate::pathtrace::next_event`]), and nowhere
//! else; a point light seen in a mirror is never found.

use glam::Vec3;

use crate::basis::Basis;
use crate::material::Material;
use crate::pathtrace::light::LightShape;
use crate::pathtrace::mis::power_heuristic;
use crate::pathtrace::next_event::{direct_light, point_light};
use crate::pathtrace::roulette::survives_roulette;
use crate::pathtrace::settings::{Sampling, Settings};
use crate::ray::{Interval, Ray};
use crate::rng::Rng;
use crate::sampling::{
    cosine_hemisphere, cosine_hemisphere_pdf, uniform_hemisphere,
    uniform_hemisphere_pdf,
};
use crate::scene::Intersect;
use crate::shapes::Hit;
use crate::spawn::Start;

/// How the emission found at the next vertex is weighted, decided by the bounce
/// that leads there.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Previous {
    /// The camera ray, a specular bounce, or a strategy without light sampling:
    /// emission counts fully.
    Full,
    /// Next event estimation has already counted the light: emission counts 0.
    LightSampled,
    /// MIS: weight by the power heuristic, BRDF density `pdf` at point `from`.
    Mis { from: Vec3, pdf: f32 },
}

// ANCHOR: radiance
/// One sample of the radiance arriving along `ray`: the light found along a path,
/// vertex by vertex, in the order the path finds it.
pub fn radiance(
    scene: &impl Intersect,
    ray: Ray,
    rng: &mut Rng,
    settings: &Settings,
) -> Vec3 {
    let mut sum = Vec3::ZERO;
    for vertex in Path::new(scene, ray, rng, settings) {
        sum += vertex.emitted;
        sum += vertex.direct;
    }
    sum
}
// ANCHOR_END: radiance

// ANCHOR: vertex
/// One vertex of a path: where the path went, and the light found there (already
/// multiplied by the throughput beta of the path up to it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// The surface the path met, or the direction in which it left the scene.
    pub at: At,
    /// Emission seen there, beta L_e (weighted by MIS), or beta times the background
    /// once the path has left the scene; 0 where nothing shines.
    pub emitted: Vec3,
    /// Light brought there by a light sample (next event estimation), beta f_r L_e
    /// cos / pdf, and by the scene's point light, beta f_r (pi I) cos / d^2; 0
    /// without either, and at the vertex where the path ends.
    pub direct: Vec3,
    /// That light sample on an emitter: the point aimed at on it, and whether it
    /// faces the vertex and its shadow ray got through (the point light's shadow
    /// ray, which every strategy traces, is not recorded here).
    pub light_sample: Option<(Vec3, bool)>,
}

/// Where a path went.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum At {
    /// The surface of object `object` (of [`Intersect::objects`]) at `point`.
    Surface {
        /// Where the path met the surface.
        point: Vec3,
        /// Which object it met.
        object: usize,
    },
    /// Nothing: the path left the scene along the unit `direction`.
    Escaped {
        /// The unit direction it left along.
        direction: Vec3,
    },
}
// ANCHOR_END: vertex

/// A path from `ray` on, one [`Vertex`] at a time ([`radiance`] sums their light;
/// figures and measurements look at the vertices themselves).
pub struct Path<'a, S> {
    scene: &'a S,
    rng: &'a mut Rng,
    settings: &'a Settings,
    /// The state after the last vertex, `None` once the path has ended.
    next: Option<Next>,
}

/// What a path carries from one vertex to the next.
#[derive(Clone, Copy, Debug)]
struct Next {
    ray: Ray,
    range: Interval,
    /// The throughput: the product of f_r cos / pdf so far.
    beta: Vec3,
    /// How the emission found by `ray` is weighted.
    previous: Previous,
    /// Bounces so far.
    bounce: u32,
}

impl<'a, S: Intersect> Path<'a, S> {
    /// The path that starts with the camera ray `ray`.
    pub fn new(
        scene: &'a S,
        ray: Ray,
        rng: &'a mut Rng,
        settings: &'a Settings,
    ) -> Self {
        let next = Next {
            ray,
            range: Interval::AHEAD,
            beta: Vec3::ONE,
            previous: Previous::Full,
            bounce: 0,
        };
        Path {
            scene,
            rng,
            settings,
            next: Some(next),
        }
    }
}

// ANCHOR: bounce
impl<S: Intersect> Iterator for Path<'_, S> {
    type Item = Vertex;

    /// The next vertex: follow the ray to the closest hit, take the light found
    /// there, then (unless the path ends) scatter, multiply beta by the bounce's
    /// factor, play Russian roulette and aim the next ray.
    fn next(&mut self) -> Option<Vertex> {
        let (scene, settings) = (self.scene, self.settings);
        let Next {
            ray,
            mut range,
            mut beta,
            previous,
            bounce,
        } = self.next.take()?;
        let Some(found) = scene.closest(&ray, range) else {
            let direction = ray.direction();
            let light = beta * scene.background();
            return Some(Vertex::at(At::Escaped { direction }, light));
        };
        let (hit, object) = (found.hit, found.object);
        let point = hit.point;
        let mut vertex = Vertex::at(At::Surface { point, object }, Vec3::ZERO);
        let surface = &scene.objects()[object];
        if surface.is_emissive() {
            let weight = emission_weight(scene, object, &hit, previous, settings);
            vertex.emitted = beta * surface.emission_seen(hit.front_face) * weight;
        }
        // A hit so far away that its point overflowed (an infinite plane met at a
        // grazing angle) gives no finite place to continue from: the path ends.
        if settings.max_depth.is_some_and(|m| bounce >= m) || !hit.point.is_finite() {
            return Some(vertex);
        }
        let material = surface.material_at(&hit); // a texture's albedo there
        let Some(next) = scatter(scene, material, &ray, &hit, self.rng, settings)
        else {
            return Some(vertex);
        };
        vertex.direct = beta * next.direct;
        vertex.light_sample = next.light_sample;
        beta *= next.weight;
        let bounce = bounce + 1;
        if survives_roulette(&mut beta, bounce, self.rng, settings) {
            range.min = next.start.t_min;
            self.next = Some(Next {
                ray: Ray::from_checked(next.start.point, next.direction),
                range,
                beta,
                previous: next.previous,
                bounce,
            });
        }
        Some(vertex)
    }
}
// ANCHOR_END: bounce

impl Vertex {
    /// A vertex `at` a place where `emitted` is seen, and no light sample.
    fn at(at: At, emitted: Vec3) -> Vertex {
        Vertex {
            at,
            emitted,
            direct: Vec3::ZERO,
            light_sample: None,
        }
    }
}

/// What happens at one vertex: light found by a light sample, and the next ray.
struct Bounce {
    /// f_r L_e cos / pdf from next event estimation, plus the point light's light
    /// (0 without either).
    direct: Vec3,
    /// The light sample behind `direct`: its point, and whether it was seen.
    light_sample: Option<(Vec3, bool)>,
    /// Where the next ray starts.
    start: Start,
    /// Its unit direction.
    direction: Vec3,
    /// The throughput factor f_r cos / pdf.
    weight: Vec3,
    /// How emission found by the next ray is weighted.
    previous: Previous,
}

// ANCHOR: scatter
/// The light sample (if any) and the next ray at `hit`, by the material there.
/// `None` only if a specular material had no direction to give.
///
/// Light is reflected about the shading normal (a smooth mesh's blend of its vertex
/// normals, [`Hit::shading`]; on every other surface its own normal), while the next
/// ray leaves from the side of the facet the path arrived on.
fn scatter(
    scene: &impl Intersect,
    material: Material,
    ray: &Ray,
    hit: &Hit,
    rng: &mut Rng,
    s: &Settings,
) -> Option<Bounce> {
    let facing = hit.facing();
    let shading = hit.shading_facing();
    match material {
        Material::Diffuse { albedo } => {
            // The light sample and the bounce leave from the same moved point, so that
            // both find a light point with the same density, as the MIS weights need
            // (from the hit point itself, grazing rays inside a sphere disagree enough
            // to bias the interior furnace).
            let start = s.offset.start(hit.point, hit.error, facing);
            let sample = direct_light(scene, start, shading, albedo, rng, s);
            let mut direct = sample.map_or(Vec3::ZERO, |l| l.light);
            if let Some(light) = scene.point_light() {
                direct += point_light(scene, &light, start, shading, albedo);
            }
            let (direction, weight, pdf) = diffuse_bounce(shading, albedo, rng, s);
            Some(Bounce {
                direct,
                light_sample: sample.map(|l| (l.point, l.seen)),
                start,
                direction,
                weight: weight * on_side(hit, direction, facing),
                previous: after_diffuse(s.sampling, start.point, pdf),
            })
        }
        specular => {
            let d = ray.direction();
            let next = specular.scatter_specular(
                d,
                shading,
                hit.front_face,
                rng.next_f32(),
            )?;
            let side = if next.transmitted { -facing } else { facing };
            Some(Bounce {
                direct: Vec3::ZERO,
                light_sample: None,
                start: s.offset.start(hit.point, hit.error, side),
                direction: next.direction,
                weight: next.weight * on_side(hit, next.direction, side),
                previous: Previous::Full,
            })
        }
    }
}

/// 1 if `direction` leaves the facet on `side`, else 0: a direction found about a
/// mesh's shading normal can point into the facet, and the path ends there (the
/// throughput 0), as pbrt's and Mitsuba's geometric check ends it. Where the
/// shading normal is the geometric one, every direction found leaves on its side.
fn on_side(hit: &Hit, direction: Vec3, side: Vec3) -> f32 {
    if hit.shading == hit.normal || direction.dot(side) > 0.0 {
        1.0
    } else {
        0.0
    }
}
// ANCHOR_END: scatter

/// The weight of emission found at `hit` (object `index`), given the bounce before.
fn emission_weight(
    scene: &impl Intersect,
    index: usize,
    hit: &Hit,
    previous: Previous,
    s: &Settings,
) -> f32 {
    match previous {
        Previous::Full => 1.0,
        Previous::LightSampled => 0.0,
        Previous::Mis { from, pdf } => {
            let shape = &scene.objects()[index].shape;
            let choose = 1.0 / scene.emitters().len() as f32;
            let light = LightShape::new(shape, s.sphere_lights);
            let light_pdf =
                choose * light.map_or(0.0, |l| l.pdf(from, hit.point, hit.normal));
            power_heuristic(pdf, light_pdf)
        }
    }
}

fn after_diffuse(sampling: Sampling, from: Vec3, pdf: f32) -> Previous {
    match sampling {
        Sampling::UniformHemisphere | Sampling::Cosine => Previous::Full,
        Sampling::NextEvent => Previous::LightSampled,
        Sampling::Mis => Previous::Mis { from, pdf },
    }
}

// ANCHOR: diffuse_bounce
/// A new direction at a Lambertian vertex with unit normal `n` (on the arriving
/// side): the direction, the throughput factor f_r cos / pdf, and the pdf.
///
/// Uniform: pdf = 1/(2 pi), factor = (albedo/pi) cos 2 pi = 2 albedo cos.
/// Cosine (all other strategies): pdf = cos/pi, factor = albedo exactly.
fn diffuse_bounce(
    n: Vec3,
    albedo: Vec3,
    rng: &mut Rng,
    s: &Settings,
) -> (Vec3, Vec3, f32) {
    let frame = Basis::around(n);
    let u = rng.next_vec2();
    match s.sampling {
        Sampling::UniformHemisphere => {
            let local = uniform_hemisphere(u);
            let pdf = uniform_hemisphere_pdf(local.z);
            (to_unit(frame, local, n), 2.0 * albedo * local.z, pdf)
        }
        _ => {
            let local = cosine_hemisphere(u);
            let pdf = cosine_hemisphere_pdf(local.z);
            (to_unit(frame, local, n), albedo, pdf)
        }
    }
}
// ANCHOR_END: diffuse_bounce

/// A local direction in world space, renormalised (the frame is orthonormal to
/// about 1e-7, the sample to about as much); the normal if rounding broke it.
fn to_unit(frame: Basis, local: Vec3, n: Vec3) -> Vec3 {
    frame.to_world(local).normalize_or(n)
}
