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
/// The colour of a surface point `p` with normal `n` and colour `albedo`, on a
/// triangle whose own (geometric) normal is `n_g`, lit by `light` as
/// [`lighting::lambert`] computes it, the light visible if `visible()` says so. The
/// normal is first turned to the side of the surface the viewer sees (two-sided
/// lighting): to `n_g`'s side, then towards the viewer if the triangle faces away
/// from it, as OpenGL decides a polygon's side by the polygon and ray casting by the
/// side the ray arrived from ([`crate::shapes::Hit::shading_facing`]). On a flat
/// triangle, n = n_g, that is the side facing the viewer.
pub fn shade(
    p: Vec3,
    (n, n_g): (Vec3, Vec3),
    albedo: Vec3,
    light: &PointLight,
    viewer: &Viewer,
    visible: impl FnOnce() -> bool,
) -> Vec3 {
    let n = n.normalize_or_zero();
    let n_g = if n_g == Vec3::ZERO { n } else { n_g }; // a sliver of no area
    let n = if n.dot(n_g) < 0.0 { -n } else { n };
    let n = if n_g.dot(viewer.toward(p)) < 0.0 {
        -n
    } else {
        n
    };
    lighting::lambert(p, n, albedo, light, visible)
}
// ANCHOR_END: lambert
