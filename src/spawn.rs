//! Where a secondary ray (a shadow ray, a bounce) may start without hitting the
//! surface it leaves: the self-intersection problem (STABILITY S13, S14).
//!
//! A hit point computed in floating point lies a little above or below the true
//! surface, by an amount that grows with |p|. A ray started there can find the same
//! surface again at a tiny t ("shadow acne"). Two cures:
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

use glam::Vec3;

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

impl Offset {
    /// The origin and minimum t of a ray leaving `p` (whose coordinates are off the
    /// surface by at most `error`, see [`crate::shapes::Hit::error`]) on the side of
    /// `n` (a unit normal pointing to the side the new ray goes to).
    pub fn start(self, p: Vec3, error: Vec3, n: Vec3) -> (Vec3, f32) {
        match self {
            Offset::Fixed(epsilon) => (p, epsilon),
            Offset::Scaled => (offset_ray_origin(p, n), 0.0),
            Offset::ErrorBound => (offset_by_error(p, error, n), 0.0),
        }
    }
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
