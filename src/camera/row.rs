//! The rays of one row of pixels, the renderers' fast way (lesson 11): the same
//! rays as [`Camera::ray`], bit for bit, with what a row shares computed once.

use glam::{Vec2, Vec3};

use super::{Camera, PinholeCamera};
use crate::ray::Ray;

// ANCHOR: row_rays
/// The rays through the centres of one row's pixels, left to right
/// ([`Camera::row`]).
///
/// What the row shares is computed once: for a perspective camera, the row's
/// height on the screen (and, once per camera, the eye in the world: see
/// [`PinholeCamera::ray_towards`]). The column counts up in f32, exactly
/// (every whole number below 2^24 is), so no pixel converts an integer to a float.
/// A ray comes out as a plain value, not an `Option` as an iterator's would: moving
/// an `Option<Ray>` through memory cost more than making the ray.
#[derive(Clone, Debug)]
pub struct RowRays<'a> {
    camera: &'a Camera,
    /// A perspective camera's pinhole, and the row's height on its screen.
    pinhole: Option<(&'a PinholeCamera, f32)>,
    /// The next pixel's column, as a float.
    x: f32,
    /// The row's pixel centre, py + 1/2.
    y: f32,
}

impl<'a> RowRays<'a> {
    /// Row `py` of `camera`, from its leftmost pixel.
    pub(crate) fn new(camera: &'a Camera, py: u32) -> RowRays<'a> {
        let y = py as f32 + 0.5;
        RowRays {
            camera,
            pinhole: camera
                .pinhole()
                .map(|c| (c, c.screen_point(Vec2::new(0.5, y)).y)),
            x: 0.0,
            y,
        }
    }

    /// The ray through the next pixel's centre: [`Camera::ray`] of it. Past the
    /// row's end, the rays go on through pixels beyond the film's right edge.
    #[inline(always)]
    pub fn next_ray(&mut self) -> Ray {
        let pixel = Vec2::new(self.x + 0.5, self.y);
        self.x += 1.0;
        match (self.pinhole, self.camera) {
            (Some((c, screen_y)), _) => {
                // The screen point's x and y are computed apart: its x here, its
                // y once for the row.
                let x = c.screen_point(Vec2::new(pixel.x, 0.5)).x;
                c.ray_towards(Vec3::new(x, screen_y, -c.screen_distance()))
            }
            (None, Camera::Ortho(c)) => c.ray_through(pixel),
            (None, camera) => camera.centre_ray(pixel),
        }
    }
}
// ANCHOR_END: row_rays
