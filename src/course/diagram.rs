//! Ray diagrams: a small 2-D drawing canvas over tiny-skia, with labels set in the
//! embedded DejaVu Sans font (ab_glyph). Lessons draw their figures with it from the
//! same cameras and rays that render, so a figure cannot disagree with the code.
//!
//! Coordinates are diagram units (y up); one uniform scale maps them to pixels, so
//! circles stay round and right angles stay right.

use std::path::Path;
use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, PxScale, ScaleFont};
use glam::Vec2;
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, PremultipliedColorU8, Stroke, Transform};

use crate::error::{Error, Result, finite};
use crate::output::write_png_rgba;

/// The embedded font (DejaVu Sans; licence in `assets/fonts/LICENSE-DejaVu.txt`).
pub const FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

fn font() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(FONT_BYTES).ok())
        .as_ref()
}

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

/// Where a label goes relative to its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// To the right, vertically centred.
    Right,
    /// To the left, vertically centred.
    Left,
    /// Above, horizontally centred.
    Above,
    /// Below, horizontally centred.
    Below,
    /// Centred on the point.
    Centre,
}

/// Font size of labels, in pixels.
pub const LABEL_SIZE: f32 = 15.0;
const GAP: f32 = 6.0;

/// A canvas showing the rectangle `x` by `y` of diagram space.
pub struct Diagram {
    pixmap: Pixmap,
    origin_px: Vec2,
    scale: f32,
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
        let mut pb = PathBuilder::new();
        for (i, p) in points.iter().map(|p| self.to_px(*p)).enumerate() {
            if i == 0 {
                pb.move_to(p.x, p.y);
            } else {
                pb.line_to(p.x, p.y);
            }
        }
        let Some(path) = pb.finish() else { return };
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
        let mut pb = PathBuilder::new();
        for (i, p) in points.iter().map(|p| self.to_px(*p)).enumerate() {
            if i == 0 {
                pb.move_to(p.x, p.y);
            } else {
                pb.line_to(p.x, p.y);
            }
        }
        pb.close();
        let Some(path) = pb.finish() else { return };
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

    /// Horizontal and vertical axes through the origin with ticks every `step`
    /// units, labelled with their values and with the axis names at the ends.
    pub fn axes(&mut self, x: (f32, f32), y: (f32, f32), step: f32, names: (&str, &str)) {
        self.arrow(Vec2::new(x.0, 0.0), Vec2::new(x.1, 0.0), palette::INK, 1.5);
        self.arrow(Vec2::new(0.0, y.0), Vec2::new(0.0, y.1), palette::INK, 1.5);
        self.text(Vec2::new(x.1, 0.0), names.0, palette::INK, Place::Right);
        self.text(Vec2::new(0.0, y.1), names.1, palette::INK, Place::Right);
        let tick = 4.0 / self.scale;
        let ticks = |lo: f32, hi: f32| {
            let first = (lo / step).ceil() as i32;
            let last = (hi / step).floor() as i32;
            (first..=last)
                .filter(|i| *i != 0)
                .map(move |i| i as f32 * step)
        };
        for t in ticks(x.0, x.1 - step * 0.5) {
            self.line(Vec2::new(t, -tick), Vec2::new(t, tick), palette::INK, 1.0);
            self.small_text(Vec2::new(t, -tick), &format_tick(t), Place::Below);
        }
        for t in ticks(y.0, y.1 - step * 0.5) {
            self.line(Vec2::new(-tick, t), Vec2::new(tick, t), palette::INK, 1.0);
            self.small_text(Vec2::new(-tick, t), &format_tick(t), Place::Left);
        }
    }

    /// A label next to the diagram point `p`.
    pub fn text(&mut self, p: Vec2, s: &str, color: Rgb, place: Place) {
        let px = self.to_px(p);
        self.text_px(px, s, LABEL_SIZE, color, place);
    }

    fn small_text(&mut self, p: Vec2, s: &str, place: Place) {
        let px = self.to_px(p);
        self.text_px(px, s, LABEL_SIZE * 0.8, palette::INK, place);
    }

    /// A title centred at the top of the canvas.
    pub fn title(&mut self, s: &str) {
        let top = Vec2::new(self.pixmap.width() as f32 * 0.5, 8.0);
        self.text_px(top, s, LABEL_SIZE * 1.2, palette::INK, Place::Below);
    }

    /// Text at pixel position `at`, `size` pixels high, placed as `place` says.
    pub fn text_px(&mut self, at: Vec2, s: &str, size: f32, color: Rgb, place: Place) {
        let Some(font) = font() else { return };
        let scaled = font.as_scaled(PxScale::from(size));
        let width: f32 = s.chars().map(|c| scaled.h_advance(font.glyph_id(c))).sum();
        let height = scaled.ascent() - scaled.descent();
        let (dx, dy) = match place {
            Place::Right => (GAP, -height * 0.5),
            Place::Left => (-GAP - width, -height * 0.5),
            Place::Above => (-width * 0.5, -GAP - height),
            Place::Below => (-width * 0.5, GAP),
            Place::Centre => (-width * 0.5, -height * 0.5),
        };
        let mut caret = Vec2::new(at.x + dx, at.y + dy + scaled.ascent());
        for c in s.chars() {
            let id = font.glyph_id(c);
            let glyph = id.with_scale_and_position(size, ab_glyph::point(caret.x, caret.y));
            caret.x += scaled.h_advance(id);
            let Some(outline) = font.outline_glyph(glyph) else {
                continue;
            };
            let bounds = outline.px_bounds();
            outline.draw(|gx, gy, coverage| {
                let x = bounds.min.x as i64 + gx as i64;
                let y = bounds.min.y as i64 + gy as i64;
                self.blend(x, y, color, coverage);
            });
        }
    }

    fn blend(&mut self, x: i64, y: i64, color: Rgb, coverage: f32) {
        let (w, h) = (self.pixmap.width() as i64, self.pixmap.height() as i64);
        if x < 0 || y < 0 || x >= w || y >= h {
            return;
        }
        let pixel = &mut self.pixmap.pixels_mut()[(y * w + x) as usize];
        let a = coverage.clamp(0.0, 1.0);
        let mix = |src: u8, dst: u8| (src as f32 * a + dst as f32 * (1.0 - a) + 0.5) as u8;
        let blended = PremultipliedColorU8::from_rgba(
            mix(color.0, pixel.red()),
            mix(color.1, pixel.green()),
            mix(color.2, pixel.blue()),
            mix(255, pixel.alpha()),
        );
        if let Some(b) = blended {
            *pixel = b;
        }
    }

    /// Writes the diagram as PNG, atomically.
    pub fn save(&self, path: &Path) -> Result<()> {
        let rgba = self.pixmap.clone().take_demultiplied();
        write_png_rgba(path, self.pixmap.width(), self.pixmap.height(), &rgba)
    }

    /// The RGBA bytes of the canvas (for tests).
    pub fn rgba(&self) -> Vec<u8> {
        self.pixmap.clone().take_demultiplied()
    }
}

fn format_tick(t: f32) -> String {
    crate::course::report::num(t as f64, if t.fract() == 0.0 { 0 } else { 1 })
}
