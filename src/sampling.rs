//! Turning uniform random numbers into directions.

use std::f32::consts::TAU;

use glam::{Vec2, Vec3};

// ANCHOR: cosine_hemisphere
/// A direction in the hemisphere around +Z with density cos(theta) / pi, from a
/// uniform point `u` of the unit square (Malley's method: a uniform point on the unit
/// disc, lifted up to the hemisphere).
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let r = u.x.sqrt();
    let phi = TAU * u.y;
    let (s, c) = phi.sin_cos();
    Vec3::new(r * c, r * s, (1.0 - u.x).max(0.0).sqrt())
}
// ANCHOR_END: cosine_hemisphere

/// An `n` x `n` grid of points at the centres of the cells of the unit square: evenly
/// spread "random" numbers for tests that must not depend on a generator.
pub fn grid(n: u32) -> impl Iterator<Item = Vec2> {
    let step = 1.0 / n as f32;
    (0..n).flat_map(move |i| {
        (0..n).map(move |j| Vec2::new((i as f32 + 0.5) * step, (j as f32 + 0.5) * step))
    })
}
