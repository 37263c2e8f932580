//! A triangle mesh as one shape: its triangles in a tree of their own (lesson 11's
//! BVH, [`crate::bvh`]), so that a scene meets a model of thousands of triangles as
//! one primitive, as pbrt and rpt do, with a normal per vertex blended at the hit
//! (smooth shading) and texture coordinates.
//!
//! A ray is tested against the triangles the mesh's tree leads it to, each by the
//! watertight test of [`Triangle`], and the nearest crossing wins, on a tie the
//! triangle listed first: the answer a list of the same triangles gives, one object
//! each (the test `mesh_shape_hits_are_the_triangle_lists`). Its hit record is the
//! triangle's ([`Triangle::hit_at`]), with two more numbers blended from the three
//! corners by the crossing's barycentric coordinates b: the shading normal
//! normalize(b0 n0 + b1 n1 + b2 n2) (Phong 1975) and the texture coordinates
//! b0 uv0 + b1 uv1 + b2 uv2.

use glam::{Vec2, Vec3};

use super::{Aabb, Barycentric, Crossings, Hit, PreparedRay, Triangle};
use crate::bvh::{Bvh, Crossing};
use crate::error::{Error, Problem, Result, finite3, vertex_indices};
use crate::ray::{Interval, Ray};

/// A triangle mesh placed in the world, searched through its own BVH.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleMesh {
    /// The vertices, in world space.
    positions: Vec<Vec3>,
    /// One unit normal per vertex, or none (the mesh is flat shaded).
    normals: Vec<Vec3>,
    /// Texture coordinates per vertex, or none.
    uvs: Vec<Vec2>,
    /// The triangles with an area, three indices into `positions` each, in the order
    /// given: a hit's triangle is an index into this list.
    triangles: Vec<[u32; 3]>,
    /// The same triangles in the tree's leaf order, so that a leaf's sit together.
    leaves: Vec<Triangle>,
    /// The tree over `triangles`.
    tree: Bvh,
    /// The box around every triangle.
    bounds: Aabb,
}

/// The tree's search reads a triangle crossing's `t`.
impl Crossing for Barycentric {
    #[inline(always)]
    fn t(&self) -> f32 {
        self.t
    }
}

impl TriangleMesh {
    /// The mesh of `triangles` (three indices into `positions` each) with `normals`
    /// and texture coordinates `uvs` per vertex, each list either empty (a flat
    /// shaded, untextured mesh) or one per position; normals are normalised (a zero
    /// one stays zero, and the hit then shades with the triangle's own normal).
    ///
    /// A triangle with no area has no plane and no normal: it is left out, as a list
    /// of triangles leaves it out (`Mesh::objects`). Errors name what is wrong: a
    /// position, normal or coordinate that is NaN or infinite, a list of normals or
    /// coordinates of the wrong length, an index past the last vertex, or no
    /// triangle with an area.
    pub fn new(
        positions: Vec<Vec3>,
        triangles: &[[u32; 3]],
        normals: Vec<Vec3>,
        uvs: Vec<Vec2>,
    ) -> Result<TriangleMesh> {
        for p in &positions {
            finite3("position", *p)?;
        }
        let normals = per_vertex("normals", normals, positions.len())?;
        for n in &normals {
            finite3("normal", *n)?;
        }
        let uvs = per_vertex("uvs", uvs, positions.len())?;
        if let Some(uv) = uvs.iter().find(|uv| !uv.is_finite()) {
            finite3("uv", uv.extend(0.0))?;
        }
        vertex_indices(triangles, positions.len())?;
        let mut kept = Vec::with_capacity(triangles.len());
        let mut shapes = Vec::with_capacity(triangles.len());
        for t in triangles {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            if let Ok(shape) = Triangle::new(a, b, c) {
                kept.push(*t);
                shapes.push(shape);
            }
        }
        let corners = kept.iter().flatten().map(|&i| positions[i as usize]);
        let Some(bounds) = Aabb::around(corners) else {
            return Err(Error::Value {
                param: "mesh",
                problem: Problem::Invalid {
                    reason: "has no triangle with an area",
                },
            });
        };
        let tree = Bvh::build(&shapes);
        let leaves = tree.primitives().iter().map(|&i| shapes[i]).collect();
        Ok(TriangleMesh {
            normals: normals.iter().map(|n| n.normalize_or_zero()).collect(),
            positions,
            uvs,
            triangles: kept,
            leaves,
            tree,
            bounds,
        })
    }

    /// How many triangles it has (those with an area).
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// `false`: a mesh has at least one triangle ([`TriangleMesh::new`]).
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Triangle `i` (of those with an area, in the order given).
    pub fn triangle(&self, i: usize) -> Triangle {
        let [a, b, c] = self.triangles[i].map(|k| self.positions[k as usize]);
        Triangle::from_checked(a, b, c)
    }

