//! Reading a Wavefront OBJ file into a [`Mesh`]. A model's file is plain text, one
//! statement a line: `v x y z` a vertex, `f 1 2 3 4` a face naming its corners by
//! vertex number (from 1; a negative number counts back from the last vertex), the
//! corners' normals, texture coordinates and materials (read by
//! `src/mesh/attributes.rs`), and lines this reader skips (groups, comments).
//! Models from the wild are made of quads and larger polygons as often as of
//! triangles, while the rasterizer and the ray caster draw triangles only: a face
//! of n corners becomes n - 2 triangles ([`ear_clip`]), and a triangle with no
//! area (the pole of a sphere or of the teapot's lid, where a quad has two equal
//! corners) is left out and counted.

use std::fmt;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};

use glam::DVec3;

use super::Mesh;
use super::attributes::Attributes;
use super::polygon::ear_clip;
use crate::error::{Error, Result};

/// What reading an OBJ file did to its faces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FaceCounts {
    /// Faces read: `f` lines of three corners or more.
    pub faces: usize,
    /// Faces of four corners or more, each split into triangles ([`ear_clip`]).
    pub faces_triangulated: usize,
    /// Triangles with no area (a corner repeated, or three corners on a line), left
    /// out of the mesh.
    pub skipped_degenerate: usize,
    /// `f` lines of fewer than three corners (an edge or a point: no area), left
    /// out.
    pub skipped_edges: usize,
}

/// "2048 faces triangulated, 64 degenerate triangles skipped"; the parts that are
/// zero are left out, so a file of good triangles says nothing.
impl fmt::Display for FaceCounts {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts = [
            (self.faces_triangulated, "faces triangulated"),
            (self.skipped_degenerate, "degenerate triangles skipped"),
            (self.skipped_edges, "faces of fewer than 3 corners skipped"),
        ];
        let said: Vec<String> = parts
            .iter()
            .filter(|(count, _)| *count > 0)
            .map(|(count, what)| format!("{count} {what}"))
            .collect();
        write!(f, "{}", said.join(", "))
    }
}

/// An OBJ file is read with at most about this many bytes of memory per byte of
/// text: the vertices in f64 and the triangles as they are read, then the mesh.
/// Measured with `/usr/bin/time -f %M` on 20 real models (tinyrenderer's, Keenan
/// Crane's Spot, the Stanford bunny, Nefertiti, the ogre, ...) and the teapot cut
/// into 128 x 128 quads a patch (31 MB): at most 1.7.
pub const PARSE_BYTES_PER_BYTE: u64 = 2;

/// A mesh read from an OBJ file, and what reading it did.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedMesh {
    /// The triangles with an area and their vertices, in f32 around
    /// [`LoadedMesh::origin`]: a position p of the mesh is the file's p + origin.
    pub mesh: Mesh,
    /// Faces read, split, and left out.
    pub counts: FaceCounts,
    /// The point of the file's space the mesh is stored around ([`origin`]): zero
    /// for a model near the file's origin, which keeps its coordinates.
    pub origin: DVec3,
    /// The diffuse texture of the first material its faces use that has one
    /// (`map_Kd` in a library named by `mtllib`), if any: a path, to be read with
    /// [`crate::texture::Texture::read`].
    pub texture: Option<PathBuf>,
}

impl Mesh {
    // ANCHOR: from_obj
    /// Reads a Wavefront OBJ file: every object and group merged into one mesh,
    /// every face cut into triangles ([`ear_clip`]), every triangle with no area
    /// left out, and the faces of fewer than three corners too; [`FaceCounts`] says
    /// how many of each. The vertices the faces use are kept, in the order first
    /// used, with the file's normals and texture coordinates where every corner has
    /// them (`src/mesh/attributes.rs`); else the normals are averaged from the
    /// triangles ([`Mesh::new`]).
    ///
    /// The text is read in f64 and stored in f32 around an [`origin`] near the
    /// model, so a model far from its file's origin keeps its shape. Bytes that are
    /// not UTF-8 (a Latin-1 letter in a comment) become U+FFFD, and a byte-order
    /// mark at the start is dropped. A big file shows a bar of the bytes read.
    ///
    /// Errors name the file and, where they can, the line: a missing file, a
    /// vertex without three numbers or with a NaN or infinite one, a corner that
    /// names no vertex, a face whose edges cross, a model too large for f32 even
    /// around its origin, no face at all, or no triangle with an area.
    pub fn from_obj(path: impl AsRef<Path>) -> Result<LoadedMesh> {
        let path = path.as_ref();
        let mut obj = ObjText::default();
        each_line(path, |number, line| {
            obj.read(number, line)
                .map_err(|message| obj_error(path, Some(number), message))
        })?;
        obj.mesh(path)
    }
    // ANCHOR_END: from_obj
}

