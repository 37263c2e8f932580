//! Chapter 01, Geometric transformations: coding exercise 1.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch01`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use glam::Mat4;

/// Coding exercise 1.1: the rotation by `theta` radians about the Y axis, as the 4x4
/// matrix of Lecture 3's slide.
///
/// glam stores a matrix column by column: `Mat4::from_cols_array_2d` takes columns,
/// so write the slide's rows and transpose them (or build the four columns yourself).
pub fn rotation_y(theta: f32) -> Mat4 {
    todo!("Coding exercise 1.1 (chapter 01, Geometric transformations): the rotation about Y")
}
