//! Cameras: how a pixel becomes a ray (Lecture 4).
//!
//! Both cameras first build their ray in camera space (eye at the origin, looking
//! down -Z, +Y up) and then carry it to the world with the frame's basis and position.

mod film;
mod frame;
mod ortho;
mod pinhole;

pub use film::{Film, MAX_RESOLUTION};
pub use frame::{Frame, MIN_UP_SINE, camera_basis, camera_basis_as_on_slide};
pub use ortho::OrthoCamera;
pub use pinhole::PinholeCamera;

use glam::Vec2;
use glam::Vec3;

use crate::ray::Ray;

/// One of the course's cameras. An enum, not a trait: there are few, and a `match`
/// shows all of them at once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Camera {
    /// Parallel rays.
    Ortho(OrthoCamera),
    /// Rays from one eye point.
    Pinhole(PinholeCamera),
}

impl Camera {
    /// The ray through the centre of pixel (`px`, `py`), `py` counted from the top row.
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        match self {
            Camera::Ortho(c) => c.ray(px, py),
            Camera::Pinhole(c) => c.ray(px, py),
        }
    }

    /// The plane extents and resolution.
    pub fn film(&self) -> &Film {
        match self {
            Camera::Ortho(c) => c.film(),
            Camera::Pinhole(c) => c.film(),
        }
    }

    /// The camera's position and basis.
    pub fn frame(&self) -> &Frame {
        match self {
            Camera::Ortho(c) => c.frame(),
            Camera::Pinhole(c) => c.frame(),
        }
    }

    /// Where the world point `x` lands, in continuous pixel coordinates, if it does.
    pub fn project(&self, x: Vec3) -> Option<Vec2> {
        match self {
            Camera::Ortho(c) => Some(c.project(x)),
            Camera::Pinhole(c) => c.project(x),
        }
    }
}

impl From<OrthoCamera> for Camera {
    fn from(c: OrthoCamera) -> Camera {
        Camera::Ortho(c)
    }
}

impl From<PinholeCamera> for Camera {
    fn from(c: PinholeCamera) -> Camera {
        Camera::Pinhole(c)
    }
}