// ANCHOR: origin
/// The point a mesh whose box runs from `lo` to `hi` is stored around: the box's
/// centre rounded to a multiple of the smallest power of two at least twice as long
/// as the box's longest side. A model whose box holds the file's origin keeps its
/// coordinates exactly (its centre is within a quarter of a step of 0, so the
/// origin is 0); one far away is moved by a round number, and its f32 coordinates,
/// within 2.5 times its size of 0, are as precise as f32 can be at its size.
pub fn origin(lo: DVec3, hi: DVec3) -> DVec3 {
    let side = (hi - lo).max_element();
    let step = 2f64.powi((2.0 * side).log2().ceil() as i32);
    ((lo + (hi - lo) / 2.0) / step).round() * step
}
// ANCHOR_END: origin

/// The `v` and `f` lines of a file as read so far.
#[derive(Default)]
struct ObjText {
    /// Every vertex, as written (f64).
    vertices: Vec<DVec3>,
    /// The line of each vertex.
    lines: Vec<usize>,
    /// The triangles of the faces, numbering the vertices from 0.
    triangles: Vec<[u32; 3]>,
    counts: FaceCounts,
    /// The corners of the face being read.
    corners: Vec<u32>,
    /// The corners' normals and texture coordinates, and the materials.
    attributes: Attributes,
}

impl ObjText {
    /// Reads line `number`, `line`; the error says what is wrong with it.
    fn read(&mut self, number: usize, line: &str) -> std::result::Result<(), String> {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => self.vertex(number, words),
            Some("f") => self.face(words),
            Some(keyword) => self.attributes.read(keyword, words),
            None => Ok(()),
        }
    }

    fn vertex<'a>(
        &mut self,
        number: usize,
        mut words: impl Iterator<Item = &'a str>,
    ) -> std::result::Result<(), String> {
        let mut xyz = [0.0; 3];
        for x in &mut xyz {
            let word = words.next().ok_or("a vertex (v) needs three coordinates")?;
            *x = word
                .parse::<f64>()
                .map_err(|_| format!("the coordinate '{word}' is not a number"))?;
        }
        let v = DVec3::from(xyz);
        if !v.is_finite() {
            return Err("a vertex has a NaN or infinite coordinate".into());
        }
        if self.vertices.len() == u32::MAX as usize {
            return Err("more than 2^32 - 1 vertices".into());
        }
        self.vertices.push(v);
        self.lines.push(number);
        Ok(())
    }

    fn face<'a>(
        &mut self,
        words: impl Iterator<Item = &'a str>,
    ) -> std::result::Result<(), String> {
        self.corners.clear();
        self.attributes.start_face();
        let defined = self.vertices.len() as i64;
        for word in words {
            let number = word.split('/').next().unwrap_or(word);
            let i = number.parse::<i64>().map_err(|_| {
                format!("the face corner '{word}' is not a vertex number")
            })?;
            let index = if i > 0 { i - 1 } else { defined + i };
            if i == 0 || !(0..defined).contains(&index) {
                return Err(format!(
                    "the face corner {i} names no vertex ({defined} defined above)"
                ));
            }
            self.corners.push(index as u32);
            self.attributes.corner(word)?;
        }
        let n = self.corners.len();
        if n < 3 {
            self.counts.skipped_edges += 1;
            return Ok(());
        }
        self.counts.faces += 1;
        self.counts.faces_triangulated += usize::from(n > 3);
        let before = self.triangles.len();
        let without_area = ear_clip(&self.corners, &self.vertices, &mut self.triangles)
            .map_err(|_| {
                format!(
                    "the face of {n} corners is not a simple polygon: its edges cross"
                )
            })?;
        self.counts.skipped_degenerate += without_area;
        self.attributes
            .cut(&self.corners, &self.triangles[before..]);
        Ok(())
    }

    /// The mesh of the triangles read: the vertices they use, in the order first
    /// used, in f32 around their [`origin`].
    fn mesh(mut self, path: &Path) -> Result<LoadedMesh> {
        if self.triangles.is_empty() {
            return Err(self.nothing_to_draw(path));
        }
        let mut new_index = vec![u32::MAX; self.vertices.len()];
        let mut used = Vec::new();
        for i in self.triangles.iter_mut().flatten() {
            let k = &mut new_index[*i as usize];
            if *k == u32::MAX {
                *k = used.len() as u32;
                used.push(*i as usize);
            }
            *i = *k;
        }
        let (lo, hi) = used
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &i| {
                (lo.min(self.vertices[i]), hi.max(self.vertices[i]))
            });
        let origin = origin(lo, hi);
        let mut positions = Vec::with_capacity(used.len());
        for &i in &used {
            let p = self.vertices[i] - origin;
            let far = p.abs().max_element();
            if far.is_nan() || far > f64::from(f32::MAX) {
                let message = format!(
                    "this vertex lies {far:.1e} from the model's centre: too large for \
                     f32, whose largest number is {:.1e}",
                    f32::MAX
                );
                return Err(obj_error(path, Some(self.lines[i]), message));
            }
            positions.push(p.as_vec3());
        }
        let texture = self.attributes.texture(path);
        let mesh = self
            .attributes
            .mesh(positions, self.triangles)
            .map_err(|e| obj_error(path, None, e.to_string()))?;
        Ok(LoadedMesh {
            mesh,
            counts: self.counts,
            origin,
            texture,
        })
    }

    /// The error for a file that gives no triangle to draw.
    fn nothing_to_draw(&self, path: &Path) -> Error {
        let what = match (self.counts.faces, self.vertices.is_empty()) {
            (0, true) => "has no vertices (v lines)".to_string(),
            (0, false) => "has no faces (f lines of three or more corners)".to_string(),
            _ => format!(
                "has no triangle with an area: all {} are degenerate",
                self.counts.skipped_degenerate
            ),
        };
        obj_error(path, None, what)
    }
}

