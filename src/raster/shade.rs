//! Lighting (Lecture 2, "Rasterization Pipeline: Lighting"): Lambert's cosine law
//! from one point light, the formula of `raycast::lit`, but with no shadow ray:
//! a rasterizer sees one triangle at a time and cannot ask what lies in between.
//! Whether the light is visible comes from elsewhere (a shadow map) or is assumed.

use glam::Vec3;

use crate::lighting;
use crate::scene::PointLight;

/// Where lighting is computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shading {
    /// Gouraud shading: light each vertex, interpolate the colours.
    PerVertex,
    /// Per-pixel shading: interpolate position and normal, light every fragment
    /// (the lecture's "per pixel shading").
    #[default]
    PerPixel,
}

/// Where the viewer is, to decide which side of a surface faces it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Viewer {
    /// A pinhole camera's eye.
    Point(Vec3),
    /// An orthographic camera: the direction from the scene towards the camera.
    Direction(Vec3),
}

impl Viewer {
    /// The direction from `p` towards the viewer (not unit).
    pub fn toward(&self, p: Vec3) -> Vec3 {
        match self {
            Viewer::Point(eye) => *eye - p,
            Viewer::Direction(d) => *d,
        }
    }
}

// ANCHOR: lambert
/// The colour of a surface point `p` with normal `n` and colour `albedo`, lit by
/// `light` as [`lighting::lambert`] computes it, the light visible if `visible()`
/// says so. The normal is turned to face the viewer first (two-sided lighting), as
/// ray casting shades the side the ray arrived from.
pub fn shade(
    p: Vec3,
    n: Vec3,
    albedo: Vec3,
    light: &PointLight,
    viewer: &Viewer,
    visible: impl FnOnce() -> bool,
) -> Vec3 {
    let n = n.normalize_or_zero();
    let n = if n.dot(viewer.toward(p)) < 0.0 { -n } else { n };
    lighting::lambert(p, n, albedo, light, visible)
}
// ANCHOR_END: lambert
