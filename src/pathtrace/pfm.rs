//! The Portable Float Map (PFM): an image of raw 32-bit floats, so a render can be
//! compared or post-processed without the clamping and 8-bit rounding of PNG.
//!
//! Header "PF\n{width} {height}\n-1.0\n" (PF: three channels; a negative scale means
//! little-endian), then width x height RGB triples of f32, rows from the bottom of
//! the image to the top (the format's convention, opposite to PNG's).

use std::path::Path;

use crate::error::{Error, Result};
use crate::files::write_atomically;
use crate::framebuffer::Framebuffer;

// ANCHOR: pfm
/// The PFM bytes of `image`; fails on the first NaN or infinite pixel.
pub fn pfm_bytes(image: &Framebuffer) -> Result<Vec<u8>> {
    let (w, h) = (image.width(), image.height());
    let mut bytes = format!("PF\n{w} {h}\n-1.0\n").into_bytes();
    bytes.reserve(w as usize * h as usize * 12);
    for y in (0..h).rev() {
        for x in 0..w {
            let c = image.get(x, y).unwrap_or_default();
            if !c.is_finite() {
                return Err(Error::NonFinitePixel { x, y });
            }
            for channel in c.to_array() {
                bytes.extend_from_slice(&channel.to_le_bytes());
            }
        }
    }
    Ok(bytes)
}
// ANCHOR_END: pfm

/// Writes `image` as a PFM file, atomically (a crash never leaves half a file).
pub fn save_pfm(path: &Path, image: &Framebuffer) -> Result<()> {
    write_atomically(path, &pfm_bytes(image)?)
}
