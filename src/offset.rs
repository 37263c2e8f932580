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
//!   Self-Intersection", Ray Tracing Gems ch. 6, 2019).

use glam::Vec3;

/// How a secondary ray avoids its own surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Offset {
    /// Start at the hit point and ignore crossings closer than this distance.
    Fixed(f32),
    /// Move the origin off the surface by a few units in the last place of |p|
    /// (Wachter and Binder), and accept any t > 0.
    Scaled,
}

impl Offset {
    /// The origin and minimum t of a ray leaving `p` on the side of `n` (a unit normal
    /// pointing to the side the new ray goes to).
    pub fn start(self, p: Vec3, n: Vec3) -> (Vec3, f32) {
        match self {
            Offset::Fixed(epsilon) => (p, epsilon),
            Offset::Scaled => (offset_ray_origin(p, n), 0.0),
        }
    }
}

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
