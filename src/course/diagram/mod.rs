//! Ray diagrams: a small 2-D drawing canvas over tiny-skia, with labels set in the
//! embedded DejaVu Sans font (ab_glyph). Lessons draw their figures with it from the
//! same cameras and rays that render, so a figure cannot disagree with the code.
//!
//! Coordinates are diagram units (y up); one uniform scale maps them to pixels, so
//! circles stay round and right angles stay right.

mod axes;
mod glyphs;
mod labels;
mod place;

pub use glyphs::FONT_BYTES;
pub use labels::{Collision, LABEL_SIZE, Label, LabelKind};
pub use place::{Place, PxBox};

use std::path::Path;

use glam::{Vec2, Vec3};
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, PremultipliedColorU8, Stroke, Transform};

use crate::camera::{Camera, Film};
use crate::course::report::num;
use crate::error::{Error, Result, finite};
use crate::output::write_png_rgba;
use crate::ray::Ray;
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

/// Which world plane a diagram shows, and how a world point lands on the page.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Seen from the side (from +x): z to the right, y up.
    Side,
    /// Seen from above (from +y): x to the right, -z up.
    Top,
}

impl View {
    /// Where the world point `p` lands on the page.
    pub fn project(self, p: Vec3) -> Vec2 {
        match self {
            View::Side => Vec2::new(p.z, p.y),
            View::Top => Vec2::new(p.x, -p.z),
        }
    }

    /// The names of the page's horizontal and vertical axes, for [`Diagram::axes`].
    pub fn axis_names(self) -> (&'static str, &'static str) {
        match self {
            View::Side => ("z", "y"),
            View::Top => ("x", "-z"),
        }
    }
}

/// The most rays a [`CameraRays`] figure draws: beyond that a figure is a smear.
const MAX_RAYS: u32 = 32;

/// `0..n`, or [`MAX_RAYS`] indices spread evenly over it, first and last included.
fn spread(n: u32) -> impl Iterator<Item = u32> {
    let shown = n.min(MAX_RAYS);
    (0..shown).map(move |i| {
        if shown == n {
            i
        } else {
            (u64::from(i) * u64::from(n - 1) / u64::from(shown - 1)) as u32
        }
    })
}

/// The standard picture of a camera and its rays, drawn by [`CameraRays::draw`]:
/// the projection plane edge-on, one arrow per chosen pixel from the ray's origin to
/// `reach` units in front of the camera, a dot where each ray crosses the plane (the
/// pixel centre, or the pinhole's screen point), and optionally labels, the camera's
/// basis and its eye. Everything comes from the camera's own `ray`, so the picture
/// cannot disagree with the renderer.
#[derive(Clone, Debug)]
pub struct CameraRays {
    camera: Camera,
    view: View,
    reach: f32,
    pixels: Vec<(u32, u32)>,
    plane: String,
    labels: Option<fn(u32, u32) -> String>,
    eye: Option<(String, Place)>,
    basis: Option<f32>,
    ray_width: f32,
    dot: f32,
}

impl CameraRays {
    /// The camera seen from the side; the rays of the middle column.
    pub fn side(camera: impl Into<Camera>, reach: f32) -> CameraRays {
        CameraRays::new(camera.into(), View::Side, reach)
    }

    /// The camera seen from above; the rays of the middle row.
    pub fn top(camera: impl Into<Camera>, reach: f32) -> CameraRays {
        CameraRays::new(camera.into(), View::Top, reach)
    }

    fn new(camera: Camera, view: View, reach: f32) -> CameraRays {
        let film = camera.film();
        let (w, h) = (film.width(), film.height());
        let pixels = match view {
            View::Side => spread(h).map(|y| (w / 2, y)).collect(),
            View::Top => spread(w).map(|x| (x, h / 2)).collect(),
        };
        CameraRays {
            camera,
            view,
            reach,
            pixels,
            plane: "projection plane".into(),
            labels: None,
            eye: None,
            basis: None,
            ray_width: 2.0,
            dot: 4.0,
        }
    }

    /// Draws the rays of every pixel of image column `x` instead.
    pub fn column(mut self, x: u32) -> CameraRays {
        self.pixels = spread(self.camera.film().height())
            .map(|y| (x, y))
            .collect();
        self
    }

    /// Draws the rays of every pixel of image row `y` instead.
    pub fn row(mut self, y: u32) -> CameraRays {
        self.pixels = spread(self.camera.film().width()).map(|x| (x, y)).collect();
        self
    }

    /// The projection plane's label, under its lower or left end.
    pub fn plane(mut self, label: impl Into<String>) -> CameraRays {
        self.plane = label.into();
        self
    }

    /// Labels each ray's dot on the plane with `label(x, y)` of its pixel.
    pub fn labels(mut self, label: fn(u32, u32) -> String) -> CameraRays {
        self.labels = Some(label);
        self
    }

    /// Marks the camera's position (the eye) with a dot and `name`, placed as `place`.
    pub fn eye(mut self, name: impl Into<String>, place: Place) -> CameraRays {
        self.eye = Some((name.into(), place));
        self
    }

