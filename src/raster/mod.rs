//! Rasterization (Lecture 2, "Rasterization Pipeline"): modeling (a vertex list and
//! a triangle list) -> transform -> lighting -> primitive rasterization with a
//! z-buffer -> per-pixel shading. The same scenes as the ray caster of lesson 08,
//! drawn triangle by triangle instead of ray by ray.
//!
//! [`pipeline`] runs the stages in order; each stage has a file of its own.

pub mod clip;
pub mod compare;
pub mod mesh;
pub mod obj;
pub mod pipeline;
pub mod projection;
pub mod rasterize;
pub mod shade;
pub mod shadow_map;
pub mod subdivide;
pub mod teapot;
pub mod tessellate;
pub mod vertex;

pub use clip::clip_triangle;
pub use compare::{Agreement, Reference, TOLERANCE, agreement, difference, reference};
pub use mesh::{LECTURE_TRIANGLES, LECTURE_VERTICES, Mesh};
pub use obj::{FaceCounts, LoadedMesh, fan};
pub use pipeline::{BAND_ROWS, rasterize, viewer};
pub use projection::{CameraTransforms, DepthRange};
pub use rasterize::{Cull, Fragment, ScreenVertex, rasterize_triangle};
pub use shade::{Shading, Viewer, shade};
pub use shadow_map::{ShadowMap, Shadows};
pub use subdivide::{MAX_SUBDIVISIONS, check_subdivisions, subdivided_count};
pub use teapot::{patch_point, teapot_obj};
pub use tessellate::{
    FLOOR_DEPTH, FLOOR_SIZE, check_segments, floor_settings, point_light, tessellate,
};
pub use vertex::{ClipVertex, Varyings};

use glam::Vec3;

use crate::error::Result;
use crate::scene::Object;
use crate::transform::Transform;

/// A mesh placed in the world by a model transform, with one colour (linear RGB albedo).
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

/// Everything about a rasterization that is not the scene or the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterSettings {
    /// Near and far planes.
    pub depth: DepthRange,
    /// Per vertex or per pixel.
    pub shading: Shading,
    /// Which faces to skip.
    pub cull: Cull,
    /// The colour where no triangle is drawn.
    pub background: Vec3,
    /// A shadow map to build and use, or none: every surface facing the light is lit.
    pub shadows: Option<Shadows>,
}

impl RasterSettings {
    /// These settings with `shading` and `shadows` instead.
    pub fn with(self, shading: Shading, shadows: Option<Shadows>) -> RasterSettings {
        RasterSettings {
            shading,
            shadows,
            ..self
        }
    }
}

impl Default for RasterSettings {
    /// Near 0.1, far 1000, per-pixel shading, no culling, black background, no
    /// shadows.
    fn default() -> RasterSettings {
        RasterSettings {
            depth: DepthRange {
                near: 0.1,
                far: 1000.0,
            },
            shading: Shading::PerPixel,
            cull: Cull::None,
            background: Vec3::ZERO,
            shadows: None,
        }
    }
}
