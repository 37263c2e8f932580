//! Ray / sphere: the quadratic |o + t d - c|^2 = r^2, solved two ways.
//!
//! With f = o - c the equation is a t^2 + b t + c' = 0 where a = d . d, b = 2 f . d
//! and c' = f . f - r^2. The textbook solves it as printed; the stable form avoids the
//! two cancellations that break it (STABILITY S1, S2).

use glam::Vec3;

use crate::error::{Result, finite3, positive};
use crate::ray::{Interval, Ray};
use crate::shapes::aabb::gamma;
use crate::shapes::{Aabb, Crossings, Hit, on_ray_error};

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
    /// Both roots, ascending, by the school formula t = (-b +- sqrt(b^2 - 4ac)) / 2a.
    ///
    /// For a small sphere far away b^2 and 4ac are both about 4 D^2 and their
    /// difference, of order r^2, is lost to rounding: in f32 the roots' error grows with
    /// D/r, and from a few thousand radii on hit/miss answers go wrong, about half of
    /// them at D/r = 1e4 (STABILITY S1; lesson 11's chart 1 measures where). Kept to
    /// show that failure.
    pub fn roots_textbook(&self, ray: &Ray) -> Option<(f32, f32)> {
        let f = ray.origin() - self.centre;
        let d = ray.direction();
        let a = d.dot(d);
        let b = 2.0 * f.dot(d);
        let c = f.dot(f) - self.radius * self.radius;
        let disc = b * b - 4.0 * a * c;
        if disc.is_nan() || disc < 0.0 {
            return None;
        }
        let s = disc.sqrt();
        finite_pair((-b - s) / (2.0 * a), (-b + s) / (2.0 * a))
    }
    // ANCHOR_END: roots_textbook

    // ANCHOR: roots_stable
    /// Both roots, ascending, computed so that neither cancels.
    ///
    /// Discriminant (Hearn-Baker form, Ray Tracing Gems ch. 7): with l = f - (f.d / a) d,
    /// the vector from the centre to the point of the line nearest it,
    /// b^2 - 4ac = 4a (r^2 - |l|^2); for a unit d this is 4 (r^2 - |f - (f.d) d|^2).
    /// Roots (Numerical Recipes 5.6): q = -(b + sign(b) sqrt(disc)) / 2 with
    /// sign(0) = +1, then t = c/q and q/a; no root subtracts nearly equal numbers.
    #[inline]
    pub fn roots_stable(&self, ray: &Ray) -> Option<(f32, f32)> {
        let f = ray.origin() - self.centre;
        let d = ray.direction();
        let a = d.dot(d);
        let half_b = f.dot(d);
        let c = f.dot(f) - self.radius * self.radius;
        let l = f - (half_b / a) * d;
        let delta = self.radius * self.radius - l.dot(l);
        if delta.is_nan() || delta < 0.0 {
            return None;
        }
        // q = -(b + sign(b) sqrt(4 a delta)) / 2 with b = 2 half_b.
        let sign = if half_b >= 0.0 { 1.0 } else { -1.0 };
        let q = -(half_b + sign * (a * delta).sqrt());
        if q == 0.0 {
            // b = 0 and disc = 0: a double root at -b / 2a = 0.
            return Some((0.0, 0.0));
        }
        finite_pair(c / q, q / a)
    }
    // ANCHOR_END: roots_stable

    // ANCHOR: sphere_hit
    /// The nearest root with `t_min < t < t_max`, by [`Sphere::roots_stable`]: all
    /// that the closest-hit loop asks of a sphere.
    #[inline]
    pub fn nearest(&self, ray: &Ray, range: Interval) -> Option<f32> {
        let (t0, t1) = self.roots_stable(ray)?;
        if range.contains(t0) {
            Some(t0)
        } else {
            range.contains(t1).then_some(t1)
        }
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
        let normal = ((point - self.centre) / self.radius).normalize_or(-ray.direction());
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

    /// The nearest crossing with `t_min < t < t_max`: [`Sphere::nearest`], then
    /// [`Sphere::hit_at`].
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = self.nearest(ray, range)?;
        Some(self.hit_at(ray, t))
    }
    // ANCHOR_END: sphere_hit

    /// Both crossings of the ray's line, ascending, from [`Sphere::roots_stable`]:
    /// entry and exit, negative behind the origin, equal for a tangent ray.
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        match self.roots_stable(ray) {
            Some((t0, t1)) => Crossings::two(t0, t1),
            None => Crossings::NONE,
        }
    }

    /// The outward unit normal at `p`: (p - c) / r, normalised (p on the surface makes
    /// it unit already); the zero vector at the centre.
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        ((p - self.centre) / self.radius).normalize_or_zero()
    }
}

/// `(t0, t1)` in ascending order, or `None` if either overflowed or is NaN.
fn finite_pair(t0: f32, t1: f32) -> Option<(f32, f32)> {
    if t0.is_finite() && t1.is_finite() {
        Some((t0.min(t1), t0.max(t1)))
    } else {
        None
    }
}
