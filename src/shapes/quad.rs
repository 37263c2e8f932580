//! Ray / parallelogram ("quad"): a corner q and two edge vectors a and b span the
//! points q + u a + v b with 0 <= u, v <= 1. The path tracer's area lights are quads.

use glam::Vec3;

use crate::error::{Result, finite3, unit};
use crate::ray::{Interval, Ray};
use crate::shapes::plane::{onto_plane, plane_error};
use crate::shapes::{Aabb, Crossings, Hit};

/// The parallelogram with corner `corner` and edges `a`, `b`; its normal is
/// (a x b)/|a x b|.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quad {
    corner: Vec3,
    a: Vec3,
    b: Vec3,
    normal: Vec3,
    area: f32,
}

impl Quad {
    /// The quad q + u a + v b, 0 <= u, v <= 1. Rejects non-finite input and parallel
    /// (or zero) edges, which span no area.
    pub fn new(corner: Vec3, a: Vec3, b: Vec3) -> Result<Quad> {
        let (corner, a, b) = (
            finite3("corner", corner)?,
            finite3("edge a", a)?,
            finite3("edge b", b)?,
        );
        let cross = a.cross(b);
        let normal = unit("edges (a x b)", cross)?;
        Ok(Quad {
            corner,
            a,
            b,
            normal,
            area: cross.length(),
        })
    }

    /// The corner q.
    pub fn corner(&self) -> Vec3 {
        self.corner
    }

    /// The point q + u a + v b.
    pub fn point(&self, u: f32, v: f32) -> Vec3 {
        self.corner + u * self.a + v * self.b
    }

    /// The unit normal (a x b)/|a x b|.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    /// The box around the four corners (flat for a quad parallel to an axis plane).
    pub fn bounds(&self) -> Option<Aabb> {
        Aabb::around([
            self.point(0.0, 0.0),
            self.point(1.0, 0.0),
            self.point(0.0, 1.0),
            self.point(1.0, 1.0),
        ])
    }

    /// The quad's area, |a x b|.
    pub fn area(&self) -> f32 {
        self.area
    }

    // ANCHOR: quad_hit
    /// The crossing's `t` within `range`, if any: the plane through q
    /// first, then the hit's coordinates (u, v) in the edges, from the dual vectors
    /// w = n / |a x b| with u = w . (p' x b) and v = w . (a x p'), p' = p - q.
    #[inline]
    pub fn nearest(&self, ray: &Ray, range: Interval) -> Option<f32> {
        let denom = ray.direction().dot(self.normal);
        if denom == 0.0 {
            return None;
        }
        let t = (self.corner - ray.origin()).dot(self.normal) / denom;
        if !range.contains(t) {
            return None;
        }
        let rel = ray.at(t) - self.corner;
        let w = self.normal / self.area;
        let u = w.dot(rel.cross(self.b));
        let v = w.dot(self.a.cross(rel));
        let inside = (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v);
        inside.then_some(t)
    }

    /// The hit record at `t`: the point o + t d, the quad's normal.
    pub fn hit_at(&self, ray: &Ray, t: f32) -> Hit {
        let (point, error) = onto_plane(ray.at(t), self.corner, self.normal);
        Hit::new(ray, t, point, self.normal, error)
    }

    /// The error bound of a point of the quad found by [`Quad::point`] or a hit: the
    /// plane's (see [`crate::shapes::Plane`]'s hits).
    pub fn error_at(&self, point: Vec3) -> Vec3 {
        plane_error(point, self.corner)
    }

    /// The crossing within `range`, if any.
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = self.nearest(ray, range)?;
        Some(self.hit_at(ray, t))
    }
    // ANCHOR_END: quad_hit

    /// The crossing of the ray's line inside the parallelogram, if any:
    /// [`Quad::hit`] over the whole line, -inf < t < inf.
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        self.hit(ray, Interval::EVERYWHERE)
            .map_or(Crossings::NONE, |h| Crossings::one(h.t))
    }

    /// The unit normal (a x b)/|a x b|, the same at every point `_p`.
    pub fn normal_at(&self, _p: Vec3) -> Vec3 {
        self.normal
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ray::{Interval, Ray};

    #[test]
    fn quad_hits_inside_and_misses_outside() {
        let q = Quad::new(Vec3::ZERO, Vec3::X * 2.0, Vec3::Z * 3.0).unwrap();
        assert_eq!(q.normal(), -Vec3::Y);
        assert_eq!(q.area(), 6.0);
        let down = |x, z| Ray::new(Vec3::new(x, 1.0, z), -Vec3::Y).unwrap();
        let h = q.hit(&down(1.0, 1.5), Interval::AHEAD).unwrap();
        assert_eq!(h.t, 1.0);
        assert!(!h.front_face);
        assert!(q.hit(&down(2.1, 1.5), Interval::AHEAD).is_none());
        assert!(q.hit(&down(1.0, -0.1), Interval::AHEAD).is_none());
        let edge_on = Ray::new(Vec3::new(-1.0, 0.0, 1.0), Vec3::X).unwrap();
        assert!(q.hit(&edge_on, Interval::AHEAD).is_none());
    }
}
