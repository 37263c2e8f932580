//! Tessellation: a scene of analytic primitives (lesson 08's) as triangle meshes,
//! the only thing a rasterizer draws (its settings for such a scene are
//! [`crate::raster::floor_settings`]).

use super::{Mesh, Model};
use crate::error::{Error, Problem, Result};
use crate::scene::Scene;
use crate::shapes::Shape;

/// Side of the square that stands in for an infinite floor.
pub const FLOOR_SIZE: f32 = 1e4;

// ANCHOR: tessellate
/// The scene as triangle meshes, object by object in the same order: a sphere
/// becomes a uv sphere of `segments` x `segments / 2`, a box 12 triangles, a plane
/// a square of side [`FLOOR_SIZE`], a triangle itself.
pub fn tessellate(scene: &Scene, segments: u32) -> Result<Vec<Model>> {
    check_segments(scene, segments)?;
    let mut models = Vec::new();
    for object in scene.objects() {
        let mesh = match &object.shape {
            Shape::Sphere(s) => {
                Mesh::uv_sphere(s.centre(), s.radius(), segments, segments / 2)?
            }
            Shape::Aabb(b) => Mesh::cuboid(b.min(), b.max())?,
            Shape::Plane(p) => Mesh::floor(p.point(), FLOOR_SIZE)?,
            Shape::Triangle(t) => Mesh::new(t.vertices().to_vec(), vec![[0, 1, 2]])?,
            _ => {
                return Err(Error::Value {
                    param: "scene",
                    problem: Problem::Invalid {
                        reason: "may hold only spheres, boxes, planes and triangles",
                    },
                });
            }
        };
        models.push(Model::new(mesh, object.colour()));
    }
    Ok(models)
}
// ANCHOR_END: tessellate

/// `Ok` if a sphere of `segments` x `segments / 2` can be built (at least 4, so two
/// bands of latitude) and every sphere of `scene` fits in memory at that resolution
/// ([`crate::limits`]: about 100 bytes a triangle, with its vertices and the
/// rasterizer's copies).
pub fn check_segments(scene: &Scene, segments: u32) -> Result<()> {
    if segments < 4 {
        return Err(Error::Value {
            param: "segments",
            problem: Problem::TooFew {
                value: segments,
                min: 4,
            },
        });
    }
    let spheres = scene
        .objects()
        .iter()
        .filter(|o| matches!(o.shape, Shape::Sphere(_)))
        .count() as u64;
    let triangles = u64::from(segments).saturating_mul(u64::from(segments));
    crate::limits::memory(
        "segments",
        spheres.saturating_mul(triangles).saturating_mul(100),
    )
}
