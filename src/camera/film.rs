//! The projection plane and the image resolution (Lecture 4, "Setting Up the
//! Orthographic Camera"): which rectangle of the camera's z = 0 plane the image
//! covers, and in how many pixels.

use glam::Vec2;

use crate::error::{Error, Problem, Result, finite};
use crate::limits::Resolution;

/// A rectangle [x_min, x_max] x [y_min, y_max] of the camera plane, cut into
/// `width` x `height` pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Film {
    width: u32,
    height: u32,
    /// (resolution_x, resolution_y): the width and height as floats, converted once.
    resolution: Vec2,
    x_min: f32,
    x_max: f32,
    y_min: f32,
    y_max: f32,
}

fn range(param: &'static str, (min, max): (f32, f32)) -> Result<(f32, f32)> {
    let (min, max) = (finite(param, min)?, finite(param, max)?);
    if min < max && (max - min).is_finite() {
        Ok((min, max))
    } else {
        Err(Error::Value {
            param,
            problem: Problem::EmptyRange { min, max },
        })
    }
}

impl Film {
    /// `width` x `height` square pixels centred on the camera's axis: `half_height`
    /// above and below it, and as wide as the aspect ratio asks,
    /// x = ±half_height · width / height.
    pub fn centred(width: u32, height: u32, half_height: f32) -> Result<Film> {
        let half_width = half_height * width as f32 / height.max(1) as f32;
        Film::new(
            width,
            height,
            (-half_width, half_width),
            (-half_height, half_height),
        )
    }

    /// `width` x `height` pixels over the plane extents `x` = (x_min, x_max) and
    /// `y` = (y_min, y_max).
    pub fn new(width: u32, height: u32, x: (f32, f32), y: (f32, f32)) -> Result<Film> {
        let size = Resolution::new(width, height)?;
        let (width, height) = (size.width(), size.height());
        let (x_min, x_max) = range("x extent", x)?;
        let (y_min, y_max) = range("y extent", y)?;
        Ok(Film {
            width,
            height,
            resolution: Vec2::new(width as f32, height as f32),
            x_min,
            x_max,
            y_min,
            y_max,
        })
    }

    /// The image width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The image height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// (x_min, x_max).
    pub fn x_extent(&self) -> (f32, f32) {
        (self.x_min, self.x_max)
    }

    /// (y_min, y_max).
    pub fn y_extent(&self) -> (f32, f32) {
        (self.y_min, self.y_max)
    }

    /// The width and height of one pixel on the plane:
    /// ((x_max - x_min) / resolution_x, (y_max - y_min) / resolution_y), the steps
    /// between neighbouring pixel centres in [`Film::pixel_to_plane`].
    pub fn pixel_size(&self) -> Vec2 {
        Vec2::new(
            (self.x_max - self.x_min) / self.width as f32,
            (self.y_max - self.y_min) / self.height as f32,
        )
    }

    // ANCHOR: film_point
    /// The point of the plane at the continuous pixel position `pixel` = (column, row
    /// from the top), measured in pixels: pixel (x, y) covers [x, x + 1] x [y, y + 1].
    ///
    /// Lecture 4's "Computing the ray origin", for any point of a pixel:
    ///
    /// x = pixel_x / resolution_x * width + x_min
    /// y = (resolution_y - pixel_y) / resolution_y * height + y_min
    ///
    /// The slides count rows from the bottom of the image; image files (and this crate)
    /// count them from the top. resolution_y - pixel_y is that conversion, made here
    /// and nowhere else.
    #[inline]
    pub fn film_point(&self, pixel: Vec2) -> Vec2 {
        let resolution = self.resolution;
        let from_bottom = resolution.y - pixel.y;
        let width = self.x_max - self.x_min;
        let height = self.y_max - self.y_min;
        Vec2::new(
            pixel.x / resolution.x * width + self.x_min,
            from_bottom / resolution.y * height + self.y_min,
        )
    }
    // ANCHOR_END: film_point

    // ANCHOR: pixel_to_plane
    /// The centre of pixel (`px`, `py`) on the plane, `py` counted from the top row:
    /// [`Film::film_point`] at (px + 0.5, py + 0.5). That is the slides' formula
    ///
    /// x = (x_pixel + 0.5) / resolution_x * width + x_min
    /// y = (y_pixel + 0.5) / resolution_y * height + y_min
    ///
    /// with the row counted from the bottom, y_pixel = resolution_y - 1 - py.
    pub fn pixel_to_plane(&self, px: u32, py: u32) -> Vec2 {
        self.film_point(Film::pixel_centre(px, py))
    }

    /// The continuous position of the centre of pixel (`px`, `py`): (px + 0.5, py +
    /// 0.5).
    #[inline]
    pub fn pixel_centre(px: u32, py: u32) -> Vec2 {
        Vec2::new(px as f32 + 0.5, py as f32 + 0.5)
    }
    // ANCHOR_END: pixel_to_plane

    // ANCHOR: plane_to_pixel
    /// The inverse of [`Film::film_point`]: continuous pixel coordinates (column, row
    /// from the top) of a plane point, so a pixel centre maps to (px + 0.5, py + 0.5).
    pub fn plane_to_pixel(&self, p: Vec2) -> Vec2 {
        let sx = (p.x - self.x_min) / (self.x_max - self.x_min) * self.width as f32;
        let sy = (p.y - self.y_min) / (self.y_max - self.y_min) * self.height as f32;
        Vec2::new(sx, self.height as f32 - sy)
    }
    // ANCHOR_END: plane_to_pixel
}
