//! The Portable Float Map (PFM): an image of raw 32-bit floats, so a render can be
//! compared or post-processed without the clamping and 8-bit rounding of PNG.
//!
//! Header "PF\n{width} {height}\n-1.0\n" (PF: three channels; a negative scale means
//! little-endian), then width x height RGB triples of f32, rows from the bottom of
//! the image to the top (the format's convention, opposite to PNG's).
//!
//! The writer writes exactly that; the reader takes any PFM (Paul Debevec's
//! description of the format, as pbrt-v3's `ReadImagePFM` reads it): `PF` (colour)
//! or `Pf` (grey, read as three equal channels), either byte order (the sign of the
//! scale), and a scale other than 1 multiplying every value.

use std::path::Path;

use glam::Vec3;

use crate::error::{Error, Problem, Result};
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
                return Err(Error::Value {
                    param: "pixel",
                    problem: Problem::NonFinitePixel { x, y },
                });
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

/// The image held by the PFM `bytes`, [`pfm_bytes`] read back: every value
/// bit for bit, rows turned back so that row 0 is the top.
///
/// Errors (an [`Error::File`] whose path is "PFM data") say what is wrong: the header
/// (not `PF` or `Pf`, a size that is not two whole numbers, a scale that is 0 or not
/// a number), the size (width x height pixels and the bytes that follow disagree, or
/// the image is larger than [`crate::limits::MAX_RESOLUTION`] a side), or a pixel that
/// is NaN or infinite, named by its position (x, y from the top).
///
/// ```
/// use glam::Vec3;
/// use render_lessons::framebuffer::Framebuffer;
/// use render_lessons::framebuffer::pfm::{pfm_bytes, read_pfm};
///
/// let image = Framebuffer::from_fn(3, 2, |x, y| Vec3::new(x as f32, y as f32, 0.1))?;
/// assert_eq!(read_pfm(&pfm_bytes(&image)?)?, image);
///
/// let err = read_pfm(b"P6\n3 2\n255\n").unwrap_err();
/// assert_eq!(err.to_string(), "PFM data: bad header: starts with \"P6\", not PF or Pf");
/// # Ok::<(), render_lessons::Error>(())
/// ```
pub fn read_pfm(bytes: &[u8]) -> Result<Framebuffer> {
    parse(bytes).map_err(|message| Error::File {
        path: "PFM data".to_string(),
        line: None,
        message,
    })
}

/// The image in the PFM file at `path` ([`read_pfm`]); errors name the file.
pub fn load_pfm(path: &Path) -> Result<Framebuffer> {
    let name = || path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| Error::File {
        path: name(),
        line: None,
        message: e.to_string(),
    })?;
    parse(&bytes).map_err(|message| Error::File {
        path: name(),
        line: None,
        message,
    })
}

/// The header: the number of channels, the size, the scale (negative for
/// little-endian), and where the pixels start.
struct Header {
    channels: usize,
    width: u32,
    height: u32,
    scale: f32,
    data: usize,
}

/// The next whitespace-separated word of `bytes` from `*at`, leaving `*at` on the
/// byte after it.
fn word(bytes: &[u8], at: &mut usize) -> Option<String> {
    while bytes.get(*at).is_some_and(u8::is_ascii_whitespace) {
        *at += 1;
    }
    let start = *at;
    while bytes.get(*at).is_some_and(|b| !b.is_ascii_whitespace()) {
        *at += 1;
    }
    let w = String::from_utf8_lossy(&bytes[start..*at]);
    (!w.is_empty()).then(|| w.into_owned())
}

fn header(bytes: &[u8]) -> std::result::Result<Header, String> {
    let mut at = 0;
    let channels = match word(bytes, &mut at).as_deref() {
        Some("PF") => 3,
        Some("Pf") => 1,
        Some(other) => {
            let other: String = other.chars().take(8).collect();
            return Err(format!("bad header: starts with {other:?}, not PF or Pf"));
        }
        None => return Err("bad header: empty, not PF or Pf".to_string()),
    };
    let mut number = |what: &str| {
        word(bytes, &mut at).ok_or_else(|| format!("bad header: no {what}"))
    };
    let side = |what: &str, w: String| {
        w.parse::<u32>()
            .map_err(|_| format!("bad header: {what} {w:?} is not a whole number"))
    };
    let width = side("width", number("width")?)?;
    let height = side("height", number("height")?)?;
    let scale_word = number("scale")?;
    let scale = scale_word
        .parse::<f32>()
        .ok()
        .filter(|s| s.is_finite() && *s != 0.0)
        .ok_or_else(|| {
            format!("bad header: scale {scale_word:?} is not a non-zero number")
        })?;
    // Exactly one whitespace byte ends the header.
    if !bytes.get(at).is_some_and(u8::is_ascii_whitespace) {
        return Err("bad header: no pixels after the scale".to_string());
    }
    Ok(Header {
        channels,
        width,
        height,
        scale,
        data: at + 1,
    })
}

/// The image, or what is wrong with `bytes`.
fn parse(bytes: &[u8]) -> std::result::Result<Framebuffer, String> {
    let h = header(bytes)?;
    let max = crate::limits::MAX_RESOLUTION;
    if !(1..=max).contains(&h.width) || !(1..=max).contains(&h.height) {
        return Err(format!(
            "wrong size: {} x {} pixels, each side must be 1 to {max}",
            h.width, h.height
        ));
    }
    let (w, rows) = (h.width as usize, h.height as usize);
    let data = &bytes[h.data..];
    let expected = w * rows * h.channels * 4;
    if data.len() != expected {
        return Err(format!(
            "wrong size: {w} x {rows} pixels of {} channels need {expected} bytes, found {}",
            h.channels,
            data.len()
        ));
    }
    let little = h.scale < 0.0;
    let factor = h.scale.abs();
    let value = |i: usize| {
        let b = [data[i], data[i + 1], data[i + 2], data[i + 3]];
        let v = if little {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        };
        if factor == 1.0 { v } else { v * factor }
    };
    let mut pixels = Vec::with_capacity(w * rows);
    for y in 0..rows {
        for x in 0..w {
            // The file's first row is the image's bottom row.
            let at = ((rows - 1 - y) * w + x) * h.channels * 4;
            let c = match h.channels {
                3 => Vec3::new(value(at), value(at + 4), value(at + 8)),
                _ => Vec3::splat(value(at)),
            };
            if !c.is_finite() {
                return Err(format!("pixel ({x}, {y}) is NaN or infinite"));
            }
            pixels.push(c);
        }
    }
    Framebuffer::from_pixels(h.width, h.height, pixels).map_err(|e| e.to_string())
}
