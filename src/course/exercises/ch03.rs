//! Chapter 03, The orthographic camera: coding exercise 3.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch03`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use glam::Vec2;

/// Coding exercise 3.1: the centre of pixel (`px`, `py`) on the projection plane.
///
/// The image has `width` x `height` pixels and covers `x` = (x_min, x_max) by
/// `y` = (y_min, y_max) of the plane. `py` counts rows from the top of the image
/// (row 0 is the top row, as in image files); the slide's formula counts them from
/// the bottom. With the slide's 4x3 pixels over [-8, 8] x [-6, 6], pixel (0, 0)
/// must map to (-6, 4).
pub fn pixel_to_plane(
    x: (f32, f32),
    y: (f32, f32),
    width: u32,
    height: u32,
    px: u32,
    py: u32,
) -> Vec2 {
    todo!(
        "Coding exercise 3.1 (chapter 03, The orthographic camera): map a pixel to its point on the plane"
    )
}
