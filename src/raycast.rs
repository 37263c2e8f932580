//! Ray casting (Lecture 4, after Appel 1968): one ray per pixel, the closest hit.

use glam::Vec3;

use crate::lighting::{self, AMBIENT};
use crate::offset::Offset;
use crate::ray::Ray;
use crate::scene::Scene;

// ANCHOR: shadowless
/// The lecture's shadowless ray casting for one ray: the colour of the primitive
/// with the closest intersection, or the background colour.
pub fn shadowless(scene: &Scene, ray: &Ray) -> Vec3 {
    match scene.closest_hit(ray, 0.0, f32::INFINITY) {
        Some((_, object)) => object.colour(),
        None => scene.background(),
    }
}
// ANCHOR_END: shadowless

// ANCHOR: lambert
/// One step past the slides: Lambert's cosine law from the scene's point light
/// ([`lighting::lambert`]), with a shadow ray towards the light deciding whether it
/// is visible. A scene without a point light is lit by the ambient term alone.
pub fn lit(scene: &Scene, ray: &Ray, offset: Offset) -> Vec3 {
    let Some((hit, object)) = scene.closest_hit(ray, 0.0, f32::INFINITY) else {
        return scene.background();
    };
    let Some(light) = scene.light() else {
        return object.colour() * AMBIENT;
    };
    let n = hit.facing();
    lighting::lambert(hit.point, n, object.colour(), &light, || {
        let (origin, t_min) = offset.start(hit.point, n);
        let distance = (light.position - hit.point).length();
        Ray::new(origin, light.position - origin)
            .is_ok_and(|r| !scene.occluded(&r, t_min, distance))
    })
}
// ANCHOR_END: lambert

// ANCHOR: unshadowed
/// The same light with no shadow ray: every surface facing the light is lit. This is
/// what a rasterizer computes without a shadow trick, and the reference lesson 09
/// compares its images against.
pub fn lit_unshadowed(scene: &Scene, ray: &Ray) -> Vec3 {
    let Some((hit, object)) = scene.closest_hit(ray, 0.0, f32::INFINITY) else {
        return scene.background();
    };
    let Some(light) = scene.light() else {
        return object.colour() * AMBIENT;
    };
    lighting::lambert(hit.point, hit.facing(), object.colour(), &light, || true)
}
// ANCHOR_END: unshadowed
