//! The path tracer's estimator of the rendering equation (Lecture 2, Kajiya 1986):
//!
//! L_o(p, w_o) = L_e(p, w_o) + integral over the hemisphere of f_r L_i cos theta_i dw_i.
//!
//! One sample of the integral follows one direction; L_i in that direction is again
//! L_o of the next surface, so the estimate is a path: a loop that keeps a throughput
//! beta (the product of f_r cos / pdf so far) and adds beta L_e at every vertex where
//! light is found. Four ways to find it, from worst to best in most scenes:
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
//! hit: after a specular bounce emission always counts fully. The environment is not
//! a light that can be sampled, so every strategy counts it fully when a ray escapes.

use glam::Vec3;

use crate::basis::Basis;
use crate::material::Material;
use crate::pathtrace::light::LightShape;
use crate::pathtrace::mis::power_heuristic;
use crate::pathtrace::next_event::{Start, direct_light};
use crate::pathtrace::observer::PathObserver;
use crate::pathtrace::rng::Rng;
use crate::pathtrace::roulette::survives_roulette;
use crate::pathtrace::settings::{Sampling, Settings};
use crate::ray::{Interval, Ray};
use crate::sampling::{
    cosine_hemisphere, cosine_hemisphere_pdf, uniform_hemisphere, uniform_hemisphere_pdf,
};
use crate::scene::Intersect;
use crate::shapes::Hit;

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
/// One sample of the radiance arriving along `ray`: a path, traced iteratively.
pub fn radiance(scene: &impl Intersect, ray: Ray, rng: &mut Rng, settings: &Settings) -> Vec3 {
    radiance_observed(scene, ray, rng, settings, &mut ())
}

/// [`radiance`], telling `observer` every vertex of the path as it is traced. The
/// observer only watches: the random numbers and the sample are the same.
pub fn radiance_observed(
    scene: &impl Intersect,
    ray: Ray,
    rng: &mut Rng,
    settings: &Settings,
    observer: &mut impl PathObserver,
) -> Vec3 {
    let mut sum = Vec3::ZERO;
    let mut beta = Vec3::ONE;
    let (mut ray, mut range) = (ray, Interval::AHEAD);
    let mut previous = Previous::Full;
    let mut bounce = 0u32;
    // A diffuse vertex, then only specular ones since: light found now is a caustic
    // (told to the observer only; the sample is the same).
    let (mut diffuse_seen, mut caustic) = (false, false);
    loop {
        let Some(found) = scene.closest(&ray, range) else {
            sum += beta * scene.background();
            observer.light(beta * scene.background(), caustic);
            observer.escaped(ray.direction());
            break;
        };
        let (hit, index) = (found.hit, found.object);
        observer.vertex(hit.point, index);
        let object = &scene.objects()[index];
        if object.is_emissive() {
            let weight = emission_weight(scene, index, &hit, previous, settings);
            let found = beta * object.emission_seen(hit.front_face) * weight;
            sum += found;
            observer.light(found, caustic);
        }
        // A hit so far away that its point overflowed (an infinite plane met at a
        // grazing angle) gives no finite place to continue from: the path ends.
        if settings.max_depth.is_some_and(|m| bounce >= m) || !hit.point.is_finite() {
            break;
        }
        let material = object.material;
        let Some(next) = scatter(scene, material, &ray, &hit, rng, settings, observer) else {
            break;
        };
        sum += beta * next.direct;
        observer.light(beta * next.direct, false);
        (diffuse_seen, caustic) = if next.specular {
            (diffuse_seen, diffuse_seen)
        } else {
            (true, false)
        };
        beta *= next.weight;
        bounce += 1;
        if !survives_roulette(&mut beta, bounce, rng, settings) {
            break;
        }
        ray = Ray::from_checked(next.start.point, next.direction);
        range.min = next.start.t_min;
        previous = next.previous;
    }
    sum
}
// ANCHOR_END: radiance

/// What happens at one vertex: light found by a light sample, and the next ray.
struct Bounce {
    /// f_r L_e cos / pdf from next event estimation (0 without it).
    direct: Vec3,
    /// Where the next ray starts.
    start: Start,
    /// Its unit direction.
    direction: Vec3,
    /// The throughput factor f_r cos / pdf.
    weight: Vec3,
    /// How emission found by the next ray is weighted.
    previous: Previous,
    /// The bounce was specular (mirror or glass).
    specular: bool,
}

// ANCHOR: scatter
/// The light sample (if any) and the next ray at `hit`, by the material there.
/// `None` only if a specular material had no direction to give.
fn scatter(
    scene: &impl Intersect,
    material: Material,
    ray: &Ray,
    hit: &Hit,
    rng: &mut Rng,
    s: &Settings,
    observer: &mut impl PathObserver,
) -> Option<Bounce> {
    let facing = hit.facing();
    match material {
        Material::Diffuse { albedo } => {
            let start = Start::new(hit.point, hit.error, facing, s.offset);
            let direct = direct_light(scene, start, facing, albedo, rng, s, observer);
            let (direction, weight, pdf) = diffuse_bounce(facing, albedo, rng, s);
            Some(Bounce {
                direct,
                start,
                direction,
                weight,
                previous: after_diffuse(s.sampling, start.point, pdf),
                specular: false,
            })
        }
        specular => {
            let d = ray.direction();
            let next = specular.scatter_specular(d, facing, hit.front_face, rng.next_f32())?;
            let side = if next.transmitted { -facing } else { facing };
            Some(Bounce {
                direct: Vec3::ZERO,
                start: Start::new(hit.point, hit.error, side, s.offset),
                direction: next.direction,
                weight: next.weight,
                previous: Previous::Full,
                specular: true,
            })
        }
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
            let choose = 1.0 / scene.lights().len() as f32;
            let light = LightShape::new(shape, s.sphere_lights);
            let light_pdf = choose * light.map_or(0.0, |l| l.pdf(from, hit.point, hit.normal));
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
fn diffuse_bounce(n: Vec3, albedo: Vec3, rng: &mut Rng, s: &Settings) -> (Vec3, Vec3, f32) {
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
