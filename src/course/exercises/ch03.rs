//! Chapter 03, The orthographic camera: coding exercises 3.5 and 3.6.
//!
//! Check them with `cargo test --test exercises ch03`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec2;

use crate::camera::Film;

/// Coding exercise 3.5: the centre of pixel (`px`, `py`) on the projection plane.
///
/// The `film` has `film.width()` x `film.height()` pixels and covers
/// `film.x_extent()` = (x_min, x_max) by `film.y_extent()` = (y_min, y_max) of the
/// plane. `py` counts rows from the top of the image (row 0 is the top row, as in
/// image files); the slide's formula counts them from the bottom. With the slide's
/// 4x3 pixels over [-8, 8] x [-6, 6], pixel (0, 0) must map to (-6, 4). (Write the
/// formula: `film.pixel_to_plane` is the crate's answer.)
pub fn pixel_to_plane(film: &Film, px: u32, py: u32) -> Vec2 {
    todo!(
        "Coding exercise 3.5 (chapter 03, The orthographic camera): map a pixel to its point on the plane"
    )
}

/// Coding exercise 3.6: the way back, from a point `p` of the projection plane to
/// continuous pixel coordinates (column, row), both counted from the image's top-left
/// corner, so that the centre of pixel (px, py) is (px + 0.5, py + 0.5) and the
/// film's corner (x_min, y_max) is (0, 0). Points outside the film map outside
/// [0, width] x [0, height]. (`film.plane_to_pixel` is the crate's answer.)
pub fn plane_to_pixel(film: &Film, p: Vec2) -> Vec2 {
    todo!(
        "Coding exercise 3.6 (chapter 03, The orthographic camera): from a point on the plane back to pixels"
    )
}
