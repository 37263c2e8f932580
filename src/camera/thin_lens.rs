//! The thin-lens camera: depth of field on top of the pinhole camera of Lecture 4.
//!
//! A pinhole lets through one ray per screen point; a lens of radius `aperture` lets
//! through a bundle, all of which meet again on the plane in focus, at distance
//! `focus_distance` in front of the lens (pbrt-v3 section 6.2.3). Points on that plane
//! are sharp; points nearer or farther blur into discs. With aperture 0 the bundle is
//! the pinhole ray itself, bit for bit.

use glam::{Vec2, Vec3};

use super::{Film, Frame, PinholeCamera};
use crate::error::{Error, Problem, Result, finite, positive};
use crate::ray::Ray;
use crate::sampling::uniform_disc;

/// A pinhole camera's frame and film, with a lens of radius `aperture` focused at
/// `focus_distance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinLensCamera {
    pinhole: PinholeCamera,
    aperture: f32,
    focus_distance: f32,
}

impl ThinLensCamera {
    /// A thin lens on `pinhole`'s frame and film. Rejects a negative or non-finite
    /// aperture and a focus distance that is not finite and positive.
    pub fn new(
        pinhole: PinholeCamera,
        aperture: f32,
        focus_distance: f32,
    ) -> Result<ThinLensCamera> {
        if finite("aperture", aperture)? < 0.0 {
            return Err(Error::Value {
                param: "aperture",
                problem: Problem::Invalid {
                    reason: "must be >= 0 (0 is a pinhole)",
                },
            });
        }
        let camera = ThinLensCamera {
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
            let focus = self.pinhole.screen_point(corner) * scale;
            if focus.normalize_or_zero() == Vec3::ZERO {
                return Err(Error::Value {
                    param: "focus",
                    problem: Problem::Invalid {
                        reason: "puts the plane in focus out of f32's reach",
                    },
                });
            }
            for rim in [Vec2::X, Vec2::NEG_X, Vec2::Y, Vec2::NEG_Y] {
                let lens = (self.aperture * rim).extend(0.0);
                let direction = (focus - lens).normalize_or_zero();
                let origin = frame.point_to_world(lens);
                if direction == Vec3::ZERO || !origin.is_finite() {
                    return Err(Error::Value {
                        param: "aperture",
                        problem: Problem::Invalid {
                            reason: "is too large for f32 rays with this focus distance",
                        },
                    });
                }
            }
        }
        Ok(())
    }

    /// The same camera with a lens of radius `aperture` focused at `focus_distance`
    /// (validated as in [`ThinLensCamera::new`]).
    pub fn with_lens(
        &self,
        aperture: f32,
        focus_distance: f32,
    ) -> Result<ThinLensCamera> {
        ThinLensCamera::new(self.pinhole, aperture, focus_distance)
    }

    /// The pinhole camera the lens sits on.
    pub fn pinhole(&self) -> &PinholeCamera {
        &self.pinhole
    }

    /// The film: resolution and screen rectangle.
    pub fn film(&self) -> &Film {
        self.pinhole.film()
    }

    /// The camera's position and basis.
    pub fn frame(&self) -> &Frame {
        self.pinhole.frame()
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
    /// With aperture 0 it is the pinhole's ray.
    pub fn ray_through(&self, pixel: Vec2, u: Vec2) -> Ray {
        if self.aperture == 0.0 {
            return self.pinhole.ray_through(pixel);
        }
        let s = self.pinhole.screen_point(pixel);
        let lens = (self.aperture * uniform_disc(u)).extend(0.0);
        let focus = s * (self.focus_distance / self.pinhole.screen_distance());
        let local = Ray::from_checked(lens, (focus - lens).normalize());
        self.frame().ray_to_world(&local)
    }
    // ANCHOR_END: ray
}
