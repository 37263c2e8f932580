//! Chapter 01, Geometric transformations: coding exercises 1.5 and 1.6.
//!
//! Check them with `cargo test --test exercises ch01`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Mat4;

use crate::transform::Transform;

/// Coding exercise 1.5: the rotation by `theta` radians about the Y axis, as the 4x4
/// matrix of Lecture 3's slide.
///
/// glam stores a matrix column by column: `Mat4::from_cols_array_2d` takes columns,
/// so write the slide's rows and transpose them (or build the four columns yourself).
pub fn rotation_y(theta: f32) -> Mat4 {
    todo!(
        "Coding exercise 1.5 (chapter 01, Geometric transformations): the rotation about Y"
    )
}

/// Coding exercise 1.6: the matrix of "first `first`, then `second`", from their
/// matrices `first.matrix()` and `second.matrix()` (glam's `*` multiplies two
/// `Mat4`). A matrix acts on the column vector to its right. (`first.then(second)` is
/// the crate's answer.)
pub fn compose(first: &Transform, second: &Transform) -> Mat4 {
    todo!(
        "Coding exercise 1.6 (chapter 01, Geometric transformations): compose two transforms"
    )
}
