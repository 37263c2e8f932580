//! Chapter 08, Ray casting: coding exercise 8.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch08`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use crate::ray::{Interval, Ray};
use crate::scene::SceneHit;
use crate::shapes::Shape;

/// Coding exercise 8.1: the closest hit of `ray` over all `shapes`, counting only
/// hits with `t` inside `range` (`range.min < t < range.max`): the `Hit` and the index
/// of the shape hit, as a `SceneHit { hit, object }`; `None` if no shape is hit.
///
/// `shape.hit(ray, range)` tests one shape and returns its nearest crossing in that
/// range (a `Hit`, whose field `t` is the distance).
pub fn closest(ray: &Ray, shapes: &[Shape], range: Interval) -> Option<SceneHit> {
    todo!("Coding exercise 8.1 (chapter 08, Ray casting): the closest-hit loop over every shape")
}
