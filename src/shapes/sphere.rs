//! Ray / sphere: the quadratic |o + t d - c|^2 = r^2, solved two ways.
//!
//! With f = o - c the equation is a t^2 + b t + c' = 0 where a = d . d, b = 2 f . d
//! and c' = f . f - r^2. The textbook solves it as printed; the stable form avoids the
//! two cancellations that break it (STABILITY S1, S2).

use glam::Vec3;

use crate::error::{Result, finite3, positive};
use crate::float::gamma;
use crate::quadratic;
use crate::ray::{Crossings, Interval, Ray};
use crate::shapes::{Aabb, Hit, on_ray_error};

/// A sphere with centre `c` and radius `r > 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    centre: Vec3,
    radius: f32,
}

impl Sphere {
    /// A sphere around `centre`; rejects a non-finite centre and a radius that is not
    /// finite and strictly positive.
    pub fn new(centre: Vec3, radius: f32) -> Result<Sphere> {
        Ok(Sphere {
            centre: finite3("centre", centre)?,
            radius: positive("radius", radius)?,
        })
    }

    /// The centre `c`.
    pub fn centre(&self) -> Vec3 {
        self.centre
    }

    /// The radius `r`.
    pub fn radius(&self) -> f32 {
        self.radius
    }

    /// The bounding box c - r to c + r, moved out by gamma(3) (max |c_i| + r) so
    /// that the rounding of c +- r cannot cut into the sphere; `None` if it overflows.
    pub fn bounds(&self) -> Option<Aabb> {
        let r = Vec3::splat(self.radius);
        let margin = gamma(3) * (self.centre.abs().max_element() + self.radius);
        Aabb::new(self.centre - r, self.centre + r)
            .ok()?
            .padded(margin)
    }

    // ANCHOR: roots_textbook
    /// Both roots, ascending, by the school formula t = (-b +- sqrt(b^2 - 4ac)) / 2a
    /// ([`quadratic::textbook`]).
    ///
    /// For a small sphere far away b^2 and 4ac are both about 4 D^2 and their
    /// difference, of order r^2, is lost to rounding: in f32 the roots' error grows
    /// with D/r, and from a few thousand radii on hit/miss answers go wrong, about half
    /// of them at D/r = 1e4 (STABILITY S1; lesson 11's chart 1 measures where). Kept to
    /// show that failure.
    pub fn roots_textbook(&self, ray: &Ray) -> Crossings {
        let f = ray.origin() - self.centre;
        let d = ray.direction();
        let a = d.dot(d);
        let b = 2.0 * f.dot(d);
        let c = f.dot(f) - self.radius * self.radius;
        quadratic::textbook(a, b, c)
    }
    // ANCHOR_END: roots_textbook

    // ANCHOR: roots_stable
    /// Both roots, ascending, computed so that neither cancels.
    ///
    /// Discriminant (Hearn-Baker form, Ray Tracing Gems ch. 7): with l = f - (f.d / a)
    /// d, the vector from the centre to the point of the line nearest it,
    /// b^2 - 4ac = 4a (r^2 - |l|^2); for a unit d this is 4 (r^2 - |f - (f.d) d|^2).
    /// Roots: [`quadratic::stable`], q = -(b + sign(b) sqrt(disc)) / 2, then t = c/q
    /// and q/a; no root subtracts nearly equal numbers.
    #[inline]
    pub fn roots_stable(&self, ray: &Ray) -> Crossings {
        let f = ray.origin() - self.centre;
        let d = ray.direction();
        let a = d.dot(d);
        let half_b = f.dot(d);
        let c = f.dot(f) - self.radius * self.radius;
        let l = f - (half_b / a) * d;
        let delta = self.radius * self.radius - l.dot(l);
        quadratic::stable(a, 2.0 * half_b, c, 4.0 * (a * delta))
    }
    // ANCHOR_END: roots_stable

    // ANCHOR: sphere_hit
    /// The nearest root within `range`, by [`Sphere::roots_stable`]: all
    /// that the closest-hit loop asks of a sphere.
    #[inline]
    pub fn nearest(&self, ray: &Ray, range: Interval) -> Option<f32> {
        self.roots_stable(ray).first_in(range)
    }

    /// The hit record at `t`: the point, its error bound and the outward normal.
    ///
    /// o + t d carries t's rounding error, which grows with t: seen from far away the
    /// point can lie inside the sphere by more than any offset scaled to |p|. So the
    /// point is projected back onto the sphere in the sphere's own frame,
    /// l = (o + t d - c) r / |o + t d - c| (pbrt-v4 section 6.8.5, "Refining the hit
    /// point"), whose error no longer depends on t: gamma(5) |l| for the projection,
    /// one step more for safety, and gamma(1) |c + l| for the sum that takes it back
    /// to the world. The normal is l / r.
    pub fn hit_at(&self, ray: &Ray, t: f32) -> Hit {
        let local = ray.at(t) - self.centre;
        let length = local.length();
        if !(length > 0.0 && length.is_finite()) {
            let point = ray.at(t);
            return Hit::new(ray, t, point, -ray.direction(), on_ray_error(ray, t));
        }
        let (point, error) = self.surface_point(local / length);
        let normal =
            ((point - self.centre) / self.radius).normalize_or(-ray.direction());
        Hit::new(ray, t, point, normal, error)
    }

    /// The point c + r u of the sphere in the direction `u` (unit up to rounding), and
    /// its error bound: gamma(6) r |u| for r u, whose length is r only up to u's
    /// rounding, and gamma(1) |c + r u| for the sum.
    pub fn surface_point(&self, u: Vec3) -> (Vec3, Vec3) {
        let local = self.radius * u;
        let point = self.centre + local;
        (point, gamma(6) * local.abs() + gamma(1) * point.abs())
    }

    /// The nearest crossing within `range`: [`Sphere::nearest`], then
    /// [`Sphere::hit_at`].
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = self.nearest(ray, range)?;
        Some(self.hit_at(ray, t))
    }
    // ANCHOR_END: sphere_hit

    /// Both crossings of the ray's line, ascending: [`Sphere::roots_stable`], entry
    /// and exit, negative behind the origin, equal for a tangent ray.
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        self.roots_stable(ray)
    }

    /// The outward unit normal at `p`: (p - c) / r, normalised (p on the surface makes
    /// it unit already); the zero vector at the centre.
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        ((p - self.centre) / self.radius).normalize_or_zero()
    }
}
