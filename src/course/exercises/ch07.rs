//! Chapter 07, Ray/primitive intersections: coding exercises 7.1 and 7.2.
//!
//! Check them with `cargo test --features exercises --test exercises ch07`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

/// Coding exercise 7.1: the `t` at which the line o + t d meets the plane through
/// `p0` with normal `n` (`d` and `n` have length 1).
///
/// `None` when the ray is parallel to the plane. A crossing behind the origin
/// (t < 0) is still returned.
pub fn ray_plane_t(o: Vec3, d: Vec3, p0: Vec3, n: Vec3) -> Option<f32> {
    todo!(
        "Coding exercise 7.1 (chapter 07, Ray/primitive intersections): where the ray meets the plane"
    )
}

/// Coding exercise 7.2: both `t` at which the line o + t d (`d` of length 1) meets
/// the sphere with centre `c` and radius `r`, in ascending order, or `None` if it
/// misses. Negative roots (behind the origin) are returned too; a tangent line gives
/// the same root twice.
pub fn ray_sphere_roots(o: Vec3, d: Vec3, c: Vec3, r: f32) -> Option<(f32, f32)> {
    todo!(
        "Coding exercise 7.2 (chapter 07, Ray/primitive intersections): solve the ray/sphere quadratic"
    )
}
