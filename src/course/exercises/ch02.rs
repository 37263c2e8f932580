//! Chapter 02, The ray: coding exercises 2.5 and 2.6.
//!
//! Check them with `cargo test --test exercises ch02`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

use crate::ray::Ray;

/// Coding exercise 2.5: the point r(t) of the ray from `o` along `d` at parameter `t`.
///
/// `d` need not have length 1, but `t` must be the signed distance from `o`
/// (negative behind it), as for the crate's `Ray`. Mind the chapter's last pitfall:
/// for a direction such as (1e30, 1e30, 0) |d|^2 overflows `f32`, and for
/// (1e-30, 1e-30, 0) it underflows to 0; `Ray::new` accepts both, and so must you.
pub fn point_at(o: Vec3, d: Vec3, t: f32) -> Vec3 {
    todo!(
        "Coding exercise 2.5 (chapter 02, The ray): the point at distance t along the ray"
    )
}

/// Coding exercise 2.6: the `t` of the point of the ray's line closest to `p`: for a
/// point on the line, its own `t`. `ray.origin()` is o and `ray.direction()` the unit
/// direction d. The answer may be negative (behind the origin). (`ray.t_closest_to(p)`
/// is the crate's answer.)
pub fn t_closest(ray: &Ray, p: Vec3) -> f32 {
    todo!("Coding exercise 2.6 (chapter 02, The ray): the t of the point closest to p")
}
