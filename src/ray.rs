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

    // ANCHOR: t_closest_to
    /// The `t` of the point on the ray's line closest to `p`: (p - o) . d.
    pub fn t_closest_to(&self, p: Vec3) -> f32 {
        (p - self.origin).dot(self.direction)
    }
    // ANCHOR_END: t_closest_to
}

// ANCHOR: interval
/// The ray parameters a query accepts: `min < t < max`, both ends open, as in Ray
/// Tracing in One Weekend's `interval` (pbrt keeps only `t_max`, with 0 below).
///
/// A closest-hit loop shrinks `max` to each hit it finds, so that later primitives
/// count only if nearer; a shadow ray to a light at distance `s` asks (0, s).
///
/// ```
/// use render_lessons::ray::Interval;
///
/// assert!(Interval::AHEAD.contains(3.0));
/// assert!(!Interval::AHEAD.contains(0.0)); // open: the origin itself is not ahead
/// assert!(!Interval::AHEAD.contains(f32::NAN));
/// let nearer = Interval::AHEAD.up_to(2.0);
/// assert!(nearer.contains(1.5) && !nearer.contains(2.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The open lower end.
    pub min: f32,
    /// The open upper end.
    pub max: f32,
}

impl Interval {
    /// Every `t` ahead of the origin: 0 < t < infinity.
    pub const AHEAD: Interval = Interval::new(0.0, f32::INFINITY);

    /// The whole line, behind the origin too: -infinity < t < infinity.
    pub const EVERYWHERE: Interval = Interval::new(f32::NEG_INFINITY, f32::INFINITY);

    /// `min < t < max`.
    pub const fn new(min: f32, max: f32) -> Interval {
        Interval { min, max }
    }

    /// `min < t < max`, and `false` for NaN.
    pub fn contains(&self, t: f32) -> bool {
        t > self.min && t < self.max
    }

    /// The same interval, its upper end moved to `max`.
    pub fn up_to(self, max: f32) -> Interval {
        Interval { max, ..self }
    }
}
// ANCHOR_END: interval
