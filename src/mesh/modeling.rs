//! Modeling (Lecture 2, "Rasterization Pipeline: Modeling"): an object is a vertex
//! list and a triangle list. Each triangle names three vertices by their index, so a
//! vertex shared by several triangles is stored (and later transformed and lit) once.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use crate::error::{Error, Problem, Result, finite3, positive, vertex_indices};
use crate::scene::Object;
use crate::shapes::{Shape, Triangle};

/// The vertex list as the slide prints it (numbers 1 to 4; the slide cuts the list
/// off after vertex 4 with "⋮").
pub const LECTURE_VERTICES: [[f32; 3]; 4] = [
    [5.0, 5.0, 5.0],
    [5.0, 5.0, 1.0],
    [9.0, 5.0, 1.0],
    [9.0, 5.0, 5.0],
];

/// The triangle list as the slide prints it, with the slide's 1-based vertex numbers
/// (triangles 1 to 4; the list is cut off with "⋮" too). Triangles 1 and 2 refer to
/// vertices 5 and 8, which are not shown: they are kept here as data, not invented.
pub const LECTURE_TRIANGLES: [[u32; 3]; 4] =
    [[1, 4, 5], [5, 4, 8], [2, 1, 4], [3, 2, 4]];

/// A triangle mesh: positions, one normal per vertex, texture coordinates per vertex
/// if it has a texture, and triangles of 0-based vertex indices, counter-clockwise
/// when seen from the outside.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// The vertex list.
    pub positions: Vec<Vec3>,
    /// One unit normal per vertex (zero where no triangle gives the vertex a
    /// direction).
    pub normals: Vec<Vec3>,
    /// Texture coordinates (u, v), one per vertex, or none ([`Mesh::with_uvs`]).
    pub uvs: Vec<Vec2>,
    /// The triangle list, three 0-based indices into `positions` each.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// A mesh whose vertex normals are the area-weighted average of the normals of
    /// the triangles around each vertex.
    pub fn new(positions: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<Mesh> {
        check(&positions, &triangles)?;
        let normals = vertex_normals(&positions, &triangles);
        Ok(Mesh {
            positions,
            normals,
            uvs: Vec::new(),
            triangles,
        })
    }

    /// A mesh with normals given per vertex (normalised here; a zero normal stays
    /// zero).
    pub fn with_normals(
        positions: Vec<Vec3>,
        normals: Vec<Vec3>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Mesh> {
        check(&positions, &triangles)?;
        if normals.len() != positions.len() {
            return Err(Error::Value {
                param: "normals (one per vertex)",
                problem: Problem::TooFew {
                    value: normals.len().min(u32::MAX as usize) as u32,
                    min: positions.len().min(u32::MAX as usize) as u32,
                },
            });
        }
        for n in &normals {
            finite3("normal", *n)?;
        }
        Ok(Mesh {
            positions,
            normals: normals.iter().map(|n| n.normalize_or_zero()).collect(),
            uvs: Vec::new(),
            triangles,
        })
    }

    /// The same mesh with texture coordinates `uvs`, one per vertex, each finite.
    pub fn with_uvs(self, uvs: Vec<Vec2>) -> Result<Mesh> {
        if uvs.len() != self.positions.len() {
            return Err(Error::Value {
                param: "uvs (one per vertex)",
                problem: Problem::TooFew {
                    value: uvs.len().min(u32::MAX as usize) as u32,
                    min: self.positions.len().min(u32::MAX as usize) as u32,
                },
            });
        }
        for uv in &uvs {
            finite3("uv", uv.extend(0.0))?;
        }
        Ok(Mesh { uvs, ..self })
    }

    // ANCHOR: lecture_fixture
    /// What of the slide's object can be built: its four vertices
    /// ([`LECTURE_VERTICES`]) and the two triangles that use only them (slide
    /// triangles 3 and 4, renumbered from 0). Together they are the square y = 5,
    /// 5 <= x <= 9, 1 <= z <= 5, facing +Y. Triangles 1 and 2 need vertices 5 and 8,
    /// which the slide does not show, so [`Mesh::new`] refuses the full table.
    pub fn lecture_fixture() -> Mesh {
        let positions = LECTURE_VERTICES.iter().map(|&p| Vec3::from(p)).collect();
        let triangles = LECTURE_TRIANGLES[2..]
            .iter()
            .map(|t| t.map(|i| i - 1))
            .collect();
        Mesh::new(positions, triangles).unwrap_or_else(|_| unreachable!("fixed data"))
    }
    // ANCHOR_END: lecture_fixture

    // ANCHOR: uv_sphere
    /// A sphere tessellated along `rings` bands of latitude and `segments` slices of
    /// longitude: a vertex at each pole and (rings - 1) x segments in between, at
    /// p(theta, phi) = centre + radius (sin theta cos phi, cos theta, sin theta sin
    /// phi), theta = pi i / rings, phi = 2 pi j / segments. Vertices are shared (the
    /// mesh is closed) and every triangle winds counter-clockwise seen from outside.
    pub fn uv_sphere(
        centre: Vec3,
        radius: f32,
        segments: u32,
        rings: u32,
    ) -> Result<Mesh> {
        let centre = finite3("centre", centre)?;
        let radius = positive("radius", radius)?;
        let segments = at_least("segments", segments, 3)?;
        let rings = at_least("rings", rings, 2)?;
        let mut normals = vec![Vec3::Y];
        for i in 1..rings {
            let theta = PI * i as f32 / rings as f32;
            for j in 0..segments {
                let phi = 2.0 * PI * j as f32 / segments as f32;
                let (st, ct) = theta.sin_cos();
                let (sp, cp) = phi.sin_cos();
                normals.push(Vec3::new(st * cp, ct, st * sp));
            }
        }
        normals.push(Vec3::NEG_Y);
        let positions: Vec<Vec3> =
            normals.iter().map(|&n| centre + radius * n).collect();
        let triangles = sphere_triangles(segments, rings);
        check(&positions, &triangles)?;
        Ok(Mesh {
            positions,
            normals,
            uvs: Vec::new(),
            triangles,
        })
    }
    // ANCHOR_END: uv_sphere

    /// The box `min`..`max` as 12 triangles: four vertices per face, each carrying
    /// the face's normal, so the box shades flat as the ray caster's box does.
    pub fn cuboid(min: Vec3, max: Vec3) -> Result<Mesh> {
        let (min, max) = (finite3("min", min)?, finite3("max", max)?);
        let mut positions = Vec::new();
        let mut normals = Vec::new();
        let mut triangles = Vec::new();
        for axis in 0..3 {
            for side in [-1.0f32, 1.0] {
                let n = Vec3::AXES[axis] * side;
                let (u, v) = (Vec3::AXES[(axis + 1) % 3], Vec3::AXES[(axis + 2) % 3]);
                let corner = |a: f32, b: f32| {
                    let pick = |k: usize| {
                        let t = if k == axis {
                            (side + 1.0) / 2.0
                        } else {
                            a * u[k] + b * v[k]
                        };
                        min[k] + t * (max[k] - min[k])
                    };
                    Vec3::new(pick(0), pick(1), pick(2))
                };
                let first = positions.len() as u32;
                positions.extend([
                    corner(0., 0.),
                    corner(1., 0.),
                    corner(1., 1.),
                    corner(0., 1.),
                ]);
                normals.extend([n; 4]);
                // u x v = n on the + side: counter-clockwise seen from outside.
                if side > 0.0 {
                    triangles.extend([
                        [first, first + 1, first + 2],
                        [first, first + 2, first + 3],
                    ]);
                } else {
                    triangles.extend([
                        [first, first + 2, first + 1],
                        [first, first + 3, first + 2],
                    ]);
                }
            }
        }
        Mesh::with_normals(positions, normals, triangles)
    }

    /// The mesh as the ray caster sees it: one triangle primitive per triangle, all
    /// coloured `colour` (flat: a primitive has no vertex normals).
    ///
    /// Degenerate triangles (no area, or an area too large for f32) have no plane and
    /// no normal, so they are left out: [`Mesh::degenerate`] counts them. Where every
    /// triangle is degenerate the mesh has nothing to show, and that is an error.
    pub fn objects(&self, colour: Vec3) -> Result<Vec<Object>> {
        let objects: Vec<Object> = self
            .triangles
            .iter()
            .filter_map(|t| self.triangle(t).ok())
            .map(|t| Object::diffuse(Shape::Triangle(t), colour))
            .collect();
        if objects.is_empty() && !self.triangles.is_empty() {
            return Err(Error::Value {
                param: "mesh",
                problem: Problem::Invalid {
                    reason: "has no triangle with an area: every one is degenerate",
                },
            });
        }
        Ok(objects)
    }

    /// How many triangles have no area (or an area f32 cannot hold):
    /// [`Mesh::objects`] leaves them out.
    pub fn degenerate(&self) -> usize {
        self.triangles
            .iter()
            .filter(|t| self.triangle(t).is_err())
            .count()
    }

    fn triangle(&self, t: &[u32; 3]) -> Result<Triangle> {
        let [a, b, c] = t.map(|i| self.positions[i as usize]);
        Triangle::new(a, b, c)
    }

    /// The same triangles with no shared vertices, each corner carrying its
    /// triangle's normal (and its texture coordinates): flat shading, as the ray
    /// caster sees a triangle primitive.
    pub fn flat_shaded(&self) -> Result<Mesh> {
        let mut positions = Vec::new();
        let mut normals = Vec::new();
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| self.positions[i as usize]);
            positions.extend([a, b, c]);
            normals.extend([(b - a).cross(c - a).normalize_or_zero(); 3]);
        }
        let triangles = (0..self.triangles.len() as u32)
            .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
            .collect();
        let flat = Mesh::with_normals(positions, normals, triangles)?;
        match self.uvs.as_slice() {
            [] => Ok(flat),
            uvs => {
                let corners = self.triangles.iter().flatten();
                flat.with_uvs(corners.map(|&i| uvs[i as usize]).collect())
            }
        }
    }

    /// The square of side `size` centred on `centre` in the plane y = centre.y,
    /// facing +Y: two triangles standing in for lesson 08's infinite floor.
    pub fn floor(centre: Vec3, size: f32) -> Result<Mesh> {
        let centre = finite3("centre", centre)?;
        let h = positive("size", size)? / 2.0;
        let positions = [(-h, -h), (-h, h), (h, h), (h, -h)]
            .map(|(x, z)| centre + Vec3::new(x, 0.0, z))
            .to_vec();
        Mesh::with_normals(positions, vec![Vec3::Y; 4], vec![[0, 1, 2], [0, 2, 3]])
    }
}

