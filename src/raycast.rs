//! Ray casting (Lecture 4, after Appel 1968): one ray per pixel, the closest hit.

use glam::Vec3;

use crate::offset::Offset;
use crate::ray::Ray;
use crate::scene::Scene;

// ANCHOR: shadowless
/// The lecture's shadowless ray casting for one ray: the colour of the primitive
/// with the closest intersection, or the background colour.
pub fn shadowless(scene: &Scene, ray: &Ray) -> Vec3 {
    match scene.closest_hit(ray, 0.0, f32::INFINITY) {
        Some((_, object)) => object.colour,
        None => scene.background(),
    }
}
// ANCHOR_END: shadowless

/// The share of light that reaches surfaces in shadow (a crude stand-in for the
/// light bounced around the scene, which lesson 10 computes properly).
pub const AMBIENT: f32 = 0.1;

// ANCHOR: lambert
/// One step past the slides: Lambert's cosine law from the point light, and a shadow
/// ray towards it. Colour = albedo (ambient + I cos(theta) / distance^2 if the light
/// is visible), theta the angle between the normal and the direction to the light.
pub fn lambert(scene: &Scene, ray: &Ray, offset: Offset) -> Vec3 {
    let Some((hit, object)) = scene.closest_hit(ray, 0.0, f32::INFINITY) else {
        return scene.background();
    };
    // Shade the side the ray arrived from.
    let n = if hit.front_face {
        hit.normal
    } else {
        -hit.normal
    };
    let light = scene.light();
    let to_light = light.position - hit.point;
    let distance = to_light.length();
    let l = to_light / distance;
    let cos_theta = n.dot(l);
    let mut colour = object.colour * AMBIENT;
    if cos_theta > 0.0 && distance > 0.0 {
        let (origin, t_min) = offset.start(hit.point, n);
        let shadow_ray = Ray::new(origin, light.position - origin);
        let lit = shadow_ray.is_ok_and(|r| !scene.occluded(&r, t_min, distance));
        if lit {
            colour += object.colour * light.intensity * cos_theta / (distance * distance);
        }
    }
    colour
}
// ANCHOR_END: lambert
