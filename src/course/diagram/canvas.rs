//! Drawing over tiny-skia: lines, dashes, outlines, translucent fills, arrows, dots,
//! circles and pasted images, each stroke remembered for label placement; and the
//! finished canvas, every label set on top, written as PNG.

use std::path::Path;

use glam::Vec2;
use tiny_skia::{
    FillRule, Paint, PathBuilder, Pixmap, PremultipliedColorU8, Stroke, Transform,
};

use super::glyphs::draw_label;
use super::{Diagram, Rgb, Segment};
use crate::error::Result;
use crate::files::write_png_rgba;

fn paint(color: Rgb) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(color.0, color.1, color.2, 255);
    p.anti_alias = true;
    p
}

impl Diagram {
    fn stroke(&mut self, points: &[Vec2], color: Rgb, width_px: f32, dash: bool) {
        let px: Vec<Vec2> = points.iter().map(|p| self.to_px(*p)).collect();
        for pair in px.windows(2) {
            self.segments.push(Segment {
                a: pair[0],
                b: pair[1],
                half_width: 0.5 * width_px,
                axis: self.drawing_axes,
            });
        }
        let Some(path) = self.path(points, false) else {
            return;
        };
        let stroke = Stroke {
            width: width_px,
            dash: if dash {
                tiny_skia::StrokeDash::new(vec![6.0, 5.0], 0.0)
            } else {
                None
            },
            ..Stroke::default()
        };
        self.pixmap.stroke_path(
            &path,
            &paint(color),
            &stroke,
            Transform::identity(),
            None,
        );
    }

    /// The polyline through `points` (diagram coordinates) in pixels, closed if
    /// `closed`; `None` for fewer than two points.
    fn path(&self, points: &[Vec2], closed: bool) -> Option<tiny_skia::Path> {
        let mut pb = PathBuilder::new();
        for (i, p) in points.iter().map(|p| self.to_px(*p)).enumerate() {
            if i == 0 {
                pb.move_to(p.x, p.y);
            } else {
                pb.line_to(p.x, p.y);
            }
        }
        if closed {
            pb.close();
        }
        pb.finish()
    }

    /// A straight line from `a` to `b`.
    pub fn line(&mut self, a: Vec2, b: Vec2, color: Rgb, width_px: f32) {
        self.stroke(&[a, b], color, width_px, false);
    }

    /// A dashed line from `a` to `b`.
    pub fn dashed(&mut self, a: Vec2, b: Vec2, color: Rgb, width_px: f32) {
        self.stroke(&[a, b], color, width_px, true);
    }

    /// A closed outline through `points`.
    pub fn outline(&mut self, points: &[Vec2], color: Rgb, width_px: f32) {
        let mut closed = points.to_vec();
        closed.extend(points.first());
        self.stroke(&closed, color, width_px, false);
    }

    /// A filled polygon with a translucent fill (`alpha` from 0 to 255).
    pub fn fill(&mut self, points: &[Vec2], color: Rgb, alpha: u8) {
        let Some(path) = self.path(points, true) else {
            return;
        };
        let mut p = paint(color);
        p.set_color_rgba8(color.0, color.1, color.2, alpha);
        self.pixmap.fill_path(
            &path,
            &p,
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }

    /// An arrow from `from` to `to`, its head at `to`.
    pub fn arrow(&mut self, from: Vec2, to: Vec2, color: Rgb, width_px: f32) {
        self.line(from, to, color, width_px);
        let (a, b) = (self.to_px(from), self.to_px(to));
        let Some(dir) = (b - a).try_normalize() else {
            return;
        };
        let size = 6.0 + 2.0 * width_px;
        let side = dir.perp() * (size * 0.45);
        let base = b - dir * size;
        let head = [b, base + side, base - side];
        let head =
            head.map(|p| (p - self.origin_px) / self.scale * Vec2::new(1.0, -1.0));
        self.fill(&head, color, 255);
    }

    /// A filled dot of radius `radius_px` pixels.
    pub fn dot(&mut self, p: Vec2, radius_px: f32, color: Rgb) {
        let c = self.to_px(p);
        self.segments.push(Segment {
            a: c,
            b: c,
            half_width: radius_px,
            axis: false,
        });
        if let Some(path) = PathBuilder::from_circle(c.x, c.y, radius_px) {
            self.pixmap.fill_path(
                &path,
                &paint(color),
                FillRule::Winding,
                Transform::identity(),
                None,
            );
        }
    }

    /// Copies an opaque image (RGBA bytes, `width` pixels a row) onto the canvas
    /// with its top-left pixel at (`left`, `top`); what falls off the canvas is cut.
    pub fn image_px(&mut self, left: u32, top: u32, width: u32, rgba: &[u8]) {
        let (w, h) = (self.pixmap.width(), self.pixmap.height());
        let pixels = self.pixmap.pixels_mut();
        for (i, p) in rgba.chunks_exact(4).enumerate() {
            let (x, y) = (
                left as usize + i % width as usize,
                top as usize + i / width as usize,
            );
            if x >= w as usize || y >= h as usize {
                continue;
            }
            if let Some(c) = PremultipliedColorU8::from_rgba(p[0], p[1], p[2], 255) {
                pixels[y * w as usize + x] = c;
            }
        }
    }

    /// A circle of radius `r` diagram units.
    pub fn circle(&mut self, centre: Vec2, r: f32, color: Rgb, width_px: f32) {
        let c = self.to_px(centre);
        if let Some(path) = PathBuilder::from_circle(c.x, c.y, r * self.scale) {
            let stroke = Stroke {
                width: width_px,
                ..Stroke::default()
            };
            self.pixmap.stroke_path(
                &path,
                &paint(color),
                &stroke,
                Transform::identity(),
                None,
            );
        }
    }

    /// The finished canvas: the shapes, then every shown label on top, with a white
    /// halo where it lies over a line or a dot.
    fn finished(&self) -> Pixmap {
        let mut pixmap = self.pixmap.clone();
        for l in self.labels() {
            let over_line = self
                .segments
                .iter()
                .any(|g| l.bounds.touches(g.a, g.b, g.half_width));
            draw_label(&mut pixmap, l.at, &l.text, l.size, l.color, over_line);
        }
        pixmap
    }

    /// Writes the diagram as PNG, atomically.
    pub fn save(&self, path: &Path) -> Result<()> {
        let pixmap = self.finished();
        let rgba = pixmap.clone().take_demultiplied();
        write_png_rgba(path, pixmap.width(), pixmap.height(), &rgba)
    }

    /// The RGBA bytes of the finished canvas (for tests).
    pub fn rgba(&self) -> Vec<u8> {
        self.finished().take_demultiplied()
    }
}
