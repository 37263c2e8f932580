//! The orthographic camera (Lecture 4): parallel rays, no perspective distortion.

use glam::{Vec2, Vec3};

use super::{Film, Frame};
use crate::ray::Ray;

/// An orthographic camera: each ray starts on the camera's z = 0 plane at its pixel
/// centre and travels along the camera's -Z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrthoCamera {
    film: Film,
    frame: Frame,
}

impl OrthoCamera {
    /// The camera of the first slides: at the origin, looking down -Z.
    pub fn at_origin(film: Film) -> OrthoCamera {
        OrthoCamera::new(film, Frame::AT_ORIGIN)
    }

    /// A camera placed and turned by `frame` (see [`Frame::look`]).
    pub fn new(film: Film, frame: Frame) -> OrthoCamera {
        OrthoCamera { film, frame }
    }

    /// The projection plane and resolution.
    pub fn film(&self) -> &Film {
        &self.film
    }

    /// The camera's position and basis.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    // ANCHOR: local_ray
    /// The ray of pixel (`px`, `py`) in camera space: origin (x, y, 0) at the pixel
    /// centre on the plane, direction (0, 0, -1).
    pub fn local_ray(&self, px: u32, py: u32) -> (Vec3, Vec3) {
        let on_plane = self.film.pixel_to_plane(px, py);
        (on_plane.extend(0.0), Vec3::NEG_Z)
    }
    // ANCHOR_END: local_ray

    // ANCHOR: ray
    /// The ray of pixel (`px`, `py`) in world space:
    /// origin_world = B origin_cam + p, direction_world = B direction_cam.
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        let (origin, direction) = self.local_ray(px, py);
        Ray::from_checked(
            self.frame.point_to_world(origin),
            self.frame.vector_to_world(direction),
        )
    }
    // ANCHOR_END: ray

    /// Where the world point `x` lands in the image, in continuous pixel coordinates
    /// (column, row from the top); every point projects, whatever its depth.
    pub fn project(&self, x: Vec3) -> Vec2 {
        let local = self.frame.point_to_camera(x);
        self.film.plane_to_pixel(local.truncate())
    }
}
