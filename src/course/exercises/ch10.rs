//! Chapter 10, Path tracing: coding exercises 10.11 and 10.12.
//!
//! Check them with `cargo test --test exercises ch10`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::{Vec2, Vec3};

/// Coding exercise 10.11: a cosine-weighted direction in the hemisphere around +Z,
/// and its density per unit solid angle, from a uniform point `u` of the unit square.
///
/// Use Malley's method, as `sampling::cosine_hemisphere` does: `u.x` chooses the
/// distance from the centre of the unit disc (so that the point is uniform over the
/// disc's area), `u.y` the angle `phi = 2 pi u.y`; then lift the point straight up
/// onto the hemisphere. Return the unit direction and its pdf, cos(theta) / pi.
pub fn cosine_sample(u: Vec2) -> (Vec3, f32) {
    todo!(
        "Coding exercise 10.11 (chapter 10, Path tracing): a cosine-weighted direction and its pdf"
    )
}

/// Coding exercise 10.12: the factor by which one bounce multiplies a path's
/// throughput at a matte (Lambertian) surface, f_r cos(theta) / pdf.
///
/// The surface has colour `albedo` and unit normal `n`; the path leaves along the
/// unit direction `wi`, which was drawn with density `pdf` (per unit solid angle).
/// Lambert's BRDF is f_r = albedo / pi (`material::diffuse_brdf`), and theta is the
/// angle between `n` and `wi`. A direction below the surface (cos(theta) <= 0)
/// carries nothing, and neither does a direction of density 0 (never divide by it).
pub fn bounce_weight(albedo: Vec3, n: Vec3, wi: Vec3, pdf: f32) -> Vec3 {
    todo!(
        "Coding exercise 10.12 (chapter 10, Path tracing): the throughput factor of a bounce"
    )
}
