//! Chapter 06, The pinhole camera: coding exercises 6.3 and 6.4.
//!
//! Check them with `cargo test --test exercises ch06`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::{Vec2, Vec3};

use crate::camera::{Film, Frame};

/// Coding exercise 6.3: the world-space ray (origin, unit direction) of pixel
/// (`px`, `py`, row 0 at the top) of a pinhole camera whose screen lies at
/// distance `s` in front of the eye.
///
/// In camera space the eye is at the origin and the screen is the film's rectangle
/// on the plane z = -s; `film.pixel_to_plane(px, py)` gives the pixel centre's
/// (x, y) on it. `frame` carries camera space to the world: see
/// `Frame::point_to_world` and `Frame::vector_to_world`.
pub fn pinhole_ray(
    film: &Film,
    s: f32,
    frame: &Frame,
    px: u32,
    py: u32,
) -> (Vec3, Vec3) {
    todo!(
        "Coding exercise 6.3 (chapter 06, The pinhole camera): the ray from the eye through the screen point"
    )
}

/// Coding exercise 6.4: where the world point `x` lands in the image of the same
/// pinhole camera, in continuous pixel coordinates (column, row from the top, as
/// `film.plane_to_pixel` gives them for a point of the screen), or `None` if `x` is
/// not in front of the eye.
///
/// `frame.point_to_camera(x)` gives x in camera space, (X, Y, Z); the camera looks
/// down its -Z, so "in front" means Z < 0. (`PinholeCamera::project` is the crate's
/// answer.)
pub fn project(film: &Film, s: f32, frame: &Frame, x: Vec3) -> Option<Vec2> {
    todo!(
        "Coding exercise 6.4 (chapter 06, The pinhole camera): where a point lands in the image"
    )
}
