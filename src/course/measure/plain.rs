//! The plain reference: a scene cast with the textbook tests, each answering only
//! `t`, with no robustness at all. It is what a first ray tracer written from
//! *Ray Tracing in One Weekend* computes, and it is here only to be timed against
//! the crate's robust caster in the same run, so that what robustness costs is
//! measured rather than guessed (lesson 11, BENCHMARKS.md).
//!
//! - sphere: the school formula (-b +- sqrt(b^2 - 4ac)) / 2a (STABILITY S1 fails);
//! - triangle: Möller-Trumbore (S4, S5 leak);
//! - box: the slab test with 1/d from the ray, not NaN-safe for rays in a face plane;
//! - plane: (p0 - o) . n / (d . n).
//!
//! It renders the same picture as [`crate::raycast::shadowless`] almost everywhere;
//! the pixels where the two differ are the failures the robust tests fix.

use glam::Vec3;

use crate::ray::Ray;
use crate::scene::Scene;
use crate::shapes::Shape;

/// One primitive, as the textbook stores it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Plain {
    Sphere { centre: Vec3, radius_sq: f32 },
    Plane { point: Vec3, normal: Vec3 },
    Box { min: Vec3, max: Vec3 },
    Triangle { v0: Vec3, e1: Vec3, e2: Vec3 },
}

/// A scene of spheres, planes, boxes and triangles, with each object's colour.
#[derive(Clone, Debug, PartialEq)]
pub struct PlainScene {
    primitives: Vec<(Plain, Vec3)>,
    background: Vec3,
}

impl PlainScene {
    /// The plain copy of `scene`, or `None` if it holds a shape the textbook caster
    /// does not know (a quad, a quadric, an instance).
    pub fn new(scene: &Scene) -> Option<PlainScene> {
        let primitives = scene
            .objects()
            .iter()
            .map(|o| Some((plain(&o.shape)?, o.colour())))
            .collect::<Option<Vec<_>>>()?;
        Some(PlainScene {
            primitives,
            background: scene.background(),
        })
    }

    /// Shadowless ray casting: the colour of the nearest primitive, or the background.
    pub fn shadowless(&self, ray: &Ray) -> Vec3 {
        let (o, d) = (ray.origin(), ray.direction());
        let inv_d = d.recip();
        let mut t_max = f32::INFINITY;
        let mut colour = self.background;
        for &(primitive, c) in &self.primitives {
            if let Some(t) = nearest(primitive, o, d, inv_d, t_max) {
                t_max = t;
                colour = c;
            }
        }
        colour
    }
}

fn plain(shape: &Shape) -> Option<Plain> {
    Some(match shape {
        Shape::Sphere(s) => Plain::Sphere {
            centre: s.centre(),
            radius_sq: s.radius() * s.radius(),
        },
        Shape::Plane(p) => Plain::Plane {
            point: p.point(),
            normal: p.normal(),
        },
        Shape::Aabb(b) => Plain::Box {
            min: b.min(),
            max: b.max(),
        },
        Shape::Triangle(tri) => {
            let [v0, v1, v2] = tri.vertices();
            Plain::Triangle {
                v0,
                e1: v1 - v0,
                e2: v2 - v0,
            }
        }
        _ => return None,
    })
}

/// The textbook `t` of the nearest crossing with 0 < t < t_max.
#[inline]
fn nearest(primitive: Plain, o: Vec3, d: Vec3, inv_d: Vec3, t_max: f32) -> Option<f32> {
    let t = match primitive {
        Plain::Sphere { centre, radius_sq } => {
            let f = o - centre;
            let (half_b, c) = (f.dot(d), f.dot(f) - radius_sq);
            let disc = half_b * half_b - c;
            if disc < 0.0 {
                return None;
            }
            let s = disc.sqrt();
            let t0 = -half_b - s;
            if t0 > 0.0 { t0 } else { -half_b + s }
        }
        Plain::Plane { point, normal } => (point - o).dot(normal) / d.dot(normal),
        Plain::Box { min, max } => {
            let (a, b) = ((min - o) * inv_d, (max - o) * inv_d);
            let (t0, t1) = (a.min(b).max_element(), a.max(b).min_element());
            if t0 > t1 {
                return None;
            }
            if t0 > 0.0 { t0 } else { t1 }
        }
        Plain::Triangle { v0, e1, e2 } => {
            let p = d.cross(e2);
            let inv = 1.0 / e1.dot(p);
            let tvec = o - v0;
            let b1 = tvec.dot(p) * inv;
            let q = tvec.cross(e1);
            let b2 = d.dot(q) * inv;
            if b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0 {
                return None;
            }
            e2.dot(q) * inv
        }
    };
    (t > 0.0 && t < t_max).then_some(t)
}
