//! Two squares facing the camera, a small red one at Z = -3 in front of a large
//! blue one at Z = -5: the z-buffer's scene in lesson 09 (its test draws them in
//! both orders, its figure shows the image).

use glam::Vec3;

use crate::camera::{Camera, Film, PinholeCamera};
use crate::error::Result;
use crate::mesh::{Mesh, Model};
use crate::scene::PointLight;

/// The two squares, the camera that sees them (16 x 9 pixels, at the origin looking
/// down -Z, screen at distance 1) and a point light behind the camera.
pub struct Squares {
    /// The small red square in front, half side 1 at Z = -3.
    pub near: Model,
    /// The large blue square behind, half side 6 at Z = -5.
    pub far: Model,
    /// The camera that sees them.
    pub camera: Camera,
    /// The light behind the camera.
    pub light: PointLight,
}

/// [`Squares`], built.
pub fn squares() -> Result<Squares> {
    let film = Film::new(16, 9, (-1.6, 1.6), (-0.9, 0.9))?;
    Ok(Squares {
        near: Model::new(square(-3.0, 1.0)?, Vec3::new(1.0, 0.2, 0.2)),
        far: Model::new(square(-5.0, 6.0)?, Vec3::new(0.2, 0.2, 1.0)),
        camera: PinholeCamera::at_origin(film, 1.0)?.into(),
        light: PointLight {
            position: Vec3::new(0.0, 0.0, 2.0),
            intensity: Vec3::splat(20.0),
        },
    })
}

/// A square of half side `half` in the plane Z = `z`, centred on the Z axis, as two
/// counter-clockwise triangles seen from the origin.
fn square(z: f32, half: f32) -> Result<Mesh> {
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    let vertices = corners.map(|(x, y)| Vec3::new(x * half, y * half, z));
    Mesh::new(vertices.to_vec(), vec![[0, 1, 2], [0, 2, 3]])
}