    /// `true` if the mesh has a normal per vertex (smooth shading).
    pub fn has_normals(&self) -> bool {
        !self.normals.is_empty()
    }

    /// `true` if the mesh has texture coordinates.
    pub fn has_uvs(&self) -> bool {
        !self.uvs.is_empty()
    }

    /// The box around every triangle.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// The tree over the triangles.
    pub fn tree(&self) -> &Bvh {
        &self.tree
    }

    // ANCHOR: mesh_closest
    /// The nearest crossing within `range` and its triangle's index: the tree's
    /// search ([`Bvh::closest`]), each leaf's triangles by the watertight test.
    #[inline]
    pub fn closest(
        &self,
        ray: &PreparedRay,
        range: Interval,
    ) -> Option<(Barycentric, usize)> {
        let tree = &self.tree;
        let no_unbounded = |_, _| None;
        tree.closest(&ray.box_ray(), range, no_unbounded, |leaf, nearest| {
            let indices = &tree.primitives()[leaf.clone()];
            nearest.offer_leaf(&self.leaves[leaf], indices, range, |t, r| {
                t.watertight_prepared(ray, r)
            })
        })
    }
    // ANCHOR_END: mesh_closest

    // ANCHOR: mesh_hit
    /// The hit record of triangle `i`'s `crossing`: the triangle's own
    /// ([`Triangle::hit_at`]), with the shading normal and the texture coordinates
    /// blended from its corners by the crossing's barycentric coordinates.
    pub fn hit_at(&self, ray: &Ray, i: usize, crossing: Barycentric) -> Hit {
        let hit = self.triangle(i).hit_at(ray, crossing);
        let corners = self.triangles[i].map(|k| k as usize);
        let b = crossing.b;
        let shading = match self.normals.as_slice() {
            [] => hit.normal,
            n => {
                let [n0, n1, n2] = corners.map(|k| n[k]);
                (b[0] * n0 + b[1] * n1 + b[2] * n2).normalize_or(hit.normal)
            }
        };
        let uv = match self.uvs.as_slice() {
            [] => Vec2::ZERO,
            uv => {
                let [uv0, uv1, uv2] = corners.map(|k| uv[k]);
                b[0] * uv0 + b[1] * uv1 + b[2] * uv2
            }
        };
        hit.with_shading(shading, uv)
    }
    // ANCHOR_END: mesh_hit

    /// The nearest hit within `range`.
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let (crossing, i) = self.closest(&PreparedRay::new(ray), range)?;
        Some(self.hit_at(ray, i, crossing))
    }

    /// The first and the last crossing of the ray's whole line, -inf < t < inf: all
    /// there are for a convex mesh; [`Crossings`] holds no more than two, and a mesh
    /// of another shape may have more. The last is the first of the reversed ray
    /// (the watertight test gives it as -t exactly: the shear is the same, the
    /// depths change sign).
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        let first = |ray: &Ray| {
            self.closest(&PreparedRay::new(ray), Interval::EVERYWHERE)
                .map(|(c, _)| c.t)
        };
        let reversed = Ray::from_checked(ray.origin(), -ray.direction());
        match (first(ray), first(&reversed)) {
            (Some(t0), Some(t1)) if t0 != -t1 => Crossings::two(t0, -t1),
            (Some(t0), _) => Crossings::one(t0),
            _ => Crossings::NONE,
        }
    }

    /// The outward unit normal of the triangle that `p` lies on: of those whose
    /// plane `p` is nearest to among those it projects into, the first; the zero
    /// vector if it projects into none. A search of every triangle, for the rare
    /// caller that has a point but no hit.
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        let mut best = (f32::INFINITY, Vec3::ZERO);
        for i in 0..self.len() {
            let t = self.triangle(i);
            let [a, b, c] = t.vertices();
            let n = t.normal();
            let distance = n.dot(p - a).abs();
            let q = p - n.dot(p - a) * n;
            let inside = [(a, b), (b, c), (c, a)]
                .iter()
                .all(|&(u, v)| (v - u).cross(q - u).dot(n) >= 0.0);
            if inside && distance < best.0 {
                best = (distance, n);
            }
        }
        best.1
    }
}

/// `values`, if there are none or one per vertex of `vertices`.
fn per_vertex<T>(
    param: &'static str,
    values: Vec<T>,
    vertices: usize,
) -> Result<Vec<T>> {
    if values.is_empty() || values.len() == vertices {
        return Ok(values);
    }
    Err(Error::Value {
        param,
        problem: Problem::Invalid {
            reason: "must be empty or one per vertex",
        },
    })
}
