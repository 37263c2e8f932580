//! Chapter 05, An arbitrary orthographic camera: coding exercise 5.1.
//!
//! Check it with `cargo test --features exercises --test exercises ch05`.
// The parameters are unused until you write the body.
#![allow(unused_variables)]

use glam::Vec3;

/// Coding exercise 5.1: the camera basis (u, v, w) of a camera looking along `d`
/// with up vector `k`.
///
/// Neither `d` nor `k` need have length 1, and `k` need not be perpendicular to `d`
/// (it is never parallel to it here). The camera looks down its local -Z: the local
/// direction (0, 0, -1) must become d/|d| in the world. The result must be
/// orthonormal and right-handed, with v on the same side as k.
pub fn camera_basis(d: Vec3, k: Vec3) -> (Vec3, Vec3, Vec3) {
    todo!(
        "Coding exercise 5.1 (chapter 05, An arbitrary orthographic camera): build u, v, w from d and k"
    )
}
