//! Writing files so that a crash or an error never leaves half a file behind: the
//! bytes go to a temporary file in the same folder, which is renamed over the
//! target only once it is complete.

use std::io::Write;
use std::path::Path;

use crate::error::{Error, Result};

fn io_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::File {
        path: path.display().to_string(),
        line: None,
        message: e.to_string(),
    }
}

/// Writes `bytes` to `path` atomically, creating the parent folders if needed.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir).map_err(|e| io_error(dir, e))?;
    let mut file =
        tempfile::NamedTempFile::new_in(dir).map_err(|e| io_error(dir, e))?;
    file.write_all(bytes).map_err(|e| io_error(path, e))?;
    readable_by_all(file.as_file()).map_err(|e| io_error(path, e))?;
    file.persist(path).map_err(|e| io_error(path, e.error))?;
    Ok(())
}

/// A temporary file is created readable by its owner only; the image it becomes
/// should be readable like any other file the student writes (rw-r--r--).
#[cfg(unix)]
fn readable_by_all(file: &std::fs::File) -> std::io::Result<()> {
    use std::os::unix::fs::PermissionsExt;
    file.set_permissions(std::fs::Permissions::from_mode(0o644))
}

#[cfg(not(unix))]
fn readable_by_all(_file: &std::fs::File) -> std::io::Result<()> {
    Ok(())
}

/// Encodes an 8-bit RGBA image as PNG and writes it atomically. The settings are
/// those the `image` crate gave the same `png` encoder (fast deflate, adaptive
/// filters), so that the committed figures stayed the same bytes when the crate
/// dropped `image`.
pub fn write_png_rgba(path: &Path, width: u32, height: u32, rgba: &[u8]) -> Result<()> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, width, height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::Filter::Adaptive);
    encoder
        .write_header()
        .and_then(|mut writer| writer.write_image_data(rgba))
        .map_err(|e| io_error(path, e))?;
    write_atomically(path, &bytes)
}

/// Reads a PNG file as 8-bit RGBA: its width, height and pixels, row by row from
/// the top. Palettes and grey levels are expanded, 16-bit channels keep their high
/// byte, and a missing alpha channel is opaque.
pub fn read_png_rgba(path: &Path) -> Result<(u32, u32, Vec<u8>)> {
    let file = std::fs::File::open(path).map_err(|e| io_error(path, e))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().map_err(|e| io_error(path, e))?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| io_error(path, "the image is too large to read"))?;
    let mut pixels = vec![0; size];
    let frame = reader
        .next_frame(&mut pixels)
        .map_err(|e| io_error(path, e))?;
    pixels.truncate(frame.buffer_size());
    let rgba = match frame.color_type {
        png::ColorType::Rgba => pixels,
        png::ColorType::Rgb => pixels
            .chunks(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect(),
        png::ColorType::GrayscaleAlpha => pixels
            .chunks(2)
            .flat_map(|p| [p[0], p[0], p[0], p[1]])
            .collect(),
        png::ColorType::Grayscale => {
            pixels.iter().flat_map(|&g| [g, g, g, 255]).collect()
        }
        png::ColorType::Indexed => {
            return Err(io_error(path, "a palette left unexpanded"));
        }
    };
    Ok((frame.width, frame.height, rgba))
}