    /// Draws the two camera basis vectors that lie in the page (u and w from above,
    /// v and w from the side) as arrows `length` units long from the camera position.
    pub fn basis(mut self, length: f32) -> CameraRays {
        self.basis = Some(length);
        self
    }

    /// Ray width and dot radius in pixels (2 and 4 unless set).
    pub fn sizes(mut self, ray_width: f32, dot: f32) -> CameraRays {
        (self.ray_width, self.dot) = (ray_width, dot);
        self
    }

    /// Each chosen pixel's ray, with the point where it crosses the projection plane
    /// and the parameter t where its arrow ends, in world space.
    pub fn rays(&self) -> Vec<(Ray, Vec3, f32)> {
        let w = self.camera.frame().basis().w();
        let pixel = |&(x, y): &(u32, u32)| {
            let ray = self.camera.ray(x, y);
            match &self.camera {
                Camera::Ortho(_) => (ray, ray.origin(), self.reach),
                Camera::Pinhole(c) => {
                    let s = c.frame().point_to_world(c.screen_point(x, y));
                    (ray, s, self.reach / ray.direction().dot(-w))
                }
            }
        };
        self.pixels.iter().map(pixel).collect()
    }

    /// Every point the rays are drawn between, and the camera position, on the page:
    /// what a figure's extent must hold.
    pub fn points(&self) -> Vec<Vec2> {
        let mut points = vec![self.view.project(self.camera.frame().position())];
        for (ray, _, t) in self.rays() {
            points.extend([ray.origin(), ray.at(t)].map(|p| self.view.project(p)));
        }
        points
    }

    /// Draws the picture on `d`: plane, rays, dots and labels, basis, eye.
    pub fn draw(&self, d: &mut Diagram) {
        let page = |p: Vec3| self.view.project(p);
        let frame = self.camera.frame();
        let film = self.camera.film();
        let depth = match &self.camera {
            Camera::Ortho(_) => 0.0,
            Camera::Pinhole(c) => -c.screen_distance(),
        };
        // The plane edge-on: its midline along v from the side, along u from above.
        let (edge, on_plane) = match self.view {
            View::Side => (film.y_extent(), Vec3::new(0.0, 1.0, 0.0)),
            View::Top => (film.x_extent(), Vec3::new(1.0, 0.0, 0.0)),
        };
        let edge = [edge.0, edge.1].map(|a| {
            let local = on_plane * a + Vec3::new(0.0, 0.0, depth);
            page(frame.point_to_world(local))
        });
        d.line(edge[0], edge[1], palette::PLANE, 4.0);
        let rays = self.rays();
        for (ray, on_plane, t) in &rays {
            d.arrow(
                page(ray.origin()),
                page(ray.at(*t)),
                palette::RAY,
                self.ray_width,
            );
            d.dot(page(*on_plane), self.dot, palette::HIT);
        }
        let p = page(frame.position());
        let mut tips = Vec::new();
        if let Some(length) = self.basis {
            let b = frame.basis();
            let first = match self.view {
                View::Side => (b.v(), "v", palette::Y_AXIS),
                View::Top => (b.u(), "u", palette::X_AXIS),
            };
            for (v, name, color) in [first, (b.w(), "w", palette::Z_AXIS)] {
                let tip = p + page(v) * length;
                d.arrow(p, tip, color, 3.5);
                tips.push((tip, name, color));
            }
        }
        if self.eye.is_some() {
            d.dot(p, 6.0, palette::CAMERA);
        }
        // The labels last, each where the lines and dots leave it room.
        let beside = [
            Place::Right,
            Place::AboveRight,
            Place::BelowRight,
            Place::Left,
            Place::AboveLeft,
            Place::BelowLeft,
        ];
        if let Some(label) = self.labels {
            for ((x, y), (_, on_plane, _)) in self.pixels.iter().zip(&rays) {
                d.text_clear(page(*on_plane), &label(*x, *y), palette::INK, &beside);
            }
        }
        for (tip, name, color) in tips {
            d.text_clear(tip, name, color, &beside);
        }
        if let Some((name, place)) = &self.eye {
            d.text_clear(p, name, palette::CAMERA, &place.nearest_first());
        }
        let under = [
            Place::Below,
            Place::BelowLeft,
            Place::BelowRight,
            Place::Left,
            Place::Right,
        ];
        d.text_clear(edge[0], &self.plane, palette::PLANE, &under);
    }
}

/// The smallest ranges (x, y) that hold every point, widened by `margin` on all sides.
pub fn extent(points: &[Vec2], margin: f32) -> ((f32, f32), (f32, f32)) {
    let lo = points
        .iter()
        .copied()
        .fold(Vec2::splat(f32::MAX), Vec2::min)
        - margin;
    let hi = points
        .iter()
        .copied()
        .fold(Vec2::splat(f32::MIN), Vec2::max)
        + margin;
    ((lo.x, hi.x), (lo.y, hi.y))
}

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
