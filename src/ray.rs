//! The ray model of Lecture 4: the parametric line r(t) = o + t d.

use glam::Vec3;

use crate::error::{Result, finite3, unit};

/// A ray with origin `o` and unit direction `d`.
///
/// Because `d` has length 1, the parameter `t` of a point is its signed distance
/// from the origin; a negative `t` lies behind it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    origin: Vec3,
    direction: Vec3,
}

impl Ray {
    // ANCHOR: new
    /// A ray from `origin` along `direction`, which is normalised here.
    ///
    /// Rejects a non-finite origin, and a direction that is zero or not finite.
    pub fn new(origin: Vec3, direction: Vec3) -> Result<Ray> {
        Ok(Ray {
            origin: finite3("origin", origin)?,
            direction: unit("direction", direction)?,
        })
    }
    // ANCHOR_END: new

    /// A ray from values the caller has already checked: finite, `direction` of unit length.
    pub(crate) fn from_checked(origin: Vec3, direction: Vec3) -> Ray {
        debug_assert!(origin.is_finite() && direction.is_normalized());
        Ray { origin, direction }
    }

    /// The origin `o`.
    pub fn origin(&self) -> Vec3 {
        self.origin
    }

    /// The unit direction `d`.
    pub fn direction(&self) -> Vec3 {
        self.direction
    }

    // ANCHOR: at
    /// The point r(t) = o + t d, at signed distance `t` from the origin.
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
    // ANCHOR_END: at

    /// The `t` of the point on the ray's line closest to `p`: (p - o) . d.
    pub fn t_closest_to(&self, p: Vec3) -> f32 {
        (p - self.origin).dot(self.direction)
    }
}
