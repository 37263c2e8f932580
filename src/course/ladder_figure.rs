//! Lesson 10's convergence figure: the ladder's renders (1, 4, 16, 64 samples per
//! pixel by default) in a grid two wide, each enlarged with square pixels, so the
//! noise stays visible, under a caption naming its sample count.

use glam::Vec2;

use crate::Result;
use crate::course::diagram::{Diagram, Place, palette};
use crate::framebuffer::Framebuffer;

/// Panels in a row.
const COLUMNS: usize = 2;
/// Each render is enlarged by the whole factor that makes it about this wide (at least
/// 1).
const PANEL_WIDTH: u32 = 320;
/// The captions' size in pixels.
const CAPTION_SIZE: f32 = 16.0;
/// The height of the band above each panel that holds its caption.
const BAND: u32 = 26;
/// White pixels around the figure and between its panels.
const GAP: u32 = 12;

/// The figure `10_convergence.png`: each `(spp, image)` of the ladder in order, left
/// to right and top to bottom, enlarged nearest-neighbour (2x at the default 160 x 120)
/// and captioned "`spp` spp".
pub fn ladder_figure(ladder: &[(u32, Framebuffer)]) -> Result<Diagram> {
    let (w, h) = ladder.iter().fold((1, 1), |(w, h), (_, i)| {
        (i.width().max(w), i.height().max(h))
    });
    let zoom = (PANEL_WIDTH / w).max(1);
    let (pw, ph) = (w * zoom, h * zoom);
    let columns = ladder.len().clamp(1, COLUMNS) as u32;
    let rows = ladder.len().div_ceil(COLUMNS).max(1) as u32;
    let width = GAP + columns * (pw + GAP);
    let height = GAP + rows * (BAND + ph + GAP);
    let mut d = Diagram::new(width, height, (0.0, width as f32), (0.0, height as f32))?;
    for (k, (spp, image)) in ladder.iter().enumerate() {
        let (col, row) = (k as u32 % columns, k as u32 / columns);
        let (left, top) = (GAP + col * (pw + GAP), GAP + row * (BAND + ph + GAP));
        let big = Framebuffer::from_fn(
            image.width() * zoom,
            image.height() * zoom,
            |x, y| image.get(x / zoom, y / zoom).unwrap_or_default(),
        )?;
        d.image_px(left, top + BAND, big.width(), &big.to_srgb8()?);
        let centre = Vec2::new((left + pw / 2) as f32, top as f32 + BAND as f32 * 0.5);
        let caption = format!("{spp} spp");
        d.text_px(centre, &caption, CAPTION_SIZE, palette::INK, Place::Centre);
    }
    Ok(d)
}
