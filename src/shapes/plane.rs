//! Ray / plane: the points p with (p - p0) . n = 0.

use glam::Vec3;

use crate::error::{Result, finite3, unit};
use crate::float::gamma;
use crate::ray::{Interval, Ray};
use crate::shapes::{Crossings, Hit};

/// The infinite plane through `point` with unit `normal`; the normal's side is the
/// front.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    point: Vec3,
    normal: Vec3,
}

impl Plane {
    /// The plane through `point` perpendicular to `normal` (normalised here).
    ///
    /// Rejects a non-finite point, and a normal that is zero or not finite.
    pub fn new(point: Vec3, normal: Vec3) -> Result<Plane> {
        Ok(Plane {
            point: finite3("point", point)?,
            normal: unit("normal", normal)?,
        })
    }

    /// A point p0 on the plane.
    pub fn point(&self) -> Vec3 {
        self.point
    }

    /// The unit normal n.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    // ANCHOR: plane_t
    /// The `t` where the ray's line meets the plane: t = (p0 - o) . n / (d . n).
    ///
    /// `None` for a ray parallel to the plane (d . n = 0), and when the quotient
    /// overflows (d . n tiny): never NaN, never infinite.
    #[inline]
    pub fn t(&self, ray: &Ray) -> Option<f32> {
        let denom = ray.direction().dot(self.normal);
        if denom == 0.0 {
            return None;
        }
        let t = (self.point - ray.origin()).dot(self.normal) / denom;
        t.is_finite().then_some(t)
    }
    // ANCHOR_END: plane_t

    // ANCHOR: plane_hit
    /// [`Plane::t`] if it lies within `range`.
    #[inline]
    pub fn nearest(&self, ray: &Ray, range: Interval) -> Option<f32> {
        self.t(ray).filter(|&t| range.contains(t))
    }

    /// The hit record at `t`: the point o + t d, the plane's normal.
    pub fn hit_at(&self, ray: &Ray, t: f32) -> Hit {
        let (point, error) = onto_plane(ray.at(t), self.point, self.normal);
        Hit::new(ray, t, point, self.normal, error)
    }

    /// The crossing within `range`, if any.
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = self.nearest(ray, range)?;
        Some(self.hit_at(ray, t))
    }
    // ANCHOR_END: plane_hit

    /// The crossing of the ray's line, [`Plane::t`]: one, or none for a ray parallel
    /// to the plane (in it or not).
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        self.t(ray).map_or(Crossings::NONE, Crossings::one)
    }

    /// The unit normal n, the same at every point `_p` of the plane.
    pub fn normal_at(&self, _p: Vec3) -> Vec3 {
        self.normal
    }
}

/// `p` projected onto the plane through `p0` with unit normal `n`,
/// p - ((p - p0) . n) n, and a bound on its rounding error.
///
/// o + t d carries t's error, which grows with t; the projection's does not. Its
/// distance from the plane is the rounding of (p - p0) . n and of the subtraction,
/// a few gamma times the coordinates involved: gamma(10) (|p| + |p0|) per coordinate
/// bounds it with room to spare (and covers the same rounding when a spawned ray's
/// test evaluates the plane again at its origin).
pub(crate) fn onto_plane(p: Vec3, p0: Vec3, n: Vec3) -> (Vec3, Vec3) {
    let point = p - (p - p0).dot(n) * n;
    (point, plane_error(point, p0))
}

/// The error bound of a point near the plane through `p0`: gamma(10) (|p| + |p0|).
pub(crate) fn plane_error(point: Vec3, p0: Vec3) -> Vec3 {
    gamma(10) * (point.abs() + p0.abs())
}
