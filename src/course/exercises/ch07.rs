//! Chapter 07, Ray/primitive intersections: coding exercises 7.16, 7.17 and 7.18.
//!
//! Check them with `cargo test --test exercises ch07`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

/// Coding exercise 7.16: the `t` at which the line o + t d meets the plane through
/// `p0` with normal `n` (`d` and `n` have length 1).
///
/// `None` when the ray is parallel to the plane. A crossing behind the origin
/// (t < 0) is still returned.
pub fn ray_plane_t(o: Vec3, d: Vec3, p0: Vec3, n: Vec3) -> Option<f32> {
    todo!(
        "Coding exercise 7.16 (chapter 07, Ray/primitive intersections): where the ray meets the plane"
    )
}

/// Coding exercise 7.17: both `t` at which the line o + t d (`d` of length 1) meets
/// the sphere with centre `c` and radius `r`, in ascending order, or `None` if it
/// misses. Negative roots (behind the origin) are returned too; a tangent line gives
/// the same root twice.
pub fn ray_sphere_roots(o: Vec3, d: Vec3, c: Vec3, r: f32) -> Option<(f32, f32)> {
    todo!(
        "Coding exercise 7.17 (chapter 07, Ray/primitive intersections): solve the ray/sphere quadratic"
    )
}

/// Coding exercise 7.18: the Möller-Trumbore test. Where the ray o + t d (`d` of
/// length 1) hits the triangle `v0, v1, v2`, as `(t, b1, b2)`: the distance `t` and
/// the barycentric weights of `v1` and `v2`, so that the point is
/// (1 - b1 - b2) v0 + b1 v1 + b2 v2.
///
/// With e1 = v1 - v0 and e2 = v2 - v0, solve o + t d = v0 + b1 e1 + b2 e2 for t,
/// b1 and b2 by Cramer's rule (the chapter's page on the triangle). Return `None`
/// when the ray is parallel to the triangle's plane (det = 0), when the point lies
/// outside the triangle, or when it is not in front of the origin (t > 0 is
/// required). The triangle has two sides: a ray may hit it from the back. A point on
/// an edge or a corner is inside, so that a ray through the edge that two triangles
/// share hits both.
pub fn moller_trumbore(
    o: Vec3,
    d: Vec3,
    v0: Vec3,
    v1: Vec3,
    v2: Vec3,
) -> Option<(f32, f32, f32)> {
    todo!(
        "Coding exercise 7.18 (chapter 07, Ray/primitive intersections): the Möller-Trumbore ray/triangle test"
    )
}
