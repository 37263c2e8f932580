//! Ray diagrams: a small 2-D drawing canvas over tiny-skia, with labels set in the
//! embedded DejaVu Sans font (ab_glyph). Lessons draw their figures with it from the
//! same cameras and rays that render, so a figure cannot disagree with the code.
//!
//! Coordinates are diagram units (y up); one uniform scale maps them to pixels, so
//! circles stay round and right angles stay right.

mod axes;
mod camera_rays;
mod film;
mod glyphs;
mod labels;
mod place;

pub use camera_rays::{CameraRays, View, extent};
pub use glyphs::FONT_BYTES;
pub use labels::{Collision, LABEL_SIZE, Label, LabelKind};
pub use place::{Place, PxBox};

use std::path::Path;

use glam::Vec2;
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, PremultipliedColorU8, Stroke, Transform};

use crate::error::{Error, Result, finite};
use crate::output::write_png_rgba;
use glyphs::draw_label;

/// An opaque colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rgb(pub u8, pub u8, pub u8);

/// The course's colours, the same in every figure.
pub mod palette {
    use super::Rgb;
    /// Text, axes and outlines.
    pub const INK: Rgb = Rgb(40, 40, 40);
    /// Light guide lines.
    pub const GRID: Rgb = Rgb(215, 215, 215);
    /// Rays.
    pub const RAY: Rgb = Rgb(30, 100, 200);
    /// Hit points and highlighted points.
    pub const HIT: Rgb = Rgb(210, 50, 40);
    /// Normals.
    pub const NORMAL: Rgb = Rgb(30, 150, 70);
    /// Projection planes and screens.
    pub const PLANE: Rgb = Rgb(230, 140, 20);
    /// Cameras and eyes.
    pub const CAMERA: Rgb = Rgb(120, 60, 170);
    /// The first basis vector (x or u).
    pub const X_AXIS: Rgb = Rgb(210, 50, 40);
    /// The second basis vector (y or v).
    pub const Y_AXIS: Rgb = Rgb(30, 150, 70);
    /// The third basis vector (z or w).
    pub const Z_AXIS: Rgb = Rgb(30, 100, 200);
}

/// A stroke the canvas remembers, so that labels can keep clear of it.
#[derive(Clone, Copy, Debug)]
struct Segment {
    a: Vec2,
    b: Vec2,
    half_width: f32,
    axis: bool,
}

/// A canvas showing the rectangle `x` by `y` of diagram space.
///
/// Shapes are drawn at once; labels are kept (text, place, ink box) and set on top of
/// everything when the diagram is saved, so no later line can hide one. The canvas
/// also remembers its strokes and dots, so that [`Diagram::text_clear`] can put a
/// label where nothing is, a label over a line gets a white halo, a tick value that
/// would cover another label is left out, and [`Diagram::label_collisions`] can tell
/// a test what still collides.
pub struct Diagram {
    pixmap: Pixmap,
    origin_px: Vec2,
    scale: f32,
    labels: Vec<Label>,
    segments: Vec<Segment>,
    /// While `axes` draws: strokes then count as axis lines and ticks.
    drawing_axes: bool,
}

fn paint(color: Rgb) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(color.0, color.1, color.2, 255);
    p.anti_alias = true;
    p
}

impl Diagram {
    /// A white `width` x `height` pixel canvas showing at least [x.0, x.1] x [y.0, y.1],
    /// centred, with a margin of 50 px.
    pub fn new(width: u32, height: u32, x: (f32, f32), y: (f32, f32)) -> Result<Diagram> {
        let pixmap = Pixmap::new(width, height).ok_or(Error::Resolution {
            param: "diagram size",
            value: width.min(height),
            max: u32::MAX,
        })?;
        let span = |param, (a, b): (f32, f32)| -> Result<f32> {
            let s = finite(param, b)? - finite(param, a)?;
            if s > 0.0 {
                Ok(s)
            } else {
                Err(Error::EmptyRange {
                    param,
                    min: a,
                    max: b,
                })
            }
        };
        let (w, h) = (span("x range", x)?, span("y range", y)?);
        let margin = 50.0;
        let scale = ((width as f32 - 2.0 * margin) / w).min((height as f32 - 2.0 * margin) / h);
        let centre = Vec2::new(x.0 + x.1, y.0 + y.1) * 0.5;
        let origin_px =
            Vec2::new(width as f32, height as f32) * 0.5 - Vec2::new(centre.x, -centre.y) * scale;
        let mut d = Diagram {
            pixmap,
            origin_px,
            scale,
            labels: Vec::new(),
            segments: Vec::new(),
            drawing_axes: false,
        };
        d.pixmap.fill(tiny_skia::Color::WHITE);
        Ok(d)
    }

    /// Pixels per diagram unit.
    pub fn scale(&self) -> f32 {
        self.scale
    }

    /// A diagram point in pixel coordinates (y down).
    pub fn to_px(&self, p: Vec2) -> Vec2 {
        self.origin_px + Vec2::new(p.x, -p.y) * self.scale
    }

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
        self.pixmap
            .stroke_path(&path, &paint(color), &stroke, Transform::identity(), None);
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
        self.pixmap
            .fill_path(&path, &p, FillRule::Winding, Transform::identity(), None);
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
        let head = head.map(|p| (p - self.origin_px) / self.scale * Vec2::new(1.0, -1.0));
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
            self.pixmap
                .stroke_path(&path, &paint(color), &stroke, Transform::identity(), None);
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

    /// The width and height of the canvas in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.pixmap.width(), self.pixmap.height())
    }

    /// The RGBA bytes of the finished canvas (for tests).
    pub fn rgba(&self) -> Vec<u8> {
        self.finished().take_demultiplied()
    }
}
