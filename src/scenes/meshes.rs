//! A mesh from a file standing in the still life (lesson 09's second scene); the
//! ray caster and the path tracer see it as one shape with a tree of its own
//! ([`Model::shape`]).

use std::path::Path;
use std::sync::Arc;

use glam::Vec3;

use super::asset_path;
use super::placement::{Fit, Up, place};
use crate::camera::Camera;
use crate::error::{Error, Problem, Result};
use crate::mesh::{FaceCounts, LoadedMesh, Mesh, Model};
use crate::mesh::{check_subdivisions, subdivided_count};
use crate::scene::{Object, Scene};
use crate::texture::Texture;
use crate::{limits, progress};

/// The mesh lesson 09 draws by default: a torus of 1024 triangles, relative to the
/// repository's root (see [`asset_path`] for other folders).
pub const TORUS_OBJ: &str = "assets/meshes/torus.obj";

/// The Newell teapot as 2048 quads (`mesh::teapot::teapot_obj(8)`), relative to the
/// repository's root: `--mesh assets/meshes/teapot.obj`.
pub const TEAPOT_OBJ: &str = "assets/meshes/teapot.obj";

/// The memory a triangle of lesson 09's mesh takes at the lesson's peak: its
/// flat-shaded copy (three vertices), the ray caster's primitive and its place in a
/// BVH, the rasterizer's transformed vertices and screen triangle. Measured with
/// `/usr/bin/time -f %M` on lesson 09 with the teapot split in four 1 to 4 times
/// (16 128 to 1 032 192 triangles), less the run with the teapot as it is: 679 to
/// 869 bytes a triangle; rounded up.
pub const MESH_BYTES_PER_TRIANGLE: u64 = 900;

/// A mesh placed in the still life, and what reading and placing it did.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedMesh {
    /// The mesh, placed on the floor and coloured.
    pub model: Model,
    /// What reading the file did to its faces.
    pub counts: FaceCounts,
    /// How many times every triangle was split in four.
    pub subdivisions: u32,
    /// What placing it did: the triangles left out of the fit, the frame's say.
    pub fit: Fit,
}

// ANCHOR: mesh_on_the_floor
/// The mesh of the OBJ file at `path`, whose file has `up` up, placed in lesson
/// 08's scene where lesson 09 draws it through `camera` ([`place`]: standing on
/// the floor at the front right, tilted towards the camera, as large as the torus
/// where the frame allows), then every triangle split in four `subdivisions` times,
/// shaded smooth by its vertex normals in both renderers (the file's, or the
/// average of the triangles' around each vertex: [`Mesh::new`]) and textured by its
/// material's texture if it names one (`map_Kd`). Before the work, the triangles it
/// would make are checked against the memory ([`MESH_BYTES_PER_TRIANGLE`] each).
pub fn mesh_on_the_floor(
    path: &Path,
    up: Up,
    subdivisions: u32,
    camera: &Camera,
) -> Result<PlacedMesh> {
    let subdivisions = check_subdivisions("subdivide", subdivisions)?;
    let LoadedMesh {
        mut mesh,
        counts,
        texture,
        ..
    } = Mesh::from_obj(asset_path(path))?;
    let triangles = subdivided_count(mesh.triangles.len(), subdivisions);
    let param = if subdivisions == 0 {
        "mesh"
    } else {
        "subdivide"
    };
    limits::memory(param, triangles.saturating_mul(MESH_BYTES_PER_TRIANGLE))?;
    for p in mesh.positions.iter_mut().chain(&mut mesh.normals) {
        *p = up.to_y_up(*p);
    }
    let (model, fit) = place(&mut mesh, camera)?;
    let mesh = match subdivisions {
        0 => mesh,
        n => progress::spinner(
            format!("subdividing into {triangles} triangles"),
            || mesh.subdivided(n),
        )?,
    };
    if mesh.degenerate() == mesh.triangles.len() {
        return Err(Error::Value {
            param: "mesh",
            problem: Problem::Invalid {
                reason: "has no triangle with an area: every one is degenerate",
            },
        });
    }
    Ok(PlacedMesh {
        model: Model {
            mesh,
            model,
            colour: Vec3::new(0.8, 0.55, 0.3),
            texture: texture.map(Texture::read).transpose()?.map(Arc::new),
        },
        counts,
        subdivisions,
        fit,
    })
}
// ANCHOR_END: mesh_on_the_floor

impl PlacedMesh {
    /// The same mesh textured by the image file at `path` if one is given (lesson
    /// 09's `--texture`: tinyrenderer's models, for one, come without a material
    /// library to name theirs); its texture coordinates are checked when it is drawn.
    pub fn textured(self, path: Option<&Path>) -> Result<PlacedMesh> {
        let Some(path) = path else {
            return Ok(self);
        };
        let texture = Texture::read(asset_path(path))?;
        Ok(PlacedMesh {
            model: self.model.textured(texture),
            ..self
        })
    }
}

/// The floor of `scene` (its first object) with `mesh` standing on it, as the ray
/// caster sees them: the mesh as one shape ([`Model::object`]), the same background
/// and light.
pub fn floor_and_mesh(scene: &Scene, mesh: &Model) -> Result<Scene> {
    floor_and(scene, mesh.object()?)
}

/// The floor of `scene` (its first object) and `object`, with the same background
/// and light.
pub fn floor_and(scene: &Scene, object: Object) -> Result<Scene> {
    let objects = vec![scene.objects()[0].clone(), object];
    let floor_and_object = Scene::new(objects, scene.background())?;
    match scene.point_light() {
        Some(light) => floor_and_object.with_light(light),
        None => Ok(floor_and_object),
    }
}
