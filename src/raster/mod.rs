//! The rasterizer: meshes drawn into an image triangle by triangle, with a z-buffer.
//!
//! Rasterization (Lecture 2, "Rasterization Pipeline"): modeling (a vertex list and
//! a triangle list, [`crate::mesh`]) -> transform -> lighting -> primitive
//! rasterization with a z-buffer -> per-pixel shading. The same scenes as the ray
//! caster of lesson 08, drawn triangle by triangle instead of ray by ray.
//!
//! [`pipeline`] runs the stages in order; each stage has a file of its own.

pub mod clip;
pub mod pipeline;
pub mod projection;
pub mod rasterize;
pub mod shade;
pub mod shadow_map;
pub mod vertex;

pub use clip::clip_triangle;
pub use pipeline::{BAND_ROWS, rasterize, viewer};
pub use projection::{CameraTransforms, DepthRange};
pub use rasterize::{Cull, Fragment, ScreenVertex, rasterize_triangle};
pub use shade::{Shading, Viewer, shade};
pub use shadow_map::{ShadowMap, Shadows};
pub use vertex::{ClipVertex, Varyings};

use glam::Vec3;

use crate::error::{Error, Problem, Result};
use crate::scene::{PointLight, Scene};

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

/// A rasterization needs a far plane; this one lies beyond the far edge of a floor
/// of [`FLOOR_SIZE`](crate::mesh::FLOOR_SIZE) seen from near its centre.
pub const FLOOR_DEPTH: DepthRange = DepthRange {
    near: 0.1,
    far: 2e4,
};

/// How to rasterize a tessellated scene: depth range [`FLOOR_DEPTH`], the scene's
/// background, per-pixel shading, no culling, no shadows.
pub fn floor_settings(scene: &Scene) -> RasterSettings {
    RasterSettings {
        depth: FLOOR_DEPTH,
        background: scene.background(),
        ..RasterSettings::default()
    }
}

/// The scene's point light: the one light a rasterizer shades with.
pub fn point_light(scene: &Scene) -> Result<PointLight> {
    scene.point_light().ok_or(Error::Value {
        param: "scene",
        problem: Problem::Invalid {
            reason: "needs a point light to be rasterized",
        },
    })
}
