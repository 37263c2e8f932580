//! Ray / primitive intersection (Lecture 4): sphere, plane, axis-aligned box and
//! triangle, each in its own file, each with the naive method next to the robust one
//! (STABILITY cases S1, S2, S4 to S8).
//!
//! Every routine takes a [`Ray`] (finite origin, unit direction) and reports the
//! nearest crossing with `t_min < t < t_max`. For finite input none of them panics or
//! returns NaN: a comparison that meets a NaN always falls on the "miss" side.

use glam::Vec3;

use crate::ray::Ray;

pub mod aabb;
pub mod instance;
pub mod plane;
pub mod quad;
pub mod quadric;
pub mod sphere;
pub mod triangle;

pub use aabb::Aabb;
pub use instance::Instance;
pub use plane::Plane;
pub use quad::Quad;
pub use quadric::Quadric;
pub use sphere::Sphere;
pub use triangle::Triangle;

/// Where a ray crosses a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter: the signed distance from the ray's origin.
    pub t: f32,
    /// The point on the surface.
    pub point: Vec3,
    /// The unit normal, pointing out of the surface whichever side the ray came from.
    pub normal: Vec3,
    /// `true` if the ray arrived from the side the normal points to (d . n < 0).
    pub front_face: bool,
}

impl Hit {
    /// A hit at `t` and `point` with outward unit `normal`; `front_face` follows from
    /// the sign of d . n.
    pub(crate) fn new(ray: &Ray, t: f32, point: Vec3, normal: Vec3) -> Hit {
        Hit {
            t,
            point,
            normal,
            front_face: ray.direction().dot(normal) < 0.0,
        }
    }

    // ANCHOR: facing
    /// The front-face rule, written once for every renderer: the unit normal on the
    /// side the ray came from, `normal` for a front face and `-normal` for a back
    /// face, so that shading and the offset of the next ray see the lit side.
    pub fn facing(&self) -> Vec3 {
        if self.front_face {
            self.normal
        } else {
            -self.normal
        }
    }
    // ANCHOR_END: facing
}

/// `t_min < t < t_max`, and `false` for NaN.
pub(crate) fn in_open_range(t: f32, t_min: f32, t_max: f32) -> bool {
    t > t_min && t < t_max
}

/// One primitive of a scene.
///
/// Not `Copy`: an [`Instance`] owns the shape it places, behind a `Box`.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Sphere(Sphere),
    Plane(Plane),
    Aabb(Aabb),
    Triangle(Triangle),
    Quadric(Quadric),
    Quad(Quad),
    Instance(Box<Instance>),
}

impl Shape {
    /// The nearest crossing of `ray` with `t_min < t < t_max`, if any.
    pub fn hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        match self {
            Shape::Sphere(s) => s.hit(ray, t_min, t_max),
            Shape::Plane(p) => p.hit(ray, t_min, t_max),
            Shape::Aabb(b) => b.hit(ray, t_min, t_max),
            Shape::Triangle(tri) => tri.hit(ray, t_min, t_max),
            Shape::Quadric(q) => q.hit(ray, t_min, t_max),
            Shape::Quad(q) => q.hit(ray, t_min, t_max),
            Shape::Instance(i) => i.hit(ray, t_min, t_max),
        }
    }

    /// The shape's bounding box, for an acceleration structure ([`crate::bvh`]), or
    /// `None` for a shape without one: a plane, a quadric (most are unbounded; an
    /// ellipsoid is not, but no scene here needs its box), an instance of either, or
    /// a box that overflows f32.
    pub fn bounds(&self) -> Option<Aabb> {
        match self {
            Shape::Sphere(s) => s.bounds(),
            Shape::Plane(_) | Shape::Quadric(_) => None,
            Shape::Aabb(b) => Some(*b),
            Shape::Triangle(tri) => tri.bounds(),
            Shape::Quad(q) => q.bounds(),
            Shape::Instance(i) => i.bounds(),
        }
    }
}
