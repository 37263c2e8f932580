//! Chapter 05, An arbitrary orthographic camera: coding exercises 5.4 and 5.5.
//!
//! Check them with `cargo test --test exercises ch05`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

use crate::camera::{Film, Frame};

/// Coding exercise 5.4: the camera basis (u, v, w) of a camera looking along `d`
/// with up vector `k`.
///
/// Neither `d` nor `k` need have length 1, and `k` need not be perpendicular to `d`
/// (it is never parallel to it here, but once only 1e-5 rad from it: STABILITY S10,
/// the chapter's step 3). The camera looks down its local -Z: the local direction
/// (0, 0, -1) must become d/|d| in the world. The result must be orthonormal and
/// right-handed, with v on the same side as k.
pub fn camera_basis(d: Vec3, k: Vec3) -> (Vec3, Vec3, Vec3) {
    todo!(
        "Coding exercise 5.4 (chapter 05, An arbitrary orthographic camera): build u, v, w from d and k"
    )
}

/// Coding exercise 5.5: the world-space ray (origin, unit direction) of pixel
/// (`px`, `py`, row 0 at the top) of the orthographic camera placed by `frame`.
///
/// In camera space the ray starts at the pixel centre (x, y, 0), where
/// `film.pixel_to_plane(px, py)` gives (x, y) (lesson 03), and goes along (0, 0, -1).
/// `frame.basis()` is B, with `to_world` (lesson 04), and `frame.position()` is p.
/// (`Frame::point_to_world` and `Frame::vector_to_world` are the crate's answer.)
pub fn ortho_ray(film: &Film, frame: &Frame, px: u32, py: u32) -> (Vec3, Vec3) {
    todo!(
        "Coding exercise 5.5 (chapter 05, An arbitrary orthographic camera): carry the pixel's ray to the world"
    )
}
