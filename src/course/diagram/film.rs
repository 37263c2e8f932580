//! The film drawn flat, as the camera faces it: the projection plane, its pixel grid
//! and every pixel centre, labelled with its pixel and plane coordinates.

use glam::Vec2;

use super::place::Place;
use super::{Diagram, palette};
use crate::camera::Film;
use crate::course::report::num;

impl Diagram {
    /// The film seen from the camera, in its own plane coordinates: the plane
    /// [x_min, x_max] x [y_min, y_max], its pixel grid and every pixel centre, each
    /// labelled with its pixel and coordinates when there are at most 48 pixels.
    pub fn film(&mut self, film: &Film) {
        let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
        let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(Vec2::from);
        self.fill(&corners, palette::PLANE, 40);
        self.outline(&corners, palette::PLANE, 2.0);
        let (w, h) = (film.width(), film.height());
        if w > MAX_FILM_SIDE || h > MAX_FILM_SIDE {
            let note = format!("{w} x {h} pixels: too many to draw one by one");
            self.text(
                Vec2::new(0.5 * (x0 + x1), y0),
                &note,
                palette::INK,
                Place::Below,
            );
            return;
        }
        let cell = Vec2::new((x1 - x0) / w as f32, (y1 - y0) / h as f32);
        for i in 1..w {
            let x = x0 + i as f32 * cell.x;
            self.line(Vec2::new(x, y0), Vec2::new(x, y1), palette::PLANE, 1.0);
        }
        for j in 1..h {
            let y = y0 + j as f32 * cell.y;
            self.line(Vec2::new(x0, y), Vec2::new(x1, y), palette::PLANE, 1.0);
        }
        for (y, x) in (0..h).flat_map(|y| (0..w).map(move |x| (y, x))) {
            let o = film.pixel_to_plane(x, y);
            self.dot(o, 4.0, palette::HIT);
            if w * h <= 48 {
                let at = format!("({}, {})", num(o.x as f64, 1), num(o.y as f64, 1));
                self.text(o, &format!("pixel ({x},{y})"), palette::INK, Place::Above);
                self.text(o, &at, palette::HIT, Place::Below);
            }
        }
    }
}

/// The most pixels a side of [`Diagram::film`] draws one by one.
const MAX_FILM_SIDE: u32 = 64;
