//! Triangle meshes, for the rasterizer, the ray caster and the path tracer alike.
//!
//! A mesh is a vertex list and a triangle list, read from a file or made from
//! shapes, and placed in the world by a [`Model`]. The rasterizer draws nothing
//! else; the ray caster and the path tracer take a placed mesh as one shape with a
//! tree of its own ([`Model::shape`], a [`TriangleMesh`]), shaded smooth by its
//! vertex normals as the rasterizer shades it, or its triangles as primitives, one
//! flat-shaded object each ([`Model::objects`], [`Mesh::objects`]), as lesson 11
//! measures a tree over a scene's primitives.
//!
//! - [`modeling`]: the [`Mesh`] itself (Lecture 2, "Modeling"), and the meshes made
//!   from shapes (a uv sphere, a box, a floor square);
//! - [`obj`]: reading a Wavefront OBJ file, faces split into triangles, with the
//!   corners' normals and texture coordinates (`attributes`) and the texture of
//!   their material ([`mtl`]);
//! - [`polygon`]: a face of any number of corners cut into triangles (ear
//!   clipping);
//! - [`teapot`]: the Newell teapot's patches, cut into quads and written as OBJ;
//! - [`subdivide`]: every triangle split in four, for meshes of a million triangles;
//! - [`tessellate`](mod@tessellate): a scene of analytic primitives as meshes, object
//!   by object.

mod attributes;
pub mod modeling;
pub mod mtl;
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

use std::sync::Arc;

use glam::Vec3;

use crate::error::{Error, Problem, Result};
use crate::scene::Object;
use crate::shapes::TriangleMesh;
use crate::texture::Texture;
use crate::transform::Transform;

/// A mesh placed in the world by a model transform, with one colour (linear RGB
/// albedo) or a texture.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    /// The vertex and triangle lists.
    pub mesh: Mesh,
    /// Model space to world space.
    pub model: Transform,
    /// The albedo, where there is no texture.
    pub colour: Vec3,
    /// The texture the albedo is looked up in, by the mesh's texture coordinates.
    pub texture: Option<Arc<Texture>>,
}

impl Model {
    /// `mesh` as it is (model = identity), coloured `colour`.
    pub fn new(mesh: Mesh, colour: Vec3) -> Model {
        Model {
            mesh,
            model: Transform::IDENTITY,
            colour,
            texture: None,
        }
    }

    /// The same model placed in the world by `model` (model space to world space).
    pub fn placed(self, model: Transform) -> Model {
        Model { model, ..self }
    }

    /// The same model with its albedo looked up in `texture` at each point, by the
    /// mesh's texture coordinates ([`Mesh::with_uvs`]).
    pub fn textured(self, texture: Texture) -> Model {
        Model {
            texture: Some(Arc::new(texture)),
            ..self
        }
    }

    /// The model's texture, `Ok(None)` for none; an error if it has one but its mesh
    /// has no texture coordinates to look it up by.
    pub fn checked_texture(&self) -> Result<Option<&Texture>> {
        match (&self.texture, self.mesh.uvs.is_empty()) {
            (Some(_), true) => Err(Error::Value {
                param: "texture",
                problem: Problem::Invalid {
                    reason: "needs a mesh with texture coordinates (vt lines)",
                },
            }),
            (texture, _) => Ok(texture.as_deref()),
        }
    }

    // ANCHOR: model_shape
    /// The mesh placed in the world as one shape: its vertices taken there by the
    /// model transform, its normals by the inverse transpose (normalised, as the
    /// rasterizer's vertex stage takes them), its triangles in a tree of their own.
    /// The ray caster and the path tracer shade it smooth, by the vertex normals
    /// blended at each hit; a flat-shaded mesh ([`Mesh::flat_shaded`]) shades flat.
    pub fn shape(&self) -> Result<TriangleMesh> {
        let normal_matrix = self.model.inverse()?.matrix().transpose();
        let mesh = &self.mesh;
        let positions = mesh.positions.iter().map(|&p| self.model.point(p));
        let normals = mesh
            .normals
            .iter()
            .map(|&n| normal_matrix.transform_vector3(n).normalize_or_zero());
        TriangleMesh::new(
            positions.collect(),
            &mesh.triangles,
            normals.collect(),
            mesh.uvs.clone(),
        )
    }

    /// The model as one object of the scene: its [`Model::shape`], diffuse of its
    /// colour, or of its texture's colours ([`Object::textured`]).
    pub fn object(&self) -> Result<Object> {
        self.checked_texture()?;
        let shape = self.shape()?;
        Ok(match &self.texture {
            Some(texture) => Object::textured(shape, texture.clone()),
            None => Object::diffuse(shape, self.colour),
        })
    }
    // ANCHOR_END: model_shape

    /// The mesh placed in the world as primitives: one triangle per triangle,
    /// coloured [`Model::colour`] and shaded flat (lesson 11 measures a tree over
    /// a scene of primitives).
    pub fn objects(&self) -> Result<Vec<Object>> {
        let mut world = self.mesh.clone();
        for p in &mut world.positions {
            *p = self.model.point(*p);
        }
        world.objects(self.colour)
    }
}
