//! The perspective (pinhole) camera (Lecture 4): every ray starts at the centre of
//! projection e and passes through a point s on a screen at distance `s` in front.

use glam::{Vec2, Vec3};

use super::{Film, Frame};
use crate::error::{Error, Problem, Result, finite, positive};
use crate::ray::Ray;

/// A pinhole camera: eye at the camera origin, screen on the plane z = -s, its
/// rectangle [x_min, x_max] x [y_min, y_max] given by the film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PinholeCamera {
    film: Film,
    screen_distance: f32,
    frame: Frame,
    /// The eye in the world, B 0 + p: the same for every ray, so computed once
    /// (see [`PinholeCamera::ray_towards`]).
    eye: Vec3,
}

impl PinholeCamera {
    /// A pinhole camera at the origin looking down -Z, its screen `screen_distance`
    /// in front of the eye.
    pub fn at_origin(film: Film, screen_distance: f32) -> Result<PinholeCamera> {
        PinholeCamera::new(film, screen_distance, Frame::AT_ORIGIN)
    }

    /// A pinhole camera placed and turned by `frame`.
    ///
    /// Rejects a screen distance that is not finite and positive, and one so large
    /// (or a film so wide) that |s - e| of a corner overflows f32: no ray of such a
    /// camera could be normalised.
    pub fn new(
        film: Film,
        screen_distance: f32,
        frame: Frame,
    ) -> Result<PinholeCamera> {
        let camera = PinholeCamera {
            film,
            screen_distance: positive("screen distance", screen_distance)?,
            frame,
            eye: frame.point_to_world(Vec3::ZERO),
        };
        let corners = [
            Vec2::ZERO,
            Vec2::new(film.width() as f32, film.height() as f32),
        ];
        if corners
            .iter()
            .any(|&corner| !camera.screen_point(corner).length_squared().is_finite())
        {
            return Err(Error::Value {
                param: "screen distance",
                problem: Problem::Invalid {
                    reason: "is too large for the film: a ray's length |s - e| overflows f32",
                },
            });
        }
        Ok(camera)
    }

    // ANCHOR: look_at
    /// A `width` x `height` pinhole camera at `eye` looking at `target`, `up` towards
    /// the top of the image, with a vertical field of view of `vfov_degrees`.
    ///
    /// The screen sits at distance s = 1 (as in The Ray Tracer Challenge and in
    /// Shirley's Ray Tracing in One Weekend), so its half-height is h = tan(vfov/2)
    /// and its half-width h * width/height (square pixels): the film spans
    /// [-h w/H, h w/H] x [-h, h], and [`Film::pixel_size`] is 2h/height both ways.
    ///
    /// The field of view is vertical. A course whose field of view spans the longer
    /// side (The Ray Tracer Challenge) converts for a wide image with
    /// vfov = 2 atan(tan(fov/2) height/width).
    ///
    /// Errors name the parameter at fault: `eye`, `target`, `up` (see
    /// [`Frame::look_at`]), `vfov_degrees` (not finite, or outside 0 < vfov < 180),
    /// `width` and `height` (0 or above [`crate::limits::MAX_RESOLUTION`]).
    pub fn look_at(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        vfov_degrees: f32,
        width: u32,
        height: u32,
    ) -> Result<PinholeCamera> {
        let frame = Frame::look_at(eye, target, up)?;
        let vfov = positive("vfov_degrees", finite("vfov_degrees", vfov_degrees)?)?;
        // tan in f64, rounded once: below 180 degrees the half angle stays below pi/2.
        let half_height = (f64::from(vfov).to_radians() / 2.0).tan() as f32;
        if vfov >= 180.0 || !(half_height.is_finite() && half_height > 0.0) {
            return Err(Error::Value {
                param: "vfov_degrees",
                problem: Problem::Invalid {
                    reason: "must be below 180 degrees",
                },
            });
        }
        let film = Film::centred(width, height, half_height)?;
        PinholeCamera::new(film, 1.0, frame)
    }
    // ANCHOR_END: look_at

    /// The screen rectangle and resolution.
    pub fn film(&self) -> &Film {
        &self.film
    }

    /// The camera's position and basis.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// The distance `s` from the eye to the screen.
    pub fn screen_distance(&self) -> f32 {
        self.screen_distance
    }

    // ANCHOR: screen_point
    /// The screen point at the continuous pixel position `pixel`, in camera space
    /// (Lecture 4, "Pinhole Camera Setup"): with a = (x_max - x_min) x,
    /// b = (y_max - y_min) y and corner c = x_min x + y_min y - s z, the point is
    /// c + u a + v b, where u and v are the position's fractions of the image's width
    /// and height (for a pixel centre, u = (x + 0.5)/resolution_x and
    /// v = (y + 0.5)/resolution_y, rows counted from the bottom).
    ///
    /// The film point already is x_min + u (x_max - x_min) (and the same for y), so the
    /// screen point is the film point at z = -s.
    #[inline]
    pub fn screen_point(&self, pixel: Vec2) -> Vec3 {
        self.film.film_point(pixel).extend(-self.screen_distance)
    }
    // ANCHOR_END: screen_point

    // ANCHOR: ray
    /// The ray through the continuous pixel position `pixel` in world space: it starts
    /// at the eye e and goes through the screen point s.
    pub fn ray_through(&self, pixel: Vec2) -> Ray {
        self.ray_towards(self.screen_point(pixel))
    }

    /// The ray from the eye through the screen point `screen` (camera space, where
    /// the eye e is the origin): direction (s - e)/|s - e| = s/|s|, which B turns to
    /// the world, as for the orthographic camera. Its origin, the eye in the world,
    /// B e + p = p, is the same for every ray, so the camera computes it once, when it
    /// is made: written per ray, the products B 0 would stay in the loop (the compiler
    /// may not drop them, since 0 times infinity is NaN).
    #[inline]
    pub fn ray_towards(&self, screen: Vec3) -> Ray {
        let direction = screen.normalize();
        Ray::from_checked(self.eye, self.frame.vector_to_world(direction))
    }

    /// The ray through the centre of pixel (`px`, `py`), `py` counted from the top row.
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        self.ray_through(Film::pixel_centre(px, py))
    }
    // ANCHOR_END: ray

    // ANCHOR: project
    /// Where the world point `x` lands in the image, in continuous pixel coordinates,
    /// or `None` when it is not in front of the eye.
    pub fn project(&self, x: Vec3) -> Option<Vec2> {
        let local = self.frame.point_to_camera(x);
        if local.z >= 0.0 {
            return None;
        }
        let on_screen = local.truncate() * (self.screen_distance / -local.z);
        Some(self.film.plane_to_pixel(on_screen))
    }
    // ANCHOR_END: project
}
