//! Lighting shared by every renderer of lessons 08 and 09: Lambert's cosine law from
//! one point light (Lecture 2, "Rasterization Pipeline: Lighting"; Lecture 4 shades
//! ray casting the same way). One formula, so that the ray caster and the
//! rasterizer can only differ in *where* they evaluate it and *whether the light is
//! visible*, never in the arithmetic.

use glam::Vec3;

use crate::scene::{Object, PointLight, Scene};
use crate::shapes::Hit;

/// The share of light that reaches surfaces in shadow (a crude stand-in for the
/// light bounced around the scene and the light of the sky, the scene's background,
/// both of which lesson 10 computes properly).
pub const AMBIENT: f32 = 0.1;

// ANCHOR: lambert
/// The colour of a surface point `p` whose normal `n` (unit) faces the viewer:
/// albedo (AMBIENT + V I cos(theta) / d^2), theta the angle between `n` and the
/// direction to the light, d the distance to it, and V = 1 if `visible()` says the
/// light is seen from `p`, else 0. No direct term when cos(theta) <= 0, and
/// `visible` is only asked then (a shadow ray costs time). Always finite.
pub fn lambert(
    p: Vec3,
    n: Vec3,
    albedo: Vec3,
    light: &PointLight,
    visible: impl FnOnce() -> bool,
) -> Vec3 {
    let to_light = light.position - p;
    let d2 = to_light.length_squared();
    let mut colour = albedo * AMBIENT;
    if d2 > f32::MIN_POSITIVE && d2.is_finite() {
        let cos_theta = n.dot(to_light / d2.sqrt());
        if cos_theta > 0.0 && visible() {
            colour += albedo * light.intensity * cos_theta / d2;
        }
    }
    colour.clamp(Vec3::splat(-f32::MAX), Vec3::splat(f32::MAX))
}
// ANCHOR_END: lambert

/// The colour of `object` at `hit` under `scene`'s point light, by [`lambert`] with
/// the albedo there ([`Object::albedo_at`]: a texture's colour, or the material's)
/// and the shading normal on the side the ray arrived from ([`Hit::shading_facing`]:
/// a smooth mesh's blend of its vertex normals, elsewhere the surface's own normal);
/// `visible(light)` decides whether the light is seen from the hit (a shadow ray, or
/// `true`). A scene with no point light is lit by the ambient term alone. The ray
/// caster and the rasterizer's reference both shade their hits here.
pub fn at_hit(
    scene: &Scene,
    hit: &Hit,
    object: &Object,
    visible: impl FnOnce(&PointLight) -> bool,
) -> Vec3 {
    let albedo = object.albedo_at(hit);
    let Some(light) = scene.point_light() else {
        return albedo * AMBIENT;
    };
    lambert(hit.point, hit.shading_facing(), albedo, &light, || {
        visible(&light)
    })
}
