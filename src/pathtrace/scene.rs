//! The path tracer's scene: a plain list of objects (shape, material, emission),
//! the emissive ones also listed as lights to aim samples at, and a uniform
//! environment radiance for rays that escape. Closest hit by testing every object,
//! as in Appel's ray casting: no acceleration structure.

use glam::Vec3;

use crate::error::{Error, Result, finite3};
use crate::pathtrace::material::Material;
use crate::ray::Ray;
use crate::shapes::{Hit, Shape};

/// One primitive with its material and the radiance L_e it emits.
///
/// Emission is two-sided: L_e leaves the surface on both sides. The furnace seen
/// from inside a sphere needs that; a light that must shine one way (the Cornell
/// box's ceiling panel) is placed with its back facing a wall.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The surface.
    pub shape: Shape,
    /// How it scatters light.
    pub material: Material,
    /// The radiance it emits, linear RGB; zero for most objects.
    pub emission: Vec3,
}

impl Object {
    /// A surface that does not emit.
    pub fn new(shape: Shape, material: Material) -> Object {
        Object {
            shape,
            material,
            emission: Vec3::ZERO,
        }
    }

    /// A surface that emits `emission`.
    pub fn emitting(shape: Shape, material: Material, emission: Vec3) -> Object {
        Object {
            shape,
            material,
            emission,
        }
    }

    /// `true` if it emits any light.
    pub fn is_emissive(&self) -> bool {
        self.emission != Vec3::ZERO
    }
}

/// Objects, lights and the environment.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    objects: Vec<Object>,
    lights: Vec<usize>,
    environment: Vec3,
}

/// `v` if finite and not negative in any channel.
fn radiance(param: &'static str, v: Vec3) -> Result<Vec3> {
    let v = finite3(param, v)?;
    if v.min_element() >= 0.0 {
        Ok(v)
    } else {
        Err(Error::Invalid {
            param,
            reason: "must not be negative",
        })
    }
}

impl Scene {
    /// A scene of `objects` under a uniform `environment` radiance.
    ///
    /// Rejects NaN, infinite or negative emission and environment, materials that
    /// fail [`Material::check`], and emission on
    /// any shape but a sphere or a quad: every emitter must be a light that next
    /// event estimation can sample, or its light would be missed.
    pub fn new(objects: Vec<Object>, environment: Vec3) -> Result<Scene> {
        let mut lights = Vec::new();
        for (i, o) in objects.iter().enumerate() {
            radiance("emission", o.emission)?;
            o.material.check()?;
            if o.is_emissive() {
                if !matches!(o.shape, Shape::Sphere(_) | Shape::Quad(_)) {
                    return Err(Error::Invalid {
                        param: "emission",
                        reason: "is only allowed on spheres and quads (the lights we can sample)",
                    });
                }
                lights.push(i);
            }
        }
        Ok(Scene {
            objects,
            lights,
            environment: radiance("environment", environment)?,
        })
    }

    /// The objects.
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The indices (into [`Scene::objects`]) of the emissive objects.
    pub fn lights(&self) -> &[usize] {
        &self.lights
    }

    /// The radiance of every ray that escapes.
    pub fn environment(&self) -> Vec3 {
        self.environment
    }

    // ANCHOR: closest_hit
    /// The nearest crossing with `t_min < t < t_max` and the index of its object:
    /// every object is tested, the window shrinking to each hit found.
    pub fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<(Hit, usize)> {
        let mut closest = None;
        let mut t_max = t_max;
        for (i, object) in self.objects.iter().enumerate() {
            if let Some(hit) = object.shape.hit(ray, t_min, t_max) {
                t_max = hit.t;
                closest = Some((hit, i));
            }
        }
        closest
    }
    // ANCHOR_END: closest_hit

    /// `true` if anything crosses the ray with `t_min < t < t_max` (a shadow ray).
    pub fn occluded(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        self.objects
            .iter()
            .any(|o| o.shape.hit(ray, t_min, t_max).is_some())
    }
}
