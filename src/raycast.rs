//! Ray casting (Lecture 4, after Appel 1968): one ray per pixel, the closest hit.

use glam::Vec3;

use crate::camera::Camera;
use crate::error::Result;
use crate::framebuffer::Framebuffer;
use crate::lighting;
use crate::ray::{Interval, Ray};
use crate::render::render;
use crate::scene::Intersect;
use crate::spawn::{Offset, Start};

/// The whole image in one call: every pixel [`lit`] by the scene's point light,
/// with shadow rays offset as the renderers' default ([`Offset::default`]). The
/// lessons write the same thing as `render(camera, |r| lit(scene, r, offset))`.
pub fn ray_cast(scene: &impl Intersect, camera: &Camera) -> Result<Framebuffer> {
    render(camera, |ray| lit(scene, ray, Offset::default()))
}

// ANCHOR: shadowless
/// The lecture's shadowless ray casting for one ray: the colour of the primitive
/// with the closest intersection, or the background colour.
pub fn shadowless(scene: &impl Intersect, ray: &Ray) -> Vec3 {
    match scene.closest_object(ray, Interval::AHEAD) {
        Some(object) => scene.objects()[object].colour(),
        None => scene.background(),
    }
}
// ANCHOR_END: shadowless

// ANCHOR: lambert
/// One step past the slides: Lambert's cosine law from the scene's point light
/// ([`lighting::at_hit`]), with a shadow ray towards the light deciding whether it
/// is visible.
pub fn lit(scene: &impl Intersect, ray: &Ray, offset: Offset) -> Vec3 {
    let Some(found) = scene.closest(ray, Interval::AHEAD) else {
        return scene.background();
    };
    let hit = found.hit;
    lighting::at_hit(scene.scene(), &hit, scene.object(&found), |light| {
        let from = offset.start(hit.point, hit.error, hit.facing());
        from.ray_to(Start::at(light.position))
            .is_some_and(|shadow| !scene.occluded(&shadow.ray, shadow.range))
    })
}
// ANCHOR_END: lambert

// ANCHOR: unshadowed
/// The same light with no shadow ray: every surface facing the light is lit. This is
/// what a rasterizer computes without a shadow trick, and the reference lesson 09
/// compares its images against.
pub fn lit_unshadowed(scene: &impl Intersect, ray: &Ray) -> Vec3 {
    match scene.closest(ray, Interval::AHEAD) {
        Some(found) => {
            lighting::at_hit(scene.scene(), &found.hit, scene.object(&found), |_| true)
        }
        None => scene.background(),
    }
}
// ANCHOR_END: unshadowed
