//! The thin-lens camera: depth of field on top of the pinhole camera of Lecture 4.
//!
//! A pinhole lets through one ray per screen point; a lens of radius `aperture` lets
//! through a bundle, all of which meet again on the plane in focus, at distance
//! `focus_distance` in front of the lens (pbrt-v3 section 6.2.3). Points on that plane
//! are sharp; points nearer or farther blur into discs. With aperture 0 the bundle is
//! the pinhole ray itself, bit for bit.

use glam::{Vec2, Vec3};

use crate::camera::{Camera, Film, PinholeCamera};
use crate::error::{Error, Result, finite, positive};
use crate::ray::Ray;
use crate::sampling::uniform_disc;

/// A pinhole camera's frame and film, with a lens of radius `aperture` focused at
/// `focus_distance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LensCamera {
    pinhole: PinholeCamera,
    aperture: f32,
    focus_distance: f32,
}

impl LensCamera {
    /// A thin lens on `pinhole`'s frame and film. Rejects a negative or non-finite
    /// aperture and a focus distance that is not finite and positive.
    pub fn new(pinhole: PinholeCamera, aperture: f32, focus_distance: f32) -> Result<LensCamera> {
        if finite("aperture", aperture)? < 0.0 {
            return Err(Error::Invalid {
                param: "aperture",
                reason: "must be >= 0 (0 is a pinhole)",
            });
        }
        let camera = LensCamera {
            pinhole,
            aperture,
            focus_distance: positive("focus", focus_distance)?,
        };
        camera.check_rays()?;
        Ok(camera)
    }

    /// `Ok` if every ray of the camera can be made: at the film's corners and the
    /// lens's rim, the focus point, the lens point in the world and the direction
    /// between them are finite and not zero. A focus distance of 1e30 or an
    /// aperture of 1e20 fails here, naming the flag, instead of turning every
    /// sample into NaN (a black image).
    fn check_rays(&self) -> Result<()> {
        let film = self.pinhole.film();
        let (w, h) = (film.width() as f32, film.height() as f32);
        let scale = self.focus_distance / self.pinhole.screen_distance();
        let frame = self.pinhole.frame();
        for corner in [
            Vec2::ZERO,
            Vec2::new(w, 0.0),
            Vec2::new(0.0, h),
            Vec2::new(w, h),
        ] {
            let s = screen_point(film, corner).extend(-self.pinhole.screen_distance());
            let focus = s * scale;
            if focus.normalize_or_zero() == Vec3::ZERO {
                return Err(Error::Invalid {
                    param: "focus",
                    reason: "puts the plane in focus out of f32's reach",
                });
            }
            for rim in [Vec2::X, Vec2::NEG_X, Vec2::Y, Vec2::NEG_Y] {
                let lens = (self.aperture * rim).extend(0.0);
                let direction = (focus - lens).normalize_or_zero();
                let origin = frame.point_to_world(lens);
                if direction == Vec3::ZERO || !origin.is_finite() {
                    return Err(Error::Invalid {
                        param: "aperture",
                        reason: "is too large for f32 rays with this focus distance",
                    });
                }
            }
        }
        Ok(())
    }

    /// The pinhole camera itself (aperture 0; focus distance irrelevant, set to 1).
    pub fn pinhole(pinhole: PinholeCamera) -> LensCamera {
        LensCamera {
            pinhole,
            aperture: 0.0,
            focus_distance: 1.0,
        }
    }

    /// The same camera with a lens of radius `aperture` focused at `focus_distance`
    /// (validated as in [`LensCamera::new`]).
    pub fn with_lens(&self, aperture: f32, focus_distance: f32) -> Result<LensCamera> {
        LensCamera::new(self.pinhole, aperture, focus_distance)
    }

    /// The film: resolution and screen rectangle.
    pub fn film(&self) -> &Film {
        self.pinhole.film()
    }

    // ANCHOR: ray
    /// The ray through the continuous pixel position `pixel` (column, row from the
    /// top; pixel (x, y)'s centre is (x + 0.5, y + 0.5)) and the lens point chosen by
    /// `u` in the unit square.
    ///
    /// In camera space the pinhole ray goes from the eye through the screen point
    /// **s** = (x, y, -s), s the screen distance; it meets the plane in focus, at
    /// distance z_f in front of the eye, at p_f = **s** z_f / s. The lens ray starts
    /// at a uniform point o' (`lens`) of the lens disc (z = 0) and goes towards p_f.
    pub fn ray(&self, pixel: Vec2, u: Vec2) -> Ray {
        let s = screen_point(self.pinhole.film(), pixel).extend(-self.pinhole.screen_distance());
        let (origin, direction) = if self.aperture == 0.0 {
            (Vec3::ZERO, s.normalize())
        } else {
            let lens = (self.aperture * uniform_disc(u)).extend(0.0);
            let focus = s * (self.focus_distance / self.pinhole.screen_distance());
            (lens, (focus - lens).normalize())
        };
        let frame = self.pinhole.frame();
        Ray::from_checked(
            frame.point_to_world(origin),
            frame.vector_to_world(direction),
        )
    }
    // ANCHOR_END: ray
}

// ANCHOR: path_camera
/// A camera the path tracer can render through: a film, and a ray through any point
/// of a pixel, not only its centre (and through the lens point chosen by `lens`).
pub trait PathCamera: Sync {
    /// The film: resolution and screen rectangle.
    fn film(&self) -> &Film;
    /// The ray through the continuous pixel position `pixel` (column, row from the
    /// top), `lens` in the unit square choosing a point of the lens if there is one.
    fn sample_ray(&self, pixel: Vec2, lens: Vec2) -> Ray;
}

impl PathCamera for LensCamera {
    fn film(&self) -> &Film {
        self.pinhole.film()
    }

    fn sample_ray(&self, pixel: Vec2, lens: Vec2) -> Ray {
        self.ray(pixel, lens)
    }
}

/// The cameras of Lecture 4: a pinhole is a lens of aperture 0; an orthographic
/// camera's ray starts at the screen point and runs along the camera's -Z.
impl PathCamera for Camera {
    fn film(&self) -> &Film {
        Camera::film(self)
    }

    fn sample_ray(&self, pixel: Vec2, lens: Vec2) -> Ray {
        match self {
            Camera::Pinhole(c) => LensCamera::pinhole(*c).ray(pixel, lens),
            Camera::Ortho(c) => {
                let origin = screen_point(c.film(), pixel).extend(0.0);
                let frame = c.frame();
                Ray::from_checked(
                    frame.point_to_world(origin),
                    frame.vector_to_world(Vec3::NEG_Z),
                )
            }
        }
    }
}
// ANCHOR_END: path_camera

/// The screen-plane point of a continuous pixel position, the inverse of
/// [`Film::plane_to_pixel`]; at a pixel centre it is bit for bit
/// [`Film::pixel_to_plane`], rows flipped the same way (counted from the bottom on the
/// plane, from the top in the image).
fn screen_point(film: &Film, pixel: Vec2) -> Vec2 {
    let (x_min, x_max) = film.x_extent();
    let (y_min, y_max) = film.y_extent();
    let from_bottom = film.height() as f32 - pixel.y;
    Vec2::new(
        pixel.x / film.width() as f32 * (x_max - x_min) + x_min,
        from_bottom / film.height() as f32 * (y_max - y_min) + y_min,
    )
}
