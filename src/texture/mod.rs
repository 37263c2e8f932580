//! A diffuse texture: an image whose colours a mesh's surface takes as its albedo,
//! looked up by the texture coordinates (u, v) of each point (Catmull 1974; the
//! `map_Kd` of a Wavefront material).
//!
//! The image's 8-bit sRGB values are turned into linear albedo once, when it is
//! read, as the renderers compute in linear RGB. A lookup is bilinear: the four
//! texels whose centres surround the point, weighted by how near each is, so that a
//! texture seen close up is smooth rather than made of squares.

use std::path::Path;

use glam::{Vec2, Vec3};

use crate::error::{Error, Problem, Result};

mod tga;

/// A texture's texels, linear RGB, row 0 at the top of the image.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    width: u32,
    height: u32,
    texels: Vec<Vec3>,
}

/// Bytes of memory a texel takes once read: the decoder's 4 bytes, and the 12 of its
/// linear colour.
const BYTES_PER_TEXEL: u64 = 16;

/// `Ok` if a texture of `texels` texels fits in memory ([`crate::limits::memory`]).
fn fits(texels: u64) -> Result<()> {
    crate::limits::memory("texture", texels.saturating_mul(BYTES_PER_TEXEL))
}

impl Texture {
    /// A `width` x `height` texture of `texels`, row by row from the top, each channel
    /// a fraction of light reflected in [0, 1].
    pub fn new(width: u32, height: u32, texels: Vec<Vec3>) -> Result<Texture> {
        let invalid = |reason| Error::Value {
            param: "texture",
            problem: Problem::Invalid { reason },
        };
        if width == 0
            || height == 0
            || texels.len() as u64 != u64::from(width) * u64::from(height)
        {
            return Err(invalid("needs width x height texels, at least one"));
        }
        if !texels
            .iter()
            .all(|t| t.cmpge(Vec3::ZERO).all() && t.cmple(Vec3::ONE).all())
        {
            return Err(invalid("must lie between 0 and 1 in every channel"));
        }
        Ok(Texture {
            width,
            height,
            texels,
        })
    }

    /// Reads the image file at `path`, PNG (by [`crate::files::read_png_rgba`]) or TGA
    /// (by its name's extension), as a texture, its sRGB colours made linear
    /// ([`from_srgb8`]). The memory it takes is checked against the machine's
    /// ([`crate::limits::memory`]) from the image's size before it is decoded.
    pub fn read(path: impl AsRef<Path>) -> Result<Texture> {
        let path = path.as_ref();
        let fail = |message: String| Error::File {
            path: path.display().to_string(),
            line: None,
            message,
        };
        let extension = path.extension().map(|e| e.to_string_lossy().to_lowercase());
        let (width, height, codes) = match extension.as_deref() {
            Some("png") => {
                let (w, h) =
                    png_size(path).ok_or_else(|| fail("is no PNG image".into()))?;
                fits(u64::from(w) * u64::from(h))?;
                let (w, h, rgba) = crate::files::read_png_rgba(path)?;
                (w, h, rgba.chunks(4).map(|p| [p[0], p[1], p[2]]).collect())
            }
            Some("tga") => {
                let bytes = std::fs::read(path).map_err(|e| fail(e.to_string()))?;
                tga::decode(&bytes, fits, fail)?
            }
            _ => {
                return Err(fail(
                    "is not named as a PNG or TGA image (.png, .tga)".into(),
                ));
            }
        };
        let texels = codes.iter().map(|c| Vec3::from(c.map(from_srgb8)));
        Texture::new(width, height, texels.collect())
    }

    /// Width in texels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Texel (i, j): column i, row j from the top.
    pub fn texel(&self, i: u32, j: u32) -> Vec3 {
        self.texels[(j * self.width + i) as usize]
    }

    /// The mean of the texels: the one colour of the textured surface for a renderer
    /// that looks up no point (lesson 08's shadowless ray caster).
    pub fn mean(&self) -> Vec3 {
        let sum: glam::DVec3 = self.texels.iter().map(|t| t.as_dvec3()).sum();
        (sum / self.texels.len() as f64).as_vec3()
    }

    // ANCHOR: sample
    /// The albedo at texture coordinates `uv`, bilinear. The image spans u and v from
    /// 0 to 1, v = 0 at its bottom row (OBJ's convention, and OpenGL's), and repeats
    /// beyond; texel (i, j) has its centre at u = (i + 1/2) / width, v = 1 - (j + 1/2)
    /// / height. At x = u width - 1/2 and y = (1 - v) height - 1/2, in texels, the four
    /// texels round (x, y) are blended with the weights (1 - fx)(1 - fy), fx (1 - fy),
    /// (1 - fx) fy and fx fy, fx and fy the fractional parts of x and y.
    pub fn sample(&self, uv: Vec2) -> Vec3 {
        let uv = if uv.is_finite() { uv } else { Vec2::ZERO };
        let x = uv.x * self.width as f32 - 0.5;
        let y = (1.0 - uv.y) * self.height as f32 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let at = |i: f32, j: f32| {
            let wrap = |k: f32, n: u32| (k as i64).rem_euclid(i64::from(n)) as u32;
            self.texel(wrap(i, self.width), wrap(j, self.height))
        };
        // a + (b - a) t: exactly a where the texels are equal, inside a flat patch.
        let mix = |a: Vec3, b: Vec3, t: f32| a + (b - a) * t;
        let top = mix(at(x0, y0), at(x0 + 1.0, y0), fx);
        let bottom = mix(at(x0, y0 + 1.0), at(x0 + 1.0, y0 + 1.0), fx);
        mix(top, bottom, fy)
    }
    // ANCHOR_END: sample
}

/// An 8-bit sRGB code as a linear value in [0, 1], by the inverse of the sRGB transfer
/// curve (IEC 61966-2-1) that [`crate::framebuffer::to_srgb8`] applies.
pub fn from_srgb8(code: u8) -> f32 {
    let c = f32::from(code) / 255.0;
    if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The width and height a PNG file's header (its IHDR chunk, bytes 16 to 24) gives,
/// read before the image is; `None` if the file is not a PNG.
fn png_size(path: &Path) -> Option<(u32, u32)> {
    use std::io::Read;
    let mut head = [0u8; 24];
    std::fs::File::open(path).ok()?.read_exact(&mut head).ok()?;
    let signature = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];
    let word =
        |k: usize| u32::from_be_bytes([head[k], head[k + 1], head[k + 2], head[k + 3]]);
    (head[..8] == signature && &head[12..16] == b"IHDR").then(|| (word(16), word(20)))
}
