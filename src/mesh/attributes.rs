//! What an OBJ file says of its corners besides their positions: texture
//! coordinates (`vt u v`) and normals (`vn x y z`), which a face names corner by
//! corner (`f v/vt/vn ...`, or `v/vt`, or `v//vn`), and the material library
//! (`mtllib`) and materials (`usemtl`) that give a texture (`map_Kd`, read by
//! [`super::mtl`]). `src/mesh/obj.rs` reads the positions and cuts the faces; this
//! file follows the corners through the cut and gives the mesh its normals and
//! texture coordinates.
//!
//! In a file, a position, a texture coordinate and a normal are numbered apart, so
//! one position can be a corner with one texture coordinate in a face and another
//! in the next (a *seam*, where a texture's image is cut open). A mesh has one of
//! each per vertex, so a position used with two texture coordinates becomes two
//! vertices.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::{Vec2, Vec3};

use super::Mesh;
use super::mtl::diffuse_texture;
use crate::error::Result;

/// A corner's texture coordinate and normal, by their 0-based numbers; [`NONE`]
/// where the face does not name one.
type Corner = [u32; 2];

/// A corner that names no texture coordinate (or no normal).
const NONE: u32 = u32::MAX;

/// The attributes of an OBJ file as read so far.
#[derive(Default)]
pub(super) struct Attributes {
    /// Every `vt`, as (u, v).
    uvs: Vec<Vec2>,
    /// Every `vn`.
    normals: Vec<Vec3>,
    /// The corners of the face being read, in order.
    face: Vec<Corner>,
    /// The corners of every triangle kept, in the order of the mesh's triangles,
    /// from the first face cut after a `vt` or `vn` line.
    triangles: Vec<[Corner; 3]>,
    /// Triangles cut before any `vt` or `vn` line: their corners name neither.
    bare: usize,
    /// The material libraries named by `mtllib`, as written.
    libraries: Vec<String>,
    /// The materials named by `usemtl` before a face, each once, in order.
    materials: Vec<String>,
    /// The material in use.
    material: Option<String>,
}

