//! Chapter 02, The ray: coding exercise 2.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch02`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use glam::Vec3;

/// Coding exercise 2.1: the point r(t) of the ray from `o` along `d` at parameter `t`.
///
/// `d` need not have length 1, but `t` must be the signed distance from `o`
/// (negative behind it), as for the crate's `Ray`.
pub fn point_at(o: Vec3, d: Vec3, t: f32) -> Vec3 {
    todo!("Coding exercise 2.1 (chapter 02, The ray): the point at distance t along the ray")
}
