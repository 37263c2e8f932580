//! Chapter 08, Ray casting: coding exercise 8.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch08`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use crate::ray::Ray;
use crate::shapes::Shape;

/// Coding exercise 8.1: the closest hit of `ray` over all `shapes`, as the index of
/// the shape hit and its `t`, counting only hits with `t_min < t < t_max`; `None`
/// if no shape is hit.
///
/// `shape.hit(ray, t_min, t_max)` tests one shape and returns its nearest crossing
/// in that range (a `Hit`, whose field `t` is the distance).
pub fn closest(ray: &Ray, shapes: &[Shape], t_min: f32, t_max: f32) -> Option<(usize, f32)> {
    todo!("Coding exercise 8.1 (chapter 08, Ray casting): the closest-hit loop over every shape")
}