/// Calls `read` with the number (from 1) and the text of each line of the file at
/// `path`, decoded as UTF-8 with every byte that is not replaced by U+FFFD, and a
/// byte-order mark at the start dropped, once the memory the reading will take
/// ([`PARSE_BYTES_PER_BYTE`]) is known to fit. A big file shows a bar of the bytes
/// read.
fn each_line(
    path: &Path,
    mut read: impl FnMut(usize, &str) -> Result<()>,
) -> Result<()> {
    let fail = |message: String| obj_error(path, None, message);
    let metadata = std::fs::metadata(path).map_err(|e| fail(e.to_string()))?;
    if metadata.is_dir() {
        return Err(fail("is a folder, not an OBJ file".into()));
    }
    let size = metadata.len();
    crate::limits::memory("mesh", size.saturating_mul(PARSE_BYTES_PER_BYTE))?;
    let file = std::fs::File::open(path).map_err(|e| fail(e.to_string()))?;
    let bar = crate::progress::bytes(size);
    let mut reader = BufReader::new(bar.wrap_read(file));
    let mut bytes = Vec::new();
    let mut number = 0;
    let result = loop {
        bytes.clear();
        match reader.read_until(b'\n', &mut bytes) {
            Ok(0) => break Ok(()),
            Ok(_) => {}
            Err(e) => break Err(fail(e.to_string())),
        }
        number += 1;
        let text = String::from_utf8_lossy(&bytes);
        let line = match number {
            1 => text.strip_prefix('\u{feff}').unwrap_or(&text),
            _ => &text,
        };
        if let Err(e) = read(number, line) {
            break Err(e);
        }
    };
    bar.finish_and_clear();
    result
}

fn obj_error(path: &Path, line: Option<usize>, message: String) -> Error {
    Error::File {
        path: path.display().to_string(),
        line,
        message,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_origin_is_zero_for_a_box_round_it_and_within_2_5_sides_of_a_far_one() {
        let boxes = [
            (DVec3::ZERO, DVec3::ONE),
            (DVec3::splat(-3.0), DVec3::new(3.434, 3.15, 2.0)),
            (DVec3::new(-1e-3, 0.0, 5e-4), DVec3::splat(1e-3)),
        ];
        for (lo, hi) in boxes {
            assert_eq!(origin(lo, hi), DVec3::ZERO, "{lo} {hi}");
        }
        for (k, side) in [0.01, 1.0, 3.7, 1e11].into_iter().enumerate() {
            for offset in [1e6, -2.5e9, 123.456, 3e12] {
                let lo = DVec3::new(offset, -offset / 3.0, k as f64 * side);
                let hi = lo + DVec3::new(side, side / 2.0, side / 7.0);
                let o = origin(lo, hi);
                let far = (lo - o).abs().max((hi - o).abs()).max_element();
                assert!(far <= 2.5 * side, "{lo} {hi} {o}");
            }
        }
    }
}
