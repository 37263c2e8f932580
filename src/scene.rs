//! A scene: a plain list of primitives with their colours, a background, and one
//! point light. No acceleration structure: every ray is tested against every
//! primitive, as in Appel's ray casting (Lecture 4); lesson 11 measures when that
//! stops paying.

use glam::Vec3;

use crate::error::{Result, finite3};
use crate::ray::Ray;
use crate::shapes::{Hit, Shape};

/// One primitive and its colour (linear RGB albedo).
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The surface.
    pub shape: Shape,
    /// Its colour.
    pub colour: Vec3,
}

/// A point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Where it is.
    pub position: Vec3,
    /// Its colour and strength, linear RGB.
    pub intensity: Vec3,
}

/// Everything a ray caster needs to know about the world.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    objects: Vec<Object>,
    background: Vec3,
    light: PointLight,
}

impl Scene {
    /// A scene of `objects` in front of `background`, lit by `light`.
    pub fn new(objects: Vec<Object>, background: Vec3, light: PointLight) -> Result<Scene> {
        for o in &objects {
            finite3("colour", o.colour)?;
        }
        finite3("light position", light.position)?;
        finite3("light intensity", light.intensity)?;
        Ok(Scene {
            objects,
            background: finite3("background", background)?,
            light,
        })
    }

    /// The primitives.
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The colour of rays that hit nothing.
    pub fn background(&self) -> Vec3 {
        self.background
    }

    /// The light.
    pub fn light(&self) -> PointLight {
        self.light
    }

    // ANCHOR: closest_hit
    /// The closest crossing with `t_min < t < t_max` over every primitive, and the
    /// object it belongs to: the inner loop of the lecture's ray casting algorithm.
    /// Each hit found shrinks `t_max`, so later primitives only count if nearer.
    pub fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<(Hit, &Object)> {
        let mut closest = None;
        let mut t_max = t_max;
        for object in &self.objects {
            if let Some(hit) = object.shape.hit(ray, t_min, t_max) {
                t_max = hit.t;
                closest = Some((hit, object));
            }
        }
        closest
    }
    // ANCHOR_END: closest_hit

    /// True if anything lies on the ray with `t_min < t < t_max` (a shadow ray's question).
    pub fn occluded(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        self.objects
            .iter()
            .any(|o| o.shape.hit(ray, t_min, t_max).is_some())
    }
}
