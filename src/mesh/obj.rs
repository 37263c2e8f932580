//! Reading a Wavefront OBJ file into a [`Mesh`]. tobj parses the text; this file
//! turns its faces into triangles. Models from the wild are made of quads and larger
//! polygons as often as of triangles, while the rasterizer and the ray caster draw
//! triangles only: a face of n corners becomes n - 2 triangles, and a triangle with
//! no area (the pole of a sphere or of the teapot's lid, where a quad has two equal
//! corners) is left out and counted.

use std::fmt;
use std::io::BufReader;
use std::path::Path;

use glam::Vec3;

use super::Mesh;
use crate::error::{Error, Result};
use crate::shapes::Triangle;

/// What reading an OBJ file did to its faces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FaceCounts {
    /// Faces read: `f` lines of three corners or more.
    pub faces: usize,
    /// Faces of four corners or more, each split into triangles ([`fan`]).
    pub faces_triangulated: usize,
    /// Triangles with no area (a corner repeated, three corners on a line, or an
    /// area too large for f32), left out of the mesh.
    pub skipped_degenerate: usize,
}

/// "2048 faces triangulated, 64 degenerate triangles skipped"; the parts that are
/// zero are left out, so a file of good triangles says nothing.
impl fmt::Display for FaceCounts {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts = Vec::new();
        if self.faces_triangulated > 0 {
            parts.push(format!("{} faces triangulated", self.faces_triangulated));
        }
        if self.skipped_degenerate > 0 {
            parts.push(format!(
                "{} degenerate triangles skipped",
                self.skipped_degenerate
            ));
        }
        write!(f, "{}", parts.join(", "))
    }
}

/// A mesh read from an OBJ file, and what reading it did.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedMesh {
    /// The triangles with an area, and their vertices.
    pub mesh: Mesh,
    /// Faces read, split, and left out.
    pub counts: FaceCounts,
}

/// An OBJ file is read with about this many bytes of memory per byte of text: a
/// face line of 8 bytes (`f 1 2 3`) becomes about 80 bytes in tobj's lists.
pub const PARSE_BYTES_PER_BYTE: u64 = 10;

// ANCHOR: fan
/// The triangles of a face whose corners are `corners`, in order: the fan
/// (c0, c_k, c_k+1) for k = 1 to n - 2, each turning the way the face turns. A quad
/// a b c d becomes a b c and a c d; a pentagon becomes three triangles.
///
/// tobj 4 splits faces the same way when asked to (`triangulate: true`: a quad into
/// a b c and a c d, a larger polygon into the fan around its first corner). The fan
/// is right for every convex polygon, and for any polygon whose first corner sees
/// every other corner. For other non-convex polygons it is wrong: some triangles
/// overlap, or cover area outside the polygon. Ear clipping would handle those;
/// modelling tools rarely write them, and this crate does not try.
pub fn fan(corners: &[u32]) -> impl Iterator<Item = [u32; 3]> + '_ {
    let n = corners.len();
    (1..n.saturating_sub(1)).map(move |k| [corners[0], corners[k], corners[k + 1]])
}
// ANCHOR_END: fan

impl Mesh {
    // ANCHOR: from_obj
    /// Reads a Wavefront OBJ file: every object and group merged into one mesh,
    /// every face of four or more corners split into triangles ([`fan`]), and every
    /// triangle with no area left out; [`FaceCounts`] says how many of each. Normals
    /// come from the file when every vertex has one, else they are averaged from the
    /// triangles ([`Mesh::new`]). A big file shows a bar of the bytes read.
    ///
    /// Errors name the file and, where they can, the line: a missing file, a line
    /// tobj cannot parse, a corner that names no vertex, a NaN or infinite
    /// coordinate, no face at all, or no triangle with an area.
    pub fn from_obj(path: impl AsRef<Path>) -> Result<LoadedMesh> {
        let path = path.as_ref();
        let models = parse(path)?;
        let mut positions: Vec<Vec3> = Vec::new();
        let mut normals = Vec::new();
        let mut triangles = Vec::new();
        let mut counts = FaceCounts::default();
        for model in &models {
            let m = &model.mesh;
            let base = u32::try_from(positions.len()).map_err(|_| too_big(path))?;
            positions.extend(m.positions.chunks_exact(3).map(Vec3::from_slice));
            normals.extend(m.normals.chunks_exact(3).map(Vec3::from_slice));
            check_finite(path, &positions[base as usize..])?;
            let mut first = 0;
            for arity in arities(m) {
                let corners = &m.indices[first..first + arity];
                first += arity;
                counts.faces += 1;
                counts.faces_triangulated += usize::from(arity > 3);
                for t in fan(corners).map(|t| t.map(|i| i + base)) {
                    let [a, b, c] = t.map(|i| positions[i as usize]);
                    match Triangle::new(a, b, c) {
                        Ok(_) => triangles.push(t),
                        Err(_) => counts.skipped_degenerate += 1,
                    }
                }
            }
        }
        if triangles.is_empty() {
            return Err(nothing_to_draw(path, &counts));
        }
        let mesh = if normals.len() == positions.len() {
            Mesh::with_normals(positions, normals, triangles)
        } else {
            Mesh::new(positions, triangles)
        };
        let mesh = mesh.map_err(|e| obj_error(path, None, e.to_string()))?;
        Ok(LoadedMesh { mesh, counts })
    }
    // ANCHOR_END: from_obj
}

