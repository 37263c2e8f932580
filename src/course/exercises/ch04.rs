//! Chapter 04, Change of basis: coding exercises 4.5 and 4.6.
//!
//! Check them with `cargo test --test exercises ch04`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

/// Coding exercise 4.5: the world coordinates a of the vector whose coordinates in
/// the orthonormal basis (`u`, `v`, `w`) are `b`.
pub fn to_world(u: Vec3, v: Vec3, w: Vec3, b: Vec3) -> Vec3 {
    todo!("Coding exercise 4.5 (chapter 04, Change of basis): a = B b")
}

/// Coding exercise 4.6: the coordinates b, in the orthonormal basis (`u`, `v`, `w`),
/// of the vector whose world coordinates are `a`.
pub fn to_local(u: Vec3, v: Vec3, w: Vec3, a: Vec3) -> Vec3 {
    todo!("Coding exercise 4.6 (chapter 04, Change of basis): b = B^T a")
}
