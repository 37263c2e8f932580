//! Triangle meshes, for the rasterizer, the ray caster and the path tracer alike.
//!
//! A mesh is a vertex list and a triangle list, read from a file or made from
//! shapes, and placed in the world by a [`Model`]. The rasterizer draws nothing
//! else; the ray caster and the path tracer take a mesh's triangles as primitives
//! ([`Mesh::objects`], [`Model::objects`]).
//!
//! - [`modeling`]: the [`Mesh`] itself (Lecture 2, "Modeling"), and the meshes made
//!   from shapes (a uv sphere, a box, a floor square);
//! - [`obj`]: reading a Wavefront OBJ file, faces split into triangles;
//! - [`polygon`]: a face of any number of corners cut into triangles (ear
//!   clipping);
//! - [`teapot`]: the Newell teapot's patches, cut into quads and written as OBJ;
//! - [`subdivide`]: every triangle split in four, for meshes of a million triangles;
//! - [`tessellate`](mod@tessellate): a scene of analytic primitives as meshes, object
//!   by object.

pub mod modeling;
pub mod obj;
pub mod polygon;
pub mod subdivide;
pub mod teapot;
pub mod tessellate;

pub use modeling::{LECTURE_TRIANGLES, LECTURE_VERTICES, Mesh};
pub use obj::{FaceCounts, LoadedMesh, PARSE_BYTES_PER_BYTE, origin};
pub use polygon::{NotSimple, ear_clip};
pub use subdivide::{MAX_SUBDIVISIONS, check_subdivisions, subdivided_count};
pub use teapot::{patch_point, teapot_obj};
pub use tessellate::{FLOOR_SIZE, check_segments, tessellate};

use glam::Vec3;

use crate::error::Result;
use crate::scene::Object;
use crate::transform::Transform;

/// A mesh placed in the world by a model transform, with one colour (linear RGB
/// albedo).
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    /// The vertex and triangle lists.
    pub mesh: Mesh,
    /// Model space to world space.
    pub model: Transform,
    /// The albedo.
    pub colour: Vec3,
}

impl Model {
    /// `mesh` as it is (model = identity), coloured `colour`.
    pub fn new(mesh: Mesh, colour: Vec3) -> Model {
        Model {
            mesh,
            model: Transform::IDENTITY,
            colour,
        }
    }

    /// The same model placed in the world by `model` (model space to world space).
    pub fn placed(self, model: Transform) -> Model {
        Model { model, ..self }
    }

    /// The mesh as the ray caster sees it, placed in the world: one triangle
    /// primitive per triangle, coloured [`Model::colour`].
    pub fn objects(&self) -> Result<Vec<Object>> {
        let mut world = self.mesh.clone();
        for p in &mut world.positions {
            *p = self.model.point(*p);
        }
        world.objects(self.colour)
    }
}