impl Attributes {
    /// Reads a line whose first word, `keyword`, is not `v` or `f`: `vt`, `vn`,
    /// `mtllib` and `usemtl` are taken, other lines (groups, smoothing, comments)
    /// skipped. The error says what is wrong with the line.
    pub(super) fn read<'a>(
        &mut self,
        keyword: &str,
        mut words: impl Iterator<Item = &'a str>,
    ) -> std::result::Result<(), String> {
        match keyword {
            "vt" => {
                let [u, v] =
                    numbers(&mut words, [true, false], "a texture coordinate (vt)")?;
                self.uvs.push(Vec2::new(u, v));
            }
            "vn" => {
                let n = numbers(&mut words, [true; 3], "a normal (vn)")?;
                self.normals.push(Vec3::from(n));
            }
            "mtllib" => self.libraries.extend(words.map(String::from)),
            "usemtl" => self.material = words.next().map(String::from),
            _ => {}
        }
        Ok(())
    }

    /// Starts a face.
    pub(super) fn start_face(&mut self) {
        self.face.clear();
        if let Some(material) = self.material.take()
            && !self.materials.contains(&material)
        {
            self.materials.push(material);
        }
    }

    /// Reads the texture coordinate and normal of the face corner written `word`
    /// (`v`, `v/vt`, `v/vt/vn` or `v//vn`; a negative number counts back from the
    /// last one defined). The error names a number that is not one, or that names
    /// nothing.
    pub(super) fn corner(&mut self, word: &str) -> std::result::Result<(), String> {
        let mut parts = word.split('/').skip(1);
        let mut index = |defined: usize, what: &str| match parts.next() {
            None | Some("") => Ok(NONE),
            Some(number) => {
                let i = number.parse::<i64>().map_err(|_| {
                    format!(
                        "the face corner '{word}' names {what} that is not a number"
                    )
                })?;
                let defined = defined as i64;
                let k = if i > 0 { i - 1 } else { defined + i };
                if i == 0 || !(0..defined).contains(&k) {
                    return Err(format!(
                        "the face corner '{word}' names {what} {i}, of {defined} defined above"
                    ));
                }
                Ok(k as u32)
            }
        };
        let uv = index(self.uvs.len(), "texture coordinate")?;
        let normal = index(self.normals.len(), "normal")?;
        self.face.push([uv, normal]);
        Ok(())
    }

    /// Follows the face through its cut: `added` are the triangles the cut made, of
    /// the face's `corners` (positions); each triangle corner takes the attributes
    /// of the face's first corner at its position.
    pub(super) fn cut(&mut self, corners: &[u32], added: &[[u32; 3]]) {
        if self.uvs.is_empty() && self.normals.is_empty() {
            self.bare += added.len(); // a file of positions alone stores nothing here
            return;
        }
        for t in added {
            let corner = |p: u32| {
                let k = corners.iter().position(|&c| c == p).unwrap_or(0);
                self.face.get(k).copied().unwrap_or([NONE; 2])
            };
            let t = t.map(corner);
            self.triangles.push(t);
        }
    }

    /// The mesh of `positions` and `triangles` (the mesh's own numbering, its
    /// triangles in the order the faces were cut), with the file's texture
    /// coordinates if every corner has one and its normals if every corner has one
    /// (else they are averaged from the triangles, [`Mesh::new`]); a position used
    /// with different ones becomes as many vertices.
    pub(super) fn mesh(
        self,
        positions: Vec<Vec3>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Mesh> {
        let every = |k: usize| {
            self.bare == 0
                && !self.triangles.is_empty()
                && self.triangles.iter().flatten().all(|c| c[k] != NONE)
        };
        let (with_uvs, with_normals) = (every(0), every(1));
        if !with_uvs && !with_normals {
            return Mesh::new(positions, triangles);
        }
        let mut vertices: HashMap<[u32; 3], u32> = HashMap::new();
        let (mut points, mut uvs, mut normals) = (Vec::new(), Vec::new(), Vec::new());
        let mut numbered = Vec::with_capacity(triangles.len());
        for (t, corners) in triangles.iter().zip(&self.triangles) {
            numbered.push([0, 1, 2].map(|k| {
                let [uv, normal] = corners[k];
                let key = [
                    t[k],
                    uv * u32::from(with_uvs),
                    normal * u32::from(with_normals),
                ];
                *vertices.entry(key).or_insert_with(|| {
                    points.push(positions[t[k] as usize]);
                    uvs.extend(with_uvs.then(|| self.uvs[uv as usize]));
                    normals.extend(with_normals.then(|| self.normals[normal as usize]));
                    (points.len() - 1) as u32
                })
            }));
        }
        let mesh = match with_normals {
            true => Mesh::with_normals(points, normals, numbered)?,
            false => Mesh::new(points, numbered)?,
        };
        match with_uvs {
            true => mesh.with_uvs(uvs),
            false => Ok(mesh),
        }
    }

    /// The texture of the first material used that has one (`map_Kd`), looked for
    /// in the material libraries named, each a path relative to the folder of the
    /// OBJ file at `obj` ([`diffuse_texture`]): the texture's path; `None` where no
    /// material used has one, or no library can be read.
    pub(super) fn texture(&self, obj: &Path) -> Option<PathBuf> {
        let folder = obj.parent().unwrap_or(Path::new(""));
        self.materials.iter().find_map(|material| {
            let library = |l: &String| diffuse_texture(&folder.join(l), material);
            self.libraries.iter().find_map(library)
        })
    }
}

/// The first numbers of `words`, one per entry of `needed`: a number that is
/// needed and missing, or any that is not a finite number, is refused; one that is
/// not needed and missing is 0 (a `vt` of u alone).
fn numbers<'a, const N: usize>(
    words: &mut impl Iterator<Item = &'a str>,
    needed: [bool; N],
    what: &str,
) -> std::result::Result<[f32; N], String> {
    let mut out = [0.0; N];
    for (x, needed) in out.iter_mut().zip(needed) {
        match words.next() {
            None if needed => return Err(format!("{what} needs {N} numbers")),
            None => {}
            Some(word) => {
                *x = word
                    .parse::<f32>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| {
                        format!("'{word}' in {what} is not a finite number")
                    })?;
            }
        }
    }
    Ok(out)
}
