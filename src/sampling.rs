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

// ANCHOR: uniform_hemisphere
/// A direction in the hemisphere around +Z with constant density 1 / (2 pi): the
/// height z = cos(theta) is uniform in [0, 1] (Archimedes' hat-box theorem).
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let z = u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}
// ANCHOR_END: uniform_hemisphere

/// A direction on the whole unit sphere with constant density 1 / (4 pi).
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// A point of the unit disc with constant density 1 / pi (polar map: r = sqrt(u)).
pub fn uniform_disc(u: Vec2) -> Vec2 {
    let r = u.x.sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec2::new(r * c, r * s)
}

/// An `n` x `n` grid of points at the centres of the cells of the unit square: evenly
/// spread "random" numbers for tests that must not depend on a generator.
pub fn grid(n: u32) -> impl Iterator<Item = Vec2> {
    let step = 1.0 / n as f32;
    (0..n).flat_map(move |i| {
        (0..n).map(move |j| Vec2::new((i as f32 + 0.5) * step, (j as f32 + 0.5) * step))
    })
}
