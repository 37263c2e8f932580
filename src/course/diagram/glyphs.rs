//! Glyphs: the embedded font, text set in it with ab_glyph, and the white halo
//! that keeps a label readable where it lies over a line. This file measures and
//! draws text; where a label goes is decided in `place.rs` and `labels.rs`.

use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, PxScale, ScaleFont};
use glam::Vec2;
use tiny_skia::{Pixmap, PremultipliedColorU8};

use super::Rgb;

/// The embedded font (DejaVu Sans; licence in `assets/fonts/LICENSE-DejaVu.txt`).
pub const FONT_BYTES: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

fn font() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(FONT_BYTES).ok())
        .as_ref()
}

/// The layout box of `s` set `size` pixels high: its width (the glyphs' advances
/// summed) and height (ascent to descent); `None` when the font is missing.
pub(super) fn layout_size(s: &str, size: f32) -> Option<(f32, f32)> {
    let font = font()?;
    let scaled = font.as_scaled(PxScale::from(size));
    let width: f32 = s.chars().map(|c| scaled.h_advance(font.glyph_id(c))).sum();
    let height = scaled.ascent() - scaled.descent();
    Some((width, height))
}

/// Calls `each` with every glyph outline of `s` set from the layout box's top-left
/// corner `top_left`.
pub(super) fn glyphs(
    top_left: Vec2,
    s: &str,
    size: f32,
    mut each: impl FnMut(ab_glyph::OutlinedGlyph),
) {
    let Some(font) = font() else { return };
    let scaled = font.as_scaled(PxScale::from(size));
    let mut caret = Vec2::new(top_left.x, top_left.y + scaled.ascent());
    for c in s.chars() {
        let id = font.glyph_id(c);
        let glyph = id.with_scale_and_position(size, ab_glyph::point(caret.x, caret.y));
        caret.x += scaled.h_advance(id);
        if let Some(outline) = font.outline_glyph(glyph) {
            each(outline);
        }
    }
}

/// Sets `s` with its layout box's top-left corner at `top_left`; with `halo`, first
/// in white at every offset of [`HALO`], so that it stays readable over a line.
pub(super) fn draw_label(
    pixmap: &mut Pixmap,
    top_left: Vec2,
    s: &str,
    size: f32,
    color: Rgb,
    halo: bool,
) {
    if halo {
        for (dx, dy) in HALO {
            let at = top_left + Vec2::new(dx, dy);
            draw_text(pixmap, at, s, size, Rgb(255, 255, 255));
        }
    }
    draw_text(pixmap, top_left, s, size, color);
}

/// The offsets a label's white halo is drawn at, 2 pixels around it.
const HALO: [(f32, f32); 12] = [
    (-2.0, 0.0),
    (2.0, 0.0),
    (0.0, -2.0),
    (0.0, 2.0),
    (-1.5, -1.5),
    (1.5, -1.5),
    (-1.5, 1.5),
    (1.5, 1.5),
    (-1.0, 0.0),
    (1.0, 0.0),
    (0.0, -1.0),
    (0.0, 1.0),
];

/// Sets `s` with its layout box's top-left corner at `top_left`.
fn draw_text(pixmap: &mut Pixmap, top_left: Vec2, s: &str, size: f32, color: Rgb) {
    glyphs(top_left, s, size, |outline| {
        let bounds = outline.px_bounds();
        outline.draw(|gx, gy, coverage| {
            let x = bounds.min.x as i64 + gx as i64;
            let y = bounds.min.y as i64 + gy as i64;
            blend(pixmap, x, y, color, coverage);
        });
    });
}

fn blend(pixmap: &mut Pixmap, x: i64, y: i64, color: Rgb, coverage: f32) {
    let (w, h) = (pixmap.width() as i64, pixmap.height() as i64);
    if x < 0 || y < 0 || x >= w || y >= h {
        return;
    }
    let pixel = &mut pixmap.pixels_mut()[(y * w + x) as usize];
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
