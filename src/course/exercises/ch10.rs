//! Chapter 10, Path tracing: coding exercise 10.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch10`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use glam::{Vec2, Vec3};

/// Coding exercise 10.1: a cosine-weighted direction in the hemisphere around +Z,
/// and its density per unit solid angle, from a uniform point `u` of the unit square.
///
/// Use Malley's method, as `sampling::cosine_hemisphere` does: `u.x` chooses the
/// distance from the centre of the unit disc (so that the point is uniform over the
/// disc's area), `u.y` the angle `phi = 2 pi u.y`; then lift the point straight up
/// onto the hemisphere. Return the unit direction and its pdf, cos(theta) / pi.
pub fn cosine_sample(u: Vec2) -> (Vec3, f32) {
    todo!(
        "Coding exercise 10.1 (chapter 10, Path tracing): a cosine-weighted direction and its pdf"
    )
}
