//! Chapter 08, Ray casting: coding exercises 8.3 and 8.7.
//!
//! Check them with `cargo test --test exercises ch08`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

use crate::ray::{Interval, Ray};
use crate::scene::{PointLight, SceneHit};
use crate::shapes::Shape;

/// Coding exercise 8.3: the closest hit of `ray` over all `shapes`, counting only
/// hits with `t` inside `range` (`range.min < t < range.max`): the `Hit` and the index
/// of the shape hit, as a `SceneHit { hit, object }`; `None` if no shape is hit.
///
/// `shape.hit(ray, range)` tests one shape and returns its nearest crossing in that
/// range (a `Hit`, whose field `t` is the distance).
pub fn closest(ray: &Ray, shapes: &[Shape], range: Interval) -> Option<SceneHit> {
    todo!(
        "Coding exercise 8.3 (chapter 08, Ray casting): the closest-hit loop over every shape"
    )
}

/// Coding exercise 8.7: Lambert's cosine law. The colour of a surface point `p` with
/// unit normal `n` (already turned towards the viewer) and colour `albedo`, lit by
/// the point `light` (`light.position`, `light.intensity`), which the shadow ray has
/// found `visible` or not:
///
/// albedo (AMBIENT + V I cos(theta) / d^2) if cos(theta) > 0, albedo AMBIENT otherwise,
///
/// with d the distance from `p` to the light, theta the angle between `n` and the unit
/// direction l from `p` to the light, and V = 1 if `visible`, else 0.
/// `crate::lighting::AMBIENT` is the ambient share, 0.1. (`lighting::lambert` is the
/// crate's answer.)
pub fn lambert(
    p: Vec3,
    n: Vec3,
    albedo: Vec3,
    light: &PointLight,
    visible: bool,
) -> Vec3 {
    todo!(
        "Coding exercise 8.7 (chapter 08, Ray casting): Lambert's cosine law from a point light"
    )
}
