//! Where a secondary ray (a shadow ray, a bounce) may start without hitting the
//! surface it leaves: the self-intersection problem (STABILITY S13, S14).
//!
//! A hit point computed in floating point lies a little above or below the true
//! surface, by an amount that grows with |p|. A ray started there can find the same
//! surface again at a tiny t ("shadow acne"). Three cures:
//!
//! - a fixed minimum distance, `t > epsilon`: simple, but no single epsilon suits
//!   every |p| (too small far from the origin, too large near it: light leaks through
//!   thin gaps);
//! - moving the origin off the surface along the normal by an amount that scales with
//!   |p| (Wachter and Binder, "A Fast and Robust Method for Avoiding
//!   Self-Intersection", Ray Tracing Gems ch. 6, 2019). It fails where the hit
//!   point's error does not scale with |p|: a point near the world origin found by a
//!   ray from far away carries the error of o + t d, which grows with t;
//! - moving the origin along the normal just past a bound on the hit point's own
//!   rounding error, which each shape computes with its hit (pbrt-v4, Pharr, Jakob
//!   and Humphreys, 4th ed., section 6.8.6, "Robust Spawned Ray Origins").
//!
//! A shadow ray aimed at a point has the same problem at its far end (STABILITY
//! S20): [`Start::ray_to`] stops it a little short of its target.

use glam::Vec3;

use crate::error::unit_and_length;
use crate::ray::{Interval, Ray};

/// How a secondary ray avoids its own surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Offset {
    /// Start at the hit point and ignore crossings closer than this distance.
    Fixed(f32),
    /// Move the origin off the surface by a few units in the last place of |p|
    /// (Wachter and Binder), and accept any t > 0.
    Scaled,
    /// Move the origin off the surface past the hit point's error bound (pbrt-v4),
    /// and accept any t > 0. The renderers' default.
    ErrorBound,
}

/// [`Offset::ErrorBound`], the renderers' choice.
impl Default for Offset {
    fn default() -> Offset {
        Offset::ErrorBound
    }
}

impl Offset {
    /// Where a ray leaving `p` (whose coordinates are off the surface by at most
    /// `error`, see [`crate::shapes::Hit::error`]) on the side of `n` (a unit normal
    /// pointing to the side the new ray goes to) starts, and the t it must exceed.
    pub fn start(self, p: Vec3, error: Vec3, n: Vec3) -> Start {
        match self {
            Offset::Fixed(epsilon) => Start {
                point: p,
                t_min: epsilon,
            },
            Offset::Scaled => Start::at(offset_ray_origin(p, n)),
            Offset::ErrorBound => Start::at(offset_by_error(p, error, n)),
        }
    }
}

/// Where a spawned ray starts, and the t it must exceed to count as a hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Start {
    /// The ray's origin: the surface point, moved off the surface or not.
    pub point: Vec3,
    /// Crossings at this t or nearer are the surface left behind (0 once the origin
    /// has been moved off it).
    pub t_min: f32,
}

/// The share of a shadow ray's length it leaves unchecked at its far end, pbrt-v4's
/// `ShadowEpsilon` (section 6.8.6).
pub const SHADOW_EPSILON: f32 = 1e-4;

/// A shadow ray and the stretch of it along which a crossing blocks the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowRay {
    /// From the start towards the target, with a unit direction.
    pub ray: Ray,
    /// Crossings strictly inside this range are occluders.
    pub range: Interval,
}

impl Start {
    /// A point that leaves no surface behind (a point light, a camera): any t > 0.
    pub const fn at(point: Vec3) -> Start {
        Start { point, t_min: 0.0 }
    }

    // ANCHOR: ray_to
    /// The shadow ray from this start to `to`, a point on a light moved off the
    /// light's surface towards this start by the same offset (or [`Start::at`] a
    /// point light). `None` when the two points coincide.
    ///
    /// Its far end stops `to.t_min` short of the target, and then
    /// [`SHADOW_EPSILON`] of the way short of that (pbrt-v4's `SpawnRayTo`). The
    /// light's own error bound is not enough (STABILITY S20): a shadow ray finds the
    /// light again by intersecting it, and that t carries the rounding of the whole
    /// ray, a few ulps of t, growing with the ray's length; ended at the error bound
    /// alone, up to a fifth of the samples of a small light 20 units away found the
    /// light itself just short of the end and counted it as their own occluder.
    pub fn ray_to(self, to: Start) -> Option<ShadowRay> {
        self.ray_to_short_by(to, SHADOW_EPSILON)
    }

    /// [`Start::ray_to`] with its far end `share` of the way short instead of
    /// [`SHADOW_EPSILON`]: 0 is the end at the light's error bound alone, the naive
    /// end that S20 measures.
    pub fn ray_to_short_by(self, to: Start, share: f32) -> Option<ShadowRay> {
        // The gap's unit direction and its length, from one square root; none for
        // two points that coincide or are not finite (a finite gap has finite ends).
        let (direction, length) = unit_and_length(to.point - self.point)?;
        let ray = Ray::from_checked(self.point, direction);
        let t_max = (length - to.t_min) * (1.0 - share);
        let range = Interval::new(self.t_min, t_max);
        Some(ShadowRay { ray, range })
    }
    // ANCHOR_END: ray_to
}

// ANCHOR: offset_by_error
/// Moves `p` off its surface along the unit normal `n` just past its rounding error
/// (pbrt-v4 section 6.8.6). The true surface point lies in the box `p +- error`; the
/// farthest that box reaches along n is |n| . error (|n| taken per coordinate), so
/// the origin moves by that distance along n. The sum p + distance n is rounded
/// itself, so each coordinate then goes one more float away from p, on the side n
/// points to. A shape with an exact point (error 0, a box's face) still moves by one
/// float.
pub fn offset_by_error(p: Vec3, error: Vec3, n: Vec3) -> Vec3 {
    let distance = n.abs().dot(error);
    let moved = p + distance * n;
    let away = |moved: f32, n: f32| {
        if n > 0.0 {
            moved.next_up()
        } else if n < 0.0 {
            moved.next_down()
        } else {
            moved
        }
    };
    Vec3::new(away(moved.x, n.x), away(moved.y, n.y), away(moved.z, n.z))
}
// ANCHOR_END: offset_by_error

// ANCHOR: offset_ray_origin
/// Moves `p` off its surface along the unit normal `n` (Ray Tracing Gems ch. 6,
/// listing 6-1). Far from the origin each coordinate is nudged by 256 units in the
/// last place, scaled by the normal's component, so the step grows with |p| exactly
/// as the rounding error of p does; near the origin, where float spacing becomes tiny,
/// a fixed step of n / 65536 is used instead.
pub fn offset_ray_origin(p: Vec3, n: Vec3) -> Vec3 {
    const ORIGIN: f32 = 1.0 / 32.0;
    const FLOAT_SCALE: f32 = 1.0 / 65536.0;
    const INT_SCALE: f32 = 256.0;
    let nudge = |p: f32, n: f32| {
        let ulps = (INT_SCALE * n) as i32;
        let ulps = if p < 0.0 { -ulps } else { ulps };
        let moved = f32::from_bits((p.to_bits() as i32).wrapping_add(ulps) as u32);
        if p.abs() < ORIGIN {
            p + FLOAT_SCALE * n
        } else {
            moved
        }
    };
    Vec3::new(nudge(p.x, n.x), nudge(p.y, n.y), nudge(p.z, n.z))
}
// ANCHOR_END: offset_ray_origin
