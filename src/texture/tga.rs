//! Truevision TGA, the image format of tinyrenderer's textures (Truevision TGA File
//! Format Specification 2.0, 1989). An 18-byte header gives the image's type, its
//! size, the bits of a pixel and where its first row lies; an image ID and a colour
//! map may follow (skipped), then the pixels: as they are (type 2, colour; type 3,
//! grey) or run-length encoded (types 10 and 11), in packets of a byte whose high
//! bit says a run (the next pixel repeated n + 1 times) or raw (n + 1 pixels
//! follow), n its low seven bits. A colour pixel is stored blue, green, red (and
//! alpha, which a texture drops); rows run from the bottom unless bit 5 of the
//! header's last byte says from the top.
//!
//! Read here rather than through an image crate: the course writes its images with
//! `png` alone, and a TGA reader is a page of code (issue 31's build time).

/// The bytes of a TGA file, read front to back.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Cursor<'_> {
    /// The next `n` bytes, or `None` if the file ends first.
    fn take(&mut self, n: usize) -> Option<&[u8]> {
        let taken = self.bytes.get(self.at..self.at.checked_add(n)?)?;
        self.at += n;
        Some(taken)
    }
}

use crate::error::{Error, Result};

/// The image of the TGA file `bytes` as its width, height and 8-bit RGB pixels, row
/// by row from the top, once `fits(width x height)` has accepted its size. What is
/// wrong with the file (a type or a pixel size this reader does not take, or too
/// few bytes) goes to `fail`, which makes the error.
pub(super) fn decode(
    bytes: &[u8],
    fits: impl FnOnce(u64) -> Result<()>,
    fail: impl Fn(String) -> Error,
) -> Result<(u32, u32, Vec<[u8; 3]>)> {
    let short = || fail("ends before its last pixel".into());
    let header = bytes
        .get(..18)
        .ok_or_else(|| fail("is shorter than a TGA header (18 bytes)".into()))?;
    let (id_length, has_map, kind, bits) =
        (header[0], header[1], header[2], header[16]);
    let word = |k: usize| u16::from_le_bytes([header[k], header[k + 1]]);
    let map_bytes = match has_map {
        0 => 0,
        _ => usize::from(word(5)) * usize::from(header[7]).div_ceil(8),
    };
    let (width, height) = (u32::from(word(12)), u32::from(word(14)));
    let size = match (kind, bits) {
        (2 | 10, 24) => 3,
        (2 | 10, 32) => 4,
        (3 | 11, 8) => 1,
        _ => {
            let what = format!("is a TGA image of type {kind} with {bits}-bit pixels");
            return Err(fail(
                what + ": only 8-bit grey and 24- or 32-bit colour are read",
            ));
        }
    };
    let texels = u64::from(width) * u64::from(height);
    fits(texels)?;
    let mut data = Cursor {
        bytes,
        at: 18 + usize::from(id_length) + map_bytes,
    };
    let pixel = |data: &mut Cursor| {
        let p = data.take(size).ok_or_else(short)?;
        Ok(if size == 1 {
            [p[0]; 3]
        } else {
            [p[2], p[1], p[0]]
        })
    };
    let mut pixels = Vec::with_capacity(texels as usize);
    while (pixels.len() as u64) < texels {
        if kind == 2 || kind == 3 {
            pixels.push(pixel(&mut data)?);
            continue;
        }
        let packet = data.take(1).ok_or_else(short)?[0];
        let count = usize::from(packet & 0x7f) + 1;
        if packet & 0x80 != 0 {
            let p = pixel(&mut data)?;
            pixels.extend(std::iter::repeat_n(p, count));
        } else {
            for _ in 0..count {
                pixels.push(pixel(&mut data)?);
            }
        }
    }
    pixels.truncate(texels as usize); // a packet may run past the last pixel
    if header[17] & 0x20 == 0 {
        let rows: Vec<&[[u8; 3]]> =
            pixels.chunks(width.max(1) as usize).rev().collect();
        pixels = rows.concat();
    }
    Ok((width, height, pixels))
}