/// `value` if it is at least `min`.
fn at_least(param: &'static str, value: u32, min: u32) -> Result<u32> {
    if value >= min {
        Ok(value)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::TooFew { value, min },
        })
    }
}

/// The triangles of [`Mesh::uv_sphere`]: a fan round each pole, two triangles per
/// quad in between. Vertex 0 is the north pole, then ring by ring, then the south pole.
fn sphere_triangles(segments: u32, rings: u32) -> Vec<[u32; 3]> {
    let ring = |i: u32, j: u32| 1 + (i - 1) * segments + j % segments;
    let south = 1 + (rings - 1) * segments;
    let mut triangles = Vec::new();
    for j in 0..segments {
        triangles.push([0, ring(1, j + 1), ring(1, j)]);
        for i in 1..rings - 1 {
            let (a, b) = (ring(i, j), ring(i, j + 1));
            let (c, d) = (ring(i + 1, j), ring(i + 1, j + 1));
            triangles.push([a, b, c]);
            triangles.push([b, d, c]);
        }
        triangles.push([ring(rings - 1, j), ring(rings - 1, j + 1), south]);
    }
    triangles
}

/// Every position finite and every index in range; the error names the triangle.
fn check(positions: &[Vec3], triangles: &[[u32; 3]]) -> Result<()> {
    for p in positions {
        finite3("position", *p)?;
    }
    vertex_indices(triangles, positions.len())
}

/// Area-weighted vertex normals: the cross product (b - a) x (c - a) of a triangle
/// is its normal times twice its area, so summing them weights big triangles more.
fn vertex_normals(positions: &[Vec3], triangles: &[[u32; 3]]) -> Vec<Vec3> {
    let mut normals = vec![Vec3::ZERO; positions.len()];
    for t in triangles {
        let [a, b, c] = t.map(|i| positions[i as usize]);
        let n = (b - a).cross(c - a);
        for i in t {
            normals[*i as usize] += n;
        }
    }
    normals.iter().map(|n| n.normalize_or_zero()).collect()
}
