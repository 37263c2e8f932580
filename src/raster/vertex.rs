//! What travels with a vertex from the vertex stage to the fragments: its clip-space
//! position and the attributes ("varyings") that the rasterizer interpolates.

use glam::{Vec2, Vec3, Vec4};

/// The interpolated attributes of a vertex or fragment.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Varyings {
    /// World-space position (for per-pixel lighting).
    pub world: Vec3,
    /// World-space normal (not unit after interpolation).
    pub normal: Vec3,
    /// Per-vertex lit colour (Gouraud) or albedo (per-pixel shading), or any other
    /// three numbers a lesson wants interpolated.
    pub colour: Vec3,
    /// Texture coordinates (u, v), for a textured mesh.
    pub uv: Vec2,
}

impl Varyings {
    /// `self + t (other - self)`.
    pub fn lerp(&self, other: &Varyings, t: f32) -> Varyings {
        Varyings {
            world: self.world.lerp(other.world, t),
            normal: self.normal.lerp(other.normal, t),
            colour: self.colour.lerp(other.colour, t),
            uv: self.uv.lerp(other.uv, t),
        }
    }

    /// The weighted sum sum_k weights\[k\] v\[k\].
    pub fn weighted(v: &[Varyings; 3], weights: [f32; 3]) -> Varyings {
        let sum = |f: fn(&Varyings) -> Vec3| {
            f(&v[0]) * weights[0] + f(&v[1]) * weights[1] + f(&v[2]) * weights[2]
        };
        let [uv0, uv1, uv2] = v.map(|v| v.uv);
        Varyings {
            world: sum(|v| v.world),
            normal: sum(|v| v.normal),
            colour: sum(|v| v.colour),
            uv: uv0 * weights[0] + uv1 * weights[1] + uv2 * weights[2],
        }
    }
}

/// A vertex after the projection matrix: homogeneous clip-space position, and its
/// attributes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// (x, y, z, w) in clip space.
    pub clip: Vec4,
    /// The attributes to interpolate.
    pub varyings: Varyings,
}

impl ClipVertex {
    /// The point a fraction `t` of the way to `other`: clip space is linear in the
    /// homogeneous coordinates, so a straight lerp is exact there.
    pub fn lerp(&self, other: &ClipVertex, t: f32) -> ClipVertex {
        ClipVertex {
            clip: self.clip.lerp(other.clip, t),
            varyings: self.varyings.lerp(&other.varyings, t),
        }
    }
}
