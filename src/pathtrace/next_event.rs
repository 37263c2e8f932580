//! Next event estimation: at a diffuse vertex, one sample aimed at a light and a
//! shadow ray to check that nothing blocks it (the direct-lighting estimator of
//! pbrt-v3 section 14.3, with the MIS weight of Veach 1997 section 9.2); and the
//! scene's point light, a delta light that only a shadow ray can find (pbrt-v3
//! section 12.2), at every diffuse vertex whatever the strategy.

use glam::Vec3;

use crate::material::diffuse_brdf;
use crate::pathtrace::light::{LightPoint, LightShape};
use crate::pathtrace::mis::power_heuristic;
use crate::pathtrace::settings::{Sampling, Settings};
use crate::rng::Rng;
use crate::sampling::cosine_hemisphere_pdf;
use crate::scene::{Intersect, PointLight};
use crate::spawn::{Offset, Start};

// ANCHOR: direct_light
/// One light sample of next event estimation: the point aimed at on a light,
/// whether it was seen, and the light it brings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct LightSample {
    pub(super) point: Vec3,
    /// The point faces the vertex and its shadow ray got through.
    pub(super) seen: bool,
    /// f_r L_e cos / pdf (times the MIS weight); 0 unless seen.
    pub(super) light: Vec3,
}

/// Next event estimation at a Lambertian vertex: one light chosen uniformly, one
/// point on it, one shadow ray. `None` when the strategy samples no light, the
/// scene has none, or no point could be drawn.
pub(super) fn direct_light(
    scene: &impl Intersect,
    from: Start,
    n: Vec3,
    albedo: Vec3,
    rng: &mut Rng,
    s: &Settings,
) -> Option<LightSample> {
    if !matches!(s.sampling, Sampling::NextEvent | Sampling::Mis)
        || scene.emitters().is_empty()
    {
        return None;
    }
    let count = scene.emitters().len();
    let pick = ((rng.next_f32() * count as f32) as usize).min(count - 1);
    let light = &scene.objects()[scene.emitters()[pick]];
    let u = rng.next_vec2();
    let y = LightShape::new(&light.shape, s.sphere_lights)?.sample(from.point, u)?;
    // Behind a lamp there is nothing to see, and no shadow ray to trace.
    let radiance = light.emission_seen(y.normal.dot(from.point - y.point) > 0.0);
    let seen = if radiance == Vec3::ZERO {
        None
    } else {
        unoccluded(scene, from, n, &y, s.offset)
    };
    let Some(cos) = seen else {
        let (point, seen, light) = (y.point, false, Vec3::ZERO);
        return Some(LightSample { point, seen, light });
    };
    let pdf = y.pdf / count as f32;
    let weight = match s.sampling {
        Sampling::Mis => power_heuristic(pdf, cosine_hemisphere_pdf(cos)),
        _ => 1.0,
    };
    let light = diffuse_brdf(albedo) * radiance * (cos * weight / pdf);
    Some(LightSample {
        point: y.point,
        seen: true,
        light,
    })
}
// ANCHOR_END: direct_light

/// The cosine (with the unit normal `n`) of the direction from `from` to the light
/// point `light` (its point y, normal n_l and error bound), if y is above the surface
/// and no object lies between: a shadow ray from `from` to y moved off the light
/// towards it by `offset`, the same rule at both ends.
fn unoccluded(
    scene: &impl Intersect,
    from: Start,
    n: Vec3,
    light: &LightPoint,
    offset: Offset,
) -> Option<f32> {
    let (y, n_l) = (light.point, light.normal);
    let direction = (y - from.point).try_normalize()?;
    let cos = n.dot(direction);
    if cos.is_nan() || cos <= 0.0 {
        return None;
    }
    let n_l = if n_l.dot(from.point - y) >= 0.0 {
        n_l
    } else {
        -n_l
    };
    let shadow = from.ray_to(offset.start(y, light.error, n_l))?;
    (!scene.occluded(&shadow.ray, shadow.range)).then_some(cos)
}

// ANCHOR: point_light
/// The light of the point `light` at a Lambertian vertex (unit normal `n`, albedo):
/// f_r (pi I) cos(theta) / d^2, if the shadow ray from `from` to the light gets
/// through. A point light sends all its light to `from` along one direction, so
/// the integral over the hemisphere collapses to that one term (pbrt-v3
/// section 12.2), with no density to divide by; no bounce can meet a point, so this
/// is the only place it is counted, in every strategy, and under MIS its weight is 1.
pub(super) fn point_light(
    scene: &impl Intersect,
    light: &PointLight,
    from: Start,
    n: Vec3,
    albedo: Vec3,
) -> Vec3 {
    let to_light = light.position - from.point;
    let d2 = to_light.length_squared();
    let cos = n.dot(to_light) / d2.sqrt();
    let lit = cos > 0.0 // also false for NaN: the vertex at the light
        && from
            .ray_to(Start::at(light.position))
            .is_some_and(|shadow| !scene.occluded(&shadow.ray, shadow.range));
    let sample = diffuse_brdf(albedo) * light.radiant_intensity() * (cos / d2);
    if lit && sample.is_finite() {
        sample
    } else {
        Vec3::ZERO
    }
}
// ANCHOR_END: point_light
