//! Lighting (Lecture 2, "Rasterization Pipeline: Lighting"): Lambert's cosine law
//! from one point light, the formula of `raycast::lambert` without the shadow ray
//! (a rasterizer sees one triangle at a time and cannot ask what lies in between).

use glam::Vec3;

use crate::raycast::AMBIENT;
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
/// The colour of a surface point `p` with normal `n` and colour `albedo`:
/// albedo (AMBIENT + I cos(theta) / d^2), theta the angle between the normal and the
/// direction to the light, d the distance to it, and no direct term when cos <= 0.
/// The normal is turned to face the viewer first (two-sided lighting), as ray casting
/// shades the side the ray arrived from. Always finite.
pub fn lambert(p: Vec3, n: Vec3, albedo: Vec3, light: &PointLight, viewer: &Viewer) -> Vec3 {
    let n = n.normalize_or_zero();
    let n = if n.dot(viewer.toward(p)) < 0.0 { -n } else { n };
    let to_light = light.position - p;
    let d2 = to_light.length_squared();
    let mut colour = albedo * AMBIENT;
    if d2 > f32::MIN_POSITIVE && d2.is_finite() {
        let cos_theta = n.dot(to_light / d2.sqrt());
        if cos_theta > 0.0 {
            colour += albedo * light.intensity * cos_theta / d2;
        }
    }
    colour.clamp(Vec3::splat(-f32::MAX), Vec3::splat(f32::MAX))
}
// ANCHOR_END: lambert
