//! A Wavefront material library (`.mtl`): the materials an OBJ file's faces name
//! with `usemtl`. Each is a `newmtl NAME` line followed by its statements; of those
//! the crate reads one, `map_Kd FILE`, the image whose colours are the material's
//! diffuse albedo, a texture ([`crate::texture::Texture`]). The colours of the
//! other statements (`Kd`, `Ks`, ...) and the other maps are left to the model's
//! own colour and to the renderers' materials.

use std::path::{Path, PathBuf};

/// The path of the diffuse texture (`map_Kd`) of the material `name` in the library
/// at `library`, relative to the library's folder as the format says; `None` if the
/// library cannot be read (models are often shared without theirs), has no such
/// material, or the material no texture. Options before the file name
/// (`map_Kd -s 1 1 1 file.png`) are skipped: the file is the last word. Bytes that
/// are not UTF-8 are read as U+FFFD.
pub fn diffuse_texture(library: &Path, name: &str) -> Option<PathBuf> {
    let bytes = std::fs::read(library).ok()?;
    let text = String::from_utf8_lossy(&bytes);
    let mut current = None;
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("newmtl") => current = words.next(),
            Some("map_Kd") if current == Some(name) => {
                let folder = library.parent().unwrap_or(Path::new(""));
                return words.last().map(|file| folder.join(file));
            }
            _ => {}
        }
    }
    None
}
