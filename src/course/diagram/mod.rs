//! Ray diagrams: the lessons' 2-D figures, drawn from the real cameras and shapes.
//!
//! A small 2-D drawing canvas over tiny-skia, with labels set in the embedded
//! DejaVu Sans font (ab_glyph). Lessons draw their figures with it from the same
//! cameras and rays that render, so a figure cannot disagree with the code.
//!
//! Coordinates are diagram units (y up); one uniform scale maps them to pixels, so
//! circles stay round and right angles stay right.
//!
//! This file holds the canvas itself ([`Diagram`]: its pixels, its mapping from
//! diagram units to pixels, and what it remembers for its labels) and the colours.
//! One file per job adds the rest, and everything public is re-exported here:
//! `canvas.rs` draws shapes over tiny-skia and saves the PNG; `glyphs.rs` sets text
//! in the font, with halos; `place.rs` and `labels.rs` decide where each label goes;
//! `axes.rs` draws axes and ticks; `camera_rays.rs` and `film.rs` draw the lessons'
//! cameras; `cross_section.rs` a ray through a shape (lesson 07).

mod axes;
mod camera_rays;
mod canvas;
mod cross_section;
mod film;
mod glyphs;
mod labels;
mod place;

pub use camera_rays::{CameraRays, View, extent};
pub use cross_section::cross_section;
pub use glyphs::FONT_BYTES;
pub use labels::{Collision, LABEL_SIZE, Label, LabelKind};
pub use place::{Place, PxBox};

use glam::Vec2;
use tiny_skia::Pixmap;

use crate::error::{Error, Problem, Result, finite};

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

impl Diagram {
    /// A white `width` x `height` pixel canvas showing at least [x.0, x.1] x [y.0,
    /// y.1], centred, with a margin of 50 px.
    pub fn new(
        width: u32,
        height: u32,
        x: (f32, f32),
        y: (f32, f32),
    ) -> Result<Diagram> {
        let pixmap = Pixmap::new(width, height).ok_or(Error::Value {
            param: "diagram size",
            problem: Problem::Resolution {
                value: width.min(height),
                max: u32::MAX,
            },
        })?;
        let span = |param, (a, b): (f32, f32)| -> Result<f32> {
            let s = finite(param, b)? - finite(param, a)?;
            if s > 0.0 {
                Ok(s)
            } else {
                Err(Error::Value {
                    param,
                    problem: Problem::EmptyRange { min: a, max: b },
                })
            }
        };
        let (w, h) = (span("x range", x)?, span("y range", y)?);
        let margin = 50.0;
        let scale =
            ((width as f32 - 2.0 * margin) / w).min((height as f32 - 2.0 * margin) / h);
        let centre = Vec2::new(x.0 + x.1, y.0 + y.1) * 0.5;
        let origin_px = Vec2::new(width as f32, height as f32) * 0.5
            - Vec2::new(centre.x, -centre.y) * scale;
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

    /// The width and height of the canvas in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.pixmap.width(), self.pixmap.height())
    }
}
