//! Cameras: how a pixel becomes a ray (Lecture 4).
//!
//! Every camera first builds its ray in camera space (eye at the origin, looking
//! down -Z, +Y up) and then carries it to the world with the frame's basis and
//! position. The film turns a position on the image (in pixels) into a point of the
//! camera's plane, once for all cameras ([`Film::film_point`]).

mod film;
mod frame;
mod ortho;
mod pinhole;
mod row;
mod thin_lens;

pub use film::Film;
pub use frame::{Frame, MIN_UP_SINE, camera_basis, camera_basis_as_on_slide};
pub use ortho::OrthoCamera;
pub use pinhole::PinholeCamera;
pub use row::RowRays;
pub use thin_lens::ThinLensCamera;

use glam::Vec2;
use glam::Vec3;

use crate::error::{Error, Problem, Result};
use crate::ray::Ray;

/// One of the course's cameras. An enum, not a trait: there are few, and a `match`
/// shows all of them at once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Camera {
    /// Parallel rays.
    Ortho(OrthoCamera),
    /// Rays from one eye point.
    Pinhole(PinholeCamera),
    /// Rays from a lens disc, meeting on the plane in focus (lesson 10's depth of
    /// field).
    ThinLens(ThinLensCamera),
}

impl Camera {
    /// A pinhole camera at `eye` looking at `target`, `up` the image's up, with a
    /// vertical field of view of `vfov_degrees`, `width` x `height` pixels: the
    /// [`PinholeCamera::look_at`] most programs want, as a [`Camera`].
    pub fn look_at(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        vfov_degrees: f32,
        width: u32,
        height: u32,
    ) -> Result<Camera> {
        Ok(
            PinholeCamera::look_at(eye, target, up, vfov_degrees, width, height)?
                .into(),
        )
    }

    // ANCHOR: ray_through
    /// The ray through the continuous pixel position `pixel` (column, row from the
    /// top), `lens` in the unit square choosing the point of the lens it leaves from
    /// (ignored by the cameras without a lens).
    pub fn ray_through(&self, pixel: Vec2, lens: Vec2) -> Ray {
        match self {
            Camera::Ortho(c) => c.ray_through(pixel),
            Camera::Pinhole(c) => c.ray_through(pixel),
            Camera::ThinLens(c) => c.ray_through(pixel, lens),
        }
    }
    // ANCHOR_END: ray_through

    /// The ray through the centre of pixel (`px`, `py`), `py` counted from the top row
    /// (from the lens's centre for a thin lens).
    #[inline]
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        self.centre_ray(Film::pixel_centre(px, py))
    }

    // ANCHOR: row
    /// The rays through the centres of row `py`'s pixels, one after another from
    /// the left ([`RowRays::next_ray`]): those of [`Camera::ray`], bit for bit, made
    /// the renderers' fast way.
    pub fn row(&self, py: u32) -> RowRays<'_> {
        RowRays::new(self, py)
    }
    // ANCHOR_END: row

    /// The ray through `pixel` from the lens's centre: a thin lens's pinhole ray.
    #[inline]
    pub(crate) fn centre_ray(&self, pixel: Vec2) -> Ray {
        match self {
            Camera::Ortho(c) => c.ray_through(pixel),
            Camera::Pinhole(c) => c.ray_through(pixel),
            Camera::ThinLens(c) => c.pinhole().ray_through(pixel),
        }
    }

    /// The same camera with a lens of radius `aperture` focused at `focus_distance`
    /// ([`ThinLensCamera::new`]): a pinhole gains one, a thin lens changes its own.
    /// An orthographic camera has none to give: an error naming `aperture`.
    pub fn with_lens(&self, aperture: f32, focus_distance: f32) -> Result<Camera> {
        match self {
            Camera::Ortho(_) => Err(Error::Value {
                param: "aperture",
                problem: Problem::Invalid {
                    reason: "needs a pinhole camera: an orthographic camera has no lens",
                },
            }),
            Camera::Pinhole(c) => {
                Ok(ThinLensCamera::new(*c, aperture, focus_distance)?.into())
            }
            Camera::ThinLens(c) => Ok(c.with_lens(aperture, focus_distance)?.into()),
        }
    }

    /// The pinhole camera of a perspective camera (a pinhole, or the pinhole a thin
    /// lens sits on); `None` for an orthographic one.
    pub fn pinhole(&self) -> Option<&PinholeCamera> {
        match self {
            Camera::Ortho(_) => None,
            Camera::Pinhole(c) => Some(c),
            Camera::ThinLens(c) => Some(c.pinhole()),
        }
    }

    /// The plane extents and resolution.
    pub fn film(&self) -> &Film {
        match self {
            Camera::Ortho(c) => c.film(),
            Camera::Pinhole(c) => c.film(),
            Camera::ThinLens(c) => c.film(),
        }
    }

    /// The camera's position and basis.
    pub fn frame(&self) -> &Frame {
        match self {
            Camera::Ortho(c) => c.frame(),
            Camera::Pinhole(c) => c.frame(),
            Camera::ThinLens(c) => c.frame(),
        }
    }

    /// Where the world point `x` lands, in continuous pixel coordinates, if it does
    /// (a thin lens: where its pinhole would put it, the centre of the blur disc).
    pub fn project(&self, x: Vec3) -> Option<Vec2> {
        match self {
            Camera::Ortho(c) => Some(c.project(x)),
            Camera::Pinhole(c) => c.project(x),
            Camera::ThinLens(c) => c.pinhole().project(x),
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

impl From<ThinLensCamera> for Camera {
    fn from(c: ThinLensCamera) -> Camera {
        Camera::ThinLens(c)
    }
}
