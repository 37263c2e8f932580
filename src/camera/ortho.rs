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
    /// The ray through the continuous pixel position `pixel` in camera space: its
    /// origin is the film point on the plane z = 0 ([`Film::film_point`]), its
    /// direction (0, 0, -1).
    pub fn local_ray(&self, pixel: Vec2) -> Ray {
        let origin = self.film.film_point(pixel).extend(0.0);
        Ray::from_checked(origin, Vec3::NEG_Z)
    }
    // ANCHOR_END: local_ray

    // ANCHOR: ray
    /// The same ray in world space: origin_world = B origin_cam + p,
    /// direction_world = B direction_cam.
    pub fn ray_through(&self, pixel: Vec2) -> Ray {
        self.frame.ray_to_world(&self.local_ray(pixel))
    }

    /// The ray through the centre of pixel (`px`, `py`), `py` counted from the top row.
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        self.ray_through(Film::pixel_centre(px, py))
    }
    // ANCHOR_END: ray

    /// Where the world point `x` lands in the image, in continuous pixel coordinates
    /// (column, row from the top); every point projects, whatever its depth.
    pub fn project(&self, x: Vec3) -> Vec2 {
        let local = self.frame.point_to_camera(x);
        self.film.plane_to_pixel(local.truncate())
    }
}