/// How tobj reads: one index per vertex (position, normal and texture coordinate
/// together), faces kept whole, points and lines skipped.
const OPTIONS: tobj::LoadOptions = tobj::LoadOptions {
    triangulate: false,
    single_index: true,
    ignore_points: true,
    ignore_lines: true,
};

/// The models of the file at `path`, parsed by tobj from a buffered reader (a bar
/// counts the bytes on a terminal), after checking that the parse fits in memory.
fn parse(path: &Path) -> Result<Vec<tobj::Model>> {
    let fail = |line, message: String| obj_error(path, line, message);
    let metadata = std::fs::metadata(path).map_err(|e| fail(None, e.to_string()))?;
    if metadata.is_dir() {
        return Err(fail(None, "is a folder, not an OBJ file".into()));
    }
    let size = metadata.len();
    crate::limits::memory("mesh", size.saturating_mul(PARSE_BYTES_PER_BYTE))?;
    let file = std::fs::File::open(path).map_err(|e| fail(None, e.to_string()))?;
    let bar = crate::progress::bytes(size);
    let mut reader = BufReader::new(bar.wrap_read(file));
    let parsed = tobj::load_obj_buf(&mut reader, &OPTIONS, |_| Ok(Default::default()));
    bar.finish_and_clear();
    match parsed {
        Ok((models, _)) => Ok(models),
        Err(tobj::LoadError::ReadError) => {
            Err(fail(None, "cannot be read as text".into()))
        }
        Err(e) => Err(fail(bad_line(path), e.to_string())),
    }
}

/// The number of corners of each face of `m`: tobj leaves `face_arities` empty when
/// every face is a triangle.
fn arities(m: &tobj::Mesh) -> Vec<usize> {
    if m.face_arities.is_empty() {
        vec![3; m.indices.len() / 3]
    } else {
        m.face_arities.iter().map(|&a| a as usize).collect()
    }
}

/// `Ok` if every position is finite; else an error naming the line of the first
/// `v` line with a NaN or infinite coordinate.
fn check_finite(path: &Path, positions: &[Vec3]) -> Result<()> {
    if positions.iter().all(|p| p.is_finite()) {
        return Ok(());
    }
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let line = text.lines().position(|l| {
        let mut words = l.split_whitespace();
        words.next() == Some("v")
            && words
                .take(3)
                .any(|w| w.parse::<f32>().is_ok_and(|x| !x.is_finite()))
    });
    let message = "a vertex has a NaN or infinite coordinate".to_string();
    Err(obj_error(path, line.map(|n| n + 1), message))
}

/// The error for a file that gives no triangle to draw.
fn nothing_to_draw(path: &Path, counts: &FaceCounts) -> Error {
    let has_vertices = std::fs::read_to_string(path)
        .is_ok_and(|text| text.lines().any(|l| l.trim_start().starts_with("v ")));
    let what = match (counts.faces, has_vertices) {
        (0, false) => "has no vertices (v lines)".to_string(),
        (0, true) => "has no faces (f lines of three or more corners)".to_string(),
        _ => format!(
            "has no triangle with an area: all {} are degenerate",
            counts.skipped_degenerate
        ),
    };
    obj_error(path, None, what)
}

fn too_big(path: &Path) -> Error {
    obj_error(path, None, "has more than 2^32 vertices".to_string())
}

fn obj_error(path: &Path, line: Option<usize>, message: String) -> Error {
    Error::File {
        path: path.display().to_string(),
        line,
        message,
    }
}

/// The 1-based line of the first line tobj refuses: a `v` line without three
/// numbers, or an `f` line with a corner that is not a number, is 0, or names a
/// vertex not yet defined (OBJ numbers vertices from 1; negative numbers count
/// back from the last).
fn bad_line(path: &Path) -> Option<usize> {
    let text = std::fs::read_to_string(path).ok()?;
    let mut vertices = 0i64;
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let bad = match words.next() {
            Some("v") => {
                vertices += 1;
                words.take(3).filter(|w| w.parse::<f32>().is_ok()).count() < 3
            }
            Some("f") => words.any(|w| {
                let index = w.split('/').next().and_then(|i| i.parse::<i64>().ok());
                index.is_none_or(|i| i == 0 || i > vertices || -i > vertices)
            }),
            _ => false,
        };
        if bad {
            return Some(n + 1);
        }
    }
    None
}
